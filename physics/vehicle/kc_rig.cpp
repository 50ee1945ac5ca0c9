#include "vehicle/kc_rig.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>

#include "config/units.h"
#include "multibody/kinematics.h"
#include "multibody/model_error.h"
#include "vehicle/linkage_sweep.h"
#include "vehicle/motion_ratio.h"
#include "vehicle/vehicle_sheet.h"
#include "portable_math.h"

namespace bdfcar::vehicle {

namespace {

using Eigen::VectorXd;
using Travels = std::array<double, 4>;

constexpr double kSide[4] = {1, -1, 1, -1};  // + left
constexpr double kH = 1e-4;                  // m (or rad of roll): central-difference step at a rig point

// One corner at one rig configuration, in the vehicle frame on the ground.
struct CornerPose {
  Vec3 centre, contact;
  Mat3 carrier;                 // the carrier's attitude
  double steer = 0, toe = 0, camber = 0;
  std::vector<double> lengths;  // of the corner's spring-dampers
};
using Poses = std::array<CornerPose, 4>;

// Rotation vector of Rp Rm^T, for close attitudes (rad).
Vec3 turnBetween(const Mat3& Rp, const Mat3& Rm) {
  const Mat3 t = Rp * Rm.transpose();
  return 0.5 * Vec3(t(2, 1) - t(1, 2), t(0, 2) - t(2, 0), t(1, 0) - t(0, 1));
}

// The linkage on the rig: solves configurations and reads the corners.
class Rig {
 public:
  explicit Rig(const Vehicle& v) : v_(v), ls_(v), rack0_(ls_.design()(v.layout.rackQ)), ratios_(motionRatios(v)) {
    for (size_t k = 0; k < ratios_.size(); ++k)
      if (ratios_[k].wheel >= 0) springs_[ratios_[k].wheel].push_back(static_cast<int>(k));
    for (int w = 0; w < 4; ++w)
      if (springs_[w].empty())
        throw mb::ModelError(std::string("K&C rig: no spring-damper moves with wheel ") + kCornerNames[w]);
  }

  const Vehicle& vehicle() const { return v_; }
  double rack0() const { return rack0_; }
  const VectorXd& design() const { return ls_.design(); }
  const std::vector<int>& springs(int w) const { return springs_[w]; }
  // dL/ds of spring-damper k at design (motion_ratio.h).
  double motionRatio(int k) const { return ratios_[k].ratio; }

  // Solves from q (updated) at travels s and rack coordinate r; throws if the linkage cannot be assembled there.
  Poses at(const Travels& s, double r, VectorXd& q) {
    if (!ls_.solve(s, r, q)) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "the linkage cannot be assembled at wheel travels %.3f %.3f %.3f %.3f m, rack %.4f m",
                    s[0], s[1], s[2], s[3], r);
      throw mb::ModelError(buf);
    }
    return poses(ls_.at(q));
  }
  // The same from q, leaving q as it was.
  Poses near(const Travels& s, double r, const VectorXd& q) {
    VectorXd qq = q;
    return at(s, r, qq);
  }

  // The design configuration: the whole vehicle's centre of mass (vehicle frame).
  Vec3 centreOfMass() {
    const mb::Data& d = ls_.at(ls_.design());
    Vec3 sum = Vec3::Zero();
    for (size_t b = 0; b < v_.model.bodies.size(); ++b)
      sum += v_.model.bodies[b].mass * inVehicle(d, mb::pointPosition(d, static_cast<int>(b), v_.model.bodies[b].com));
    return sum / v_.model.totalMass();
  }

 private:
  // A world point in the vehicle frame on the ground under the chassis frame.
  Vec3 inVehicle(const mb::Data& d, const Vec3& x) const {
    const int ch = v_.layout.chassis;
    return d.R[ch].transpose() * (x - d.p[ch]) + Vec3(0, 0, v_.spec.designHeight);
  }

