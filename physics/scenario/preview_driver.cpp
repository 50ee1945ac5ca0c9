#include "scenario/preview_driver.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <Eigen/Dense>

#include "tyre/tyre_model.h"
#include "vehicle/vehicle_sheet.h"
#include "portable_math.h"

namespace bdfcar::scenario {

namespace {
constexpr int kMaxPoints = 64;
constexpr int kMaxMoves = 16;
constexpr int kIterations = 2;       // Gauss-Newton steps from the rack's steer (the problem is nearly linear)
constexpr double kDifference = 1e-3; // of the normalised command, for the sensitivities

// The internal car's state and its rates.
struct Motion {
  double x = 0, y = 0, yaw = 0, vy = 0, r = 0;
};
}  // namespace

void PreviewDriver::predict(const PreviewCarState& s0, const double* commands, double* offsets) const {
  const vehicle::SingleTrack& c = p_.car;
  const double u = std::max(s0.vx, 1.0);
  auto rates = [&](const Motion& m, double steer) {
    const double delta = c.roadWheelPerSteer * steer;
    const double Ff = std::clamp(c.frontStiffness * (delta - (m.vy + c.a * m.r) / u), -p_.frontGrip, p_.frontGrip);
    const double Fr = std::clamp(-c.rearStiffness * (m.vy - c.b * m.r) / u, -p_.rearGrip, p_.rearGrip);
    const double cy = pm::cos(m.yaw), sy = pm::sin(m.yaw);
    return Motion{u * cy - m.vy * sy, u * sy + m.vy * cy, m.r, (Ff + Fr) / c.mass - u * m.r,
                  (c.a * Ff - c.b * Fr) / c.yawInertia};
  };
  auto advance = [](const Motion& m, const Motion& d, double h) {
    return Motion{m.x + h * d.x, m.y + h * d.y, m.yaw + h * d.yaw, m.vy + h * d.vy, m.r + h * d.r};
  };
  Motion m{s0.x, s0.y, s0.yaw, s0.vy, s0.yawRate};
  double steer = s0.steer, rate = s0.steerRate;
  const int ticks = windowTicks(), points = previewPoints(), moves = commandMoves();
  int next = 0;
  for (int k = 1; k <= ticks; ++k) {
    // The rack over the tick as the steering system moves it toward the
    // command of this part of the window (steering_system.h); Heun's method.
    const double command = commands[std::min(moves - 1, (k - 1) * moves / ticks)];
    const double a = steeringAcceleration(p_.steering, steer, rate, command, p_.tick);
    const double h = p_.tick;
    const double steerEnd = steer + (rate + 0.5 * a * h) * h;
    const Motion d0 = rates(m, steer);
    const Motion d1 = rates(advance(m, d0, h), steerEnd);
    m = advance(m, Motion{0.5 * (d0.x + d1.x), 0.5 * (d0.y + d1.y), 0.5 * (d0.yaw + d1.yaw), 0.5 * (d0.vy + d1.vy),
                          0.5 * (d0.r + d1.r)},
                h);
    steer = steerEnd;
    rate += a * h;
    // Preview point j at (j + 1) / points of the window.
    while (next < points && k >= (next + 1) * ticks / points) offsets[next++] = offset_(m.x, m.y);
  }
}

int PreviewDriver::windowTicks() const { return std::max(1, static_cast<int>(std::lround(p_.previewTime / p_.tick))); }
int PreviewDriver::previewPoints() const { return std::clamp(p_.previewPoints, 1, kMaxPoints); }
int PreviewDriver::commandMoves() const { return std::clamp(p_.commandMoves, 1, std::min(kMaxMoves, windowTicks())); }

double PreviewDriver::previewError(const PreviewCarState& s, double command) const {
  std::array<double, kMaxPoints> e{};
  std::array<double, kMaxMoves> c;
  c.fill(command);
  predict(s, c.data(), e.data());
  double sum = 0;
  for (int i = 0; i < previewPoints(); ++i) sum += e[i] * e[i];
  return sum;
}

double PreviewDriver::steer(const PreviewCarState& s) const {
  // Gauss-Newton on the commands of the window's parts: minimise
  //   sum_i e_i(c)^2 + w sum_k (delta_k - delta_k-1)^2,
  // e the preview points' offsets, delta_k = roadWheelPerSteer c_k the
  // road-wheel angles (delta_0: the rack's now), w = changeWeight.
  const int n = previewPoints(), M = commandMoves();
  const double k = p_.car.roadWheelPerSteer, w = p_.changeWeight * k * k;
  std::array<double, kMaxPoints> e{}, e1{};
  std::array<double, kMaxMoves> c;
  c.fill(std::clamp(s.steer, -1.0, 1.0));
  // Bounded sizes: no heap allocation in a tick.
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxPoints, kMaxMoves> J(n, M);
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxMoves, kMaxMoves> H(M, M);
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxMoves, 1> g(M), dc(M);
  for (int it = 0; it < kIterations; ++it) {
    predict(s, c.data(), e.data());
    for (int j = 0; j < M; ++j) {
      std::array<double, kMaxMoves> probe = c;
      const double step = c[j] + kDifference <= 1.0 ? kDifference : -kDifference;
      probe[j] += step;
      predict(s, probe.data(), e1.data());
      for (int i = 0; i < n; ++i) J(i, j) = (e1[i] - e[i]) / step;
    }
    H.noalias() = J.transpose() * J;
    g.noalias() = J.transpose() * Eigen::Map<const Eigen::VectorXd>(e.data(), n);
    // The change penalty: D c with D the first differences from the rack's steer.
    for (int j = 0; j < M; ++j) {
      const double before = j == 0 ? std::clamp(s.steer, -1.0, 1.0) : c[j - 1];
      const double d = c[j] - before;
      H(j, j) += w;
      g(j) += w * d;
      if (j > 0) {
        H(j - 1, j - 1) += w;
        H(j - 1, j) -= w;
        H(j, j - 1) -= w;
        g(j - 1) -= w * d;
      }
    }
    dc = H.ldlt().solve(-g);
    if (!dc.allFinite()) break;
    for (int j = 0; j < M; ++j) c[j] = std::clamp(c[j] + dc(j), -1.0, 1.0);
  }
  return c[0];
}

PreviewDriverParams previewDriverParams(const vehicle::Vehicle& v, double mu, double tick) {
  PreviewDriverParams p;
  p.tick = tick;
  p.car = vehicle::singleTrack(v);
  p.steering = steeringLimits(v.spec.steering);
  const vehicle::VehicleSheet sheet = vehicle::vehicleSheet(v);
  p.frontGrip = 0.5 * sheet.axleLoad[0] * (tyre::peakFriction(v.wheel(0).tyre, mu) + tyre::peakFriction(v.wheel(1).tyre, mu));
  p.rearGrip = 0.5 * sheet.axleLoad[1] * (tyre::peakFriction(v.wheel(2).tyre, mu) + tyre::peakFriction(v.wheel(3).tyre, mu));
  return p;
}

}  // namespace bdfcar::scenario
