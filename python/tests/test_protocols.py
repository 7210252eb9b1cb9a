"""The protocols from Python: in memory, through the command line with its results
directory, and one written in Python."""

import numpy as np
import pytest

import cbbg
from in_subprocess import run_python

QUICK = {"plant.kind": "analytic", "seeds": 2, "max_trials": 5}

# Indices outside the lists, in a subprocess, as they once crashed the interpreter (or read
# memory past the runs).
RUN_OUT_OF_RANGE = """
import cbbg

results = cbbg.run_experiment(cbbg.parameters(
    {"plant.kind": "analytic", "seeds": 2, "seed": 1, "max_trials": 2, "experiment": "cbbg"}))
assert results.arms == ["cbbg"] and results.seeds == [1, 2]
for arm, seed_index in ((0, 2), (1, 0), (-1, 0), (0, -1)):
    try:
        results.run(arm, seed_index)
        print("no error")
    except IndexError as error:
        print(error)
print(results.run(arm=0, seed_index=1).seed)
"""


def test_run_takes_indices_and_refuses_those_outside_the_arms_and_seeds():
    done = run_python(RUN_OUT_OF_RANGE)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines() == [
        "ExperimentResults.run: seed_index must be in [0, 2) (an index of seeds); got 2",
        "ExperimentResults.run: arm must be in [0, 1) (an index of arms); got 1",
        "ExperimentResults.run: arm must be in [0, 1) (an index of arms); got -1",
        "ExperimentResults.run: seed_index must be in [0, 2) (an index of seeds); got -1",
        "2",
    ]


# A per-seed body that keeps what it was given past its call, then uses it.
KEPT_PAST_THE_CALL = """
import cbbg

kept = []
def keeper(parameters, arm, run, loop):
    run.add_trial(loop.trial(parameters, 1, 0.05))
    kept.append((arm, run, loop))

cbbg.register_protocol("keeper", "one trial, keeping its handles", keeper)
results = cbbg.run_experiment(cbbg.parameters(
    {"plant.kind": "analytic", "seeds": 1, "arms": ["bg_only"], "experiment": "keeper"}))
arm, run, loop = kept[0]
print(arm.name, run.arm, len(run.trials), len(results.runs[0].trials))
for use in (lambda: loop.context, lambda: loop.trial(cbbg.parameters(), 2, 0.05)):
    try:
        use()
        print("no error")
    except RuntimeError as error:
        print(error)
"""


def test_what_a_per_seed_body_keeps_past_its_call_is_safe():
    done = run_python(KEPT_PAST_THE_CALL)
    assert done.returncode == 0, done.stderr
    refusal = ("SeedLoop: its per-seed call has returned; keep the records its trials gave, not "
               "the loop")
    assert done.stdout.splitlines() == ["bg_only bg_only 1 1", refusal, refusal]


def test_exp3_and_exp2_run_and_return_their_records():
    exp3 = cbbg.run_experiment(cbbg.parameters({**QUICK, "experiment": "exp3"}), jobs=2)
    assert exp3.experiment == "exp3" and exp3.arms == ["cbbg", "bg_only"]
    assert all(run.trials[0].value("actor_alone") is not None for run in exp3.runs)
    assert all(run.figure("trials_to_skill") == len(run.trials) for run in exp3.runs
               if run.figure("trials_to_skill") is not None)
    assert [f.name for f in exp3.schema.figures] == ["trials_to_skill", "failures_to_skill"]
    exp2 = cbbg.run_experiment(
        cbbg.parameters({**QUICK, "experiment": "exp2", "exp2.trials": 3}), jobs=2)
    assert [len(run.trials) for run in exp2.runs] == [3, 3]
    assert [t.k1 for t in exp2.runs[0].trials] == [10.0, 10.0, 10.0]


