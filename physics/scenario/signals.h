// Scripted driver inputs as functions of manoeuvre time with exact first and
// second derivatives (the rack driver needs them at the velocity and
// acceleration constraint levels).
#pragma once

#include <memory>
#include <vector>

#include "multibody/time_signal.h"

namespace bdfcar::scenario {

using mb::SignalValue;
using Signal = mb::TimeSignal;

// 0 before `start`, linear to `level` over `rise` seconds, then held (the J-turn).
class RampSignal final : public Signal {
 public:
  RampSignal(double start, double rise, double level) : start_(start), rise_(rise), level_(level) {}
  SignalValue at(double t) const override;

 private:
  double start_, rise_, level_;
};

// amplitude * sin(2 pi (t - start) / period) for `periods` whole periods
// from `start`, else 0 (one period: the lane change).
class SinePeriodSignal final : public Signal {
 public:
  SinePeriodSignal(double start, double period, double amplitude, int periods = 1)
      : start_(start), period_(period), amplitude_(amplitude), periods_(periods) {}
  SignalValue at(double t) const override;

 private:
  double start_, period_, amplitude_;
  int periods_;
};

// Sine with dwell (FMVSS 126): amplitude * sin(2 pi (t - start) / period)
// for 3/4 of a period (to its second peak, -amplitude), held for `dwell`,
// then the last quarter period back to zero; 0 elsewhere. C1 across the
// dwell, with exact derivatives on each piece; at its end the value returns
// to zero from its last slope (as the regulation's steering robot stops).
class SineWithDwellSignal final : public Signal {
 public:
  SineWithDwellSignal(double start, double period, double amplitude, double dwell)
      : start_(start), period_(period), amplitude_(amplitude), dwell_(dwell) {}
  SignalValue at(double t) const override;

 private:
  double start_, period_, amplitude_, dwell_;
};

// Linear chirp: amplitude * sin(phi) with phi = 2 pi (f0 tau + (f1 - f0)
// tau^2 / (2 duration)), tau = t - start, for `duration` from `start` (the
// frequency sweeps from f0 to f1); 0 elsewhere. For frequency responses.
class ChirpSignal final : public Signal {
 public:
  ChirpSignal(double start, double duration, double amplitude, double f0, double f1)
      : start_(start), duration_(duration), amplitude_(amplitude), f0_(f0), f1_(f1) {}
  SignalValue at(double t) const override;

 private:
  double start_, duration_, amplitude_, f0_, f1_;
};

// +amplitude for the first half of each period from `start`, -amplitude for
// the second, 0 before: a flip-flop input (as a driver's command only: its
// jumps are not a motion a rack could follow).
class SquareSignal final : public Signal {
 public:
  SquareSignal(double start, double period, double amplitude) : start_(start), period_(period), amplitude_(amplitude) {}
  SignalValue at(double t) const override;

 private:
  double start_, period_, amplitude_;
};

// Piecewise linear through (t_i, value_i), held before the first and after the last point.
class TableSignal final : public Signal {
 public:
  TableSignal(std::vector<double> t, std::vector<double> v) : t_(std::move(t)), v_(std::move(v)) {}
  SignalValue at(double t) const override;

 private:
  std::vector<double> t_, v_;
};

// A scripted signal ramped in during the settling phase [t0, 0): from 0 at
// t0 to the signal's value at 0, C1 (smoothstep), so that a steering that does
// not start at zero moves the rack smoothly instead of jumping at t0.
class RampedInSignal final : public Signal {
 public:
  RampedInSignal(std::unique_ptr<Signal> inner, double t0) : inner_(std::move(inner)), t0_(t0) {}
  SignalValue at(double t) const override;

 private:
  std::unique_ptr<Signal> inner_;
  double t0_;
};

class ConstantSignal final : public Signal {
 public:
  explicit ConstantSignal(double v = 0) : v_(v) {}
  SignalValue at(double) const override { return {v_, 0, 0}; }

 private:
  double v_;
};

}  // namespace bdfcar::scenario
