"""The toolbox from Python: primitives wired into diagrams and simulated, their errors, the
control helpers, and a block written in Python that reproduces a C++ one bit for bit."""

import math

import numpy as np
import pytest

import cbbg


def simulate(diagram, ports, period, duration, accuracy=1e-6):
    """Runs `diagram` for `duration` s and returns a log of each port, sampled every `period`
    (events at exactly `duration` are left for a next advance_to: simulator.h)."""
    simulator = cbbg.Simulator(diagram, cbbg.SimulatorOptions(accuracy=accuracy))
    logs = [simulator.add_log(port, period) for port in ports]
    simulator.initialize()
    simulator.advance_to(duration)
    return logs


# --- A PID loop built from primitives ------------------------------------------------------


def pid_loop_expected(kp, ki, kd, a, b, h, ticks):
    """x(t_k), k < ticks, of x' = -a x + b u under the PID of pid_controller.h with r = 1, in
    closed form: u_k is held over [t_k, t_{k+1}), so x_{k+1} = e^(-a h) x_k + b/a (1 - e^(-a h)) u_k."""
    decay = math.exp(-a * h)
    gain = b / a * (1.0 - decay)
    x, integral, previous_error = 0.0, 0.0, None
    xs = []
    for _ in range(ticks):
        xs.append(x)
        error = 1.0 - x
        derivative = 0.0 if previous_error is None else (error - previous_error) / h
        command = kp * error + ki * integral + kd * derivative
        integral += h * error
        previous_error = error
        x = decay * x + gain * command
    return np.array(xs)


def test_pid_loop_follows_the_closed_form():
    a, b, h, ticks = 2.0, 3.0, 0.01, 300
    params = cbbg.PidController.Params(kp=2.0, ki=1.5, kd=0.05)
    builder = cbbg.DiagramBuilder("loop")
    reference = builder.add(cbbg.StepSource("reference", 0.0, 1.0, 0.0))
    error = builder.add(cbbg.Adder("error", [("r", +1), ("y", -1)], 1))
    pid = builder.add(cbbg.PidController("pid", params, h))
    plant = builder.add(cbbg.LinearSystem("plant", [[-a]], [[b]], [[1.0]], [[0.0]]))
    builder.connect(reference, "y", error, "r")
    builder.connect(plant, "y", error, "y")
    builder.connect(error, "y", pid, "e")
    builder.connect(pid, "u", plant, "u")
    diagram = builder.build()

    (log,) = simulate(diagram, [plant.output_port("y")], h, ticks * h, accuracy=1e-10)

    assert isinstance(log.values, np.ndarray) and log.values.shape == (1, ticks)
    expected = pid_loop_expected(2.0, 1.5, 0.05, a, b, h, ticks)
    np.testing.assert_allclose(log.values[0], expected, rtol=0, atol=1e-8)
    np.testing.assert_allclose(log.times, h * np.arange(ticks), rtol=0, atol=1e-12)
    assert abs(log.values[0, -1] - 1.0) < 0.05  # the integral brings it to the reference


def test_first_order_low_pass_step_response():
    tau = 0.25
    builder = cbbg.DiagramBuilder("filter")
    step = builder.add(cbbg.ConstantSource("one", np.array([1.0, 2.0])))
    lag = builder.add(cbbg.FirstOrderLowPass("lag", tau, 2))
    builder.connect(step.output_port("y"), lag.input_port("u"))
    (log,) = simulate(builder.build(), [lag.output_port("y")], 0.05, 1.0, accuracy=1e-10)
    t = log.times
    np.testing.assert_allclose(log.values[0], 1.0 - np.exp(-t / tau), atol=1e-8)
    np.testing.assert_allclose(log.values[1], 2.0 * (1.0 - np.exp(-t / tau)), atol=1e-8)


def test_routing_blocks_take_tuples_and_objects():
    builder = cbbg.DiagramBuilder("routing")
    source = builder.add(cbbg.ConstantSource("source", [1.0, 2.0, 3.0]))
    split = builder.add(cbbg.Demultiplexer("split", [("a", 1), cbbg.Demultiplexer.Output("b", 2)]))
    join = builder.add(cbbg.Multiplexer("join", [("b", 2), cbbg.Multiplexer.Input("a", 1)]))
    pick = builder.add(cbbg.Selector("pick", 3, [2, 0]))
    scale = builder.add(cbbg.Gain("scale", np.array([[1.0, 10.0]])))
    builder.connect(source, "y", split, "u")
    builder.connect(split, "a", join, "a")
    builder.connect(split, "b", join, "b")
    builder.connect(join, "y", pick, "u")
    builder.connect(pick, "y", scale, "u")
    diagram = builder.build()
    context = diagram.create_context()
    np.testing.assert_array_equal(diagram.eval_output(context, join.output_port("y")), [2, 3, 1])
    np.testing.assert_array_equal(diagram.eval_output(context, pick.output_port("y")), [1, 2])
    assert diagram.eval_output(context, scale.output_port("y"))[0] == 21.0


