"""The vectorised environment: each of its environments is a BalanceEnv seeded seed + i,
stepped in C++ threads with Gymnasium 1.x's autoreset; and both environments pass the
Gymnasium contract (gymnasium_contract.py)."""

import pickle

import numpy as np
import pytest

import cbbg
from gymnasium_contract import check_box, check_env, check_vector_env

SHORT = {"plant.kind": "analytic", "trial.duration": 0.3}


def test_the_environment_passes_gymnasiums_contract():
    check_env(cbbg.BalanceEnv({"plant.kind": "analytic", "trial.duration": 2.0},
                              render_mode="rgb_array"))


def test_the_vector_environment_passes_gymnasiums_contract():
    check_vector_env(cbbg.VecBalanceEnv(4, {"plant.kind": "analytic", "trial.duration": 0.2}))


def test_each_environment_is_a_single_one_seeded_seed_plus_its_index():
    envs = cbbg.VecBalanceEnv(3, {**SHORT, "sensors.noise_std": [0.01] * 6}, threads=2)
    singles = [cbbg.BalanceEnv({**SHORT, "sensors.noise_std": [0.01] * 6}) for _ in range(3)]
    observations, infos = envs.reset(seed=10)
    alone = [env.reset(seed=10 + i) for i, env in enumerate(singles)]
    for i in range(3):
        np.testing.assert_array_equal(observations[i], alone[i][0])
        assert infos["supervisor_action"][i] == alone[i][1]["supervisor_action"]
    for _ in range(30):  # 30 steps of 0.3 s episodes: one truncation each
        observations, rewards, terminated, truncated, infos = envs.step(infos["supervisor_action"])
        for i, env in enumerate(singles):
            if infos["autoreset"][i]:
                expected = env.reset()
                np.testing.assert_array_equal(observations[i], expected[0])
                assert rewards[i] == 0.0 and not terminated[i] and not truncated[i]
                alone[i] = expected
                continue
            step = env.step(alone[i][1]["supervisor_action"])
            np.testing.assert_array_equal(observations[i], step[0])
            assert (rewards[i], terminated[i], truncated[i]) == step[1:4]
            alone[i] = (step[0], step[4])
    assert np.all(truncated), "each episode ran out its 0.3 s at the 30th step"


def test_an_ended_episode_is_reset_at_the_next_step_and_its_action_ignored():
    envs = cbbg.VecBalanceEnv(2, SHORT)
    envs.reset(seed=1)
    for _ in range(30):
        observations, rewards, terminated, truncated, infos = envs.step(np.zeros(2))
    assert np.all(truncated) and not np.any(infos["autoreset"])
    final = observations.copy()
    after, rewards, terminated, truncated, infos = envs.step(np.array([5.0, -5.0]))
    assert np.all(infos["autoreset"]) and np.all(rewards == 0.0)
    assert not np.any(terminated | truncated)
    assert np.all(infos["time"] == 0.0) and not np.array_equal(after, final)
    # The ignored actions acted on nothing: both start where a reset starts them.
    np.testing.assert_array_equal(after[0, 0], after[1, 0])


@pytest.mark.parametrize("threads", [1, 2, 3])
def test_the_same_bytes_with_any_number_of_threads(threads):
    def run(threads):
        envs = cbbg.VecBalanceEnv(5, {"plant.kind": "analytic", "trial.duration": 0.5,
                                      "sensors.noise_std": [0.02] * 6},
                                  threads=threads, initial_pitch=(-0.3, 0.3))
        observations, infos = envs.reset(seed=4)
        trace = [observations]
        for step in range(120):
            observations, *_ = envs.step(np.sin(np.arange(5) + step / 5.0) * 4.0)
            trace.append(observations)
        return np.array(trace)

    assert cbbg.VecBalanceEnv(5, SHORT, threads=threads).threads == threads
    np.testing.assert_array_equal(run(threads), run(1))


def test_the_reset_distribution_draws_from_the_seed():
    env = cbbg.BalanceEnv(SHORT)
    theta0 = cbbg.parameters(SHORT)["trial.theta0"]  # the paper's fixed angle, by default
    assert {env.reset(seed=s)[1]["state"][0] for s in range(4)} == {theta0}
    spread = cbbg.BalanceEnv(SHORT, initial_pitch=(-0.2, 0.2))
    pitches = [spread.reset(seed=s)[1]["state"][0] for s in range(20)]
    assert len(set(pitches)) == 20 and all(-0.2 <= p <= 0.2 for p in pitches)
    assert spread.reset(seed=3)[1]["state"][0] == pitches[3]
    assert spread.reset(seed=3, options={"initial_pitch": 0.05})[1]["state"][0] == 0.05
    with pytest.raises(ValueError, match="strictly inside"):
        cbbg.BalanceEnv(SHORT, initial_pitch=(-0.2, 0.9))
    with pytest.raises(ValueError, match="low <= high"):
        cbbg.VecBalanceEnv(2, SHORT, initial_pitch=(0.2, -0.2))


def test_the_supervisors_action_lies_in_the_action_space():
    env = cbbg.BalanceEnv(SHORT)
    observation, info = env.reset(seed=1, options={"initial_pitch": 0.4})
    assert info["supervisor_action"] == env.action_space.high[0]  # saturated: 50 x 0.4 > 5


