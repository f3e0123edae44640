"""pgm.MarkovNetwork: built from factors, read from a .uai file, its tasks against brute force,
and pgm.InferenceEngine on it (pgmpy's MarkovNetwork both ways: test_pgmpy.py)."""

import itertools
import math

import numpy as np
import pytest

import pgm

# a – b – c: Z = (1+3)(1+1) + (2+4)(1+5) = 44.
CHAIN = "MARKOV\n3\n2 2 2\n2\n2 0 1\n2 1 2\n\n4\n 1 2 3 4\n\n4\n 1 1 1 5\n"


def chain():
    return pgm.MarkovNetwork(
        {"a": ["0", "1"], "b": ["0", "1"], "c": ["0", "1"]},
        [(("a", "b"), [[1, 2], [3, 4]]), (("b", "c"), [[1, 1], [1, 5]])],
    )


def brute_force(model, evidence=None):
    evidence = evidence or {}
    names = model.variables
    z = 0.0
    sums = {n: np.zeros(len(model.states(n))) for n in names}
    for states in itertools.product(*(range(len(model.states(n))) for n in names)):
        assignment = dict(zip(names, states))
        if any(model.states(n)[assignment[n]] != s for n, s in evidence.items()):
            continue
        w = 1.0
        for scope, values in model.factors:
            w *= values[tuple(assignment[v] for v in scope)]
        z += w
        for n in names:
            sums[n][assignment[n]] += w
    return z, {n: s / z for n, s in sums.items()}


def test_a_model_from_factors_answers_as_brute_force():
    model = chain()
    assert model.variables == ["a", "b", "c"]
    assert model.factors[1][1].shape == (2, 2)
    z, marginals = brute_force(model)
    for engine in ("jt", "ve", "bp", "auto"):
        assert model.log_partition_function(engine=engine) == pytest.approx(math.log(z), abs=1e-12)
        got = model.marginals(engine=engine)
        for name, series in got.items():
            assert list(series.index) == ["0", "1"]
            assert series.to_numpy() == pytest.approx(marginals[name], abs=1e-12)
    z_c, marginals_c = brute_force(model, {"c": "1"})
    assert model.log_partition_function({"c": "1"}) == pytest.approx(math.log(z_c), abs=1e-12)
    assert model.marginals({"c": "1"})["b"].to_numpy() == pytest.approx(marginals_c["b"], abs=1e-12)
    assert model.map() == {"a": "1", "b": "1", "c": "1"}
    sampled = model.marginals(engine="gibbs")  # 10,000 sweeps: within a few hundredths
    for name, series in sampled.items():
        assert series.to_numpy() == pytest.approx(marginals[name], abs=0.03)


def test_read_network_reads_a_markov_uai_file_and_writes_it_back(tmp_path):
    (tmp_path / "chain.uai").write_text(CHAIN)
    model = pgm.read_network(tmp_path / "chain.uai")
    assert isinstance(model, pgm.MarkovNetwork)
    assert model.variables == ["v0", "v1", "v2"]
    assert model.log_partition_function() == pytest.approx(math.log(44.0), abs=1e-14)
    model.write(tmp_path / "again.uai")
    again = pgm.read_network(tmp_path / "again.uai")
    for (s1, v1), (s2, v2) in zip(model.factors, again.factors):
        assert s1 == s2 and np.array_equal(v1, v2)


def test_a_markov_network_keeps_its_names_in_json(tmp_path):
    model = chain()
    model.write(tmp_path / "chain.json")
    assert '"kind": "markov"' in (tmp_path / "chain.json").read_text()
    again = pgm.read_network(tmp_path / "chain.json")
    assert isinstance(again, pgm.MarkovNetwork)
    assert again.variables == ["a", "b", "c"]
    for (s1, v1), (s2, v2) in zip(model.factors, again.factors):
        assert s1 == s2 and np.array_equal(v1, v2)
    assert again.log_partition_function() == pytest.approx(math.log(44.0), abs=1e-14)
    # A Bayesian network's JSON is still a Network.
    (tmp_path / "b.uai").write_text("BAYES\n2\n2 2\n2\n1 0\n2 0 1\n2\n0.3 0.7\n4\n0.9 0.1 0.2 0.8\n")
    pgm.read_network(tmp_path / "b.uai").write(tmp_path / "b.json")
    assert isinstance(pgm.read_network(tmp_path / "b.json"), pgm.Network)


def test_a_bayes_uai_file_is_a_network(tmp_path):
    (tmp_path / "b.uai").write_text("BAYES\n2\n2 2\n2\n1 0\n2 0 1\n2\n0.3 0.7\n4\n0.9 0.1 0.2 0.8\n")
    network = pgm.read_network(tmp_path / "b.uai")
    assert isinstance(network, pgm.Network)
    assert pgm.InferenceEngine(network).log_partition_function() == pytest.approx(0.0, abs=1e-15)


