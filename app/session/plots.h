// Plots of a run's telemetry through gnuplot (pngcairo): the path with the
// course's lane limits, and the lateral acceleration over time.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scenario/iso3888_course.h"

namespace bdfcar::app {

// Writes path.png and lateral_acceleration.png into outDir from the
// telemetry CSV. Returns an empty string on success, else why not (gnuplot
// missing or failing): plots are a convenience, never a reason to fail a run.
std::string plotDrive(const std::string& telemetryCsv, const std::string& outDir,
                      const std::optional<scenario::Iso3888Course>& course, const std::string& title);

// A line plot of CSV columns, by their header names, against one of them
// (or, where xs is given, each ys[k] against its own xs[k], curves in a
// plane, and x only names the axis).
struct CsvPlot {
  std::string csv, png, title, x;
  std::vector<std::string> ys;
  std::vector<std::string> xs = {};
};

// Writes the plots through one gnuplot script (`script`, kept beside them).
// Returns "" on success, else why not, as plotDrive.
std::string plotCsvColumns(const std::vector<CsvPlot>& plots, const std::string& script);

}  // namespace bdfcar::app
