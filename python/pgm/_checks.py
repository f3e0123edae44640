"""Argument checks shared by the package's public functions: a TypeError for a wrong type, a
pgm.Error for a wrong value, each naming the argument and what was expected."""

import numbers
import os
from collections.abc import Mapping

import numpy as np

from . import _core
from ._core import Error


def _network(network, what="network", markov=False):
    from . import Network

    if not isinstance(network, Network):
        kinds = "a pgm.Network or a pgm.MarkovNetwork" if markov else "a pgm.Network"
        raise TypeError(f"{what} must be {kinds} (from pgm.read_network or pgm.fit), got {type(network).__name__}")
    return network


def _text(value, what):
    if value is None:
        return None
    if not isinstance(value, str):
        raise TypeError(f"{what} must be a string, got {type(value).__name__}")
    return value


def _path(value, what):
    if not isinstance(value, (str, os.PathLike)):
        raise TypeError(f"{what} must be a path (a string or os.PathLike), got {type(value).__name__}")
    return os.fspath(value)


UINT64_MAX = 2**64 - 1
THREADS_MAX = 1024  # the program's --threads bound


def _whole(value, what, least=0, most=None):
    """An int (or NumPy integer) of at least `least` and, when given, at most `most` (the bound of
    the program's option of the same name, checked here before C++ could wrap, overflow or run
    for hours); bools and floats are refused."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{what} must be a whole number, got {value!r}")
    if most is not None and not least <= value <= most:
        shown = "2**64 - 1 (18446744073709551615)" if most == UINT64_MAX else most
        raise Error(f"{what} must be a whole number from {least} to {shown}, got {value}")
    if value < least:
        raise Error(f"{what} must be a whole number of at least {least}, got {value}")
    return int(value)


def _seed(value, what="seed"):
    """A seed: any unsigned 64-bit number, as the program's --seed."""
    return _whole(value, what, 0, UINT64_MAX)


def _threads(value, what="threads"):
    return _whole(value, what, 0, THREADS_MAX)


def _real(value, what):
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{what} must be a number, got {value!r}")
    return float(value)


def _flag(value, what):
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{what} must be True or False, got {value!r}")
    return bool(value)


def _names(value, what, allow_empty=False):
    """A name or a list of names, at least one unless `allow_empty` (where no variable is a
    question of its own: d-separation given nothing, no variable marked)."""
    if isinstance(value, str):
        return [value]
    if isinstance(value, Mapping) or not hasattr(value, "__iter__"):
        raise TypeError(f"{what} must be a name or a list of names, got {type(value).__name__}")
    names = list(value)
    for name in names:
        if not isinstance(name, str):
            raise TypeError(f"{what} must be names (strings), got {name!r}")
    if not names and not allow_empty:
        raise Error(f"{what} is empty: name at least one variable")
    return names


def _assignment(value, what, example):
    """{variable: value} as the library takes it, or the text form ("a=1,b=2")."""
    if isinstance(value, str):
        return value
    if not isinstance(value, Mapping):
        raise TypeError(f"{what} must be a dict {{variable: value}} such as {example}, got {type(value).__name__}")
    for name in value:
        if not isinstance(name, str):
            raise TypeError(f"{what} must have variable names (strings) as keys, got {name!r}")
    return value


def _evidence(value, what="evidence"):
    """{variable: state} as the library takes it (states as text); None is none."""
    if value is None:
        return {}
    if not isinstance(value, Mapping):
        raise TypeError(
            f"{what} must be a dict {{variable: state}} such as {{'PKA': 'HIGH'}}, got {type(value).__name__}"
        )
    result = {}
    for name, state in value.items():
        if not isinstance(name, str):
            raise TypeError(f"{what} must have variable names (strings) as keys, got {name!r}")
        result[name] = str(state)
    return result


def _likelihoods(value, what="soft_evidence"):
    """{variable: [weight per state]}; None is none."""
    if value is None:
        return {}
    if not isinstance(value, Mapping):
        raise TypeError(f"{what} must be a dict {{variable: [weight per state]}}, got {type(value).__name__}")
    result = {}
    for name, weights in value.items():
        if not isinstance(name, str):
            raise TypeError(f"{what} must have variable names (strings) as keys, got {name!r}")
        if isinstance(weights, (str, bytes)) or not hasattr(weights, "__iter__"):
            raise TypeError(f"{what}: the weights of '{name}' must be a list of numbers, one per state")
        result[name] = [_real(w, f"{what}['{name}']") for w in weights]
    return result


def _did_you_mean(word, known):
    """The library's "; did you mean 'x'?" for the one of `known` that `word` was most likely
    meant to be (text::closest_name: within two edits, and fewer than half its length), else ""."""
    best = _core.closest_name(word, [str(name) for name in known])
    return "" if best is None else f"; did you mean '{best}'?"


def _choice(value, what, known, kind):
    """`value` if it is one of `known`, else the library's error for an unknown name
    (pgm::unknown_name): "unknown {kind} 'x'; did you mean 'y'? (known: ...)"."""
    if not isinstance(value, str):
        raise TypeError(f"{what} must be one of {', '.join(known)}, got {type(value).__name__}")
    if value not in known:
        raise Error(_core.unknown_name_message(kind, value, list(known)))
    return value


def _axes(ax):
    """A matplotlib Axes to draw into, or None for a new figure."""
    if ax is None:
        return None
    from matplotlib.axes import Axes

    if not isinstance(ax, Axes):
        raise TypeError(f"ax must be a matplotlib Axes (e.g. from plt.subplots()) or None, got {type(ax).__name__}")
    return ax


def _shared(named):
    """The first variable in two of the (argument, names) pairs, with both arguments, else None."""
    seen = {}
    for what, names in named:
        for name in names:
            first = seen.setdefault(name, what)
            if first != what:
                return name, first, what
    return None
