#include "render/embedded_viewer.h"

#include <osgUtil/SceneView>
#include <osgUtil/Statistics>
#include <osgViewer/Renderer>

#include "render/nodes.h"

namespace bdfcar::render {

// Embedded single-threaded viewer with a fixed sun (sky light) instead of OSG's headlight.
osg::ref_ptr<osgViewer::Viewer> makeEmbeddedViewer(Scene::Impl& scene, int width, int height) {
  osg::ref_ptr<osgViewer::Viewer> viewer = new osgViewer::Viewer;
  viewer->setUpViewerAsEmbeddedInWindow(0, 0, width, height);
  viewer->setThreadingModel(osgViewer::Viewer::SingleThreaded);
  viewer->setKeyEventSetsDone(0);  // input/ owns the keyboard; ESC must not stop the viewer
  viewer->setQuitEventSetsDone(false);
  viewer->setSceneData(scene.root.get());

  viewer->setLightingMode(osg::View::SKY_LIGHT);
  osg::Light* sun = viewer->getLight();
  osg::Vec3 towardsSun(-0.35f, 0.45f, 0.82f);
  towardsSun.normalize();
  sun->setPosition(osg::Vec4(towardsSun, 0.0f));  // w = 0: directional
  sun->setAmbient(osg::Vec4(0.42f, 0.42f, 0.45f, 1.0f));
  sun->setDiffuse(osg::Vec4(0.78f, 0.77f, 0.72f, 1.0f));
  sun->setSpecular(osg::Vec4(0.6f, 0.6f, 0.6f, 1.0f));

  osg::Camera* camera = viewer->getCamera();
  camera->setClearColor(kSkyHorizon);
  camera->setClearMask(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  camera->setSmallFeatureCullingPixelSize(-1.0f);  // never cull distant cones as "small"
  // Past the far plane (the haze's end: camera_rig.h) nothing shows but the fog's colour.
  camera->setCullingMode(camera->getCullingMode() | osg::CullSettings::FAR_PLANE_CULLING);
  scene.applyView(*camera, width, height);
  viewer->realize();
  return viewer;
}

// Follows the context size, aims the camera, then runs OSG's event/update/cull/draw.
void drawFrame(osgViewer::Viewer& viewer, Scene::Impl& scene, int width, int height) {
  osg::Camera* camera = viewer.getCamera();
  const osg::Viewport* vp = camera->getViewport();
  if (!vp || int(vp->width()) != width || int(vp->height()) != height) {
    if (auto* gw = dynamic_cast<osgViewer::GraphicsWindow*>(camera->getGraphicsContext()))
      gw->resized(0, 0, width, height);
    camera->setViewport(0, 0, width, height);
  }
  scene.applyView(*camera, width, height);
  viewer.frame();
}

DrawLoad lastDrawLoad(osgViewer::Viewer& viewer) {
  DrawLoad load;
  auto* renderer = dynamic_cast<osgViewer::Renderer*>(viewer.getCamera()->getRenderer());
  const osgUtil::SceneView* view = renderer ? renderer->getSceneView(0) : nullptr;
  if (!view || !view->getRenderStage()) return load;
  osgUtil::Statistics stats;
  view->getRenderStage()->getStats(stats);
  load.drawables = stats.numDrawables;
  for (const auto& [mode, count] : stats.getPrimitiveCountMap())
    if (mode == GL_TRIANGLES || mode == GL_TRIANGLE_STRIP || mode == GL_TRIANGLE_FAN) load.triangles += count;
  return load;
}

// Drops GL objects of everything the viewer drew, in the current context.
void releaseViewer(osgViewer::Viewer& viewer) {
  if (osg::GraphicsContext* gc = viewer.getCamera()->getGraphicsContext()) gc->close(true);
}

}  // namespace bdfcar::render
