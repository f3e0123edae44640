"""pgm: causal Bayesian networks with priors transferred between robot tasks.

The Python face of the pgm C++ library: pandas DataFrames in and out, the same calls as the
`pgm` program (read and write networks, fit with priors and prior transfer, exact queries,
prediction and failure prevention, PC-stable structure learning, discretization, simulation and
the paper's experiments), and the same results to the last bit. See docs/python.md.
"""

import numbers
import os

import numpy as np
import pandas as pd

from . import _core, _frame
from ._core import Error

__all__ = [
    "Error",
    "Network",
    "backends",
    "discretize",
    "experiment",
    "fit",
    "from_pgmpy",
    "learn_structure",
    "predict",
    "prevent",
    "query",
    "read_network",
    "simulate",
]

Error.__module__ = "pgm"
Error.__doc__ = "An error in pgm's input, with the library's message (a ValueError)."


class Network:
    """A discrete Bayesian network with one table per variable."""

    __slots__ = ("_net",)

    def __init__(self, handle):
        if not isinstance(handle, _core.Network):
            raise TypeError("make a Network with pgm.read_network, pgm.fit or pgm.from_pgmpy")
        self._net = handle

    @property
    def variables(self):
        """The variables' names, in the network's order."""
        return self._net.variables

    @property
    def edges(self):
        """The edges as (parent, child) pairs."""
        return self._net.edges

    @property
    def free_parameters(self):
        return self._net.free_parameters

    @property
    def success(self):
        """The success event a JSON model names in its metadata ("onTop2=1"), else None."""
        return self._net.success

    @property
    def notes(self):
        """What the fit that made this network chose: the proposed map, the prior weights."""
        return list(self._net.notes)

    def states(self, name):
        """The states of a variable, in order."""
        return self._net.states(name)

    def parents(self, name):
        """The parents of a variable, in its table's order."""
        return self._net.parents(name)

    def interval_edges(self, name):
        """The interval edges of a discretized variable, else None."""
        return self._net.interval_edges(name)

    def cpt(self, name):
        """P(name | parents) as a DataFrame: one row per parent configuration (last parent
        fastest), the parents' states, then one column of probabilities per state of `name`."""
        parents, codes, states, values = self._net.table(name)
        columns = {}
        for p, parent in enumerate(parents):
            labels = np.array(self._net.states(parent), dtype=object)
            columns[parent] = labels[codes[:, p]]
        for x, state in enumerate(states):
            columns[state] = values[:, x]
        return pd.DataFrame(columns)

    def write(self, path):
        """Writes the network as .bif, .xml (XMLBIF), .net (Hugin) or .json (by the extension), atomically."""
        self._net.write(os.fspath(path))

    def to_pgmpy(self):
        """The network as a pgmpy model (pgmpy must be importable)."""
        from ._pgmpy import to_pgmpy

        return to_pgmpy(self)

    def __repr__(self):
        return (
            f"<pgm.Network: {len(self.variables)} variables, {len(self.edges)} edges, "
            f"{self.free_parameters} free parameters>"
        )


def read_network(path):
    """Reads a network from a .bif, .xml (XMLBIF), .net (Hugin) or .json file, as the `pgm` program does."""
    return Network(_core.read_network(os.fspath(path)))


def from_pgmpy(model):
    """A Network with the variables, states and tables of a pgmpy model."""
    from ._pgmpy import from_pgmpy as convert

    return convert(model)


def backends():
    """The simulator back-ends this build has ("analytic", and "bullet" when built)."""
    return _core.backends()


def _edge_pairs(edges):
    if isinstance(edges, str):
        return _core.parse_edge_list(edges)
    pairs = []
    for edge in edges:
        parent, child = edge
        pairs.append((str(parent), str(child)))
    return pairs


def _edges_argument(edges, what):
    """({name: edges}, None) for a dict of interval edges, (None, path) for a discretization file."""
    if edges is None:
        return None, None
    if isinstance(edges, (str, os.PathLike)):
        return None, os.fspath(edges)
    if isinstance(edges, dict):
        return {str(name): [float(e) for e in values] for name, values in edges.items()}, None
    raise TypeError(f"{what} must be a dict of interval edges (from pgm.discretize) or a path to an edges file")


def _text(value, what):
    if value is None:
        return None
    if not isinstance(value, str):
        raise TypeError(f"{what} must be a string, got {type(value).__name__}")
    return value


