"""cbbg.gymnasium.register() against a stand-in for Gymnasium's registry and Env (Debian does
not ship Gymnasium): the id registered once, make_env's environment a subclass of the
installed gymnasium.Env whose reset seeds np_random through it and steps cbbg's robot."""

import sys
import types

import numpy as np
import pytest


@pytest.fixture
def stand_in_gymnasium(monkeypatch):
    gymnasium = types.ModuleType("gymnasium")
    gymnasium.registry = {}

    def register(id, entry_point):  # noqa: A002 (Gymnasium's own parameter name)
        if id in gymnasium.registry:
            raise ValueError(f"{id} registered twice")
        gymnasium.registry[id] = entry_point

    class Env:
        def reset(self, *, seed=None, options=None):
            self.np_random = np.random.default_rng(seed)

    class Box:
        def __init__(self, low, high, shape, dtype):
            self.low, self.high, self.shape, self.dtype = low, high, shape, dtype

    gymnasium.register = register
    gymnasium.Env = Env
    gymnasium.spaces = types.SimpleNamespace(Box=Box)
    monkeypatch.setitem(sys.modules, "gymnasium", gymnasium)
    return gymnasium


def test_register_twice_changes_nothing_and_make_env_is_a_gymnasium_env(stand_in_gymnasium):
    import cbbg.gymnasium

    cbbg.gymnasium.register()
    cbbg.gymnasium.register()  # a notebook cell run again
    make = stand_in_gymnasium.registry["cbbg/Balance-v0"]
    env = make(settings={"plant.kind": "analytic", "trial.duration": 0.1})
    assert isinstance(env, stand_in_gymnasium.Env)
    assert env.action_space.shape == (1,) and env.observation_space.shape == (6,)
    observation, info = env.reset(seed=4)
    assert isinstance(env.np_random, np.random.Generator)
    observation, reward, terminated, truncated, info = env.step(info["supervisor_action"])
    assert observation.shape == (6,) and not terminated
    env.close()


def test_register_without_gymnasium_says_so(monkeypatch):
    import cbbg.gymnasium

    monkeypatch.setitem(sys.modules, "gymnasium", None)
    with pytest.raises(ModuleNotFoundError):
        cbbg.gymnasium.register()
