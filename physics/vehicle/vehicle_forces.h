// The forces a vehicle adds to its multibody model: tyres on the terrain,
// drive and brake torques on the wheel spin joints, aerodynamic drag.
//
// Terrain: rays are cast once per step, where the wheels will be: from the
// accepted state extrapolated over the next step (x + v h; at the first step
// from the predicted state). Within the step a point-contact tyre sees that
// local plane, so the residual stays smooth for Newton and the
// finite-difference Jacobian. An enveloping tyre (tyre/envelope.h) gets the
// road profile along its wheel plane instead, once per step from a height
// lattice the rays fill, and its cams ride on it at the wheel's position in
// every residual: the ground follows the wheel inside the step. Tyres are evaluated
// inside the residual (implicit), which is what keeps the stiff slip dynamics
// (h * lambda ~ 6 at 10 ms) stable.
//
// A planar model (no vertical motion) gives each tyre its normal load from
// its load transfer instead of the tyre's deflection: see planarLoads.
//
// Anti-roll bars act between the wheel centres and the chassis, on the
// suspension travel, whatever the rung.
//
// Drive torques react where the vehicle file says (chassis, carrier or nowhere).
// A car with a powertrain gets them from its driveline instead (powertrain.h):
// the engine's torque on its crank joint (reacting on the chassis), the
// clutch's torque from the crank into the gearbox, and the gearbox output
// shared among the driven wheels by the differential, reacting on the chassis.
// Aerodynamic lift is a force on the chassis above each axle (rolling
// resistance is the tyre's, tyre/fiala.h).
// Brakes hold without creep: the brake torque is a stiff torsional spring
// (with damping) on the spin angle since the wheel last slipped, saturated
// at the available brake torque; its deflection advances once per accepted
// step (backward Euler inside the step). At speed it saturates at once and
// is plain Coulomb friction.
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <vector>

#include "multibody/multibody_dae.h"
#include "terrain/height_lattice.h"
#include "terrain/terrain.h"
#include "vehicle/powertrain.h"
#include "tyre/tyre_model.h"
#include "vehicle/vehicle_builder.h"

namespace bdfcar::vehicle {

struct TerrainContactOptions {
  int raysPerWheel = 1;          // 1: plane under the wheel centre; >1: envelope over the footprint
  double footprintHalfLength = 0.6;  // of the unloaded radius, for the extra rays
  // An enveloping tyre's cams placed at the wheel in every residual, and a
  // point contact's plane cast again at the end of a step other than the
  // one the accepted step prepared for (true); or both held where the
  // accepted step's prediction put them (false: the frozen ground, kept to
  // show what it costs, tests/test_envelope.cpp).
  bool groundInsideStep = true;
};

// One wheel's force-law state (plain data, part of the run state): what
// carries from step to step, and what the last accepted step produced.
struct WheelContact {
  tyre::ContactPlane plane;      // the ground at the step's predicted position
  tyre::RoadProfile profile;     // an enveloping tyre's road along its wheel plane for the step
  tyre::SlipState slip;          // transient slips at the last accepted step
  double brakeDeflection = 0;    // rad, brake spring at the last accepted step
  double driveTorque = 0;        // N m about the spin axis (+ drives forward)
  double brakeCapacity = 0;      // N m available now
  // The tyre at the last accepted step (what `auto`'s policy and a planar
  // model's load transfer read).
  Eigen::Vector3d acceptedForce = Eigen::Vector3d::Zero();  // N, world
  bool acceptedInContact = false;
  double acceptedFx = 0, acceptedFy = 0, acceptedFz = 0;     // N, contact frame
  bool operator==(const WheelContact&) const = default;
};

// One wheel's outputs of the latest evaluation (a residual, a sample): not
// state, recomputed by every evaluation; read after one.
struct WheelOutput {
  tyre::TyreOutput out;
  double spinRate = 0;           // absolute, rad/s
  double modelLoad = 0;          // N, a planar model's normal load
  double cornerSpring = 0, cornerDamper = 0;  // N, a planar model's corner spring and damper at the wheel, + pushing the body up
};

class VehicleForces final : public mb::ForceProvider {
 public:
  VehicleForces(const Vehicle& vehicle, const terrain::Terrain& terrain, const TerrainContactOptions& options = {});
  VehicleForces(const VehicleForces&) = delete;  // it points into its own state
  VehicleForces& operator=(const VehicleForces&) = delete;

