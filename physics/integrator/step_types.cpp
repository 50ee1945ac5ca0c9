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

bool IntegratorState::sameHistory(const IntegratorState& o) const {
  if (count != o.count) return false;
  for (int i = 0; i < count; ++i)
    if (!(node(i) == o.node(i))) return false;
  return true;
}

void bindHistory(IntegratorState& s, const DaeSizes& n) {
  auto fits = [&](const SolutionPoint& p) {
    return p.q.size() == n.nq && p.v.size() == n.nv && p.a.size() == n.nv && p.lambda.size() == n.nc;
  };
  for (int i = 0; i < s.count; ++i)
    if (!fits(s.node(i))) s.count = 0;
  for (SolutionPoint& p : s.ring)
    if (!fits(p)) p.resize(n);
}

Counters& operator+=(Counters& a, const Counters& b) {
  a.steps += b.steps;
  a.substeps += b.substeps;
  a.newtonIterations += b.newtonIterations;
  a.residuals += b.residuals;
  a.jacobianResiduals += b.jacobianResiduals;
  a.jacobians += b.jacobians;
  a.columnRefreshes += b.columnRefreshes;
  a.factorizations += b.factorizations;
  a.solves += b.solves;
  a.refreshes += b.refreshes;
  a.rescues += b.rescues;
  a.splits += b.splits;
  a.refinements += b.refinements;
  return a;
}

}  // namespace bdfcar::integ
