// The Python module `bdfcar._bdfcar` (pybind11): Car (python/car.h), the
// vector stepping of many cars on worker threads with the interpreter's lock
// released, and run() of a whole scenario with its telemetry as an array.
// The pure-Python package around it (python/bdfcar/) adds the environments.
// Every error is a Python exception: bad files and keys ConfigError, a state
// of another car StateError (both ValueError), a failed step SimulationError.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>

#include "car_core.h"
#include "car_pool.h"
#include "config/toml_reader.h"
#include "scenario/row_file.h"
#include "scenario/run_state_bytes.h"

namespace py = pybind11;
using namespace bdfcar;

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

using api::carOverrides;
using api::driverInput;

std::vector<api::CarCore*> carList(const py::list& cars) {
  std::vector<api::CarCore*> out;
  for (const py::handle& h : cars) out.push_back(h.cast<api::CarCore*>());
  // One car twice would be stepped by two threads at once.
  std::vector<api::CarCore*> sorted = out;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    throw py::value_error("the same Car is in the list twice: each car steps once per call");
  return out;
}

const scenario::Iso3888Course& course(const api::CarCore& c) {
  if (!c.simulation().course()) throw py::value_error("this scenario has no [course]");
  return *c.simulation().course();
}

std::unique_ptr<python::CarPool>& poolHolder() {
  static std::unique_ptr<python::CarPool> p = std::make_unique<python::CarPool>();
  return p;
}
python::CarPool& pool() { return *poolHolder(); }
// Held while the pool runs or is replaced (Python threads may call both at once).
std::mutex& poolMutex() {
  static std::mutex m;
  return m;
}

// Ticks every car once (actions: (N, 3) steer, throttle, brake, or None for
// the scenarios' own drivers); a car whose step fails is marked, not raised.
py::array_t<bool> tickMany(const py::list& cars, const std::optional<Array>& actions) {
  std::vector<api::CarCore*> list = carList(cars);
  const int n = static_cast<int>(list.size());
  std::vector<scenario::DriverInput> inputs;
  if (actions) {
    if (actions->ndim() != 2 || actions->shape(0) != n || actions->shape(1) != 3)
      throw py::value_error("actions must have shape (" + std::to_string(n) + ", 3) (steer, throttle, brake), got " +
                            py::str(py::tuple(py::cast(std::vector<py::ssize_t>(
                                actions->shape(), actions->shape() + actions->ndim())))).cast<std::string>());
    auto a = actions->unchecked<2>();
    for (int i = 0; i < n; ++i) inputs.push_back(driverInput(a(i, 0), a(i, 1), a(i, 2)));
  }
  for (int i = 0; i < n; ++i)
    if (list[i]->failed())
      throw api::SimulationError("car " + std::to_string(i) + " failed (" + list[i]->failure() +
                                    "): reset() or restore() it before it steps again");
  py::array_t<bool> failed(n);
  bool* f = failed.mutable_data();
  {
    py::gil_scoped_release release;
    std::lock_guard lock(poolMutex());
    pool().run(n, [&](int i) {
      try {
        list[i]->tick(actions ? std::optional(inputs[i]) : std::nullopt);
      } catch (const api::SimulationError&) {
        // marked below; the car says why (failure)
      }
      f[i] = list[i]->failed();
    });
  }
  return failed;
}

py::array_t<double> observeMany(const py::list& cars) {
  std::vector<api::CarCore*> list = carList(cars);
  const int n = static_cast<int>(list.size());
  py::array_t<double> out({n, api::kObservationSize});
  double* o = out.mutable_data();
  {
    py::gil_scoped_release release;
    std::lock_guard lock(poolMutex());
    pool().run(n, [&](int i) { list[i]->observation(o + i * api::kObservationSize); });
  }
  return out;
}