  // Inputs, held over a step.
  void setDriveTorque(int wheel, double torque) { state_->wheels[wheel].driveTorque = torque; }
  void setBrakeCapacity(int wheel, double torque) { state_->wheels[wheel].brakeCapacity = torque; }
  // A powertrain's command for the next step (ignored without one).
  void setDriveline(const DrivelineCommand& c) { state_->driveline.command = c; }
  const DrivelineState& driveline() const { return state_->driveline; }

  // The planes are cast at acceptance for a step as long as the accepted one;
  // a step ending elsewhere (a refined step's halves, the pieces after them)
  // casts its point contacts' again at its own predicted end (an enveloping
  // tyre's ground follows the wheel inside the step: its profile stays).
  bool needsBeginStep(double t) const override {
    return !state_->planesReady || (pointContacts_ && t != state_->planesFor && state_->planesFor != kAnyStep);
  }
  void beginStep(const mb::Model& model, const mb::Data& data, double t) override;
  void apply(const mb::Model& model, mb::Data& data, double t) override;
  void acceptStep(const mb::Model& model, const mb::Data& data, double t, double h) override;
  // The wheel spins' columns from the tyres and brakes (their forces change
  // tenfold with the slip and the load) and a powertrain's driveline (its
  // clutch and differential couple the driven spins to each other and to
  // the crank).
  bool hasFastColumnParts() const override { return true; }
  void addFastColumnParts(const mb::Model& model, const mb::Data& data, double t, const std::vector<int>& columns,
                          Eigen::MatrixXd& parts) override;
  bool addFastRowChange(const mb::Model& model, const mb::Data& data, double t, int column, double dv,
                        double& change) override;

  // The force laws of one wheel from its kinematics alone, for a model that
  // is not an mb::Model (the closed-form planar car, planar_car.h); apply()
  // and acceptStep() go through the same functions.
  // The contact planes under wheel centres at the predicted end t of a step
  // (what beginStep casts from a multibody model's positions): every wheel's
  // at the start of a run, the point contacts' for a step other than the one
  // prepared at acceptance (needsBeginStep).
  void beginContacts(double t, const std::array<Eigen::Vector3d, 4>& centres,
                     const std::array<Eigen::Vector3d, 4>& spinAxes);
  // The tyre at k on the wheel's contact plane (outputs()[w] holds it after).
  const tyre::TyreOutput& evaluateTyre(int w, const tyre::WheelKinematics& k, double h, std::optional<double> load);
  // The brake's torque about the spin axis (+ with the spin) at a spin
  // relative to the carrier, h after the last accepted step; T double or
  // ad::Dual (below).
  template <typename T>
  T brakeTorque(int w, const T& relativeSpin, double h) const;
  // The tyre as evaluateTyre takes it, for a scalar type T (double, or
  // ad::Dual where a closed form differentiates its residual: autodiff.h),
  // nothing stored: on the ground the residual sees (the step's plane, or
  // an enveloping tyre's cams at k's centre).
  template <typename T>
  void tyreForce(int w, const tyre::WheelKinematicsT<T>& k, double h, std::optional<T> load,
                 tyre::TyreOutputT<T>& out) const;
  // Advances wheel w's states over an accepted step of length h (transient
  // slips, brake spring, the accepted tyre force) and casts its next contact
  // plane, hNext ahead; then markAccepted(t, hNext) once for the four.
  void acceptWheel(int w, const tyre::WheelKinematics& k, double relativeSpin, double h, double hNext);
  // Wheel w's tyre at kinematics k on the ground, slip state and load of
  // its latest evaluation, h after the last accepted step, nothing stored:
  // a closed-form model's fast columns (a tyre at a spin moved by
  // spinIncrement), as addFastColumnParts takes a multibody model's.
  tyre::TyreOutput tyreAt(int w, const tyre::WheelKinematics& k, double h) const;
  // The forward-difference increment of a spin rate (rad/s) for its forces' column.
  static double spinIncrement(double spinRate);
  // A powertrain's driveline at the crank's speed relative to the chassis
  // and the wheels' spins relative to their carriers: the crank's joint
  // torque (the engine's less the clutch's); the driven wheels' drive
  // torques go into their WheelContact. acceptDriveline advances the clutch
  // over an accepted step of length h.
  double drivelineTorques(double engineSpeed, const std::array<double, 4>& spins, double h);
  void acceptDriveline(double engineSpeed, const std::array<double, 4>& spins, double h);
  // The driveline's torques at the crank's and the wheels' speeds, from its
  // state, nothing stored (drivelineTorques stores them there); T double or
  // ad::Dual.
  template <typename T>
  struct DrivelineTorquesT {
    T engine = T(0.0), clutch = T(0.0), output = T(0.0);  // N m, N m, rad/s (the differential's output speed)
    std::array<T, 4> drive{T(0.0), T(0.0), T(0.0), T(0.0)};  // N m, the driven wheels'
  };
  using DrivelineTorques = DrivelineTorquesT<double>;
  template <typename T>
  DrivelineTorquesT<T> drivelineAt(const T& engine, const std::array<T, 4>& spins, double h) const;
  const std::vector<int>& drivenWheels() const { return driven_; }
  void markAccepted(double t, double hNext = 0);
  double sinceAccepted(double t) const { return std::max(0.0, t - state_->lastAccepted); }
  // A planar model's load from its roll centres and pitch axis: the share of
  // each wheel's load the accepted tyre forces move (the base's forward and
  // left axes in the world).
  // T double or ad::Dual.
  template <typename T>
  std::array<T, 4> planarLoadShift(const tyre::Vec3T<T>& forward, const tyre::Vec3T<T>& left) const;
  // A model's own outputs of wheel w (the closed-form planar car's loads and corner springs).
  WheelOutput& output(int w) { return outputs_[w]; }

