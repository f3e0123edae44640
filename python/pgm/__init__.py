"""pgm: causal Bayesian networks with priors transferred between robot tasks.

The Python face of the pgm C++ library: pandas DataFrames in and out, the same calls as the
`pgm` program (read and write networks, fit with priors and prior transfer, exact queries,
prediction and failure prevention, PC-stable structure learning, discretization, simulation and
the paper's experiments), and the same results to the last bit. See docs/python.md.
"""

import inspect
import math
import numbers
import os
from collections.abc import Mapping

import numpy as np
import pandas as pd

from . import _core, _frame
from ._checks import _assignment, _choice, _did_you_mean, _flag, _names, _path, _real, _seed, _text, _threads, _whole
from ._core import Error
from . import _checks
from ._inference import ENGINES, InferenceEngine
from ._dynamic import DynamicNetwork, _long_form_columns
from ._markov import MarkovNetwork
from ._decisions import DecisionSolution, InfluenceDiagram

__version__ = _core.__version__

__all__ = [
    "ENGINES",
    "backdoor_sets",
    "check",
    "counterfactual",
    "d_separated",
    "DecisionSolution",
    "DynamicNetwork",
    "Error",
    "InferenceEngine",
    "InfluenceDiagram",
    "intervene",
    "Network",
    "backends",
    "discretize",
    "experiment",
    "fit",
    "fit_dynamic",
    "from_pgmpy",
    "learn_structure",
    "MarkovNetwork",
    "mpe",
    "predict",
    "prevent",
    "query",
    "read_network",
    "score",
    "simulate",
]

Error.__module__ = "pgm"
Error.__doc__ = "An error in pgm's input, with the library's message (a ValueError)."


