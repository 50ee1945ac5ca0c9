// A test DAE that stalls Newton the way a tyre does on a rough road: a
// wheel whose slip force saturates (its stiffness in the iteration matrix 25
// times the wheel's inertia term, as a car's tyre at 80 km/h), driven by a
// road velocity that jumps at every step. Used by test_fast_columns and
// test_allocation.
#pragma once

#include <cmath>
#include <utility>
#include <vector>

#include "integrator/dae.h"

namespace bdfcar::test {

using integ::Vec;

// Coordinates: x (a carriage, m), w (its wheel's spin angle, rad), z (a
// coordinate held at zero by the one constraint, so the constraint path is
// exercised too). The wheel's slip force F = F0 s / sqrt(1 + s^2),
// s = C (R w' - x' - u(t)) / F0, pushes the carriage and brakes the wheel.
class SaturatingWheel final : public integ::Dae {
 public:
  // parts: the fast column's slip-force share given analytically
  // (Dae::fastColumnParts), as a vehicle's tyres give theirs.
  SaturatingWheel(std::vector<int> fast, double roadAmplitude, bool parts = false)
      : fast_(std::move(fast)), amplitude_(roadAmplitude), parts_(parts) {}
  integ::DaeSizes sizes() const override { return {3, 3, 1}; }
  void retract(const Vec& q, const Vec& dq, Vec& out) const override { out = q + dq; }
  void localCoordinates(const Vec& base, const Vec& q, Vec& out) const override { out = q - base; }
  void localRate(const Vec&, const Vec& v, Vec& out) const override { out = v; }
  const std::vector<int>& fastColumns() const override { return fast_; }

  // The road's velocity under the wheel: a new pseudo-random value in
  // [-amplitude, amplitude] every 10 ms.
  double road(double t) const {
    const long k = std::lround(std::floor(t / 0.01 + 1e-9));
    const double r = std::sin(12.9898 * static_cast<double>(k)) * 43758.5453;
    return amplitude_ * (2.0 * (r - std::floor(r)) - 1.0);
  }
  double slipForce(double vCarriage, double spin, double t) const {
    const double s = kC * (kR * spin - vCarriage - road(t)) / kF0;
    return kF0 * s / std::sqrt(1.0 + s * s);
  }

  bool hasFastColumnParts() const override { return parts_ && !fast_.empty(); }
  // dF/dv_k of the slip force at the last residual's state: F0 s / sqrt(1 + s^2)
  // has the slope C R (1 + s^2)^-3/2 in the spin rate.
  void fastColumnParts(double t, integ::Mat& parts) override {
    parts.setZero(3, static_cast<int>(fast_.size()));
    const double s = kC * (kR * last_(1) - last_(0) - road(t)) / kF0;
    const double slope = kC * kR / std::pow(1.0 + s * s, 1.5);
    for (size_t k = 0; k < fast_.size(); ++k) {
      if (fast_[k] != 1) continue;
      parts(0, static_cast<int>(k)) = -slope;
      parts(1, static_cast<int>(k)) = kR * slope;
    }
  }

  // The spin's own row (kI a + kR F) moves by kR times the slip force's
  // change when the spin rate moves by dv (Dae::fastRowChange).
  bool fastRowChange(double t, int k, double dv, double& change) override {
    if (!parts_ || fast_[k] != 1) return false;
    change = kR * (slipForce(last_(0), last_(1) + dv, t) - slipForce(last_(0), last_(1), t));
    return true;
  }

  integ::EvalStatus residual(double t, const Vec& q, const Vec& v, const Vec& a, const Vec& lambda,
                             integ::Residual& out, bool withConstraints, integ::Message&) override {
    last_ = v;
    const double F = slipForce(v(0), v(1), t);
    out.F(0) = kM * a(0) + kDamping * (v(0) - 15.0) - F;  // pulled towards 15 m/s
    out.F(1) = kI * a(1) + kR * F;
    out.F(2) = kM * a(2) - lambda(0);
    if (withConstraints) {
      out.phi(0) = q(2);
      out.phiDot(0) = v(2);
      out.phiDDot(0) = a(2);
    }
    return integ::EvalStatus::Ok;
  }

  static constexpr double kM = 50, kI = 0.05, kR = 0.3, kF0 = 100, kC = 2000, kDamping = 20;

 private:
  std::vector<int> fast_;
  double amplitude_;
  bool parts_;
  Vec last_ = Vec::Zero(3);  // the last residual's velocities
};

}  // namespace bdfcar::test
