"""Network.to_pgmpy and pgm.from_pgmpy: the same variables, states and tables both ways, and
pgmpy's own answers on the converted model agreeing with pgm's.

pgmpy is not a Debian package. CMake registers this file with ctest only when pgmpy is
importable at configure time (python/tests/CMakeLists.txt, PGM_PYTHONPATH); run by hand
without pgmpy, every test here is skipped with the reason below.
"""

import numpy as np
import pytest
from conftest import SOURCE_DIR, python_blocks, stacking_frame

import pgm

pgmpy = pytest.importorskip("pgmpy", reason="pgmpy is not importable (put it on PYTHONPATH, see docs/python.md)")

SACHS = SOURCE_DIR / "tests" / "data" / "networks" / "sachs.bif"


def test_a_published_network_crosses_both_ways_unchanged():
    net = pgm.read_network(SACHS)
    model = net.to_pgmpy()
    assert sorted(model.nodes()) == sorted(net.variables)
    assert sorted(model.edges()) == sorted(net.edges)
    for name in net.variables:
        cpd = model.get_cpds(name)
        assert [str(s) for s in cpd.state_names[name]] == net.states(name)
        assert list(cpd.variables[1:]) == net.parents(name)
    back = pgm.from_pgmpy(model)
    # from_pgmpy orders variables as pgmpy lists its nodes; compare by name.
    for name in net.variables:
        assert back.states(name) == net.states(name)
        assert back.parents(name) == net.parents(name)
        a, b = net.cpt(name), back.cpt(name)
        assert list(a.columns) == list(b.columns)
        for state in net.states(name):
            assert np.array_equal(a[state].to_numpy(), b[state].to_numpy()), (name, state)


def test_a_pgmpy_table_holds_pgms_probabilities():
    net = pgm.read_network(SACHS)
    cpd = net.to_pgmpy().get_cpds("Akt")
    # pgmpy: one row per child state, one column per configuration, last parent fastest.
    values = cpd.get_values()
    table = net.cpt("Akt")
    for x, state in enumerate(net.states("Akt")):
        assert np.array_equal(values[x], table[state].to_numpy())


def test_pgmpys_inference_agrees_with_pgms_query():
    from pgmpy.inference import VariableElimination

    net = pgm.fit(stacking_frame(3000, 5), "xOff1->onTop1,yOff1->onTop1,onTop1->onTop2,xOff2->onTop2")
    theirs = VariableElimination(net.to_pgmpy()).query(["onTop2"], evidence={"xOff1": "2"}, show_progress=False)
    ours = pgm.query(net, "onTop2", {"xOff1": "2"})
    for state in net.states("onTop2"):
        assert theirs.get_value(onTop2=state) == pytest.approx(ours[state], abs=1e-12)


def test_a_model_fitted_by_pgmpy_comes_over():
    from pgmpy.estimators import MaximumLikelihoodEstimator

    frame = stacking_frame(2000, 3)[["xOff1", "yOff1", "onTop1"]].astype(str)
    model_class = getattr(pgmpy.models, "DiscreteBayesianNetwork", None) or pgmpy.models.BayesianNetwork
    model = model_class([("xOff1", "onTop1"), ("yOff1", "onTop1")])
    model.fit(frame, estimator=MaximumLikelihoodEstimator)
    back = pgm.from_pgmpy(model)
    ours = pgm.fit(frame, "xOff1->onTop1,yOff1->onTop1")
    for name in ours.variables:
        # pgmpy sorts states as text too; the tables agree up to its floating-point division.
        assert back.states(name) == ours.states(name)
        a, b = ours.cpt(name), back.cpt(name)
        for state in ours.states(name):
            assert np.allclose(a[state].to_numpy(), b[state].to_numpy(), rtol=0, atol=1e-15)


def test_something_else_is_refused():
    with pytest.raises(TypeError, match="expected a pgmpy"):
        pgm.from_pgmpy("not a model")


