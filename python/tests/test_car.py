"""A car stepped tick by tick: states as bytes restored bit for bit, many cars on threads giving
each its single run, and bad calls refused with a Python exception."""
import math

import numpy as np
import pytest

import bdfcar
from conftest import scenario


def steer_signal(i, k):
    """A different steering input per car: sine sweeps of different phases."""
    return 0.3 * math.sin(0.05 * k + 0.7 * i)


@pytest.fixture(scope="module")
def lane_car(root):
    return bdfcar.Car(scenario(root, "lane_change.toml"), fidelity="planar")


def test_a_restored_state_continues_bit_for_bit(lane_car):
    car = lane_car
    car.reset()
    for k in range(30):
        car.tick(steer=steer_signal(0, k))
    state = car.save()
    assert isinstance(state, bytes)
    for k in range(60):
        car.tick(steer=steer_signal(0, 30 + k))
    first = np.concatenate([car.observation(), car.telemetry_row()])
    car.restore(state)
    for k in range(60):
        car.tick(steer=steer_signal(0, 30 + k))
    again = np.concatenate([car.observation(), car.telemetry_row()])
    assert first.tobytes() == again.tobytes()
    assert car.save() != state  # it moved on


def test_a_copy_runs_as_the_reset_original(lane_car):
    a = lane_car
    b = a.copy()
    a.reset()
    for k in range(50):
        a.tick(steer=0.2)
        b.tick(steer=0.2)
    assert a.observation().tobytes() == b.observation().tobytes()
    assert a.time == pytest.approx(0.5)


def test_many_cars_on_threads_give_their_single_runs(lane_car):
    n, ticks = 6, 80
    cars = [lane_car.copy() for _ in range(n)]
    for k in range(ticks):
        actions = np.array([[steer_signal(i, k), 0.0, 0.0] for i in range(n)])
        assert not bdfcar.tick_many(cars, actions).any()
    together = bdfcar.observe_many(cars)
    assert together.shape == (n, len(bdfcar.OBSERVATION_NAMES))
    for i in range(n):
        alone = lane_car.copy()
        for k in range(ticks):
            alone.tick(steer=steer_signal(i, k))
        assert alone.observation().tobytes() == together[i].tobytes(), f"car {i}"
    # Different inputs, different cars: the test can tell them apart.
    assert len({together[i, 2] for i in range(n)}) == n


def test_the_scripted_driver_ticks_without_input(root):
    car = bdfcar.Car(scenario(root, "jturn.toml"), fidelity="planar", duration=1.0)
    while car.time < car.duration - 1e-9:
        car.tick()
    t = bdfcar.run(scenario(root, "jturn.toml"), fidelity="planar", duration=1.0)
    # The same manoeuvre: the yaw rate at the end agrees with the scenario's run (a Jacobian
    # boundary at the start makes it differ in the last digits, not more).
    obs = dict(zip(bdfcar.OBSERVATION_NAMES, car.observation()))
    assert obs["yawrate_radps"] == pytest.approx(t["yawrate_radps"][-1], rel=1e-6)
    assert obs["time_s"] == pytest.approx(1.0)


def test_telemetry_names_are_the_csv_header(lane_car, root, cli, tmp_path):
    import subprocess
    out = tmp_path / "h.csv"
    subprocess.run([cli, "run", scenario(root, "lane_change.toml"), "--duration", "0.02", "--out", str(out)],
                   check=True, stdout=subprocess.DEVNULL)
    assert out.read_text().splitlines()[0].split(",") == lane_car.telemetry_names
    assert len(lane_car.telemetry_row()) == len(lane_car.telemetry_names)


def test_bad_calls_raise_clear_exceptions(lane_car, root):
    car = lane_car
    with pytest.raises(ValueError, match="steer must be a finite number"):
        car.tick(steer=float("nan"))
    with pytest.raises(ValueError, match="throttle must be a finite number"):
        car.tick(steer=0.0, throttle=float("inf"))
    with pytest.raises(ValueError, match=r"shape \(2, 3\)"):
        bdfcar.tick_many([car, car.copy()], np.zeros((2, 2)))
    with pytest.raises(ValueError, match="finite"):
        bdfcar.tick_many([car], np.array([[0.0, float("nan"), 0.0]]))
    with pytest.raises(bdfcar.StateError):
        car.restore(b"not a state")
    state = car.save()
    with pytest.raises(bdfcar.StateError):
        car.restore(state[:-3])
    other = bdfcar.Car(scenario(root, "lane_change.toml"), fidelity="planar",
                       vehicle=f"{root}/assets/vehicles/paper.toml", duration=0.1)
    with pytest.raises(bdfcar.StateError):
        car.restore(other.save())
    assert issubclass(bdfcar.StateError, ValueError)
    with pytest.raises(bdfcar.ConfigError, match="no_such.toml"):
        bdfcar.Car(f"{root}/assets/scenarios/no_such.toml")
    with pytest.raises(bdfcar.ConfigError, match="fidelity"):
        bdfcar.Car(scenario(root, "lane_change.toml"), fidelity="wobbly")
    with pytest.raises(bdfcar.ConfigError, match="start.speed"):
        bdfcar.Car(scenario(root, "lane_change.toml"), settings=["start.speed=\"fast\""])
    with pytest.raises(ValueError, match="no \\[course\\]"):
        car.course_reference_y(0.0)
    # After all that the car still steps, and its state is intact.
    car.restore(state)
    car.tick(steer=0.1)


def test_two_cars_in_one_scene_each_run_as_alone(root):
    """Another vehicle on another rung joins the first car's scene; stepped in turn, each gives its
    run alone."""
    alone_a = bdfcar.Car(scenario(root, "jturn.toml"), fidelity="kinematic")
    alone_b = bdfcar.Car(scenario(root, "lane_change.toml"), vehicle=f"{root}/assets/vehicles/paper.toml",
                         fidelity="planar")
    a = bdfcar.Car(scenario(root, "jturn.toml"), fidelity="kinematic")
    b = bdfcar.Car(scenario(root, "lane_change.toml"), vehicle=f"{root}/assets/vehicles/paper.toml",
                   fidelity="planar", scene=a)
    for _ in range(150):
        a.tick()
        b.tick(steer=0.1)
        alone_a.tick()
        alone_b.tick(steer=0.1)
    assert a.telemetry_row().tobytes() == alone_a.telemetry_row().tobytes()
    assert b.telemetry_row().tobytes() == alone_b.telemetry_row().tobytes()
    with pytest.raises(RuntimeError, match="not the scene's"):
        bdfcar.Car(scenario(root, "proving_ground/hill_stop.toml"), fidelity="planar", scene=a)
