"""The docstrings of the classes bound from C++ are their headers' class comments, generated at
build time (python/generate_docstrings.py), not copies that drift: each is compared here with
the comment read from the source tree by this file's own reading of it."""

import inspect
import pathlib
import re

import pytest

import cbbg

SOURCE_ROOT = pathlib.Path(__file__).resolve().parents[2]
# Where the classes documented by their header comment live.
HEADER_DIRS = ["blocks", "plant", "framework/primitives", "framework/control"]

# Classes defined in those headers whose docstring the binding writes, and why.
HAND_WRITTEN = {
    "RobotPlant": "the base a Python plant subclasses: what it declares and overrides",
    "RobotParams": "no comment above the struct",
    "PushParams": "no comment above the struct",
    "CriticParams": "the binding declares frozen beside describe()'s keys",
    "ActorParams": "the binding declares frozen beside describe()'s keys",
    "OmegaParams": "the binding declares mode and constant beside describe()'s keys",
    "ExplorationParams": "a summary of the keys, longer than the struct's comment",
    "SignalIndex": "says what -1 means, which the struct's comment leaves to its fields",
    "LinearizeOptions": "no comment above the struct, no docstring",
}
# Docstrings that are a binding's summary line, a blank line, then the header's comment.
PREFIXED = {"StateSpace": "A linear time-invariant system in state-space form.\n\n"}
# What bind_params (params_binding.h) appends to a params struct's docstring.
PARAMS_SUFFIX = "\n\nMade with keywords, each key's default otherwise: "


def definitions(class_name):
    """The headers under HEADER_DIRS that define class or struct `class_name`."""
    pattern = re.compile(
        r"^\s*(?:class|struct)\s+" + re.escape(class_name) + r"\b(?:\s+final)?\s*(?::.*|\{.*)?$",
        re.M,
    )
    found = []
    for directory in HEADER_DIRS:
        for header in sorted((SOURCE_ROOT / directory).rglob("*.h")):
            if pattern.search(header.read_text(encoding="utf-8")):
                found.append(header)
    return found


def header_comment(header, class_name):
    """The `///` or `//` lines right above the definition of `class_name`, markers and the
    space after them removed, blank lines at either end dropped."""
    lines = header.read_text(encoding="utf-8").splitlines()
    definition = re.compile(
        r"^\s*(?:class|struct)\s+" + re.escape(class_name) + r"\b(?:\s+final)?\s*(?::.*|\{.*)?$"
    )
    index = next(i for i, line in enumerate(lines) if definition.match(line))
    comment = []
    for line in reversed(lines[:index]):
        stripped = line.strip()
        if not stripped.startswith("//"):
            if comment or not stripped.startswith("template"):
                break
            continue
        text = stripped[3:] if stripped.startswith("///") else stripped[2:]
        comment.insert(0, (text[1:] if text.startswith(" ") else text).rstrip())
    return "\n".join(comment).strip("\n")


def bound_classes():
    """(Python name, class) of every class the C++ half binds, in cbbg and cbbg.control."""
    classes = []
    for module in (cbbg._cbbg, cbbg.control):
        for name, value in vars(module).items():
            if inspect.isclass(value) and value.__module__.startswith("cbbg._cbbg"):
                classes.append((name, value))
    return classes


HEADER_DOCUMENTED = [
    (name, cls)
    for name, cls in bound_classes()
    if name not in HAND_WRITTEN and not issubclass(cls, BaseException) and definitions(name)
]


def test_reward_docstring_is_the_headers_with_k_phi():
    doc = cbbg.Reward.__doc__
    assert doc.startswith("Reward: the sliding-surface reward of docs/model.md §2.9.")
    assert "s(t) = a1 theta_b + a2 theta_b' + k_phi phi'" in doc
    assert "k_phi = reward.k_phi" in doc
    assert "| reward   | out | 1    |" in doc  # the port table, as the header lays it out
    assert not doc.startswith("///") and "\n///" not in doc and "\n// " not in doc


def test_every_library_block_and_primitive_is_documented_from_its_header():
    """Every bound block of blocks/, plant/ and framework/primitives/ is checked below, so a
    block bound with hand-written text (or none) fails here."""
    names = {name for name, _ in HEADER_DOCUMENTED}
    blocks = {name for name, cls in bound_classes() if issubclass(cls, cbbg.Block)}
    for expected in ["Actor", "Critic", "Reward", "Sensors", "ExternalPush", "AnalyticPlant",
                     "SimbodyPlant", "Adder", "PidController", "CsvSink", "StateSpace"]:
        assert expected in names
    # Every bound block but the framework's own and the Python-facing bases.
    assert blocks - names == {"Block", "Diagram", "LeafBlock", "RobotPlant"}


@pytest.mark.parametrize("name, cls", HEADER_DOCUMENTED, ids=[n for n, _ in HEADER_DOCUMENTED])
def test_docstring_is_the_header_comment(name, cls):
    headers = definitions(name)
    assert len(headers) == 1, f"{name} is defined in {headers}"
    comment = header_comment(headers[0], name)
    assert comment, f"{headers[0]}: {name} has no comment"
    expected = PREFIXED.get(name, "") + comment
    doc = cls.__doc__
    if name.endswith("Params"):
        assert doc.startswith(expected + PARAMS_SUFFIX + name + "(")
    else:
        assert doc == expected


def test_hand_written_exceptions_are_still_bound():
    bound = {name for name, _ in bound_classes()}
    assert set(HAND_WRITTEN) <= bound
    assert set(PREFIXED) <= bound
