// Reads the reference telemetry (tests/data/ref_jturn.csv, the independent
// Chrono run) and compares a run with it: RMS and peak differences of a
// column, as a percentage of the reference's peak.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace bdfcar::test {

struct Table {
  std::vector<std::string> columns;
  std::map<std::string, std::vector<double>> values;
};

Table readCsv(const std::string& path);

struct ColumnError {
  double rmsPercent = 0;   // RMS difference / peak |reference| * 100
  double maxAbs = 0;       // largest |difference|
};

ColumnError compareColumn(const Table& reference, const std::vector<double>& run, const std::string& column);

}  // namespace bdfcar::test
