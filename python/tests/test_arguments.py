"""Every public function checks its arguments: a wrong type is a TypeError, a wrong value a
pgm.Error, each naming the argument and what was expected (issue 28: AttributeErrors and pandas'
messages came out instead)."""

import numpy as np
import pandas as pd
import pytest

import pgm


@pytest.fixture(scope="module")
def network():
    frame = pd.DataFrame({"a": [0, 1, 1, 0, 1], "b": [1, 1, 0, 0, 1]})
    return pgm.fit(frame, "a->b")


def test_query_arguments(network):
    assert list(pgm.query(network, "b", {"a": "1"})) == list(pgm.query(network, ["b"], {"a": 1}))
    expected = r"evidence must be a dict \{variable: state\} such as \{'PKA': 'HIGH'\}, got list"
    with pytest.raises(TypeError, match=expected):
        pgm.query(network, "b", [("a", "1")])
    with pytest.raises(pgm.Error, match="variables is empty: name at least one variable"):
        pgm.query(network, [])
    with pytest.raises(TypeError, match="variables must be names"):
        pgm.query(network, [1])
    with pytest.raises(TypeError, match="variables must be a name or a list of names, got int"):
        pgm.query(network, 3)
    with pytest.raises(TypeError, match="network must be a pgm.Network"):
        pgm.query("m.bif", "b")
    with pytest.raises(TypeError, match="evidence must have variable names"):
        pgm.query(network, "b", {0: "1"})


def test_fit_arguments():
    frame = pd.DataFrame({"a": [0, 1, 1], "b": [1, 0, 1]})
    with pytest.raises(TypeError, match=r"edges must be \(parent, child\) pairs, got 'ab'"):
        pgm.fit(frame, ["ab"])
    with pytest.raises(TypeError, match=r"edges must be pairs of names \(strings\), got \('a', 1\)"):
        pgm.fit(frame, [("a", 1)])
    with pytest.raises(TypeError, match="edges must be"):
        pgm.fit(frame, 3)
    with pytest.raises(pgm.Error, match="edges is empty"):
        pgm.fit(frame, [])
    with pytest.raises(TypeError, match="threads must be a whole number, got 2.5"):
        pgm.fit(frame, "a->b", threads=2.5)
    with pytest.raises(pgm.Error, match="threads must be a whole number of at least 0, got -1"):
        pgm.fit(frame, "a->b", threads=-1)
    with pytest.raises(TypeError, match="alpha must be a number, got 'x'"):
        pgm.fit(frame, "a->b", estimator="bayes", prior="dirichlet", alpha="x")
    with pytest.raises(TypeError, match="estimator must be a string, got int"):
        pgm.fit(frame, "a->b", estimator=1)
    assert pgm.fit(frame, "a->b", threads=np.int64(1)).states("a") == ["0", "1"]


def test_network_and_decision_arguments(network, tmp_path):
    with pytest.raises(TypeError, match="name must be a variable's name"):
        network.states(0)
    with pytest.raises(TypeError, match="path must be a path"):
        network.write(3)
    with pytest.raises(TypeError, match="path must be a path"):
        pgm.read_network(None)
    with pytest.raises(TypeError, match=r"assign must be a dict \{variable: value\}"):
        pgm.predict(network, [("a", 1)], success="b=1")
    with pytest.raises(TypeError, match="marginalize must be True or False"):
        pgm.predict(network, {"a": 1}, success="b=1", marginalize="yes")
    with pytest.raises(TypeError, match="epsilon must be a number"):
        pgm.prevent(network, {"a": 1}, success="b=1", epsilon="high")
    with pytest.raises(pgm.Error, match="controllable is empty"):
        pgm.prevent(network, {"a": 1}, success="b=1", controllable=[])


def test_data_and_simulation_arguments():
    frame = pd.DataFrame({"x": [0.5, 1.5, 2.5], "y": [0, 1, 0]})
    with pytest.raises(TypeError, match="bins must be a whole number, got 2.0"):
        pgm.discretize(frame, bins=2.0)
    with pytest.raises(pgm.Error, match="bins must be a whole number of at least 1, got 0"):
        pgm.discretize(frame, bins=0)
    with pytest.raises(TypeError, match="columns must be names"):
        pgm.discretize(frame, columns=[1])
    with pytest.raises(pgm.Error, match="rows must be positive"):
        pgm.simulate("1-stack", 0)
    with pytest.raises(TypeError, match="rows must be a whole number, got '10'"):
        pgm.simulate("1-stack", "10")
    with pytest.raises(pgm.Error, match="rows: 10000000000 are more than 1000000000, pgm's limit of rows to simulate"):
        pgm.simulate("1-stack", 10**10)
    with pytest.raises(TypeError, match="seed must be a whole number"):
        pgm.simulate("1-stack", 10, seed=1.5)
    with pytest.raises(TypeError, match=r"each tier must be a name or a list of names"):
        pgm.learn_structure(pd.DataFrame({"a": [0, 1], "b": [1, 0]}), tiers=[3])
