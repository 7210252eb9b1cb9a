"""The controller's slots, arms and plants from Python, through exp1."""

import numpy as np
import pytest

import cbbg
from pd_supervisor import PdSupervisor as PdSupervisorInPython
from two_wheeler import RobotParams, TwoWheeler


def python_supervised_cbbg():
    options = cbbg.preset("cbbg").options
    options.slots.supervisor = PdSupervisorInPython
    return options


def analytic(seeds=3, **settings):
    return cbbg.parameters({"plant.kind": "analytic", "seeds": seeds, **settings})


def per_seed_numbers(results):
    """Everything exp1 records per seed, as plain values."""
    return [(run.arm, run.seed, run.failures_before_success, run.succeeded,
             [(t.trial, t.outcome.status, t.outcome.steps, t.outcome.final_theta,
               t.outcome.mean_temperature, t.outcome.mean_entropy) for t in run.trials],
             [(e.theta0, e.outcome.status, e.outcome.steps, e.outcome.final_theta)
              for e in run.evaluation],
             run.weights.actor.tolist() if run.weights else None)
            for run in results.runs]


def test_a_python_supervisor_gives_the_per_seed_exp1_numbers_of_the_cpp_pd_it_copies():
    p = analytic()
    python = cbbg.run_exp1(p, [cbbg.make_arm("cbbg", python_supervised_cbbg())], jobs=2)
    native = cbbg.run_exp1(p, [cbbg.preset_arm("cbbg")], jobs=2)
    assert per_seed_numbers(python) == per_seed_numbers(native)


def test_a_python_block_in_the_loop_gives_the_same_results_in_one_thread_or_two():
    p = analytic(seeds=2)
    arms = [cbbg.make_arm("cbbg", python_supervised_cbbg())]
    assert per_seed_numbers(cbbg.run_exp1(p, arms, jobs=1)) == per_seed_numbers(
        cbbg.run_exp1(p, arms, jobs=2))


def test_a_slot_reads_back_the_python_callable_it_was_given():
    options = python_supervised_cbbg()
    assert options.slots.supervisor is PdSupervisorInPython
    assert options.slots.features is None
    options.slots.supervisor = None
    assert options.slots.supervisor is None


class ConstantOmega(cbbg.LeafBlock):
    def __init__(self, name, value):
        super().__init__(name)
        self.value = value
        self.declare_output_port("omega", 1, self.calc)

    def calc(self, context, out):
        out[:] = self.value


def test_a_python_omega_of_one_makes_cbbg_learn_as_the_basal_ganglia_alone():
    options = cbbg.preset("cbbg").options
    options.slots.omega = lambda name, p: ConstantOmega(name, 1.0)
    loop = cbbg.make_arm("omega_one", options).learner(analytic())
    assert loop.controller.block("omega").type_name == "ConstantOmega"

    def exp1_numbers(omega_options):
        arm = cbbg.make_arm("omega_one", omega_options)
        return per_seed_numbers(cbbg.run_exp1(analytic(seeds=2), [arm]))

    python = exp1_numbers(options)
    # The library's own omega held at one: the same numbers, trial by trial.
    native = cbbg.preset("cbbg").options
    native.omega = "one"
    assert python == exp1_numbers(native)
    # Not what the scheduled omega (cbbg's) learns: the comparison tells omegas apart.
    assert python != exp1_numbers(cbbg.preset("cbbg").options)


def test_a_python_plant_runs_exp1_as_the_analytic_plant_does():
    p = analytic(seeds=1)
    arm = cbbg.make_arm("cbbg", cbbg.preset("cbbg").options,
                        plant=lambda name, q: TwoWheeler(name, RobotParams.of(q)))
    python = cbbg.run_exp1(p, [arm])
    native = cbbg.run_exp1(p, [cbbg.preset_arm("cbbg")])
    ours, theirs = python.runs[0], native.runs[0]
    assert ours.failures_before_success == theirs.failures_before_success
    assert [e.outcome.status for e in ours.evaluation] == [e.outcome.status for e in theirs.evaluation]
    # The same equations, solved by NumPy instead of Eigen's Cholesky: equal to rounding.
    assert ours.trials[-1].outcome.final_theta == pytest.approx(
        theirs.trials[-1].outcome.final_theta, abs=1e-9)


