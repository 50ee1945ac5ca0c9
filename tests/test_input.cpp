// input/: mapping files, axis response, keyboard ramps, hot-plug, fallback to
// the keyboard and force feedback, on SDL virtual devices (no hardware, no
// display). Expected values are computed here from the numbers written in the
// test's own mapping files, not through the library's functions.
#include <SDL.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "input/axis_response.h"
#include "input/driver_controls.h"
#include "input/force_feedback.h"
#include "input/input_system.h"
#include "input/mapping.h"
#include "input/monitor.h"
#include "input_virtual.h"

namespace {

using namespace bdfcar::input;
using namespace bdfcar::test_input;

// Mapping files of the tests. The numbers here are the ones the expected
// values below are computed from.
const char* const kKeyboardToml = R"(
[device]
type = "keyboard"

[keys]
steer_left = "Left"
steer_right = "Right"
throttle = ["Up", "W"]
brake = "Down"

[ramps]
steer_rate = 2.0       # full lock in 0.5 s
centre_rate = 4.0      # straight ahead in 0.25 s
pedal_rise_rate = 5.0  # 0 -> 1 in 0.2 s
pedal_fall_rate = 10.0

[actions]
gear_up = "E"
reset = "R"
quit = "Escape"
rewind = "Backspace"
)";

const char* const kWheelToml = R"(
[device]
type = "wheel"
name_contains = ["BDFCAR-TEST"]

[axes.steering]
axis = 0
invert = true
deadzone = 0.1
curve = "power"
exponent = 2.0
gain = 1.25
min = -30000
max = 30000

[axes.throttle]
axis = 1
min = 32767
max = -32768

[axes.brake]
axis = 2
deadzone = 0.05

[actions]
gear_up = 4
reset = [6, 7]

[force_feedback]
gain = 0.5
)";

const char* const kGamepadToml = R"(
[device]
type = "gamecontroller"

[axes.steering]
axis = "leftx"
invert = true
deadzone = 0.2

[axes.throttle]
axis = "righttrigger"
curve = "power"
exponent = 0.5

[axes.brake]
axis = "lefttrigger"
gain = 2.0

[actions]
pause = "start"
gear_down = "leftshoulder"
)";

// Steering of kWheelToml: centre 0, half span 30000, inverted, deadzone 0.1, squared, gain 1.25.
double wheelSteering(int raw) {
  const double x = std::clamp(-raw / 30000.0, -1.0, 1.0);
  if (std::fabs(x) <= 0.1) return 0.0;
  const double past = (std::fabs(x) - 0.1) / 0.9;
  return std::copysign(std::min(1.0, 1.25 * past * past), x);
}

// Throttle of kWheelToml: released at +32767, fully down at -32768.
double wheelThrottle(int raw) { return std::clamp((32767.0 - raw) / 65535.0, 0.0, 1.0); }

// Brake of kWheelToml: -32768 released .. 32767 down, deadzone 0.05.
double wheelBrake(int raw) {
  const double x = (raw + 32768.0) / 65535.0;
  return x <= 0.05 ? 0.0 : (x - 0.05) / 0.95;
}

// Steering of kGamepadToml: full stick range, inverted, deadzone 0.2, linear.
double padSteering(int raw) {
  const double x = -(raw + 0.5) / 32767.5;  // centre of [-32768, 32767] is -0.5
  if (std::fabs(x) <= 0.2) return 0.0;
  return std::copysign((std::fabs(x) - 0.2) / 0.8, x);
}

// Throttle of kGamepadToml: trigger 0..32767, square root.
double padThrottle(int raw) { return std::sqrt(raw / 32767.0); }

// Brake of kGamepadToml: trigger 0..32767, gain 2, clamped at 1.
double padBrake(int raw) { return std::min(1.0, 2.0 * raw / 32767.0); }

// Unplugs a virtual device.
void detach(Virtual& v) {
  SDL_JoystickClose(v.joystick);
  ASSERT_EQ(SDL_JoystickDetachVirtual(deviceIndex(v.id)), 0) << SDL_GetError();
  v = Virtual{};
}

