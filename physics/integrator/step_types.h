// Types shared by all integrators: a solution point, step outcome, counters
// and timers (the paper's split of one step into Jacobian, residual and
// back-substitution).
#pragma once

#include "integrator/dae.h"

namespace bdfcar::integ {

struct SolutionPoint {
  double t = 0;
  Vec q;       // (nq)
  Vec v;       // (nv)
  Vec a;       // (nv)
  Vec lambda;  // (nc)
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
  bool ok() const { return status == StepStatus::Ok; }
};

struct Counters {
  long steps = 0;             // accepted outer steps
  long substeps = 0;          // solved implicit stages (start-up sub-steps count separately)
  long newtonIterations = 0;
  long residuals = 0;         // residual evaluations in Newton iterations / explicit stages
  long jacobianResiduals = 0; // residual evaluations spent on finite-difference Jacobians
  long jacobians = 0;         // Jacobian block evaluations
  long factorizations = 0;    // LU factorizations of the iteration matrix
  long solves = 0;            // solves with a factorized matrix (3 per BDF Newton iteration)
  long refreshes = 0;         // Jacobians forced because Newton stopped contracting
  long rescues = 0;           // steps iterated on to tolerance beyond the fixed count
  long splits = 0;            // steps rejected and taken as two half steps
};

// Wall time, seconds, accumulated over the run (when timing is on).
struct Timers {
  double jacobian = 0;          // blocks + LU
  double residual = 0;          // residual evaluations of the Newton iterations
  double backSubstitution = 0;  // right-hand sides, the three solves, updates
};

// Common interface of the implicit and explicit integrators.
class Integrator {
 public:
  virtual ~Integrator() = default;
  // Starts from q0, v0 satisfying the position and velocity constraints; the
  // consistent acceleration and multipliers are solved for.
  virtual EvalStatus initialize(double t0, const Vec& q0, const Vec& v0, Message& msg) = 0;
  virtual StepReport step(double h) = 0;
  virtual const SolutionPoint& current() const = 0;
  virtual const Counters& counters() const = 0;
  virtual const Timers& timers() const = 0;
};

}  // namespace bdfcar::integ
