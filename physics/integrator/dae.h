// The only view of a system the integrators have (as SUNDIALS IDA's residual):
// sizes, the manifold structure of the positions, the residuals of the
// over-determined DAE, and optional analytic Jacobian blocks (finite
// differences otherwise). The BDF code never knows it is integrating a car.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdio>
#include <cstring>
#include <vector>

namespace bdfcar::integ {

using Vec = Eigen::VectorXd;
using Mat = Eigen::MatrixXd;

struct DaeSizes {
  int nq = 0;  // stored position coordinates (rotations as quaternions)
  int nv = 0;  // velocity coordinates = tangent dimension of the positions
  int nc = 0;  // constraint equations
};

enum class EvalStatus { Ok, Recoverable, Fatal };

// A short reason attached to a non-Ok status: a C string in a fixed buffer
// (no allocation on the step path). Only the string is set and copied, not
// the buffer's 200 bytes: a step makes and returns a few reports whose
// messages are mostly empty.
class Message {
 public:
  Message() { text_[0] = '\0'; }
  Message(const Message& o) { copyFrom(o); }
  Message& operator=(const Message& o) {
    copyFrom(o);
    return *this;
  }
  template <typename... Args>
  void set(const char* fmt, Args... args) {
    std::snprintf(text_.data(), text_.size(), fmt, args...);
  }
  const char* c_str() const { return text_.data(); }

 private:
  void copyFrom(const Message& o) {
    if (&o != this) std::memcpy(text_.data(), o.text_.data(), std::strlen(o.text_.data()) + 1);
  }
  std::array<char, 200> text_;  // bytes past the string's end are unspecified
};

// Residuals of the over-determined DAE at one point.
struct Residual {
  Vec F;        // (nv) equations of motion F(q, v, a, lambda)
  Vec phi;      // (nc) Phi(q, t)
  Vec phiDot;   // (nc) Phi_q v + Phi_t
  Vec phiDDot;  // (nc) Phi_q a + (Phi_q v)_q v + Phi_tt
  void resize(const DaeSizes& s) {
    F.setZero(s.nv);
    phi.setZero(s.nc);
    phiDot.setZero(s.nc);
    phiDDot.setZero(s.nc);
  }
};

class Dae {
 public:
  virtual ~Dae() = default;
  virtual DaeSizes sizes() const = 0;

  // q (+) dq, dq a tangent increment (nv).
  virtual void retract(const Vec& q, const Vec& dq, Vec& out) const = 0;
  // Local coordinates of q around base (nv): base (+) out = q.
  virtual void localCoordinates(const Vec& base, const Vec& q, Vec& out) const = 0;
  // Time derivative of local coordinates delta given velocities v (identity for vector spaces).
  virtual void localRate(const Vec& delta, const Vec& v, Vec& out) const = 0;

  // Once per step, before the Newton iterations, at the predicted state
  // (per-step work such as terrain queries belongs here).
  virtual void beginStep(double /*t*/, const Vec& /*q*/, const Vec& /*v*/) {}

  // Once per accepted step of length h ending at t, with the accepted state:
  // advance the states a force law owns (e.g. tyre transient slips, backward
  // Euler over the step), prepare the next step, and check the state for
  // divergence (non-Ok stops the run with msg). Called right after the last
  // residual evaluation of the step, whose intermediate results (kinematics,
  // constraint values) differ from the accepted state only by the last Newton
  // correction (or, after a fast-column refresh, by a finite-difference
  // increment of one fast velocity, ~1e-8 relative): an implementation may
  // use them where that is immaterial.
  virtual EvalStatus acceptStep(double /*t*/, double /*h*/, const Vec& /*q*/, const Vec& /*v*/, Message& /*msg*/) {
    return EvalStatus::Ok;
  }

  // Residuals at (t, q, v, a, lambda). F always; the constraint levels only
  // when withConstraints (finite-difference columns need F alone).
  virtual EvalStatus residual(double t, const Vec& q, const Vec& v, const Vec& a, const Vec& lambda,
                              Residual& out, bool withConstraints, Message& msg) = 0;

  // Velocity coordinates whose F_v columns change much faster with the state
  // than the rest of the Jacobian (a wheel spin under its tyre's slip
  // stiffness, which falls tenfold when the tyre saturates; the tyre depends
  // on the spin rate, not the spin angle). When Newton stalls, the BDF
  // integrator re-evaluates these columns alone (a residual per column)
  // before it pays for the whole Jacobian. Empty: no such columns.
  virtual const std::vector<int>& fastColumns() const {
    static const std::vector<int> none;
    return none;
  }

  // The fast columns' fast part at the state of the last residual evaluation:
  // the share of dF/dv that the forces making them fast give (a tyre's and a
  // brake's dependence on its wheel's spin), from those force laws alone, in
  // the order of fastColumns() (nv x their number). The rest of a fast
  // column changes slowly, so a refresh takes (column at the Jacobian) -
  // (part there) + (part now): no residual. Without it (false), a refresh
  // takes a residual per column (finite differences).
  virtual bool hasFastColumnParts() const { return false; }
  virtual void fastColumnParts(double /*t*/, Mat& /*parts*/) {}
  // The same force laws' change, not their slope: how far the fast
  // coordinate fastColumns()[k]'s own equation (that row of F) moves when
  // its velocity moves by dv from the state of the last residual
  // evaluation, the rest held (exact for that dv, where fastColumnParts is
  // the slope at 0). What Newton needs to solve that row in its own
  // coordinate (BdfOptions::fastRowSolve): a saturating tyre makes it far
  // from linear within one correction. False: not given.
  virtual bool fastRowChange(double /*t*/, int /*k*/, double /*dv*/, double& /*change*/) { return false; }

  // Optional analytic blocks; return false to get finite differences.
  virtual bool massMatrix(double /*t*/, const Vec& /*q*/, Mat& /*Fa*/) { return false; }
  // F_q (along the retraction: column i the change by a tangent increment
  // e_i) and F_v at (t, q, v, a), right after the residual there (whose
  // force-law inputs it may take); a DAE that has it has no constraint rows
  // (their derivative terms stay zero). False: finite differences.
  virtual bool stateJacobian(double /*t*/, const Vec& /*q*/, const Vec& /*v*/, const Vec& /*a*/, Mat& /*Fq*/,
                             Mat& /*Fv*/) {
    return false;
  }
  virtual bool constraintJacobian(double /*t*/, const Vec& /*q*/, Mat& /*Phi_q*/) { return false; }
};

}  // namespace bdfcar::integ
