// The Magic Formula tyre, MF 5.2 / PAC2002 (Pacejka, "Tire and Vehicle
// Dynamics", 2nd ed. 2006, section 4.3.2), from a .tir file
// (tyre/pac2002_file.h), in two evaluations of the same data:
//  - Textbook: the equations as published, in the TNO / ISO convention
//    (alpha = atan(v_y / |v_x|), forces and moments in the contact frame
//    x forward, y left, z up), camber from the wheel's attitude, combined
//    slip by the PAC2002 weighting functions (a file without their R*
//    coefficients has no combined-slip reduction: the loader says so), the
//    effective rolling radius from BREFF, DREFF, FREFF, the force at the
//    contact point.
//  - Chrono9: the same data as Chrono 9.0.1's ChPac02Tire evaluates it
//    (../shared/reference/tyre-pac2002.md, reproduced to its check values):
//    camber ignored, slips softened by 0.1 m/s at every speed, a friction
//    ellipse for combined slip unless FE_METHOD = 'NO', its sign convention
//    and clamps, R_eff = R0 - delta / 3, the force applied delta above the
//    contact point; for cross-checking against an independent code.
// Both: the mounted side against TYRESIDE mirrors the asymmetric
// coefficients; the normal load is the linear spring and damper of
// [VERTICAL] (scaled by LCZ), its zero corner rounded as the Fiala tyre's;
// the peak factors scale with the road's friction over the file's
// reference (reference_friction, 0.8 by default) and nothing else does.
//
// Low speed (both, as the Fiala tyre: tyre/low_speed_slips.h): below
// low_speed_blend_end the slips become transient slips over relaxation
// lengths (the file's PTX / PTY lengths for the textbook evaluation, the
// vehicle file's for Chrono9, whose own Dahl bristle model at its fixed
// 1 ms sub-step is not reproduced), so a car holds on a slope and pulls
// away without a jerk. Above it the law is exactly the variant's.
#pragma once

#include <optional>
#include <string>

#include "tyre/envelope.h"
#include "tyre/low_speed_slips.h"
#include "tyre/pac2002_coefficients.h"
#include "tyre/tyre.h"

namespace bdfcar::tyre {

enum class Pac2002Variant { Textbook, Chrono9 };

struct Pac2002Coefficients {
#define BDFCAR_PAC2002_FIELD(section, name, value) double name = value;
  BDFCAR_PAC2002_COEFFICIENTS(BDFCAR_PAC2002_FIELD)
#undef BDFCAR_PAC2002_FIELD
  bool operator==(const Pac2002Coefficients&) const = default;
};

struct Pac2002Params {
  std::string file;                    // the .tir it was read from
  Pac2002Variant variant = Pac2002Variant::Textbook;
  Pac2002Coefficients c;
  // [DIMENSION], [VERTICAL], [MODEL] in SI.
  double unloadedRadius = 0;           // R0, m
  double width = 0;                    // m
  double verticalStiffness = 0;        // N/m
  double verticalDamping = 0;          // N s/m
  double nominalLoad = 0;              // FNOMIN, N
  double breff = 0, dreff = 0, freff = 0;  // effective rolling radius (textbook)
  double longvl = 16.7;                // m/s, the measurement speed (rolling resistance)
  bool combined = true;                // USE_MODE 4 (combined) or 3 (uncombined)
  bool ellipse = false;                // combined slip by the friction ellipse (Chrono9 unless FE_METHOD = 'NO')
  bool measuredLeft = true;            // TYRESIDE
  bool mountedLeft = true;             // the wheel it is on (set by the vehicle loader)
  double referenceFriction = 0.8;      // mu0: the road friction the peak factors stand for
  LowSpeedSlipSpec lowSpeed;           // relaxation lengths here are the Chrono9 variant's
  EnvelopeSpec contact;
  bool operator==(const Pac2002Params&) const = default;
};

// The steady-state Magic Formula at slips (kappa, alpha, gamma) and load Fz
// in the variant's own frame and sign convention (Chrono9: alpha is its
// alpha_c, the outputs its internal ones, tyre-pac2002.md 3): the check
// values of the spec and the textbook's closed-form limits are stated there.
template <typename T>
struct MagicFormulaForcesT {
  T Fx = T(0.0), Fy = T(0.0), Mz = T(0.0), Mx = T(0.0), My = T(0.0);
  T Kx = T(0.0), Ky = T(0.0);  // slip stiffnesses at the load (N, N/rad)
  T Dx = T(0.0), Dy = T(0.0);  // peak factors (N)
};
using MagicFormulaForces = MagicFormulaForcesT<double>;
// mu: the road's friction (scales the peak factors by mu / referenceFriction);
// vx: forward speed for the rolling resistance. p's coefficients are used as
// they are: a tyre mounted on the other side from TYRESIDE needs
// mountedCoefficients(p) first (Pac2002Tyre's constructor does that).
// For T double and ad::Dual (pac2002.cpp).
template <typename T>
MagicFormulaForcesT<T> magicFormula(const Pac2002Params& p, const T& kappa, const T& alpha, const T& gamma,
                                    const T& Fz, double mu, const T& vx = T(0.0));
inline MagicFormulaForces magicFormula(const Pac2002Params& p, double kappa, double alpha, double gamma, double Fz,
                                       double mu, double vx = 0.0) {
  return magicFormula<double>(p, kappa, alpha, gamma, Fz, mu, vx);
}

// The mirrored coefficients of a tyre mounted on the other side from TYRESIDE.
Pac2002Coefficients mountedCoefficients(const Pac2002Params& p);

// The peak friction coefficient (D over the load) at the nominal load on road friction mu.
double pac2002PeakFriction(const Pac2002Params& p, double mu);

class Pac2002Tyre {
 public:
  explicit Pac2002Tyre(const Pac2002Params& p);
  // Into out, every field of it (the step's path: no output copied); T
  // double or ad::Dual (a closed form's Jacobian, autodiff.h).
  template <typename T>
  void evaluate(const WheelKinematicsT<T>& wheel, const ContactPlaneT<T>& ground, const SlipState& previous, double h,
                std::optional<T> load, TyreOutputT<T>& out) const;
  TyreOutput evaluate(const WheelKinematics& wheel, const ContactPlane& ground, const SlipState& previous, double h,
                      std::optional<double> load = std::nullopt) const {
    TyreOutput out;
    evaluate(wheel, ground, previous, h, load, out);
    return out;
  }
  double unloadedRadius() const { return p_.unloadedRadius; }
  const Pac2002Params& params() const { return p_; }

 private:
  Pac2002Params p_;  // with the mounted side's coefficients
};

}  // namespace bdfcar::tyre
