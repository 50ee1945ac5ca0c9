// A multibody Model seen by the integrators as a DAE: residual (recursive
// Newton-Euler + cut-joint constraints at three levels), analytic F_a and
// Phi_q, and the manifold structure of the joint coordinates. Extra forces
// (tyres, drive torques) come in through ForceProvider.
#pragma once

#include <utility>
#include <vector>

#include "integrator/dae.h"
#include "multibody/data.h"

namespace bdfcar::mb {

// Applies forces that are not part of the Model (tyres, drive and brake torques).
class ForceProvider {
 public:
  virtual ~ForceProvider() = default;
  // Before a step ending at t, at the predicted state (positions in data
  // are current), when needsBeginStep(t): the first step of a run, a step
  // other than the one the accepted state prepared for, or always for
  // providers that cannot prepare the step from the accepted state.
  virtual bool needsBeginStep(double /*t*/) const { return false; }
  virtual void beginStep(const Model& /*model*/, const Data& /*data*/, double /*t*/) {}
  // Adds wrenches to data.fext and joint forces to data.jointForce. Positions
  // and velocities in data are current.
  virtual void apply(const Model& model, Data& data, double t) = 0;
  // Once per accepted step; positions and velocities in data are those of the
  // last residual evaluation (the last Newton iterate: the accepted state up
  // to the last correction). May prepare the next step, of length about h.
  virtual void acceptStep(const Model& /*model*/, const Data& /*data*/, double /*t*/, double /*h*/) {}
  // The share of dF/dv in the velocity coordinates `columns` (the DAE's fast
  // columns) that this provider's fast-changing forces give at the state of
  // its last apply(), from its force laws alone (integ::Dae::fastColumnParts),
  // added to parts (nv x columns). False: it gives none it can compute so.
  virtual bool hasFastColumnParts() const { return false; }
  virtual void addFastColumnParts(const Model& /*model*/, const Data& /*data*/, double /*t*/,
                                  const std::vector<int>& /*columns*/, Eigen::MatrixXd& /*parts*/) {}
  // Those forces' change of the equation of velocity coordinate `column`
  // when that velocity moves by dv from the state of the last apply()
  // (integ::Dae::fastRowChange), added to change. False: none given.
  virtual bool addFastRowChange(const Model& /*model*/, const Data& /*data*/, double /*t*/, int /*column*/,
                                double /*dv*/, double& /*change*/) {
    return false;
  }
};

struct StateLimits {
  double maxConstraintViolation = 1e-2;  // |Phi| (m or rad) beyond which a state has diverged
  double maxVelocity = 1e4;              // |v_i| (m/s, rad/s)
};

class MultibodyDae final : public integ::Dae {
 public:
  explicit MultibodyDae(const Model& model);

  void addForceProvider(ForceProvider* p) { providers_.push_back(p); }
  void setDriverSignal(int slot, const TimeSignal* s) { data_.driverSignals.at(slot) = s; }
  void setLimits(const StateLimits& l) { limits_ = l; }
  // Velocity coordinates whose Jacobian columns change fast (integ::Dae::fastColumns).
  void setFastColumns(std::vector<int> columns) { fastColumns_ = std::move(columns); }
  const std::vector<int>& fastColumns() const override { return fastColumns_; }
  const Model& model() const { return model_; }
  Data& data() { return data_; }
  const Data& data() const { return data_; }

  // Fills data() with kinematics and forces at (t, q, v) (a = 0), for output.
  void evaluateKinematics(double t, const integ::Vec& q, const integ::Vec& v);

  integ::DaeSizes sizes() const override { return {model_.nq, model_.nv, model_.nc}; }
  void retract(const integ::Vec& q, const integ::Vec& dq, integ::Vec& out) const override;
  void localCoordinates(const integ::Vec& base, const integ::Vec& q, integ::Vec& out) const override;
  void localRate(const integ::Vec& delta, const integ::Vec& v, integ::Vec& out) const override;
  void beginStep(double t, const integ::Vec& q, const integ::Vec& v) override;
  integ::EvalStatus acceptStep(double t, double h, const integ::Vec& q, const integ::Vec& v, integ::Message& msg) override;
  integ::EvalStatus residual(double t, const integ::Vec& q, const integ::Vec& v, const integ::Vec& a,
                             const integ::Vec& lambda, integ::Residual& out, bool withConstraints,
                             integ::Message& msg) override;
  bool massMatrix(double t, const integ::Vec& q, integ::Mat& Fa) override;
  bool constraintJacobian(double t, const integ::Vec& q, integ::Mat& Phi_q) override;
  bool hasFastColumnParts() const override;
  void fastColumnParts(double t, integ::Mat& parts) override;
  bool fastRowChange(double t, int k, double dv, double& change) override;

 private:
  void applyForces(double t);

  const Model& model_;
  Data data_;
  std::vector<ForceProvider*> providers_;
  StateLimits limits_;
  std::vector<int> fastColumns_;
  integ::Vec zeroV_;
};

}  // namespace bdfcar::mb
