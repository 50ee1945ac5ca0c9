// Telemetry CSV: one row per output interval, a header of named columns with
// units, the same names as tests/data/ref_jturn.csv (docs/reference-vehicle.md
// 12.5) for the same quantities, then bdfcar's own columns. Values are written with a fixed
// format so that identical runs give identical files.
#pragma once

#include <cstdio>
#include <string>

#include "vehicle/vehicle_builder.h"
#include "vehicle/vehicle_sample.h"

namespace bdfcar::scenario {

// Quantities of a row that are not in the vehicle sample.
struct TelemetryInputs {
  double steer = 0;      // normalised steering input s
  double throttle = 0, brake = 0;
  int newtonIterations = 0;
  double newtonCorrection = 0;  // weighted norm of the last correction (1 = tolerance)
};

class TelemetryWriter {
 public:
  // Opens the file (throws std::runtime_error naming it on failure) and writes the header.
  TelemetryWriter(const std::string& path, const vehicle::Vehicle& v);
  ~TelemetryWriter();
  TelemetryWriter(const TelemetryWriter&) = delete;
  TelemetryWriter& operator=(const TelemetryWriter&) = delete;
  // The first row fixes the references of dz_com_m and rack_m.
  void write(const vehicle::VehicleSample& s, const TelemetryInputs& in);
  static const char* header();

 private:
  std::FILE* f_ = nullptr;
  const vehicle::Vehicle& v_;
  bool first_ = true;
  double z0_ = 0, rack0_ = 0;
};

}  // namespace bdfcar::scenario
