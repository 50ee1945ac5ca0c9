// Mapping files on disk: one file, a folder of them, the shipped folder.
#include <algorithm>
#include <fstream>
#include <sstream>

#include "config/file_kind.h"
#include "config/input_files.h"
#include "input/mapping.h"

namespace bdfcar::input {

// Reads and parses one mapping file.
DeviceMapping loadMappingFile(const std::filesystem::path& path) {
  std::string text;
  try {
    text = config::readDataFile(path.string(), "mapping file");
  } catch (const std::runtime_error& e) {
    throw MappingError(e.what());
  }
  config::noteInputFile(path.string());
  return parseMapping(text, path.string());
}

// Every *.toml of a folder in file-name order.
std::vector<DeviceMapping> loadMappingDir(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw MappingError(dir.string() + ": not a folder of input mapping files");
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".toml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());  // directory order is arbitrary; matching ties need a fixed order
  std::vector<DeviceMapping> mappings;
  for (const auto& file : files) mappings.push_back(loadMappingFile(file));
  return mappings;
}

// The source tree's assets/input, fixed at build time.
std::filesystem::path defaultMappingDir() { return BDFCAR_INPUT_MAPPING_DIR; }

}  // namespace bdfcar::input
