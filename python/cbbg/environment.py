"""The balancing task as Gymnasium environments, without Gymnasium (Debian does not ship it):
the same methods, tuples, spaces and rules, so an agent written for Gymnasium's API runs on
them, and cbbg.gymnasium.register() makes them Gymnasium's where it is installed.

    env = cbbg.BalanceEnv({"plant.kind": "analytic"})
    observation, info = env.reset(seed=1)
    while True:
        action = info["supervisor_action"]          # the teacher's, for imitation or residual RL
        observation, reward, terminated, truncated, info = env.step(action)
        if terminated or truncated:
            break

    envs = cbbg.VecBalanceEnv(64, {"plant.kind": "analytic"})  # stepped in C++ threads
    observations, infos = envs.reset(seed=1)                    # (64, 6); env i seeded 1 + i
    observations, rewards, terminated, truncated, infos = envs.step(actions)  # (64,) each
"""

import numbers
from dataclasses import dataclass

import numpy as np

from . import _cbbg


class Box:
    """A box of real arrays, as gymnasium.spaces.Box describes one: low, high, shape, dtype,
    sample(), contains() and `in`, seed(), np_random."""

    def __init__(self, low, high, dtype=np.float64, seed=None):
        self.dtype = np.dtype(dtype)
        self.low = np.asarray(low, dtype=self.dtype)
        self.high = np.asarray(high, dtype=self.dtype)
        if self.low.shape != self.high.shape:
            raise ValueError(f"Box: low {self.low.shape} and high {self.high.shape} differ in shape")
        self._np_random = None
        if seed is not None:
            self.seed(seed)

    @property
    def shape(self):
        return self.low.shape

    @property
    def np_random(self):
        """The generator sample() draws from (seeded by seed(), else from the OS)."""
        if self._np_random is None:
            self.seed()
        return self._np_random

    def seed(self, seed=None):
        self._np_random = np.random.default_rng(seed)
        return [seed]

    def sample(self, mask=None):
        """Gymnasium's draw: uniform where both bounds are finite, normal where neither is,
        shifted exponential where one is."""
        if mask is not None:
            raise ValueError("Box.sample: a Box takes no mask")
        rng = self.np_random
        bounded_low, bounded_high = np.isfinite(self.low), np.isfinite(self.high)
        x = rng.normal(size=self.shape)
        both = bounded_low & bounded_high
        x[both] = rng.uniform(self.low[both], self.high[both])
        x[bounded_low & ~bounded_high] = self.low[bounded_low & ~bounded_high] + rng.exponential(
            size=int(np.sum(bounded_low & ~bounded_high)))
        x[~bounded_low & bounded_high] = self.high[~bounded_low & bounded_high] - rng.exponential(
            size=int(np.sum(~bounded_low & bounded_high)))
        return x.astype(self.dtype)

    def contains(self, x):
        """Gymnasium's rule: an array (or what converts to one) of this shape, of a dtype that
        casts safely to this one (no text, no complex), within the bounds."""
        if not isinstance(x, np.ndarray):
            try:
                x = np.asarray(x)
            except (TypeError, ValueError):
                return False
        if not np.can_cast(x.dtype, self.dtype):
            return False
        return x.shape == self.shape and bool(np.all(x >= self.low) and np.all(x <= self.high))

    __contains__ = contains

    def __eq__(self, other):
        return (isinstance(other, Box) and self.dtype == other.dtype and self.shape == other.shape
                and np.array_equal(self.low, other.low) and np.array_equal(self.high, other.high))

    def __repr__(self):
        return f"Box({self.low.min()}, {self.high.max()}, {self.shape}, {self.dtype})"


@dataclass(frozen=True)
class EnvSpec:
    """What Gymnasium's registry would say of the environment."""

    id: str
    max_episode_steps: int
    reward_threshold: float = 0.0


def _parameters(settings):
    from . import parameters as make_parameters  # the package's, after it loaded

    if isinstance(settings, _cbbg.Parameters):
        return settings
    if isinstance(settings, _cbbg.Config):
        return _cbbg.validated_parameters(settings)
    return make_parameters(settings)


def _from_yaml(text):
    """Parameters from their YAML text (pickling)."""
    from . import Config

    config = Config()
    config.merge_yaml(text, "a pickled environment's parameters")
    return _cbbg.validated_parameters(config)


def _check_seed(seed):
    """A reset's seed: None or a whole number >= 0, as Gymnasium's."""
    if seed is None:
        return
    if isinstance(seed, bool) or not isinstance(seed, numbers.Integral) or seed < 0:
        raise TypeError(f"reset: seed is None or a whole number >= 0; got "
                        f"{type(seed).__name__} {seed!r}")


