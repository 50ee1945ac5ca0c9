// Plots of a run's telemetry through gnuplot (pngcairo): the path with the
// course's lane limits, and the lateral acceleration over time.
#pragma once

#include <optional>
#include <string>

#include "scenario/iso3888_course.h"

namespace bdfcar::app {

// Writes path.png and lateral_acceleration.png into outDir from the
// telemetry CSV. Returns an empty string on success, else why not (gnuplot
// missing or failing): plots are a convenience, never a reason to fail a run.
std::string plotDrive(const std::string& telemetryCsv, const std::string& outDir,
                      const std::optional<scenario::Iso3888Course>& course, const std::string& title);

}  // namespace bdfcar::app
