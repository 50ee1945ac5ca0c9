// The BDF step's vector work (bdf.cpp) on raw storage, written once for a
// size known at compile time and for any size (N = Eigen::Dynamic, the size
// at run time). A small system (the closed-form rungs: 9 to 15 coordinates,
// no constraint) pays more for a dynamic-size expression's set-up, its
// alignment peeling and remainder loops, than for its arithmetic: with N
// fixed each loop is straight-line vector code and each product an
// unrolled fixed-size one (a 9 x 9 matrix-vector product: 129 instructions
// against 339). Element-wise sums keep the order of the nodes and
// coordinates whatever N, so the dynamic path gives the bits it always did;
// a fixed-size product sums in another order than the dynamic one (the
// closed forms' last bits differ between the two, each deterministic).
#pragma once

#include <Eigen/Core>

namespace bdfcar::integ::kernels {

// The BDF history terms xi and the predictor (BdfIntegrator::substep): with
// delta[i] the local coordinates of node i around node 0 (delta[0] = 0, not
// read), v[i] and a[i] its velocities and accelerations,
//   xiQ = sum_{i=1..k} xi[i] delta[i-1],  xiV = sum_{i=1..k} xi[i] v[i-1],
//   (dPred, vPred, aPred) = sum_{i<np} w[i] (delta[i], v[i], a[i]),
// and Newton's start (d, v, a) = the predictor.
struct History {
  int k = 0, np = 0;
  const double* xi = nullptr;  // [1..k]
  const double* w = nullptr;   // [0..np-1]
  const double* const* delta = nullptr;
  const double* const* v = nullptr;
  const double* const* a = nullptr;
};
struct Prediction {
  double *xiQ, *xiV, *dPred, *vPred, *aPred, *d, *v, *a;
};

// The BDF residuals of an iterate, rhoQ = d - xiQ - h' rate and
// rhoV = v - xiV - h' a, and the right-hand side of eq. 3.8's velocity rows,
// rhs = -h'^2 F - h' F_v rhoQ - F_a (rhoQ + h' rhoV) (tmp: rhoQ + h' rhoV).
struct Iterate {
  const double *d, *v, *a, *rate, *xiQ, *xiV, *F, *Fv, *Fa;
};
struct Residuals {
  double *rhoQ, *rhoV, *tmp, *rhs;
};

// The correction applied: d += dq, v += dv, a += da; returns the sum of
// squares of the weighted correction [dq; h' dv] / (atol + rtol |d|) over
// the coordinates in order, and adds x - x of each new d, v, a to
// nonFinite (0 while every one is finite).
struct Update {
  double *d, *v, *a;
  const double *dq, *dv, *da;
  double atol, rtol, hPrime;
};

struct StepKernels {
  void (*predict)(int n, const History& h, const Prediction& out);
  void (*residuals)(int n, double hPrime, const Iterate& in, const Residuals& out);
  // x = A b, A n x n column-major.
  void (*product)(int n, const double* A, const double* b, double* x);
  // out = c (x + y).
  void (*scaledSum)(int n, double c, const double* x, const double* y, double* out);
  double (*update)(int n, const Update& u, double& nonFinite);
};

// Fixed-size kernels for a system of nv velocity coordinates without
// constraints (nc == 0) up to 16 of them, the dynamic ones otherwise.
const StepKernels& stepKernels(int nv, int nc);

}  // namespace bdfcar::integ::kernels
