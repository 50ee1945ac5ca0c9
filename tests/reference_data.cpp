#include "reference_data.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace bdfcar::test {

Table readCsv(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error(path + ": cannot open");
  Table t;
  std::string line;
  std::getline(f, line);
  std::stringstream header(line);
  for (std::string c; std::getline(header, c, ',');) t.columns.push_back(c);
  while (std::getline(f, line)) {
    std::stringstream row(line);
    std::string cell;
    for (const std::string& c : t.columns) {
      if (!std::getline(row, cell, ',')) throw std::runtime_error(path + ": short row");
      t.values[c].push_back(std::stod(cell));
    }
  }
  return t;
}

ColumnError compareColumn(const Table& reference, const std::vector<double>& run, const std::string& column) {
  const std::vector<double>& ref = reference.values.at(column);
  const size_t n = std::min(ref.size(), run.size());
  double peak = 0, sum = 0;
  ColumnError e;
  for (size_t i = 0; i < n; ++i) {
    peak = std::max(peak, std::abs(ref[i]));
    const double d = run[i] - ref[i];
    sum += d * d;
    e.maxAbs = std::max(e.maxAbs, std::abs(d));
  }
  e.rmsPercent = 100.0 * std::sqrt(sum / static_cast<double>(n)) / peak;
  return e;
}

}  // namespace bdfcar::test
