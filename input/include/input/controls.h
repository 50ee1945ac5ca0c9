// What a person commands in one tick, as plain data: the output of
// InputSystem::poll(). No SDL types; the app maps it onto the physics'
// DriverInput (input/ uses only physics/config, to read its mapping files).
#pragma once

#include <limits>
#include <string_view>

namespace bdfcar::input {

// Which kind of device a mapping file describes and a connected device is.
enum class DeviceKind { Keyboard, Wheel, GameController, Joystick };

// The analog controls a mapping can bind to an axis (or, for the keyboard, ramp).
enum class Axis { Steering, Throttle, Brake, Clutch, Handbrake };
inline constexpr int kAxisCount = 5;

// Speed-sensitive steering (a mapping file's [speed_sensitive_steering]): the
// steering input is scaled by 1 at a standstill, falling linearly with the
// car's speed to `scale` at `speed` and held there above it. Off (speed 0,
// the default): the input is left exactly as it is.
//
// Or, with lateralAcceleration set (the grip law), the input is scaled so
// that full input asks the car for that lateral acceleration at any speed,
// as a kinematic (no-slip) car would turn: by a L / (v^2 delta), delta the
// road-wheel angle of full input and L the wheelbase (the car's), never
// above 1 (full lock at low speed) nor below `scale`. Full lock then means
// "as hard as the grip allows" at every speed: the lock and the rate at
// which a key winds it on fall as 1 / v^2, the way a driver's hands do.
struct SpeedSensitiveSteering {
  double speed = 0.0;  // m/s at which the scale reaches `scale`; 0: off
  double scale = 1.0;  // (0, 1]: the fraction of the input kept at and above `speed` (the grip law: the least kept)
  double lateralAcceleration = 0.0;  // m/s^2: the grip law (speed is 0 then); 0: the linear law or off
  bool on() const { return speed > 0.0 || lateralAcceleration > 0.0; }
};

// Edge-triggered commands: true in the one tick in which the button went down.
enum class Action { GearUp, GearDown, Reset, Pause, SingleStep, Camera, View, Record, Quit, Rewind, Menu, MenuUp,
                    MenuDown, MenuSelect };
inline constexpr int kActionCount = 14;

struct Controls {
  // Analog, from the active device (the highest-ranked connected one, else the keyboard).
  double steering = 0.0;  // [-1, 1], + = left
  // The device's steering angle, rad (+ left), where its mapping gives the
  // wheel's rotation (rotation_deg): steering x half the rotation. NaN: not known.
  double steeringWheelAngle = std::numeric_limits<double>::quiet_NaN();
  double throttle = 0.0;  // [0, 1]
  double brake = 0.0;     // [0, 1]
  double clutch = 0.0;    // [0, 1], 1 = pedal down (disengaged); 0 unless hasClutch
  bool hasClutch = false; // the active device's mapping binds a clutch
  double handbrake = 0.0; // [0, 1], 1 = pulled fully
  // The active device's (or keyboard's) mapping's speed-sensitive steering,
  // applied by toDriverInput (driver_controls.h), which knows the car's speed.
  SpeedSensitiveSteering speedSensitive;

  // Edge-triggered, from every connected device and the keyboard together.
  bool gearUp = false;
  bool gearDown = false;
  bool reset = false;
  bool pause = false;
  bool singleStep = false;
  bool camera = false;
  bool view = false;      // switch the body display (solid, translucent, hidden: the suspension moving)
  bool record = false;
  bool quit = false;
  bool rewind = false;    // one snapshot (0.5 s) back in the drive
  // The pause menu: open / close it, move through it, choose (acted on
  // only while it is open: the keys may steer or pedal otherwise).
  bool menu = false, menuUp = false, menuDown = false, menuSelect = false;

  DeviceKind source = DeviceKind::Keyboard;  // the device the analog values came from
};

// The flag of `action` inside `controls` (one switch instead of eight ifs in callers).
bool& actionFlag(Controls& controls, Action action);
bool actionFlag(const Controls& controls, Action action);

// The name used in mapping files: "steering", "throttle", "brake", "clutch", "handbrake".
std::string_view axisName(Axis axis);

// The name used in mapping files: "gear_up", "reset", "single_step", "rewind", ...
std::string_view actionName(Action action);

// The name used in mapping files' `type`: "keyboard", "wheel", "gamecontroller", "joystick".
std::string_view deviceKindName(DeviceKind kind);

}  // namespace bdfcar::input
