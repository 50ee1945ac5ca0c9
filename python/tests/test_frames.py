"""Headless frames as NumPy arrays (OSMesa): the picture is the car's, drawn again the same, and
follows the car; bad arguments are refused."""
import numpy as np
import pytest

import bdfcar
from conftest import scenario


@pytest.fixture(scope="module")
def car_and_camera(root):
    car = bdfcar.Car(scenario(root, "iso_lane_change.toml"), fidelity="planar")
    return car, bdfcar.Camera(car, 320, 180)


def red_columns(frame):
    """Mean column of the car body's red pixels (the chase camera looks at the car)."""
    r, g, b = (frame[..., i].astype(int) for i in range(3))
    ys, xs = np.nonzero((r > 150) & (g < 80) & (b < 80))
    return xs.mean(), xs.size


def test_a_frame_of_the_car(car_and_camera):
    car, cam = car_and_camera
    car.reset()
    f = cam.render()
    assert f.shape == (180, 320, 3) and f.dtype == np.uint8
    assert "llvmpipe" in cam.renderer or cam.renderer
    # The chase camera sits behind the car: the red body is in the middle of the picture.
    x, n = red_columns(f)
    assert n > 200
    assert abs(x - 160) < 20
    # The same state draws the same picture.
    assert np.array_equal(cam.render(), f)


def test_the_picture_follows_the_car(car_and_camera, root):
    car, _ = car_and_camera
    car.reset()
    top = bdfcar.Camera(car, 320, 180, camera="top-down")
    before = top.render()
    car.tick(steer=0.0, ticks=100)  # 1 s at 60 km/h: the road moves under the car
    after = top.render()
    assert not np.array_equal(before, after)


def test_bad_arguments(car_and_camera):
    car, _ = car_and_camera
    with pytest.raises(ValueError, match="camera: expected chase"):
        bdfcar.Camera(car, 320, 180, camera="drone")
    with pytest.raises(ValueError, match="frame size"):
        bdfcar.Camera(car, 0, 180)
