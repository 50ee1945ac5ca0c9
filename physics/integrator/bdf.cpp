#include "integrator/bdf.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace bdfcar::integ {

namespace {

using Clock = std::chrono::steady_clock;

// Accumulates elapsed wall time into a timer when timing is on.
class ScopedTimer {
 public:
  ScopedTimer(bool on, double& acc) : on_(on), acc_(acc) {
    if (on_) t0_ = Clock::now();
  }
  ~ScopedTimer() {
    if (on_) acc_ += std::chrono::duration<double>(Clock::now() - t0_).count();
  }

 private:
  bool on_;
  double& acc_;
  Clock::time_point t0_;
};

// Number of start-up sub-steps: the first is h / 2^m with h / 2^m ~ h^2 / 1 s,
// so its first-order local error is O(h^4); each following one doubles.
int startupHalvings(double h) { return std::clamp(static_cast<int>(std::ceil(std::log2(1.0 / h))), 1, 12); }

// Times accumulate round-off, so h' of equal steps differs in the last
// bits: the same h' for the iteration matrix within 1e-9 of it (0: none).
bool sameHPrime(double hp, double other) { return other != 0 && std::abs(hp - other) <= 1e-9 * hp; }

// A vector of the system's into one of the same size (the integrator's own
// and its history's are sized once, bindHistory): a plain copy, without an
// Eigen assignment's size check and set-up, which cost more than the copy
// of a closed form's 9 to 15 coordinates.
void copyInto(const Vec& from, Vec& to) { std::copy_n(from.data(), from.size(), to.data()); }

// A first Newton iterate this many refineError from the predictor ends the
// attempt as refined (BdfIntegrator::newton, refineEarly).
constexpr double kFirstIterateMiss = 2.0;

}  // namespace

BdfIntegrator::BdfIntegrator(Dae& dae, const BdfOptions& options)
    : dae_(dae),
      opt_(options),
      n_(dae.sizes()),
      kernels_(kernels::stepKernels(n_.nv, n_.nc)),
      forward_(dae),
      lu_(n_.nv + n_.nc) {
  opt_.order = std::clamp(opt_.order, 1, kMaxBdfOrder);
  const int nv = n_.nv, nc = n_.nc, n = nv + nc;
  ws_.resize(n_);
  bindState(own_);
  for (auto& d : delta_) d.setZero(nv);
  missScratch_.setZero(nv);
  dx_.resize(n_);
  Fa_.setZero(nv, nv);
  J_.setZero(nc, nv);
  A_.setZero(n, n);
  Ainv_.setZero(n, n);
  for (Vec* x : {&xiQ_, &xiV_, &dPred_, &vPred_, &aPred_, &d_, &v_, &a_, &d0_, &v0_, &a0_, &rate_, &rhoQ_, &rhoV_,
                 &tmpV_, &dq_, &dv_, &da_})
    x->setZero(nv);
  for (Vec* x : {&lamPred_, &lam_, &lam0_, &c_, &dlam_}) x->setZero(nc);
  q_.setZero(n_.nq);
  rhs_.setZero(n);
  const int m = static_cast<int>(dae_.fastColumns().size());
  fastBaseFv_.setZero(nv, m);
  for (KeptFactorization& k : kept_) {
    k.Ainv.setZero(n, n);
    k.fastBaseFv.setZero(nv, m);
  }
  U_.setZero(nv, m);
  Z_.setZero(n, m);
  S_.setZero(m, m);
  slowFv_.setZero(nv, m);
  partsNow_.setZero(nv, m);
  pending_.resize(n_);
  pendingFa_.setZero(nv, nv);
  pendingJ_.setZero(nc, nv);
  pendingSlowFv_.setZero(nv, m);
  pendingParts_.setZero(nv, m);
  sLu_ = Eigen::PartialPivLU<Mat>(m);
  w_.setZero(m);
  w2_.setZero(m);
  sol_.setZero(n);
  e_.setZero(n);
  r_.resize(n_);
}

EvalStatus BdfIntegrator::initialize(double t0, const Vec& q0, const Vec& v0, Message& msg) {
  SolutionPoint p;
  p.resize(n_);
  p.t = t0;
  p.q = q0;
  p.v = v0;
  dae_.beginStep(t0, q0, v0);
  const EvalStatus st = forward_.solve(t0, q0, v0, 0.0, 0.0, p.a, p.lambda, st_->counters, msg);
  if (st != EvalStatus::Ok) return st;
  initializeConsistent(p);
  return EvalStatus::Ok;
}

EvalStatus BdfIntegrator::restart(double t0, const Vec& q0, const Vec& v0, Message& msg) {
  const bool blocks = haveBlocks_;
  const long since = stepsSinceJacobian_;
  const EvalStatus st = initialize(t0, q0, v0, msg);
  // The blocks stay; the iteration matrix is factorized again for the
  // restart's first-order step (initializeConsistent cleared its h').
  haveBlocks_ = blocks;
  stepsSinceJacobian_ = since;
  return st;
}

void BdfIntegrator::initializeConsistent(const SolutionPoint& p) {
  st_->head = 0;
  st_->count = 1;
  node(0) = p;
  haveBlocks_ = false;
  slice_ = -1;
  stepsSinceJacobian_ = 0;
  dropFactorizations();
}

void BdfIntegrator::bindState(IntegratorState& s) {
  st_ = &s;
  bindHistory(s, n_);  // the Jacobian stays (markJacobianStale drops it)
}

