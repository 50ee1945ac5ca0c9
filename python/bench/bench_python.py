#!/usr/bin/env python3
"""Timings of the Python module against issue 29's targets, as a Markdown section for
docs/RESULTS.md (scripts/report.sh appends it). Medians over REPEATS runs; ratios within one run.

    python3 python/bench/bench_python.py [REPEATS]

- step() overhead: car.tick(steer=s) called N times from Python against car.tick(steer=s, ticks=N)
  (the same N ticks looped in C++), per call: what the Python call adds to the step.
- vector stepping: 64 planar cars through tick_many, car-steps per second on 1 and 2 threads.
- reset from a saved state: car.restore(bytes).
- a headless frame (OSMesa) of 640x360 to a NumPy array, the car moved 30 ms between frames.
"""
import statistics
import sys
import time

import numpy as np

import bdfcar


def median_of(repeats, f):
    return statistics.median(f() for _ in range(repeats))


def main(repeats=5):
    scenario = bdfcar.asset("scenarios/lane_change.toml")
    car = bdfcar.Car(scenario, fidelity="planar", duration=1e4)
    start = car.save()
    n = 2000

    def python_loop():
        car.restore(start)
        t0 = time.perf_counter()
        for _ in range(n):
            car.tick(steer=0.05)
        return (time.perf_counter() - t0) / n

    def cpp_loop():
        car.restore(start)
        t0 = time.perf_counter()
        car.tick(steer=0.05, ticks=n)
        return (time.perf_counter() - t0) / n

    pairs = [(python_loop(), cpp_loop()) for _ in range(repeats)]
    py_call = statistics.median(p for p, _ in pairs)
    cpp_call = statistics.median(c for _, c in pairs)
    overhead = statistics.median(p - c for p, c in pairs)

    def restore():
        t0 = time.perf_counter()
        for _ in range(1000):
            car.restore(start)
        return (time.perf_counter() - t0) / 1000

    restore_s = median_of(repeats, restore)

    cars = [car.copy() for _ in range(64)]
    actions = np.zeros((64, 3))
    actions[:, 0] = np.linspace(-0.2, 0.2, 64)
    rates = {}
    for threads in (1, 2):
        bdfcar.set_threads(threads)

        def batch():
            for c in cars:
                c.restore(start)
            t0 = time.perf_counter()
            for _ in range(200):
                bdfcar.tick_many(cars, actions)
            return 64 * 200 / (time.perf_counter() - t0)

        rates[threads] = median_of(repeats, batch)
    bdfcar.set_threads(2)

    frame_car = bdfcar.Car(bdfcar.asset("scenarios/iso_lane_change.toml"), fidelity="planar")
    camera = bdfcar.Camera(frame_car, 640, 360)
    frame_times = []
    for _ in range(30 * repeats):
        frame_car.tick(ticks=3)
        t0 = time.perf_counter()
        camera.render()
        frame_times.append(time.perf_counter() - t0)
    frame_times.sort()
    frame_p50 = frame_times[len(frame_times) // 2]
    frame_p99 = frame_times[min(len(frame_times) - 1, int(0.99 * len(frame_times)))]

    print("## 12. Python (`import bdfcar`, issue 29)")
    print()
    print(f"The planar rung on the lane change ({scenario.split('/assets/')[-1]}), one 10 ms tick per call; "
          f"medians of {repeats} runs, each figure's pair measured in the same run.")
    print("Command: `PYTHONPATH=build/python python3 python/bench/bench_python.py`.")
    print()
    print("| what | figure | target |")
    print("|---|---|---|")
    print(f"| `car.tick(steer=...)` from Python, per call | {py_call * 1e6:.2f} us | |")
    print(f"| the same ticks looped in C++ (`ticks=N`), per tick | {cpp_call * 1e6:.2f} us | |")
    print(f"| what the Python call adds | {overhead * 1e6:.2f} us | <= 2 us |")
    print(f"| `bdfcar.tick_many`, 64 cars, 1 thread | {rates[1]:,.0f} car-steps/s | |")
    print(f"| `bdfcar.tick_many`, 64 cars, 2 threads | {rates[2]:,.0f} car-steps/s ({rates[2] / rates[1]:.2f}x "
          f"the one thread) | >= 50,000 |")
    print(f"| `car.restore(state)` (reset from saved bytes) | {restore_s * 1e6:.2f} us | <= 20 us |")
    print(f"| `bdfcar.Camera(car, 640, 360).render()` to a NumPy array ({camera.renderer}) | p50 "
          f"{frame_p50 * 1e3:.1f} ms, p99 {frame_p99 * 1e3:.1f} ms | report p50 |")


if __name__ == "__main__":
    main(*(int(a) for a in sys.argv[1:]))
