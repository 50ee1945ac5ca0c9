// Why a path a data file names cannot be read as a data file: missing, or
// not a regular file (a folder, a device such as /dev/zero, a FIFO, a
// socket), in words for the loaders' messages. One rule for every file the
// program is given, so that "does not exist" means exactly that.
#pragma once

#include <chrono>

#include <filesystem>
#include <cstddef>
#include <optional>
#include <string>

namespace bdfcar::config {

// nullopt for a regular file (or a link to one); else "does not exist",
// "is a folder, not a file", "is a device, not a regular file", "is a FIFO
// (a named pipe), not a regular file" ...
std::optional<std::string> notARegularFile(const std::filesystem::path& p);

// What a data file (a TOML file, a CSV table, an input mapping) may be: a regular file,
// or a FIFO or pipe (`cat table.csv | ... /dev/stdin`), read to at most
// kMaxDataFileBytes. Never a folder, a device (/dev/zero would never end)
// or a socket.
constexpr std::size_t kMaxDataFileBytes = 16u << 20;
// How long a FIFO given as a data file may stay silent before it is an error.
inline constexpr std::chrono::seconds kFifoWait{5};
// The whole text; throws std::runtime_error "PATH:0: <what> ..." naming the
// rule broken (missing, a device, larger than the cap).
std::string readDataFile(const std::string& path, const std::string& what);

}  // namespace bdfcar::config
