// Wheel and controller setup: `bdfcar input --calibrate` (the capture ->
// mapping rules, the file it writes read back through the real loader, and
// the whole command on a scripted SDL virtual wheel), pedals read from where
// they rest, the force-feedback test, and speed-sensitive steering. Expected
// values are the numbers the tests write into their samples and files, worked
// out by hand here, not through the library's functions.
#include <SDL.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "config/toml_reader.h"
#include "input/axis_response.h"
#include "input/calibration.h"
#include "input/driver_controls.h"
#include "input/force_feedback.h"
#include "input/input_system.h"
#include "input/mapping.h"
#include "input/monitor.h"
#include "input_virtual.h"

namespace {

using namespace bdfcar::input;
using namespace bdfcar::test_input;

// A wheel file as shipped: pedals expected to rest at +32767 and read
// -32768 fully down, a power curve on the brake, buttons, force feedback.
const char* const kShippedLikeWheel = R"(
[device]
type = "wheel"
name_contains = ["bdfcar-test"]

[axes.steering]
axis = 0
invert = true
rotation_deg = 900

[axes.throttle]
axis = 2
min = 32767
max = -32768

[axes.brake]
axis = 3
min = 32767
max = -32768
curve = "power"
exponent = 1.5

[axes.clutch]
axis = 6               # more axes than the test's wheel has
min = 32767
max = -32768

[actions]
gear_up = 4
reset = [6, 7]

[force_feedback]
gain = 0.6
)";

const char* const kKeyboard = R"(
[device]
type = "keyboard"

[keys]
steer_left = "Left"

[speed_sensitive_steering]
speed = "72 km/h"
scale = 0.4
)";

DeviceMapping shippedLikeWheel() { return parseMapping(kShippedLikeWheel, "wheel.toml"); }

// Control value of `control` in a mapping at a raw reading.
double read(const DeviceMapping& m, Axis control, int raw) {
  return axisResponse(m.axes[static_cast<int>(control)], control, raw);
}

const AxisMapping& axisOf(const DeviceMapping& m, Axis control) { return m.axes[static_cast<int>(control)]; }

// Samples of a 5-axis device: `still` rows of rests, then each axis's moves
// one after the other (a move: linear from the rest to a value and back, 20 rows each way).
struct Script {
  std::vector<int> rest;
  std::vector<std::vector<int>> rows;
  Script(std::vector<int> rests, int still) : rest(std::move(rests)), rows(still, rest) {}
  void move(int axis, int to) {
    for (int leg = 0; leg < 2; ++leg)
      for (int k = 1; k <= 20; ++k) {
        std::vector<int> row = rest;
        const double f = leg == 0 ? k / 20.0 : 1.0 - k / 20.0;
        row[axis] = static_cast<int>(std::lround(rest[axis] + f * (to - rest[axis])));
        rows.push_back(row);
      }
  }
};

// A wheel's capture: steering (axis 0) resting at 120, throttle (2) at
// 32767, brake (3) at 32000 (not quite its end), clutch (4) at -32768; axis 1
// wobbles a little. Turned left and right, then throttle, brake, clutch.
Script wheelCapture() {
  Script s({120, 0, 32767, 32000, -32768}, 100);
  for (std::size_t t = 0; t < s.rows.size(); ++t) s.rows[t][1] = t % 2 ? 40 : -40;
  s.move(0, -32768);
  s.move(0, 32767);
  s.move(2, -32768);
  s.move(3, -30000);
  s.move(4, 32767);
  return s;
}

