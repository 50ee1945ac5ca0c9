// The public C++ API (include/bdfcar/bdfcar.h) over api::CarCore.
#include "bdfcar/bdfcar.h"

#include <dlfcn.h>

#include <algorithm>
#include <filesystem>

#include "car_core.h"
#include "scenario/run_state_bytes.h"

namespace bdfcar {

namespace {

app::ScenarioOverrides overrides(const CarOptions& o) {
  return api::carOverrides(o.vehicle, o.fidelity, o.step, o.duration, o.settings);
}

}  // namespace

std::string version() { return BDFCAR_VERSION; }

std::string assetDir() {
  // Installed: <prefix>/lib[/<triplet>]/libbdfcar.so and <prefix>/share/bdfcar/assets.
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&assetDir), &info) && info.dli_fname) {
    // The library folder is <prefix>/lib or, multiarch, <prefix>/lib/<triplet>.
    std::filesystem::path dir = std::filesystem::absolute(info.dli_fname).parent_path();
    for (int up = 0; up < 2 && dir.has_parent_path(); ++up) {
      dir = dir.parent_path();
      const std::filesystem::path installed = dir / "share" / "bdfcar" / "assets";
      std::error_code ec;
      if (std::filesystem::is_directory(installed, ec)) return installed.string();
    }
  }
  return BDFCAR_ASSET_DIR;
}

Car::Car(const std::string& scenario, const CarOptions& options)
    : core_(std::make_unique<api::CarCore>(scenario, overrides(options))) {}
Car::Car(const std::string& scenario, const CarOptions& options, const Car& sceneOf)
    : core_(std::make_unique<api::CarCore>(scenario, overrides(options), sceneOf.core_.get())) {}
Car::Car(std::unique_ptr<api::CarCore> core) : core_(std::move(core)) {}
Car::~Car() = default;
Car::Car(Car&&) noexcept = default;
Car& Car::operator=(Car&&) noexcept = default;
Car Car::copy() const { return Car(std::make_unique<api::CarCore>(*core_)); }

void Car::tick() {
  try {
    core_->tick(std::nullopt);
  } catch (const api::SimulationError& e) {
    throw SimulationFailed(e.what());
  }
}

void Car::tick(const DriverCommand& c) {
  const scenario::DriverInput in = api::driverInput(c.steer, c.throttle, c.brake);
  try {
    core_->tick(in);
  } catch (const api::SimulationError& e) {
    throw SimulationFailed(e.what());
  }
}

void Car::reset() { core_->reset(); }
double Car::time() const { return core_->time(); }
double Car::duration() const { return core_->duration(); }
bool Car::failed() const { return core_->failed(); }
std::string Car::failure() const { return core_->failure(); }
const std::vector<std::string>& Car::observationNames() { return api::observationNames(); }

std::vector<double> Car::observation() {
  std::vector<double> out(api::kObservationSize);
  core_->observation(out.data());
  return out;
}

std::vector<std::string> Car::telemetryNames() const { return core_->telemetryNames(); }

std::vector<double> Car::telemetryRow() {
  std::vector<double> out(static_cast<std::size_t>(core_->telemetryColumns()));
  core_->telemetryRow(out.data());
  return out;
}

std::vector<char> Car::save() { return core_->save(); }

void Car::restore(const std::vector<char>& state) {
  try {
    core_->restore(state);
  } catch (const scenario::RunStateBytesError& e) {
    throw std::invalid_argument(e.what());
  }
}

api::CarCore& Car::core() { return *core_; }

double Telemetry::at(std::size_t row, const std::string& column) const {
  const auto it = std::find(columns.begin(), columns.end(), column);
  if (it == columns.end()) throw std::out_of_range("no telemetry column \"" + column + "\"");
  if (row >= rows()) throw std::out_of_range("row " + std::to_string(row) + " of " + std::to_string(rows()));
  return data[row * columns.size() + static_cast<std::size_t>(it - columns.begin())];
}

Telemetry run(const std::string& scenario, const CarOptions& options, const std::string& csvPath) {
  api::RunTelemetry r = api::runScenario(scenario, overrides(options), csvPath);
  Telemetry t;
  t.columns = std::move(r.columns);
  t.data = std::move(r.rows);
  t.ok = r.result.ok;
  t.failure = r.result.failure;
  return t;
}

}  // namespace bdfcar
