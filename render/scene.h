// The 3-D scene of a run: terrain (the same triangles the physics queries),
// road with lane markings, ISO 3888-1 cones, the car (body, steering and
// spinning wheels, suspension links), a HUD and four cameras. Updated once per
// frame from plain physics data; shown by render/window.h (on screen) or
// render/headless.h (OSMesa). OSG types stay behind Scene::Impl.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scenario/iso3888_course.h"
#include "terrain/terrain_data.h"
#include "vehicle/vehicle_view.h"

namespace bdfcar::render {

enum class CameraMode { Chase, Hood, Orbit, TopDown };
// Solid: the painted body. Translucent / Hidden: show the suspension links moving.
enum class BodyDisplay { Solid, Translucent, Hidden };

struct SceneConfig {
  terrain::TerrainData terrain;                  // drawn via terrain::triangulate (the physics' triangles)
  std::optional<scenario::Iso3888Course> course; // cones, if the run is on the course
  vehicle::VehicleGeometry geometry;             // geometry.bodyMesh: OBJ path (absolute, or relative to
                                                 // assetRoot, the working directory or the source tree)
  std::string assetRoot;                         // optional base folder of relative asset paths
  bool hud = true;
  std::vector<Eigen::Vector2d> trackMap;         // a timed circuit's centre line: the HUD's map (empty: none)
};

class Scene {
 public:
  explicit Scene(const SceneConfig& config);
  ~Scene();
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  // Moves the car, links, cameras and HUD to this frame's state (call once per drawn frame).
  void update(const vehicle::VehicleView& view, const vehicle::HudInfo& hud);

  void setCamera(CameraMode mode);
  CameraMode camera() const;
  CameraMode nextCamera();           // chase -> hood -> orbit -> top-down -> chase
  // Turns / tilts the orbit camera (rad) and scales its distance; other modes ignore it.
  void orbitBy(double yaw, double pitch, double zoomFactor = 1.0);

  void setBodyDisplay(BodyDisplay display);
  BodyDisplay bodyDisplay() const;
  BodyDisplay nextBodyDisplay();     // solid -> translucent -> hidden -> solid

  // Problems met while building the scene (e.g. body mesh missing, box drawn instead).
  const std::vector<std::string>& warnings() const;

  struct Impl;  // defined in scene_impl.h, private to render/
  Impl& impl();

 private:
  std::unique_ptr<Impl> impl_;
};

const char* cameraName(CameraMode mode);
const char* bodyDisplayName(BodyDisplay display);

}  // namespace bdfcar::render