TEST(Calibration, CapturedExtremesReadFullAndRestsReadReleasedThroughTheLoader) {
  const Script s = wheelCapture();
  const Calibration cal = calibrateAxes(s.rows, 100, shippedLikeWheel());
  ASSERT_TRUE(cal.steeringFound);
  const std::string text = mappingToml(cal.mapping, {"a test"});
  const DeviceMapping m = parseMapping(text, "calibrated.toml");  // the real loader
  SCOPED_TRACE(text);

  EXPECT_EQ(axisOf(m, Axis::Steering).axis, 0);
  EXPECT_EQ(axisOf(m, Axis::Throttle).axis, 2);
  EXPECT_EQ(axisOf(m, Axis::Brake).axis, 3);
  EXPECT_EQ(axisOf(m, Axis::Clutch).axis, 4);
  EXPECT_FALSE(axisOf(m, Axis::Handbrake).bound);
  // Steering: SDL reads + to the right, bdfcar steers + to the left.
  EXPECT_EQ(read(m, Axis::Steering, -32768), 1.0);
  EXPECT_EQ(read(m, Axis::Steering, 32767), -1.0);
  EXPECT_EQ(read(m, Axis::Steering, 120), 0.0);
  // Pedals: released at their rest (and beyond), fully down at the extreme pressed.
  EXPECT_EQ(read(m, Axis::Throttle, 32767), 0.0);
  EXPECT_EQ(read(m, Axis::Throttle, -32768), 1.0);
  EXPECT_EQ(read(m, Axis::Brake, 32000), 0.0);
  EXPECT_EQ(read(m, Axis::Brake, 32767), 0.0);
  EXPECT_EQ(read(m, Axis::Brake, -30000), 1.0);
  EXPECT_NEAR(read(m, Axis::Brake, 1000), std::pow(0.5, 1.5), kTol);  // half-way, through the file's curve
  EXPECT_EQ(read(m, Axis::Clutch, -32768), 0.0);
  EXPECT_EQ(read(m, Axis::Clutch, 32767), 1.0);
  // What the device's file had besides the axes is kept; the file claims the device by name.
  const DeviceMapping base = shippedLikeWheel();
  EXPECT_EQ(m.kind, DeviceKind::Wheel);
  EXPECT_EQ(m.nameContains, base.nameContains);
  EXPECT_EQ(m.actions, base.actions);
  EXPECT_EQ(axisOf(m, Axis::Steering).rotationDeg, 900.0);
  EXPECT_TRUE(m.forceFeedback.enabled);
  EXPECT_EQ(m.forceFeedback.gain, 0.6);
  EXPECT_EQ(text.rfind("# a test\n", 0), 0u);
}

TEST(Calibration, PedalsAreNamedByTheOrderInWhichTheyWerePressed) {
  Script s({0, 32767, 32767, 32767}, 50);
  s.move(0, -32768);  // one count further left: no note on an uneven turn
  s.move(0, 32767);
  s.move(3, -32768);  // brake first ...
  s.move(1, -32768);  // ... then throttle, then clutch
  s.move(2, -32768);
  DeviceMapping stick;  // a base file without axes
  stick.kind = DeviceKind::Joystick;
  const Calibration cal = calibrateAxes(s.rows, 50, stick);
  EXPECT_EQ(axisOf(cal.mapping, Axis::Throttle).axis, 3);
  EXPECT_EQ(axisOf(cal.mapping, Axis::Brake).axis, 1);
  EXPECT_EQ(axisOf(cal.mapping, Axis::Clutch).axis, 2);
  // Without a steering in the base file: SDL's + to the right is inverted.
  EXPECT_TRUE(axisOf(cal.mapping, Axis::Steering).invert);
  ASSERT_EQ(cal.report.size(), 4u);
  EXPECT_EQ(cal.report[1], "throttle: axis 3, released at 32767, fully down at -32768 (pressed 1st)");
}

TEST(Calibration, NoSteeringWithoutAnAxisTurnedBothWays) {
  Script s({0, 32767}, 50);
  s.move(0, 5000);    // a nudge: too little to be anything
  s.move(1, -32768);  // a pedal
  const Calibration cal = calibrateAxes(s.rows, 50, shippedLikeWheel());
  EXPECT_FALSE(cal.steeringFound);
  EXPECT_FALSE(axisOf(cal.mapping, Axis::Steering).bound);
  EXPECT_EQ(axisOf(cal.mapping, Axis::Throttle).axis, 1);
}

TEST(Calibration, TheWiderCentredAxisSteersAndTheOtherIsReportedUnassigned) {
  Script s({0, 0, -32768}, 50);
  s.move(1, -20000);
  s.move(1, 20000);
  s.move(0, -32768);  // wider: the wheel, though turned after the other
  s.move(0, 32767);
  s.move(2, 32767);
  const Calibration cal = calibrateAxes(s.rows, 50, shippedLikeWheel());
  EXPECT_EQ(axisOf(cal.mapping, Axis::Steering).axis, 0);
  EXPECT_EQ(axisOf(cal.mapping, Axis::Throttle).axis, 2);
  ASSERT_FALSE(cal.report.empty());
  EXPECT_NE(cal.report.back().find("axis 1: moved -20000 .. 20000 from rest 0 but rests mid-travel"), std::string::npos)
      << cal.report.back();
}

