// Keyboard steering that a new driver can lap with (issue 30): the shipped
// keyboard mapping (assets/input/keyboard.toml) through the input system, as
// `bdfcar drive` reads it, steering the drivable sedan through the circuit's
// first corner (90 degrees left, R 70 m) at 60 km/h. The driver is a person
// tapping the arrow keys: the key toward the centre line is held while a
// point a second ahead is more than half a metre off it, none otherwise (the
// steering centres itself). With the shipped mapping the car stays on the
// 12 m road without sliding; the same keys through a mapping without
// speed-sensitive steering (full lock in 0.5 s at any speed, as before)
// leave the road or spin, which is what the test guards against.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "input/driver_controls.h"
#include "input/input_system.h"
#include "input_virtual.h"
#include "session/drive_session.h"
#include "test_files.h"

using namespace bdfcar;
using namespace bdfcar::input;
using namespace bdfcar::test_input;

namespace {

// Signed distance of (x, y) from a polyline, + left of its direction.
double offsetFrom(const std::vector<Eigen::Vector2d>& line, const Eigen::Vector2d& p) {
  double best = INFINITY, signedBest = 0;
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    const Eigen::Vector2d a = line[i], d = line[i + 1] - a;
    const double s = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    const Eigen::Vector2d r = p - (a + s * d);
    if (r.norm() < best) {
      best = r.norm();
      signedBest = d.x() * r.y() - d.y() * r.x() >= 0 ? best : -best;
    }
  }
  return signedBest;
}

void pushKey(SDL_Scancode code, bool down) {
  SDL_Event e{};
  e.type = down ? SDL_KEYDOWN : SDL_KEYUP;
  e.key.state = down ? SDL_PRESSED : SDL_RELEASED;
  e.key.keysym.scancode = code;
  e.key.keysym.sym = SDL_GetKeyFromScancode(code);
  ASSERT_EQ(SDL_PushEvent(&e), 1) << SDL_GetError();
}

struct CornerDrive {
  double maxOffset = 0;    // m, the car's centre of mass from the centre line
  double maxSideslip = 0;  // rad, at the centre of mass
  double endHeading = 0;   // rad, where the car points after the corner
};

// The first corner at 60 km/h with the keyboard mapping in `mappingDir`.
CornerDrive driveTheFirstCorner(const fs::path& mappingDir) {
  const std::vector<config::Setting> settings{config::parseSetting("start.position=[730.0, 0.0]"),
                                              config::parseSetting("start.speed=\"60 km/h\""),
                                              config::parseSetting("scenario.duration=\"13 s\"")};
  const scenario::ScenarioSpec spec =
      scenario::loadScenarioFile(test::asset("scenarios/proving_ground/circuit_lap.toml"), settings);
  app::DriveSession d(spec, {});
  const scenario::CarSteering car = d.simulation().carSteering();
  InputOptions o;
  o.mappingDir = mappingDir;
  o.deviceFilter = kVirtualPrefix;  // the keyboard only, whatever is plugged in
  InputSystem input(o);
  const std::vector<Eigen::Vector2d>& line = spec.pathFollower.points;
  bool left = false, right = false;
  CornerDrive r;
  while (!d.finished()) {
    const vehicle::VehicleSample& s = d.lastSample();
    // The person: a point a second ahead along the heading, against the line.
    const Eigen::Vector2d ahead =
        s.com.head<2>() + std::max(s.speed, 1.0) * Eigen::Vector2d(std::cos(s.yaw), std::sin(s.yaw));
    const double e = offsetFrom(line, ahead);
    const bool wantLeft = e < -0.5, wantRight = e > 0.5;
    if (wantLeft != left) pushKey(SDL_SCANCODE_LEFT, left = wantLeft);
    if (wantRight != right) pushKey(SDL_SCANCODE_RIGHT, right = wantRight);
    const Controls c = input.poll(kDt);
    if (!d.tick(toDriverInput(c, car, s.speed))) {
      ADD_FAILURE() << d.failure();
      break;
    }
    r.maxOffset = std::max(r.maxOffset, std::abs(offsetFrom(line, d.lastSample().com.head<2>())));
    r.maxSideslip = std::max(r.maxSideslip, std::abs(d.lastSample().sideslip));
  }
  r.endHeading = d.lastSample().yaw;
  return r;
}

class KeyboardDriving : public VirtualDevicesTest {};

TEST_F(KeyboardDriving, ANewDriverTakesTheFirstCornerAt60OnTheShippedKeyboard) {
  const CornerDrive shipped = driveTheFirstCorner(BDFCAR_SHIPPED_INPUT_DIR);
  // On the 12 m road: the car's half width (1.1 m) inside its 6 m half.
  EXPECT_LT(shipped.maxOffset, 6.0 - 1.1);
  EXPECT_LT(shipped.maxSideslip, 3.0 * M_PI / 180.0);  // gripping, not sliding
  EXPECT_NEAR(shipped.endHeading, M_PI / 2, 0.15);     // out of the corner heading north

  // The keyboard as it was: the same file without speed-sensitive steering.
  std::ifstream in(std::string(BDFCAR_SHIPPED_INPUT_DIR) + "/keyboard.toml");
  std::stringstream text;
  text << in.rdbuf();
  std::string old = text.str();
  const size_t table = old.find("[speed_sensitive_steering]");
  ASSERT_NE(table, std::string::npos) << "the shipped keyboard has no speed-sensitive steering";
  old.erase(table, old.find("\n\n", table) - table);
  writeFile(dir, "keyboard.toml", old);
  const CornerDrive before = driveTheFirstCorner(dir);
  std::printf("first corner at 60 km/h on the keys: shipped mapping %.2f m off the line at most, sideslip %.2f deg; "
              "without speed-sensitive steering %.2f m, %.2f deg\n",
              shipped.maxOffset, shipped.maxSideslip * 180 / M_PI, before.maxOffset, before.maxSideslip * 180 / M_PI);
  EXPECT_TRUE(before.maxOffset > 6.0 - 1.1 || before.maxSideslip > 3.0 * M_PI / 180.0)
      << "offset " << before.maxOffset << " m, sideslip " << before.maxSideslip * 180 / M_PI << " deg";
}

}  // namespace
