// Strict readers for mapping-file fields: every error names the file, the
// line, the dotted key and what was expected (private to input/).
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <toml.hpp>
#include <vector>

namespace bdfcar::input::fields {

// A closed or open interval a number must lie in.
struct Range {
  double lo, hi;
  bool loOpen = false, hiOpen = false;
};

// How a button / key / axis is named in a file: an integer index in [lo, hi],
// or (fromName set) a name that fromName resolves (-1: no such name).
struct CodeSpec {
  int lo = 0, hi = 255;
  std::function<int(std::string_view)> fromName;
  std::string expected;  // e.g. "a button index 0..255" or "an SDL key name such as \"Left\""
};

// "file:line" of a value.
std::string where(const toml::value& at);

// Throws MappingError "file:line: key 'path.key': expected <expected>, got <value>".
[[noreturn]] void fail(const toml::value& at, const std::string& dottedKey, const std::string& expected);

// Throws MappingError naming the first key of `table` (by line) not in `allowed`.
void checkKeys(const toml::value& table, const std::string& path, const std::vector<std::string_view>& allowed);

// `table.key` if present (a table), else nullptr; `required` makes absence an error.
const toml::value* subTable(const toml::value& table, const std::string& path, const std::string& key,
                            bool required);

// Optional number (integer or float) in `range`; `fallback` when absent.
double readNumber(const toml::value& table, const std::string& path, const std::string& key, Range range,
                  double fallback);

// Optional integer in [lo, hi]; `fallback` when absent.
int readInteger(const toml::value& table, const std::string& path, const std::string& key, int lo, int hi,
                int fallback);

// Optional boolean; `fallback` when absent.
bool readBool(const toml::value& table, const std::string& path, const std::string& key, bool fallback);

// Optional string that must be one of `choices`; `fallback` when absent.
std::string readChoice(const toml::value& table, const std::string& path, const std::string& key,
                       const std::vector<std::string_view>& choices, const std::string& fallback);

// Optional string or array of strings; empty when absent.
std::vector<std::string> readStrings(const toml::value& table, const std::string& path, const std::string& key);

// Required single code (index or name) per `spec`.
int readCode(const toml::value& table, const std::string& path, const std::string& key, const CodeSpec& spec);

// Optional code or array of codes per `spec`; empty when absent.
std::vector<int> readCodes(const toml::value& table, const std::string& path, const std::string& key,
                           const CodeSpec& spec);

}  // namespace bdfcar::input::fields
