#include "render/scaled_world.h"

#include <osg/Geometry>
#include <osg/Depth>

#include <algorithm>
#include <cmath>

#include "render/nodes.h"

namespace bdfcar::render {

namespace {

// The picture over the whole viewport: unlit, no depth, no fog.
osg::ref_ptr<osg::Camera> makeStretchCamera(osg::Texture2D* picture) {
  osg::ref_ptr<osg::Camera> stretch = new osg::Camera;
  stretch->setReferenceFrame(osg::Transform::ABSOLUTE_RF);
  stretch->setRenderOrder(osg::Camera::NESTED_RENDER);
  stretch->setClearMask(0);
  stretch->setProjectionMatrix(osg::Matrix::ortho2D(0, 1, 0, 1));
  stretch->setViewMatrix(osg::Matrix::identity());
  osg::ref_ptr<osg::Geometry> quad =
      osg::createTexturedQuadGeometry(osg::Vec3(0, 0, 0), osg::Vec3(1, 0, 0), osg::Vec3(0, 1, 0));
  osg::StateSet* ss = quad->getOrCreateStateSet();
  ss->setTextureAttributeAndModes(0, picture);
  ss->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
  ss->setMode(GL_FOG, osg::StateAttribute::OFF);
  ss->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
  ss->setAttribute(new osg::Depth(osg::Depth::ALWAYS, 0, 1, false));
  stretch->addChild(quad);
  return stretch;
}

}  // namespace

ScaledWorld::ScaledWorld(osg::Node* sky, osg::Node* world, osg::Node* hud)
    : root_(new osg::Group), ways_(new osg::Switch), toTexture_(new osg::Camera), picture_(new osg::Texture2D) {
  osg::ref_ptr<osg::Group> straight = new osg::Group;
  straight->addChild(sky);
  straight->addChild(world);

  picture_->setInternalFormat(GL_RGBA);
  picture_->setFilter(osg::Texture::MIN_FILTER, osg::Texture::LINEAR);
  picture_->setFilter(osg::Texture::MAG_FILTER, osg::Texture::LINEAR);
  picture_->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_EDGE);
  picture_->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_EDGE);
  picture_->setResizeNonPowerOfTwoHint(false);
  // The main camera's view and projection (RELATIVE_RF, identity), its
  // clearing and culling, drawn before the main camera into the picture.
  toTexture_->setReferenceFrame(osg::Transform::RELATIVE_RF);
  toTexture_->setRenderOrder(osg::Camera::PRE_RENDER);
  toTexture_->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
  toTexture_->setClearColor(kSkyHorizon);
  toTexture_->setClearMask(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  toTexture_->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
  toTexture_->setSmallFeatureCullingPixelSize(-1.0f);
  toTexture_->setCullingMode(toTexture_->getCullingMode() | osg::CullSettings::FAR_PLANE_CULLING);
  toTexture_->attach(osg::Camera::COLOR_BUFFER, picture_.get());
  toTexture_->attach(osg::Camera::DEPTH_BUFFER, GL_DEPTH_COMPONENT24);
  toTexture_->addChild(sky);
  toTexture_->addChild(world);
  osg::ref_ptr<osg::Group> scaled = new osg::Group;
  scaled->addChild(toTexture_);
  scaled->addChild(makeStretchCamera(picture_.get()));

  ways_->addChild(straight, true);
  ways_->addChild(scaled, false);
  root_->addChild(ways_);
  if (hud) root_->addChild(hud);
}

void ScaledWorld::set(double scale, int width, int height) {
  scale = std::clamp(scale, 0.1, 1.0);
  if (scale == scale_ && width == width_ && height == height_) return;
  scale_ = scale;
  width_ = width;
  height_ = height;
  if (scale >= 1) {
    ways_->setSingleChildOn(0);
    return;
  }
  ways_->setSingleChildOn(1);
  const int w = std::max(1, int(std::lround(scale * width))), h = std::max(1, int(std::lround(scale * height)));
  if (picture_->getTextureWidth() == w && picture_->getTextureHeight() == h) return;
  // A picture of the new size; the camera's framebuffer is made again to match.
  picture_->setTextureSize(w, h);
  picture_->dirtyTextureObject();
  toTexture_->setViewport(0, 0, w, h);
  toTexture_->dirtyAttachmentMap();
}

}  // namespace bdfcar::render
