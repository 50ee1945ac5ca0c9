#include "config/toml_reader.h"
#include "config/input_files.h"
#include "config/file_kind.h"

#include <algorithm>
#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <toml.hpp>

namespace bdfcar::config {

class TomlDocument {
 public:
  std::string path;
  toml::value root;
};

namespace {

// Files whose long lines the reader split before parsing (prescan):
// for each, the line of the file each parsed line came from, so that
// messages name the file's own lines. Loaders may run on several threads.
std::mutex splitMutex;
std::map<std::string, std::shared_ptr<const std::vector<int>>> splitLines;
std::atomic<bool> anySplit{false};

int originalLine(const std::string& file, int line) {
  if (!anySplit.load(std::memory_order_relaxed)) return line;
  std::lock_guard lock(splitMutex);
  const auto it = splitLines.find(file);
  if (it == splitLines.end() || line < 1 || static_cast<std::size_t>(line) > it->second->size()) return line;
  return (*it->second)[static_cast<std::size_t>(line - 1)];
}

const toml::value& V(const void* p) { return *static_cast<const toml::value*>(p); }

int lineOf(const toml::value& v) {
  const auto loc = v.location();
  return originalLine(loc.file_name(), static_cast<int>(loc.line()));
}

// Values parsed from a --set option carry its text as their file name.
constexpr std::string_view kSettingPrefix = "--set ";
bool fromSetting(const std::string& file) { return file.rfind(kSettingPrefix, 0) == 0; }

// What a value is, for "got ..." in messages: scalars by value (what the
// reader typed), arrays by size, the rest by type.
std::string describe(const toml::value& v) {
  switch (v.type()) {
    case toml::value_t::boolean: return v.as_boolean() ? "true" : "false";
    case toml::value_t::integer: return std::to_string(v.as_integer());
    case toml::value_t::floating: return formatNumber(v.as_floating());
    case toml::value_t::string: return "\"" + v.as_string().str + "\"";
    case toml::value_t::array: {
      const std::size_t n = v.as_array().size();
      return n == 0 ? "an empty array" : "an array of " + std::to_string(n) + (n == 1 ? " element" : " elements");
    }
    case toml::value_t::table: return "a table";
    default: return "a date/time";
  }
}

bool isNumber(const toml::value& v) { return v.is_integer() || v.is_floating(); }
double asNumber(const toml::value& v) {
  return v.is_integer() ? static_cast<double>(v.as_integer()) : v.as_floating();
}

// "one of \"a\", \"b\"" and "a, b" for messages.
std::string listed(const std::vector<std::string_view>& words, bool quoted) {
  std::string out;
  for (std::string_view w : words) {
    if (!out.empty()) out += ", ";
    out += quoted ? "\"" + std::string(w) + "\"" : std::string(w);
  }
  return out;
}

}  // namespace

Table::Table(std::shared_ptr<const TomlDocument> doc, const void* value, std::string context)
    : doc_(std::move(doc)), value_(value), context_(std::move(context)), used_(std::make_shared<std::set<std::string>>()) {}

const std::string& Table::file() const { return doc_->path; }

std::string Table::folderOf(const std::string& key) const {
  const void* v = find(key);
  const std::string file = v ? V(v).location().file_name() : doc_->path;
  if (fromSetting(file)) return "";
  if (file.empty() || file == "unknown file") return std::filesystem::path(doc_->path).parent_path().string();
  return std::filesystem::path(file).parent_path().string();
}

std::string Table::dotted(const std::string& key) const { return context_.empty() ? key : context_ + "." + key; }

int Table::line(const std::string& key) const {
  if (!key.empty())
    if (const void* v = find(key)) return lineOf(V(v));
  return lineOf(V(value_));
}

std::string Table::sourceOf(const std::string& key) const {
  const void* v = key.empty() ? nullptr : find(key);
  std::string f = V(v ? v : value_).location().file_name();
  if (f.empty() || f == "unknown file") f = doc_->path;
  return f;
}

// "file:line: message", where the file is the one the value was written in
// (an included file, or a --set option, which has no line).
void Table::failAt(const void* value, const std::string& message) const {
  const toml::value& at = value ? V(value) : V(value_);
  std::string file = at.location().file_name();
  if (file.empty() || file == "unknown file") file = doc_->path;
  std::ostringstream os;
  if (fromSetting(file))
    os << file << ": " << message;
  else
    os << file << ":" << lineOf(at) << ": " << message;
  throw ConfigError(os.str());
}

void Table::failValue(const void* value, const std::string& key, const std::string& expectation) const {
  failAt(value, "key '" + dotted(key) + "': expected " + expectation + ", got " + describe(V(value)));
}

void Table::fail(const std::string& message, const std::string& key) const {
  if (!key.empty()) failAt(find(key), "key '" + dotted(key) + "': " + message);
  failAt(nullptr, (context_.empty() ? "" : "in [" + context_ + "] ") + message);
}

void Table::require(bool ok, const std::string& key, const std::string& expectation) const {
  if (!ok) fail("expected " + expectation, key);
}

void Table::reject(const std::string& key, const std::string& expectation, int element) const {
  const void* v = find(key);
  if (!v) failAt(nullptr, "missing key '" + dotted(key) + "': expected " + expectation);
  if (element >= 0 && V(v).is_array() && static_cast<std::size_t>(element) < V(v).as_array().size())
    v = &V(v).as_array()[static_cast<std::size_t>(element)];
  failValue(v, key, expectation);
}

namespace {
std::set<std::pair<std::string, std::string>>* keyLog = nullptr;

// "bodies[3].joint" -> "bodies[].joint"
std::string withoutIndices(const std::string& dotted) {
  std::string out;
  for (std::size_t i = 0; i < dotted.size(); ++i) {
    out += dotted[i];
    if (dotted[i] == '[') {
      while (i + 1 < dotted.size() && dotted[i + 1] != ']') ++i;
    }
  }
  return out;
}
}  // namespace

void startKeyLog() {
  delete keyLog;
  keyLog = new std::set<std::pair<std::string, std::string>>();
}

std::set<std::pair<std::string, std::string>> stopKeyLog() {
  std::set<std::pair<std::string, std::string>> out;
  if (keyLog) out.swap(*keyLog);
  delete keyLog;
  keyLog = nullptr;
  return out;
}

const void* Table::find(const std::string& key) const {
  if (keyLog) keyLog->emplace(doc_->path, withoutIndices(dotted(key)));
  const toml::value& t = V(value_);
  if (!t.is_table()) return nullptr;
  const auto& tab = t.as_table();
  const auto it = tab.find(key);
  return it == tab.end() ? nullptr : &it->second;
}

bool Table::has(const std::string& key) const { return find(key) != nullptr; }

std::vector<std::string> Table::scalarTexts(const std::string& key) {
  const std::string exp = "an array of numbers, strings or booleans";
  const void* v = get(key, exp);
  if (!V(v).is_array() || V(v).as_array().empty()) failValue(v, key, "a non-empty " + exp.substr(3));
  std::vector<std::string> out;
  int i = 0;
  for (const toml::value& e : V(v).as_array()) {
    if (isNumber(e)) {
      if (!std::isfinite(asNumber(e))) reject(key, "finite numbers", i);
      char text[32];
      std::snprintf(text, sizeof text, "%.17g", e.is_integer() ? 0.0 : e.as_floating());
      out.push_back(e.is_integer() ? std::to_string(e.as_integer()) : std::string(text));
    } else if (e.is_string()) {
      out.push_back(toml::format(e));
    } else if (e.is_boolean()) {
      out.push_back(e.as_boolean() ? "true" : "false");
    } else {
      reject(key, exp, i);
    }
    ++i;
  }
  return out;
}
bool Table::isString(const std::string& key) const { const void* v = find(key); return v && V(v).is_string(); }
bool Table::isArray(const std::string& key) const { const void* v = find(key); return v && V(v).is_array(); }
bool Table::isTable(const std::string& key) const { const void* v = find(key); return v && V(v).is_table(); }

std::vector<std::string> Table::keys() const {
  std::vector<std::string> out;
  for (const auto& [k, v] : V(value_).as_table()) out.push_back(k);
  return out;
}

const void* Table::get(const std::string& key, const std::string& expectation) {
  const void* v = find(key);
  if (!v) failAt(nullptr, "missing key '" + dotted(key) + "': expected " + expectation);
  used_->insert(key);
  return v;
}

namespace {

// A number, or a quantity string "<number> <unit>" of dimension d.
bool toQuantity(const toml::value& v, Dimension d, double& out, std::string& why) {
  if (isNumber(v)) {
    out = asNumber(v);
    return true;
  }
  if (v.is_string()) {
    const auto q = parseQuantity(v.as_string().str, d, why);
    if (q) out = *q;
    return q.has_value();
  }
  why = "got " + describe(v);
  return false;
}

std::string quantityExpectation(Dimension d) {
  if (d == Dimension::None) return "a number";
  return std::string("a ") + dimensionName(d) + " (a number in " + siUnit(d) + ", or a string with a unit)";
}

std::string rangeExpectation(const Range& r) {
  const std::string interval = r.text();
  return interval.empty() ? "a finite number" : "a number " + interval;
}

std::string integerExpectation(long lo, long hi) {
  return "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
}

bool isIntegerIn(const toml::value& v, long lo, long hi) {
  return v.is_integer() && v.as_integer() >= lo && v.as_integer() <= hi;
}

}  // namespace

double Table::number(const std::string& key, Dimension d) {
  const std::string exp = quantityExpectation(d);
  const void* v = get(key, exp);
  double x;
  std::string why;
  if (!toQuantity(V(v), d, x, why)) fail("expected " + exp + ", " + why, key);
  if (!std::isfinite(x)) failValue(v, key, "a finite " + (d == Dimension::None ? std::string("number") : dimensionName(d)));
  return x;
}

double Table::number(const std::string& key, Dimension d, const Range& range) {
  const double x = number(key, d);
  if (!range.contains(x)) {
    const std::string unit = siUnit(d);
    const std::string name = dimensionName(d);
    const bool vowel = !name.empty() && std::string_view("aeiou").find(name.front()) != std::string_view::npos;
    const std::string what = d == Dimension::None ? "a number " : (vowel ? "an " : "a ") + name + " ";
    failValue(find(key), key, what + range.text() + (unit.empty() ? "" : " " + unit));
  }
  return x;
}

double Table::number(const std::string& key, Dimension d, const Range& range, double fallback) {
  return has(key) ? number(key, d, range) : fallback;
}

std::vector<double> Table::numbers(const std::string& key, Dimension d, const Range& range) {
  std::vector<double> out = numbers(key, d);
  for (std::size_t i = 0; i < out.size(); ++i)
    if (!range.contains(out[i])) {
      const std::string unit = siUnit(d);
      reject(key, "every element " + range.text() + (unit.empty() ? "" : " " + unit), static_cast<int>(i));
    }
  return out;
}

Eigen::Vector3d Table::vector3(const std::string& key, Dimension d, const Range& range) {
  const std::vector<double> x = numbers(key, d, range);
  if (x.size() != 3) fail("expected 3 components [x, y, z], got " + std::to_string(x.size()), key);
  return Eigen::Vector3d(x[0], x[1], x[2]);
}

double Table::number(const std::string& key, Dimension d, double fallback) {
  return has(key) ? number(key, d) : fallback;
}

// A string from a data file is printed (names in summaries, messages, the
// HUD) and used in file names: a control character (TOML lets one in as an
// escape such as \u001b) would reach the terminal as a command. Refused:
// C0 controls but tab, DEL, and the C1 controls (U+0080-U+009F, which some
// terminals obey too).
std::string Table::string(const std::string& key) {
  const void* v = get(key, "a string");
  if (!V(v).is_string()) failValue(v, key, "a string");
  const std::string& text = V(v).as_string().str;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    unsigned code = c;
    if (c == 0xC2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
        static_cast<unsigned char>(text[i + 1]) <= 0x9F)
      code = static_cast<unsigned char>(text[i + 1]);
    else if (!((c < 0x20 && c != '\t') || c == 0x7F))
      continue;
    char hex[16];
    std::snprintf(hex, sizeof hex, "U+%04X", code);
    failAt(v, "key '" + dotted(key) + "': expected text without control characters, got " + hex + " at byte " +
                  std::to_string(i + 1));
  }
  return text;
}

