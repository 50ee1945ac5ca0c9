// Private to render/: levels of detail for the ground's tiles.
//
// A terrain as fine as the rough road (0.1 m cells, half a million triangles)
// costs a software rasteriser more to transform and set up than the rest of
// the frame, even 150 m away where it covers a few pixels. Far tiles are drawn
// from coarser stand-ins made by vertex clustering, as soon as what they take
// away is under a pixel; every level is indexed so that each corner is
// transformed once, not once per triangle that uses it.
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

// The distance (m) from which `size` m across the line of sight covers less
// than a pixel (720 lines over a 60 deg field): where a simpler stand-in
// that strays `size` from the finer geometry takes over.
float underAPixelFrom(float size);

// The builder's triangles as indexed geometry: corners equal in position,
// normal, colour and texture coordinate become one vertex. The same picture.
osg::ref_ptr<osg::Geometry> weldTriangles(const TriangleBuilder& tb);

// Where the corners of one look's triangles (every tile's) lie on its
// outline: an outline edge is one a single triangle uses (where asphalt
// meets grass, a road's end), not a cut between tiles or parts. A corner is
// inside (kInside), on outline edges facing outwards in one of eight
// directions (1..8), or held (kHeld: it stays where it is in every
// stand-in): where the outline turns, every corner of the tiles
// `drawnInFull` (the look's tiles that get no stand-ins: a corner moved
// beside one would open a crack to it), and the corners of triangles longer
// than two parts (the plane around the pieces).
constexpr std::uint8_t kInside = 0, kHeld = 255;
class LookOutline {
 public:
  explicit LookOutline(const std::vector<const TriangleBuilder*>& tiles,
                       const std::vector<const TriangleBuilder*>& drawnInFull = {});
  // Each of the builder's corners' place (the builder: a tile or part of the look).
  std::vector<std::uint8_t> places(const TriangleBuilder& tb) const;

 private:
  std::unordered_map<std::uint64_t, std::uint8_t> place_;  // by the corner's position; inside ones absent
};

// Sums of the corners' positions and normals in each column of side `cell`
// (clusterTriangles), by their place on the outline (held corners left out),
// over every builder added: the stand-ins of tiles and parts drawn apart take
// their clusters' means from one such table, so they meet edge to edge (a
// road's triangle and its neighbour may lie in two tiles).
struct ClusterMeans {
  struct Sum {
    osg::Vec3 p, n;
    int count = 0;
  };
  float cell = 0;
  std::unordered_map<std::array<std::uint32_t, 12>, Sum, ClusterKeyHash> sums;
  void add(const TriangleBuilder& tb, const std::vector<std::uint8_t>& places);
};
// The tables of every level of detail's cell, over these builders (their
// corners' places alongside).
std::vector<ClusterMeans> clusterMeans(const std::vector<const TriangleBuilder*>& builders,
                                       const std::vector<const std::vector<std::uint8_t>*>& places);

// A coarser stand-in by vertex clustering: the corners in one column of side
// `cell` (m) over the xy plane and of one colour merge into one vertex at
// their mean position with their mean normal; triangles that collapse are
// dropped, repeats drawn once. Texture coordinates follow the merged position
// (world xy / texelRepeat). Corners on the outline (`places`, by default
// those of the builder's own outline) cluster apart from the inside, by the
// direction the outline faces there: a straight edge between two looks stays
// where it is (asphalt and grass meet on their line, not on a staircase of
// columns); held corners stay put. With `shared` (at the same cell) a vertex
// is its cluster's mean over everything the table was built from. `error`:
// the largest distance of a corner from its merged vertex's tangent plane,
// or the cell times the sine of the largest angle between their normals
// (the relief a stand-in takes away, as a height), m.
osg::ref_ptr<osg::Geometry> clusterTriangles(const TriangleBuilder& tb, float cell, float texelRepeat,
                                             const std::vector<std::uint8_t>* places = nullptr,
                                             const ClusterMeans* shared = nullptr, float* error = nullptr);

// A ground tile drawn with `state`: one indexed geometry, or, for a dense tile,
// smaller parts that each switch to coarser stand-ins with distance: where a
// stand-in's error would be under a pixel (at 720 lines over 60 deg), and
// never later than where a cell is about 5 pixels deep; a stand-in without
// error (a level or evenly sloped stretch) replaces the finer level outright.
// `look` (the outline of the tile's look) and `means` (clusterMeans over that
// look's tiles) default to the tile's own. `levels`: whether the tile gets
// stand-ins at all (by default if it is dense itself; the ground also gives
// them to a dense tile's neighbours, whose triangles may share corners with
// it: a full tile beside a clustered one would leave slits between them).
bool isDense(const TriangleBuilder& tb);
osg::ref_ptr<osg::Node> groundTile(const TriangleBuilder& tb, osg::StateSet* state, float texelRepeat,
                                   const LookOutline* look, const std::vector<ClusterMeans>* means, bool levels);
// A tile that is not dense but still has triangles to spare far away (a
// circuit's curbs: 1,500 triangles 800 m off): whole, with the stand-ins
// (its own outline kept) a dense tile's part takes, at the same distances. The corners where it meets its neighbours may move: only
// for a layer drawn over another, where a slit shows the layer beneath,
// not the sky.
osg::ref_ptr<osg::Node> thinnedWithDistance(const TriangleBuilder& tb, osg::StateSet* state, float texelRepeat);
inline osg::ref_ptr<osg::Node> groundTile(const TriangleBuilder& tb, osg::StateSet* state, float texelRepeat) {
  return groundTile(tb, state, texelRepeat, nullptr, nullptr, isDense(tb));
}

}  // namespace bdfcar::render