TEST(Calibration, AnUnevenTurnTakesFullLockAtTheShorterSideAndSaysSo) {
  Script s({1000, 32767}, 50);
  s.move(0, -20000);  // 21000 one way
  s.move(0, 32767);   // 31767 the other
  s.move(1, -32768);
  const Calibration cal = calibrateAxes(s.rows, 50, shippedLikeWheel());
  const DeviceMapping m = parseMapping(mappingToml(cal.mapping, {}), "calibrated.toml");
  EXPECT_EQ(read(m, Axis::Steering, -20000), 1.0);
  EXPECT_EQ(read(m, Axis::Steering, 22000), -1.0);  // 1000 + 21000
  EXPECT_EQ(read(m, Axis::Steering, 1000), 0.0);
  EXPECT_NEAR(read(m, Axis::Steering, 11500), -0.5, kTol);
  ASSERT_GE(cal.report.size(), 2u);
  EXPECT_NE(cal.report[1].find("turned 31767 one way but 21000 the other"), std::string::npos) << cal.report[1];
}

TEST(Calibration, TheStillReadingIsTheMedianSoATwitchDoesNotMoveTheRest) {
  Script s({0, 32767}, 51);
  s.rows[10][1] = -32768;  // a foot on the pedal for one sample of the still reading
  s.move(0, -32768);
  s.move(0, 32767);
  s.move(1, -32768);
  const Calibration cal = calibrateAxes(s.rows, 51, shippedLikeWheel());
  EXPECT_EQ(cal.axes[1].rest, 32767);
  EXPECT_EQ(axisOf(cal.mapping, Axis::Throttle).rawMin, 32767);
  EXPECT_THROW(calibrateAxes(s.rows, 0, shippedLikeWheel()), std::invalid_argument);
  EXPECT_THROW(calibrateAxes(s.rows, static_cast<int>(s.rows.size()), shippedLikeWheel()), std::invalid_argument);
}

// Every key of a device's file, written and read back, comes back the same
// (names for a game controller's axes and buttons, escapes in the name).
TEST(MappingText, ReadsBackToTheSameMapping) {
  const char* const pad = R"(
[device]
type = "gamecontroller"
name_contains = ["Pad \"Pro\" \\ 2", "other"]

[axes.steering]
axis = "leftx"
invert = true
deadzone = 0.15
gain = 1.25
curve = "power"
exponent = 1.7
min = -30000
max = 31000
rotation_deg = 540

[axes.throttle]
axis = "righttrigger"

[axes.handbrake]
axis = "lefty"
min = 0
max = -32768

[speed_sensitive_steering]
speed = "100 km/h"
scale = 0.35

[actions]
pause = "start"
reset = ["y", "back"]
rewind = "dpleft"

[force_feedback]
gain = 0.3
invert = true
)";
  const DeviceMapping a = parseMapping(pad, "pad.toml");
  const std::string text = mappingToml(a, {"line one", "", "line three"});
  const DeviceMapping b = parseMapping(text, "again.toml");
  SCOPED_TRACE(text);
  EXPECT_EQ(b.kind, a.kind);
  EXPECT_EQ(b.nameContains, (std::vector<std::string>{"Pad \"Pro\" \\ 2", "other"}));
  for (int i = 0; i < kAxisCount; ++i) {
    SCOPED_TRACE(i);
    const AxisMapping &x = a.axes[i], &y = b.axes[i];
    EXPECT_EQ(y.bound, x.bound);
    EXPECT_EQ(y.axis, x.axis);
    EXPECT_EQ(y.invert, x.invert);
    EXPECT_EQ(y.deadzone, x.deadzone);
    EXPECT_EQ(y.gain, x.gain);
    EXPECT_EQ(y.curve, x.curve);
    EXPECT_EQ(y.exponent, x.exponent);
    EXPECT_EQ(y.rawMin, x.rawMin);
    EXPECT_EQ(y.rawMax, x.rawMax);
    EXPECT_EQ(y.rotationDeg, x.rotationDeg);
  }
  EXPECT_EQ(b.axes[static_cast<int>(Axis::Throttle)].rawMin, 0);  // a trigger's default, written out
  EXPECT_EQ(b.speedSensitive.speed, a.speedSensitive.speed);
  EXPECT_EQ(b.speedSensitive.scale, 0.35);
  EXPECT_EQ(b.actions, a.actions);
  EXPECT_EQ(b.forceFeedback.gain, 0.3);
  EXPECT_TRUE(b.forceFeedback.invert);
  EXPECT_EQ(text.rfind("# line one\n#\n# line three\n\n[device]\n", 0), 0u);
  EXPECT_NE(text.find("axis = \"righttrigger\""), std::string::npos);
  EXPECT_THROW(mappingToml(parseMapping(kKeyboard, "k.toml"), {}), std::invalid_argument);
}

