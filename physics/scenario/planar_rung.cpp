#include "scenario/planar_rung.h"

#include <cmath>
#include <map>
#include <mutex>

#include "scenario/rung_runs.h"
#include "tyre/tyre_model.h"
#include "vehicle/derivation_cache.h"
#include "vehicle/motion_ratio.h"

namespace bdfcar::scenario {

void identifyRollAxis(const ScenarioSpec& scene, const vehicle::Vehicle& linkage, vehicle::PlanarDerivation& p) {
  constexpr double kG = 9.81;
  // A step steer to about 0.3 of the tyres' limit (the neutral-steer angle).
  const double limit = tyre::peakFriction(linkage.wheel(0).tyre, kRungRunFriction) * kG;
  const double full = 0.9 * std::abs(vehicle::roadWheelAnglePerSteer(linkage));
  ScenarioSpec s = rungRunBase(scene);
  s.steering = roadWheelRamp(std::min(full, linkage.spec.geometry.wheelbase * 0.3 * limit / (kRungRunSpeed * kRungRunSpeed)));
  const SteadyState k = steadyState(runOnModel(s, linkage, p.kinematic.vehicle));
  vehicle::PlanarLoads& P = *p.vehicle.planar;
  p.geometricAxisHeight = P.axisHeight;
  if (!k.ok || !(std::abs(k.ay) > 0.1)) return;  // keeps the construction's axis
  const double target = k.roll / k.ay;
  p.kinematicRollGradient = target;
  auto gradientAt = [&](double axis) {
    vehicle::setPlanarRollAxis(p.vehicle, axis);
    const SteadyState r = steadyState(runOnModel(s, linkage, p.vehicle));
    return r.ok && std::abs(r.ay) > 0.1 ? r.roll / r.ay : NAN;
  };
  // Secant on the axis height; the roll gradient grows smoothly as the axis
  // drops (the sprung weight's arm about it grows).
  double h0 = p.geometricAxisHeight, h1 = h0 - 0.05;
  double g0 = gradientAt(h0), g1 = gradientAt(h1);
  for (int i = 0; i < 4 && std::isfinite(g0) && std::isfinite(g1) && g1 != g0; ++i) {
    const double h2 = h1 + (target - g1) * (h1 - h0) / (g1 - g0);
    if (!std::isfinite(h2) || std::abs(h2 - p.geometricAxisHeight) > 0.5) break;  // no sensible axis: keep the best
    h0 = h1, g0 = g1;
    h1 = h2, g1 = gradientAt(h2);
    if (std::abs(g1 - target) <= 1e-3 * std::abs(target)) break;
  }
  const double best = std::isfinite(g1) && std::abs(g1 - target) <= std::abs(g0 - target) ? h1 : h0;
  vehicle::setPlanarRollAxis(p.vehicle, std::isfinite(g0) || std::isfinite(g1) ? best : p.geometricAxisHeight);
}

vehicle::PlanarDerivation derivePlanarRung(const ScenarioSpec& scene, const vehicle::Vehicle& linkage) {
  static std::mutex mutex;
  static std::map<std::string, vehicle::PlanarDerivation> known;
  const std::string key = std::to_string(vehicle::derivationFingerprint(linkage)) + '|' + rungRunsKey(scene);
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (auto it = known.find(key); it != known.end()) return it->second;
  }
  vehicle::PlanarDerivation p = vehicle::derivePlanar(linkage);
  identifyRollAxis(scene, linkage, p);
  std::lock_guard<std::mutex> lock(mutex);
  known.emplace(key, p);
  return p;
}

}  // namespace bdfcar::scenario