  const std::array<WheelContact, 4>& wheels() const { return state_->wheels; }
  // The latest evaluation's outputs (after apply(): a residual or a sample).
  const std::array<WheelOutput, 4>& outputs() const { return outputs_; }
  // Resets the per-step states (start of a run).
  void reset(double t);

  // What the force laws carry from step to step, as one value (part of the
  // run state): per wheel the contact plane, transient slips, brake spring,
  // held inputs and the accepted step's tyre force; the time of the last
  // accepted step. The latest evaluation's outputs are not in it.
  struct State {
    std::array<WheelContact, 4> wheels;
    DrivelineState driveline;
    double lastAccepted = 0;
    bool planesReady = false;
    double planesFor = 0;  // the time of the step's end the planes were cast for (kAnyStep: a run's first)
    bool operator==(const State&) const = default;
  };
  const State& state() const { return *state_; }
  void setState(const State& s) { *state_ = s; }
  // The force laws work on s from now on (a run state's, which the
  // simulation owns); their own until then.
  void bindState(State& s) { state_ = &s; }

  static constexpr double kAnyStep = -std::numeric_limits<double>::infinity();  // State::planesFor
  static constexpr double kBrakeStiffness = 1.0e5;  // N m/rad
  static constexpr double kBrakeDamping = 1.0e3;    // N m s/rad