def test_a_factory_that_returns_no_block_is_refused_by_name():
    options = cbbg.preset("cbbg").options
    options.slots.features = lambda name, p: 42
    with pytest.raises(ValueError, match="the factory of slot 'features': expected a Block, got int"):
        cbbg.make_arm("bad", options).learner(analytic())


def test_an_exception_in_a_python_factory_keeps_its_type():
    def broken(name, parameters):
        raise KeyError("no such gain")

    options = cbbg.preset("cbbg").options
    options.slots.supervisor = broken
    with pytest.raises(KeyError, match="no such gain"):
        cbbg.run_exp1(analytic(seeds=1), [cbbg.make_arm("broken", options)], jobs=2)


def test_settings_from_dicts_are_checked_key_by_key():
    assert cbbg.parameters({"critic": {"gamma": 0.9}})["critic.gamma"] == 0.9
    with pytest.raises(cbbg.ConfigError) as error:
        cbbg.parameters({"critic.gama": 0.9})
    assert str(error.value) == ("settings['critic.gama']: unknown key 'critic.gama'; did you mean "
                                "'critic.gamma'?")
    with pytest.raises(cbbg.ConfigError, match=r"critic.gamma must be in \(0, 1\]; got 2"):
        cbbg.parameters({"critic.gamma": 2})


def test_a_dict_given_to_a_key_is_refused_as_the_command_line_refuses_it():
    with pytest.raises(cbbg.ConfigError) as error:
        cbbg.parameters({"critic.beta": {}})
    assert str(error.value) == "settings['critic.beta']: critic.beta must be a number; got {}"
    with pytest.raises(cbbg.ConfigError,
                       match=r"^settings\['critic.bta'\]: unknown key 'critic.bta'"):
        cbbg.parameters({"critic": {"bta": {}}})
    assert cbbg.parameters({"critic": {}})["critic.beta"] == cbbg.parameters()["critic.beta"]


@pytest.mark.parametrize("spec, refusal", [
    (cbbg.number_key(-1.0, "a gain", min=0.0), "oops.key must be >= 0; got -1"),
    (cbbg.number_key(0.0, "a gain", min=0.0, min_exclusive=True), "oops.key must be > 0; got 0"),
    (cbbg.integer_key(5, "a count", max=3), "oops.key must be an integer <= 3; got 5"),
    (cbbg.numbers_key([1.0, -2.0], "gains", min=0.0), "oops.key[1] must be >= 0; got -2"),
    (cbbg.text_key("c", "a word", choices=["a", "b"]), "oops.key must be one of a, b; got 'c'"),
])
def test_a_section_whose_default_is_outside_its_bounds_is_refused_at_registration(spec, refusal):
    with pytest.raises(ValueError) as error:
        cbbg.register_section("oops", {"key": spec})
    assert str(error.value) == (
        f"config key 'oops.key' has a default outside its declaration: {refusal}")
    assert "oops.key" not in [key.path for key in cbbg.schema()]


def test_a_sections_own_check_refuses_its_values_at_the_edge():
    def check(values):
        if values["low"] >= values["high"]:
            raise ValueError("band.low must be below band.high")

    cbbg.register_section("band", {"low": cbbg.number_key(1.0, "the lower edge"),
                                   "high": cbbg.number_key(2.0, "the upper edge")}, check=check)
    assert cbbg.parameters({"band": {"low": 1.5}})["band.low"] == 1.5
    with pytest.raises(cbbg.ConfigError, match=r"^band.low must be below band.high$"):
        cbbg.parameters({"band": {"low": 3.0}})


