"""Blocks written in Python: ports, state, events, errors, ownership."""

import gc
import traceback
import weakref

import numpy as np
import pytest

import cbbg
from in_subprocess import run_python
from two_wheeler import RobotParams, TwoWheeler


class Counter(cbbg.LeafBlock):
    """Counts ticks of 10 ms; ends the simulation at `limit`."""

    def __init__(self, name, limit=None):
        super().__init__(name)
        self.limit = limit
        self.count = self.declare_discrete_state("count", [0.0])
        self.declare_output_port("n", 1, self.calc_n, holds_between_events=True)
        self.declare_periodic_update(0.01, 0.0, self.update)

    def calc_n(self, context, out):
        out[:] = context.state("count")

    def update(self, context, next_state):
        next_state[0] += 1.0
        if self.limit is not None and next_state[0] >= self.limit:
            return cbbg.EventStatus.terminate("enough")
        return None


class Scale(cbbg.LeafBlock):
    """y = k u, k a parameter."""

    def __init__(self, name, size=1):
        super().__init__(name)
        self.u = self.declare_input_port("u", size)
        self.declare_parameter("k", [2.0])
        self.declare_output_port("y", size, self.calc, reads=[self.u])

    def calc(self, context, out):
        out[:] = context.parameter("k")[0] * context.input(self.u)


class Integrate(cbbg.LeafBlock):
    """x' = u, the simulator integrating it."""

    def __init__(self, name):
        super().__init__(name)
        self.u = self.declare_input_port("u", 1)
        self.declare_continuous_state([0.0], self.derivatives)
        self.declare_output_port("x", 1, self.calc)

    def derivatives(self, context, out):
        out[:] = context.input(self.u)

    def calc(self, context, out):
        out[:] = context.continuous_state


def counter_diagram(limit=None):
    builder = cbbg.DiagramBuilder("top")
    counter = builder.add(Counter("counter", limit))
    scale = builder.add(Scale("scale"))
    builder.connect(counter.output_port("n"), scale.input_port("u"))
    builder.export_output(scale.output_port("y"), "y")
    return builder.build(), counter, scale


# A block kept after its diagram is gone: it belongs to no diagram any more.
BLOCK_KEPT_PAST_ITS_DIAGRAM = """
import cbbg

def kept_gain():
    builder = cbbg.DiagramBuilder("top")
    gain = builder.add(cbbg.Gain("k", 2.0, 1))
    builder.export_input(gain.input_port("u"))
    builder.export_output(gain.output_port("y"))
    builder.build()  # dropped at once
    return gain

gain = kept_gain()
print(gain.path)
print(repr(gain.output_port("y")))
builder = cbbg.DiagramBuilder("again")
print(builder.add(gain).path)
"""


def test_a_block_kept_past_its_diagram_belongs_to_none_and_may_join_another():
    done = run_python(BLOCK_KEPT_PAST_ITS_DIAGRAM)
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert lines[0] == "k"
    assert "k" in lines[1] and "y" in lines[1]
    assert lines[2] == "again/k"


def test_a_diagram_of_python_blocks_simulates_and_logs_numpy_arrays():
    diagram, _, _ = counter_diagram()
    simulator = cbbg.Simulator(diagram)
    log = simulator.add_log(diagram.output_port("y"), 0.01)
    simulator.advance_to(0.1)
    assert isinstance(log.values, np.ndarray) and log.values.shape == (1, 10)
    np.testing.assert_array_equal(log.times, np.arange(10) * 0.01)
    np.testing.assert_array_equal(log.values[0], 2.0 * np.arange(10))


def test_an_update_ends_the_simulation_with_its_reason_and_block():
    diagram, _, _ = counter_diagram(limit=5)
    status = cbbg.Simulator(diagram).advance_to(1.0)
    assert status.terminated
    assert status.reason == "enough"
    assert status.terminated_by == "top/counter"
    assert status.time == pytest.approx(0.04)


def test_a_parameter_set_in_the_context_changes_the_output():
    diagram, _, scale = counter_diagram()
    context = diagram.create_context()
    context.set_parameter(scale, "k", [3.0])
    simulator = cbbg.Simulator(diagram, context)
    log = simulator.add_log(diagram.output_port("y"), 0.01)
    simulator.advance_to(0.05)
    np.testing.assert_array_equal(log.values[0], 3.0 * np.arange(5))


def test_continuous_state_is_integrated_from_python_derivatives():
    builder = cbbg.DiagramBuilder("top")
    integrate = builder.add(Integrate("integrate"))
    builder.fix_input(integrate.u, [0.5])
    builder.export_output(integrate.output_port("x"), "x")
    diagram = builder.build()
    simulator = cbbg.Simulator(diagram)
    simulator.advance_to(2.0)
    assert simulator.context.continuous_state(integrate)[0] == pytest.approx(1.0, abs=1e-9)


class PerTrial(cbbg.LeafBlock):
    def __init__(self, name):
        super().__init__(name)
        self.declare_discrete_state("kept", [0.0])
        self.declare_discrete_state("trace", [0.0], per_trial=True)
        self.declare_periodic_update(0.01, 0.0, self.update)

    def update(self, context, next_state):
        next_state += 1.0


