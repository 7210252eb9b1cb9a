"""A sweep from Python: cbbg.load_sweep's one table of every point, arm and seed, and the
disturbance search's front read from it (scripts/disturbance_front.py)."""

import os
import subprocess
import sys

import numpy as np
import pytest

import cbbg

SCRIPTS = os.path.join(os.path.dirname(__file__), os.pardir, os.pardir, "scripts")
CONDITIONS = "[evaluation.noise_std=0, evaluation.noise_std=0.05, evaluation.push_force=74]"


@pytest.fixture(scope="module")
def sweep(tmp_path_factory):
    out = tmp_path_factory.mktemp("sweep") / "search"
    assert cbbg.main(["run", "--experiment", "transfer", "--set", "plant.kind=analytic",
                      "--set", "arms=[cbbg, bg_only]", "--seeds", "3", "--set", "log.decimation=0",
                      "--set", f"transfer.conditions={CONDITIONS}", "--no-figures",
                      "--grid", "training.pitch_spread=0,0.1",
                      "--grid", "normaliser.inputs=pitch,pitch_wheel_rate", "--out", out]) == 0
    return out


def test_a_sweep_loads_as_one_typed_table_of_every_point_arm_and_seed(sweep):
    table = cbbg.load_sweep(sweep)
    assert len(table["point"]) == 4 * 2 * 3  # points x arms x seeds
    assert table["point"].dtype == np.int64 and table["seed"].dtype == np.int64
    assert table["training.pitch_spread"].dtype == np.float64
    assert sorted(set(table["normaliser.inputs"])) == ["pitch", "pitch_wheel_rate"]
    assert table["succeeded"].dtype == bool
    assert list(table["arm"][:6]) == ["cbbg"] * 3 + ["bg_only"] * 3
    # Each point's figures are its own figures.csv's, seed by seed.
    rows = (table["point"] == 3) & (table["arm"] == "bg_only")
    with open(os.path.join(sweep, "points", "003", "figures.csv")) as f:
        lines = [line.strip().split(",") for line in f]
    column = lines[0].index("balanced@evaluation.noise_std=0.05")
    expected = [int(line[column]) for line in lines[1:] if line[0] == "bg_only"]
    assert list(table["balanced@evaluation.noise_std=0.05"][rows]) == expected


def test_what_is_not_a_finished_sweep_is_refused_in_one_line(tmp_path, sweep):
    with pytest.raises(ValueError, match="is not a finished cbbg sweep"):
        cbbg.load_sweep(tmp_path)
    with pytest.raises(ValueError, match="is not a finished cbbg sweep"):
        cbbg.load_sweep(os.path.join(sweep, "points", "001"))
    with pytest.raises(TypeError, match="load_sweep: the directory is a path"):
        cbbg.load_sweep(3)


def test_the_front_keeps_the_points_no_other_beats(sweep):
    done = subprocess.run([sys.executable, os.path.join(SCRIPTS, "disturbance_front.py"),
                           str(sweep)], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    sys.path.insert(0, SCRIPTS)
    import disturbance_front
    points = disturbance_front.points(cbbg.load_sweep(sweep), "cbbg")
    best = disturbance_front.front(points)
    for p in points:
        dominated = any(q["noise"] >= p["noise"] and q["push"] >= p["push"]
                        and q["skill"] <= p["skill"] and q != p
                        and (q["noise"], q["push"], q["skill"]) != (p["noise"], p["push"],
                                                                     p["skill"])
                        for q in points)
        assert (p in best) == (not dominated)
    assert all(f"| {p['point']:03d} " in done.stdout for p in best)
    with open(os.path.join(sweep, "front.png"), "rb") as png:
        assert png.read(8) == b"\x89PNG\r\n\x1a\n"


def test_the_front_never_replaces_a_file_it_did_not_write(tmp_path, sweep):
    import shutil
    copy = tmp_path / "copy"
    shutil.copytree(sweep, copy)
    for name in ("front.md", "front.png", ".cbbg-front"):
        if (copy / name).exists():
            (copy / name).unlink()
    (copy / "front.md").write_text("mine")
    done = subprocess.run([sys.executable, os.path.join(SCRIPTS, "disturbance_front.py"),
                           str(copy)], capture_output=True, text=True, timeout=120)
    assert done.returncode == 2
    assert "front.md exists and is not this script's: move it away first" in done.stderr
    assert (copy / "front.md").read_text() == "mine" and not (copy / "front.png").exists()
