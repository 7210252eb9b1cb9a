#!/usr/bin/python3
"""Every built-in protocol and a user's (examples/cartpole's curriculum), each read by its
results' schema alone: written, read back against schema.json, killed and resumed to the same
bytes, run as two shards of a sweep and merged to the same bytes (but evaluate, whose weights a
sweep does not take), plotted as the schema
names, and loaded from Python with the schema's types.

Usage: /usr/bin/python3 tests/apps/schema_table_test.py BUILD_DIR [unittest arguments]
"""

import csv
import filecmp
import json
import os
import subprocess
import sys
import tempfile
import unittest

BUILD = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else "build"
CBBG = os.path.join(BUILD, "apps", "cbbg")
CARTPOLE = os.path.join(BUILD, "examples", "cartpole")
sys.path.insert(0, os.path.join(BUILD, "python"))
sys.dont_write_bytecode = True

import cbbg  # noqa: E402  (the build's module, found through the path above)

QUICK = ["--set", "plant.kind=analytic", "--set", "seeds=2", "--set", "max_trials=4",
         "--set", "evaluation.angles=[0.1, 0.2]", "--set", "log.decimation=50"]
# Per protocol: the program that knows it and its own settings (evaluate's weights: below).
PROTOCOLS = {
    "exp1": (CBBG, []),
    "exp2": (CBBG, ["--set", "exp2.trials=4"]),
    "exp3": (CBBG, []),
    "evaluate": (CBBG, ["--set", "arms=[bg_only, pd_only]"]),
    "transfer": (CBBG, ["--set", "transfer.conditions=[evaluation.noise_std=0.05]"]),
    "curriculum": (CARTPOLE, []),
}
CORE_TRIAL_COLUMNS = ["arm", "seed", "trial", "failed", "steps", "mean_temperature",
                      "mean_entropy", "final_theta", "status"]
RESULT_FILES = ["schema.json", "summary.json", "trials.csv", "evaluation.csv", "figures.csv",
                "steps.csv", "config.yaml"]


def run(program, *args, env=None):
    done = subprocess.run([program, "--log-level", "warn", *args], capture_output=True,
                          text=True, env={**os.environ, **(env or {})})
    return done


def header(path):
    with open(path, newline="") as f:
        return next(csv.reader(f))


