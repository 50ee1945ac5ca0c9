// Times LFDM's 18-DOF model (uwsbel/low-fidelity-dynamic-models, its
// half-implicit solver and the Sedan data) stepping a lane change at 80 km/h
// with a 10 ms step, for scripts/lfdm_side_by_side.sh. Not part of the
// build: the script compiles it against an LFDM source tree it is given
// (nothing is fetched). Prints the median time per step over the runs and
// the real-time factor, one line each, "name value".
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "dof18_halfImplicit.h"

namespace {

// The steering of a lane change (ISO 3888-1-like, as bdfcar's lane_change.toml
// shapes it): one period of a sine of 0.1 of full lock over 2.5 s from t = 1 s.
double steering(double t) {
  const double s = t - 1.0;
  if (s < 0 || s > 2.5) return 0.0;
  return 0.1 * std::sin(2 * M_PI * s / 2.5);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    std::fprintf(stderr, "usage: %s VEHICLE_JSON TMEASY_JSON [RUNS]\n", argv[0]);
    return 2;
  }
  const int runs = argc == 4 ? std::max(1, std::atoi(argv[3])) : 5;
  const double h = 0.01, duration = 6.0, speed = 80.0 / 3.6;
  std::vector<double> perStep;
  for (int run = 0; run < runs; ++run) {
    d18SolverHalfImplicit solver;
    solver.Construct(argv[1], argv[2]);
    solver.SetTimeStep(h);
    d18::VehicleState vs;
    d18::TMeasyState lf, rf, lr, rr;
    vs._u = speed;
    for (d18::TMeasyState* tyre : {&lf, &rf, &lr, &rr}) tyre->_omega = speed / 0.3;  // about the Sedan's rolling radius
    solver.Initialize(vs, lf, rf, lr, rr);
    const int steps = static_cast<int>(std::lround(duration / h));
    double t = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) t = solver.IntegrateStep(t, 0.2, steering(t), 0.0);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    perStep.push_back(s / steps);
  }
  std::sort(perStep.begin(), perStep.end());
  const double median = perStep[perStep.size() / 2];
  std::printf("lfdm18_us_per_step %.3f\nlfdm18_real_time_factor %.0f\n", 1e6 * median, h / median);
  return 0;
}