StepReport BdfIntegrator::step(double h) {
  const bool periodic = haveBlocks_ && opt_.jacobianEvery > 0 && stepsSinceJacobian_ >= opt_.jacobianEvery &&
                        !(skipsFreshJacobian() && worstContraction_ < kStaleContraction);
  // The periodic Jacobian in slices: one a step from here until it is whole.
  if (periodic && slice_ < 0 && spreadsJacobian()) slice_ = 0;
  sliceThisStep_ = periodic && slice_ >= 0;
  const bool due = !haveBlocks_ || (periodic && !sliceThisStep_);
  const StartUp mode = opt_.startUp == StartUp::Auto ? (opt_.order >= 3 ? StartUp::Substeps : StartUp::OrderRamp)
                                                     : opt_.startUp;
  StepReport rep;
  if (st_->count == 1 && mode == StartUp::Substeps && opt_.order > 1) {
    const int m = startupHalvings(h);
    double hs = h / std::ldexp(1.0, m);
    const double tEnd = node(0).t + h;
    rep = substep(hs, due);
    for (int i = 1; i <= m && rep.ok(); ++i) {
      const double hi = (i == m) ? tEnd - node(0).t : hs;  // land exactly on t0 + h
      rep = substep(hi, false);
      hs *= 2;
    }
  } else {
    rep = pieces(h, due);
  }
  if (rep.ok()) {
    ++st_->counters.steps;
    ++stepsSinceJacobian_;
  }
  return rep;
}

// A step that Newton cannot converge (a wheel landing, a curb strike), or
// whose residual failed recoverably (as IDA retries a recoverable residual
// failure with a smaller step), is rejected and taken as two half steps,
// recursively, kMaxSplits times below the piece that failed. The history
// holds node times, so uneven steps are exact BDF steps.
//
// A converged step that left its predictor by more than refineError (an
// impact, a wheel landing: BdfOptions) is taken as halves the same way, to
// refineDepth; each half is judged again, so the pieces are h / 2^k where
// the motion turns sharply and grow back by twice at most (within the
// stable step ratio of BDF2, 1 + sqrt 2).
StepReport BdfIntegrator::splitOnFailure(double h, bool jacobianDue, int depth, int failures) {
  const bool mayRefine = depth < opt_.refineDepth && opt_.refineError > 0 && opt_.refreshWhenNotContracting;
  StepReport rep = substep(h, jacobianDue, failures >= kMaxSplits, mayRefine);
  if (rep.refine) {
    ++st_->counters.refinements;
    return halves(h, depth, failures);
  }
  const bool retry = rep.status == StepStatus::Diverged || (rep.status == StepStatus::EvaluationFailed && rep.recoverable);
  if (rep.ok() || !retry || failures >= kMaxSplits || !opt_.refreshWhenNotContracting) return rep;
  ++st_->counters.splits;
  return halves(h, depth, failures + 1);
}

// [t, t + h] as two halves, each judged (and split again) one level deeper;
// the second lands exactly on t + h.
StepReport BdfIntegrator::halves(double h, int depth, int failures) {
  const double tEnd = node(0).t + h;
  const StepReport rep = splitOnFailure(0.5 * h, false, depth + 1, failures);
  if (!rep.ok()) return rep;
  return splitOnFailure(tEnd - node(0).t, false, depth + 1, failures);
}

bool BdfIntegrator::refining() const {
  return opt_.refineDepth > 0 && opt_.refineError > 0 && opt_.refreshWhenNotContracting;
}

// A step right after refined ones goes on in pieces as long as the last one
// (on relief a whole h, or twice the piece, would miss its predictor again:
// an attempt wasted, and the Newton iterations at a step too long for the
// road); a piece doubles, on the doubled piece's grid of the step, where the
// predictor's error model says the doubled one would pass. The history's
// nodes say how the last step ended, so a run restored from its state cuts
// the same way.
StepReport BdfIntegrator::pieces(double h, bool jacobianDue) {
  // The deepest piece a step can end in: refined, then split for failures.
  const int deepest = refining() && opt_.carryRefinedPieces ? opt_.refineDepth + kMaxSplits : 0;
  int j = deepest > 0 ? nextDepth(h, deepest, 0) : 0;
  if (j == 0) return splitOnFailure(h, jacobianDue, 0, 0);
  const double tEnd = node(0).t + h;
  const long total = 1L << deepest;  // the step in pieces of the deepest
  StepReport rep;
  for (long at = 0; at < total;) {
    const long size = total >> j;
    const double piece = at + size == total ? tEnd - node(0).t : std::ldexp(h, -j);  // the last lands on t + h
    rep = splitOnFailure(piece, jacobianDue && at == 0, j, 0);
    if (!rep.ok()) return rep;
    at += size;
    if (at < total) j = nextDepth(h, deepest, at);
  }
  return rep;
}

// The halvings of h the next piece takes, at `at` of the deepest pieces
// into the step: the last piece's, one fewer where the doubled piece starts
// on its own grid and the last piece's predictor miss times 2^(k+1) (a miss
// of order k grows as h^(k+1)) is within refineError. So the pieces grow
// back by doubling at most, after refinements and failure splits alike
// (within BDF2's stable step ratio); those deeper than refineDepth are not
// refined again (splitOnFailure).
int BdfIntegrator::nextDepth(double h, int deepest, long at) {
  if (st_->count < 2) return 0;
  const double last = node(0).t - node(1).t;
  if (!(last < h * (1 - 1e-9))) return 0;  // the last step was whole
  int j = 0;
  while (j < deepest && std::ldexp(h, -j) > last * (1 + 1e-9)) ++j;
  if (j == 0) return 0;
  const long doubled = 2 * ((1L << deepest) >> j);
  if (at % doubled != 0) return j;
  const int k = std::min(opt_.order, st_->count - 1);  // the order the last piece was taken with
  return std::ldexp(lastPieceMiss(k), k + 1) <= opt_.refineError ? j - 1 : j;
}

