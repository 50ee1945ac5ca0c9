// A scenario as plain data (assets/scenarios/*.toml): which vehicle on which
// terrain, how it starts, what the driver does, how it is integrated and how
// long it runs. Times are manoeuvre time: tau = 0 after the settling phase.
#pragma once

#include <string>
#include <vector>

#include "config/toml_reader.h"
#include "integrator/bdf.h"
#include "integrator/explicit.h"
#include "scenario/speed_controller.h"
#include "vehicle/vehicle_builder.h"

namespace bdfcar::scenario {

enum class IntegratorMethod { Bdf, Rk4, SemiImplicitEuler };

// How a scenario is integrated: the method, the step, and the integrators'
// own options (their defaults are stated there, once).
struct IntegratorSpec {
  IntegratorMethod method = IntegratorMethod::Bdf;
  double step = 0.01;          // s; divides the driver's tick
  integ::BdfOptions bdf;       // order, Newton policy, tolerances, Jacobian reuse
  integ::ExplicitOptions explicitMethod;  // rk4 / euler (method set from `method`)
};

// A scripted input channel (steering in [-1, 1], throttle and brake in [0, 1]).
struct SignalSpec {
  // step is a ramp (its rise time); csv a table read from a CSV file.
  enum class Kind { None, Constant, Ramp, Sine, SineWithDwell, Chirp, Square, Table } kind = Kind::None;
  // Steering only: what the levels, amplitudes and values are. The run
  // turns them into the normalised input s with the vehicle's scales
  // (normalisedSteering, simulation.cpp).
  enum class Unit { Normalised, SteeringWheelAngle, RoadWheelAngle, RackTravel } unit = Unit::Normalised;
  std::string where;                          // "file:line" of the table, for errors found then
  double start = 0, duration = 0, level = 0;  // ramp: from 0 at start to level after duration; sine, square: period = duration, amplitude = level
  int periods = 1;                            // sine: whole periods
  double dwell = 0.5;                         // sine with dwell: s at the second peak
  double f0 = 0, f1 = 0;                      // chirp: Hz at its start and end (duration: its length)
  std::vector<double> times, values;          // table
  bool asDriverCommand = false;               // steering: through the steering system, once a tick
};

// A named start of the scene ([[places]]): where a drive can go from the
// menu (the hill, the skid pad), the car at rest there as at the start.
struct Place {
  std::string name;
  double x = 0, y = 0, heading = 0;  // m, m, rad
};

struct SpeedControlSpec {
  bool enabled = false;
  SpeedProfile profile;        // target (m/s), its ramp, when the hold acts (speed_controller.h)
  double kp = 600, ki = 300;   // per driven wheel: N m/(m/s), N m/m
};

struct CourseSpec {
  bool iso3888 = false;
  int part = 1;                // ISO 3888-1 (double lane change) or -2 (obstacle avoidance)
  double startX = 50;          // m, where the course begins
  double centreY = std::numeric_limits<double>::quiet_NaN();  // m, its entry lane's centre; NaN: the start's y
};

struct PathFollowerSpec {
  bool enabled = false;
  double lookAheadTime = 0.9;  // s
  double minLookAhead = 5.0;   // m
  // What it follows (driver_paths.h): the course's driving line, a polyline
  // (a CSV of x, y, or a track's centre line from the terrain), or a circle
  // through the start.
  enum class Path { Course, Polyline, Circle } path = Path::Course;
  // How it steers: pure pursuit of a point a look-ahead ahead (path_follower.h),
  // or MacAdam's preview driver, which knows the car (preview_driver.h): it
  // follows the path through a course computed for the car's footprint
  // (course_line.h), grown by lineMargin on every side.
  enum class Law { PurePursuit, Preview } law = Law::PurePursuit;
  double previewTime = 1.0;    // s
  double lineMargin = 0.15;    // m
  std::vector<Eigen::Vector2d> points;
  bool closed = false;
  double radius = 0;           // m
  double direction = 1;        // +1 left (counter-clockwise), -1 right
};

// [laps]: lap timing on a closed track of the scenario's terrain (lap_timer.h).
struct LapTimingSpec {
  bool enabled = false;
  std::vector<Eigen::Vector2d> line;  // the track's centre line, world, closed; the start line at its first point
  double width = 0;                   // m, the road's (0: not known: no cut is judged)
  int sectors = 3;
};

// What a hard case must show ([check] in a scenario file; `bdfcar check`).
// Every run must finish without a divergence and with finite states; the
// outcome names what the car must do; the bounds are physical limits.
struct CheckSpec {
  bool enabled = false;
  enum class Outcome { Survives, ComesToRest, DrivesOn, StaysOnFourWheels, LandsAndDrivesOn } outcome =
      Outcome::Survives;
  double maxConstraintPosition = 1e-3;      // m (or rad), largest |Phi| over the run
  double maxConstraintVelocity = 1e-2;      // m/s
  double maxConstraintAcceleration = 10.0;  // m/s^2
  double maxSpeed = 100.0;                  // m/s
  double maxRise = 2.0;                     // m, centre of mass above its start
  double restSpeed = 0.05;                  // m/s, "at rest"
  double maxWheelLift = 0.3;                // s, StaysOnFourWheels: longest time a wheel is off the ground
};

// What the scene needs of the vehicle model ([fidelity]): the rung of the
// ladder the vehicle file is turned into (docs/DESIGN.md, "Fidelity").
// "auto": the cheapest rungs whose certificate for the car is within
// error_budget (rung_certificate.h), and where that is the planar model, the
// kinematic one wherever the scene needs heave, roll and pitch of the base,
// is near the tyres' limit or beyond the planar rung's certified range,
// switched in mid-run (scenario/fidelity_policy.h).
struct FidelitySpec {
  vehicle::Fidelity suspension = vehicle::Fidelity::Linkage;
  bool automatic = false;
  double errorBudget = 0.10;  // fraction of the linkage's peak: RMS of yaw rate, a_y, roll and chassis height
  // The planar rung's equations: written out in closed form (vehicle/planar_car.h),
  // or through the generic multibody machinery (the same equations, several
  // times the cost: kept to measure one against the other).
  bool planarClosedForm = true;
  // The kinematic rung's, likewise (vehicle/kinematic_car.h).
  bool kinematicClosedForm = true;
  // Newton on the derived rungs (kinematic, planar; integrator.newton_iterations
  // is the linkage's): at most newtonIterations a step (0 = to tolerance).
  int newtonIterations = 2;
  // On every rung, the linkage included: a step's fixed count ends early at
  // an iteration whose correction is within tolerance (the next would move
  // the state by less than the tolerance). From the BDF predictor one
  // iteration is within tolerance at many steps: where the motion is smooth
  // a step costs one residual instead of the count's two (the J-turn: the
  // linkage 1.3 a step, the planar rung 1.05, whose closed form also ends
  // where the iterate is within tolerance by Newton's contraction:
  // integ::BdfOptions::earlyEndFromContraction), where it is not (a rough road,
  // a curb) no more than the count, and the early end loses no accuracy
  // against the count in full (RESULTS 6b, tests/test_newton_early_end.cpp).
  // Not in the tyres' low-speed range (Simulation::step): there the count in
  // full lets a stopped car settle. Off: the count in full, as the paper
  // (and --as-published).
  bool stopWithinTolerance = true;
};

// The default error budget of `auto` (fidelity.error_budget): each derived
// rung is used where its certificate for the car (rung_certificate.h) is
// within the scene's budget.
constexpr double kPlanarErrorBound = 0.10;

// A standard test the scenario is ([metrics] test): its metrics are
// computed after the run (scenario/standard_tests.h).
enum class StandardTest { None, Iso7401StepSteer, Fmvss126SineWithDwell, Iso4138ConstantSteer, Iso4138ConstantRadius };

struct ScenarioSpec {
  std::string name, sourceFile;
  std::string vehicleFile, terrainFile;  // resolved paths; terrainFile empty = flat plane z = 0
  double groundGrade = 0;  // without a terrain file: the plane rises at this grade along +x (set in code, no key)
  std::vector<config::Setting> vehicleSettings;  // --set vehicle.KEY=VALUE: over the vehicle file
  double duration = 4.0;       // manoeuvre time, s
  double initialSpeed = 0;     // m/s
  double settleTime = 0;       // s of straight running before tau = 0 (not recorded)
  double startX = 0, startY = 0, startHeading = 0;  // m, m, rad
  double outputInterval = 0.01;  // telemetry period, s
  // The driver's input period (a person's device poll, a replay's line, the
  // path follower's decision): each tick runs tick / integrator.step steps.
  double tick = 0.01;          // s
  int raysPerWheel = 1;
  // An enveloping tyre's ground at the wheel in every residual, a point
  // contact's at each step's own end (false: held at the accepted step's
  // prediction, for comparison; vehicle_forces.h).
  bool groundInsideStep = true;
  FidelitySpec fidelity;
  IntegratorSpec integrator;
  SignalSpec steering, throttle, brake;
  SpeedControlSpec speedControl;
  CourseSpec course;
  PathFollowerSpec pathFollower;
  LapTimingSpec laps;
  std::vector<Place> places;
  CheckSpec check;
  StandardTest standardTest = StandardTest::None;
};

// A steering signal in the normalised input s, from steering-wheel angle,
// road-wheel angle (at small angles: the linkage's mean front road-wheel
// angle per unit s) or rack travel; throws config::ConfigError (at
// s.where) when a value is beyond the vehicle's full steering.
SignalSpec normalisedSteering(const SignalSpec& s, const vehicle::Vehicle& linkage);

// "linkage", "kinematic" or "planar"; false for anything else.
bool parseFidelity(const std::string& name, vehicle::Fidelity& out);
// Also "auto".
bool parseFidelity(const std::string& name, FidelitySpec& out);

// Integration steps per driver tick; 0 when the step does not divide the tick.
int stepsPerTick(double tick, double step);

// Loads a scenario file; throws config::ConfigError with file:line; the
// vehicle and terrain paths are resolved relative to the file that names
// them and must exist. Settings (--set KEY=VALUE) apply over the file; those
// whose key starts with "vehicle." apply to the vehicle file (without the
// prefix) when the vehicle is loaded (ScenarioSpec::vehicleSettings).
ScenarioSpec loadScenarioFile(const std::string& path, const std::vector<config::Setting>& settings = {});

}  // namespace bdfcar::scenario
