#include "scenario/failure_hint.h"

#include <algorithm>
#include <cstdio>

#include "config/units.h"

namespace bdfcar::scenario {

namespace {

constexpr const char* kCornerWords[4] = {"front left", "front right", "rear left", "rear right"};

template <typename... Args>
std::string format(const char* fmt, Args... args) {
  char text[256];
  std::snprintf(text, sizeof text, fmt, args...);
  return text;
}

}  // namespace

std::string failureHint(const vehicle::VehicleSample& last, double weight, const IntegratorSpec& integrator) {
  // What the car was doing.
  int heaviest = 0, inAir = 0;
  for (int w = 0; w < 4; ++w) {
    if (last.Fz[w] > last.Fz[heaviest]) heaviest = w;
    if (!last.inContact[w]) ++inAir;
  }
  const double share = weight > 0 ? last.Fz[heaviest] / (0.25 * weight) : 0.0;
  std::string what = format("at the last accepted step (t = %.3f s, %.0f km/h) ", last.t, config::mpsToKmh(last.speed));
  if (share > kImpactLoadRatio)
    what += format(
        "the %s tyre carried %.1f kN, %.1f times its share of the "
        "car's weight: an impact (a landing, a "
        "drop, a kerb) ",
        kCornerWords[heaviest], last.Fz[heaviest] / 1000.0, share);
  else if (inAir == 4)
    what += "all four wheels were in the air ";
  else
    what += format("the car was rolled %.0f deg and pitched %.0f deg ", config::radToDeg(last.roll),
                   config::radToDeg(last.pitch));

  // What follows such motion: Newton to tolerance, a shorter step, the implicit
  // method.
  const double shorter = integrator.step / 5.0;
  std::string tries;
  if (integrator.method != IntegratorMethod::Bdf)
    tries = format(
        "the implicit integrator (--integrator bdf) or a shorter "
        "step (--step %g)",
        shorter);
  else if (integrator.bdf.newtonIterations > 0)
    tries = format(
        "Newton to tolerance (--newton 0, or integrator.newton_iterations = 0) "
        "or a shorter step (--step %g)",
        shorter);
  else
    tries = format("a shorter step (--step %g)", shorter);
  return " (hint: " + what + "that a " + format("%g ms", integrator.step * 1000.0) + " step did not follow; try " +
         tries + ")";
}

}  // namespace bdfcar::scenario
