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

// The reference sedan as one file's text, for tests that edit it: sedan.toml
// with its linkage part (parts/sedan_linkage.toml) written in place of its
// include; the other parts stay included (relative to assets/vehicles/, or
// to `partsFolder` when given: a copy written elsewhere).
inline std::string sedanText(const std::string& partsFolder = "") {
  std::string text = readFile(asset("vehicles/sedan.toml"));
  const std::string linkage = "\n  \"parts/sedan_linkage.toml\",";
  const auto at = text.find(linkage);
  if (at == std::string::npos) return text;
  text.erase(at, text.find('\n', at + 1) - at);
  if (!partsFolder.empty())
    for (std::string::size_type i = 0; (i = text.find("\"parts/", i)) != std::string::npos; i += partsFolder.size())
      text.replace(i + 1, 6, partsFolder);
  return text + "\n" + readFile(asset("vehicles/parts/sedan_linkage.toml"));
}

}  // namespace bdfcar::test
