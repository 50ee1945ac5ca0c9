// The simulator around the physics: recording and bit-exact replay, a
// steering wheel driving the car (through SDL's virtual devices, headless),
// and the path-following driver on the ISO 3888-1 course.
#include <SDL.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "input/input_system.h"
#include "scenario/run.h"
#include "session/drive_session.h"

#include "test_files.h"

using namespace bdfcar;

namespace {

using test::asset;
using test::readFile;
std::string temp(const std::string& name) { return test::tempFile("app", name); }

}  // namespace

TEST(Replay, ARecordedDriveReplaysToIdenticalTelemetry) {
  const scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/drive.toml"));
  const std::string rec = temp("drive.rec"), a = temp("drive_a.csv"), b = temp("drive_b.csv");
  {
    app::SessionOptions o;
    o.telemetryPath = a;
    o.recordPath = rec;
    app::DriveSession drive(spec, o);
    // A person's inputs: weaving, accelerating, braking (3 s).
    for (int i = 0; i < 300; ++i) {
      const double t = 0.01 * i;
      scenario::DriverInput in;
      in.steer = 0.3 * std::sin(2.0 * t) + 0.05 * std::sin(37.0 * t);
      in.throttle = t < 1.5 ? 0.6 : 0.0;
      in.brake = t > 2.2 ? 0.4 : 0.0;
      ASSERT_TRUE(drive.tick(in)) << drive.failure();
    }
  }
  const app::Recording r = app::readRecording(rec);
  EXPECT_EQ(r.inputCount(), 300);
  {
    app::SessionOptions o;
    o.telemetryPath = b;
    app::DriveSession replay(spec, o);
    for (const auto& e : r.entries) ASSERT_TRUE(replay.replay(e));
  }
  const std::string ta = readFile(a), tb = readFile(b);
  EXPECT_GT(ta.size(), 20000u);
  EXPECT_EQ(ta, tb) << "replay differs from the recorded drive";
}

TEST(Replay, ABadRecordingNamesFileAndLine) {
  const std::string rec = temp("bad.rec");
  std::ofstream(rec) << "scenario x.toml\n0 0x0p+0 0x0p+0 0x0p+0\n2 0 0 0\n";
  try {
    app::readRecording(rec);
    FAIL() << "no error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("bad.rec:3:"), std::string::npos) << e.what();
  }
}

TEST(Input, SteeringTheWheelLeftTurnsTheCarLeft) {
  setenv("SDL_VIDEODRIVER", "dummy", 1);
  ASSERT_EQ(SDL_Init(SDL_INIT_EVENTS | SDL_INIT_JOYSTICK), 0) << SDL_GetError();
  SDL_VirtualJoystickDesc desc{};
  desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
  desc.type = SDL_JOYSTICK_TYPE_WHEEL;
  desc.naxes = 4;
  desc.nbuttons = 8;
  desc.name = "bdfcar-test wheel";
  const int index = SDL_JoystickAttachVirtualEx(&desc);
  ASSERT_GE(index, 0) << SDL_GetError();
  SDL_Joystick* js = SDL_JoystickOpen(index);
  {
    input::InputOptions io;
    io.mappingDir = asset("input");  // the shipped mapping files
    io.deviceFilter = "bdfcar-test";
    input::InputSystem devices(io);
    // Full left lock, as assets/input/wheel.toml calibrates it (raw min = full left).
    SDL_JoystickSetVirtualAxis(js, 0, -32768);
    scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/drive.toml"));
    app::DriveSession drive(spec, {});
    double steer = 0;
    for (int i = 0; i < 150; ++i) {
      const input::Controls c = devices.poll(0.01);
      steer = c.steering;
      ASSERT_TRUE(drive.tick(scenario::DriverInput{0.3 * c.steering, 0.0, 0.0}));
    }
    EXPECT_GT(steer, 0.95) << "left lock reads as + (left)";
    const vehicle::VehicleView v = drive.view();
    EXPECT_GT(drive.lastSample().yawRate, 0.1) << "the car yaws to the left";
    EXPECT_GT(drive.lastSample().com.y(), spec.startY) << "and moves to the left";
    (void)v;
  }
  SDL_JoystickClose(js);
  SDL_Quit();
}

TEST(PathFollower, PassesTheIsoDoubleLaneChangeAt60WithTheReferenceSedan) {
  const scenario::ScenarioSpec spec = scenario::loadScenarioFile(asset("scenarios/iso_lane_change.toml"));
  ASSERT_NEAR(spec.speedControl.profile.target, 60 / 3.6, 1e-9);
  scenario::Simulation sim(spec);
  const scenario::RunResult r = scenario::runScenario(sim, {});
  ASSERT_TRUE(r.ok) << r.failure;
  ASSERT_TRUE(r.course.has_value());
  EXPECT_TRUE(r.course->passed) << "a corner left the course at x = " << r.course->firstFailureX;
  EXPECT_GE(r.course->exitTime, 0) << "the course was completed";
  EXPECT_EQ(r.course->coneHits, 0);
  // A real manoeuvre: the car moved into the side lane and back.
  double maxY = -1e9;
  for (const auto& s : r.samples) maxY = std::max(maxY, s.com.y());
  EXPECT_GT(maxY, spec.startY + 3.0);
  EXPECT_GT(r.course->peakLateralAcceleration, 2.0);
}
