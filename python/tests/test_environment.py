"""The Gymnasium-style environment: its rollouts are the library's trials."""

from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import cbbg
from two_wheeler import RobotParams, TwoWheeler


def closed_loop_pitch(parameters, theta0, seed, ticks):
    """The pitch of the pd_only preset's closed loop at each tick, from C++ end to end."""
    loop = cbbg.build_preset("pd_only", parameters)
    context = loop.diagram.create_context(seed)
    loop.start_trial(context, theta0)
    simulator = cbbg.Simulator(loop.diagram, context,
                               cbbg.SimulatorOptions(accuracy=loop.accuracy))
    log = simulator.add_log(loop.plant.state_output, parameters["trial.period"])
    simulator.advance_to(ticks * parameters["trial.period"])
    return log.values[0]


def supervised_rollout(env, seed, theta0):
    """The environment played with info["supervisor_action"]: the true pitch at each tick."""
    observation, info = env.reset(seed=seed, options={"initial_pitch": theta0})
    pitch = [info["state"][0]]
    while True:
        observation, reward, terminated, truncated, info = env.step(info["supervisor_action"])
        if terminated or truncated:
            return np.array(pitch), terminated, truncated
        pitch.append(info["state"][0])


@pytest.mark.parametrize("settings", [{"plant.kind": "analytic"},
                                      {"plant.kind": "analytic", "sensors.noise_std": [0.01] * 6}])
def test_a_rollout_under_the_pd_law_is_the_closed_loops_trial_to_1e_12(settings):
    parameters = cbbg.parameters(settings)
    env = cbbg.BalanceEnv(parameters)
    pitch, terminated, truncated = supervised_rollout(env, seed=3, theta0=0.15)
    assert truncated and not terminated
    assert len(pitch) == 2000
    expected = closed_loop_pitch(parameters, 0.15, seed=3, ticks=2000)
    assert np.max(np.abs(pitch - expected)) <= 1e-12


def test_the_simbody_robot_steps_too():
    env = cbbg.BalanceEnv({"plant.kind": "simbody", "trial.duration": 0.2})
    observation, info = env.reset(seed=1)
    steps = 0
    while True:
        observation, reward, terminated, truncated, info = env.step(info["supervisor_action"])
        steps += 1
        if terminated or truncated:
            break
    assert (steps, truncated) == (20, True)
    assert info["signal_names"][0] == "pitch"


def test_a_python_plant_is_the_environments_robot():
    env = cbbg.BalanceEnv({"plant.kind": "analytic", "trial.duration": 0.5},
                          plant=lambda name, p: TwoWheeler(name, RobotParams.of(p)))
    observation, info = env.reset(seed=1, options={"initial_pitch": 0.1})
    observation, reward, terminated, truncated, info = env.step(np.array([0.0]))
    assert info["time"] == pytest.approx(0.01)
    assert observation[0] > 0.1  # it falls forward while nothing holds it


def test_the_spaces_and_the_episode_end():
    env = cbbg.BalanceEnv({"plant.kind": "analytic"})
    assert env.action_space.shape == (1,)
    np.testing.assert_array_equal(env.action_space.high, [5.0])
    assert env.observation_space.shape == (6,)
    assert env.failure_angle == pytest.approx(0.5236)
    observation, info = env.reset(seed=2, options={"initial_pitch": 0.3})
    assert env.observation_space.contains(observation)
    for _ in range(1000):
        observation, reward, terminated, truncated, info = env.step(0.0)
        if terminated:
            break
    assert terminated and reward == -1.0 and info["failure_reason"]
    # The last observation lies beyond the failure angle, and in the observation space.
    assert abs(observation[0]) > env.failure_angle
    assert observation in env.observation_space
    with pytest.raises(RuntimeError, match="the episode has ended .terminated or truncated.; call "
                                           "reset.. to start another"):
        env.step(0.0)
    with pytest.raises(ValueError, match="unknown option.s. \\['angle'\\]; allowed: initial_pitch"):
        env.reset(options={"angle": 0.1})
    env.reset()
    with pytest.raises(ValueError, match="the action must be a finite torque in N m; got nan"):
        env.step(float("nan"))
    with pytest.raises(ValueError, match="the action is one torque"):
        env.step([1.0, 2.0])


@pytest.mark.parametrize("action, what", [
    (1 + 2j, "complex (1+2j)"),
    (np.complex128(0.5), "complex128 (0.5+0j)"),
    (np.array([0.5 + 0j]), "an array of complex128 array([0.5+0.j])"),
    ("0.5", "str '0.5'"),
    ([0.5j], "list [0.5j]"),
    (None, "NoneType None"),
])
def test_an_action_that_is_no_real_number_is_refused_not_converted(action, what):
    env = cbbg.BalanceEnv({"plant.kind": "analytic"})
    env.reset(seed=1)
    with pytest.raises(TypeError) as error:
        env.step(action)
    assert str(error.value) == ("step: the action is one torque, N m: a real number or an array "
                                f"of one real number; got {what}")


def test_real_actions_of_every_kind_step():
    env = cbbg.BalanceEnv({"plant.kind": "analytic"})
    observations = []
    for action in (0.5, np.float32(0.5), np.array([0.5]), [0.5], Fraction(1, 2)):
        env.reset(seed=1, options={"initial_pitch": 0.1})
        observations.append(env.step(action)[0])
    for observation in observations[1:]:
        np.testing.assert_array_equal(observation, observations[0])


def test_the_same_seed_gives_the_same_episode():
    env = cbbg.BalanceEnv({"plant.kind": "analytic", "sensors.noise_std": [0.01] * 6,
                           "trial.duration": 1.0})
    first, _, _ = supervised_rollout(env, seed=5, theta0=0.1)
    second, _, _ = supervised_rollout(env, seed=5, theta0=0.1)
    other, _, _ = supervised_rollout(env, seed=6, theta0=0.1)
    np.testing.assert_array_equal(first, second)
    assert not np.array_equal(first, other)


def mujoco_parameters(settings):
    """cbbg.parameters on the MuJoCo plant; skipped in a build without MuJoCo."""
    try:
        return cbbg.parameters({"plant.kind": "mujoco", **settings})
    except ValueError as error:
        if "plant.kind must be one of" not in str(error):
            raise
        pytest.skip(f"a build without MuJoCo: {error}")


def test_the_mujoco_robot_is_the_closed_loops_trial():
    parameters = mujoco_parameters({"trial.duration": 2.0})
    env = cbbg.BalanceEnv(parameters)
    pitch, terminated, truncated = supervised_rollout(env, seed=2, theta0=0.15)
    assert truncated and not terminated
    expected = closed_loop_pitch(parameters, 0.15, seed=2, ticks=200)
    assert np.max(np.abs(pitch - expected)) <= 1e-12


def test_a_model_files_robot_steps_with_its_own_signals():
    model = Path(__file__).resolve().parents[2] / "examples" / "mujoco" / "reaction_wheel.xml"
    parameters = mujoco_parameters({"mujoco.model": str(model), "mujoco.actuators": ["motor"],
                                    "mujoco.body": "rod", "trial.duration": 0.5})
    env = cbbg.BalanceEnv(parameters)
    observation, info = env.reset(seed=1)
    assert info["signal_names"] == ["pitch", "pitch_rate", "wheel", "wheel_rate"]
    pitch, terminated, truncated = supervised_rollout(env, seed=1, theta0=0.1)
    assert truncated and not terminated
    assert abs(pitch[-1]) < abs(pitch[0])  # the paper's PD law holds it up