// The predictor's miss of node(0), from the history: the polynomial through
// the np nodes before it, at its time, against it, in local coordinates
// around node(1) (as substep judged it, to rounding); infinite where the
// history is too short to have judged it.
double BdfIntegrator::lastPieceMiss(int k) {
  const int np = std::min(k + 1, st_->count - 1);
  if (np < 2) return std::numeric_limits<double>::infinity();
  std::array<double, kMaxBdfOrder + 2> times{}, w{};
  for (int i = 0; i < np; ++i) times[i] = node(i + 1).t;
  lagrangeWeights(times.data(), np, node(0).t, w.data());
  for (int i = 1; i < np; ++i) dae_.localCoordinates(node(1).q, node(i + 1).q, delta_[i]);
  dae_.localCoordinates(node(1).q, node(0).q, missScratch_);
  double miss = 0;
  for (int c = 0; c < n_.nv; ++c) {
    double predicted = 0;
    for (int i = 1; i < np; ++i) predicted += w[i] * delta_[i](c);
    miss = std::max(miss, std::abs(missScratch_(c) - predicted));
  }
  return miss;
}

EvalStatus BdfIntegrator::evaluateJacobian(double t, Message& msg) {
  ScopedTimer timer(opt_.timing, timers_.jacobian);
  long& cnt = st_->counters.jacobianResiduals;
  const bool parts = opt_.fastColumnRescue && dae_.hasFastColumnParts();
  EvalStatus st = stateDerivativeBlocks(dae_, t, q_, v_, a_, lam_, dx_, ws_, cnt, parts ? &partsNow_ : nullptr);
  if (st == EvalStatus::Ok) st = massMatrixBlock(dae_, t, q_, v_, a_, lam_, Fa_, ws_, cnt);
  if (st == EvalStatus::Ok) st = constraintJacobianBlock(dae_, t, q_, J_, ws_, cnt);
  if (st != EvalStatus::Ok) {
    msg = ws_.msg;
    return st;
  }
  // The fast columns' slow rest: each less the force laws' part at the
  // blocks' own point.
  fastParts_ = parts;
  if (fastParts_) {
    const std::vector<int>& fast = dae_.fastColumns();
    for (int k = 0; k < static_cast<int>(fast.size()); ++k) slowFv_.col(k) = dx_.Fv.col(fast[k]) - partsNow_.col(k);
  }
  blocksEvaluated();
  return EvalStatus::Ok;
}

void BdfIntegrator::blocksEvaluated() {
  ++st_->counters.jacobians;
  haveBlocks_ = true;
  slice_ = -1;  // a whole Jacobian ends one in slices under way
  stepsSinceJacobian_ = 0;
  worstContraction_ = 0;
  contractionMeasured_ = false;
  dropFactorizations();  // force a factorization with the new blocks
}

bool BdfIntegrator::skipsFreshJacobian() const {
  // Without constraints (the closed forms, whose blocks are exact: dual
  // numbers) a Newton that has contracted fast since the blocks were taken
  // says they are still good: the periodic refresh waits for a contraction
  // slower than kStaleContraction (a stale Jacobian contracts linearly, at
  // the rate of its error; a good one's second correction is a few per cent
  // of its first). A rung on steps Newton takes in a residual or two then
  // pays for no Jacobian it does not use. The multibody models (blocks by
  // differences, in slices) keep the paper's every jacobianEvery steps, and
  // so does a run without refreshWhenNotContracting, the refresh a stale
  // Jacobian falls back on. A Jacobian asked for every few steps
  // (kAskedFresh) is one a run wants fresh: taken as asked.
  return n_.nc == 0 && opt_.refreshWhenNotContracting && opt_.jacobianEvery > kAskedFresh;
}

bool BdfIntegrator::spreadsJacobian() const {
  // The closed forms' exact blocks (no constraints) cost a residual or two:
  // whole. So is a Jacobian asked for every few steps (kAskedFresh): a run
  // that wants it fresh, where slices a few steps old would be most of its
  // age (the default's is 200 steps).
  return opt_.jacobianSlices > 1 && opt_.refreshWhenNotContracting && n_.nc > 0 &&
         opt_.jacobianEvery >= kAskedFresh * opt_.jacobianSlices;
}

EvalStatus BdfIntegrator::evaluateJacobianSlice(double t, Message& msg, bool& installed) {
  ScopedTimer timer(opt_.timing, timers_.jacobian);
  installed = false;
  long& cnt = st_->counters.jacobianResiduals;
  const int nv = n_.nv, slices = std::min(opt_.jacobianSlices, nv), k = slice_;
  const int begin = nv * k / slices, end = nv * (k + 1) / slices;
  // The fast columns of this slice with the force laws' part at its own
  // point (their slow rest is a difference at one point).
  const std::vector<int>& fast = dae_.fastColumns();
  const bool parts = opt_.fastColumnRescue && dae_.hasFastColumnParts();
  bool fastHere = false;
  for (int c : fast) fastHere = fastHere || (c >= begin && c < end);
  EvalStatus st = stateDerivativeColumns(dae_, t, q_, v_, a_, lam_, begin, end, pending_, ws_, cnt,
                                         parts && fastHere ? &pendingParts_ : nullptr);
  const bool last = k == slices - 1;
  if (st == EvalStatus::Ok && last) st = massMatrixBlock(dae_, t, q_, v_, a_, lam_, pendingFa_, ws_, cnt);
  if (st == EvalStatus::Ok && last) st = constraintJacobianBlock(dae_, t, q_, pendingJ_, ws_, cnt);
  if (st != EvalStatus::Ok) {
    msg = ws_.msg;
    slice_ = -1;  // taken again, from its first slice, at the next step
    return st;
  }
  if (parts && fastHere)
    for (int j = 0; j < static_cast<int>(fast.size()); ++j)
      if (fast[j] >= begin && fast[j] < end) pendingSlowFv_.col(j) = pending_.Fv.col(fast[j]) - pendingParts_.col(j);
  if (!last) {
    ++slice_;
    return EvalStatus::Ok;
  }
  std::swap(dx_, pending_);
  std::swap(Fa_, pendingFa_);
  std::swap(J_, pendingJ_);
  std::swap(slowFv_, pendingSlowFv_);
  fastParts_ = parts;
  blocksEvaluated();
  installed = true;
  return EvalStatus::Ok;
}