  Poses poses(const mb::Data& d) const {
    const int ch = v_.layout.chassis;
    Poses out;
    for (int w = 0; w < 4; ++w) {
      CornerPose& c = out[w];
      const int sp = v_.layout.wheels[w].spindle;
      c.centre = inVehicle(d, mb::pointPosition(d, sp, v_.model.bodies[sp].inChild.origin));
      Vec3 n = d.R[ch].transpose() * d.R[sp].col(1);  // spin axis
      if (n.y() < 0) n = -n;                           // pointing left
      c.steer = pm::atan2(-n.x(), n.y());
      c.toe = -kSide[w] * c.steer;
      c.camber = -kSide[w] * pm::asin(std::clamp(n.z(), -1.0, 1.0));
      // Down the wheel's plane from the centre to the ground.
      const Vec3 down = n.cross(n.cross(Vec3::UnitZ()).normalized());
      c.contact = c.centre + (c.centre.z() / -down.z()) * down;
      c.carrier = d.R[ch].transpose() * d.R[v_.layout.wheels[w].carrier];
      for (int k : springs_[w]) {
        const mb::SpringDamper& e = v_.model.springs[k];
        c.lengths.push_back((mb::pointPosition(d, e.bodyA, e.pointA) - mb::pointPosition(d, e.bodyB, e.pointB)).norm());
      }
    }
    return out;
  }

  const Vehicle& v_;
  LinkageSweep ls_;
  double rack0_;
  std::vector<MotionRatio> ratios_;
  std::array<std::vector<int>, 4> springs_;
};

Travels parallel(double s) { return {s, s, s, s}; }
// Wheel travels for body roll phi (+ left side up: left wheels in rebound).
Travels rolled(double phi, const std::array<double, 2>& track) {
  Travels s;
  for (int w = 0; w < 4; ++w) s[w] = -kSide[w] * 0.5 * track[w / 2] * phi;
  return s;
}

// Rate of change of the carrier's point at corner w's contact point (the
// wheel's point touching the ground, moving with the wheel and its carrier):
// between poses p and m of the swept variable 2h apart, around p0.
Vec3 contactPointRate(const Poses& p0, const Poses& p, const Poses& m, int w, double h) {
  const Vec3 omega = turnBetween(p[w].carrier, m[w].carrier) / (2 * h);
  return (p[w].centre - m[w].centre) / (2 * h) + omega.cross(p0[w].contact - p0[w].centre);
}

// Front-view roll centre of an axle (the instant-centre construction): each
// contact point turns about a centre on the line through it perpendicular
// to its motion with parallel travel; the two lines meet at the roll centre.
// Returns (y, z); NaN if the lines are parallel.
Eigen::Vector2d rollCentre(const Poses& p0, const Poses& p, const Poses& m, int left) {
  Eigen::Matrix2d A;
  Eigen::Vector2d b;
  for (int k = 0; k < 2; ++k) {
    const int w = left + k;
    const Vec3 v = contactPointRate(p0, p, m, w, 1.0), c = p0[w].contact;
    A.row(k) << v.y(), v.z();
    b(k) = v.y() * c.y() + v.z() * c.z();
  }
  if (std::abs(A.determinant()) < 1e-14 * A.squaredNorm()) return Eigen::Vector2d(NAN, NAN);
  return A.partialPivLu().solve(b);
}

// Samples of a sweep from its centre outwards, each solve starting from its
// neighbour's solution: record(i, q) at each of n points over [-range, range].
void sweep(Rig& rig, int n, double range, const std::function<std::pair<Travels, double>(double)>& config,
           const std::function<void(int, double, const Poses&, const VectorXd&)>& record) {
  const int c = n / 2;
  VectorXd qc = rig.design();
  for (int dir : {+1, -1}) {
    VectorXd q = qc;
    for (int i = dir > 0 ? c : c - 1; i >= 0 && i < n; i += dir) {
      const double x = -range + 2 * range * i / (n - 1);
      const auto [s, r] = config(x);
      const Poses p = rig.at(s, r, q);
      if (i == c) qc = q;
      record(i, x, p, q);
    }
  }
}

KcColumn& column(KcTable& t, const std::string& name, const std::string& unit, int n) {
  t.columns.push_back({name, unit, std::vector<double>(n, NAN)});
  return t.columns.back();
}

