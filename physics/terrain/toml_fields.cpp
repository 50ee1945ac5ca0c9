// Reading TOML values with messages that say where and what was expected.
#include "terrain/toml_fields.h"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "terrain/terrain_file.h"

namespace bdfcar::terrain::toml_fields {

namespace {

// "a string", "an array", ... for "got ..." in messages.
std::string typeName(const Value& v) {
  switch (v.type()) {
    case toml::value_t::boolean: return "a boolean";
    case toml::value_t::integer: return "an integer";
    case toml::value_t::floating: return "a float";
    case toml::value_t::string: return "a string";
    case toml::value_t::array: return "an array";
    case toml::value_t::table: return "a table";
    case toml::value_t::empty: return "nothing";
    default: return "a date/time";
  }
}

std::string formatNumber(double x) {
  std::ostringstream os;
  os << x;
  return os.str();
}

// "in (0, 2]", "> 0", "<= 5", or "finite" for an unbounded range.
std::string describe(const Range& r) {
  const bool finiteLo = std::isfinite(r.lo), finiteHi = std::isfinite(r.hi);
  if (finiteLo && finiteHi)
    return "in " + std::string(r.loOpen ? "(" : "[") + formatNumber(r.lo) + ", " + formatNumber(r.hi) + (r.hiOpen ? ")" : "]");
  if (finiteLo) return (r.loOpen ? "> " : ">= ") + formatNumber(r.lo);
  if (finiteHi) return (r.hiOpen ? "< " : "<= ") + formatNumber(r.hi);
  return "finite";
}

bool inRange(const Range& r, double x) {
  return (r.loOpen ? x > r.lo : x >= r.lo) && (r.hiOpen ? x < r.hi : x <= r.hi);
}

// A missing required key: the top level has no useful line, a table has its header's.
[[noreturn]] void failMissing(const Table& t, const std::string& key, const std::string& expected) {
  const std::string message = "missing key '" + keyName(t, key) + "' (" + expected + ")";
  if (t.name.empty()) throw TerrainFileError(t.value.location().file_name() + ": " + message);
  fail(t.value, message, "in this table");
}

const Value* find(const Table& t, const std::string& key) {
  const auto& table = t.value.as_table();
  const auto it = table.find(key);
  return it == table.end() ? nullptr : &it->second;
}

}  // namespace

// Parses with toml11; its own messages already carry file and line.
Value parseFile(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw TerrainFileError(path + ": terrain file not found");
  try {
    return toml::parse<toml::discard_comments, std::map, std::vector>(path);
  } catch (const toml::syntax_error& e) {
    throw TerrainFileError(path + ": TOML syntax error\n" + e.what());
  } catch (const std::exception& e) {
    throw TerrainFileError(path + ": " + e.what());
  }
}

// Throws the message prefixed with file:line and followed by the offending line.
void fail(const Value& at, const std::string& message, const std::string& mark) {
  const toml::source_location loc = at.location();
  const std::string head = loc.file_name() + ":" + std::to_string(loc.line()) + ": " + message;
  throw TerrainFileError(toml::format_error(head, at, mark));
}

std::string keyName(const Table& t, const std::string& key) { return t.name.empty() ? key : t.name + "." + key; }

// The first (alphabetical) key not in `known` is an error at its line.
void rejectUnknownKeys(const Table& t, const std::vector<std::string_view>& known) {
  for (const auto& [key, value] : t.value.as_table()) {
    bool ok = false;
    for (std::string_view k : known) ok = ok || k == key;
    if (ok) continue;
    std::string list;
    for (std::string_view k : known) list += (list.empty() ? "" : ", ") + std::string(k);
    fail(value, "unknown key '" + keyName(t, key) + "' (expected one of: " + list + ")");
  }
}

bool has(const Table& t, const std::string& key) { return find(t, key) != nullptr; }

// A number checked against its range.
double number(const Table& t, const std::string& key, const Range& range, std::optional<double> fallback) {
  const Value* v = find(t, key);
  if (!v) {
    if (fallback) return *fallback;
    failMissing(t, key, "a number " + describe(range));
  }
  const double x = asNumber(*v, keyName(t, key));
  if (!inRange(range, x)) fail(*v, keyName(t, key) + " must be " + describe(range) + ", got " + formatNumber(x));
  return x;
}

// An integer checked against [lo, hi].
long long integer(const Table& t, const std::string& key, long long lo, long long hi, std::optional<long long> fallback) {
  const std::string expected = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  const Value* v = find(t, key);
  if (!v) {
    if (fallback) return *fallback;
    failMissing(t, key, expected);
  }
  if (!v->is_integer()) fail(*v, keyName(t, key) + " must be " + expected + ", got " + typeName(*v));
  const long long x = v->as_integer();
  if (x < lo || x > hi) fail(*v, keyName(t, key) + " must be " + expected + ", got " + std::to_string(x));
  return x;
}

// A string value.
std::string text(const Table& t, const std::string& key, std::optional<std::string> fallback) {
  const Value* v = find(t, key);
  if (!v) {
    if (fallback) return *fallback;
    failMissing(t, key, "a string");
  }
  if (!v->is_string()) fail(*v, keyName(t, key) + " must be a string, got " + typeName(*v));
  return v->as_string().str;
}

// A string from a fixed set of words.
std::string choice(const Table& t, const std::string& key, std::initializer_list<std::string_view> choices,
                   std::optional<std::string> fallback) {
  std::string list;
  for (std::string_view c : choices) list += (list.empty() ? "\"" : ", \"") + std::string(c) + "\"";
  if (!has(t, key) && !fallback) failMissing(t, key, "one of " + list);
  const std::string s = text(t, key, fallback);
  for (std::string_view c : choices)
    if (c == s) return s;
  fail(*find(t, key), keyName(t, key) + " must be one of " + list + ", got \"" + s + "\"");
}

// [x, y, z] of finite numbers.
Eigen::Vector3d vector3(const Table& t, const std::string& key, std::optional<Eigen::Vector3d> fallback) {
  const Value* v = find(t, key);
  if (!v) {
    if (fallback) return *fallback;
    failMissing(t, key, "an array of 3 numbers [x, y, z]");
  }
  if (!v->is_array() || v->as_array().size() != 3)
    fail(*v, keyName(t, key) + " must be an array of 3 numbers [x, y, z], got " +
                 (v->is_array() ? std::to_string(v->as_array().size()) + " elements" : typeName(*v)));
  Eigen::Vector3d out;
  for (int i = 0; i < 3; ++i) out[i] = asNumber(v->as_array()[i], keyName(t, key) + "[" + std::to_string(i) + "]");
  return out;
}

// A nested table that must be present.
Table subtable(const Table& t, const std::string& key) {
  const Value* v = find(t, key);
  if (!v) failMissing(t, key, "a table [" + keyName(t, key) + "]");
  if (!v->is_table()) fail(*v, keyName(t, key) + " must be a table, got " + typeName(*v));
  return {*v, keyName(t, key)};
}

// The entries of [[key]], each named key[i].
std::vector<Table> tableArray(const Table& t, const std::string& key) {
  std::vector<Table> out;
  const Value* v = find(t, key);
  if (!v) return out;
  if (!v->is_array()) fail(*v, keyName(t, key) + " must be an array of tables [[" + key + "]], got " + typeName(*v));
  const auto& array = v->as_array();
  for (std::size_t i = 0; i < array.size(); ++i) {
    const std::string name = keyName(t, key) + "[" + std::to_string(i) + "]";
    if (!array[i].is_table()) fail(array[i], name + " must be a table, got " + typeName(array[i]));
    out.push_back({array[i], name});
  }
  return out;
}

// A finite number, whether TOML wrote it as an integer or a float.
double asNumber(const Value& v, const std::string& what) {
  if (v.is_integer()) return static_cast<double>(v.as_integer());
  if (!v.is_floating()) fail(v, what + " must be a number, got " + typeName(v));
  if (!std::isfinite(v.as_floating())) fail(v, what + " must be a finite number");
  return v.as_floating();
}

// Cross-field checks (x_max > x_min, ...) reported at the second key.
void require(bool ok, const Table& t, const std::string& key, const std::string& expected) {
  if (ok) return;
  const Value* v = find(t, key);
  if (!v) v = &t.value;
  fail(*v, keyName(t, key) + " " + expected);
}

}  // namespace bdfcar::terrain::toml_fields