def _initial_pitch(initial_pitch):
    """None, a pitch (rad) or a range (low, high) as the C++ environment takes it."""
    if initial_pitch is None:
        return None
    if np.isscalar(initial_pitch):
        return (float(initial_pitch), float(initial_pitch))
    low, high = initial_pitch
    return (float(low), float(high))


class _Environment:
    """What both environments share: unwrapped, the reset options' check, close."""

    @property
    def unwrapped(self):
        return self

    def _reset_options(self, options):
        self._check_open()
        options = options or {}
        unknown = set(options) - {"initial_pitch"}
        if unknown:
            raise ValueError(f"reset: unknown option(s) {sorted(unknown)}; allowed: initial_pitch")
        return options

    def close(self):
        """Releases the simulation (and its threads); reset and step refuse afterwards.
        Idempotent."""
        self._env = None

    def _check_open(self):
        if self._env is None:
            raise RuntimeError("the environment is closed; make a new one")


class BalanceEnv(_Environment):
    """The robot, the task's reward and failure, one 10 ms hold per step (trial.period).

    settings: a dict of config keys (or cbbg.Parameters); plant: None for plant.kind's
    (simbody, analytic, a registered kind) or a callable(name, parameters) -> RobotPlant;
    initial_pitch: the reset distribution, None for trial.theta0 (the paper's fixed angle), a
    pitch, or (low, high) for a uniform draw, rad; render_mode: None or "rgb_array".
    reset(seed=None, options={"initial_pitch": rad}); step(action): the torque, N m on both
    wheels (a real number or an array of one; beyond the action space the plant saturates it).
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 100}

    def __init__(self, settings=None, plant=None, initial_pitch=None, render_mode=None):
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode must be None or 'rgb_array'; got {render_mode!r}")
        self._parameters = _parameters(settings)
        self._plant = plant
        self._initial_pitch = initial_pitch
        self.render_mode = render_mode
        self._env = _cbbg.BalanceEnvironment(self._parameters, plant, _initial_pitch(initial_pitch))
        self.observation_space = Box(np.asarray(self._env.observation_low),
                                     np.asarray(self._env.observation_high))
        self.action_space = Box(np.array([self._env.action_low]), np.array([self._env.action_high]))
        self.period = self._env.period
        self.duration = self._env.duration
        self.failure_angle = self._env.failure_angle
        self.signal_names = self._env.signal_names
        self.spec = EnvSpec("cbbg/Balance-v0", int(round(self.duration / self.period)))
        self._np_random = None
        self._observation = None

    @property
    def np_random(self):
        """A NumPy generator for the agent's own draws: seeded by reset(seed=...), else by
        run.seed. The environment's own draws (sensor noise, the reset distribution) come
        from cbbg's streams, which the same seed decides."""
        if self._np_random is None:
            self._np_random = np.random.default_rng(self._parameters.seed)
        return self._np_random

    def reset(self, seed=None, options=None):
        options = self._reset_options(options)
        _check_seed(seed)
        if seed is not None:
            self._np_random = np.random.default_rng(seed)
        observation, info = self._env.reset(seed, options.get("initial_pitch"))
        self._observation = observation
        return observation, info

    def step(self, action):
        self._check_open()
        result = self._env.step(action)
        self._observation = result[0]
        return result

    def render(self):
        """The robot seen from its side, an (H, W, 3) uint8 image (render_mode "rgb_array");
        None without a render mode, as Gymnasium's environments do."""
        if self.render_mode is None:
            return None
        if self._observation is None:
            raise RuntimeError("render: no episode has started; call reset() first")
        return _side_view(self._observation, self._parameters["plant.wheel_radius"],
                          2 * self._parameters["plant.com_height"])

    @property
    def closed_loop(self):
        """The closed loop stepped (to draw it: closed_loop.diagram.to_dot())."""
        self._check_open()
        return self._env.closed_loop

    def __getstate__(self):
        """The configuration, not an episode in progress: a copy starts unreset."""
        return {"parameters": self._parameters.to_yaml(), "plant": self._plant,
                "initial_pitch": self._initial_pitch, "render_mode": self.render_mode}

    def __setstate__(self, state):
        self.__init__(_from_yaml(state["parameters"]), state["plant"], state["initial_pitch"],
                      state["render_mode"])

    def __repr__(self):
        return (f"BalanceEnv(plant.kind={self._parameters['plant.kind']!r}, "
                f"period={self.period}, duration={self.duration})")