def test_per_trial_state_restarts_and_persistent_state_carries_on():
    builder = cbbg.DiagramBuilder("top")
    block = builder.add(PerTrial("block"))
    diagram = builder.build()
    simulator = cbbg.Simulator(diagram)
    simulator.advance_to(0.05)
    context = simulator.context
    np.testing.assert_array_equal(context.discrete_state(block), [5.0, 5.0])
    context.reset_trial_state()
    np.testing.assert_array_equal(context.discrete_state(block), [5.0, 0.0])
    assert [part.name for part in block.discrete_state_parts] == ["kept", "trace"]
    assert block.discrete_state_part("trace").per_trial


class Noise(cbbg.LeafBlock):
    def __init__(self, name, draw_in_output=False):
        super().__init__(name)
        self.draw_in_output = draw_in_output
        self.declare_discrete_state("x", [0.0])
        self.declare_output_port("y", 1, self.calc, holds_between_events=True)
        self.declare_periodic_update(0.01, 0.0, self.update)

    def calc(self, context, out):
        out[:] = context.random_normal() if self.draw_in_output else context.state("x")

    def update(self, context, next_state):
        next_state[0] = context.random_normal()


def noise_samples(seed):
    builder = cbbg.DiagramBuilder("top")
    noise = builder.add(Noise("noise"))
    builder.export_output(noise.output_port("y"), "y")
    diagram = builder.build()
    simulator = cbbg.Simulator(diagram, seed=seed)
    log = simulator.add_log(diagram.output_port("y"), 0.01)
    simulator.advance_to(0.2)
    return log.values[0]


def test_random_draws_come_from_the_blocks_own_seeded_stream():
    np.testing.assert_array_equal(noise_samples(7), noise_samples(7))
    assert not np.array_equal(noise_samples(7), noise_samples(8))


def python_error(build_block):
    builder = cbbg.DiagramBuilder("top")
    block = builder.add(build_block())
    builder.export_output(block.output_port(0), "y")
    diagram = builder.build()
    with pytest.raises(cbbg.BlockError) as error:
        cbbg.Simulator(diagram).advance_to(0.1)
    return str(error.value)


def test_an_output_may_not_draw_random_numbers():
    message = python_error(lambda: Noise("noise", draw_in_output=True))
    assert message.startswith("block 'top/noise' (Noise), its output 'y': RuntimeError: block "
                              "'top/noise': only an update draws random numbers")


class Faulty(cbbg.LeafBlock):
    def __init__(self, name, fault):
        super().__init__(name)
        self.fault = fault
        self.declare_discrete_state("x", [0.0])
        self.declare_output_port("y", 1, self.calc)
        self.declare_periodic_update(0.01, 0.0, self.update)

    def calc(self, context, out):
        if self.fault == "raise":
            raise ValueError("the sensor is unplugged")
        if self.fault == "return":
            return 1.0
        out[:] = 0.0

    def update(self, context, next_state):
        if self.fault == "update":
            return "stop"


def test_an_exception_inside_a_python_block_surfaces_with_the_blocks_path():
    message = python_error(lambda: Faulty("sensor", "raise"))
    assert message.startswith(
        "block 'top/sensor' (Faulty), its output 'y': ValueError: the sensor is unplugged")


def test_a_block_error_is_one_line_raised_from_the_exception_the_block_raised():
    builder = cbbg.DiagramBuilder("top")
    block = builder.add(Faulty("sensor", "raise"))
    builder.export_output(block.output_port(0), "y")
    diagram = builder.build()
    with pytest.raises(cbbg.BlockError) as error:
        cbbg.Simulator(diagram).advance_to(0.1)
    assert str(error.value) == (
        "block 'top/sensor' (Faulty), its output 'y': ValueError: the sensor is unplugged")
    cause = error.value.__cause__
    assert type(cause) is ValueError and str(cause) == "the sensor is unplugged"
    # With its own traceback, down to the line that raised it.
    assert traceback.extract_tb(cause.__traceback__)[-1].name == "calc"


def test_a_bad_return_is_a_block_error_without_a_cause():
    builder = cbbg.DiagramBuilder("top")
    block = builder.add(Faulty("f", "return"))
    builder.export_output(block.output_port(0), "y")
    diagram = builder.build()
    with pytest.raises(cbbg.BlockError, match="returned a value") as error:
        cbbg.Simulator(diagram).advance_to(0.1)
    assert error.value.__cause__ is None


class BrokenReset(TwoWheeler):
    def reset(self, context, initial_pitch):
        raise ZeroDivisionError("no pitch")


def test_a_python_plants_reset_error_is_raised_from_its_exception():
    env = cbbg.BalanceEnv({"plant.kind": "analytic"},
                          plant=lambda name, p: BrokenReset(name, RobotParams.of(p)))
    with pytest.raises(cbbg.BlockError) as error:
        env.reset(seed=1)
    assert str(error.value) == (
        "block 'environment/plant' (BrokenReset), its reset: ZeroDivisionError: no pitch")
    assert type(error.value.__cause__) is ZeroDivisionError