// The parallel-travel table: travel, per corner toe, camber, wheel-centre x,
// contact-point y, spring-damper lengths and motion ratios, per axle track
// and roll-centre height.
KcTable parallelTable(Rig& rig, int n, double range) {
  const Vehicle& v = rig.vehicle();
  KcTable t{"parallel_travel", {}};
  column(t, "travel", "m", n);
  for (int w = 0; w < 4; ++w) {
    const std::string c = kCornerNames[w];
    for (const char* q : {"toe_", "camber_"}) column(t, q + c, "rad", n);
    column(t, "wheel_centre_x_" + c, "m", n);
    column(t, "contact_y_" + c, "m", n);
    for (int k : rig.springs(w)) {
      column(t, "length_" + v.model.springs[k].name, "m", n);
      column(t, "motion_ratio_" + v.model.springs[k].name, "m/m", n);
    }
  }
  for (const char* a : {"front", "rear"}) {
    column(t, std::string("track_") + a, "m", n);
    column(t, std::string("roll_centre_") + a, "m", n);
  }
  sweep(rig, n, range, [&](double s) { return std::pair{parallel(s), rig.rack0()}; },
        [&](int i, double s, const Poses& p, const VectorXd& q) {
          const Poses pp = rig.near(parallel(s + kH), rig.rack0(), q), pm = rig.near(parallel(s - kH), rig.rack0(), q);
          int col = 0;
          t.columns[col++].values[i] = s;
          for (int w = 0; w < 4; ++w) {
            t.columns[col++].values[i] = p[w].toe;
            t.columns[col++].values[i] = p[w].camber;
            t.columns[col++].values[i] = p[w].centre.x();
            t.columns[col++].values[i] = p[w].contact.y();
            for (size_t k = 0; k < p[w].lengths.size(); ++k) {
              t.columns[col++].values[i] = p[w].lengths[k];
              t.columns[col++].values[i] = (pp[w].lengths[k] - pm[w].lengths[k]) / (2 * kH);
            }
          }
          for (int a = 0; a < 2; ++a) {
            t.columns[col++].values[i] = p[2 * a].contact.y() - p[2 * a + 1].contact.y();
            t.columns[col++].values[i] = rollCentre(p, pp, pm, 2 * a)(1);
          }
        });
  return t;
}

// The roll table: body roll, per corner travel, toe and camber to the ground.
KcTable rollTable(Rig& rig, int n, double range, const std::array<double, 2>& track) {
  KcTable t{"roll", {}};
  column(t, "roll", "rad", n);
  for (int w = 0; w < 4; ++w) {
    const std::string c = kCornerNames[w];
    column(t, "travel_" + c, "m", n);
    column(t, "toe_" + c, "rad", n);
    column(t, "camber_to_ground_" + c, "rad", n);
  }
  sweep(rig, n, range, [&](double phi) { return std::pair{rolled(phi, track), rig.rack0()}; },
        [&](int i, double phi, const Poses& p, const VectorXd&) {
          t.columns[0].values[i] = phi;
          const Travels s = rolled(phi, track);
          for (int w = 0; w < 4; ++w) {
            t.columns[1 + 3 * w].values[i] = s[w];
            t.columns[2 + 3 * w].values[i] = p[w].toe;
            t.columns[3 + 3 * w].values[i] = p[w].camber - kSide[w] * phi;  // the body's roll tilts every wheel toward -y
          }
        });
  return t;
}

