#!/usr/bin/python3
"""Tests of the sweep figures of scripts/plot_results.py on synthetic sweep directories, and
of scripts/robustness_report.py on a synthetic transfer run's figures.csv.

Run them all:  /usr/bin/python3 tests/plot/sweep_reports_test.py
"""

import os
import shutil
import struct
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPTS = os.path.join(HERE, "..", "..", "scripts")
PLOT = os.path.join(SCRIPTS, "plot_results.py")
REPORT = os.path.join(SCRIPTS, "robustness_report.py")
sys.dont_write_bytecode = True  # keep the source tree clean

HEADER = ("point,{key},arm,seeds,succeeded,failures_before_success_median,"
          "failures_before_success_min,failures_before_success_max,evaluated,balanced,"
          "balance_rate\n")


def sweep_csv(key, rows):
    """rows: (value, arm, balanced of 10 evaluated)."""
    text = HEADER.format(key=key)
    for point, (value, arm, balanced) in enumerate(rows, start=1):
        text += f"{point:03},{value},{arm},2,2,1,0,2,10,{balanced},{balanced / 10}\n"
    return text


def png_size(path):
    with open(path, "rb") as file:
        head = file.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
    return struct.unpack(">II", head[16:24])


def run(script, directory):
    return subprocess.run([sys.executable, script, directory], capture_output=True, text=True,
                          timeout=60)


