import os
import sys

import pytest

ROOT = os.environ.get("BDFCAR_ROOT", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))
if "PYTHONPATH" not in os.environ:  # run by hand: the default build folder's package
    sys.path.insert(0, os.path.join(ROOT, "build", "python"))


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture(scope="session")
def cli(root):
    return os.environ.get("BDFCAR_CLI", os.path.join(root, "build", "app", "bdfcar"))


def scenario(root, name):
    return os.path.join(root, "assets", "scenarios", name)
