"""The thread pool: any thread count gives the same cars, one car twice is refused."""
import numpy as np
import pytest

import bdfcar
from conftest import scenario


def test_thread_count_does_not_change_the_cars(root):
    first = bdfcar.Car(scenario(root, "lane_change.toml"), fidelity="planar")
    results = []
    for threads in (1, 2, 3):
        bdfcar.set_threads(threads)
        assert bdfcar.threads() == threads
        cars = [first.copy() for _ in range(5)]
        actions = np.zeros((5, 3))
        actions[:, 0] = np.linspace(-0.4, 0.4, 5)
        for _ in range(40):
            bdfcar.tick_many(cars, actions)
        results.append(bdfcar.observe_many(cars).tobytes())
    assert results[0] == results[1] == results[2]
    with pytest.raises(ValueError, match="twice"):
        bdfcar.tick_many([cars[0], cars[0]], None)
    with pytest.raises(ValueError, match="1 or more"):
        bdfcar.set_threads(0)
