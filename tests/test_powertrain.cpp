// The powertrain (vehicle/powertrain.h, scenario/transmission.h) on the
// drivable sedan (assets/vehicles/sedan_drive.toml), against hand-computed
// cases from the vehicle file's numbers: the engine held at idle by its
// governor (with the clutch open, and closed in first gear, where the car
// creeps at the speed the idle speed gives), the top speed where the
// engine's power meets drag and rolling resistance, the speeds at which the
// shift schedule shifts, the rev limiter's speed in first, reverse, and the
// handbrake on a 10 % slope (holding above the torque the slope needs,
// slipping below it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "scenario/run.h"
#include "scenario/simulation.h"
#include "terrain/terrain_file.h"
#include "test_files.h"
#include "tyre/tyre_model.h"
#include "vehicle/powertrain.h"
#include "vehicle/vehicle_file.h"

using namespace bdfcar;
using test::asset;

namespace {

constexpr double kRpm = 2.0 * M_PI / 60.0;
constexpr double kG = 9.81;

scenario::ScenarioSpec driveSpec(double speed, const std::vector<std::string>& settings = {},
                                 const std::string& terrain = "") {
  scenario::ScenarioSpec s;
  s.name = "powertrain test";
  s.sourceFile = "test_powertrain";
  s.vehicleFile = asset("vehicles/sedan_drive.toml");
  s.terrainFile = terrain.empty() ? "" : asset("terrain/" + terrain);
  for (const std::string& k : settings) s.vehicleSettings.push_back(config::parseSetting(k));
  s.initialSpeed = speed;
  s.settleTime = 0.5;
  s.duration = 1e4;
  return s;
}

// A person's input held for `seconds`, a callback after every tick.
void drive(scenario::Simulation& sim, scenario::DriverInput in, double seconds,
           const std::function<void(scenario::Simulation&)>& each = {}) {
  const long ticks = std::lround(seconds / sim.spec().tick);
  for (long i = 0; i < ticks; ++i) {
    sim.beginTick(in);
    in.shift = 0;  // a request is made once
    for (int k = 0; k < sim.stepsPerTick(); ++k) ASSERT_TRUE(sim.step().ok()) << "t = " << sim.time();
    if (each) each(sim);
  }
}

// The numbers a hand calculation needs, from the vehicle file.
struct Car {
  vehicle::VehicleSpec spec = vehicle::loadVehicleFile(asset("vehicles/sedan_drive.toml"));
  const vehicle::PowertrainSpec& pt = *spec.powertrain;
  double mass() const {
    double m = 0;
    for (const vehicle::BodySpec& b : spec.bodies) m += b.mass;
    return m;
  }
  const tyre::FialaParams& tyre() const { return std::get<tyre::FialaParams>(spec.wheels[2].tyre); }
  // The rolling radius of a wheel carrying Fz: the slip's, R0 - delta.
  double radius(double Fz) const { return tyre().unloadedRadius - Fz / tyre().verticalStiffness; }
  // The lever of the longitudinal force about the wheel centre: the tyre
  // applies its force at R0 - 2 delta below the centre, as the reference
  // does (tyre/fiala.cpp), so a drive torque T gives Fx = T / (R0 - 2 delta).
  double lever(double Fz) const { return tyre().unloadedRadius - 2 * Fz / tyre().verticalStiffness; }
  // The speed at which the idle governor's torque meets a load torque at the crank.
  double governedSpeed(double load) const {
    const vehicle::EngineSpec& e = pt.engine;
    double w = e.idleSpeed;
    for (int i = 0; i < 50; ++i)
      w = e.idleSpeed - e.governorBand * (vehicle::engineFriction(e, w) + load) / vehicle::fullLoadTorque(e, w);
    return w;
  }
};

// The rear axle's static load, from the sheet's numbers (the test reads it
// from the simulation at rest, as the hand calculation would from a scale).
double rearLoad(scenario::Simulation& sim) {
  vehicle::VehicleSample s = sim.sample();
  return s.Fz[2] + s.Fz[3];
}

}  // namespace