def test_the_round_trip_of_docs_python_md_runs_as_written(capsys):
    _, first, round_trip, _, _ = python_blocks("docs/python.md")
    names = {}
    exec(compile(first, "docs/python.md", "exec"), names)
    exec(compile(round_trip, "docs/python.md", "exec"), names)
    assert "onTop2" in capsys.readouterr().out
    for name in names["minimal"].variables:
        assert names["back"].states(name) == names["minimal"].states(name)
        assert names["back"].cpt(name).equals(names["minimal"].cpt(name))


def test_pgmpy_markov_networks_both_ways():
    from pgmpy.inference import VariableElimination

    model = pgm.MarkovNetwork(
        {"a": ["0", "1"], "b": ["0", "1"], "c": ["0", "1"]},
        [(("a", "b"), [[1, 2], [3, 4]]), (("b", "c"), [[1, 1], [1, 5]])],
    )
    theirs = model.to_pgmpy()
    answer = VariableElimination(theirs).query(["b"], evidence={"c": "1"}, show_progress=False).values
    # pgmpy leaves a Markov network's answer unnormalized: [4, 30] here.
    assert answer / answer.sum() == pytest.approx(model.marginals({"c": "1"})["b"].to_numpy(), abs=1e-12)
    back = pgm.from_pgmpy(theirs)
    assert isinstance(back, pgm.MarkovNetwork)
    assert back.log_partition_function() == pytest.approx(model.log_partition_function(), abs=1e-12)


def dynamic_example(tmp_path, text=None):
    import re

    page = (SOURCE_DIR / "docs" / "dynamic.md").read_text()
    path = tmp_path / "tower.json"
    path.write_text(text or re.search(r"```json\n(.*?)```", page, re.S).group(1))
    return pgm.read_network(path)


def test_a_dynamic_network_crosses_to_pgmpy_and_back_unchanged(tmp_path):
    model = dynamic_example(tmp_path)
    theirs = model.to_pgmpy()
    edges = sorted((tuple(a), tuple(b)) for a, b in theirs.edges())
    assert edges == [(("a", 0), ("a", 1)), (("a", 0), ("b", 0)), (("a", 1), ("b", 1)), (("b", 0), ("b", 1))]
    # pgmpy's columns are the parents' configurations, last parent fastest, as pgm's rows.
    cpd = theirs.get_cpds(node=("b", 1))
    assert [tuple(v) for v in cpd.variables] == [("b", 1), ("a", 1), ("b", 0)]
    assert np.array_equal(cpd.get_values(), np.array([[0.7, 0.5, 0.2, 0.1], [0.3, 0.5, 0.8, 0.9]]))
    assert [str(s) for s in cpd.state_names[("a", 1)]] == ["off", "on"]
    back = pgm.from_pgmpy(theirs)
    assert isinstance(back, pgm.DynamicNetwork)
    assert back.variables == model.variables
    assert sorted(back.transition_edges) == sorted(model.transition_edges)
    ours, again = model.unroll(3), back.unroll(3)
    for name in ours.variables:
        assert again.parents(name) == ours.parents(name)
        assert again.cpt(name).equals(ours.cpt(name)), name


def test_pgmpys_filtering_agrees_with_pgms_where_pgmpy_is_right(tmp_path):
    import pandas as pd
    from pgmpy.inference import DBNInference

    # pgmpy's DBNInference on a model with state names fails as the hashes of its names fall
    # (KeyError or IndexError), and forward_inference asked for several steps at once answers
    # wrongly from the third on (docs/dynamic.md); asked for one step of a model whose states
    # are numbered (to_pgmpy(state_names=False)), it agrees with pgm's filter.
    model = dynamic_example(tmp_path)
    numbered = model.to_pgmpy(state_names=False)
    observed = ["high", "low", "low", "high", "high"]
    filtered = model.filter(pd.DataFrame({"b": observed}))
    for t in range(len(observed)):
        evidence = {("b", k): model.states("b").index(state) for k, state in enumerate(observed[: t + 1])}
        theirs = DBNInference(numbered).forward_inference([("a", t)], evidence)
        ours = filtered[(filtered.t == t) & (filtered.variable == "a")].probability.to_numpy()
        assert theirs[("a", t)].values == pytest.approx(ours, abs=1e-12), t


