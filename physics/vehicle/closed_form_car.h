// What the rungs stepped in closed form share (planar_car.h, kinematic_car.h):
// a model written out for its one topology, with the steering an input (no
// rack driver constraints), stepped by the same integrators as the
// multibody model it stands for, and mapped onto that model for everything
// else (telemetry, rendering, switches between rungs, run states): the
// multibody model stays the one definition of the car's coordinates.
//
// Each holds its chassis first (the planar base's planar joint, or the
// sprung body's free joint) at q and v index 0, as the multibody models do,
// and says where its wheel spins and its crank are (spinV, engineV).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "integrator/dae.h"
#include "integrator/step_types.h"
#include "autodiff.h"
#include "multibody/multibody_dae.h"
#include "multibody/time_signal.h"
#include "portable_math.h"
#include "terrain/terrain.h"
#include "vehicle/vehicle_builder.h"
#include "vehicle/vehicle_forces.h"

namespace bdfcar::vehicle {

// The closed forms' equations are written for a scalar type T: double (the
// residual) or ad::Dual (their Jacobian, autodiff.h).
template <typename T>
using Vec3T = Eigen::Matrix<T, 3, 1>;
template <typename T>
using Mat3T = Eigen::Matrix<T, 3, 3>;

class ClosedFormCar : public integ::Dae {
 public:
  ClosedFormCar(const Vehicle& v, const terrain::Terrain& terrain, const TerrainContactOptions& options);

  // The rack travel (m along the rack, as the multibody model's rack drivers).
  void setRack(const mb::TimeSignal* rack) { rack_ = rack; }
  void setLimits(const mb::StateLimits& l) { limits_ = l; }
  VehicleForces& forces() { return forces_; }
  const VehicleForces& forces() const { return forces_; }

  // The multibody model's coordinates for this model's (q, v) at time t
  // (what the rack drives from the rack signal), and back.
  virtual void toMultibody(double t, const integ::Vec& q, const integ::Vec& v, integ::Vec& qm, integ::Vec& vm) const = 0;
  virtual void fromMultibody(const integ::Vec& qm, const integ::Vec& vm, integ::Vec& q, integ::Vec& v) const = 0;
  // A solution point in the multibody model's coordinates, its rack drivers'
  // multipliers (the rack force) from the multibody residual there: view
  // must be that model with forces() as its force provider; its data holds
  // that evaluation after.
  integ::SolutionPoint multibodyPoint(const integ::SolutionPoint& p, mb::MultibodyDae& view);
  // Wheel w's centre (world) at the last residual evaluation, and the
  // chassis frame's origin (world) at positions q.
  const Vec3& wheelCentre(int w) const { return kinematics_[w].centre; }
  virtual Vec3 chassisOrigin(const integ::Vec& q) const = 0;
  // Where wheel w's spin joint rate and the crank's rate (-1: none) are in v.
  virtual int spinV(int w) const = 0;
  virtual int engineV() const = 0;

  int coordinates() const { return n_; }
  integ::DaeSizes sizes() const override { return {nq_, n_, 0}; }
  bool constraintJacobian(double, const integ::Vec&, integ::Mat& Phi_q) override {
    Phi_q.resize(0, n_);  // no constraint: nothing to difference
    return true;
  }
  const std::vector<int>& fastColumns() const override { return fastColumns_; }
  // The wheel spins' columns from their force laws alone, at the last
  // residual's state (integ::Dae::fastColumnParts): each tyre again at its
  // spin moved by a forward difference, its brake, a powertrain's driveline
  // (the clutch and the differential: the crank's torque and every driven
  // wheel's), taken into the equations as the residual takes them
  // (addTyreForces, addDriveTorque). A refresh then costs four tyre
  // evaluations, not four residuals.
  bool hasFastColumnParts() const override { return true; }
  // F_q (along the retraction) and F_v exactly: the derived class's
  // equations evaluated once on dual numbers (autodiff.h), seeded with the
  // tangent increments of the positions the equations read and the
  // velocities, kDirections of them a pass (one pass for the planar rung,
  // two for the kinematic); finite differences above 16 coordinates. The
  // force laws' states and inputs are those of the last residual (as its
  // fast columns').
  bool stateJacobian(double t, const integ::Vec& q, const integ::Vec& v, const integ::Vec& a, integ::Mat& Fq,
                     integ::Mat& Fv) override;
  // F = equations(q, v, a), non-finite F a recoverable failure.
  integ::EvalStatus residual(double t, const integ::Vec& q, const integ::Vec& v, const integ::Vec& a,
                             const integ::Vec& lambda, integ::Residual& out, bool withConstraints,
                             integ::Message& msg) final;
  void fastColumnParts(double t, integ::Mat& parts) override;
  bool fastRowChange(double t, int k, double dv, double& change) override;
  // The chassis' joint (its first coordinates), then plain vector coordinates.
  void retract(const integ::Vec& q, const integ::Vec& dq, integ::Vec& out) const override;
  void localCoordinates(const integ::Vec& base, const integ::Vec& q, integ::Vec& out) const override;
  void localRate(const integ::Vec& delta, const integ::Vec& v, integ::Vec& out) const override;