def test_discrete_derivative_transient_enum():
    keep = cbbg.DiscreteDerivative.InitialTransient.KEEP
    block = cbbg.DiscreteDerivative("d", 1, 0.1, transient=keep)
    assert block.input_port("u").size == 1
    assert cbbg.DiscreteDerivative.InitialTransient.SUPPRESS != keep


# --- Errors keep their C++ messages --------------------------------------------------------


def test_gain_with_nan_is_a_value_error_with_the_message():
    with pytest.raises(ValueError) as raised:
        cbbg.Gain("g", np.array([[1.0, float("nan")]]))
    assert str(raised.value) == (
        "Gain 'g': matrix element (0, 1) is nan; every element must be finite")


def test_connect_of_mismatched_sizes():
    builder = cbbg.DiagramBuilder("d")
    source = builder.add(cbbg.ConstantSource("source", [1.0, 2.0]))
    gain = builder.add(cbbg.Gain("gain", 2.0, 3))
    with pytest.raises(ValueError, match=r"^connect: size mismatch: output 'd/source\.y' has size 2 "
                                         r"but input 'd/gain\.u' has size 3"):
        builder.connect(source.output_port("y"), gain.input_port("u"))


def test_unknown_port_name():
    gain = cbbg.Gain("gain", 2.0, 1)
    with pytest.raises(ValueError, match=r"^block 'gain' has no output port 'out'"):
        gain.output_port("out")


def test_constructor_checks_cross_as_value_errors():
    with pytest.raises(ValueError, match=r"^Saturation 'sat': lower limit 1 is above upper limit 0"):
        cbbg.Saturation("sat", 1.0, 0.0, 1)
    with pytest.raises(ValueError, match=r"^UnitDelay 'z': period 0 must be positive and finite"):
        cbbg.UnitDelay("z", 1, 0.0)
    with pytest.raises(ValueError, match=r"PidController 'pid'"):
        cbbg.PidController("pid", cbbg.PidController.Params(kp=-1.0), 0.01)
    with pytest.raises(ValueError, match=r"^Adder 'add'"):
        cbbg.Adder("add", [("r", 2)], 1)


def test_csv_sink_writes_rows(tmp_path):
    path = tmp_path / "out.csv"
    builder = cbbg.DiagramBuilder("sinks")
    ramp = builder.add(cbbg.RampSource("ramp", 2.0, 0.0))
    sink = builder.add(cbbg.CsvSink("sink", path, ["ramp"], 0.5))
    builder.connect(ramp, "y", sink, "ramp")
    simulate(builder.build(), [], 0.5, 1.25)
    sink.flush()
    assert sink.column_names == ["ramp"] and sink.num_rows == 3
    rows = np.loadtxt(path, delimiter=",", skiprows=2)
    np.testing.assert_array_equal(rows, [[0.0, 0.0], [0.5, 1.0], [1.0, 2.0]])


# --- cbbg.control ---------------------------------------------------------------------------


def test_lqr_of_a_double_integrator():
    A = np.array([[0.0, 1.0], [0.0, 0.0]])
    B = np.array([[0.0], [1.0]])
    result = cbbg.control.lqr(A, B, np.eye(2), np.array([[1.0]]))
    # The CARE's solution by hand: S = [[sqrt 3, 1], [1, sqrt 3]], K = B' S = [1, sqrt 3].
    np.testing.assert_allclose(result.K, [[1.0, math.sqrt(3.0)]], rtol=1e-12)
    np.testing.assert_allclose(result.S, [[math.sqrt(3.0), 1.0], [1.0, math.sqrt(3.0)]], rtol=1e-12)
    assert result.K.shape == (1, 2)


def test_discrete_lqr_and_riccati_residual():
    h = 0.1
    model = cbbg.control.c2d(np.array([[0.0, 1.0], [0.0, 0.0]]), np.array([[0.0], [1.0]]), h)
    np.testing.assert_allclose(model.A, [[1.0, h], [0.0, 1.0]], atol=1e-15)
    np.testing.assert_allclose(model.B, [[h * h / 2.0], [h]], atol=1e-15)
    assert model.is_discrete and model.time_period == h
    Q, R = np.eye(2), np.array([[1.0]])
    result = cbbg.control.discrete_lqr(model.A, model.B, Q, R)
    residual = cbbg.control.discrete_riccati_residual(model.A, model.B, Q, R, result.S)
    assert np.max(np.abs(residual)) < 1e-10
    assert np.max(np.abs(np.linalg.eigvals(model.A - model.B @ result.K))) < 1.0


