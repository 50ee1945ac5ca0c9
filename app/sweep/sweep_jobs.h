// A sweep's cases as work for any runner: one shell command line per case
// (`bdfcar run TEST --set ... --metrics ... --out ...`), written to
// DIR/jobs.txt (what GNU parallel reads), a Slurm array job script that runs
// line $SLURM_ARRAY_TASK_ID of it, and DIR/cases.csv (which case is which).
// The built-in runner (cmd_sweep.cpp) runs the same lines.
#pragma once

#include <string>
#include <vector>

#include "sweep/sweep_spec.h"

namespace bdfcar::app {

struct SweepLayout {
  std::string dir;  // absolute
  std::string casesCsv() const { return dir + "/cases.csv"; }
  std::string jobs() const { return dir + "/jobs.txt"; }
  std::string plotToml() const { return dir + "/plot.toml"; }
  std::string metrics(const SweepCase& c) const { return dir + "/cases/" + c.id + ".csv"; }
  std::string telemetry(const SweepCase& c) const { return dir + "/cases/" + c.id + "_telemetry.csv"; }
  std::string log(const SweepCase& c) const { return dir + "/cases/" + c.id + ".log"; }
};

// The shell command line of a case (absolute paths; the output to its log).
std::string caseCommand(const std::string& bdfcar, const SweepLayout& out, const SweepCase& c);

// Creates DIR and DIR/cases, writes cases.csv, jobs.txt and plot.toml;
// throws scenario::OutputError.
void writeSweepJobs(const std::string& bdfcar, const SweepLayout& out, const SweepSpec& spec,
                    const std::vector<SweepCase>& cases);
// DIR/sweep.sbatch: a Slurm array job of one task per line of jobs.txt.
std::string writeSlurmScript(const SweepLayout& out, const SweepSpec& spec, std::size_t cases);

// Single-quotes a word for the shell.
std::string shellQuote(const std::string& s);

}  // namespace bdfcar::app