// A pedal resting inside its travel reads released there, and the travel
// from there to the pressed end spans 0..1.
TEST(PedalRest, TheRestInsideTheTravelBecomesTheReleasedEnd) {
  AxisMapping p;  // as the shipped wheel's throttle: released at +32767, down at -32768
  p.bound = true;
  p.rawMin = 32767;
  p.rawMax = -32768;
  const AxisMapping atZero = pedalFromRest(p, 0);
  EXPECT_EQ(axisResponse(p, Axis::Throttle, 0), 32767.0 / 65535.0);  // the issue's "constant ~50 %"
  EXPECT_EQ(axisResponse(atZero, Axis::Throttle, 0), 0.0);
  EXPECT_EQ(axisResponse(atZero, Axis::Throttle, 20000), 0.0);
  EXPECT_EQ(axisResponse(atZero, Axis::Throttle, -16384), 0.5);
  EXPECT_EQ(axisResponse(atZero, Axis::Throttle, -32768), 1.0);
  // At or beyond the released end, or at the pressed end: the file as it is.
  EXPECT_EQ(pedalFromRest(p, 32767).rawMin, 32767);
  EXPECT_EQ(pedalFromRest(p, -32768).rawMin, 32767);
  // Inverted (released at rawMax): the rest moves rawMax.
  AxisMapping q;
  q.bound = true;
  q.invert = true;
  q.rawMin = -32768;
  q.rawMax = 32767;
  EXPECT_EQ(pedalFromRest(q, 0).rawMax, 0);
  EXPECT_EQ(axisResponse(pedalFromRest(q, 0), Axis::Brake, -16384), 0.5);
  // More released: towards +32767 for both, towards -32768 for a plain pedal.
  EXPECT_EQ(moreReleased(p, 100, 200), 200);
  EXPECT_EQ(moreReleased(q, 100, 200), 200);
  AxisMapping plain;
  plain.bound = true;
  EXPECT_EQ(moreReleased(plain, 100, 200), 100);
}

TEST(ForceFeedbackTest, PushesLeftThenRightGentlyEasedInAndOut) {
  // Hand-computed points of the phases: 0.3 s in, 1 s held, 0.3 s out; left, then right.
  EXPECT_EQ(forceFeedbackTestCommand(-0.01), 0.0);
  EXPECT_EQ(forceFeedbackTestCommand(0.0), 0.0);
  EXPECT_NEAR(forceFeedbackTestCommand(0.15), 0.125, kTol);
  EXPECT_NEAR(forceFeedbackTestCommand(0.8), 0.25, kTol);
  EXPECT_NEAR(forceFeedbackTestCommand(1.45), 0.125, kTol);
  EXPECT_NEAR(forceFeedbackTestCommand(1.75), -0.125, kTol);
  EXPECT_NEAR(forceFeedbackTestCommand(2.4), -0.25, kTol);
  EXPECT_NEAR(forceFeedbackTestCommand(3.05), -0.125, kTol);
  EXPECT_EQ(forceFeedbackTestCommand(3.2), 0.0);
  EXPECT_EQ(forceFeedbackTestPhase(3.2), -1);
  EXPECT_EQ(forceFeedbackTestPhase(0.5), 1);
  // Tick by tick: never above a quarter, never a jump above the ramp's step, left before right.
  double previous = 0.0, firstPush = 0.0;
  for (int i = 0; i <= 400; ++i) {
    const double c = forceFeedbackTestCommand(i * 0.01);
    EXPECT_LE(std::abs(c), 0.25 + kTol);
    EXPECT_LE(std::abs(c - previous), 0.25 / 0.3 * 0.01 + 1e-9) << i;
    if (firstPush == 0.0) firstPush = c;
    previous = c;
  }
  EXPECT_GT(firstPush, 0.0);
  EXPECT_EQ(previous, 0.0);
  // Through the shipped wheel's gain (0.6): at most 15 % of the device's full force.
  EXPECT_EQ(forceFeedbackLevel(shippedLikeWheel().forceFeedback, kForceFeedbackTestCommand), 4915);  // 0.15 * 32767
}

