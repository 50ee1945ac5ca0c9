// Running a sweep's command lines (sweep_jobs.h) on this machine: `jobs`
// threads, each starting one line at a time through /bin/sh and waiting for
// it, until all have run or an interrupt is requested (interrupt.h).
#pragma once

#include <string>
#include <vector>

namespace bdfcar::app {

// progress: a bar on stderr (a line per case when stderr is not a terminal).
void runCommandLines(const std::vector<std::string>& lines, int jobs, bool progress);

}  // namespace bdfcar::app
