"""Gymnasium's contract, checked without Gymnasium (Debian does not ship it): the rules its
documentation states for gymnasium.Env, gymnasium.vector.VectorEnv and gymnasium.spaces.Box,
written out one by one, so that an agent written for Gymnasium runs on cbbg's environments."""

import pickle
from numbers import Real

import numpy as np


def check_box(space):
    """gymnasium.spaces.Box: shape and dtype, low <= high, sample() inside, contains() and `in`
    agree, seed() makes sample() repeat, and what is not a real array of its shape is out."""
    assert isinstance(space.shape, tuple) and space.low.shape == space.high.shape == space.shape
    assert space.dtype == np.float64 and space.low.dtype == space.high.dtype == space.dtype
    assert np.all(space.low <= space.high)
    space.seed(7)
    first = [space.sample() for _ in range(5)]
    space.seed(7)
    assert all(np.array_equal(a, space.sample()) for a in first)
    for sample in first:
        assert sample.dtype == space.dtype and sample.shape == space.shape
        assert space.contains(sample) and sample in space
    assert not space.contains(np.zeros(space.shape + (1,)))
    assert not space.contains(np.full(space.shape, 1 + 2j))
    assert not space.contains("text")
    assert isinstance(space.np_random, np.random.Generator)


def _check_info(info):
    assert isinstance(info, dict)


def _check_step(env, result):
    observation, reward, terminated, truncated, info = result
    assert observation in env.observation_space, observation
    assert isinstance(reward, Real) and not isinstance(reward, bool)
    assert isinstance(terminated, bool) and isinstance(truncated, bool)
    _check_info(info)
    return terminated or truncated


def rollout(env, seed, actions):
    """The observations of an episode from reset(seed) under `actions` (a function of the
    step), until it ends."""
    observation, info = env.reset(seed=seed)
    observations = [observation]
    for step in range(10_000):
        observation, reward, terminated, truncated, info = env.step(actions(step))
        observations.append(observation)
        if terminated or truncated:
            break
    return np.array(observations)


def check_env(env, make_copy=None):
    """gymnasium.Env: the spaces, reset's and step's tuples and types, observations inside the
    observation space (the last one of an episode too), the action space's samples accepted,
    determinism under a seed, np_random, the end of an episode, render, close, pickling."""
    check_box(env.observation_space)
    check_box(env.action_space)
    observation, info = env.reset(seed=3)
    assert observation in env.observation_space
    assert observation.dtype == env.observation_space.dtype
    _check_info(info)
    assert isinstance(env.np_random, np.random.Generator)
    env.action_space.seed(3)
    ended = False
    for _ in range(10_000):
        ended = _check_step(env, env.step(env.action_space.sample()))
        if ended:
            break
    assert ended, "an episode of random actions ends (falls or runs out of time)"
    first = rollout(env, 11, lambda step: 0.3 * np.sin(step / 7.0))
    second = rollout(env, 11, lambda step: 0.3 * np.sin(step / 7.0))
    assert np.array_equal(first, second), "the same seed and actions give the same episode"
    if env.render_mode == "rgb_array":
        env.reset(seed=1)
        image = env.render()
        assert image.dtype == np.uint8 and image.ndim == 3 and image.shape[2] == 3
    copy = pickle.loads(pickle.dumps(env))
    assert copy.observation_space == env.observation_space
    assert copy.action_space == env.action_space
    assert np.array_equal(rollout(copy, 11, lambda step: 0.3 * np.sin(step / 7.0)), first)
    env.close()
    env.close()  # idempotent


def check_vector_env(envs):
    """gymnasium.vector.VectorEnv (1.x, autoreset NEXT_STEP): batched spaces, (N, ...) arrays
    of the right dtypes, per-environment seeds, and the autoreset rule: the step after an
    episode's end resets that environment, ignores its action, and returns the reset's
    observation with reward 0 and both flags False."""
    n = envs.num_envs
    check_box(envs.single_observation_space)
    check_box(envs.single_action_space)
    assert envs.observation_space.shape == (n,) + envs.single_observation_space.shape
    assert envs.action_space.shape == (n,) + envs.single_action_space.shape
    assert envs.metadata["autoreset_mode"] == "NextStep"
    observations, infos = envs.reset(seed=5)
    assert observations.shape == envs.observation_space.shape and observations in envs.observation_space
    assert all(len(value) == n for value in infos.values())
    ended = np.zeros(n, dtype=bool)
    envs.action_space.seed(5)
    for _ in range(3000):
        observations, rewards, terminated, truncated, infos = envs.step(envs.action_space.sample())
        assert observations.dtype == np.float64 and observations in envs.observation_space
        assert rewards.shape == (n,) and rewards.dtype == np.float64
        assert terminated.dtype == truncated.dtype == np.bool_
        assert terminated.shape == truncated.shape == (n,)
        reset_now = infos["autoreset"]
        assert np.array_equal(reset_now, ended), "exactly the environments that ended reset"
        assert np.all(rewards[reset_now] == 0.0)
        assert not np.any(terminated[reset_now] | truncated[reset_now])
        ended = terminated | truncated
        if np.all(reset_now[:1]) and np.any(reset_now):
            break
    assert np.any(infos["autoreset"]), "some environment's episode ended and was reset"
