"""The library's blocks and plants from Python, and their params structs, bound from the keys
each struct declares in C++."""

import math

import numpy as np
import pytest

import cbbg


def evaluate(block, input_name, value, output_name):
    """The output of `block` with `value` on its input, in a diagram of its own."""
    builder = cbbg.DiagramBuilder("harness")
    source = builder.add(cbbg.ConstantSource("source", np.asarray(value, dtype=float)))
    builder.add(block)
    builder.connect(source, "y", block, input_name)
    diagram = builder.build()
    return diagram.eval_output(diagram.create_context(), block.output_port(output_name))


# --- Params structs -------------------------------------------------------------------------


def test_keyword_constructor_sets_keys_and_keeps_defaults():
    params = cbbg.PdSupervisorParams(k_theta=40.0, k_dphi=2)
    assert params.k_theta == 40.0 and params.k_dphi == 2.0
    assert params.k_dtheta == 10.0 and params.k_phi == 1.0  # the C++ defaults
    assert params.to_dict() == {"k_theta": 40.0, "k_dtheta": 10.0, "k_phi": 1.0, "k_dphi": 2.0}
    assert repr(params) == "PdSupervisorParams(k_theta=40.0, k_dtheta=10.0, k_phi=1.0, k_dphi=2.0)"
    assert params == cbbg.PdSupervisorParams(k_theta=40.0, k_dphi=2.0)
    params.k_phi = 3.5
    assert params.k_phi == 3.5


def test_unknown_keyword_names_it_and_lists_the_keys():
    with pytest.raises(ValueError) as raised:
        cbbg.PdSupervisorParams(k_thta=1.0)
    assert str(raised.value) == (
        "PdSupervisorParams: unknown keyword 'k_thta'; the keys are k_theta, k_dtheta, k_phi, "
        "k_dphi")


def test_wrong_types_and_lengths_are_refused():
    with pytest.raises(TypeError, match=r"^CriticParams\.beta takes a number, got str 'fast'"):
        cbbg.CriticParams(beta="fast")
    with pytest.raises(ValueError, match=r"^SensorsParams\.noise_std takes 6 numbers, got 3"):
        cbbg.SensorsParams(noise_std=[0.1, 0.1, 0.1])
    with pytest.raises(TypeError, match=r"^CriticParams\.frozen takes True or False"):
        cbbg.CriticParams(frozen=1)


def test_choices_are_their_words():
    actor = cbbg.ActorParams(rule="weighted", frozen=True)
    assert actor.rule == "weighted" and actor.frozen is True
    with pytest.raises(ValueError, match=r"^ActorParams\.rule must be one of improved, weighted; "
                                         r"got 'best'"):
        actor.rule = "best"
    assert cbbg.OmegaParams(mode="constant", constant=0.25).to_dict() == {
        "n2": 500.0, "n3": 200.0, "mode": "constant", "constant": 0.25}
    assert cbbg.RobotParams().simbody_integrator == "merson"


def test_lists_of_numbers():
    rbf = cbbg.RbfParams(centres=np.linspace(-1.0, 1.0, 3))
    assert rbf.centres == [-1.0, 0.0, 1.0]
    assert cbbg.LqrSupervisorParams().lqr_q == [100.0, 1.0, 1.0, 1.0]


def test_ranges_are_checked_by_validate_and_by_the_block():
    params = cbbg.CriticParams(gamma=1.5)
    with pytest.raises(ValueError, match=r"^critic\.gamma must be in \(0, 1\]; got 1\.5$"):
        params.validate()
    with pytest.raises(ValueError, match=r"^critic\.gamma must be in \(0, 1\]; got 1\.5$"):
        cbbg.Critic("critic", 4, params, 0.01)
    with pytest.raises(ValueError, match=r"^supervisor\.k_theta must be finite; got nan$"):
        cbbg.PdSupervisor("pd", cbbg.PdSupervisorParams(k_theta=float("nan")))


# --- Blocks ---------------------------------------------------------------------------------


