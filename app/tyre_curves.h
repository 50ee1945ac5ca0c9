// A tyre's characteristic curves and headline numbers (`bdfcar tyre`), from
// its data alone: the steady-state force law of physics/tyre swept in slip
// angle, slip ratio and load, no vehicle and no time.
//
// One convention for every model, ISO / TNO (the Fiala tyre's and the
// textbook PAC2002's own): slip angle alpha = atan(v_y / |v_x|), slip ratio
// kappa > 0 driving, forces and moments in the contact frame (x forward,
// y left, z up). A tyre's lateral force opposes its slip angle (Fy < 0 for
// alpha > 0) and its aligning moment turns it toward its velocity (Mz > 0
// for alpha > 0). The Chrono9 evaluation of PAC2002 works in Chrono's
// alpha_c = -alpha with Fy and Mz negated (tyre-pac2002.md 2.3): it is
// evaluated at -alpha and its Fy and Mz negated here. Stiffnesses are
// reported as magnitudes: C_alpha = -dFy/dalpha, C_kappa = dFx/dkappa.
//
// The lateral and longitudinal curves are pure slip (the other slip zero,
// the combined-slip reduction off: Pacejka's Fy0(alpha), Fx0(kappa)); the
// combined curves are the model's full law. Camber zero. SI throughout
// (rad, N, N m); degrees are for the printing and the CSV files only.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "tyre/tyre_model.h"

namespace bdfcar::app {

// The tyre's steady forces at (kappa, alpha, Fz) on road friction mu, in
// the convention above; pureSlip: without the combined-slip reduction.
struct SteadyTyreForces {
  double Fx = 0, Fy = 0, Mz = 0;  // N, N, N m
};
SteadyTyreForces steadyTyreForces(const tyre::TyreParams& p, double kappa, double alpha, double Fz, double mu,
                                  bool pureSlip);

// The largest |F| of a curve on one side of zero slip, as a friction
// coefficient |F| / Fz, with the slip where it is reached (the smallest
// |slip| when the curve is flat there) and the signed force.
struct CurvePeak {
  double mu = 0;      // |F| / Fz (for the aligning moment: |Mz|, N m)
  double slip = 0;    // rad or 1
  double value = 0;   // N (N m)
  bool atSweepEnd = false;  // the largest |F| is at the end of the sweep: the peak lies beyond it
};

// The stiffnesses at one load: the slope of the pure-slip curve at zero
// slip (central difference) and the model's own value where it has one
// (PAC2002: |Ky|, Kx of the Magic Formula; Fiala: its C_alpha, C_kappa).
struct LoadStiffness {
  double Fz = 0;                 // N
  double cornering = 0;          // N/rad, -dFy/dalpha at alpha = 0
  double corneringModel = 0;     // N/rad
  double slip = 0;               // N, dFx/dkappa at kappa = 0
  double slipModel = 0;          // N
};

struct TyreCurves {
  std::string model;             // "Fiala", "PAC2002 (textbook)", "PAC2002 (chrono9)"
  double unloadedRadius = 0;     // m
  double nominalLoad = 0;        // N
  double friction = 0;           // road friction mu the curves are on
  double referenceFriction = 0;  // mu0 of the tyre's peak factors

  // Pure slip at loadFactors x nominal load.
  static constexpr std::array<double, 3> loadFactors = {0.5, 1.0, 1.5};
  std::vector<double> alpha;                   // rad
  std::array<std::vector<double>, 3> Fy, Mz;   // N, N m, per load
  std::vector<double> kappa;                   // 1
  std::array<std::vector<double>, 3> Fx;       // N, per load

  // Combined slip at the nominal load: kappa swept (the kappa grid) at each
  // fixed slip angle.
  static constexpr std::array<double, 4> combinedAlphaDeg = {0, 2, 4, 8};
  std::array<std::vector<double>, 4> combinedFx, combinedFy;  // N

  // Stiffness over the load, 0.1 to 2.5 x nominal in steps of 0.1.
  std::vector<LoadStiffness> stiffness;
  LoadStiffness atNominal;

  // At the nominal load, pure slip, on each side (positive, negative slip).
  CurvePeak lateral[2], longitudinal[2], aligning[2];
};

// The stiffness table's row at `factor` x nominal load (factor a multiple of 0.1 in [0.1, 2.5]).
const LoadStiffness& stiffnessAt(const TyreCurves& c, double factor);

// nominalLoad: the load the headline numbers are at (N, > 0); friction:
// the road's mu (the tyre's reference friction gives the file's own peaks).
TyreCurves tyreCurves(const tyre::TyreParams& p, double nominalLoad, double friction);

// A short name of the tyre's model and evaluation.
std::string tyreModelName(const tyre::TyreParams& p);

// Whether two tyres have the same force law and geometry (the wheels that
// share one tyre are reported together).
bool sameTyre(const tyre::TyreParams& a, const tyre::TyreParams& b);

}  // namespace bdfcar::app
