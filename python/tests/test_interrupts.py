"""Ctrl-C and the other exceptions that are not errors: they reach Python as they are, from a
Python block, a factory or long C++ work, promptly, and `except Exception` does not catch them."""

import pytest

import cbbg
from in_subprocess import interrupt_python

# The call under test runs in a subprocess that says "ready" as it starts it; SIGINT follows.
# An Exception caught first would be a KeyboardInterrupt turned into an error.
CALL = """
import time
import cbbg
{setup}
print("ready", flush=True)
start = time.monotonic()
try:
    {call}
    print("returned")
except Exception as error:
    print("an Exception:", type(error).__name__, error)
except KeyboardInterrupt:
    print(f"KeyboardInterrupt after {{time.monotonic() - start:.1f}} s")
"""

# Long: a trial of 2000 s of the analytic robot takes seconds (the default is 20 s).
LONG = '{"plant.kind": "analytic", "seeds": 4, "trial.duration": 2000.0}'


def assert_interrupted_promptly(setup, call):
    done, took = interrupt_python(CALL.format(setup=setup, call=call))
    assert done.returncode == 0, done.stderr
    last = done.stdout.splitlines()[-1]
    assert last.startswith("KeyboardInterrupt after "), done.stdout + done.stderr
    # The signal came during the call (a second after it started), and ended it at once.
    assert float(last.split()[2]) >= 0.9
    assert took < 3.0, f"KeyboardInterrupt took {took:.1f} s"
    return done


LOOPING_BLOCK = """
class Stuck(cbbg.LeafBlock):
    def __init__(self, name):
        super().__init__(name)
        self.declare_discrete_state("x", [0.0])
        self.declare_periodic_update(0.01, 0.0, self.update)

    def update(self, context, next_state):
        print("ready", flush=True)
        {body}

builder = cbbg.DiagramBuilder("top")
builder.add(Stuck("stuck"))
simulator = cbbg.Simulator(builder.build())
"""


@pytest.mark.parametrize("body", ["time.sleep(60)", "while True: pass"])
def test_ctrl_c_inside_a_python_block_is_a_keyboard_interrupt(body):
    # The block says "ready" itself: the signal comes while it runs.
    code = CALL.format(setup=LOOPING_BLOCK.format(body=body), call="simulator.advance_to(1.0)")
    code = code.replace('print("ready", flush=True)\nstart', "start", 1)
    done, took = interrupt_python(code)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[-1].startswith("KeyboardInterrupt after "), done.stdout
    assert took < 3.0


def test_ctrl_c_during_a_long_advance_to_arrives_between_ticks():
    setup = """
parameters = cbbg.parameters({"plant.kind": "analytic"})
loop = cbbg.build_preset("pd_only", parameters)
simulator = cbbg.Simulator(loop.diagram, loop.diagram.create_context(1))
"""
    assert_interrupted_promptly(setup, "simulator.advance_to(1e7)")


@pytest.mark.parametrize("jobs", [1, 2])
def test_ctrl_c_during_run_experiment_arrives_between_ticks(jobs):
    assert_interrupted_promptly(f"parameters = cbbg.parameters({LONG})",
                                f"cbbg.run_experiment(parameters, jobs={jobs})")


def test_ctrl_c_during_cbbg_main_is_a_keyboard_interrupt_not_an_error_exit(tmp_path):
    call = (f'cbbg.main(["run", "--set", "plant.kind=analytic", "--set", "trial.duration=2000", '
            f'"--seeds", "4", "--jobs", "2", "--no-figures", "--out", "{tmp_path / "out"}"])')
    done = assert_interrupted_promptly("", call)
    assert "error" not in done.stderr


def test_ctrl_c_while_the_calling_thread_waits_for_a_worker_stops_the_worker():
    # Only a worker thread runs trials: the calling thread, its seeds done (each after a pause
    # that leaves the worker time to take one), waits for it.
    setup = f"""
import threading

def body(parameters, arm, run, loop):
    if threading.current_thread() is threading.main_thread():
        time.sleep(0.05)
    else:
        run.add_trial(loop.trial(parameters, 1))

cbbg.register_protocol("workers_only", "trials in worker threads only", body, evaluates=False)
parameters = cbbg.parameters({{**{LONG}, "experiment": "workers_only", "arms": ["pd_only"]}})
"""
    assert_interrupted_promptly(setup, "cbbg.run_experiment(parameters, jobs=2)")


class Raising(cbbg.LeafBlock):
    def __init__(self, name, exception):
        super().__init__(name)
        self.exception = exception
        self.declare_output_port("action", 1, self.calc)
        self.declare_input_port("measured", 6)

    def calc(self, context, out):
        raise self.exception


@pytest.mark.parametrize("exception", [KeyboardInterrupt(), SystemExit(3)])
def test_a_python_block_raising_what_is_no_error_raises_it_as_it_is(exception):
    builder = cbbg.DiagramBuilder("top")
    block = builder.add(Raising("raising", exception))
    builder.fix_input(block.input_port("measured"), [0.0] * 6)
    builder.export_output(block.output_port("action"), "action")
    diagram = builder.build()
    simulator = cbbg.Simulator(diagram)
    simulator.add_log(diagram.output_port("action"), 0.01)
    with pytest.raises(type(exception)) as raised:
        simulator.advance_to(0.1)
    assert raised.value is exception


def raising_arm(name, exception, where):
    options = cbbg.preset("cbbg").options
    if where == "block":
        options.slots.supervisor = lambda block_name, p: Raising(block_name, exception)
    else:
        def factory(block_name, p):
            raise exception
        options.slots.supervisor = factory
    cbbg.register_arm(name, f"its supervisor raises {exception.__name__} ({where})", options)


for _where in ("block", "factory"):
    raising_arm(f"interrupted_{_where}", KeyboardInterrupt, _where)


@pytest.mark.parametrize("where", ["block", "factory"])
@pytest.mark.parametrize("jobs", [1, 2])
def test_the_command_line_lets_a_keyboard_interrupt_through(tmp_path, where, jobs):
    with pytest.raises(KeyboardInterrupt):
        cbbg.main(["run", "--set", "plant.kind=analytic", "--set", f"arms=[interrupted_{where}]",
                   "--seeds", "2", "--jobs", str(jobs), "--no-figures", "--out", tmp_path / "out"])