std::string Table::string(const std::string& key, const std::string& fallback) {
  return has(key) ? string(key) : fallback;
}

bool Table::boolean(const std::string& key) {
  const void* v = get(key, "true or false");
  if (!V(v).is_boolean()) failValue(v, key, "true or false");
  return V(v).as_boolean();
}

bool Table::boolean(const std::string& key, bool fallback) { return has(key) ? boolean(key) : fallback; }

long Table::integer(const std::string& key) {
  const void* v = get(key, "an integer");
  if (!V(v).is_integer()) failValue(v, key, "an integer");
  return static_cast<long>(V(v).as_integer());
}

long Table::integer(const std::string& key, long fallback) { return has(key) ? integer(key) : fallback; }

std::vector<double> Table::numbers(const std::string& key, Dimension d) {
  const std::string exp = "an array of " + quantityExpectation(d).substr(2) + "s";
  const void* v = get(key, exp);
  if (!V(v).is_array()) failValue(v, key, exp);
  std::vector<double> out;
  for (const auto& e : V(v).as_array()) {
    double x;
    std::string why;
    if (!toQuantity(e, d, x, why)) failAt(&e, "key '" + dotted(key) + "': expected " + exp + ", element " + why);
    // NaN and inf are never a measurement: refuse them where they are written.
    if (!std::isfinite(x)) failValue(&e, key, "finite numbers");
    out.push_back(x);
  }
  return out;
}

