// Reading TOML config files (toml11) into plain structs with errors that name
// the file, the line, the dotted key ("bumps[0].length") and what was
// expected. Every key a reader does not consume (finish) or does not allow
// (rejectUnknownKeys) is reported as unknown, so typos do not pass silently.
// This is the only reader of TOML: toml.hpp costs ~20 s per file that
// includes it, so it stays inside toml_reader.cpp.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <optional>
#include <set>
#include <utility>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "config/range.h"
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
  Eigen::Vector3d vector3(const std::string& key, Dimension d, const Eigen::Vector3d& fallback);
  std::optional<Table> optionalTable(const std::string& key);
  std::vector<Table> optionalTables(const std::string& key);

  // Quantities (numbers or strings with a unit) in a physical range; errors
  // read "key 'bodies[0].mass': expected a mass in (0, 1e+06) kg, got -3".
  // Every number reader refuses NaN and inf.
  double number(const std::string& key, Dimension d, const Range& range);
  double number(const std::string& key, Dimension d, const Range& range, double fallback);
  std::vector<double> numbers(const std::string& key, Dimension d, const Range& range);
  Eigen::Vector3d vector3(const std::string& key, Dimension d, const Range& range);

  // Checked plain values (TOML numbers and strings, no unit strings); errors
  // show what was found: "key 'friction': expected a number in (0, 2], got 5".
  // A finite number in `range`.
  double numberIn(const std::string& key, const Range& range);
  double numberIn(const std::string& key, const Range& range, double fallback);
  // An integer in [lo, hi].
  long integerIn(const std::string& key, long lo, long hi);
  long integerIn(const std::string& key, long lo, long hi, long fallback);
  // One integer in [lo, hi] or an array of them; none when absent.
  std::vector<long> integersIn(const std::string& key, long lo, long hi);
  // A string that is one of `choices`.
  std::string choice(const std::string& key, const std::vector<std::string_view>& choices);
  std::string choice(const std::string& key, const std::vector<std::string_view>& choices,
                     const std::string& fallback);
  // One string or an array of strings; none when absent.
  std::vector<std::string> stringOrStrings(const std::string& key);
  // An array of at least minRows rows, each an array of at least minColumns
  // finite numbers and all as long as the first (a grid of samples).
  std::vector<std::vector<double>> grid(const std::string& key, std::size_t minRows, std::size_t minColumns);

  // Each element of an array of numbers, strings or booleans as TOML text
  // (what a Setting's value takes): 30000, "80 km/h", true.
  std::vector<std::string> scalarTexts(const std::string& key);

  bool has(const std::string& key) const;
  bool isString(const std::string& key) const;
  bool isArray(const std::string& key) const;
  bool isTable(const std::string& key) const;
  std::vector<std::string> keys() const;

  // Checks on values already read (error located at the key).
  void require(bool ok, const std::string& key, const std::string& expectation) const;
  // "key 'k': expected <expectation>, got <the value>" at the key (at element
  // `element` of its array when >= 0); "missing key 'k'" when it is absent.
  [[noreturn]] void reject(const std::string& key, const std::string& expectation, int element = -1) const;
  // An error located at this table (or at `key` when given).
  [[noreturn]] void fail(const std::string& message, const std::string& key = "") const;
  // Throws at the first key (by line) that was never read.
  void finish() const;
  // Throws at the first key (by line) not in `known`, listing them; for
  // readers that check keys before reading (or read only some of them).
  void rejectUnknownKeys(const std::vector<std::string_view>& known) const;

  const std::string& context() const { return context_; }  // e.g. "bodies[3]", "axes.steering"
  std::string dotted(const std::string& key) const;        // context.key, or key at the top
  const std::string& file() const;                          // the document's (the top file's) path
  // The folder a relative path in `key`'s value is relative to: that of the
  // file the value was written in (an included file's own folder), or the
  // working directory for a command-line setting (empty).
  std::string folderOf(const std::string& key) const;
  int line(const std::string& key = "") const;
  // The file the key's value (or this table) was written in: an included
  // file's name where it came from one.
  std::string sourceOf(const std::string& key = "") const;

  Table(std::shared_ptr<const TomlDocument> doc, const void* value, std::string context);

 private:
  const void* find(const std::string& key) const;
  const void* get(const std::string& key, const std::string& expectation);
  [[noreturn]] void failAt(const void* value, const std::string& message) const;
  [[noreturn]] void failValue(const void* value, const std::string& key, const std::string& expectation) const;
  void failFirstUnknown(const std::vector<std::string_view>& known, const std::string& suffix) const;

  std::shared_ptr<const TomlDocument> doc_;
  const void* value_;  // const toml::value*
  std::string context_;
  std::shared_ptr<std::set<std::string>> used_;
};

// A command-line override of one key (`--set KEY=VALUE`): a key path of
// dotted names and array indices ("springs[2].damping", "start.speed") and a
// TOML value ("80", "\"80 km/h\"", "[1, 2]"); a value that is not TOML (a
// bare word: planar, 80 km/h) is taken as a string. Messages about the value
// name it as its file: "--set start.speed=80 km/h: key 'start.speed': ...".
struct Setting {
  std::string key, value;
  std::string written;  // the option as given, when the key was taken from a longer one ("vehicle.KEY")
  std::string origin() const { return "--set " + (written.empty() ? key + "=" + value : written); }
};
// Splits "KEY=VALUE"; throws ConfigError when there is no '=' or no key.
Setting parseSetting(const std::string& keyEqualsValue);
// A setting addressed to a part of the input ("vehicle.springs[0].damping"
// for the scenario's vehicle): the key below the prefix, its messages still
// naming the option as written; nullopt when the key does not start with it.
std::optional<Setting> underPrefix(const Setting& s, const std::string& prefix);

// The key log, for the test that every key a reader looks up is documented
// (docs/SCENARIOS.md, docs/VEHICLES.md): while on, every key a Table looks up,
// present or not, is recorded as its dotted path with array indices dropped
// ("bodies[].mass"), under the document's path. Off by default (no cost).
void startKeyLog();
std::set<std::pair<std::string, std::string>> stopKeyLog();  // (document path, key)

// Parses a file (read whole, so pipes work too); throws ConfigError (with the
// line) on syntax errors, nesting deeper than 64 arrays / inline tables, or
// when the file cannot be read (missing, a directory, over 16 MiB).
//
// A file may include others: `include = "shared.toml"` or an array of names,
// at the top, relative to the including file. Their tables are merged under
// the including file's: a key the including file writes wins (tables merge
// key by key, any other value, arrays too, is replaced whole), and of two
// included files the later wins. Includes nest (8 deep at most, no cycles).
// Every value keeps the file and line it was written at, for messages.
// The settings are applied last, over everything.
Table parseTomlFile(const std::string& path, const std::vector<Setting>& settings = {});
// Parses TOML text read elsewhere; `fileName` is what messages call it.
Table parseTomlText(const std::string& text, const std::string& fileName);

}  // namespace bdfcar::config
