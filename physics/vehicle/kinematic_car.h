// The kinematic rung in closed form (issue 25): the equations of motion of
// the kinematic model (kinematic_model.h) written out for its one topology,
// with the steering an input, instead of the generic multibody machinery
// (joint recursion over 6D motions, the rack and the steered tables' rack
// travel as driver constraints and their multipliers).
//
// Coordinates: q = (chassis position (world) and attitude quaternion (w, x,
// y, z) as the free joint's, travel FL FR RL RR, spin FL FR RL RR[, crank]);
// v = (the chassis origin's velocity and the angular velocity, both in
// chassis axes, the travels' and spins' rates[, the crank's rate relative
// to the chassis]): 14 (15) velocity coordinates, no constraint.
//
// Bodies, all from the multibody model it stands for (one derivation, one
// set of numbers): the chassis; the rack, sliding on it with the rack
// signal; per corner one rigid body (the carrier with its wheel's mass and
// transverse inertia, both constant in the carrier's frame for a wheel
// symmetric about its axis) on the carrier's table over its travel (and the
// rack travel where it steers), evaluated once per residual; the wheel's
// spin as a rotor on it; the crank as a rotor about the chassis' x axis.
// Equations by virtual power (Kane's form) in chassis axes: each corner's
// inertial and applied forces reduced to a wrench about its carrier's
// origin, projected on the chassis' six motions and its own travel.
// Forces: VehicleForces' force laws fed by per-wheel kinematics (one tyre
// model, one terrain query path), the springs and dampers through the
// tables' lengths, the anti-roll bars, drag and lift.
//
// Not carried (the constructor refuses, the multibody kinematic model runs
// instead): bodies other than these, point-to-point springs, wheels not
// symmetric about their spin axis.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "vehicle/closed_form_car.h"

namespace bdfcar::vehicle {

class KinematicCar final : public ClosedFormCar {
 public:
  static constexpr int kPositions = 15, kCoordinates = 14;  // without an engine
  // Indices of the travels and spins in q (Q) and v (V), the crank's last.
  static constexpr int TravelQ = 7, SpinQ = 11, EngineQ = 15;
  static constexpr int TravelV = 6, SpinV = 10, EngineV = 14;

  // kinematic: a kinematic model (deriveKinematic). Throws mb::ModelError
  // naming what the closed form does not carry.
  KinematicCar(const Vehicle& kinematic, const terrain::Terrain& terrain, const TerrainContactOptions& options = {});

  void toMultibody(double t, const integ::Vec& q, const integ::Vec& v, integ::Vec& qm, integ::Vec& vm) const override;
  void fromMultibody(const integ::Vec& qm, const integ::Vec& vm, integ::Vec& q, integ::Vec& v) const override;
  Vec3 chassisOrigin(const integ::Vec& q) const override { return q.head<3>(); }
  int spinV(int w) const override { return SpinV + w; }
  int engineV() const override { return engineMultibodyV_ >= 0 ? int(EngineV) : -1; }

  void beginStep(double t, const integ::Vec& q, const integ::Vec& v) override;
  integ::EvalStatus acceptStep(double t, double h, const integ::Vec& q, const integ::Vec& v,
                               integ::Message& msg) override;
  bool massMatrix(double t, const integ::Vec& q, integ::Mat& Fa) override;

 protected:
  void equationsOf(double t, const double* q, const double* v, const integ::Vec& a, double* F) override {
    equations(t, q, v, a, F);
  }
  bool dualEquations(double t, const ad::Dual* q, const ad::Dual* v, const integ::Vec& a, ad::Dual* F) override {
    equations(t, q, v, a, F);
    return true;
  }
  void addTyreForces(int w, const tyre::TyreOutput& tyre, double scale, Eigen::Ref<integ::Vec> col) const override;
  void addDriveTorque(int w, double scale, Eigen::Ref<integ::Vec> col) const override;
  double spinSign(int w) const override { return corners_[w].spinSign; }

