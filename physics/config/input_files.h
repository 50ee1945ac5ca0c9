// Every data file this process has read: TOML files with their includes, CSV
// inputs, OBJ meshes, files a vehicle names, recordings. An output is checked
// against them before it is opened (scenario/row_file.h's
// refuseOverwritingInputs), so that `--out` onto an included vehicle part or
// a steering table is refused instead of destroying it. Thread-safe.
#pragma once

#include <string>
#include <vector>

namespace bdfcar::config {

void noteInputFile(const std::string& path);
std::vector<std::string> inputFilesRead();

}  // namespace bdfcar::config
