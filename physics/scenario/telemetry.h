// Telemetry CSV: one row per output interval, a header of named columns with
// units, the same names as tests/data/ref_jturn.csv (docs/reference-vehicle.md
// 12.5) for the same quantities, then bdfcar's own columns. Values are written with a fixed
// format so that identical runs give identical files.
#pragma once

#include <condition_variable>
#include <cstdio>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "scenario/row_file.h"
#include "scenario/telemetry_row.h"
#include "vehicle/vehicle_builder.h"
#include "vehicle/vehicle_sample.h"

namespace bdfcar::scenario {

// Rows are formatted and written by a thread of the writer's own, so that
// the stepping thread pays for a copy of the sample, not for 86 numbers
// through to_chars (as much as a third of a step): write() queues the sample
// and returns; the writer thread formats the rows in order and hands them to
// a RowFile (row_file.h: whole rows, flushed at least every second). The
// queue never drops a row: when it is full, write() waits. A write error on
// the writer thread is thrown as OutputError by the next write(), flush() or
// close() of the caller. The file's bytes are those of a synchronous writer.
class TelemetryWriter {
 public:
  // Opens the file (throws OutputError naming it on failure) and writes the header.
  // laps: the scenario times laps (TelemetryRowMaker's lap columns).
  TelemetryWriter(const std::string& path, const vehicle::Vehicle& v, bool laps = false);
  ~TelemetryWriter();  // drains and closes; a failure there is lost, so call close()
  TelemetryWriter(const TelemetryWriter&) = delete;
  TelemetryWriter& operator=(const TelemetryWriter&) = delete;

  // Queues one row; the first row fixes the references of dz_com_m and rack_m.
  void write(const vehicle::VehicleSample& s, const TelemetryInputs& in);
  // Waits until every queued row is written, then hands them to the system;
  // throws OutputError when it cannot.
  void flush();
  void close();
  const std::string& path() const { return file_.path(); }
  // The header (TelemetryRowMaker's names).
  static const char* header() { return TelemetryRowMaker::header(); }
  static std::string header(const vehicle::Vehicle& v, bool laps = false) { return TelemetryRowMaker::header(v, laps); }
  static const char* powertrainHeader() { return TelemetryRowMaker::powertrainHeader(); }

 private:
  struct Row {
    vehicle::VehicleSample sample;
    TelemetryInputs inputs;
  };
  static constexpr std::size_t kQueueRows = 1024, kBatchRows = 32;

  void writerLoop();
  void formatRow(const Row& r);  // on the writer thread
  void waitUntilWritten(std::unique_lock<std::mutex>& lock);
  void rethrowWriterError();

  RowFile file_;
  TelemetryRowMaker maker_;  // writer thread

  std::vector<Row> queue_;  // a ring of kQueueRows
  std::size_t head_ = 0, size_ = 0;
  bool busy_ = false;     // the writer thread is formatting a row taken from the queue
  bool stop_ = false;
  bool closed_ = false;
  std::exception_ptr error_;
  std::mutex mutex_;
  std::condition_variable wake_, written_;
  std::thread thread_;
};

}  // namespace bdfcar::scenario
