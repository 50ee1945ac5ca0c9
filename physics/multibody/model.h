// The immutable description of a multibody system in relative (joint)
// coordinates: a spanning tree of bodies connected by tree joints, closed
// loops cut at cut joints (constraints with Lagrange multipliers), force
// elements and gravity. Built once (ModelBuilder), then read-only while
// stepping; all per-evaluation scratch lives in Data (data.h).
#pragma once

#include <string>
#include <vector>

#include "multibody/spatial.h"
#include "multibody/spline_grid.h"

namespace bdfcar::mb {

constexpr int kGround = -1;

// Tree joint types. Axis conventions are in the joint frames: revolute about
// z, prismatic along z, cylindrical about and along z, universal about x of
// the parent joint frame then y of the child joint frame, spherical any
// rotation about the joint point, free: the body frame relative to the parent
// joint frame (position + rotation). Tabulated1 / Tabulated2: the body frame
// relative to the parent body frame is a tabulated function of one or two
// coordinates (a JointTable; e.g. a wheel carrier moving with suspension
// travel and rack travel as the linkage it stands for moves it). Planar:
// translation in the x-y plane of the parent joint frame and rotation about
// its z (a vehicle on level ground without heave, roll or pitch); q = (x, y,
// angle), v = (forward, sideways, angular rate) in the child joint frame.
enum class JointType { Revolute, Prismatic, Cylindrical, Universal, Spherical, Free, Tabulated1, Tabulated2, Planar };

// Number of position coordinates (rotations stored as unit quaternions).
int jointNq(JointType t);
// Number of velocity coordinates = relative degrees of freedom.
int jointNv(JointType t);
const char* jointTypeName(JointType t);

// A joint frame: origin and axes (columns) expressed in a body frame.
struct JointFrame {
  Vec3 origin = Vec3::Zero();
  Mat3 axes = Mat3::Identity();
};

// The pose of a tabulated joint's body frame in its parent body frame as a
// function of the joint coordinates c: grid components 0-2 are the origin,
// 3-5 the angles (psi, phi, theta) of R = rest Rz(psi) Rx(phi) Ry(theta)
// (no gimbal lock short of phi = 90 deg: a wheel carrier never gets there).
// Further components are lengths of tabulated spring-dampers (SpringDamper::
// tableComponent). Both joint frames of a tabulated joint are the body frames.
struct JointTable {
  SplineGrid grid;
  Mat3 rest = Mat3::Identity();
  static constexpr int kPoseComponents = 6;
};

// A body and the tree joint that connects it to its parent.
struct Body {
  std::string name;
  double mass = 0.0;
  Vec3 com = Vec3::Zero();           // centre of mass in body frame
  Mat3 inertia = Mat3::Zero();       // rotational inertia about the COM, body axes
  // A rotor spinning with the body about rotorAxis (body frame, through the
  // COM), e.g. an axle shaft tied to a wheel's spin: inertia about that axis
  // only, so it is not checked as a rigid body.
  double rotorInertia = 0.0;
  Vec3 rotorAxis = Vec3::UnitY();
  int parent = kGround;              // parent body index (kGround = the world)
  std::string jointName;
  JointType joint = JointType::Revolute;
  JointFrame inParent;               // joint frame fixed in the parent body (world if ground)
  JointFrame inChild;                // joint frame fixed in this body
  // Filled by the builder:
  int qIndex = 0, nq = 0;            // slice of the position vector
  int vIndex = 0, nv = 0;            // slice of the velocity vector
  Mat6 spatialInertia = Mat6::Zero();
  // Constant joint data, so that a kinematic pass is a few products per body:
  // child axes in parent coordinates at zero joint coordinates, and for
  // joints about the joint z axis a (revolute, cylindrical) the Rodrigues
  // terms [a]x R0 and [a]x^2 R0: R(theta) = R0 + sin(theta) P1 + (1 - cos(theta)) P2.
  Mat3 restRotation = Mat3::Identity();
  Mat3 rodrigues1 = Mat3::Zero(), rodrigues2 = Mat3::Zero();
  Vec3 axisInParent = Vec3::UnitZ();
  bool identityAxes = false;         // both joint frames have the body axes
  int table = -1;                    // Tabulated1/2: index in Model::tables
};

// Cut-joint (closed-loop) constraint types.
//  Spherical: point A on body A coincides with point B on body B (3 equations,
//             expressed in the frame of the nearest common ancestor body).
//  Distance:  |x_A - x_B| = length (1 equation), a massless link.
//  Driver:    a scalar joint coordinate follows a prescribed signal (1 equation).
enum class CutJointType { Spherical, Distance, Driver };

struct CutJoint {
  std::string name;
  CutJointType type = CutJointType::Spherical;
  int bodyA = kGround, bodyB = kGround;
  Vec3 pointA = Vec3::Zero(), pointB = Vec3::Zero();  // in body frames (world if ground)
  double length = 0.0;       // Distance
  int drivenBody = -1;       // Driver: body whose tree joint coordinate is prescribed
  int drivenCoordinate = 0;  // Driver: which of that joint's coordinates (0 but for Tabulated2)
  int driverSlot = 0;        // Driver: index of the signal in Data::drivers
  // Filled by the builder:
  int row = 0, rows = 0;     // slice of the constraint vector
  int frameBody = kGround;   // nearest common ancestor of A and B; Spherical equations are in its frame
};

// Force law of a spring or damper: linear coefficient, or a piecewise-linear
// table (x, F) with linear extrapolation beyond the ends.
struct ForceCurve {
  double coefficient = 0.0;
  std::vector<double> x, force;  // empty = linear
  // T double or ad::Dual (a closed form's Jacobian, autodiff.h; model.cpp).
  template <typename T>
  T eval(const T& x) const;
};

// Point-to-point spring-damper with optional bump and rebound stops.
// Positive force pushes the two points apart. Spring force is a function of
// compression (freeLength - L), damper force of the compression rate (-dL/dt).
struct SpringDamper {
  std::string name;
  int bodyA = kGround, bodyB = kGround;
  Vec3 pointA = Vec3::Zero(), pointB = Vec3::Zero();
  double freeLength = 0.0;
  double preload = 0.0;          // constant force added (N, + pushes apart)
  ForceCurve spring;             // force vs compression (m)
  ForceCurve damper;             // force vs compression rate (m/s)
  double bumpLength = 0.0;       // bump stop engages when L < bumpLength (0 = none)
  double bumpStiffness = 0.0;    // N/m
  double reboundLength = 0.0;    // rebound stop engages when L > reboundLength (0 = none)
  double reboundStiffness = 0.0;
  // A reduced model's correction (N, + apart), 0 in a linkage: the links'
  // weight along this element's travel that lumping them into the chassis
  // and the carrier put on the element (kinematic_model.h). It acts as the
  // element's force does but is not the element's: Parts::weight, outside
  // the spring, damper and stop a telemetry channel reports.
  double lumpedWeight = 0.0;
  // Tabulated length (a reduced model): the length is component
  // tableComponent of body tableBody's joint table, a function of that joint's
  // coordinates, and the force acts on them as the generalised force
  // F dL/dc (points unused). -1: a point-to-point element.
  int tableBody = -1, tableComponent = -1;
  // The force (+ = apart) at length L and rate dL/dt, by where it comes
  // from: the spring with its preload, the damper, the bump and rebound
  // stops, and a reduced model's lumped weight.
  // T double or ad::Dual (a closed form's Jacobian, autodiff.h; model.cpp).
  template <typename T>
  struct PartsT {
    T spring = T(0.0), damper = T(0.0), stop = T(0.0), weight = T(0.0);
    T total() const { return spring + damper + stop + weight; }
  };
  using Parts = PartsT<double>;
  template <typename T>
  PartsT<T> parts(const T& length, const T& lengthRate) const;
  template <typename T>
  T force(const T& length, const T& lengthRate) const {
    return parts(length, lengthRate).total();
  }
  Parts parts(double length, double lengthRate) const { return parts<double>(length, lengthRate); }
  double force(double length, double lengthRate) const { return parts<double>(length, lengthRate).total(); }
};

struct Model {
  std::vector<Body> bodies;          // topological order: parent index < own index
  std::vector<CutJoint> cutJoints;
  std::vector<SpringDamper> springs;
  std::vector<JointTable> tables;    // of the Tabulated1/2 joints
  Vec3 gravity = Vec3(0, 0, -9.81);
  int nq = 0, nv = 0, nc = 0;        // positions, velocities (= relative coordinates), constraint rows
  // Joint motion subspaces in body coordinates (6 x nv); constant except for
  // universal joints, whose columns updatePositions() rewrites in Data::S.
  Eigen::Matrix<double, 6, Eigen::Dynamic> S;
  int nDrivers = 0;

