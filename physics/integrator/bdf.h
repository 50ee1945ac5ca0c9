// Fixed-step BDF on the over-determined DAE (paper eqs. 3.3-3.14).
//
// Unknowns of a step: q (through local coordinates delta around q_{n-1}),
// v, a, lambda. Each Newton iteration evaluates the residual once and solves
// three systems with ONE factorization of
//     A = [K* Phi_q^T; Phi_q 0],   K* = F_a + h' F_v + h'^2 F_q,
// for the position correction (3.8), then the velocity (3.12) and
// acceleration (3.14) corrections, which keep the BDF relations in the
// tangent directions and impose the velocity / acceleration constraints in
// the others. The factorization is kept as an explicit inverse, so the three
// solves are matrix-vector products (the last two use only its constraint
// columns). The Jacobian blocks are reused for jacobianEvery steps; when
// Newton stalls, the DAE's fast columns are refreshed first (recover()).
#pragma once

#include <Eigen/LU>
#include <array>

#include "integrator/bdf_coefficients.h"
#include "integrator/bdf_kernels.h"
#include "integrator/dae_blocks.h"
#include "integrator/forward_dynamics.h"
#include "integrator/step_types.h"

namespace bdfcar::integ {

enum class StartUp {
  Auto,       // OrderRamp for order <= 2, Substeps above
  OrderRamp,  // fixed step, order raised by one per step (order-2 accurate start)
  Substeps,   // first step split into geometrically growing sub-steps (full-order start)
};

// The defaults are the paper's setting as bdfcar runs it (2 Newton
// iterations, the Jacobian every 200 steps, refreshed when Newton stops
// contracting); scenario files and the CLI write into these fields.
struct BdfOptions {
  int order = 2;                  // BDF order, 1..5
  int newtonIterations = 2;       // fixed count (the paper: 2); 0 = iterate to tolerance
  int maxNewtonIterations = 10;   // cap when iterating to tolerance
  // A fixed count ends early at an iteration whose correction is within
  // tolerance (bdfcar's scenes, every rung: scenario FidelitySpec). Off: the
  // count in full, as the paper.
  bool stopWithinTolerance = false;
  // With stopWithinTolerance: the early end judges the iterate, not only the
  // correction (Hairer and Wanner, Solving ODEs II, IV.8: the chord
  // iteration's error after a correction d is about eta |d|, eta = theta /
  // (1 - theta) for a contraction theta): once a contraction has been
  // measured on the blocks in use, a correction whose iterate is then
  // within tolerance ends the count, eta the slowest contraction since the
  // blocks raised to 0.8 (their safety exponent), for a correction of a few
  // tolerances at most (BdfIntegrator::iterateWithinTolerance). The closed
  // forms' (no constraints: their blocks exact, a chord step's contraction
  // steady): most of the steps that took a second residual to show their
  // iterate within tolerance take one (the sedan's J-turn: 1.17 residuals a
  // step -> 1.06 on the kinematic rung, 1.19 -> 1.05 on the planar).
  bool earlyEndFromContraction = false;
  double atol = 1e-6;             // Newton tolerance on the correction, absolute (m, rad)
  double rtol = 1e-6;             // ... relative to the motion over the step
  int jacobianEvery = 200;        // evaluate the Jacobian every N steps; 0 = first step only
  // (without constraints, with refreshWhenNotContracting and N over 10:
  // every N steps once Newton has contracted slower than kStaleContraction
  // since the last; skipsFreshJacobian)
  // That periodic Jacobian taken in this many slices of its columns, one at
  // the start of each of as many steps (at that step's predictor), used
  // once the last is in: the step that refreshes it pays a slice's
  // residuals, not the 2 nv + 1 of the whole (on the linkage 75, about a
  // millisecond on relief: the longest step of a run, RESULTS 4b). The
  // columns of a few steps apart are as good an iteration matrix as those
  // of one step (it is 200 steps old when refreshed). With
  // refreshWhenNotContracting only, where the DAE's blocks come by
  // differences (constraints: the multibody models) and jacobianEvery is
  // at least ten times the slices (a Jacobian asked for every few steps is
  // asked for fresh); 1: whole, at one step (the paper's). A Jacobian
  // Newton needs at once (none yet, a stalled step's rescue) is always whole.
  int jacobianSlices = 16;
  // When the fixed count ends above tolerance and the last correction shrank
  // less than contractionLimit times: refresh a stale Jacobian and redo the
  // step, then (fresh Jacobian) iterate on to tolerance. Off = the paper's
  // method as published (for its Tables 3 and 4).
  bool refreshWhenNotContracting = true;
  double contractionLimit = 0.5;
  // A fixed-count step whose last correction is above this many tolerances
  // has not converged whatever its contraction (an impact): treated as stalled.
  double largeCorrection = 100.0;
  // Below the tyres' low-speed range (Integrator::setLowSpeed) a fixed count
  // that ends within tolerance but with a correction above this fraction of
  // it goes on, up to maxNewtonIterations, while it contracts: there the
  // contacts are stiff, lightly damped springs, and the error a correction
  // just within tolerance leaves (about 1e-4 m/s on velocity) keeps a
  // stopped car trembling, with how much depending on the Jacobian it stops
  // with (tests/test_scenario.cpp, Standstill: 0.01 removes it in all of
  // its 18 brakings). Only below the low-speed range, so a moving car's
  // steps are the fixed count's as before (RESULTS 1-3 do not move). 0: off.
  double lowSpeedTolerance = 0.01;
  // Parts of that policy, each on by default (off only to measure what it
  // buys, RESULTS 4b): chord iterations past the fixed count while an
  // impact's large correction still contracts; the rescue by the DAE's fast
  // columns (Dae::fastColumns) before the whole Jacobian.
  bool chordContinuation = true;
  bool fastColumnRescue = true;
  // In that rescue's full Newton, each fast coordinate's own equation
  // solved in that coordinate, nonlinearly (Dae::fastRowChange), after each
  // linear correction: a tyre's force saturates within one correction, where
  // the linear one overshoots and Newton cycles (a rough road's loads swing
  // the tyres in and out of saturation step to step). Only there: in the
  // fixed count it would let a rescue end on the fixed count's acceptance
  // further from the solution, and on smooth ground it costs a tyre
  // evaluation per wheel and iteration for nothing.
  bool fastRowSolve = true;
  // The factorized matrices of the last few h' kept since the Jacobian (off:
  // an LU and inverse at every change of h').
  bool keepFactorizations = true;
  // A converged step whose solution lies further than refineError (m, rad,
  // the largest over the coordinates' increments) from its predictor is
  // not accepted but taken as two halves, recursively, at most refineDepth
  // times (3: down to an eighth). The predictor's miss grows as h^3 times
  // the motion's third derivative: an impact, a wheel landing, a kink in
  // the road or the steering; smooth driving stays far below it. 0: off
  // (and off with refreshWhenNotContracting: the paper's method).
  double refineError = 3e-3;
  int refineDepth = 3;
  // The miss judged after the first Newton iteration too: a first iterate
  // twice refineError from the predictor (Newton's first correction from it
  // is the miss to first order) is halved at once, before the iterations,
  // fast-column refreshes and rescues that would converge a step taken
  // again anyway (on the rough road and the washboard an eighth of all
  // iterations). Off only to measure what it buys (RESULTS 4b).
  bool refineFromFirstIterate = true;
  // A step after refined pieces goes on in pieces of the last one's length,
  // doubled only where the last piece's miss times 2^(order+1) is within
  // refineError (on relief a whole step would miss again: on the rough road
  // nearly every step was refined, a first attempt wasted each time). Off
  // (every step first tried whole) only to measure what it buys (RESULTS 4b).
  bool carryRefinedPieces = true;
  StartUp startUp = StartUp::Auto;
  // Accumulate the Jacobian / residual / back-substitution split (the
  // report's section 5, the benchmarks). Off unless asked: its clock reads,
  // about 40 ns each and 8 a step, are a tenth of a planar step.
  bool timing = false;
};

class BdfIntegrator final : public Integrator {
 public:
  BdfIntegrator(Dae& dae, const BdfOptions& options);
  BdfIntegrator(const BdfIntegrator&) = delete;  // it points into its own state
  BdfIntegrator& operator=(const BdfIntegrator&) = delete;

