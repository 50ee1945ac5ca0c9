#include "scenario/row_file.h"
#include "config/input_files.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace bdfcar::scenario {

namespace {

constexpr std::size_t kBufferBytes = 1 << 16;

// The folders a new output goes into, made when missing (as `mkdir -p`):
// `--out runs/today/lap.csv` is a user's request for that place, and a run
// that fails at its start for want of a folder loses nothing but time.
void makeParentFolders(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (parent.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(parent, ec);
  if (ec) throw OutputError(path + ": cannot make the folder " + parent.string() + ": " + ec.message());
}

// PATH.partial opened without truncation (another writer's rows are not
// touched before the lock says whether there is one) and locked.
int openLocked(const std::string& path, const std::string& writing) {
  const int fd = ::open(writing.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw OutputError(path + ": cannot open " + writing + " for writing: " + std::strerror(errno));
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int e = errno;
    ::close(fd);
    if (e == EWOULDBLOCK)
      throw OutputError(path + ": another process is writing this output now (" + writing +
                        " is locked); choose another file or wait for it to finish");
    throw OutputError(path + ": cannot lock " + writing + ": " + std::strerror(e));
  }
  return fd;
}

// Moves `file` to the first free name file.1, file.2 ... (link then unlink:
// a name another process took meanwhile is never overwritten); the new name.
std::string keepAside(const std::string& file) {
  for (int n = 1; n < 10000; ++n) {
    const std::string kept = file + "." + std::to_string(n);
    if (::link(file.c_str(), kept.c_str()) == 0) {
      ::unlink(file.c_str());
      return kept;
    }
    if (errno == EEXIST) continue;
    // A file system without hard links: rename onto a name that is free now.
    std::error_code ec;
    if (std::filesystem::exists(kept, ec)) continue;
    if (::rename(file.c_str(), kept.c_str()) == 0) return kept;
    throw OutputError(file + ": cannot keep the rows of an earlier run aside as " + kept + ": " + std::strerror(errno));
  }
  throw OutputError(file + ": cannot keep the rows of an earlier run aside: " + file + ".1 to .9999 all exist");
}

}  // namespace

RowFile::RowFile(const std::string& path, double flushInterval)
    : path_(path),
      writing_(path),
      flushInterval_(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(flushInterval))),
      lastFlush_(std::chrono::steady_clock::now()) {
  struct stat st {};
  const bool special = ::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode);
  if (special) {
    if (S_ISDIR(st.st_mode)) throw OutputError(path + ": cannot open for writing: it is a folder");
    // A device or a FIFO: written directly. O_NONBLOCK: a FIFO with no
    // reader is refused now rather than blocking for ever (ENXIO).
    fd_ = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd_ < 0 && errno == ENXIO)
      throw OutputError(path + ": cannot open for writing: a FIFO with no reader (start the reader first)");
    if (fd_ < 0) throw OutputError(path + ": cannot open for writing: " + std::strerror(errno));
    const int flags = ::fcntl(fd_, F_GETFL);
    if (flags >= 0) ::fcntl(fd_, F_SETFL, flags & ~O_NONBLOCK);  // then block as a file does
  } else {
    writing_ = partialPath(path);
    renameAtClose_ = true;
    makeParentFolders(path);
    fd_ = openLocked(path, writing_);
    // Rows already there, with no writer holding the lock: an earlier run of
    // this output that was killed or stopped by a write error. They are the
    // user's: moved aside (PATH.partial.1, .2 ...), never truncated.
    struct stat ps {};
    if (::fstat(fd_, &ps) == 0 && ps.st_size > 0) {
      keptEarlierRows_ = keepAside(writing_);
      ::close(fd_);
      fd_ = openLocked(path, writing_);
      std::fprintf(stderr, "note: %s held %lld bytes of rows from an earlier run of %s that did not finish: kept as %s\n",
                   writing_.c_str(), static_cast<long long>(ps.st_size), path.c_str(), keptEarlierRows_.c_str());
    }
    if (::ftruncate(fd_, 0) != 0) {
      const int e = errno;
      ::close(fd_);
      fd_ = -1;
      throw OutputError(path + ": cannot truncate " + writing_ + ": " + std::strerror(e));
    }
  }
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
  const char* const begin = p;
  while (n > 0) {
    const ssize_t w = ::write(fd_, p, n);
    if (w < 0) {
      if (errno == EINTR) continue;
      const int e = errno;
      failed_ = true;
      if (!renameAtClose_) throw OutputError(path_ + ": cannot write: " + std::strerror(e));
      // Back to the last whole row written (this batch's rows are whole up
      // to its last newline that reached the file); the earlier file of this
      // name is kept.
      const char* last = p;
      while (last > begin && last[-1] != '\n') --last;
      const bool cut = ::ftruncate(fd_, committed_ + (last - begin)) == 0;
      throw OutputError(path_ + ": cannot write: " + std::strerror(e) + "; " +
                        (cut ? "the whole rows written so far are in " + writing_
                             : "the rows written so far are in " + writing_ + " (its last row may be cut)") +
                        ", and an earlier " + path_ + " is kept");
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
    committed_ += static_cast<long long>(size);
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
  committed_ += static_cast<long long>(rows.size());
}

void RowFile::close() {
  if (fd_ < 0) return;
  try {
    if (!failed_) flush();
  } catch (const OutputError&) {
    ::close(fd_);
    fd_ = -1;
    throw;
  }
  const int fd = fd_;
  fd_ = -1;
  if (failed_) {  // the partial file stays; the write error was reported
    ::close(fd);
    return;
  }
  if (renameAtClose_) {
    // On the disk before it replaces the earlier file (the lock held until then).
    if (::fsync(fd) != 0) {
      const int e = errno;
      ::close(fd);
      throw OutputError(path_ + ": cannot write: " + std::strerror(e) + "; the rows are in " + writing_ +
                        ", and an earlier " + path_ + " is kept");
    }
    if (::rename(writing_.c_str(), path_.c_str()) != 0) {
      const int e = errno;
      ::close(fd);
      throw OutputError(path_ + ": cannot rename " + writing_ + " into place: " + std::strerror(e));
    }
  }
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