std::vector<std::string> Table::strings(const std::string& key) {
  const void* v = get(key, "an array of strings");
  if (!V(v).is_array()) failValue(v, key, "an array of strings");
  std::vector<std::string> out;
  for (const auto& e : V(v).as_array()) {
    if (!e.is_string()) failValue(&e, key, "an array of strings");
    out.push_back(e.as_string().str);
  }
  return out;
}

Eigen::Vector3d Table::vector3(const std::string& key, Dimension d) {
  const std::vector<double> x = numbers(key, d);
  if (x.size() != 3) fail("expected 3 components [x, y, z], got " + std::to_string(x.size()), key);
  return Eigen::Vector3d(x[0], x[1], x[2]);
}

Eigen::Vector3d Table::vector3(const std::string& key, Dimension d, const Eigen::Vector3d& fallback) {
  return has(key) ? vector3(key, d) : fallback;
}

Table Table::table(const std::string& key) {
  const void* v = get(key, "a table");
  if (!V(v).is_table()) failValue(v, key, "a table");
  return Table(doc_, v, dotted(key));
}

std::optional<Table> Table::optionalTable(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return table(key);
}

std::vector<Table> Table::tables(const std::string& key) {
  const std::string exp = "an array of tables ([[" + key + "]])";
  const void* v = get(key, exp);
  if (!V(v).is_array()) failValue(v, key, exp);
  std::vector<Table> out;
  int i = 0;
  for (const auto& e : V(v).as_array()) {
    if (!e.is_table()) failValue(&e, key, exp);
    out.emplace_back(doc_, &e, dotted(key) + "[" + std::to_string(i++) + "]");
  }
  return out;
}

