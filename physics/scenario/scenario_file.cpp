#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <fstream>
#include <sstream>

#include "config/toml_reader.h"
#include "config/input_files.h"
#include "config/line_reader.h"
#include "config/file_kind.h"
#include "scenario/scenario_spec.h"
#include "terrain/terrain_file.h"
#include "vehicle/ladder.h"
#include "vehicle/motion_ratio.h"

namespace bdfcar::scenario {

using config::Dimension;
using config::Range;
using config::Table;

namespace {

// Ranges the scenario loader enforces (docs/INPUT-CHECKS.md); where the CLI
// overrides the same setting (app/scenario_overrides.cpp) the bounds are its.
const Range kDuration{1e-3, 1e6};                  // s (--duration)
const Range kSettle{0.0, 1e4};                     // s (--settle)
const Range kStep{1e-6, 0.1};                      // s (--step)
const Range kTick{1e-3, 0.1};                      // s (--tick)
const Range kOutputInterval{0.0, 1e6, true, true}; // s
const Range kErrorBudget{0.0, 1.0, true, false};   // fraction of peak ("5 %")
const Range kFrequency{0.0, 1e3};                  // Hz (a chirp's ends)
const Range kSpeed{0.0, 150.0, false, true};       // m/s (540 km/h)
const Range kPosition{-1e6, 1e6};                  // m
const Range kHeading{-1e3, 1e3};                   // rad
const Range kTime{-1e6, 1e6};                      // s, signal times
const Range kSpan{0.0, 1e6, true, false};          // s, ramp durations and periods
const Range kTolerance{0.0, 1.0, true, false};
const Range kGain{0.0, 1e6};                       // speed-hold gains
const Range kLookAheadTime{0.0, 100.0, true, false};  // s
const Range kLookAhead{0.0, 1e3, true, false};        // m

// A file the scenario names, relative to the file that names it: it must be a regular
// file (an empty name or a folder would be read as one).
std::string resolveAsset(Table& t, const std::string& key) {
  const std::filesystem::path rel = t.string(key);
  if (rel.empty()) t.fail("expected a file name, got \"\"", key);
  const std::filesystem::path p = rel.is_absolute() ? rel : (std::filesystem::path(t.folderOf(key)) / rel).lexically_normal();
  if (const auto why = config::notARegularFile(p)) t.fail("the file '" + p.string() + "' " + *why, key);
  return p.string();
}

// Columns of a CSV file named by `fileKey` (a header line of names, then
// rows of numbers), each column given as (its name, the key that named it);
// errors name the table's key, or the CSV's own file and line.
std::vector<std::vector<double>> readCsvColumns(Table& t, const std::string& fileKey,
                                                const std::vector<std::pair<std::string, std::string>>& columns,
                                                std::string& path) {
  const std::filesystem::path rel = t.string(fileKey);
  const std::filesystem::path p = rel.is_absolute() ? rel : std::filesystem::path(t.folderOf(fileKey)) / rel;
  path = p.string();
  std::optional<config::LineReader> in;
  try {
    in.emplace(path, "CSV file", config::kCsvLines);
  } catch (const std::runtime_error& e) {
    t.fail(std::string("cannot read the CSV file: ") + e.what(), fileKey);
  }
  config::noteInputFile(path);
  auto next = [&](std::string& text) {
    try {
      return in->next(text);
    } catch (const std::runtime_error& e) {  // a limit of config::LineReader, with the CSV's file and line
      throw config::ConfigError(e.what());
    }
  };
  std::string line;
  next(line);
  std::vector<std::string> names;
  for (std::stringstream ss(line); std::getline(ss, line, ',');) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    names.push_back(line);
  }
  std::vector<std::size_t> index;
  for (const auto& [name, key] : columns) {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) t.fail("the CSV file '" + path + "' has no column '" + name + "'", key);
    index.push_back(static_cast<std::size_t>(it - names.begin()));
  }
  std::vector<std::vector<double>> out(columns.size());
  while (next(line)) {
    const long row = in->lineNumber();
    if (line.empty() || line == "\r") continue;
    std::vector<std::string> f;
    for (std::stringstream ss(line); std::getline(ss, line, ',');) f.push_back(line);
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const std::size_t i = index[c];
      char* end = nullptr;
      const double x = i < f.size() ? std::strtod(f[i].c_str(), &end) : std::nan("");
      if (i >= f.size() || end == f[i].c_str() || !std::isfinite(x))
        throw config::ConfigError(path + ":" + std::to_string(row) + ": column '" + columns[c].first +
                                  "': expected a finite number" + (i < f.size() ? ", got \"" + f[i] + "\"" : ""));
      out[c].push_back(x);
    }
  }
  if (out[0].empty()) t.fail("the CSV file '" + path + "' has no rows", fileKey);
  return out;
}

