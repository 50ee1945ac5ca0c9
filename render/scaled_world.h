// Private to render/: the world drawn into a texture at a fraction of the
// window's pixels and stretched over the window, the HUD drawn over it at the
// window's own resolution (its text stays sharp). At scale 1 the world is
// drawn straight into the window, as the headless renderer draws it.
#pragma once

#include <osg/Camera>
#include <osg/Switch>
#include <osg/Texture2D>

namespace bdfcar::render {

class ScaledWorld {
 public:
  // sky and world: drawn by the main camera's view (both ways); hud: on top.
  ScaledWorld(osg::Node* sky, osg::Node* world, osg::Node* hud);
  // What the viewer draws.
  osg::Group* root() const { return root_.get(); }
  // The world at scale (0 < scale <= 1) of a width x height window.
  void set(double scale, int width, int height);
  double scale() const { return scale_; }

 private:
  osg::ref_ptr<osg::Group> root_;
  osg::ref_ptr<osg::Switch> ways_;       // child 0: straight, child 1: through the texture
  osg::ref_ptr<osg::Camera> toTexture_;  // the main camera's view, into picture_
  osg::ref_ptr<osg::Texture2D> picture_;
  double scale_ = 1;
  int width_ = 0, height_ = 0;
};

}  // namespace bdfcar::render