// 72 km/h = 20 m/s, scale 0.4: the factor falls from 1 to 0.4 over 0..20 m/s.
TEST(SpeedSensitiveSteering, FollowsTheStatedLineAndIsOffByDefault) {
  const DeviceMapping keyboard = parseMapping(kKeyboard, "keyboard.toml");
  EXPECT_NEAR(keyboard.speedSensitive.speed, 20.0, 1e-12);
  Controls c;
  c.steering = 0.5;
  c.speedSensitive = keyboard.speedSensitive;
  EXPECT_EQ(toDriverInput(c, {1.0}, 0.0).steer, 0.5);
  EXPECT_NEAR(toDriverInput(c, {1.0}, 5.0).steer, 0.425, kTol);   // 0.5 * (1 - 0.6 * 0.25)
  EXPECT_NEAR(toDriverInput(c, {1.0}, 10.0).steer, 0.35, kTol);   // 0.5 * (1 - 0.6 * 0.5)
  EXPECT_NEAR(toDriverInput(c, {1.0}, -10.0).steer, 0.35, kTol);  // reversing
  EXPECT_NEAR(toDriverInput(c, {1.0}, 20.0).steer, 0.2, kTol);
  EXPECT_NEAR(toDriverInput(c, {1.0}, 45.0).steer, 0.2, kTol);    // held above the speed
  // A wheel turning the car's wheel by its own angle: 90 of 210 degrees, then x 0.7 at 10 m/s.
  c.steeringWheelAngle = 90.0 * M_PI / 180.0;
  EXPECT_NEAR(toDriverInput(c, {210.0 * M_PI / 180.0}, 10.0).steer, 0.3, kTol);

  // Off (no table): the input bit for bit what it was, at any speed.
  const DeviceMapping plain = shippedLikeWheel();
  EXPECT_EQ(plain.speedSensitive.speed, 0.0);
  Controls d;
  d.speedSensitive = plain.speedSensitive;
  for (double steer : {-1.0, -0.123456789, 0.0, 0.3, 0.987654321}) {
    d.steering = steer;
    for (double v : {0.0, 3.3, 27.8, 80.0}) {
      EXPECT_EQ(toDriverInput(d, {1.0}, v), toDriverInput(d, {1.0}, 0.0));
      EXPECT_EQ(toDriverInput(d, {1.0}, v).steer, steer);
    }
  }
  EXPECT_EQ(speedSensitiveFactor(plain.speedSensitive, 50.0, {}), 1.0);
}

// The grip law: full input asks for the stated lateral acceleration as a
// kinematic car turns (a = v^2 delta f / L), never more than the whole input
// (low speed) nor less than the scale; a car with no steering data is left whole.
TEST(SpeedSensitiveSteering, TheGripLawAsksForTheStatedLateralAcceleration) {
  const DeviceMapping mapping = parseMapping(
      std::string(kShippedLikeWheel) + "\n[speed_sensitive_steering]\nlateral_acceleration = \"0.8 g\"\nscale = 0.05\n",
      "wheel.toml");
  const double a = 0.8 * 9.80665;
  EXPECT_NEAR(mapping.speedSensitive.lateralAcceleration, a, 1e-9);
  EXPECT_EQ(mapping.speedSensitive.speed, 0.0);
  const CarSteering car{3.66, 0.25, 2.9};  // 210 deg of wheel, 0.25 rad of road wheel
  Controls c;
  c.steering = 1.0;
  c.speedSensitive = mapping.speedSensitive;
  for (double v : {12.0, 16.7, 27.8, -20.0}) {
    SCOPED_TRACE(v);
    const double f = toDriverInput(c, car, v).steer;
    EXPECT_NEAR(v * v * car.roadWheelFull * f / car.wheelbase, a, 1e-9);
  }
  EXPECT_EQ(toDriverInput(c, car, 3.0).steer, 1.0);  // full lock asks for less than a: whole
  EXPECT_EQ(toDriverInput(c, car, 300.0).steer, 0.05);  // the floor
  c.steering = -0.5;
  EXPECT_NEAR(toDriverInput(c, car, 20.0).steer, -0.5 * a * 2.9 / (400.0 * 0.25), 1e-12);
  EXPECT_EQ(toDriverInput(c, {}, 20.0).steer, -0.5);  // no steering data: untouched
  // Written back (a device's file, as calibration writes it), read again, the same law.
  const DeviceMapping again = parseMapping(mappingToml(mapping, {}), "again.toml");
  EXPECT_EQ(again.speedSensitive.lateralAcceleration, mapping.speedSensitive.lateralAcceleration);
  EXPECT_EQ(again.speedSensitive.scale, 0.05);
}