// The steering table over the full steer range (normalised steer -1..1):
// rack, steering-wheel angle, front road-wheel angles and the outer angle
// Ackermann geometry would give for the inner one. Keeps each sample's
// solution for the Ackermann figure.
KcTable steeringTable(Rig& rig, int n, double wheelbase, double track, std::vector<VectorXd>& solutions) {
  const SteeringSpec& st = rig.vehicle().spec.steering;
  const double rackPerSteer = -rig.vehicle().layout.rackAxisSign * st.rackTravelFull;
  KcTable t{"steering", {}};
  for (auto [name, unit] : {std::pair{"steer", "1"}, {"rack", "m"}, {"steering_wheel", "rad"}, {"steer_FL", "rad"},
                            {"steer_FR", "rad"}, {"ackermann_outer", "rad"}})
    column(t, name, unit, n);
  solutions.assign(n, VectorXd());
  sweep(rig, n, 1.0, [&](double u) { return std::pair{parallel(0), rig.rack0() + rackPerSteer * u}; },
        [&](int i, double u, const Poses& p, const VectorXd& q) {
          const double inner = u >= 0 ? p[0].steer : p[1].steer;
          const double values[6] = {u, rackPerSteer * u, st.steeringWheelFull * u, p[0].steer, p[1].steer,
                                    std::copysign(ackermannOuter(std::abs(inner), wheelbase, track), inner)};
          for (int k = 0; k < 6; ++k) t.columns[k].values[i] = values[k];
          solutions[i] = q;
        });
  return t;
}

// Ackermann % at 10 deg of the inner (left, turning left) road-wheel angle:
// the rack found by bisection between the steering sweep's samples.
double ackermannAtTenDegrees(Rig& rig, const KcTable& steering, const std::vector<VectorXd>& solutions,
                             double wheelbase, double track) {
  const double inner = config::degToRad(10);
  const std::vector<double>& rack = steering.columns[1].values;
  const std::vector<double>& left = steering.columns[3].values;
  for (size_t i = 0; i + 1 < left.size(); ++i) {
    if (!(left[i] <= inner && left[i + 1] >= inner)) continue;
    double lo = rack[i], hi = rack[i + 1];
    Poses p;
    for (int it = 0; it < 40; ++it) {
      p = rig.near(parallel(0), rig.rack0() + 0.5 * (lo + hi), solutions[i]);
      (p[0].steer < inner ? lo : hi) = 0.5 * (lo + hi);
    }
    return ackermannPercent(p[0].steer, p[1].steer, wheelbase, track);
  }
  return NAN;  // the steering does not reach it
}

// The steering axis of corner w at q (see KcCorner).
void steeringAxis(Rig& rig, const VectorXd& q, const Poses& p0, int w, KcCorner& c) {
  const double hr = 1e-5;  // m of rack
  const Poses rp = rig.near(parallel(0), rig.rack0() + hr, q), rm = rig.near(parallel(0), rig.rack0() - hr, q);
  const Poses sp = rig.near(parallel(kH), rig.rack0(), q), sm = rig.near(parallel(-kH), rig.rack0(), q);
  // Twists of the carrier (angular velocity, velocity of the wheel centre)
  // per unit rack and per unit travel, and the spring-damper's length rates.
  const Vec3 wr = turnBetween(rp[w].carrier, rm[w].carrier) / (2 * hr), vr = (rp[w].centre - rm[w].centre) / (2 * hr);
  const Vec3 ws = turnBetween(sp[w].carrier, sm[w].carrier) / (2 * kH), vs = (sp[w].centre - sm[w].centre) / (2 * kH);
  const double lr = (rp[w].lengths[0] - rm[w].lengths[0]) / (2 * hr), ls = (sp[w].lengths[0] - sm[w].lengths[0]) / (2 * kH);
  c.steered = wr.norm() > 1e-3;  // rad per m of rack
  if (!c.steered) {
    c.caster = c.kingpinInclination = c.scrubRadius = c.trail = NAN;
    return;
  }
  // The rack's motion with the travel that keeps the spring-damper's length.
  Vec3 omega = wr - (lr / ls) * ws;
  const Vec3 v = vr - (lr / ls) * vs;
  const Vec3 onAxis = p0[w].centre + omega.cross(v) / omega.squaredNorm();  // the axis point nearest the centre
  if (omega.z() < 0) omega = -omega;
  const Vec3 a = omega.normalized();
  const Vec3 ground = onAxis - (onAxis.z() / a.z()) * a;
  c.caster = pm::atan2(-a.x(), a.z());
  c.kingpinInclination = pm::atan2(-kSide[w] * a.y(), a.z());
  c.scrubRadius = kSide[w] * (p0[w].contact.y() - ground.y());
  c.trail = ground.x() - p0[w].contact.x();
}

