#include "vehicle/vehicle_file.h"

#include "tyre/pac2002_file.h"
#include "config/input_files.h"
#include "config/file_kind.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include "config/toml_reader.h"
#include "vehicle/ladder.h"
#include "vehicle/powertrain_file.h"

namespace bdfcar::vehicle {

using config::Dimension;
using config::Range;
using config::Table;

namespace {

// Physical ranges the loader enforces (docs/INPUT-CHECKS.md): wide enough for
// any road vehicle, narrow enough to catch a slipped unit, sign or digit.
const Range kMass{1e-3, 1e6, false, true};                // kg
const double kMaxGyration = 10.0;                          // m, radius of gyration of a body
const double kMinLink = 1e-3;                              // m, between a link's or a spring's ends
const double kMinPlacementMargin = 0.5;                    // m, see checkPlacement
const Range kCoordinate{-100.0, 100.0, true, true};       // m, a point in the chassis frame
const Range kDirection{-1e3, 1e3};                        // components of a direction vector
const Range kInertiaEntry{-1e6, 1e6, true, true};         // kg m^2
const Range kPositiveLength{0.0, 100.0, true, true};      // m
const Range kFreeLength{0.0, 100.0, false, true};         // m (0: none)
const Range kDesignHeight{0.0, 10.0, true, true};         // m
const Range kForce{-1e7, 1e7};                            // N, preloads
const Range kStiffness{0.0, 1e9};                         // N/m, springs and stops (0: none)
const Range kDamping{0.0, 1e8};                           // N s/m
const Range kTorsion{0.0, 1e8};                           // N m/rad, anti-roll bars
const Range kCurveEntry{-1e9, 1e9};                       // x (m or m/s) and force (N) of a curve
const Range kTyreRadius{0.05, 2.0};                       // m
const Range kTyreWidth{0.0, 2.0, true, false};            // m
const Range kTyreStiffness{0.0, 1e9, true, false};        // N/m, N, N/rad
const Range kFriction{0.0, 3.0, true, false};
const Range kRelaxationLength{0.0, 10.0, true, false};    // m
const Range kEnvelopeOrder{1.2, 10.0};                    // the cams' superellipse exponent
const Range kEnvelopeBase{0.0, 2.0, true, false};         // m, the cams' distance
const Range kEnvelopeSpacing{0.005, 0.2};                 // m, the road lattice's
const Range kBlendSpeed{0.0, 50.0, true, false};          // m/s
const Range kRollingResistance{0.0, 1.0};
const Range kSpinInertia{0.0, 100.0};                     // kg m^2
const Range kTorque{0.0, 1e6};                            // N m, brakes and drive
const Range kRackTravel{-1.0, 1.0};                       // m at full steering input
const Range kSteeringWheelAngle{0.0, 100.0, true, false}; // rad at full steering input
const Range kDragArea{0.0, 100.0};                        // 0.5 rho Cd A, N s^2/m^2
const Range kLiftArea{-100.0, 100.0};                     // 0.5 rho Cl A, N s^2/m^2
const Range kCertificate{1e-6, 1.0};                      // fraction of the linkage's peak
const Range kResponseTime{0.005, 1.0};                    // s, the steering system's
const Range kRackSpeed{0.0, 5.0, true, false};            // m/s
const Range kRackAcceleration{0.0, 1000.0, true, false};  // m/s^2
const Range kColour{0.0, 1.0};

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
  Loader(const std::string& path, const std::vector<config::Setting>& settings)
      : root_(config::parseTomlFile(path, settings)) {
    spec_.sourceFile = path;
  }
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
  void readAntiRollBars();
  void readWheels();
  void readSteeringAndDriveline();
  void readAppearance();
  void readCertificate();
  void checkPlacement();
  // A point the vehicle places, where it was given (for checkPlacement).
  struct Placed {
    Table table;
    std::string key;
    Vec3 at;
  };
  void place(const Table& t, const std::string& key, const Vec3& at) { placed_.push_back({t, key, at}); }
  // Refuses two ends closer than kMinLink (a link or spring of no length).
  void requireApart(Table& t, const Vec3& a, const Vec3& b, const std::string& key, const char* what);
  tyre::TyreParams readTyre(Table t);
  tyre::FialaParams readFiala(Table& t);
  tyre::Pac2002Params readPac2002(Table& t);
  void readLowSpeed(Table& t, tyre::LowSpeedSlipSpec& s);
  tyre::EnvelopeSpec readContact(Table& t);