// The test's mapping files and only the test's virtual devices.
class SetupDevices : public VirtualDevicesTest {
 protected:
  void SetUp() override {
    VirtualDevicesTest::SetUp();
    writeFile(dir, "keyboard.toml", kKeyboard);
    writeFile(dir, "wheel.toml", kShippedLikeWheel);
  }
  InputOptions options() const {
    InputOptions o;
    o.mappingDir = dir;
    o.deviceFilter = kVirtualPrefix;
    return o;
  }
  MonitorOptions commandOptions(std::FILE* out) const {
    MonitorOptions o;
    o.mappingDir = dir;
    o.deviceFilter = kVirtualPrefix;
    o.out = out;
    return o;
  }
  Virtual attachWheel(void (*update)(void*) = nullptr, void* userdata = nullptr) {
    return attach(SDL_JOYSTICK_TYPE_WHEEL, "bdfcar-test wheel", 4, 8, update, userdata);
  }
};

// The issue's wheel: pedals resting at mid-range where the file expects +32767
// read released, not ~50 % throttle and ~35 % brake; a clutch on an axis the
// wheel lacks reads released.
TEST_F(SetupDevices, PedalsRestingWhereTheFileDoesNotExpectReadReleased) {
  Virtual wheel = attachWheel();
  ASSERT_GE(wheel.id, 0) << SDL_GetError();
  SDL_JoystickSetVirtualAxis(wheel.joystick, 2, 0);
  SDL_JoystickSetVirtualAxis(wheel.joystick, 3, 0);
  InputSystem input(options());
  Controls c = input.poll(kDt);
  ASSERT_EQ(c.source, DeviceKind::Wheel);
  EXPECT_EQ(c.throttle, 0.0);
  EXPECT_EQ(c.brake, 0.0);
  EXPECT_TRUE(c.hasClutch);
  EXPECT_EQ(c.clutch, 0.0);
  // From the rest to the pressed end: 0..1 (the brake through its curve).
  SDL_JoystickSetVirtualAxis(wheel.joystick, 2, -16384);
  SDL_JoystickSetVirtualAxis(wheel.joystick, 3, -32768);
  c = input.poll(kDt);
  EXPECT_EQ(c.throttle, 0.5);
  EXPECT_EQ(c.brake, 1.0);
  // A pedal that then reads further towards released moves its rest there.
  SDL_JoystickSetVirtualAxis(wheel.joystick, 2, 32767);
  EXPECT_EQ(input.poll(kDt).throttle, 0.0);
  SDL_JoystickSetVirtualAxis(wheel.joystick, 2, 0);
  EXPECT_EQ(input.poll(kDt).throttle, 32767.0 / 65535.0);
}

TEST_F(SetupDevices, AKeyboardOrDeviceMappingsSpeedSensitiveSteeringReachesTheControls) {
  InputSystem keyboardOnly(options());
  EXPECT_NEAR(keyboardOnly.poll(kDt).speedSensitive.speed, 20.0, 1e-12);
  EXPECT_EQ(keyboardOnly.poll(kDt).speedSensitive.scale, 0.4);
  ASSERT_GE(attachWheel().id, 0);
  const Controls c = keyboardOnly.poll(kDt);
  EXPECT_EQ(c.source, DeviceKind::Wheel);
  EXPECT_EQ(c.speedSensitive.speed, 0.0);  // the wheel's file has none
}

