#include "multibody/model.h"

#include "autodiff.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "matrix_blocking.h"
#include "multibody/joint.h"
#include "multibody/model_error.h"

namespace bdfcar::mb {

int jointNq(JointType t) {
  switch (t) {
    case JointType::Revolute:
    case JointType::Prismatic:
    case JointType::Tabulated1: return 1;
    case JointType::Cylindrical:
    case JointType::Universal:
    case JointType::Tabulated2: return 2;
    case JointType::Spherical: return 4;
    case JointType::Free: return 7;
    case JointType::Planar: return 3;
  }
  return 0;
}

int jointNv(JointType t) {
  switch (t) {
    case JointType::Revolute:
    case JointType::Prismatic:
    case JointType::Tabulated1: return 1;
    case JointType::Cylindrical:
    case JointType::Universal:
    case JointType::Tabulated2: return 2;
    case JointType::Spherical:
    case JointType::Planar: return 3;
    case JointType::Free: return 6;
  }
  return 0;
}

const char* jointTypeName(JointType t) {
  switch (t) {
    case JointType::Revolute: return "revolute";
    case JointType::Prismatic: return "prismatic";
    case JointType::Cylindrical: return "cylindrical";
    case JointType::Universal: return "universal";
    case JointType::Spherical: return "spherical";
    case JointType::Free: return "free";
    case JointType::Planar: return "planar";
    case JointType::Tabulated1: return "tabulated (1 coordinate)";
    case JointType::Tabulated2: return "tabulated (2 coordinates)";
  }
  return "?";
}

template <typename T>
T ForceCurve::eval(const T& xv) const {
  if (x.empty()) return coefficient * xv;
  const size_t n = x.size();
  if (n == 1) return T(force[0]);
  // Index of the segment holding xv (clamped to the end segments: linear extrapolation).
  size_t i = static_cast<size_t>(std::upper_bound(x.begin(), x.end(), ad::value(xv)) - x.begin());
  i = std::clamp<size_t>(i, 1, n - 1);
  const T s = (xv - x[i - 1]) / (x[i] - x[i - 1]);
  return force[i - 1] + s * (force[i] - force[i - 1]);
}

template <typename T>
SpringDamper::PartsT<T> SpringDamper::parts(const T& L, const T& Ldot) const {
  PartsT<T> p;
  p.spring = preload + spring.eval(T(freeLength - L));
  p.damper = damper.eval(T(-Ldot));
  p.weight = T(lumpedWeight);
  if (bumpLength > 0 && ad::value(L) < bumpLength) p.stop += bumpStiffness * (bumpLength - L);
  if (reboundLength > 0 && ad::value(L) > reboundLength) p.stop -= reboundStiffness * (L - reboundLength);
  return p;
}

template double ForceCurve::eval(const double&) const;
template ad::Dual ForceCurve::eval(const ad::Dual&) const;
template SpringDamper::PartsT<double> SpringDamper::parts(const double&, const double&) const;
template SpringDamper::PartsT<ad::Dual> SpringDamper::parts(const ad::Dual&, const ad::Dual&) const;
// A kinematic corner's springs on its two directions (KinematicCar::cornerMotion).
template ad::DualN<2> ForceCurve::eval(const ad::DualN<2>&) const;
template SpringDamper::PartsT<ad::DualN<2>> SpringDamper::parts(const ad::DualN<2>&, const ad::DualN<2>&) const;

int Model::bodyIndex(const std::string& name) const {
  for (size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].name == name) return static_cast<int>(i);
  return -1;
}

double Model::totalMass() const {
  double m = 0;
  for (const auto& b : bodies) m += b.mass;
  return m;
}

namespace {

void checkAxes(const Mat3& axes, const std::string& what) {
  if (!axes.allFinite() || (axes.transpose() * axes - Mat3::Identity()).norm() > 1e-9 ||
      axes.determinant() < 0)
    throw ModelError(what + ": joint axes must form a right-handed orthonormal frame");
}

bool isAncestor(const Model& m, int ancestor, int body) {
  for (int b = body; b != kGround; b = m.bodies[b].parent)
    if (b == ancestor) return true;
  return ancestor == kGround;
}

int commonAncestor(const Model& m, int a, int b) {
  for (int x = a; x != kGround; x = m.bodies[x].parent)
    if (isAncestor(m, x, b)) return x;
  return kGround;
}

}  // namespace

