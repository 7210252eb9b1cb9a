"""Type errors in cbbg's words: the C++ module's functions and constructors, called with
arguments of the wrong types, say in one line what they take and what they got, instead of
pybind11's list of overloads with its internal module names.

Methods keep pybind11's message (wrapping them would cost every call, env.step's too); a
constructor's and a function's call happens once per object or per run.
"""

import functools
import re

_INCOMPATIBLE = re.compile(r"^(\S+)\(\): incompatible (?:function|constructor) arguments")
_OVERLOAD = re.compile(r"^\s+\d+\. (.*)$", re.MULTILINE)
_INVOKED = re.compile(r"Invoked with: (.*)$", re.DOTALL)


def _shorten(text, limit=160):
    text = " ".join(text.split())
    return text if len(text) <= limit else text[:limit - 3] + "..."


def one_line(name, message):
    """pybind11's "incompatible arguments" message of cbbg.`name` in one line, or None for
    another message."""
    if _INCOMPATIBLE.match(message) is None:
        return None
    takes = []
    for overload in _OVERLOAD.findall(message):
        overload = overload.replace("cbbg._cbbg.", "cbbg.")
        overload = re.sub(r"^cbbg\.\w+(\()", r"\1", overload)  # a constructor names its class
        overload = re.sub(r"\) -> .*$", ")", overload)
        overload = re.sub(r"^\(self: [^,)]+(, )?", "(", overload)
        takes.append(overload)
    invoked = _INVOKED.search(message)
    got = _shorten(invoked.group(1).replace("cbbg._cbbg.", "cbbg.")) if invoked else "?"
    return f"cbbg.{name} takes {' or '.join(takes)}; got {got}"


def _translated(function, name):
    @functools.wraps(function)
    def call(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        except TypeError as error:
            text = one_line(name, str(error))
            if text is None:
                raise
        raise TypeError(text)

    return call


def install(namespace, module):
    """Replaces, in `namespace` (the package's globals), each function of the C++ `module`
    by one that translates its type errors, and wraps each of its classes' constructors."""
    for name in dir(module):
        if name.startswith("_"):
            continue
        value = getattr(module, name)
        if type(value).__name__ == "builtin_function_or_method" and namespace.get(name) is value:
            namespace[name] = _translated(value, name)
        elif isinstance(value, type) and value.__module__ == module.__name__:
            init = value.__dict__.get("__init__")
            if init is not None and type(init).__name__ == "instancemethod":
                value.__init__ = _translated(init, name)
