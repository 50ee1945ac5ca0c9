// Private to render/: the OSG side of Scene, used by the window and headless backends.
#pragma once

#include <osg/Camera>
#include <osg/Group>
#include <osg/MatrixTransform>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "render/camera_rig.h"
#include "render/car_nodes.h"
#include "render/hud_node.h"
#include "render/scene.h"
#include "render/surface_sampler.h"
#include "terrain/terrain_mesh.h"

namespace bdfcar::render {

struct Scene::Impl {
  explicit Impl(const SceneConfig& config);

  // Moves car, links, shadow and HUD texts to this frame's state.
  void update(const vehicle::VehicleView& view, const vehicle::HudInfo& hud);
  // Sets the main camera's view and projection, the sky and the HUD for a viewport of width x height.
  void applyView(osg::Camera& camera, int width, int height);

  SceneConfig config;
  terrain::TriangleMesh surface;           // what the physics queries, drawn as is
  std::unique_ptr<SurfaceSampler> ground;  // heights of `surface` for road, cones, shadow

  osg::ref_ptr<osg::Group> root;           // handed to the viewer: world + HUD camera
  osg::ref_ptr<osg::Group> world;
  osg::ref_ptr<osg::MatrixTransform> sky, chassis, shadow;
  std::array<osg::ref_ptr<osg::MatrixTransform>, 4> wheels;
  BodyNode body;
  // The best lap's ghost: the body again, translucent, where the view puts it.
  osg::ref_ptr<osg::MatrixTransform> ghost;
  BodyNode ghostBody;
  osg::ref_ptr<osg::Group> cones;          // the course's, knocked over as the HUD reports them
  LinkPool links;
  HudNode hud;

  CameraMode cameraMode = CameraMode::Chase;
  BodyDisplay display = BodyDisplay::Solid;
  OrbitState orbit;
  vehicle::BodyPose chassisPose;
  ChaseHeading chase;  // the chase camera's lagging heading
  vehicle::HudInfo lastHud;
  std::vector<std::string> warnings;
};

}  // namespace bdfcar::render
