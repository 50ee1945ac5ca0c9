// Types shared by all integrators: a solution point, step outcome, counters
// and timers (the paper's split of one step into Jacobian, residual and
// back-substitution).
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "integrator/dae.h"

namespace bdfcar::integ {

struct SolutionPoint {
  double t = 0;
  Vec q;       // (nq)
  Vec v;       // (nv)
  Vec a;       // (nv)
  Vec lambda;  // (nc)
  bool operator==(const SolutionPoint& o) const;
  void resize(const DaeSizes& s) {
    q.setZero(s.nq);
    v.setZero(s.nv);
    a.setZero(s.nv);
    lambda.setZero(s.nc);
  }
};

enum class StepStatus { Ok, Diverged, EvaluationFailed, StateCheckFailed };
const char* stepStatusName(StepStatus s);

struct StepReport {
  StepStatus status = StepStatus::Ok;
  int iterations = 0;           // Newton iterations of the accepted attempt
  double correction = 0;        // weighted norm of the last Newton correction
  double contraction = 0;       // ratio of the last two correction norms (0 if one iteration)
  bool jacobianEvaluated = false;
  Message message;
  // An evaluation failure the DAE marked recoverable (EvalStatus::Recoverable):
  // the BDF integrator retries it with smaller steps, as IDA does.
  bool recoverable = false;
  // The step converged but missed its predictor by more than
  // BdfOptions::refineError: not accepted, to be taken as halves.
  bool refine = false;
  bool ok() const { return status == StepStatus::Ok; }
};

struct Counters {
  bool operator==(const Counters&) const = default;
  long steps = 0;             // accepted outer steps
  long substeps = 0;          // solved implicit stages (start-up sub-steps count separately)
  long newtonIterations = 0;
  long residuals = 0;         // residual evaluations in Newton iterations / explicit stages
  long jacobianResiduals = 0; // residual evaluations spent on finite-difference Jacobians
  long jacobians = 0;         // Jacobian block evaluations (the whole Jacobian)
  long columnRefreshes = 0;   // re-evaluations of the DAE's fast columns alone (Dae::fastColumns)
  long factorizations = 0;    // LU factorizations of the iteration matrix
  long solves = 0;            // solves with a factorized matrix (3 per BDF Newton iteration)
  long refreshes = 0;         // Jacobians forced because Newton stopped contracting
  long rescues = 0;           // steps iterated on to tolerance beyond the fixed count
  long splits = 0;            // steps rejected and taken as two half steps
  long refinements = 0;       // converged steps taken again as two halves (BdfOptions::refineError)
};

// Work of several integrators (a run that switches between models).
Counters& operator+=(Counters& a, const Counters& b);

// Everything an integrator carries from one step to the next, as one plain
// value: the solution history and the work counters. The integrator works on
// it in place (bindState): the history is a ring of kSlots points, node(0)
// the newest, so that a step moves no point. What it can recompute (the
// Jacobian, its factorization and age) is not part of it: a run continued
// from a state evaluates a fresh Jacobian at its first step.
struct IntegratorState {
  static constexpr int kSlots = 7;  // BDF order 5 + 2 (bdf.h checks)
  std::array<SolutionPoint, kSlots> ring;
  int head = 0;   // ring slot of node(0)
  int count = 0;  // points in the history (BDF: up to order + 1; explicit: one)
  Counters counters;
  // (head + i) mod kSlots for 0 <= head, i < kSlots: one compare, not a
  // division by 7 (a step asks for its nodes a few dozen times).
  const SolutionPoint& node(int i) const { return ring[slot(i)]; }
  SolutionPoint& node(int i) { return ring[slot(i)]; }
  int slot(int i) const { return head + i < kSlots ? head + i : head + i - kSlots; }
  // A new newest point (the oldest slot reused): node(0) is then it.
  SolutionPoint& push() {
    head = head == 0 ? kSlots - 1 : head - 1;
    count = std::min(count + 1, kSlots);
    return node(0);
  }
  // The same history (newest first, bit for bit), wherever the ring starts;
  // and the same counters too.
  bool sameHistory(const IntegratorState& o) const;
  bool operator==(const IntegratorState& o) const { return sameHistory(o) && counters == o.counters; }
};

// Sizes s's points for a system of sizes n (an integrator bound to it): a
// history of other sizes (another model's) is dropped, one of these sizes kept.
void bindHistory(IntegratorState& s, const DaeSizes& n);

// Wall time, seconds, accumulated over the run (when timing is on).
struct Timers {
  double jacobian = 0;          // blocks + LU
  double residual = 0;          // residual evaluations of the Newton iterations
  double backSubstitution = 0;  // right-hand sides, the three solves, updates
  Timers& operator+=(const Timers& o) {
    jacobian += o.jacobian;
    residual += o.residual;
    backSubstitution += o.backSubstitution;
    return *this;
  }
};

// Common interface of the implicit and explicit integrators.
class Integrator {
 public:
  virtual ~Integrator() = default;
  // Starts from q0, v0 satisfying the position and velocity constraints; the
  // consistent acceleration and multipliers are solved for.
  virtual EvalStatus initialize(double t0, const Vec& q0, const Vec& v0, Message& msg) = 0;
  // As initialize (the history starts again), but a Jacobian the integrator
  // holds is kept: the same system restarted at another point (a vehicle
  // model switched back to), where a fresh one would cost its residuals.
  virtual EvalStatus restart(double t0, const Vec& q0, const Vec& v0, Message& msg) {
    return initialize(t0, q0, v0, msg);
  }
  virtual StepReport step(double h) = 0;
  virtual const SolutionPoint& current() const = 0;
  virtual const Counters& counters() const = 0;
  virtual const Timers& timers() const = 0;
  // The state the integrator works on: its own until bound to another (a
  // run state's, which the simulation owns); binding sizes the ring's points
  // for this system and keeps the history of the right sizes.
  virtual void bindState(IntegratorState& s) = 0;
  virtual const IntegratorState& state() const = 0;
  // The next step evaluates a fresh Jacobian (a snapshot boundary: the run
  // that goes on and a run restored to the snapshot then step alike).
  virtual void markJacobianStale() {}
  // An implicit method's fixed Newton count ends early at an iteration within
  // tolerance (BdfOptions::stopWithinTolerance), from the next step on.
  virtual void setNewtonEarlyEnd(bool /*on*/) {}
  // The vehicle is below its tyres' low-speed range (BdfOptions::
  // lowSpeedTolerance), from the next step on.
  virtual void setLowSpeed(bool /*on*/) {}
};

}  // namespace bdfcar::integ
