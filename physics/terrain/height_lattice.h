// The ground as a height field on a world-anchored square lattice, filled by
// the terrain's own ray queries as wheels come near and kept while they
// stay: a tyre's enveloping contact (tyre/envelope.h) reads the road along
// its wheel plane from it every step, and a node is cast once, not once per
// step per wheel (a wheel moves a few nodes a step; the rear wheels follow
// the front ones' nodes). Between nodes the surface is bilinear.
//
// A node's height is a pure function of the terrain and its position (the
// first ray that asks for it decides only where the ray starts), so what a
// run reads does not depend on what the cache held: a run restored from a
// saved state, with an empty lattice, reads the same heights.
#pragma once

#include <vector>

#include "terrain/terrain.h"

namespace bdfcar::terrain {

class HeightLattice {
 public:
  explicit HeightLattice(const Terrain& terrain, double spacing = 0.05);
  double spacing() const { return spacing_; }
  void clear();

  // The bilinear surface at (x, y): its height, gradient and the friction
  // of the nearest node. Rays start at height zTop and reach `reach` metres
  // down. False where one of the four nodes around (x, y) finds no ground.
  struct Point {
    double z = 0, dzdx = 0, dzdy = 0, friction = 0.8;
  };
  bool at(double x, double y, double zTop, double reach, Point& out) const;

  // Rays cast since construction (a count for the cost reports).
  long raysCast() const { return rays_; }

 private:
  struct Slot {
    long long i = 0, j = 0;
    bool used = false, hit = false;
    double z = 0, friction = 0.8;
  };
  static constexpr int kSide = 128;  // slots per side, direct-mapped: 6.4 m at 5 cm
  const Slot& node(long long i, long long j, double zTop, double reach) const;
  const Slot& cast(Slot& s, long long i, long long j, double zTop, double reach) const;  // node's miss: its ray into s

  const Terrain& terrain_;
  double spacing_;
  mutable std::vector<Slot> slots_;
  mutable long rays_ = 0;
};

}  // namespace bdfcar::terrain
