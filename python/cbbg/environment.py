"""The balancing task as a Gymnasium-style environment, without Gymnasium (Debian does not
ship it): the same methods, tuples and spaces, so an agent written for Gymnasium's API runs
on it, and gymnasium.Env can wrap it where Gymnasium is installed.

    env = cbbg.BalanceEnv({"plant.kind": "analytic"})
    observation, info = env.reset(seed=1)
    while True:
        action = info["supervisor_action"]          # the teacher's, for imitation or residual RL
        observation, reward, terminated, truncated, info = env.step(action)
        if terminated or truncated:
            break
"""

from dataclasses import dataclass

import numpy as np

from . import _cbbg


@dataclass(frozen=True)
class Box:
    """A box of real vectors, as gymnasium.spaces.Box describes one."""

    low: np.ndarray
    high: np.ndarray

    @property
    def shape(self):
        return self.low.shape

    dtype = np.float64

    def contains(self, x):
        x = np.asarray(x, dtype=np.float64)
        return x.shape == self.shape and bool(np.all(x >= self.low) and np.all(x <= self.high))

    def sample(self, rng):
        """A uniform draw where both bounds are finite (the action space)."""
        return rng.uniform(self.low, self.high)


class BalanceEnv:
    """The robot, the task's reward and failure, one 10 ms hold per step (trial.period).

    settings: a dict of config keys (or cbbg.Parameters); plant: None for plant.kind's
    (simbody, analytic, a registered kind) or a callable(name, parameters) -> RobotPlant.
    reset(seed=None, options={"initial_pitch": rad}); step(action) with the torque in N m.
    """

    metadata = {"render_modes": []}

    def __init__(self, settings=None, plant=None):
        from . import parameters as make_parameters  # the package's, after it loaded

        parameters = settings if isinstance(settings, _cbbg.Parameters) else make_parameters(settings)
        self._env = _cbbg.BalanceEnvironment(parameters, plant)
        self.observation_space = Box(np.asarray(self._env.observation_low),
                                     np.asarray(self._env.observation_high))
        self.action_space = Box(np.array([self._env.action_low]), np.array([self._env.action_high]))
        self.period = self._env.period
        self.duration = self._env.duration
        self.signal_names = self._env.signal_names

    def reset(self, seed=None, options=None):
        options = options or {}
        unknown = set(options) - {"initial_pitch"}
        if unknown:
            raise ValueError(f"reset: unknown option(s) {sorted(unknown)}; allowed: initial_pitch")
        return self._env.reset(seed, options.get("initial_pitch"))

    def step(self, action):
        return self._env.step(action)

    @property
    def closed_loop(self):
        """The closed loop stepped (to draw it: closed_loop.diagram.to_dot())."""
        return self._env.closed_loop

    def close(self):
        pass
