// The error certificate of the fidelity ladder's derived rungs
// (scenario/rung_certificate.h): each rung run against the linkage it was
// derived from on the battery, and `auto`'s choice from it. The reference
// here is always the linkage, run through the same scenario: an independent
// model of the same car (the reduced rungs share none of its loop closure).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "scenario/planar_rung.h"
#include "scenario/rung_certificate.h"
#include "scenario/run.h"
#include "scenario/simulation.h"
#include "vehicle/ladder.h"
#include "vehicle/planar_model.h"
#include "vehicle/vehicle_file.h"

namespace bdfcar {
namespace {

std::string asset(const std::string& rel) { return std::string(BDFCAR_SOURCE_DIR) + "/assets/" + rel; }

struct Certified {
  vehicle::Vehicle linkage;
  scenario::LadderCertificate certificate;
};

// The scene: the scenario default's integrator (10 ms BDF2, 2 Newton
// iterations, Jacobian every 200 steps) for a vehicle file. `derivedFrom`:
// the vehicle file the rungs are derived from (the ablation below), by
// default the same.
Certified certify(const std::string& file, const std::string& derivedFrom = "") {
  scenario::ScenarioSpec scene;
  scene.vehicleFile = asset(file);
  scene.sourceFile = scene.vehicleFile;
  Certified c;
  c.linkage = vehicle::buildVehicle(vehicle::loadVehicleFile(scene.vehicleFile));
  const vehicle::Vehicle source =
      derivedFrom.empty() ? c.linkage : vehicle::buildVehicle(vehicle::loadVehicleFile(asset(derivedFrom)));
  c.certificate = scenario::certifyLadder(scene, c.linkage, scenario::derivePlanarRung(scene, source));
  return c;
}

const scenario::ManoeuvreError& manoeuvre(const scenario::RungCertificate& r, const std::string& prefix) {
  for (const scenario::ManoeuvreError& e : r.manoeuvres)
    if (e.manoeuvre.rfind(prefix, 0) == 0) return e;
  throw std::runtime_error("no manoeuvre " + prefix);
}

// The battery spans what `auto` asks of a rung: the linkage's own response
// reaches the levels it is named for (an understeering car a little less
// than the neutral-steer estimate), and the planar rung is not run on the
// grade (outside its validity), every other rung is.
TEST(RungCertificate, TheBatterySpansTheRungsUse) {
  const Certified c = certify("vehicles/sedan.toml");
  ASSERT_TRUE(c.certificate.failure.empty()) << c.certificate.failure;
  ASSERT_EQ(c.certificate.rungs.size(), 2u);
  const scenario::RungCertificate& k = *c.certificate.find(vehicle::Fidelity::Kinematic);
  const scenario::RungCertificate& p = *c.certificate.find(vehicle::Fidelity::Planar);
  ASSERT_EQ(k.manoeuvres.size(), 6u);
  const double low = manoeuvre(k, "step steer 0.3").limitShare, high = manoeuvre(k, "step steer 0.6").limitShare;
  EXPECT_GT(low, 0.2);
  EXPECT_LT(low, 0.4);
  EXPECT_GT(high, 0.4);
  EXPECT_LT(high, 0.75);
  EXPECT_TRUE(manoeuvre(p, "stop and release").refused.size() > 0);
  EXPECT_TRUE(manoeuvre(k, "stop and release").refused.empty());
  for (const scenario::ManoeuvreError& e : k.manoeuvres) EXPECT_TRUE(e.refused.empty()) << e.manoeuvre;
}

// The reference sedan: the kinematic rung within a tenth of a per cent of
// the linkage on every manoeuvre (its tables are within micrometres), the
// planar rung within the default 10 % budget, so `auto` uses both.
TEST(RungCertificate, TheReferenceSedansRungsAreWithinTheDefaultBudget) {
  const Certified c = certify("vehicles/sedan.toml");
  const scenario::RungCertificate& k = *c.certificate.find(vehicle::Fidelity::Kinematic);
  const scenario::RungCertificate& p = *c.certificate.find(vehicle::Fidelity::Planar);
  EXPECT_LT(k.worst, 1.0) << k.worstManoeuvre << ", " << k.worstQuantity;
  EXPECT_LT(p.worst, 10.0) << p.worstManoeuvre << ", " << p.worstQuantity;
  const scenario::AutoRungChoice choice = scenario::chooseAutoRungs(c.certificate, 0.10);
  EXPECT_EQ(choice.full, vehicle::Fidelity::Kinematic);
  EXPECT_TRUE(choice.planar);
  EXPECT_TRUE(choice.refusals.empty());
  // A budget below the kinematic rung's figure leaves the linkage alone.
  const scenario::AutoRungChoice strict = scenario::chooseAutoRungs(c.certificate, 0.5 * k.worst / 100.0);
  EXPECT_EQ(strict.full, vehicle::Fidelity::Linkage);
  EXPECT_FALSE(strict.planar);
}

// Strong roll steer (sedan_roll_steer.toml: the front inner tie rods 40 mm
// low): both derived rungs carry it (the kinematic rung in its tables, the
// planar rung as the carriers' rotation per travel from the same sweep) and
// stay within the budget. The same planar rung with that rotation removed
// (its roll and bump steer and camber gain dropped, nothing else) misses
// the effect: its certificate exceeds the budget and `auto` refuses it,
// saying on which manoeuvre and quantity.
TEST(RungCertificate, APlanarRungWithoutItsRollSteerIsRefused) {
  const Certified c = certify("vehicles/sedan_roll_steer.toml");
  const scenario::RungCertificate& k = *c.certificate.find(vehicle::Fidelity::Kinematic);
  const scenario::RungCertificate& p = *c.certificate.find(vehicle::Fidelity::Planar);
  EXPECT_LT(k.worst, 1.0) << k.worstManoeuvre;
  EXPECT_LT(p.worst, 10.0) << p.worstManoeuvre;
  EXPECT_TRUE(scenario::chooseAutoRungs(c.certificate, 0.10).planar);

  scenario::ScenarioSpec scene;
  scene.vehicleFile = asset("vehicles/sedan_roll_steer.toml");
  scene.sourceFile = scene.vehicleFile;
  vehicle::PlanarDerivation without = scenario::derivePlanarRung(scene, c.linkage);
  for (vehicle::Vec3& turn : without.vehicle.planar->turnPerTravel) turn.setZero();
  const scenario::LadderCertificate ablated = scenario::certifyLadder(scene, c.linkage, without);
  const scenario::RungCertificate& pa = *ablated.find(vehicle::Fidelity::Planar);
  EXPECT_GT(pa.worst, 10.0) << pa.worstManoeuvre;
  const scenario::AutoRungChoice choice = scenario::chooseAutoRungs(ablated, 0.10);
  EXPECT_EQ(choice.full, vehicle::Fidelity::Kinematic);
  EXPECT_FALSE(choice.planar);
  ASSERT_EQ(choice.refusals.size(), 1u);
  EXPECT_NE(choice.refusals[0].find("planar not used"), std::string::npos) << choice.refusals[0];
}

// The ablation: the roll-steer car's rungs derived from the same car with
// its tie rods where the reference has them (the rung's roll steer removed,
// nothing else) and certified against the roll-steer linkage: the kinematic
// rung now misses the effect, its certificate exceeds the budget and `auto`
// refuses it (and the planar rung with it: the linkage alone runs).
TEST(RungCertificate, ARungWithItsRollSteerRemovedIsRefused) {
  const Certified own = certify("vehicles/sedan_roll_steer.toml");
  const Certified ablated = certify("vehicles/sedan_roll_steer.toml", "vehicles/sedan.toml");
  const scenario::RungCertificate& k = *ablated.certificate.find(vehicle::Fidelity::Kinematic);
  EXPECT_GT(k.worst, 10.0) << k.worstManoeuvre;
  EXPECT_GT(k.worst, 10 * own.certificate.find(vehicle::Fidelity::Kinematic)->worst);
  const scenario::AutoRungChoice choice = scenario::chooseAutoRungs(ablated.certificate, 0.10);
  EXPECT_EQ(choice.full, vehicle::Fidelity::Linkage);
  EXPECT_FALSE(choice.planar);
  ASSERT_FALSE(choice.refusals.empty());
  EXPECT_NE(choice.refusals[0].find("kinematic not used"), std::string::npos) << choice.refusals[0];
}

// Under `auto` the world is built from the certificate: with the default
// budget both derived rungs; with a budget below the planar rung's figure
// the kinematic rung alone, and the refusal says why.
TEST(RungCertificate, AutoBuildsItsWorldFromTheCertificate) {
  scenario::ScenarioSpec s = scenario::loadScenarioFile(asset("scenarios/lane_change.toml"));
  s.fidelity.automatic = true;
  const auto w = scenario::buildWorld(s);
  EXPECT_TRUE(w->planar.has_value());
  EXPECT_TRUE(w->autoRefusals.empty());
  ASSERT_TRUE(w->certificate.has_value());
  s.fidelity.errorBudget = 0.5 * w->certificate->find(vehicle::Fidelity::Planar)->worst / 100.0;
  const auto strict = scenario::buildWorld(s);
  EXPECT_FALSE(strict->planar.has_value());
  EXPECT_EQ(strict->vehicle.fidelity, vehicle::Fidelity::Kinematic);
  ASSERT_EQ(strict->autoRefusals.size(), 1u);
  EXPECT_NE(strict->autoRefusals[0].find("planar not used"), std::string::npos) << strict->autoRefusals[0];
}


// `auto` against the linkage at the same step on the reference manoeuvres,
// for the reference sedan and its roll-steer and anti-dive variants: within
// the default 10 % budget on yaw rate, a_y, roll and chassis height (RMS as
// % of the linkage's peak), with the planar rung in use.
TEST(RungCertificate, AutoStaysWithinItsBudgetOnTheVariants) {
  for (const char* vehicleFile : {"vehicles/sedan.toml", "vehicles/sedan_roll_steer.toml", "vehicles/sedan_anti_dive.toml"}) {
    for (const char* scenarioFile : {"scenarios/jturn.toml", "scenarios/lane_change.toml"}) {
      scenario::ScenarioSpec linkage = scenario::loadScenarioFile(asset(scenarioFile));
      linkage.vehicleFile = asset(vehicleFile);
      scenario::ScenarioSpec automatic = linkage;
      automatic.fidelity.automatic = true;
      scenario::Simulation a(linkage), b(automatic);
      const scenario::RunResult ra = scenario::runScenario(a, {}), rb = scenario::runScenario(b, {});
      ASSERT_TRUE(ra.ok) << ra.failure;
      ASSERT_TRUE(rb.ok) << rb.failure;
      ASSERT_EQ(ra.samples.size(), rb.samples.size());
      EXPECT_GT(rb.stepsPerModel[2], 0) << vehicleFile << " " << scenarioFile;
      auto rmsPercent = [&](auto q) {
        double sum = 0, peak = 0;
        for (size_t i = 0; i < ra.samples.size(); ++i) {
          sum += std::pow(q(ra.samples[i]) - q(rb.samples[i]), 2);
          peak = std::max(peak, std::abs(q(ra.samples[i])));
        }
        return 100 * std::sqrt(sum / ra.samples.size()) / peak;
      };
      using S = vehicle::VehicleSample;
      const double yaw = rmsPercent([](const S& x) { return x.yawRate; });
      const double ay = rmsPercent([](const S& x) { return x.ay; });
      const double roll = rmsPercent([](const S& x) { return x.roll; });
      const double z = rmsPercent([](const S& x) { return x.chassisOrigin.z(); });
      std::printf("%s %s: yaw rate %.2f %%, a_y %.2f %%, roll %.2f %%, height %.3f %%\n", vehicleFile, scenarioFile, yaw,
                  ay, roll, z);
      for (double e : {yaw, ay, roll, z}) EXPECT_LT(e, 10.0) << vehicleFile << " " << scenarioFile;
    }
  }
}


// Every shipped vehicle file that requires certificates ([certificate],
// docs/VEHICLES.md) keeps them: each required rung's worst figure within
// its bound. At least the reference sedan and its variants require them.
TEST(RungCertificate, ShippedVehiclesKeepTheCertificatesTheyRequire) {
  int required = 0;
  for (const auto& entry : std::filesystem::directory_iterator(asset("vehicles"))) {
    if (entry.path().extension() != ".toml") continue;
    const std::string file = entry.path().string();
    const vehicle::VehicleSpec spec = vehicle::loadVehicleFile(file);
    if (spec.certificateRequired.empty()) continue;
    scenario::ScenarioSpec scene;
    scene.vehicleFile = file;
    scene.sourceFile = file;
    const vehicle::Vehicle linkage = vehicle::buildVehicle(spec);
    const scenario::LadderCertificate c =
        scenario::certifyLadder(scene, linkage, scenario::derivePlanarRung(scene, linkage));
    ASSERT_TRUE(c.failure.empty()) << file << ": " << c.failure;
    for (const auto& [rung, bound] : spec.certificateRequired) {
      const scenario::RungCertificate* r = c.find(*vehicle::rungByName(rung));
      ASSERT_NE(r, nullptr) << file << " " << rung;
      EXPECT_LE(r->worst, 100 * bound) << file << ": " << rung << ", " << r->worstQuantity << " on " << r->worstManoeuvre;
      ++required;
    }
  }
  EXPECT_GE(required, 6);
}

}  // namespace
}  // namespace bdfcar
