// Sweeps (app/sweep/): the cases a sweep file makes, and the same summary
// whether the built-in runner or GNU parallel (the Debian package) runs the
// emitted command lines, or a Slurm array task runs one of them.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "sweep/sweep_spec.h"

using namespace bdfcar;
namespace fs = std::filesystem;

namespace {

const fs::path kSource = BDFCAR_SOURCE_DIR;

std::string quoted(const std::string& s) { return "'" + s + "'"; }

int shell(const std::string& command) {
  const int status = std::system((command + " > /dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string readText(const fs::path& p) {
  std::ifstream in(p);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

fs::path fresh(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("bdfcar_sweep_test_" + name);
  fs::remove_all(d);
  return d;
}

}  // namespace

// A grid is the product of the values, the last variable fastest; keys given
// together get the same value.
TEST(SweepCases, GridIsTheProductOfTheValues) {
  const app::SweepSpec spec = app::loadSweepFile((kSource / "tests/data/sweep_small.toml").string());
  const std::vector<app::SweepCase> cases = app::sweepCases(spec);
  ASSERT_EQ(cases.size(), 4u);
  const std::vector<std::vector<std::string>> expected = {
      {"60 km/h", "300000"}, {"60 km/h", "450000"}, {"80 km/h", "300000"}, {"80 km/h", "450000"}};
  for (size_t i = 0; i < cases.size(); ++i) {
    EXPECT_EQ(cases[i].values, expected[i]) << i;
    ASSERT_EQ(cases[i].settings.size(), 2u + 3u);  // two fixed, speed twice, the spring
    EXPECT_EQ(cases[i].settings[2].key, "start.speed");
    EXPECT_EQ(cases[i].settings[3].key, "speed_control.target");
    EXPECT_EQ(cases[i].settings[2].value, cases[i].settings[3].value);
  }
}

// A Monte Carlo draw: the same seed gives the same cases, another seed others;
// uniform draws stay in their bounds and their mean is near the middle.
TEST(SweepCases, MonteCarloIsSeededAndInBounds) {
  const fs::path f = fresh("mc.toml");
  std::ofstream(f) << "[sweep]\nname = \"mc\"\ntests = " << quoted((kSource / "assets/scenarios/jturn.toml").string())
                   << "\nmode = \"monte_carlo\"\nsamples = 400\nseed = 7\n"
                      "[[vary]]\nkey = \"start.speed\"\nmin = 20\nmax = 30\nunit = \"m/s\"\n"
                      "[[vary]]\nkey = \"vehicle.springs[0].stiffness\"\ndistribution = \"normal\"\nmean = 4e5\nsd = 2e4\n";
  const app::SweepSpec spec = app::loadSweepFile(f.string());
  const std::vector<app::SweepCase> a = app::sweepCases(spec), b = app::sweepCases(spec);
  ASSERT_EQ(a.size(), 400u);
  double mean = 0, meanK = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].values, b[i].values);
    const double v = std::stod(a[i].values[0]);
    EXPECT_GE(v, 20.0);
    EXPECT_LE(v, 30.0);
    EXPECT_NE(a[i].values[0].find("m/s"), std::string::npos);
    mean += v / a.size();
    meanK += std::stod(a[i].values[1]) / a.size();
  }
  // Standard errors: 10/sqrt(12*400) = 0.14 and 2e4/sqrt(400) = 1000; bounds at 4 of them.
  EXPECT_NEAR(mean, 25.0, 0.6);
  EXPECT_NEAR(meanK, 4e5, 4000);
  app::SweepSpec other = spec;
  other.seed = 8;
  EXPECT_NE(app::sweepCases(other)[0].values, a[0].values);
}

// The built-in runner, GNU parallel over the emitted jobs.txt, and the Slurm
// script's task for one line: the same summary, byte for byte.
TEST(Sweep, GnuParallelAndSlurmGiveTheBuiltInSummary) {
  ASSERT_EQ(shell("command -v parallel"), 0) << "GNU parallel is not installed (scripts/packages.txt lists it)";
  const std::string bdfcar = quoted(BDFCAR_BINARY), sweep = quoted((kSource / "tests/data/sweep_small.toml").string());
  const fs::path local = fresh("local"), emitted = fresh("parallel"), slurm = fresh("slurm");
  ASSERT_EQ(shell(bdfcar + " sweep " + sweep + " --out " + quoted(local) + " --jobs 2"), 0);
  ASSERT_EQ(shell(bdfcar + " sweep " + sweep + " --out " + quoted(emitted) + " --emit parallel"), 0);
  ASSERT_FALSE(fs::exists(emitted / "summary.csv"));  // emitted, not run
  ASSERT_EQ(shell("parallel --will-cite -j 2 --joblog " + quoted(emitted / "joblog.txt") + " < " +
                  quoted(emitted / "jobs.txt")),
            0);
  ASSERT_EQ(shell(bdfcar + " sweep --collect " + quoted(emitted)), 0);
  const std::string a = readText(local / "summary.csv"), b = readText(emitted / "summary.csv");
  EXPECT_EQ(a, b);
  // Four cases, each ok, and the speed made a difference to the yaw rate.
  std::istringstream rows(a);
  std::string line;
  std::getline(rows, line);
  EXPECT_NE(line.find("start.speed,vehicle.springs[0].stiffness,status,ok"), std::string::npos) << line;
  std::set<std::string> peaks;
  int n = 0;
  while (std::getline(rows, line)) {
    ++n;
    EXPECT_NE(line.find(",ok,1,"), std::string::npos) << line;
    peaks.insert(line.substr(line.find(",ok,1,")));
  }
  EXPECT_EQ(n, 4);
  EXPECT_EQ(peaks.size(), 4u) << "every case gave other metrics";
  // One Slurm array task (SLURM_ARRAY_TASK_ID=3) runs the third case.
  ASSERT_EQ(shell(bdfcar + " sweep " + sweep + " --out " + quoted(slurm) + " --emit slurm"), 0);
  ASSERT_EQ(shell("SLURM_ARRAY_TASK_ID=3 bash " + quoted(slurm / "sweep.sbatch")), 0);
  EXPECT_EQ(readText(slurm / "cases/case_0003.csv"), readText(local / "cases/case_0003.csv"));
  EXPECT_FALSE(fs::exists(slurm / "cases/case_0001.csv"));
  // A sweep folder is never overwritten.
  EXPECT_NE(shell(bdfcar + " sweep " + sweep + " --out " + quoted(local)), 0);
}
