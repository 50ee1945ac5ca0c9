#!/usr/bin/env python3
"""The ISO 3888-1 double lane change from Python, two ways:

1. as `bdfcar run` runs it (the scenario's path follower), its telemetry as a NumPy array;
2. as a control task (bdfcar.LaneChangeEnv), steered by a small preview controller.

Plots both with matplotlib where it is installed (python3-matplotlib), to lane_change.png in the
folder given (default: the current one). Usage: python3 lane_change.py [OUT_DIR]
"""
import os
import sys

import numpy as np

import bdfcar


def main(out_dir="."):
    scenario = bdfcar.asset("scenarios/iso_lane_change.toml")

    t = bdfcar.run(scenario, fidelity="planar")
    print(f"path follower: {t.steps} steps, course {'passed' if t.course_passed else 'FAILED'}, "
          f"{t.cone_hits} cones hit, peak lateral acceleration {np.abs(t['ay_mps2']).max():.2f} m/s^2")

    env = bdfcar.LaneChangeEnv(scenario, fidelity="planar")
    obs, _ = env.reset(seed=0)
    xs, ys, total = [], [], 0.0
    while True:
        # Toward the line 1 s ahead, damped by the heading and lateral errors.
        steer = np.clip(0.03 * obs[7] - 4.0 * obs[1] - 0.05 * obs[0], -1.0, 1.0)
        obs, reward, terminated, truncated, info = env.step([steer])
        raw = dict(zip(bdfcar.OBSERVATION_NAMES, env.car.observation()))
        xs.append(raw["x_m"])
        ys.append(raw["y_m"])
        total += reward
        if terminated or truncated:
            break
    outcome = "passed" if info.get("passed") else "left the course" if info.get("left_course") else "ran out of time"
    print(f"preview controller: {outcome} at t = {env.car.time:.2f} s, return {total:.1f}")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not installed: no plot (apt install python3-matplotlib)")
        return 0 if info.get("passed") and t.course_passed else 1
    fig, ax = plt.subplots(2, 1, figsize=(8, 6))
    ax[0].plot(t["x_m"], t["y_m"], label="path follower (bdfcar.run)")
    ax[0].plot(xs, ys, "--", label="preview controller (LaneChangeEnv)")
    ax[0].set_xlabel("x, m")
    ax[0].set_ylabel("y, m")
    ax[0].legend()
    ax[1].plot(t["time_s"], t["ay_mps2"])
    ax[1].set_xlabel("time, s")
    ax[1].set_ylabel("lateral acceleration, m/s^2")
    fig.tight_layout()
    path = os.path.join(out_dir, "lane_change.png")
    fig.savefig(path)
    print(f"plot: {path}")
    return 0 if info.get("passed") and t.course_passed else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