// Wheel rate of corner w: minus the derivative of the springs' generalised
// force along travel, sum of F(L) dL/ds, by differences over 2 mm.
double wheelRate(Rig& rig, int w) {
  const double h = 1e-3;
  std::array<Poses, 5> p;
  for (int k = 0; k < 5; ++k) p[k] = rig.near(parallel((k - 2) * h), rig.rack0(), rig.design());
  double force[2] = {0, 0};
  for (int side = 0; side < 2; ++side) {
    const int k = 1 + 2 * side;  // at -h and +h
    for (size_t j = 0; j < rig.springs(w).size(); ++j) {
      const double dl = (p[k + 1][w].lengths[j] - p[k - 1][w].lengths[j]) / (2 * h);
      force[side] += rig.vehicle().model.springs[rig.springs(w)[j]].force(p[k][w].lengths[j], 0) * dl;
    }
  }
  return -(force[1] - force[0]) / (2 * h);
}

KcResult measure(Rig& rig, const KcRigSettings& set, double travel) {
  const Vehicle& v = rig.vehicle();
  KcResult out;
  out.travelRange = travel;
  const VectorXd q0 = rig.design();
  const double r0 = rig.rack0();
  const Poses p0 = rig.near(parallel(0), r0, q0);
  const Poses pp = rig.near(parallel(kH), r0, q0), pm = rig.near(parallel(-kH), r0, q0);
  std::array<double, 2> track{};
  for (int a = 0; a < 2; ++a) track[a] = p0[2 * a].contact.y() - p0[2 * a + 1].contact.y();
  const Poses rp = rig.near(rolled(kH, track), r0, q0), rm = rig.near(rolled(-kH, track), r0, q0);
  for (int w = 0; w < 4; ++w) {
    KcCorner& c = out.corner[w];
    c.toe = p0[w].toe;
    c.camber = p0[w].camber;
    c.bumpSteer = (pp[w].toe - pm[w].toe) / (2 * kH);
    c.camberGain = (pp[w].camber - pm[w].camber) / (2 * kH);
    c.halfTrackChange = kSide[w] * (pp[w].contact.y() - pm[w].contact.y()) / (2 * kH);
    c.rollSteer = (rp[w].toe - rm[w].toe) / (2 * kH);
    c.rollCamber = (rp[w].camber - rm[w].camber) / (2 * kH) - kSide[w];
    c.wheelRate = wheelRate(rig, w);
    for (int k : rig.springs(w)) {
      c.springNames.push_back(v.model.springs[k].name);
      c.motionRatio.push_back(rig.motionRatio(k));
    }
    steeringAxis(rig, q0, p0, w, c);
  }
  for (int a = 0; a < 2; ++a) {
    KcAxle& x = out.axle[a];
    const int l = 2 * a, r = l + 1;
    x.track = track[a];
    x.trackChange = out.corner[l].halfTrackChange + out.corner[r].halfTrackChange;
    x.rollCentre = rollCentre(p0, pp, pm, l)(1);
    x.rollSteer = 0.5 * ((rp[l].steer - rm[l].steer) + (rp[r].steer - rm[r].steer)) / (2 * kH);
  }
  // The migration from the roll centres 1 mm either side of design.
  const double d = 1e-3;
  auto rollCentreAt = [&](double s, int left) {
    const Poses c = rig.near(parallel(s), r0, q0);
    return rollCentre(c, rig.near(parallel(s + kH), r0, q0), rig.near(parallel(s - kH), r0, q0), left)(1);
  };
  for (int a = 0; a < 2; ++a)
    out.axle[a].rollCentreMigration = (rollCentreAt(d, 2 * a) - rollCentreAt(-d, 2 * a)) / (2 * d);

  // Anti-dive and anti-squat (side view): a longitudinal force F on a wheel
  // whose point of application moves dx/ds forward per metre of bump pushes
  // the suspension with F dx/ds; against the load transfer m a h / L, the
  // percentage is share x (dx/ds) x (L / h) x 100 (Milliken, RCVD 17.4).
  out.wheelbase = 0.5 * (p0[0].contact.x() + p0[1].contact.x() - p0[2].contact.x() - p0[3].contact.x());
  out.comHeight = rig.centreOfMass().z();
  auto slope = [&](int l, bool centre) {
    double sum = 0;
    for (int w : {l, l + 1})
      sum += centre ? (pp[w].centre.x() - pm[w].centre.x()) / (2 * kH) : contactPointRate(p0, pp, pm, w, kH).x();
    return sum / 2;
  };
  double brake[2] = {0, 0}, driven[2] = {0, 0};
  for (int w = 0; w < 4; ++w) {
    brake[w / 2] += v.wheel(w).brakeTorque;
    driven[w / 2] += v.wheel(w).driven ? 1 : 0;
  }
  const double lOverH = out.wheelbase / out.comHeight;
  out.brakeFront = brake[0] + brake[1] > 0 ? brake[0] / (brake[0] + brake[1]) : NAN;
  // Brakes react on the carrier: the force acts at the contact point.
  out.antiDive = 100 * out.brakeFront * slope(0, false) * lOverH;
  // A drive reacted by the chassis (or by nothing) acts at the wheel centre;
  // one reacted by the carrier (hub motor) at the contact point. The rear
  // squats: anti-squat when the point moves rearward in bump.
  const double rearDrive = driven[0] + driven[1] > 0 ? driven[1] / (driven[0] + driven[1]) : 0;
  out.antiSquat = rearDrive > 0 ? -100 * rearDrive * slope(2, v.spec.driveReaction != DriveReaction::Carrier) * lOverH : NAN;

  // Steering ratio at centre (the wheels at design height).
  const double rackPerSteer = -v.layout.rackAxisSign * v.spec.steering.rackTravelFull, du = 1e-3;
  const Poses up = rig.near(parallel(0), r0 + rackPerSteer * du, q0), um = rig.near(parallel(0), r0 - rackPerSteer * du, q0);
  const double perSteer = 0.25 * (up[0].steer + up[1].steer - um[0].steer - um[1].steer) / du;
  out.steeringRatio = perSteer != 0 ? v.spec.steering.steeringWheelFull / perSteer : NAN;

  // The curves. The roll sweep keeps each wheel within the travel reached.
  const int n = std::max(3, set.points | 1);  // odd: a sample at design
  out.tables.push_back(parallelTable(rig, n, travel));
  out.rollRange = std::min(set.roll, travel / (0.5 * std::max(track[0], track[1])));
  out.tables.push_back(rollTable(rig, n, out.rollRange, track));
  std::vector<VectorXd> solutions;
  out.tables.push_back(steeringTable(rig, n, out.wheelbase, track[0], solutions));
  out.ackermann = ackermannAtTenDegrees(rig, out.tables.back(), solutions, out.wheelbase, track[0]);
  return out;
}

}  // namespace

KcResult runKcRig(const Vehicle& linkage, const KcRigSettings& settings) {
  if (linkage.fidelity != Fidelity::Linkage) throw mb::ModelError("K&C rig: a linkage vehicle only");
  if (linkage.layout.rack < 0) throw mb::ModelError("K&C rig: the vehicle has no steering rack");
  std::optional<Rig> rig;
  try {
    rig.emplace(linkage);
  } catch (const mb::ModelError& e) {
    throw mb::ModelError(std::string("K&C rig: cannot sweep the linkage: ") + e.what());
  }
  // The widest travel the linkage reaches, from the settings' down to a quarter of it.
  double travel = settings.travel;
  for (int attempt = 0;; ++attempt) {
    try {
      return measure(*rig, settings, travel);
    } catch (const mb::ModelError& e) {
      if (attempt == 4) throw mb::ModelError(std::string("K&C rig: ") + e.what());
      travel *= 0.75;
    }
  }
}

}  // namespace bdfcar::vehicle