std::vector<Table> Table::optionalTables(const std::string& key) {
  if (!has(key)) return {};
  return tables(key);
}

double Table::numberIn(const std::string& key, const Range& range) {
  const std::string exp = rangeExpectation(range);
  const void* v = get(key, exp);
  // NaN and inf are outside every range, even an unbounded one.
  if (!isNumber(V(v)) || !std::isfinite(asNumber(V(v))) || !range.contains(asNumber(V(v)))) failValue(v, key, exp);
  return asNumber(V(v));
}

double Table::numberIn(const std::string& key, const Range& range, double fallback) {
  return has(key) ? numberIn(key, range) : fallback;
}

long Table::integerIn(const std::string& key, long lo, long hi) {
  const std::string exp = integerExpectation(lo, hi);
  const void* v = get(key, exp);
  if (!isIntegerIn(V(v), lo, hi)) failValue(v, key, exp);
  return static_cast<long>(V(v).as_integer());
}

long Table::integerIn(const std::string& key, long lo, long hi, long fallback) {
  return has(key) ? integerIn(key, lo, hi) : fallback;
}

std::vector<long> Table::integersIn(const std::string& key, long lo, long hi) {
  if (!has(key)) return {};
  const std::string exp = integerExpectation(lo, hi) + " or an array of them";
  const void* v = get(key, exp);
  if (!V(v).is_array()) {
    if (!isIntegerIn(V(v), lo, hi)) failValue(v, key, exp);
    return {static_cast<long>(V(v).as_integer())};
  }
  std::vector<long> out;
  for (const auto& e : V(v).as_array()) {
    if (!isIntegerIn(e, lo, hi)) failValue(&e, key, exp);
    out.push_back(static_cast<long>(e.as_integer()));
  }
  return out;
}

std::string Table::choice(const std::string& key, const std::vector<std::string_view>& choices) {
  const std::string exp = "one of " + listed(choices, true);
  const void* v = get(key, exp);
  if (!V(v).is_string() || std::find(choices.begin(), choices.end(), V(v).as_string().str) == choices.end())
    failValue(v, key, exp);
  return V(v).as_string().str;
}

std::string Table::choice(const std::string& key, const std::vector<std::string_view>& choices,
                          const std::string& fallback) {
  return has(key) ? choice(key, choices) : fallback;
}

std::vector<std::string> Table::stringOrStrings(const std::string& key) {
  if (!has(key)) return {};
  const std::string exp = "a string or an array of strings";
  const void* v = get(key, exp);
  if (V(v).is_string()) return {V(v).as_string().str};
  if (!V(v).is_array()) failValue(v, key, exp);
  std::vector<std::string> out;
  for (const auto& e : V(v).as_array()) {
    if (!e.is_string()) failValue(&e, key, exp);
    out.push_back(e.as_string().str);
  }
  return out;
}

