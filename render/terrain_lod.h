// Private to render/: levels of detail for the ground's tiles.
//
// A terrain as fine as the rough road (0.1 m cells, half a million triangles)
// costs a software rasteriser more to transform and set up than the rest of
// the frame, even 150 m away where it covers a few pixels. Far tiles are drawn
// from coarser stand-ins made by vertex clustering; every level is indexed so
// that each corner is transformed once, not once per triangle that uses it.
#pragma once

#include <osg/Geometry>
#include <osg/Node>
#include <osg/StateSet>

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "render/osg_convert.h"

namespace bdfcar::render {

// FNV-1a over the words of a cluster's or corner's key.
struct ClusterKeyHash {
  std::size_t operator()(const std::array<std::uint32_t, 12>& k) const {
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint32_t w : k) h = (h ^ w) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

// The builder's triangles as indexed geometry: corners equal in position,
// normal, colour and texture coordinate become one vertex. The same picture.
osg::ref_ptr<osg::Geometry> weldTriangles(const TriangleBuilder& tb);

// Sums of the corners' positions and normals in each column of side `cell`
// (clusterTriangles) over every builder added: the stand-ins of tiles and
// parts drawn apart take their columns' means from one such table, so they
// meet edge to edge (a road's triangle and its neighbour may lie in two tiles).
struct ClusterMeans {
  struct Sum {
    osg::Vec3 p, n;
    int count = 0;
  };
  float cell = 0;
  std::unordered_map<std::array<std::uint32_t, 12>, Sum, ClusterKeyHash> sums;
  void add(const TriangleBuilder& tb);
};
// The tables of every level of detail's cell, over these builders.
std::vector<ClusterMeans> clusterMeans(const std::vector<const TriangleBuilder*>& builders);

// A coarser stand-in by vertex clustering: the corners in one column of side
// `cell` (m) over the xy plane and of one colour merge into one vertex at
// their mean position with their mean normal; triangles that collapse are
// dropped, repeats drawn once. Texture coordinates follow the merged position
// (world xy / texelRepeat). With `shared` (at the same cell) the position and
// normal are the column's over everything the table was built from.
osg::ref_ptr<osg::Geometry> clusterTriangles(const TriangleBuilder& tb, float cell, float texelRepeat,
                                             const ClusterMeans* shared = nullptr);

// A ground tile drawn with `state`: one indexed geometry, or, for a dense tile,
// smaller parts that each switch to coarser stand-ins with distance, so that
// a cell never spans more than a few pixels.
// Stand-ins cluster with `means` (clusterMeans of the whole ground), or with
// the tile's own when none are given. `levels`: whether the tile gets
// stand-ins at all (by default if it is dense itself; the ground also gives
// them to a dense tile's neighbours, whose triangles may share corners with
// it: a full tile beside a clustered one would leave slits between them).
bool isDense(const TriangleBuilder& tb);
osg::ref_ptr<osg::Node> groundTile(const TriangleBuilder& tb, osg::StateSet* state, float texelRepeat,
                                   const std::vector<ClusterMeans>* means, bool levels);
inline osg::ref_ptr<osg::Node> groundTile(const TriangleBuilder& tb, osg::StateSet* state, float texelRepeat) {
  return groundTile(tb, state, texelRepeat, nullptr, isDense(tb));
}

}  // namespace bdfcar::render