 protected:
  // A wheel spinning on a revolute joint, symmetric about its axis (the
  // closed forms' wheels): its inertia about the axis and the axis' sign
  // along the wheel's y, and its inertia made exactly symmetric: the two
  // transverse moments' mean for each (data rounded from a sum of parts
  // differ by parts in a million: the sedan's 3.240478 and 3.240496 kg m^2;
  // the multibody model turns that difference with the spin angle, the
  // closed forms do not). Throws mb::ModelError naming the wheel if its
  // centre of mass is off the axis, the axis is not principal or the
  // transverse moments differ by more than kTransverseSpread.
  static constexpr double kTransverseSpread = 1e-3;  // of their mean
  struct SpinJoint {
    double inertia = 0;  // kg m^2 about the spin axis
    double sign = 1;     // the joint's axis along the wheel's y (+1 or -1)
    Mat3 symmetric;      // the whole inertia, symmetric about the axis (wheel axes)
  };
  static SpinJoint spinJoint(const mb::Body& wheel, const std::string& name, const std::string& model);
  // A body's rotational inertia with its rotor's (Body::rotorInertia), body axes.
  static Mat3 fullInertia(const mb::Body& b) {
    const Vec3 axis = b.rotorAxis.normalized();  // as the multibody model takes it (ModelBuilder::addBody)
    return b.inertia + b.rotorInertia * axis * axis.transpose();
  }