// Pushes a key press or release as the window system would.
void pushKey(SDL_Scancode code, bool down, bool repeat = false) {
  SDL_Event e{};
  e.type = down ? SDL_KEYDOWN : SDL_KEYUP;
  e.key.state = down ? SDL_PRESSED : SDL_RELEASED;
  e.key.repeat = repeat ? 1 : 0;
  e.key.keysym.scancode = code;
  e.key.keysym.sym = SDL_GetKeyFromScancode(code);
  ASSERT_EQ(SDL_PushEvent(&e), 1) << SDL_GetError();
}

// SDL headless, the test's mapping files, and only the test's virtual devices.
class InputDevices : public VirtualDevicesTest {
 protected:
  void SetUp() override {
    VirtualDevicesTest::SetUp();
    writeFile(dir, "keyboard.toml", kKeyboardToml);
    writeFile(dir, "wheel.toml", kWheelToml);
    writeFile(dir, "gamepad.toml", kGamepadToml);
  }
  // Options that ignore any real device on the machine.
  InputOptions options() {
    InputOptions o;
    o.mappingDir = dir;
    o.deviceFilter = kVirtualPrefix;
    o.onMessage = [this](const std::string& m) { messages.push_back(m); };
    return o;
  }
  // Whether some message contains `text`.
  bool told(const std::string& text) const {
    return std::any_of(messages.begin(), messages.end(),
                       [&](const std::string& m) { return m.find(text) != std::string::npos; });
  }
  Virtual attachWheel() { return attach(SDL_JOYSTICK_TYPE_WHEEL, "bdfcar-test wheel", 4, 8); }
  Virtual attachPad() {
    return attach(SDL_JOYSTICK_TYPE_GAMECONTROLLER, "bdfcar-test pad", SDL_CONTROLLER_AXIS_MAX,
                  SDL_CONTROLLER_BUTTON_MAX);
  }

  std::vector<std::string> messages;
};

TEST_F(InputDevices, WheelAxesMapThroughCalibrationDeadzoneCurveAndGain) {
  Virtual wheel = attachWheel();
  ASSERT_GE(wheel.id, 0) << SDL_GetError();
  // Pedals released when the wheel is opened, as the file expects them (their still reading).
  SDL_JoystickSetVirtualAxis(wheel.joystick, 1, 32767);
  SDL_JoystickSetVirtualAxis(wheel.joystick, 2, -32768);
  InputSystem input(options());
  for (int raw : {-32768, -30000, -12345, -3001, -2999, 0, 1500, 3001, 17000, 29999, 32767}) {
    SCOPED_TRACE(raw);
    SDL_JoystickSetVirtualAxis(wheel.joystick, 0, static_cast<Sint16>(raw));
    SDL_JoystickSetVirtualAxis(wheel.joystick, 1, static_cast<Sint16>(raw));
    SDL_JoystickSetVirtualAxis(wheel.joystick, 2, static_cast<Sint16>(raw));
    const Controls c = input.poll(kDt);
    EXPECT_EQ(c.source, DeviceKind::Wheel);
    EXPECT_NEAR(c.steering, wheelSteering(raw), kTol);
    EXPECT_NEAR(c.throttle, wheelThrottle(raw), kTol);
    EXPECT_NEAR(c.brake, wheelBrake(raw), kTol);
    EXPECT_FALSE(c.hasClutch);
    EXPECT_EQ(c.clutch, 0.0);
  }
  // Sanity of the expectations themselves: left of the deadzone the wheel steers left (+), saturating.
  EXPECT_EQ(wheelSteering(-32768), 1.0);
  EXPECT_EQ(wheelSteering(2999), 0.0);
}

