"""cbbg's environments as Gymnasium's, where Gymnasium is installed (Debian does not ship it;
cbbg does not need it):

    import gymnasium
    import cbbg.gymnasium

    cbbg.gymnasium.register()        # "cbbg/Balance-v0"; again in a notebook cell: no error
    env = gymnasium.make("cbbg/Balance-v0", settings={"plant.kind": "analytic"})

The registered environment is a gymnasium.Env around cbbg.BalanceEnv with gymnasium.spaces
boxes; Gymnasium's make() adds its own wrappers (the episode's step limit, its checks).
"""

import numpy as np

from .environment import BalanceEnv

ENV_ID = "cbbg/Balance-v0"


def register(env_id=ENV_ID):
    """Registers the balancing task as `env_id`; a second call changes nothing. Raises
    ModuleNotFoundError where Gymnasium is not installed."""
    import gymnasium

    if env_id not in gymnasium.registry:
        gymnasium.register(id=env_id, entry_point=make_env)


def make_env(**kwargs):
    """A gymnasium.Env of the balancing task; kwargs: BalanceEnv's (settings, plant,
    initial_pitch, render_mode)."""
    import gymnasium

    class CbbgBalanceEnv(gymnasium.Env):
        metadata = BalanceEnv.metadata

        def __init__(self, **arguments):
            self.cbbg_env = BalanceEnv(**arguments)
            self.render_mode = self.cbbg_env.render_mode
            self.observation_space = _box(gymnasium, self.cbbg_env.observation_space)
            self.action_space = _box(gymnasium, self.cbbg_env.action_space)

        def reset(self, *, seed=None, options=None):
            super().reset(seed=seed)  # seeds self.np_random, as Gymnasium's environments do
            return self.cbbg_env.reset(seed=seed, options=options)

        def step(self, action):
            return self.cbbg_env.step(action)

        def render(self):
            return self.cbbg_env.render()

        def close(self):
            self.cbbg_env.close()

    return CbbgBalanceEnv(**kwargs)


def _box(gymnasium, box):
    return gymnasium.spaces.Box(low=box.low, high=box.high, shape=box.shape, dtype=np.float64)