def test_bad_actions_and_calls_are_refused_in_one_line():
    envs = cbbg.VecBalanceEnv(3, SHORT)
    with pytest.raises(RuntimeError, match="no episode has started; call reset"):
        envs.step(np.zeros(3))
    envs.reset(seed=1)
    with pytest.raises(ValueError, match=r"the actions must have shape \(3,\) or \(3, 1\); got \(2,\)"):
        envs.step(np.zeros(2))
    with pytest.raises(ValueError, match="action 1 must be a finite torque in N m; got nan"):
        envs.step(np.array([0.0, np.nan, 0.0]))
    with pytest.raises(TypeError, match="an array of real numbers"):
        envs.step(np.array(["a", "b", "c"]))
    with pytest.raises(TypeError, match="an array of real numbers"):
        envs.step(np.zeros(3) + 1j)
    envs.step(np.zeros((3, 1)))
    with pytest.raises(ValueError, match="num_envs must be at least 1; got 0"):
        cbbg.VecBalanceEnv(0, SHORT)
    envs.close()
    with pytest.raises(RuntimeError, match="closed"):
        envs.reset()


def test_a_vector_environment_pickles_as_its_configuration():
    envs = cbbg.VecBalanceEnv(2, SHORT, initial_pitch=(-0.1, 0.1))
    copy = pickle.loads(pickle.dumps(envs))
    assert copy.num_envs == 2 and copy.action_space == envs.action_space
    np.testing.assert_array_equal(copy.reset(seed=2)[0], envs.reset(seed=2)[0])


def test_a_python_plant_steps_in_the_vector_environment():
    from two_wheeler import RobotParams, TwoWheeler

    envs = cbbg.VecBalanceEnv(2, SHORT, plant=lambda name, p: TwoWheeler(name, RobotParams.of(p)))
    observations, infos = envs.reset(seed=1)
    observations, *_ = envs.step(infos["supervisor_action"])
    assert observations.shape == (2, 6) and np.all(np.isfinite(observations))


def test_box_follows_gymnasiums_rules():
    box = cbbg.Box([-1.0, -np.inf], [1.0, np.inf])
    check_box(box)
    assert [0.5, 1e9] in box and [2.0, 0.0] not in box
    assert repr(box) == "Box(-inf, inf, (2,), float64)"


def planar_model(parameters):
    """A linearisation of the upright robot for a Python plant kind (x = (pitch, wheel angle,
    their rates), u the torque): an inverted pendulum on a wheel, near enough for LQR."""
    a = np.zeros((4, 4))
    a[0, 2] = a[1, 3] = 1.0
    a[2, 0], a[3, 0] = 30.0, -8.0
    return a, np.array([[0.0], [0.0], [-6.0], [20.0]])


def test_a_python_plant_kind_offers_its_linearisation_to_the_lqr_supervisor():
    from two_wheeler import RobotParams, TwoWheeler

    def plant(name, p):
        return TwoWheeler(name, RobotParams.of(p))

    cbbg.register_plant_kind("linear_numpy", "the NumPy two-wheeler with its linearisation", plant,
                             linearize=planar_model, replace=True)
    env = cbbg.BalanceEnv({"plant.kind": "linear_numpy", "supervisor.kind": "lqr",
                           "trial.duration": 0.1})
    observation, info = env.reset(seed=1)
    assert np.isfinite(info["supervisor_action"]) and info["supervisor_action"] != 0.0
    cbbg.register_plant_kind("linear_numpy", "a wrong linearisation", plant,
                             linearize=lambda p: (np.eye(3), np.ones((3, 1))), replace=True)
    with pytest.raises(ValueError, match="plant kind 'linear_numpy': linearize must return finite "
                                         r"A \(4 x 4\) and B \(4 x 1\)"):
        cbbg.BalanceEnv({"plant.kind": "linear_numpy", "supervisor.kind": "lqr"})
    cbbg.unregister_plant_kind("linear_numpy")


def test_a_plant_kinds_torque_limit_is_the_action_space():
    from two_wheeler import RobotParams, TwoWheeler

    cbbg.register_plant_kind("limited_numpy", "the NumPy two-wheeler, 3 N m motors",
                             lambda name, p: TwoWheeler(name, RobotParams.of(p)),
                             torque_limit=lambda p: 3.0, replace=True)
    settings = {"plant.kind": "limited_numpy", "trial.duration": 0.1}
    env = cbbg.BalanceEnv(settings)
    assert list(env.action_space.high) == [3.0] and list(env.action_space.low) == [-3.0]
    assert env.reset(seed=1, options={"initial_pitch": 0.4})[1]["supervisor_action"] == 3.0
    assert cbbg.VecBalanceEnv(2, settings).single_action_space == env.action_space
    cbbg.register_plant_kind("limited_numpy", "a wrong limit",
                             lambda name, p: TwoWheeler(name, RobotParams.of(p)),
                             torque_limit=lambda p: -1.0, replace=True)
    with pytest.raises(ValueError, match="plant kind 'limited_numpy': its torque limit must be a "
                                         "finite number > 0, N m; got -1"):
        cbbg.BalanceEnv(settings)
    cbbg.unregister_plant_kind("limited_numpy")


def test_settings_of_another_type_are_refused_in_cbbgs_words():
    with pytest.raises(TypeError, match=r"settings are a dict of config keys .* or None; got int 5"):
        cbbg.BalanceEnv(5)
    assert cbbg.BalanceEnv(cbbg.Config({"plant.kind": "analytic"})).period == 0.01