  int bodyIndex(const std::string& name) const;  // -1 if absent
  double totalMass() const;
};

// Builds a Model with checked indices; throws ModelError with a message
// naming the offending element.
class ModelBuilder {
 public:
  int addBody(Body body);
  int addCutJoint(CutJoint cut);
  void addSpring(SpringDamper s);
  int addTable(JointTable table);    // index for Body::table
  void setGravity(const Vec3& g) { model_.gravity = g; }
  Model build();  // validates, assigns coordinate and row slices

 private:
  Model model_;
};

// After a built model's joint frames of `body` were moved (a derived model
// adjusted in place): what build() computed from them, again.
void refreshJointFrames(Model& m, int body);

// Neutral (zero-displacement) position vector: identity quaternions, zeros.
Eigen::VectorXd neutralPositions(const Model& model);

// Design-configuration helpers: build joint frames from world positions.
struct Pose {
  Mat3 R = Mat3::Identity();
  Vec3 p = Vec3::Zero();
};
// The joint frame, fixed in a body whose design pose is `body`, that sits at
// the world point with the world axes at design (the joint is then at zero).
JointFrame frameAt(const Pose& body, const Vec3& worldPoint, const Mat3& worldAxes = Mat3::Identity());
// A right-handed orthonormal frame whose z axis is along `z`.
Mat3 axesWithZ(const Vec3& z);
// A right-handed orthonormal frame whose x axis is along `x` and y axis along
// the part of `y` orthogonal to x.
Mat3 axesWithXY(const Vec3& x, const Vec3& y);

}  // namespace bdfcar::mb