class SchemaTable(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.root = tempfile.mkdtemp(prefix="cbbg-schema-table-")
        cls.weights = os.path.join(cls.root, "bg_only.txt")
        done = run(CBBG, "run", *QUICK, "--experiment", "bg_only", "--set", "seeds=1",
                   "--no-figures", "--save-weights", cls.weights,
                   "--out", os.path.join(cls.root, "trained"))
        assert done.returncode == 0, done.stderr

    @classmethod
    def tearDownClass(cls):
        subprocess.run(["rm", "-rf", cls.root], check=True)

    def command(self, protocol):
        program, own = PROTOCOLS[protocol]
        args = [*QUICK, "--experiment", protocol, *own]
        if protocol == "evaluate":
            args += ["--load-weights", self.weights]
        return program, args

    def whole(self, protocol):
        out = os.path.join(self.root, protocol, "whole")
        if not os.path.isdir(out):
            program, args = self.command(protocol)
            done = run(program, "run", *args, "--no-figures", "--out", out)
            self.assertEqual(done.returncode, 0, done.stderr)
        return out

    def assert_same_results(self, expected, actual, but=()):
        for name in (n for n in RESULT_FILES if n not in but):
            there = os.path.exists(os.path.join(expected, name))
            self.assertEqual(os.path.exists(os.path.join(actual, name)), there, name)
            if there:
                self.assertTrue(filecmp.cmp(os.path.join(expected, name),
                                            os.path.join(actual, name), shallow=False),
                                f"{actual}/{name} differs from {expected}/{name}")

    def check_written_by_the_schema(self, protocol):
        out = self.whole(protocol)
        with open(os.path.join(out, "schema.json")) as f:
            schema = json.load(f)
        self.assertEqual(schema["experiment"], protocol)
        own_columns = [c["name"] for c in schema["trial_columns"]]
        self.assertEqual(header(os.path.join(out, "trials.csv")),
                         CORE_TRIAL_COLUMNS + own_columns)
        self.assertEqual(os.path.exists(os.path.join(out, "evaluation.csv")),
                         schema["evaluates"])
        own_figures = [f for f in schema["figures"]
                       if f["name"] not in ("failures_before_success", "succeeded")]
        if own_figures:
            self.assertEqual(header(os.path.join(out, "figures.csv")),
                             ["arm", "seed"] + [f["name"] for f in own_figures])
        else:
            self.assertFalse(os.path.exists(os.path.join(out, "figures.csv")))
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        for arm in summary["arms"].values():
            for figure in schema["figures"]:
                if figure["summary"] == "list":
                    self.assertEqual(len(arm[figure["name"]]), len(summary["seeds"]))
                    for key in figure["statistics"].values():
                        self.assertIn(key, arm)
                elif figure["summary"] == "sum":
                    self.assertIn(figure["name"], arm["figures"])
                else:
                    self.assertNotIn(figure["name"], arm)
                    self.assertNotIn(figure["name"], arm.get("figures", {}))
        paired = [p["figure"] for p in summary.get("paired", [])]
        declared = (["failures_before_success"] if schema["pairs_failures"] else []) + [
            f["name"] for f in own_figures if f["paired"]]
        if len(summary["arms"]) > 1:
            self.assertEqual(paired[:len(declared)], declared)
        return schema

    def check_killed_and_resumed(self, protocol):
        program, args = self.command(protocol)
        out = os.path.join(self.root, protocol, "killed")
        killed = run(program, "run", *args, "--no-figures", "--jobs", "1", "--out", out,
                     env={"CBBG_FAULT_AT": "task:record@2"})
        self.assertEqual(killed.returncode, 86, killed.stderr)
        resumed = run(program, "run", "--resume", out)
        self.assertEqual(resumed.returncode, 0, resumed.stderr)
        self.assert_same_results(self.whole(protocol), out)

    def check_sharded_and_merged(self, protocol):
        program, args = self.command(protocol)
        out = os.path.join(self.root, protocol, "sweep")
        for shard in ("1/2", "2/2"):
            done = run(program, "run", *args, "--no-figures", "--grid", "seed=1",
                       "--shard", shard, "--out", out)
            self.assertEqual(done.returncode, 0, done.stderr)
        merged = run(program, "merge", out)
        self.assertEqual(merged.returncode, 0, merged.stderr)
        point = os.path.join(out, "points", "001")
        self.assert_same_results(self.whole(protocol), point, but=["config.yaml"])
        with open(os.path.join(out, "sweep.csv")) as f:
            names = next(csv.reader(f))
        with open(os.path.join(point, "schema.json")) as f:
            headline = json.load(f)["headline"]
        self.assertIn(headline + "_median", names)

    def check_plotted_as_named(self, protocol, schema):
        out = os.path.join(self.root, protocol, "plotted")
        subprocess.run(["cp", "-r", self.whole(protocol), out], check=True)
        program = PROTOCOLS[protocol][0]
        done = run(program, "plot", out)
        self.assertEqual(done.returncode, 0, done.stderr)
        drawn = set(os.listdir(os.path.join(out, "figures")))
        expected = {"failures": "failures.png", "skill": "skill.png",
                    "annealing": "temperature_entropy.png", "evaluation": "evaluation.png",
                    "figures": "figures.png"}
        for drawing, file in expected.items():
            self.assertEqual(file in drawn, drawing in schema["plots"], file)
        self.assertEqual(any(f.startswith("pitch_") and f != "pitch_early_late.png"
                             for f in drawn), "pitch" in schema["plots"])

    def check_loaded_typed(self, protocol, schema):
        results = cbbg.load_results(self.whole(protocol))
        self.assertEqual(results.schema, schema)
        kinds = {"integer": "i", "flag": "b", "number": "f"}
        for column in schema["trial_columns"]:
            values = results.trials[column["name"]]
            self.assertIn(values.dtype.kind, (kinds[column["type"]], "f"), column["name"])
        self.assertEqual(results.trials["seed"].dtype.kind, "i")
        for figure in schema["figures"]:
            if "figures" in results.tables and figure["name"] in results.figures:
                values = results.figures[figure["name"]]
                self.assertIn(values.dtype.kind, (kinds[figure["type"]], "f"), figure["name"])
        ticks = results.steps(seed=1)  # a protocol that runs no trials logs no ticks
        self.assertEqual(len(ticks["t"]) > 0, len(results.trials["trial"]) > 0)

    def check(self, protocol):
        schema = self.check_written_by_the_schema(protocol)
        self.check_killed_and_resumed(protocol)
        if protocol != "evaluate":  # a sweep starts from zero: it takes no --load-weights
            self.check_sharded_and_merged(protocol)
        self.check_plotted_as_named(protocol, schema)
        self.check_loaded_typed(protocol, schema)

    def test_exp1(self):
        self.check("exp1")

    def test_exp2(self):
        self.check("exp2")

    def test_exp3(self):
        self.check("exp3")

    def test_evaluate(self):
        self.check("evaluate")

    def test_transfer(self):
        self.check("transfer")

    def test_a_users_protocol(self):
        self.check("curriculum")


if __name__ == "__main__":
    unittest.main()
