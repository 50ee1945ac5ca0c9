#include "tyre/tir_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

#include "config/input_files.h"
#include "config/line_reader.h"

namespace bdfcar::tyre {

namespace {

// A .tir is a few hundred short lines; the limits only keep a wrong file cheap.
constexpr config::LineLimits kTirLines{1u << 20, 4096, 100'000};

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// One line into the entries (section tracking in `section`).
void parseLine(std::string text, int line, const std::string& path, std::string& section,
               std::vector<TirFile::Entry>& entries, std::map<std::string, int>& sections) {
  if (!text.empty() && text.back() == '\r') text.pop_back();
  const std::string t = trim(text);
  if (t.empty() || t[0] == '!' || t[0] == '$') return;
  if (t[0] == '[') {
    const auto close = t.find(']');
    if (close == std::string::npos || close == 1)
      throw TirError(path + ":" + std::to_string(line) + ": expected a section name in brackets, got '" + t + "'");
    section = upper(trim(t.substr(1, close - 1)));
    if (sections.count(section))
      throw TirError(path + ":" + std::to_string(line) + ": section [" + section + "] appears twice (first at line " +
                     std::to_string(sections[section]) + ")");
    sections[section] = line;
    return;
  }
  const auto eq = t.find('=');
  if (eq == std::string::npos) return;  // a table row or a table header inside a section: kept out of the keys
  if (section.empty())
    throw TirError(path + ":" + std::to_string(line) + ": '" + t + "' comes before any [SECTION]");
  TirFile::Entry e;
  e.section = section;
  e.key = upper(trim(t.substr(0, eq)));
  e.line = line;
  std::string value = trim(t.substr(eq + 1));
  if (!value.empty() && value[0] == '\'') {
    const auto end = value.find('\'', 1);
    if (end == std::string::npos)
      throw TirError(path + ":" + std::to_string(line) + ": key '" + e.key + "': a quoted value without its closing quote");
    e.value = value.substr(1, end - 1);
    e.quoted = true;
  } else {
    e.value = trim(value.substr(0, value.find('$')));  // a trailing $ comment
  }
  if (e.key.empty() || e.key.find_first_of(" \t") != std::string::npos)
    throw TirError(path + ":" + std::to_string(line) + ": expected KEY = value, got '" + t + "'");
  entries.push_back(std::move(e));
}

}  // namespace

TirFile TirFile::parse(const std::string& text, const std::string& path) {
  TirFile f;
  f.path_ = path;
  std::string section, line;
  std::istringstream in(text);
  for (int n = 1; std::getline(in, line); ++n) parseLine(line, n, path, section, f.entries_, f.sections_);
  for (std::size_t i = 0; i < f.entries_.size(); ++i) {
    const Entry& e = f.entries_[i];
    const auto [it, fresh] = f.index_.emplace(e.section + "/" + e.key, i);
    if (!fresh)
      throw TirError(path + ":" + std::to_string(e.line) + ": key '" + e.key + "' appears twice in [" + e.section +
                     "] (first at line " + std::to_string(f.entries_[it->second].line) + ")");
  }
  return f;
}

TirFile TirFile::read(const std::string& path) {
  std::string text, line;
  try {
    config::LineReader in(path, "tyre property file", kTirLines);
    while (in.next(line)) text += line + "\n";
  } catch (const TirError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw TirError(e.what());
  }
  config::noteInputFile(path);
  return parse(text, path);
}

bool TirFile::hasSection(const std::string& section) const { return sections_.count(section) > 0; }

const TirFile::Entry* TirFile::find(const std::string& section, const std::string& key) const {
  const auto it = index_.find(section + "/" + key);
  return it == index_.end() ? nullptr : &entries_[it->second];
}

void TirFile::fail(const Entry& e, const std::string& what) const {
  throw TirError(path_ + ":" + std::to_string(e.line) + ": key '" + e.key + "' in [" + e.section + "]: " + what);
}

void TirFile::fail(const std::string& section, const std::string& key, const std::string& what) const {
  const auto s = sections_.find(section);
  throw TirError(path_ + ":" + std::to_string(s == sections_.end() ? 0 : s->second) + ": key '" + key + "' in [" +
                 section + "]: " + what);
}

double TirFile::number(const std::string& section, const std::string& key) const {
  const Entry* e = find(section, key);
  if (!e) fail(section, key, hasSection(section) ? "missing (required)" : "missing, and so is its section");
  double x = 0;
  const char* b = e->value.data();
  const char* end = b + e->value.size();
  if (b != end && *b == '+') ++b;  // from_chars takes no '+'
  const auto [p, ec] = std::from_chars(b, end, x);
  if (e->quoted || ec != std::errc() || p != end || !std::isfinite(x))
    fail(*e, "expected a finite number, got '" + e->value + "'");
  return x;
}

double TirFile::number(const std::string& section, const std::string& key, double fallback) const {
  return find(section, key) ? number(section, key) : fallback;
}

std::string TirFile::word(const std::string& section, const std::string& key, const std::string& fallback) const {
  const Entry* e = find(section, key);
  return e ? upper(e->value) : fallback;
}

double TirFile::unitFactor(const std::string& dimension) const {
  const Entry* e = find("UNITS", dimension);
  if (!e) return 1.0;
  static const std::map<std::string, std::map<std::string, double>> kUnits{
      {"LENGTH", {{"METER", 1}, {"METRE", 1}, {"M", 1}, {"MM", 1e-3}, {"MILLIMETER", 1e-3}, {"CM", 1e-2},
                  {"CENTIMETER", 1e-2}, {"KM", 1e3}, {"INCH", 0.0254}, {"FOOT", 0.3048}}},
      {"FORCE", {{"NEWTON", 1}, {"N", 1}, {"KN", 1e3}, {"KILO_NEWTON", 1e3}, {"POUND_FORCE", 4.4482216152605}}},
      {"MASS", {{"KG", 1}, {"KILOGRAM", 1}, {"GRAM", 1e-3}, {"G", 1e-3}, {"TONNE", 1e3}, {"POUND_MASS", 0.45359237}}},
      {"TIME", {{"SECOND", 1}, {"SEC", 1}, {"S", 1}, {"MILLISECOND", 1e-3}, {"MS", 1e-3}, {"MINUTE", 60}}},
      {"ANGLE", {{"RADIAN", 1}, {"RADIANS", 1}, {"RAD", 1}}},  // the coefficients are per radian: no other
  };
  const auto& table = kUnits.at(dimension);
  const auto it = table.find(upper(e->value));
  if (it == table.end()) {
    std::string known;
    for (const auto& [name, factor] : table) known += (known.empty() ? "" : ", ") + name;
    fail(*e, "unknown unit '" + e->value + "' (expected one of " + known + ")");
  }
  return it->second;
}

}  // namespace bdfcar::tyre
