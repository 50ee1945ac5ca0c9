// Why a path a data file names cannot be read as a data file: missing, or
// not a regular file (a folder, a device such as /dev/zero, a FIFO, a
// socket), in words for the loaders' messages. One rule for every file the
// program is given, so that "does not exist" means exactly that.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace bdfcar::config {

// nullopt for a regular file (or a link to one); else "does not exist",
// "is a folder, not a file", "is a device, not a regular file", "is a FIFO
// (a named pipe), not a regular file" ...
std::optional<std::string> notARegularFile(const std::filesystem::path& p);

}  // namespace bdfcar::config
