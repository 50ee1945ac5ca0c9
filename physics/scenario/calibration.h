// What the standards do before a test so that it fits the car in hand:
//  - ISO 7401: the steering that gives the asked steady lateral
//    acceleration (4 m/s^2) at the test speed, found by runs;
//  - FMVSS 126 S7.6: the steering-wheel angle A that gives 0.3 g in the
//    slowly increasing steer (13.5 deg/s at 80 km/h), by a least-squares
//    line of the angle against the lateral acceleration, and the rule's
//    series of sine-with-dwell amplitudes from it (S7.9);
//  - ISO 4138 constant steering-wheel angle: the steering for a circle of
//    the asked radius at the starting speed.
// Plain functions of a response (one run per call) or of a time history,
// tested on the single-track car's closed forms.
#pragma once

#include <functional>
#include <vector>

#include "scenario/standard_tests.h"

namespace bdfcar::scenario {

struct Calibration {
  double input = 0;       // the input found (as the response function takes it)
  double response = 0;    // its response
  bool converged = false; // within the tolerance of the target
  std::vector<std::pair<double, double>> tries;  // (input, response), in order
};

// The input x with response(x) within tolerance (relative) of target, by
// the secant method from `guess` (the second try scaled as if the response
// were proportional), x kept in [-limit, limit]; at most maxRuns calls.
Calibration calibrate(const std::function<double(double)>& response, double target, double guess,
                      double tolerance = 0.005, int maxRuns = 8, double limit = 1.0);

// FMVSS 126 S7.6: the steering-wheel angle (the history's unit) at lateral
// acceleration ayTarget, from the line fitted by least squares to the angle
// against |a_y| over the samples with |a_y| in [low, high] while the angle
// grows. NaN when fewer than 10 samples fall in the window.
double sisAngleAt(const TimeHistory& h, double ayTarget = 0.3 * 9.80665, double low = 0.1 * 9.80665,
                  double high = 0.375 * 9.80665);

// FMVSS 126 S7.9: the amplitudes of a series from A (deg): 1.5 A, 2.0 A,
// ... in steps of 0.5 A, the last the greater of 6.5 A and 270 deg, or 300
// deg where a step would pass 300 deg.
std::vector<double> fmvss126Amplitudes(double A);

// The series' verdict (S5.2.1-S5.2.3): every run's yaw-rate ratios within
// their limits, and the lateral displacement reached in the runs of 5 A and
// more. amplitudes[i] is runs[i]'s (deg).
struct SeriesVerdict {
  bool pass = true;
  std::string why;  // the first criterion missed
};
SeriesVerdict fmvss126Verdict(const std::vector<double>& amplitudes, const std::vector<SineWithDwellMetrics>& runs, double A);

}  // namespace bdfcar::scenario
