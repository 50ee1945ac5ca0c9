// Private to render/: the HUD's g-g diagram. Rings at 0.5 g and 1 g and a dot
// at the car's acceleration in the ground plane, seen from above with the car
// pointing up the screen: accelerating moves the dot up, braking down, a left
// turn (a_y > 0, + left, docs/TELEMETRY.md) to the left. The dot's last half
// second trails behind it, fading. Drawn in the HUD camera's pixel coordinates
// (origin bottom left).
#pragma once

#include <osg/Geode>
#include <osg/Geometry>
#include <osgText/Text>

#include <deque>

namespace bdfcar::render {

class GgDiagram {
 public:
  explicit GgDiagram(osgText::Font* font);
  osg::Geode* node() { return geode_.get(); }
  // Centre (cx, cy) and the 1 g ring's radius, pixels; textSize for the ring's label.
  void layout(float cx, float cy, float radius, float textSize);
  // This frame's acceleration: ax along chassis x (+ forward), ay along chassis y
  // (+ left), m/s^2, at simulated time `time` (a time going back clears the trail).
  void update(double time, double ax, double ay);

  static constexpr float kClampG = 1.2f;  // the dot stops at this ring, on the panel

 private:
  struct Sample {
    double time;
    osg::Vec2 at;  // in units of the 1 g radius, from the centre
  };
  void redraw();

  osg::ref_ptr<osg::Geode> geode_;
  osg::ref_ptr<osg::Geometry> grid_, trail_, dot_;
  osg::ref_ptr<osgText::Text> label_;
  std::deque<Sample> samples_;  // oldest first, the last one is the dot
  float cx_ = 0, cy_ = 0, radius_ = 1;
};

}  // namespace bdfcar::render
