// Typed, range-checked reading of TOML tables for the terrain loaders. Every
// failure throws TerrainFileError naming the file, the line, the key and what
// was expected. Only the loaders include this header (it pulls in toml11).
#pragma once

#include <Eigen/Core>
#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <toml.hpp>
#include <vector>

namespace bdfcar::terrain::toml_fields {

// Tables keep their keys sorted, so "the first unknown key" is well defined.
using Value = toml::basic_value<toml::discard_comments, std::map, std::vector>;

// A table being read and its dotted name for messages ("" at the top level).
struct Table {
  const Value& value;
  std::string name;
};

// Accepted numbers: an interval, open or closed at each end.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool loOpen = false, hiOpen = false;
};

// The TOML file as a tree; a missing file or a syntax error is a TerrainFileError.
Value parseFile(const std::string& path);

// "file:line: message" and toml11's excerpt of the line marked with `mark`, thrown as TerrainFileError.
[[noreturn]] void fail(const Value& at, const std::string& message, const std::string& mark = "here");

// The dotted name of a key in a table: "friction", "plane.normal", "bumps[1].height".
std::string keyName(const Table& t, const std::string& key);

// Throws at the first key of t not in `known`.
void rejectUnknownKeys(const Table& t, const std::vector<std::string_view>& known);

bool has(const Table& t, const std::string& key);

// A number (TOML integer or float) in `range`; `fallback` when absent, else the key is required.
double number(const Table& t, const std::string& key, const Range& range, std::optional<double> fallback = {});

// A TOML integer in [lo, hi].
long long integer(const Table& t, const std::string& key, long long lo, long long hi,
                  std::optional<long long> fallback = {});

// A string.
std::string text(const Table& t, const std::string& key, std::optional<std::string> fallback = {});

// A string that must be one of `choices`.
std::string choice(const Table& t, const std::string& key, std::initializer_list<std::string_view> choices,
                   std::optional<std::string> fallback = {});

// An array of three finite numbers.
Eigen::Vector3d vector3(const Table& t, const std::string& key, std::optional<Eigen::Vector3d> fallback = {});

// A required [table].
Table subtable(const Table& t, const std::string& key);

// The tables of an array of tables ([[key]]); none when absent.
std::vector<Table> tableArray(const Table& t, const std::string& key);

// A value (a key's or an array element's) as a finite number; `what` names it for messages.
double asNumber(const Value& v, const std::string& what);

// Throws at t[key] unless the value read from it satisfies `ok`.
void require(bool ok, const Table& t, const std::string& key, const std::string& expected);

}  // namespace bdfcar::terrain::toml_fields