// In neutral (the automatic clutch open at idle: the car held in first with
// no throttle is the same), the governor holds the engine where its torque
// meets the friction: idle - band x friction / full load.
TEST(Powertrain, TheGovernorHoldsIdleWithTheClutchOpen) {
  const Car car;
  scenario::Simulation sim(driveSpec(0.0));
  sim.prepare();
  scenario::DriverInput in;
  in.brake = 1.0;
  drive(sim, in, 3.0);
  const double expected = car.governedSpeed(0.0);
  EXPECT_NEAR(sim.powertrainChannels().engineRpm, expected / kRpm, 0.5);
  EXPECT_LT(sim.powertrainChannels().clutch, 1e-9);
  EXPECT_NEAR(sim.sample().vx, 0.0, 1e-3);
  // The hand figure is below idle by the droop, not at idle.
  EXPECT_GT(car.pt.engine.idleSpeed - expected, 5 * kRpm);
}

// Clutch pedal up in first, no throttle: the governor carries the rolling
// resistance too, and the car creeps at the speed the governed engine speed
// gives through the gears: v = w R / G.
TEST(Powertrain, TheEngineHeldAtIdleWithTheClutchOutCreepsInFirst) {
  const Car car;
  scenario::Simulation sim(driveSpec(0.0));
  sim.prepare();
  const double Fz = sim.sample().Fz[0] + sim.sample().Fz[1] + rearLoad(sim);
  scenario::DriverInput in;
  in.clutchPedal = true;
  in.clutch = 1.0;
  drive(sim, in, 0.5);  // pedal down, first gear
  for (int i = 0; i < 100; ++i) {
    in.clutch = 1.0 - 0.01 * i;  // let it up over a second
    drive(sim, in, 0.01);
  }
  in.clutch = 0.0;
  drive(sim, in, 15.0);
  const double G = car.pt.gearbox.overall(1);
  const double R = car.radius(0.25 * Fz);
  // The load at the crank: each tyre's rolling resistance moment rr Fz (tyre/fiala.h), through the gears.
  const double load = car.tyre().rollingResistance * Fz / G;
  const double w = car.governedSpeed(load);
  const scenario::PowertrainChannels pt = sim.powertrainChannels();
  EXPECT_EQ(pt.gear, 1);
  EXPECT_NEAR(pt.engineRpm, w / kRpm, 1.0);
  EXPECT_NEAR(sim.sample().vx, w * R / G, 0.01 * w * R / G);
}