// A signal from a CSV file's time and value columns.
void readCsvSignal(Table& t, const std::string& defaultColumn, const Range& levels, SignalSpec& s) {
  const std::string column = t.string("column", defaultColumn), timeColumn = t.string("time_column", "time_s");
  std::string path;
  const auto cols = readCsvColumns(t, "file", {{timeColumn, "time_column"}, {column, "column"}}, path);
  for (std::size_t r = 0; r < cols[0].size(); ++r) {
    const double time = cols[0][r], value = cols[1][r];
    if (r > 0 && !(time > cols[0][r - 1]))
      t.fail("the CSV file '" + path + "': expected strictly increasing times in column '" + timeColumn + "' (row " +
                 std::to_string(r + 1) + ")",
             "time_column");
    if (!kTime.contains(time) || !levels.contains(value))
      t.fail("the CSV file '" + path + "', row " + std::to_string(r + 1) + ": expected a value " + levels.text() +
                 " in column '" + column + "' at a time " + kTime.text(),
             "column");
  }
  s.times = cols[0];
  s.values = cols[1];
}

// A signal table; steering (`steering` true) may be in engineering units.
SignalSpec readSignal(Table t, double lo, double hi, const std::string& csvColumn, bool steering = false) {
  SignalSpec s;
  s.where = t.file() + ":" + std::to_string(t.line());
  const std::string type = t.string("type");
  Dimension dim = Dimension::None;
  Range levels{lo, hi};
  if (steering) {
    const std::string unit =
        t.choice("unit", {"normalised", "steering_wheel_angle", "road_wheel_angle", "rack_travel"}, "normalised");
    using U = SignalSpec::Unit;
    s.unit = unit == "steering_wheel_angle" ? U::SteeringWheelAngle
             : unit == "road_wheel_angle"   ? U::RoadWheelAngle
             : unit == "rack_travel"        ? U::RackTravel
                                            : U::Normalised;
    // In engineering units the vehicle's full steering bounds them, checked
    // when the vehicle is known (normalisedSteering).
    if (s.unit == U::RackTravel) dim = Dimension::Length, levels = Range{-10.0, 10.0};
    else if (s.unit != U::Normalised) dim = Dimension::Angle, levels = Range{-100.0, 100.0};
  }
  auto level = [&](const char* key) { return t.number(key, dim, levels); };
  if (type == "none") {
    s.kind = SignalSpec::Kind::None;
  } else if (type == "constant") {
    s.kind = SignalSpec::Kind::Constant;
    s.level = level("level");
  } else if (type == "ramp") {
    s.kind = SignalSpec::Kind::Ramp;
    s.start = t.number("start", Dimension::Time, kTime);
    s.duration = t.number("duration", Dimension::Time, kSpan);
    s.level = level("level");
  } else if (type == "step") {
    // A step of `level` at `start`, reached in `rise_time` (linear): ISO 7401's 0.1 s by default.
    s.kind = SignalSpec::Kind::Ramp;
    s.start = t.number("start", Dimension::Time, kTime);
    s.duration = t.number("rise_time", Dimension::Time, kSpan, 0.1);
    s.level = level("level");
  } else if (type == "sine") {
    s.kind = SignalSpec::Kind::Sine;
    s.start = t.number("start", Dimension::Time, kTime);
    s.duration = t.number("period", Dimension::Time, kSpan);
    s.level = level("amplitude");
    s.periods = static_cast<int>(t.integerIn("periods", 1, 10000, 1));
  } else if (type == "sine_with_dwell") {
    s.kind = SignalSpec::Kind::SineWithDwell;
    s.start = t.number("start", Dimension::Time, kTime);
    s.duration = t.number("period", Dimension::Time, kSpan);
    s.level = level("amplitude");
    s.dwell = t.number("dwell", Dimension::Time, kTime, s.dwell);
  } else if (type == "chirp") {
    s.kind = SignalSpec::Kind::Chirp;
    s.start = t.number("start", Dimension::Time, kTime);
    s.duration = t.number("duration", Dimension::Time, kSpan);
    s.level = level("amplitude");
    s.f0 = t.number("f0", Dimension::Frequency, kFrequency);
    s.f1 = t.number("f1", Dimension::Frequency, kFrequency);
  } else if (type == "square") {
    s.kind = SignalSpec::Kind::Square;
    s.start = t.number("start", Dimension::Time, kTime);
    s.duration = t.number("period", Dimension::Time, kSpan);
    s.level = level("amplitude");
  } else if (type == "table") {
    s.kind = SignalSpec::Kind::Table;
    // Finite, increasing times: TableSignal::at searches them (a NaN breaks the search).
    s.times = t.numbers("times", Dimension::Time, kTime);
    s.values = t.numbers("values", dim, levels);
    t.require(!s.times.empty(), "times", "at least one time");
    t.require(s.times.size() == s.values.size(), "values", "as many values as times (" + std::to_string(s.times.size()) + ")");
    for (size_t i = 1; i < s.times.size(); ++i)
      if (!(s.times[i] > s.times[i - 1])) t.reject("times", "strictly increasing times", static_cast<int>(i));
  } else if (type == "csv") {
    s.kind = SignalSpec::Kind::Table;
    readCsvSignal(t, csvColumn, levels, s);
  } else {
    t.fail("unknown signal type '" + type +
               "': expected none, constant, ramp, step, sine, sine_with_dwell, chirp, square, table or csv",
           "type");
  }
  // A driver's command through the vehicle's steering system (as a person's
  // input, sampled once a tick) rather than a prescribed rack motion.
  s.asDriverCommand = t.boolean("as_driver_command", false);
  t.finish();
  return s;
}

