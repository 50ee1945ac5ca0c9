#include "sweep/sweep_jobs.h"

#include <filesystem>

#include "scenario/row_file.h"
#include "sweep/sweep_collect.h"

namespace bdfcar::app {

std::string shellQuote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string caseCommand(const std::string& bdfcar, const SweepLayout& out, const SweepCase& c) {
  std::string line = shellQuote(bdfcar) + " run " + shellQuote(c.test);
  for (const config::Setting& s : c.settings) line += " --set " + shellQuote(s.key + "=" + s.value);
  line += " --metrics " + shellQuote(out.metrics(c)) + " --out " + shellQuote(out.telemetry(c));
  return line + " > " + shellQuote(out.log(c)) + " 2>&1";
}

namespace {

void writeFile(const std::string& path, const std::string& text) {
  scenario::RowFile f(path);
  f.append(text);
  f.close();
}

}  // namespace

void writeSweepJobs(const std::string& bdfcar, const SweepLayout& out, const SweepSpec& spec,
                    const std::vector<SweepCase>& cases) {
  std::error_code ec;
  std::filesystem::create_directories(out.dir + "/cases", ec);
  if (ec) throw scenario::OutputError(out.dir + ": cannot create the sweep's folder (" + ec.message() + ")");
  std::vector<std::string> head = {"case", "test"};
  for (const SweepVariable& v : spec.vary) head.push_back(v.label);
  std::string table = csvLine(head);
  table += "\n";
  std::string jobs;
  for (const SweepCase& c : cases) {
    std::vector<std::string> row = {c.id, std::filesystem::path(c.test).filename().string()};
    row.insert(row.end(), c.values.begin(), c.values.end());
    table += csvLine(row);
    table += "\n";
    jobs += caseCommand(bdfcar, out, c) + "\n";
  }
  writeFile(out.casesCsv(), table);
  writeFile(out.jobs(), jobs);
  writeFile(out.plotToml(), "# what bdfcar sweep --collect plots (from " + spec.sourceFile + ")\n[plot]\nname = " +
                                tomlQuoted(spec.name) + "\nmetric = " + tomlQuoted(spec.plotMetric) +
                                "\nchannel = " + tomlQuoted(spec.plotChannel) + "\n");
}

std::string writeSlurmScript(const SweepLayout& out, const SweepSpec& spec, std::size_t cases) {
  const std::string path = out.dir + "/sweep.sbatch";
  writeFile(path, "#!/bin/bash\n"
                  "# " + spec.name + ": one Slurm array task per case (line $SLURM_ARRAY_TASK_ID of jobs.txt).\n"
                  "# Submit: sbatch " + path + "; then: bdfcar sweep --collect " + out.dir + "\n"
                  "#SBATCH --job-name=bdfcar-sweep\n"
                  "#SBATCH --array=1-" + std::to_string(cases) + "\n"
                  "#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=1\n"
                  "#SBATCH --output=" + out.dir + "/cases/slurm_%a.out\n"
                  "set -euo pipefail\n"
                  "line=$(sed -n \"${SLURM_ARRAY_TASK_ID}p\" " + shellQuote(out.jobs()) + ")\n"
                  "exec bash -c \"$line\"\n");
  return path;
}

}  // namespace bdfcar::app