int ModelBuilder::addBody(Body body) {
  const int index = static_cast<int>(model_.bodies.size());
  const std::string what = "body '" + body.name + "'";
  if (model_.bodyIndex(body.name) >= 0) throw ModelError(what + ": duplicate body name");
  if (body.parent != kGround && (body.parent < 0 || body.parent >= index))
    throw ModelError(what + ": parent must be the ground or a body defined before it");
  // A pure rotor (a flywheel whose mass another body carries): no mass, no
  // rigid-body inertia, its rotor inertia about its revolute joint's axis.
  const bool rotorOnly = body.mass == 0.0 && body.inertia.isZero(0.0) && body.rotorInertia > 0 &&
                         body.joint == JointType::Revolute &&
                         body.rotorAxis.normalized().cross(body.inChild.axes.col(2)).norm() < 1e-9;
  if (!rotorOnly) {
    if (!(body.mass > 0) || !std::isfinite(body.mass))
      throw ModelError(what + ": mass must be positive (got " + std::to_string(body.mass) + " kg)");
    if (!body.inertia.allFinite() || (body.inertia - body.inertia.transpose()).norm() > 1e-9 * body.inertia.norm())
      throw ModelError(what + ": inertia must be a finite symmetric matrix");
    Eigen::SelfAdjointEigenSolver<Mat3> eig(body.inertia);
    const Vec3 p = eig.eigenvalues();  // ascending
    if (!(p(0) > 0) || p(0) + p(1) < p(2) * (1 - 1e-9))
      throw ModelError(what + ": inertia must be positive definite and satisfy the triangle inequality"
                              " (principal moments " + std::to_string(p(0)) + ", " + std::to_string(p(1)) +
                       ", " + std::to_string(p(2)) + " kg m^2)");
  }
  if (!body.com.allFinite()) throw ModelError(what + ": centre of mass must be finite");
  checkAxes(body.inParent.axes, what + " joint '" + body.jointName + "' parent frame");
  checkAxes(body.inChild.axes, what + " joint '" + body.jointName + "' child frame");
  if (body.joint == JointType::Free && body.parent != kGround)
    throw ModelError(what + ": a free joint must connect the body to the ground");
  if (body.joint == JointType::Tabulated1 || body.joint == JointType::Tabulated2) {
    if (body.table < 0 || body.table >= static_cast<int>(model_.tables.size()))
      throw ModelError(what + ": a tabulated joint needs a table added before it");
    const int dims = model_.tables[body.table].grid.dimensions();
    if (dims != (body.joint == JointType::Tabulated1 ? 1 : 2))
      throw ModelError(what + ": the joint's table has " + std::to_string(dims) + " coordinate(s)");
    if (!body.inParent.origin.isZero(0.0) || !body.inChild.origin.isZero(0.0) ||
        !body.inParent.axes.isIdentity(0.0) || !body.inChild.axes.isIdentity(0.0))
      throw ModelError(what + ": a tabulated joint's frames are the body frames");
  }
  if (!(body.rotorInertia >= 0) || !std::isfinite(body.rotorInertia))
    throw ModelError(what + ": rotor inertia must be non-negative");
  const Vec3 axis = body.rotorAxis.normalized();
  body.spatialInertia =
      spatialInertia(body.mass, body.com, body.inertia + body.rotorInertia * axis * axis.transpose());
  model_.bodies.push_back(std::move(body));
  return index;
}

int ModelBuilder::addCutJoint(CutJoint cut) {
  const int nb = static_cast<int>(model_.bodies.size());
  const std::string what = "cut joint '" + cut.name + "'";
  auto checkBody = [&](int b, const char* which) {
    if (b != kGround && (b < 0 || b >= nb)) throw ModelError(what + ": " + which + " is not a body of the model");
  };
  if (cut.type == CutJointType::Driver) {
    checkBody(cut.drivenBody, "driven body");
    if (cut.drivenBody == kGround) throw ModelError(what + ": the driven body must not be the ground");
    const JointType t = model_.bodies[cut.drivenBody].joint;
    const bool scalar = t == JointType::Revolute || t == JointType::Prismatic || t == JointType::Tabulated1;
    if (!scalar && t != JointType::Tabulated2)
      throw ModelError(what + ": a driver needs a revolute, prismatic or tabulated joint");
    if (cut.drivenCoordinate < 0 || cut.drivenCoordinate >= jointNv(t))
      throw ModelError(what + ": the driven joint has no coordinate " + std::to_string(cut.drivenCoordinate));
    cut.driverSlot = model_.nDrivers++;
  } else {
    checkBody(cut.bodyA, "body A");
    checkBody(cut.bodyB, "body B");
    if (cut.bodyA == cut.bodyB) throw ModelError(what + ": both ends are on the same body");
    if (cut.type == CutJointType::Distance && !(cut.length > 0))
      throw ModelError(what + ": length must be positive");
  }
  model_.cutJoints.push_back(std::move(cut));
  return static_cast<int>(model_.cutJoints.size()) - 1;
}

void ModelBuilder::addSpring(SpringDamper s) {
  const int nb = static_cast<int>(model_.bodies.size());
  for (int b : {s.bodyA, s.bodyB})
    if (b != kGround && (b < 0 || b >= nb))
      throw ModelError("spring '" + s.name + "': attached to a body that does not exist");
  for (const ForceCurve* c : {&s.spring, &s.damper}) {
    if (c->x.size() != c->force.size())
      throw ModelError("spring '" + s.name + "': curve has different numbers of x and force values");
    for (size_t i = 1; i < c->x.size(); ++i)
      if (!(c->x[i] > c->x[i - 1]))
        throw ModelError("spring '" + s.name + "': curve x values must increase strictly");
  }
  if (s.tableBody >= 0) {
    if (s.tableBody >= nb || model_.bodies[s.tableBody].table < 0)
      throw ModelError("spring '" + s.name + "': its length table belongs to a body without a tabulated joint");
    const JointTable& t = model_.tables[model_.bodies[s.tableBody].table];
    if (s.tableComponent < JointTable::kPoseComponents || s.tableComponent >= t.grid.components())
      throw ModelError("spring '" + s.name + "': its length is not a component of the joint table");
  }
  model_.springs.push_back(std::move(s));
}

