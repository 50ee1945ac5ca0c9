// Building a Scene (the terrain with its Bullet shapes, shared by the cars
// in it) and a World (simulation.h): the vehicle file turned into the rung
// the scenario asks for (and, under `auto`, the certificate and the rungs it
// allows), the planar road plane, the ISO course; once per car, const while
// it runs.
#include "scenario/simulation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "multibody/model_error.h"
#include "terrain/bullet/bullet_terrain.h"
#include "terrain/terrain_file.h"
#include "scenario/planar_rung.h"
#include "vehicle/vehicle_file.h"

namespace bdfcar::scenario {

double vehicleWidth(const vehicle::Vehicle& v) {
  const auto& g = v.spec.geometry;
  return std::max(g.trackFront, g.trackRear) + g.wheelWidth;
}

namespace {

std::unique_ptr<terrain::Terrain> loadGround(const ScenarioSpec& spec) {
  if (spec.terrainFile.empty())
    return std::make_unique<terrain::PlaneTerrain>(Eigen::Vector3d::Zero(),
                                                   Eigen::Vector3d(-spec.groundGrade, 0.0, 1.0).normalized());
  return terrain::makeTerrain(terrain::loadTerrain(spec.terrainFile));
}

void checkStep(const ScenarioSpec& spec) {
  if (stepsPerTick(spec.tick, spec.integrator.step) == 0)
    throw std::runtime_error(spec.sourceFile + ": the step of " + std::to_string(spec.integrator.step * 1e3) +
                             " ms does not divide the driver's tick of " + std::to_string(spec.tick * 1e3) + " ms");
}

// What every world needs besides its vehicle: the step against the tick, the
// scene (its own, or the one given), the planar road plane, the course.
void finishWorld(World& w, std::shared_ptr<const Scene> scene = nullptr) {
  const ScenarioSpec& spec = w.spec;
  checkStep(spec);
  w.stepsPerTick = stepsPerTick(spec.tick, spec.integrator.step);
  w.scene = scene ? std::move(scene) : buildScene(spec);
  w.terrain = w.scene->terrain;
  // The planar model's road is the level plane through the ground at the start.
  const terrain::Hit g = w.terrain->castRay(Eigen::Vector3d(spec.startX, spec.startY, 1e3), -Eigen::Vector3d::UnitZ(), 2e3);
  if (w.vehicle.fidelity == vehicle::Fidelity::Planar) vehicle::setPlanarGround(w.vehicle, g.hit ? g.point.z() : 0.0);
  if (w.planar) vehicle::setPlanarGround(*w.planar, g.hit ? g.point.z() : 0.0);
  if (spec.course.iso3888) w.course = makeIso3888Course(vehicleWidth(w.vehicle), spec.course.startX,
                                                     std::isnan(spec.course.centreY) ? spec.startY : spec.course.centreY, spec.course.part);
}

}  // namespace

bool Scene::holds(const ScenarioSpec& spec) const {
  return spec.terrainFile == terrainFile && (!terrainFile.empty() || spec.groundGrade == groundGrade);
}

std::shared_ptr<const Scene> buildScene(const ScenarioSpec& spec) {
  auto s = std::make_shared<Scene>();
  s->terrainFile = spec.terrainFile;
  s->groundGrade = spec.groundGrade;
  s->terrain = loadGround(spec);
  return s;
}

std::shared_ptr<const World> buildWorld(const ScenarioSpec& spec) { return buildWorld(spec, nullptr); }

std::shared_ptr<const World> buildWorld(const ScenarioSpec& spec, std::shared_ptr<const Scene> scene) {
  if (scene && !scene->holds(spec))
    throw std::runtime_error(spec.sourceFile + ": its ground (" +
                             (spec.terrainFile.empty() ? std::string("the plane") : spec.terrainFile) +
                             ") is not the scene's (" +
                             (scene->terrainFile.empty() ? std::string("the plane") : scene->terrainFile) +
                             "): a car joins a scene on the scene's ground");
  auto w = std::make_shared<World>();
  w->spec = spec;
  checkStep(spec);  // before the vehicle is derived (seconds), naming the step and the tick
  w->vehicle = vehicle::buildVehicle(vehicle::loadVehicleFile(spec.vehicleFile, spec.vehicleSettings));
  // Steering in engineering units becomes the normalised input, from the linkage's scales.
  w->spec.steering = normalisedSteering(spec.steering, w->vehicle);
  const vehicle::Fidelity rung = spec.fidelity.suspension;
  if (spec.fidelity.automatic || rung != vehicle::Fidelity::Linkage)
    w->linkage = std::make_shared<const vehicle::Vehicle>(w->vehicle);
  // A derived model names the vehicle file and the rung the scenario asked for.
  auto derive = [&](auto derivation) {
    try {
      return derivation(w->vehicle);
    } catch (const mb::ModelError& e) {
      throw mb::ModelError(spec.vehicleFile + ": " + e.what() + " (the scenario asks for [fidelity] suspension = " +
                           (spec.fidelity.automatic ? "auto" : vehicle::fidelityName(rung)) + ")");
    }
  };
  if (spec.fidelity.automatic) {
    // Both derived rungs from one derivation (the planar model is the
    // kinematic one's), certified against the linkage for this car at this
    // step; `auto` uses those within the budget. A car without a planar rung
    // (every wheel steers) is certified on the kinematic rung alone.
    std::optional<vehicle::PlanarDerivation> p;
    std::optional<vehicle::KinematicDerivation> k;
    try {
      p = derivePlanarRung(spec, w->vehicle);
    } catch (const mb::ModelError& e) {
      k = derive([](const vehicle::Vehicle& v) { return vehicle::deriveKinematic(v); });
      w->autoRefusals.push_back(std::string("planar not derived: ") + e.what());
    }
    vehicle::KinematicDerivation& kin = p ? p->kinematic : *k;
    w->certificate = certifyLadder(spec, w->vehicle, kin.vehicle, p ? &p->vehicle : nullptr);
    const AutoRungChoice choice = chooseAutoRungs(*w->certificate, spec.fidelity.errorBudget);
    w->autoRefusals.insert(w->autoRefusals.end(), choice.refusals.begin(), choice.refusals.end());
    w->planarLevel = choice.planarLevel;
    if (choice.full == vehicle::Fidelity::Kinematic) {
      w->vehicle = std::move(kin.vehicle);
      w->kinematicCheck = kin.check;
      if (choice.planar && p) w->planar = std::move(p->vehicle);
    }
  } else if (rung == vehicle::Fidelity::Kinematic) {
    vehicle::KinematicDerivation k = derive([](const vehicle::Vehicle& v) { return vehicle::deriveKinematic(v); });
    w->vehicle = std::move(k.vehicle);
    w->kinematicCheck = k.check;
  } else if (rung == vehicle::Fidelity::Planar) {
    vehicle::PlanarDerivation p = derive([&](const vehicle::Vehicle& v) { return derivePlanarRung(spec, v); });
    w->vehicle = std::move(p.vehicle);
    w->kinematicCheck = p.kinematic.check;
  }
  finishWorld(*w, std::move(scene));
  return w;
}

std::shared_ptr<const World> buildWorld(const ScenarioSpec& spec, const vehicle::Vehicle& linkage,
                                        vehicle::Vehicle model) {
  auto w = std::make_shared<World>();
  w->spec = spec;
  w->spec.fidelity = FidelitySpec{};
  w->spec.fidelity.suspension = model.fidelity;
  w->spec.steering = normalisedSteering(spec.steering, linkage);
  w->vehicle = std::move(model);
  if (w->vehicle.fidelity != vehicle::Fidelity::Linkage) w->linkage = std::make_shared<const vehicle::Vehicle>(linkage);
  finishWorld(*w);
  return w;
}

}  // namespace bdfcar::scenario
