// The bad-input corpus (tests/data/bad/): every file is given to the `bdfcar`
// binary as a user would, and must produce its message and exit code, never a
// crash or a library text. Each file states what it expects in comment lines:
//   # expect: REGEX      (searched for in stdout + stderr, ECMAScript syntax)
//   # exit: CODE         (0 ok, 1 bad input, 2 usage, 3 simulation failed, 4 course failed)
//   # args: ARGS         ({} is the file, {tmp} a scratch folder)
// Files under tests/data/bad/parts/ are referenced by the others, not run;
// files under tests/data/bad/fuzz/ are the fuzzers' findings, run like the rest.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path kBadDir = fs::path(BDFCAR_SOURCE_DIR) / "tests/data/bad";

struct Outcome {
  int exitCode = -1;  // -1: killed by a signal (a crash)
  int signal = 0;
  std::string output;
};

// Runs a shell command line, stdout and stderr together.
Outcome runShell(const std::string& command) {
  Outcome o;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return o;
  std::array<char, 4096> buffer;
  for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;) o.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  if (WIFEXITED(status)) o.exitCode = WEXITSTATUS(status);
  // sh reports a child killed by signal N as exit status 128 + N.
  if (WIFSIGNALED(status)) o.signal = WTERMSIG(status);
  if (o.exitCode > 128) o.signal = o.exitCode - 128, o.exitCode = -1;
  return o;
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

std::string binary() { return quoted(BDFCAR_BINARY); }

struct Expectation {
  std::string regex, args;
  int exitCode = -1;
};

// The "# expect:", "# exit:" and "# args:" lines of a corpus file (anywhere in it:
// a CSV must start with its header).
Expectation expectationOf(const fs::path& file) {
  Expectation e;
  std::ifstream in(file, std::ios::binary);
  for (std::string line; std::getline(in, line);) {
    auto value = [&](const std::string& tag) { return line.rfind(tag, 0) == 0 ? line.substr(tag.size()) : std::string(); };
    if (const std::string v = value("# expect: "); !v.empty()) e.regex = v;
    if (const std::string v = value("# exit: "); !v.empty()) e.exitCode = std::stoi(v);
    if (const std::string v = value("# args: "); !v.empty()) e.args = v;
  }
  return e;
}

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t i = 0; (i = s.find(from, i)) != std::string::npos; i += to.size()) s.replace(i, from.size(), to);
  return s;
}