def test_pd_supervisor_gives_the_pd_law():
    params = cbbg.PdSupervisorParams(k_theta=50.0, k_dtheta=10.0, k_phi=1.5, k_dphi=0.5)
    theta, theta_dot, phi_l, phi_r, phi_l_dot, phi_r_dot = 0.1, -0.3, 0.7, 0.5, 2.0, 1.0
    action = evaluate(cbbg.PdSupervisor("pd", params), "measured",
                      [theta, theta_dot, phi_l, phi_r, phi_l_dot, phi_r_dot], "action")
    expected = (50.0 * theta + 10.0 * theta_dot + 1.5 * (phi_l + phi_r) / 2.0
                + 0.5 * (phi_l_dot + phi_r_dot) / 2.0)
    assert action.shape == (1,)
    assert action[0] == expected  # the same operations in the same order


def test_lqr_supervisor_gain_is_control_lqr_of_the_linearised_robot():
    robot = cbbg.RobotParams()
    params = cbbg.LqrSupervisorParams(lqr_q=[10.0, 1.0, 2.0, 3.0], lqr_r=0.5)
    model = cbbg.linearize_planar_upright(robot)
    expected = cbbg.control.lqr(model.A, model.B, np.diag(params.lqr_q), [[params.lqr_r]]).K[0]
    np.testing.assert_allclose(cbbg.LqrSupervisor("lqr", robot, params).gain, expected, rtol=1e-9)
    np.testing.assert_allclose(cbbg.LqrSupervisor("lqr", model, params).gain, expected, rtol=1e-9)


def test_normaliser_and_features():
    params = cbbg.NormaliserParams(scale_theta=0.1, scale_dtheta=0.5, saturation=3.0)
    normaliser = cbbg.Normaliser("normaliser", params)
    x = evaluate(normaliser, "measured", [0.05, 10.0, 0, 0, 0, 0], "x")
    np.testing.assert_array_equal(x, [0.05 / 0.1, 3.0])  # the rate clamped to the grid
    assert normaliser.layout()["normaliser.scale_theta"] == [0.1]

    features = cbbg.RbfFeatures("rbf", cbbg.RbfParams(centres=[-1.0, 0.0, 1.0], width=0.5))
    assert features.num_features == 9
    phi = evaluate(features, "x", [0.0, 1.0], "features")
    assert phi[1 * 3 + 2] == 1.0  # the unit at (c_1, c_2) = (0, 1)
    assert phi[0] == pytest.approx(math.exp(-(1.0 + 4.0) / (2 * 0.25)))  # the unit at (-1, -1)


def test_learners_weights_and_schedules():
    critic = cbbg.Critic("critic", 4, cbbg.CriticParams(), 0.01)
    builder = cbbg.DiagramBuilder("learners")
    builder.add(critic)
    for port in ("features", "reward", "failed"):
        builder.export_input(critic.input_port(port))
    diagram = builder.build()
    context = diagram.create_context()
    np.testing.assert_array_equal(critic.weights(context), np.zeros(4))
    critic.set_weights(context, [1.0, 2.0, 3.0, 4.0])
    np.testing.assert_array_equal(critic.weights(context), [1.0, 2.0, 3.0, 4.0])
    with pytest.raises(ValueError, match=r"has 4 weights, got 2"):
        critic.set_weights(context, [1.0, 2.0])

    omega = cbbg.OmegaSchedule("omega", cbbg.OmegaParams(n2=10.0, n3=5.0), 0.01)
    assert omega.omega_at(5.0) == 0.0
    assert omega.omega_at(15.0) == pytest.approx(1.0 - math.exp(-1.0))
    assert evaluate(cbbg.Tropism("tropism", cbbg.TropismParams(k1=10.0, k2=0.1)), "value", [0.0],
                    "temperature")[0] == 5.0