class Network:
    """A discrete Bayesian network with one table per variable."""

    __slots__ = ("_net", "_engines")

    def __init__(self, handle):
        if not isinstance(handle, _core.Network):
            raise TypeError("make a Network with pgm.read_network, pgm.fit or pgm.from_pgmpy")
        self._net = handle
        self._engines = {}

    def _engine(self, name):
        """The network's own engine of that name, compiled on first use (pgm.query, pgm.mpe)."""
        engine = self._engines.get(name)
        if engine is None:
            engine = self._engines[name] = InferenceEngine(self, name)
        return engine

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
        return self._net.states(_variable(name))

    def parents(self, name):
        """The parents of a variable, in its table's order."""
        return self._net.parents(_variable(name))

    def interval_edges(self, name):
        """The interval edges of a discretized variable, else None."""
        return self._net.interval_edges(_variable(name))

    def cpt(self, name):
        """P(name | parents) as a DataFrame: one row per parent configuration (last parent
        fastest), the parents' states, then one column of probabilities per state of `name`."""
        parents, codes, states, values = self._net.table(_variable(name))
        columns = {}
        for p, parent in enumerate(parents):
            labels = np.array(self._net.states(parent), dtype=object)
            columns[parent] = labels[codes[:, p]]
        for x, state in enumerate(states):
            columns[state] = values[:, x]
        return pd.DataFrame(columns)

    def write(self, path):
        """Writes the network as .bif, .xml (XMLBIF), .net (Hugin) or .json (by the extension), atomically.
        A network with counts (`has_counts`) keeps them, in BIF, XMLBIF and NET as a property
        that other tools ignore."""
        self._net.write(_path(path, "path"))

    @property
    def has_counts(self):
        """Whether the network carries the counts it was estimated from, so that `update` can
        add rows to them (pgm.fit(..., keep_counts=True), or a model file written so)."""
        return self._net.has_counts

    def update(self, data, decay=1.0, *, threads=0):
        """A new network: this one's counts, times `decay` in (0, 1], plus the rows of `data` (a
        DataFrame with a column per variable, holding the network's states; a missing value
        leaves out only the tables it is in), each table estimated again under the prior it was
        fitted with. With decay 1 it equals fitting all the rows at once, to the last bit. As
        `pgm update`; the network itself is unchanged."""
        decay = _real(decay, "decay")
        if not 0 < decay <= 1:
            raise Error(f"decay must be in (0, 1], got {decay}")
        names = self.variables
        columns = _frame.columns_of(data, names)
        return Network(_core.update(self._net, columns, _frame.column_names(data), decay, _threads(threads)))

    def to_dot(self, success=None, controllable=None):
        """The structure as Graphviz DOT text, as `pgm draw --out NAME.dot`: the success
        variable (default: the one `success` names) bold on green, the `controllable` ones as
        blue boxes."""
        return self._net.to_dot(*self._marks(success, controllable))

    def draw(self, path=None, *, success=None, controllable=None):
        """The structure drawn by Graphviz's dot (Debian's graphviz), as `pgm draw`: the SVG text
        when `path` is None (a str that a notebook shows as the picture), else written to `path`
        (.svg, .png, .pdf, or .dot for the text)."""
        text = self.to_dot(success, controllable)
        if path is None:
            return _Svg(_graphviz(text, "svg").decode("utf-8"))
        path = _path(path, "path")
        kind = os.path.splitext(path)[1].lower().lstrip(".")
        if kind not in ("svg", "png", "pdf", "dot"):
            raise Error(f"path '{path}': expected a .svg, .png, .pdf or .dot file")
        data = text.encode("utf-8") if kind == "dot" else _graphviz(text, kind)
        temporary = f"{path}.tmp-{os.getpid()}"
        with open(temporary, "wb") as out:
            out.write(data)
        os.replace(temporary, path)
        return None

    def plot_table(self, node, x, y, *, given=None, average=False, state=None, counts=False, path=None, ax=None):
        """The table of `node` as a heat map over its parents `x` (across) and `y` (up), as
        `pgm plot-table`: the probability of `state` (default: the success state when `node` is
        the success variable, else the last state) in each cell, ticks at the interval edges in
        the variables' units. The other parents are fixed by `given` ({name: value}, a number
        in an interval variable's units or "@label", as for pgm.predict) or, with `average`,
        summed out under the network's joint. counts: write each cell's rows too (a network fitted
        with keep_counts=True). Draws into `ax` when given, else a new figure; writes `path`
        (.png, .svg, .pdf) when given. Returns the matplotlib Figure. Needs matplotlib."""
        try:
            from matplotlib.figure import Figure
        except ImportError:
            raise Error("plot_table needs matplotlib (Debian: apt-get install python3-matplotlib)") from None
        ax = _checks._axes(ax)
        if path is not None:
            path = _path(path, "path")
            kind = os.path.splitext(path)[1].lower().lstrip(".")
            if kind not in ("png", "svg", "pdf"):
                raise Error(f"path '{path}': expected a .png, .svg or .pdf file")
        if state is None and self.success is not None and self.success.split("=")[0] == node:
            state = self.success.split("=", 1)[1]
        given = None if given is None else _assignment(given, "given", "{'xOff1': '@2'}")
        probability, rows, label = _core.slice_table(
            self._net, _variable(node), _variable(x), _variable(y), given, _flag(average, "average"),
            None if state is None else str(state), _flag(counts, "counts"),
        )
        if ax is None:
            figure = Figure(figsize=(6.4, 5.2), layout="constrained")
            ax = figure.add_subplot()
        figure = ax.figure
        x_edges, x_ticks, x_labels = self._axis(x)
        y_edges, y_ticks, y_labels = self._axis(y)
        mesh = ax.pcolormesh(x_edges, y_edges, probability, cmap="viridis", vmin=0.0, vmax=1.0)
        ax.set_xticks(x_ticks, x_labels)
        ax.set_yticks(y_ticks, y_labels)
        ax.set_xlabel(x)
        ax.set_ylabel(y)
        if isinstance(given, str):
            conditions = [x, y, given]
        else:
            conditions = [x, y] + [f"{name} = {value}" for name, value in (given or {}).items()]
        title = f"P({node} = {label} | {', '.join(conditions)})" + (", others averaged" if average else "")
        ax.set_title(title, fontsize=10)
        figure.colorbar(mesh, ax=ax, label=f"P({node} = {label})")
        if rows is not None:
            for j in range(probability.shape[0]):
                for i in range(probability.shape[1]):
                    ax.text(
                        (x_edges[i] + x_edges[i + 1]) / 2, (y_edges[j] + y_edges[j + 1]) / 2,
                        f"{probability[j, i]:.2f}\n{rows[j, i]:g} rows", ha="center", va="center", fontsize=8,
                        color="white" if probability[j, i] < 0.6 else "black",
                    )
        if path is not None:
            temporary = f"{path}.tmp-{os.getpid()}.{kind}"
            figure.savefig(temporary, format=kind, dpi=110)
            os.replace(temporary, path)
        return figure

    def _axis(self, name):
        """A plot axis of a variable: cell edges, tick positions and labels (interval edges in its
        units; one unit per state of a categorical variable, labelled at its middle)."""
        edges = self.interval_edges(name)
        if edges is not None:
            return np.asarray(edges), edges, [f"{e:.3g}" for e in edges]
        states = self.states(name)
        return np.arange(len(states) + 1.0), [k + 0.5 for k in range(len(states))], states

    def _repr_html_(self):
        """A notebook's table of the network: each variable's states, parents and table size."""
        from html import escape

        rows = []
        for name in self.variables:
            states = self.states(name)
            shown = ", ".join(states[:8]) + (f", … ({len(states)} states)" if len(states) > 8 else "")
            parents = self.parents(name)
            size = len(states)
            for parent in parents:
                size *= len(self.states(parent))
            rows.append(
                f"<tr><td><b>{escape(name)}</b></td><td>{escape(shown)}</td>"
                f"<td>{escape(', '.join(parents)) or '—'}</td><td style='text-align:right'>{size}</td></tr>"
            )
        counts = "; it carries its counts" if self.has_counts else ""
        success = f"; success: {escape(self.success)}" if self.success else ""
        return (
            f"<p><b>pgm.Network</b>: {len(self.variables)} variables, {len(self.edges)} edges, "
            f"{self.free_parameters} free parameters{success}{counts}</p>"
            "<table><thead><tr><th>variable</th><th>states</th><th>parents</th><th>table cells</th></tr></thead>"
            f"<tbody>{''.join(rows)}</tbody></table>"
        )

    def _repr_svg_(self):
        """A notebook's picture of the network (None where Graphviz is not installed)."""
        try:
            return str(self.draw())
        except Error:
            return None

    def _marks(self, success, controllable):
        if success is None:
            success = [] if self.success is None else [self.success.split("=")[0]]
        else:
            success = _names(success, "success", allow_empty=True)  # []: no variable marked
        controllable = [] if controllable is None else _names(controllable, "controllable", allow_empty=True)
        return success, controllable

    def to_pgmpy(self):
        """The network as a pgmpy model (pgmpy must be importable)."""
        from ._pgmpy import to_pgmpy

        return to_pgmpy(self)

    def __repr__(self):
        return (
            f"<pgm.Network: {len(self.variables)} variables, {len(self.edges)} edges, "
            f"{self.free_parameters} free parameters>"
        )


