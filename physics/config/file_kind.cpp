#include "config/file_kind.h"

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

std::string readDataFile(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status s = fs::status(path, ec);
  if (const auto why = notARegularFile(path); why && s.type() != fs::file_type::fifo)
    throw std::runtime_error(path + ":0: the " + what + " " + *why);
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
