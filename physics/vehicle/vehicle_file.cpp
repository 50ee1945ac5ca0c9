#include "vehicle/vehicle_file.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <filesystem>
#include <set>

#include "config/toml_reader.h"

namespace bdfcar::vehicle {

using config::Dimension;
using config::Table;

namespace {

// One copy of a (possibly mirrored) item: the side suffix and the reflection.
struct Side {
  std::string suffix;                // "", "L" or "R"
  Mat3 M = Mat3::Identity();         // diag(1, -1, 1) on the right
};

std::vector<Side> sidesOf(Table& t) {
  if (t.boolean("mirror", false)) return {Side{"L", Mat3::Identity()}, Side{"R", Vec3(1, -1, 1).asDiagonal()}};
  return {Side{}};
}

class Loader {
 public:
  explicit Loader(const std::string& path) : root_(config::parseTomlFile(path)) { spec_.sourceFile = path; }
  VehicleSpec load();

 private:
  Vec3 point(Table& t, const std::string& key, const Side& s);
  Vec3 vectorOf(Table& t, const std::string& key, const Side& s);
  Mat3 inertiaAxes(Table& ax, const Side& s);
  Vec3 vectorValue(Table& t, const std::string& key, const std::string& text, const Side& s);
  std::string bodyRef(Table& t, const std::string& key, const Side& s);
  void readPoints();
  void readBodies();
  void readCutJoints();
  void readSprings();
  void readWheels();
  void readSteeringAndDriveline();
  void readAppearance();
  tyre::TyreParams readTyre(Table t);
  tyre::FialaParams readFiala(Table& t);

