"""Influence diagrams for Python: pgm.InfluenceDiagram reads a diagram of chance, decision and
utility nodes (XMLBIF, as aGrUM writes it) and finds the policy of maximum expected utility,
exactly when every decision remembers what earlier ones knew and chose, or by single policy
updating when each knows its parents only (limited_memory=True)."""

import pandas as pd

from . import _core
from ._checks import _evidence


class DecisionSolution:
    """What InfluenceDiagram.solve returns.

    meu: the expected utility of the policies (the maximum unless local_optimum).
    policies: {decision: DataFrame}, one row per configuration of what the decision observes,
    a column per observed variable and the column "action".
    local_optimum: True when found by single policy updating (a local optimum);
    start_expected_utility and rounds then say where it started and how long it climbed."""

    __slots__ = ("meu", "policies", "local_optimum", "start_expected_utility", "rounds")

    def __init__(self, meu, policies, local_optimum, start_expected_utility, rounds):
        self.meu = meu
        self.policies = policies
        self.local_optimum = local_optimum
        self.start_expected_utility = start_expected_utility
        self.rounds = rounds

    def __repr__(self):
        return f"DecisionSolution(meu={self.meu!r}, decisions={list(self.policies)!r})"


class InfluenceDiagram:
    """Chance variables with tables, decisions whose parents are what is known when each is
    taken, and utilities (payoffs over their parents, adding up). Read one with
    InfluenceDiagram.read(path)."""

    __slots__ = ("_model",)

    def __init__(self, handle):
        if not isinstance(handle, _core.InfluenceDiagram):
            raise TypeError("use InfluenceDiagram.read(path) to make an influence diagram")
        self._model = handle

    @classmethod
    def read(cls, path):
        """Reads an influence diagram: pgm's JSON model (a .json path) or XMLBIF (TYPE="decision"
        and TYPE="utility" variables)."""
        return cls(_core.read_influence_diagram(str(path)))

    @property
    def decisions(self):
        """The decisions, in the order they are taken."""
        return self._model.decisions

    @property
    def chance_variables(self):
        return self._model.chance_variables

    @property
    def utilities(self):
        return self._model.utilities

    def states(self, variable):
        return self._model.states(variable)

    def solve(self, evidence=None, limited_memory=False):
        """The best policies given the evidence {variable: state} (what is known before the
        first decision; the MEU is then E[U | evidence]). A DecisionSolution."""
        meu, policies, local, start, rounds = self._model.solve(_evidence(evidence), bool(limited_memory))
        frames = {}
        for decision, observed, rows in policies:
            frames[decision] = pd.DataFrame(rows, columns=[*observed, "action"])
        return DecisionSolution(meu, frames, local, start, rounds)

    def value_of_information(self, variable, before, evidence=None, limited_memory=False):
        """What knowing the chance variable before the decision `before` (and, with perfect
        recall, later) adds to the MEU."""
        return self._model.value_of_information(str(variable), str(before), _evidence(evidence), bool(limited_memory))

    def write(self, path):
        """Writes the diagram atomically: pgm's JSON model to a .json path, else XMLBIF."""
        self._model.write(str(path))