TEST_F(InputDevices, GameControllerAxesMapAsTheFileSays) {
  Virtual pad = attachPad();
  ASSERT_GE(pad.id, 0) << SDL_GetError();
  SDL_GameController* view = SDL_GameControllerOpen(deviceIndex(pad.id));  // to read what SDL reports
  ASSERT_NE(view, nullptr) << SDL_GetError();
  // Triggers released when the pad is opened (a virtual axis at 0 reads half-way on a trigger).
  SDL_JoystickSetVirtualAxis(pad.joystick, SDL_CONTROLLER_AXIS_TRIGGERRIGHT, -32768);
  SDL_JoystickSetVirtualAxis(pad.joystick, SDL_CONTROLLER_AXIS_TRIGGERLEFT, -32768);
  InputSystem input(options());
  for (int raw : {-32768, -20000, -6553, -6000, 0, 6000, 6554, 25000, 32767}) {
    SCOPED_TRACE(raw);
    SDL_JoystickSetVirtualAxis(pad.joystick, SDL_CONTROLLER_AXIS_LEFTX, static_cast<Sint16>(raw));
    SDL_JoystickSetVirtualAxis(pad.joystick, SDL_CONTROLLER_AXIS_TRIGGERRIGHT, static_cast<Sint16>(raw));
    SDL_JoystickSetVirtualAxis(pad.joystick, SDL_CONTROLLER_AXIS_TRIGGERLEFT, static_cast<Sint16>(-raw / 2));
    const Controls c = input.poll(kDt);
    // Triggers: SDL rescales the virtual device's full range to 0..32767; read what it reports.
    const int stick = SDL_GameControllerGetAxis(view, SDL_CONTROLLER_AXIS_LEFTX);
    const int right = SDL_GameControllerGetAxis(view, SDL_CONTROLLER_AXIS_TRIGGERRIGHT);
    const int left = SDL_GameControllerGetAxis(view, SDL_CONTROLLER_AXIS_TRIGGERLEFT);
    EXPECT_EQ(stick, raw);
    EXPECT_EQ(c.source, DeviceKind::GameController);
    EXPECT_NEAR(c.steering, padSteering(stick), kTol);
    EXPECT_NEAR(c.throttle, padThrottle(right), kTol);
    EXPECT_NEAR(c.brake, padBrake(left), kTol);
  }
  SDL_GameControllerClose(view);
}

TEST_F(InputDevices, ButtonsFireActionsOnceInTheTickTheyGoDown) {
  Virtual wheel = attachWheel();
  Virtual pad = attachPad();
  InputSystem input(options());
  input.poll(kDt);
  SDL_JoystickSetVirtualButton(wheel.joystick, 4, SDL_PRESSED);
  SDL_JoystickSetVirtualButton(pad.joystick, SDL_CONTROLLER_BUTTON_START, SDL_PRESSED);
  Controls c = input.poll(kDt);
  EXPECT_TRUE(c.gearUp);
  EXPECT_TRUE(c.pause);  // from the pad while the wheel drives: actions come from every device
  EXPECT_FALSE(c.reset);
  EXPECT_EQ(c.source, DeviceKind::Wheel);
  c = input.poll(kDt);  // still held: no new edge
  EXPECT_FALSE(c.gearUp);
  EXPECT_FALSE(c.pause);
  SDL_JoystickSetVirtualButton(wheel.joystick, 7, SDL_PRESSED);  // the second of reset's two buttons
  c = input.poll(kDt);
  EXPECT_TRUE(c.reset);
  EXPECT_FALSE(c.gearDown);
}

TEST_F(InputDevices, DevicePluggedInMidDriveIsPickedUp) {
  InputSystem input(options());
  Controls c = input.poll(kDt);
  EXPECT_EQ(c.source, DeviceKind::Keyboard);
  EXPECT_TRUE(input.devices().empty());

  Virtual wheel = attachWheel();
  ASSERT_GE(wheel.id, 0) << SDL_GetError();
  SDL_JoystickSetVirtualAxis(wheel.joystick, 0, -15000);
  c = input.poll(kDt);
  EXPECT_EQ(c.source, DeviceKind::Wheel);
  EXPECT_NEAR(c.steering, wheelSteering(-15000), kTol);
  const std::vector<DeviceStatus> devices = input.devices();
  ASSERT_EQ(devices.size(), 1u);
  EXPECT_EQ(devices[0].name, "bdfcar-test wheel");
  EXPECT_EQ(devices[0].kind, DeviceKind::Wheel);
  EXPECT_EQ(fs::path(devices[0].mappingFile).filename(), "wheel.toml");
  EXPECT_TRUE(devices[0].active);
  ASSERT_EQ(devices[0].rawAxes.size(), 4u);
  EXPECT_EQ(devices[0].rawAxes[0], -15000);
  EXPECT_TRUE(told("connected 'bdfcar-test wheel' as wheel"));

  // A pad plugged in later does not take over from the wheel.
  attachPad();
  c = input.poll(kDt);
  EXPECT_EQ(c.source, DeviceKind::Wheel);
  EXPECT_EQ(input.devices().size(), 2u);
}