def fit(
    data,
    edges,
    estimator="mle",
    prior=None,
    ess=None,
    prior_model=None,
    strategy=None,
    map=None,
    w_prior=None,
    *,
    alpha=None,
    intervals=None,
    empty="uniform",
    success=None,
    match=None,
    threads=0,
    missing="error",
):
    """Estimates every table of the network `edges` describe from `data`, as `pgm fit`.

    data: a DataFrame whose columns named by the edges hold states (integer, string,
    categorical). edges: (parent, child) pairs or "a->b,c->b". estimator: "mle" or "bayes";
    prior: "k2", "bdeu" (default for bayes) or "dirichlet", with `ess` (bdeu) or `alpha`
    (dirichlet). prior_model: a Network of a related task whose tables become priors by
    `strategy` ("minimal", the default, "direct", "cross" or a registered one) through the
    correspondence `map` ("onTop2=onTop1,xOff2~xOff1" or "auto"), weighted by `w_prior` (a
    number, 5 by default, or "auto"). intervals: the interval edges the columns' codes stand
    for ({name: edges} from pgm.discretize, or an edges file), kept with the model. missing:
    what a missing value (NaN, None, pd.NA) does, as `--missing`: "error" (the default), "drop"
    (rows with one are left out, with a warning) or "available" (each table counted over the
    rows where its family is present).
    """
    names = _frame.column_names(data)
    pairs = _edge_pairs(edges)
    wanted = {name for pair in pairs for name in pair}
    data = _frame.with_missing(data, wanted, missing)
    columns = _frame.columns_of(data, wanted)
    interval_edges, interval_file = _edges_argument(intervals, "intervals")
    if prior_model is None:
        if strategy is not None or map is not None or w_prior is not None or success is not None or match is not None:
            raise Error("strategy, map, w_prior, success and match apply with prior_model")
        handle = None
    elif isinstance(prior_model, Network):
        handle = prior_model._net
        if map is None:
            raise Error('prior_model needs map, e.g. map="onTop2=onTop1,xOff2~xOff1" or map="auto"')
    else:
        raise TypeError("prior_model must be a pgm.Network")
    if w_prior is None:
        weight = 5.0
    elif isinstance(w_prior, str):
        if w_prior != "auto":
            raise Error(f"w_prior must be a number >= 0 or 'auto', got '{w_prior}'")
        weight = None
    elif isinstance(w_prior, numbers.Real) and not isinstance(w_prior, bool):
        weight = float(w_prior)
    else:
        raise TypeError("w_prior must be a number or 'auto'")
    net = _core.fit(
        columns,
        names,
        pairs,
        estimator,
        _text(prior, "prior"),
        None if alpha is None else float(alpha),
        None if ess is None else float(ess),
        empty,
        int(threads),
        interval_edges,
        interval_file,
        handle,
        strategy or "minimal",
        map or "",
        weight,
        success or "1",
        match or "midpoint",
    )
    return Network(net)


def query(network, variables, evidence=None):
    """P(variables | evidence) by variable elimination, as a Series indexed by state (a
    MultiIndex over several variables, the last fastest). variables: a name or a list of
    names; evidence: {name: state}."""
    if isinstance(variables, str):
        variables = [variables]
    variables = list(variables)
    observed = {str(k): str(v) for k, v in (evidence or {}).items()}
    states, values, _ = _core.query(network._net, variables, observed)
    if len(variables) == 1:
        index = pd.Index(states[0], name=variables[0])
    else:
        index = pd.MultiIndex.from_product(states, names=variables)
    return pd.Series(values, index=index, name="probability")


def predict(network, assign, success=None, marginalize=False):
    """The predicted probability that the plan `assign` succeeds, as `pgm predict`.
    assign: {variable: value} or "xOff1=0.3,yOff1=-1.2": a number is binned by an interval
    variable's edges, other values are state labels ("@2" names the state labelled 2)."""
    return _core.predict(network._net, assign, success, bool(marginalize))


def prevent(network, assign, controllable=None, epsilon=0.8, success=None, distance="steps", marginalize=False):
    """Predicts the plan `assign`; below `epsilon`, explains the failure and suggests the
    nearest values of the `controllable` variables (default: every parent of the success
    variable) predicted to succeed, as `pgm prevent`. Returns a dict: predicted,
    failure_predicted, suggestion ({variable: value}), predicted_after, responsible (the
    variables that move), steps, distance, target_succeeds and success."""
    if isinstance(controllable, str):
        controllable = [c.strip() for c in controllable.split(",")]
    return _core.prevent(
        network._net,
        assign,
        None if controllable is None else list(controllable),
        float(epsilon),
        distance,
        success,
        bool(marginalize),
    )


