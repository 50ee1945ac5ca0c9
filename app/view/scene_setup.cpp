#include "view/scene_setup.h"

#include "terrain/terrain_file.h"

namespace bdfcar::app {

render::SceneConfig sceneConfigFor(const scenario::Simulation& sim, bool hud) {
  render::SceneConfig cfg;
  const scenario::ScenarioSpec& spec = sim.spec();
  if (!spec.terrainFile.empty()) {
    cfg.terrain = terrain::loadTerrain(spec.terrainFile);
  } else {
    cfg.terrain.name = "plane";
    cfg.terrain.road.present = true;
    cfg.terrain.road.centreY = spec.startY;
  }
  cfg.course = sim.course();
  cfg.geometry = sim.vehicle().spec.geometry;
  cfg.assetRoot = BDFCAR_ASSET_DIR;
  cfg.hud = hud;
  if (spec.laps.enabled) cfg.trackMap = spec.laps.line;
  return cfg;
}

}  // namespace bdfcar::app