TEST_F(InputDevices, UnpluggedWheelFallsBackToTheKeyboardWithAMessage) {
  Virtual wheel = attachWheel();
  SDL_JoystickSetVirtualAxis(wheel.joystick, 1, 32767);  // the throttle released when opened
  InputSystem input(options());
  SDL_JoystickSetVirtualAxis(wheel.joystick, 0, -24000);
  SDL_JoystickSetVirtualAxis(wheel.joystick, 1, 10000);
  const Controls before = input.poll(kDt);
  ASSERT_EQ(before.source, DeviceKind::Wheel);
  ASSERT_GT(before.steering, 0.5);
  ASSERT_NEAR(before.throttle, wheelThrottle(10000), kTol);

  detach(wheel);
  // The keyboard (no key held) takes over from the wheel's last values and
  // ramps them down at its rates: centring 4/s, pedals falling 10/s.
  for (int n = 1; n <= 30; ++n) {
    SCOPED_TRACE(n);
    const Controls c = input.poll(kDt);
    EXPECT_EQ(c.source, DeviceKind::Keyboard);
    EXPECT_NEAR(c.steering, std::max(0.0, before.steering - 4.0 * n * kDt), 1e-9);
    EXPECT_NEAR(c.throttle, std::max(0.0, before.throttle - 10.0 * n * kDt), 1e-9);
  }
  EXPECT_TRUE(input.devices().empty());
  EXPECT_TRUE(told("'bdfcar-test wheel' unplugged"));
  EXPECT_TRUE(told("driving with the keyboard"));
}

TEST_F(InputDevices, KeyboardSteeringRampsAtTheStatedRateThenSaturates) {
  InputSystem input(options());
  pushKey(SDL_SCANCODE_LEFT, true);
  for (int n = 1; n <= 60; ++n) {  // steer_rate 2/s: full lock after 50 ticks
    SCOPED_TRACE(n);
    const Controls c = input.poll(kDt);
    EXPECT_EQ(c.source, DeviceKind::Keyboard);
    EXPECT_NEAR(c.steering, std::min(1.0, 2.0 * n * kDt), 1e-9);
  }
  pushKey(SDL_SCANCODE_LEFT, false);
  for (int n = 1; n <= 30; ++n) {  // centre_rate 4/s: straight after 25 ticks
    SCOPED_TRACE(n);
    EXPECT_NEAR(input.poll(kDt).steering, std::max(0.0, 1.0 - 4.0 * n * kDt), 1e-9);
  }
  pushKey(SDL_SCANCODE_RIGHT, true);
  for (int n = 1; n <= 10; ++n) EXPECT_NEAR(input.poll(kDt).steering, -2.0 * n * kDt, 1e-9);
  pushKey(SDL_SCANCODE_LEFT, true);  // both held: centres
  EXPECT_NEAR(input.poll(kDt).steering, -0.2 + 4.0 * kDt, 1e-9);
}

TEST_F(InputDevices, KeyboardPedalsRampUpAndDown) {
  InputSystem input(options());
  pushKey(SDL_SCANCODE_W, true);  // the second throttle key
  for (int n = 1; n <= 25; ++n) {  // pedal_rise_rate 5/s: 0 -> 1 in 0.2 s
    SCOPED_TRACE(n);
    const Controls c = input.poll(kDt);
    EXPECT_NEAR(c.throttle, std::min(1.0, 5.0 * n * kDt), 1e-9);
    EXPECT_EQ(c.brake, 0.0);
  }
  pushKey(SDL_SCANCODE_W, false);
  pushKey(SDL_SCANCODE_DOWN, true);
  const Controls c = input.poll(kDt);
  EXPECT_NEAR(c.throttle, 1.0 - 10.0 * kDt, 1e-9);
  EXPECT_NEAR(c.brake, 5.0 * kDt, 1e-9);
  EXPECT_FALSE(c.hasClutch);  // the test's keyboard binds no clutch
}

