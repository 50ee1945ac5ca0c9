#include "vehicle/powertrain.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include "autodiff.h"
#include "portable_math.h"

namespace bdfcar::vehicle {

// The speed-dependent laws for a scalar type T (double, or ad::Dual for a
// closed form's Jacobian: autodiff.h), the bits of the double ones as before.
template <typename T>
T fullLoadTorque(const EngineSpec& e, const T& wT) {
  const double w = ad::value(wT);
  const std::vector<double>& x = e.speed;
  if (x.empty()) return T(0.0);
  if (w <= x.front()) return T(e.torque.front());
  if (w >= x.back()) return T(e.torque.back());
  const auto hi = std::upper_bound(x.begin(), x.end(), w);
  const std::size_t i = static_cast<std::size_t>(hi - x.begin());
  const T s = (wT - x[i - 1]) / (x[i] - x[i - 1]);
  return e.torque[i - 1] + s * (e.torque[i] - e.torque[i - 1]);
}

template <typename T>
T effectiveThrottle(const EngineSpec& e, const T& w, double throttle) {
  const T governor = ad::clamp(T((e.idleSpeed - w) / e.governorBand), 0.0, 1.0);
  const T open = ad::max(std::clamp(throttle, 0.0, 1.0), governor);
  // The fuel cut closes the throttle over the first 1 % above the limit
  // (a ramp rather than a switch: Newton sees a continuous residual).
  const T cut = ad::clamp(T((1.01 * e.revLimit - w) / (0.01 * e.revLimit)), 0.0, 1.0);
  return open * cut;
}

template <typename T>
T engineFriction(const EngineSpec& e, const T& w) {
  using std::abs;
  // tanh over 1 rad/s: the friction of a turning engine, zero at rest.
  return (e.friction + e.frictionSlope * abs(w)) * pm::tanh(w);
}

template <typename T>
T engineTorque(const EngineSpec& e, const T& w, double throttle) {
  return effectiveThrottle(e, w, throttle) * fullLoadTorque(e, w) - engineFriction(e, w);
}

template <typename T>
T clutchTorque(const ClutchSpec& c, double capacity, double deflection, const T& slip, double h) {
  if (capacity <= 0) return T(0.0);
  const T t = c.stiffness * (deflection + h * slip) + c.damping * slip;
  return capacity * pm::tanh(T(t / capacity));
}

#define BDFCAR_POWERTRAIN_LAWS(T)                                                    \
  template T fullLoadTorque(const EngineSpec&, const T&);                           \
  template T effectiveThrottle(const EngineSpec&, const T&, double);                \
  template T engineFriction(const EngineSpec&, const T&);                           \
  template T engineTorque(const EngineSpec&, const T&, double);                     \
  template T clutchTorque(const ClutchSpec&, double, double, const T&, double);
BDFCAR_POWERTRAIN_LAWS(double)
BDFCAR_POWERTRAIN_LAWS(ad::Dual)
#undef BDFCAR_POWERTRAIN_LAWS

double advanceClutchDeflection(const ClutchSpec& c, double capacity, double deflection, double slip, double h) {
  if (capacity <= 0) return 0.0;
  const double limit = capacity / c.stiffness;
  return std::clamp(deflection + h * slip, -limit, limit);
}

std::string describePowertrain(const PowertrainSpec& p, double wheelRadius) {
  const EngineSpec& e = p.engine;
  const double rpm = 60.0 / (2.0 * M_PI);
  // The best torque and power over the curve, sampled every 10 rpm.
  double bestT = 0, atT = 0, bestP = 0, atP = 0;
  for (double w = e.speed.front(); w <= std::min(e.speed.back(), e.revLimit); w += 10.0 / rpm) {
    const double T = fullLoadTorque(e, w);
    if (T > bestT) bestT = T, atT = w;
    if (T * w > bestP) bestP = T * w, atP = w;
  }
  char buf[400];
  std::string out;
  std::snprintf(buf, sizeof buf,
                "powertrain: %.0f N m at %.0f rpm, %.0f kW at %.0f rpm; idle %.0f rpm, limit %.0f rpm; %s gearbox\n",
                bestT, atT * rpm, bestP * 1e-3, atP * rpm, e.idleSpeed * rpm, e.revLimit * rpm,
                p.gearbox.automatic ? "automatic" : "manual");
  out += buf;
  const GearboxSpec& g = p.gearbox;
  for (int k = 1; k <= g.gears(); ++k) {
    const double top = k == g.gears() ? e.revLimit : g.upshiftSpeed;
    std::snprintf(buf, sizeof buf, "  gear %d: ratio %.2f x %.2f, %.0f km/h at %.0f rpm\n", k, g.ratios[k - 1],
                  g.finalDrive, top / g.overall(k) * wheelRadius * 3.6, top * rpm);
    out += buf;
  }
  std::snprintf(buf, sizeof buf, "  reverse: ratio %.2f x %.2f; handbrake %.0f N m per rear wheel\n", g.reverse,
                g.finalDrive, p.handbrakeTorque);
  return out + buf;
}

}  // namespace bdfcar::vehicle
