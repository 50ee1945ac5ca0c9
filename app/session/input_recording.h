// Recording of a drive's inputs, one line per 10 ms tick with the values in
// exact hexadecimal floating point, so that a replay feeds the simulation the
// very same bits and reproduces the run (and its telemetry) bit for bit.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "scenario/driver_input.h"

namespace bdfcar::app {

class InputRecorder {
 public:
  // Opens the file (throws std::runtime_error naming it) and writes a header
  // naming the scenario the inputs belong to.
  InputRecorder(const std::string& path, const std::string& scenarioFile);
  ~InputRecorder();
  InputRecorder(const InputRecorder&) = delete;
  InputRecorder& operator=(const InputRecorder&) = delete;
  void record(long tick, const scenario::DriverInput& in);

 private:
  std::FILE* f_ = nullptr;
};

struct Recording {
  std::string scenarioFile;
  std::vector<scenario::DriverInput> inputs;  // one per tick, from tick 0
};

// Reads a recording; throws std::runtime_error with file:line on a bad line.
Recording readRecording(const std::string& path);

}  // namespace bdfcar::app
