// One running scenario. What is built once (the World: vehicle, terrain,
// course) is kept apart from what changes while it runs (the RunState: the
// integrator's history, the force laws' states, the driver's), so that a run
// can be saved, restored, rewound and restarted by assignment.
//
//   Simulation sim(spec);              // builds the world, the force laws, the integrator
//   sim.prepare();                     // assembly, static equilibrium, initial speed, settling
//   sim.beginTick(std::nullopt);       // each driver tick: the scripted driver's decision,
//   sim.beginTick(driverInput);        //   or a person's input, held for the tick
//   for (int i = 0; i < sim.stepsPerTick(); ++i) sim.step();
//   RunState s = sim.save(); ...; sim.restore(s);
//
// The run driver (scenario/run.h) does exactly this for every command.
#pragma once

#include <atomic>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>
#include <stdexcept>
#include <string>

#include "integrator/step_types.h"
#include "multibody/data.h"
#include "multibody/multibody_dae.h"
#include "scenario/driver_input.h"
#include "scenario/fidelity_policy.h"
#include "scenario/iso3888_course.h"
#include "scenario/path_follower.h"
#include "scenario/preview_driver.h"
#include "scenario/rung_certificate.h"
#include "scenario/scenario_spec.h"
#include "scenario/signals.h"
#include "scenario/speed_controller.h"
#include "scenario/steering_system.h"
#include "scenario/telemetry.h"
#include "scenario/transmission.h"
#include "terrain/terrain.h"
#include "vehicle/equilibrium.h"
#include "vehicle/vehicle_builder.h"
#include "vehicle/kinematic_model.h"
#include "vehicle/closed_form_car.h"
#include "vehicle/planar_model.h"
#include "vehicle/vehicle_forces.h"
#include "vehicle/vehicle_sample.h"