// Full throttle in top gear: the speed where the engine's torque through the
// gears meets drag and the tyres' rolling resistance (lift unloading the
// tyres), approached from 3 % below and 3 % above. Per wheel: the tyre force
// is (drive torque - rolling resistance moment) / lever; summed over the car
// it meets the drag.
TEST(Powertrain, TopSpeedIsWherePowerMeetsDragAndRollingResistance) {
  const Car car;
  const vehicle::GearboxSpec& g = car.pt.gearbox;
  const double G = g.overall(g.gears());
  const double weight = car.mass() * kG;
  const double kx = car.tyre().slipStiffness;
  auto excess = [&](double v) {
    const double lift = (car.spec.liftAreaFront + car.spec.liftAreaRear) * v * v;
    const double Fz = weight - lift;
    const double R = car.radius(0.25 * Fz), lever = car.lever(0.25 * Fz);  // near enough for both axles at speed
    const double drag = car.spec.dragArea * v * v;
    const double slip = 0.5 * drag / kx;     // the rear tyres' longitudinal slip (the drag on two tyres)
    const double w = G * v / R * (1 + slip);
    return (vehicle::engineTorque(car.pt.engine, w, 1.0) * G - car.tyre().rollingResistance * Fz) / lever - drag;
  };
  double lo = 30, hi = 120;
  for (int i = 0; i < 60; ++i) (excess(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
  const double vmax = 0.5 * (lo + hi);
  // In top gear (no shift) and below the rev limit: a power limit, not a gearing one.
  ASSERT_LT(G * vmax / car.radius(0.25 * weight), car.pt.engine.revLimit);
  for (double start : {0.97 * vmax, 1.03 * vmax}) {
    scenario::Simulation sim(driveSpec(start));
    sim.prepare();
    ASSERT_EQ(sim.transmission()->state().gear, g.gears());
    scenario::DriverInput in;
    in.throttle = 1.0;
    drive(sim, in, 90.0);
    EXPECT_EQ(sim.transmission()->state().gear, g.gears());
    EXPECT_NEAR(sim.sample().vx, vmax, 0.005 * vmax) << "from " << start << " m/s";
  }
}

// Full throttle from rest in the automatic box: each upshift starts where the
// gear turns the engine at the full-throttle upshift speed, v = w_up R /
// (G_k (1 + slip)), R the rear tyres' rolling radius under their load then,
// with the engine locked to the wheels through the closed clutch at w_up;
// gear after gear, never back (the engine lands above the downshift speed).
// Then, coasting with the throttle closed,
// the box shifts down where the gear turns the engine at the downshift speed.
TEST(Powertrain, TheScheduleShiftsAtTheSpeedsTheGearsGive) {
  const Car car;
  const vehicle::GearboxSpec& g = car.pt.gearbox;
  scenario::Simulation sim(driveSpec(0.0));
  sim.prepare();
  scenario::DriverInput in;
  in.throttle = 1.0;
  struct Shift {
    int from = 0;
    double vx = 0, kappa = 0, Fz = 0, engine = 0;
  };
  std::vector<Shift> ups;
  bool was = false;
  // The engine at the tick before a shift began: the last the schedule read
  // with the clutch locked (within the shift's first tick the clutch opens
  // and the engine falls, 1.2 % by its end in a run converged at 1 ms).
  double engineBefore = 0;
  drive(sim, in, 25.0, [&](scenario::Simulation& s) {
    const bool now = s.transmission()->shifting();
    if (now && !was) {
      const vehicle::VehicleSample v = s.sample();
      ups.push_back({s.transmission()->state().gear, v.vx, 0.5 * (v.kappa[2] + v.kappa[3]), 0.5 * (v.Fz[2] + v.Fz[3]),
                     engineBefore});
    }
    was = now;
    engineBefore = s.powertrainChannels().engineRpm * kRpm;
  });
  ASSERT_GE(ups.size(), 3u);
  for (std::size_t i = 0; i < ups.size(); ++i) EXPECT_EQ(ups[i].from, static_cast<int>(i) + 1);
  for (const Shift& u : ups) {
    const double expected = g.upshiftSpeed * car.radius(u.Fz) / (g.overall(u.from) * (1 + u.kappa));
    EXPECT_NEAR(u.vx, expected, 0.01 * expected) << "upshift from gear " << u.from;
    // The schedule reads the speed the gear gives the engine: locked, that is the engine's.
    EXPECT_NEAR(u.engine, g.upshiftSpeed, 0.01 * g.upshiftSpeed) << "upshift from gear " << u.from;
  }
  // Coast down: the first downshift begins at the downshift speed.
  in.throttle = 0.0;
  in.brake = 0.15;
  const int top = sim.transmission()->state().gear;
  double vDown = -1;
  drive(sim, in, 20.0, [&](scenario::Simulation& s) {
    if (vDown < 0 && s.transmission()->shifting() && s.transmission()->state().nextGear == top - 1)
      vDown = s.sample().vx;
  });
  const double expected = g.downshiftSpeed * car.radius(0.5 * rearLoad(sim)) / g.overall(top);
  EXPECT_NEAR(vDown, expected, 0.01 * expected);
}

// A manual box does not shift by itself: full throttle in first ends at the
// rev limiter, v = w_limit R / G_1 (the fuel cut acts over 1 % above it).
TEST(Powertrain, AManualBoxRunsToTheRevLimiterInFirst) {
  const Car car;
  scenario::Simulation sim(driveSpec(0.0, {"powertrain.gearbox.mode=manual"}));
  sim.prepare();
  const double R = car.radius(0.5 * rearLoad(sim));
  scenario::DriverInput in;
  in.throttle = 1.0;
  drive(sim, in, 8.0);
  const double limit = car.pt.engine.revLimit;
  const scenario::PowertrainChannels pt = sim.powertrainChannels();
  EXPECT_EQ(pt.gear, 1);
  EXPECT_GT(pt.engineRpm * kRpm, limit);
  EXPECT_LT(pt.engineRpm * kRpm, 1.01 * limit);
  const double v = limit * R / car.pt.gearbox.overall(1);
  EXPECT_NEAR(sim.sample().vx, v, 0.02 * v);
  // Shifting up by hand: second gear.
  in.shift = 1;
  drive(sim, in, 1.0);
  EXPECT_EQ(sim.powertrainChannels().gear, 2);
}

// Reverse: refused while rolling forwards, engaged at rest; the car backs
// up, the engine driving it through the clutch (the clutch's slip and
// torque positive: the engine turns faster than the gearbox input, which
// turns at G_R x the wheels' negative spin).
TEST(Powertrain, ReverseIsEngagedAtRestAndBacksTheCarUp) {
  const Car car;
  scenario::Simulation rolling(driveSpec(5.0));
  rolling.prepare();
  scenario::DriverInput in;
  in.shift = -1;
  drive(rolling, in, 1.0);
  EXPECT_GE(rolling.transmission()->state().gear, 1);

  scenario::Simulation sim(driveSpec(0.0));
  sim.prepare();
  in.shift = -1;
  drive(sim, in, 0.5);
  EXPECT_EQ(sim.transmission()->state().gear, -1);
  in.throttle = 0.3;
  drive(sim, in, 4.0);
  const vehicle::VehicleSample s = sim.sample();
  EXPECT_LT(s.vx, -1.0);
  const double wheels = 0.5 * (s.spinRate[2] + s.spinRate[3]);
  EXPECT_LT(wheels, 0.0);
  const scenario::PowertrainChannels pt = sim.powertrainChannels();
  const double input = car.pt.gearbox.overall(-1) * wheels;
  EXPECT_GT(input, 0.0);
  EXPECT_NEAR(pt.clutchSlipRpm * kRpm, pt.engineRpm * kRpm - input, 1e-6 * input);
  EXPECT_GT(pt.clutchSlipRpm, 0.0);
  EXPECT_GT(pt.clutchTorque, 0.0);
}

// On the 10 % slope, facing uphill, the handbrake holds the car when its
// two rear wheels' torque exceeds m g sin(theta) R, and the car rolls back
// when it does not.
TEST(Powertrain, TheHandbrakeHoldsOnTheSlopeAboveTheTorqueTheSlopeNeeds) {
  const Car car;
  const double theta = std::atan(0.1);
  const double needed = car.mass() * kG * std::sin(theta) * car.radius(0.25 * car.mass() * kG) / 2;  // N m per rear wheel
  for (double torque : {1.5 * needed, 0.8 * needed}) {
    scenario::Simulation sim(
        driveSpec(0.0, {"powertrain.handbrake_torque=" + std::to_string(torque)}, "slope10.toml"));
    scenario::DriverInput in;
    in.brake = 1.0;
    in.handbrake = 1.0;
    sim.prepare();
    drive(sim, in, 1.0);  // held by the foot brake, handbrake pulled
    in.brake = 0.0;
    const double x0 = sim.sample().com.x();
    drive(sim, in, 4.0);
    const double moved = sim.sample().com.x() - x0;
    if (torque > needed) {
      EXPECT_NEAR(moved, 0.0, 0.01) << torque << " N m";
      EXPECT_NEAR(sim.sample().vx, 0.0, 1e-3);
    } else {
      EXPECT_LT(moved, -0.5) << torque << " N m";  // rolled back down the slope
    }
  }
}

// ---------------------------------------------------------------------------
// The proving ground (assets/terrain/proving_ground.toml), driven.

namespace {

// A driver's input held tick by tick until `done` or `seconds` have passed; false on the time limit.
bool driveUntil(scenario::Simulation& sim, scenario::DriverInput in, double seconds,
                const std::function<bool(scenario::Simulation&)>& done) {
  const long ticks = std::lround(seconds / sim.spec().tick);
  for (long i = 0; i < ticks; ++i) {
    drive(sim, in, sim.spec().tick);
    in.shift = 0;
    if (done(sim)) return true;
  }
  return false;
}

// Distance from p to the closed polyline.
double distanceToLoop(const std::vector<Eigen::Vector2d>& loop, const Eigen::Vector2d& p) {
  double best = 1e300;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector2d a = loop[i], b = loop[(i + 1) % loop.size()];
    const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + t * (b - a) - p).norm());
  }
  return best;
}

}  // namespace