class _Svg(str):
    """SVG text that a notebook shows as the picture."""

    def _repr_svg_(self):
        return str(self)


def _graphviz(text, kind):
    """`text` rendered by Graphviz's dot as `kind` (svg, png, pdf)."""
    import shutil
    import subprocess

    if shutil.which("dot") is None:
        raise Error("drawing needs Graphviz's dot (Debian: apt-get install graphviz); to_dot() gives the text")
    result = subprocess.run(["dot", f"-T{kind}"], input=text.encode("utf-8"), capture_output=True)
    if result.returncode != 0:
        raise Error(f"Graphviz's dot could not draw the network: {result.stderr.decode(errors='replace')}")
    return result.stdout


def read_network(path):
    """Reads a network from a .bif, .xml (XMLBIF), .net (Hugin), .json or .uai file, as the `pgm`
    program does; a .uai file that declares MARKOV, or a .json model of "kind": "markov", is a
    pgm.MarkovNetwork, and a .json model of "kind": "dynamic" a pgm.DynamicNetwork."""
    path = _path(path, "path")
    name = os.fspath(path).lower()
    if name.endswith(".uai") or name.endswith(".uai.gz"):
        kind, handle = _core.read_uai(path)
        return MarkovNetwork(handle, None) if kind == "markov" else Network(handle)
    if name.endswith(".json") or name.endswith(".json.gz"):
        handle = _core.read_markov_json(path)
        if handle is not None:
            return MarkovNetwork(handle, None)
        found = _core.read_dynamic_json(path)
        if found is not None:
            return DynamicNetwork(*found)
    return Network(_core.read_network(path))


def from_pgmpy(model):
    """A Network with the variables, states and tables of a pgmpy Bayesian network, a
    MarkovNetwork with the factors of a pgmpy MarkovNetwork or FactorGraph, or a DynamicNetwork
    with the two slices of a pgmpy DynamicBayesianNetwork."""
    if type(model).__name__ in ("MarkovNetwork", "FactorGraph"):
        from ._markov import markov_from_pgmpy

        return markov_from_pgmpy(model)
    if type(model).__name__ == "DynamicBayesianNetwork":
        from ._pgmpy import dynamic_from_pgmpy

        return dynamic_from_pgmpy(model)
    from ._pgmpy import from_pgmpy as convert

    return convert(model)


def backends():
    """The simulator back-ends this build has ("analytic", and "bullet" when built)."""
    return _core.backends()


def _edge_pairs(edges, what="edges"):
    if isinstance(edges, str):
        return _core.parse_edge_list(edges)
    if isinstance(edges, Mapping) or not hasattr(edges, "__iter__"):
        raise TypeError(f'{what} must be "a->b,c->b" or a list of (parent, child) pairs, got {type(edges).__name__}')
    pairs = []
    for edge in edges:
        if isinstance(edge, str) or not hasattr(edge, "__len__") or len(edge) != 2:
            raise TypeError(f"{what} must be (parent, child) pairs, got {edge!r}")
        parent, child = edge
        if not isinstance(parent, str) or not isinstance(child, str):
            raise TypeError(f"{what} must be pairs of names (strings), got {edge!r}")
        pairs.append((parent, child))
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




def _variable(name):
    if not isinstance(name, str):
        raise TypeError(f"name must be a variable's name (a string), got {name!r}")
    return name




def _handle(network, what="network"):
    if not isinstance(network, Network):
        raise TypeError(
            f"{what} must be a pgm.Network (from pgm.read_network or pgm.fit), got {type(network).__name__}"
        )
    return network._net