// The corpus, and the fuzzers' findings in fuzz/ (each a regression test too).
std::vector<std::string> corpusFiles() {
  std::vector<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(kBadDir))
    if (e.is_regular_file()) names.push_back(e.path().filename().string());
  if (fs::is_directory(kBadDir / "fuzz"))
    for (const fs::directory_entry& e : fs::directory_iterator(kBadDir / "fuzz"))
      if (e.is_regular_file()) names.push_back("fuzz/" + e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// gtest names allow letters, digits and underscores only.
std::string testName(const testing::TestParamInfo<std::string>& info) {
  std::string n = info.param;
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

void expectOutcome(const Outcome& o, int exitCode, const std::string& regex, const std::string& command) {
  EXPECT_EQ(o.signal, 0) << "killed by signal " << o.signal << ": " << command << "\n" << o.output;
  EXPECT_EQ(o.exitCode, exitCode) << command << "\n" << o.output;
  EXPECT_TRUE(std::regex_search(o.output, std::regex(regex))) << "expected /" << regex << "/ in:\n" << o.output;
  // Library texts must never reach the user.
  for (const char* leak : {"std::", "bad_alloc", "stod", "filesystem error", "terminate called"})
    EXPECT_EQ(o.output.find(leak), std::string::npos) << "library text '" << leak << "' in:\n" << o.output;
}

class BadInput : public testing::TestWithParam<std::string> {};

TEST_P(BadInput, GivesItsMessageAndExitCode) {
  const fs::path file = kBadDir / GetParam();
  const Expectation e = expectationOf(file);
  ASSERT_FALSE(e.regex.empty()) << file << " has no '# expect: ' line";
  ASSERT_GE(e.exitCode, 0) << file << " has no '# exit: ' line";
  ASSERT_FALSE(e.args.empty()) << file << " has no '# args: ' line";
  const fs::path tmp = fs::temp_directory_path() / ("bdfcar_bad_" + testName({GetParam(), 0}));
  fs::create_directories(tmp);
  const std::string command =
      binary() + " " + replaceAll(replaceAll(e.args, "{tmp}", quoted(tmp.string())), "{}", quoted(file.string()));
  expectOutcome(runShell(command), e.exitCode, e.regex, command);
  fs::remove_all(tmp);
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInput, testing::ValuesIn(corpusFiles()), testName);

TEST(BadInputCorpus, HasAtLeastSixtyFiles) { EXPECT_GE(corpusFiles().size(), 60u); }

// Command-line values: CLI11's range checks let NaN through; main adds a
// finite check to every floating-point option.
struct CliCase {
  std::string name, args, regex;
  int exitCode;
};

class BadCommandLine : public testing::TestWithParam<CliCase> {};

TEST_P(BadCommandLine, GivesItsMessageAndExitCode) {
  const CliCase& c = GetParam();
  const std::string command = replaceAll(c.args, "{bdfcar}", binary());
  expectOutcome(runShell(command), c.exitCode, c.regex, command);
}

const std::string kScenario = quoted((kBadDir / "parts/mini_scenario.toml").string());
const std::string kVehicle = quoted((kBadDir / "parts/mini_vehicle.toml").string());

std::vector<CliCase> cliCases() {
  std::vector<CliCase> cases = {
      {"step_nan", "{bdfcar} run " + kScenario + " --step nan", "--step: expected a finite number, got nan", 1},
      {"duration_nan", "{bdfcar} run " + kScenario + " --duration nan", "--duration: expected a finite number, got nan", 1},
      {"settle_inf", "{bdfcar} run " + kScenario + " --settle inf", "--settle", 1},
      {"tick_nan", "{bdfcar} run " + kScenario + " --tick nan", "--tick: expected a finite number, got nan", 1},
      {"step_negative", "{bdfcar} run " + kScenario + " --step -1", "--step", 1},
      {"step_word", "{bdfcar} run " + kScenario + " --step fast", "--step", 1},
      {"step_not_dividing", "{bdfcar} run " + kScenario + " --step 0.003", "--step 0.003 s does not divide", 1},
      {"missing_scenario_file", "{bdfcar} run /no/such/scenario.toml", "File does not exist", 1},
      {"scenario_directory", "{bdfcar} run " + quoted(kBadDir.string()), "directory", 1},
      {"info_long_name", "{bdfcar} info " + std::string(300, 'x') + ".toml", "does not exist", 1},
      {"unknown_option", "{bdfcar} run " + kScenario + " --no-such-option", "no-such-option", 2},
      {"missing_argument", "{bdfcar} run", "scenario is required", 2},
      {"unknown_command", "{bdfcar} nosuch", "nosuch", 2},
      {"no_command", "{bdfcar}", "name a command", 2},
      // A file read through a pipe is read whole (it used to be parsed as empty).
      {"vehicle_through_pipe", "cat " + kVehicle + " | {bdfcar} info /dev/stdin", "relative coordinates: 7 ", 0},
      {"valid_scenario", "{bdfcar} run " + kScenario + " --duration 0.05", "steps of 0.01 s", 0},
  };
#ifdef BDFCAR_WITH_GRAPHICS
  cases.push_back({"input_seconds_huge", "{bdfcar} input --seconds 1e300", "--seconds", 1});
  cases.push_back({"input_seconds_nan", "{bdfcar} input --seconds nan", "--seconds: expected a finite number, got nan", 1});
#endif
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Cli, BadCommandLine, testing::ValuesIn(cliCases()),
                         [](const testing::TestParamInfo<CliCase>& info) { return info.param.name; });

}  // namespace