void BdfIntegrator::dropFactorizations() {
  factorizedHPrime_ = 0;
  for (KeptFactorization& k : kept_) k.hPrime = 0;
}

void BdfIntegrator::factorize(double hp) {
  ScopedTimer timer(opt_.timing, timers_.jacobian);
  factorizeFor(hp);
}

void BdfIntegrator::factorizeFor(double hp) {
  if (!opt_.keepFactorizations) {
    factorizeAnew(hp);
    return;
  }
  for (const KeptFactorization& k : kept_) {
    if (!sameHPrime(hp, k.hPrime)) continue;
    Ainv_ = k.Ainv;
    fastBaseFv_ = k.fastBaseFv;
    factorizedHPrime_ = k.hPrime;
    lowRank_ = false;
    const std::vector<int>& fast = dae_.fastColumns();
    bool same = true;
    for (int c = 0; c < static_cast<int>(fast.size()) && same; ++c) same = dx_.Fv.col(fast[c]) == fastBaseFv_.col(c);
    if (same || updateFastColumns(hp)) return;
    break;  // near singular by the update: an LU of the whole matrix
  }
  factorizeAnew(hp);
}

void BdfIntegrator::factorizeAnew(double hp) {
  const int nv = n_.nv, nc = n_.nc;
  A_.topLeftCorner(nv, nv) = Fa_ + hp * dx_.Fv + (hp * hp) * dx_.Fq;
  A_.topRightCorner(nv, nc) = J_.transpose();
  A_.bottomLeftCorner(nc, nv) = J_;
  A_.bottomRightCorner(nc, nc).setZero();
  lu_.compute(A_);
  Ainv_.noalias() = lu_.inverse();
  ++st_->counters.factorizations;
  factorizedHPrime_ = hp;
  const std::vector<int>& fast = dae_.fastColumns();
  for (int k = 0; k < static_cast<int>(fast.size()); ++k) fastBaseFv_.col(k) = dx_.Fv.col(fast[k]);
  lowRank_ = false;
  if (!opt_.keepFactorizations) return;
  // In place of one kept for this h' (its update was near singular), or of
  // the oldest.
  int slot = nextKept_;
  for (int i = 0; i < kKeptFactorizations; ++i)
    if (sameHPrime(hp, kept_[i].hPrime)) slot = i;
  if (slot == nextKept_) nextKept_ = (nextKept_ + 1) % kKeptFactorizations;
  KeptFactorization& kept = kept_[slot];
  kept.hPrime = hp;
  kept.Ainv = Ainv_;
  kept.fastBaseFv = fastBaseFv_;
}

// The fast columns of F_v re-evaluated at the iterate; the factorized matrix
// follows by a rank-m update (Woodbury): with U the change of those columns
// of A (h' dF_v, m of them) and E the unit vectors of their indices,
//   (A + U E^T)^-1 = A^-1 - Z (I + E^T Z)^-1 E^T A^-1,   Z = A^-1 U,
// so a refresh costs m residuals (differenced against the iteration's own)
// and an n x n x m product, no LU of A.
EvalStatus BdfIntegrator::refreshFastColumns(double t, double hp, const Residual& base, Message& msg) {
  ScopedTimer timer(opt_.timing, timers_.jacobian);
  const std::vector<int>& fast = dae_.fastColumns();
  const int m = static_cast<int>(fast.size());
  if (fastParts_) {  // the force laws' part at this iterate (its residual's state)
    dae_.fastColumnParts(t, partsNow_);
    for (int k = 0; k < m; ++k) dx_.Fv.col(fast[k]) = slowFv_.col(k) + partsNow_.col(k);
  } else {
    dae_.retract(node(0).q, d_, q_);
    const EvalStatus st = fastVelocityColumns(dae_, t, q_, v_, a_, lam_, base, dx_, ws_, st_->counters.jacobianResiduals);
    if (st != EvalStatus::Ok) {
      msg = ws_.msg;
      return st;
    }
  }
  ++st_->counters.columnRefreshes;
  if (!sameHPrime(hp, factorizedHPrime_)) {
    factorizeFor(hp);  // a new step size: a kept matrix for it, or a new one
    return EvalStatus::Ok;
  }
  // A nearly singular update (the refreshed matrix itself near singular):
  // factorize the whole matrix instead.
  if (!updateFastColumns(hp)) factorizeAnew(hp);
  return EvalStatus::Ok;
}

bool BdfIntegrator::updateFastColumns(double hp) {
  const std::vector<int>& fast = dae_.fastColumns();
  const int m = static_cast<int>(fast.size()), nv = n_.nv;
  for (int k = 0; k < m; ++k) U_.col(k) = hp * (dx_.Fv.col(fast[k]) - fastBaseFv_.col(k));
  Z_.noalias() = Ainv_.leftCols(nv) * U_;
  for (int k = 0; k < m; ++k) S_.row(k) = Z_.row(fast[k]);
  S_ += Mat::Identity(m, m);
  sLu_.compute(S_);
  if (!(std::abs(sLu_.determinant()) > 1e-12)) return false;
  lowRank_ = true;
  return true;
}

