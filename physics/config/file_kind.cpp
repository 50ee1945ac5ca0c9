#include "config/file_kind.h"

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

}  // namespace bdfcar::config