// A person at a virtual wheel, scripted per SDL update: still, then the
// wheel lock to lock, then the throttle, then the brake (part-way).
struct Person {
  SDL_Joystick* joystick = nullptr;
  int calls = 0;
  bool done = false;
  static int along(int n, int from, int to, int start, int length) {  // linear from -> to over [start, start + length)
    return static_cast<int>(std::lround(from + (to - from) * std::clamp((n - start) / double(length), 0.0, 1.0)));
  }
  static void update(void* self) {
    Person& p = *static_cast<Person*>(self);
    if (!p.joystick || p.done) return;
    const int n = p.calls++;
    int steer = 120, throttle = -32768, brake = -31000;
    if (n >= 130 && n < 150) steer = along(n, 120, -32768, 130, 19);
    else if (n >= 150 && n < 170) steer = along(n, -32768, 32767, 150, 19);
    else if (n >= 170 && n < 180) steer = along(n, 32767, 120, 170, 9);
    if (n >= 180 && n < 200) throttle = along(n, -32768, 32767, 180, 19);
    else if (n >= 200 && n < 210) throttle = along(n, 32767, -32768, 200, 9);
    if (n >= 210 && n < 230) brake = along(n, -31000, 30000, 210, 19);
    else if (n >= 230 && n < 240) brake = along(n, 30000, -31000, 230, 9);
    SDL_JoystickSetVirtualAxis(p.joystick, 0, static_cast<Sint16>(steer));
    SDL_JoystickSetVirtualAxis(p.joystick, 2, static_cast<Sint16>(throttle));
    SDL_JoystickSetVirtualAxis(p.joystick, 3, static_cast<Sint16>(brake));
  }
};

// The whole command on a virtual wheel whose pedals rest at -32768 (the file
// expects +32767): the file it writes, through the real loader and a fresh
// InputSystem, reads the person's extremes as full lock / full pedal and the
// rests as straight ahead / released.
TEST_F(SetupDevices, CalibrateWritesAFileThatReadsThePersonsWheelRight) {
  Person person;
  Virtual wheel = attachWheel(Person::update, &person);
  ASSERT_GE(wheel.id, 0) << SDL_GetError();
  person.joystick = wheel.joystick;
  std::FILE* out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  MonitorOptions o = commandOptions(out);
  o.seconds = 2.6;
  o.calibrateOut = dir / "calibrated" / "wheel-calibrated.toml";
  fs::create_directories(o.calibrateOut.parent_path());
  ASSERT_EQ(runInputCalibration(o), 0);
  person.done = true;
  const std::string text = readAndClose(out);
  SCOPED_TRACE(text);
  EXPECT_NE(text.find("steering: axis 0, straight ahead at 120"), std::string::npos);
  EXPECT_NE(text.find("throttle: axis 2, released at -32768, fully down at 32767 (pressed 1st)"), std::string::npos);
  EXPECT_NE(text.find("brake: axis 3, released at -31000, fully down at 30000 (pressed 2nd)"), std::string::npos);
  EXPECT_NE(text.find("wrote " + o.calibrateOut.string()), std::string::npos);

  const DeviceMapping m = loadMappingFile(o.calibrateOut);
  EXPECT_EQ(m.kind, DeviceKind::Wheel);
  EXPECT_EQ(m.nameContains, std::vector<std::string>{"bdfcar-test wheel"});
  EXPECT_FALSE(axisOf(m, Axis::Clutch).bound);  // the old file's axis 6 is not this wheel's

  // The calibrated file alone drives the wheel.
  writeFile(o.calibrateOut.parent_path(), "keyboard.toml", kKeyboard);
  InputOptions io = options();
  io.mappingDir = o.calibrateOut.parent_path();
  InputSystem input(io);
  const auto drive = [&](int steer, int throttle, int brake) {
    SDL_JoystickSetVirtualAxis(wheel.joystick, 0, static_cast<Sint16>(steer));
    SDL_JoystickSetVirtualAxis(wheel.joystick, 2, static_cast<Sint16>(throttle));
    SDL_JoystickSetVirtualAxis(wheel.joystick, 3, static_cast<Sint16>(brake));
    return input.poll(kDt);
  };
  Controls c = drive(120, -32768, -31000);
  EXPECT_EQ(c.steering, 0.0);
  EXPECT_EQ(c.throttle, 0.0);
  EXPECT_EQ(c.brake, 0.0);
  c = drive(-32768, 32767, 30000);
  EXPECT_EQ(c.steering, 1.0);  // full left
  EXPECT_EQ(c.throttle, 1.0);
  EXPECT_EQ(c.brake, 1.0);
  c = drive(32767, 0, -500);
  EXPECT_EQ(c.steering, -1.0);  // full right
  EXPECT_EQ(c.throttle, 32768.0 / 65535.0);
  EXPECT_NEAR(c.brake, std::pow(0.5, 1.5), kTol);  // half-way, through the old file's brake curve
}