def fit(
    data,
    edges,
    estimator="mle",
    prior="bdeu",
    ess=1.0,
    prior_model=None,
    strategy=None,
    map=None,
    w_prior=None,
    *,
    alpha=1.0,
    intervals=None,
    empty="uniform",
    success=None,
    match=None,
    threads=0,
    missing="error",
    latent=None,
    restarts=1,
    seed=0,
    max_iterations=100,
    tolerance=1e-6,
    hard=False,
    keep_counts=False,
    states=None,
):
    """Estimates every table of the network `edges` describe from `data`, as `pgm fit`.

    data: a DataFrame whose columns named by the edges hold states (integer, string,
    categorical). edges: (parent, child) pairs or "a->b,c->b". estimator: "mle" or "bayes";
    prior: "bdeu", "dirichlet", "k2", "none" or a registered prior; NAME[KEY=VALUE,...] sets
    its options, as "dirichlet[alpha=2]"; `ess` (bdeu's) and `alpha` (dirichlet's) set one when
    they differ from their defaults (the library's). prior_model: a Network of a related task whose tables become priors by
    `strategy` ("minimal", the default, "direct", "cross" or a registered one) through the
    correspondence `map` ("onTop2=onTop1,xOff2~xOff1" or "auto"), weighted by `w_prior` (a
    number, 5 by default, or "auto"). intervals: the interval edges the columns' codes stand
    for ({name: edges} from pgm.discretize, or an edges file), kept with the model. missing:
    what a missing value (NaN, None, pd.NA) does, as `--missing`: "error" (the default), "drop"
    (rows with one are left out, with a warning) or "available" (each table counted over the
    rows where its family is present) or "em" (expectation-maximization, as `--missing em`:
    the missing values and the `latent` variables are estimated; docs/incomplete-data.md).
    latent: with "em", the variables of the edges that no column holds, {name: number of
    states (named 0, 1, ...) or a list of state names}. restarts, seed: random starts of the
    latent tables (the best kept) and their seed; max_iterations, tolerance: when EM stops
    (relative change of the log-likelihood plus the prior's term); hard: hard EM. How EM went
    is in the network's `notes`. keep_counts: keep the counts with the network, so that
    `Network.update` can add rows later (as `--keep-counts`; not with "em"). states: {name:
    states in order} for columns whose states are not just the values seen (a success variable
    whose first trials all failed): each is a state, also one no row has yet.
    """
    names = _frame.column_names(data)
    pairs = _edge_pairs(edges)
    if not pairs:
        raise Error('edges is empty: give the network\'s edges, e.g. "a->b,c->b" or [("a", "b")]')
    wanted = {name for pair in pairs for name in pair}
    em = _em_arguments(missing, latent, restarts, seed, max_iterations, tolerance, hard, keep_counts)
    latent_states = _latent_states(latent, wanted)
    data = _frame.with_missing(data, wanted, "available" if missing == "em" else missing)
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
            raise Error(f"w_prior must be a number >= 0 or 'auto', got '{w_prior}'{_did_you_mean(w_prior, ['auto'])}")
        weight = None
    elif isinstance(w_prior, numbers.Real) and not isinstance(w_prior, bool):
        weight = float(w_prior)
    else:
        raise TypeError("w_prior must be a number or 'auto'")
    net = _core.fit(
        columns,
        names,
        pairs,
        _text(estimator, "estimator"),
        _text(prior, "prior"),
        _prior_settings(alpha=_real(alpha, "alpha"), ess=_real(ess, "ess")),
        _text(empty, "empty"),
        _threads(threads),
        interval_edges,
        interval_file,
        handle,
        _text(strategy, "strategy") or "minimal",
        _text(map, "map") or "",
        weight,
        _text(success, "success") or "1",
        _text(match, "match") or "midpoint",
        em,
        latent_states,
        _named_states(states),
        _flag(keep_counts, "keep_counts"),
    )
    return Network(net)


def fit_dynamic(
    data,
    edges=None,
    estimator="mle",
    prior="bdeu",
    ess=1.0,
    prior_model=None,
    strategy=None,
    map=None,
    w_prior=None,
    *,
    model=None,
    alpha=1.0,
    initial_map=None,
    initial_strategy=None,
    empty="uniform",
    missing="error",
    latent=None,
    restarts=1,
    seed=0,
    max_iterations=100,
    tolerance=1e-6,
    keep_counts=False,
    threads=0,
):
    """Fits a dynamic network (a 2-TBN with tied tables) from episodes, as `pgm fit --dynamic`.

    data: a DataFrame in long form, one row per episode and step: columns `t` (0, 1, … within
    an episode), `episode` (any labels; without it, one episode) and the template variables'
    states. edges: "a->b" within a slice, "a@-1->b" from the step before, as a text or (parent,
    child) pairs; or model: a DynamicNetwork whose structure and states to fit instead.
    estimator, prior, ess, alpha and empty as pgm.fit takes them. prior_model: a static
    pgm.Network (the 1-Stack's, say) whose tables become the priors of the template variables'
    tables by `strategy` through `map` (template variables as targets, "x@-1" for a parent in
    the step before) at `w_prior` (5 by default); initial_map and initial_strategy are the
    first slice's own (docs/dynamic.md). missing: "error" (the default), "available" (each
    family counted over the steps where it is present) or "em" (expectation-maximization over
    whole episodes: the missing values and the `latent` template variables, {name: number of
    states or list of state names}, are estimated; restarts, seed, max_iterations and tolerance
    as pgm.fit takes them). keep_counts: keep the counts, so that DynamicNetwork.update can add
    episodes later (not with "em"). How EM went and how the priors were transferred is in the
    model's `notes`.
    """
    if (edges is None) == (model is None):
        raise Error('give the structure as edges ("a->b, a@-1->a") or as model (a pgm.DynamicNetwork), one of them')
    if model is not None and not isinstance(model, DynamicNetwork):
        raise TypeError("model must be a pgm.DynamicNetwork")
    if missing not in ("error", "available", "em"):
        raise Error(f"missing must be 'error', 'available' or 'em' for a dynamic network, got '{missing}'"
                    + ("; 'drop' would leave gaps in the episodes" if missing == "drop" else ""))
    em = _em_arguments(missing, latent, restarts, seed, max_iterations, tolerance, False, keep_counts)
    text = edges if edges is None or isinstance(edges, str) else ", ".join(f"{a}->{b}" for a, b in _edge_pairs(edges))
    if model is not None:
        variables = model.variables
    else:
        variables = sorted({name.split("@")[0] for pair in _core.parse_edge_list(text) for name in pair})
    if prior_model is None:
        if any(v is not None for v in (strategy, map, w_prior, initial_map, initial_strategy)):
            raise Error("strategy, map, w_prior, initial_map and initial_strategy apply with prior_model")
    elif not isinstance(prior_model, Network):
        raise TypeError("prior_model must be a pgm.Network")
    elif map is None:
        raise Error('prior_model needs map, e.g. map="onTop=onTop1, xOff~xOff1, xOff@-1==xOff1"')
    weight = None if w_prior is None else _real(w_prior, "w_prior")
    latent_states = _latent_states(latent, variables)
    hidden = {name for name, _ in latent_states}
    if model is not None:  # a model's latent variables keep its states
        latent_states = []
    wanted = _long_form_columns(data, [v for v in variables if v not in hidden])
    data = _frame.with_missing(data, wanted, "available" if missing == "em" else missing)
    columns = _frame.columns_of(data, wanted)
    found, notes = _core.fit_dynamic(
        columns,
        text or "",
        None if model is None else model._model,
        _text(estimator, "estimator"),
        _text(prior, "prior"),
        _prior_settings(alpha=_real(alpha, "alpha"), ess=_real(ess, "ess")),
        _text(empty, "empty"),
        _threads(threads),
        None if prior_model is None else prior_model._net,
        _text(strategy, "strategy") or "minimal",
        _text(map, "map") or "",
        5.0 if weight is None else weight,
        _text(initial_map, "initial_map"),
        _text(initial_strategy, "initial_strategy"),
        em,
        latent_states,
        _flag(keep_counts, "keep_counts"),
    )
    return DynamicNetwork(*found, notes=notes)