  Table root_;
  VehicleSpec spec_;
  std::map<std::string, Vec3> points_;
  std::set<std::string> mirroredBodies_;   // base names
  std::set<std::string> bodies_;           // expanded names
};

Vec3 Loader::vectorValue(Table& t, const std::string& key, const std::string& text, const Side& s) {
  // "A->B": from point A to point B.
  const auto arrow = text.find("->");
  if (arrow == std::string::npos) t.fail("expected a vector [x, y, z] or \"A->B\" between two points, got \"" + text + "\"", key);
  const std::string a = text.substr(0, arrow), b = text.substr(arrow + 2);
  for (const std::string& p : {a, b})
    if (!points_.count(p)) t.fail("unknown point '" + p + "' (define it in [points])", key);
  return s.M * (points_.at(b) - points_.at(a));
}

// A direction: [x, y, z], "A->B" between two points, or { cross = ["A->B", "C->D"] }.
Vec3 Loader::vectorOf(Table& t, const std::string& key, const Side& s) {
  if (t.isString(key)) return vectorValue(t, key, t.string(key), s);
  if (t.isTable(key)) {
    Table c = t.table(key);
    const std::vector<std::string> f = c.strings("cross");
    c.require(f.size() == 2, "cross", "two vectors [\"A->B\", \"C->D\"]");
    const Vec3 r = vectorValue(c, "cross", f[0], s).cross(vectorValue(c, "cross", f[1], s));
    c.finish();
    return r;
  }
  return s.M * t.vector3(key, Dimension::None);
}

Vec3 Loader::point(Table& t, const std::string& key, const Side& s) {
  if (t.isString(key)) {
    const std::string name = t.string(key);
    if (!points_.count(name)) t.fail("unknown point '" + name + "' (define it in [points])", key);
    return s.M * points_.at(name);
  }
  if (t.isTable(key)) {
    Table m = t.table(key);
    const std::string a = m.string("midpoint_of"), b = m.string("and");
    for (const std::string& p : {a, b})
      if (!points_.count(p)) m.fail("unknown point '" + p + "'", "midpoint_of");
    m.finish();
    return s.M * (0.5 * (points_.at(a) + points_.at(b)));
  }
  return s.M * t.vector3(key, Dimension::Length);
}

std::string Loader::bodyRef(Table& t, const std::string& key, const Side& s) {
  const std::string base = t.string(key);
  std::string name = base;
  if (mirroredBodies_.count(base)) {
    if (s.suffix.empty()) t.fail("'" + base + "' is mirrored: refer to it from a mirrored item or as " + base + "L / " + base + "R", key);
    name = base + s.suffix;
  }
  if (!bodies_.count(name)) t.fail("unknown body '" + base + "' (bodies must be defined before they are used)", key);
  return name;
}

void Loader::readPoints() {
  if (auto p = root_.optionalTable("points")) {
    for (const std::string& k : p->keys()) points_[k] = p->vector3(k, Dimension::Length);
    p->finish();
  }
  spec_.points = points_;
}

Mat3 inertiaTensor(Table& t, const Mat3& axes) {
  const std::vector<double> v = t.numbers("inertia", Dimension::Inertia);
  t.require(v.size() == 3 || v.size() == 6, "inertia",
            "3 principal moments [Ixx, Iyy, Izz] or 6 values [Ixx, Iyy, Izz, Ixy, Ixz, Iyz] (kg m^2)");
  Mat3 I = Vec3(v[0], v[1], v[2]).asDiagonal();
  if (v.size() == 6) {
    I(0, 1) = I(1, 0) = v[3];
    I(0, 2) = I(2, 0) = v[4];
    I(1, 2) = I(2, 1) = v[5];
  }
  Eigen::SelfAdjointEigenSolver<Mat3> eig(I);
  const Vec3 p = eig.eigenvalues();
  t.require(p(0) > 0 && p(0) + p(1) >= p(2) * (1 - 1e-9), "inertia",
            "a positive-definite inertia that satisfies the triangle inequality (principal moments " +
                std::to_string(p(0)) + ", " + std::to_string(p(1)) + ", " + std::to_string(p(2)) + ")");
  return axes * I * axes.transpose();
}

// A right-handed frame from two of its axes x, y, z (the second made orthogonal to the first).
Mat3 Loader::inertiaAxes(Table& ax, const Side& s) {
  const bool hx = ax.has("x"), hy = ax.has("y"), hz = ax.has("z");
  ax.require(hx + hy + hz == 2, "x", "exactly two of the axes x, y, z");
  Mat3 A;
  if (hx && hy) {
    A = mb::axesWithXY(vectorOf(ax, "x", s), vectorOf(ax, "y", s));
  } else if (hy && hz) {  // frame (y, z, x) is right-handed
    const Mat3 B = mb::axesWithXY(vectorOf(ax, "y", s), vectorOf(ax, "z", s));
    A << B.col(2), B.col(0), B.col(1);
  } else {  // z, x: frame (z, x, y)
    const Mat3 B = mb::axesWithXY(vectorOf(ax, "z", s), vectorOf(ax, "x", s));
    A << B.col(1), B.col(2), B.col(0);
  }
  ax.require(A.allFinite() && std::abs(A.determinant() - 1.0) < 1e-6, "x", "two non-parallel, non-zero axis directions");
  ax.finish();
  return A;
}

void Loader::readBodies() {
  std::vector<Table> list = root_.tables("bodies");
  for (Table& b : list) {
    const std::string base = b.string("name");
    const std::vector<Side> sides = sidesOf(b);
    if (sides.size() == 2) mirroredBodies_.insert(base);
    for (const Side& s : sides) {
      BodySpec body;
      body.name = base + s.suffix;
      body.line = b.line();
      if (bodies_.count(body.name)) b.fail("duplicate body name '" + body.name + "'", "name");
      body.mass = b.number("mass", Dimension::Mass);
      b.require(body.mass > 0, "mass", "a positive mass (kg), got " + std::to_string(body.mass));
      body.com = point(b, "com", s);
      // Inertia axes: the chassis axes (reflected on the right: M I M), or a
      // frame from two directions (computed from the mirrored points).
      Mat3 axes = s.M;
      if (auto ax = b.optionalTable("inertia_axes")) axes = inertiaAxes(*ax, s);
      body.inertia = inertiaTensor(b, axes);
      // Point masses lumped into the body (e.g. halves of links modelled as massless distance constraints).
      for (Table& pm : b.optionalTables("point_masses")) {
        const double mi = pm.number("mass", Dimension::Mass);
        pm.require(mi > 0, "mass", "a positive mass (kg)");
        const Vec3 pi = point(pm, "at", s);
        pm.finish();
        const double M = body.mass + mi;
        const Vec3 com = (body.mass * body.com + mi * pi) / M;
        auto shift = [](double m, const Vec3& r) { return m * (r.squaredNorm() * Mat3::Identity() - r * r.transpose()); };
        body.inertia += shift(body.mass, body.com - com) + shift(mi, pi - com);
        body.mass = M;
        body.com = com;
      }
      Table j = b.table("joint");
      const std::string type = j.string("type");
      JointSpec& js = body.joint;
      if (type == "free") {
        js.type = mb::JointType::Free;
        b.require(spec_.bodies.empty(), "joint", "the free joint on the first body (the chassis) only");
      } else {
        js.parent = bodyRef(j, "parent", s);
        js.at = point(j, "at", s);
        if (type == "revolute" || type == "prismatic" || type == "cylindrical") {
          js.type = type == "revolute" ? mb::JointType::Revolute
                                       : (type == "prismatic" ? mb::JointType::Prismatic : mb::JointType::Cylindrical);
          js.axis = vectorOf(j, "axis", s);
          j.require(js.axis.norm() > 1e-9, "axis", "a non-zero axis");
          js.axis.normalize();
        } else if (type == "universal") {
          js.type = mb::JointType::Universal;
          js.axisParent = vectorOf(j, "axis_parent", s).normalized();
          js.axisChild = vectorOf(j, "axis_child", s).normalized();
          j.require(std::abs(js.axisParent.dot(js.axisChild)) < 1e-3, "axis_child",
                    "an axis perpendicular to axis_parent (the cross of a universal joint)");
        } else if (type == "spherical") {
          js.type = mb::JointType::Spherical;
        } else {
          j.fail("unknown joint type '" + type + "': expected free, revolute, prismatic, cylindrical, universal or spherical",
                 "type");
        }
        b.require(!spec_.bodies.empty(), "joint", "a free joint on the first body (the chassis)");
      }
      j.finish();
      spec_.bodies.push_back(body);
      bodies_.insert(body.name);
    }
    b.finish();
  }
  if (spec_.bodies.empty()) root_.fail("no [[bodies]]", "bodies");
}

void Loader::readCutJoints() {
  for (Table& c : root_.optionalTables("cut_joints")) {
    const std::string base = c.string("name");
    for (const Side& s : sidesOf(c)) {
      CutJointSpec cut;
      cut.name = base + s.suffix;
      cut.line = c.line();
      const std::string type = c.string("type");
      cut.bodyA = bodyRef(c, "body_a", s);
      cut.bodyB = bodyRef(c, "body_b", s);
      if (type == "spherical") {
        cut.kind = CutKind::Spherical;
        cut.pointA = cut.pointB = point(c, "at", s);
      } else if (type == "distance") {
        cut.kind = CutKind::Distance;
        cut.pointA = point(c, "at_a", s);
        cut.pointB = point(c, "at_b", s);
        cut.length = c.number("length", Dimension::Length, -1.0);
        if (c.has("length")) c.require(cut.length > 0, "length", "a positive length (m)");
      } else {
        c.fail("unknown cut joint type '" + type + "': expected spherical or distance", "type");
      }
      spec_.cutJoints.push_back(cut);
    }
    c.finish();
  }
}

mb::ForceCurve curve(Table& t, const std::string& linearKey, const std::string& tableKey, Dimension linearDim) {
  mb::ForceCurve c;
  if (t.has(tableKey)) {
    const std::vector<double> flat = t.numbers(tableKey, Dimension::None);
    t.require(flat.size() >= 4 && flat.size() % 2 == 0, tableKey, "pairs [x0, F0, x1, F1, ...] (at least two points)");
    for (size_t i = 0; i < flat.size(); i += 2) {
      c.x.push_back(flat[i]);
      c.force.push_back(flat[i + 1]);
    }
    for (size_t i = 1; i < c.x.size(); ++i)
      t.require(c.x[i] > c.x[i - 1], tableKey, "strictly increasing x values");
  } else {
    c.coefficient = t.number(linearKey, linearDim, 0.0);
  }
  return c;
}

void Loader::readSprings() {
  for (Table& t : root_.optionalTables("springs")) {
    const std::string base = t.string("name");
    for (const Side& s : sidesOf(t)) {
      SpringSpec sp;
      sp.name = base + s.suffix;
      sp.line = t.line();
      sp.bodyA = bodyRef(t, "body_a", s);
      sp.bodyB = bodyRef(t, "body_b", s);
      sp.pointA = point(t, "at_a", s);
      sp.pointB = point(t, "at_b", s);
      sp.freeLength = t.number("free_length", Dimension::Length, 0.0);
      sp.preload = t.number("preload", Dimension::Force, 0.0);
      sp.spring = curve(t, "stiffness", "spring_curve", Dimension::Stiffness);
      sp.damper = curve(t, "damping", "damper_curve", Dimension::Damping);
      t.require(sp.spring.coefficient >= 0, "stiffness", "a non-negative stiffness (N/m)");
      t.require(sp.damper.coefficient >= 0, "damping", "a non-negative damping (N s/m)");
      if (sp.spring.coefficient > 0 || !sp.spring.x.empty())
        t.require(sp.freeLength > 0, "free_length", "a positive free length (m) for a spring");
      if (auto b = t.optionalTable("bump_stop")) {
        sp.bumpLength = b->number("length", Dimension::Length);
        sp.bumpStiffness = b->number("stiffness", Dimension::Stiffness);
        b->finish();
      }
      if (auto r = t.optionalTable("rebound_stop")) {
        sp.reboundLength = r->number("length", Dimension::Length);
        sp.reboundStiffness = r->number("stiffness", Dimension::Stiffness);
        r->finish();
      }
      spec_.springs.push_back(sp);
    }
    t.finish();
  }
}

// The [tyres.NAME] table: `model` picks one of the closed set of tyre models.
tyre::TyreParams Loader::readTyre(Table t) {
  const std::string model = t.string("model");
  if (model == "fiala") return readFiala(t);
  t.fail("unknown tyre model '" + model + "': expected fiala", "model");
  return {};
}

tyre::FialaParams Loader::readFiala(Table& t) {
  tyre::FialaParams p;
  auto positive = [&](const char* key, Dimension d, double& out) {
    out = t.number(key, d);
    t.require(out > 0, key, std::string("a positive ") + config::dimensionName(d));
  };
  positive("unloaded_radius", Dimension::Length, p.unloadedRadius);
  positive("width", Dimension::Length, p.width);
  positive("vertical_stiffness", Dimension::Stiffness, p.verticalStiffness);
  p.verticalDamping = t.number("vertical_damping", Dimension::Damping);
  p.rollingResistance = t.number("rolling_resistance", Dimension::None);
  positive("slip_stiffness", Dimension::Force, p.slipStiffness);
  p.corneringStiffness = t.number("cornering_stiffness", Dimension::None);  // N/rad
  t.require(p.corneringStiffness > 0, "cornering_stiffness", "a positive cornering stiffness (N/rad)");
  p.uMin = t.number("u_min");
  p.uMax = t.number("u_max");
  t.require(p.uMin > 0 && p.uMax >= p.uMin && p.uMax <= 3, "u_max", "0 < u_min <= u_max <= 3");
  p.referenceFriction = t.number("reference_friction", Dimension::None, p.referenceFriction);
  p.relaxationLengthX = t.number("relaxation_length_x", Dimension::Length, p.relaxationLengthX);
  p.relaxationLengthY = t.number("relaxation_length_y", Dimension::Length, p.relaxationLengthY);
  t.require(p.relaxationLengthX > 0 && p.relaxationLengthY > 0, "relaxation_length_x", "positive relaxation lengths");
  p.lowSpeedBlend0 = t.number("low_speed_blend_start", Dimension::Speed, p.lowSpeedBlend0);
  p.lowSpeedBlend1 = t.number("low_speed_blend_end", Dimension::Speed, p.lowSpeedBlend1);
  t.require(p.lowSpeedBlend0 > 0 && p.lowSpeedBlend1 > p.lowSpeedBlend0, "low_speed_blend_end",
            "0 < low_speed_blend_start < low_speed_blend_end (m/s)");
  p.lowSpeedDampingX = t.number("low_speed_damping_x", Dimension::Damping, p.lowSpeedDampingX);
  p.lowSpeedDampingY = t.number("low_speed_damping_y", Dimension::Damping, p.lowSpeedDampingY);
  t.finish();
  return p;
}

void Loader::readWheels() {
  Table tyres = root_.table("tyres");
  std::map<std::string, tyre::TyreParams> byName;
  for (const std::string& k : tyres.keys()) byName[k] = readTyre(tyres.table(k));
  tyres.finish();
  for (Table& w : root_.tables("wheels")) {
    const std::string base = w.string("position");
    for (const Side& s : sidesOf(w)) {
      WheelSpec wh;
      wh.position = base + s.suffix;
      wh.spindle = bodyRef(w, "spindle", s);
      const std::string tyreName = w.string("tyre");
      if (!byName.count(tyreName)) w.fail("unknown tyre '" + tyreName + "' (define it as [tyres." + tyreName + "])", "tyre");
      wh.tyre = byName.at(tyreName);
      wh.spinInertia = w.number("spin_inertia", Dimension::Inertia, 0.0);
      wh.brakeTorque = w.number("brake_torque", Dimension::Torque, 0.0);
      wh.driven = w.boolean("driven", false);
      w.require(wh.spinInertia >= 0 && wh.brakeTorque >= 0, "brake_torque", "non-negative values");
      spec_.wheels.push_back(wh);
    }
    w.finish();
  }
  const char* order[4] = {"FL", "FR", "RL", "RR"};
  root_.require(spec_.wheels.size() == 4, "wheels", "four wheels FL, FR, RL, RR");
  std::vector<WheelSpec> sorted;
  for (const char* pos : order) {
    bool found = false;
    for (const WheelSpec& w : spec_.wheels)
      if (w.position == pos) {
        sorted.push_back(w);
        found = true;
      }
    root_.require(found, "wheels", std::string("a wheel at position ") + pos);
  }
  spec_.wheels = sorted;
}

void Loader::readSteeringAndDriveline() {
  Table st = root_.table("steering");
  const Side none;
  spec_.steering.rack = bodyRef(st, "rack", none);
  spec_.steering.rackTravelFull = st.number("rack_travel_full", Dimension::Length);
  spec_.steering.steeringWheelFull = st.number("steering_wheel_angle_full", Dimension::Angle);
  st.require(spec_.steering.rackTravelFull != 0, "rack_travel_full", "a non-zero rack travel (m) at full input");
  st.require(spec_.steering.steeringWheelFull > 0, "steering_wheel_angle_full", "a positive angle");
  st.finish();
  if (auto d = root_.optionalTable("driveline")) {
    spec_.maxDriveTorque = d->number("max_torque", Dimension::Torque);
    d->require(spec_.maxDriveTorque >= 0, "max_torque", "a non-negative torque (N m)");
    const std::string reaction = d->string("torque_reaction", "chassis");
    if (reaction == "chassis") spec_.driveReaction = DriveReaction::Chassis;
    else if (reaction == "carrier") spec_.driveReaction = DriveReaction::Carrier;
    else if (reaction == "none") spec_.driveReaction = DriveReaction::None;
    else d->fail("unknown torque_reaction '" + reaction + "': expected chassis, carrier or none", "torque_reaction");
    d->finish();
  }
  if (auto a = root_.optionalTable("aerodynamics")) {
    spec_.dragArea = a->number("drag_area", Dimension::None);
    a->require(spec_.dragArea >= 0, "drag_area", "a non-negative 0.5 rho Cd A (N s^2/m^2)");
    a->finish();
  }
}

void Loader::readAppearance() {
  auto a = root_.optionalTable("appearance");
  VehicleGeometry& g = spec_.geometry;
  if (a) {
    if (a->has("body_mesh")) {
      const std::filesystem::path mesh = a->string("body_mesh");
      g.bodyMesh = mesh.is_absolute() ? mesh.string()
                                      : (std::filesystem::path(spec_.sourceFile).parent_path() / mesh).lexically_normal().string();
    }
    if (a->has("colour")) g.bodyColour = a->vector3("colour", Dimension::None);
    g.length = a->number("length", Dimension::Length, g.length);
    g.width = a->number("width", Dimension::Length, g.width);
    g.height = a->number("height", Dimension::Length, g.height);
    if (a->has("body_offset")) g.bodyOffset = a->vector3("body_offset", Dimension::Length);
    a->finish();
  }
  // Wheel layout from the data, for drawing.
  const auto& w = spec_.wheels;
  auto centre = [&](int i) {
    for (const BodySpec& b : spec_.bodies)
      if (b.name == w[i].spindle) return b.com;
    return Vec3(Vec3::Zero());
  };
  g.wheelbase = centre(0).x() - centre(2).x();
  g.trackFront = centre(0).y() - centre(1).y();
  g.trackRear = centre(2).y() - centre(3).y();
  g.wheelRadius = tyre::unloadedRadius(w[0].tyre);
  g.wheelWidth = tyre::width(w[0].tyre);
}

VehicleSpec Loader::load() {
  Table v = root_.table("vehicle");
  spec_.name = v.string("name");
  spec_.description = v.string("description", "");
  spec_.designHeight = v.number("design_height", Dimension::Length);
  v.require(spec_.designHeight > 0, "design_height", "a positive height of the chassis frame above the ground (m)");
  v.finish();
  readPoints();
  readBodies();
  readCutJoints();
  readSprings();
  readWheels();
  readSteeringAndDriveline();
  readAppearance();
  root_.finish();
  return spec_;
}

}  // namespace

VehicleSpec loadVehicleFile(const std::string& path) { return Loader(path).load(); }

}  // namespace bdfcar::vehicle
