#include "toml_fields.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "input/mapping.h"

namespace bdfcar::input::fields {
namespace {

// A number as a person would write it (no trailing zeros).
std::string formatNumber(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", x);
  return buffer;
}

// What a value is, for "got ..." in messages: scalars by value, others by type.
std::string describe(const toml::value& v) {
  switch (v.type()) {
    case toml::value_t::boolean: return v.as_boolean() ? "true" : "false";
    case toml::value_t::integer: return std::to_string(v.as_integer());
    case toml::value_t::floating: return formatNumber(v.as_floating());
    case toml::value_t::string: return "\"" + v.as_string().str + "\"";
    case toml::value_t::array: return "an array";
    case toml::value_t::table: return "a table";
    case toml::value_t::empty: return "nothing";
    default: return "a date or time";
  }
}

// "a number in [lo, hi)" and the like.
std::string describe(const Range& r) {
  return "a number in " + std::string(r.loOpen ? "(" : "[") + formatNumber(r.lo) + ", " + formatNumber(r.hi) +
         (r.hiOpen ? ")" : "]");
}

// Whether x lies in the range (NaN does not).
bool inRange(double x, const Range& r) {
  const bool aboveLo = r.loOpen ? x > r.lo : x >= r.lo;
  const bool belowHi = r.hiOpen ? x < r.hi : x <= r.hi;
  return aboveLo && belowHi;
}

// "path.key" ("key" at the top level).
std::string dotted(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

// `table.key` or nullptr when absent.
const toml::value* find(const toml::value& table, const std::string& key) {
  const auto& t = table.as_table();
  const auto it = t.find(key);
  return it == t.end() ? nullptr : &it->second;
}

// One code (index or name) per spec, reported as `key` when wrong.
int toCode(const toml::value& v, const std::string& key, const CodeSpec& spec) {
  if (spec.fromName) {
    if (!v.is_string()) fail(v, key, spec.expected);
    const int code = spec.fromName(v.as_string().str);
    if (code < 0) fail(v, key, spec.expected);
    return code;
  }
  if (!v.is_integer() || v.as_integer() < spec.lo || v.as_integer() > spec.hi) fail(v, key, spec.expected);
  return static_cast<int>(v.as_integer());
}

}  // namespace

// "file:line" of a value.
std::string where(const toml::value& at) {
  const toml::source_location loc = at.location();
  return loc.file_name() + ":" + std::to_string(loc.line());
}

// Throws the standard "expected ..., got ..." error at a value.
void fail(const toml::value& at, const std::string& dottedKey, const std::string& expected) {
  throw MappingError(where(at) + ": key '" + dottedKey + "': expected " + expected + ", got " + describe(at));
}

// Throws for the first (by line) key of `table` not in `allowed`.
void checkKeys(const toml::value& table, const std::string& path, const std::vector<std::string_view>& allowed) {
  const toml::value* first = nullptr;
  std::string firstKey;
  for (const auto& [key, value] : table.as_table()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    if (!first || value.location().line() < first->location().line()) first = &value, firstKey = key;
  }
  if (!first) return;
  std::string expected;
  for (std::string_view k : allowed) expected += (expected.empty() ? "" : ", ") + std::string(k);
  throw MappingError(where(*first) + ": unknown key '" + dotted(path, firstKey) + "'; expected one of: " + expected);
}

// A sub-table, checked to be a table.
const toml::value* subTable(const toml::value& table, const std::string& path, const std::string& key,
                            bool required) {
  const toml::value* v = find(table, key);
  if (!v) {
    if (required)
      throw MappingError(where(table) + ": missing table '" + dotted(path, key) + "'");
    return nullptr;
  }
  if (!v->is_table()) fail(*v, dotted(path, key), "a table");
  return v;
}

// An optional number within a range.
double readNumber(const toml::value& table, const std::string& path, const std::string& key, Range range,
                  double fallback) {
  const toml::value* v = find(table, key);
  if (!v) return fallback;
  double x;
  if (v->is_integer()) x = static_cast<double>(v->as_integer());
  else if (v->is_floating()) x = v->as_floating();
  else fail(*v, dotted(path, key), describe(range));
  if (!inRange(x, range)) fail(*v, dotted(path, key), describe(range));
  return x;
}

// An optional integer within [lo, hi].
int readInteger(const toml::value& table, const std::string& path, const std::string& key, int lo, int hi,
                int fallback) {
  const toml::value* v = find(table, key);
  if (!v) return fallback;
  if (!v->is_integer() || v->as_integer() < lo || v->as_integer() > hi)
    fail(*v, dotted(path, key), "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return static_cast<int>(v->as_integer());
}

// An optional boolean.
bool readBool(const toml::value& table, const std::string& path, const std::string& key, bool fallback) {
  const toml::value* v = find(table, key);
  if (!v) return fallback;
  if (!v->is_boolean()) fail(*v, dotted(path, key), "true or false");
  return v->as_boolean();
}

// An optional string from a fixed set.
std::string readChoice(const toml::value& table, const std::string& path, const std::string& key,
                       const std::vector<std::string_view>& choices, const std::string& fallback) {
  const toml::value* v = find(table, key);
  if (!v) return fallback;
  std::string expected;
  for (std::string_view c : choices) expected += (expected.empty() ? "one of \"" : ", \"") + std::string(c) + "\"";
  if (!v->is_string() || std::find(choices.begin(), choices.end(), v->as_string().str) == choices.end())
    fail(*v, dotted(path, key), expected);
  return v->as_string().str;
}

// An optional string or array of strings.
std::vector<std::string> readStrings(const toml::value& table, const std::string& path, const std::string& key) {
  const toml::value* v = find(table, key);
  if (!v) return {};
  if (v->is_string()) return {v->as_string().str};
  if (!v->is_array()) fail(*v, dotted(path, key), "a string or an array of strings");
  std::vector<std::string> out;
  for (const toml::value& item : v->as_array()) {
    if (!item.is_string()) fail(item, dotted(path, key), "a string or an array of strings");
    out.push_back(item.as_string().str);
  }
  return out;
}

// A required code.
int readCode(const toml::value& table, const std::string& path, const std::string& key, const CodeSpec& spec) {
  const toml::value* v = find(table, key);
  if (!v) throw MappingError(where(table) + ": table '" + path + "' lacks key '" + key + "' (" + spec.expected + ")");
  return toCode(*v, dotted(path, key), spec);
}

// An optional code or array of codes.
std::vector<int> readCodes(const toml::value& table, const std::string& path, const std::string& key,
                           const CodeSpec& spec) {
  const toml::value* v = find(table, key);
  if (!v) return {};
  if (!v->is_array()) return {toCode(*v, dotted(path, key), spec)};
  std::vector<int> out;
  for (const toml::value& item : v->as_array()) out.push_back(toCode(item, dotted(path, key), spec));
  return out;
}

}  // namespace bdfcar::input::fields