// Each fast coordinate's correction with its own equation solved in that
// coordinate alone, the rest of the correction held. Row i of the linear
// step reads K_ii (x - dq_i) = 0 around the linear correction dq_i, with
// K_ii = F_a + h' F_v + h'^2 F_q on the diagonal, whose F_v holds the fast
// part P (the force laws' slope, dF/dv at the Jacobian or the last refresh).
// In the velocity change y = (x + rhoQ_i) / h' that x makes, with y0 the
// linear one, the row with the force laws' exact change N(y) in place of
// their slope is
//   e(y) = s (y - y0) + N(y) - P y0,   s = K_ii / h' - P,
// increasing in y (s > 0: the wheel's inertia over h'; N increasing: a tyre
// and a brake resist their spin), e(0) = -(s + P) y0 since N(0) = 0. Its
// root by the secant method from (0, e(0)) and (y0, e(y0)), Illinois' once
// bracketed: a few force-law evaluations per coordinate, no residual.
void BdfIntegrator::solveFastRows(double t, double hp) {
  constexpr int kMaxEvaluations = 5;
  constexpr double kTolerance = 1e-2;  // of the Newton correction's tolerance (its norm in newton())
  const std::vector<int>& fast = dae_.fastColumns();
  for (int k = 0; k < static_cast<int>(fast.size()); ++k) {
    const int i = fast[k];
    const double P = dx_.Fv(i, i) - slowFv_(i, k);
    const double s = (Fa_(i, i) + hp * dx_.Fv(i, i) + hp * hp * dx_.Fq(i, i)) / hp - P;
    if (!(s > 0)) continue;
    const double y0 = (dq_(i) + rhoQ_(i)) / hp;
    const double tol = kTolerance * (opt_.atol + opt_.rtol * std::abs(d_(i))) / hp;
    auto rowAt = [&](double y, double& e) {
      double n = 0;
      if (!dae_.fastRowChange(t, k, y, n)) return false;
      e = s * (y - y0) + n - P * y0;
      return std::isfinite(e);
    };
    double y1 = 0, e1 = -(s + P) * y0, y2 = y0, e2 = 0;
    if (!(std::abs(y0) > tol) || !rowAt(y2, e2)) continue;
    double y = y2;
    for (int it = 1; it < kMaxEvaluations && e2 != 0 && e2 != e1; ++it) {
      const double y3 = y2 - e2 * (y2 - y1) / (e2 - e1);
      if (!std::isfinite(y3)) break;
      if (std::abs(y3 - y2) <= tol) {
        y = y3;
        break;
      }
      double e3 = 0;
      if (!rowAt(y3, e3)) break;
      y = y3;
      const bool bracketed = (e1 < 0) != (e2 < 0);
      if (!bracketed || (e3 < 0) != (e2 < 0)) {
        y1 = y2;
        e1 = e2;
      } else {
        e1 *= 0.5;  // Illinois: the end that stays is weighed down
      }
      y2 = y3;
      e2 = e3;
    }
    dq_(i) = hp * y - rhoQ_(i);
  }
}

// x -= Z (I + E^T Z)^-1 E^T x: the Woodbury correction of x = A^-1 b.
void BdfIntegrator::applyLowRankUpdate(Vec& x, int rows) {
  if (!lowRank_) return;
  const std::vector<int>& fast = dae_.fastColumns();
  for (int k = 0; k < static_cast<int>(fast.size()); ++k) w_(k) = x(fast[k]);
  w2_ = sLu_.solve(w_);
  x.head(rows).noalias() -= Z_.topRows(rows) * w2_;
}