 private:
  // A corner: the carrier and its wheel as one body over the carrier's table.
  struct Corner {
    const mb::SplineGrid* table = nullptr;  // pose (3 + 3 angles) and the springs' lengths over travel (and rack)
    Mat3 rest = Mat3::Identity();           // the table's rest rotation
    bool steered = false;                   // tabulated over the rack travel too
    double mass = 0;
    Vec3 com = Vec3::Zero();                // carrier frame
    Mat3 inertia = Mat3::Zero();            // about com, carrier axes (the wheel's whole, it is symmetric)
    double spinInertia = 0, spinSign = 1;   // the wheel about its axis; the joint's axis along its y
    Vec3 axisY = Vec3::UnitY();             // the wheel's y axis, carrier frame
    Vec3 centre = Vec3::Zero();             // the wheel's centre, carrier frame
    std::vector<std::pair<int, int>> springs;  // (model spring, table component)
    int travelQ = 0, travelV = 0, spinQ = 0, spinV = 0;  // the multibody model's
  };
  // A corner's pose and motion relative to the chassis at one evaluation
  // (chassis axes): its table at the travel and rack, the rates' share. T
  // double, or a Dual (the Jacobian: the travel and its rate dual).
  template <typename T>
  struct CornerMotionT {
    Mat3T<T> R;                    // carrier axes in chassis axes
    Vec3T<T> t;                    // carrier origin
    Vec3T<T> ts, ws;               // origin velocity and angular velocity per unit travel rate
    Vec3T<T> velocity, omega;      // relative origin velocity and angular velocity at the rates
    Vec3T<T> accelBias, alphaBias; // relative accelerations but the travel's acceleration's share
    T springForce = T(0.0);        // the springs' and dampers' generalised force on the travel (+ pushing it up)
  };
  using CornerMotion = CornerMotionT<double>;
  // withRates false: the pose and the partials alone (positions only).
  // (T ad::Dual: cornerMotionOn on the corner's two directions, lifted.)
  template <typename T>
  void cornerMotion(int w, const T& travel, const T& travelRate, CornerMotionT<T>& m, bool withRates) const;
  template <typename T>
  void cornerMotionOn(int w, const T& travel, const T& travelRate, CornerMotionT<T>& m, bool withRates) const;
  // A corner's table at a travel and the step's rack travel, the angles'
  // sines and cosines and the pose from them.
  template <typename T>
  struct CornerPoseT {
    mb::SplineGrid::SampleT<T> s;
    T phiS, phiC, thetaS, thetaC;  // of the roll and pitch angles (the rates need them)
    Mat3T<T> R, E;                 // E: the angles' rates to the angular velocity, carrier axes
    Vec3T<T> t, ts, w0;
  };
  template <typename T>
  void poseAt(int w, const T& travel, CornerPoseT<T>& P) const;
  // The double one kept for the last (travel, rack) pair, a pure function
  // of the two (where the ground needs beginStep, the step's first residual
  // is at the travel it took; a finite-difference Jacobian moves a corner's
  // travel in 2 of its 2 nv + 1 residuals).
  struct CornerPose : CornerPoseT<double> {
    std::uint64_t travelBits = 0, rackBits = 0;
    bool valid = false;
  };
  const CornerPose& cornerPose(int w, double travel) const;
  // F(q, v, a) for T double (the residual) or ad::Dual (the Jacobian).
  template <typename T>
  void equations(double t, const T* q, const T* v, const integ::Vec& a, T* F);
  void updateSteering(double t);

  Vec3 gravity_;
  // The chassis body (its frame is the free joint's).
  double chassisMass_ = 0;
  Vec3 chassisCom_;
  Mat3 chassisInertia_;
  // The rack: its centre of mass over the rack travel, its inertia (chassis axes).
  double rackMass_ = 0;
  Vec3 rackCom0_, rackAxis_;
  Mat3 rackInertia_;
  // The crank: a rotor about the chassis' x axis.
  double engineInertia_ = 0;
  int engineMultibodyQ_ = -1, engineMultibodyV_ = -1;
  std::array<Corner, 4> corners_;
  // Where the last residual took the tyres and drive torques
  // (fastColumnParts): the chassis' attitude and origin, the corners' motion.
  Mat3 chassisAxes_ = Mat3::Identity();
  Vec3 chassisOrigin_ = Vec3::Zero();
  std::array<CornerMotion, 4> motions_;
  // Each corner's table in the travel's cell, contracted along the rack at
  // the step's rack travel where it is steered (SplineGrid::RowCache): the
  // residuals of a step evaluate cubics in the travel.
  mutable std::array<mb::SplineGrid::RowCache, 4> rows_;
  mutable std::array<CornerPose, 4> poses_;
  // The rack at the step's time.
  double steeringTime_;
  mb::SignalValue rackNow_;
};

}  // namespace bdfcar::vehicle
