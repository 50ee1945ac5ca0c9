#include "config/toml_reader.h"

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

const toml::value& V(const void* p) { return *static_cast<const toml::value*>(p); }

int lineOf(const toml::value& v) {
  const auto loc = v.location();
  return static_cast<int>(loc.line());
}

std::string describe(const toml::value& v) {
  switch (v.type()) {
    case toml::value_t::boolean: return "a boolean";
    case toml::value_t::integer: return "an integer";
    case toml::value_t::floating: return "a number";
    case toml::value_t::string: return "a string";
    case toml::value_t::array: return "an array";
    case toml::value_t::table: return "a table";
    default: return "a date/time";
  }
}

}  // namespace

Table::Table(std::shared_ptr<const TomlDocument> doc, const void* value, std::string context)
    : doc_(std::move(doc)), value_(value), context_(std::move(context)), used_(std::make_shared<std::set<std::string>>()) {}

const std::string& Table::file() const { return doc_->path; }

int Table::line(const std::string& key) const {
  if (!key.empty())
    if (const void* v = find(key)) return lineOf(V(v));
  return lineOf(V(value_));
}

void Table::failAt(const void* value, const std::string& message) const {
  const int ln = value ? lineOf(V(value)) : lineOf(V(value_));
  std::ostringstream os;
  os << doc_->path << ":" << ln << ": " << message;
  throw ConfigError(os.str());
}

void Table::fail(const std::string& message, const std::string& key) const {
  const void* at = key.empty() ? nullptr : find(key);
  const std::string where = context_.empty() ? "" : "in [" + context_ + "] ";
  failAt(at, where + (key.empty() ? "" : "key '" + key + "': ") + message);
}

void Table::require(bool ok, const std::string& key, const std::string& expectation) const {
  if (!ok) fail("expected " + expectation, key);
}

const void* Table::find(const std::string& key) const {
  const toml::value& t = V(value_);
  if (!t.is_table()) return nullptr;
  const auto& tab = t.as_table();
  const auto it = tab.find(key);
  return it == tab.end() ? nullptr : &it->second;
}

bool Table::has(const std::string& key) const { return find(key) != nullptr; }
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
  if (!v) {
    const std::string where = context_.empty() ? "" : " in [" + context_ + "]";
    failAt(nullptr, "missing key '" + key + "'" + where + ": expected " + expectation);
  }
  used_->insert(key);
  return v;
}

namespace {

// A number, or a quantity string "<number> <unit>" of dimension d.
bool toQuantity(const toml::value& v, Dimension d, double& out, std::string& why) {
  if (v.is_floating()) {
    out = v.as_floating();
    return true;
  }
  if (v.is_integer()) {
    out = static_cast<double>(v.as_integer());
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

}  // namespace

double Table::number(const std::string& key, Dimension d) {
  const std::string exp = quantityExpectation(d);
  const void* v = get(key, exp);
  double x;
  std::string why;
  if (!toQuantity(V(v), d, x, why)) fail("expected " + exp + ", " + why, key);
  if (!std::isfinite(x)) fail("expected a finite value", key);
  return x;
}

double Table::number(const std::string& key, Dimension d, double fallback) {
  return has(key) ? number(key, d) : fallback;
}

std::string Table::string(const std::string& key) {
  const void* v = get(key, "a string");
  if (!V(v).is_string()) fail("expected a string, got " + describe(V(v)), key);
  return V(v).as_string().str;
}

std::string Table::string(const std::string& key, const std::string& fallback) {
  return has(key) ? string(key) : fallback;
}

bool Table::boolean(const std::string& key) {
  const void* v = get(key, "true or false");
  if (!V(v).is_boolean()) fail("expected true or false, got " + describe(V(v)), key);
  return V(v).as_boolean();
}

bool Table::boolean(const std::string& key, bool fallback) { return has(key) ? boolean(key) : fallback; }

long Table::integer(const std::string& key) {
  const void* v = get(key, "an integer");
  if (!V(v).is_integer()) fail("expected an integer, got " + describe(V(v)), key);
  return static_cast<long>(V(v).as_integer());
}

long Table::integer(const std::string& key, long fallback) { return has(key) ? integer(key) : fallback; }

std::vector<double> Table::numbers(const std::string& key, Dimension d) {
  const std::string exp = "an array of " + quantityExpectation(d).substr(2) + "s";
  const void* v = get(key, exp);
  if (!V(v).is_array()) fail("expected " + exp + ", got " + describe(V(v)), key);
  std::vector<double> out;
  for (const auto& e : V(v).as_array()) {
    double x;
    std::string why;
    if (!toQuantity(e, d, x, why)) failAt(&e, "key '" + key + "': expected " + exp + ", element " + why);
    out.push_back(x);
  }
  return out;
}

std::vector<std::string> Table::strings(const std::string& key) {
  const void* v = get(key, "an array of strings");
  if (!V(v).is_array()) fail("expected an array of strings, got " + describe(V(v)), key);
  std::vector<std::string> out;
  for (const auto& e : V(v).as_array()) {
    if (!e.is_string()) failAt(&e, "key '" + key + "': expected an array of strings, element is " + describe(e));
    out.push_back(e.as_string().str);
  }
  return out;
}

Eigen::Vector3d Table::vector3(const std::string& key, Dimension d) {
  const std::vector<double> x = numbers(key, d);
  if (x.size() != 3) fail("expected 3 components [x, y, z], got " + std::to_string(x.size()), key);
  return Eigen::Vector3d(x[0], x[1], x[2]);
}

Table Table::table(const std::string& key) {
  const void* v = get(key, "a table");
  if (!V(v).is_table()) fail("expected a table, got " + describe(V(v)), key);
  return Table(doc_, v, context_.empty() ? key : context_ + "." + key);
}

std::optional<Table> Table::optionalTable(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return table(key);
}

std::vector<Table> Table::tables(const std::string& key) {
  const void* v = get(key, "an array of tables ([[" + key + "]])");
  if (!V(v).is_array()) fail("expected an array of tables, got " + describe(V(v)), key);
  std::vector<Table> out;
  int i = 0;
  for (const auto& e : V(v).as_array()) {
    if (!e.is_table()) failAt(&e, "key '" + key + "': expected tables, got " + describe(e));
    out.emplace_back(doc_, &e, key + "[" + std::to_string(i++) + "]");
  }
  return out;
}

std::vector<Table> Table::optionalTables(const std::string& key) {
  if (!has(key)) return {};
  return tables(key);
}

void Table::finish() const {
  for (const auto& [k, v] : V(value_).as_table())
    if (!used_->count(k)) {
      const std::string where = context_.empty() ? "" : " in [" + context_ + "]";
      failAt(&v, "unknown key '" + k + "'" + where);
    }
}

Table parseTomlFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path + ":0: cannot open the file");
  auto doc = std::make_shared<TomlDocument>();
  doc->path = path;
  try {
    doc->root = toml::parse(in, path);
  } catch (const toml::syntax_error& e) {
    const auto& loc = e.location();
    std::string msg = e.what();
    // toml11 prefixes "[error] " and adds an excerpt; keep its first line.
    if (msg.rfind("[error] ", 0) == 0) msg = msg.substr(8);
    const auto nl = msg.find('\n');
    if (nl != std::string::npos) msg = msg.substr(0, nl);
    throw ConfigError(path + ":" + std::to_string(loc.line()) + ": TOML syntax error: " + msg);
  }
  return Table(doc, &doc->root, "");
}

}  // namespace bdfcar::config
