// Private to render/: the HUD's track map (issue 30): a timed circuit's
// centre line seen from above, north up, scaled into a square panel, with
// the car as a yellow arrow at its place and heading. Drawn in the HUD
// camera's pixel coordinates (origin bottom left), like the g-g diagram.
#pragma once

#include <Eigen/Core>
#include <osg/Geode>
#include <osg/Geometry>

#include <vector>

namespace bdfcar::render {

class TrackMap {
 public:
  // line: the circuit's centre line (world x, y), closed.
  explicit TrackMap(const std::vector<Eigen::Vector2d>& line);
  osg::Geode* node() { return geode_.get(); }
  // The panel's lower left corner and side, pixels.
  void layout(float x0, float y0, float side);
  // The car's centre of mass (world x, y) and heading (rad from world x).
  void update(double x, double y, double yaw);

 private:
  osg::Vec3 toPanel(double x, double y) const;

  std::vector<Eigen::Vector2d> line_;
  Eigen::Vector2d centre_ = Eigen::Vector2d::Zero();
  double extent_ = 1;  // the line's larger side, m
  float x0_ = 0, y0_ = 0, side_ = 1;
  double carX_ = 0, carY_ = 0, carYaw_ = 0;
  osg::ref_ptr<osg::Geode> geode_;
  osg::ref_ptr<osg::Geometry> track_, car_;
};

}  // namespace bdfcar::render
