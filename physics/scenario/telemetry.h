// Telemetry CSV: one row per output interval, a header of named columns with
// units, the same names as tests/data/ref_jturn.csv (docs/reference-vehicle.md
// 12.5) for the same quantities, then bdfcar's own columns. Values are written with a fixed
// format so that identical runs give identical files.
#pragma once

#include <cstdio>
#include <string>

#include "scenario/row_file.h"
#include "vehicle/vehicle_builder.h"
#include "vehicle/vehicle_sample.h"

namespace bdfcar::scenario {

// Quantities of a row that are not in the vehicle sample.
struct TelemetryInputs {
  double steer = 0;      // normalised steering input s
  double throttle = 0, brake = 0;
  int newtonIterations = 0;
  double newtonCorrection = 0;  // weighted norm of the last correction (1 = tolerance)
  int segment = 0;              // a drive's segment: +1 at each reset, rewind or divergence reset
};

// Rows go out whole through a RowFile (row_file.h): flushed at least every
// second, a write error throws OutputError.
class TelemetryWriter {
 public:
  // Opens the file (throws OutputError naming it on failure) and writes the header.
  TelemetryWriter(const std::string& path, const vehicle::Vehicle& v);
  // The first row fixes the references of dz_com_m and rack_m.
  void write(const vehicle::VehicleSample& s, const TelemetryInputs& in);
  // Writes what is buffered; throws OutputError when it cannot.
  void flush() { file_.flush(); }
  void close() { file_.close(); }
  const std::string& path() const { return file_.path(); }
  static const char* header();

 private:
  RowFile file_;
  const vehicle::Vehicle& v_;
  bool first_ = true;
  double z0_ = 0, rack0_ = 0;
};

}  // namespace bdfcar::scenario
