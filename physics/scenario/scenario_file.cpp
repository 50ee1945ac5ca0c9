#include <cmath>
#include <filesystem>

#include "config/toml_reader.h"
#include "scenario/scenario_spec.h"

namespace bdfcar::scenario {

using config::Dimension;
using config::Table;

namespace {

std::string resolveAsset(Table& t, const std::string& key, const std::string& scenarioFile) {
  const std::filesystem::path rel = t.string(key);
  const std::filesystem::path p =
      rel.is_absolute() ? rel : (std::filesystem::path(scenarioFile).parent_path() / rel).lexically_normal();
  if (!std::filesystem::exists(p)) t.fail("the file '" + p.string() + "' does not exist", key);
  return p.string();
}

SignalSpec readSignal(Table t, double lo, double hi) {
  SignalSpec s;
  const std::string type = t.string("type");
  auto level = [&](const char* key) {
    const double v = t.number(key);
    t.require(v >= lo && v <= hi, key, "a value in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v;
  };
  if (type == "none") {
    s.kind = SignalSpec::Kind::None;
  } else if (type == "constant") {
    s.kind = SignalSpec::Kind::Constant;
    s.level = level("level");
  } else if (type == "ramp") {
    s.kind = SignalSpec::Kind::Ramp;
    s.start = t.number("start", Dimension::Time);
    s.duration = t.number("duration", Dimension::Time);
    t.require(s.duration > 0, "duration", "a positive ramp duration (s)");
    s.level = level("level");
  } else if (type == "sine") {
    s.kind = SignalSpec::Kind::Sine;
    s.start = t.number("start", Dimension::Time);
    s.duration = t.number("period", Dimension::Time);
    t.require(s.duration > 0, "period", "a positive period (s)");
    s.level = level("amplitude");
  } else if (type == "table") {
    s.kind = SignalSpec::Kind::Table;
    s.times = t.numbers("times", Dimension::Time);
    s.values = t.numbers("values");
    t.require(s.times.size() == s.values.size() && !s.times.empty(), "values", "as many values as times");
    for (size_t i = 1; i < s.times.size(); ++i) t.require(s.times[i] > s.times[i - 1], "times", "increasing times");
    for (double v : s.values) t.require(v >= lo && v <= hi, "values", "values in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  } else {
    t.fail("unknown signal type '" + type + "': expected none, constant, ramp, sine or table", "type");
  }
  t.finish();
  return s;
}

}  // namespace

int stepsPerTick(double tick, double step) {
  if (!(tick > 0) || !(step > 0)) return 0;
  const double n = std::round(tick / step);
  return n >= 1 && n <= 1e6 && std::abs(n * step - tick) <= 1e-9 * tick ? static_cast<int>(n) : 0;
}

ScenarioSpec loadScenarioFile(const std::string& path) {
  Table root = config::parseTomlFile(path);
  ScenarioSpec s;
  s.sourceFile = path;
  Table sc = root.table("scenario");
  s.name = sc.string("name");
  s.vehicleFile = resolveAsset(sc, "vehicle", path);
  if (sc.has("terrain")) s.terrainFile = resolveAsset(sc, "terrain", path);
  s.duration = sc.number("duration", Dimension::Time);
  sc.require(s.duration > 0 && s.duration < 1e6, "duration", "a positive duration (s)");
  s.outputInterval = sc.number("output_interval", Dimension::Time, s.outputInterval);
  sc.require(s.outputInterval > 0, "output_interval", "a positive interval (s)");
  s.tick = sc.number("tick", Dimension::Time, s.tick);
  sc.require(s.tick >= 1e-3 && s.tick <= 0.1, "tick", "a driver tick in [1, 100] ms");
  s.raysPerWheel = static_cast<int>(sc.integer("rays_per_wheel", 1));
  sc.require(s.raysPerWheel >= 1 && s.raysPerWheel <= 15, "rays_per_wheel", "1 to 15 rays");
  sc.finish();

  if (auto st = root.optionalTable("start")) {
    s.initialSpeed = st->number("speed", Dimension::Speed, 0.0);
    st->require(s.initialSpeed >= 0 && s.initialSpeed < 150, "speed", "a speed in [0, 540 km/h)");
    s.settleTime = st->number("settle", Dimension::Time, 0.0);
    st->require(s.settleTime >= 0, "settle", "a non-negative settling time (s)");
    if (st->has("position")) {
      const std::vector<double> p = st->numbers("position", Dimension::Length);
      st->require(p.size() == 2, "position", "[x, y] (m)");
      s.startX = p[0];
      s.startY = p[1];
    }
    s.startHeading = st->number("heading", Dimension::Angle, 0.0);
    st->finish();
  }
  if (auto it = root.optionalTable("integrator")) {
    IntegratorSpec& i = s.integrator;
    integ::BdfOptions& b = i.bdf;
    const std::string m = it->string("method", "bdf");
    if (m == "bdf") i.method = IntegratorMethod::Bdf;
    else if (m == "rk4") i.method = IntegratorMethod::Rk4;
    else if (m == "euler") i.method = IntegratorMethod::SemiImplicitEuler;
    else it->fail("unknown method '" + m + "': expected bdf, rk4 or euler", "method");
    i.step = it->number("step", Dimension::Time, i.step);
    it->require(i.step > 0 && i.step <= 0.1, "step", "a step in (0, 0.1] s");
    it->require(stepsPerTick(s.tick, i.step) > 0, "step",
                "a step that divides the driver's tick of " + std::to_string(s.tick * 1e3) +
                    " ms (a whole number of steps per tick)");
    b.order = static_cast<int>(it->integer("order", b.order));
    it->require(b.order >= 1 && b.order <= 5, "order", "a BDF order from 1 to 5");
    b.newtonIterations = static_cast<int>(it->integer("newton_iterations", b.newtonIterations));
    it->require(b.newtonIterations >= 0 && b.newtonIterations <= 50, "newton_iterations", "0 (to tolerance) to 50");
    b.jacobianEvery = static_cast<int>(it->integer("jacobian_every", b.jacobianEvery));
    it->require(b.jacobianEvery >= 0, "jacobian_every", "0 (first step only) or a positive number of steps");
    b.refreshWhenNotContracting = it->boolean("refresh_when_not_contracting", b.refreshWhenNotContracting);
    b.atol = it->number("atol", Dimension::None, b.atol);
    b.rtol = it->number("rtol", Dimension::None, b.rtol);
    it->require(b.atol > 0 && b.rtol >= 0, "atol", "positive tolerances");
    it->finish();
  }
  if (auto t = root.optionalTable("steering")) s.steering = readSignal(*t, -1.0, 1.0);
  if (auto t = root.optionalTable("throttle")) s.throttle = readSignal(*t, 0.0, 1.0);
  if (auto t = root.optionalTable("brake")) s.brake = readSignal(*t, 0.0, 1.0);
  if (auto sp = root.optionalTable("speed_control")) {
    s.speedControl.enabled = true;
    s.speedControl.target = sp->number("target", Dimension::Speed);
    s.speedControl.kp = sp->number("kp", Dimension::TorqueRate, s.speedControl.kp);
    s.speedControl.ki = sp->number("ki", Dimension::None, s.speedControl.ki);
    sp->require(s.speedControl.kp >= 0 && s.speedControl.ki >= 0, "kp", "non-negative gains");
    sp->finish();
  }
  if (auto c = root.optionalTable("course")) {
    const std::string type = c->string("type");
    if (type != "iso3888") c->fail("unknown course '" + type + "': expected iso3888", "type");
    s.course.iso3888 = true;
    s.course.startX = c->number("start_x", Dimension::Length, s.course.startX);
    c->finish();
  }
  if (auto d = root.optionalTable("driver")) {
    const std::string type = d->string("type");
    if (type != "path_follower") d->fail("unknown driver '" + type + "': expected path_follower", "type");
    s.pathFollower.enabled = true;
    s.pathFollower.lookAheadTime = d->number("look_ahead_time", Dimension::Time, s.pathFollower.lookAheadTime);
    s.pathFollower.minLookAhead = d->number("min_look_ahead", Dimension::Length, s.pathFollower.minLookAhead);
    d->finish();
    if (!s.course.iso3888) root.fail("a path_follower driver needs a [course] to follow", "driver");
    if (s.steering.kind != SignalSpec::Kind::None) root.fail("give either [steering] or a path_follower [driver], not both", "driver");
  }
  root.finish();
  return s;
}

}  // namespace bdfcar::scenario
