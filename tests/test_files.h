// Files the tests read and write: shipped assets, scratch files in the
// temporary folder (named per test file), whole-file reads for comparisons.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace bdfcar::test {

inline std::string asset(const std::string& rel) { return std::string(BDFCAR_SOURCE_DIR) + "/assets/" + rel; }

// TMPDIR/bdfcar_<prefix>_<name>.
inline std::string tempFile(const std::string& prefix, const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("bdfcar_" + prefix + "_" + name)).string();
}

inline std::string readFile(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

}  // namespace bdfcar::test
