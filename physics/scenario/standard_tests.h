// The metrics of standard vehicle-dynamics tests, computed from a run's
// time histories (docs/STANDARD_TESTS.md gives each definition and its
// source):
//  - ISO 7401 step steer: response times and peak response times of yaw
//    rate and lateral acceleration, measured from the instant the steering
//    reaches 50 % of its step; overshoot; steady-state gains;
//  - FMVSS 126 / UN R13-H sine with dwell: yaw rate 1.00 s and 1.75 s after
//    the completion of steer as % of the peak yaw rate, lateral displacement
//    1.07 s after the beginning of steer, each with the regulation's limit;
//  - ISO 4138 steady-state circular driving, constant steering-wheel angle
//    with a slowly increasing speed: the understeer gradient, the sideslip
//    and roll gradients over a lateral-acceleration window.
// Plain functions of arrays (time, inputs, responses): tested on synthetic
// responses with known answers, then applied to simulated runs.
#pragma once

#include <string>
#include <vector>

#include "scenario/run.h"
#include "scenario/run_metrics.h"
#include "scenario/scenario_spec.h"

namespace bdfcar::scenario {

struct TimeHistory {
  std::vector<double> t;       // s, increasing
  std::vector<double> steer;   // steering-wheel angle, deg (any consistent unit)
  std::vector<double> yawRate; // rad/s
  std::vector<double> ay;      // m/s^2
  std::vector<double> x, y;    // m, centre of mass in the ground plane
  std::vector<double> heading; // rad
  std::vector<double> speed;   // m/s
  std::vector<double> sideslip, roll;  // rad
  double wheelbase = 0;        // m (ISO 4138)
  double steeringRatio = 0;    // steering-wheel angle per road-wheel angle at small angles (0: unknown)
};

// One response (yaw rate or lateral acceleration) to a step.
struct StepResponse {
  double steady = 0;        // mean over the steady window
  double gain = 0;          // steady / steady steering
  double responseTime = 0;  // s from the 50 % steering instant to 90 % of steady
  double peakTime = 0;      // s from the 50 % steering instant to the peak
  double overshoot = 0;     // (peak - steady) / steady, 0 when the peak is the steady value
};

struct StepSteerMetrics {
  bool valid = false;
  std::string why;          // when !valid
  double steerStep = 0;     // steady steering (same unit as the input)
  double t50 = 0;           // s, the steering at 50 % of its step
  StepResponse yawRate, ay;
};

// steadyWindow: the last seconds of the run over which the steady values are averaged.
StepSteerMetrics iso7401StepSteer(const TimeHistory& h, double steadyWindow = 1.0);

struct SineWithDwellMetrics {
  bool valid = false;
  std::string why;
  double beginOfSteer = 0, completionOfSteer = 0;  // s
  double peakYawRate = 0;                          // rad/s, the peak after the steering reverses
  double yawRatio1000 = 0, yawRatio1750 = 0;       // % of the peak, 1.00 s and 1.75 s after completion
  double lateralDisplacement = 0;                  // m, 1.07 s after the beginning of steer
  bool passYaw1000 = false, passYaw1750 = false, passDisplacement = false;
  // The regulation's limits (FMVSS 126 S5.2, S5.3; vehicles up to 3500 kg).
  static constexpr double kYaw1000Limit = 35.0, kYaw1750Limit = 20.0, kDisplacementLimit = 1.83;
  // The completion of steer: the second lobe back within this fraction of its peak.
  static constexpr double kZeroBand = 0.01;
};

// beginThreshold: |steer| that marks the beginning of steer (the
// regulation's 5 deg of handwheel angle when steer is in degrees).
SineWithDwellMetrics fmvss126SineWithDwell(const TimeHistory& h, double beginThreshold = 5.0);

// ISO 4138 (constant steering-wheel angle or constant radius): over the
// samples with a_y in [ayLow, ayHigh] and moving, least-squares slopes
// against a_y of
//  - delta - L / R (delta the steering-wheel angle over the steering ratio,
//    R = v / r, L the wheelbase): the understeer gradient U, since
//    delta = L / R + U a_y. With no steering ratio given, delta is taken as
//    constant (the constant steering-wheel angle method);
//  - the sideslip angle and the roll angle.
struct SteadyStateMetrics {
  bool valid = false;
  std::string method = "constant steering-wheel angle";
  std::string why;
  double steer = 0;                // steering-wheel angle, mean over the window, as the input (deg)
  double understeerGradient = 0;   // deg/g of road-wheel angle (+ understeer)
  double sideslipGradient = 0;     // deg per m/s^2
  double rollGradient = 0;         // deg per m/s^2 (+ rolling out of the turn)
  double ayLow = 0, ayHigh = 0;    // the window, m/s^2
  int samples = 0;                 // in the window
  double maxAy = 0;                // m/s^2, the largest reached
};
SteadyStateMetrics iso4138ConstantSteer(const TimeHistory& h, double ayLow = 1.0, double ayHigh = 4.0);

// A run's time history (its kept samples and steering inputs); the steering
// as steering-wheel angle in deg, from the input's full scale (rad).
TimeHistory timeHistory(const RunResult& r, double steeringWheelFull, double wheelbase = 0);
// The same with the vehicle's steering scale and wheelbase (wheel centres at design).
TimeHistory timeHistory(const RunResult& r, const vehicle::Vehicle& v);

// The scenario's standard test on a time history: its metrics as text lines
// and as one JSON object.
struct StandardTestReport {
  bool valid = false;
  std::string text, json;
  std::vector<Metric> metrics;  // flat, prefixed by the test (iso7401_..., fmvss126_...); a verdict is 1 or 0
};
StandardTestReport standardTestReport(StandardTest test, const TimeHistory& h);

// The metrics as text lines and as one JSON object.
std::string describe(const StepSteerMetrics& m);
std::string describe(const SineWithDwellMetrics& m);
std::string describe(const SteadyStateMetrics& m);
std::string toJson(const StepSteerMetrics& m);
std::string toJson(const SineWithDwellMetrics& m);
std::string toJson(const SteadyStateMetrics& m);

}  // namespace bdfcar::scenario
