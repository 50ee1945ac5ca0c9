// A drivable car's powertrain as plain data ([powertrain] in a vehicle file,
// docs/VEHICLES.md): engine, clutch, gearbox, differential, handbrake. SI
// units (engine speeds in rad/s). The reference vehicles carry none: their
// speed hold applies a torque to the wheels directly ([driveline]).
#pragma once

#include <vector>

namespace bdfcar::vehicle {

struct EngineSpec {
  // Full-load torque over engine speed, piecewise linear between the points
  // and held at the end values outside them.
  std::vector<double> speed;   // rad/s, increasing
  std::vector<double> torque;  // N m at full throttle
  double idleSpeed = 0;        // rad/s, held by the idle governor
  double revLimit = 0;         // rad/s, fuel cut above
  double inertia = 0;          // kg m^2: crank, flywheel, clutch and gearbox input shaft
  // Friction and pumping torque with the throttle closed (engine braking):
  // friction + frictionSlope * speed.
  double friction = 0;         // N m
  double frictionSlope = 0;    // N m s/rad
  // The idle governor opens the throttle fully this far below idle and not
  // at all at idle (a proportional governor; its droop is what the friction
  // costs).
  double governorBand = 0;     // rad/s
};

struct ClutchSpec {
  double maxTorque = 0;        // N m, torque capacity fully engaged
  // A locked clutch is a stiff torsional spring-damper (the driveline's
  // compliance seen at the engine), saturated at the capacity: it holds
  // without creep and slips above the capacity (vehicle_forces.h).
  double stiffness = 0;        // N m/rad
  double damping = 0;          // N m s/rad
  // Automatic clutch (no clutch pedal mapped): it engages as the engine
  // speeds up from idle to launchSpeed, and opens for a shift over shiftTime.
  double launchSpeed = 0;      // rad/s
  double shiftTime = 0;        // s, open - change gear - close
};

struct GearboxSpec {
  std::vector<double> ratios;  // forward gears, engine turns per gearbox output turn, first gear first
  double reverse = 0;          // ratio of reverse (> 0; the gearbox reverses the sense)
  double finalDrive = 0;       // differential ratio
  bool automatic = true;       // shifts by itself (the driver's up / down requests still work)
  // Shift schedule: up when the engine passes upshiftSpeed at full throttle
  // (upshiftSpeedLight with the throttle closed, linear in between); down
  // when it falls below downshiftSpeed.
  double upshiftSpeed = 0, upshiftSpeedLight = 0, downshiftSpeed = 0;  // rad/s
  int gears() const { return static_cast<int>(ratios.size()); }
  // Overall ratio engine : wheels in gear g (-1 reverse, 0 neutral, 1..n): negative in reverse.
  double overall(int g) const {
    if (g == 0) return 0.0;
    return (g < 0 ? -reverse : ratios[g - 1]) * finalDrive;
  }
};

struct PowertrainSpec {
  EngineSpec engine;
  ClutchSpec clutch;
  GearboxSpec gearbox;
  // An open differential shares the torque equally among the driven wheels;
  // a viscous limited-slip coupling adds lockTorque = coupling * (speed
  // difference) from the faster wheel to the slower one.
  double viscousCoupling = 0;  // N m s/rad, 0: open
  double handbrakeTorque = 0;  // N m per rear wheel at full handbrake
};

}  // namespace bdfcar::vehicle
