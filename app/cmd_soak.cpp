// `bdfcar soak`: a long drive with seeded, bounded random inputs (or the
// flip-flop steering input) replayed the way `drive --replay --batch` replays
// a recording, watching what a long run must keep: no divergence, no NaN,
// the constraints' drift bounded, memory flat. Writes the recording, so the
// same drive can be replayed with `bdfcar drive --replay FILE --batch`.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <memory>

#include "cli_errors.h"
#include "commands.h"
#include "interrupt.h"
#include "scenario_overrides.h"
#include "session/drive_session.h"

namespace bdfcar::app {

namespace {

struct SoakArgs {
  std::string scenario = std::string(BDFCAR_ASSET_DIR) + "/scenarios/drive.toml";
  std::string kind = "random", recording = "soak.rec", telemetry;
  double seconds = 3600;
  std::uint64_t seed = 1;
  ScenarioOverrides overrides;
};

// splitmix64: the same numbers on every platform (std's distributions are not).
class Random {
 public:
  explicit Random(std::uint64_t seed) : s_(seed) {}
  double uniform(double lo, double hi) {  // [lo, hi)
    std::uint64_t z = (s_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return lo + (hi - lo) * static_cast<double>(z >> 11) * 0x1.0p-53;
  }

 private:
  std::uint64_t s_;
};

// A driver's bounded random inputs: every 0.5-2.5 s new targets, reached
// gradually (as a person moves a wheel and pedals); throttle only below
// 30 m/s, so the car stays at road speeds without a speed hold.
class RandomDriver {
 public:
  explicit RandomDriver(std::uint64_t seed) : rng_(seed) {}
  scenario::DriverInput next(double speed, double tick) {
    if ((hold_ -= tick) <= 0) {
      hold_ = rng_.uniform(0.5, 2.5);
      steer_ = rng_.uniform(-1, 1) * rng_.uniform(0, 1);
      const double pedal = rng_.uniform(-0.6, 1);
      throttle_ = std::max(0.0, pedal);
      brake_ = std::max(0.0, -pedal);
    }
    auto toward = [&](double& x, double target, double rate) { x += std::clamp(target - x, -rate * tick, rate * tick); };
    toward(in_.steer, steer_, 2.0);
    toward(in_.throttle, speed < 30 ? throttle_ : 0.0, 5.0);
    toward(in_.brake, speed > 1 ? brake_ : 0.0, 5.0);
    return in_;
  }