def run_block(block, inputs, output_name, ticks, seed=7):
    """The output `output_name` of `block`, its inputs held at `inputs` (name -> value), after
    each of `ticks` ticks of 0.01 s under root seed `seed`; and the last context."""
    builder = cbbg.DiagramBuilder("loop")
    builder.add(block)
    for name, value in inputs.items():
        source = builder.add(cbbg.ConstantSource(name + "_source", np.asarray(value, dtype=float)))
        builder.connect(source, "y", block, name)
    diagram = builder.build()
    simulator = cbbg.Simulator(diagram, seed=seed)
    values = []
    for t in range(ticks):
        simulator.advance_to((t + 0.5) * 0.01)
        values.append(diagram.eval_output(simulator.context, block.output_port(output_name))[0])
    return values, simulator.context


def test_the_alternatives_keys_default_to_the_papers():
    assert cbbg.ExplorationParams().to_dict() == {
        "kind": "boltzmann", "sigma": 1.58, "half_life": 0.0, "ou_theta": 5.0}
    critic = cbbg.CriticParams()
    assert list(critic.to_dict())[0] == "kind" and list(critic.to_dict())[-2:] == [
        "epsilon", "frozen"]
    assert critic.kind == "td_lambda" and critic.epsilon == 0.001
    reward = cbbg.RewardParams()
    assert reward.kind == "sliding" and reward.q == [1.0, 0.1, 0.0]
    assert cbbg.TropismParams().kind == "value"
    with pytest.raises(ValueError, match=r"^ExplorationParams\.kind must be one of boltzmann, "
                                         r"gaussian, ou; got 'normal'"):
        cbbg.ExplorationParams(kind="normal")
    with pytest.raises(ValueError, match=r"^exploration\.half_life must be finite and >= 0; "
                                         r"got -1$"):
        cbbg.GaussianExploration("sampler", cbbg.ExplorationParams(half_life=-1.0), 0.01)
    with pytest.raises(ValueError, match=r"^reward\.q must be a list of 3 numbers .*; got a list "
                                         r"of 2$"):
        cbbg.QuadraticReward("reward", cbbg.RewardParams(kind="quadratic", q=[1.0, 0.1]), 0.01)


def test_exploration_alternatives_draw_the_samplers_numbers():
    # At the same path and seed the three kinds see the same eps: with sigma = 1 the Gaussian
    # is the Boltzmann sampler at K_B T / 2 = 1, and an OU process that forgets at once.
    boltzmann, _ = run_block(cbbg.BoltzmannSampler("sampler", cbbg.SamplerParams(), 0.01),
                             {"actor_action": [0.5], "temperature": [2.0]},
                             "exploration_action", 50)
    gaussian, _ = run_block(
        cbbg.GaussianExploration("sampler", cbbg.ExplorationParams(kind="gaussian", sigma=1.0),
                                 0.01),
        {"actor_action": [0.5]}, "exploration_action", 50)
    forgetful, _ = run_block(
        cbbg.OuExploration("sampler", cbbg.ExplorationParams(kind="ou", sigma=1.0, ou_theta=1e6),
                           0.01),
        {"actor_action": [0.5]}, "exploration_action", 50)
    assert gaussian == boltzmann and forgetful == gaussian
    assert len(set(gaussian)) == 50  # a fresh draw at every tick

    annealed = cbbg.GaussianExploration(
        "sampler", cbbg.ExplorationParams(kind="gaussian", sigma=2.0, half_life=0.05), 0.01)
    assert annealed.sigma_at(0.05) == 1.0 and annealed.sigma_at(0.1) == 0.5
    _, context = run_block(annealed, {"actor_action": [0.0]}, "exploration_action", 5)
    assert annealed.elapsed(context) == pytest.approx(0.05, abs=1e-12)
    assert [part.name for part in annealed.discrete_state_parts] == ["noise", "elapsed"]


