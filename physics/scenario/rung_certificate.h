// The error certificate of the fidelity ladder's derived rungs for the car
// in hand: each rung is run against the linkage it was derived from, at the
// scene's step and integrator settings, on a fixed battery that spans what
// `auto` may ask of it:
//   step steer at about 0.3 and 0.6 of the tyres' limit (80 km/h),
//   a sine steer (0.5 Hz, about 0.4 of the limit),
//   braking in a turn (about 0.4 of the limit, then 0.3 g of braking),
//   full throttle from 5 m/s (the powertrain's, or a speed hold at 0.4 g),
//   a stop on a 10 % grade with the brakes held, then released.
// Per manoeuvre: the RMS difference to the linkage's run as % of the
// linkage's peak, of yaw rate, lateral acceleration, roll, pitch and the
// height of the centre of mass. Yaw rate, a_y, roll and height are the
// quantities `auto`'s error budget is held on (the worst of them is the
// rung's figure); pitch is reported beside them (the planar rung has no
// anti-dive or anti-squat: its pitch shows what that costs).
// A manoeuvre outside a rung's validity (the planar rung on the grade) is
// not run on it: the rung is refused there by its validity, not certified.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "scenario/scenario_spec.h"
#include "vehicle/kinematic_model.h"
#include "vehicle/planar_model.h"

namespace bdfcar::scenario {

// One manoeuvre of the battery on one rung.
struct ManoeuvreError {
  std::string manoeuvre;
  std::string refused;  // not empty: outside the rung's validity (why), no figures
  double yawRate = 0, ay = 0, roll = 0, pitch = 0, z = 0;  // RMS % of the linkage's peak
  double limitShare = 0;  // the linkage's peak |a_y| over the tyres' limit (mu g)
  // The largest of the budgeted quantities (yaw rate, a_y, roll, z) and its name.
  double worst(const char** quantity = nullptr) const;
};

struct RungCertificate {
  vehicle::Fidelity rung = vehicle::Fidelity::Kinematic;
  std::vector<ManoeuvreError> manoeuvres;
  double worst = 0;               // % (budgeted quantities, every manoeuvre run)
  std::string worstManoeuvre;     // where
  std::string worstQuantity;      // which
};

struct LadderCertificate {
  double step = 0;                          // s, the scene's integration step
  std::vector<RungCertificate> rungs;       // the derived rungs certified
  std::string failure;                      // not empty: the linkage itself failed a manoeuvre (no figures)
  const RungCertificate* find(vehicle::Fidelity f) const;
};

// The battery's scenarios for a scene's vehicle and integrator (exposed for
// the tests and the report): on flat ground (the grade's on a plane tilted
// about y), on the linkage.
std::vector<ScenarioSpec> certificateBattery(const ScenarioSpec& scene, const vehicle::Vehicle& linkage);

// Runs the battery on the linkage and on each derived rung given. The
// result is kept per process for the same vehicle file, settings and
// integrator (each derived rung a pure function of them).
LadderCertificate certifyLadder(const ScenarioSpec& scene, const vehicle::Vehicle& linkage,
                                const vehicle::PlanarDerivation& derived);
// The same for a car whose planar rung cannot be derived (planar: null).
LadderCertificate certifyLadder(const ScenarioSpec& scene, const vehicle::Vehicle& linkage,
                                const vehicle::Vehicle& kinematic, const vehicle::Vehicle* planar);

// The rungs `auto` uses for a scene, from the certificate and the budget
// (fraction): the full rung it switches up to (kinematic where its
// certificate is within the budget, else the linkage), whether the planar
// rung may be switched down to and up to which lateral acceleration, and a
// line for each rung refused or limited, saying why ("planar not used: yaw
// rate 31.2 % over the 10 % budget on step steer 0.3 of the limit (it omits:
// ...)"). The planar rung is used where every manoeuvre is within the
// budget; the harder step steer alone over it limits the rung to lateral
// accelerations between the two step steers' levels.
struct AutoRungChoice {
  vehicle::Fidelity full = vehicle::Fidelity::Linkage;
  bool planar = false;
  // The planar rung's certified range: lateral acceleration up to this share
  // of the tyres' limit (mu g); infinite where the harder step steer is
  // within the budget too.
  double planarLevel = std::numeric_limits<double>::infinity();
  std::vector<std::string> refusals;  // a rung not used, or used in part, and why
};
AutoRungChoice chooseAutoRungs(const LadderCertificate& c, double errorBudget);

// The certificate as a table, for `bdfcar info` and the report.
std::string describeCertificate(const LadderCertificate& c, double errorBudget);

}  // namespace bdfcar::scenario