// A whole scenario with its own driver, as `bdfcar run` runs it (api::runScenario).
py::dict runScenario(const std::string& path, const std::optional<std::string>& out,
                     const app::ScenarioOverrides& ov) {
  api::RunTelemetry t;
  {
    py::gil_scoped_release release;
    t = api::runScenario(path, ov, out.value_or(""));
  }
  const std::vector<std::string>& names = t.columns;
  const std::vector<double>& rows = t.rows;
  const scenario::RunResult& r = t.result;
  const py::ssize_t cols = static_cast<py::ssize_t>(names.size());
  py::array_t<double> data({static_cast<py::ssize_t>(rows.size()) / cols, cols});
  std::copy(rows.begin(), rows.end(), data.mutable_data());
  py::dict d;
  d["columns"] = names;
  d["data"] = data;
  d["ok"] = r.ok;
  d["failure"] = r.failure;
  d["failure_time"] = r.failureTime;
  d["steps"] = r.steps;
  d["wall_seconds"] = r.wallSeconds;
  d["simulated_seconds"] = r.simulatedSeconds;
  if (r.course) {
    d["course_passed"] = r.course->passed && r.course->exitTime >= 0;
    d["cone_hits"] = r.course->coneHits;
  }
  return d;
}

}  // namespace

PYBIND11_MODULE(_bdfcar, m) {
  m.doc() = "bdfcar: a multibody car integrated by BDF (the C++ core; see the bdfcar package)";
  m.attr("__version__") = BDFCAR_VERSION;
  m.attr("ASSET_DIR") = BDFCAR_ASSET_DIR;

  static py::exception<config::ConfigError> configError(m, "ConfigError", PyExc_ValueError);
  static py::exception<scenario::PrepareError> vehicleError(m, "VehicleError", PyExc_ValueError);
  static py::exception<scenario::RunStateBytesError> stateError(m, "StateError", PyExc_ValueError);
  static py::exception<api::SimulationError> simulationError(m, "SimulationError", PyExc_RuntimeError);
  static py::exception<scenario::OutputError> outputError(m, "OutputError", PyExc_OSError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const config::ConfigError& e) {
      configError(e.what());
    } catch (const scenario::PrepareError& e) {
      vehicleError(e.what());
    } catch (const scenario::RunStateBytesError& e) {
      stateError(e.what());
    } catch (const api::SimulationError& e) {
      simulationError(e.what());
    } catch (const scenario::OutputError& e) {
      outputError(e.what());
    }
  });

  m.attr("OBSERVATION_NAMES") = api::observationNames();

  py::class_<api::CarCore>(m, "Car", "A scenario's car, stepped one driver tick at a time")
      .def(py::init([](const std::string& scenario, std::optional<std::string> vehicle,
                       std::optional<std::string> fidelity, std::optional<double> step,
                       std::optional<double> duration, std::vector<std::string> settings,
                       const api::CarCore* scene) {
             const app::ScenarioOverrides ov = carOverrides(vehicle, fidelity, step, duration, settings);
             py::gil_scoped_release release;
             return std::make_unique<api::CarCore>(scenario, ov, scene);
           }),
           py::arg("scenario"), py::kw_only(), py::arg("vehicle") = py::none(), py::arg("fidelity") = py::none(),
           py::arg("step") = py::none(), py::arg("duration") = py::none(),
           py::arg("settings") = std::vector<std::string>{}, py::arg("scene") = py::none(),
           "Loads the scenario file (with a vehicle file, a fidelity rung, a step, a duration and KEY=VALUE "
           "settings replacing its own), builds the world and settles the car; scene=another car: this one "
           "joins that car's scene (its ground, built once; the scenario must name the same ground)")
      .def("copy", [](const api::CarCore& c) { return std::make_unique<api::CarCore>(c); },
           "Another car in the same world (built once, shared), at the start")
      .def("reset", &api::CarCore::reset, py::call_guard<py::gil_scoped_release>(),
           "Back to the start of the manoeuvre")
      .def(
          "tick",
          [](api::CarCore& c, std::optional<double> steer, double throttle, double brake, int ticks) {
            std::optional<scenario::DriverInput> in;
            if (steer) in = driverInput(*steer, throttle, brake);
            if (ticks < 0) throw py::value_error("ticks must be 0 or more, got " + std::to_string(ticks));
            py::gil_scoped_release release;
            for (int i = 0; i < ticks; ++i) c.tick(in);
          },
          py::arg("steer") = py::none(), py::arg("throttle") = 0.0, py::arg("brake") = 0.0, py::kw_only(),
          py::arg("ticks") = 1,
          "One driver tick (or `ticks` of them, the input held): steer [-1, 1] (+ left), throttle and brake "
          "[0, 1] (clamped; NaN refused), or, with no steer, the scenario's own driver. Raises SimulationError "
          "when a step fails")
      .def("observation",
           [](api::CarCore& c) {
             py::array_t<double> out(api::kObservationSize);
             c.observation(out.mutable_data());
             return out;
           },
           "The observation now (OBSERVATION_NAMES)")
      .def("telemetry_row",
           [](api::CarCore& c) {
             py::array_t<double> out(c.telemetryColumns());
             c.telemetryRow(out.mutable_data());
             return out;
           },
           "The telemetry row now (telemetry_names; docs/TELEMETRY.md)")
      .def_property_readonly("telemetry_names", &api::CarCore::telemetryNames)
      .def("save", [](api::CarCore& c) {
             const std::vector<char> b = c.save();
             return py::bytes(b.data(), b.size());
           }, "The run state as bytes (versioned, checksummed)")
      .def("restore",
           [](api::CarCore& c, const py::bytes& b) {
             const std::string_view v = b;
             const std::vector<char> bytes(v.begin(), v.end());
             py::gil_scoped_release release;
             c.restore(bytes);
           },
           py::arg("state"), "Restores a state from save(); StateError for bytes of another car or none")
      .def_property_readonly("time", &api::CarCore::time, "s, 0 at the start of the manoeuvre")
      .def_property_readonly("duration", &api::CarCore::duration, "s, the scenario's manoeuvre")
      .def_property_readonly("tick_seconds", &api::CarCore::tickSeconds, "s, the driver's input period")
      .def_property_readonly("steps_per_tick", &api::CarCore::stepsPerTick)
      .def_property_readonly("fidelity", &api::CarCore::fidelity, "the rung driving now: 0 linkage, 1 kinematic, 2 planar")
      .def_property_readonly("has_course", [](const api::CarCore& c) { return c.simulation().course().has_value(); })
      .def("course_reference_y",
           [](const api::CarCore& c, double x) { return course(c).referenceY(x); }, py::arg("x"),
           "The ISO 3888 course's reference centre line y(x), m (ValueError without a course)")
      .def("course_contains", [](const api::CarCore& c, double x, double y) { return course(c).contains(x, y); },
           py::arg("x"), py::arg("y"), "Whether the point is inside the course's lanes")
      .def_property_readonly("course_end_x", [](const api::CarCore& c) { return course(c).endX; })
      .def_property_readonly("failed", &api::CarCore::failed)
      .def_property_readonly("failure", &api::CarCore::failure);

  m.def("tick_many", &tickMany, py::arg("cars"), py::arg("actions") = py::none(),
        "Ticks every car once on worker threads (the interpreter's lock released): actions (N, 3) of steer, "
        "throttle, brake, or None for the scenarios' drivers. Returns which cars failed");
  m.def("observe_many", &observeMany, py::arg("cars"), "The cars' observations, (N, len(OBSERVATION_NAMES))");
  m.def("threads", [] { return pool().threads(); }, "Threads that step cars (the caller's included)");
  m.def(
      "set_threads",
      [](int n) {
        if (n < 1) throw py::value_error("threads must be 1 or more, got " + std::to_string(n));
        py::gil_scoped_release release;
        std::lock_guard lock(poolMutex());
        poolHolder() = std::make_unique<python::CarPool>(n - 1);
      },
      py::arg("n"), "Steps cars on n threads (the caller's included; default: one per core)");
  m.def(
      "run",
      [](const std::string& scenario, std::optional<std::string> out, std::optional<std::string> vehicle,
         std::optional<std::string> fidelity, std::optional<double> step, std::optional<double> duration,
         std::vector<std::string> settings) {
        return runScenario(scenario, out, carOverrides(vehicle, fidelity, step, duration, settings));
      },
      py::arg("scenario"), py::kw_only(), py::arg("out") = py::none(), py::arg("vehicle") = py::none(),
      py::arg("fidelity") = py::none(), py::arg("step") = py::none(), py::arg("duration") = py::none(),
      py::arg("settings") = std::vector<std::string>{},
      "Runs a scenario with its own driver as `bdfcar run` does: a dict of columns, data (rows x columns), "
      "ok, failure, steps ... (and the CSV at out, the command's bytes)");
}
