// The enveloping contact (physics/tyre/envelope.h): its cams against the
// closed-form geometry of an ellipse resting on a step's edge, its effective
// plane against planes and long road waves (where a point contact reads the
// road exactly), and a car striking a curb at the driver's 10 ms step against
// the same car at 0.5 ms, with the ground inside the step and, on purpose,
// held at the step's prediction; the point contact's curb strike at the
// driver's step, refined where it misses its predictor, and not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <numbers>
#include <stdexcept>

#include "config/toml_reader.h"
#include "run_error.h"
#include "scenario/run.h"
#include "scenario/scenario_spec.h"
#include "terrain/height_lattice.h"
#include "tyre/envelope.h"

namespace bdfcar {
namespace {

using testing_run_error::rmsPercent;
using testing_run_error::yawAndLateralRmsPercent;
using tyre::Envelope;
using tyre::RoadProfile;

Envelope cams(double a, double b, double c, double base) {
  tyre::EnvelopeSpec s;
  s.on = true;
  s.halfLength = a;
  s.halfHeight = b;
  s.order = c;
  s.base = base;
  return tyre::resolveEnvelope(s, 0.3, 2e5, 4000);
}

// A profile along x through the origin, z(s) and its cross slope given.
template <class Z>
RoadProfile profile(double half, double ds, Z z, double cross = 0.0) {
  RoadProfile p;
  p.valid = true;
  p.ds = ds;
  p.n = 2 * static_cast<int>(std::lround(half / ds)) + 1;
  if (p.n > RoadProfile::kCapacity) throw std::invalid_argument("a test profile longer than a RoadProfile holds");
  p.s0 = -0.5 * (p.n - 1) * ds;
  for (int k = 0; k < p.n; ++k) {
    p.z[k] = z(p.s0 + k * ds);
    p.cross[k] = cross;
  }
  return p;
}

TEST(Envelope, CamOnAStepEdgeIsTheSuperellipseThroughTheEdge) {
  // A step of height H at s = e: a cam centred at s < e rests on the edge
  // point (e, H) once its contour reaches it, its lowest point at
  // H - b (1 - (1 - ((e - s) / a)^c)^(1/c)), and on the lower road (0) before.
  const double H = 0.1, e = 0.2;
  for (const double c : {2.0, 1.6, 3.0}) {
    const Envelope env = cams(0.34, 0.3, c, 0.2);
    const RoadProfile p = profile(1.0, 0.01, [&](double s) { return s >= e - 1e-12 ? H : 0.0; });
    for (int i = 0; i <= 66; ++i) {
      const double s = -0.4 + 0.015 * i;  // on the profile's samples: the lower road read exactly
      const double d = e - s;
      double expected = H;
      if (d > 0) {
        const double u = d / env.a;
        expected = u >= 1 ? 0.0 : std::max(0.0, H - env.b * (1 - std::pow(1 - std::pow(u, c), 1 / c)));
      }
      // The profile's last sample before the edge (e - ds) is a point of the
      // lower road: where the edge's rise falls below 0 the cam rests there.
      EXPECT_NEAR(tyre::camHeight(env, p, s), expected, 1e-12) << "c = " << c << ", s = " << s;
    }
  }
}

TEST(Envelope, EffectivePlaneOfAnyPlaneIsThatPlane) {
  // On a plane the cams both stand off it by their support function: taken
  // out, the effective road is the plane itself, height and normal, at any
  // slope, whatever the cams' shape (the point contact's reading exactly).
  for (const double c : {2.0, 1.7, 4.0})
    for (const double m : {0.0, 0.05, -0.2, 0.6})
      for (const double lateral : {0.0, 0.1, -0.3}) {
        const Envelope env = cams(0.32, 0.28, c, 0.18);
        const RoadProfile p = profile(0.6, 0.01, [&](double s) { return 0.3 + m * s; }, lateral);
        const Eigen::Vector3d centre(0.013, 0.02, 0.6);
        const tyre::ContactPlane g = tyre::effectivePlane(env, p, centre);
        ASSERT_TRUE(g.valid);
        const Eigen::Vector3d normal = Eigen::Vector3d(-m, -lateral, 1).normalized();
        EXPECT_NEAR(g.point.z(), 0.3 + m * 0.013 + lateral * 0.02, 1e-9) << c << " " << m << " " << lateral;
        EXPECT_LT((g.normal - normal).norm(), 1e-9) << c << " " << m << " " << lateral;
        // The straight road's shortcut (findLine) reads the same.
        RoadProfile line = p;
        tyre::findLine(line);
        ASSERT_TRUE(line.linear);
        EXPECT_NEAR(tyre::effectivePlane(env, line, centre).point.z(), g.point.z(), 1e-12);
      }
}

TEST(Envelope, OnLevelGroundTheEnvelopeIsThePoint) {
  // The J-turn on flat ground: the sedan on enveloping tyres and on point
  // contacts write the same telemetry, byte for byte (the cams on a level
  // road stand exactly on it).
  std::string bytes[2];
  for (int i = 0; i < 2; ++i) {
    scenario::ScenarioSpec s = scenario::loadScenarioFile(std::string(BDFCAR_SOURCE_DIR) + "/assets/scenarios/jturn.toml");
    if (i == 1) s.vehicleFile = std::string(BDFCAR_SOURCE_DIR) + "/assets/vehicles/sedan_envelope.toml";
    scenario::Simulation sim(s);
    scenario::RunOptions o;
    o.telemetryPath = (std::filesystem::temp_directory_path() / ("bdfcar_envelope_flat_" + std::to_string(i) + ".csv")).string();
    ASSERT_TRUE(scenario::runScenario(sim, o).ok);
    std::ifstream in(o.telemetryPath, std::ios::binary);
    bytes[i].assign(std::istreambuf_iterator<char>(in), {});
    std::filesystem::remove(o.telemetryPath);
  }
  EXPECT_GT(bytes[0].size(), 10000u);
  EXPECT_TRUE(bytes[0] == bytes[1]) << "the envelope moved a flat-road run";
}

TEST(Envelope, LongRoadWavesAreReadAsThePointReadsThem) {
  // A wave 20 m long and 5 cm high, slopes up to 1.6 %: the cams (the
  // unloaded circle of 0.34 m) bridge nothing of it, and the effective height
  // and slope stay within what its curvature (4.9e-3 / m) makes of a 0.34 m
  // circle: R^2 kappa / 2 = 0.3 mm of height.
  const double A = 0.05, L = 20.0, k = 2 * std::numbers::pi / L;
  const Envelope env = cams(0.34, 0.34, 2.0, 0.19);
  for (double x = 0; x < L; x += 0.7) {
    const RoadProfile p = profile(0.6, 0.005, [&](double s) { return A * std::sin(k * (x + s)); });
    tyre::EffectiveRoad r;
    ASSERT_TRUE(tyre::effectiveRoad(env, p, Eigen::Vector3d(0, 0, 0.4), r));
    EXPECT_NEAR(r.height, A * std::sin(k * x), 0.34 * 0.34 * A * k * k / 2 + 1e-5) << "x = " << x;
    EXPECT_NEAR(r.forwardSlope, A * k * std::cos(k * x), 1e-3) << "x = " << x;
  }
}

TEST(Envelope, ShortObstaclesAreBridged) {
  // A 2 cm cleat 1 cm long under the wheel centre: a point rises 2 cm; each
  // cam, 0.1 m from it, only by the cleat less its contour's rise there
  // (0.3 (1 - sqrt(1 - (0.095 / 0.3)^2)) = 1.55 cm at the cleat's near edge).
  const Envelope env = cams(0.3, 0.3, 2.0, 0.2);
  const RoadProfile p = profile(0.6, 0.005, [](double s) { return std::abs(s) <= 0.0051 ? 0.02 : 0.0; });
  tyre::EffectiveRoad r;
  ASSERT_TRUE(tyre::effectiveRoad(env, p, Eigen::Vector3d::Zero(), r));
  EXPECT_NEAR(r.height, 0.02 - 0.3 * (1 - std::sqrt(1 - std::pow(0.095 / 0.3, 2))), 1e-12);
  EXPECT_NEAR(r.forwardSlope, 0.0, 1e-12);  // symmetric: both cams on the cleat alike
}

TEST(HeightLattice, BilinearSurfaceOfAPlaneIsThePlane) {
  const terrain::PlaneTerrain tilted(Eigen::Vector3d(0, 0, 0.2), Eigen::Vector3d(-0.1, 0.05, 1).normalized());
  terrain::HeightLattice lattice(tilted, 0.04);
  terrain::HeightLattice::Point at;
  for (double x : {-3.01, 0.0, 0.517, 12.3})
    for (double y : {-0.77, 0.0, 2.02}) {
      ASSERT_TRUE(lattice.at(x, y, 5.0, 10.0, at));
      EXPECT_NEAR(at.z, 0.2 + 0.1 * x - 0.05 * y, 1e-12);
      EXPECT_NEAR(at.dzdx, 0.1, 1e-9);
      EXPECT_NEAR(at.dzdy, -0.05, 1e-9);
    }
  // Each node cast once: asking again casts nothing.
  const long rays = lattice.raysCast();
  ASSERT_TRUE(lattice.at(0.517, 2.02, 5.0, 10.0, at));
  EXPECT_EQ(lattice.raysCast(), rays);
}

// The curb strike (assets/scenarios/hard/curb_strike.toml) on the given
// vehicle file, to 2.5 s (the strike is at 1.5-2 s) unless a duration is given.
scenario::ScenarioSpec curbStrike(const char* vehicle, double step, int newton, int jacobianEvery,
                                  double duration = 2.5) {
  scenario::ScenarioSpec s =
      scenario::loadScenarioFile(std::string(BDFCAR_SOURCE_DIR) + "/assets/scenarios/hard/curb_strike.toml");
  s.vehicleFile = std::string(BDFCAR_SOURCE_DIR) + "/assets/vehicles/" + vehicle;
  s.duration = duration;
  s.integrator.step = step;
  s.integrator.bdf.newtonIterations = newton;
  s.integrator.bdf.jacobianEvery = jacobianEvery;
  return s;
}
// On enveloping tyres, every step taken whole (no refinement: the contact's
// own error at the step, not the integrator's cure for it).
scenario::ScenarioSpec curbOnEnvelopes(double step, int newton, int jacobianEvery) {
  scenario::ScenarioSpec s = curbStrike("sedan_envelope.toml", step, newton, jacobianEvery);
  s.integrator.bdf.refineError = 0;
  return s;
}

double frontLeftLoadRmsPercent(const scenario::RunResult& ref, const scenario::RunResult& run) {
  return rmsPercent(ref, run, [](const vehicle::VehicleSample& s) { return s.Fz[0]; });
}
TEST(Envelope, CurbStrikeLoadAtTheDriversStepFollowsTheConvergedRun) {
  // The 10 ms step (BDF2, two Newton iterations) against 0.5 ms converged
  // (Newton to tolerance, a Jacobian every step): the front-left tyre's load
  // through the strike within 1.5 % of its peak, RMS (measured 0.64 %). The
  // same with the ground held where each step's prediction put the wheel
  // (the frozen plane of the point contact) is 2.4 %: it must fail this.
  scenario::Simulation fineSim(curbOnEnvelopes(0.0005, 0, 1));
  const scenario::RunResult fine = scenario::runScenario(fineSim, {});
  ASSERT_TRUE(fine.ok) << fine.failure;
  scenario::Simulation inside(curbOnEnvelopes(0.01, 2, 200));
  const scenario::RunResult r = scenario::runScenario(inside, {});
  ASSERT_TRUE(r.ok) << r.failure;
  const double error = frontLeftLoadRmsPercent(fine, r);
  EXPECT_LT(error, 1.5);

  scenario::ScenarioSpec frozenSpec = curbOnEnvelopes(0.01, 2, 200);
  frozenSpec.groundInsideStep = false;
  scenario::Simulation frozen(frozenSpec);
  const scenario::RunResult f = scenario::runScenario(frozen, {});
  ASSERT_TRUE(f.ok) << f.failure;
  EXPECT_GT(frontLeftLoadRmsPercent(fine, f), 1.5) << "the frozen ground passes the test the ground inside the step passes ("
                                                  << error << " %)";
}

// A run of spec (which must succeed).
scenario::RunResult runOf(const scenario::ScenarioSpec& spec) {
  scenario::Simulation sim(spec);
  scenario::RunResult r = scenario::runScenario(sim, {});
  EXPECT_TRUE(r.ok) << r.failure;
  return r;
}
// The point contact's curb strike as its file runs it (10 ms, the default
// policy), and the same converged at 0.5 ms: the whole run.
scenario::ScenarioSpec curbAsItsFileRunsIt() {
  const scenario::ScenarioSpec spec = scenario::loadScenarioFile(std::string(BDFCAR_SOURCE_DIR) +
                                                                 "/assets/scenarios/hard/curb_strike.toml");
  return curbStrike("sedan.toml", spec.integrator.step, spec.integrator.bdf.newtonIterations,
                    spec.integrator.bdf.jacobianEvery, spec.duration);
}
scenario::RunResult curbConverged() { return runOf(curbStrike("sedan.toml", 0.0005, 0, 1, curbAsItsFileRunsIt().duration)); }

TEST(Envelope, CurbStrikeAtTheDriversStepIsRefinedWhereTheWheelsHitTheCurb) {
  // The point contact's curb strike as its file runs it (10 ms, the default
  // policy) against 0.5 ms converged, the whole run (the measure,
  // RESULTS 5c): yaw rate and lateral acceleration within 1 % of their
  // peaks, RMS (measured 0.55 %). The steps that miss their
  // predictor (the wheels hitting the curb and landing) are taken as
  // halves; without that (refine_error = 0) the same run is 5.2 / 6.3 %
  // off: it must fail this.
  const scenario::RunResult fine = curbConverged();
  const scenario::ScenarioSpec refinedSpec = curbAsItsFileRunsIt();
  const scenario::RunResult r = runOf(refinedSpec);
  ASSERT_TRUE(fine.ok && r.ok);
  EXPECT_GT(r.counters.refinements, 0);
  const double error = yawAndLateralRmsPercent(fine, r);
  EXPECT_LT(error, 1.0);

  scenario::ScenarioSpec offSpec = refinedSpec;
  offSpec.integrator.bdf.refineError = 0;
  const scenario::RunResult o = runOf(offSpec);
  ASSERT_TRUE(o.ok);
  EXPECT_EQ(o.counters.refinements, 0);
  EXPECT_GT(yawAndLateralRmsPercent(fine, o), 1.0) << "the unrefined step passes the test the refined one passes ("
                                                   << error << " %)";
}

TEST(Envelope, RefinedPiecesOfThePointContactCastTheirOwnPlanes) {
  // The point contact's curb strike as its file runs it against 0.5 ms
  // converged, as above: a refined step's halves, and the pieces after
  // them, cast their contact planes at their own predicted ends (the
  // accepted step cast them for a step as long as itself): within 0.8 % of
  // the peaks (measured 0.55 %). Held where the accepted step's prediction put
  // the wheels (ground_inside_step = false) the halves meet the curb edge
  // with the plane of a step that ends elsewhere: measured 1.06 %, it
  // must fail this.
  const scenario::RunResult fine = curbConverged();
  const scenario::ScenarioSpec ownSpec = curbAsItsFileRunsIt();
  const scenario::RunResult r = runOf(ownSpec);
  scenario::ScenarioSpec heldSpec = ownSpec;
  heldSpec.groundInsideStep = false;
  const scenario::RunResult f = runOf(heldSpec);
  ASSERT_TRUE(fine.ok && r.ok && f.ok);
  ASSERT_GT(r.counters.refinements, 0);
  const double error = yawAndLateralRmsPercent(fine, r);
  EXPECT_LT(error, 0.8);
  EXPECT_GT(yawAndLateralRmsPercent(fine, f), 0.8) << "the held planes pass the test the pieces' own pass (" << error
                                                   << " %)";
}

// The rough road lane change as its file runs it (10 ms, the default
// policy), to 3 s (its first second of manoeuvre: the sine starts at 2 s),
// on the point contact (the reference sedan's: the file's own tyres
// envelop the road, which these tests of the step's pieces do not need).
scenario::ScenarioSpec roughRoadFirstSecond() {
  scenario::ScenarioSpec spec = scenario::loadScenarioFile(std::string(BDFCAR_SOURCE_DIR) +
                                                           "/assets/scenarios/hard/rough_lane_change.toml");
  spec.vehicleFile = std::string(BDFCAR_SOURCE_DIR) + "/assets/vehicles/sedan.toml";
  spec.duration = 3.0;
  return spec;
}
// spec converged at 1 ms (Newton to tolerance, a Jacobian every step), as RESULTS 5d takes it.
scenario::RunResult convergedAt1ms(scenario::ScenarioSpec spec) {
  spec.integrator.step = 0.001;
  spec.integrator.bdf.newtonIterations = 0;
  spec.integrator.bdf.jacobianEvery = 1;
  return runOf(spec);
}

// The lane change on level ground at a long step, 30 and 40 ms (80 km/h: the
// wheel moves 0.7-0.9 m a step), on a tyre model and vehicle file given.
scenario::ScenarioSpec levelLaneChangeAt(double step, const char* vehicle) {
  scenario::ScenarioSpec spec = scenario::loadScenarioFile(std::string(BDFCAR_SOURCE_DIR) + "/assets/scenarios/lane_change.toml");
  spec.vehicleFile = std::string(BDFCAR_SOURCE_DIR) + "/assets/vehicles/" + vehicle;
  spec.integrator.step = step;
  spec.tick = step;
  return spec;
}

TEST(Envelope, RefinedPiecesOfALongStepStayOnTheirProfile) {
  // On level ground the envelope is the plane, as the point contact reads
  // it (the second algorithm). At 30 and 40 ms the lane change refines
  // steps into pieces, which end short of the end their profile was
  // sampled around and keep that profile: it must reach back over the
  // wheel's whole path in the step. The wheel loads of the two contacts
  // within 50 N of each other at every sample, under 1 % of a static wheel
  // load (the two runs' Newton iterations stop on different paths: measured
  // 0.18 N at 30 ms, 13 N at 40 ms); with the profile sampled ahead of the
  // predicted end alone, the pieces' cams fell off it and whole wheels read
  // no ground (4 kN and more).
  // The same at 40 ms on a 5 mm lattice (the finest a file may ask): the
  // path and the cams need more samples than a profile holds, which are
  // then spaced further apart, not cut short (cut, the cams fell off).
  struct Case {
    double step, spacing;
  };
  for (const auto [step, spacing] : {Case{0.03, 0.0}, Case{0.04, 0.0}, Case{0.04, 0.005}}) {
    scenario::ScenarioSpec envelopeSpec = levelLaneChangeAt(step, "sedan_envelope.toml");
    if (spacing > 0) envelopeSpec.vehicleSettings.push_back(config::parseSetting("tyres.fiala.envelope_spacing=" + std::to_string(spacing)));
    const scenario::RunResult envelope = runOf(envelopeSpec);
    const scenario::RunResult point = runOf(levelLaneChangeAt(step, "sedan.toml"));
    ASSERT_TRUE(envelope.ok && point.ok);
    EXPECT_GT(envelope.counters.refinements, 0) << "no piece at " << step << " s: the test tests nothing there";
    ASSERT_EQ(envelope.samples.size(), point.samples.size());
    double worst = 0;
    for (std::size_t i = 0; i < point.samples.size(); ++i)
      for (int w = 0; w < 4; ++w) worst = std::max(worst, std::abs(envelope.samples[i].Fz[w] - point.samples[i].Fz[w]));
    EXPECT_LT(worst, 50.0) << "at a " << step << " s step, lattice " << spacing;
  }
}

TEST(Envelope, StepsAfterRefinedOnesGoOnInTheirPieces) {
  // The rough road lane change as its file runs it, its first second of
  // manoeuvre: a step after refined ones goes on in pieces of the last
  // one's length, doubled where the last miss says a doubled piece passes
  // (BdfOptions::carryRefinedPieces). Against every step first tried
  // whole (the second algorithm), which on this road refines nearly every
  // step: at most a fifth of the refinements and at most 80 % of the Newton
  // iterations (measured 9 and 2,327 against 462 and 3,924), and as close
  // to the run converged at 1 ms, no more than 0.1 point further (measured
  // 1.60 % against 1.68 %).
  const scenario::ScenarioSpec spec = roughRoadFirstSecond();
  const scenario::RunResult carried = runOf(spec);
  scenario::ScenarioSpec wholeSpec = spec;
  wholeSpec.integrator.bdf.carryRefinedPieces = false;
  const scenario::RunResult whole = runOf(wholeSpec);
  const scenario::RunResult fine = convergedAt1ms(spec);
  ASSERT_TRUE(carried.ok && whole.ok && fine.ok);
  ASSERT_GT(whole.counters.refinements, 100);
  EXPECT_LT(static_cast<double>(carried.counters.refinements), 0.2 * static_cast<double>(whole.counters.refinements));
  EXPECT_LT(static_cast<double>(carried.counters.newtonIterations),
            0.8 * static_cast<double>(whole.counters.newtonIterations));
  EXPECT_LT(yawAndLateralRmsPercent(fine, carried), yawAndLateralRmsPercent(fine, whole) + 0.1);
}

TEST(Envelope, AStepJudgedAfterItsFirstIterationRefinesAsTheConvergedMissDoes) {
  // The rough road lane change as its file runs it (10 ms, the default
  // policy), its first second of manoeuvre: a step whose first Newton
  // iterate is already twice refine_error from its predictor is halved at
  // once instead of converged first (BdfOptions::refineFromFirstIterate).
  // Against the same run judged only when converged (the second
  // algorithm): as many steps refined (the judged ones are those the
  // converged miss refines anyway), fewer Newton iterations, and as close
  // to the run converged at 1 ms (as RESULTS 5d takes it): yaw rate and
  // lateral acceleration, RMS as % of their peaks, no more than 0.1 point
  // further. Measured: 462 steps refined against 460, 3924 Newton
  // iterations against 4574, 1.68 % from the 1 ms run against 1.66 %;
  // judged at once refine_error away (not twice), 485 steps are refined:
  // some the converged miss keeps whole (this test fails).
  scenario::ScenarioSpec spec = roughRoadFirstSecond();
  // Every step first tried whole: with the refined pieces carried over
  // (BdfOptions::carryRefinedPieces) the road's steps are rarely refined.
  spec.integrator.bdf.carryRefinedPieces = false;
  const scenario::RunResult judged = runOf(spec);
  scenario::ScenarioSpec convergedSpec = spec;
  convergedSpec.integrator.bdf.refineFromFirstIterate = false;
  const scenario::RunResult converged = runOf(convergedSpec);
  const scenario::RunResult fine = convergedAt1ms(spec);
  ASSERT_TRUE(judged.ok && converged.ok && fine.ok);

  const double refined = static_cast<double>(converged.counters.refinements);
  ASSERT_GT(refined, 100);
  EXPECT_NEAR(static_cast<double>(judged.counters.refinements), refined, 0.05 * refined);
  EXPECT_LT(static_cast<double>(judged.counters.newtonIterations),
            0.95 * static_cast<double>(converged.counters.newtonIterations));
  const double judgedError = yawAndLateralRmsPercent(fine, judged);
  const double convergedError = yawAndLateralRmsPercent(fine, converged);
  EXPECT_LT(judgedError, convergedError + 0.1) << "converged only: " << convergedError << " %";
}

}  // namespace
}  // namespace bdfcar
