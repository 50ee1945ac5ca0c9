// A text file written by whole rows, so that nothing a user records is lost
// or left half-written: rows are collected in memory and handed to the
// operating system only whole (one write(2) of complete rows), at least every
// flushInterval seconds and whenever the buffer fills, so a run killed at any
// moment leaves a file that ends on a complete row with at most the last
// second missing. A failed write (a full disk) throws OutputError naming the
// file and the system's reason; close() flushes and reports the same way.
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
  // Creates (truncates) the file; throws OutputError when it cannot.
  explicit RowFile(const std::string& path, double flushInterval = 1.0);
  ~RowFile();  // flushes what is left; a failure there is lost, so call close()
  RowFile(const RowFile&) = delete;
  RowFile& operator=(const RowFile&) = delete;

  // One or more whole rows (each ending in '\n').
  void append(const char* text, std::size_t size);
  void append(const std::string& text) { append(text.data(), text.size()); }
  void flush();
  void close();
  const std::string& path() const { return path_; }
  long rows() const { return rows_; }

 private:
  void writeAll(const char* p, std::size_t n);

  std::string path_;
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
