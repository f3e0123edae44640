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
