#!/usr/bin/python3
"""Tests of scripts/plot_results.py on synthetic results directories (make_fixtures.py).

Run one case:  /usr/bin/python3 tests/plot/plot_results_test.py PlotResults.test_<case>
Run them all:  /usr/bin/python3 tests/plot/plot_results_test.py
"""

import importlib.util
import json
import os
import struct
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "..", "..", "scripts", "plot_results.py")
sys.dont_write_bytecode = True  # keep the source tree clean
sys.path.insert(0, HERE)

import make_fixtures  # noqa: E402  (found through the path above)

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
WIDTH, HEIGHT = 800, 450  # 8 x 4.5 in at 100 dpi
MIN_BYTES = 15_000  # an empty 800x450 canvas with axes is well below this


def load_script():
    spec = importlib.util.spec_from_file_location("plot_results", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


plot_results = load_script()


def run_script(results_dir):
    return subprocess.run([sys.executable, SCRIPT, results_dir], capture_output=True,
                          text=True, timeout=60)


def trial(arm, seed, number, status):
    return plot_results.Trial(arm=arm, seed=seed, trial=number, failed=status != "success",
                              steps=100, mean_temperature=1.0, mean_entropy=0.5,
                              final_theta=0.0, status=status)


class PlotResults(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory(prefix="cbbg-plot-test-")
        self.root = self._tmp.name

    def tearDown(self):
        self._tmp.cleanup()

    def assert_png(self, path):
        self.assertTrue(os.path.isfile(path), f"{path} was not written")
        with open(path, "rb") as f:
            head = f.read(24)
        self.assertEqual(head[:8], PNG_SIGNATURE, f"{path} is not a PNG")
        self.assertEqual(head[12:16], b"IHDR", f"{path} has no IHDR chunk first")
        width, height = struct.unpack(">II", head[16:24])
        self.assertEqual((width, height), (WIDTH, HEIGHT), path)
        self.assertGreater(os.path.getsize(path), MIN_BYTES, f"{path} looks empty")

    def assert_figures(self, results_dir, names, stdout, users=()):
        """DIR/figures holds `names` (listed in its manifest as cbbg's) and the user's files."""
        figures = os.path.join(results_dir, "figures")
        self.assertEqual(sorted(os.listdir(figures)),
                         sorted(list(names) + list(users) + [".cbbg-written"]))
        with open(os.path.join(figures, ".cbbg-written"), encoding="utf-8") as f:
            listed = f.read().splitlines()
        self.assertEqual(listed[0], "cbbg-written 1")
        self.assertEqual(sorted(listed[1:]), sorted(names))
        for name in names:
            self.assert_png(os.path.join(figures, name))
        wrote = [line for line in stdout.splitlines() if line.startswith("wrote ")]
        self.assertEqual(sorted(wrote),
                         sorted(f"wrote {os.path.join(figures, name)}" for name in names))
        leftovers = [n for n in os.listdir(results_dir) if ".cbbg-tmp-" in n]
        self.assertEqual(leftovers, [], "staging folders left behind")

    def assert_input_error(self, result, file_name, what):
        self.assertEqual(result.returncode, 2, result.stderr)
        self.assertNotIn("Traceback", result.stderr)
        lines = result.stderr.strip().splitlines()
        self.assertEqual(len(lines), 1, result.stderr)
        self.assertIn(file_name, lines[0])
        self.assertIn(what, lines[0])

    # ------------------------------------------------------------ whole runs

    def test_a_temporary_is_stale_once_its_writer_is_gone_or_its_pid_taken(self):
        start = plot_results.process_start(os.getpid())
        self.assertFalse(plot_results.writer_gone(f"{os.getpid()}.{start}"))
        self.assertTrue(plot_results.writer_gone(f"{os.getpid()}.{int(start) + 1}"))
        self.assertTrue(plot_results.writer_gone("999999999.5"))
        self.assertIn(f"-{os.getpid()}.{start}-0",
                      plot_results.temporary_name("/x", "failures.png"))

    def test_a_full_disk_names_the_path_and_the_reason_on_one_line(self):
        import contextlib
        import io
        original = plot_results.run
        def full(_directory):
            raise OSError(28, "No space left on device")  # as savefig raises it: no filename
        plot_results.run = full
        stderr = io.StringIO()
        try:
            with contextlib.redirect_stderr(stderr):
                status = plot_results.main(["plot_results.py", "/data/results"])
        finally:
            plot_results.run = original
        self.assertEqual(status, 1)
        self.assertEqual(stderr.getvalue(), "plot_results.py: error: cannot write "
                         "'/data/results/figures': No space left on device\n")

    def test_exp1_writes_every_figure(self):
        results = os.path.join(self.root, "exp1")
        make_fixtures.make_exp1(results)
        result = run_script(results)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assert_figures(results, ["pitch_cbbg.png", "pitch_bg_only.png", "failures.png"],
                            result.stdout)

    def test_exp2_writes_every_figure(self):
        results = os.path.join(self.root, "exp2")
        make_fixtures.make_exp2(results)
        result = run_script(results)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assert_figures(results, ["temperature_entropy.png", "pitch_early_late.png",
                                      "oscillation.png"], result.stdout)

    def test_the_schema_names_the_drawings_whatever_the_protocols_name(self):
        results = os.path.join(self.root, "mine")
        make_fixtures.make_exp1(results)
        with open(os.path.join(results, "schema.json"), "w") as f:
            json.dump({"format": "cbbg-schema 1", "plots": ["failures"]}, f)
        result = run_script(results)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assert_figures(results, ["failures.png"], result.stdout)
        self.assertFalse(os.path.exists(os.path.join(results, "figures", "pitch_cbbg.png")))

    def test_a_schema_naming_an_unknown_drawing_exits_2_naming_it(self):
        results = os.path.join(self.root, "mine")
        make_fixtures.make_exp1(results)
        with open(os.path.join(results, "schema.json"), "w") as f:
            json.dump({"format": "cbbg-schema 1", "plots": ["failures", "radar"]}, f)
        result = run_script(results)
        self.assertEqual(result.returncode, 2)
        self.assertEqual(result.stderr, "plot_results.py: error: "
                         f"{os.path.join(results, 'schema.json')}: names no drawing 'radar' "
                         "(pitch, failures, skill, annealing, evaluation, figures)\n")

    def test_single_seed_exp2_draws_without_spread(self):
        results = os.path.join(self.root, "exp2")
        make_fixtures.make_exp2(results, seeds=(4,))
        result = run_script(results)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assert_figures(results, ["temperature_entropy.png", "pitch_early_late.png",
                                      "oscillation.png"], result.stdout)

    def test_without_step_log_skips_pitch_figures_with_a_note(self):
        results = os.path.join(self.root, "exp1")
        make_fixtures.make_exp1(results, with_steps=False)
        result = run_script(results)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assert_figures(results, ["failures.png"], result.stdout)
        self.assertIn("steps.csv absent", result.stdout)

    def test_rerun_replaces_its_own_figures_and_keeps_the_users(self):
        results = os.path.join(self.root, "exp1")
        make_fixtures.make_exp1(results)
        mine = os.path.join(results, "figures", "my_plot.png")
        os.makedirs(os.path.dirname(mine))
        with open(mine, "wb") as f:
            f.write(b"mine")
        names = ["pitch_cbbg.png", "pitch_bg_only.png", "failures.png"]
        for _ in range(2):
            result = run_script(results)
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assert_figures(results, names, result.stdout, users=["my_plot.png"])
        with open(mine, "rb") as f:
            self.assertEqual(f.read(), b"mine")

    def test_a_figures_name_taken_by_a_users_file_exits_2_and_moves_nothing(self):
        results = os.path.join(self.root, "exp1")
        make_fixtures.make_exp1(results)
        taken = os.path.join(results, "figures", "failures.png")
        os.makedirs(os.path.dirname(taken))
        with open(taken, "wb") as f:
            f.write(b"mine")
        result = run_script(results)
        self.assertEqual(result.returncode, 2, result.stderr)
        self.assertIn(f"{taken}: exists and cbbg did not write it", result.stderr)
        self.assertEqual(os.listdir(os.path.dirname(taken)), ["failures.png"])
        with open(taken, "rb") as f:
            self.assertEqual(f.read(), b"mine")
        self.assertEqual([n for n in os.listdir(results) if ".cbbg-tmp-" in n], [])

    # ------------------------------------------------------------ bad input

    def test_malformed_trials_csv_exits_2_and_keeps_old_figures(self):
        results = os.path.join(self.root, "exp1")
        make_fixtures.make_exp1(results)
        self.assertEqual(run_script(results).returncode, 0)
        before = sorted(os.listdir(os.path.join(results, "figures")))
        trials_csv = os.path.join(results, "trials.csv")
        with open(trials_csv, encoding="utf-8") as f:
            lines = f.read().splitlines()
        lines[3] = lines[3].replace(",", ",x", 1)  # arm,xseed,...: seed is not a number
        with open(trials_csv, "w", encoding="utf-8") as f:
            f.write("\n".join(lines) + "\n")
        result = run_script(results)
        self.assert_input_error(result, trials_csv, "line 4: seed 'x")
        self.assertEqual(sorted(os.listdir(os.path.join(results, "figures"))), before)
        self.assertEqual([n for n in os.listdir(results) if ".cbbg-tmp-" in n], [])

    def test_trials_csv_with_a_short_row_exits_2(self):
        results = os.path.join(self.root, "exp1")
        make_fixtures.make_exp1(results)
        trials_csv = os.path.join(results, "trials.csv")
        with open(trials_csv, "a", encoding="utf-8") as f:
            f.write("cbbg,1,2,0\n")
        result = run_script(results)
        self.assert_input_error(result, trials_csv, "expected 9 fields, got 4")
        self.assertFalse(os.path.exists(os.path.join(results, "figures")))

    def test_trials_csv_without_a_column_exits_2(self):
        results = os.path.join(self.root, "exp2")
        make_fixtures.make_exp2(results)
        trials_csv = os.path.join(results, "trials.csv")
        with open(trials_csv, encoding="utf-8") as f:
            text = f.read()
        with open(trials_csv, "w", encoding="utf-8") as f:
            f.write(text.replace("mean_entropy", "entropy", 1))
        result = run_script(results)
        self.assert_input_error(result, trials_csv, "header lacks column(s) mean_entropy")

    def test_missing_summary_json_exits_2(self):
        results = os.path.join(self.root, "exp1")
        make_fixtures.make_exp1(results)
        summary = os.path.join(results, "summary.json")
        os.remove(summary)
        result = run_script(results)
        self.assert_input_error(result, summary, "missing")
        self.assertFalse(os.path.exists(os.path.join(results, "figures")))

    def test_truncated_summary_json_exits_2(self):
        results = os.path.join(self.root, "exp1")
        make_fixtures.make_exp1(results)
        summary = os.path.join(results, "summary.json")
        with open(summary, encoding="utf-8") as f:
            text = f.read()
        with open(summary, "w", encoding="utf-8") as f:
            f.write(text[: len(text) // 2])
        result = run_script(results)
        self.assert_input_error(result, summary, "not valid JSON")

    def test_summary_json_with_wrong_failure_count_exits_2(self):
        results = os.path.join(self.root, "exp1")
        make_fixtures.make_exp1(results)
        summary = os.path.join(results, "summary.json")
        with open(summary, encoding="utf-8") as f:
            text = f.read()
        with open(summary, "w", encoding="utf-8") as f:
            f.write(text.replace('"seeds": [\n    1,', '"seeds": [', 1))
        result = run_script(results)
        self.assert_input_error(result, summary, '"failures_before_success" has 3 entries but '
                                                 '"seeds" has 2')

    def test_malformed_steps_csv_row_exits_2(self):
        results = os.path.join(self.root, "exp1")
        make_fixtures.make_exp1(results)
        steps_csv = os.path.join(results, "steps.csv")
        with open(steps_csv, encoding="utf-8") as f:
            lines = f.read().splitlines()
        fields = lines[1].split(",")  # the first logged tick of cbbg seed 1 trial 1
        fields[4] = "abc"
        lines[1] = ",".join(fields)
        with open(steps_csv, "w", encoding="utf-8") as f:
            f.write("\n".join(lines) + "\n")
        result = run_script(results)
        self.assert_input_error(result, steps_csv, "line 2: t '0.00' or theta_b 'abc'")

    def test_wrong_argument_count_prints_usage_and_exits_2(self):
        result = subprocess.run([sys.executable, SCRIPT], capture_output=True, text=True,
                                timeout=60)
        self.assertEqual(result.returncode, 2)
        self.assertIn("usage:", result.stderr)

    # ------------------------------------------------------ what gets drawn

    def test_exp1_pitch_shows_first_trial_failures_between_and_first_success(self):
        seed_trials = [trial("bg_only", 1, n, "failed") for n in range(1, 9)]
        seed_trials += [trial("bg_only", 1, 9, "success"), trial("bg_only", 1, 10, "success")]
        selection = plot_results.exp1_pitch_selection(seed_trials)
        self.assertEqual(selection.first.trial, 1)
        self.assertEqual([t.trial for t in selection.between], list(range(2, 9)))
        self.assertEqual(selection.last.trial, 9)
        self.assertTrue(selection.succeeded)

    def test_exp1_pitch_of_a_seed_that_never_succeeded_ends_with_its_last_trial(self):
        seed_trials = [trial("bg_only", 2, n, "failed") for n in range(1, 4)]
        seed_trials.append(trial("bg_only", 2, 4, "diverged"))
        selection = plot_results.exp1_pitch_selection(seed_trials)
        self.assertEqual((selection.first.trial, selection.last.trial), (1, 4))
        self.assertFalse(selection.succeeded)

    def test_exp1_pitch_of_a_first_trial_success_is_one_curve(self):
        selection = plot_results.exp1_pitch_selection([trial("cbbg", 1, 1, "success")])
        self.assertIs(selection.first, selection.last)
        self.assertEqual(selection.between, [])

    def test_exp2_early_trials_follow_the_coordinated_one_and_late_are_the_last_two(self):
        self.assertEqual(plot_results.early_late_trials(range(1, 26)), ([2, 3], [24, 25]))
        self.assertEqual(plot_results.early_late_trials([1, 2, 3]), ([2, 3], []))
        self.assertEqual(plot_results.early_late_trials([1]), ([1], []))

    def test_failures_are_counted_from_trials_when_summary_lacks_them(self):
        trials = [trial("bg_only", 1, 1, "failed"), trial("bg_only", 1, 2, "failed"),
                  trial("bg_only", 1, 3, "success"), trial("bg_only", 2, 1, "failed"),
                  trial("bg_only", 2, 2, "failed")]
        counted = plot_results.failures_per_seed({"arms": {"bg_only": {}}}, trials, "bg_only")
        self.assertEqual([(s.seed, s.failures, s.succeeded) for s in counted],
                         [(1, 2, True), (2, 2, False)])
        self.assertEqual(plot_results.median_failures({}, "bg_only", counted), 2.0)

    def test_step_log_keeps_only_the_wanted_trial_in_order(self):
        results = os.path.join(self.root, "exp1")
        make_fixtures.make_exp1(results)
        expected = make_fixtures.pitch_curve(-0.25, 0.8 + 0.05 * 3, True)  # cbbg seed 3
        pitch = plot_results.read_pitch(os.path.join(results, "steps.csv"),
                                        {("cbbg", 3, 1), ("cbbg", 3, 99)})
        self.assertEqual(set(pitch), {("cbbg", 3, 1)})
        t, theta = pitch[("cbbg", 3, 1)]
        self.assertEqual(len(t), len(expected))
        for (t_expected, theta_expected), t_read, theta_read in zip(expected, t, theta):
            self.assertAlmostEqual(t_read, t_expected, places=9)
            self.assertAlmostEqual(theta_read, theta_expected, delta=1e-6)  # written %.6f

    def test_config_yields_failure_angle_and_annealing_stages(self):
        config = plot_results.parse_config(make_fixtures.config_yaml("exp2", ["cbbg"], [1], 100))
        self.assertEqual(config["experiment"], "exp2")
        self.assertEqual(config["plant.kind"], "analytic")
        self.assertEqual(plot_results.config_number(config, "trial.failure_angle", "c"), 0.5236)
        self.assertEqual(plot_results.annealing_stages(config, "c"),
                         [(1, 10.0), (11, 5.0), (16, 1.0), (21, 0.5), (23, 0.1)])
        flow = plot_results.parse_config("trial: {theta0: 0.1744, failure_angle: 0.4}\n")
        self.assertEqual(flow["trial.failure_angle"], "0.4")


if __name__ == "__main__":
    unittest.main()
