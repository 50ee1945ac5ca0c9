// Private to render/: the car's parts as OSG nodes (body, wheels, suspension links).
#pragma once

#include <osg/Geometry>
#include <osg/Group>
#include <osg/MatrixTransform>
#include <osg/StateSet>

#include <string>
#include <vector>

#include "render/scene.h"
#include "vehicle/vehicle_view.h"

namespace bdfcar::render {

// Lamps of the body mesh (a material of their own): one drawable, unlit (they
// glow whatever the sun), in one of two colours.
struct Lamp {
  osg::ref_ptr<osg::Geometry> geometry;  // none if the mesh has no such part (the box has none)
  osg::Vec4 off, on;
  bool lit = false;
};

struct BodyNode {
  osg::ref_ptr<osg::Group> node;                     // in the chassis frame
  osg::ref_ptr<osg::StateSet> solid, translucent;    // swapped by applyBodyDisplay
  std::string source;                                // file the mesh came from, or "box"
  std::string warning;                               // why the box fallback is drawn, if it is
  Lamp brakeLights;                                  // the mesh's "taillight" parts: dark red, bright when braking
  Lamp reverseLights;                                // its "reverselight" parts: grey glass, white in reverse gear
  osg::ref_ptr<osg::Node> frame;                     // the chassis as lines (suspension views), a sibling of node
};

// First existing file among: path as given, under assetRoot, under the source tree; "" if none.
std::string resolveAssetPath(const std::string& path, const std::string& assetRoot);

// The body from geometry.bodyMesh (OBJ, chassis frame; material "paint" takes bodyColour),
// or a two-box body of geometry's size when the file is missing or unreadable.
BodyNode makeBodyNode(const vehicle::VehicleGeometry& geometry, const std::string& assetRoot);

// Lights a lamp (brake lights, reverse lights) or puts it out.
void setLamp(Lamp& lamp, bool on);

// Solid, see-through (the links inside show) or hidden body.
void applyBodyDisplay(BodyNode& body, BodyDisplay display);

// A wheel in its spindle frame (y = spin axis): tyre, rim and five spokes on both faces.
osg::ref_ptr<osg::Node> makeWheelNode(double radius, double width);

// Cylinders for the suspension links, re-placed every frame from world segments.
class LinkPool {
 public:
  LinkPool();
  osg::Group* node() { return group_.get(); }
  // Shows one cylinder per segment (growing the pool as needed) and hides the rest.
  void update(const std::vector<vehicle::LinkSegment>& links);

 private:
  osg::ref_ptr<osg::Group> group_;
  std::vector<osg::ref_ptr<osg::MatrixTransform>> pool_;
  std::vector<osg::ref_ptr<osg::Node>> unitCylinders_;  // one per LinkKind, radius 1, length 1 along z
};

}  // namespace bdfcar::render
