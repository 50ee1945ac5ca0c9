// bdfcar as a C++ library: a multibody car integrated by BDF, driven by a
// scenario file. The only header a program needs (with camera.h for
// frames); it includes no Eigen, Bullet or other library header, and the
// library hides the rest (find_package(bdfcar) -> bdfcar::bdfcar, shared, or
// bdfcar::bdfcar_static). docs/API.md.
//
//   bdfcar::Car car(bdfcar::assetDir() + "/scenarios/lane_change.toml", {.fidelity = "planar"});
//   while (car.time() < car.duration()) car.tick({.steer = 0.1});
//   std::vector<double> obs = car.observation();     // bdfcar::Car::observationNames()
//   std::vector<char> state = car.save();            // restore(state) continues bit for bit
//
// Errors are exceptions: std::invalid_argument for a bad argument (NaN
// input, bytes that are no state of this car), SimulationFailed for a step
// that failed, std::runtime_error naming the file, line and key for a bad
// file, key or value (an unknown fidelity too).
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace bdfcar {

namespace api {
class CarCore;
}

// The library's version ("0.1.0").
std::string version();
// The folder of the assets installed with the library (scenarios, vehicles,
// terrain): <prefix>/share/bdfcar/assets beside the library, else the
// source tree it was built from.
std::string assetDir();

// What replaces a scenario file's own settings (as `bdfcar run`'s options).
struct CarOptions {
  std::optional<std::string> vehicle;   // a vehicle file
  std::optional<std::string> fidelity;  // linkage, kinematic, planar or auto
  std::optional<double> step;           // s, the integration step
  std::optional<double> duration;       // s, the manoeuvre
  std::vector<std::string> settings;    // "KEY=VALUE" as --set
};

// A driver's input for one tick: steer [-1, 1] (+ left), throttle and brake
// [0, 1]; clamped to those ranges, NaN refused (std::invalid_argument).
struct DriverCommand {
  double steer = 0, throttle = 0, brake = 0;
};

// A step failed (diverged, a state check): reset or restore the car.
class SimulationFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Car {
 public:
  // Loads the scenario, builds its world (or joins sceneOf's scene: its
  // ground, built once) and settles the car.
  explicit Car(const std::string& scenario, const CarOptions& options = {});
  Car(const std::string& scenario, const CarOptions& options, const Car& sceneOf);
  ~Car();
  Car(Car&&) noexcept;
  Car& operator=(Car&&) noexcept;
  // Another car in the same world (vehicle and scene built once), at the start.
  Car copy() const;

  void tick();                           // the scenario's own driver
  void tick(const DriverCommand& input);  // a person's or an agent's
  void reset();                          // back to the start of the manoeuvre

  double time() const;      // s, 0 at the start of the manoeuvre
  double duration() const;  // s, the scenario's
  bool failed() const;
  std::string failure() const;

  static const std::vector<std::string>& observationNames();
  std::vector<double> observation();
  std::vector<std::string> telemetryNames() const;  // the CSV header (docs/TELEMETRY.md)
  std::vector<double> telemetryRow();               // the CSV row now

  std::vector<char> save();  // versioned, checksummed bytes
  // Throws std::invalid_argument for bytes that are no state or another car's.
  void restore(const std::vector<char>& state);

  api::CarCore& core();  // for bdfcar::Camera

 private:
  explicit Car(std::unique_ptr<api::CarCore> core);
  std::unique_ptr<api::CarCore> core_;
};

// A whole scenario with its own driver, as `bdfcar run` runs it.
struct Telemetry {
  std::vector<std::string> columns;
  std::vector<double> data;  // row after row, columns.size() values each
  bool ok = true;
  std::string failure;       // when !ok: when and why
  std::size_t rows() const { return columns.empty() ? 0 : data.size() / columns.size(); }
  double at(std::size_t row, const std::string& column) const;  // std::out_of_range for a bad row or name
};
// csvPath: also writes the command's CSV file, byte for byte.
Telemetry run(const std::string& scenario, const CarOptions& options = {}, const std::string& csvPath = "");

}  // namespace bdfcar