// A person's drive with a manual box on the circuit's main straight: pull
// away in first, shift up by hand at 5500 rpm to third, down to second (the
// engine speed per road speed then rises by the ratio of the two gears, read
// from the file), stop, select reverse and back up.
TEST(ProvingGround, ADriverPullsAwayShiftsUpAndDownStopsAndReverses) {
  const Car car;
  scenario::ScenarioSpec spec = driveSpec(0.0, {"powertrain.gearbox.mode=manual"}, "proving_ground.toml");
  spec.startX = 5.0;
  scenario::Simulation sim(spec);
  sim.prepare();
  auto gear = [&] { return sim.powertrainChannels().gear; };
  EXPECT_EQ(gear(), 1);
  scenario::DriverInput in;
  in.throttle = 0.7;
  for (int target : {2, 3}) {
    ASSERT_TRUE(driveUntil(sim, in, 15.0, [](scenario::Simulation& s) { return s.powertrainChannels().engineRpm > 5500; }));
    in.shift = 1;
    drive(sim, in, 0.01);
    in.shift = 0;
    ASSERT_TRUE(driveUntil(sim, in, 2.0, [&](scenario::Simulation&) { return gear() == target; }));
  }
  // Cruise in third, then second: engine turns per metre travelled go up by r2 / r3.
  in.throttle = 0.25;
  drive(sim, in, 2.0);
  const double perMetre3 = sim.powertrainChannels().engineRpm / sim.sample().vx;
  in.shift = -1;
  drive(sim, in, 0.01);
  in.shift = 0;
  drive(sim, in, 1.5);
  ASSERT_EQ(gear(), 2);
  EXPECT_LT(std::abs(sim.powertrainChannels().clutchSlipRpm), 1.0);  // the clutch has closed
  const double perMetre2 = sim.powertrainChannels().engineRpm / sim.sample().vx;
  const vehicle::GearboxSpec& box = car.pt.gearbox;
  EXPECT_NEAR(perMetre2 / perMetre3, box.overall(2) / box.overall(3), 0.01 * box.overall(2) / box.overall(3));
  // Stop, then down through first and neutral (a manual box does not skip
  // it) into reverse, and back up.
  in.throttle = 0.0;
  in.brake = 0.7;
  ASSERT_TRUE(driveUntil(sim, in, 20.0, [](scenario::Simulation& s) { return std::abs(s.sample().vx) < 0.01; }));
  for (int target : {1, 0, -1}) {
    in.shift = -1;
    drive(sim, in, 0.01);
    in.shift = 0;
    drive(sim, in, 0.6);
    EXPECT_EQ(gear(), target);
  }
  const double x0 = sim.sample().com.x();
  in.brake = 0.0;
  in.throttle = 0.3;
  drive(sim, in, 3.0);
  EXPECT_LT(sim.sample().vx, -1.0);
  EXPECT_LT(sim.sample().com.x(), x0 - 1.0);
}

