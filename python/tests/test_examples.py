"""The examples a user starts from run as docs/python.md shows them."""

import os
import subprocess
import sys

EXAMPLES = os.path.join(os.path.dirname(__file__), os.pardir, "examples")


def run_example(name, *args, cwd):
    return subprocess.run([sys.executable, os.path.join(EXAMPLES, name), *args], cwd=cwd,
                          capture_output=True, text=True, timeout=300)


def test_the_python_supervisor_example_runs_exp1_and_plots(tmp_path):
    done = run_example("python_supervisor.py", "--plant", "analytic", "--out", "f.png",
                       cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert "cbbg_lean  failures before the first success, seeds [1, 2, 3, 4, 5]" in done.stdout
    with open(tmp_path / "f.png", "rb") as png:
        assert png.read(8) == b"\x89PNG\r\n\x1a\n"


def test_the_example_leaves_a_users_file_alone(tmp_path):
    (tmp_path / "f.png").write_text("mine")
    done = run_example("python_supervisor.py", "--plant", "analytic", "--out", "f.png",
                       cwd=tmp_path)
    assert done.returncode == 2
    assert "'f.png' exists; give another --out (it is not replaced)" in done.stderr
    assert (tmp_path / "f.png").read_text() == "mine"
