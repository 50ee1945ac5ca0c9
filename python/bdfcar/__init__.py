"""bdfcar: a multibody car integrated by BDF, as a Python library.

    import bdfcar
    car = bdfcar.Car(bdfcar.asset("scenarios/iso_lane_change.toml"), fidelity="planar")
    while car.time < car.duration:
        car.tick()                       # the scenario's own driver; car.tick(steer=0.1) a person's
    print(car.observation())            # OBSERVATION_NAMES

    t = bdfcar.run(bdfcar.asset("scenarios/lane_change.toml"))   # a whole scenario, as `bdfcar run`
    t["yawrate_radps"]                  # a column as a NumPy array

Environments with the Gymnasium conventions (no gymnasium needed):
LaneChangeEnv and VectorLaneChangeEnv (bdfcar.env). docs/API.md.
"""
import os
import sys

from ._bdfcar import (ASSET_DIR, OBSERVATION_NAMES, Car, ConfigError, OutputError, SimulationError, StateError,
                      VehicleError, __version__, observe_many, set_threads, threads, tick_many)
from ._bdfcar import run as _run
from .telemetry import Telemetry
from .env import Box, LaneChangeEnv, VectorLaneChangeEnv


def Camera(car, width=640, height=360, camera="chase", hud=False):
    """A headless camera on the car (OSMesa, no display needed): camera.render() draws the car as it
    is now into a (height, width, 3) uint8 RGB array. camera: chase, hood, orbit or top-down."""
    return _load_frames().Camera(car, width, height, camera, hud)


def _load_frames():
    """The frames module, loaded on first use with its libraries in the global scope: OpenSceneGraph
    looks GL functions up there (dlsym), and must find libOSMesa's, not another libGL's."""
    flags = sys.getdlopenflags()
    sys.setdlopenflags(flags | os.RTLD_GLOBAL)
    try:
        from . import _frames as module
    finally:
        sys.setdlopenflags(flags)
    return module


def asset(relative):
    """The path of a file under bdfcar's assets/ (scenarios, vehicles, terrain)."""
    return os.path.join(ASSET_DIR, relative)


def run(scenario, *, out=None, vehicle=None, fidelity=None, step=None, duration=None, settings=()):
    """Runs a scenario with its own driver, as `bdfcar run SCENARIO --out OUT` does (the CSV at out is
    the command's, byte for byte), and returns its telemetry (Telemetry; .ok and .failure say how it
    ended). Keyword arguments as the command's options; settings: "KEY=VALUE" strings as --set."""
    r = _run(scenario, out=out, vehicle=vehicle, fidelity=fidelity, step=step, duration=duration,
             settings=list(settings))
    return Telemetry(r)


__all__ = ["ASSET_DIR", "OBSERVATION_NAMES", "Box", "Camera", "Car", "ConfigError", "LaneChangeEnv", "OutputError",
           "SimulationError", "StateError", "Telemetry", "VectorLaneChangeEnv", "VehicleError", "__version__",
           "asset", "observe_many", "run", "set_threads", "threads", "tick_many"]