def _em_arguments(missing, latent, restarts, seed, max_iterations, tolerance, hard, keep_counts):
    """missing="em"'s options for _core.fit, None for any other rule (whose EM options are
    refused when set). The numbers are checked either way, within the bounds of `pgm fit`'s options."""
    _choice(missing, "missing", (*_frame._MISSING, "em"), "missing-value policy")
    tolerance = _real(tolerance, "tolerance")
    if not tolerance >= 0:  # also NaN
        raise Error(f"tolerance must be a number >= 0, got {tolerance}")
    options = (
        _whole(restarts, "restarts", 1, 1000),
        _seed(seed),
        _whole(max_iterations, "max_iterations", 0, 1_000_000),
        tolerance,
        _flag(hard, "hard"),
    )
    if missing != "em":
        if latent is not None:
            raise Error('latent applies with missing="em"')
        return None
    if keep_counts:
        raise Error('keep_counts does not apply with missing="em": EM\'s counts are expectations under its tables')
    return options


def _named_states(states):
    """[(name, labels)] of states={name: [state, ...]}; a state is labelled as a column's value is
    (0 → "0")."""
    if states is None:
        return []
    if not isinstance(states, Mapping):
        raise TypeError(f"states must be a dict {{name: list of states}}, got {states!r}")
    result = []
    for name, values in states.items():
        _text(name, "states' names")
        if isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
            raise TypeError(f"states['{name}'] must be a list of states, got {values!r}")
        labels = [_frame._label(v) for v in values]
        if not labels or len(set(labels)) != len(labels):
            raise Error(f"states['{name}'] must name each state once, got {list(values)!r}")
        result.append((name, labels))
    return result


def _latent_states(latent, variables):
    """[(name, states)] of latent={name: count or states}, each a variable of the edges."""
    if latent is None:
        return []
    if not isinstance(latent, Mapping):
        raise TypeError(f"latent must be a dict {{name: number of states or list of states}}, got {latent!r}")
    result = []
    for name, states in latent.items():
        _text(name, "latent's names")
        if name not in variables:
            raise Error(f"the latent variable '{name}' is in no edge")
        if isinstance(states, numbers.Integral) and not isinstance(states, bool):
            count = _whole(states, f"latent['{name}']", 1)
            result.append((name, [str(k) for k in range(count)]))
        elif isinstance(states, (list, tuple)) and states and all(isinstance(x, str) for x in states):
            result.append((name, list(states)))
        else:
            raise TypeError(f"latent['{name}'] must be a number of states or a list of state names, got {states!r}")
    return result


def query(network, variables, evidence=None, *, do=None, engine="auto", soft_evidence=None):
    """P(variables | evidence) as a Series indexed by state (a MultiIndex over several
    variables, the last fastest). variables: a name or a list of names; evidence: {name:
    state}; do: interventions {name: state} (graph surgery: P(variables | do(...), evidence));
    soft_evidence: {name: [weight per state]}; engine: as for pgm.InferenceEngine (compiled
    once per network and engine, then reused)."""
    _handle(network)
    names = _names(variables, "variables")
    e = network._engine(engine)
    e._set(_checks._evidence(evidence), _checks._likelihoods(soft_evidence), _checks._evidence(do, "do"))
    return e.joint(names)


def mpe(network, evidence=None, *, variables=None, do=None, engine="auto", soft_evidence=None):
    """The most probable joint state of the unobserved variables (or of `variables`, the
    others summed out) given the evidence and interventions: ({variable: state}, its
    probability)."""
    _handle(network)
    e = network._engine(engine)
    e._set(_checks._evidence(evidence), _checks._likelihoods(soft_evidence), _checks._evidence(do, "do"))
    return e.mpe(variables)


