// Kinematics of one tree joint: the pose of the child joint frame relative to
// the parent joint frame, the motion subspace, and the manifold operations
// (retraction, local coordinates, rate of local coordinates) that let the
// integrators treat rotations without singularities.
//
// Rotations are unit quaternions (w, x, y, z) in q; their velocities are the
// angular velocity in the child joint frame; increments are rotation vectors
// applied on the right: R' = R exp(dtheta).
#pragma once

#include "multibody/model.h"

namespace bdfcar::mb {

using SubspaceBlock = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6>;

// Child joint frame relative to the parent joint frame: rotation Rj, origin dj.
void jointRelativePose(JointType type, const double* q, Mat3& Rj, Vec3& dj);

// Motion subspace (lin; ang) of the joint in the child joint frame (6 x nv).
void jointSubspace(JointType type, const double* q, SubspaceBlock& Sj);

// q (+) dq: move the coordinates by a tangent increment dq (size nv).
void jointRetract(JointType type, const double* q, const double* dq, double* out);
// Local coordinates of q around base: base (+) out = q.
void jointLocal(JointType type, const double* base, const double* q, double* out);
// The planar joint's two above with the sine and cosine of the base's
// heading (q[2], base[2]) given: a caller that moves many increments around
// one base computes them once.
void planarRetract(const double* q, const double* dq, double s, double c, double* out);
void planarLocal(const double* base, const double* q, double s, double c, double* out);
// Time derivative of the local coordinates delta given the joint velocity v.
void jointLocalRate(JointType type, const double* delta, const double* v, double* out);

// Rotation matrix of a stored quaternion (w, x, y, z).
Mat3 quatToMatrix(const double* wxyz);

}  // namespace bdfcar::mb
