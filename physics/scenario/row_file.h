// A text file written by whole rows, so that nothing a user records is lost
// or left half-written, and nothing a user had is destroyed:
//  - A regular file is written as PATH.partial beside it and renamed onto
//    PATH when closed complete: until then an earlier PATH stays as it was.
//    The partial file is locked (flock) while written, so a second writer of
//    the same output is refused, never interleaved.
//  - Rows are collected in memory and handed to the operating system only
//    whole (one write(2) of complete rows), at least every flushInterval
//    seconds and whenever the buffer fills, so a run killed outright leaves
//    PATH.partial ending on a complete row (but for the rows being written at
//    that instant) with at most the last second missing.
//  - A failed write (a full disk) cuts PATH.partial back to its last whole
//    row, leaves it there and the earlier PATH as it was, and throws
//    OutputError naming both and the system's reason; close() the same.
//  - Rows an earlier run of the same output left in PATH.partial (killed, or
//    stopped by a write error) are moved aside to PATH.partial.N (the first
//    free N) and said on stderr, never truncated.
//  - A path that exists and is no regular file (a device, a FIFO) is written
//    directly: there is nothing to rename.
#pragma once

#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace bdfcar::scenario {

// Telemetry, a recording or another output could not be written.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class RowFile {
 public:
  // Creates PATH.partial (or opens the device); throws OutputError when it
  // cannot, or when another process is writing the same output.
  explicit RowFile(const std::string& path, double flushInterval = 1.0);
  // Flushes what is left and renames it into place (after a write error: leaves
  // PATH.partial); a failure there is lost, so call close().
  ~RowFile();
  RowFile(const RowFile&) = delete;
  RowFile& operator=(const RowFile&) = delete;

  // One or more whole rows (each ending in '\n').
  void append(const char* text, std::size_t size);
  void append(const std::string& text) { append(text.data(), text.size()); }
  void flush();
  // Flushes, syncs and renames PATH.partial onto PATH.
  void close();
  const std::string& path() const { return path_; }
  // Where the rows are until close(): PATH.partial (or PATH for a device).
  const std::string& writingPath() const { return writing_; }
  static std::string partialPath(const std::string& path) { return path + ".partial"; }
  // Where the rows an earlier, unfinished run of this output had left in
  // PATH.partial were moved (PATH.partial.N), or empty when there were none.
  const std::string& keptEarlierRows() const { return keptEarlierRows_; }
  long rows() const { return rows_; }

 private:
  void writeAll(const char* p, std::size_t n);

  std::string path_, writing_, keptEarlierRows_;
  bool renameAtClose_ = false;
  bool failed_ = false;       // a write failed: the partial file stays
  long long committed_ = 0;   // bytes of whole rows written
  int fd_ = -1;
  std::vector<char> buffer_;
  std::chrono::steady_clock::duration flushInterval_;
  std::chrono::steady_clock::time_point lastFlush_;
  long rows_ = 0;
};

// Refuses an output path that names one of the inputs given or any data
// file the process has read (config/input_files.h: TOML files and their
// includes, CSV inputs, meshes, recordings): writing over them would destroy
// them. Compared by file where both exist, else by normalised path. Throws
// OutputError naming both.
void refuseOverwritingInputs(const std::string& output, const std::vector<std::string>& inputs);
// Refuses two outputs that are one file ({option, path} pairs: "--out" and
// "--metrics"): one would overwrite the other. Empty paths are skipped.
void refuseSameOutputs(const std::vector<std::pair<std::string, std::string>>& outputs);

}  // namespace bdfcar::scenario