 private:
  // A planar model's wheel attitude for its tyre (PlanarLoads::turnPerTravel).
  void planarWheelAttitude(const mb::Data& d, int w, tyre::WheelKinematics& k) const;
  std::array<double, 4> cornerTravel_{};  // m, a planar model's suspension travel from static (+ bump), per evaluation
  // The ground under wheel w for the next step, at its predicted centre:
  // the plane (point contact) or the road profile and the plane it gives.
  // travel: the wheel centre's move over the predicted step (sampleProfile).
  void prepareGround(int w, const Eigen::Vector3d& centre, const Eigen::Vector3d& spinAxis,
                     const Eigen::Vector3d& travel = Eigen::Vector3d::Zero());
  tyre::ContactPlane queryGround(const Eigen::Vector3d& centre, const Eigen::Vector3d& spinAxis, double radius) const;
  void sampleProfile(int w, const Eigen::Vector3d& centre, const Eigen::Vector3d& spinAxis,
                     const Eigen::Vector3d& travel);
  // Fills p (its line and samples set) when the terrain says the road
  // under it is level; false otherwise.
  bool levelProfile(tyre::RoadProfile& p, double zTop, double reach) const;
  // Whether wheel w's ground follows the wheel inside the step (an
  // enveloping tyre's cams on the step's profile) rather than the step's plane.
  bool groundFollowsWheel(int w) const { return envelopes_[w].on && options_.groundInsideStep; }
  // The ground a tyre at centre feels in a residual: the step's plane (a
  // point contact), or the envelope's at centre (kept in insideStep_[w]).
  const tyre::ContactPlane& groundAt(int w, const Eigen::Vector3d& centre);
  // The ground of wheel w's latest evaluation (what groundAt last gave).
  const tyre::ContactPlane& latestGround(int w) const;
  tyre::WheelKinematics wheelKinematics(const mb::Data& data, int wheel) const;
  double relativeSpin(const mb::Data& data, int wheel) const;
  // A planar model's normal loads (PlanarLoads): the corner springs' forces
  // go on the sprung body and the base, the loads into outputs_[w].modelLoad.
  void planarLoads(mb::Data& data);
  // The anti-roll bars (AntiRollBarSpec): forces between each wheel centre
  // and the chassis; on a planar model also its tyres' loads.
  void antiRollBars(mb::Data& data);
  // The powertrain (powertrain.h): engine and clutch torques on the crank,
  // the drive torques of the driven wheels into state_->wheels[w].driveTorque.
  void powertrain(mb::Data& data, double h, const std::array<double, 4>& spins);
  double engineSpeed(const mb::Data& data) const;
  // Mean of the driven wheels' spins relative to their carriers (spins: all four), + forward.
  template <typename T>
  T drivenSpeed(const std::array<T, 4>& spins) const;
  void applyDriveTorque(mb::Data& data, int wheel, const tyre::WheelKinematics& k) const;
  void addDriveTorqueColumn(const mb::Model& model, const mb::Data& data, int wheel, const tyre::WheelKinematics& k,
                            double scale, Eigen::Ref<Eigen::VectorXd> out) const;
  void aerodynamics(mb::Data& data) const;
  // The wheels where the last apply() took them, for their spins' columns.
  struct SpinPoint {
    std::array<tyre::WheelKinematics, 4> ks;
    std::array<double, 4> spins{};
    bool driveline = false;
    double engine = 0, h = 0;
    DrivelineTorques T0;
  };
  SpinPoint spinPoint(const mb::Data& data, double t) const;
  void addSpinChange(const mb::Model& model, const mb::Data& data, const SpinPoint& p, int w, double dv, double per,
                     Eigen::Ref<Eigen::VectorXd> part) const;
  Eigen::VectorXd rowScratch_;  // addFastRowChange's column
  std::optional<double> modelLoad(int w) const {
    return vehicle_.planar ? std::optional<double>(outputs_[w].modelLoad) : std::nullopt;
  }

  const Vehicle& vehicle_;
  const terrain::Terrain& terrain_;
  TerrainContactOptions options_;
  std::array<tyre::Tyre, 4> tyres_;
  std::array<tyre::Envelope, 4> envelopes_;  // each tyre's cams (off: the point contact)
  bool pointContacts_ = false;  // a wheel whose ground is the step's plane, cast again for another step's end
  std::array<tyre::ContactPlane, 4> insideStep_;  // an enveloping tyre's ground at its latest evaluation
  // The enveloping tyres' road, cast node by node (none without one: the
  // lattice's table is 0.6 MB).
  std::optional<terrain::HeightLattice> lattice_;
  State own_;              // the state until bindState
  State* state_ = &own_;   // planesReady: contact planes of the next step prepared at acceptance
  std::array<WheelOutput, 4> outputs_;
  std::vector<int> driven_;  // the driven wheels
};

}  // namespace bdfcar::vehicle