// Newton iterations from the current iterate: `iterations` of them, or up to
// maxNewtonIterations until the correction is within tolerance.
BdfIntegrator::NewtonOutcome BdfIntegrator::newton(double t, const BdfCoefficients& c, int iterations,
                                                   bool toTolerance, StepReport& rep, bool refreshFast, bool solveRows,
                                                   bool refineEarly) {
  bool refreshNow = refreshFast;
  solveRows = solveRows && fastParts_ && opt_.fastRowSolve;
  const int nv = n_.nv, nc = n_.nc;
  const double hp = c.hPrime, cj = 1.0 / hp;
  int maxIt = toTolerance ? opt_.maxNewtonIterations : iterations;
  double prevNorm = 0;
  for (int it = 1; it <= maxIt; ++it) {
    EvalStatus st;
    {
      ScopedTimer timer(opt_.timing, timers_.residual);
      if (!qAtPredictor_) dae_.retract(node(0).q, d_, q_);
      qAtPredictor_ = false;  // the iterate moves below
      st = dae_.residual(t, q_, v_, a_, lam_, r_, true, rep.message);
      ++st_->counters.residuals;
    }
    if (st == EvalStatus::Ok && refreshNow) st = refreshFastColumns(t, hp, r_, rep.message);
    refreshNow = false;
    if (st != EvalStatus::Ok) {
      rep.status = StepStatus::EvaluationFailed;
      rep.recoverable = st == EvalStatus::Recoverable;
      return NewtonOutcome::Failed;
    }
    ScopedTimer timer(opt_.timing, timers_.backSubstitution);
    // BDF residuals of the current iterate, and the right-hand side of (3.8):
    // [K* Phi_q^T; Phi_q 0][dq; h'^2 dlambda] = [-h'^2 F - h' F_v rhoQ - F_a (rhoQ + h' rhoV); -Phi]
    // (the vector work in bdf_kernels.h: fixed-size for a small ODE).
    dae_.localRate(d_, v_, rate_);
    kernels_.residuals(nv, hp, {d_.data(), v_.data(), a_.data(), rate_.data(), xiQ_.data(), xiV_.data(), r_.F.data(),
                                dx_.Fv.data(), Fa_.data()},
                       {rhoQ_.data(), rhoV_.data(), tmpV_.data(), rhs_.data()});
    for (int i = 0; i < nc; ++i) rhs_(nv + i) = -r_.phi(i);
    kernels_.product(nv + nc, Ainv_.data(), rhs_.data(), sol_.data());
    applyLowRankUpdate(sol_, nv + nc);
    std::copy_n(sol_.data(), nv, dq_.data());
    for (int i = 0; i < nc; ++i) dlam_(i) = sol_(nv + i) / (hp * hp);
    if (solveRows) solveFastRows(t, hp);
    // (3.12): dv = w + e, w = cj (dq + rhoQ) the BDF correction, e the
    // K*-orthogonal correction that restores the linearised velocity
    // constraint Phi_q v + Phi_t + (Phi_q v)_q dq + Phi_q dv = 0.
    kernels_.scaledSum(nv, cj, dq_.data(), rhoQ_.data(), dv_.data());
    if (nc > 0) {  // (an ODE, e.g. the closed-form planar car, has no constraint to restore)
      c_.noalias() = -(J_ * dv_);
      c_.noalias() -= dx_.phiDotQ * dq_;
      c_ -= r_.phiDot;
      // Only the velocity rows of the solution are used (the fast columns
      // index velocities, so the low-rank update needs no more).
      e_.head(nv).noalias() = Ainv_.topRightCorner(nv, nc) * c_;
      applyLowRankUpdate(e_, nv);
      dv_ += e_.head(nv);
    }
    // (3.14): the same for the accelerations and g + g_q dq + g_v dv + Phi_q da = 0.
    kernels_.scaledSum(nv, cj, dv_.data(), rhoV_.data(), da_.data());
    if (nc > 0) {
      c_.noalias() = -(J_ * da_);
      c_.noalias() -= dx_.phiDDotQ * dq_;
      c_.noalias() -= dx_.phiDDotV * dv_;
      c_ -= r_.phiDDot;
      e_.head(nv).noalias() = Ainv_.topRightCorner(nv, nc) * c_;
      applyLowRankUpdate(e_, nv);
      da_ += e_.head(nv);
    }
    st_->counters.solves += 3;
    ++st_->counters.newtonIterations;

    // The update, its norm (the weighted RMS of [dq; h' dv], weights
    // 1 / (atol + rtol |delta|)) and the iterate's finiteness in one pass:
    // x - x is 0 for a finite x and NaN otherwise.
    double nonFinite = 0;
    const double squares = kernels_.update(nv, {d_.data(), v_.data(), a_.data(), dq_.data(), dv_.data(), da_.data(),
                                                opt_.atol, opt_.rtol, factorizedHPrime_},
                                           nonFinite);
    for (int i = 0; i < nc; ++i) {
      lam_(i) += dlam_(i);
      nonFinite += lam_(i) - lam_(i);
    }
    const double norm = std::sqrt(squares / (2.0 * std::max(1, nv)));
    if (it == 1) firstCorrection_ = norm;
    rep.iterations += 1;
    rep.correction = norm;
    rep.contraction = it > 1 ? norm / prevNorm : 0.0;
    worstContraction_ = std::max(worstContraction_, rep.contraction);
    contractionMeasured_ = contractionMeasured_ || it > 1;
    if (!std::isfinite(norm) || !(nonFinite == 0)) {
      rep.status = StepStatus::Diverged;
      rep.message.set("non-finite Newton correction at t = %.6g s (iteration %d)", t, it);
      return NewtonOutcome::Failed;
    }
    // From the predictor, the first correction is the predictor's miss to
    // first order: a first iterate twice refineError away is a step that
    // will be taken again as halves (the factor: a stale Jacobian's first
    // correction may overshoot; at twice, the steps judged here are those
    // the converged miss refines anyway, tests/test_envelope.cpp). Within
    // tolerance it is millimetres below that (and judged when accepted):
    // most steps pay no pass over the coordinates for it.
    if (refineEarly && it == 1 && norm > 1.0 &&
        predictorMiss() > kFirstIterateMiss * opt_.refineError)
      return NewtonOutcome::Refine;
    if (norm <= 1.0 || iterateWithinTolerance(norm)) {
      if (toTolerance || opt_.stopWithinTolerance) return NewtonOutcome::Converged;
    } else if (it > 1 && rep.contraction > (toTolerance ? 1.0 : opt_.contractionLimit)) {
      rep.message.set("Newton not contracting at t = %.6g s: correction %.3g -> %.3g (iteration %d)", t, prevNorm, norm,
                      it);
      if (toTolerance) return NewtonOutcome::NotContracting;
    }
    prevNorm = norm;
    // A fixed count that ends far above tolerance (an impact) but still
    // contracting goes on while it contracts: chord iterations (a residual
    // each) are the cheapest way there.
    const bool chord = opt_.refreshWhenNotContracting && opt_.chordContinuation && !toTolerance;
    if (chord && it == maxIt && it > 1 && it < opt_.maxNewtonIterations && norm > opt_.largeCorrection &&
        rep.contraction < opt_.contractionLimit)
      ++maxIt;
    // Below the low-speed range: on past the count to a fraction of
    // tolerance while contracting (BdfOptions::lowSpeedTolerance).
    else if (lowSpeed_ && opt_.refreshWhenNotContracting && !toTolerance && opt_.lowSpeedTolerance > 0 &&
             it == maxIt && it < opt_.maxNewtonIterations && norm > opt_.lowSpeedTolerance &&
             (it == 1 || rep.contraction < 1.0))
      ++maxIt;
  }
  if (toTolerance) {
    rep.message.set("Newton did not converge in %d iterations at t = %.6g s (correction %.3g)", maxIt, t,
                    rep.correction);
    return NewtonOutcome::NotContracting;
  }
  // A fixed count: fine unless it ended above tolerance without contracting,
  // or far above tolerance (an impact the fixed count cannot absorb).
  const bool stalled = rep.correction > opt_.largeCorrection ||
                       (rep.correction > 1.0 && iterations > 1 && rep.contraction > opt_.contractionLimit);
  return stalled ? NewtonOutcome::NotContracting : NewtonOutcome::Converged;
}

