// The car's sound (audio/, app/session/car_sound.h) without a sound card:
// the engine note's pitch follows the engine speed the telemetry records
// (the firing frequency of a four-stroke four, rpm / 60 x 2, found as the
// strongest tone of the soundtrack by a Hann-windowed Fourier scan, window
// by window, over a full-throttle run through the gears); the same drive
// sounds the same, sample for sample; and the hand-over between the tick
// and the audio thread (a triple buffer) only ever gives the reader whole,
// ever newer values.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <sstream>
#include <thread>
#include <vector>

#include "audio/car_synth.h"
#include "audio/latest_value.h"
#include "session/car_sound.h"
#include "test_files.h"

using namespace bdfcar;

namespace {

constexpr int kRate = 48000;

// |sum x_i w_i e^{-2 pi i f t_i}| with a Hann window w.
double magnitudeAt(const std::vector<float>& x, size_t first, size_t n, double f) {
  double re = 0, im = 0;
  const double step = 2 * M_PI * f / kRate;
  for (size_t i = 0; i < n; ++i) {
    const double w = 0.5 - 0.5 * std::cos(2 * M_PI * i / (n - 1));
    re += w * x[first + i] * std::cos(step * i);
    im -= w * x[first + i] * std::sin(step * i);
  }
  return std::hypot(re, im);
}

// The strongest tone between lo and hi Hz: a 1 Hz scan, then 0.05 Hz around its best.
double strongestTone(const std::vector<float>& x, size_t first, size_t n, double lo, double hi) {
  double best = lo, most = -1;
  for (double f = lo; f <= hi; f += 1.0)
    if (const double m = magnitudeAt(x, first, n, f); m > most) most = m, best = f;
  const double centre = best;
  for (double f = centre - 1.0; f <= centre + 1.0; f += 0.05)
    if (const double m = magnitudeAt(x, first, n, f); m > most) most = m, best = f;
  return best;
}

struct Drive {
  std::vector<float> sound;
  std::vector<double> rpm;  // the telemetry's engine_rpm, a row per tick
};

// Full throttle from 20 km/h in the drivable sedan, 6 s: through the gears.
Drive fullThrottle() {
  std::vector<config::Setting> settings{config::parseSetting("start.speed=\"20 km/h\"")};
  scenario::ScenarioSpec spec = scenario::loadScenarioFile(test::asset("scenarios/drive.toml"), settings);
  spec.vehicleFile = test::asset("vehicles/sedan_drive.toml");
  const std::string csv = test::tempFile("sound", "full_throttle.csv");
  Drive d;
  {
    app::SessionOptions o;
    o.telemetryPath = csv;
    app::DriveSession session(spec, o);
    app::CarSound carSound;
    audio::CarSynth synth(kRate);
    std::vector<float> block(kRate / 100);
    for (int i = 0; i < 600; ++i) {
      EXPECT_TRUE(session.tick(scenario::DriverInput{0.0, 1.0, 0.0})) << session.failure();
      synth.render(carSound.update(session), block.data(), static_cast<int>(block.size()));
      d.sound.insert(d.sound.end(), block.begin(), block.end());
    }
    session.closeOutputs();
  }
  std::istringstream in(test::readFile(csv));
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::istringstream header(line);
  for (std::string n; std::getline(header, n, ',');) names.push_back(n);
  const size_t column = std::find(names.begin(), names.end(), "engine_rpm") - names.begin();
  EXPECT_LT(column, names.size());
  std::getline(in, line);  // the start's row: before the first tick
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string cell;
    for (size_t k = 0; k <= column; ++k) std::getline(row, cell, ',');
    d.rpm.push_back(std::stod(cell));
  }
  return d;
}

}  // namespace

TEST(CarSound, TheEngineNoteFollowsTheEngineSpeedInTheTelemetry) {
  const Drive d = fullThrottle();
  ASSERT_EQ(d.rpm.size(), 600u);
  ASSERT_EQ(d.sound.size(), 600u * kRate / 100);
  const int ticks = 20;  // 0.2 s windows, where the engine speed holds within 4 %
  int checked = 0;
  double lowest = 1e9, highest = 0;
  for (int w = 0; (w + 1) * ticks <= 600; ++w) {
    const auto [lo, hi] = std::minmax_element(d.rpm.begin() + w * ticks, d.rpm.begin() + (w + 1) * ticks);
    if (*hi > 1.04 * *lo || *lo < 600) continue;  // a shift or a launch inside the window
    double mean = 0;
    for (int k = w * ticks; k < (w + 1) * ticks; ++k) mean += d.rpm[k] / ticks;
    const double expected = audio::firingFrequency(mean, 4);
    const double found = strongestTone(d.sound, static_cast<size_t>(w) * ticks * kRate / 100, ticks * kRate / 100,
                                       10.0, 400.0);
    EXPECT_NEAR(found / expected, 1.0, 0.03) << "window at " << w * 0.2 << " s: " << mean << " rpm";
    ++checked;
    lowest = std::min(lowest, mean);
    highest = std::max(highest, mean);
  }
  EXPECT_GE(checked, 10);
  EXPECT_GT(highest - lowest, 1500.0);  // the note followed the revs over a real range
  // The same drive, the same sound: sample for sample.
  EXPECT_EQ(fullThrottle().sound, d.sound);
}

TEST(CarSound, TheHandOverGivesOnlyWholeEverNewerValues) {
  struct Pair {
    long a = 0, b = 0;  // written together: a torn read would differ
  };
  audio::LatestValue<Pair> latest;
  constexpr long kLast = 200000;
  std::atomic<bool> done{false};
  std::thread writer([&] {
    for (long i = 1; i <= kLast; ++i) latest.publish({i, -i});
    done = true;
  });
  Pair seen, v;
  long reads = 0;
  for (;;) {
    const bool finished = done.load();
    if (latest.take(v)) {
      ASSERT_EQ(v.b, -v.a);
      ASSERT_GT(v.a, seen.a);
      seen = v;
      ++reads;
    } else if (finished) {
      break;
    }
  }
  writer.join();
  EXPECT_EQ(seen.a, kLast);  // the newest is never lost
  EXPECT_GT(reads, 0);
}