class SweepReports(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory(prefix="cbbg-sweep-report-test-")
        self.root = self._tmp.name

    def tearDown(self):
        self._tmp.cleanup()

    def write_sweep(self, folder, key, rows, balance=True):
        directory = os.path.join(self.root, folder)
        os.makedirs(directory)
        text = sweep_csv(key, rows)
        if not balance:
            text = "\n".join(line.rsplit(",", 3)[0] for line in text.splitlines()) + "\n"
        with open(os.path.join(directory, "sweep.csv"), "w") as file:
            file.write(text)
        with open(os.path.join(directory, "config.yaml"), "w") as file:
            file.write("experiment: exp3\nplant:\n  kind: analytic\nevaluation:\n"
                       "  push_start: 5\n  push_duration: 0.5\n")
        return directory

    def write_transfer(self, columns, rows):
        """DIR/transfer/: figures.csv of `columns` (after arm, seed) and `rows`, config.yaml."""
        directory = os.path.join(self.root, "transfer")
        os.makedirs(directory)
        with open(os.path.join(directory, "figures.csv"), "w") as file:
            file.write(",".join(["arm", "seed"] + columns) + "\n")
            file.writelines(",".join(str(field) for field in row) + "\n" for row in rows)
        with open(os.path.join(directory, "config.yaml"), "w") as file:
            file.write("experiment: transfer\nseeds: 2\nplant:\n  kind: analytic\n"
                       "evaluation:\n  push_start: 5\n  push_duration: 0.5\n"
                       "transfer:\n  training: exp3\n")
        return directory

    def study(self):
        """Two seeds of cbbg and pd_only under two masses, two pushes from outside and one
        through the motors, 5 angles each."""
        os.makedirs(self.root, exist_ok=True)
        open(os.path.join(self.root, ".cbbg-robustness-study"), "w").close()
        conditions = ["evaluation.body_mass_scale=0.7", "evaluation.body_mass_scale=1.3",
                      "evaluation.push_force=0", "evaluation.push_force=74",
                      "evaluation.push_torque=5"]
        columns = [f"{what}@{condition}" for condition in conditions
                   for what in ("balanced", "evaluated")]
        balanced = {("cbbg", 1): [5, 2, 5, 0, 1], ("cbbg", 2): [4, 2, 4, 0, 0],
                    ("pd_only", 1): [5, 5, 5, 4, 5], ("pd_only", 2): [5, 5, 5, 3, 5]}
        rows = [[arm, seed] + [field for b in counts for field in (b, 5)]
                for (arm, seed), counts in balanced.items()]
        return self.write_transfer(columns, rows)

    def test_a_sweep_with_balance_rates_gets_the_evaluation_panel(self):
        with_rates = self.write_sweep("rates", "evaluation.noise_std",
                                      [(0, "cbbg", 9), (0.05, "cbbg", 2)])
        without = self.write_sweep("plain", "actor.alpha", [(0.1, "cbbg", 0), (0.2, "cbbg", 0)],
                                   balance=False)
        for directory, width in ((with_rates, 1200), (without, 800)):
            result = run(PLOT, directory)
            self.assertEqual(result.returncode, 0, result.stderr)
            figure = os.path.join(directory, "figures",
                                  "sweep_" + ("evaluation.noise_std" if directory == with_rates
                                              else "actor.alpha") + ".png")
            self.assertEqual(png_size(figure), (width, 450))

    def test_a_malformed_balance_rate_names_the_file_and_line(self):
        directory = self.write_sweep("bad", "evaluation.noise_std", [(0, "cbbg", 9)])
        path = os.path.join(directory, "sweep.csv")
        with open(path) as file:
            text = file.read().replace(",0.9\n", ",lots\n")
        with open(path, "w") as file:
            file.write(text)
        result = run(PLOT, directory)
        self.assertEqual(result.returncode, 2, result.stderr)
        self.assertIn(path, result.stderr)
        self.assertIn("balance_rate", result.stderr)
        self.assertNotIn("Traceback", result.stderr)

    def test_the_table_counts_each_arm_at_each_value(self):
        self.study()
        result = run(REPORT, self.root)
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(os.path.join(self.root, "robustness.md")) as file:
            table = file.read()
        self.assertEqual(result.stdout, table)
        self.assertEqual(table.splitlines(), [
            "| perturbation | value | cbbg | pd_only |",
            "|---|---|---|---|",
            "| body mass and inertias x | 0.7 | 9/10 | 10/10 |",
            "| body mass and inertias x | 1.3 | 4/10 | 10/10 |",
            "| push at the centre of mass, from outside (N, 0.5 s from 5 s) | 0 | 9/10 | 10/10 |",
            "| push at the centre of mass, from outside (N, 0.5 s from 5 s) | 74 | 0/10 | 7/10 |",
            "| push through the motors, on each wheel (N m, 0.5 s from 5 s) | 5 | 1/10 | 10/10 |",
        ])
        width, height = png_size(os.path.join(self.root, "robustness.png"))
        self.assertEqual((width, height), (1040, 720))  # three panels, two rows
        leftovers = [n for n in os.listdir(self.root) if n.startswith(".robustness")]
        self.assertEqual(leftovers, [])

    def test_a_missing_or_malformed_figures_csv_is_refused_naming_it(self):
        result = run(REPORT, self.root)
        self.assertEqual(result.returncode, 2)
        self.assertIn("transfer/figures.csv: missing", result.stderr)
        directory = self.write_transfer(["trials"], [["cbbg", 1, 3]])
        result = run(REPORT, self.root)
        self.assertEqual(result.returncode, 2)
        self.assertIn("figures.csv: has no balanced@ column", result.stderr)
        shutil.rmtree(directory)
        self.write_transfer(["balanced@evaluation.noise_std=0"], [["cbbg", 1, 3]])
        result = run(REPORT, self.root)
        self.assertEqual(result.returncode, 2)
        self.assertIn("has no evaluated@evaluation.noise_std=0 column", result.stderr)

    def test_a_malformed_count_names_the_file_and_line(self):
        self.write_transfer(["balanced@evaluation.noise_std=0", "evaluated@evaluation.noise_std=0"],
                            [["cbbg", 1, 3, 5], ["cbbg", 2, "lots", 5]])
        result = run(REPORT, self.root)
        self.assertEqual(result.returncode, 2)
        self.assertIn("figures.csv: line 3: balanced@evaluation.noise_std=0 'lots' is not a "
                      "number", result.stderr)
        self.assertNotIn("Traceback", result.stderr)

    def test_outputs_it_did_not_make_are_kept(self):
        self.write_transfer(["balanced@evaluation.noise_std=0", "evaluated@evaluation.noise_std=0"],
                            [["cbbg", 1, 3, 5]])
        mine = os.path.join(self.root, "robustness.md")
        with open(mine, "w") as file:
            file.write("my notes\n")
        result = run(REPORT, self.root)
        self.assertEqual(result.returncode, 2)
        self.assertIn("robustness.md exists and this is not a study of robustness_study.sh",
                      result.stderr)
        with open(mine) as file:
            self.assertEqual(file.read(), "my notes\n")


if __name__ == "__main__":
    unittest.main()
