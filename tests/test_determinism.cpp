// Determinism across processes and commits: the telemetry of the J-turn and
// of a replayed drive hash to the values recorded in
// tests/data/golden_hashes.txt for this build flavour (the AVX2/FMA build
// rounds differently from the generic one). A change of the numbers, meant
// or not, fails here; when it is meant, regenerate the file with
// scripts/update-golden.sh and say why in the commit.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "matrix_blocking.h"
#include "scenario/run.h"
#include "session/drive_session.h"

using namespace bdfcar;

namespace {

const std::string kSource = BDFCAR_SOURCE_DIR;
const std::string kGolden = kSource + "/tests/data/golden_hashes.txt";

std::string temp(const std::string& name) {
  // Per process: ctest runs the golden cases in several processes at once
  // (Golden.UnderTunables_*), which must not write each other's files.
  return (std::filesystem::temp_directory_path() / ("bdfcar_golden_" + std::to_string(getpid()) + "_" + name)).string();
}

// FNV-1a (64 bits) of a telemetry file, which must not be trivially short.
std::string fileHash(const std::string& path) {
  EXPECT_GT(std::filesystem::file_size(path), 10000u) << path << ": telemetry too short";
  return app::fileContentHash(path);
}

// "flavour case" -> hash, from the golden file.
std::map<std::string, std::string> readGolden() {
  std::map<std::string, std::string> m;
  std::ifstream f(kGolden);
  std::string line;
  while (std::getline(f, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    std::string flavour, name, hash;
    if (s >> flavour >> name >> hash) m[flavour + " " + name] = hash;
  }
  return m;
}

void writeGolden(const std::map<std::string, std::string>& m) {
  std::ofstream f(kGolden);
  f << "# Telemetry hashes (FNV-1a 64) per build flavour: flavour case hash.\n"
       "# Written by scripts/update-golden.sh (BDFCAR_UPDATE_GOLDEN=1); checked by test_determinism.\n";
  for (const auto& [key, hash] : m) f << key << " " << hash << "\n";
}

void checkGolden(const std::string& name, const std::string& hash) {
  const std::string key = std::string(BDFCAR_FLAVOUR) + " " + name;
  std::map<std::string, std::string> golden = readGolden();
  if (const char* u = std::getenv("BDFCAR_UPDATE_GOLDEN"); u && std::string(u) == "1") {
    golden[key] = hash;
    writeGolden(golden);
    std::printf("golden hash of %s recorded: %s\n", key.c_str(), hash.c_str());
    return;
  }
  if (!golden.count(key) && std::string(BDFCAR_FLAVOUR).ends_with("-sanitize"))
    GTEST_SKIP() << "no golden hash for the sanitizer flavour '" << key
                 << "' (it optimises differently); determinism is checked in the normal builds";
  ASSERT_TRUE(golden.count(key)) << "no golden hash for '" << key << "' in " << kGolden
                                 << ": record it with scripts/update-golden.sh";
  EXPECT_EQ(hash, golden[key]) << key << ": the telemetry changed. If the change is meant, regenerate with "
                                          "scripts/update-golden.sh and say why in the commit.";
}

}  // namespace

void checkJTurnGolden() {
  scenario::Simulation sim(scenario::loadScenarioFile(kSource + "/assets/scenarios/jturn.toml"));
  scenario::RunOptions o;
  o.telemetryPath = temp("jturn.csv");
  o.keepSamples = false;
  ASSERT_TRUE(scenario::runScenario(sim, o).ok);
  checkGolden("jturn", fileHash(o.telemetryPath));
  std::filesystem::remove(o.telemetryPath);
}

TEST(Golden, JTurnTelemetryHash) { checkJTurnGolden(); }

TEST(Golden, JTurnTelemetryHashWhateverTheCachesTheCpuReports) {
  // Eigen blocks its products by the cache sizes it reads from the CPU: as
  // on a machine with a 16 KiB L1 data cache (a 48 KiB one changed the
  // J-turn's last bits before the sizes were pinned, matrix_blocking.h).
  // Building the model pins them back.
  Eigen::setCpuCacheSizes(16 * 1024, 256 * 1024, 4 * 1024 * 1024);
  checkJTurnGolden();
  EXPECT_EQ(Eigen::l1CacheSize(), kPinnedL1);
}

TEST(Golden, AutoJTurnTelemetryHash) {
  // The ladder under `auto`: the kinematic model and the closed-form planar
  // one, switched between in mid-run.
  scenario::ScenarioSpec spec = scenario::loadScenarioFile(kSource + "/assets/scenarios/jturn.toml");
  ASSERT_TRUE(scenario::parseFidelity("auto", spec.fidelity));
  scenario::Simulation sim(spec);
  ASSERT_EQ(sim.rungCount(), 2);
  scenario::RunOptions o;
  o.telemetryPath = temp("jturn_auto.csv");
  o.keepSamples = false;
  ASSERT_TRUE(scenario::runScenario(sim, o).ok);
  EXPECT_GT(sim.fidelitySwitches(), 0);
  checkGolden("jturn_auto", fileHash(o.telemetryPath));
  std::filesystem::remove(o.telemetryPath);
}

TEST(Golden, ReplayedDriveTelemetryHash) {
  // A recorded drive (tests/data/weave_300.rec) replayed as `drive --replay
  // --batch` does: a rewindable session, the recording's ticks.
  const app::Recording rec = app::readRecording(kSource + "/tests/data/weave_300.rec");
  ASSERT_EQ(rec.inputCount(), 300);
  app::SessionOptions so;
  so.telemetryPath = temp("drive.csv");
  so.rewindable = true;
  {
    app::DriveSession drive(scenario::loadScenarioFile(kSource + "/assets/scenarios/drive.toml"), so);
    for (const app::RecordedTick& e : rec.entries) ASSERT_TRUE(drive.replay(e));
    EXPECT_NEAR(drive.time(), 3.0, 1e-9);
  }
  checkGolden("drive_replay", fileHash(so.telemetryPath));
  std::filesystem::remove(so.telemetryPath);
}