def test_a_users_own_section_is_set_from_a_dict_and_read_by_a_factory():
    cbbg.register_section("lean", {"gain": cbbg.number_key(40.0, "the lean gain", min=0.0)})
    p = cbbg.parameters({"lean": {"gain": 55.0}})
    assert p["lean.gain"] == 55.0
    assert cbbg.parameters()["lean.gain"] == 40.0
    with pytest.raises(cbbg.ConfigError, match=r"lean.gain must be >= 0; got -1"):
        cbbg.parameters({"lean.gain": -1})
    seen = []
    options = cbbg.preset("cbbg").options

    def supervisor(name, parameters):
        seen.append(parameters["lean.gain"])
        return PdSupervisorInPython(name, parameters)

    options.slots.supervisor = supervisor
    cbbg.make_arm("lean", options).learner(cbbg.parameters({"lean.gain": 12.5, "plant.kind": "analytic"}))
    assert seen == [12.5]


cbbg.register_arm("cbbg_python_pd", "cbbg with the PD supervisor written in Python",
                  python_supervised_cbbg())
cbbg.register_plant_kind("numpy_two_wheeler", "the two-wheeler written in Python with NumPy",
                         lambda name, p: TwoWheeler(name, RobotParams.of(p)))


def test_a_registered_python_arm_and_plant_run_exp1_into_a_results_directory(tmp_path):
    assert "cbbg_python_pd" in cbbg.arm_names()
    assert "numpy_two_wheeler" in cbbg.plant_kinds()
    out = tmp_path / "python_pd"
    assert cbbg.main(["run", "--set", "plant.kind=analytic", "--set", "arms=[cbbg_python_pd, cbbg]",
                      "--seeds", "2", "--jobs", "2", "--no-figures", "--out", out]) == 0
    arms = cbbg.load_results(out).summary["arms"]
    assert arms["cbbg_python_pd"]["failures_before_success"] == arms["cbbg"]["failures_before_success"]
    out = tmp_path / "numpy_plant"
    assert cbbg.main(["run", "--set", "plant.kind=numpy_two_wheeler", "--set", "arms=[cbbg]",
                      "--seeds", "1", "--no-figures", "--out", out]) == 0
    results = cbbg.load_results(out)
    assert results.summary["plant"] == "numpy_two_wheeler"
    assert len(results.evaluation["balanced"]) == 5


class LoggingTwoWheeler(TwoWheeler):
    """The NumPy two-wheeler, logging its yaw rate and true pitch into steps.csv."""

    def logged_signals(self):
        return ["yaw_rate", "pitch"]


def test_a_python_plants_logged_signals_reach_steps_csv(tmp_path):
    cbbg.register_plant_kind("logging_numpy", "the NumPy two-wheeler, logging two signals",
                             lambda name, p: LoggingTwoWheeler(name, RobotParams.of(p)),
                             replace=True)
    out = tmp_path / "logged"
    assert cbbg.main(["run", "--set", "plant.kind=logging_numpy", "--set", "arms=[pd_only]",
                      "--set", "trial.duration=0.2", "--seeds", "1", "--no-figures",
                      "--out", out]) == 0
    with open(out / "steps.csv") as f:
        assert f.readline().rstrip("\n").endswith(",reward,x,y,yaw,yaw_rate,pitch")
    steps = cbbg.load_results(out).steps()
    assert len(steps["pitch"]) == 20
    # Exact sensors: the true pitch logged is the measured one; both wheels alike, no turn.
    assert np.array_equal(steps["pitch"], steps["theta_b"])
    assert np.all(np.abs(steps["yaw_rate"]) < 1e-9)
    cbbg.unregister_plant_kind("logging_numpy")


class MisloggingTwoWheeler(TwoWheeler):
    def logged_signals(self):
        return ["torque"]


def test_a_python_plant_logging_what_it_lacks_is_refused_in_one_line():
    cbbg.register_plant_kind("mislogging_numpy", "logs a signal it does not have",
                             lambda name, p: MisloggingTwoWheeler(name, RobotParams.of(p)),
                             replace=True)
    with pytest.raises(ValueError, match="plant 'plant' logs 'torque', which is not one of its "
                                         r"signals \(pitch, pitch_rate, "):
        cbbg.BalanceEnv({"plant.kind": "mislogging_numpy"})
    cbbg.unregister_plant_kind("mislogging_numpy")
