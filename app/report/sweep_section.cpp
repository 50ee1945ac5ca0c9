// RESULTS.md section: the shipped sweep (assets/sweeps/front_spring_x_speed_swd.toml)
// run through the same machinery as `bdfcar sweep`: its summary as a table
// and its carpet and overlay plots.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "report/studies.h"
#include "sweep/sweep_collect.h"
#include "sweep/sweep_jobs.h"
#include "sweep/sweep_runner.h"

namespace bdfcar::app {

void sweepSection(std::ostream& md, const std::string& imageDir) {
  namespace fs = std::filesystem;
  const std::string file = "sweeps/front_spring_x_speed_swd.toml";
  const SweepSpec spec = loadSweepFile(asset(file));
  const std::vector<SweepCase> cases = sweepCases(spec);
  SweepLayout out;
  out.dir = (fs::temp_directory_path() / "bdfcar_report_sweep").string();
  fs::remove_all(out.dir);
  const std::string self = fs::read_symlink("/proc/self/exe").string();
  writeSweepJobs(self, out, spec, cases);
  std::vector<std::string> lines;
  for (const SweepCase& c : cases) lines.push_back(caseCommand(self, out, c));
  runCommandLines(lines, 2, false);
  const SweepSummary s = collectSweep(out.dir);
  md << "## 5f. A sweep: front spring rate x speed on the sine with dwell\n\n"
     << "`bdfcar sweep assets/" << file << "` (docs/SWEEPS.md): the reference sedan's front strut spring rate "
     << "(369 kN/m as built) against the entry speed, " << s.cases << " cases (" << s.ok << " ok, " << s.failed
     << " failed, " << s.missing << " without results). FMVSS 126's yaw-rate ratio 1 s after the completion of "
     << "steer must stay under 35 % (1.75 s: 20 %); a stiffer front axle takes more of the roll moment, loses "
     << "front grip first and so spins less. The same sweep through GNU parallel gives this summary byte for "
     << "byte (`tests/test_sweep.cpp`).\n\n";
  std::ifstream in(s.summaryCsv);
  std::string header;
  std::getline(in, header);
  auto split = [](const std::string& line) { return csvFields(line); };
  const std::vector<std::string> head = split(header);
  auto col = [&](const std::string& n) {
    for (size_t i = 0; i < head.size(); ++i)
      if (head[i] == n) return static_cast<int>(i);
    return -1;
  };
  const int k = col("vehicle.springs[0].stiffness"), v = col("start.speed"), r1 = col("fmvss126_yaw_ratio_1000_pct"),
            r2 = col("fmvss126_yaw_ratio_1750_pct"), d = col("fmvss126_lateral_displacement_m"),
            pass = col("fmvss126_pass");
  md << "| front spring (N/m) | speed | yaw ratio 1.00 s (%) | yaw ratio 1.75 s (%) | displacement (m) | verdict |\n"
        "|---|---|---|---|---|---|\n";
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> f = split(line);
    auto at = [&](int i) { return i >= 0 && i < static_cast<int>(f.size()) ? f[i] : std::string("-"); };
    md << "| " << at(k) << " | " << at(v) << " | " << at(r1).substr(0, 6) << " | " << at(r2).substr(0, 6) << " | "
       << at(d).substr(0, 5) << " | " << (at(pass) == "1" ? "pass" : "FAIL") << " |\n";
  }
  for (const char* image : {"carpet", "overlay"}) {
    const fs::path from = fs::path(out.dir) / (std::string(image) + ".png");
    const fs::path to = fs::path(imageDir) / (std::string("sweep_") + image + ".png");
    std::error_code ec;
    if (fs::exists(from)) fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
    if (!ec && fs::exists(to)) md << "\n![sweep " << image << "](images/sweep_" << image << ".png)\n";
  }
  if (!s.plotNote.empty()) md << "\n(plots: " << s.plotNote << ")\n";
  md << "\n";
}

}  // namespace bdfcar::app