 private:
  Random rng_;
  double hold_ = 0, steer_ = 0, throttle_ = 0, brake_ = 0;
  scenario::DriverInput in_;
};

double residentMegabytes() {
  std::ifstream f("/proc/self/statm");
  long size = 0, resident = 0;
  f >> size >> resident;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1048576.0;
}

int runSoak(const SoakArgs& a) {
  scenario::ScenarioSpec spec = loadScenario(a.scenario, a.overrides);
  spec.duration = a.seconds + 1.0;
  scenario::refuseSameOutputs({{"--record", a.recording}, {"--telemetry", a.telemetry}});
  for (const std::string& out : {a.recording, a.telemetry})
    scenario::refuseOverwritingInputs(out, {a.scenario, spec.vehicleFile, spec.terrainFile});
  InterruptGuard interrupts;
  SessionOptions so;
  so.recordPath = a.recording;
  so.telemetryPath = a.telemetry;
  so.rewindable = true;  // as `drive`: a divergence would go back to the last good snapshot (and is counted)
  DriveSession session(spec, so);
  RandomDriver driver(a.seed);
  const long ticks = std::lround(a.seconds / spec.tick), perMinute = std::lround(60.0 / spec.tick);
  scenario::Simulation::ConstraintViolation worst;
  double rssAfterFirstMinute = 0, rssMax = 0, speedMax = 0;
  long nonFinite = 0;
  const auto wall0 = std::chrono::steady_clock::now();
  std::printf("%8s %10s %12s %12s %12s %9s\n", "t (s)", "speed", "|Phi| (m)", "|Phi'| (m/s)", "|Phi''|", "RSS (MB)");
  long i = 0;
  for (; i < ticks && !interruptRequested(); ++i) {
    const double speed = session.lastSample().speed;
    scenario::DriverInput in = a.kind == "flipflop"
                                   ? scenario::DriverInput{i % 2 ? 1.0 : -1.0, speed < 80 / 3.6 ? 0.6 : 0.0, 0.0}
                                   : driver.next(speed, spec.tick);
    if (!session.tick(in)) break;
    if ((i + 1) % std::lround(1.0 / spec.tick) == 0) {  // once a simulated second
      const auto c = session.simulation().constraintViolation();
      worst.position = std::max(worst.position, c.position);
      worst.velocity = std::max(worst.velocity, c.velocity);
      worst.acceleration = std::max(worst.acceleration, c.acceleration);
      const vehicle::VehicleSample s = session.simulation().sample();
      if (!std::isfinite(c.position + c.velocity + c.acceleration) || !s.com.allFinite() || !std::isfinite(s.speed))
        ++nonFinite;
      speedMax = std::max(speedMax, s.speed);
    }
    if ((i + 1) % perMinute == 0) {
      const double rss = residentMegabytes();
      if (rssAfterFirstMinute == 0) rssAfterFirstMinute = rss;
      rssMax = std::max(rssMax, rss);
      if ((i + 1) % (10 * perMinute) == 0)
        std::printf("%8.0f %8.1f m/s %12.3g %12.3g %12.3g %9.1f\n", session.time(), session.lastSample().speed,
                    worst.position, worst.velocity, worst.acceleration, rss);
    }
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  session.closeOutputs();
  std::printf("soak (%s, seed %llu): %.0f s simulated in %.1f s of wall time (%.0fx real time), %d divergence%s "
              "absorbed, %ld non-finite samples, top speed %.1f m/s\n",
              a.kind.c_str(), static_cast<unsigned long long>(a.seed), session.time(), wall,
              wall > 0 ? session.time() / wall : 0.0, session.resets(), session.resets() == 1 ? "" : "s", nonFinite,
              speedMax);
  std::printf("constraint drift (largest over the run): position %.3g m, velocity %.3g m/s, acceleration %.3g m/s^2\n",
              worst.position, worst.velocity, worst.acceleration);
  std::printf("resident memory: %.1f MB after the first minute, %.1f MB at most afterwards\n", rssAfterFirstMinute,
              rssMax);
  std::printf("recording: %s (bdfcar drive %s --replay %s --batch replays it)\n", a.recording.c_str(),
              a.scenario.c_str(), a.recording.c_str());
  if (interruptRequested()) return interruptExitStatus();
  if (session.failed()) {
    std::fprintf(stderr, "error: %s\n", session.failure().c_str());
    return 3;
  }
  return nonFinite > 0 ? 3 : 0;
}

}  // namespace

void addSoakCommand(CLI::App& app, CommandList& commands) {
  CLI::App* cmd = app.add_subcommand("soak", "A long drive with seeded random (or flip-flop) inputs: divergence, NaN, "
                                             "constraint drift and memory over the run");
  auto a = std::make_shared<SoakArgs>();
  cmd->add_option("scenario", a->scenario, "Scenario file (default: free driving on the flat road)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--kind", a->kind, "random (bounded random inputs) or flipflop (full left / full right every tick)")
      ->check(CLI::IsMember({"random", "flipflop"}));
  cmd->add_option("--seconds", a->seconds, "Simulated seconds")->check(CLI::Range(1.0, 86400.0));
  cmd->add_option("--seed", a->seed, "Seed of the random inputs");
  cmd->add_option("--record", a->recording, "The recording written (replay it with drive --replay FILE --batch)");
  cmd->add_option("--telemetry", a->telemetry, "Also write telemetry");
  addOverrideOptions(*cmd, a->overrides);
  commands.push_back({cmd, [a] { return reportErrors([&] { return runSoak(*a); }); }});
}

}  // namespace bdfcar::app
