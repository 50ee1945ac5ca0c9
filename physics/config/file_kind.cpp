#include "config/file_kind.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace bdfcar::config {

std::optional<std::string> notARegularFile(const std::filesystem::path& p) {
  namespace fs = std::filesystem;
  std::error_code ec;  // no exceptions: a name too long or unreadable is "does not exist"
  const fs::file_status s = fs::status(p, ec);
  if (ec || !fs::exists(s)) return std::string("does not exist");
  switch (s.type()) {
    case fs::file_type::regular: return std::nullopt;
    case fs::file_type::directory: return std::string("is a folder, not a file");
    case fs::file_type::character:
    case fs::file_type::block: return std::string("is a device, not a regular file");
    case fs::file_type::fifo: return std::string("is a FIFO (a named pipe), not a regular file");
    case fs::file_type::socket: return std::string("is a socket, not a regular file");
    default: return std::string("is not a regular file");
  }
}

namespace {

// A FIFO (a pipe from `<(...)`): opened without waiting for a writer, and
// read only once its writer has sent something within kFifoWait, so that a
// named pipe nobody writes to is an error, not a hang.
std::string readFifo(const std::string& path, const std::string& what) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error(path + ":0: cannot open the " + what + ": " + std::strerror(errno));
  std::string text;
  char buffer[65536];
  const auto deadline = std::chrono::steady_clock::now() + kFifoWait;
  bool started = false;
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n > 0) {
      started = true;
      text.append(buffer, static_cast<std::size_t>(n));
      if (text.size() > kMaxDataFileBytes) {
        ::close(fd);
        throw std::runtime_error(path + ":0: the " + what + " is larger than " +
                                 std::to_string(kMaxDataFileBytes >> 20) + " MiB");
      }
      continue;
    }
    if (n == 0 && started) break;  // the writer closed its end
    if (n < 0 && errno != EAGAIN && errno != EINTR) {
      const int e = errno;
      ::close(fd);
      throw std::runtime_error(path + ":0: cannot read the " + what + ": " + std::strerror(e));
    }
    // Nothing yet (no writer, or a writer that has not written): wait a little.
    if (std::chrono::steady_clock::now() > deadline) {
      ::close(fd);
      throw std::runtime_error(path + ":0: the " + what + " is a FIFO that nothing wrote to in " +
                               std::to_string(std::chrono::duration_cast<std::chrono::seconds>(kFifoWait).count()) +
                               " s (start its writer first, or give a file)");
    }
    pollfd p{fd, POLLIN, 0};
    ::poll(&p, 1, 50);
  }
  ::close(fd);
  return text;
}

}  // namespace

std::string readDataFile(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status s = fs::status(path, ec);
  if (const auto why = notARegularFile(path); why && s.type() != fs::file_type::fifo)
    throw std::runtime_error(path + ":0: the " + what + " " + *why);
  if (s.type() == fs::file_type::fifo) return readFifo(path, what);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ":0: cannot open the " + what);
  std::string text;
  char buffer[65536];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxDataFileBytes)
      throw std::runtime_error(path + ":0: the " + what + " is larger than " + std::to_string(kMaxDataFileBytes >> 20) +
                               " MiB");
  }
  if (in.bad()) throw std::runtime_error(path + ":0: cannot read the " + what);
  return text;
}

}  // namespace bdfcar::config