std::vector<std::vector<double>> Table::grid(const std::string& key, std::size_t minRows, std::size_t minColumns) {
  const std::string exp = "an array of at least " + std::to_string(minRows) + " rows, each an array of at least " +
                          std::to_string(minColumns) + " numbers";
  const void* v = get(key, exp);
  if (!V(v).is_array() || V(v).as_array().size() < minRows) failValue(v, key, exp);
  std::vector<std::vector<double>> rows;
  for (const auto& row : V(v).as_array()) {
    if (!row.is_array() || row.as_array().size() < minColumns) failValue(&row, key, exp);
    // Ragged rows are reported at the first one that differs from the first row.
    if (!rows.empty() && row.as_array().size() != rows.front().size())
      failValue(&row, key, "rows of " + std::to_string(rows.front().size()) + " numbers like the first");
    std::vector<double>& out = rows.emplace_back();
    for (const auto& e : row.as_array()) {
      if (!isNumber(e) || !std::isfinite(asNumber(e))) failValue(&e, key, "finite numbers in every row");
      out.push_back(asNumber(e));
    }
  }
  return rows;
}

// Reports the unknown key written first, so the message points at the first typo.
void Table::failFirstUnknown(const std::vector<std::string_view>& known, const std::string& suffix) const {
  // Sorted, looked up by halving: a table of 100,000 keys (all known) took
  // 10^10 comparisons by a linear search per key.
  std::vector<std::string_view> sorted = known;
  std::sort(sorted.begin(), sorted.end());
  const toml::value* first = nullptr;
  std::string firstKey;
  for (const auto& [k, v] : V(value_).as_table()) {
    if (std::binary_search(sorted.begin(), sorted.end(), std::string_view(k))) continue;
    const bool earlier = !first || lineOf(v) < lineOf(*first) || (lineOf(v) == lineOf(*first) && k < firstKey);
    if (earlier) first = &v, firstKey = k;
  }
  if (first) failAt(first, "unknown key '" + dotted(firstKey) + "'" + suffix);
}

void Table::finish() const {
  failFirstUnknown(std::vector<std::string_view>(used_->begin(), used_->end()), "");
}

void Table::rejectUnknownKeys(const std::vector<std::string_view>& known) const {
  if (keyLog)
    for (std::string_view k : known) keyLog->emplace(doc_->path, withoutIndices(dotted(std::string(k))));
  failFirstUnknown(known, "; expected one of: " + listed(known, false));
}

namespace {

// Arrays and inline tables nested deeper than this are refused before toml11
// sees them: its recursive descent parser would overflow the stack.
constexpr int kMaxNesting = 64;

// The whole content of `path` within the data-file cap (config/file_kind.h),
// read as a stream so that pipes (/dev/stdin, <(...)) work too: seeking to
// the end to learn the size (what toml11 does) fails on a pipe and, on a
// directory, asks for a 2^63-byte buffer.
std::string readWholeFile(const std::string& path) {
  std::string text;
  try {
    text = readDataFile(path, "TOML file");
  } catch (const std::runtime_error& e) {
    throw ConfigError(e.what());
  }
  noteInputFile(path);
  return text;
}

// A cursor over TOML text that counts lines, for the nesting scan.
struct Scan {
  const std::string& text;
  std::size_t i = 0;
  int line = 1;