def test_transfer_records_each_conditions_figures():
    p = cbbg.parameters({**QUICK, "experiment": "transfer",
                         "transfer.conditions": ["evaluation.body_mass_scale=1.2"]})
    results = cbbg.run_experiment(p, jobs=2)
    # Trained as exp3 (the default), exp3's own figures follow the conditions'.
    assert [f.name for f in results.runs[0].figures] == [
        "balanced@evaluation.body_mass_scale=1.2", "evaluated@evaluation.body_mass_scale=1.2",
        "skilled", "trials_to_skill"]
    assert results.runs[0].figures[1].value == 5.0  # the five evaluation.angles
    run = results.runs[0]
    assert run.figures[3].value == len(run.trials)


def test_evaluate_runs_the_weights_exp1_learnt(tmp_path):
    trained = cbbg.run_experiment(cbbg.parameters({**QUICK, "experiment": "cbbg", "seeds": 1}))
    weights = trained.runs[0].weights
    path = tmp_path / "weights.txt"
    cbbg.save_weights(path, weights)
    loaded = cbbg.load_weights(path)
    np.testing.assert_array_equal(loaded.actor, weights.actor)
    evaluated = cbbg.run_experiment(
        cbbg.parameters({**QUICK, "experiment": "evaluate", "arms": ["cbbg"], "seeds": 1}),
        initial_weights=loaded)
    assert [e.outcome.status for e in evaluated.runs[0].evaluation] == [
        e.outcome.status for e in trained.runs[0].evaluation]


def test_the_command_line_writes_a_results_directory_that_loads_as_arrays(tmp_path):
    out = tmp_path / "exp1"
    assert cbbg.main(["run", "--set", "plant.kind=analytic", "--seeds", "2", "--no-figures",
                      "--out", out]) == 0
    results = cbbg.load_results(out)
    in_memory = cbbg.run_experiment(cbbg.parameters({"plant.kind": "analytic", "seeds": 2}))
    failures = [run.failures_before_success for run in in_memory.runs]
    assert results.summary["arms"]["cbbg"]["failures_before_success"] == failures[:2]
    assert results.summary["arms"]["bg_only"]["failures_before_success"] == failures[2:]
    bg_only = results.table("trials", arm="bg_only")
    assert bg_only["failed"].sum() == sum(failures[2:])
    # Typed by the results' schema; the config and the ticks are there too.
    assert results.trials["seed"].dtype == np.int64 and results.trials["failed"].dtype == bool
    assert results.trials["final_theta"].dtype == np.float64
    assert results.evaluation["balanced"].dtype == bool
    assert results.schema["headline"] == "failures_before_success"
    assert results.config["plant.kind"] == "analytic"
    ticks = results.steps(arm="bg_only", seed=2, trial=1)
    assert set(ticks["arm"]) == {"bg_only"} and set(ticks["trial"]) == {1}
    assert ticks["t"].dtype == np.float64 and len(ticks["t"]) > 1
    assert "exp1" in repr(results)
    with pytest.raises(ValueError, match="is not a finished cbbg results directory"):
        cbbg.load_results(tmp_path)


def test_a_bad_setting_on_the_command_line_exits_two():
    assert cbbg.main(["run", "--set", "critic.gamma=2", "--out", "/nonexistent/x"]) == 2


def test_an_argument_holding_a_nul_is_refused_not_cut(tmp_path):
    out = tmp_path / "x"
    with pytest.raises(ValueError) as error:
        cbbg.main(["run", "--set", "plant.kind=analytic", "--out", f"{out}\0y"])
    assert str(error.value) == (f"cbbg.main: args[4] '{out}\\0y' contains a NUL character; an "
                                "argument is text without NUL")
    assert not out.exists()


def two_angles(parameters, arm, run, loop):
    """A protocol of the user's: one trial from 0.05 rad, then one from trial.theta0."""
    for number, theta0 in ((1, 0.05), (2, None)):
        record = loop.trial(parameters, number, theta0)
        record.set_value("from_small_angle", 1.0 if theta0 else 0.0)
        run.add_trial(record)
    run.succeeded = all(t.outcome.balanced for t in run.trials)
    run.add_figure("balanced_trials", sum(t.outcome.balanced for t in run.trials))