def test_a_callable_that_returns_instead_of_writing_is_told_so():
    assert python_error(lambda: Faulty("f", "return")) == (
        "block 'top/f' (Faulty), its output 'y': returned a value; write into the array it is "
        "given (out[:] = ...)")
    assert python_error(lambda: Faulty("f", "update")) == (
        "block 'top/f' (Faulty), its periodic update: returned str; an update returns None or "
        "cbbg.EventStatus.terminate(reason)")


class Keeper(cbbg.LeafBlock):
    """Keeps the context it was given, which must not work after the call."""

    def __init__(self, name):
        super().__init__(name)
        self.kept = None
        self.declare_output_port("y", 1, self.calc)

    def calc(self, context, out):
        self.kept = context
        out[:] = 0.0


def test_a_context_kept_after_its_call_refuses_to_be_read():
    builder = cbbg.DiagramBuilder("top")
    keeper = builder.add(Keeper("keeper"))
    builder.export_output(keeper.output_port("y"), "y")
    diagram = builder.build()
    diagram.eval_output(diagram.create_context(), diagram.output_port("y"))
    with pytest.raises(RuntimeError, match="a context is valid only during the call"):
        keeper.kept.time


# Every use of a kept context once its simulator and diagram are gone: each the documented
# RuntimeError, in a subprocess, as it once crashed the interpreter.
KEPT_AFTER_ITS_DIAGRAM = """
import gc
import cbbg

kept = []

class Keeper(cbbg.LeafBlock):
    def __init__(self, name):
        super().__init__(name)
        self.u = self.declare_input_port("u", 1)
        self.declare_discrete_state("x", [0.0])
        self.declare_parameter("k", [2.0])
        self.declare_output_port("y", 1, self.calc)
        self.declare_periodic_update(0.01, 0.0, self.update)

    def calc(self, context, out):
        kept.append(context)
        out[:] = 0.0

    def update(self, context, next_state):
        kept.append(context)


def simulate():
    builder = cbbg.DiagramBuilder("top")
    keeper = builder.add(Keeper("keeper"))
    builder.fix_input(keeper.u, [1.0])
    builder.export_output(keeper.output_port("y"), "y")
    diagram = builder.build()
    simulator = cbbg.Simulator(diagram)
    simulator.add_log(diagram.output_port("y"), 0.01)
    simulator.advance_to(0.05)


simulate()
gc.collect()
uses = [lambda c: c.time, lambda c: c.input("u"), lambda c: c.discrete_state,
        lambda c: c.state("x"), lambda c: c.continuous_state, lambda c: c.parameter("k"),
        lambda c: c.random_normal(), lambda c: c.random_uniform()]
for context in (kept[0], kept[-1]):  # an output's, an update's
    for use in uses:
        try:
            use(context)
            print("no error")
        except RuntimeError as error:
            print(error)
"""


def test_a_context_kept_after_its_diagram_is_gone_refuses_every_use():
    done = run_python(KEPT_AFTER_ITS_DIAGRAM)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines() == [
        "block 'top/keeper': a context is valid only during the call it was given to"] * 16


def test_library_errors_cross_as_exceptions_with_their_messages():
    builder = cbbg.DiagramBuilder("top")
    counter = builder.add(Counter("counter"))
    scale = builder.add(Scale("scale", size=2))
    with pytest.raises(ValueError) as error:
        builder.connect(counter.output_port("n"), scale.input_port("u"))
    assert str(error.value) == (
        "connect: size mismatch: output 'top/counter.n' has size 1 but input 'top/scale.u' has "
        "size 2")
    with pytest.raises(ValueError, match="has no output port 'z'; its output ports are: n"):
        counter.output_port("z")
    with pytest.raises(ValueError, match="'top/scale.u' .size 2. is neither connected"):
        builder.build()


def test_a_block_belongs_to_one_diagram():
    first = cbbg.DiagramBuilder("first")
    counter = first.add(Counter("counter"))
    with pytest.raises(ValueError, match="block 'first/counter' is in a diagram already"):
        cbbg.DiagramBuilder("second").add(counter)


def test_a_diagram_keeps_its_python_blocks_and_lets_them_go_with_it():
    diagram, counter, scale = counter_diagram()
    watch = weakref.ref(counter)
    del counter, scale
    gc.collect()
    assert watch() is not None and diagram.block("counter") is watch()
    cbbg.Simulator(diagram).advance_to(0.05)
    del diagram
    gc.collect()
    assert watch() is None


def test_diagrams_nest_and_graphviz_names_python_types():
    inner, _, _ = counter_diagram()
    builder = cbbg.DiagramBuilder("outer")
    builder.add(inner)
    builder.export_output(inner.output_port("y"), "y")
    outer = builder.build()
    assert outer.block("top").block("counter").path == "outer/top/counter"
    dot = outer.to_dot()
    assert "Counter" in dot and "Scale" in dot
    assert cbbg.to_dot(outer, max_depth=0) != dot
