#include "session/drive_picks.h"

#include <algorithm>
#include <filesystem>

#include "scenario_overrides.h"
#include "vehicle/vehicle_builder.h"

namespace bdfcar::app {

std::string driveOutput(const std::string& path, int drive) {
  if (path.empty() || drive <= 1) return path;
  const std::filesystem::path p(path);
  for (int n = drive;; ++n) {
    std::filesystem::path q = p;
    q.replace_filename(p.stem().string() + "-" + std::to_string(n) + p.extension().string());
    if (!std::filesystem::exists(q)) return q.string();
  }
}

DrivePicks drivePicks(const scenario::ScenarioSpec& spec) {
  DrivePicks p;
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(std::string(BDFCAR_ASSET_DIR) + "/vehicles"))
    if (e.is_regular_file() && e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::error_code ec;
  auto current = std::find_if(files.begin(), files.end(), [&](const std::filesystem::path& f) {
    return std::filesystem::equivalent(f, spec.vehicleFile, ec);
  });
  if (current == files.end()) current = files.insert(files.begin(), spec.vehicleFile);
  p.menu.car = static_cast<int>(current - files.begin());
  for (const auto& f : files) {
    p.carFiles.push_back(f.string());
    p.menu.cars.push_back(f.stem().string());
  }
  p.menu.fidelities = fidelityChoices();
  const std::string now = spec.fidelity.automatic ? "auto" : vehicle::fidelityName(spec.fidelity.suspension);
  for (size_t i = 0; i < p.menu.fidelities.size(); ++i)
    if (p.menu.fidelities[i] == now) p.menu.fidelity = static_cast<int>(i);
  return p;
}

}  // namespace bdfcar::app
