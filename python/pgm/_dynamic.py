"""Dynamic networks for Python: pgm.DynamicNetwork holds a two-slice temporal network (a first
slice, and a transition whose tables are tied across slices, their parents in the same slice or
the one before), read from pgm's JSON model of "kind": "dynamic" (docs/dynamic.md), and unrolls
it into a pgm.Network of T slices whose variables are named X@0 … X@(T−1)."""

import numpy as np

from . import _core, _frame
from ._checks import _did_you_mean, _evidence, _path, _real, _threads, _whole


class DynamicNetwork:
    """A two-slice temporal Bayesian network: pgm.read_network returns one for a JSON model of
    "kind": "dynamic"."""

    __slots__ = ("_model", "_counts", "notes")

    def __init__(self, handle, counts=None, notes=()):
        if not isinstance(handle, _core.DynamicNetwork):
            raise TypeError("read a DynamicNetwork with pgm.read_network, or fit one with pgm.fit_dynamic")
        self._model = handle
        self._counts = counts
        self.notes = list(notes)

    @property
    def has_counts(self):
        """Whether the model keeps the counts it was estimated from, so that `update` can add
        episodes to them (pgm.fit_dynamic(..., keep_counts=True), or a model file written so)."""
        return self._counts is not None

    def update(self, data, decay=1.0, *, threads=0):
        """A new model: this one's counts, times `decay` in (0, 1], plus the episodes of `data`
        (long form, as pgm.fit_dynamic reads it, holding the model's states), each table
        estimated again under the prior it was fitted with. With decay 1 it equals fitting all
        the episodes at once, to the last bit. As `pgm update`; this model is unchanged."""
        decay = _real(decay, "decay")
        if not 0 < decay <= 1:
            raise _core.Error(f"decay must be in (0, 1], got {decay}")
        columns = _frame.columns_of(data, _long_form_columns(data, self.variables))
        model, counts = _core.update_dynamic(self._model, self._counts, columns, decay, _threads(threads))
        return DynamicNetwork(model, counts)

    @property
    def variables(self):
        """The template variables, in the first slice's order."""
        return self._model.variables

    def states(self, variable):
        return self._model.states(variable)

    @property
    def initial(self):
        """The first slice, a pgm.Network over the template variables."""
        from . import Network

        return Network(self._model.initial)

    @property
    def transition_edges(self):
        """The transition's edges: (parent, child), a parent named "X" (this slice) or "X@-1"."""
        return self._model.transition_edges

    def unroll(self, steps):
        """The pgm.Network of the first `steps` slices (at least 1), variables X@0 … X@(steps−1)."""
        from . import Network

        return Network(self._model.unroll(_whole(steps, "steps", 1, 1 << 20)))

    def filter(self, data, predict=0, do=None):
        """Every variable's distribution at each step of one episode given the steps up to it,
        P(X_t | e_0..t), then `predict` steps past its end, by the interface algorithm: two junction
        trees compiled once, so a step costs the same however long the episode (docs/dynamic.md).

        data: a DataFrame with one row per step, in order, and a column per observed template
        variable (a missing value is unobserved); an "episode" column (one value) and a "t" column
        (0, 1, … in order) may be there, as pgm filter reads them. do: {"x@3": "on"} sets x at step
        3, its table left out there. Returns a DataFrame of t, variable, state, probability for
        every variable neither observed nor set at that step; attrs["log_evidence_probability"]
        is ln P(evidence)."""
        return self._over_time(data, _whole(predict, "predict", 0, 1 << 20), do, smooth=False)

    def smooth(self, data, do=None):
        """Every variable's distribution at each step given the whole episode, P(X_t | e_0..T−1);
        data and do as filter takes them."""
        return self._over_time(data, 0, do, smooth=True)

    def most_probable_sequence(self, data, do=None):
        """The most probable joint state of every variable at every step given the episode
        (Viterbi through the interface); data and do as filter takes them. Returns a DataFrame of
        t, variable, state for every variable neither observed nor set at that step;
        attrs["log_probability"] is ln P(x*, evidence)."""
        import pandas as pd

        observed, interventions = self._steps(data, do, 0)
        if len(interventions) > len(observed):
            raise _core.Error("do: a step past the data has no most probable state; filter with predict reaches it")
        states, log_probability = self._model.most_probable(observed, interventions)
        rows = []
        for t, chosen in enumerate(states):
            fixed = set(observed[t]) | (set(interventions[t]) if t < len(interventions) else set())
            for name, state in zip(self.variables, chosen):
                if name not in fixed:
                    rows.append((t, name, self.states(name)[state]))
        answer = pd.DataFrame(rows, columns=["t", "variable", "state"])
        answer.attrs["log_probability"] = log_probability
        return answer

    def _over_time(self, data, predict, do, smooth):
        import pandas as pd

        observed, interventions = self._steps(data, do, predict)
        if smooth and len(interventions) > len(observed):
            raise _core.Error("do: a step past the data is not smoothed; filter with predict reaches it")
        t, variable, state, probability, log_evidence = self._model.filter_columns(
            observed, interventions, predict, smooth
        )
        # The labels by index: a frame made of whole columns costs a fraction of one made row by row.
        names = self.variables
        labels = [self.states(name) for name in names]
        offsets = np.cumsum([0] + [len(s) for s in labels])[:-1]
        answer = pd.DataFrame(
            {
                "t": t,
                "variable": np.array(names, dtype=object)[variable],
                "state": np.array([s for states in labels for s in states], dtype=object)[offsets[variable] + state],
                "probability": probability,
            }
        )
        answer.attrs["log_evidence_probability"] = log_evidence
        return answer

    def _steps(self, data, do, predict):
        """Each step's observed states from the DataFrame and each step's do() from the dict."""
        import pandas as pd

        if not isinstance(data, pd.DataFrame):
            raise TypeError(f"data must be a pandas DataFrame with one row per step, got {type(data).__name__}")
        names = self.variables
        for column in data.columns:
            if column not in ("episode", "t") and column not in names:
                raise _core.Error(
                    f"data: column '{column}' is neither episode, t nor a variable of the model{_did_you_mean(str(column), names)}"
                )
        if "episode" in data.columns and data["episode"].nunique(dropna=False) > 1:
            raise _core.Error("data: the rows are of several episodes; filter answers one episode at a time")
        if "t" in data.columns:
            for row, t in enumerate(data["t"].tolist()):
                if pd.isna(t) or float(t) != row:
                    raise _core.Error(f"data: row {row} has t = {t} where {row} was expected (t = 0, 1, 2, … in order)")
        variables = [c for c in data.columns if c in names]
        observed = [{} for _ in range(len(data))]
        for name in variables:
            for step, value in zip(observed, data[name].tolist()):
                if isinstance(value, str) or not pd.isna(value):
                    step[name] = str(value)
        interventions = []
        for key, state in _evidence(do, "do").items():
            name, at, step = key.rpartition("@")[0], "@" in key, key.rpartition("@")[2]
            if not at or not step.isdigit():
                raise _core.Error(f"do: '{key}' is not variable@step (e.g. 'x@3')")
            step = int(step)
            if step >= len(observed) + predict:
                raise _core.Error(f"do: '{key}': the step must be from 0 to {len(observed) + predict - 1}")
            while len(interventions) <= step:
                interventions.append({})
            interventions[step][name] = state
        return observed, interventions

    def to_pgmpy(self, state_names=True):
        """The model as pgmpy's DynamicBayesianNetwork, nodes (X, 0) and (X, 1) (pgmpy must be
        importable); with state_names=False its states are numbered 0, 1, … in this model's
        order, which pgmpy's DBNInference needs (it fails on names, docs/dynamic.md). pgmpy has
        one set of edges within a slice for both slices, and a node of the second slice only
        where an edge leads into it or lies within the slice: a model beyond that is refused,
        naming what pgmpy cannot hold."""
        from ._pgmpy import dynamic_to_pgmpy

        return dynamic_to_pgmpy(self, bool(state_names))

    def write(self, path):
        """Writes the model as pgm's JSON ("kind": "dynamic"), atomically, with its counts when
        it keeps them (pgm update and DynamicNetwork.update read them)."""
        if self._counts is None:
            self._model.write(_path(path, "path"))
        else:
            self._counts.write(self._model, _path(path, "path"))

    def __repr__(self):
        return f"<pgm.DynamicNetwork: {len(self.variables)} template variables>"


def _long_form_columns(data, variables):
    """The columns of a long-form frame a fit reads: t, the episode's when there is one, and
    `variables`; a missing one is an error naming it."""
    names = list(variables) + ["t"]
    if "episode" in data.columns:
        names.append("episode")
    return names