class VecBalanceEnv(_Environment):
    """num_envs environments stepped together in C++ threads, with Gymnasium 1.x's vector-env
    rules (gymnasium.vector.VectorEnv, autoreset mode NEXT_STEP): an environment whose
    episode ended at a step is reset at the next step, its action ignored, and returns the
    reset's observation with reward 0, terminated and truncated False, info["autoreset"] True;
    an episode's final observation is the one returned with its terminated or truncated flag.

    reset(seed=s) seeds environment i with s + i, as Gymnasium's SyncVectorEnv does; the same
    seed and actions give the same bytes with any number of threads. settings, plant and
    initial_pitch as BalanceEnv's; threads: 0 for the machine's, at most num_envs. A Python
    plant works too, its calls serialised by Python's lock (threads then gain little).
    """

    metadata = {"autoreset_mode": "NextStep", "render_modes": []}

    def __init__(self, num_envs, settings=None, plant=None, threads=0, initial_pitch=None):
        for name, value in (("num_envs", num_envs), ("threads", threads)):
            if isinstance(value, bool) or not isinstance(value, numbers.Integral):
                raise TypeError(f"VecBalanceEnv: {name} is a whole number; got "
                                f"{type(value).__name__} {value!r}")
        self._parameters = _parameters(settings)
        self._plant = plant
        self._threads = threads
        self._initial_pitch = initial_pitch
        self._env = _cbbg.VecBalanceEnvironment(self._parameters, num_envs, plant, threads,
                                                _initial_pitch(initial_pitch))
        single = self._env.environment(0)
        self.num_envs = num_envs
        self.single_observation_space = Box(np.asarray(single.observation_low),
                                            np.asarray(single.observation_high))
        self.single_action_space = Box(np.array([single.action_low]),
                                       np.array([single.action_high]))
        self.observation_space = Box(np.tile(self.single_observation_space.low, (num_envs, 1)),
                                     np.tile(self.single_observation_space.high, (num_envs, 1)))
        self.action_space = Box(np.tile(self.single_action_space.low, (num_envs, 1)),
                                np.tile(self.single_action_space.high, (num_envs, 1)))
        self.period = single.period
        self.duration = single.duration
        self.failure_angle = single.failure_angle
        self.spec = EnvSpec("cbbg/Balance-v0", int(round(self.duration / self.period)))

    @property
    def threads(self):
        return self._env.threads

    def reset(self, seed=None, options=None):
        pitches = self._reset_options(options).get("initial_pitch")
        _check_seed(seed)
        if pitches is not None:
            pitches = [float(p) for p in np.broadcast_to(np.asarray(pitches, dtype=float),
                                                         (self.num_envs,))]
        return self._env.reset(seed, pitches)

    def step(self, actions):
        self._check_open()
        return self._env.step(actions)

    def __getstate__(self):
        return {"num_envs": self.num_envs, "parameters": self._parameters.to_yaml(),
                "plant": self._plant, "threads": self._threads,
                "initial_pitch": self._initial_pitch}

    def __setstate__(self, state):
        self.__init__(state["num_envs"], _from_yaml(state["parameters"]), state["plant"],
                      state["threads"], state["initial_pitch"])

    def __repr__(self):
        return (f"VecBalanceEnv(num_envs={self.num_envs}, "
                f"plant.kind={self._parameters['plant.kind']!r}, threads={self.threads})")


def _side_view(observation, wheel_radius, body_length, size=(240, 320)):
    """The robot from its side: the wheel where its mean angle rolled it, the body tilted by
    the pitch, on a ground line; white background."""
    height, width = size
    scale = height / (2.5 * (wheel_radius + body_length))
    pitch = float(observation[0])
    rolled = wheel_radius * (float(observation[2]) + float(observation[3])) / 2.0
    ground = height - 10
    cx = width / 2 + ((rolled * scale) % (width / 2) if np.isfinite(rolled) else 0.0) - width / 4
    cy = ground - wheel_radius * scale
    y, x = np.mgrid[0:height, 0:width]
    image = np.full((height, width, 3), 255, dtype=np.uint8)
    image[ground:ground + 2, :] = (90, 90, 90)
    tip = (cx + body_length * scale * np.sin(pitch), cy - body_length * scale * np.cos(pitch))
    along = np.clip(((x - cx) * (tip[0] - cx) + (y - cy) * (tip[1] - cy))
                    / max((tip[0] - cx) ** 2 + (tip[1] - cy) ** 2, 1e-9), 0.0, 1.0)
    distance = np.hypot(x - (cx + along * (tip[0] - cx)), y - (cy + along * (tip[1] - cy)))
    image[distance <= 4] = (40, 90, 200)
    image[np.hypot(x - cx, y - cy) <= wheel_radius * scale] = (30, 30, 30)
    return image