CheckSpec readCheck(Table& t) {
  CheckSpec c;
  c.enabled = true;
  using O = CheckSpec::Outcome;
  const std::string outcome = t.string("outcome", "survives");
  if (outcome == "survives") c.outcome = O::Survives;
  else if (outcome == "comes_to_rest") c.outcome = O::ComesToRest;
  else if (outcome == "drives_on") c.outcome = O::DrivesOn;
  else if (outcome == "stays_on_four_wheels") c.outcome = O::StaysOnFourWheels;
  else if (outcome == "lands_and_drives_on") c.outcome = O::LandsAndDrivesOn;
  else
    t.fail("unknown outcome '" + outcome +
               "': expected survives, comes_to_rest, drives_on, stays_on_four_wheels or lands_and_drives_on",
           "outcome");
  auto positive = [&](const char* key, Dimension d, double& x) {
    x = t.number(key, d, x);
    t.require(x > 0 && x < 1e6, key, "a positive bound");
  };
  positive("max_constraint_position", Dimension::Length, c.maxConstraintPosition);
  positive("max_constraint_velocity", Dimension::Speed, c.maxConstraintVelocity);
  positive("max_constraint_acceleration", Dimension::Acceleration, c.maxConstraintAcceleration);
  positive("max_speed", Dimension::Speed, c.maxSpeed);
  positive("max_rise", Dimension::Length, c.maxRise);
  positive("rest_speed", Dimension::Speed, c.restSpeed);
  positive("max_wheel_lift", Dimension::Time, c.maxWheelLift);
  t.finish();
  return c;
}

}  // namespace

