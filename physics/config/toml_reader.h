// Reading TOML config files (toml11) into plain structs with errors that name
// the file, the line, the key and what was expected. Every key a reader does
// not consume is reported as unknown, so typos do not pass silently.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "config/units.h"

namespace toml {
struct discard_comments;
}

namespace bdfcar::config {

// An error in a config file: what() is "file:line: message".
struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class TomlDocument;

// A view of one TOML table that records which keys were read.
class Table {
 public:
  // Required keys.
  double number(const std::string& key, Dimension d = Dimension::None);
  std::string string(const std::string& key);
  bool boolean(const std::string& key);
  long integer(const std::string& key);
  Eigen::Vector3d vector3(const std::string& key, Dimension d = Dimension::Length);
  std::vector<double> numbers(const std::string& key, Dimension d = Dimension::None);
  std::vector<std::string> strings(const std::string& key);
  Table table(const std::string& key);
  std::vector<Table> tables(const std::string& key);  // array of tables

  // Optional keys: the fallback when absent.
  double number(const std::string& key, Dimension d, double fallback);
  std::string string(const std::string& key, const std::string& fallback);
  bool boolean(const std::string& key, bool fallback);
  long integer(const std::string& key, long fallback);
  std::optional<Table> optionalTable(const std::string& key);
  std::vector<Table> optionalTables(const std::string& key);

  bool has(const std::string& key) const;
  bool isString(const std::string& key) const;
  bool isArray(const std::string& key) const;
  bool isTable(const std::string& key) const;
  std::vector<std::string> keys() const;

  // Checks on values already read (error located at the key).
  void require(bool ok, const std::string& key, const std::string& expectation) const;
  // An error located at this table (or at `key` when given).
  [[noreturn]] void fail(const std::string& message, const std::string& key = "") const;
  // Throws for every key that was never read.
  void finish() const;

  const std::string& context() const { return context_; }  // e.g. "bodies[3]"
  const std::string& file() const;
  int line(const std::string& key = "") const;

  Table(std::shared_ptr<const TomlDocument> doc, const void* value, std::string context);

 private:
  const void* find(const std::string& key) const;
  const void* get(const std::string& key, const std::string& expectation);
  [[noreturn]] void failAt(const void* value, const std::string& message) const;

  std::shared_ptr<const TomlDocument> doc_;
  const void* value_;  // const toml::value*
  std::string context_;
  std::shared_ptr<std::set<std::string>> used_;
};

// Parses a file; throws ConfigError (with line and column) on syntax errors
// or when the file cannot be read.
Table parseTomlFile(const std::string& path);

}  // namespace bdfcar::config