def learn_structure(
    data, test="g2", alpha=0.01, tiers=None, forbid=None, require=None, *, max_cond=3, threads=0, missing="error"
):
    """PC-stable on the frame's columns (all discrete), as `pgm learn-structure`: the edges of
    one DAG of the learned equivalence class, as (parent, child) pairs. tiers: "a,b;c;d" or a
    list of lists of names, earliest first; forbid and require: edges as for pgm.fit. missing:
    as for pgm.fit; with "available" each test counts the rows where its variables are present."""
    names = _frame.column_names(data)
    data = _frame.with_missing(data, names, missing)
    columns = _frame.columns_of(data, names)

    def edges_text(edges):
        if edges is None:
            return ""
        if isinstance(edges, str):
            return edges
        return ",".join(f"{parent}->{child}" for parent, child in edges)

    if tiers is None:
        tiers_text = ""
    elif isinstance(tiers, str):
        tiers_text = tiers
    else:
        tiers_text = ";".join(",".join(tier) for tier in tiers)
    return _core.learn_structure(
        columns, test, float(alpha), int(max_cond), tiers_text, edges_text(forbid), edges_text(require), int(threads)
    )


def discretize(data, bins=5, columns=None, *, method="quantile", edges=None, missing="error"):
    """Bins continuous columns, as `pgm discretize`: the named columns, or every numeric column
    with more distinct values than `bins`; by quantile (equal frequency, as in the paper) or
    "width", or by saved `edges` ({name: edges} or an edges file) to bin new data the same
    way. Returns (a copy of the frame with each binned column replaced by its bin codes
    0..k-1, {name: edges}). missing: as for pgm.fit, over the binned columns; with "available"
    a missing value stays missing (pd.NA in the binned column) and edges are fitted on the rest."""
    names = _frame.column_names(data)
    wanted = [] if columns is None else ([columns] if isinstance(columns, str) else list(columns))
    saved, saved_file = _edges_argument(edges, "edges")
    if wanted:
        convert = set(wanted)
    else:  # only numbers can be binned: other columns need not cross
        convert = {n for n in names if _frame.is_number_column(data[n])} | set(saved or {})
    data = _frame.with_missing(data, convert, missing)
    specs = [_frame.numeric_column(name, data[name]) for name in names if name in convert]
    binned, fitted = _core.discretize(specs, names, int(bins), wanted, method, saved, saved_file)
    result = data.copy()
    for name, kind, array, labels in binned:
        result[name] = _frame.series_of(kind, array, labels)
    return result, fitted


def simulate(task, rows, seed=0, backend="analytic", variant="sim", *, threads=0, tasks_dir=None):
    """Runs `rows` experiments of a task (1-stack, 2-stack, drop-plate, …) with a simulator
    back-end, as `pgm simulate`: the raw data as a DataFrame. The same seed gives the same data
    for any number of threads. variant "reality" is the stacking tasks' stand-in for the real
    robot (not real data)."""
    columns = _core.simulate(
        task, int(rows), int(seed), backend, variant, int(threads), None if tasks_dir is None else os.fspath(tasks_dir)
    )
    return _frame.frame_of(columns)


def experiment(scenario, reps=None, seed=1, backend="analytic", *, threads=0, distance="steps", auto=True, tasks_dir=None):
    """Runs a transfer scenario of the paper (2-stack-sim, 2-stack-reality, 2-stack-sim-to-real,
    sphere-dropping, stack-to-drop, or "all"), as `pgm experiment`: a tidy DataFrame with the
    columns of points.csv (scenario, target, strategy, w, rows, repetition, metric, value).
    The protocol's notes are in `.attrs["notes"]`."""
    columns, notes = _core.experiment(
        scenario,
        0 if reps is None else int(reps),
        int(seed),
        backend,
        int(threads),
        distance,
        bool(auto),
        None if tasks_dir is None else os.fspath(tasks_dir),
    )
    frame = pd.DataFrame(
        {
            name: pd.Categorical.from_codes(value[0], categories=value[1]) if isinstance(value, tuple) else value
            for name, value in columns.items()
        }
    )
    frame.attrs["notes"] = list(notes)
    return frame
