// The interval a config number must lie in, each end open or closed, and how
// it reads in messages ("in (0, 2]"), so that every loader words ranges alike.
#pragma once

#include <limits>
#include <string>

namespace bdfcar::config {

struct Range {
  double lo = -std::numeric_limits<double>::infinity();  // an infinite end is no bound
  double hi = std::numeric_limits<double>::infinity();
  bool loOpen = false, hiOpen = false;

  // Whether x lies in the interval (NaN does not).
  bool contains(double x) const;
  // "in (0, 2]", "> 0", "<= 5", or "" when unbounded.
  std::string text() const;
};

// A number as a person would write it: 0.5, 10000, 1e+06 (printf's %g).
std::string formatNumber(double x);

}  // namespace bdfcar::config
