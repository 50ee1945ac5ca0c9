// Wheel and controller setup: pedals read from where they rest. Expected
// values are the numbers the tests write into their files, worked out by
// hand here, not through the library's functions.
#include <SDL.h>
#include <gtest/gtest.h>

#include <string>

#include "input/axis_response.h"
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
)";

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

}  // namespace
