// Private to render/: the heads-up display as an orthographic OSG camera
// drawn after the scene: driving figures top left, course and camera top right,
// the g-g diagram bottom left, the message line at the bottom.
#pragma once

#include <osg/Camera>
#include <osg/Geometry>
#include <osgText/Text>

#include <memory>
#include <string>

#include "render/gg_diagram.h"
#include "render/track_map.h"
#include "render/scene.h"
#include "vehicle/vehicle_view.h"

namespace bdfcar::render {

class HudNode {
 public:
  HudNode();
  osg::Camera* node() { return camera_.get(); }
  // Sets the texts from this frame's figures (only strings that changed are re-laid out).
  void update(const vehicle::HudInfo& hud, CameraMode camera, BodyDisplay body);
  // Places panels and sizes text for a viewport of width x height pixels.
  void layout(int width, int height);
  // A map of this closed centre line, bottom right, with the car on it.
  void setTrackMap(const std::vector<Eigen::Vector2d>& line);

 private:
  osg::ref_ptr<osgText::Text> makeText(osgText::Text::AlignmentType align);
  static void setIfChanged(osgText::Text& text, const std::string& value);

  osg::ref_ptr<osg::Camera> camera_;
  osg::ref_ptr<osgText::Font> font_;
  bool unicode_ = false;  // the font has degree and superscript signs
  osg::ref_ptr<osgText::Text> figures_, course_, message_, menu_;
  osg::ref_ptr<osg::Geometry> panels_;
  std::unique_ptr<GgDiagram> gg_;  // built once the font is loaded
  std::unique_ptr<TrackMap> map_;  // a timed circuit's
  int width_ = 0, height_ = 0;
  bool showMessage_ = false;
  int courseLines_ = 2;
  int courseColumns_ = 18;
  int menuLines_ = 0, menuColumns_ = 0;  // the pause menu's panel (0: closed)
  int figureLines_ = 7;  // kFigureLines, one more with a powertrain
};

}  // namespace bdfcar::render
