"""Readable reprs for the result objects the C++ module returns, and cbbg.Parameters as a
read-only mapping of every key path to its value: what a notebook shows of them."""

from collections.abc import Mapping

import numpy as np

from . import _cbbg

# Each result type and the fields its repr shows, in order.
_FIELDS = {
    "SimulationStatus": ("terminated", "time", "terminated_by", "reason"),
    "EventStatus": ("terminates", "reason"),
    "TrialOutcome": ("status", "steps", "final_theta", "message"),
    "TrialRecord": ("trial", "k1", "outcome"),
    "EvaluationRecord": ("theta0", "outcome"),
    "SeedFigure": ("name", "value"),
    "LearntWeights": ("num_features",),
    "SeedRun": ("arm", "seed", "succeeded", "failures_before_success"),
    "ExperimentResults": ("experiment", "arms", "seeds"),
    "LqrResult": ("K",),
    "LinearModel": ("A", "B"),
    "ResultsSchema": ("headline", "evaluates"),
    "Figure": ("name", "type", "summary"),
    "Column": ("name",),
}


def _shown(value):
    if isinstance(value, np.ndarray):
        return np.array2string(value, precision=4, threshold=8)
    if isinstance(value, float):
        return f"{value:.6g}"
    return repr(value)


def _field_repr(fields):
    def __repr__(self):
        shown = ", ".join(f"{field}={_shown(getattr(self, field))}" for field in fields)
        return f"{type(self).__name__}({shown})"

    return __repr__


def _key_paths():
    return [spec.path for spec in _cbbg.schema()]


def _parameters_repr(self):
    keys = ("experiment", "plant.kind", "seed", "seeds")
    return "Parameters(" + ", ".join(f"{k}={self[k]!r}" for k in keys) + f", ... {len(self)} keys)"


def _keyed(lookup):
    """Parameters' lookup, refusing a key that is not text in cbbg's words."""

    def by_key(self, key):
        if not isinstance(key, str):
            raise TypeError(f"Parameters: a key is a str ('critic.gamma'); got "
                            f"{type(key).__name__} {key!r}")
        return lookup(self, key)

    return by_key


def install():
    for name, fields in _FIELDS.items():
        cls = getattr(_cbbg, name, None) or getattr(_cbbg.control, name, None)
        if cls is not None and cls.__repr__ is object.__repr__:
            cls.__repr__ = _field_repr(fields)
    parameters = _cbbg.Parameters
    parameters.__getitem__ = _keyed(parameters.__getitem__)
    parameters.value = _keyed(parameters.value)
    parameters.__iter__ = lambda self: iter(_key_paths())
    parameters.__len__ = lambda self: len(_key_paths())
    parameters.__contains__ = lambda self, key: isinstance(key, str) and key in _key_paths()
    parameters.keys = lambda self: Mapping.keys(self)
    parameters.items = lambda self: Mapping.items(self)
    parameters.values = lambda self: Mapping.values(self)
    parameters.get = lambda self, key, default=None: self[key] if key in self else default
    parameters.__repr__ = _parameters_repr
    Mapping.register(parameters)