def test_control_errors_cross_with_their_messages():
    with pytest.raises(ValueError):
        cbbg.control.lqr(np.eye(2), np.ones((3, 1)), np.eye(2), np.eye(1))


def test_linearize_gives_back_a_linear_system():
    A = np.array([[0.0, 1.0], [-2.0, -0.5]])
    B = np.array([[0.0], [1.0]])
    C = np.array([[1.0, 0.0]])
    D = np.array([[0.0]])
    builder = cbbg.DiagramBuilder("linearized")
    system = builder.add(cbbg.LinearSystem("system", A, B, C, D))
    builder.export_input(system.input_port("u"))
    builder.export_output(system.output_port("y"))
    diagram = builder.build()
    context = diagram.create_context()
    context.fix_input(diagram.input_port(0), np.zeros(1))
    model = cbbg.control.linearize(diagram, context)
    for got, want in ((model.A, A), (model.B, B), (model.C, C), (model.D, D)):
        np.testing.assert_allclose(got, want, atol=1e-9)
    assert not model.is_discrete


# --- A Python block against its C++ twin, bit for bit ----------------------------------------


def matrix_times(matrix, vector):
    """Each row's sum over the columns in order, from 0.0: what Eigen's matrix-vector kernel
    computes for these small column-major matrices (no FMA on the baseline x86-64 build)."""
    result = []
    for row in matrix:
        total = 0.0
        for element, value in zip(row, vector):
            total += element * value
        result.append(total)
    return result


class PythonDiscreteLinearSystem(cbbg.LeafBlock):
    """DiscreteLinearSystem written in Python, with discrete_linear_system.cc's order of
    operations: y = C x, then y += D u; next = A x, then next += B u (each product summed on
    its own before it is added)."""

    def __init__(self, name, A, B, C, D, initial_state, period):
        super().__init__(name)
        self.A, self.B, self.C, self.D = (np.asarray(m, dtype=float).tolist() for m in (A, B, C, D))
        self.u = self.declare_input_port("u", len(self.B[0]))
        self.declare_discrete_state("x", np.asarray(initial_state, dtype=float), per_trial=True)
        self.declare_output_port("y", len(self.C), self.calc_y, reads=[self.u])
        self.declare_periodic_update(period, 0.0, self.update)

    def calc_y(self, context, y):
        x = context.discrete_state.tolist()
        u = context.input(self.u).tolist()
        y[:] = [cx + du for cx, du in zip(matrix_times(self.C, x), matrix_times(self.D, u))]

    def update(self, context, next_state):
        x = context.discrete_state.tolist()
        u = context.input(self.u).tolist()
        next_state[:] = [ax + bu for ax, bu in zip(matrix_times(self.A, x), matrix_times(self.B, u))]


def test_python_block_matches_its_cpp_twin_bit_for_bit():
    # Values with no exact binary form, so every rounding shows; three states, two inputs and
    # two outputs, so that each sum has more than two terms and D feeds through.
    A = [[0.9, 0.1, -0.07], [-0.05, 0.95, 0.02], [0.013, 0.0, 0.8]]
    B = [[0.1, 0.0], [0.0, 0.2], [0.05, -0.03]]
    C = [[1.0, 0.5, -0.3], [0.0, 1.1, 0.7]]
    D = [[0.01, 0.0], [0.02, -0.01]]
    x0 = [0.1, -0.2, 0.3]
    h, ticks = 0.01, 1000

    builder = cbbg.DiagramBuilder("twins")
    sine = builder.add(cbbg.SineSource("sine", [1.0, 0.5], [2.0, 7.3], [0.0, 0.3], [0.0, 0.1]))
    native = builder.add(cbbg.DiscreteLinearSystem("native", A, B, C, D, x0, h))
    python = builder.add(PythonDiscreteLinearSystem("python", A, B, C, D, x0, h))
    builder.connect(sine, "y", native, "u")
    builder.connect(sine, "y", python, "u")
    diagram = builder.build()

    native_log, python_log = simulate(
        diagram, [native.output_port("y"), python.output_port("y")], h, ticks * h)

    assert native_log.num_samples == ticks  # t_0 ... t_999, each before that tick's update
    assert np.ptp(native_log.values, axis=1).min() > 0.1  # the signal moves: nothing trivial
    assert np.array_equal(python_log.times, native_log.times)
    assert np.array_equal(python_log.values, native_log.values)
