#include "config/range.h"

#include <cmath>
#include <cstdio>

namespace bdfcar::config {

bool Range::contains(double x) const {
  const bool aboveLo = loOpen ? x > lo : x >= lo;
  const bool belowHi = hiOpen ? x < hi : x <= hi;
  return aboveLo && belowHi;
}

// An unbounded end is left out rather than printed as "inf".
std::string Range::text() const {
  const bool finiteLo = std::isfinite(lo), finiteHi = std::isfinite(hi);
  if (finiteLo && finiteHi)
    return "in " + std::string(loOpen ? "(" : "[") + formatNumber(lo) + ", " + formatNumber(hi) + (hiOpen ? ")" : "]");
  if (finiteLo) return (loOpen ? "> " : ">= ") + formatNumber(lo);
  if (finiteHi) return (hiOpen ? "< " : "<= ") + formatNumber(hi);
  return "";
}

std::string formatNumber(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", x);
  return buffer;
}

}  // namespace bdfcar::config