// Newton on to tolerance (the fast-column rescue with a fixed count: on to
// that count's acceptance) with the iteration matrix re-evaluated at every
// iterate (a tyre may have moved between its linear and sliding regimes,
// where a Jacobian from the other regime makes the chord iteration cycle):
// the fast columns alone, or the whole Jacobian. A correction that does not
// reduce the correction norm is halved.
BdfIntegrator::NewtonOutcome BdfIntegrator::fullNewton(double t, const BdfCoefficients& c, JacobianScope scope,
                                                       StepReport& rep) {
  double prev = rep.correction;
  for (int it = 0; it < opt_.maxNewtonIterations; ++it) {
    if (scope == JacobianScope::Whole) {
      dae_.retract(node(0).q, d_, q_);
      const EvalStatus st = evaluateJacobian(t, rep.message);
      if (st != EvalStatus::Ok) {
        rep.status = StepStatus::EvaluationFailed;
        rep.recoverable = st == EvalStatus::Recoverable;
        return NewtonOutcome::Failed;
      }
      factorize(c.hPrime);
    }
    d0_ = d_;
    v0_ = v_;
    a0_ = a_;
    lam0_ = lam_;
    // The fast columns are refreshed inside the iteration, from its residual.
    const bool fastScope = scope == JacobianScope::FastColumns;
    const NewtonOutcome one = newton(t, c, 1, false, rep, fastScope, fastScope);
    if (one == NewtonOutcome::Failed) return one;
    // Damping: a correction larger than the last one is halved (up to 4 times).
    for (int halving = 0; halving < 4 && rep.correction > prev && prev > 1.0; ++halving) {
      d_ = 0.5 * (d_ + d0_);
      v_ = 0.5 * (v_ + v0_);
      a_ = 0.5 * (a_ + a0_);
      lam_ = 0.5 * (lam_ + lam0_);
      rep.correction *= 0.5;
    }
    if (rep.correction <= 1.0) return NewtonOutcome::Converged;
    // With a fixed count, the fast-column rescue ends on the fixed count's own
    // terms: a correction within largeCorrection that contracted (as an
    // ordinary step with 2 iterations is accepted); it need not do better
    // than the steps that never stalled. The whole-Jacobian rescue (the last
    // resort, and DAEs without fast columns) still goes to tolerance.
    if (scope == JacobianScope::FastColumns && opt_.newtonIterations > 0 && it > 0 &&
        rep.correction <= opt_.largeCorrection && rep.correction < opt_.contractionLimit * prev)
      return NewtonOutcome::Converged;
    prev = rep.correction;
  }
  rep.message.set("Newton did not converge at t = %.6g s (correction %.3g after %d full Newton iterations)", t,
                  rep.correction, opt_.maxNewtonIterations);
  return NewtonOutcome::NotContracting;
}

// BdfOptions::earlyEndFromContraction: the iterate's error estimated from
// the correction (in tolerances) and the blocks' slowest contraction. The
// estimate trusts the contraction of earlier steps, which a step that turns
// sharply (a wheel landing, a curb) need not share: it is taken for a
// correction of 1 / kStaleContraction tolerances at most, so that even a
// step contracting as slowly as blocks still counted fresh leaves its
// iterate within tolerance. (Without that bound the estimate ended steps of
// the curb strike and the ramp jump whose iterate was not: RESULTS 5b's
// kinematic rung there 3-4 times further from the linkage.)
bool BdfIntegrator::iterateWithinTolerance(double correction) const {
  if (!opt_.earlyEndFromContraction || !opt_.stopWithinTolerance || n_.nc > 0 || !contractionMeasured_ ||
      !(worstContraction_ < kStaleContraction) || correction * kStaleContraction > 1.0)
    return false;
  const double eta = std::pow(std::max(worstContraction_ / (1.0 - worstContraction_), 1e-16), 0.8);
  return eta * correction <= 1.0;
}

double BdfIntegrator::predictorMiss() const {
  double miss = 0;
  for (int i = 0; i < n_.nv; ++i) miss = std::max(miss, std::abs(d_(i) - dPred_(i)));
  return miss;
}

void BdfIntegrator::startFromPredictor() {
  d_ = dPred_;
  v_ = vPred_;
  a_ = aPred_;
  lam_ = lamPred_;
}

// A step whose fixed count stalled. With fast columns (Dae::fastColumns):
// (a) those columns re-evaluated at the stalled iterate (at the predictor if
// the attempt got nowhere) and the fixed count again; (b) Newton on to
// tolerance, the fast columns re-evaluated at every iterate; failing that the
// step is split, and only at the last split (c) the whole Jacobian at the
// predictor and Newton on to tolerance with it re-evaluated at every iterate.
// A few residuals and a rank-m update per iterate instead of 1 + 2 nv
// residuals and an LU: the bounded step of a rough road. Without fast
// columns: the whole Jacobian at the predictor and the fixed count again,
// then Newton on to tolerance with the whole Jacobian at every iterate.
BdfIntegrator::NewtonOutcome BdfIntegrator::recover(double t, const BdfCoefficients& c, bool fresh, bool lastResort,
                                                    StepReport& rep) {
  auto attempt = [&](bool refreshFast) {
    rep.status = StepStatus::Ok;
    rep.recoverable = false;
    rep.iterations = 0;
    return newton(t, c, opt_.newtonIterations, opt_.newtonIterations <= 0, rep, refreshFast);
  };
  auto failed = [&](EvalStatus st) {
    rep.status = StepStatus::EvaluationFailed;
    rep.recoverable = st == EvalStatus::Recoverable;
    return NewtonOutcome::Failed;
  };
  NewtonOutcome out = NewtonOutcome::NotContracting;
  if (opt_.fastColumnRescue && !dae_.fastColumns().empty()) {
    // (a) the refresh from the attempt's first residual
    if (!(rep.correction < firstCorrection_)) startFromPredictor();
    ++st_->counters.refreshes;
    out = attempt(true);
    if (out != NewtonOutcome::NotContracting) return out;
    // (b)
    ++st_->counters.rescues;
    out = fullNewton(t, c, JacobianScope::FastColumns, rep);
    if (out != NewtonOutcome::NotContracting) return out;
    if (!lastResort) return out;  // split: a shorter step is the cheaper cure
    // (c)
    startFromPredictor();
    dae_.retract(node(0).q, d_, q_);
    if (const EvalStatus st = evaluateJacobian(t, rep.message); st != EvalStatus::Ok) return failed(st);
    factorize(c.hPrime);
    return fullNewton(t, c, JacobianScope::Whole, rep);
  }
  if (!fresh) {  // stale Jacobian: the whole Jacobian at the predictor, the fixed count again
    ++st_->counters.refreshes;
    startFromPredictor();
    dae_.retract(node(0).q, d_, q_);
    if (const EvalStatus st = evaluateJacobian(t, rep.message); st != EvalStatus::Ok) return failed(st);
    factorize(c.hPrime);
    out = attempt(false);
    if (out != NewtonOutcome::NotContracting) return out;
  }
  ++st_->counters.rescues;
  return fullNewton(t, c, JacobianScope::Whole, rep);
}

