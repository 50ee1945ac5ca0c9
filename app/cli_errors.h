// Runs a command body and turns the errors bad input can raise into a clear
// message on stderr and a non-zero exit code (never a crash), and the exit
// codes and checks every command shares.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace bdfcar::app {

// Exit codes of every command (README.md, "Exit codes").
enum ExitCode : int {
  kExitOk = 0,
  kExitBadInput = 1,          // a file, key or value (in a file or on the command line) is refused
  kExitUsage = 2,             // the command line itself: unknown option, missing argument, no command
  kExitSimulationFailed = 3,  // the run diverged or failed
  kExitCourseFailed = 4,      // the course was not passed
  kExitOutputFailed = 5,      // telemetry or a recording could not be written (a full disk)
  // 128 + N: stopped by signal N (SIGINT 130, SIGTERM 143, SIGHUP 129), outputs complete
};

// Runs body; exceptions become "error: ..." on stderr and kExitBadInput.
int reportErrors(const std::function<int()>& body);

// CLI11's parse errors: its message (or help) printed by app.exit, then
// kExitOk for --help, kExitBadInput for a refused value (conversion or
// check), kExitUsage for the rest.
int cliExitCode(const CLI::App& app, const CLI::ParseError& e);

// CLI11's Range and PositiveNumber let NaN through (every comparison with NaN
// is false): a finite check for every floating-point option of `app` and its
// subcommands, added once in main so that no command can forget it.
void requireFiniteNumbers(CLI::App& app);

}  // namespace bdfcar::app
