#include "scenario/driver_paths.h"

#include <algorithm>
#include <cmath>
#include "portable_math.h"

namespace bdfcar::scenario {

PolylinePath::PolylinePath(std::vector<Eigen::Vector2d> points, bool closed) : p_(std::move(points)), closed_(closed) {
  if (closed_ && (p_.front() - p_.back()).norm() > 0) p_.push_back(p_.front());
  s_.assign(p_.size(), 0.0);
  for (size_t i = 1; i < p_.size(); ++i) s_[i] = s_[i - 1] + (p_[i] - p_[i - 1]).norm();
}

Eigen::Vector2d PolylinePath::at(double s) const {
  const double total = s_.back();
  s = closed_ ? s - total * std::floor(s / total) : std::clamp(s, 0.0, total);
  const size_t i = std::min<size_t>(std::upper_bound(s_.begin(), s_.end(), s) - s_.begin(), s_.size() - 1);
  const size_t a = i == 0 ? 0 : i - 1;
  const double len = s_[a + 1] - s_[a];
  const double u = len > 0 ? (s - s_[a]) / len : 0.0;
  return p_[a] + u * (p_[a + 1] - p_[a]);
}

Eigen::Vector2d PolylinePath::target(double x, double y, double lookAhead) const {
  const Eigen::Vector2d q(x, y);
  double best = 1e300, sBest = 0;
  for (size_t i = 0; i + 1 < p_.size(); ++i) {
    const Eigen::Vector2d d = p_[i + 1] - p_[i];
    const double u = std::clamp((q - p_[i]).dot(d) / d.squaredNorm(), 0.0, 1.0);
    const double dist = (p_[i] + u * d - q).squaredNorm();
    if (dist < best) best = dist, sBest = s_[i] + u * (s_[i + 1] - s_[i]);
  }
  return at(sBest + lookAhead);
}

Eigen::Vector2d CirclePath::target(double x, double y, double lookAhead) const {
  const double angle = pm::atan2(y - centre.y(), x - centre.x()) + direction * lookAhead / radius;
  return centre + radius * Eigen::Vector2d(pm::cos(angle), pm::sin(angle));
}

}  // namespace bdfcar::scenario
