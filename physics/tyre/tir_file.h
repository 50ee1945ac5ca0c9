// A tyre property file (.tir, the TNO / ADAMS format Magic Formula data
// comes in): [SECTIONS] of `KEY = value` lines, '!' and '$' comments
// (whole-line, and '$' after a value), quoted strings, CRLF line ends, and
// tables inside some sections ([SHAPE], [DEFLECTION_LOAD_CURVE] ...) that
// are kept by section but not interpreted. Keys are case-insensitive and
// count only in their own section. [UNITS] names the units of the
// dimensional entries; unitFactor() converts them to SI. Read through
// config::LineReader (its limits); every error names the file, the line and
// the key.
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace bdfcar::tyre {

class TirError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class TirFile {
 public:
  struct Entry {
    std::string section, key, value;  // section and key upper-case; value unquoted
    int line = 0;
    bool quoted = false;
  };

  static TirFile read(const std::string& path);
  // From text (tests, fuzzing); `path` names it in messages.
  static TirFile parse(const std::string& text, const std::string& path);

  const std::string& path() const { return path_; }
  bool hasSection(const std::string& section) const;
  const Entry* find(const std::string& section, const std::string& key) const;
  // A number: required, or `fallback` when the key is absent. A value that
  // is not a finite number is an error at its line.
  double number(const std::string& section, const std::string& key) const;
  double number(const std::string& section, const std::string& key, double fallback) const;
  // A string (quotes removed), upper-cased; `fallback` when absent.
  std::string word(const std::string& section, const std::string& key, const std::string& fallback) const;
  const std::vector<Entry>& entries() const { return entries_; }

  // SI per unit of a dimension as [UNITS] names it (LENGTH, FORCE, MASS,
  // TIME; ANGLE must be radians, the unit the coefficients are fitted in):
  // 1 when the section or key is absent; an unknown unit is an error at its line.
  double unitFactor(const std::string& dimension) const;

  [[noreturn]] void fail(const Entry& e, const std::string& what) const;
  [[noreturn]] void fail(const std::string& section, const std::string& key, const std::string& what) const;

 private:
  std::string path_;
  std::vector<Entry> entries_;
  std::map<std::string, int> sections_;  // name -> line
  std::map<std::string, std::size_t> index_;  // "SECTION/KEY" -> entries_ index
};

}  // namespace bdfcar::tyre