  bool done() const { return i >= text.size(); }
  bool at(std::string_view s) const { return text.compare(i, s.size(), s) == 0; }
  void advance() {
    if (text[i] == '\n') ++line;
    ++i;
  }
  // Past a string opened by `quote` (", ', """ or '''); backslash escapes in
  // basic strings; a single-line string also ends at the end of its line.
  void skipString(std::string_view quote) {
    const bool multiLine = quote.size() == 3, basic = quote[0] == '"';
    i += quote.size();
    while (!done() && !at(quote) && (multiLine || text[i] != '\n')) {
      if (basic && text[i] == '\\' && i + 1 < text.size()) advance();
      advance();
    }
    if (at(quote)) i += quote.size();
  }
};

// toml11 looks at the whole line of every value it parses (for comments,
// even when they are discarded): a line of n values costs n^2 (100,000
// numbers on one line took over 30 s). A line longer than kSplitLine is
// broken after the commas of its arrays (a newline is whitespace there),
// and the lines map recorded, so that the cost is linear and messages still
// name the file's own lines. Refuses a file of more than kMaxValues values
// (commas in arrays and '=' outside strings and comments), and arrays or
// inline tables nested deeper than kMaxNesting, naming the limit and line.
// One scan for all three (brackets in strings and comments do not count).
constexpr std::size_t kSplitLine = 512;
constexpr std::size_t kMaxValues = std::size_t{1} << 21;  // 2,097,152

std::string prescan(const std::string& text, const std::string& path, std::vector<int>& lines) {
  lines.clear();
  std::size_t longest = 0, run = 0;
  for (char c : text) {
    run = c == '\n' ? 0 : run + 1;
    longest = std::max(longest, run);
  }
  Scan s{text};
  std::string out;
  const bool split = longest > kSplitLine;
  if (split) {
    out.reserve(text.size() + text.size() / 16);
    lines.push_back(1);
  }
  std::size_t lineLength = 0, values = 0;
  std::vector<char> open;
  auto copyTo = [&](std::size_t end) {  // the input up to `end`, lines mapped
    while (s.i < end) {
      const char c = text[s.i];
      s.advance();
      if (!split) continue;
      out += c;
      lineLength = c == '\n' ? 0 : lineLength + 1;
      if (c == '\n') lines.push_back(s.line);
    }
  };
  while (!s.done()) {
    const char c = text[s.i];
    const std::size_t start = s.i;
    if (c == '#') {
      std::size_t e = s.i;
      while (e < text.size() && text[e] != '\n') ++e;
      copyTo(e);
    } else if (s.at("\"\"\"") || s.at("'''") || c == '"' || c == '\'') {
      const std::string_view quote = s.at("\"\"\"") ? "\"\"\"" : s.at("'''") ? "'''" : c == '"' ? "\"" : "'";
      Scan probe{text, s.i, s.line};
      probe.skipString(quote);
      copyTo(probe.i);
    } else {
      if ((c == '[' || c == '{') && static_cast<int>(open.size()) >= kMaxNesting)
        throw ConfigError(path + ":" + std::to_string(s.line) + ": arrays or inline tables nested deeper than " +
                          std::to_string(kMaxNesting) + " levels");
      if (c == '[' || c == '{') open.push_back(c);
      if ((c == ']' || c == '}') && !open.empty()) open.pop_back();
      const bool inArray = !open.empty() && open.back() == '[';
      if ((c == ',' && inArray) || c == '=') ++values;
      if (values > kMaxValues)
        throw ConfigError(path + ":" + std::to_string(s.line) + ": more than " + std::to_string(kMaxValues) +
                          " values in one file (the limit of a data file; split the data over several files or "
                          "use a coarser table)");
      copyTo(start + 1);
      if (split && c == ',' && inArray && lineLength > kSplitLine) {
        out += '\n';
        lineLength = 0;
        lines.push_back(s.line);
      }
    }
  }
  return split ? out : std::string();
}

// TOML is UTF-8; toml11 reads past the end of its buffer on some invalid
// sequences inside strings (found by fuzzing: tests/data/bad/fuzz/), so
// text that is not UTF-8 is refused here, at the line of the first bad byte.
void checkUtf8(const std::string& text, const std::string& path) {
  int line = 1;
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') ++line;
    // RFC 3629: lead bytes C2-F4; the second byte's range excludes overlong
    // forms, surrogates (ED A0-BF) and code points above U+10FFFF (F4 90-,
    // F5-FF): toml11 decodes F6 9A 91 A5 past its buffer too (fuzz finding).
    const std::size_t n = c < 0x80 ? 1 : (c >= 0xc2 && c <= 0xdf) ? 2 : (c >= 0xe0 && c <= 0xef) ? 3 : (c >= 0xf0 && c <= 0xf4) ? 4 : 0;
    bool ok = n > 0 && i + n <= text.size();
    if (ok && n > 1) {
      const auto c1 = static_cast<unsigned char>(text[i + 1]);
      const unsigned char lo = c == 0xe0 ? 0xa0 : c == 0xf0 ? 0x90 : 0x80;
      const unsigned char hi = c == 0xed ? 0x9f : c == 0xf4 ? 0x8f : 0xbf;
      ok = c1 >= lo && c1 <= hi;
    }
    for (std::size_t k = 2; ok && k < n; ++k) ok = (static_cast<unsigned char>(text[i + k]) >> 6) == 0x2;
    if (!ok) throw ConfigError(path + ":" + std::to_string(line) + ": not UTF-8 text (byte " + std::to_string(c) +
                               " at offset " + std::to_string(i) + "): a TOML file must be UTF-8");
    i += n;
  }
}

// The whole document, or a ConfigError naming the line where the syntax breaks.
toml::value parseValue(const std::string& text, const std::string& path) {
  checkUtf8(text, path);
  auto lines = std::make_shared<std::vector<int>>();
  const std::string split = prescan(text, path, *lines);
  {
    std::lock_guard lock(splitMutex);
    if (split.empty()) {
      splitLines.erase(path);
    } else {
      splitLines[path] = lines;
      anySplit = true;
    }
  }
  try {
    std::istringstream in(split.empty() ? text : split);
    return toml::parse(in, path);
  } catch (const toml::exception& e) {
    const auto& loc = e.location();
    std::string msg = e.what();
    // toml11 prefixes "[error] " and adds an excerpt; keep its first line.
    if (msg.rfind("[error] ", 0) == 0) msg = msg.substr(8);
    const auto nl = msg.find('\n');
    if (nl != std::string::npos) msg = msg.substr(0, nl);
    throw ConfigError(path + ":" + std::to_string(originalLine(path, static_cast<int>(loc.line()))) +
                      ": TOML syntax error: " + msg);
  } catch (const std::exception& e) {  // e.g. std::bad_alloc, std::out_of_range from inside the parser
    throw ConfigError(path + ":0: TOML file could not be parsed (" + std::string(e.what()) + ")");
  }
}