// The automatic box up the proving ground's 10 % concrete slope: drive onto
// its face, stop with the foot brake, pull the handbrake and let the brake
// go: the car stands, pitched by the slope's angle (the hill is a piece of
// the ground, not a plane: its face is what the tyres read); the handbrake
// released, it rolls back.
TEST(ProvingGround, TheHandbrakeHoldsTheCarOnTheSlope) {
  scenario::ScenarioSpec spec = driveSpec(0.0, {}, "proving_ground.toml");
  spec.startX = 603.0;  // on the hill's flat approach, 17 m before its face (x = 620 .. 650)
  spec.startY = -60.0;
  scenario::Simulation sim(spec);
  sim.prepare();
  scenario::DriverInput in;
  in.throttle = 0.35;
  ASSERT_TRUE(driveUntil(sim, in, 30.0, [](scenario::Simulation& s) { return s.sample().com.x() > 635.0; }));
  in.throttle = 0.0;
  in.brake = 1.0;
  ASSERT_TRUE(driveUntil(sim, in, 10.0, [](scenario::Simulation& s) { return std::abs(s.sample().vx) < 0.01; }));
  in.handbrake = 1.0;
  drive(sim, in, 0.5);
  in.brake = 0.0;
  const Eigen::Vector3d held = sim.sample().com;
  drive(sim, in, 4.0);
  EXPECT_LT((sim.sample().com - held).norm(), 0.01);
  EXPECT_GT(held.z(), 1.5);  // up the face: 15 m along it is 1.5 m up
  // Held on the analytic 10 % plane (slope10.toml) the same way, the car
  // pitches as much: the hill's face is that plane, seen through Bullet.
  scenario::Simulation plane(driveSpec(0.0, {}, "slope10.toml"));
  plane.prepare();
  scenario::DriverInput hold;
  hold.brake = 1.0;
  hold.handbrake = 1.0;
  drive(plane, hold, 0.5);
  hold.brake = 0.0;
  drive(plane, hold, 4.0);
  EXPECT_NEAR(sim.sample().pitch, plane.sample().pitch, 1e-3);
  in.handbrake = 0.0;
  drive(sim, in, 3.0);
  EXPECT_LT(sim.sample().vx, -0.3);
}

