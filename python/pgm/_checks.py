"""Argument checks shared by the package's public functions: a TypeError for a wrong type, a
pgm.Error for a wrong value, each naming the argument and what was expected."""

import numbers
import os
from collections.abc import Mapping

import numpy as np

from ._core import Error


def _network(network, what="network"):
    from . import Network

    if not isinstance(network, Network):
        raise TypeError(
            f"{what} must be a pgm.Network (from pgm.read_network or pgm.fit), got {type(network).__name__}"
        )
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


def _whole(value, what, least=0):
    """An int (or NumPy integer) of at least `least`; bools and floats are refused."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{what} must be a whole number, got {value!r}")
    if value < least:
        raise Error(f"{what} must be a whole number of at least {least}, got {value}")
    return int(value)


def _real(value, what):
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{what} must be a number, got {value!r}")
    return float(value)


def _flag(value, what):
    if not isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{what} must be True or False, got {value!r}")
    return bool(value)


def _names(value, what):
    """A name or a list of names, at least one."""
    if isinstance(value, str):
        return [value]
    if isinstance(value, Mapping) or not hasattr(value, "__iter__"):
        raise TypeError(f"{what} must be a name or a list of names, got {type(value).__name__}")
    names = list(value)
    for name in names:
        if not isinstance(name, str):
            raise TypeError(f"{what} must be names (strings), got {name!r}")
    if not names:
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
