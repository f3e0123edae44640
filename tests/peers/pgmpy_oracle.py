#!/usr/bin/python3
"""Answers from pgmpy, for the agreement tests (tests/peers) and docs/structure-learning.md.

    pgmpy_oracle.py queries NETWORK.bif REQUEST.json   # [{"query": [...], "evidence": {...}}, ...]
    pgmpy_oracle.py ci DATA.csv REQUEST.json           # [{"x": .., "y": .., "z": [...]}, ...]
    pgmpy_oracle.py formats - REQUEST.json             # {"read": [NET.bif|.xml, ...],
                                                       #  "rewrite": [{"in": .., "bif": .., "xmlbif": ..}]}

prints JSON on stdout: for queries, per request the list of {"states": {var: state}, "p": value}
from pgmpy's VariableElimination (joint over the query variables), or for a request with
"mpe": true, {"mpe": {var: state}} from its map_query over the query variables, or for a request
with "do": {var: state}, the joint from CausalInference.query; for ci, per request the
statistic, p-value and degrees of freedom of pgmpy's chi_square and g_sq (which correct 2 x 2
strata by Yates through scipy); for formats, per file to read (BIFReader or XMLBIFReader by
extension) per CPD its variable, parents, states and values (one row per parent configuration,
the last parent fastest, as pgm stores them), after pgmpy has read each "in" file and written
it again with its BIFWriter and XMLBIFWriter. (One run for all: pgmpy takes long to import.)
pgmpy must be importable (PYTHONPATH); it is not part of pgm.
"""

import itertools
import json
import math
import logging
import sys

logging.disable(logging.WARNING)


def queries(network_path, requests):
    from pgmpy.inference import VariableElimination

    model = read_model(network_path)
    engine = VariableElimination(model)
    answers = []
    for request in requests:
        if request.get("do"):
            from pgmpy.inference import CausalInference

            factor = CausalInference(model).query(
                request["query"], do=request["do"], evidence=request["evidence"] or None, show_progress=False
            )
            names = [factor.state_names[v] for v in factor.variables]
            rows = []
            for states in itertools.product(*names):
                p = float(factor.get_value(**dict(zip(factor.variables, states))))
                rows.append({"states": dict(zip(factor.variables, states)), "p": None if math.isnan(p) else p})
            answers.append(rows)  # NaN (0/0 in pgmpy's adjustment) crosses as null
            continue
        if request.get("mpe"):
            best = engine.map_query(request["query"], evidence=request["evidence"] or None, show_progress=False)
            answers.append({"mpe": {k: str(v) for k, v in best.items()}})
            continue
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


def read_model(network_path):
    from pgmpy.readwrite import BIFReader, XMLBIFReader

    if network_path.endswith(".bif"):
        return BIFReader(network_path).get_model()
    return XMLBIFReader(network_path).get_model()


def tables(network_path):
    model = read_model(network_path)
    answers = []
    for cpd in model.get_cpds():
        values = cpd.get_values()  # child states x parent configurations, the last parent fastest
        answers.append({"variable": cpd.variable, "parents": list(cpd.variables[1:]),
                        "states": {v: [str(s) for s in cpd.state_names[v]] for v in cpd.variables},
                        "values": [[float(values[x][u]) for x in range(values.shape[0])]
                                   for u in range(values.shape[1])]})
    return answers


def formats(_, request):
    from pgmpy.readwrite import BIFWriter, XMLBIFWriter

    for entry in request.get("rewrite", []):
        model = read_model(entry["in"])
        BIFWriter(model).write_bif(entry["bif"])
        XMLBIFWriter(model).write_xmlbif(entry["xmlbif"])
    return [tables(path) for path in request.get("read", [])]


def main():
    modes = {"queries": queries, "ci": ci, "formats": formats}
    if len(sys.argv) != 4 or sys.argv[1] not in modes:
        sys.exit(__doc__)
    with open(sys.argv[3], encoding="utf-8") as f:
        requests = json.load(f)
    answers = modes[sys.argv[1]](sys.argv[2], requests)
    json.dump(answers, sys.stdout)


if __name__ == "__main__":
    main()