namespace bdfcar::scenario {

// The vehicle's data cannot be assembled or brought to static equilibrium at
// the start: bad input (the vehicle file), not a failed simulation.
class PrepareError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The stop flag given to prepare() was set while the car settled (a signal:
// app/interrupt.h): nothing was run yet.
class PrepareInterrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What a scene builds once and every car in it shares, read-only: the
// ground (the terrain file with its Bullet shapes, or the graded plane).
// Cars are added to a scene by building their worlds with it (buildWorld's
// scene argument); each car has its own vehicle, rung, driver and state.
struct Scene {
  std::string terrainFile;   // as the scenario names it (empty: the plane)
  double groundGrade = 0;    // of the plane
  std::shared_ptr<const terrain::Terrain> terrain;
  // Whether a scenario's ground is this scene's (the same file or plane).
  bool holds(const ScenarioSpec& spec) const;
};

// Loads the scenario's terrain file (or makes its plane); throws on bad data.
std::shared_ptr<const Scene> buildScene(const ScenarioSpec& spec);

// What a scenario builds once and never changes while it runs: a car (its
// vehicle and rungs, its course, its scenario) in a scene.
struct World {
  ScenarioSpec spec;
  vehicle::Vehicle vehicle;
  // The linkage the vehicle was derived from (none: the vehicle is the
  // linkage): what a driver steers by (its steering ratio, its single-track
  // model) is the car's, the same on every rung.
  std::shared_ptr<const vehicle::Vehicle> linkage;
  const vehicle::Vehicle& linkageVehicle() const { return linkage ? *linkage : vehicle; }
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const terrain::Terrain> terrain;  // the scene's
  // The ISO 3888 course is the car's: its lanes are sized to the car's width.
  std::optional<Iso3888Course> course;
  int stepsPerTick = 1;                             // spec.tick / spec.integrator.step
  // The derived model against the linkage, when the vehicle is not the linkage.
  std::optional<vehicle::KinematicCheck> kinematicCheck;
  // `auto` with the planar model allowed: the rung it switches down to
  // (`vehicle` is then the kinematic model it switches up to).
  std::optional<vehicle::Vehicle> planar;
  // `auto`: the derived rungs' certificate for this car at this step, and
  // why a rung it does not use was refused (printed by `run`).
  std::optional<LadderCertificate> certificate;
  std::vector<std::string> autoRefusals;
  double planarLevel = std::numeric_limits<double>::infinity();  // the planar rung's certified lateral range (share of mu g)
};

// Loads the vehicle and terrain files and builds the world; throws on bad
// data or a step that does not divide the tick.
std::shared_ptr<const World> buildWorld(const ScenarioSpec& spec);
// A car in a scene built before (its terrain shared, not loaded again);
// throws std::runtime_error when the scenario names another ground.
std::shared_ptr<const World> buildWorld(const ScenarioSpec& spec, std::shared_ptr<const Scene> scene);
// A world for one model already derived from `linkage` (the certificate's
// runs): the scenario's terrain, course and step, the rung as given.
std::shared_ptr<const World> buildWorld(const ScenarioSpec& spec, const vehicle::Vehicle& linkage,
                                        vehicle::Vehicle model);

// Everything that changes while a scenario runs, as one plain value:
// copyable, comparable, restorable. A Simulation owns one and its parts work
// on their members in place (the integrator on `integrator`, the force laws
// on `forces`, the controllers on theirs). The Jacobian is not part of it (a
// run continued from a state evaluates a fresh one).
struct RunState {
  // The models it is a state of: Simulation's fingerprint of its rungs'
  // vehicles (bodies, joints, springs, layout), so that a state of another
  // car with the same sizes is refused, not run.
  std::uint64_t model = 0;
  integ::IntegratorState integrator;
  vehicle::VehicleForces::State forces;
  RackSegment rack;
  double speedIntegral = 0;            // the speed controller's integral, m
  PathFollower::State follower;
  DriverInput input;                   // held for the current tick
  bool scriptedDriver = true;          // the scenario's driver (vs a person's held input)
  double airborne = 0;                 // s with no ground under any wheel
  int rung = 0;                        // the model driving: 0 = world.vehicle, 1 = world.planar
  FidelityPolicy::State fidelity;      // `auto`'s
  TransmissionState transmission;      // a powertrain's gear, shift and clutch
  bool operator==(const RunState&) const = default;
};

// The rack target as a signal: steer s(t) in [-1, 1] -> rack travel.
class RackSignal final : public Signal {
 public:
  // segment: the run state's, where the signal keeps its segment.
  RackSignal(double rackPerSteer, const Signal& scripted, RackSegment& segment)
      : segment(segment), gain_(rackPerSteer), scripted_(scripted) {}
  RackSegment& segment;
  SignalValue at(double t) const override;
  double steerAt(double t) const;
  double rateAt(double t) const;

 private:
  double gain_;
  const Signal& scripted_;
};

class Simulation {
 public:
  explicit Simulation(const ScenarioSpec& spec);
  explicit Simulation(std::shared_ptr<const World> world);
  ~Simulation();

  // Assembly, static equilibrium at the start pose, initial speed, then the
  // settling phase (tau = 0 at its end). Returns the static equilibrium.
  // Throws PrepareError when the vehicle cannot be assembled or settled
  // statically, std::runtime_error when the run diverges while settling.
  // stop: looked at after every settling step; set, prepare throws
  // PrepareInterrupted (a settling of 1e4 s or a step of 1 us takes hours).
  vehicle::EquilibriumReport prepare(const std::atomic<bool>* stop = nullptr);

  // Starts a driver tick: nullopt = the scenario's own driver (scripted
  // signals, evaluated at every step; the path follower decides now), or a
  // person's (a replay's) input, held for the tick. A person's and the path
  // follower's steering reach the rack through the steering system
  // (steering_system.h).
  void beginTick(const std::optional<DriverInput>& input);
  // One integration step of spec().integrator.step seconds.
  integ::StepReport step();
  int stepsPerTick() const { return world_->stepsPerTick; }

  // The run state. save() makes the current point a Jacobian boundary: the
  // next step evaluates a fresh Jacobian, in this run and in any run
  // restored to the state, so both continue bit for bit alike.
  RunState save();
  void restore(const RunState& s);
  // The same as bytes (run_state_bytes.h). restoreBytes throws
  // RunStateBytesError for bytes that are no run state, or one that does
  // not fit this simulation (another vehicle, rung count or model size),
  // and leaves the simulation as it was.
  std::vector<char> saveBytes();
  void restoreBytes(const std::vector<char>& bytes);
  // Why a run state does not fit this simulation (nullopt: it fits).
  std::optional<std::string> misfit(const RunState& s) const;

  double time() const { return integrator_->current().t; }
  // The rung driving now (0: world().vehicle; 1: world().planar under
  // `auto`), how many there are, and a switch to another (the state mapped,
  // the integrator restarted; what `auto` does at a tick).
  int rung() const { return state_.rung; }
  int rungCount() const { return static_cast<int>(rungs_.size()); }
  // False when the switch down was refused: the mapping would have moved
  // the chassis by more than FidelityPolicy::kMaxJump or kMaxTurn.
  bool switchRung(int rung);
  // The largest chassis jump (m) of the switches made since the last call.
  double takeSwitchJump();
  const FidelityPolicy::State& fidelityState() const { return state_.fidelity; }
  long fidelitySwitches() const { return state_.fidelity.switches; }
  // The work of every rung's integrator.
  integ::Counters counters() const;
  integ::Timers timers() const;
  // The largest constraint residual of the current state at the position,
  // velocity and acceleration levels (m or rad, per s, per s^2): the drift a
  // long run must keep bounded.
  struct ConstraintViolation {
    double position = 0, velocity = 0, acceleration = 0;
  };
  ConstraintViolation constraintViolation();
  vehicle::VehicleSample sample();                  // at the current state
  vehicle::VehicleView view();                      // after sample()
  const World& world() const { return *world_; }
  const ScenarioSpec& spec() const { return world_->spec; }
  const vehicle::Vehicle& vehicle() const { return *rungs_[state_.rung].vehicle; }
  // The integrator of the rung driving (a closed form's holds its own coordinates).
  const integ::Integrator& integrator() const { return *integrator_; }
  // The current point in the active rung's multibody coordinates (what the
  // integrator holds, or a closed form's mapped: its rack multipliers from
  // the multibody residual).
  integ::SolutionPoint multibodyPoint();
  const std::optional<Iso3888Course>& course() const { return world_->course; }
  // Steering input in [-1, 1] applied at time t (scripted, path follower or person).
  double steerAt(double t) const { return rack_.steerAt(t); }
  DriverInput lastInput() const { return state_.input; }
  // The car's steering as a person's controls need it (the linkage's).
  CarSteering carSteering() const;
  // Where prepare() puts the car (the scenario's [start] until set): a
  // drive going to one of the scene's places sets it, then prepares again.
  void setStart(double x, double y, double heading) { startX_ = x, startY_ = y, startHeading_ = heading; }
  // The speed the scenario's speed hold keeps now (m/s), or -1 when none
  // does: it drives the car then, whatever the throttle input says.
  double speedHoldTarget() const { return speed_ && speed_->active(time()) ? speed_->target(time()) : -1.0; }
  double driveTorque(int wheel) const { return forces_->wheels()[wheel].driveTorque; }
  // A powertrain's controller (none without a powertrain) and its driveline's latest evaluation.
  const Transmission* transmission() const { return transmission_ ? &*transmission_ : nullptr; }
  const vehicle::DrivelineState& driveline() const { return forces_->driveline(); }
  // The powertrain's telemetry channels now (zeros without one).
  PowertrainChannels powertrainChannels() const;

 private:
  struct StartPose {
    Eigen::Matrix3d rotation;
    Eigen::Vector3d origin;
    double groundZ = 0;
  };
  StartPose startPose() const;
  struct ChassisState {
    Eigen::Vector3d com;
    double yaw = 0, vx = 0, vy = 0, yawRate = 0;  // vx, vy: the centre of mass's, chassis axes
  };
  ChassisState chassisState() const;
  // Its vx alone (what the speed hold reads at every step): no attitude, no trigonometry.
  double forwardSpeed() const;
  // derived: a derived rung's (its own Newton count: FidelitySpec::newtonIterations).
  std::unique_ptr<integ::Integrator> makeIntegrator(integ::Dae& dae, bool derived) const;
  void applyDrive(const DriverInput& in, double vx, double h);
  // A powertrain car's step: the speed hold works the pedals, the
  // transmission decides gear and clutch; the handbrake on the rear wheels.
  void applyPowertrain(DriverInput in, double vx, double h);
  // From the active rung's velocities (multibody: the multibody model's coordinates).
  DrivelineSpeeds drivelineSpeeds(const integ::Vec& v, double vx, bool multibody = false) const;
  void steerToward(double command);
  // The road's friction under the start (the preview driver's grip).
  double startFriction() const;
  // The preview driver's path: the follower's, as signed distances.
  PathOffset pathOffset(const vehicle::Vehicle& veh) const;

  // One model of the vehicle with its force laws and integrator. A derived
  // model steps in closed form where one carries it (car: its own force
  // laws; dae is then the multibody model of the same equations, evaluated
  // for outputs only).
  struct Rung {
    const vehicle::Vehicle* vehicle = nullptr;
    std::unique_ptr<vehicle::VehicleForces> forces;
    std::unique_ptr<mb::MultibodyDae> dae;
    std::unique_ptr<vehicle::ClosedFormCar> car;
    integ::Dae* stepping = nullptr;  // dae or car
    std::unique_ptr<integ::Integrator> integrator;
    mb::Data scratch;  // poses for the switch's jump check (no allocation then)
  };
  // The multibody coordinates of a rung's (q, v) at time t, and back.
  void toMultibody(int rung, double t, const integ::Vec& q, const integ::Vec& v, integ::Vec& qm, integ::Vec& vm) const;
  void fromMultibody(int rung, const integ::Vec& qm, const integ::Vec& vm, integ::Vec& q, integ::Vec& v) const;
  struct ChassisPose {
    Eigen::Vector3d p;
    Eigen::Matrix3d R;
  };
  ChassisPose chassisPose(int rung, const integ::Vec& q);
  Rung makeRung(const vehicle::Vehicle& v);
  void activate(int rung);
  void chooseRung();  // `auto`, at a tick

  std::shared_ptr<const World> world_;
  std::unique_ptr<Signal> steering_, throttle_, brake_;
  // The run state, which the parts below work on in place (each bound to its
  // member): save() is a copy, restore() an assignment. Declared before them.
  RunState state_;
  std::vector<Rung> rungs_;
  std::uint64_t modelFingerprint_ = 0;  // RunState::model of this simulation's states
  // The active rung's parts.
  vehicle::VehicleForces* forces_ = nullptr;
  mb::MultibodyDae* dae_ = nullptr;          // the multibody model (a closed form's: for outputs only)
  vehicle::ClosedFormCar* car_ = nullptr;    // the closed form stepping, if one is
  integ::Dae* stepping_ = nullptr;
  integ::Integrator* integrator_ = nullptr;
  std::optional<FidelityPolicy> policy_;
  double switchJump_ = 0;  // m, for the telemetry: see takeSwitchJump
  std::optional<SpeedController> speed_;
  std::optional<PathFollower> follower_;
  std::optional<PreviewDriver> preview_;  // [driver] law = "preview" (the follower's path, its own steering law)
  std::optional<Transmission> transmission_;
  RackSignal rack_;
  SteeringLimits steeringLimits_;
  bool prepared_ = false;
  double startX_ = 0, startY_ = 0, startHeading_ = 0;  // the start pose (setStart)
  // Time with no ground under any wheel (RunState::airborne): off the edge of
  // a bounded terrain the car would fall for ever, so the run stops with a
  // message instead. A jump off a ramp lasts well under kMaxAirborne.
  static constexpr double kMaxAirborne = 3.0;  // s
  // Where the ground under a planar model's wheel leaves its road plane
  // (FidelityPolicy::level's tolerances): a rough road's or a curb's height,
  // or a slope, needs a rung with heave, roll and pitch.
  std::optional<std::string> offLevelGround() const;
  // The car on its roof or side (chassis up axis below the horizon): the run
  // stops (a drive resets) saying so, never records a car rolling on.
  std::optional<std::string> overturned() const;
  // The start's ground under a wheel off the plane through the four by more
  // than this: a wall or a step under the car.
  static constexpr double kStartGroundStep = 0.25;  // m
  // A wheel centre or the chassis below the ground (any rung): the run stops
  // saying where, never records a car inside the ground.
  std::optional<std::string> belowGround() const;
};

// The vehicle width used for the ISO course: overall width over the tyres.
double vehicleWidth(const vehicle::Vehicle& v);

std::unique_ptr<Signal> makeSignal(const SignalSpec& s);

}  // namespace bdfcar::scenario