// The shipped lap (assets/scenarios/proving_ground/circuit_lap.toml): from
// a standstill on the start line, the path follower and the automatic box
// take the car round the whole circuit on its asphalt: it comes within 3 m
// of every point of the centre line (the whole lap is driven) and is never
// more than 3 m off it (the asphalt reaches 6 m either side and the car is
// 1.8 m wide: 2 m to spare, for a look-ahead driver that cuts corners), and
// the box went up through first and second into third.
TEST(ProvingGround, TheDriverLapsTheCircuitFromAStandstillOnItsAsphalt) {
  const scenario::ScenarioSpec spec =
      scenario::loadScenarioFile(asset("scenarios/proving_ground/circuit_lap.toml"));
  terrain::WorldCentreLine line;
  ASSERT_TRUE(terrain::findCentreLine(terrain::loadTerrain(spec.terrainFile), "circuit", line));
  scenario::Simulation sim(spec);
  std::vector<int> gears;
  double worst = 0;
  scenario::RunOptions o;
  o.onSample = [&](const vehicle::VehicleSample& s) {
    const int g = sim.powertrainChannels().gear;
    if (gears.empty() || gears.back() != g) gears.push_back(g);
    worst = std::max(worst, distanceToLoop(line.points, s.com.head<2>()));
  };
  const scenario::RunResult r = scenario::runScenario(sim, o);
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_LT(worst, 3.0);
  for (std::size_t i = 0; i < line.points.size(); i += 10) {
    double nearest = 1e300;
    for (const vehicle::VehicleSample& s : r.samples) nearest = std::min(nearest, (s.com.head<2>() - line.points[i]).norm());
    EXPECT_LT(nearest, 3.0) << "centre-line point " << i << " at (" << line.points[i].transpose() << ")";
  }
  ASSERT_GE(gears.size(), 3u);
  EXPECT_EQ(gears[0], 1);
  EXPECT_EQ(gears[1], 2);
  EXPECT_EQ(gears[2], 3);
}
