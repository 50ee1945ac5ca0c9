"""The ISO 3888-1 double lane change as a control task, with the Gymnasium conventions
(reset(seed=...) -> (obs, info); step(action) -> (obs, reward, terminated, truncated, info);
observation_space / action_space as Box), without needing gymnasium installed.

The car is the scenario's (assets/scenarios/iso_lane_change.toml: the sedan at 60 km/h, its speed
held by the scenario's speed control); the agent steers. Observation (float64):

    0  lateral_error_m     y - y_ref(x): the car's centre of mass from the course's reference line
    1  heading_error_rad   yaw - the reference line's heading at x
    2  vy_mps              sideways velocity (chassis axes)
    3  yawrate_radps
    4  ay_mps2
    5  steer_in            the steering input now, [-1, 1]
    6+ preview_m           y_ref(x + v t_i) - y for each preview time t_i (default 0.5, 1.0, 1.5 s)

Reward per tick: -(lateral error / 1 m)^2 - 0.1 (change of steer)^2; leaving the course ends the
episode (terminated, reward -100), so does passing its end (terminated, no penalty); the scenario's
duration truncates it. A step that diverges ends it too (terminated, info["failure"]).
"""
import numpy as np

from ._bdfcar import OBSERVATION_NAMES, Car, SimulationError, observe_many, tick_many

_O = {name: i for i, name in enumerate(OBSERVATION_NAMES)}


class Box:
    """A box of float64 values, as Gymnasium's spaces.Box: low, high, shape, dtype, sample(), contains()."""

    def __init__(self, low, high, shape):
        self.shape = tuple(shape)
        self.dtype = np.float64
        self.low = np.full(self.shape, low, dtype=np.float64)
        self.high = np.full(self.shape, high, dtype=np.float64)
        self._rng = np.random.default_rng()

    def seed(self, seed=None):
        self._rng = np.random.default_rng(seed)

    def sample(self):
        low = np.where(np.isfinite(self.low), self.low, -1.0)
        high = np.where(np.isfinite(self.high), self.high, 1.0)
        return self._rng.uniform(low, high)

    def contains(self, x):
        x = np.asarray(x)
        return x.shape == self.shape and bool(np.all(x >= self.low) and np.all(x <= self.high))

    def __repr__(self):
        return f"Box({self.low.min()}, {self.high.max()}, {self.shape}, float64)"


def _default_scenario():
    from . import asset
    return asset("scenarios/iso_lane_change.toml")


class _Course:
    """The course's reference line as a table (one lookup per car and step, vectorised)."""

    def __init__(self, car):
        if not car.has_course:
            raise ValueError("the lane-change task needs a scenario with a [course]")
        self.end_x = car.course_end_x
        self.x = np.arange(-100.0, self.end_x + 200.0, 0.05)
        self.y = np.array([car.course_reference_y(x) for x in self.x])
        self.heading = np.gradient(self.y, self.x)

    def reference(self, x):
        return np.interp(x, self.x, self.y)

    def heading_at(self, x):
        return np.arctan(np.interp(x, self.x, self.heading))


def _task_observation(raw, course, preview):
    """raw: (N, len(OBSERVATION_NAMES)) -> (N, 6 + len(preview))."""
    x, y = raw[:, _O["x_m"]], raw[:, _O["y_m"]]
    speed = raw[:, _O["speed_mps"]]
    cols = [y - course.reference(x), raw[:, _O["yaw_rad"]] - course.heading_at(x), raw[:, _O["vy_mps"]],
            raw[:, _O["yawrate_radps"]], raw[:, _O["ay_mps2"]], raw[:, _O["steer_in"]]]
    cols += [course.reference(x + speed * t) - y for t in preview]
    return np.stack(cols, axis=1)


def _check_actions(action, n):
    a = np.asarray(action, dtype=np.float64)
    if a.size != n:
        raise ValueError(f"expected {n} steering action{'s' if n > 1 else ''} (shape ({n},) or ({n}, 1)), "
                         f"got shape {a.shape}")
    a = a.reshape(n)
    if not np.all(np.isfinite(a)):
        raise ValueError(f"actions must be finite numbers, got {a}")
    return np.clip(a, -1.0, 1.0)