# [docs python-protocol]
cbbg.register_protocol("two_angles", "a trial from 0.05 rad, then from trial.theta0", two_angles,
                       figures=[cbbg.Figure("balanced_trials", type="integer", paired=True)],
                       trial_columns=[cbbg.Column("from_small_angle", "flag")])
# [docs python-protocol end]


def test_a_protocol_written_in_python_runs_in_memory_and_through_the_command_line(tmp_path):
    assert "two_angles" in cbbg.protocol_names()
    p = cbbg.parameters({**QUICK, "experiment": "two_angles"})
    results = cbbg.run_experiment(p, jobs=2)
    assert results.experiment == "two_angles"
    assert [len(run.trials) for run in results.runs] == [2, 2, 2, 2]
    assert results.runs[0].figures[0].name == "balanced_trials"
    assert results.runs[0].evaluation  # finished as exp1's: evaluated
    out = tmp_path / "two"
    assert cbbg.main(["run", "--experiment", "two_angles", "--set", "plant.kind=analytic",
                      "--seeds", "2", "--no-figures", "--out", out]) == 0
    figures = cbbg.load_results(out).figures
    np.testing.assert_array_equal(figures["balanced_trials"],
                                  [run.figures[0].value for run in results.runs])
    assert figures["balanced_trials"].dtype == np.int64  # as its schema declares it
    loaded = cbbg.load_results(out)
    assert list(loaded.trials["from_small_angle"][:2]) == [True, False]
    assert [p["figure"] for p in loaded.summary["paired"]] == ["failures_before_success",
                                                               "balanced_trials"]


def test_a_protocol_declares_what_it_records_or_is_told_in_one_line():
    with pytest.raises(ValueError, match="type must be one of integer, number, flag; got 'int'"):
        cbbg.Figure("x", type="int")
    # A figure its schema does not declare would be lost: refused, naming it.
    cbbg.register_protocol("undeclared", "records a figure it does not declare",
                           lambda p, arm, run, loop: run.add_figure("surprise", 1.0))
    with pytest.raises(RuntimeError, match="records the figure 'surprise', which the "
                                           "protocol's schema does not declare"):
        cbbg.run_experiment(cbbg.parameters({**QUICK, "experiment": "undeclared", "seeds": 1}))


def test_an_exp3_seed_without_the_skill_loads_as_nan_where_it_has_none(tmp_path):
    out = tmp_path / "exp3"
    assert cbbg.main(["run", "--experiment", "exp3", "--set", "plant.kind=analytic",
                      "--set", "arms=[bg_only]", "--seeds", "2", "--set", "max_trials=2",
                      "--no-figures", "--out", out]) == 0
    results = cbbg.load_results(out)
    assert np.isnan(results.figures["trials_to_skill"]).all()  # never in 2 trials
    assert results.summary["arms"]["bg_only"]["trials_to_skill"] == [None, None]
    assert results.trials["actor_alone"].dtype == bool  # tested after every trial


def test_a_python_protocols_trials_learn_under_the_training_section():
    """training.* reaches the trials of a protocol written in Python as it does exp1's: every
    trial starts from a pitch drawn about the one it asks for."""
    def outcomes(settings):
        p = cbbg.parameters({**QUICK, "experiment": "two_angles", **settings})
        return [(t.outcome.steps, t.outcome.final_theta)
                for run in cbbg.run_experiment(p, jobs=2).runs for t in run.trials]

    nominal = outcomes({})
    spread = outcomes({"training": {"pitch_spread": 0.1}})
    assert all(a != b for a, b in zip(nominal, spread))
    # A robot of its own each trial, through the kit's SeedLoop.trial
    masses = outcomes({"training": {"body_mass_spread": 0.4}})
    assert len(masses) == len(nominal) and all(a != b for a, b in zip(nominal, masses))
    with pytest.raises(cbbg.ConfigError, match="training.pitch_spread"):
        outcomes({"training.pitch_spread": -1})
