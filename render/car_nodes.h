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

struct BodyNode {
  osg::ref_ptr<osg::Group> node;                     // in the chassis frame
  osg::ref_ptr<osg::StateSet> solid, translucent;    // swapped by applyBodyDisplay
  std::string source;                                // file the mesh came from, or "box"
  std::string warning;                               // why the box fallback is drawn, if it is
  osg::ref_ptr<osg::Geometry> tailLights;            // the mesh's "taillight" parts (none on the box)
  osg::ref_ptr<osg::Node> frame;                     // the chassis as lines (suspension views), a sibling of node
  bool brakeLightsOn = false;
};

// First existing file among: path as given, under assetRoot, under the source tree; "" if none.
std::string resolveAssetPath(const std::string& path, const std::string& assetRoot);

// The body from geometry.bodyMesh (OBJ, chassis frame; material "paint" takes bodyColour),
// or a two-box body of geometry's size when the file is missing or unreadable.
BodyNode makeBodyNode(const vehicle::VehicleGeometry& geometry, const std::string& assetRoot);

// Brake lights on (the tail lights bright) or off.
void setBrakeLights(BodyNode& body, bool on);

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