TEST_F(InputDevices, KeyActionsAreEdgeTriggered) {
  InputSystem input(options());
  pushKey(SDL_SCANCODE_R, true);
  Controls c = input.poll(kDt);
  EXPECT_TRUE(c.reset);
  EXPECT_FALSE(c.quit);
  pushKey(SDL_SCANCODE_R, true, /*repeat=*/true);  // auto-repeat is not a new press
  EXPECT_FALSE(input.poll(kDt).reset);
  pushKey(SDL_SCANCODE_R, false);
  pushKey(SDL_SCANCODE_R, true);  // released and pressed within one tick still fires
  pushKey(SDL_SCANCODE_ESCAPE, true);
  c = input.poll(kDt);
  EXPECT_TRUE(c.reset);
  EXPECT_TRUE(c.quit);
  EXPECT_FALSE(c.gearUp);
}

// Rewind is the one action a held key repeats (the key's auto-repeat): held,
// it keeps going back; the others stay one press, one action.
TEST_F(InputDevices, AHeldRewindKeyRepeatsAndNoOtherActionDoes) {
  InputSystem input(options());
  pushKey(SDL_SCANCODE_BACKSPACE, true);
  EXPECT_TRUE(input.poll(kDt).rewind);
  EXPECT_FALSE(input.poll(kDt).rewind);  // held, no repeat yet
  pushKey(SDL_SCANCODE_BACKSPACE, true, /*repeat=*/true);
  pushKey(SDL_SCANCODE_R, true, /*repeat=*/true);
  const Controls c = input.poll(kDt);
  EXPECT_TRUE(c.rewind);
  EXPECT_FALSE(c.reset);
}

TEST_F(InputDevices, ForceFeedbackIsSilentlyOffWithoutHaptics) {
  ASSERT_GE(attachWheel().id, 0);  // virtual devices have no haptic motor
  InputSystem input(options());
  input.poll(kDt);
  input.setSteeringTorque(0.7);
  input.setSteeringTorque(-2.0);
  ASSERT_EQ(input.devices().size(), 1u);
  EXPECT_FALSE(input.devices()[0].forceFeedback);
  EXPECT_EQ(input.poll(kDt).source, DeviceKind::Wheel);
}

TEST_F(InputDevices, MonitorListsDevicesAndShowsLiveValues) {
  Virtual wheel = attachWheel();
  SDL_JoystickSetVirtualAxis(wheel.joystick, 0, -15000);
  std::FILE* out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  MonitorOptions o;
  o.mappingDir = dir;
  o.deviceFilter = kVirtualPrefix;
  o.seconds = 0.03;
  o.printInterval = 0.01;
  o.out = out;
  EXPECT_EQ(runInputMonitor(o), 0);
  const std::string text = readAndClose(out);
  EXPECT_NE(text.find("'bdfcar-test wheel'  wheel  mapping wheel.toml  4 axes"), std::string::npos) << text;
  EXPECT_NE(text.find("axes [-15000 0 0 0]"), std::string::npos) << text;
  char steering[32];
  std::snprintf(steering, sizeof steering, "steering %+.3f", wheelSteering(-15000));
  EXPECT_NE(text.find(std::string("-> wheel: ") + steering), std::string::npos) << text;

  o.mappingDir = dir / "missing";
  EXPECT_EQ(runInputMonitor(o), 1);
}

// A bad mapping file: its text, the line and key the error must name, and a
// fragment of what was expected.
struct BadFile {
  const char* name;
  const char* text;
  int line;
  const char* key;
  const char* expected;
};

