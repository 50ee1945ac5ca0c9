#include "render/osg_convert.h"
#include "render/scene_impl.h"

namespace bdfcar::render {

// Camera from the current mode and chassis pose; fixed near/far planes because
// OSG's automatic ones would be stretched by the sky dome and the large terrain.
void Scene::Impl::applyView(osg::Camera& camera, int width, int height) {
  const CameraPose c = cameraPose(cameraMode, chassisPose, orbit, chase.heading());
  camera.setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
  camera.setViewMatrixAsLookAt(toOsg(c.eye), toOsg(c.centre), toOsg(c.up));
  camera.setProjectionMatrixAsPerspective(c.fovYDeg, double(width) / std::max(1, height), c.zNear, c.zFar);
  sky->setMatrix(osg::Matrixd::translate(toOsg(c.eye)));
  hud.layout(width, height);
}

}  // namespace bdfcar::render
