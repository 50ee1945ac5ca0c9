#include "terrain/height_lattice.h"

#include <cmath>

namespace bdfcar::terrain {

HeightLattice::HeightLattice(const Terrain& terrain, double spacing)
    : terrain_(terrain), spacing_(spacing), slots_(kSide * kSide) {}

void HeightLattice::clear() {
  for (Slot& s : slots_) s.used = false;
}

// The hit inline, the miss (a ray) out of line: a profile's samples find
// their four nodes cast nearly every time, where the call cost as much as the lookup.
inline const HeightLattice::Slot& HeightLattice::node(long long i, long long j, double zTop, double reach) const {
  // Two's complement: & keeps non-negative indices for negative i, j.
  Slot& s = slots_[static_cast<std::size_t>((i & (kSide - 1)) * kSide + (j & (kSide - 1)))];
  if (s.used && s.i == i && s.j == j) [[likely]] return s;
  return cast(s, i, j, zTop, reach);
}

const HeightLattice::Slot& HeightLattice::cast(Slot& s, long long i, long long j, double zTop, double reach) const {
  const Hit h = terrain_.castRay(Eigen::Vector3d(i * spacing_, j * spacing_, zTop), -Eigen::Vector3d::UnitZ(), reach);
  ++rays_;
  s.i = i;
  s.j = j;
  s.used = true;
  s.hit = h.hit;
  s.z = h.point.z();
  s.friction = h.friction;
  return s;
}

bool HeightLattice::at(double x, double y, double zTop, double reach, Point& out) const {
  const double fx = x / spacing_, fy = y / spacing_;
  const long long i = static_cast<long long>(std::floor(fx)), j = static_cast<long long>(std::floor(fy));
  const double u = fx - i, v = fy - j;
  const Slot& a = node(i, j, zTop, reach);
  const Slot& b = node(i + 1, j, zTop, reach);
  const Slot& c = node(i, j + 1, zTop, reach);
  const Slot& d = node(i + 1, j + 1, zTop, reach);
  if (!(a.hit && b.hit && c.hit && d.hit)) return false;
  const double za = a.z, zb = b.z, zc = c.z, zd = d.z;
  out.z = (1 - u) * (1 - v) * za + u * (1 - v) * zb + (1 - u) * v * zc + u * v * zd;
  out.dzdx = ((1 - v) * (zb - za) + v * (zd - zc)) / spacing_;
  out.dzdy = ((1 - u) * (zc - za) + u * (zd - zb)) / spacing_;
  const Slot& nearest = u < 0.5 ? (v < 0.5 ? a : c) : (v < 0.5 ? b : d);
  out.friction = nearest.friction;
  return true;
}

}  // namespace bdfcar::terrain
