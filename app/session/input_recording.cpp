#include "session/input_recording.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace bdfcar::app {

InputRecorder::InputRecorder(const std::string& path, const std::string& scenarioFile, double tick) {
  f_ = std::fopen(path.c_str(), "w");
  if (!f_) throw std::runtime_error(path + ": cannot open the input recording for writing");
  std::fprintf(f_, "# bdfcar input recording: one line per %g ms driver tick: tick steer throttle brake (hex floats);\n",
               tick * 1e3);
  std::fprintf(f_, "# 'reset' and 'rewind' lines are the driver's restart and rewind between ticks\n");
  std::fprintf(f_, "scenario %s\n", scenarioFile.c_str());
}

InputRecorder::~InputRecorder() {
  if (f_) std::fclose(f_);
}

void InputRecorder::record(const RecordedTick& e) {
  switch (e.kind) {
    case RecordedTick::Kind::Input:
      std::fprintf(f_, "%ld %a %a %a\n", inputs_++, e.input.steer, e.input.throttle, e.input.brake);
      break;
    case RecordedTick::Kind::Reset: std::fprintf(f_, "reset\n"); break;
    case RecordedTick::Kind::Rewind: std::fprintf(f_, "rewind\n"); break;
  }
}

long Recording::inputCount() const {
  return std::count_if(entries.begin(), entries.end(),
                       [](const RecordedTick& e) { return e.kind == RecordedTick::Kind::Input; });
}

Recording readRecording(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ":0: cannot open the input recording");
  Recording r;
  std::string line;
  int lineNo = 0;
  long inputs = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.empty() || line[0] == '#') continue;
    if (line.rfind("scenario ", 0) == 0) {
      r.scenarioFile = line.substr(9);
      continue;
    }
    if (line == "reset" || line == "rewind") {
      r.entries.push_back({line == "reset" ? RecordedTick::Kind::Reset : RecordedTick::Kind::Rewind, {}});
      continue;
    }
    std::istringstream s(line);
    long tick;
    std::string a, b, c;
    if (!(s >> tick >> a >> b >> c) || tick != inputs)
      throw std::runtime_error(path + ":" + std::to_string(lineNo) +
                               ": expected 'tick steer throttle brake' with consecutive ticks from 0, or an event "
                               "(reset, rewind)");
    scenario::DriverInput d;
    try {
      d.steer = std::stod(a);
      d.throttle = std::stod(b);
      d.brake = std::stod(c);
    } catch (const std::exception&) {
      throw std::runtime_error(path + ":" + std::to_string(lineNo) + ": expected three numbers");
    }
    r.entries.push_back({RecordedTick::Kind::Input, d});
    ++inputs;
  }
  return r;
}

}  // namespace bdfcar::app
