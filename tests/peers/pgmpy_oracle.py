#!/usr/bin/python3
"""Answers from pgmpy, for the agreement tests (tests/peers) and docs/structure-learning.md.

    pgmpy_oracle.py queries NETWORK.bif REQUEST.json   # [{"query": [...], "evidence": {...}}, ...]
    pgmpy_oracle.py ci DATA.csv REQUEST.json           # [{"x": .., "y": .., "z": [...]}, ...]

prints JSON on stdout: for queries, per request the list of {"states": {var: state}, "p": value}
from pgmpy's VariableElimination (joint over the query variables); for ci, per request the
statistic, p-value and degrees of freedom of pgmpy's chi_square and g_sq (which correct 2 x 2
strata by Yates through scipy). pgmpy must be importable (PYTHONPATH); it is not part of pgm.
"""

import itertools
import json
import logging
import sys

logging.disable(logging.WARNING)


def queries(network_path, requests):
    from pgmpy.inference import VariableElimination
    from pgmpy.readwrite import BIFReader

    model = BIFReader(network_path).get_model()
    engine = VariableElimination(model)
    answers = []
    for request in requests:
        factor = engine.query(request["query"], evidence=request["evidence"] or None, joint=True,
                              show_progress=False)
        rows = []
        names = [factor.state_names[v] for v in factor.variables]
        for states in itertools.product(*names):
            rows.append({"states": dict(zip(factor.variables, states)),
                         "p": float(factor.get_value(**dict(zip(factor.variables, states))))})
        answers.append(rows)
    return answers


def ci(data_path, requests):
    import pandas as pd
    from pgmpy.estimators.CITests import chi_square, g_sq

    data = pd.read_csv(data_path, dtype=str)
    answers = []
    for request in requests:
        answer = {}
        for name, test in (("chi2", chi_square), ("g2", g_sq)):
            statistic, p_value, dof = test(request["x"], request["y"], request["z"], data, boolean=False)
            answer[name] = {"statistic": float(statistic), "p": float(p_value), "df": float(dof)}
        answers.append(answer)
    return answers


def main():
    if len(sys.argv) != 4 or sys.argv[1] not in ("queries", "ci"):
        sys.exit(__doc__)
    with open(sys.argv[3], encoding="utf-8") as f:
        requests = json.load(f)
    answers = queries(sys.argv[2], requests) if sys.argv[1] == "queries" else ci(sys.argv[2], requests)
    json.dump(answers, sys.stdout)


if __name__ == "__main__":
    main()
