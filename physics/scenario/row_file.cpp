#include "scenario/row_file.h"
#include "config/input_files.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

namespace bdfcar::scenario {

namespace {
constexpr std::size_t kBufferBytes = 1 << 16;
}

RowFile::RowFile(const std::string& path, double flushInterval)
    : path_(path),
      flushInterval_(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(flushInterval))),
      lastFlush_(std::chrono::steady_clock::now()) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) throw OutputError(path + ": cannot open for writing: " + std::strerror(errno));
  buffer_.reserve(kBufferBytes);
}

RowFile::~RowFile() {
  try {
    close();
  } catch (const OutputError&) {
    // Reported by an explicit close(); a destructor must not throw.
  }
}

void RowFile::writeAll(const char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd_, p, n);
    if (w < 0) {
      if (errno == EINTR) continue;
      throw OutputError(path_ + ": cannot write: " + std::strerror(errno));
    }
    p += w;
    n -= static_cast<std::size_t>(w);
  }
}

void RowFile::append(const char* text, std::size_t size) {
  if (fd_ < 0) throw OutputError(path_ + ": written after it was closed");
  if (buffer_.size() + size > kBufferBytes) flush();
  if (size > kBufferBytes) {
    writeAll(text, size);
  } else {
    buffer_.insert(buffer_.end(), text, text + size);
  }
  rows_ += std::count(text, text + size, '\n');
  if (std::chrono::steady_clock::now() - lastFlush_ >= flushInterval_) flush();
}

void RowFile::flush() {
  lastFlush_ = std::chrono::steady_clock::now();
  if (fd_ < 0 || buffer_.empty()) return;
  // Cleared first: after a failure the rows are reported lost, not retried forever.
  std::vector<char> rows;
  rows.swap(buffer_);
  buffer_.reserve(kBufferBytes);
  writeAll(rows.data(), rows.size());
}

void RowFile::close() {
  if (fd_ < 0) return;
  flush();
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) throw OutputError(path_ + ": cannot write: " + std::strerror(errno));
}

namespace {
// The same file: one inode where both exist (links, ../ detours), else the
// same normalised absolute path (an output not written yet).
bool sameFile(const std::string& a, const std::string& b) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec) && !ec;
  const fs::path ca = fs::weakly_canonical(a, ec);
  if (ec) return false;
  const fs::path cb = fs::weakly_canonical(b, ec);
  return !ec && ca == cb;
}
}  // namespace

void refuseOverwritingInputs(const std::string& output, const std::vector<std::string>& inputs) {
  if (output.empty()) return;
  std::vector<std::string> all = inputs;
  for (const std::string& f : config::inputFilesRead()) all.push_back(f);
  for (const std::string& in : all) {
    if (in.empty()) continue;
    if (sameFile(output, in))
      throw OutputError(output + ": this is an input of the run (" + in +
                        "); choose another output file, the input would be overwritten");
  }
}

void refuseSameOutputs(const std::vector<std::pair<std::string, std::string>>& outputs) {
  for (size_t i = 0; i < outputs.size(); ++i)
    for (size_t j = i + 1; j < outputs.size(); ++j)
      if (!outputs[i].second.empty() && !outputs[j].second.empty() && sameFile(outputs[i].second, outputs[j].second))
        throw OutputError(outputs[j].second + ": " + outputs[i].first + " and " + outputs[j].first +
                          " name the same file; one would overwrite the other");
}

}  // namespace bdfcar::scenario
