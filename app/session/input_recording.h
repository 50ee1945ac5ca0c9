// Recording of a drive's inputs, one line per driver tick with the values in
// exact hexadecimal floating point, so that a replay feeds the simulation the
// very same bits and reproduces the run (and its telemetry) bit for bit.
// What the driver did besides steering is recorded as events on lines of
// their own: `reset` (back to the start) and `rewind` (one snapshot back).
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "scenario/driver_input.h"

namespace bdfcar::app {

// One line of a recording: a tick's input, or an event between ticks.
struct RecordedTick {
  enum class Kind { Input, Reset, Rewind } kind = Kind::Input;
  scenario::DriverInput input;  // Kind::Input
};

class InputRecorder {
 public:
  // Opens the file (throws std::runtime_error naming it) and writes a header
  // naming the scenario the inputs belong to and the tick they were taken at.
  InputRecorder(const std::string& path, const std::string& scenarioFile, double tick);
  ~InputRecorder();
  InputRecorder(const InputRecorder&) = delete;
  InputRecorder& operator=(const InputRecorder&) = delete;
  void record(const RecordedTick& entry);

 private:
  std::FILE* f_ = nullptr;
  long inputs_ = 0;
};

struct Recording {
  std::string scenarioFile;
  std::vector<RecordedTick> entries;  // in order: inputs numbered from 0, events between them
  long inputCount() const;
};

// Reads a recording; throws std::runtime_error with file:line on a bad line.
Recording readRecording(const std::string& path);

}  // namespace bdfcar::app
