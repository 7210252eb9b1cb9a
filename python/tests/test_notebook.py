"""What a notebook needs: cbbg.main's output through Python's sys.stdout and sys.stderr and a
check that raises, cbbg.Parameters a read-only mapping, and readable reprs of results."""

from collections.abc import Mapping

import pytest

import cbbg


def test_main_prints_through_pythons_streams(capsys):
    assert cbbg.main(["list"]) == 0
    assert "Diagrams (presets" in capsys.readouterr().out


def test_main_with_check_raises_with_the_commands_error(capsys):
    with pytest.raises(cbbg.CommandError) as error:
        cbbg.main(["run", "--seeds", "0"], check=True)
    assert error.value.exit_code == 2
    assert "--seeds" in error.value.stderr and "--seeds" in str(error.value)
    assert "--seeds" in capsys.readouterr().err
    assert cbbg.main(["run", "--seeds", "0"]) == 2  # without check: the code, as before


def test_parameters_are_a_read_only_mapping_of_every_key():
    parameters = cbbg.parameters({"plant.kind": "analytic", "critic.gamma": 0.9})
    assert isinstance(parameters, Mapping)
    assert "critic.gamma" in parameters and "critic.gama" not in parameters
    assert dict(parameters)["critic.gamma"] == 0.9 == parameters.get("critic.gamma")
    assert len(parameters) == len(list(parameters)) == len(cbbg.schema())
    assert parameters.get("no.such.key", "none") == "none"
    with pytest.raises(TypeError):
        parameters["critic.gamma"] = 0.5
    assert repr(parameters).startswith("Parameters(experiment='exp1', plant.kind='analytic'")


def test_results_have_readable_reprs():
    parameters = cbbg.parameters({"plant.kind": "analytic", "trial.duration": 0.05})
    loop = cbbg.build_preset("pd_only", parameters)
    context = loop.diagram.create_context(1)
    loop.start_trial(context, 0.1)
    status = cbbg.Simulator(loop.diagram, context).advance_to(0.05)
    assert repr(status) == "SimulationStatus(terminated=False, time=0.05, terminated_by='', reason='')"
    for cls in (cbbg.EventStatus, cbbg.TrialOutcome, cbbg.TrialRecord, cbbg.EvaluationRecord,
                cbbg.SeedFigure, cbbg.LearntWeights, cbbg.SeedRun, cbbg.ExperimentResults,
                cbbg.control.LqrResult, cbbg.ResultsSchema, cbbg.LinearModel):
        assert cls.__repr__ is not object.__repr__, cls.__name__
    assert repr(cbbg.SeedFigure("trials_to_skill", 3.0)) == \
        "SeedFigure(name='trials_to_skill', value=3)"


def test_a_notebook_cell_that_registers_runs_again_with_replace_and_can_unregister():
    from two_wheeler import RobotParams, TwoWheeler

    def plant(name, p):
        return TwoWheeler(name, RobotParams.of(p))

    def one_trial(parameters, arm, run, loop):
        run.add_trial(loop.trial(parameters, 1, 0.05))

    def cell():
        cbbg.register_arm("cell_arm", "an arm of a notebook cell", cbbg.preset("pd_only").options,
                          replace=True)
        cbbg.register_plant_kind("cell_plant", "a plant of a notebook cell", plant, replace=True)
        cbbg.register_protocol("cell_protocol", "a protocol of a notebook cell", one_trial,
                               evaluates=False, replace=True)
        cbbg.register_section("cell", {"gain": cbbg.number_key(2.0, "a gain")}, replace=True)

    cell()
    cell()  # run again: no "registered twice"
    assert cbbg.parameters({"plant.kind": "cell_plant", "cell.gain": 3.0})["cell.gain"] == 3.0
    with pytest.raises(ValueError, match="registered twice"):
        cbbg.register_arm("cell_arm", "again", cbbg.preset("pd_only").options)
    cbbg.unregister_arm("cell_arm")
    cbbg.unregister_plant_kind("cell_plant")
    cbbg.unregister_protocol("cell_protocol")
    cbbg.unregister_section("cell")
    assert "cell_arm" not in cbbg.arm_names() and "cell_plant" not in cbbg.plant_kinds()
    assert "cell_protocol" not in cbbg.protocol_names()
    assert "cell.gain" not in cbbg.parameters({"plant.kind": "analytic"})
    with pytest.raises(ValueError, match="plant.kind must be one of"):
        cbbg.parameters({"plant.kind": "cell_plant"})
    with pytest.raises(ValueError, match="no registered arm 'cbbg' to unregister .a preset stays."):
        cbbg.unregister_arm("cbbg")
    with pytest.raises(ValueError, match="no registered plant kind 'analytic'"):
        cbbg.unregister_plant_kind("analytic")
    with pytest.raises(ValueError, match="no registered protocol 'exp1'"):
        cbbg.unregister_protocol("exp1")
    with pytest.raises(ValueError, match="no section 'critic' registered from Python"):
        cbbg.unregister_section("critic")


@pytest.mark.parametrize("call, message", [
    (lambda: cbbg.make_arm(5, None),
     "cbbg.make_arm takes (name: str, options: cbbg.ControllerOptions, plant: object = None, "
     "task: Optional[cbbg.TaskSlots] = None); got 5, None"),
    (lambda: cbbg.evaluated_parameters({"plant.kind": "analytic"}),
     "cbbg.evaluated_parameters takes (parameters: cbbg.Parameters); got {'plant.kind': "
     "'analytic'}"),
    (lambda: cbbg.ControllerOptions(5),
     "cbbg.ControllerOptions takes (); got "),
    (lambda: cbbg.main("run"),
     "cbbg.main: args are a list of the command's words (['run', '--seeds', '5']); got str 'run'"),
    (lambda: cbbg.main(["run", 5]), "cbbg.main: args[1] is int 5; each word is a str (or a path)"),
    (lambda: cbbg.parameters({})[5], "Parameters: a key is a str ('critic.gamma'); got int 5"),
    (lambda: cbbg.load_results(5),
     "load_results: the directory is a path (str or os.PathLike); got int 5"),
    (lambda: cbbg.VecBalanceEnv("2", {"plant.kind": "analytic"}),
     "VecBalanceEnv: num_envs is a whole number; got str '2'"),
    (lambda: cbbg.BalanceEnv({"plant.kind": "analytic"}).reset(seed="a"),
     "reset: seed is None or a whole number >= 0; got str 'a'"),
])
def test_a_call_with_arguments_of_the_wrong_type_says_so_in_cbbgs_words(call, message):
    with pytest.raises(TypeError) as raised:
        call()
    text = str(raised.value)
    assert text.startswith(message)
    assert "\n" not in text and "_cbbg" not in text and "incompatible" not in text


def test_the_translation_leaves_other_type_errors_and_right_calls_alone():
    assert cbbg.evaluated_parameters(cbbg.parameters({"plant.kind": "analytic"}))["seed"] == 1
    from cbbg import _type_errors
    assert _type_errors.one_line("f", "f() missing 1 required positional argument") is None
