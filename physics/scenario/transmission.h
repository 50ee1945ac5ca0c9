// The gearbox's and clutch's controller: what a car's transmission decides
// once per step, outside the implicit step (the engine speed it reads is the
// accepted state's), held over the step as a DrivelineCommand.
//
//  - Gears: reverse (-1), neutral (0), 1..n. The driver's requests move one
//    gear at a time; reverse is refused above 1 m/s forwards, first gear
//    from reverse above 1 m/s backwards. An automatic box goes from first
//    straight to reverse and back (no neutral, as D and R), and shifts by
//    its schedule (powertrain_spec.h): up when the engine speed the gear
//    would give passes the throttle-dependent upshift speed, down below the
//    downshift speed.
//  - Shifting without a clutch pedal: the clutch opens over the first half
//    of shiftTime with the throttle closed, the gear changes, the clutch
//    closes over the second half with the throttle opening as it closes (an
//    automated manual gearbox). With a
//    pedal, the gear changes at once and the clutch is the driver's.
//  - Pulling away without a pedal: the clutch's engagement follows the
//    engine speed from 5 % above idle (open) to launchSpeed (closed), so
//    the engine idles with the car held and takes up the drive as the
//    throttle opens; once the gear turns the engine faster than
//    launchSpeed it stays closed. Its engagement changes by at most 1 per
//    0.2 s (a clutch actuator's rate).
#pragma once

#include "scenario/driver_input.h"
#include "vehicle/powertrain.h"

namespace bdfcar::scenario {

struct TransmissionState {
  int gear = 1;               // -1 reverse, 0 neutral, 1..n
  int nextGear = 1;           // during a shift: the gear it goes to
  double shiftClock = -1;     // s since the shift began; < 0: not shifting
  double engagement = 0;      // [0, 1] of the clutch's capacity
  bool operator==(const TransmissionState&) const = default;
};

// The speeds the controller reads, from the accepted state.
struct DrivelineSpeeds {
  double engine = 0;   // rad/s, crank relative to the chassis
  double output = 0;   // rad/s, mean relative spin of the driven wheels, + forwards
  double vx = 0;       // m/s, the car's forward speed
};

class Transmission {
 public:
  // state: where its run state lives (a RunState's).
  Transmission(const vehicle::PowertrainSpec& spec, TransmissionState& state) : spec_(spec), state_(state) {}

  // The gear a car starting at forward speed vx with its driven wheels at
  // `output` rad/s starts in: first at rest, else the lowest gear that does
  // not turn the engine past the light-throttle upshift speed; clutch closed
  // when moving.
  void start(double output, double vx);
  // The command for the next step of length h.
  vehicle::DrivelineCommand update(const DriverInput& in, const DrivelineSpeeds& s, double h);

  const TransmissionState& state() const { return state_; }
  bool shifting() const { return state_.shiftClock >= 0; }

  static constexpr double kEngagementRate = 5.0;   // 1/s
  static constexpr double kReverseSpeed = 1.0;     // m/s

 private:
  void request(int direction, double vx, double output);
  void beginShift(int to);
  double launchEngagement(double engineSpeed, double lockedSpeed) const;

  const vehicle::PowertrainSpec& spec_;
  TransmissionState& state_;
  bool pedal_ = false;        // the current request came with a clutch pedal (this update's input)
};

}  // namespace bdfcar::scenario
