// `bdfcar info VEHICLE.toml`: bodies, joints, cut joints and the coordinate,
// constraint and degree-of-freedom counts of a vehicle file; `bdfcar info
// TERRAIN.toml`: what a terrain file builds (both check the file fully).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "cli_errors.h"
#include "commands.h"
#include "kc_summary.h"
#include "scenario_overrides.h"
#include "config/toml_reader.h"
#include "multibody/model.h"
#include "multibody/model_error.h"
#include "terrain/terrain_file.h"
#include "scenario/planar_rung.h"
#include "scenario/rung_certificate.h"
#include "scenario/scenario_spec.h"
#include "vehicle/ladder.h"
#include "vehicle/kinematic_model.h"
#include "vehicle/planar_model.h"
#include "vehicle/vehicle_sheet.h"
#include "vehicle/motion_ratio.h"
#include "vehicle/powertrain.h"
#include "vehicle/vehicle_builder.h"
#include "vehicle/vehicle_file.h"

namespace bdfcar::app {

namespace {

const char* cutTypeName(mb::CutJointType t) {
  switch (t) {
    case mb::CutJointType::Spherical: return "spherical";
    case mb::CutJointType::Distance: return "distance";
    case mb::CutJointType::Driver: return "driver";
  }
  return "?";
}

// One terrain's kind, friction, size and track, indented.
void printTerrain(const terrain::TerrainData& t, const char* indent) {
  static const char* kKind[] = {"plane", "mesh", "heightfield", "ground"};
  std::printf("%skind: %s, friction %.3f\n", indent, kKind[static_cast<int>(t.kind)], t.friction);
  if (t.kind == terrain::TerrainKind::Mesh)
    std::printf("%s%zu vertices, %zu triangles\n", indent, t.vertices.size(), t.triangles.size());
  if (t.kind == terrain::TerrainKind::Heightfield)
    std::printf("%s%d x %d heights, %g x %g m cells\n", indent, t.rows, t.cols, t.dx, t.dy);
  if (!t.centreLine.empty()) {
    double length = 0;
    for (std::size_t i = 1; i < t.centreLine.size(); ++i) length += (t.centreLine[i] - t.centreLine[i - 1]).norm();
    if (t.centreLineClosed) length += (t.centreLine.front() - t.centreLine.back()).norm();
    std::printf("%strack: %s, centre line %.1f m\n", indent, t.centreLineClosed ? "circuit" : "open", length);
  }
}

// The terrain's kind and size, and those of a ground's pieces.
int runTerrainInfo(const std::string& path) {
  const terrain::TerrainData t = terrain::loadTerrain(path);
  std::printf("%s (%s)\n", t.name.c_str(), path.c_str());
  printTerrain(t, "  ");
  for (const terrain::GroundPiece& p : t.pieces) {
    std::printf("  piece '%s' at (%.1f, %.1f, %.1f) m, heading %.1f deg (%s)\n", p.name.c_str(), p.at.x(), p.at.y(),
                p.at.z(), p.heading * 180.0 / 3.14159265358979323846, p.terrain.sourceFile.c_str());
    printTerrain(p.terrain, "    ");
  }
  return 0;
}

// A terrain file has a top-level `kind` or `friction` and no [vehicle];
// anything else is read (and its errors reported) as a vehicle. A pipe can be
// read only once: it is always a vehicle.
bool isTerrainFile(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  const config::Table root = config::parseTomlFile(path);
  return (root.has("kind") || root.has("friction")) && !root.has("vehicle");
}

// A model derived from the linkage (kinematic or planar): its bodies, its
// figures with the check of the tables against the linkage, what the rung
// models and leaves out (the ladder's list), and its error certificate
// against the linkage at the driver's step (the scenario default's
// integrator: 10 ms BDF2, 2 Newton iterations).
void printDerived(const std::string& path, const std::vector<config::Setting>& settings,
                  const vehicle::Vehicle& linkage, vehicle::Fidelity f) {
  std::string figures;
  vehicle::Vehicle derived;
  scenario::ScenarioSpec scene;
  scene.sourceFile = path;
  scene.vehicleFile = path;
  scene.vehicleSettings = settings;
  // The planar rung is derived from the kinematic one; a car without one
  // (every wheel steers) has the kinematic rung alone.
  std::optional<vehicle::PlanarDerivation> p;
  std::optional<vehicle::KinematicDerivation> k;
  try {
    p = scenario::derivePlanarRung(scene, linkage);
  } catch (const mb::ModelError&) {
    if (f == vehicle::Fidelity::Planar) throw;
    k = vehicle::deriveKinematic(linkage);
  }
  const vehicle::KinematicDerivation& kin = p ? p->kinematic : *k;
  if (f == vehicle::Fidelity::Planar) {
    figures = vehicle::describePlanar(*p) + vehicle::describeKinematic(kin);
    derived = p->vehicle;
  } else {
    figures = vehicle::describeKinematic(kin);
    derived = kin.vehicle;
  }
  const vehicle::RungDescription& rung = vehicle::describeRung(f);
  figures += std::string("rung '") + rung.name + "': derived from " + rung.derivedFrom + "\n  models: " + rung.models +
             "\n  leaves out: " + rung.omits + "\n  valid: " + rung.validity + "\n";
  const scenario::LadderCertificate c = scenario::certifyLadder(scene, linkage, kin.vehicle, p ? &p->vehicle : nullptr);
  figures += scenario::describeCertificate(c, scene.fidelity.errorBudget);
  for (const auto& [name, bound] : linkage.spec.certificateRequired)
    if (const scenario::RungCertificate* r = c.find(*vehicle::rungByName(name)))
      figures += "the vehicle file requires " + name + " within " + std::to_string(100 * bound).substr(0, 5) +
                 " %: " + (r->worst <= 100 * bound ? "kept" : "NOT kept") + "\n";
  for (const std::string& why : scenario::chooseAutoRungs(c, scene.fidelity.errorBudget).refusals)
    figures += "auto (" + std::to_string(static_cast<int>(std::lround(100 * scene.fidelity.errorBudget))) +
               " % budget): " + why + "\n";
  const mb::Model& m = derived.model;
  std::printf("\nderived: the %s model (--fidelity %s)\n", vehicle::fidelityName(f), vehicle::fidelityName(f));
  std::printf("  %-18s %9s  %-26s %s\n", "body", "mass kg", "joint", "parent");
  for (const mb::Body& b : m.bodies)
    std::printf("  %-18s %9.3f  %-26s %s\n", b.name.c_str(), b.mass, mb::jointTypeName(b.joint),
                b.parent < 0 ? "(ground)" : m.bodies[b.parent].name.c_str());
  std::printf("%s", figures.c_str());
}

int runInfo(const std::string& path, const std::string& fidelity, const std::vector<std::string>& set) {
  if (isTerrainFile(path)) {
    if (!fidelity.empty()) throw std::runtime_error("--fidelity applies to a vehicle file, not to the terrain file " + path);
    if (!set.empty()) throw std::runtime_error("--set applies to a vehicle file, not to the terrain file " + path);
    return runTerrainInfo(path);
  }
  std::vector<config::Setting> settings;
  // Keys as `run --set` writes a vehicle's (vehicle.springs[0].damping) or
  // as the vehicle file does (springs[0].damping): this command has only the vehicle.
  for (const std::string& x : set) {
    const config::Setting s = config::parseSetting(x);
    settings.push_back(config::underPrefix(s, "vehicle.").value_or(s));
  }
  const vehicle::Vehicle v = vehicle::buildVehicle(vehicle::loadVehicleFile(path, settings));
  const mb::Model& m = v.model;
  std::printf("%s (%s)\n", v.spec.name.c_str(), path.c_str());
  if (!v.spec.description.empty()) std::printf("  %s\n", v.spec.description.c_str());
  std::printf("\nbodies and tree joints (%zu):\n", m.bodies.size());
  std::printf("  %-18s %9s  %-11s %-18s %s\n", "body", "mass kg", "joint", "parent", "coordinates");
  for (const mb::Body& b : m.bodies)
    std::printf("  %-18s %9.3f  %-11s %-18s %d\n", b.name.c_str(), b.mass, mb::jointTypeName(b.joint),
                b.parent < 0 ? "(ground)" : m.bodies[b.parent].name.c_str(), b.nv);
  std::printf("\ncut joints (%zu):\n", m.cutJoints.size());
  for (const mb::CutJoint& c : m.cutJoints) {
    if (c.type == mb::CutJointType::Driver) {
      std::printf("  %-18s %-10s prescribes '%s' (%d equation)\n", c.name.c_str(), cutTypeName(c.type),
                  m.bodies[c.drivenBody].name.c_str(), c.rows);
      continue;
    }
    std::printf("  %-18s %-10s %s - %s (%d equation%s)\n", c.name.c_str(), cutTypeName(c.type),
                c.bodyA < 0 ? "ground" : m.bodies[c.bodyA].name.c_str(),
                c.bodyB < 0 ? "ground" : m.bodies[c.bodyB].name.c_str(), c.rows, c.rows > 1 ? "s" : "");
  }
  std::printf("\nspring-dampers (%zu), motion ratio dL/dz of the wheel centre at design:\n", m.springs.size());
  const std::vector<vehicle::MotionRatio> ratios = vehicle::motionRatios(v);
  for (size_t k = 0; k < m.springs.size(); ++k) {
    const mb::SpringDamper& s = m.springs[k];
    std::printf("  %-18s %s - %s", s.name.c_str(), m.bodies[s.bodyA].name.c_str(), m.bodies[s.bodyB].name.c_str());
    if (ratios[k].wheel >= 0) std::printf("  (%s: %+.5f)", vehicle::kCornerNames[ratios[k].wheel], ratios[k].ratio);
    std::printf("\n");
  }
  for (const vehicle::AntiRollBarSpec& b : v.spec.antiRollBars)
    std::printf("  %-18s anti-roll bar %s - %s, %.0f N/m at the wheels\n", b.name.c_str(), vehicle::kCornerNames[b.left],
                vehicle::kCornerNames[b.right], b.rate);
  const int spin = v.layout.spinCoordinates;
  const int engine = v.layout.engine >= 0 ? 1 : 0;
  const int coords = m.nv - spin - engine, cuts = v.layout.cutJointEquations;
  const std::string rotors = "+" + std::to_string(spin) + " wheel spin" + (engine ? ", +1 engine" : "");
  std::printf("\nrelative coordinates: %d (%s)\n", coords, rotors.c_str());
  std::printf("cut-joint constraint equations: %d (+%d driving constraint: rack travel)\n", cuts, m.nc - cuts);
  std::printf("degrees of freedom: %d (%s); with the rack prescribed: %d\n", coords - cuts, rotors.c_str(),
              coords - cuts - (m.nc - cuts));
  if (v.spec.powertrain) std::printf("%s", vehicle::describePowertrain(*v.spec.powertrain, v.spec.geometry.wheelRadius).c_str());
  std::printf("total mass: %.3f kg\n", m.totalMass());
  // The sheet, when the linkage can be swept (a vehicle that cannot is
  // still described above).
  try {
    std::printf("\n%s", vehicle::describe(vehicle::vehicleSheet(v)).c_str());
  } catch (const mb::ModelError& e) {
    std::printf("\nno vehicle sheet: %s\n", e.what());
  }
  // Its kinematics at design from the K&C rig (bdfcar kc: the curves too).
  try {
    std::printf("\n%s", kcSummary(v, path, vehicle::runKcRig(v)).c_str());
  } catch (const mb::ModelError& e) {
    std::printf("\nno K&C: %s\n", e.what());
  }
  vehicle::Fidelity f = vehicle::Fidelity::Linkage;
  if (!fidelity.empty()) scenario::parseFidelity(fidelity, f);
  if (f != vehicle::Fidelity::Linkage) printDerived(path, settings, v, f);
  return 0;
}

}  // namespace

void addInfoCommand(CLI::App& app, CommandList& commands) {
  CLI::App* cmd = app.add_subcommand("info", "Print the bodies, joints, cut joints and coordinate/constraint/DOF counts of a "
                                              "vehicle file (or check a terrain file and print its size)");
  auto path = std::make_shared<std::string>();
  cmd->add_option("file", *path, "Vehicle file (assets/vehicles/*.toml) or terrain file (assets/terrain/*.toml)")
      ->required()
      ->check(CLI::ExistingFile);
  auto fidelity = std::make_shared<std::string>();
  cmd->add_option("--fidelity", *fidelity,
                  "Also derive this model from the vehicle and print it with its check against the linkage")
      ->check(CLI::IsMember(rungNameList()));
  auto set = std::make_shared<std::vector<std::string>>();
  addSetOption(*cmd, *set,
               "KEY=VALUE: set a key of the vehicle file (springs[0].stiffness=300000, or as run --set writes it: "
               "vehicle.springs[0].stiffness=300000; docs/VEHICLES.md), checked "
               "as in the file: the sheet of a variant without editing the file. Repeatable");
  commands.push_back({cmd, [path, fidelity, set] { return reportErrors([&] { return runInfo(*path, *fidelity, *set); }); }});
}

}  // namespace bdfcar::app
