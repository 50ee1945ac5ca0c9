// The linkage on a quasi-static rig: the chassis held at its design pose,
// each wheel centre moved vertically relative to the chassis by its own
// travel, the rack at a given travel. Newton on the loop constraints plus one
// travel equation per wheel over the suspension coordinates (all but the
// chassis, the rack, the engine and the wheel spins). What the kinematic rung
// tabulates (kinematic_model.h) and the K&C rig sweeps (kc_rig.h).
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <array>
#include <vector>

#include "multibody/data.h"
#include "vehicle/vehicle_builder.h"

namespace bdfcar::vehicle {

class LinkageSweep {
 public:
  // Assembles the linkage at design; throws mb::ModelError if it does not,
  // or if it has not exactly one free motion per wheel with the rack held.
  explicit LinkageSweep(const Vehicle& v);

  const Eigen::VectorXd& design() const { return design_; }

  // Solves from q (updated in place) for wheel travels s (m, + bump, FL FR
  // RL RR) and rack coordinate r; false if Newton does not converge.
  bool solve(const std::array<double, 4>& s, double r, Eigen::VectorXd& q);
  bool solve(double s, double r, Eigen::VectorXd& q) { return solve({s, s, s, s}, r, q); }

  // Suspension-coordinate direction of a unit travel of wheel w alone, at q.
  Eigen::VectorXd travelDirection(const Eigen::VectorXd& q, int w);

  // Positions at q (the chassis at its design pose).
  mb::Data& at(const Eigen::VectorXd& q);
  // Wheel w's centre in the chassis frame, in the data of the last at().
  Vec3 wheelCentre(int w) const;

 private:
  int rows() const { return static_cast<int>(rows_.size()) + 4; }
  void residual(const Eigen::VectorXd& q, const std::array<double, 4>& s, Eigen::VectorXd& out);
  void step(const Eigen::VectorXd& q, const Eigen::VectorXd& dx, Eigen::VectorXd& out);
  void jacobian(const Eigen::VectorXd& q, const std::array<double, 4>& s);

  const Vehicle& v_;
  const mb::Model& m_;
  mb::Data d_;
  std::vector<int> rows_, free_;
  Eigen::VectorXd design_;
  std::array<double, 4> z0_{};
  Eigen::MatrixXd J_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

}  // namespace bdfcar::vehicle
