"""cbbg from Python: the systems framework, the blocks, the controller and its protocols.

The C++ library does the work (the GIL is released while it runs); this package adds what is
easier in Python on top of it: configs from dicts, the command line, results directories as
arrays.

    import cbbg
    parameters = cbbg.parameters({"plant.kind": "analytic", "seeds": 5})
    results = cbbg.run_experiment(parameters, jobs=2)
"""

import json
import os
import sys
from collections.abc import Mapping

from . import _cbbg, _output
from ._cbbg import *  # noqa: F401,F403
from ._cbbg import __doc__  # noqa: F401
from ._cbbg import control  # noqa: F401

# `import cbbg.control` finds the C++ submodule as a module of the package.
sys.modules[__name__ + ".control"] = control
from .environment import BalanceEnv, Box, VecBalanceEnv  # noqa: F401
from .results import load_results, load_sweep  # noqa: F401
from . import _reprs, _type_errors

_reprs.install()


def _yaml(value):
    """A Python value as the YAML text a config key reads (JSON is YAML)."""
    return json.dumps(value, default=lambda o: o.tolist() if hasattr(o, "tolist") else str(o))


def _sections():
    """Every section of the config tree, built-in and registered: "plant", "evaluation", ..."""
    sections = set()
    for spec in schema():  # noqa: F405
        parts = spec.path.split(".")
        sections.update(".".join(parts[:i]) for i in range(1, len(parts)))
    return sections


def _assignments(settings, prefix="", sections=None):
    """(key.path, value) of a dict, nested sections ({"plant": {"kind": ...}}) flattened. A
    dict under anything but a section ({"critic.beta": {}}) stays a value, which the config
    refuses as the command line does."""
    if sections is None:
        sections = _sections()
    for key, value in settings.items():
        path = f"{prefix}{key}"
        if isinstance(value, dict) and path in sections:
            yield from _assignments(value, f"{path}.", sections)
        else:
            yield path, value


class Config(_cbbg.Config):
    """The configuration tree: the defaults, then a YAML file, then settings from a dict.

    Keys are the config's ("critic.gamma"), or nested dicts of sections; values are Python
    numbers, strings and lists. Each is checked as it arrives (ConfigError naming the key).
    """

    def __init__(self, settings=None, file=None):
        if settings is not None and not isinstance(settings, Mapping):
            raise TypeError("settings are a dict of config keys ({'critic.gamma': 0.9}) or None; "
                            f"got {type(settings).__name__} {settings!r}")
        super().__init__()
        if file is not None:
            self.merge_file(os.fspath(file))
        if settings:
            self.update(settings)

    def set(self, key, value):
        self.set_assignment(f"{key}={_yaml(value)}", f"settings['{key}']")

    def update(self, settings):
        for key, value in _assignments(settings):
            self.set(key, value)


def parameters(settings=None, file=None):
    """The run's typed, checked parameters from the defaults, a YAML file and a dict."""
    return validated_parameters(Config(settings, file))  # noqa: F405


def _share_dir():
    """The share/cbbg of the tree this module belongs to (build tree or install), or the
    other one where that has none (the module installed alone by scripts/build.sh)."""
    module_dir = os.path.dirname(os.path.abspath(_cbbg.__file__))
    build_share = _cbbg._build_share_dir
    build_root = os.path.dirname(os.path.dirname(build_share))
    ours, other = build_share, _cbbg._install_share_dir
    if not module_dir.startswith(build_root + os.sep):
        ours, other = other, ours
    return ours if os.path.isdir(ours) or not os.path.isdir(other) else other


class CommandError(RuntimeError):
    """cbbg.main(args, check=True) for a command that exits non-zero: its exit code, and what
    it wrote to stderr when main forwarded it (else None: it went to the terminal)."""

    def __init__(self, args, exit_code, stderr):
        self.args_given, self.exit_code, self.stderr = list(args), exit_code, stderr
        last = (stderr or "").strip().splitlines()
        super().__init__(f"cbbg {' '.join(map(str, args))} exited with code {exit_code}"
                         + (f": {last[-1]}" if last else ""))


def main(args, check=False):
    """Runs the cbbg command line (["run", "--out", "results", ...]) in this process, with its
    registrations (arms, plant kinds, protocols, sections), and returns the exit code; with
    check=True a non-zero one raises CommandError. What the command prints reaches Python's
    sys.stdout and sys.stderr (a notebook shows it as it comes)."""
    if isinstance(args, (str, bytes, os.PathLike)) or not hasattr(args, "__iter__"):
        raise TypeError("cbbg.main: args are a list of the command's words (['run', "
                        f"'--seeds', '5']); got {type(args).__name__} {args!r}")
    arguments = []
    for index, arg in enumerate(args):
        if not isinstance(arg, (str, os.PathLike)):
            raise TypeError(f"cbbg.main: args[{index}] is {type(arg).__name__} {arg!r}; each "
                            "word is a str (or a path)")
        arguments.append(os.fspath(arg))
    with _output.forwarded() as stderr:
        code = cli(arguments, _share_dir())  # noqa: F405
    if check and code != 0:
        raise CommandError(arguments, code, stderr())
    return code


_type_errors.install(globals(), _cbbg)
