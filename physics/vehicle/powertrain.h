// The powertrain's force laws, evaluated inside the implicit step
// (vehicle_forces.h): the engine's torque at its speed and throttle, the
// clutch between the engine and the gearbox, the differential's split. The
// engine is a body of the multibody model (a rotor on a revolute joint in
// the chassis, vehicle_builder.h), so its speed is a state of the BDF
// integration like the wheels' spins; the clutch's locked stiffness is what
// makes it stiff (h * sqrt(k / I) ~ 0.7 at 10 ms: an explicit step of 10 ms
// would not hold it).
//
// What the transmission's controller decides once per step (gear, clutch
// engagement, throttle) is held over the step as a DrivelineCommand.
#pragma once

#include <string>

#include "vehicle/powertrain_spec.h"

namespace bdfcar::vehicle {

// Held over a step: set before the step from the driver and the gearbox's
// controller (scenario/transmission.h).
struct DrivelineCommand {
  double throttle = 0;        // [0, 1] at the engine (the idle governor adds to it)
  double clutchCapacity = 0;  // N m the clutch can carry now (0: open)
  double ratio = 0;           // overall engine : wheel-carrier speed (0: neutral; < 0: reverse)
  bool operator==(const DrivelineCommand&) const = default;
};

// What the driveline carries from step to step and its latest evaluation.
struct DrivelineState {
  DrivelineCommand command;
  double clutchDeflection = 0;  // rad, the locked clutch's spring at the last accepted step
  // Latest evaluation (telemetry):
  double engineSpeed = 0;       // rad/s, relative to the chassis
  double engineTorque = 0;      // N m, combustion less friction
  double clutchTorque = 0;      // N m, from the engine into the gearbox
  double outputSpeed = 0;       // rad/s, mean spin of the driven wheels relative to their carriers
  bool operator==(const DrivelineState&) const = default;
};

// The laws of the engine and clutch speeds below are written for T double
// or ad::Dual (a closed form's Jacobian, autodiff.h; powertrain.cpp).
// Full-load torque at engine speed w (the table, held at its end values).
template <typename T>
T fullLoadTorque(const EngineSpec& e, const T& w);
// The throttle after the idle governor (fully open governorBand below idle,
// closed at idle) and the fuel cut (closed from 1 % above the rev limit).
template <typename T>
T effectiveThrottle(const EngineSpec& e, const T& w, double throttle);
// Friction and pumping torque at speed w (opposes the rotation; smooth through 0).
template <typename T>
T engineFriction(const EngineSpec& e, const T& w);
// Net engine torque on the crank: effective throttle x full load - friction.
template <typename T>
T engineTorque(const EngineSpec& e, const T& w, double throttle);

// The clutch's torque from the engine into the gearbox: a spring-damper on
// the slip since the clutch last slipped (deflection, advanced per accepted
// step, plus h x slip inside the step), saturated smoothly at the capacity,
// as the brakes (vehicle_forces.h).
template <typename T>
T clutchTorque(const ClutchSpec& c, double capacity, double deflection, const T& slip, double h);
// The deflection after an accepted step of length h (clamped to what the capacity holds).
double advanceClutchDeflection(const ClutchSpec& c, double capacity, double deflection, double slip, double h);

// A few lines for `bdfcar info`: the engine's best torque and power, the
// gears with the road speed each reaches at the full-throttle upshift (and
// at the rev limit in top), at the rolling radius wheelRadius.
std::string describePowertrain(const PowertrainSpec& p, double wheelRadius);

}  // namespace bdfcar::vehicle
