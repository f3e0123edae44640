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
    with pytest.raises(pgm.Error, match="threads must be a whole number from 0 to 1024, got -1"):
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
    with pytest.raises(pgm.Error, match="bins must be a whole number from 1 to 10000, got 0"):
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


@pytest.fixture
def before_cpp(network, monkeypatch):
    """pgm._core's calls made to fail the test: an argument out of the program's bounds must be
    refused before C++, where it would run for hours, allocate without end or wrap."""

    def reached(name):
        def call(*arguments, **keywords):
            raise AssertionError(f"pgm._core.{name} was called")

        return call

    for name in ("fit", "update", "learn_structure", "score", "check", "discretize", "simulate", "experiment", "Engine"):
        monkeypatch.setattr(pgm._core, name, reached(name))
    return network


def test_counts_past_the_programs_bounds_are_refused(before_cpp):
    # Issue 49: restarts=10**6 hung (the program takes at most 1,000), samples=10**12 ended in
    # std::bad_alloc (the program takes at most 10**9).
    network = before_cpp
    frame = pd.DataFrame({"a": [0, 1, 1, 0, 1], "b": [1, 1, 0, 0, 1]})
    cases = [
        (lambda: pgm.fit(frame, "a->b", missing="em", restarts=10**6), "restarts", 1, 1000, 10**6),
        (lambda: pgm.fit(frame, "a->b", missing="em", max_iterations=-1), "max_iterations", 0, 1_000_000, -1),
        (lambda: pgm.fit(frame, "a->b", threads=1025), "threads", 0, 1024, 1025),
        (lambda: network.update(frame, threads=-1), "threads", 0, 1024, -1),
        (lambda: pgm.learn_structure(frame, algorithm="hc", restarts=10**6), "restarts", 0, 100_000, 10**6),
        (lambda: pgm.learn_structure(frame, algorithm="tabu", tabu=0), "tabu", 1, 100_000, 0),
        (lambda: pgm.learn_structure(frame, algorithm="tabu", max_tabu=10**5 + 1), "max_tabu", 0, 100_000, 10**5 + 1),
        (lambda: pgm.learn_structure(frame, algorithm="hc", perturb=0), "perturb", 1, 100_000, 0),
        (lambda: pgm.learn_structure(frame, algorithm="hc", max_parents=-1), "max_parents", 0, 1024, -1),
        (lambda: pgm.learn_structure(frame, max_cond=65), "max_cond", 0, 64, 65),
        (lambda: pgm.learn_structure(frame, threads=2**64), "threads", 0, 1024, 2**64),
        (lambda: pgm.score(network, frame, threads=-1), "threads", 0, 1024, -1),
        (lambda: pgm.check(network, frame, threads=-1), "threads", 0, 1024, -1),
        (lambda: pgm.discretize(frame, bins=10_001), "bins", 1, 10_000, 10_001),
        (lambda: pgm.simulate("1-stack", 10, threads=-1), "threads", 0, 1024, -1),
        (lambda: pgm.experiment("2-stack-sim", reps=1001), "reps", 1, 1000, 1001),
        (lambda: pgm.experiment("2-stack-sim", reps=0), "reps", 1, 1000, 0),
        (lambda: pgm.InferenceEngine(network, "lw", samples=10**12), "samples", 1, 10**9, 10**12),
        (lambda: pgm.InferenceEngine(network, "lw", samples=0), "samples", 1, 10**9, 0),
        (lambda: pgm.InferenceEngine(network, "gibbs", burn_in=-1), "burn_in", 0, 10**8, -1),
        (lambda: pgm.InferenceEngine(network, "lw", threads=-1), "threads", 0, 1024, -1),
    ]
    for call, what, least, most, value in cases:
        with pytest.raises(pgm.Error, match=f"^{what} must be a whole number from {least} to {most}, got {value}$"):
            call()


@pytest.mark.parametrize("seed", [-1, 2**64])
def test_a_seed_outside_64_bits_is_refused_by_every_function(before_cpp, seed):
    # Issue 49: a seed past 2**64 - 1 failed in pybind11's conversion; fit took a negative one
    # without missing="em".
    network = before_cpp
    frame = pd.DataFrame({"a": [0, 1, 1, 0, 1], "b": [1, 1, 0, 0, 1]})
    message = rf"^seed must be a whole number from 0 to 2\*\*64 - 1 \(18446744073709551615\), got {seed}$"
    for call in (
        lambda: pgm.fit(frame, "a->b", seed=seed),
        lambda: pgm.fit(frame, "a->b", missing="em", seed=seed),
        lambda: pgm.learn_structure(frame, algorithm="hc", seed=seed),
        lambda: pgm.simulate("1-stack", 10, seed=seed),
        lambda: pgm.experiment("2-stack-sim", reps=1, seed=seed),
        lambda: pgm.InferenceEngine(network, "lw", seed=seed),
    ):
        with pytest.raises(pgm.Error, match=message):
            call()


def test_the_largest_seed_and_restarts_are_taken(network):
    engine = pgm.InferenceEngine(network, "lw", samples=1000, seed=2**64 - 1, threads=1)
    assert engine.marginal("b").sum() == pytest.approx(1.0)
    assert len(pgm.simulate("1-stack", 5, seed=2**64 - 1)) == 5
    frame = pd.DataFrame({"a": [0, 1, 1, 0, 1], "b": [1, 1, 0, 0, 1]})
    assert pgm.fit(frame, "a->b", missing="em", restarts=1000, seed=2**64 - 1).states("b") == ["0", "1"]