def test_a_dynamic_network_pgmpy_cannot_hold_is_refused_naming_why(tmp_path):
    import json

    document = {
        "format": "pgm-model",
        "version": 1,
        "kind": "dynamic",
        "variables": [{"name": "a", "states": ["0", "1"]}, {"name": "b", "states": ["0", "1"]}],
        "initial": {
            "edges": [],
            "tables": [
                {"variable": "a", "parents": [], "values": [[0.5, 0.5]]},
                {"variable": "b", "parents": [], "values": [[0.5, 0.5]]},
            ],
        },
        "transition": {
            "edges": [["a@-1", "a"], ["a", "b"]],
            "tables": [
                {"variable": "a", "parents": ["a@-1"], "values": [[0.9, 0.1], [0.2, 0.8]]},
                {"variable": "b", "parents": ["a"], "values": [[0.9, 0.1], [0.2, 0.8]]},
            ],
        },
    }
    with pytest.raises(pgm.Error, match="one set of edges within a slice for both slices.*a->b"):
        dynamic_example(tmp_path, json.dumps(document)).to_pgmpy()
    document["transition"]["edges"] = [["a@-1", "a"]]
    document["transition"]["tables"][1]["parents"] = []
    document["transition"]["tables"][1]["values"] = [[0.5, 0.5]]
    with pytest.raises(pgm.Error, match="cannot hold 'b' after the first slice"):
        dynamic_example(tmp_path, json.dumps(document)).to_pgmpy()


def test_a_dynamic_network_built_in_pgmpy_comes_over():
    from pgmpy.factors.discrete import TabularCPD
    from pgmpy.models import DynamicBayesianNetwork

    # pgmpy's own example: grade G given difficulty D and intelligence I, D and I persisting.
    theirs = DynamicBayesianNetwork()
    theirs.add_edges_from([(("D", 0), ("G", 0)), (("I", 0), ("G", 0)), (("D", 0), ("D", 1)), (("I", 0), ("I", 1))])
    grade = [[0.3, 0.05, 0.9, 0.5], [0.4, 0.25, 0.08, 0.3], [0.3, 0.7, 0.02, 0.2]]
    theirs.add_cpds(
        TabularCPD(("D", 0), 2, [[0.6], [0.4]]),
        TabularCPD(("I", 0), 2, [[0.7], [0.3]]),
        TabularCPD(("G", 0), 3, grade, evidence=[("I", 0), ("D", 0)], evidence_card=[2, 2]),
        TabularCPD(("D", 1), 2, [[0.6, 0.3], [0.4, 0.7]], evidence=[("D", 0)], evidence_card=[2]),
        TabularCPD(("I", 1), 2, [[0.5, 0.4], [0.5, 0.6]], evidence=[("I", 0)], evidence_card=[2]),
        TabularCPD(("G", 1), 3, grade, evidence=[("I", 1), ("D", 1)], evidence_card=[2, 2]),
    )
    ours = pgm.from_pgmpy(theirs)
    assert ours.variables == ["D", "G", "I"]
    assert ours.states("G") == ["0", "1", "2"]
    assert sorted(ours.transition_edges) == [("D", "G"), ("D@-1", "D"), ("I", "G"), ("I@-1", "I")]
    unrolled = ours.unroll(2)
    assert unrolled.parents("G@1") == ["I@1", "D@1"]
    assert unrolled.cpt("D@1").to_numpy().tolist()[1][-2:] == [0.3, 0.7]
