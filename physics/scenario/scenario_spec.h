// A scenario as plain data (assets/scenarios/*.toml): which vehicle on which
// terrain, how it starts, what the driver does, how it is integrated and how
// long it runs. Times are manoeuvre time: tau = 0 after the settling phase.
#pragma once

#include <string>
#include <vector>

namespace bdfcar::scenario {

enum class IntegratorMethod { Bdf, Rk4, SemiImplicitEuler };

struct IntegratorSpec {
  IntegratorMethod method = IntegratorMethod::Bdf;
  double step = 0.01;          // s
  int order = 2;               // BDF order
  int newtonIterations = 2;    // 0 = iterate to tolerance
  int jacobianEvery = 200;     // steps; 0 = first step only
  bool refreshWhenNotContracting = true;
  double atol = 1e-6, rtol = 1e-6;  // Newton tolerance when iterating to tolerance
};

// A scripted input channel (steering in [-1, 1], throttle and brake in [0, 1]).
struct SignalSpec {
  enum class Kind { None, Constant, Ramp, Sine, Table } kind = Kind::None;
  double start = 0, duration = 0, level = 0;  // ramp: from 0 at start to level after duration; sine: period = duration, amplitude = level
  std::vector<double> times, values;          // table
};

struct SpeedControlSpec {
  bool enabled = false;
  double target = 0;           // m/s
  double kp = 600, ki = 300;   // per driven wheel: N m/(m/s), N m/m
};

struct CourseSpec {
  bool iso3888 = false;
  double startX = 50;          // m, where the course begins
};

struct PathFollowerSpec {
  bool enabled = false;
  double lookAheadTime = 0.9;  // s
  double minLookAhead = 5.0;   // m
};

struct ScenarioSpec {
  std::string name, sourceFile;
  std::string vehicleFile, terrainFile;  // resolved paths; terrainFile empty = flat plane z = 0
  double duration = 4.0;       // manoeuvre time, s
  double initialSpeed = 0;     // m/s
  double settleTime = 0;       // s of straight running before tau = 0 (not recorded)
  double startX = 0, startY = 0, startHeading = 0;  // m, m, rad
  double outputInterval = 0.01;  // telemetry period, s
  int raysPerWheel = 1;
  IntegratorSpec integrator;
  SignalSpec steering, throttle, brake;
  SpeedControlSpec speedControl;
  CourseSpec course;
  PathFollowerSpec pathFollower;
};

// Loads a scenario file; throws config::ConfigError with file:line; the
// vehicle and terrain paths are resolved relative to the scenario file and
// must exist.
ScenarioSpec loadScenarioFile(const std::string& path);

}  // namespace bdfcar::scenario