  Table root_;
  VehicleSpec spec_;
  std::map<std::string, Vec3> points_;
  std::set<std::string> mirroredBodies_;   // base names
  std::set<std::string> bodies_;           // expanded names
  std::vector<Placed> placed_;
};

void Loader::requireApart(Table& t, const Vec3& a, const Vec3& b, const std::string& key, const char* what) {
  if ((a - b).norm() >= kMinLink) return;
  char text[200];
  std::snprintf(text, sizeof text, "the two ends of %s are %.3g mm apart: expected two distinct points (at least %g mm)",
                what, (a - b).norm() * 1e3, kMinLink * 1e3);
  t.fail(text, key);
}

Vec3 Loader::vectorValue(Table& t, const std::string& key, const std::string& text, const Side& s) {
  auto at = [&](std::string name) -> Vec3 {
    name.erase(0, name.find_first_not_of(' '));
    name.erase(name.find_last_not_of(' ') + 1);
    if (!points_.count(name)) t.fail("unknown point '" + name + "' (define it in [points])", key);
    return s.M * points_.at(name);
  };
  // "normal(A, B, C)": the normal of the plane through three points, (B - A) x (C - A)
  // (from the mirrored points on a mirrored side, as the joints' geometry is).
  if (text.rfind("normal(", 0) == 0 && text.back() == ')') {
    const std::string inner = text.substr(7, text.size() - 8);
    const auto c1 = inner.find(','), c2 = inner.find(',', c1 == std::string::npos ? c1 : c1 + 1);
    if (c1 == std::string::npos || c2 == std::string::npos || inner.find(',', c2 + 1) != std::string::npos)
      t.fail("expected \"normal(A, B, C)\" naming three points, got \"" + text + "\"", key);
    const Vec3 a = at(inner.substr(0, c1)), b = at(inner.substr(c1 + 1, c2 - c1 - 1)), c = at(inner.substr(c2 + 1));
    return (b - a).cross(c - a);
  }
  // "A->B": from point A to point B.
  const auto arrow = text.find("->");
  if (arrow == std::string::npos)
    t.fail("expected a vector [x, y, z], \"A->B\" between two points or \"normal(A, B, C)\", got \"" + text + "\"", key);
  return at(text.substr(arrow + 2)) - at(text.substr(0, arrow));
}

// A direction: [x, y, z], "A->B" between two points, "normal(A, B, C)" of
// the plane through three, or { cross = [D1, D2] } of two such strings.
Vec3 Loader::vectorOf(Table& t, const std::string& key, const Side& s) {
  if (t.isString(key)) return vectorValue(t, key, t.string(key), s);
  if (t.isTable(key)) {
    Table c = t.table(key);
    const std::vector<std::string> f = c.strings("cross");
    c.require(f.size() == 2, "cross", "two vectors [\"A->B\", \"C->D\"] (or \"normal(A, B, C)\")");
    const Vec3 r = vectorValue(c, "cross", f[0], s).cross(vectorValue(c, "cross", f[1], s));
    c.finish();
    return r;
  }
  return s.M * t.vector3(key, Dimension::None, kDirection);
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
  return s.M * t.vector3(key, Dimension::Length, kCoordinate);
}

std::string Loader::bodyRef(Table& t, const std::string& key, const Side& s) {
  const std::string base = t.string(key);
  std::string name = base;
  if (mirroredBodies_.count(base)) {
    if (s.suffix.empty()) t.fail("'" + base + "' is mirrored: refer to it from a mirrored item or as " + base + "L / " + base + "R", key);
    name = base + s.suffix;
  }
  // Bodies are defined parent first, so a joint can only name an earlier body:
  // the tree has no cycles by construction (a body naming itself is unknown here).
  if (!bodies_.count(name)) t.fail("unknown body '" + base + "' (bodies must be defined before they are used)", key);
  return name;
}

void Loader::readPoints() {
  if (auto p = root_.optionalTable("points")) {
    for (const std::string& k : p->keys()) points_[k] = p->vector3(k, Dimension::Length, kCoordinate);
    p->finish();
  }
  spec_.points = points_;
}

Mat3 inertiaTensor(Table& t, const Mat3& axes) {
  const std::vector<double> v = t.numbers("inertia", Dimension::Inertia, kInertiaEntry);
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
                config::formatNumber(p(0)) + ", " + config::formatNumber(p(1)) + ", " + config::formatNumber(p(2)) + ")");
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
      body.file = b.sourceOf();
      if (bodies_.count(body.name)) b.fail("duplicate body name '" + body.name + "'", "name");
      body.mass = b.number("mass", Dimension::Mass, kMass);
      body.com = point(b, "com", s);
      place(b, "com", body.com);
      // Inertia axes: the chassis axes (reflected on the right: M I M), or a
      // frame from two directions (computed from the mirrored points).
      Mat3 axes = s.M;
      if (auto ax = b.optionalTable("inertia_axes")) axes = inertiaAxes(*ax, s);
      body.inertia = inertiaTensor(b, axes);
      // Point masses lumped into the body (e.g. halves of links modelled as massless distance constraints).
      for (Table& pm : b.optionalTables("point_masses")) {
        const double mi = pm.number("mass", Dimension::Mass, kMass);
        const Vec3 pi = point(pm, "at", s);
        place(pm, "at", pi);
        pm.finish();
        const double M = body.mass + mi;
        const Vec3 com = (body.mass * body.com + mi * pi) / M;
        auto shift = [](double m, const Vec3& r) { return m * (r.squaredNorm() * Mat3::Identity() - r * r.transpose()); };
        body.inertia += shift(body.mass, body.com - com) + shift(mi, pi - com);
        body.mass = M;
        body.com = com;
      }
      {
        // 1e-300 kg with a car's inertia: a radius of gyration of 1e151 m.
        const double gyration = std::sqrt(Eigen::SelfAdjointEigenSolver<Mat3>(body.inertia).eigenvalues().maxCoeff() /
                                          body.mass);
        if (!(gyration <= kMaxGyration)) {
          char text[200];
          std::snprintf(text, sizeof text,
                        "a radius of gyration of %.3g m (inertia against the mass of %.3g kg): expected at most %g m; "
                        "a mass or inertia in the wrong unit?",
                        gyration, body.mass, kMaxGyration);
          b.fail(text, "inertia");
        }
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
        place(j, "at", js.at);
        if (type == "revolute" || type == "prismatic" || type == "cylindrical") {
          js.type = type == "revolute" ? mb::JointType::Revolute
                                       : (type == "prismatic" ? mb::JointType::Prismatic : mb::JointType::Cylindrical);
          js.axis = vectorOf(j, "axis", s);
          j.require(js.axis.norm() > 1e-9, "axis", "a non-zero axis");
          js.axis.normalize();
        } else if (type == "universal") {
          js.type = mb::JointType::Universal;
          // Zero axes would pass the perpendicularity check (a zero dot product).
          const Vec3 ap = vectorOf(j, "axis_parent", s), ac = vectorOf(j, "axis_child", s);
          j.require(ap.norm() > 1e-9, "axis_parent", "a non-zero axis");
          j.require(ac.norm() > 1e-9, "axis_child", "a non-zero axis");
          js.axisParent = ap.normalized();
          js.axisChild = ac.normalized();
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
  std::set<std::string> names;
  for (Table& c : root_.optionalTables("cut_joints")) {
    const std::string base = c.string("name");
    for (const Side& s : sidesOf(c)) {
      CutJointSpec cut;
      cut.name = base + s.suffix;
      cut.line = c.line();
      cut.file = c.sourceOf();
      if (!names.insert(cut.name).second) c.fail("duplicate cut joint name '" + cut.name + "'", "name");
      const std::string type = c.string("type");
      cut.bodyA = bodyRef(c, "body_a", s);
      cut.bodyB = bodyRef(c, "body_b", s);
      if (cut.bodyA == cut.bodyB) c.fail("joins body '" + cut.bodyA + "' to itself: expected two different bodies", "body_b");
      if (type == "spherical") {
        cut.kind = CutKind::Spherical;
        cut.pointA = cut.pointB = point(c, "at", s);
        place(c, "at", cut.pointA);
      } else if (type == "distance") {
        cut.kind = CutKind::Distance;
        cut.pointA = point(c, "at_a", s);
        cut.pointB = point(c, "at_b", s);
        place(c, "at_a", cut.pointA);
        place(c, "at_b", cut.pointB);
        requireApart(c, cut.pointA, cut.pointB, "at_b", ("cut joint '" + cut.name + "'").c_str());
        cut.length = c.number("length", Dimension::Length, kPositiveLength, -1.0);  // -1: the design distance
      } else {
        c.fail("unknown cut joint type '" + type + "': expected spherical or distance", "type");
      }
      spec_.cutJoints.push_back(cut);
    }
    c.finish();
  }
}

mb::ForceCurve curve(Table& t, const std::string& linearKey, const std::string& tableKey, Dimension linearDim,
                     const Range& linearRange) {
  mb::ForceCurve c;
  if (t.has(tableKey)) {
    const std::vector<double> flat = t.numbers(tableKey, Dimension::None, kCurveEntry);
    t.require(flat.size() >= 4 && flat.size() % 2 == 0, tableKey, "pairs [x0, F0, x1, F1, ...] (at least two points)");
    for (size_t i = 0; i < flat.size(); i += 2) {
      c.x.push_back(flat[i]);
      c.force.push_back(flat[i + 1]);
    }
    for (size_t i = 1; i < c.x.size(); ++i)
      t.require(c.x[i] > c.x[i - 1], tableKey, "strictly increasing x values");
  } else {
    c.coefficient = t.number(linearKey, linearDim, linearRange, 0.0);
  }
  return c;
}

void Loader::readSprings() {
  std::set<std::string> names;
  for (Table& t : root_.optionalTables("springs")) {
    const std::string base = t.string("name");
    for (const Side& s : sidesOf(t)) {
      SpringSpec sp;
      sp.name = base + s.suffix;
      sp.line = t.line();
      if (!names.insert(sp.name).second) t.fail("duplicate spring name '" + sp.name + "'", "name");
      sp.bodyA = bodyRef(t, "body_a", s);
      sp.bodyB = bodyRef(t, "body_b", s);
      sp.pointA = point(t, "at_a", s);
      sp.pointB = point(t, "at_b", s);
      place(t, "at_a", sp.pointA);
      place(t, "at_b", sp.pointB);
      requireApart(t, sp.pointA, sp.pointB, "at_b", ("spring '" + sp.name + "'").c_str());
      sp.freeLength = t.number("free_length", Dimension::Length, kFreeLength, 0.0);
      sp.preload = t.number("preload", Dimension::Force, kForce, 0.0);
      sp.spring = curve(t, "stiffness", "spring_curve", Dimension::Stiffness, kStiffness);
      sp.damper = curve(t, "damping", "damper_curve", Dimension::Damping, kDamping);
      if (sp.spring.coefficient > 0 || !sp.spring.x.empty())
        t.require(sp.freeLength > 0, "free_length", "a positive free length (m) for a spring");
      if (auto b = t.optionalTable("bump_stop")) {
        sp.bumpLength = b->number("length", Dimension::Length, kFreeLength);
        sp.bumpStiffness = b->number("stiffness", Dimension::Stiffness, kStiffness);
        b->finish();
      }
      if (auto r = t.optionalTable("rebound_stop")) {
        sp.reboundLength = r->number("length", Dimension::Length, kFreeLength);
        sp.reboundStiffness = r->number("stiffness", Dimension::Stiffness, kStiffness);
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
  if (model == "pac2002") return readPac2002(t);
  t.fail("unknown tyre model '" + model + "': expected fiala or pac2002", "model");
  return {};
}

// A Magic Formula tyre from the .tir file it names (tyre/pac2002_file.h),
// in the evaluation the variant picks; keys of the file bdfcar does not
// evaluate are said once, on stderr.
tyre::Pac2002Params Loader::readPac2002(Table& t) {
  const std::string rel = t.string("file");
  if (rel.empty()) t.fail("expected a .tir file name, got \"\"", "file");
  const std::filesystem::path path = std::filesystem::path(rel).is_absolute()
                                         ? std::filesystem::path(rel)
                                         : (std::filesystem::path(t.folderOf("file")) / rel).lexically_normal();
  if (const auto why = config::notARegularFile(path)) t.fail("the file '" + path.string() + "' " + *why, "file");
  const tyre::Pac2002Variant variant = t.choice("variant", {"textbook", "chrono9"}, "textbook") == "chrono9"
                                           ? tyre::Pac2002Variant::Chrono9
                                           : tyre::Pac2002Variant::Textbook;
  tyre::Pac2002File f;
  try {
    f = tyre::readPac2002(path.string(), variant);
  } catch (const tyre::TirError& e) {
    t.fail(std::string("the tyre property file: ") + e.what(), "file");
  }
  tyre::Pac2002Params& p = f.params;
  p.referenceFriction = t.number("reference_friction", Dimension::None, kFriction, p.referenceFriction);
  readLowSpeed(t, p.lowSpeed);
  p.contact = readContact(t);
  t.finish();
  if (!f.ignoredKeys.empty())
    std::fprintf(stderr, "warning: %s: keys bdfcar's PAC2002 evaluation does not read, ignored: %s\n", p.file.c_str(),
                 f.ignoredKeys.c_str());
  return p;
}

// The low-speed slips' settings (tyre/low_speed_slips.h), any tyre model.
void Loader::readLowSpeed(Table& t, tyre::LowSpeedSlipSpec& s) {
  s.relaxationLengthX = t.number("relaxation_length_x", Dimension::Length, kRelaxationLength, s.relaxationLengthX);
  s.relaxationLengthY = t.number("relaxation_length_y", Dimension::Length, kRelaxationLength, s.relaxationLengthY);
  s.blend0 = t.number("low_speed_blend_start", Dimension::Speed, kBlendSpeed, s.blend0);
  s.blend1 = t.number("low_speed_blend_end", Dimension::Speed, kBlendSpeed, s.blend1);
  t.require(s.blend1 > s.blend0, "low_speed_blend_end", "0 < low_speed_blend_start < low_speed_blend_end (m/s)");
  s.dampingX = t.number("low_speed_damping_x", Dimension::Damping, kDamping, s.dampingX);
  s.dampingY = t.number("low_speed_damping_y", Dimension::Damping, kDamping, s.dampingY);
}

tyre::FialaParams Loader::readFiala(Table& t) {
  tyre::FialaParams p;
  p.unloadedRadius = t.number("unloaded_radius", Dimension::Length, kTyreRadius);
  p.width = t.number("width", Dimension::Length, kTyreWidth);
  p.verticalStiffness = t.number("vertical_stiffness", Dimension::Stiffness, kTyreStiffness);
  p.verticalDamping = t.number("vertical_damping", Dimension::Damping, kDamping);
  p.rollingResistance = t.number("rolling_resistance", Dimension::None, kRollingResistance);
  p.slipStiffness = t.number("slip_stiffness", Dimension::Force, kTyreStiffness);
  p.corneringStiffness = t.number("cornering_stiffness", Dimension::None, kTyreStiffness);  // N/rad
  p.uMin = t.number("u_min", Dimension::None, kFriction);
  p.uMax = t.number("u_max", Dimension::None, kFriction);
  t.require(p.uMax >= p.uMin, "u_max", "0 < u_min <= u_max <= 3");
  p.referenceFriction = t.number("reference_friction", Dimension::None, kFriction, p.referenceFriction);
  readLowSpeed(t, p.lowSpeed);
  p.contact = readContact(t);
  t.finish();
  return p;
}

// A tyre's contact geometry (tyre/envelope.h): the point, or the envelope
// with its cams, each length derived from the tyre where not given.
tyre::EnvelopeSpec Loader::readContact(Table& t) {
  tyre::EnvelopeSpec e;
  e.on = t.choice("contact", {"point", "envelope"}, "point") == "envelope";
  e.halfLength = t.number("envelope_half_length", Dimension::Length, kTyreRadius, 0.0);
  e.halfHeight = t.number("envelope_half_height", Dimension::Length, kTyreRadius, 0.0);
  e.order = t.number("envelope_order", Dimension::None, kEnvelopeOrder, e.order);
  e.base = t.number("envelope_base", Dimension::Length, kEnvelopeBase, 0.0);
  e.spacing = t.number("envelope_spacing", Dimension::Length, kEnvelopeSpacing, e.spacing);
  return e;
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
      // A Magic Formula tyre mirrors its asymmetric coefficients on the side it was not measured on.
      if (auto* pac = std::get_if<tyre::Pac2002Params>(&wh.tyre)) pac->mountedLeft = wh.position.back() != 'R';
      wh.spinInertia = w.number("spin_inertia", Dimension::Inertia, kSpinInertia, 0.0);
      wh.brakeTorque = w.number("brake_torque", Dimension::Torque, kTorque, 0.0);
      wh.driven = w.boolean("driven", false);
      for (const WheelSpec& other : spec_.wheels)
        if (other.position == wh.position) w.fail("duplicate wheel position '" + wh.position + "'", "position");
      spec_.wheels.push_back(wh);
    }
    w.finish();
  }
  const auto& order = kCornerNames;
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

void Loader::readAntiRollBars() {
  for (Table& b : root_.optionalTables("anti_roll_bars")) {
    AntiRollBarSpec bar;
    bar.name = b.string("name");
    bar.line = b.line();
    const std::string axle = b.choice("axle", {"F", "R"});
    bar.left = axle == "F" ? 0 : 2;
    bar.right = bar.left + 1;
    // Its rate at the wheels, given directly or as the bar's torsional
    // stiffness over the square of the wheel travel per radian of twist.
    if (b.has("rate")) {
      bar.rate = b.number("rate", Dimension::Stiffness, kStiffness);
    } else {
      const double torsion = b.number("torsional_stiffness", Dimension::AngularStiffness, kTorsion);
      const double lever = b.number("lever", Dimension::Length, kPositiveLength);
      bar.rate = torsion / (lever * lever);
      b.require(bar.rate <= kStiffness.hi, "lever", "a lever giving a rate within " + kStiffness.text() + " N/m");
    }
    for (const AntiRollBarSpec& other : spec_.antiRollBars)
      if (other.name == bar.name) b.fail("duplicate anti-roll bar '" + bar.name + "'", "name");
    spec_.antiRollBars.push_back(bar);
    b.finish();
  }
}

void Loader::readSteeringAndDriveline() {
  Table st = root_.table("steering");
  const Side none;
  spec_.steering.rack = bodyRef(st, "rack", none);
  spec_.steering.rackTravelFull = st.number("rack_travel_full", Dimension::Length, kRackTravel);
  spec_.steering.steeringWheelFull = st.number("steering_wheel_angle_full", Dimension::Angle, kSteeringWheelAngle);
  st.require(spec_.steering.rackTravelFull != 0, "rack_travel_full", "a non-zero rack travel (m) at full input");
  SteeringSpec& sys = spec_.steering;
  // Range reads: a refused value is shown in the message.
  sys.responseTime = st.number("response_time", Dimension::Time, kResponseTime, sys.responseTime);
  sys.maxRackSpeed = st.number("max_rack_speed", Dimension::Speed, kRackSpeed, sys.maxRackSpeed);
  sys.maxRackAcceleration =
      st.number("max_rack_acceleration", Dimension::Acceleration, kRackAcceleration, sys.maxRackAcceleration);
  st.finish();
  if (auto p = root_.optionalTable("powertrain")) {
    spec_.powertrain = readPowertrain(*p);
    // Its differential is inboard: the drive torques react on the chassis.
    spec_.driveReaction = DriveReaction::Chassis;
    if (root_.has("driveline"))
      root_.fail("[driveline] is the reference runs' speed hold on the wheels; a vehicle with a [powertrain] is driven "
                 "by its engine: remove one of them", "driveline");
  }
  if (auto d = root_.optionalTable("driveline")) {
    spec_.maxDriveTorque = d->number("max_torque", Dimension::Torque, kTorque);
    const std::string reaction = d->string("torque_reaction", "chassis");
    if (reaction == "chassis") spec_.driveReaction = DriveReaction::Chassis;
    else if (reaction == "carrier") spec_.driveReaction = DriveReaction::Carrier;
    else if (reaction == "none") spec_.driveReaction = DriveReaction::None;
    else d->fail("unknown torque_reaction '" + reaction + "': expected chassis, carrier or none", "torque_reaction");
    d->finish();
  }
  if (auto a = root_.optionalTable("aerodynamics")) {
    spec_.dragArea = a->number("drag_area", Dimension::None, kDragArea);  // 0.5 rho Cd A, N s^2/m^2
    spec_.liftAreaFront = a->numberIn("lift_area_front", kLiftArea, 0.0);  // 0.5 rho Cl A, N s^2/m^2, - downforce
    spec_.liftAreaRear = a->numberIn("lift_area_rear", kLiftArea, 0.0);
    a->finish();
  }

}

void Loader::readCertificate() {
  // One key per derived rung of the ladder (vehicle/ladder.h).
  auto c = root_.optionalTable("certificate");
  if (!c) return;
  for (const RungDescription& r : ladder()) {
    if (!r.derived || !c->has(r.name)) continue;
    spec_.certificateRequired[r.name] = c->number(r.name, Dimension::None, kCertificate);
  }
  c->finish();
}

void Loader::readAppearance() {
  auto a = root_.optionalTable("appearance");
  VehicleGeometry& g = spec_.geometry;
  if (a) {
    if (a->has("body_mesh")) {
      const std::filesystem::path mesh = a->string("body_mesh");
      g.bodyMesh = mesh.is_absolute() ? mesh.string()
                                      : (std::filesystem::path(a->folderOf("body_mesh")) / mesh).lexically_normal().string();
      if (const auto why = config::notARegularFile(g.bodyMesh)) a->fail("the file '" + g.bodyMesh + "' " + *why, "body_mesh");
      config::noteInputFile(g.bodyMesh);  // read by the renderer: never an output
    }
    if (a->has("colour")) g.bodyColour = a->vector3("colour", Dimension::None, kColour);
    g.length = a->number("length", Dimension::Length, kPositiveLength, g.length);
    g.width = a->number("width", Dimension::Length, kPositiveLength, g.width);
    g.height = a->number("height", Dimension::Length, kPositiveLength, g.height);
    if (a->has("body_offset")) g.bodyOffset = a->vector3("body_offset", Dimension::Length, kCoordinate);
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

// Geometry that must be possible (docs/INPUT-CHECKS.md): every point the
// vehicle places (bodies' centres of mass and joints, point masses, link
// and spring ends) lies near the car, within half its size around the box
// of its wheel centres (a slipped digit or unit puts a point metres away),
// and is refused at its key and line otherwise.
void Loader::checkPlacement() {
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (const WheelSpec& w : spec_.wheels)
    for (const BodySpec& b : spec_.bodies)
      if (b.name == w.spindle) {
        lo = lo.cwiseMin(b.com);
        hi = hi.cwiseMax(b.com);
      }
  if (!(lo.x() <= hi.x())) return;  // no wheels: reported elsewhere
  const Vec3 span = hi - lo;
  const double margin = std::max(kMinPlacementMargin, 0.5 * std::max(span.x(), span.y()));
  for (Placed& p : placed_) {
    const Vec3 outside = (lo - p.at).cwiseMax(p.at - hi).cwiseMax(Vec3::Zero());
    if (outside.norm() <= margin) continue;
    char text[300];
    std::snprintf(text, sizeof text,
                  "the point [%.3f, %.3f, %.3f] m is %.2f m from the box of the wheel centres (%.2f x %.2f m), "
                  "farther than half the car's size (%.2f m): a slipped digit, sign or unit?",
                  p.at.x(), p.at.y(), p.at.z(), outside.norm(), span.x(), span.y(), margin);
    p.table.fail(text, p.key);
  }
}

VehicleSpec Loader::load() {
  Table v = root_.table("vehicle");
  spec_.name = v.string("name");
  spec_.description = v.string("description", "");
  spec_.designHeight = v.number("design_height", Dimension::Length, kDesignHeight);
  v.finish();
  readPoints();
  readBodies();
  readCutJoints();
  readSprings();
  readWheels();
  readAntiRollBars();
  readSteeringAndDriveline();
  readAppearance();
  readCertificate();
  checkPlacement();
  root_.finish();
  return spec_;
}

}  // namespace

VehicleSpec loadVehicleFile(const std::string& path, const std::vector<config::Setting>& settings) {
  return Loader(path, settings).load();
}

}  // namespace bdfcar::vehicle
