#include "session/input_recording.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace bdfcar::app {

InputRecorder::InputRecorder(const std::string& path, const std::string& scenarioFile) {
  f_ = std::fopen(path.c_str(), "w");
  if (!f_) throw std::runtime_error(path + ": cannot open the input recording for writing");
  std::fprintf(f_, "# bdfcar input recording: one line per 10 ms tick: tick steer throttle brake (hex floats)\n");
  std::fprintf(f_, "scenario %s\n", scenarioFile.c_str());
}

InputRecorder::~InputRecorder() {
  if (f_) std::fclose(f_);
}

void InputRecorder::record(long tick, const scenario::DriverInput& in) {
  std::fprintf(f_, "%ld %a %a %a\n", tick, in.steer, in.throttle, in.brake);
}

Recording readRecording(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ":0: cannot open the input recording");
  Recording r;
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.empty() || line[0] == '#') continue;
    if (line.rfind("scenario ", 0) == 0) {
      r.scenarioFile = line.substr(9);
      continue;
    }
    std::istringstream s(line);
    long tick;
    std::string a, b, c;
    if (!(s >> tick >> a >> b >> c) || tick != static_cast<long>(r.inputs.size()))
      throw std::runtime_error(path + ":" + std::to_string(lineNo) +
                               ": expected 'tick steer throttle brake' with consecutive ticks from 0");
    scenario::DriverInput d;
    try {
      d.steer = std::stod(a);
      d.throttle = std::stod(b);
      d.brake = std::stod(c);
    } catch (const std::exception&) {
      throw std::runtime_error(path + ":" + std::to_string(lineNo) + ": expected three numbers");
    }
    r.inputs.push_back(d);
  }
  return r;
}

}  // namespace bdfcar::app
