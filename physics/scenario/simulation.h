// One running scenario: vehicle, terrain, forces, integrator and the
// scripted driver, advanced one step at a time. Used by batch runs
// (`bdfcar run`), the reports and the interactive game loop alike.
//
//   Simulation sim(spec);        // loads and builds
//   sim.prepare();               // assemble, static equilibrium, initial speed, settle
//   while (sim.time() < end) sim.step();            // scripted driver
//   sim.step(driverInput);                          // or a person's input
#pragma once

#include <memory>
#include <optional>

#include "integrator/step_types.h"
#include "multibody/multibody_dae.h"
#include "scenario/driver_input.h"
#include "scenario/iso3888_course.h"
#include "scenario/path_follower.h"
#include "scenario/scenario_spec.h"
#include "scenario/signals.h"
#include "scenario/speed_controller.h"
#include "terrain/terrain.h"
#include "vehicle/equilibrium.h"
#include "vehicle/vehicle_builder.h"
#include "vehicle/vehicle_forces.h"
#include "vehicle/vehicle_sample.h"

namespace bdfcar::scenario {

// The rack target as a driver signal: steer s(t) in [-1, 1] -> rack travel.
class RackSignal final : public mb::DriverSignal {
 public:
  RackSignal(double rackPerSteer) : gain_(rackPerSteer) {}
  // Scripted: an analytic steering signal.
  void setScripted(const Signal* s) { scripted_ = s; }
  // Interactive: reach `steer` at the end of the step [t0, t1] linearly (as a
  // real rack follows a sampled input), held afterwards.
  void setSegment(double t0, double steer0, double t1, double steer1);
  mb::DriverTarget at(double t) const override;
  double steerAt(double t) const;

 private:
  double gain_;
  const Signal* scripted_ = nullptr;
  double t0_ = 0, s0_ = 0, t1_ = 0, s1_ = 0;
};

class Simulation {
 public:
  explicit Simulation(const ScenarioSpec& spec);
  ~Simulation();

  // Assembly, static equilibrium at the start pose, initial speed, then the
  // settling phase (tau = 0 at its end). Returns the static equilibrium.
  vehicle::EquilibriumReport prepare();

  // One step of spec().integrator.step seconds with the scripted driver.
  integ::StepReport step();
  // One step with a person's (or any external) input.
  integ::StepReport step(const DriverInput& input);

  double time() const { return integrator_->current().t; }
  vehicle::VehicleSample sample();                  // at the current state
  vehicle::VehicleView view();                      // after sample()
  const ScenarioSpec& spec() const { return spec_; }
  const vehicle::Vehicle& vehicle() const { return vehicle_; }
  const integ::Integrator& integrator() const { return *integrator_; }
  const std::optional<Iso3888Course>& course() const { return course_; }
  // Steering input in [-1, 1] applied at time t (scripted, path follower or person).
  double steerAt(double t) const { return rack_.steerAt(t); }
  DriverInput lastInput() const { return lastInput_; }
  double driveTorque(int wheel) const { return forces_->wheels()[wheel].driveTorque; }

 private:
  struct StartPose {
    Eigen::Matrix3d rotation;
    Eigen::Vector3d origin;
    double groundZ = 0;
  };
  StartPose startPose() const;
  struct ChassisState {
    Eigen::Vector3d com;
    double yaw = 0, vx = 0, yawRate = 0;
  };
  ChassisState chassisState() const;
  void makeIntegrator();
  void applyDrive(const DriverInput& in, double vx, double h);
  integ::StepReport advance(const DriverInput& in);

  ScenarioSpec spec_;
  vehicle::Vehicle vehicle_;
  std::unique_ptr<terrain::Terrain> terrain_;
  std::unique_ptr<vehicle::VehicleForces> forces_;
  std::unique_ptr<mb::MultibodyDae> dae_;
  std::unique_ptr<integ::Integrator> integrator_;
  std::unique_ptr<Signal> steering_, throttle_, brake_;
  std::optional<SpeedController> speed_;
  std::optional<Iso3888Course> course_;
  std::optional<PathFollower> follower_;
  RackSignal rack_;
  DriverInput lastInput_;
  bool prepared_ = false;
  // Time with no ground under any wheel: off the edge of a bounded terrain the
  // car would fall for ever, so the run stops with a message instead. A jump
  // off a ramp lasts well under kMaxAirborne.
  double airborne_ = 0;
  static constexpr double kMaxAirborne = 3.0;  // s
};

// The vehicle width used for the ISO course: overall width over the tyres.
double vehicleWidth(const vehicle::Vehicle& v);

std::unique_ptr<Signal> makeSignal(const SignalSpec& s);

}  // namespace bdfcar::scenario
