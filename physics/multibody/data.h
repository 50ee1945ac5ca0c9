// Per-evaluation workspace of a Model (as MuJoCo's mjData): inputs set by the
// caller, then fields "computed by" each stage of the forward pass. Sized once
// by makeData(); evaluating a model never allocates afterwards.
#pragma once

#include <array>
#include <vector>

#include "multibody/model.h"
#include "multibody/time_signal.h"

namespace bdfcar::mb {

struct Data {
  // --- inputs ---
  std::vector<const TimeSignal*> driverSignals;  // (nDrivers) prescribed motions; null = held at 0

  // --- computed by updatePositions (q) ---
  std::vector<Transform> Xup;     // (nbody) parent -> body motion transform
  std::vector<Mat3> R;            // (nbody) body axes in world
  std::vector<Vec3> p;            // (nbody) body origin in world
  Eigen::Matrix<double, 6, Eigen::Dynamic> S;  // (6 x nv) joint motion subspaces, body coordinates
  // (nbody) sine and cosine of a universal joint's second angle, on which its
  // subspace and its rate bias depend (taken once per evaluation).
  std::vector<std::array<double, 2>> secondAngleSinCos;

  // Tabulated joints (one entry per Model::tables): the table at the joint
  // coordinates, and d S_k / d c_l of the subspace columns (index 2 k + l).
  std::vector<SplineGrid::Sample> tableSamples;
  std::vector<std::array<Vec6, 4>> tableSubspaceDerivatives;

  // --- computed by updateVelocities (v) ---
  std::vector<Vec6> vel;          // (nbody) spatial velocity (v; w), body coordinates
  std::vector<Vec6> bias;         // (nbody) velocity-product acceleration c_J + v x S qdot
  std::vector<std::array<double, 2>> tableRates;  // (ntables) joint coordinate rates of the tabulated joints

  // --- computed by updateAccelerations (a) ---
  std::vector<Vec6> acc;          // (nbody) spatial acceleration, body coordinates

  // --- forces: applied wrenches accumulate here (body coordinates, at body origin) ---
  std::vector<Vec6> fext;         // (nbody)
  std::vector<Vec6> f;            // (nbody) joint wrench from the backward pass
  Eigen::VectorXd jointForce;     // (nv) applied joint-space forces (drive, brake torques)
  Eigen::VectorXd tau;            // (nv) joint-space inverse dynamics + constraint forces

  // --- constraints: computed by constraintResiduals ---
  Eigen::VectorXd phi, phiDot, phiDDot;  // (nc) the three constraint levels
  std::vector<SignalValue> driverTargets;  // (nDrivers) sampled at the evaluation time

  // --- computed by massMatrix (CRBA) ---
  std::vector<Mat6> Ic;           // (nbody) composite inertias

  // --- spring-damper state, for telemetry: computed by applySprings ---
  std::vector<double> springLength, springLengthRate, springForce;  // (nspring)
};

Data makeData(const Model& model);

// World pose of a body (identity for the ground).
inline Mat3 bodyRotation(const Data& d, int body) { return body < 0 ? Mat3::Identity() : d.R[body]; }
inline Vec3 bodyOrigin(const Data& d, int body) { return body < 0 ? Vec3::Zero() : d.p[body]; }

// World position of a point fixed in a body (inline: on every residual's path).
inline Vec3 pointPosition(const Data& d, int body, const Vec3& s) {
  if (body < 0) return s;
  return d.p[body] + d.R[body] * s;
}

// World velocity of a point fixed in a body.
inline Vec3 pointVelocity(const Data& d, int body, const Vec3& s) {
  if (body < 0) return Vec3::Zero();
  const Vec6& v = d.vel[body];
  return d.R[body] * (v.head<3>() + v.tail<3>().cross(s));
}

// World (classical) acceleration of a point fixed in a body.
inline Vec3 pointAcceleration(const Data& d, int body, const Vec3& s) {
  if (body < 0) return Vec3::Zero();
  const Vec6& v = d.vel[body];
  const Vec6& a = d.acc[body];
  const Vec3 w = v.tail<3>();
  const Vec3 vp = v.head<3>() + w.cross(s);
  return d.R[body] * (a.head<3>() + a.tail<3>().cross(s) + w.cross(vp));
}

// World angular velocity of a body.
inline Vec3 angularVelocity(const Data& d, int body) {
  if (body < 0) return Vec3::Zero();
  return d.R[body] * d.vel[body].tail<3>();
}

// Adds a world-frame force applied at a world point to a body.
inline void addWorldForce(Data& d, int body, const Vec3& point, const Vec3& force) {
  if (body < 0) return;
  const Mat3& R = d.R[body];
  const Vec3 fb = R.transpose() * force;
  const Vec3 sb = R.transpose() * (point - d.p[body]);
  d.fext[body].head<3>() += fb;
  d.fext[body].tail<3>() += sb.cross(fb);
}

// A world-frame force at a world point and a world-frame torque as a spatial
// force in the body's coordinates (what addWorldWrench adds to fext).
inline Vec6 bodyWrench(const Data& d, int body, const Vec3& point, const Vec3& force, const Vec3& torque) {
  const Mat3& R = d.R[body];
  Vec6 f;
  f.head<3>() = R.transpose() * force;
  f.tail<3>() = (R.transpose() * (point - d.p[body])).cross(f.head<3>()) + R.transpose() * torque;
  return f;
}

// Adds a world-frame force at a world point and a world-frame torque to a body.
inline void addWorldWrench(Data& d, int body, const Vec3& point, const Vec3& force, const Vec3& torque) {
  if (body < 0) return;
  addWorldForce(d, body, point, force);
  d.fext[body].tail<3>() += d.R[body].transpose() * torque;
}

}  // namespace bdfcar::mb
