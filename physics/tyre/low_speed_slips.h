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

#include "autodiff.h"
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
template <typename T>
inline T exactSlipWeight(const LowSpeedSlipSpec& s, const T& absVx) {
  if (ad::value(absVx) <= s.blend0) return T(0.0);
  if (ad::value(absVx) >= s.blend1) return T(1.0);
  const T x = (absVx - s.blend0) / (s.blend1 - s.blend0);
  return T(x * x * (3.0 - 2.0 * x));
}

template <typename T>
struct BlendedSlipsT {
  T kappa = T(0.0), tanAlpha = T(0.0);
  SlipState next;  // the transient slips' values (a state: no derivative)
};
using BlendedSlips = BlendedSlipsT<double>;

// The slips at weight beta < 1 (exactSlipWeight): sx, sy the relaxation
// lengths at this load; limX, limY the transient slips' bounds (where the
// force law saturates: once the patch slides the tread stays at the
// friction force); stiffX, stiffY the law's slip stiffnesses (N per unit
// slip), which turn the damping into slip; denom the exact slips'
// denominator (|vx| held at blend0 or above, plus a model's own softening).
template <typename T>
inline BlendedSlipsT<T> lowSpeedSlips(const LowSpeedSlipSpec& s, const T& beta, const T& vsx, const T& vsy,
                                      const T& absVx, const SlipState& prev, double h, const T& sx, const T& sy,
                                      const T& limX, const T& limY, const T& stiffX, const T& stiffY,
                                      const T& denom) {
  BlendedSlipsT<T> out;
  out.next = prev;
  T fromKappa = T(prev.kappa), fromTanAlpha = T(prev.tanAlpha);
  if (!prev.active) {
    fromKappa = -vsx / denom;
    fromTanAlpha = vsy / denom;
  }
  const T nextKappa = ad::clamp(T((fromKappa - h * vsx / sx) / (1.0 + h * absVx / sx)), T(-limX), limX);
  const T nextTanAlpha = ad::clamp(T((fromTanAlpha + h * vsy / sy) / (1.0 + h * absVx / sy)), T(-limY), limY);
  out.next.kappa = ad::value(nextKappa);
  out.next.tanAlpha = ad::value(nextTanAlpha);
  out.next.active = true;
  const T dampX = -s.dampingX * vsx / stiffX;
  const T dampY = s.dampingY * vsy / stiffY;
  out.kappa = beta * (-vsx / denom) + (1.0 - beta) * (nextKappa + dampX);
  out.tanAlpha = beta * (vsy / denom) + (1.0 - beta) * (nextTanAlpha + dampY);
  return out;
}

}  // namespace bdfcar::tyre
