// The fidelity ladder inside a Simulation: each rung's force laws, DAE and
// integrator, the switch between rungs (the state mapped, the chassis's
// jump checked) and `auto`'s choice at a tick.
#include "scenario/simulation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "integrator/bdf.h"
#include "integrator/explicit.h"
#include "multibody/kinematics.h"
#include "multibody/model_error.h"
#include "vehicle/kinematic_car.h"
#include "vehicle/planar_car.h"
#include "vehicle/rung_mapping.h"
#include "portable_math.h"

namespace bdfcar::scenario {

Simulation::Rung Simulation::makeRung(const vehicle::Vehicle& veh) {
  Rung r;
  r.vehicle = &veh;
  vehicle::TerrainContactOptions contact;
  contact.raysPerWheel = spec().raysPerWheel;
  contact.groundInsideStep = spec().groundInsideStep;
  r.dae = std::make_unique<mb::MultibodyDae>(veh.model);
  // The derived models in closed form where one carries the car
  // (planar_car.h and kinematic_car.h say what they refuse): its force laws
  // are the multibody model's too.
  const FidelitySpec& f = spec().fidelity;
  try {
    if (veh.planar && f.planarClosedForm)
      r.car = std::make_unique<vehicle::PlanarCar>(veh, *world_->terrain, contact);
    else if (veh.fidelity == vehicle::Fidelity::Kinematic && f.kinematicClosedForm)
      r.car = std::make_unique<vehicle::KinematicCar>(veh, *world_->terrain, contact);
  } catch (const mb::ModelError&) {
    r.car.reset();
  }
  if (r.car) {
    r.car->setRack(&rack_);
    r.dae->addForceProvider(&r.car->forces());
  }
  if (!r.car) {
    r.forces = std::make_unique<vehicle::VehicleForces>(veh, *world_->terrain, contact);
    r.dae->addForceProvider(r.forces.get());
  }
  // The force laws' states are per wheel in every model: one for all rungs,
  // carried across a switch as it is.
  (r.car ? r.car->forces() : *r.forces).bindState(state_.forces);
  // A wheel's spin column of the Jacobian is dominated by its tyre's slip
  // stiffness, which collapses when the tyre saturates (a rough road flips
  // a tyre between the regimes from one step to the next): the integrator
  // refreshes these columns alone when Newton stalls.
  std::vector<int> spins;
  for (const vehicle::WheelLayout& w : veh.layout.wheels) spins.push_back(w.spinV);
  r.dae->setFastColumns(std::move(spins));
  // Every driver of a vehicle model is the rack's: the rack itself and, in a
  // derived model, the rack travel of each steered corner's table.
  for (int slot = 0; slot < veh.model.nDrivers; ++slot) r.dae->setDriverSignal(slot, &rack_);
  r.stepping = r.car ? static_cast<integ::Dae*>(r.car.get()) : r.dae.get();
  r.integrator = makeIntegrator(*r.stepping, veh.fidelity != vehicle::Fidelity::Linkage);
  r.scratch = mb::makeData(veh.model);
  return r;
}

std::unique_ptr<integ::Integrator> Simulation::makeIntegrator(integ::Dae& dae, bool derived) const {
  const IntegratorSpec& is = spec().integrator;
  if (is.method == IntegratorMethod::Bdf) {
    integ::BdfOptions o = is.bdf;
    o.stopWithinTolerance = spec().fidelity.stopWithinTolerance;  // every rung; FidelitySpec says why
    if (derived) o.newtonIterations = spec().fidelity.newtonIterations;
    o.earlyEndFromContraction = derived && o.stopWithinTolerance;  // the closed forms': BdfOptions says why
    return std::make_unique<integ::BdfIntegrator>(dae, o);
  }
  integ::ExplicitOptions o = is.explicitMethod;
  o.method = is.method == IntegratorMethod::Rk4 ? integ::ExplicitMethod::RK4 : integ::ExplicitMethod::SemiImplicitEuler;
  return std::make_unique<integ::ExplicitIntegrator>(dae, o);
}

void Simulation::activate(int rung) {
  state_.rung = rung;
  Rung& r = rungs_[rung];
  car_ = r.car.get();
  forces_ = car_ ? &car_->forces() : r.forces.get();
  dae_ = r.dae.get();
  stepping_ = r.stepping;
  integrator_ = r.integrator.get();
  // The one history: a switch restarts it in this model's coordinates.
  integrator_->bindState(state_.integrator);
}

void Simulation::toMultibody(int rung, double t, const integ::Vec& q, const integ::Vec& v, integ::Vec& qm,
                             integ::Vec& vm) const {
  if (const vehicle::ClosedFormCar* car = rungs_[rung].car.get()) {
    car->toMultibody(t, q, v, qm, vm);
    return;
  }
  qm = q;
  vm = v;
}

void Simulation::fromMultibody(int rung, const integ::Vec& qm, const integ::Vec& vm, integ::Vec& q, integ::Vec& v) const {
  if (const vehicle::ClosedFormCar* car = rungs_[rung].car.get()) {
    car->fromMultibody(qm, vm, q, v);
    return;
  }
  q = qm;
  v = vm;
}

integ::SolutionPoint Simulation::multibodyPoint() {
  const integ::SolutionPoint& p = integrator_->current();
  if (!car_) return p;
  return car_->multibodyPoint(p, *dae_);
}

Simulation::ChassisPose Simulation::chassisPose(int rung, const integ::Vec& q) {
  Rung& r = rungs_[rung];
  mb::updatePositions(r.vehicle->model, q, r.scratch);
  const int ch = r.vehicle->layout.chassis;  // the sprung body of the planar model
  return {r.scratch.p[ch], r.scratch.R[ch]};
}

bool Simulation::switchRung(int rung) {
  if (rung == state_.rung) return true;
  if (!world_->planar) throw std::logic_error("Simulation::switchRung: the run has one model");
  const integ::SolutionPoint from = integrator_->current();
  Eigen::VectorXd fromQ, fromV, q, v;
  toMultibody(state_.rung, from.t, from.q, from.v, fromQ, fromV);
  if (rung == 1) vehicle::kinematicToPlanar(world_->vehicle, *world_->planar, fromQ, fromV, q, v);
  else vehicle::planarToKinematic(*world_->planar, world_->vehicle, fromQ, fromV, q, v);
  // A switch never moves the chassis: what the mapping drops (heave, the
  // travels) must be what the lower rung would have anyway. Up, the mapping
  // copies the sprung body's pose (a jump there would be a bug, and staying
  // on a rung outside its validity is no option: it is measured, not refused).
  const ChassisPose a = chassisPose(state_.rung, fromQ), b = chassisPose(rung, q);
  const double jump = (b.p - a.p).norm();
  const Eigen::Matrix3d M = a.R.transpose() * b.R;
  const Eigen::Vector3d axis(M(2, 1) - M(1, 2), M(0, 2) - M(2, 0), M(1, 0) - M(0, 1));
  const double turn = pm::atan2(0.5 * axis.norm(), 0.5 * (M.trace() - 1.0));
  if (rung > state_.rung && (jump > FidelityPolicy::kMaxJump || turn > FidelityPolicy::kMaxTurn)) {
    FidelityPolicy::refuse(state_.fidelity);
    return false;
  }
  // The force laws' state (contact planes, transient slips, brakes, held
  // inputs: per wheel in both models) goes on as it is.
  activate(rung);
  integ::Message msg;
  Eigen::VectorXd toQ, toV;
  fromMultibody(rung, q, v, toQ, toV);
  if (integrator_->restart(from.t, toQ, toV, msg) != integ::EvalStatus::Ok)
    throw std::runtime_error("switching to the " + std::string(vehicle::fidelityName(vehicle().fidelity)) +
                             " model at t = " + std::to_string(from.t) + " s: " + msg.c_str());
  ++state_.fidelity.switches;
  state_.fidelity.maxJump = std::max(state_.fidelity.maxJump, jump);
  state_.fidelity.maxTurn = std::max(state_.fidelity.maxTurn, turn);
  switchJump_ = std::max(switchJump_, jump);
  return true;
}

double Simulation::takeSwitchJump() {
  const double j = switchJump_;
  switchJump_ = 0;
  return j;
}

void Simulation::chooseRung() {
  const ChassisState c = chassisState();
  const FidelityPolicy::Decision d =
      policy_->decide(state_.fidelity, c.com.head<2>(), c.yaw, c.vx, c.yawRate, forces_->wheels(), spec().tick);
  if (d == FidelityPolicy::Decision::Full) switchRung(0);
  if (d == FidelityPolicy::Decision::Planar) switchRung(1);
}

// One history for every rung, so one count of the work (a restart keeps it).
integ::Counters Simulation::counters() const { return state_.integrator.counters; }

integ::Timers Simulation::timers() const {
  integ::Timers t;
  for (const Rung& r : rungs_) t += r.integrator->timers();
  return t;
}

}  // namespace bdfcar::scenario
