// Fiala tyre as specified for the reference sedan (docs/reference-vehicle.md
// 7.1, Chrono 9.0.1 ChFialaTire): single-point contact, linear
// vertical spring-damper, combined slip only through the friction factor
// U(S), forces applied at the point delta above the contact point, rolling
// resistance as a moment. A continuous (lag-free) implementation.
//
// Low speed (our addition, the reference model has none): the slips blend
// into transient slips below lowSpeed.blend1 (tyre/low_speed_slips.h), so
// a parked or braked car holds on a slope without creeping and braking to a
// stop ends without jitter. Above it the law is exactly the spec's.
#pragma once

#include <optional>

#include "tyre/envelope.h"
#include "tyre/low_speed_slips.h"
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
  LowSpeedSlipSpec lowSpeed;           // low-speed treatment (not in the reference model)
  // The contact geometry: the road under one point, or enveloped over the patch (envelope.h).
  EnvelopeSpec contact;
};

template <typename T>
struct PatchForcesT {
  T Fx = T(0.0), Fy = T(0.0), Mz = T(0.0);
};
using PatchForces = PatchForcesT<double>;

// The Fiala patch force law (FialaPatchForces in the spec) for slips kappa and
// alpha, normal load Fz and terrain friction mu (clamped to [0.1, 1]).
PatchForces fialaPatchForces(const FialaParams& p, double kappa, double alpha, double Fz, double mu);
// The same in kappa and tan(alpha), for double and ad::Dual (fiala.cpp).
template <typename T>
PatchForcesT<T> fialaPatchForcesTan(const FialaParams& p, const T& kappa, const T& tanA, const T& Fz, double mu);

class FialaTyre {
 public:
  explicit FialaTyre(const FialaParams& p) : p_(p) {}
  // Into out, every field of it (the step's path: no output copied); T
  // double or ad::Dual (a closed form's Jacobian, autodiff.h).
  template <typename T>
  void evaluate(const WheelKinematicsT<T>& wheel, const ContactPlaneT<T>& ground, const SlipState& previous, double h,
                std::optional<T> load, TyreOutputT<T>& out) const;
  TyreOutput evaluate(const WheelKinematics& wheel, const ContactPlane& ground, const SlipState& previous,
                      double h, std::optional<double> load = std::nullopt) const {
    TyreOutput out;
    evaluate(wheel, ground, previous, h, load, out);
    return out;
  }
  double unloadedRadius() const { return p_.unloadedRadius; }
  double width() const { return p_.width; }
  const FialaParams& params() const { return p_; }
 private:
  FialaParams p_;
};

}  // namespace bdfcar::tyre
