#include "integrator/step_types.h"

namespace bdfcar::integ {

namespace {
// Bit-for-bit equality of two vectors (sizes first: Eigen asserts on a mismatch).
bool same(const Vec& a, const Vec& b) { return a.size() == b.size() && (a.array() == b.array()).all(); }
}  // namespace

const char* stepStatusName(StepStatus s) {
  switch (s) {
    case StepStatus::Ok: return "ok";
    case StepStatus::Diverged: return "diverged";
    case StepStatus::EvaluationFailed: return "evaluation failed";
    case StepStatus::StateCheckFailed: return "state check failed";
  }
  return "?";
}

bool SolutionPoint::operator==(const SolutionPoint& o) const {
  return t == o.t && same(q, o.q) && same(v, o.v) && same(a, o.a) && same(lambda, o.lambda);
}

bool IntegratorState::operator==(const IntegratorState& o) const {
  return history == o.history && counters == o.counters && stepsSinceJacobian == o.stepsSinceJacobian;
}

}  // namespace bdfcar::integ