def d_separated(network, x, y, given=None):
    """Whether the variables x and y are d-separated given `given` in the network's DAG (each a
    name or a list of names), as `pgm dsep`."""
    handle = _handle(network)
    x, y = _names(x, "x"), _names(y, "y")
    given = [] if given is None else _names(given, "given", allow_empty=True)  # []: marginal independence
    shared = _checks._shared([("x", x), ("y", y), ("given", given)])
    if shared:  # the library's message names neither the variable nor the arguments
        raise Error(f"'{shared[0]}' is in both {shared[1]} and {shared[2]}: d-separation needs disjoint sets")
    return _core.d_separated(handle, x, y, given)


def intervene(network, do):
    """The mutilated network of do(...): each variable in `do` ({name: state}) cut from its
    parents with the point distribution at its state, the other tables kept."""
    handle = _handle(network)
    return Network(_core.intervene(handle, _checks._evidence(do, "do")))


def counterfactual(model, variables, evidence=None, *, do, assume=None):
    """P(variables in the world where `do` had been done | evidence in this one), as
    `pgm counterfactual --do`: a Series indexed by state (a MultiIndex over several variables, the
    last fastest), P(evidence) in .attrs["evidence_probability"]. model: the path of a structural
    model (pgm's JSON of "kind": "structural"), or a network (a pgm.Network or the path of one)
    with assume="monotone", which reads each table as one uniform noise through its cumulative
    column (docs/causal.md); a network alone does not determine counterfactuals."""
    names = _names(variables, "variables")
    observed = _checks._evidence(evidence)
    done = _checks._evidence(do, "do")
    if not done:
        raise Error("do: name what had been set in the world asked about, e.g. do={'xOff1': '0'}")
    if assume is not None:
        _choice(assume, "assume", ("monotone",), "assumption")
    if isinstance(model, Network):
        network = model
    else:
        path = _path(model, "model")
        if _core.holds_structural_model(path):
            if assume is not None:
                raise Error(f"'{path}' is a structural model: it needs no assume")
            return _counterfactual_series(names, _core.counterfactual_structural(path, names, observed, done))
        network = read_network(path)
        if not isinstance(network, Network):
            raise Error(f"'{path}' holds no Bayesian network or structural model")
    if assume is None:
        raise Error(
            "a Bayesian network does not determine counterfactuals: pass a structural model, or "
            'assume="monotone" to read the network as one (docs/causal.md)'
        )
    return _counterfactual_series(names, _core.counterfactual_monotone(_handle(network), names, observed, done))


def _counterfactual_series(names, answer):
    values, states, evidence_probability = answer
    if len(names) == 1:
        index = pd.Index(states[0], name=names[0])
    else:
        index = pd.MultiIndex.from_product(states, names=names)
    series = pd.Series(values, index=index, name="probability")
    series.attrs["evidence_probability"] = evidence_probability
    return series


def backdoor_sets(network, x, y, *, limit=100_000):
    """The minimal sets satisfying the back-door criterion for the effect of x on y (names or
    lists of names), smallest first, and whether the search was complete within `limit` sets."""
    handle = _handle(network)
    x, y = _names(x, "x"), _names(y, "y")
    shared = _checks._shared([("the treatment (x)", x), ("the outcome (y)", y)])
    if shared:  # the library's message names neither the variable nor the arguments
        raise Error(f"'{shared[0]}' is both {shared[1]} and {shared[2]}")
    return _core.backdoor_sets(handle, x, y, _whole(limit, "limit", 1, _checks.UINT64_MAX))


def check(network, data, test="chi2", alpha=0.05, *, threads=0):
    """Tests every independence the network's DAG implies (one per pair of variables without an
    edge: each given the parents of the one that does not descend from the other) on the frame
    `data`, as `pgm check`: a DataFrame x, y, given, statistic, df, p_value, rejected, the
    smallest p-value first. test: "chi2", "g2" or a registered test; NAME[KEY=VALUE,...] sets an
    option, as "chi2[correction=yates]" or "g2[min_rows_per_cell=5]"."""
    handle = _handle(network)
    test = _text(test, "test")
    alpha = _real(alpha, "alpha")
    if not 0.0 < alpha < 1.0:
        raise Error(f"alpha must lie strictly between 0 and 1, got {alpha}")
    names = handle.variables
    columns = _frame.columns_of(data, names)
    result = pd.DataFrame(_core.check(handle, columns, test, alpha, _threads(threads)))
    result["rejected"] = result["p_value"] <= alpha
    return result


def predict(network, assign, success=None, marginalize=False):
    """The predicted probability that the plan `assign` succeeds, as `pgm predict`.
    assign: {variable: value} or "xOff1=0.3,yOff1=-1.2": a number is binned by an interval
    variable's edges, other values are state labels ("@2" names the state labelled 2)."""
    handle = _handle(network)
    assign = _assignment(assign, "assign", "{'xOff1': 0.3}")
    return _core.predict(handle, assign, _text(success, "success"), _flag(marginalize, "marginalize"))


