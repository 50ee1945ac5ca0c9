#include "render/scene.h"

#include <osg/Fog>
#include <osg/Material>
#include <osg/PositionAttitudeTransform>

#include <algorithm>
#include <cmath>

#include "render/nodes.h"
#include "render/osg_convert.h"
#include "render/scene_impl.h"
#include "render/terrain_surface.h"

namespace bdfcar::render {

// Builds the static world once: sky, terrain, road, cones, car parts, HUD.
Scene::Impl::Impl(const SceneConfig& cfg)
    : config(cfg), surface(terrainSurface(cfg.terrain)), ground(std::make_unique<SurfaceSampler>(surface)),
      root(new osg::Group), world(new osg::Group), chassis(new osg::MatrixTransform), shadow(new osg::MatrixTransform) {
  osg::StateSet* ss = world->getOrCreateStateSet();
  // Vertex colours drive ambient and diffuse under fixed-function lighting.
  osg::ref_ptr<osg::Material> material = new osg::Material;
  material->setColorMode(osg::Material::AMBIENT_AND_DIFFUSE);
  ss->setAttributeAndModes(material.get());
  // Haze towards the horizon colour hides the terrain's far edge.
  osg::ref_ptr<osg::Fog> fog = new osg::Fog;
  fog->setMode(osg::Fog::LINEAR);
  fog->setStart(float(kHazeStart));
  fog->setEnd(float(kHazeEnd));
  fog->setColor(kSkyHorizon);
  ss->setAttributeAndModes(fog.get());

  sky = makeSkyDome();
  root->addChild(sky);
  root->addChild(world);
  world->addChild(makeGroundNode(surface));
  world->addChild(makeRoadNode(cfg.terrain, *ground));
  // A ground's pieces paint their roads in their own frames.
  for (const terrain::GroundPiece& piece : cfg.terrain.pieces) {
    if (!piece.terrain.road.present) continue;
    const terrain::TriangleMesh local = terrainSurface(piece.terrain);
    osg::ref_ptr<osg::MatrixTransform> placed = new osg::MatrixTransform(
        osg::Matrixd::rotate(piece.heading, osg::Vec3d(0, 0, 1)) * osg::Matrixd::translate(toOsg(piece.at)));
    placed->addChild(makeRoadNode(piece.terrain, SurfaceSampler(local)));
    world->addChild(placed);
  }
  if (cfg.course) {
    cones = makeConesNode(cfg.course->cones(), *ground);
    world->addChild(cones);
  }

  const vehicle::VehicleGeometry& g = cfg.geometry;
  shadow->addChild(makeShadowNode(g.length * 1.05, g.width * 1.15));
  world->addChild(shadow);
  body = makeBodyNode(g, cfg.assetRoot);
  if (!body.warning.empty()) warnings.push_back(body.warning);
  chassis->addChild(body.node);
  chassis->addChild(body.frame);  // beside the body: it shows while the body is hidden
  world->addChild(chassis);
  if (!cfg.trackMap.empty()) {  // a timed circuit: the best lap's ghost
    ghostBody = makeBodyNode(g, cfg.assetRoot);
    applyBodyDisplay(ghostBody, BodyDisplay::Translucent);
    if (ghostBody.frame) ghostBody.frame->setNodeMask(0u);
    ghost = new osg::MatrixTransform;
    ghost->addChild(ghostBody.node);
    ghost->setNodeMask(0u);  // until there is a best lap
    world->addChild(ghost);
  }
  osg::ref_ptr<osg::Node> wheel = makeWheelNode(g.wheelRadius, g.wheelWidth);
  for (auto& w : wheels) {
    w = new osg::MatrixTransform;
    w->addChild(wheel);
    world->addChild(w);
  }
  world->addChild(links.node());
  if (cfg.hud) root->addChild(hud.node());
  if (!cfg.trackMap.empty()) hud.setTrackMap(cfg.trackMap);

  // Until the first update: car at rest at the origin, chassis point 0.51 m above ground.
  vehicle::VehicleView rest;
  rest.chassis.position = Eigen::Vector3d(0, 0, ground->heightOr(0, 0, 0) + 0.513);
  const double xs[4] = {1.21, 1.21, -1.25, -1.25}, ys[4] = {0.5 * g.trackFront, -0.5 * g.trackFront,
                                                          0.5 * g.trackRear, -0.5 * g.trackRear};
  for (int i = 0; i < 4; ++i) rest.wheels[i].pose.position = rest.chassis.position + Eigen::Vector3d(xs[i], ys[i], -0.22);
  update(rest, vehicle::HudInfo{});
}

// Places every moving part from the physics' world poses.
void Scene::Impl::update(const vehicle::VehicleView& view, const vehicle::HudInfo& info) {
  chassisPose = view.chassis;
  chase.update(headingOf(view.chassis), view.time);
  chassis->setMatrix(poseMatrix(view.chassis));
  if (ghost) {
    ghost->setNodeMask(view.ghost ? ~0u : 0u);
    if (view.ghost) ghost->setMatrix(poseMatrix(view.ghostChassis));
  }
  for (int i = 0; i < 4; ++i) wheels[i]->setMatrix(poseMatrix(view.wheels[i].pose));
  links.update(view.links);
  // The shadow stays flat on the ground under the body, turned with the heading only.
  const Eigen::Vector3d& p = view.chassis.position;
  const Eigen::Vector3d centre = view.chassis.rotation * config.geometry.bodyOffset + p;
  shadow->setMatrix(osg::Matrixd::rotate(headingOf(view.chassis), osg::Vec3d(0, 0, 1)) *
                    osg::Matrixd::translate(centre.x(), centre.y(), ground->heightOr(centre.x(), centre.y(), 0.0) + 0.02));
  // Cones hit stay down; a reset or rewind that un-hits them stands them up again.
  if (cones) {
    for (unsigned i = 0; i < cones->getNumChildren(); ++i)
      static_cast<osg::PositionAttitudeTransform*>(cones->getChild(i))->setAttitude(osg::Quat());
    for (const auto& [index, heading] : info.knockedCones) knockCone(*cones, index, heading);
  }
  lastHud = info;
  // A brake lamp switch: any brake pedal travel (the handbrake lights nothing).
  setLamp(body.brakeLights, info.brake > 0.02);
  // The reverse lamp switch sits on the gearbox: lit in reverse gear, whatever the car's motion.
  setLamp(body.reverseLights, info.powertrain && info.gear < 0);
  hud.update(info, cameraMode, display);
}

Scene::Scene(const SceneConfig& config) : impl_(std::make_unique<Impl>(config)) {}
Scene::~Scene() = default;

void Scene::update(const vehicle::VehicleView& view, const vehicle::HudInfo& hud) { impl_->update(view, hud); }

void Scene::setCamera(CameraMode mode) {
  impl_->cameraMode = mode;
  impl_->hud.update(impl_->lastHud, impl_->cameraMode, impl_->display);
}
CameraMode Scene::camera() const { return impl_->cameraMode; }

// Cycles chase -> hood -> orbit -> top-down.
CameraMode Scene::nextCamera() {
  setCamera(static_cast<CameraMode>((static_cast<int>(impl_->cameraMode) + 1) % 4));
  return impl_->cameraMode;
}

// Turns the orbit camera and scales its distance (kept between 3 and 60 m).
void Scene::orbitBy(double yaw, double pitch, double zoomFactor) {
  OrbitState& o = impl_->orbit;
  o.yaw += yaw;
  o.pitch = std::clamp(o.pitch + pitch, -0.1, 1.5);
  o.distance = std::clamp(o.distance * zoomFactor, 3.0, 60.0);
}

void Scene::setBodyDisplay(BodyDisplay display) {
  impl_->display = display;
  applyBodyDisplay(impl_->body, display);
  impl_->hud.update(impl_->lastHud, impl_->cameraMode, impl_->display);
}
BodyDisplay Scene::bodyDisplay() const { return impl_->display; }

// Cycles solid -> translucent -> hidden.
BodyDisplay Scene::nextBodyDisplay() {
  setBodyDisplay(static_cast<BodyDisplay>((static_cast<int>(impl_->display) + 1) % 3));
  return impl_->display;
}

const std::vector<std::string>& Scene::warnings() const { return impl_->warnings; }
Scene::Impl& Scene::impl() { return *impl_; }

const char* cameraName(CameraMode mode) {
  switch (mode) {
    case CameraMode::Chase: return "chase";
    case CameraMode::Hood: return "hood";
    case CameraMode::Orbit: return "orbit";
    case CameraMode::TopDown: return "top-down";
  }
  return "?";
}

const char* bodyDisplayName(BodyDisplay display) {
  switch (display) {
    case BodyDisplay::Solid: return "solid";
    case BodyDisplay::Translucent: return "translucent";
    case BodyDisplay::Hidden: return "hidden";
  }
  return "?";
}

}  // namespace bdfcar::render
