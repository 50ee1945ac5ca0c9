#include "session/input_recording.h"
#include "config/input_files.h"
#include "config/line_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace bdfcar::app {

std::string fileContentHash(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return "";
  std::uint64_t h = 1469598103934665603ull;
  char c;
  while (f.get(c)) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

namespace {
std::string absolute(const std::string& p) {
  std::error_code ec;
  const auto a = std::filesystem::absolute(p, ec);
  return ec ? p : a.lexically_normal().string();
}
}  // namespace

InputRecorder::InputRecorder(const std::string& path, const scenario::ScenarioSpec& spec) : file_(path) {
  char tick[64];
  std::snprintf(tick, sizeof tick, "tick %a\n", spec.tick);
  file_.append("# bdfcar input recording: one line per driver tick: tick steer throttle brake handbrake clutch\n"
               "# (hex floats) clutch_pedal shift (integers: 1 a pedal works the clutch; +1 / -1 a gear request);\n"
               "# 'reset' and 'rewind' lines are the driver's restart and rewind between ticks\n"
               "scenario " + absolute(spec.sourceFile) + "\n" +
               "scenario_hash " + fileContentHash(spec.sourceFile) + "\n" +
               "vehicle " + absolute(spec.vehicleFile) + "\n" +
               "vehicle_hash " + fileContentHash(spec.vehicleFile) + "\n" + tick);
  file_.flush();
}

void InputRecorder::record(const RecordedTick& e) {
  char line[160];
  int n = 0;
  switch (e.kind) {
    case RecordedTick::Kind::Input:
      n = std::snprintf(line, sizeof line, "%ld %a %a %a %a %a %d %d\n", inputs_++, e.input.steer, e.input.throttle,
                        e.input.brake, e.input.handbrake, e.input.clutch, e.input.clutchPedal ? 1 : 0, e.input.shift);
      break;
    case RecordedTick::Kind::Reset: n = std::snprintf(line, sizeof line, "reset\n"); break;
    case RecordedTick::Kind::Rewind: n = std::snprintf(line, sizeof line, "rewind\n"); break;
    case RecordedTick::Kind::Place: n = std::snprintf(line, sizeof line, "place %d\n", e.place); break;
  }
  file_.append(line, static_cast<std::size_t>(n));
}

long Recording::inputCount() const {
  return std::count_if(entries.begin(), entries.end(),
                       [](const RecordedTick& e) { return e.kind == RecordedTick::Kind::Input; });
}

Recording readRecording(const std::string& path) {
  config::LineReader in(path, "input recording", config::kRecordingLines);
  config::noteInputFile(path);
  Recording r;
  r.path = path;
  std::string line;
  int lineNo = 0;
  long inputs = 0;
  auto fail = [&](const std::string& what) {
    throw std::runtime_error(path + ":" + std::to_string(lineNo) + ": " + what);
  };
  while (in.next(line)) {
    lineNo = static_cast<int>(in.lineNumber());
    // A last line without its newline was cut off (the recorder writes
    // whole lines: a kill or a full disk stopped it): dropped, even where
    // it parses (a number cut short still reads as a number).
    if (!in.lineEnded() && !line.empty()) {
      r.droppedLine = lineNo;
      break;
    }
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    std::string word;
    s >> word;
    if (word == "scenario" || word == "vehicle" || word == "scenario_hash" || word == "vehicle_hash") {
      std::string value = line.substr(word.size());
      value.erase(0, value.find_first_not_of(' '));
      (word == "scenario" ? r.scenarioFile : word == "vehicle" ? r.vehicleFile
                                           : word == "scenario_hash" ? r.scenarioHash
                                                                      : r.vehicleHash) = value;
      continue;
    }
    if (word == "tick") {
      std::string v;
      s >> v;
      try {
        r.tick = std::stod(v);
      } catch (const std::exception&) {
        fail("expected 'tick SECONDS'");
      }
      if (!(r.tick >= 1e-3 && r.tick <= 0.1)) fail("expected a tick in [1, 100] ms");
      continue;
    }
    if (word == "reset" || word == "rewind") {
      r.entries.push_back({word == "reset" ? RecordedTick::Kind::Reset : RecordedTick::Kind::Rewind, {}, -1});
      continue;
    }
    if (word == "place") {
      int index = -1;
      if (!(s >> index) || index < 0 || index > 10000) fail("expected 'place N' (N: a place of the scenario, from 0)");
      r.entries.push_back({RecordedTick::Kind::Place, {}, index});
      continue;
    }
    std::istringstream t(line);
    long tick;
    std::vector<std::string> f;
    if (!(t >> tick) || tick != inputs)
      fail("expected 'tick steer throttle brake [handbrake clutch clutch_pedal shift]' with consecutive ticks "
           "from 0, or an event (reset, rewind, place N)");
    for (std::string w; t >> w;) f.push_back(w);
    // Recordings made before the powertrain have the first three values only.
    if (f.size() != 3 && f.size() != 7)
      fail("expected 3 values (steer throttle brake) or 7 (and handbrake clutch clutch_pedal shift), got " +
           std::to_string(f.size()));
    scenario::DriverInput d;
    double* numbers[] = {&d.steer, &d.throttle, &d.brake, &d.handbrake, &d.clutch};
    try {
      for (std::size_t i = 0; i < std::min<std::size_t>(f.size(), 5); ++i) {
        std::size_t used = 0;
        *numbers[i] = std::stod(f[i], &used);
        if (used != f[i].size()) throw std::invalid_argument(f[i]);
      }
    } catch (const std::exception&) {
      fail("expected numbers for steer, throttle, brake, handbrake and clutch");
    }
    for (double* x : numbers)
      if (!std::isfinite(*x)) fail("expected finite numbers");
    if (f.size() == 7) {
      if (f[5] != "0" && f[5] != "1") fail("expected clutch_pedal 0 or 1, got '" + f[5] + "'");
      if (f[6] != "0" && f[6] != "1" && f[6] != "-1") fail("expected shift -1, 0 or 1, got '" + f[6] + "'");
      d.clutchPedal = f[5] == "1";
      d.shift = std::stoi(f[6]);
    }
    r.entries.push_back({RecordedTick::Kind::Input, d, -1});
    ++inputs;
  }
  if (inputs == 0) {
    lineNo = r.droppedLine ? r.droppedLine : lineNo;
    fail(r.droppedLine ? "no whole recorded tick (the only one is cut off)" : "no recorded ticks (an empty recording)");
  }
  return r;
}

std::string replayMismatch(const Recording& rec, const scenario::ScenarioSpec& spec) {
  if (rec.scenarioHash.empty() || rec.vehicleHash.empty())
    return "it does not name the content of the scenario and vehicle it was recorded with (scenario_hash and "
           "vehicle_hash: a recording made before bdfcar wrote them, or one whose header was removed), so nothing "
           "says it replays the same drive";
  if (rec.scenarioHash != fileContentHash(spec.sourceFile))
    return "it was recorded with the scenario " + rec.scenarioFile + " (content " + rec.scenarioHash +
           "), this run's scenario " + spec.sourceFile + " differs";
  if (rec.vehicleHash != fileContentHash(spec.vehicleFile))
    return "it was recorded with the vehicle " + rec.vehicleFile + " (content " + rec.vehicleHash +
           "), this run's vehicle " + spec.vehicleFile + " differs";
  if (rec.tick > 0 && std::abs(rec.tick - spec.tick) > 1e-12)
    return "it was recorded at a " + std::to_string(rec.tick * 1e3) + " ms tick, this run's tick is " +
           std::to_string(spec.tick * 1e3) + " ms";
  return "";
}

}  // namespace bdfcar::app
