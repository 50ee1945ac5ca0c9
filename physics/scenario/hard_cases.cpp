#include "scenario/hard_cases.h"

namespace bdfcar::scenario {

std::vector<HardCase> hardCases(const std::string& assetDir) {
  const std::string terrain = assetDir + "/terrain/";
  return {
      {"curb strike (10 cm block) at 30 km/h", "jturn.toml",
       "terrain = curb.toml, rays_per_wheel = 5, 30 km/h, start y = -1.75 m, no steering, 4 s",
       [terrain](ScenarioSpec& s) {
         s.terrainFile = terrain + "curb.toml";
         s.raysPerWheel = 5;
         s.startY = -1.75;
         s.initialSpeed = s.speedControl.target = 30 / 3.6;
         s.steering = {};
         s.duration = 4.0;
         s.settleTime = 0.5;
       }},
      {"jump off the ramp at 50 km/h", "jturn.toml",
       "terrain = ramp.toml, rays_per_wheel = 5, 50 km/h, start x = 20 m, no steering, 4 s",
       [terrain](ScenarioSpec& s) {
         s.terrainFile = terrain + "ramp.toml";
         s.raysPerWheel = 5;
         s.startX = 20;
         s.initialSpeed = s.speedControl.target = 50 / 3.6;
         s.steering = {};
         s.duration = 4.0;
         s.settleTime = 0.5;
       }},
      {"rough road (ISO 8608 B/C), lane change at 80 km/h", "lane_change.toml",
       "terrain = rough.toml, rays_per_wheel = 3",
       [terrain](ScenarioSpec& s) {
         s.terrainFile = terrain + "rough.toml";
         s.raysPerWheel = 3;
       }},
      {"spin-out: full lock at 80 km/h, no speed hold", "jturn.toml",
       "steering level = 1.0, no [speed_control], 5 s",
       [](ScenarioSpec& s) {
         s.steering.level = 1.0;
         s.speedControl.enabled = false;
         s.duration = 5.0;
       }},
  };
}

}  // namespace bdfcar::scenario
