// `[fidelity] suspension = "auto"` (scenario/fidelity_policy.h): the state
// mapped between the kinematic and planar models (vehicle/rung_mapping.h),
// switches in mid-run against a run on the kinematic model alone, the switch
// up ahead of a curb (in a scene, and the policy's own scan against the
// rays), and a run restored from a state on the planar model.
#include <gtest/gtest.h>

#include <cmath>

#include "scenario/check.h"
#include "scenario/fidelity_policy.h"
#include "terrain/bullet/bullet_terrain.h"
#include "terrain/terrain_file.h"
#include "scenario/run.h"
#include "vehicle/rung_mapping.h"

namespace bdfcar {
namespace {

std::string asset(const std::string& rel) { return std::string(BDFCAR_SOURCE_DIR) + "/assets/" + rel; }

scenario::ScenarioSpec autoSpec(const char* file) {
  scenario::ScenarioSpec s = scenario::loadScenarioFile(asset(file));
  s.fidelity.automatic = true;
  s.fidelity.errorBudget = scenario::kPlanarErrorBound;
  return s;
}

// A state in mid-manoeuvre (1.5 s into the J-turn, rolled and yawing) on the
// kinematic model, mapped to the planar model and back: what both models
// have (attitude, heading, rates, rack, spins) survives both ways; a planar
// state survives the round trip exactly.
TEST(RungMapping, KeepsWhatBothModelsHave) {
  scenario::Simulation sim(autoSpec("scenarios/jturn.toml"));
  ASSERT_EQ(sim.rungCount(), 2);
  scenario::RunOptions o;
  o.sample = false;
  scenario::Run run(sim, o);
  while (sim.time() < 1.5 && run.tick(std::nullopt)) {
  }
  if (sim.rung() == 1) sim.switchRung(0);
  const vehicle::Vehicle& kin = sim.world().vehicle;
  const vehicle::Vehicle& planar = *sim.world().planar;
  const integ::SolutionPoint now = sim.multibodyPoint();  // the kinematic model's coordinates
  const Eigen::VectorXd qk = now.q, vk = now.v;
  Eigen::VectorXd qp, vp, qk2, vk2, qp2, vp2;
  vehicle::kinematicToPlanar(kin, planar, qk, vk, qp, vp);
  vehicle::planarToKinematic(planar, kin, qp, vp, qk2, vk2);
  const mb::Body& ch = kin.model.bodies[kin.layout.chassis];
  // Attitude (quaternion) and the chassis's angular velocity: exact.
  EXPECT_LT((qk.segment<4>(ch.qIndex + 3) - qk2.segment<4>(ch.qIndex + 3)).norm(), 1e-12);
  EXPECT_LT((vk.segment<3>(ch.vIndex + 3) - vk2.segment<3>(ch.vIndex + 3)).norm(), 1e-12);
  // Horizontal position and velocity: exact; height and vertical velocity:
  // the planar model has no heave (a few millimetres in this manoeuvre).
  EXPECT_LT((qk.segment<2>(ch.qIndex) - qk2.segment<2>(ch.qIndex)).norm(), 1e-12);
  EXPECT_LT(std::abs(qk(ch.qIndex + 2) - qk2(ch.qIndex + 2)), 5e-3);
  for (int w = 0; w < 4; ++w) {
    const int spin = kin.model.bodies[kin.layout.wheels[w].spindle].vIndex;
    EXPECT_EQ(vk(spin), vk2(spin));
    // Travel: the suspension's share of the corner's deflection (within 3 mm here).
    const mb::Body& c = kin.model.bodies[kin.layout.wheels[w].carrier];
    EXPECT_NEAR(qk2(c.qIndex), qk(c.qIndex), 3e-3) << w;
  }
  EXPECT_EQ(qk(kin.layout.rackQ), qk2(kin.layout.rackQ));
  vehicle::kinematicToPlanar(kin, planar, qk2, vk2, qp2, vp2);
  EXPECT_LT((qp - qp2).lpNorm<Eigen::Infinity>(), 1e-12);
  EXPECT_LT((vp - vp2).lpNorm<Eigen::Infinity>(), 1e-9) << (vp - vp2).transpose();
}

// The lane change under `auto` (down to the planar model on the straight,
// up at the tyres' limit, down again) against the kinematic model alone:
// within the planar model's bound overall, and no jump at a switch (the
// change of lateral acceleration across a switch within 0.2 m/s^2 of the
// kinematic run's over the same interval: the target).
TEST(FidelityAuto, SwitchesInMidRunWithoutAJump) {
  scenario::ScenarioSpec kinSpec = scenario::loadScenarioFile(asset("scenarios/lane_change.toml"));
  kinSpec.fidelity.suspension = vehicle::Fidelity::Kinematic;
  scenario::Simulation a(kinSpec), b(autoSpec("scenarios/lane_change.toml"));
  std::vector<int> rung;  // the model that computed each sample of b
  scenario::RunOptions keep, keepRung;
  keepRung.onSample = [&](const vehicle::VehicleSample&) { rung.push_back(b.rung()); };
  const scenario::RunResult ra = scenario::runScenario(a, keep), rb = scenario::runScenario(b, keepRung);
  ASSERT_TRUE(ra.ok) << ra.failure;
  ASSERT_TRUE(rb.ok) << rb.failure;
  EXPECT_GE(rb.fidelitySwitches, 2);
  EXPECT_GT(rb.stepsPerModel[2], 0);
  EXPECT_EQ(b.fidelityState().missed, 0);
  ASSERT_EQ(ra.samples.size(), rb.samples.size());
  ASSERT_EQ(rung.size(), rb.samples.size());
  double sumYaw = 0, sumAy = 0, peakYaw = 0, peakAy = 0;
  for (size_t i = 0; i < ra.samples.size(); ++i) {
    sumYaw += std::pow(ra.samples[i].yawRate - rb.samples[i].yawRate, 2);
    sumAy += std::pow(ra.samples[i].ay - rb.samples[i].ay, 2);
    peakYaw = std::max(peakYaw, std::abs(ra.samples[i].yawRate));
    peakAy = std::max(peakAy, std::abs(ra.samples[i].ay));
  }
  const double n = static_cast<double>(ra.samples.size());
  EXPECT_LT(std::sqrt(sumYaw / n) / peakYaw, scenario::kPlanarErrorBound);
  EXPECT_LT(std::sqrt(sumAy / n) / peakAy, scenario::kPlanarErrorBound);
  int switches = 0;
  for (size_t i = 1; i < rung.size(); ++i) {
    if (rung[i] == rung[i - 1]) continue;
    ++switches;
    const double stepAuto = rb.samples[i].ay - rb.samples[i - 1].ay;
    const double stepKinematic = ra.samples[i].ay - ra.samples[i - 1].ay;
    EXPECT_LT(std::abs(stepAuto - stepKinematic), 0.2) << "switch at t = " << rb.samples[i].t;
  }
  EXPECT_EQ(switches, rb.fidelitySwitches);
}

// The curb strike under `auto`: down to the planar model on the approach, up
// to the kinematic model before the curb (the scan ahead, not the planar
// model's own stop on ground it cannot drive on), and the scenario's check
// passes.
TEST(FidelityAuto, SwitchesUpAheadOfACurb) {
  const scenario::CheckResult c = scenario::checkScenario(autoSpec("scenarios/hard/curb_strike.toml"));
  EXPECT_TRUE(c.passed) << (c.failures.empty() ? "" : c.failures.front());
  scenario::Simulation sim(autoSpec("scenarios/hard/curb_strike.toml"));
  const scenario::RunResult r = scenario::runScenario(sim, {});
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_GT(r.stepsPerModel[2], 0);
  EXPECT_GT(r.stepsPerModel[1], 0);
  EXPECT_EQ(sim.fidelityState().missed, 0);
}

// A state saved on the planar model restores bit for bit: the rung and the
// policy's state are part of the run state.
TEST(FidelityAuto, RestoresAStateSavedOnThePlanarModel) {
  scenario::Simulation sim(autoSpec("scenarios/lane_change.toml"));
  scenario::RunOptions o;
  o.keepSamples = false;
  scenario::Run run(sim, o);
  while (sim.rung() != 1 && run.tick(std::nullopt)) {
  }
  ASSERT_EQ(sim.rung(), 1);
  const scenario::RunState saved = sim.save();
  auto drive = [&] {
    std::vector<double> out;
    for (int i = 0; i < 200; ++i) {
      sim.beginTick(std::nullopt);
      for (int k = 0; k < sim.stepsPerTick(); ++k) EXPECT_TRUE(sim.step().ok());
      const vehicle::VehicleSample s = sim.sample();
      out.push_back(s.yawRate);
      out.push_back(s.ay);
      out.push_back(sim.rung());
    }
    return out;
  };
  const std::vector<double> first = drive();
  sim.restore(saved);
  EXPECT_EQ(first, drive());
}


// The proving ground's 10 % hill (assets/scenarios/proving_ground/hill_stop.toml):
// pull away, climb, stop on the face with the brake, release and roll back.
// The chassis height follows the linkage's within 2 cm for the whole run
// under `auto` (which may not use the planar rung on the hill: the ground
// under the wheels is off its road plane) and on the kinematic rung. The
// planar rung forced onto the hill stops at the foot with a message naming
// the rung and the slope, never with a car inside the hill.
TEST(FidelityAuto, HillStopFollowsTheLinkage) {
  const scenario::ScenarioSpec hill = scenario::loadScenarioFile(asset("scenarios/proving_ground/hill_stop.toml"));
  auto run = [&](const scenario::ScenarioSpec& s) {
    scenario::Simulation sim(s);
    return scenario::runScenario(sim, {});
  };
  scenario::ScenarioSpec linkageSpec = hill;
  linkageSpec.fidelity = {};
  const scenario::RunResult ref = run(linkageSpec);
  ASSERT_TRUE(ref.ok) << ref.failure;
  double top = 0;
  for (const vehicle::VehicleSample& s : ref.samples) top = std::max(top, s.chassisOrigin.z());
  EXPECT_GT(top, 1.0);  // the car climbed the face
  scenario::ScenarioSpec kinematic = hill;
  kinematic.fidelity = {};
  kinematic.fidelity.suspension = vehicle::Fidelity::Kinematic;
  for (const scenario::ScenarioSpec& s : {hill, kinematic}) {
    const scenario::RunResult r = run(s);
    ASSERT_TRUE(r.ok) << r.failure;
    ASSERT_EQ(r.samples.size(), ref.samples.size());
    double worst = 0;
    for (size_t i = 0; i < r.samples.size(); ++i)
      worst = std::max(worst, std::abs(r.samples[i].chassisOrigin.z() - ref.samples[i].chassisOrigin.z()));
    EXPECT_LT(worst, 0.02) << (s.fidelity.automatic ? "auto" : "kinematic");
  }
  scenario::ScenarioSpec planar = hill;
  planar.fidelity = {};
  planar.fidelity.suspension = vehicle::Fidelity::Planar;
  const scenario::RunResult p = run(planar);
  EXPECT_FALSE(p.ok);
  EXPECT_NE(p.failure.find("planar"), std::string::npos) << p.failure;
  EXPECT_NE(p.failure.find("slope"), std::string::npos) << p.failure;
  for (const vehicle::VehicleSample& s : p.samples) EXPECT_LT(s.chassisOrigin.z(), 1.0) << "t = " << s.t;
}

// A switch down that would move the chassis is refused and counted: on the
// hill's face the planar rung's road plane (the start's) is metres below the
// car, so mapping the state down would drop it into the hill.
TEST(FidelityAuto, ASwitchThatWouldMoveTheChassisIsRefused) {
  scenario::Simulation sim(scenario::loadScenarioFile(asset("scenarios/proving_ground/hill_stop.toml")));
  scenario::RunOptions o;
  o.keepSamples = false;
  scenario::Run run(sim, o);
  while (sim.time() < 6.0 && run.tick(std::nullopt)) {
  }
  ASSERT_FALSE(run.failed()) << run.failure();
  ASSERT_EQ(sim.rung(), 0);
  const double before = sim.sample().chassisOrigin.z();
  ASSERT_GT(before, 1.0);
  const long refused = sim.fidelityState().refused;
  EXPECT_FALSE(sim.switchRung(1));
  EXPECT_EQ(sim.rung(), 0);
  EXPECT_EQ(sim.fidelityState().refused, refused + 1);
  EXPECT_EQ(sim.sample().chassisOrigin.z(), before);
}

// The switches `auto` makes on the lane change move the chassis by less
// than the refusal's limits, and the telemetry's jump column says so.
TEST(FidelityAuto, SwitchesMoveTheChassisByLessThanTheLimit) {
  scenario::Simulation sim(autoSpec("scenarios/lane_change.toml"));
  const scenario::RunResult r = scenario::runScenario(sim, {});
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_GE(r.fidelitySwitches, 2);
  EXPECT_LE(r.fidelity.maxJump, scenario::FidelityPolicy::kMaxJump);
  EXPECT_LE(r.fidelity.maxTurn, scenario::FidelityPolicy::kMaxTurn);
}

// A policy for a car of the sedan's size on the road plane z = 0: its
// wheels' offsets from the centre of mass (x forward, y left), default
// tyres, no limit on lateral acceleration.
const std::array<Eigen::Vector2d, 4> kWheelOffsets{Eigen::Vector2d(1.2, 0.8), Eigen::Vector2d(1.2, -0.8),
                                                   Eigen::Vector2d(-1.3, 0.8), Eigen::Vector2d(-1.3, -0.8)};
scenario::FidelityPolicy sedanSizedPolicy(const terrain::Terrain& t) {
  const std::array<tyre::TyreParams, 4> tyres{tyre::FialaParams{}, tyre::FialaParams{}, tyre::FialaParams{},
                                              tyre::FialaParams{}};
  return scenario::FidelityPolicy(t, 0.0, kWheelOffsets, tyres, INFINITY);
}

// The road scan's shortcut (Terrain::levelOver) against the rays it stands
// for: over the proving ground (a ground with the circuit's mesh, curbs,
// a gravel trap, a slope, a heightfield section), boxes along the circuit's
// centre line and its edges, boxes anywhere and a wheel's strip of a tick
// (through the mesh's plan grid, not its tree). Wherever the terrain vouches
// for a box, every ray on a 9 x 9 grid over it must find the road plane;
// and it must vouch for most of the centre line (else it buys nothing),
// never for a box over a curb or the rough section.
TEST(FidelityAuto, LevelShortcutNeverVouchesForGroundTheRaysFindOffTheRoadPlane) {
  const terrain::TerrainData data = terrain::loadTerrain(std::string(BDFCAR_SOURCE_DIR) + "/assets/terrain/proving_ground.toml");
  const std::unique_ptr<terrain::Terrain> ground = terrain::makeTerrain(data);
  const scenario::FidelityPolicy policy = sedanSizedPolicy(*ground);
  terrain::WorldCentreLine line;
  ASSERT_TRUE(terrain::findCentreLine(data, "circuit", line));
  auto query = [](const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
    terrain::Terrain::LevelQuery q;
    q.lo = lo;
    q.hi = hi;
    q.zTop = scenario::FidelityPolicy::kRayAbove;
    q.zBottom = q.zTop - scenario::FidelityPolicy::kRayLength;
    q.height = 0.0;
    q.tolerance = scenario::FidelityPolicy::kRoadHeight;
    q.minNormalZ = std::cos(scenario::FidelityPolicy::kRoadSlope);
    return q;
  };
  auto raysAllLevel = [&](const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
    for (int i = 0; i <= 8; ++i)
      for (int j = 0; j <= 8; ++j)
        if (!policy.level(lo + Eigen::Vector2d(i / 8.0 * (hi.x() - lo.x()), j / 8.0 * (hi.y() - lo.y())))) return false;
    return true;
  };
  int vouched = 0, onCentre = 0, centreBoxes = 0, refusedByRays = 0;
  uint64_t state = 99;
  auto uniform = [&]() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  const size_t n = line.points.size();
  for (size_t k = 0; k < 4000; ++k) {
    Eigen::Vector2d centre;
    double half;
    bool onLine = false;
    if (k >= 3000) {  // a wheel's strip of a tick (the policy's own query), anywhere across the road
      const size_t i = static_cast<size_t>(uniform() * (n - 1));
      const Eigen::Vector2d a = line.points[i], b = line.points[(i + 1) % n];
      const Eigen::Vector2d t = (b - a).normalized(), across(-t.y(), t.x());
      centre = a + uniform() * (b - a) + (uniform() - 0.5) * 12.0 * across;
      half = 0.02 + 0.3 * uniform();
    } else if (k < 2000) {  // along the line, across the road to beyond its edges
      const size_t i = static_cast<size_t>(uniform() * (n - 1));
      const Eigen::Vector2d a = line.points[i], b = line.points[(i + 1) % n];
      const Eigen::Vector2d t = (b - a).normalized(), across(-t.y(), t.x());
      onLine = k < 1000;
      centre = a + uniform() * (b - a) + (onLine ? 0.0 : (uniform() - 0.5) * 16.0) * across;
      half = onLine ? 1.0 + uniform() : 0.5 + 2.0 * uniform();
    } else {  // anywhere on the ground
      centre = Eigen::Vector2d(-100 + 1200 * uniform(), -400 + 700 * uniform());
      half = 0.5 + 3.0 * uniform();
    }
    const Eigen::Vector2d lo = centre - Eigen::Vector2d::Constant(half), hi = centre + Eigen::Vector2d::Constant(half);
    const bool shortcut = ground->levelOver(query(lo, hi));
    const bool rays = raysAllLevel(lo, hi);
    if (shortcut) {
      ++vouched;
      ASSERT_TRUE(rays) << "vouched for the box around (" << centre.x() << ", " << centre.y() << ") +-" << half;
    } else if (!rays) {
      ++refusedByRays;
    }
    if (onLine) {
      ++centreBoxes;
      onCentre += shortcut;
    }
  }
  EXPECT_GT(onCentre, centreBoxes / 2) << "the shortcut vouches for too little of the circuit's centre line";
  EXPECT_GT(refusedByRays, 100) << "the boxes never met a curb, slope or rough ground: the test tests nothing";
  EXPECT_GT(vouched, 0);
}

// The scan asks the terrain for a level stretch beyond the look-ahead (a
// query every few ticks), but rough ground found there is acted on only once
// it is within the look-ahead: on a straight run at 20 m/s towards a curb
// across the road (a ground with one piece: 10 cm high, 45-degree faces),
// the policy goes to the full model when the look-ahead first reaches the
// curb, not kScanAhead earlier, and stays there until the last wheel is
// kMargin past it. Where each wheel meets the curb comes from the rays
// (FidelityPolicy::level along its line, every millimetre), not from the
// scan; the tolerance is the scan's step and a tick's travel.
TEST(FidelityAuto, RoughGroundIsActedOnOnlyWithinTheLookAhead) {
  terrain::TerrainData curb;
  curb.kind = terrain::TerrainKind::Mesh;
  const double xs[4] = {-0.1, 0.0, 0.5, 0.6}, zs[4] = {0.0, 0.1, 0.1, 0.0};
  for (int i = 0; i < 4; ++i)
    for (double y : {-5.0, 5.0}) curb.vertices.emplace_back(xs[i], y, zs[i]);
  for (int i = 0; i < 3; ++i) {  // vertex 2i at y = -5, 2i + 1 at y = +5: counter-clockwise from above
    curb.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 3});
    curb.triangles.push_back({2 * i, 2 * i + 3, 2 * i + 1});
  }
  terrain::TerrainData ground;
  ground.kind = terrain::TerrainKind::Ground;
  ground.pieces.push_back(terrain::GroundPiece{"curb", curb, Eigen::Vector3d(30.0, 0.0, 0.0), 0.0});
  const std::unique_ptr<terrain::Terrain> t = terrain::makeTerrain(ground);
  const scenario::FidelityPolicy policy = sedanSizedPolicy(*t);

