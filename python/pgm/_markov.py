"""Markov networks for Python: pgm.MarkovNetwork holds named variables and any non-negative factors
over them (a factor graph, as the UAI competitions' MARKOV files and pgmpy's MarkovNetwork), and
answers the competition's tasks exactly by a junction tree or variable elimination, or
approximately by loopy belief propagation or Gibbs sampling (marginals). Factors are NumPy arrays with one axis per variable
of their scope, in scope order."""

import numpy as np
import pandas as pd

from . import _core
from ._checks import _choice, _evidence, _whole

SOLVE_ENGINES = ("auto", "jt", "ve", "bp", "gibbs")


def _engine_name(engine):
    return _choice(engine, "engine", SOLVE_ENGINES, "engine")


class MarkovNetwork:
    """An undirected graphical model: P(x) = Π φ(x_scope) / Z.

    MarkovNetwork({variable: [states]}, [(scope, values), ...]), each factor's values an array
    of one axis per variable of its scope (or flat, the last variable fastest), finite and not
    negative. pgm.read_network reads a MARKOV .uai file as one."""

    __slots__ = ("_model", "memory_limit")

    def __init__(self, variables, factors, *, memory_limit=4096):
        if isinstance(variables, _core.MarkovNetwork):
            self._model = variables
        else:
            if not hasattr(variables, "items"):
                raise TypeError(f"variables must be {{name: [states]}}, got {type(variables).__name__}")
            specs = []
            for scope, values in factors:
                names = [scope] if isinstance(scope, str) else list(scope)
                specs.append((names, np.asarray(values, dtype=float).ravel().tolist()))
            self._model = _core.MarkovNetwork([(str(n), [str(s) for s in states]) for n, states in variables.items()],
                                              specs)
        self.memory_limit = memory_limit

    @property
    def variables(self):
        return self._model.variables

    def states(self, variable):
        return self._model.states(variable)

    @property
    def factors(self):
        """[(scope, values)], values an array with one axis per variable of the scope."""
        result = []
        for scope, values in self._model.factors:
            shape = [len(self.states(v)) for v in scope]
            result.append((tuple(scope), np.asarray(values, dtype=float).reshape(shape)))
        return result

    def write(self, path):
        """Writes the model atomically: as pgm's JSON model (names and all) to a .json path, else
        as a MARKOV .uai file (which keeps no names: v0, v1, …)."""
        self._model.write(str(path))

    def _solve(self, task, evidence, engine):
        # MiB, bounded as pgm solve --memory-limit: C++ shifts it into bytes, which must not overflow.
        memory_limit = _whole(self.memory_limit, "memory_limit", 1, 1 << 24)
        return self._model.solve(task, _evidence(evidence), _engine_name(engine), memory_limit)

    def log_partition_function(self, evidence=None, engine="auto"):
        """ln Z with the evidence {variable: state} entered (−inf when it is impossible)."""
        return self._solve("PR", evidence, engine)[0]

    def marginals(self, evidence=None, engine="auto"):
        """Every variable's marginal given the evidence, {name: Series indexed by state}."""
        values = self._solve("MAR", evidence, engine)[0]
        return {
            name: pd.Series(v, index=pd.Index(self.states(name), name=name), name="probability")
            for name, v in zip(self.variables, values)
        }

    def map(self, evidence=None, engine="auto"):
        """A most probable joint state of every variable given the evidence, {name: state}."""
        states = self._solve("MAP", evidence, engine)[0]
        return {name: self.states(name)[s] for name, s in zip(self.variables, states)}

    def to_pgmpy(self):
        """pgmpy's MarkovNetwork with one DiscreteFactor per factor."""
        from itertools import combinations

        from pgmpy.factors.discrete import DiscreteFactor
        from pgmpy.models import MarkovNetwork as PgmpyMarkovNetwork

        model = PgmpyMarkovNetwork()
        model.add_nodes_from(self.variables)
        for scope, values in self.factors:
            model.add_edges_from(combinations(scope, 2))
            model.add_factors(
                DiscreteFactor(list(scope), list(values.shape), values.ravel(),
                               state_names={v: self.states(v) for v in scope}))
        return model

    def __repr__(self):
        return f"<pgm.MarkovNetwork: {len(self.variables)} variables, {len(self._model.factors)} factors>"


def markov_from_pgmpy(model):
    """A MarkovNetwork from pgmpy's MarkovNetwork or FactorGraph (their DiscreteFactors)."""
    variables = {}
    factors = []
    for factor in model.get_factors():
        for name in factor.scope():
            variables.setdefault(str(name), [str(s) for s in factor.state_names[name]])
        factors.append(([str(n) for n in factor.scope()], np.asarray(factor.values, dtype=float)))
    for node in model.nodes():
        if str(node) not in variables:
            cardinality = model.get_cardinality(node)
            variables[str(node)] = [str(s) for s in range(cardinality)]
    return MarkovNetwork(variables, factors)