Table tableOf(toml::value root, const std::string& path) {
  auto doc = std::make_shared<TomlDocument>();
  doc->path = path;
  doc->root = std::move(root);
  return Table(doc, &doc->root, "");
}

Table parseText(const std::string& text, const std::string& path) { return tableOf(parseValue(text, path), path); }

[[noreturn]] void failAtValue(const toml::value& v, const std::string& message) {
  throw ConfigError(v.location().file_name() + ":" + std::to_string(lineOf(v)) + ": " + message);
}

// Adds to `top` what `under` has and `top` does not, table by table.
void mergeUnder(toml::value& top, const toml::value& under) {
  if (!top.is_table() || !under.is_table()) return;
  toml::table& t = top.as_table();
  for (const auto& [key, value] : under.as_table()) {
    const auto it = t.find(key);
    if (it == t.end())
      t.emplace(key, value);
    else
      mergeUnder(it->second, value);
  }
}

constexpr std::size_t kMaxIncludeDepth = 8;

// A file with its includes merged under it; `chain` holds the files
// including it (to refuse cycles).
toml::value loadWithIncludes(const std::string& path, std::vector<std::string>& chain) {
  toml::value root = parseValue(readWholeFile(path), path);
  if (!root.is_table() || !root.as_table().count("include")) return root;
  const toml::value include = root.as_table().at("include");
  std::vector<std::string> names;
  const std::string expected = "key 'include': expected a file name or an array of file names, got ";
  if (include.is_string()) {
    names.push_back(include.as_string().str);
  } else if (include.is_array()) {
    for (const toml::value& n : include.as_array()) {
      if (!n.is_string()) failAtValue(include, expected + describe(n) + " in the array");
      names.push_back(n.as_string().str);
    }
  } else {
    failAtValue(include, expected + describe(include));
  }
  root.as_table().erase("include");
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  // The later of two includes wins: merge from the last.
  for (auto n = names.rbegin(); n != names.rend(); ++n) {
    if (n->empty()) failAtValue(include, "key 'include': expected a file name, got \"\"");
    const std::filesystem::path p = std::filesystem::path(*n).is_absolute() ? std::filesystem::path(*n)
                                                                           : (folder / *n).lexically_normal();
    if (const auto why = notARegularFile(p)) failAtValue(include, "key 'include': the file '" + p.string() + "' " + *why);
    std::error_code ec;
    const std::string canonical = std::filesystem::weakly_canonical(p, ec).string();
    if (std::find(chain.begin(), chain.end(), canonical) != chain.end())
      failAtValue(include, "key 'include': '" + p.string() + "' includes itself (through " +
                               std::to_string(chain.size()) + " files)");
    if (chain.size() >= kMaxIncludeDepth)
      failAtValue(include, "key 'include': includes nested deeper than " + std::to_string(kMaxIncludeDepth) + " files");
    chain.push_back(canonical);
    const toml::value under = loadWithIncludes(p.string(), chain);
    chain.pop_back();
    mergeUnder(root, under);
  }
  return root;
}

// "springs[2].damping" -> {"springs", 2, "damping"}: names and indices.
struct PathStep {
  std::string name;
  long index = -1;  // >= 0: an element of the array `name`
};

std::vector<PathStep> splitKeyPath(const Setting& s) {
  std::vector<PathStep> steps;
  std::string_view k = s.key;
  auto bad = [&](const std::string& why) -> std::vector<PathStep> {
    throw ConfigError(s.origin() + ": " + why + " (a key path is names joined by dots, with [N] for the N-th "
                                                "element of an array: springs[0].damping)");
  };
  while (!k.empty()) {
    const std::size_t end = k.find_first_of(".[");
    PathStep step{std::string(k.substr(0, end))};
    if (step.name.empty()) return bad("an empty name in the key '" + s.key + "'");
    k = end == std::string_view::npos ? std::string_view() : k.substr(end);
    if (!k.empty() && k.front() == '[') {
      const std::size_t close = k.find(']');
      if (close == std::string_view::npos) return bad("no ']' in the key '" + s.key + "'");
      const std::string digits(k.substr(1, close - 1));
      if (digits.empty() || digits.size() > 6 || digits.find_first_not_of("0123456789") != std::string::npos)
        return bad("'[" + digits + "]' is not an array index");
      step.index = std::stol(digits);
      k = k.substr(close + 1);
    }
    steps.push_back(step);
    if (!k.empty()) {
      if (k.front() != '.') return bad("expected '.' after ']' in the key '" + s.key + "'");
      k = k.substr(1);
      if (k.empty()) return bad("the key '" + s.key + "' ends with '.'");
    }
  }
  if (steps.empty()) return bad("no key");
  return steps;
}

