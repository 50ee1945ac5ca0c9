#include "multibody/data.h"

namespace bdfcar::mb {

Data makeData(const Model& model) {
  const size_t nb = model.bodies.size();
  Data d;
  d.driverSignals.assign(model.nDrivers, nullptr);
  d.Xup.resize(nb);
  d.R.assign(nb, Mat3::Identity());
  d.p.assign(nb, Vec3::Zero());
  d.S = model.S;
  d.secondAngleSinCos.assign(nb, std::array<double, 2>{});
  d.tableSamples.assign(model.tables.size(), SplineGrid::Sample{});
  d.tableSubspaceDerivatives.assign(model.tables.size(), std::array<Vec6, 4>{});
  d.tableRates.assign(model.tables.size(), std::array<double, 2>{});
  d.vel.assign(nb, Vec6::Zero());
  d.bias.assign(nb, Vec6::Zero());
  d.acc.assign(nb, Vec6::Zero());
  d.fext.assign(nb, Vec6::Zero());
  d.f.assign(nb, Vec6::Zero());
  d.jointForce = Eigen::VectorXd::Zero(model.nv);
  d.tau = Eigen::VectorXd::Zero(model.nv);
  d.phi = Eigen::VectorXd::Zero(model.nc);
  d.phiDot = Eigen::VectorXd::Zero(model.nc);
  d.phiDDot = Eigen::VectorXd::Zero(model.nc);
  d.driverTargets.assign(model.nDrivers, SignalValue{});
  d.Ic.assign(nb, Mat6::Zero());
  d.springLength.assign(model.springs.size(), 0.0);
  d.springLengthRate.assign(model.springs.size(), 0.0);
  d.springForce.assign(model.springs.size(), 0.0);
  return d;
}

}  // namespace bdfcar::mb