class LaneChangeEnv:
    """One car through the ISO 3888-1 double lane change (module docstring for the task)."""

    metadata = {"render_modes": []}

    def __init__(self, scenario=None, *, fidelity="planar", settings=(), preview=(0.5, 1.0, 1.5), car=None):
        self.car = car if car is not None else Car(scenario or _default_scenario(), fidelity=fidelity,
                                                   settings=list(settings))
        self._course = _Course(self.car)
        self._preview = tuple(preview)
        self._start = self.car.save()
        self.observation_space = Box(-np.inf, np.inf, (6 + len(self._preview),))
        self.action_space = Box(-1.0, 1.0, (1,))
        self._steer = 0.0

    def reset(self, *, seed=None, options=None):
        """Back to the start (the car settled at speed before the course). The task itself is
        deterministic; seed seeds the action space's sample()."""
        if seed is not None:
            self.action_space.seed(seed)
        self.car.restore(self._start)
        self._steer = 0.0
        return self._observe(), {"time": self.car.time}

    def _observe(self):
        return _task_observation(self.car.observation()[None, :], self._course, self._preview)[0]

    def step(self, action):
        steer = float(_check_actions(action, 1)[0])
        info = {}
        try:
            self.car.tick(steer=steer)
        except SimulationError as e:
            info["failure"] = str(e)
            return np.zeros(self.observation_space.shape), -100.0, True, False, info
        obs = self._observe()
        raw = self.car.observation()
        x, y = raw[_O["x_m"]], raw[_O["y_m"]]
        reward = -obs[0] ** 2 - 0.1 * (steer - self._steer) ** 2
        self._steer = steer
        terminated = False
        if not self.car.course_contains(x, y):
            reward, terminated, info["left_course"] = -100.0, True, True
        elif x > self._course.end_x:
            terminated, info["passed"] = True, True
        truncated = not terminated and self.car.time >= self.car.duration - 1e-9
        info["time"] = self.car.time
        return obs, float(reward), terminated, truncated, info

    def close(self):
        pass


class VectorLaneChangeEnv:
    """N cars through the lane change, stepped together on worker threads (the interpreter's lock
    released; bdfcar.threads() of them). The cars share one world (built once). Each car's result
    is that of its own single run, whatever the thread count. A car whose episode ends is reset at
    once: its observation is the new episode's, the last one in infos["final_observation"][i]."""

    metadata = {"render_modes": []}

    def __init__(self, num_envs, scenario=None, *, fidelity="planar", settings=(), preview=(0.5, 1.0, 1.5)):
        if num_envs < 1:
            raise ValueError(f"num_envs must be at least 1, got {num_envs}")
        first = Car(scenario or _default_scenario(), fidelity=fidelity, settings=list(settings))
        self.cars = [first] + [first.copy() for _ in range(num_envs - 1)]
        self.num_envs = num_envs
        self._course = _Course(first)
        self._preview = tuple(preview)
        self._start = first.save()
        self.single_observation_space = Box(-np.inf, np.inf, (6 + len(self._preview),))
        self.single_action_space = Box(-1.0, 1.0, (1,))
        self.observation_space = Box(-np.inf, np.inf, (num_envs, 6 + len(self._preview)))
        self.action_space = Box(-1.0, 1.0, (num_envs, 1))
        self._steer = np.zeros(num_envs)
        self._duration = first.duration

    def reset(self, *, seed=None, options=None):
        if seed is not None:
            self.action_space.seed(seed)
        for car in self.cars:
            car.restore(self._start)
        self._steer[:] = 0.0
        return self._observe(), {}

    def _observe(self):
        return _task_observation(observe_many(self.cars), self._course, self._preview)

    def step(self, actions):
        steer = _check_actions(actions, self.num_envs)
        a = np.zeros((self.num_envs, 3))
        a[:, 0] = steer
        failed = tick_many(self.cars, a)
        raw = observe_many(self.cars)
        obs = _task_observation(raw, self._course, self._preview)
        reward = -obs[:, 0] ** 2 - 0.1 * (steer - self._steer) ** 2
        self._steer = steer.copy()
        x, y = raw[:, _O["x_m"]], raw[:, _O["y_m"]]
        left = np.array([not c.course_contains(xi, yi) for c, xi, yi in zip(self.cars, x, y)])
        terminated = failed | left | (x > self._course.end_x)
        reward = np.where(failed | left, -100.0, reward)
        truncated = ~terminated & (raw[:, _O["time_s"]] >= self._duration - 1e-9)
        infos = {}
        done = np.flatnonzero(terminated | truncated)
        if done.size:
            infos["final_observation"] = {int(i): obs[i].copy() for i in done}
            infos["failure"] = {int(i): self.cars[i].failure for i in done if failed[i]}
            for i in done:
                self.cars[i].restore(self._start)
                self._steer[i] = 0.0
            obs[done] = _task_observation(observe_many([self.cars[i] for i in done]), self._course,
                                          self._preview)
        return obs, reward, terminated, truncated, infos

    def close(self):
        pass
