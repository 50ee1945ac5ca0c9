// The numbers of one telemetry row, in the order of the CSV header: the
// telemetry writer formats them (telemetry.h), the Python module hands them
// over as an array (python/). One place computes them, so the file and the
// array agree to the last digit the file prints.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "vehicle/vehicle_builder.h"
#include "vehicle/vehicle_sample.h"

namespace bdfcar::scenario {

// A powertrain's channels (columns after the others, on a car with one).
struct PowertrainChannels {
  double engineRpm = 0;      // crank relative to the chassis
  int gear = 0;              // -1 reverse, 0 neutral, 1..n
  double clutch = 0;         // [0, 1] engagement (1 closed)
  double clutchSlipRpm = 0;  // crank less gearbox input
  double engineTorque = 0;   // N m, combustion less friction
  double clutchTorque = 0;   // N m into the gearbox
  double throttle = 0;       // [0, 1] at the engine: the driver's, the speed hold's, closed during a shift
  double handbrake = 0;      // [0, 1]
};

// Lap timing's channels (columns after the others, on a scenario with [laps]).
struct LapChannels {
  int lap = 0;               // the lap under way: 0 the out lap, then 1, 2, ...
  double lapTime = -1;       // s into it (-1 on the out lap)
  double distance = 0;       // m along the track from the start line
};

// Quantities of a row that are not in the vehicle sample.
struct TelemetryInputs {
  double steer = 0;      // normalised steering input s
  double throttle = 0, brake = 0;
  int newtonIterations = 0;
  double newtonCorrection = 0;  // weighted norm of the last correction (1 = tolerance)
  int segment = 0;              // a drive's segment: +1 at each reset, rewind or divergence reset
  int fidelity = 0;             // the model driving: vehicle::Fidelity (0 linkage, 1 kinematic, 2 planar)
  double switchJump = 0;        // m, the chassis moved by rung switches since the last row (`auto`)
  PowertrainChannels powertrain;  // written when the vehicle has a powertrain
  LapChannels laps;               // written when the scenario times laps
};

// How the file prints a column: 10 significant digits, 4 (the Newton
// correction), or a whole number.
enum class ColumnFormat : unsigned char { Real10, Real4, Integer };

class TelemetryRowMaker {
 public:
  static constexpr int kBaseColumns = 87, kPowertrainColumns = 8, kLapColumns = 3;
  static constexpr int kMaxColumns = kBaseColumns + kPowertrainColumns + kLapColumns;
  using Values = std::array<double, kMaxColumns>;

  // laps: the scenario times laps (its lap columns after the rest).
  explicit TelemetryRowMaker(const vehicle::Vehicle& v, bool laps = false);
  int columns() const { return columns_; }
  // The header's names, with their units (docs/TELEMETRY.md).
  static const char* header();
  static const char* powertrainHeader();
  static const char* lapHeader();
  static std::string header(const vehicle::Vehicle& v, bool laps = false);
  std::vector<std::string> names() const;
  static ColumnFormat format(int column);

  // The row of a sample (columns() values; whole numbers as exact doubles).
  // The first row fixes the references of dz_com_m and rack_m.
  void fill(const vehicle::VehicleSample& s, const TelemetryInputs& in, Values& out);

 private:
  const vehicle::Vehicle& v_;
  bool laps_ = false;
  int columns_ = kBaseColumns;
  bool first_ = true;
  double z0_ = 0, rack0_ = 0;
};

}  // namespace bdfcar::scenario