SignalSpec normalisedSteering(const SignalSpec& in, const vehicle::Vehicle& linkage) {
  using U = SignalSpec::Unit;
  if (in.unit == U::Normalised) return in;
  const vehicle::SteeringSpec& st = linkage.spec.steering;
  double full = 0;  // the unit's value at s = 1
  std::string what, unit;
  if (in.unit == U::SteeringWheelAngle) full = st.steeringWheelFull, what = "steering-wheel angle", unit = "deg";
  if (in.unit == U::RackTravel) full = st.rackTravelFull, what = "rack travel", unit = "m";
  if (in.unit == U::RoadWheelAngle) full = vehicle::roadWheelAnglePerSteer(linkage), what = "road-wheel angle", unit = "deg";
  const double shown = unit == "deg" ? 180.0 / 3.14159265358979323846 : 1.0;
  if (!(std::abs(full) > 0))
    throw config::ConfigError(in.where + ": [steering] in " + what + ": the vehicle has no " + what + " scale");
  SignalSpec s = in;
  s.unit = U::Normalised;
  auto convert = [&](double x) {
    const double n = x / full;
    if (!(std::abs(n) <= 1.0))
      throw config::ConfigError(in.where + ": [steering] " + config::formatNumber(x * shown) + " " + unit + " of " +
                                what + " is beyond the vehicle's full steering (" +
                                config::formatNumber(full * shown) + " " + unit + ")");
    return n;
  };
  s.level = convert(s.level);
  for (double& v : s.values) v = convert(v);
  return s;
}

bool parseFidelity(const std::string& name, vehicle::Fidelity& out) {
  const std::optional<vehicle::Fidelity> f = vehicle::rungByName(name);
  if (f) out = *f;
  return f.has_value();
}

bool parseFidelity(const std::string& name, FidelitySpec& out) {
  out.automatic = name == "auto";
  return out.automatic || parseFidelity(name, out.suspension);
}


int stepsPerTick(double tick, double step) {
  if (!(tick > 0) || !(step > 0)) return 0;
  const double n = std::round(tick / step);
  return n >= 1 && n <= 1e6 && std::abs(n * step - tick) <= 1e-9 * tick ? static_cast<int>(n) : 0;
}

// The centre line of the scenario terrain's track piece named by `track`.
terrain::WorldCentreLine readTrack(Table& d, const std::string& terrainFile) {
  const std::string name = d.string("track");
  if (terrainFile.empty()) d.fail("follows track '" + name + "', but the scenario names no terrain", "track");
  terrain::TerrainData data;
  try {
    data = terrain::loadTerrain(terrainFile);
  } catch (const terrain::TerrainFileError& e) {
    throw config::ConfigError(e.what());
  }
  terrain::WorldCentreLine line;
  if (!terrain::findCentreLine(data, name, line)) {
    std::string known;
    for (const terrain::GroundPiece& p : data.pieces)
      if (!p.terrain.centreLine.empty()) known += (known.empty() ? "" : ", ") + ("'" + p.name + "'");
    if (!data.centreLine.empty()) known = "'" + data.name + "'";
    d.fail("names no track of terrain '" + terrainFile + "'; its tracks: " + (known.empty() ? "none" : known), "track");
  }
  return line;
}

