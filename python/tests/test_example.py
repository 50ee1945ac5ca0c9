"""The example script of docs/API.md runs and both drivers pass the course."""
import os
import subprocess
import sys


def test_the_lane_change_example_runs(root, tmp_path):
    script = os.path.join(root, "python", "examples", "lane_change.py")
    r = subprocess.run([sys.executable, script, str(tmp_path)], capture_output=True, text=True,
                       env=dict(os.environ, MPLBACKEND="Agg"))
    assert r.returncode == 0, r.stdout + r.stderr
    assert "path follower:" in r.stdout and "course passed" in r.stdout
    assert "preview controller: passed" in r.stdout