def test_td0_critic_quadratic_reward_and_fixed_temperature():
    critic = cbbg.Critic("critic", 4, cbbg.CriticParams(kind="td0", epsilon=0.5), 0.01)
    assert critic.num_features == 4
    builder = cbbg.DiagramBuilder("learners")
    builder.add(critic)
    for port in ("features", "reward", "failed"):
        builder.export_input(critic.input_port(port))
    diagram = builder.build()
    context = diagram.create_context()
    critic.set_weights(context, [1.0, 2.0, 3.0, 4.0])
    np.testing.assert_array_equal(critic.weights(context), [1.0, 2.0, 3.0, 4.0])
    assert [part.name for part in critic.discrete_state_parts] == [
        "weights", "previous_features", "has_previous"]

    reward = cbbg.QuadraticReward("reward", cbbg.RewardParams(kind="quadratic", q=[2.0, 0.5, 0.25]),
                                  0.01)
    values, _ = run_block(reward, {"measured": [0.1, 0.2, 0.0, 0.0, 1.0, 3.0], "failed": [0.0]},
                          "reward", 1)
    assert values[0] == pytest.approx(-(2.0 * 0.01 + 0.5 * 0.04 + 0.25 * 4.0), abs=1e-15)

    fixed = cbbg.Tropism("tropism", cbbg.TropismParams(k1=10.0, kind="fixed"))
    for value in (-30.0, 0.0, 30.0):
        assert evaluate(fixed, "value", [value], "temperature")[0] == 5.0


# --- Plants ---------------------------------------------------------------------------------


def falling_pitch(plant, duration, push=None):
    """The pitch of `plant` after `duration` s without torque, integrated to 1e-9; `push`, a
    cbbg.PushParams, drives its input "disturbance" through an ExternalPush."""
    builder = cbbg.DiagramBuilder("fall")
    torque = builder.add(cbbg.ConstantSource("torque", [0.0, 0.0]))
    builder.add(plant)
    builder.connect(torque, "y", plant, "torque")
    if push is not None:
        pusher = builder.add(cbbg.ExternalPush("push", push, 0.01))
        builder.connect(pusher, "disturbance", plant, "disturbance")
    diagram = builder.build()
    simulator = cbbg.Simulator(diagram, cbbg.SimulatorOptions(accuracy=1e-9))
    simulator.initialize()
    simulator.advance_to(duration)
    return diagram.eval_output(simulator.context, plant.output_port("state"))[0]


def test_plants_are_robot_plants_that_fall_alike():
    robot = cbbg.RobotParams(accuracy=1e-9)
    analytic = cbbg.AnalyticPlant("robot", robot, initial_pitch=0.1)
    simbody = cbbg.SimbodyPlant("robot", robot, initial_pitch=0.1)
    for plant in (analytic, simbody):
        assert isinstance(plant, cbbg.RobotPlant)
        assert plant.signals()[:2] == ["pitch", "pitch_rate"]
        assert plant.wheel_radius() == robot.wheel_radius
        assert plant.params == robot
    pitch = falling_pitch(analytic, 0.2)
    assert pitch > 0.1  # it falls forward
    assert falling_pitch(simbody, 0.2) == pytest.approx(pitch, abs=1e-6)


def test_plants_take_a_push_from_outside_alike():
    robot = cbbg.RobotParams(accuracy=1e-9)
    push = cbbg.PushParams(force=-30.0, pitch_torque=0.5, start=0.0, duration=0.1)
    pitches = [falling_pitch(kind("robot", robot, initial_pitch=0.1, disturbance_input=True),
                             0.2, push) for kind in (cbbg.AnalyticPlant, cbbg.SimbodyPlant)]
    assert pitches[1] == pytest.approx(pitches[0], abs=1e-6)
    # Pushed backwards at the centre of mass, it leans forward less than it falls alone.
    assert pitches[0] < falling_pitch(cbbg.AnalyticPlant("robot", robot, initial_pitch=0.1), 0.2)
    assert "disturbance" not in [port.name for port in
                                 cbbg.AnalyticPlant("robot", robot).input_ports]


def test_sensors_read_the_plant_state():
    sensors = cbbg.Sensors("sensors", cbbg.SensorsParams(), 0.01)
    state = np.arange(10.0) / 10.0
    measured = evaluate(sensors, "plant_state", state, "measured")
    np.testing.assert_array_equal(measured, state[:6])
    assert cbbg.two_wheeler_index().pitch == 0
