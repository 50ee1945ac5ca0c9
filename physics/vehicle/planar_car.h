// The planar rung in closed form (issue 25): the equations of motion of the
// planar model (planar_model.h) written out for its one topology, with the
// steering as an input, instead of the generic multibody machinery (joint
// recursion, rack drivers as constraints, their multipliers). 9 coordinates,
// no constraint: the base's x, y and yaw on the road plane, the sprung
// body's roll and pitch about the roll axis, the four wheel spins.
//
// Everything is taken from the multibody planar model it stands for (one
// derivation, one set of numbers): the sprung body as it is (mass, centre
// of mass, inertia, its universal joint); the bodies fixed in the base (the
// base, the unsteered wheels) lumped into one; those the rack moves (the
// rack, the steered carriers and wheels) as tables over the rack travel,
// sampled from the multibody model and evaluated once per step at the rack
// signal: their first moment, yaw inertia and angular momentum per rack
// rate (the steering's own inertia), each steered wheel's centre, axis and
// the carrier's turn about that axis; each wheel's spin inertia about its
// axis. The forces are VehicleForces' force laws, fed by per-wheel
// kinematics (one tyre model, one terrain query path): tyres with the
// planar load transfer and wheel attitude, brakes, drive torques, anti-roll
// bars, drag and lift.
//
// A powertrain's engine is one more coordinate: a rotor about the sprung
// body's x axis (its crank), driven by the engine and clutch torques, whose
// spin the sprung body feels (its inertia about the crank, its gyroscopic
// moment).
//
// Not carried (the constructor refuses, the multibody planar model runs
// instead): wheels that are not symmetric about their spin axis, other
// bodies on the sprung body.
//
// Coordinates: q = (x, y, yaw, roll, pitch, spin FL FR RL RR[, crank]) as
// the multibody model's planar, universal, spin and crank joints; v =
// (forward, sideways in the base frame, yaw rate, roll rate, pitch rate, the
// spins' joint rates[, the crank's rate relative to the body]).
#pragma once

#include <array>
#include <vector>

#include "multibody/spline_grid.h"
#include "terrain/terrain_data.h"
#include "vehicle/closed_form_car.h"

namespace bdfcar::vehicle {

class PlanarCar final : public ClosedFormCar {
 public:
  static constexpr int kCoordinates = 9;  // without an engine
  enum Index { X = 0, Y = 1, Yaw = 2, Roll = 3, Pitch = 4, Spin = 5, Engine = 9 };  // q; v: forward, sideways, yaw rate, ...

  // planar: a multibody planar model (Vehicle::planar set). Throws
  // mb::ModelError naming what the closed form does not carry.
  PlanarCar(const Vehicle& planar, const terrain::Terrain& terrain, const TerrainContactOptions& options = {});

  // The multibody planar model's coordinates (its rack and steered carriers
  // from the rack signal), and back.
  void toMultibody(double t, const integ::Vec& q, const integ::Vec& v, integ::Vec& qm, integ::Vec& vm) const override;
  void fromMultibody(const integ::Vec& qm, const integ::Vec& vm, integ::Vec& q, integ::Vec& v) const override;
  Vec3 chassisOrigin(const integ::Vec& q) const override;
  int spinV(int w) const override { return Spin + w; }
  int engineV() const override { return engineV_ >= 0 ? int(Engine) : -1; }

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
  double spinSign(int w) const override { return wheels_[w].spinSign; }

 private:
  // A wheel as the closed form sees it, in the base frame.
  struct Wheel {
    double spinInertia = 0;        // kg m^2 about the spin axis
    double spinSign = 1;           // the spin joint's axis along the wheel's y (+1 or -1)
    int table = -1;                // steered: index in tables_; -1: fixed in the base
    Vec3 centre, axisY;            // fixed wheels (and the steered ones at the current rack)
    Vec3 centreRate = Vec3::Zero();  // d centre / d rack travel times the rack rate
    double steeringSpin = 0;         // the carrier's angular velocity about the wheel's axis
    double steeringSpinRate = 0;     // its time derivative
    double tiltRate = 0;             // d/dt of the axis' z component (the steering tilts it)
    int multibodyQ = 0, multibodyV = 0;
  };
  // The geometry of the step's time (the steered wheels at the rack signal).
  void updateSteering(double t);
  // F(q, v, a) for T double (the residual) or ad::Dual (the Jacobian).
  template <typename T>
  void equations(double t, const T* q, const T* v, const integ::Vec& a, T* F);

  // Everything but the sprung body, riding on the base: its mass, first
  // moment in the base plane and yaw inertia about the base origin (at the
  // step's rack travel); what of it the rack moves, over the rack travel
  // (first moment x, y, yaw inertia, angular momentum about z per rack rate);
  // the generalised forces its motion relative to the base asks for.
  double baseMass_ = 0, baseYawInertia_ = 0, fixedYawInertia_ = 0;
  Vec3 baseMoment_ = Vec3::Zero(), fixedMoment_ = Vec3::Zero();  // sum m p (x, y used)
  bool steered_ = false;
  mb::SplineGrid steering_;
  Eigen::Vector2d steeringForce_ = Eigen::Vector2d::Zero(), steeringCoriolis_ = Eigen::Vector2d::Zero();
  double steeringYaw_ = 0, steeringYawCoriolis_ = 0;
  // The sprung body about its roll and pitch axis.
  Vec3 axisPoint_;                  // in the base frame
  Mat3 sprungRest_;                 // body axes in the base frame at zero roll and pitch
  Vec3 jointInBody_;                // the joint point in the body frame
  double sprungMass_ = 0;
  Vec3 comArm0_;                    // axis point -> centre of mass at zero roll and pitch (base frame)
  Mat3 inertia0_;                   // about the centre of mass, base axes at zero roll and pitch
  // Per corner, at zero roll and pitch in the base frame: the corner
  // spring's point on the body from the axis point, the carrier's turn per travel.
  std::array<Vec3, 4> cornerArm_, turnPerTravel_;
  Vec3 gravity_;
  double engineInertia_ = 0;        // kg m^2 about the sprung body's x axis (0: no engine)
  Vec3 crankAxis0_;                 // that axis in the base frame at zero roll and pitch
  int engineQ_ = -1, engineV_ = -1;  // the multibody model's crank coordinate
  double groundZ_ = 0;
  std::array<Wheel, 4> wheels_;
  // Where the last residual took the tyres and drive torques
  // (fastColumnParts): the base's heading and origin, the pitch axis, each
  // tyre's axis (base frame).
  terrain::HeadingTurn turn_;
  Vec3 origin_ = Vec3::Zero(), pitchAxis_ = Vec3::UnitY();
  std::array<Vec3, 4> tyreAxis_;
  std::vector<mb::SplineGrid> tables_;  // steered wheels over the rack travel: centre (3), y axis (3), spin per travel
  double steeringTime_;
  mb::SignalValue rackNow_;       // the rack the steering geometry is at
  bool steeringValid_ = false;
};

}  // namespace bdfcar::vehicle
