#include "config/input_files.h"

#include <algorithm>
#include <mutex>

namespace bdfcar::config {

namespace {
std::mutex& lock() {
  static std::mutex m;
  return m;
}
std::vector<std::string>& files() {
  static std::vector<std::string> f;
  return f;
}
}  // namespace

void noteInputFile(const std::string& path) {
  if (path.empty()) return;
  const std::lock_guard<std::mutex> g(lock());
  std::vector<std::string>& f = files();
  if (std::find(f.begin(), f.end(), path) == f.end()) f.push_back(path);
}

std::vector<std::string> inputFilesRead() {
  const std::lock_guard<std::mutex> g(lock());
  return files();
}

}  // namespace bdfcar::config
