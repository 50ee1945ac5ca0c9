// Slips at low speed, shared by the tyre models: the slips kappa = -vsx/|vx|
// and tan(alpha) = vsy/|vx| are singular at standstill, so below
// blend1 they blend into transient slips governed by
//   sigma_x dkappa'/dt + |vx| kappa' = -vsx,   sigma_y dt'/dt + |vx| t' = vsy,
// whose steady state is the exact slip at speed and which at vx = 0 become
// tyre deflections (a stiff spring, kappa' = -integral(vsx)/sigma): a parked
// or braked car holds on a slope without creeping, and braking to a stop
// ends without jitter. Light damping of the slip velocities is blended in
// below the same speed, as slip ahead of the force law so that the force
// stays within friction. Integrated by backward Euler over the step from
// the last accepted transient slips (from the algebraic ones when the wheel
// has just slowed into this range).
#pragma once

#include <algorithm>

#include "tyre/tyre.h"

namespace bdfcar::tyre {

struct LowSpeedSlipSpec {
  double relaxationLengthX = 0.05;  // sigma_x, m
  double relaxationLengthY = 0.15;  // sigma_y, m
  double blend0 = 0.5;              // m/s: below, transient slips only
  double blend1 = 2.0;              // m/s: above, the exact slips only
  double dampingX = 4.0e4;          // N s/m on the longitudinal slip velocity at standstill
  double dampingY = 2.0e4;          // N s/m on the lateral slip velocity at standstill
  double maxTransientSlip = 1.5;    // absolute cap of the transient slips (the friction limit is lower)
  bool operator==(const LowSpeedSlipSpec&) const = default;
};

// Weight of the exact slips against the transient ones at forward speed |vx|:
// 0 below blend0, 1 above blend1, C1-smooth in between.
inline double exactSlipWeight(const LowSpeedSlipSpec& s, double absVx) {
  if (absVx <= s.blend0) return 0.0;
  if (absVx >= s.blend1) return 1.0;
  const double x = (absVx - s.blend0) / (s.blend1 - s.blend0);
  return x * x * (3.0 - 2.0 * x);
}

struct BlendedSlips {
  double kappa = 0, tanAlpha = 0;
  SlipState next;
};

// The slips at weight beta < 1 (exactSlipWeight): sx, sy the relaxation
// lengths at this load; limX, limY the transient slips' bounds (where the
// force law saturates: once the patch slides the tread stays at the
// friction force); stiffX, stiffY the law's slip stiffnesses (N per unit
// slip), which turn the damping into slip; denom the exact slips'
// denominator (|vx| held at blend0 or above, plus a model's own softening).
inline BlendedSlips lowSpeedSlips(const LowSpeedSlipSpec& s, double beta, double vsx, double vsy, double absVx,
                                  const SlipState& prev, double h, double sx, double sy, double limX, double limY,
                                  double stiffX, double stiffY, double denom) {
  BlendedSlips out;
  out.next = prev;
  SlipState from = prev;
  if (!prev.active) {
    from.kappa = -vsx / denom;
    from.tanAlpha = vsy / denom;
  }
  out.next.kappa = std::clamp((from.kappa - h * vsx / sx) / (1.0 + h * absVx / sx), -limX, limX);
  out.next.tanAlpha = std::clamp((from.tanAlpha + h * vsy / sy) / (1.0 + h * absVx / sy), -limY, limY);
  out.next.active = true;
  const double dampX = -s.dampingX * vsx / stiffX;
  const double dampY = s.dampingY * vsy / stiffY;
  out.kappa = beta * (-vsx / denom) + (1.0 - beta) * (out.next.kappa + dampX);
  out.tanAlpha = beta * (vsy / denom) + (1.0 - beta) * (out.next.tanAlpha + dampY);
  return out;
}

}  // namespace bdfcar::tyre