ScenarioSpec loadScenarioFile(const std::string& path, const std::vector<config::Setting>& settings) {
  std::vector<config::Setting> own;
  ScenarioSpec s;
  for (const config::Setting& x : settings) {
    if (std::optional<config::Setting> v = config::underPrefix(x, "vehicle."))
      s.vehicleSettings.push_back(*v);
    else
      own.push_back(x);
  }
  Table root = config::parseTomlFile(path, own);
  s.sourceFile = path;
  Table sc = root.table("scenario");
  s.name = sc.string("name");
  s.vehicleFile = resolveAsset(sc, "vehicle");
  if (sc.has("terrain")) s.terrainFile = resolveAsset(sc, "terrain");
  s.duration = sc.number("duration", Dimension::Time, kDuration);
  s.outputInterval = sc.number("output_interval", Dimension::Time, kOutputInterval, s.outputInterval);
  s.tick = sc.number("tick", Dimension::Time, kTick, s.tick);
  s.raysPerWheel = static_cast<int>(sc.integerIn("rays_per_wheel", 1, 15, 1));
  s.groundInsideStep = sc.boolean("ground_inside_step", s.groundInsideStep);
  sc.finish();

  if (auto st = root.optionalTable("start")) {
    s.initialSpeed = st->number("speed", Dimension::Speed, kSpeed, 0.0);
    s.settleTime = st->number("settle", Dimension::Time, kSettle, 0.0);
    if (st->has("position")) {
      const std::vector<double> p = st->numbers("position", Dimension::Length, kPosition);
      st->require(p.size() == 2, "position", "[x, y] (m)");
      s.startX = p[0];
      s.startY = p[1];
    }
    s.startHeading = st->number("heading", Dimension::Angle, kHeading, 0.0);
    st->finish();
  }
  if (auto f = root.optionalTable("fidelity")) {
    const std::string susp = f->string("suspension", "linkage");
    if (!parseFidelity(susp, s.fidelity))
      f->fail("unknown suspension model '" + susp + "': expected " + vehicle::rungNames() + " or auto", "suspension");
    s.fidelity.errorBudget = f->number("error_budget", Dimension::None, kErrorBudget, s.fidelity.errorBudget);
    const std::string form = f->string("planar_equations", "closed");
    if (form != "closed" && form != "multibody")
      f->fail("unknown planar_equations '" + form + "': expected closed or multibody", "planar_equations");
    s.fidelity.planarClosedForm = form == "closed";
    const std::string kform = f->string("kinematic_equations", "closed");
    if (kform != "closed" && kform != "multibody")
      f->fail("unknown kinematic_equations '" + kform + "': expected closed or multibody", "kinematic_equations");
    s.fidelity.kinematicClosedForm = kform == "closed";
    s.fidelity.newtonIterations =
        static_cast<int>(f->integerIn("newton_iterations", 0, 50, s.fidelity.newtonIterations));  // 0: to tolerance
    s.fidelity.stopWithinTolerance = f->boolean("newton_stops_within_tolerance", s.fidelity.stopWithinTolerance);
    f->finish();
  }
  if (auto it = root.optionalTable("integrator")) {
    IntegratorSpec& i = s.integrator;
    integ::BdfOptions& b = i.bdf;
    const std::string m = it->string("method", "bdf");
    if (m == "bdf") i.method = IntegratorMethod::Bdf;
    else if (m == "rk4") i.method = IntegratorMethod::Rk4;
    else if (m == "euler") i.method = IntegratorMethod::SemiImplicitEuler;
    else it->fail("unknown method '" + m + "': expected bdf, rk4 or euler", "method");
    i.step = it->number("step", Dimension::Time, kStep, i.step);
    it->require(stepsPerTick(s.tick, i.step) > 0, "step",
                "a step that divides the driver's tick of " + std::to_string(s.tick * 1e3) +
                    " ms (a whole number of steps per tick)");
    b.order = static_cast<int>(it->integerIn("order", 1, 5, b.order));
    b.newtonIterations = static_cast<int>(it->integerIn("newton_iterations", 0, 50, b.newtonIterations));  // 0: to tolerance
    b.jacobianEvery = static_cast<int>(it->integerIn("jacobian_every", 0, 1000000000, b.jacobianEvery));  // 0: first step only
    b.jacobianSlices = static_cast<int>(it->integerIn("jacobian_slices", 1, 64, b.jacobianSlices));  // 1: whole at one step
    b.refreshWhenNotContracting = it->boolean("refresh_when_not_contracting", b.refreshWhenNotContracting);
    b.atol = it->number("atol", Dimension::None, kTolerance, b.atol);
    b.rtol = it->number("rtol", Dimension::None, Range{0.0, 1.0, false, false}, b.rtol);
    b.refineError = it->number("refine_error", Dimension::None, Range{0.0, 1.0, false, false}, b.refineError);  // 0: off
    b.refineDepth = static_cast<int>(it->integerIn("refine_depth", 0, 6, b.refineDepth));
    b.fastRowSolve = it->boolean("fast_row_solve", b.fastRowSolve);
    b.lowSpeedTolerance =
        it->number("low_speed_tolerance", Dimension::None, Range{0.0, 1.0, false, false}, b.lowSpeedTolerance);  // 0: off
    it->finish();
  }
  // A CSV file's default columns are the telemetry's (a run's telemetry replays).
  if (auto t = root.optionalTable("steering")) s.steering = readSignal(*t, -1.0, 1.0, "steer_in", true);
  if (auto t = root.optionalTable("throttle")) s.throttle = readSignal(*t, 0.0, 1.0, "throttle_in");
  if (auto t = root.optionalTable("brake")) s.brake = readSignal(*t, 0.0, 1.0, "brake_in");
  if (auto sp = root.optionalTable("speed_control")) {
    s.speedControl.enabled = true;
    SpeedProfile& p = s.speedControl.profile;
    p.target = sp->number("target", Dimension::Speed, kSpeed);
    s.speedControl.kp = sp->number("kp", Dimension::TorqueRate, kGain, s.speedControl.kp);
    s.speedControl.ki = sp->number("ki", Dimension::None, kGain, s.speedControl.ki);
    p.start = sp->number("start", Dimension::Time, kTime, p.start);
    p.end = sp->number("end", Dimension::Time, kTime, p.end);
    sp->require(p.end > p.start, "end", "an end after the start (" + config::formatNumber(p.start) + " s)");
    if (sp->has("ramp_to")) {
      p.rampTo = sp->number("ramp_to", Dimension::Speed, kSpeed);
      p.rampStart = sp->number("ramp_start", Dimension::Time, kTime);
      p.rampDuration = sp->number("ramp_duration", Dimension::Time, kSpan);
    }
    sp->finish();
  }
  if (auto c = root.optionalTable("course")) {
    const std::string type = c->string("type");
    if (type != "iso3888" && type != "iso3888_2")
      c->fail("unknown course '" + type + "': expected iso3888 (ISO 3888-1) or iso3888_2 (ISO 3888-2)", "type");
    s.course.iso3888 = true;
    s.course.part = type == "iso3888_2" ? 2 : 1;
    s.course.startX = c->number("start_x", Dimension::Length, kPosition, s.course.startX);
    s.course.centreY = c->number("centre_y", Dimension::Length, kPosition, s.course.centreY);
    c->finish();
  }
  if (auto d = root.optionalTable("driver")) {
    const std::string type = d->choice("type", {"path_follower", "path", "circle", "track"});
    PathFollowerSpec& f = s.pathFollower;
    f.enabled = true;
    f.lookAheadTime = d->number("look_ahead_time", Dimension::Time, kLookAheadTime, f.lookAheadTime);
    f.minLookAhead = d->number("min_look_ahead", Dimension::Length, kLookAhead, f.minLookAhead);
    f.law = d->choice("law", {"pure_pursuit", "preview"}, "pure_pursuit") == "preview" ? PathFollowerSpec::Law::Preview
                                                                                      : PathFollowerSpec::Law::PurePursuit;
    f.previewTime = d->number("preview_time", Dimension::Time, Range{0.2, 5.0}, f.previewTime);
    f.lineMargin = d->number("line_margin", Dimension::Length, Range{0.0, 1.0}, f.lineMargin);
    if (type == "path") {
      f.path = PathFollowerSpec::Path::Polyline;
      std::string path;
      const auto cols = readCsvColumns(*d, "file", {{d->string("x_column", "x_m"), "x_column"},
                                                    {d->string("y_column", "y_m"), "y_column"}}, path);
      for (std::size_t r = 0; r < cols[0].size(); ++r) {
        const Eigen::Vector2d p(cols[0][r], cols[1][r]);
        if (!kPosition.contains(p.x()) || !kPosition.contains(p.y()))
          d->fail("the path '" + path + "', row " + std::to_string(r + 1) + ": a point beyond " + kPosition.text() + " m", "file");
        // Repeated points (a car at rest in a telemetry) add nothing.
        if (f.points.empty() || (p - f.points.back()).norm() > 1e-6) f.points.push_back(p);
      }
      if (f.points.size() < 2) d->fail("the path '" + path + "' needs at least two distinct points", "file");
      f.closed = d->boolean("closed", false);
    } else if (type == "track") {
      terrain::WorldCentreLine line = readTrack(*d, s.terrainFile);
      f.path = PathFollowerSpec::Path::Polyline;
      f.points = std::move(line.points);
      f.closed = line.closed;
    } else if (type == "circle") {
      f.path = PathFollowerSpec::Path::Circle;
      f.radius = d->number("radius", Dimension::Length, Range{1.0, 1e4});
      f.direction = d->choice("direction", {"left", "right"}, "left") == "left" ? 1.0 : -1.0;
    }
    d->finish();
    if (type == "path_follower" && !s.course.iso3888)
      root.fail("a path_follower driver needs a [course] to follow (or type = \"path\", \"track\" or \"circle\")", "driver");
    if (s.steering.kind != SignalSpec::Kind::None) root.fail("give either [steering] or a path_follower [driver], not both", "driver");
  }
  if (auto l = root.optionalTable("laps")) {
    terrain::WorldCentreLine line = readTrack(*l, s.terrainFile);
    if (!line.closed) l->fail("track '" + l->string("track") + "' is not a circuit (its centre line is open): no laps to time", "track");
    s.laps = {true, std::move(line.points), line.width, static_cast<int>(l->integerIn("sectors", 1, 20, 3))};
    l->finish();
  }
  for (Table& p : root.optionalTables("places")) {
    Place place;
    place.name = p.string("name");
    const std::vector<double> at = p.numbers("position", Dimension::Length, kPosition);
    p.require(at.size() == 2, "position", "[x, y] (m)");
    place.x = at[0];
    place.y = at[1];
    place.heading = p.number("heading", Dimension::Angle, kHeading, 0.0);
    p.finish();
    s.places.push_back(place);
  }
  if (auto c = root.optionalTable("check")) s.check = readCheck(*c);
  if (auto m = root.optionalTable("metrics")) {
    const std::string test = m->string("test");
    if (test == "iso7401_step_steer") s.standardTest = StandardTest::Iso7401StepSteer;
    else if (test == "fmvss126_sine_with_dwell") s.standardTest = StandardTest::Fmvss126SineWithDwell;
    else if (test == "iso4138_constant_steer") s.standardTest = StandardTest::Iso4138ConstantSteer;
    else if (test == "iso4138_constant_radius") s.standardTest = StandardTest::Iso4138ConstantRadius;
    else m->fail("unknown standard test '" + test +
                     "': expected iso7401_step_steer, fmvss126_sine_with_dwell, iso4138_constant_steer or "
                     "iso4138_constant_radius",
                 "test");
    m->finish();
  }
  root.finish();
  return s;
}

}  // namespace bdfcar::scenario
