// A line-oriented data file (an OBJ mesh, a CSV table, an input recording)
// read line by line under one set of hard limits, checked as it is read so
// that no input costs more than its limits allow, whatever its shape: the
// file-kind rule of readDataFile (a regular file, or a FIFO read from its
// writer; never a folder or a device), a size cap, a cap on one line's
// length (a 1 GB line is refused at its first 64 KiB, never held whole) and
// a cap on the number of lines (the file's elements: rows, vertices and
// faces, ticks). A limit broken is a std::runtime_error naming the file, the
// line and the limit.
#pragma once

#include <cstdint>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "config/file_kind.h"

namespace bdfcar::config {

struct LineLimits {
  std::uint64_t maxBytes = kMaxDataFileBytes;
  std::size_t maxLineBytes = 64 * 1024;  // without the newline
  std::uint64_t maxLines = 4'000'000;
};

// Each line-oriented format's limits (docs/INPUT-CHECKS.md). A 16 MiB OBJ
// holds at most about 2 million vertices; its faces fan into triangles, so
// those are capped on their own. Recordings may be long (a day's drive at
// 10 ms ticks is about 650 MB) and are read as they stream.
inline constexpr LineLimits kObjLines{kMaxDataFileBytes, 64 * 1024, 4'000'000};
inline constexpr std::size_t kMaxObjTriangles = 4'000'000;  // after the faces are fanned
inline constexpr LineLimits kCsvLines{kMaxDataFileBytes, 64 * 1024, 4'000'000};
inline constexpr LineLimits kRecordingLines{std::uint64_t{2} << 30, 4 * 1024, 100'000'000};

class LineReader {
 public:
  // Opens `path` (`what` names it in messages: "OBJ file"); throws
  // "PATH:0: the WHAT ..." when it may not be read or is over maxBytes.
  LineReader(const std::string& path, const std::string& what, const LineLimits& limits = {});

  // The next line, without its newline; false at the end of the file.
  bool next(std::string& line);
  // The number of the line last read (1 for the first).
  long lineNumber() const { return line_; }
  // Whether the line last read ended with a newline (a last line without
  // one was cut off, as a killed writer leaves it).
  bool lineEnded() const { return ended_; }
  // Throws std::runtime_error "PATH:LINE: message".
  [[noreturn]] void fail(const std::string& message) const;

 private:
  std::string path_, what_;
  LineLimits limits_;
  std::ifstream file_;
  std::istringstream piped_;  // a FIFO, read whole from its writer (readDataFile)
  std::istream* in_ = nullptr;
  std::vector<char> buffer_;
  long line_ = 0;
  std::uint64_t bytes_ = 0;
  bool ended_ = true;
};

}  // namespace bdfcar::config
