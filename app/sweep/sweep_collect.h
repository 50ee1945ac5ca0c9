// Merging a sweep's results (DIR as sweep_jobs.h lays it out, whoever ran
// the jobs): DIR/summary.csv has one row per case, its varied values, its
// status and every metric its run wrote; then the plots (gnuplot): the
// chosen metric against the first variable with one curve per value of the
// second (a carpet), and a telemetry channel over time for every case.
#pragma once

#include <string>
#include <vector>

namespace bdfcar::app {

// The sweep files' CSV: a field is quoted ("" for a quote) when it holds a
// comma, a quote or a line break. One line into fields, and fields into one line.
std::vector<std::string> csvFields(const std::string& line);
std::string csvLine(const std::vector<std::string>& fields);

struct SweepSummary {
  int cases = 0, ok = 0, failed = 0, missing = 0;  // failed: the run failed (ok = 0); missing: no metrics file
  std::string summaryCsv;
  std::string plotNote;                            // empty, or why a plot is missing
};

// Throws scenario::OutputError when DIR has no cases.csv or summary.csv cannot be written.
SweepSummary collectSweep(const std::string& dir);

}  // namespace bdfcar::app