  // The rack at t as the step sees it: its acceleration is its rate's change
  // over the step, so that a jump of the rate (a steering signal's kink: an
  // impulse in the acceleration) moves the steering's inertia as the
  // multibody form's driven coordinates do, instead of being lost between
  // two samples.
  mb::SignalValue rackInStep(double t) const;
  // The multibody model's driven coordinates (q, v) set from the rack signal at t.
  void driveMultibody(double t, integ::Vec& qm, integ::Vec& vm) const;
  // Wheel w's tyre output, its drive torque (per N m) and its spin joint's
  // sign along the wheel's y, into the equations as the last residual took
  // them (its geometry): scale times what they add to F (the inertial less
  // the applied forces) added to col.
  virtual void addTyreForces(int w, const tyre::TyreOutput& tyre, double scale, Eigen::Ref<integ::Vec> col) const = 0;
  virtual void addDriveTorque(int w, double scale, Eigen::Ref<integ::Vec> col) const = 0;
  virtual double spinSign(int w) const = 0;
  // Whether tangent coordinate j is an angle the equations do not read (a
  // wheel's spin angle, the crank's: symmetric rotors), its F_q column zero.
  bool angleOnly(int j) const {
    for (int w = 0; w < 4; ++w)
      if (j == spinV(w)) return true;
    return engineV() >= 0 && j == engineV();
  }
  // The equations F(q, v, a) for doubles (the residual: the derived class
  // also keeps what the step's acceptance, the fast columns and telemetry read).
  virtual void equationsOf(double t, const double* q, const double* v, const integ::Vec& a, double* F) = 0;
  // The same on dual numbers (q the retracted positions, v the
  // velocities): what stateJacobian differentiates. False: not written for
  // them (finite differences).
  virtual bool dualEquations(double /*t*/, const ad::Dual* /*q*/, const ad::Dual* /*v*/, const integ::Vec& /*a*/,
                             ad::Dual* /*F*/) {
    return false;
  }
  // The drive torques the equations take: the crank's own torque (the
  // engine's less the clutch's, 0 without a powertrain) and each wheel's,
  // from a powertrain's driveline at the crank's rate and the wheels' spins
  // relative to their carriers now, or as the driver holds them. T double
  // (the residual: the driveline's state and the wheels' torques stored, as
  // the multibody form's) or ad::Dual (nothing stored).
  template <typename T>
  struct DriveTorques {
    T crank = T(0.0);
    std::array<T, 4> wheel{T(0.0), T(0.0), T(0.0), T(0.0)};
  };
  template <typename T>
  DriveTorques<T> driveTorques(const T& engineSpeed, const std::array<T, 4>& relativeSpins, double h);
  // Wheel w's tyre at kinematics k (load: a planar model's), h after the
  // last accepted step: for doubles as the residual keeps it (the wheel's
  // kinematics and relative spin kept, the output in forces()), for dual
  // numbers into dual, nothing kept.
  template <typename T>
  const tyre::TyreOutputT<T>& wheelTyre(int w, const tyre::WheelKinematicsT<T>& k, const T& relativeSpin, double h,
                                         std::optional<T> load, tyre::TyreOutputT<T>& dual) {
    if constexpr (std::is_same_v<T, double>) {
      kinematics_[w] = k;
      relativeSpin_[w] = relativeSpin;
      return forces_.evaluateTyre(w, k, h, load);
    } else {
      forces_.tyreForce(w, k, h, load, dual);
      return dual;
    }
  }
  // The acceptance both closed forms make: a non-finite or runaway state is
  // fatal; otherwise the force laws advance over the step with the last
  // residual's wheel kinematics (as the multibody model's acceptance does).
  integ::EvalStatus acceptWheels(double t, double h, const integ::Vec& q, const integ::Vec& v, integ::Message& msg);

  const Vehicle& vehicle_;
  int n_ = 0, nq_ = 0;
  // The chassis' joint and its position and velocity coordinates (planar: 3
  // and 3; free: 7 and 6), set by the derived class.
  mb::JointType chassisJoint_ = mb::JointType::Free;
  int chassisQ_ = 7, chassisV_ = 6;
  VehicleForces forces_;
  const mb::TimeSignal* rack_ = nullptr;
  mb::StateLimits limits_;
  std::vector<int> fastColumns_;                         // the spins
  std::vector<std::pair<int, int>> drivenCoordinates_;   // multibody (q, v) indices the rack drivers tie
  // The last residual evaluation's wheel kinematics and spins relative to
  // their carriers (what the step's acceptance advances the force laws with).
  std::array<tyre::WheelKinematics, 4> kinematics_;
  std::array<double, 4> relativeSpin_{};
  double engineSpeed_ = 0;  // a powertrain's crank rate relative to the chassis, at the last residual

 private:
  VehicleForces::DrivelineTorques drivelineNow(double h) const;
  void addSpinChange(int w, double dv, double per, double h, const VehicleForces::DrivelineTorques& T0,
                     Eigen::Ref<integ::Vec> col) const;
  integ::Vec rowScratch_;  // fastRowChange's column

 private:
  // The sine and cosine of a planar base's heading at the last base angle
  // seen (its bits): every retraction and local coordinate of a step is
  // taken around the same node, so one sincos serves the step's five or so.
  // A cache in const methods, as KinematicCar's rows: a car belongs to one
  // simulation, stepped by one thread.
  const pm::SinCos& baseHeading(double yaw) const;
  mutable bool headingKnown_ = false;
  mutable std::uint64_t headingAngleBits_ = 0;
  mutable pm::SinCos heading_{};
};

}  // namespace bdfcar::vehicle