  EvalStatus initialize(double t0, const Vec& q0, const Vec& v0, Message& msg) override;
  EvalStatus restart(double t0, const Vec& q0, const Vec& v0, Message& msg) override;
  // Starts from a point whose a and lambda are already consistent.
  void initializeConsistent(const SolutionPoint& p);
  StepReport step(double h) override;

  const SolutionPoint& current() const override { return node(0); }
  const Counters& counters() const override { return st_->counters; }
  const Timers& timers() const override { return timers_; }
  void bindState(IntegratorState& s) override;
  const IntegratorState& state() const override { return *st_; }
  void markJacobianStale() override {
    haveBlocks_ = false;
    slice_ = -1;  // a Jacobian in slices too: a run restored from its state has none
  }
  void setNewtonEarlyEnd(bool on) override { opt_.stopWithinTolerance = on; }
  void setLowSpeed(bool on) override { lowSpeed_ = on; }
  const BdfOptions& options() const { return opt_; }

 private:
  static_assert(IntegratorState::kSlots == kMaxBdfOrder + 2, "the ring holds the highest order's history");

  const SolutionPoint& node(int i) const { return st_->node(i); }
  SolutionPoint& node(int i) { return st_->node(i); }
  // lastResort: the deepest split, where a stalled step may evaluate the
  // whole Jacobian at every iterate.
  // mayRefine: a step that misses its predictor by more than refineError
  // returns refine, not accepted (splitOnFailure).
  StepReport substep(double h, bool jacobianDue, bool lastResort = false, bool mayRefine = false);
  static constexpr int kMaxSplits = 4;
  // depth: halvings of the outer step so far; failures: those of them for
  // failed attempts (kMaxSplits bounds these, refineDepth the depth).
  StepReport splitOnFailure(double h, bool jacobianDue, int depth, int failures);
  StepReport halves(double h, int depth, int failures);
  bool refining() const;  // refineError and refineDepth in force
  // The step of h in pieces: whole, or after refined steps in pieces of
  // their last length, doubled where the last miss says a doubled one would
  // pass (nextDepth, from the history: lastPieceMiss), each by splitOnFailure.
  StepReport pieces(double h, bool jacobianDue);
  int nextDepth(double h, int deepest, long at);
  double lastPieceMiss(int order);
  EvalStatus evaluateJacobian(double t, Message& msg);
  // The periodic Jacobian in slices (BdfOptions::jacobianSlices): whether
  // it is taken so, the next slice at the iterate (the step's predictor),
  // true in installed where it was the last (the blocks then in use).
  bool spreadsJacobian() const;
  bool skipsFreshJacobian() const;  // the periodic Jacobian waits for a slow contraction
  EvalStatus evaluateJacobianSlice(double t, Message& msg, bool& installed);
  // What a new set of blocks starts: the fast columns' slow rest, the counters, no factorization kept.
  void blocksEvaluated();
  // The iteration matrix for h' (its inverse): one kept for this h' since
  // the blocks were evaluated, brought to the fast columns of now by a
  // low-rank update, or a new LU.
  void factorize(double hPrime);  // timed (timers_.jacobian); the two below are not
  void factorizeFor(double hPrime);
  void factorizeAnew(double hPrime);
  void dropFactorizations();
  // The Woodbury update from the factorized fast columns to dx_.Fv's: false
  // where the updated matrix is near singular.
  bool updateFastColumns(double hPrime);
  // base: the residual at the iterate (the Newton iteration's own).
  EvalStatus refreshFastColumns(double t, double hPrime, const Residual& base, Message& msg);
  void solveFastRows(double t, double hPrime);
  // x = A^-1 b for the factorized A -> the refreshed matrix's solution, in its
  // first `rows` rows (the velocity solves use only the first nv).
  void applyLowRankUpdate(Vec& x, int rows);
  void startFromPredictor();
  // A correction (in tolerances) whose iterate is within tolerance by the contraction (earlyEndFromContraction).
  bool iterateWithinTolerance(double correction) const;
  // The iterate's largest coordinate distance from the predictor (m, rad).
  double predictorMiss() const;
  // Refine: the first iterate missed the predictor by twice refineError (refineEarly).
  enum class NewtonOutcome { Converged, NotContracting, Failed, Refine };
  // refreshFast: re-evaluate the fast columns at the first iterate (from its residual) before solving.
  // solveRows: each correction's fast coordinates by solveFastRows (the fast-column rescue's full Newton).
  // refineEarly: end with Refine after a first iterate that far from the predictor.
  NewtonOutcome newton(double t, const BdfCoefficients& c, int iterations, bool toTolerance, StepReport& rep,
                       bool refreshFast = false, bool solveRows = false, bool refineEarly = false);
  enum class JacobianScope { FastColumns, Whole };
  NewtonOutcome fullNewton(double t, const BdfCoefficients& c, JacobianScope scope, StepReport& rep);
  NewtonOutcome recover(double t, const BdfCoefficients& c, bool fresh, bool lastResort, StepReport& rep);

