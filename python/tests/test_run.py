"""bdfcar.run against the command line: the same telemetry, byte for byte."""
import os
import subprocess

import numpy as np
import pytest

import bdfcar
from conftest import scenario


def test_run_writes_the_commands_bytes_and_the_array_prints_them(root, cli, tmp_path):
    path = scenario(root, "lane_change.toml")
    py_csv, cli_csv = tmp_path / "py.csv", tmp_path / "cli.csv"
    t = bdfcar.run(path, out=str(py_csv), duration=2.0)
    subprocess.run([cli, "run", path, "--duration", "2", "--out", str(cli_csv)], check=True,
                   stdout=subprocess.DEVNULL)
    expected = cli_csv.read_bytes()
    assert py_csv.read_bytes() == expected
    lines = expected.decode().splitlines()
    assert lines[0].split(",") == t.columns
    assert t.to_csv_rows() == lines[1:]
    assert t.ok and len(t) == len(lines) - 1 and t.steps == 200


def test_run_without_a_file_gives_the_same_array(root, tmp_path):
    path = scenario(root, "jturn.toml")
    a = bdfcar.run(path, duration=3.0, fidelity="planar")
    b = bdfcar.run(path, duration=3.0, fidelity="planar", out=str(tmp_path / "j.csv"))
    assert np.array_equal(a.data, b.data)
    # A column by name: the J-turn turns left, so the yaw rate ends positive.
    assert a["yawrate_radps"][-1] > 0.05
    assert a["time_s"][-1] == pytest.approx(3.0, abs=1e-9)


def test_a_failed_run_says_where(root):
    # The explicit Euler reference at the paper's 10 ms step diverges (RESULTS, Table 3's explicit column):
    # a failed run is a result that says when and why, not an exception.
    t = bdfcar.run(scenario(root, "jturn.toml"), duration=3.0, settings=["integrator.method=euler"])
    assert not t.ok
    assert "diverged" in t.failure and "below the ground" in t.failure
    assert t.failure_time < 0  # while settling, before the manoeuvre's t = 0
    # A car that cannot settle cannot be made.
    with pytest.raises(bdfcar.SimulationError, match="diverged while it settled"):
        bdfcar.Car(scenario(root, "jturn.toml"), settings=["integrator.method=euler"])
