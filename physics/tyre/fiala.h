// Fiala tyre as specified for the reference sedan (docs/reference-vehicle.md
// 7.1, Chrono 9.0.1 ChFialaTire): single-point contact, linear
// vertical spring-damper, combined slip only through the friction factor
// U(S), forces applied at the point delta above the contact point, rolling
// resistance as a moment. A continuous (lag-free) implementation.
//
// Low speed (our addition, the reference model has none): the slips
// kappa = -vsx/|vx| and tan(alpha) = vsy/|vx| are singular at standstill.
// Below lowSpeedBlend[1] the slips blend into transient slips governed by
//   sigma_x dkappa'/dt + |vx| kappa' = -vsx,   sigma_y dt'/dt + |vx| t' = vsy,
// whose steady state is the exact slip at speed and which at vx = 0 become
// tyre deflections (a stiff spring, kappa' = -integral(vsx)/sigma): a parked
// or braked car holds on a slope without creeping, and braking to a stop
// ends without jitter. Light damping of the slip velocities is blended in
// below the same speed, as slip ahead of the force law so that the force
// stays within friction. Above lowSpeedBlend[1] the law is exactly the spec's.
#pragma once

#include <optional>

#include "tyre/envelope.h"
#include "tyre/tyre.h"

namespace bdfcar::tyre {

struct FialaParams {
  double unloadedRadius = 0.3099;      // R0, m
  double width = 0.235;                // w, m (also the Mz lever as coded in the reference)
  double verticalStiffness = 310000;   // kz, N/m
  double verticalDamping = 3100;       // cz, N s/m
  double rollingResistance = 0.001;    // rr, N m per N of load (moment, no radius factor)
  double slipStiffness = 1.0e6;        // C_kappa, N per unit slip
  double corneringStiffness = 45836.6236;  // C_alpha, N/rad
  double uMin = 0.9, uMax = 1.0;       // friction factors (sliding, peak)
  double referenceFriction = 0.8;      // mu0 the factors were measured at
  // Low-speed treatment (not in the reference model).
  double relaxationLengthX = 0.05;     // sigma_x, m
  double relaxationLengthY = 0.15;     // sigma_y, m
  double lowSpeedBlend0 = 0.5;         // m/s: below, transient slips only
  double lowSpeedBlend1 = 2.0;         // m/s: above, the exact Fiala slips only
  double lowSpeedDampingX = 4.0e4;     // N s/m on the longitudinal slip velocity at standstill
  double lowSpeedDampingY = 2.0e4;     // N s/m on the lateral slip velocity at standstill
  double maxTransientSlip = 1.5;       // absolute cap of the transient slips (the friction limit is lower)
  // The contact geometry: the road under one point, or enveloped over the patch (envelope.h).
  EnvelopeSpec contact;
};

struct PatchForces {
  double Fx = 0, Fy = 0, Mz = 0;
};

// The Fiala patch force law (FialaPatchForces in the spec) for slips kappa and
// alpha, normal load Fz and terrain friction mu (clamped to [0.1, 1]).
PatchForces fialaPatchForces(const FialaParams& p, double kappa, double alpha, double Fz, double mu);

// Weight of the exact slips against the transient ones at forward speed |vx|:
// 0 below lowSpeedBlend0, 1 above lowSpeedBlend1, C1-smooth in between.
double highSpeedWeight(const FialaParams& p, double absVx);

class FialaTyre {
 public:
  explicit FialaTyre(const FialaParams& p) : p_(p) {}
  TyreOutput evaluate(const WheelKinematics& wheel, const ContactPlane& ground, const SlipState& previous,
                      double h, std::optional<double> load = std::nullopt) const;
  double unloadedRadius() const { return p_.unloadedRadius; }
  double width() const { return p_.width; }
  const FialaParams& params() const { return p_; }
  static constexpr double kContactSmoothing = 10.0;   // N, rounding of the contact corner
  static constexpr double kAirborneClearance = 0.01;  // m above the ground: no contact at all

 private:
  FialaParams p_;
};

}  // namespace bdfcar::tyre