  Dae& dae_;
  BdfOptions opt_;
  DaeSizes n_;
  const kernels::StepKernels& kernels_;  // the step's vector work, for n_
  IntegratorState own_;            // the state until bindState
  IntegratorState* st_ = &own_;   // history and counters
  Timers timers_;
  ForwardDynamics forward_;
  BlockWorkspace ws_;

  // Jacobian state.
  bool haveBlocks_ = false;
  bool lowSpeed_ = false;  // setLowSpeed: set by the caller before each step
  long stepsSinceJacobian_ = 0;
  double worstContraction_ = 0;  // Newton's slowest contraction since the blocks were taken
  bool contractionMeasured_ = false;  // ... and whether one has been (a step of two iterations or more)
  // Between the two populations (DESIGN): exact blocks contracted by 0.10
  // at most (the sedan's J-turn, either rung), stale ones by 0.3 or more at
  // most slow steps; half the contraction at which a step stops as not
  // contracting (BdfOptions::contractionLimit).
  static constexpr double kStaleContraction = 0.25;
  static constexpr int kAskedFresh = 10;  // a Jacobian asked for every this many steps or fewer is asked fresh
  double factorizedHPrime_ = 0;
  StateDerivatives dx_;    // F_q, F_v and the constraint-level derivatives
  Mat Fa_, J_;             // (nv x nv), (nc x nv)
  Mat A_, Ainv_;           // (nv+nc)^2
  // The last few factorizations of these blocks, by h': a refined step's
  // halves and the steps after them come back to the same few h', and each
  // would otherwise cost an LU and an inverse (dropped with the blocks).
  // Eight: a washboard's pieces use eight h' (four missed at most steps;
  // sixteen saves no more).
  struct KeptFactorization {
    double hPrime = 0;  // 0: empty
    Mat Ainv, fastBaseFv;
  };
  static constexpr int kKeptFactorizations = 8;
  std::array<KeptFactorization, kKeptFactorizations> kept_;
  int nextKept_ = 0;
  Eigen::PartialPivLU<Mat> lu_;
  // Refreshed fast columns as a rank-m update of the factorized matrix
  // (refreshFastColumns): their F_v columns when it was factorized, the
  // change U, Z = A^-1 U and the LU of I + E^T Z.
  bool lowRank_ = false;
  Mat fastBaseFv_, U_, Z_, S_;
  Eigen::PartialPivLU<Mat> sLu_;
  Vec w_, w2_;
  // Where the DAE gives its fast columns' fast part (Dae::fastColumnParts):
  // the rest of each fast column at the Jacobian (slowFv_), which a refresh
  // adds to the part at the iterate (partsNow_) in place of finite differences.
  bool fastParts_ = false;
  Mat slowFv_, partsNow_;
  // A Jacobian in slices: the next slice (-1: none under way), whether this
  // step's first piece takes it, the blocks so far (swapped in when whole).
  int slice_ = -1;
  bool sliceThisStep_ = false;
  StateDerivatives pending_;
  Mat pendingFa_, pendingJ_, pendingSlowFv_, pendingParts_;
  double firstCorrection_ = 0;  // the first correction norm of the last Newton attempt

  // Step work vectors.
  std::array<Vec, kMaxBdfOrder + 2> delta_;  // local coordinates of past nodes around q_{n-1}
  Vec missScratch_;                          // lastPieceMiss's node(0) around node(1)
  Vec xiQ_, xiV_;
  Vec dPred_, vPred_, aPred_, lamPred_;
  Vec d_, q_, v_, a_, lam_;                  // Newton iterate
  // q_ already holds the predictor's configuration (substep retracted it
  // for beginStep): the first iteration from the predictor skips the retract.
  bool qAtPredictor_ = false;
  Vec d0_, v0_, a0_, lam0_;                  // the iterate before a damped full Newton correction
  Vec rate_, rhoQ_, rhoV_, tmpV_, rhs_, sol_, c_, e_;
  Vec dq_, dv_, da_, dlam_;
  Residual r_;
};

}  // namespace bdfcar::integ