int ModelBuilder::addTable(JointTable table) {
  if (table.grid.components() < JointTable::kPoseComponents)
    throw ModelError("joint table: needs the 6 pose components");
  model_.tables.push_back(std::move(table));
  return static_cast<int>(model_.tables.size()) - 1;
}

namespace {

// Motion (lin; ang) at the child joint frame origin in joint-frame axes,
// expressed at the body origin in body axes.
Vec6 jointMotionToBody(const Body& b, const Vec6& m) {
  const Mat3& Cc = b.inChild.axes;
  Vec6 out;
  out.tail<3>() = Cc * m.tail<3>();
  out.head<3>() = Cc * m.head<3>() + b.inChild.origin.cross(out.tail<3>());
  return out;
}

void precomputeJoint(Body& b) {
  b.restRotation = b.inParent.axes * b.inChild.axes.transpose();
  b.axisInParent = b.inParent.axes.col(2);
  const Mat3 A = skew(b.axisInParent);
  b.rodrigues1 = A * b.restRotation;
  b.rodrigues2 = A * A * b.restRotation;
  b.identityAxes = b.inParent.axes.isIdentity(0.0) && b.inChild.axes.isIdentity(0.0);
}

}  // namespace

Model ModelBuilder::build() {
  pinMatrixBlocking();  // every vehicle path starts here: its sweeps and equilibria are products too
  Model m = model_;
  int q = 0, v = 0;
  for (auto& b : m.bodies) {
    b.qIndex = q;
    b.nq = jointNq(b.joint);
    b.vIndex = v;
    b.nv = jointNv(b.joint);
    q += b.nq;
    v += b.nv;
    precomputeJoint(b);
  }
  m.S.setZero(6, v);
  const Eigen::VectorXd q0 = [&] {
    Eigen::VectorXd z = Eigen::VectorXd::Zero(q);
    for (const auto& b : m.bodies) {
      if (b.joint == JointType::Spherical) z(b.qIndex) = 1.0;
      if (b.joint == JointType::Free) z(b.qIndex + 3) = 1.0;
    }
    return z;
  }();
  SubspaceBlock Sj;
  for (const auto& b : m.bodies) {
    jointSubspace(b.joint, q0.data() + b.qIndex, Sj);
    for (int k = 0; k < b.nv; ++k) m.S.col(b.vIndex + k) = jointMotionToBody(b, Sj.col(k));
  }
  int row = 0;
  for (auto& c : m.cutJoints) {
    c.row = row;
    c.rows = (c.type == CutJointType::Spherical) ? 3 : 1;
    if (c.type != CutJointType::Driver) c.frameBody = commonAncestor(m, c.bodyA, c.bodyB);
    row += c.rows;
  }
  m.nq = q;
  m.nv = v;
  m.nc = row;
  return m;
}

void refreshJointFrames(Model& m, int body) {
  Body& b = m.bodies[body];
  precomputeJoint(b);
  Eigen::VectorXd q0 = neutralPositions(m);
  SubspaceBlock Sj;
  jointSubspace(b.joint, q0.data() + b.qIndex, Sj);
  for (int k = 0; k < b.nv; ++k) m.S.col(b.vIndex + k) = jointMotionToBody(b, Sj.col(k));
}

Eigen::VectorXd neutralPositions(const Model& model) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(model.nq);
  for (const auto& b : model.bodies) {
    if (b.joint == JointType::Spherical) q(b.qIndex) = 1.0;         // quaternion w
    if (b.joint == JointType::Free) q(b.qIndex + 3) = 1.0;          // (x y z | w x y z)
  }
  return q;
}

JointFrame frameAt(const Pose& body, const Vec3& worldPoint, const Mat3& worldAxes) {
  JointFrame f;
  f.origin = body.R.transpose() * (worldPoint - body.p);
  f.axes = body.R.transpose() * worldAxes;
  return f;
}

Mat3 axesWithZ(const Vec3& zIn) {
  const Vec3 z = zIn.normalized();
  const Vec3 helper = std::abs(z.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 x = (helper - helper.dot(z) * z).normalized();
  Mat3 A;
  A.col(0) = x;
  A.col(1) = z.cross(x);
  A.col(2) = z;
  return A;
}

Mat3 axesWithXY(const Vec3& xIn, const Vec3& yIn) {
  const Vec3 x = xIn.normalized();
  const Vec3 y = (yIn - yIn.dot(x) * x).normalized();
  Mat3 A;
  A.col(0) = x;
  A.col(1) = y;
  A.col(2) = x.cross(y);
  return A;
}

}  // namespace bdfcar::mb
