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

#include "render/osg_convert.h"

namespace bdfcar::render {

// The builder's triangles as indexed geometry: corners equal in position,
// normal, colour and texture coordinate become one vertex. The same picture.
osg::ref_ptr<osg::Geometry> weldTriangles(const TriangleBuilder& tb);

// A coarser stand-in by vertex clustering: the corners in one cube of side
// `cell` (m) and of one colour merge into one vertex at their mean position
// with their mean normal; triangles that collapse are dropped, repeats drawn
// once. Texture coordinates follow the merged position (world xy / texelRepeat).
osg::ref_ptr<osg::Geometry> clusterTriangles(const TriangleBuilder& tb, float cell, float texelRepeat);

// A ground tile drawn with `state`: one indexed geometry, or, for a dense tile,
// smaller tiles that each switch to coarser stand-ins with distance, so that
// a cell never spans more than a few pixels.
osg::ref_ptr<osg::Node> groundTile(const TriangleBuilder& tb, osg::StateSet* state, float texelRepeat);

}  // namespace bdfcar::render
