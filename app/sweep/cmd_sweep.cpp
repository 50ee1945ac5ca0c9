// `bdfcar sweep SWEEP.toml`: the cases of a sweep (sweep_spec.h) run on the
// local cores, or written as jobs for GNU parallel or Slurm (--emit), and
// `bdfcar sweep --collect DIR` merging what they wrote (sweep_collect.h).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <thread>

#include "cli_errors.h"
#include "commands.h"
#include "interrupt.h"
#include "scenario/row_file.h"
#include "sweep/sweep_collect.h"
#include "sweep/sweep_jobs.h"
#include "sweep/sweep_runner.h"

namespace bdfcar::app {

namespace {

struct SweepArgs {
  std::string file, out, emit, collect;
  int jobs = 0;
};

int printSummary(const SweepSummary& s) {
  std::printf("%d cases: %d ok, %d failed (the run failed: ok = 0 in the summary), %d without results\n", s.cases,
              s.ok, s.failed, s.missing);
  std::printf("summary: %s\n", s.summaryCsv.c_str());
  if (!s.plotNote.empty()) std::printf("plots: %s\n", s.plotNote.c_str());
  // Cases that wrote nothing did not run (or were stopped): the sweep is incomplete.
  return s.missing > 0 ? kExitSimulationFailed : kExitOk;
}

int runSweep(const SweepArgs& a) {
  if (!a.collect.empty() && (!a.file.empty() || !a.emit.empty())) {
    std::fprintf(stderr, "error: --collect DIR takes no sweep file and no --emit\n");
    return kExitUsage;
  }
  if (!a.collect.empty()) return printSummary(collectSweep(std::filesystem::absolute(a.collect).lexically_normal()));
  if (a.file.empty()) {
    std::fprintf(stderr, "error: give a sweep file (bdfcar sweep SWEEP.toml), or --collect DIR\n");
    return kExitUsage;
  }
  const SweepSpec spec = loadSweepFile(a.file);
  const std::vector<SweepCase> cases = sweepCases(spec);
  SweepLayout out;
  const std::string dir = a.out.empty() ? std::filesystem::path(a.file).stem().string() + "_sweep" : a.out;
  out.dir = std::filesystem::absolute(dir).lexically_normal().string();
  if (std::filesystem::exists(out.casesCsv()))
    throw scenario::OutputError(out.dir + " already holds a sweep (cases.csv): give another --out, or remove it");
  std::error_code ec;
  const std::string self = std::filesystem::read_symlink("/proc/self/exe", ec).string();
  if (ec) throw std::runtime_error("cannot find this program's own path (/proc/self/exe): " + ec.message());
  writeSweepJobs(self, out, spec, cases);
  std::printf("%s: %zu cases in %s\n", spec.name.c_str(), cases.size(), out.dir.c_str());
  if (a.emit == "parallel") {
    std::printf("jobs for GNU parallel: %s\nrun them:  parallel --joblog %s/joblog.txt < %s\n"
                "(on several hosts add --sshlogin HOST1,HOST2,..: every host needs this bdfcar and the sweep's folder "
                "at the same paths)\nthen:      bdfcar sweep --collect %s\n",
                out.jobs().c_str(), out.dir.c_str(), out.jobs().c_str(), out.dir.c_str());
    return 0;
  }
  if (a.emit == "slurm") {
    const std::string script = writeSlurmScript(out, spec, cases.size());
    std::printf("Slurm array job: %s\nsubmit it: sbatch %s\nthen:      bdfcar sweep --collect %s\n", script.c_str(),
                script.c_str(), out.dir.c_str());
    return 0;
  }
  std::vector<std::string> lines;
  for (const SweepCase& c : cases) lines.push_back(caseCommand(self, out, c));
  const int jobs = a.jobs > 0 ? a.jobs : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  InterruptGuard interrupts;
  runCommandLines(lines, std::min<int>(jobs, static_cast<int>(lines.size())), true);
  if (interruptRequested()) {
    std::fprintf(stderr, "sweep stopped by %s; what ran is in %s (bdfcar sweep --collect %s merges it)\n",
                 interruptSignalName(), out.dir.c_str(), out.dir.c_str());
    return interruptExitStatus();
  }
  return printSummary(collectSweep(out.dir));
}

}  // namespace

void addSweepCommand(CLI::App& app, CommandList& commands) {
  CLI::App* cmd = app.add_subcommand(
      "sweep", "Run a sweep of scenario runs (a grid or a Monte Carlo draw over any keys, docs/SWEEPS.md) on the "
               "local cores, or write it as jobs for GNU parallel or Slurm, and merge the results");
  auto a = std::make_shared<SweepArgs>();
  cmd->add_option("sweep", a->file, "Sweep file (assets/sweeps/*.toml)")->check(CLI::ExistingFile);
  cmd->add_option("--out,-o", a->out, "Folder for the cases and the summary (default: SWEEP_sweep, here)");
  cmd->add_option("--jobs,-j", a->jobs, "Cases run at once (default: the number of cores)")->check(CLI::Range(1, 1024));
  cmd->add_option("--emit", a->emit,
                  "Do not run: write the jobs for GNU parallel (jobs.txt, one command line per case) or a Slurm "
                  "array job script (sweep.sbatch)")
      ->check(CLI::IsMember({"parallel", "slurm"}));
  cmd->add_option("--collect", a->collect,
                  "Merge the results in this sweep folder (after the emitted jobs ran) into summary.csv and plots")
      ->check(CLI::ExistingDirectory);
  commands.push_back({cmd, [=] { return reportErrors([&] { return runSweep(*a); }); }});
}

}  // namespace bdfcar::app