@pytest.mark.parametrize("name", ["jt", "ve", "auto"])
def test_inference_engine_takes_a_markov_network(name):
    model = chain()
    engine = pgm.InferenceEngine(model, name)
    assert engine.name == "jt" if name == "auto" else name
    z, _ = brute_force(model)
    assert engine.log_partition_function() == pytest.approx(math.log(z), abs=1e-12)
    engine.set_evidence({"c": "1"})
    z_c, marginals_c = brute_force(model, {"c": "1"})
    assert engine.log_partition_function() == pytest.approx(math.log(z_c), abs=1e-12)
    assert engine.probability_of_evidence() == pytest.approx(z_c / z, abs=1e-12)
    assert engine.marginal("a").to_numpy() == pytest.approx(marginals_c["a"], abs=1e-12)
    assert engine.joint(["a", "b"]).sum() == pytest.approx(1.0, abs=1e-12)
    assert set(engine.marginals()) == {"a", "b"}
    states, probability = engine.mpe()
    assert states == {"a": "1", "b": "1"}
    # P(a=1, b=1 | c=1): the product of the factors there over Z(c=1).
    assert probability == pytest.approx(4 * 5 / z_c, abs=1e-12)


def test_the_approximate_engines_answer_a_markov_network_and_lw_says_why_not():
    model = chain()
    _, marginals_c = brute_force(model, {"c": "1"})
    bp = pgm.InferenceEngine(model, "bp")
    bp.set_evidence({"c": "1"})
    # A chain is a tree: belief propagation is exact on it.
    assert bp.marginal("a").to_numpy() == pytest.approx(marginals_c["a"], abs=1e-9)
    gibbs = pgm.InferenceEngine(model, "gibbs", samples=20_000, seed=3)
    gibbs.set_evidence({"c": "1"})
    assert gibbs.marginal("a").to_numpy() == pytest.approx(marginals_c["a"], abs=0.03)
    with pytest.raises(pgm.Error, match="the engine 'lw' does not serve a Markov network"):
        pgm.InferenceEngine(model, "lw")
    with pytest.raises(pgm.Error, match="does not handle interventions .* a Markov network"):
        pgm.InferenceEngine(model, "jt").set_interventions({"a": "1"})


def test_bad_input_is_an_error_naming_it(tmp_path):
    with pytest.raises(pgm.Error, match="must be finite and not negative"):
        pgm.MarkovNetwork({"a": ["0", "1"]}, [(("a",), [1.0, -1.0])])
    with pytest.raises(pgm.Error, match="unknown variable 'z'"):
        pgm.MarkovNetwork({"a": ["0", "1"]}, [(("z",), [1.0, 1.0])])
    with pytest.raises(pgm.Error, match="unknown engine"):
        chain().marginals(engine="lw")
    with pytest.raises(pgm.Error, match="gibbs answers MAR"):
        chain().log_partition_function(engine="gibbs")
    with pytest.raises(pgm.Error, match="has probability 0"):
        pgm.MarkovNetwork({"a": ["0", "1"]}, [(("a",), [0.0, 1.0])]).marginals({"a": "0"})
    (tmp_path / "bad.uai").write_text("MARKOV\n1\n2\n1\n1 0\n3\n1 2 3\n")
    with pytest.raises(pgm.Error, match=r"bad.uai:6:1: factor 0 has 2 entries"):
        pgm.read_network(tmp_path / "bad.uai")


def test_an_unknown_engine_is_met_with_the_one_meant():
    # Issue 49: the engine had no "did you mean" (the library's choices all have one).
    known = r"\(known: auto, jt, ve, bp, gibbs\)"
    with pytest.raises(pgm.Error, match=rf"^unknown engine 'gibs'; did you mean 'gibbs'\? {known}$"):
        chain().marginals(engine="gibs")
    with pytest.raises(TypeError, match="^engine must be one of auto, jt, ve, bp, gibbs, got int$"):
        chain().marginals(engine=1)


def test_memory_limit_is_bounded_as_the_programs():
    # Issue 49: a negative limit failed in pybind11's conversion, a huge one overflowed C++'s MiB-to-bytes shift.
    model = chain()
    for limit in (0, -1, 2**44):
        model.memory_limit = limit
        with pytest.raises(pgm.Error, match=f"^memory_limit must be a whole number from 1 to 16777216, got {limit}$"):
            model.log_partition_function()
    model.memory_limit = 1 << 24
    assert model.log_partition_function() == pytest.approx(math.log(44))
