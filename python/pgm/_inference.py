"""Inference engines for Python: pgm.InferenceEngine compiles a network once (junction tree,
variable elimination, likelihood weighting or Gibbs sampling) and answers many queries under
evidence that is set and retracted without recompiling. Results are pandas Series indexed by
state; the C++ engine computes without the GIL."""

import math

import pandas as pd

from . import _core
from ._checks import _evidence, _likelihoods, _names, _network, _seed, _threads, _whole


def _series_maker():
    """The quickest way this pandas has to make a float Series over a kept index: pandas 1.x's
    block manager (3 µs a Series instead of 10 µs, which all marginals of a network of hundreds of
    variables would feel), else the public constructor. Checked once against the constructor."""

    def public(values, index, name):
        return pd.Series(values, index=index, name=name)

    try:
        import warnings

        import numpy as np
        from pandas.core.internals import SingleBlockManager

        def managed(values, index, name):
            return pd.Series(SingleBlockManager.from_array(values, index), name=name, fastpath=True)

        with warnings.catch_warnings():
            warnings.simplefilter("error")  # a deprecated path is not taken
            index = pd.Index(["a", "b"], name="x")
            probe = managed(np.array([0.25, 0.75]), index, "p")
            if probe.equals(public(np.array([0.25, 0.75]), index, "p")) and probe.name == "p" and probe.index is index:
                return managed
    except Exception:  # noqa: BLE001 - any failure means the internal path is not this pandas's
        pass
    return public


_new_series = _series_maker()

# Every engine's name, pgm's own and any a C++ extension registered before import.
ENGINES = tuple(_core.engine_names())


class InferenceEngine:
    """Queries on one model, compiled once: a pgm.Network (Bayesian) or a pgm.MarkovNetwork.

    engine: "auto" (the junction tree unless it is too large, then likelihood weighting for a
    Bayesian network and loopy belief propagation for a Markov network), "jt", "ve", "bp",
    "gibbs", or "lw" (Bayesian networks only: it samples along the arrows); pgm.ENGINES lists
    them with any registered from C++. A name may carry the engine's options,
    "bp[damping=0.5,max_iterations=200]", as pgm._core.engine_listing() declares them. samples,
    seed, burn_in and threads set the sampling engines (the same numbers for a seed, whatever
    the threads); the brackets override them. Evidence stays until replaced:
    set_evidence({variable: state}) for observed states, set_soft_evidence({variable: [weight
    per state]}) for likelihoods."""

    def __init__(self, network, engine="auto", *, samples=100_000, seed=1, burn_in=1_000, threads=0):
        from ._markov import MarkovNetwork

        if isinstance(network, MarkovNetwork):
            model = network._model
        else:
            model = _network(network, "network", markov=True)._net
        if not isinstance(engine, str):
            raise TypeError(f"engine must be one of {', '.join(ENGINES)}, got {type(engine).__name__}")
        self.network = network
        self._engine = _core.Engine(
            model,
            engine,
            _whole(samples, "samples", 1, 1_000_000_000),  # pgm query --samples' bound: more would not fit in memory
            _seed(seed),
            _whole(burn_in, "burn_in", 0, 100_000_000),
            _threads(threads),
        )
        self._hard = {}
        self._soft = {}
        self._do = {}
        self._indexes = {}

    @property
    def name(self):
        """The engine that answers ("jt", "ve", "bp", "lw", "gibbs"; for "auto", the one it chose)."""
        return self._engine.name

    @property
    def note(self):
        """Why "auto" chose its engine; empty otherwise."""
        return self._engine.note

    def set_evidence(self, evidence=None):
        """Observed states {variable: state}; replaces the previous ones (None retracts them)."""
        self._set(_evidence(evidence), self._soft, self._do)

    def set_soft_evidence(self, evidence=None):
        """Likelihoods {variable: [weight per state, in the variable's order]}: P(x | evidence)
        is multiplied by the weight of x. Replaces the previous ones (None retracts them)."""
        self._set(self._hard, _likelihoods(evidence, "soft evidence"), self._do)

    def set_interventions(self, do=None):
        """Interventions {variable: state}: each variable set to its state and cut from its
        parents (graph surgery), so queries answer P(· | do(...), evidence). Replaces the previous
        ones (None retracts them)."""
        self._set(self._hard, self._soft, _evidence(do, "do"))

    def _set(self, hard, soft, do=None):
        do = {} if do is None else do
        self._engine.set_evidence(hard, soft, do)
        self._hard, self._soft, self._do = hard, soft, do

    def _index(self, name):
        index = self._indexes.get(name)
        if index is None:
            index = self._indexes[name] = pd.Index(self.network.states(name), name=name)
        return index

    def _series(self, names, values, errors):
        if len(names) == 1:
            index = self._index(names[0])
        else:
            index = pd.MultiIndex.from_product([self.network.states(n) for n in names], names=names)
        series = _new_series(values, index, "probability")
        if errors is not None:
            series.attrs["standard_error"] = _new_series(errors, index, "standard_error")
        return series

    def marginal(self, variable):
        """P(variable | evidence) as a Series indexed by state; a sampling engine's standard
        errors are in .attrs["standard_error"]."""
        if not isinstance(variable, str):
            raise TypeError(f"variable must be a name (str), got {type(variable).__name__}")
        values, _, errors = self._engine.joint([variable])
        return self._series([variable], values, errors)

    def joint(self, variables):
        """P(variables | evidence) over their joint states (a MultiIndex, the last fastest)."""
        names = _names(variables, "variables")
        values, _, errors = self._engine.joint(names)
        return self._series(names, values, errors)

    def marginals(self):
        """Every unobserved variable's marginal, {name: Series}, from one propagation."""
        answers = {}
        for name, values, errors in self._engine.marginals():
            if errors is None:  # an exact engine's: the Series alone
                answers[name] = _new_series(values, self._index(name), "probability")
            else:
                answers[name] = self._series([name], values, errors)
        return answers

    def mpe(self, variables=None):
        """The most probable joint state of every unobserved variable (or of `variables`, the
        others summed out) given the evidence: ({variable: state}, its probability)."""
        names = None if variables is None else _names(variables, "variables")
        states, probability, _ = self._engine.mpe(names)
        return states, probability

    def probability_of_evidence(self):
        """P(evidence); 0.0 where it underflows a double (see log_probability_of_evidence)."""
        return math.exp(self._engine.log_probability_of_evidence())

    def log_probability_of_evidence(self):
        return self._engine.log_probability_of_evidence()

    def log_partition_function(self):
        """ln Z given the evidence (the logarithm of the sum of the factors' product over every
        state the evidence allows): for a Bayesian network, ln P(evidence)."""
        return self._engine.log_partition_function()

    def __repr__(self):
        return f"<pgm.InferenceEngine {self.name} on {self.network!r}>"