  // Odometer distances (the centre of mass's x) over which some wheel is on
  // ground the rays find off the road plane.
  double roughFrom = INFINITY, roughTo = -INFINITY;
  for (const Eigen::Vector2d& o : kWheelOffsets)
    for (double x = 25.0; x <= 35.0; x += 1e-3)
      if (!policy.level(Eigen::Vector2d(x, o.y()))) {
        roughFrom = std::min(roughFrom, x - o.x());
        roughTo = std::max(roughTo, x - o.x());
      }
  ASSERT_TRUE(std::isfinite(roughFrom)) << "the rays never met the curb: the test tests nothing";

  const double speed = 20.0, tick = 0.01;
  const double lookAhead = std::max(scenario::FidelityPolicy::kMinLookAhead, speed * scenario::FidelityPolicy::kLookAhead);
  std::array<vehicle::WheelContact, 4> wheels;
  for (vehicle::WheelContact& w : wheels) {  // on the road plane, well inside the tyres' friction
    w.plane.valid = true;
    w.acceptedInContact = true;
    w.acceptedFz = 4000;
  }
  scenario::FidelityPolicy::State s;
  double firstFull = NAN, lastFull = NAN;
  for (int k = 0; k < 3000; ++k) {
    const double x = s.odometer + speed * tick;  // straight along x from the origin: the odometer after the tick
    const auto d = policy.decide(s, Eigen::Vector2d(x, 0.0), 0.0, speed, 0.0, wheels, tick);
    if (d == scenario::FidelityPolicy::Decision::Full) {
      if (std::isnan(firstFull)) firstFull = s.odometer;
      lastFull = s.odometer;
    }
  }
  ASSERT_FALSE(std::isnan(firstFull)) << "the policy never asked for the full model";
  const double slack = scenario::FidelityPolicy::kScanStep + speed * tick + 1e-9;
  EXPECT_NEAR(firstFull, roughFrom - lookAhead, slack)
      << "the full model from " << firstFull << " m, the look-ahead reaches the curb at " << roughFrom - lookAhead << " m";
  EXPECT_NEAR(lastFull, roughTo + scenario::FidelityPolicy::kMargin, slack);
  EXPECT_EQ(s.missed, 0);
}

}  // namespace
}  // namespace bdfcar
