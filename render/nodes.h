// Private to render/: builders of the static parts of the scene graph.
#pragma once

#include <osg/MatrixTransform>
#include <osg/Node>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "render/surface_sampler.h"
#include "terrain/terrain_data.h"
#include "terrain/terrain_mesh.h"

namespace bdfcar::render {

// Opaque draw order, nearest things first so that llvmpipe's early depth test
// rejects hidden ground pixels before shading them (fill rate is the cost);
// what lies beneath the ground (terrain::TriangleMesh::firstBeneath) last.
constexpr int kBinRoadPaint = 1, kBinAsphalt = 2, kBinGround = 3, kBinBeneath = 4, kBinSky = 9;

// Colours shared by sky, fog and clear colour.
inline const osg::Vec4 kSkyZenith(0.22f, 0.43f, 0.78f, 1.0f);
inline const osg::Vec4 kSkyHorizon(0.74f, 0.83f, 0.93f, 1.0f);

// Gradient sky dome (radius 1000 m) drawn behind everything; move it to the eye each frame.
osg::ref_ptr<osg::MatrixTransform> makeSkyDome();

// The terrain triangles with a grass texture (one texture repeat every 5 m).
osg::ref_ptr<osg::Node> makeGroundNode(const terrain::TriangleMesh& mesh);

// The road's markings (data.road: along the terrain's x) draped on the
// terrain: edge lines and dashed lane lines, on a plane over an asphalt ribbon.
osg::ref_ptr<osg::Node> makeRoadNode(const terrain::TerrainData& data, const SurfaceSampler& ground);

// Traffic cones standing on the terrain at the given ground points.
// One transform per cone (course order) under `group`, for knockCone.
osg::ref_ptr<osg::Group> makeConesNode(const std::vector<Eigen::Vector3d>& cones, const SurfaceSampler& ground);
// Cone `index` of a cones node lying on its side, knocked over toward the heading (rad).
void knockCone(osg::Group& cones, int index, double heading);

// Soft dark ellipse to lay under the car (length x width, m), in the xy plane.
osg::ref_ptr<osg::Node> makeShadowNode(double length, double width);

}  // namespace bdfcar::render