def prevent(
    network,
    assign,
    controllable=None,
    epsilon=0.8,
    success=None,
    distance="steps",
    marginalize=False,
    *,
    reward=None,
    move_cost=None,
    per="steps",
):
    """Predicts the plan `assign`; below `epsilon`, explains the failure and suggests the
    nearest values of the `controllable` variables (default: every parent of the success
    variable) predicted to succeed, as `pgm prevent`. Returns a dict: predicted,
    failure_predicted, suggestion ({variable: value}), predicted_after, responsible (the
    variables that move), steps, distance, target_succeeds and success.

    With a `reward` (the utility of success; failure is worth 0) it suggests instead the move of
    highest expected utility, each variable's move costing move_cost[variable] per bin step
    (per="steps") or per unit (per="units"), a variable without a cost moving for free, as
    `pgm prevent --reward`; the dict then also holds expected_utility and cost."""
    handle = _handle(network)
    assign = _assignment(assign, "assign", "{'xOff1': 0.3}")
    if isinstance(controllable, str):
        controllable = [c.strip() for c in controllable.split(",")]
    return _core.prevent(
        handle,
        assign,
        None if controllable is None else _names(controllable, "controllable"),
        _real(epsilon, "epsilon"),
        _text(distance, "distance"),
        _text(success, "success"),
        _flag(marginalize, "marginalize"),
        None if reward is None else _real(reward, "reward"),
        {} if move_cost is None else {str(k): _real(v, f"move_cost[{k!r}]") for k, v in dict(move_cost).items()},
        _text(per, "per"),
    )


def learn_structure(
    data,
    test="chi2",
    alpha=0.01,
    tiers=None,
    forbid=None,
    require=None,
    *,
    max_cond=3,
    threads=0,
    missing="error",
    algorithm="pc",
    score="bic",
    max_parents=math.inf,
    tabu=10,
    max_tabu=10,
    restarts=0,
    perturb=1,
    seed=1,
    start=None,
    prior_model=None,
    map=None,
    prior_weight=5.0,
):
    """Structure learning on the frame's columns (all discrete), as `pgm learn-structure`: the
    edges of the learned DAG as (parent, child) pairs. algorithm: "pc" (PC-stable; the DAG is one
    of its equivalence class), "hc" (hill climbing), "tabu", "mmhc" (PC-stable's skeleton
    restricts hill climbing), "empty" or a registered learner; NAME[KEY=VALUE,...] sets its
    options, as "tabu[tabu=20,score=bdeu[iss=10]]". The other keyword arguments each set one
    option of the learner, or of the "pc" that start="pc" starts from, when they differ from
    their defaults (the library's): test ("chi2", "g2" or a registered test, as
    "chi2[correction=yates]"), alpha, max_cond: PC's tests. score ("bic", "aic[k=1]",
    "bdeu[iss=1]", "k2", "loglik", or a registered score), max_parents (0 or math.inf: no
    limit), tabu, max_tabu, restarts, perturb, seed: the score searches', as
    docs/structure-learning.md says. start: a pgm.Network, (parent, child) pairs or "pc" to
    start from. prior_model (a pgm.Network of a related task), map (its correspondence, as for
    pgm.fit) and prior_weight: the structure prior, a score bonus per edge of the prior network
    that the map carries over. tiers: "a,b;c;d" or a list of lists of names, earliest first;
    forbid and require: edges as for pgm.fit. missing: as for pgm.fit; with "available" each
    family, or test, counts the rows where its variables are present."""
    names = _frame.column_names(data)
    data = _frame.with_missing(data, names, missing)
    columns = _frame.columns_of(data, names)

    def edges_text(edges):
        if edges is None:
            return ""
        if isinstance(edges, str):
            return edges
        return ",".join(f"{parent}->{child}" for parent, child in _edge_pairs(edges, "forbid and require"))

    if tiers is None:
        tiers_text = ""
    elif isinstance(tiers, str):
        tiers_text = tiers
    else:
        tiers_text = ";".join(",".join(_names(tier, "each tier")) for tier in tiers)
    limit = max_parents if max_parents == math.inf else _whole(max_parents, "max_parents", 0, 1024) or math.inf
    given = {
        "test": _text(test, "test"),
        "alpha": _real(alpha, "alpha"),
        "max_cond": _whole(max_cond, "max_cond", 0, 64),
        "score": _text(score, "score"),
        "max_parents": limit,
        "tabu": _whole(tabu, "tabu", 1, 100_000),
        "max_tabu": _whole(max_tabu, "max_tabu", 0, 100_000),
        "restarts": _whole(restarts, "restarts", 0, 100_000),
        "perturb": _whole(perturb, "perturb", 1, 100_000),
        "seed": _seed(seed),
    }
    defaults = inspect.signature(learn_structure).parameters
    settings = [(keyword, _LEARNER_OPTION.get(keyword, keyword), _option_text(value))
                for keyword, value in given.items() if value != defaults[keyword].default]
    if isinstance(start, str):
        if start != "pc":
            raise Error(f"start must be a pgm.Network, (parent, child) pairs or 'pc', got {start!r}")
        settings.append(("start", "start", "pc"))
    return _core.learn_structure(
        columns,
        _text(algorithm, "algorithm"),
        settings,
        tiers_text,
        edges_text(forbid),
        edges_text(require),
        _threads(threads),
        [] if start is None or isinstance(start, str) else
        list(start.edges if isinstance(start, Network) else _edge_pairs(start, "start")),
        _prior_edges(prior_model),
        "" if map is None else _text(map, "map"),
        _real(prior_weight, "prior_weight"),
    )


def _prior_settings(**given):
    """fit's keyword arguments that set an option of the prior: those that differ from their
    defaults, as (keyword, option, value)."""
    defaults = inspect.signature(fit).parameters
    return [(keyword, keyword, _option_text(value)) for keyword, value in given.items()
            if value != defaults[keyword].default]