TEST_F(SetupDevices, CalibrateWithoutADeviceOrWithTooShortACaptureWritesNothing) {
  std::FILE* out = std::tmpfile();
  MonitorOptions o = commandOptions(out);
  o.calibrateOut = dir / "never.toml";
  o.seconds = 2.0;
  EXPECT_EQ(runInputCalibration(o), 0);
  EXPECT_NE(readAndClose(out).find("no wheel, joystick or game controller is connected: nothing to calibrate"),
            std::string::npos);
  ASSERT_GE(attachWheel().id, 0);
  o.out = stdout;
  o.seconds = 1.5;
  EXPECT_EQ(runInputCalibration(o), 1);
  o.seconds = 2.0;  // a wheel nobody touches: no steering
  EXPECT_EQ(runInputCalibration(o), 1);
  EXPECT_FALSE(fs::exists(o.calibrateOut));
}

TEST_F(SetupDevices, ForceFeedbackTestSaysWhyThereIsNone) {
  const auto run = [&](const fs::path& mappings) {
    std::FILE* out = std::tmpfile();
    MonitorOptions o = commandOptions(out);
    o.mappingDir = mappings;
    EXPECT_EQ(runForceFeedbackTest(o), 0);
    return readAndClose(out);
  };
  EXPECT_NE(run(dir).find("no wheel, joystick or game controller is connected: no force feedback to test"),
            std::string::npos);
  ASSERT_GE(attachWheel().id, 0);
  // The file turns it on; a virtual device has no motor.
  EXPECT_NE(run(dir).find("'bdfcar-test wheel' has no force feedback here: SDL offers it no constant-force effect"),
            std::string::npos);
  const fs::path off = dir / "off";
  fs::create_directories(off);
  writeFile(off, "wheel.toml", "[device]\ntype = \"wheel\"\n[axes.steering]\naxis = 0\n");
  EXPECT_NE(run(off).find("its mapping wheel.toml does not turn force feedback on"), std::string::npos);
}

// Every key the mapping loader knows (it lists them to refuse unknown ones)
// is in assets/input/README.md: as `key =` in an example, as a [table], or
// in the list of actions.
TEST(MappingDocs, EveryKeyTheLoaderKnowsIsInTheReadme) {
  const fs::path shipped = BDFCAR_SHIPPED_INPUT_DIR;
  std::ifstream in(shipped / "README.md");
  const std::string readme((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(readme.empty());
  bdfcar::config::startKeyLog();
  loadMappingDir(shipped);
  parseMapping(kKeyboard, "keyboard.toml");
  parseMapping("[device]\ntype = \"wheel\"\n[speed_sensitive_steering]\nspeed = 20\nscale = 0.5\n", "w.toml");
  const auto log = bdfcar::config::stopKeyLog();
  std::size_t checked = 0;
  for (const auto& [file, key] : log) {
    const std::size_t dot = key.rfind('.');
    const std::string leaf = dot == std::string::npos ? key : key.substr(dot + 1);
    const bool documented = readme.find(leaf + " =") != std::string::npos ||
                            readme.find("[" + key + "]") != std::string::npos ||
                            readme.find("[" + key + ".") != std::string::npos ||
                            (key.rfind("actions.", 0) == 0 && readme.find(leaf + ",") != std::string::npos) ||
                            (key.rfind("actions.", 0) == 0 && readme.find(leaf + ".") != std::string::npos);
    EXPECT_TRUE(documented) << key << " (read in " << file << ") is not in assets/input/README.md";
    ++checked;
  }
  EXPECT_GT(checked, 30u);
}

}  // namespace
