"""The lane-change environments: Gymnasium's conventions, a simple controller that passes the
course, and the vector environment giving each car its single environment's result."""
import numpy as np
import pytest

import bdfcar


def preview_controller(obs):
    """Steer toward the reference line 1 s ahead, damped by the heading and lateral errors."""
    return np.clip(0.03 * obs[..., 7] - 4.0 * obs[..., 1] - 0.05 * obs[..., 0], -1.0, 1.0)


@pytest.fixture(scope="module")
def env():
    return bdfcar.LaneChangeEnv()


def test_the_conventions(env):
    obs, info = env.reset(seed=3)
    assert obs.shape == env.observation_space.shape == (9,)
    assert env.action_space.shape == (1,)
    a = env.action_space.sample()
    assert env.action_space.contains(a)
    out = env.step(a)
    assert len(out) == 5
    obs2, reward, terminated, truncated, info = out
    assert obs2.shape == (9,) and isinstance(reward, float)
    assert isinstance(terminated, bool) and isinstance(truncated, bool)
    with pytest.raises(ValueError, match="expected 1 steering action"):
        env.step(np.zeros(2))
    with pytest.raises(ValueError, match="finite"):
        env.step(np.array([np.nan]))


def test_a_preview_controller_passes_the_course(env):
    obs, _ = env.reset()
    total, info = 0.0, {}
    for _ in range(2000):
        obs, reward, terminated, truncated, info = env.step(preview_controller(obs)[None])
        total += reward
        if terminated or truncated:
            break
    assert info.get("passed"), info
    # Holding the wheel straight leaves the course instead (the task can be failed).
    obs, _ = env.reset()
    for _ in range(2000):
        obs, reward, terminated, truncated, info = env.step([0.0])
        if terminated or truncated:
            break
    assert info.get("left_course"), info
    assert reward == -100.0


def test_the_vector_env_gives_each_car_its_single_run(env):
    n = 4
    venv = bdfcar.VectorLaneChangeEnv(n)
    obs, _ = venv.reset(seed=1)
    assert obs.shape == (n, 9)
    gains = np.array([0.5, 0.8, 1.0, 1.2])
    history = []
    for _ in range(150):
        obs, reward, terminated, truncated, infos = venv.step((gains * preview_controller(obs))[:, None])
        history.append(obs.copy())
        assert not terminated.any()
    for i in range(n):
        single, _ = env.reset()
        for k in range(150):
            single, *_ = env.step([gains[i] * preview_controller(single)])
            assert single.tobytes() == history[k][i].tobytes(), (i, k)