StepReport BdfIntegrator::substep(double h, bool jacobianDue, bool lastResort, bool mayRefine) {
  StepReport rep;
  const double tNew = node(0).t + h;
  const int k = std::min(opt_.order, st_->count);
  const int np = std::min(k + 1, st_->count);  // nodes for the predictor polynomial
  std::array<double, kMaxBdfOrder + 2> times{};
  times[0] = tNew;
  for (int i = 1; i <= np; ++i) times[i] = node(i - 1).t;
  const BdfCoefficients c = bdfCoefficients(times.data(), k);

  // Past nodes in local coordinates around q_{n-1} (delta_0 = 0); the BDF
  // history terms xi and the predictor, the polynomial through the last np
  // nodes at tNew, which is also Newton's start (startFromPredictor); the
  // sums in the order of the nodes (bdf_kernels.h).
  for (int i = 1; i < np; ++i) dae_.localCoordinates(node(0).q, node(i).q, delta_[i]);
  std::array<double, kMaxBdfOrder + 2> w{};
  lagrangeWeights(times.data() + 1, np, tNew, w.data());
  {
    std::array<const double*, kMaxBdfOrder + 2> dl{}, vl{}, al{};
    for (int i = 0; i < np; ++i) {
      dl[i] = delta_[i].data();
      vl[i] = node(i).v.data();
      al[i] = node(i).a.data();
    }
    kernels_.predict(n_.nv, {k, np, c.xi.data(), w.data(), dl.data(), vl.data(), al.data()},
                     {xiQ_.data(), xiV_.data(), dPred_.data(), vPred_.data(), aPred_.data(), d_.data(), v_.data(),
                      a_.data()});
  }
  copyInto(node(0).lambda, lamPred_);
  copyInto(lamPred_, lam_);
  dae_.retract(node(0).q, dPred_, q_);
  dae_.beginStep(tNew, q_, vPred_);

  // The fixed count from the predictor (the iterate is already there) with
  // the Jacobian as it is (evaluated here when due); when it stalls, recover().
  qAtPredictor_ = true;
  bool fresh = false;
  if (jacobianDue || !haveBlocks_) {
    if (const EvalStatus st = evaluateJacobian(tNew, rep.message); st != EvalStatus::Ok) {
      rep.status = StepStatus::EvaluationFailed;
      rep.recoverable = st == EvalStatus::Recoverable;
      qAtPredictor_ = false;
      return rep;
    }
    fresh = true;
    rep.jacobianEvaluated = true;
  } else if (sliceThisStep_) {
    // A slice of the periodic Jacobian (the step's first piece takes it);
    // once whole, its columns are from this and the last few steps: not
    // fresh for the rescue (recover), which may want this step's own.
    sliceThisStep_ = false;
    bool installed = false;
    if (const EvalStatus st = evaluateJacobianSlice(tNew, rep.message, installed); st != EvalStatus::Ok) {
      rep.status = StepStatus::EvaluationFailed;
      rep.recoverable = st == EvalStatus::Recoverable;
      qAtPredictor_ = false;
      return rep;
    }
    rep.jacobianEvaluated = installed;
  }
  // Refactor only for a real change of step or order.
  if (!sameHPrime(c.hPrime, factorizedHPrime_)) factorize(c.hPrime);
  rep.status = StepStatus::Ok;
  const bool fixedCount = opt_.newtonIterations > 0;
  const bool judged = mayRefine && st_->count > 1;  // the predictor's miss (below)
  NewtonOutcome out =
      newton(tNew, c, opt_.newtonIterations, !fixedCount, rep, false, false, judged && opt_.refineFromFirstIterate);
  if (out == NewtonOutcome::Refine) {
    rep.refine = true;
    return rep;
  }
  if (out == NewtonOutcome::Failed) return rep;
  if (out == NewtonOutcome::NotContracting && opt_.refreshWhenNotContracting) {
    out = recover(tNew, c, fresh, lastResort, rep);
    if (out == NewtonOutcome::Failed) return rep;
    if (out != NewtonOutcome::Converged) {
      rep.status = StepStatus::Diverged;
      return rep;
    }
  }

  // The predictor's miss (from the second step on: the first's predictor is
  // a constant) measures the step's local error (Milne's device: BDF2's is
  // about 2/9 of it); too large, the step is taken again as halves.
  if (judged && predictorMiss() > opt_.refineError) {
    rep.refine = true;
    return rep;
  }
  // Accept: the new node becomes node(0).
  SolutionPoint& p = st_->push();
  p.t = tNew;
  dae_.retract(node(1).q, d_, p.q);
  copyInto(v_, p.v);
  copyInto(a_, p.a);
  copyInto(lam_, p.lambda);
  ++st_->counters.substeps;
  if (dae_.acceptStep(tNew, h, p.q, p.v, rep.message) != EvalStatus::Ok) rep.status = StepStatus::StateCheckFailed;
  return rep;
}

}  // namespace bdfcar::integ
