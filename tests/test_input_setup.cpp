// Wheel and controller setup: pedals read from where they rest, and
// speed-sensitive steering. Expected values are the numbers the tests write
// into their files, worked out by hand here, not through the library's functions.
#include <SDL.h>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "config/toml_reader.h"
#include "input/axis_response.h"
#include "input/driver_controls.h"
#include "input/input_system.h"
#include "input/mapping.h"
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

// 72 km/h = 20 m/s, scale 0.4: the factor falls from 1 to 0.4 over 0..20 m/s.
TEST(SpeedSensitiveSteering, FollowsTheStatedLineAndIsOffByDefault) {
  const DeviceMapping keyboard = parseMapping(kKeyboard, "keyboard.toml");
  EXPECT_NEAR(keyboard.speedSensitive.speed, 20.0, 1e-12);
  Controls c;
  c.steering = 0.5;
  c.speedSensitive = keyboard.speedSensitive;
  EXPECT_EQ(toDriverInput(c, 1.0, 0.0).steer, 0.5);
  EXPECT_NEAR(toDriverInput(c, 1.0, 5.0).steer, 0.425, kTol);   // 0.5 * (1 - 0.6 * 0.25)
  EXPECT_NEAR(toDriverInput(c, 1.0, 10.0).steer, 0.35, kTol);   // 0.5 * (1 - 0.6 * 0.5)
  EXPECT_NEAR(toDriverInput(c, 1.0, -10.0).steer, 0.35, kTol);  // reversing
  EXPECT_NEAR(toDriverInput(c, 1.0, 20.0).steer, 0.2, kTol);
  EXPECT_NEAR(toDriverInput(c, 1.0, 45.0).steer, 0.2, kTol);    // held above the speed
  // A wheel turning the car's wheel by its own angle: 90 of 210 degrees, then x 0.7 at 10 m/s.
  c.steeringWheelAngle = 90.0 * M_PI / 180.0;
  EXPECT_NEAR(toDriverInput(c, 210.0 * M_PI / 180.0, 10.0).steer, 0.3, kTol);

  // Off (no table): the input bit for bit what it was, at any speed.
  const DeviceMapping plain = shippedLikeWheel();
  EXPECT_EQ(plain.speedSensitive.speed, 0.0);
  Controls d;
  d.speedSensitive = plain.speedSensitive;
  for (double steer : {-1.0, -0.123456789, 0.0, 0.3, 0.987654321}) {
    d.steering = steer;
    for (double v : {0.0, 3.3, 27.8, 80.0}) {
      EXPECT_EQ(toDriverInput(d, 1.0, v), toDriverInput(d, 1.0, 0.0));
      EXPECT_EQ(toDriverInput(d, 1.0, v).steer, steer);
    }
  }
  EXPECT_EQ(speedSensitiveFactor(plain.speedSensitive, 50.0), 1.0);
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
