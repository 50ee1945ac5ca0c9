// The scene of a drive: the terrain asset the physics queries, the course's
// cones, the car's geometry from its vehicle file.
#pragma once

#include "render/scene.h"
#include "session/drive_session.h"

namespace bdfcar::app {

render::SceneConfig sceneConfigFor(const scenario::Simulation& sim, bool hud = true);
inline render::SceneConfig sceneConfigFor(DriveSession& session, bool hud = true) {
  return sceneConfigFor(session.simulation(), hud);
}

}  // namespace bdfcar::app