TEST(InputMapping, BadFilesNameFileLineKeyAndExpectation) {
  const fs::path dir = freshDir("bad");
  const BadFile cases[] = {
      {"unknown_key.toml", "[device]\ntype = \"wheel\"\n\n[axes.steering]\naxis = 0\ndeadzon = 0.1\n", 6,
       "axes.steering.deadzon", "deadzone"},
      {"rotation_on_pedal.toml", "[device]\ntype = \"wheel\"\n[axes.throttle]\naxis = 2\nrotation_deg = 900\n", 5,
       "axes.throttle.rotation_deg", "deadzone"},
      {"rotation_range.toml", "[device]\ntype = \"wheel\"\n[axes.steering]\naxis = 0\nrotation_deg = 0\n", 5,
       "axes.steering.rotation_deg", "a number in (0, 3600], got 0"},
      {"deadzone_range.toml", "[device]\ntype = \"wheel\"\n[axes.steering]\naxis = 0\n\ndeadzone = 1.5\n", 6,
       "axes.steering.deadzone", "a number in [0, 1), got 1.5"},
      {"wrong_type.toml", "[device]\ntype = \"joystick\"\n[axes.brake]\naxis = 1\ngain = \"high\"\n", 5,
       "axes.brake.gain", "a number in (0, 10], got \"high\""},
      {"wrong_bool.toml", "[device]\ntype = \"wheel\"\n[force_feedback]\ninvert = 1\n", 4,
       "force_feedback.invert", "true or false"},
      {"unknown_top.toml", "[device]\ntype = \"wheel\"\n[axis.steering]\naxis = 0\n", 3, "axis",
       "one of: device, axes, actions, force_feedback"},
      {"bad_type.toml", "[device]\ntype = \"steeringwheel\"\n", 2, "device.type", "\"wheel\""},
      {"bad_key_name.toml", "[device]\ntype = \"keyboard\"\n[keys]\nthrottle = [\"Up\", \"Upp\"]\n", 4,
       "keys.throttle", "SDL key name"},
      {"bad_button.toml", "[device]\ntype = \"gamecontroller\"\n[actions]\n\nreset = \"triangle\"\n", 5,
       "actions.reset", "game-controller button name"},
      {"exponent_linear.toml", "[device]\ntype = \"wheel\"\n[axes.throttle]\naxis = 2\nexponent = 2.0\n", 5,
       "axes.throttle.exponent", "curve = \"power\""},
      {"min_is_max.toml", "[device]\ntype = \"wheel\"\n[axes.clutch]\naxis = 1\nmin = 5\nmax = 5\n", 6,
       "axes.clutch.max", "min and max to differ"},
      {"raw_range.toml", "[device]\ntype = \"wheel\"\n[axes.clutch]\naxis = 1\nmin = -40000\n", 5,
       "axes.clutch.min", "an integer in [-32768, 32767]"},
      {"ramp_zero.toml", "[device]\ntype = \"keyboard\"\n[ramps]\nsteer_rate = 0\n", 4, "ramps.steer_rate",
       "(0, 1000]"},
      {"keyboard_name.toml", "[device]\ntype = \"keyboard\"\nname_contains = [\"x\"]\n", 3, "device.name_contains",
       "one of: type"},
      {"speed_scale_zero.toml",
       "[device]\ntype = \"wheel\"\n[speed_sensitive_steering]\nspeed = \"80 km/h\"\nscale = 0\n", 5,
       "speed_sensitive_steering.scale", "(0, 1], got 0"},
      {"speed_negative.toml",
       "[device]\ntype = \"keyboard\"\n[speed_sensitive_steering]\nspeed = \"-10 km/h\"\nscale = 0.5\n", 4,
       "speed_sensitive_steering.speed", "(0, 200]"},
      {"speed_unknown.toml",
       "[device]\ntype = \"joystick\"\n[speed_sensitive_steering]\nspeed = 20\nscale = 0.5\nmin_scale = 0.2\n", 6,
       "speed_sensitive_steering.min_scale", "one of: speed, scale"},
      {"speed_two_laws.toml",
       "[device]\ntype = \"keyboard\"\n[speed_sensitive_steering]\nspeed = 20\nscale = 0.5\nlateral_acceleration = 8\n", 6,
       "speed_sensitive_steering.lateral_acceleration", "not both"},
      {"grip_negative.toml",
       "[device]\ntype = \"keyboard\"\n[speed_sensitive_steering]\nlateral_acceleration = \"-1 m/s^2\"\nscale = 0.5\n", 4,
       "speed_sensitive_steering.lateral_acceleration", "(0, 50]"},
  };
  for (const BadFile& bad : cases) {
    SCOPED_TRACE(bad.name);
    const fs::path file = writeFile(dir, bad.name, bad.text);
    try {
      loadMappingFile(file);
      ADD_FAILURE() << "no error";
    } catch (const MappingError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(file.string() + ":" + std::to_string(bad.line) + ": ", 0), 0u) << what;
      EXPECT_NE(what.find(std::string("'") + bad.key + "'"), std::string::npos) << what;
      EXPECT_NE(what.find(bad.expected), std::string::npos) << what;
    }
  }
  fs::remove_all(dir);
}

