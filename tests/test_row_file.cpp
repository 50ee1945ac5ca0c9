// Outputs that cannot destroy (scenario/row_file.h): a file is written as
// PATH.partial and renamed into place when closed, so an earlier file of the
// name stays whole until the new one is; a second writer of the same output
// is refused while the first writes; a write error (here: the file-size
// limit, RLIMIT_FSIZE, as a full disk) leaves the earlier file and a partial
// file of whole rows.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "config/file_kind.h"
#include "scenario/row_file.h"

namespace bdfcar {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

struct TempDir {
  fs::path dir;
  TempDir() {
    char name[] = "/tmp/bdfcar_rowfile_XXXXXX";
    dir = ::mkdtemp(name);
  }
  ~TempDir() { fs::remove_all(dir); }
};

TEST(RowFile, TheEarlierFileStaysUntilTheNewOneIsWhole) {
  TempDir t;
  const fs::path out = t.dir / "run.csv";
  std::ofstream(out) << "earlier\n";
  {
    scenario::RowFile f(out.string());
    EXPECT_EQ(f.writingPath(), out.string() + ".partial");
    f.append("a,b\n1,2\n");
    f.flush();
    EXPECT_EQ(read(out), "earlier\n");  // not replaced while written
    EXPECT_EQ(read(out.string() + ".partial"), "a,b\n1,2\n");
    f.close();
  }
  EXPECT_EQ(read(out), "a,b\n1,2\n");
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
}

TEST(RowFile, ASecondWriterIsRefused) {
  TempDir t;
  const std::string out = (t.dir / "same.csv").string();
  scenario::RowFile first(out);
  first.append("first\n");
  first.flush();
  try {
    scenario::RowFile second(out);
    ADD_FAILURE() << "a second writer of " << out << " was let in";
  } catch (const scenario::OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("another process is writing this output"), std::string::npos) << e.what();
  }
  first.append("more\n");
  first.close();
  EXPECT_EQ(read(out), "first\nmore\n");  // the refused writer touched nothing
}

TEST(RowFile, AWriteErrorKeepsTheEarlierFileAndWholeRows) {
  TempDir t;
  const fs::path out = t.dir / "big.csv";
  std::ofstream(out) << "earlier\n";
  // A file-size limit makes write(2) fail as a full disk does (EFBIG; the
  // signal it would raise ignored).
  struct rlimit old {};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
  auto* previous = std::signal(SIGXFSZ, SIG_IGN);
  struct rlimit small = old;
  small.rlim_cur = 10000;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string error;
  {
    scenario::RowFile f(out.string());
    const std::string row = "0123456789,0123456789,0123456789,012345678\n";
    try {
      for (int i = 0; i < 1000; ++i) {
        f.append(row);
        if (i % 50 == 49) f.flush();
      }
      f.close();
    } catch (const scenario::OutputError& e) {
      error = e.what();
    }
  }
  ::setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, previous);
  ASSERT_FALSE(error.empty()) << "the write past the limit did not fail";
  EXPECT_NE(error.find("cannot write"), std::string::npos) << error;
  EXPECT_NE(error.find("an earlier " + out.string() + " is kept"), std::string::npos) << error;
  EXPECT_EQ(read(out), "earlier\n");
  const std::string partial = read(out.string() + ".partial");
  ASSERT_FALSE(partial.empty());
  EXPECT_EQ(partial.back(), '\n');
  EXPECT_EQ(partial.size() % 43, 0u);  // whole rows only (43 bytes each)
  // Every whole row that fitted under the limit was kept.
  EXPECT_EQ(partial.size(), 10000u / 43 * 43);
}

TEST(RowFile, ADeviceIsWrittenDirectly) {
  scenario::RowFile f("/dev/null");
  EXPECT_EQ(f.writingPath(), "/dev/null");
  f.append("x\n");
  f.close();
  EXPECT_TRUE(fs::exists("/dev/null"));
  EXPECT_FALSE(fs::exists("/dev/null.partial"));
}

// A killed run leaves its rows in PATH.partial; the next run of the same
// output moves them aside (PATH.partial.1, then .2) byte for byte instead of
// truncating them, and says where; an empty partial file is simply reused.
TEST(RowFile, RowsAnEarlierRunLeftAreKeptAside) {
  TempDir t;
  const fs::path out = t.dir / "run.csv";
  const std::string partial = out.string() + ".partial";
  std::ofstream(partial) << "t,x\n0,1\n0.01,2\n";  // as a SIGKILLed run leaves them
  {
    scenario::RowFile f(out.string());
    EXPECT_EQ(f.keptEarlierRows(), partial + ".1");
    f.append("t,x\n0,3\n");
    f.close();
  }
  EXPECT_EQ(read(partial + ".1"), "t,x\n0,1\n0.01,2\n");
  EXPECT_EQ(read(out), "t,x\n0,3\n");
  std::ofstream(partial) << "t,x\n5,5\n";
  {
    scenario::RowFile f(out.string());
    EXPECT_EQ(f.keptEarlierRows(), partial + ".2");  // .1 is taken: never overwritten
    f.close();
  }
  EXPECT_EQ(read(partial + ".1"), "t,x\n0,1\n0.01,2\n");
  EXPECT_EQ(read(partial + ".2"), "t,x\n5,5\n");
  std::ofstream{partial};  // empty: nothing to keep
  scenario::RowFile f(out.string());
  EXPECT_TRUE(f.keptEarlierRows().empty());
  EXPECT_FALSE(fs::exists(partial + ".3"));
}

// An output in folders that do not exist yet gets them (as the frames'
// --out folder does); a folder that cannot be made is named in the error.
TEST(RowFile, MissingFoldersOfAnOutputAreMade) {
  TempDir t;
  const fs::path out = t.dir / "runs" / "today" / "run.csv";
  {
    scenario::RowFile f(out.string());
    f.append("t,x\n0,1\n");
    f.close();
  }
  EXPECT_EQ(read(out), "t,x\n0,1\n");
  std::ofstream(t.dir / "plain") << "a file, not a folder";
  try {
    scenario::RowFile f((t.dir / "plain" / "run.csv").string());
    FAIL() << "a folder under a file was made";
  } catch (const scenario::OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot make the folder " + (t.dir / "plain").string()), std::string::npos)
        << e.what();
  }
}

TEST(RowFile, AFifoWithoutAReaderIsRefusedAtOnce) {
  TempDir t;
  const std::string fifo = (t.dir / "pipe").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  try {
    scenario::RowFile f(fifo);
    ADD_FAILURE() << "opened a FIFO with no reader";
  } catch (const scenario::OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("a FIFO with no reader"), std::string::npos) << e.what();
  }
}

// Inputs too: a FIFO is read when its writer sends (a pipe from <(...)), and
// one nothing writes to is an error after config::kFifoWait, not a hang.
TEST(DataFile, AFifoIsReadFromItsWriterAndASilentOneIsAnError) {
  TempDir t;
  const std::string fifo = (t.dir / "input.csv").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] {
    std::ofstream out(fifo);
    out << "t,steer\n0,0.1\n";
  });
  EXPECT_EQ(config::readDataFile(fifo, "steering input"), "t,steer\n0,0.1\n");
  writer.join();
  const auto t0 = std::chrono::steady_clock::now();
  try {
    config::readDataFile(fifo, "steering input");
    ADD_FAILURE() << "a FIFO nobody writes to was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("a FIFO that nothing wrote to"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::steady_clock::now() - t0, config::kFifoWait + std::chrono::seconds(5));
}

}  // namespace
}  // namespace bdfcar
