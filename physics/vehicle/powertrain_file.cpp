#include "vehicle/powertrain_file.h"

#include <cmath>

#include "config/range.h"
#include "config/units.h"
#include "vehicle/powertrain.h"

namespace bdfcar::vehicle {

namespace {

using config::Dimension;
using config::Range;
using config::Table;

constexpr double kRpm = 2.0 * M_PI / 60.0;  // rad/s per rpm (the torque curve's first column)

const Range kEngineSpeed{0.0, 2500.0, true, false};    // rad/s (~24,000 rpm)
const Range kCurveRpm{0.0, 25000.0};                   // rpm, the torque curve's speeds
const Range kCurveTorque{0.0, 1e5};                    // N m
const Range kEngineInertia{0.0, 100.0, true, false};   // kg m^2 (> 0: the crank is a state)
const Range kFrictionTorque{0.0, 1e4};                 // N m
const Range kFrictionSlope{0.0, 100.0};                // N m s/rad
const Range kClutchTorque{0.0, 1e5, true, false};      // N m
const Range kClutchStiffness{0.0, 1e7, true, false};   // N m/rad
const Range kClutchDamping{0.0, 1e5};                  // N m s/rad
const Range kShiftTime{0.0, 5.0, true, false};         // s
const Range kRatio{0.0, 50.0, true, false};
const Range kCoupling{0.0, 1e5};                       // N m s/rad
const Range kHandbrake{0.0, 1e6};                      // N m

EngineSpec readEngine(Table& t) {
  EngineSpec e;
  const std::vector<std::vector<double>> curve = t.grid("torque_curve", 2, 2);
  for (std::size_t i = 0; i < curve.size(); ++i) {
    t.require(curve[i].size() == 2 && kCurveRpm.contains(curve[i][0]) && kCurveTorque.contains(curve[i][1]),
              "torque_curve", "rows [engine speed in rpm " + kCurveRpm.text() + ", full-load torque in N m " + kCurveTorque.text() + "]");
    t.require(i == 0 || curve[i][0] > curve[i - 1][0], "torque_curve", "engine speeds (rpm) increasing from row to row");
    e.speed.push_back(curve[i][0] * kRpm);
    e.torque.push_back(curve[i][1]);
  }
  e.idleSpeed = t.number("idle_speed", Dimension::AngularSpeed, kEngineSpeed);
  e.revLimit = t.number("rev_limit", Dimension::AngularSpeed, kEngineSpeed);
  t.require(e.revLimit > e.idleSpeed, "rev_limit", "an engine speed above idle_speed");
  e.inertia = t.number("inertia", Dimension::Inertia, kEngineInertia);
  e.friction = t.number("friction", Dimension::Torque, kFrictionTorque, 0.0);
  e.frictionSlope = t.numberIn("friction_slope", kFrictionSlope, 0.0);
  e.governorBand = t.number("governor_band", Dimension::AngularSpeed, kEngineSpeed, 100.0 * kRpm);
  t.require(fullLoadTorque(e, e.idleSpeed) > e.friction + e.frictionSlope * e.idleSpeed, "torque_curve",
            "more full-load torque at idle_speed than the friction there (or the engine cannot idle)");
  t.finish();
  return e;
}

ClutchSpec readClutch(Table& t, const EngineSpec& e) {
  ClutchSpec c;
  c.maxTorque = t.number("max_torque", Dimension::Torque, kClutchTorque);
  c.stiffness = t.number("stiffness", Dimension::AngularStiffness, kClutchStiffness);
  c.damping = t.numberIn("damping", kClutchDamping, 0.0);
  c.launchSpeed = t.number("launch_speed", Dimension::AngularSpeed, kEngineSpeed);
  t.require(c.launchSpeed > e.idleSpeed * 1.05 && c.launchSpeed < e.revLimit, "launch_speed",
            "an engine speed between 5 % above idle_speed and rev_limit");
  c.shiftTime = t.number("shift_time", Dimension::Time, kShiftTime);
  t.finish();
  return c;
}

GearboxSpec readGearbox(Table& t, const EngineSpec& e, const ClutchSpec& c) {
  GearboxSpec g;
  g.ratios = t.numbers("ratios", Dimension::None, kRatio);
  t.require(!g.ratios.empty(), "ratios", "at least one forward gear");
  for (std::size_t i = 1; i < g.ratios.size(); ++i)
    t.require(g.ratios[i] < g.ratios[i - 1], "ratios", "ratios decreasing from first gear up");
  g.reverse = t.numberIn("reverse", kRatio);
  g.finalDrive = t.numberIn("final_drive", kRatio);
  g.automatic = t.choice("mode", {"automatic", "manual"}) == "automatic";
  g.upshiftSpeed = t.number("upshift_speed", Dimension::AngularSpeed, kEngineSpeed);
  g.upshiftSpeedLight = t.number("upshift_speed_light", Dimension::AngularSpeed, kEngineSpeed, g.upshiftSpeed);
  g.downshiftSpeed = t.number("downshift_speed", Dimension::AngularSpeed, kEngineSpeed);
  t.require(g.upshiftSpeed <= e.revLimit, "upshift_speed", "an engine speed at most rev_limit");
  t.require(g.upshiftSpeedLight <= g.upshiftSpeed && g.upshiftSpeedLight >= c.launchSpeed, "upshift_speed_light",
            "an engine speed between the clutch's launch_speed and upshift_speed");
  t.require(g.downshiftSpeed > e.idleSpeed, "downshift_speed", "an engine speed above idle_speed");
  // After an upshift the engine lands at (next ratio / this ratio) of the
  // upshift speed: above the downshift speed, or the box would hunt.
  for (std::size_t i = 1; i < g.ratios.size(); ++i) {
    const double landing = g.upshiftSpeedLight * g.ratios[i] / g.ratios[i - 1];
    t.require(landing > g.downshiftSpeed, "downshift_speed",
              "an engine speed below where an upshift lands (" + config::formatNumber(landing / kRpm) + " rpm from gear " +
                  std::to_string(i) + " to " + std::to_string(i + 1) + " at upshift_speed_light)");
  }
  t.finish();
  return g;
}

}  // namespace

PowertrainSpec readPowertrain(Table& t) {
  PowertrainSpec p;
  Table engine = t.table("engine");
  p.engine = readEngine(engine);
  Table clutch = t.table("clutch");
  p.clutch = readClutch(clutch, p.engine);
  Table gearbox = t.table("gearbox");
  p.gearbox = readGearbox(gearbox, p.engine, p.clutch);
  if (auto d = t.optionalTable("differential")) {
    p.viscousCoupling = d->numberIn("viscous_coupling", kCoupling, 0.0);
    d->finish();
  }
  p.handbrakeTorque = t.number("handbrake_torque", Dimension::Torque, kHandbrake, 0.0);
  t.finish();
  return p;
}

}  // namespace bdfcar::vehicle
