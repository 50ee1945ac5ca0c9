// Recording of a drive's inputs, one line per driver tick with the values in
// exact hexadecimal floating point, so that a replay feeds the simulation the
// very same bits and reproduces the run (and its telemetry) bit for bit.
// What the driver did besides steering is recorded as events on lines of
// their own: `reset` (back to the start), `rewind` (one snapshot back) and
// `place N` (the drive restarted at the scenario's place N, from the menu).
// The header names the scenario and vehicle files with a hash of their
// content and the tick, so that a replay against other data is refused
// rather than silently different. Lines go out whole (scenario/row_file.h).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scenario/driver_input.h"
#include "scenario/row_file.h"
#include "scenario/scenario_spec.h"

namespace bdfcar::app {

// One line of a recording: a tick's input, or an event between ticks.
struct RecordedTick {
  enum class Kind { Input, Reset, Rewind, Place } kind = Kind::Input;
  scenario::DriverInput input;  // Kind::Input
  int place = -1;               // Kind::Place: the index in the scenario's places
};

// FNV-1a (64 bits) of a file's content, as 16 hex digits ("" if unreadable).
std::string fileContentHash(const std::string& path);

class InputRecorder {
 public:
  // Creates the file (throws scenario::OutputError naming it) and writes the header.
  InputRecorder(const std::string& path, const scenario::ScenarioSpec& spec);
  void record(const RecordedTick& entry);
  void close() { file_.close(); }
  const std::string& path() const { return file_.path(); }
  long ticks() const { return inputs_; }

 private:
  scenario::RowFile file_;
  long inputs_ = 0;
};

struct Recording {
  std::string path;
  std::string scenarioFile, scenarioHash, vehicleFile, vehicleHash;  // empty in old recordings
  double tick = 0;                     // 0 in old recordings (10 ms)
  std::vector<RecordedTick> entries;   // in order: inputs numbered from 0, events between them
  int droppedLine = 0;                 // a last line cut off (no newline), not replayed; 0: none
  long inputCount() const;
};

// Reads a recording; throws std::runtime_error with file:line on a bad line
// or when no whole tick is recorded. A last line without its newline (the
// recording was cut off) is dropped: droppedLine says which.
Recording readRecording(const std::string& path);

// Why `rec` would not replay the drive it recorded with `spec` ("" when it
// would): another scenario or vehicle file content, or another tick, or a
// recording that names no content to check (made before the hashes, or its
// header removed).
std::string replayMismatch(const Recording& rec, const scenario::ScenarioSpec& spec);

}  // namespace bdfcar::app