# learn_structure's keyword arguments named otherwise than the learners' options they set.
_LEARNER_OPTION = {"max_cond": "max_conditioning"}


def _option_text(value):
    """A keyword argument's value as a learner's option is written: 0.01, 3, unlimited."""
    if value == math.inf:
        return "unlimited"
    return repr(value) if isinstance(value, float) else str(value)


def _prior_edges(prior_model):
    if prior_model is None:
        return None
    _handle(prior_model, "prior_model")
    return list(prior_model.edges)


def score(network, data, score="bic", *, by_node=False, threads=0, missing="error"):
    """The score of the network's structure on the frame, as `pgm score` and bnlearn's score()
    (larger is better): "bic", "aic[k=1]", "bdeu[iss=1]", "k2", "loglik" or a registered score;
    NAME[KEY=VALUE,...] sets an option, as "bdeu[iss=10]". The frame's columns
    are read as the network's states. Returns the total, or with by_node a dict of each node's
    term in the network's order."""
    handle = _handle(network)
    names = list(network.variables)
    data = _frame.with_missing(data, names, missing)
    missing_names = [n for n in names if n not in set(_frame.column_names(data))]
    if missing_names:
        raise Error(f"data: there is no column '{missing_names[0]}' (the network's variables: {', '.join(names)})")
    total, nodes = _core.score(
        handle, _frame.columns_of(data, names), _text(score, "score"), _threads(threads)
    )
    return dict(zip(names, nodes)) if by_node else total


def discretize(data, bins=5, columns=None, *, method="quantile", edges=None, missing="error"):
    """Bins continuous columns, as `pgm discretize`: the named columns, or every numeric column
    with more distinct values than `bins`; by quantile (equal frequency, as in the paper) or
    "width", or by saved `edges` ({name: edges} or an edges file) to bin new data the same
    way. Returns (a copy of the frame with each binned column replaced by its bin codes
    0..k-1, {name: edges}). missing: as for pgm.fit, over the binned columns; with "available"
    a missing value stays missing (pd.NA in the binned column) and edges are fitted on the rest."""
    names = _frame.column_names(data)
    wanted = [] if columns is None else _names(columns, "columns")
    saved, saved_file = _edges_argument(edges, "edges")
    if wanted:
        convert = set(wanted)
    else:  # only numbers can be binned: other columns need not cross
        convert = {n for n in names if _frame.is_number_column(data[n])} | set(saved or {})
    data = _frame.with_missing(data, convert, missing)
    specs = [_frame.numeric_column(name, data[name]) for name in names if name in convert]
    binned, fitted = _core.discretize(
        specs, names, _whole(bins, "bins", 1, 10_000), wanted, _text(method, "method"), saved, saved_file
    )
    result = data.copy()
    for name, kind, array, labels in binned:
        result[name] = _frame.series_of(kind, array, labels)
    return result, fitted


def _tasks_folder(tasks_dir):
    """Where tasks are found: `tasks_dir`, else $PGM_TASKS_DIR, else the tasks an installed
    package carries (pgm/tasks), else the library's own defaults (None: the source tree's)."""
    if tasks_dir is not None:
        return _path(tasks_dir, "tasks_dir")
    if os.environ.get("PGM_TASKS_DIR"):
        return None
    packaged = os.path.join(os.path.dirname(os.path.abspath(__file__)), "tasks")
    return packaged if os.path.isdir(packaged) else None


def simulate(task, rows, seed=0, backend="analytic", variant="sim", *, threads=0, tasks_dir=None, long_form=False):
    """Runs `rows` experiments of a task (1-stack, 2-stack, 3-stack, drop-plate, …) with a
    simulator back-end, as `pgm simulate`: the raw data as a DataFrame. The same seed gives the
    same data for any number of threads. variant "reality" is the stacking tasks' stand-in for
    the real robot (not real data). long_form: each experiment as an episode of the task's
    numbered actions, one row per action (columns episode, t, xOff, …), as pgm.fit_dynamic
    reads it."""
    columns = _core.simulate(
        _text(task, "task"),
        _whole(rows, "rows"),
        _seed(seed),
        _text(backend, "backend"),
        _text(variant, "variant"),
        _threads(threads),
        _tasks_folder(tasks_dir),
        _flag(long_form, "long_form"),
    )
    return _frame.frame_of(columns)


def experiment(scenario, reps=None, seed=1, backend="analytic", *, threads=0, distance="steps", auto=True, tasks_dir=None):
    """Runs a transfer scenario of the paper (2-stack-sim, 2-stack-reality, 2-stack-sim-to-real,
    sphere-dropping, stack-to-drop, or "all"), as `pgm experiment`: a tidy DataFrame with the
    columns of points.csv (scenario, target, strategy, w, rows, repetition, metric, value).
    The protocol's notes are in `.attrs["notes"]`."""
    columns, notes = _core.experiment(
        _text(scenario, "scenario"),
        0 if reps is None else _whole(reps, "reps", 1, 1000),  # None: the scenario's own
        _seed(seed),
        _text(backend, "backend"),
        _threads(threads),
        _text(distance, "distance"),
        _flag(auto, "auto"),
        _tasks_folder(tasks_dir),
    )
    frame = pd.DataFrame(
        {
            name: pd.Categorical.from_codes(value[0], categories=value[1]) if isinstance(value, tuple) else value
            for name, value in columns.items()
        }
    )
    frame.attrs["notes"] = list(notes)
    return frame
