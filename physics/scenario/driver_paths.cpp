#include "scenario/driver_paths.h"

#include <algorithm>
#include <cmath>
#include "portable_math.h"

namespace bdfcar::scenario {

PolylinePath::PolylinePath(std::vector<Eigen::Vector2d> points, bool closed) : p_(std::move(points)), closed_(closed) {
  if (closed_ && (p_.front() - p_.back()).norm() > 0) p_.push_back(p_.front());
  s_.assign(p_.size(), 0.0);
  for (size_t i = 1; i < p_.size(); ++i) s_[i] = s_[i - 1] + (p_[i] - p_[i - 1]).norm();
  buildGrid();
}

void PolylinePath::buildGrid() {
  const size_t segments = p_.size() - 1;
  Eigen::Vector2d lo = p_[0], hi = p_[0];
  for (const Eigen::Vector2d& x : p_) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  // Cells about twice the mean segment; a margin around the path, so that a
  // car beside it is inside the grid; at most ~1M cells.
  cell_ = std::max(2.0 * s_.back() / static_cast<double>(segments), 0.5);
  const double margin = std::max(50.0, 4.0 * cell_);
  lo -= Eigen::Vector2d::Constant(margin);
  hi += Eigen::Vector2d::Constant(margin);
  while ((hi.x() - lo.x()) / cell_ * (hi.y() - lo.y()) / cell_ > 1.0e6) cell_ *= 2.0;
  gridOrigin_ = lo;
  cols_ = static_cast<int>(std::ceil((hi.x() - lo.x()) / cell_));
  rows_ = static_cast<int>(std::ceil((hi.y() - lo.y()) / cell_));
  auto cellRange = [&](size_t i, int& c0, int& c1, int& r0, int& r1) {
    const Eigen::Vector2d a = (p_[i].cwiseMin(p_[i + 1]) - gridOrigin_) / cell_;
    const Eigen::Vector2d b = (p_[i].cwiseMax(p_[i + 1]) - gridOrigin_) / cell_;
    c0 = std::clamp(static_cast<int>(std::floor(a.x())), 0, cols_ - 1);
    c1 = std::clamp(static_cast<int>(std::floor(b.x())), 0, cols_ - 1);
    r0 = std::clamp(static_cast<int>(std::floor(a.y())), 0, rows_ - 1);
    r1 = std::clamp(static_cast<int>(std::floor(b.y())), 0, rows_ - 1);
  };
  std::vector<int> count(static_cast<size_t>(cols_) * rows_ + 1, 0);
  int c0, c1, r0, r1;
  for (size_t i = 0; i < segments; ++i) {
    cellRange(i, c0, c1, r0, r1);
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) ++count[static_cast<size_t>(r) * cols_ + c + 1];
  }
  for (size_t k = 1; k < count.size(); ++k) count[k] += count[k - 1];
  cellStart_ = count;
  cellSegments_.assign(static_cast<size_t>(count.back()), 0);
  for (size_t i = 0; i < segments; ++i) {
    cellRange(i, c0, c1, r0, r1);
    for (int r = r0; r <= r1; ++r)
      for (int c = c0; c <= c1; ++c) cellSegments_[static_cast<size_t>(count[static_cast<size_t>(r) * cols_ + c]++)] = static_cast<int>(i);
  }
}

void PolylinePath::consider(size_t i, const Eigen::Vector2d& q, Nearest& n) const {
  const Eigen::Vector2d d = p_[i + 1] - p_[i];
  const double u = std::clamp((q - p_[i]).dot(d) / d.squaredNorm(), 0.0, 1.0);
  const double dist = (p_[i] + u * d - q).squaredNorm();
  if (dist < n.dist || (dist == n.dist && i < n.index)) n = {dist, s_[i] + u * (s_[i + 1] - s_[i]), i};
}

PolylinePath::Nearest PolylinePath::scanAll(const Eigen::Vector2d& q) const {
  Nearest n;
  for (size_t i = 0; i + 1 < p_.size(); ++i) consider(i, q, n);
  return n;
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
  return at(nearest(Eigen::Vector2d(x, y)).s + lookAhead);
}

double PolylinePath::offset(double x, double y) const {
  const Eigen::Vector2d q(x, y);
  const Nearest n = nearest(q);
  const Eigen::Vector2d d = p_[n.index + 1] - p_[n.index], e = q - p_[n.index];
  const double side = d.x() * e.y() - d.y() * e.x();  // + left of the segment's direction
  return std::sqrt(n.dist) * (side < 0 ? -1.0 : 1.0);
}

PolylinePath::Nearest PolylinePath::nearest(const Eigen::Vector2d& q) const {
  const Eigen::Vector2d g = (q - gridOrigin_) / cell_;
  if (!(g.x() >= 0 && g.y() >= 0 && g.x() < cols_ && g.y() < rows_)) return scanAll(q);
  const int cx = static_cast<int>(g.x()), cy = static_cast<int>(g.y());
  Nearest n;
  const int rings = std::max({cx, cols_ - 1 - cx, cy, rows_ - 1 - cy});
  for (int ring = 0; ring <= rings; ++ring) {
    // Every segment outside the square of rings searched so far (ring - 1
    // cells around q's cell) is at least as far from q as that square's
    // nearest edge (ring - 1 cells and q's offset in its own cell); a margin
    // for rounding. Nearer than that, the nearest found is the nearest (and
    // the first of equals: none outside can tie).
    const double R = ring - 1;
    const double edge = cell_ * std::min({g.x() - (cx - R), (cx + R + 1) - g.x(), g.y() - (cy - R), (cy + R + 1) - g.y()});
    if (ring > 0 && n.dist < edge * edge * (1.0 - 1e-9)) break;
    auto visit = [&](int r, int c) {
      if (r < 0 || r >= rows_ || c < 0 || c >= cols_) return;
      const size_t cellIndex = static_cast<size_t>(r) * cols_ + c;
      for (int k = cellStart_[cellIndex]; k < cellStart_[cellIndex + 1]; ++k) consider(static_cast<size_t>(cellSegments_[k]), q, n);
    };
    if (ring == 0) {
      visit(cy, cx);
      continue;
    }
    for (int c = cx - ring; c <= cx + ring; ++c) {
      visit(cy - ring, c);
      visit(cy + ring, c);
    }
    for (int r = cy - ring + 1; r <= cy + ring - 1; ++r) {
      visit(r, cx - ring);
      visit(r, cx + ring);
    }
  }
  return n;
}

Eigen::Vector2d CirclePath::target(double x, double y, double lookAhead) const {
  const double angle = pm::atan2(y - centre.y(), x - centre.x()) + direction * lookAhead / radius;
  return centre + radius * Eigen::Vector2d(pm::cos(angle), pm::sin(angle));
}

}  // namespace bdfcar::scenario