// The setting's value: TOML when it parses as a value, a string otherwise.
toml::value settingValue(const Setting& s) {
  const std::string name = s.origin();
  try {
    checkUtf8(s.value, name);
    std::vector<int> lines;
    prescan(s.value, name, lines);
    std::istringstream in("value = " + s.value + "\n");
    toml::value doc = toml::parse(in, name);
    return doc.as_table().at("value");
  } catch (const ConfigError&) {
    throw;
  } catch (const std::exception&) {
    // Not a TOML value: the text itself, as a string (located at the option).
    std::istringstream in("value = " + toml::format(toml::value(s.value)) + "\n");
    return toml::parse(in, name).as_table().at("value");
  }
}

// An empty table whose location is the option: a key path naming a table
// the file lacks makes one, and a key in it the reader does not know is
// then reported at the option ("--set chassis.mass=1: unknown key
// 'chassis'"), not at the file's first line.
toml::value tableAtOption(const Setting& s) {
  std::istringstream in("value = {}\n");
  return toml::parse(in, s.origin()).as_table().at("value");
}

void applySetting(toml::value& root, const Setting& s) {
  const std::vector<PathStep> steps = splitKeyPath(s);
  toml::value* at = &root;
  std::string walked;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const PathStep& step = steps[i];
    const bool last = i + 1 == steps.size();
    if (!at->is_table())
      throw ConfigError(s.origin() + ": '" + walked + "' is " + describe(*at) + ", not a table with keys");
    toml::table& t = at->as_table();
    walked += (walked.empty() ? "" : ".") + step.name;
    if (step.index < 0) {
      if (last) {
        t[step.name] = settingValue(s);
        return;
      }
      at = &t[step.name];  // a new table when absent, located at the option (messages name it, not the file)
      if (at->is_uninitialized()) *at = tableAtOption(s);
      continue;
    }
    const auto it = t.find(step.name);
    if (it == t.end() || !it->second.is_array())
      throw ConfigError(s.origin() + ": '" + walked + "' is not an array in the file, so it has no element [" +
                        std::to_string(step.index) + "]");
    toml::array& a = it->second.as_array();
    if (static_cast<std::size_t>(step.index) >= a.size())
      throw ConfigError(s.origin() + ": '" + walked + "' has " + std::to_string(a.size()) + " elements, so no [" +
                        std::to_string(step.index) + "]");
    walked += "[" + std::to_string(step.index) + "]";
    if (last) {
      a[static_cast<std::size_t>(step.index)] = settingValue(s);
      return;
    }
    at = &a[static_cast<std::size_t>(step.index)];
  }
}

}  // namespace

Setting parseSetting(const std::string& keyEqualsValue) {
  const std::size_t eq = keyEqualsValue.find('=');
  if (eq == std::string::npos || eq == 0)
    throw ConfigError("--set " + keyEqualsValue + ": expected KEY=VALUE (e.g. --set start.speed=\"80 km/h\")");
  Setting s{keyEqualsValue.substr(0, eq), keyEqualsValue.substr(eq + 1), ""};
  // Spaces around '=' are the shell's quoting, not part of the key.
  while (!s.key.empty() && s.key.back() == ' ') s.key.pop_back();
  while (!s.value.empty() && s.value.front() == ' ') s.value.erase(0, 1);
  if (s.key.empty()) throw ConfigError("--set " + keyEqualsValue + ": expected KEY=VALUE, got no key");
  splitKeyPath(s);  // checks the key's form now
  return s;
}

std::optional<Setting> underPrefix(const Setting& s, const std::string& prefix) {
  if (s.key.size() <= prefix.size() || s.key.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
  return Setting{s.key.substr(prefix.size()), s.value, s.key + "=" + s.value};
}

Table parseTomlFile(const std::string& path, const std::vector<Setting>& settings) {
  std::error_code ec;
  std::vector<std::string> chain{std::filesystem::weakly_canonical(path, ec).string()};
  toml::value root = loadWithIncludes(path, chain);
  for (const Setting& s : settings) applySetting(root, s);
  return tableOf(std::move(root), path);
}

Table parseTomlText(const std::string& text, const std::string& fileName) { return parseText(text, fileName); }

}  // namespace bdfcar::config