TEST(InputMapping, SyntaxErrorsAndMissingTablesNameFileAndLine) {
  const fs::path dir = freshDir("syntax");
  const fs::path broken = writeFile(dir, "broken.toml", "[device]\ntype = \"wheel\"\ngain = = 2\n");
  EXPECT_THROW(
      {
        try {
          loadMappingFile(broken);
        } catch (const MappingError& e) {
          EXPECT_EQ(std::string(e.what()).rfind(broken.string() + ":3: ", 0), 0u) << e.what();
          throw;
        }
      },
      MappingError);
  const fs::path noDevice = writeFile(dir, "no_device.toml", "\n[axes.steering]\naxis = 0\n");
  try {
    loadMappingFile(noDevice);
    ADD_FAILURE() << "no error";
  } catch (const MappingError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(noDevice.string() + ":", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("missing key 'device': expected a table"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

// A mapping file is read within the data-file cap and never from a device:
// a 17 MiB file and /dev/zero are refused by name (the first was read whole,
// the second would never end).
TEST(InputMapping, OversizedFilesAndDevicesAreRefusedByName) {
  const fs::path dir = freshDir("oversized");
  const fs::path big = writeFile(dir, "big.toml", "# " + std::string(17u << 20, 'x') + "\n[device]\ntype = \"wheel\"\n");
  auto refused = [](const fs::path& p, const std::string& expected) {
    try {
      loadMappingFile(p);
      ADD_FAILURE() << p << " accepted";
    } catch (const MappingError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(p.string() + ":0: ", 0), 0u) << e.what();
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  refused(big, "larger than 16 MiB");
  refused("/dev/zero", "is a device, not a regular file");
  fs::remove_all(dir);
}

TEST(InputMapping, ShippedFilesLoadOnePerDeviceKindWithTheStatedKeyboardRates) {
  const std::vector<DeviceMapping> shipped = loadMappingDir(BDFCAR_SHIPPED_INPUT_DIR);
  for (DeviceKind kind : {DeviceKind::Keyboard, DeviceKind::Wheel, DeviceKind::GameController, DeviceKind::Joystick})
    EXPECT_EQ(std::count_if(shipped.begin(), shipped.end(), [&](const DeviceMapping& m) { return m.kind == kind; }),
              1)
        << deviceKindName(kind);
  const auto keyboard = std::find_if(shipped.begin(), shipped.end(),
                                     [](const DeviceMapping& m) { return m.kind == DeviceKind::Keyboard; });
  ASSERT_NE(keyboard, shipped.end());
  EXPECT_DOUBLE_EQ(1.0 / keyboard->ramps.steerRate, 0.5);      // full lock in 0.5 s
  EXPECT_DOUBLE_EQ(1.0 / keyboard->ramps.pedalRiseRate, 0.2);  // pedal 0 -> 1 in 0.2 s
  EXPECT_FALSE(keyboard->keys.steerLeft.empty());
  EXPECT_FALSE(keyboard->actions[static_cast<int>(Action::Quit)].empty());
}

TEST(InputMapping, NamedFilesBeatGenericOnesAndJoystickFilesServeWheels) {
  const auto make = [](DeviceKind kind, std::vector<std::string> names) {
    DeviceMapping m;
    m.kind = kind;
    m.nameContains = std::move(names);
    return m;
  };
  const std::vector<DeviceMapping> all = {
      make(DeviceKind::Keyboard, {}),          make(DeviceKind::Joystick, {}),
      make(DeviceKind::Wheel, {}),             make(DeviceKind::Wheel, {"g29"}),
      make(DeviceKind::GameController, {}),
  };
  EXPECT_EQ(matchMapping(all, DeviceKind::Wheel, "Logitech G29 Driving Force Racing Wheel"), 3);
  EXPECT_EQ(matchMapping(all, DeviceKind::Wheel, "Fanatec CSL"), 2);
  EXPECT_EQ(matchMapping(all, DeviceKind::Joystick, "Logitech G29 Driving Force"), 3);  // SDL did not type it a wheel
  EXPECT_EQ(matchMapping(all, DeviceKind::Joystick, "Thrustmaster T.16000M"), 1);
  EXPECT_EQ(matchMapping(all, DeviceKind::GameController, "Xbox Wireless Controller"), 4);
  EXPECT_EQ(matchMapping(all, DeviceKind::Keyboard, "keyboard"), -1);  // the keyboard is not a connected device
  const std::vector<DeviceMapping> noWheel = {make(DeviceKind::GameController, {}), make(DeviceKind::Joystick, {})};
  EXPECT_EQ(matchMapping(noWheel, DeviceKind::Wheel, "Fanatec CSL"), 1);
  EXPECT_EQ(matchMapping({make(DeviceKind::Wheel, {})}, DeviceKind::Joystick, "stick"), -1);
}

TEST(InputMapping, UnipolarInvertAndReversedCalibration) {
  AxisMapping a;
  a.bound = true;
  a.rawMin = -1000;
  a.rawMax = 1000;
  EXPECT_DOUBLE_EQ(axisResponse(a, Axis::Brake, 500), 0.75);
  a.invert = true;  // pedals: x -> 1 - x
  EXPECT_DOUBLE_EQ(axisResponse(a, Axis::Brake, 500), 0.25);
  a.invert = false;
  std::swap(a.rawMin, a.rawMax);  // a pedal whose raw value falls when pressed
  EXPECT_DOUBLE_EQ(axisResponse(a, Axis::Brake, -500), 0.75);
  EXPECT_DOUBLE_EQ(axisResponse(a, Axis::Brake, 5000), 0.0);  // beyond calibration: clamped
  EXPECT_DOUBLE_EQ(axisResponse(a, Axis::Steering, -500), 0.5);  // reversed steering reads mirrored
}

TEST(InputMapping, ForceFeedbackLevelFollowsGainInvertAndClamps) {
  ForceFeedbackMapping m{true, 0.5, false};
  EXPECT_EQ(forceFeedbackLevel(m, 0.4), 6553);  // 0.2 * 32767 = 6553.4
  EXPECT_EQ(forceFeedbackLevel(m, -3.0), -32767);
  m.invert = true;
  EXPECT_EQ(forceFeedbackLevel(m, 0.4), -6553);
  EXPECT_EQ(forceFeedbackLevel(m, std::nan("")), 0);
  m.enabled = false;
  EXPECT_EQ(forceFeedbackLevel(m, 0.4), 0);
}

}  // namespace

// A wheel whose mapping gives its rotation turns the car's steering wheel by
// its own angle (a 900 degree wheel at 20 % of its travel: 90 degrees; on a
// car with full lock at 210 degrees, 90 / 210 of full input), clamped at the
// car's lock; without it, full travel is full lock.
TEST(DriverControls, AWheelsRotationSteersTheCarsWheelByItsOwnAngle) {
  const DeviceMapping m = parseMapping("[device]\ntype = \"wheel\"\n[axes.steering]\naxis = 0\nrotation_deg = 900\n", "w.toml");
  EXPECT_EQ(m.axes[static_cast<int>(Axis::Steering)].rotationDeg, 900.0);
  const double deg = M_PI / 180.0, full = 210 * deg;
  Controls c;
  c.source = DeviceKind::Wheel;
  c.steering = 0.2;
  c.steeringWheelAngle = 0.2 * 450 * deg;
  EXPECT_NEAR(toDriverInput(c, {full}, 0.0).steer, 90.0 / 210.0, 1e-12);
  c.steering = -0.8;
  c.steeringWheelAngle = -0.8 * 450 * deg;
  EXPECT_EQ(toDriverInput(c, {full}, 0.0).steer, -1.0);  // 360 degrees: past the car's lock
  c.steeringWheelAngle = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(toDriverInput(c, {full}, 0.0).steer, -0.8);
}

// A clutch pedal is a device's clutch axis; the keyboard's clutch key is not
// (it opens the automatic clutch); gear up wins over down in one tick.
TEST(DriverControls, PedalsGearsAndHandbrakeReachTheSimulation) {
  Controls c;
  c.source = DeviceKind::Keyboard;
  c.hasClutch = true;
  c.clutch = 1.0;
  c.handbrake = 0.7;
  c.gearUp = c.gearDown = true;
  bdfcar::scenario::DriverInput in = toDriverInput(c, {1.0}, 0.0);
  EXPECT_FALSE(in.clutchPedal);
  EXPECT_EQ(in.clutch, 1.0);
  EXPECT_EQ(in.handbrake, 0.7);
  EXPECT_EQ(in.shift, 1);
  c.source = DeviceKind::Wheel;
  c.gearUp = false;
  in = toDriverInput(c, {1.0}, 0.0);
  EXPECT_TRUE(in.clutchPedal);
  EXPECT_EQ(in.shift, -1);
}
