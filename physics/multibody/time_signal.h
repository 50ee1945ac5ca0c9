// A function of time with its first two derivatives: the one signal type of
// bdfcar. Driver constraints (the rack) sample it at the velocity and
// acceleration constraint levels; the scenario's scripted inputs (steering,
// throttle, brake) are signals of this type.
#pragma once

namespace bdfcar::mb {

struct SignalValue {
  double value = 0.0, rate = 0.0, accel = 0.0;
};

class TimeSignal {
 public:
  virtual ~TimeSignal() = default;
  virtual SignalValue at(double t) const = 0;
};

}  // namespace bdfcar::mb
