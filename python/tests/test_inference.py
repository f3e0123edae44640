"""pgm.InferenceEngine, pgm.query and pgm.mpe: every engine against hand-computed answers and
against each other on a published network, evidence set and retracted, soft evidence, the most
probable explanation, the sampling engines' standard errors, the program's answers, and the
errors for arguments of the wrong kind."""

import inspect
import json
import math
import os
from pathlib import Path

import pandas as pd
import pytest

import pgm

NETWORKS = Path(os.environ.get("PGM_SOURCE_DIR", Path(__file__).resolve().parents[2])) / "tests" / "data" / "networks"


@pytest.fixture
def chain():
    # P(A=1) = 0.7; P(B=1 | A=0) = 1/3, P(B=1 | A=1) = 6/7.
    frame = pd.DataFrame({"A": [0] * 3 + [1] * 7, "B": [1, 0, 0] + [1] * 6 + [0]})
    return pgm.fit(frame, "A->B")


@pytest.fixture(scope="module")
def asia():
    return pgm.read_network(NETWORKS / "asia.bif")


@pytest.mark.parametrize("engine", ["jt", "ve", "auto"])
def test_marginal_by_bayes_rule(chain, engine):
    e = pgm.InferenceEngine(chain, engine)
    e.set_evidence({"B": 1})
    posterior = e.marginal("A")
    assert posterior.index.name == "A"
    assert posterior["0"] == pytest.approx(0.1 / 0.7, rel=1e-14)
    assert e.probability_of_evidence() == pytest.approx(0.7, rel=1e-14)
    e.set_evidence(None)  # retracted: the prior again
    assert e.marginal("A")["1"] == pytest.approx(0.7, rel=1e-14)
    assert e.name == ("jt" if engine == "auto" else engine)


def test_soft_evidence_reweights_by_likelihood(chain):
    # A likelihood (0.2, 0.8) on B: P(A=1 | soft) ∝ Σ_b P(A=1) P(b | A=1) λ(b).
    e = pgm.InferenceEngine(chain, "jt")
    e.set_soft_evidence({"B": [0.2, 0.8]})
    a1 = 0.7 * (1 / 7 * 0.2 + 6 / 7 * 0.8)
    a0 = 0.3 * (2 / 3 * 0.2 + 1 / 3 * 0.8)
    assert e.marginal("A")["1"] == pytest.approx(a1 / (a0 + a1), rel=1e-14)
    assert e.probability_of_evidence() == pytest.approx(a0 + a1, rel=1e-14)
    # Hard evidence set afterwards keeps the soft evidence; each is retracted on its own.
    e.set_evidence({"A": 1})
    assert e.marginal("B")["1"] == pytest.approx(6 / 7 * 0.8 / (6 / 7 * 0.8 + 1 / 7 * 0.2), rel=1e-14)
    e.set_soft_evidence(None)
    assert e.marginal("B")["1"] == pytest.approx(6 / 7, rel=1e-14)
    q = pgm.query(chain, "A", soft_evidence={"B": [0.2, 0.8]}, engine="ve")
    assert q["1"] == pytest.approx(a1 / (a0 + a1), rel=1e-14)


def test_engines_agree_on_a_published_network(asia):
    evidence = {"dysp": "yes", "smoke": "no"}
    answers = {}
    for name in ("jt", "ve"):
        e = pgm.InferenceEngine(asia, name)
        e.set_evidence(evidence)
        answers[name] = e.marginals()
        joint = e.joint(["lung", "tub"])
        assert list(joint.index.names) == ["lung", "tub"]
        assert joint.sum() == pytest.approx(1.0)
    assert set(answers["jt"]) == set(asia.variables) - set(evidence)
    for variable, series in answers["jt"].items():
        assert series.to_numpy() == pytest.approx(answers["ve"][variable].to_numpy(), abs=1e-15)


def test_most_probable_explanation(asia):
    states, probability = pgm.mpe(asia, {"dysp": "yes"})
    assert set(states) == set(asia.variables) - {"dysp"}
    ve_states, ve_probability = pgm.mpe(asia, {"dysp": "yes"}, engine="ve")
    assert states == ve_states
    assert probability == pytest.approx(ve_probability, rel=1e-12)
    # Of two variables, the others summed out: the best joint state of their joint query.
    subset, p = pgm.mpe(asia, {"dysp": "yes"}, variables=["lung", "tub"])
    joint = pgm.query(asia, ["lung", "tub"], {"dysp": "yes"})
    assert p == pytest.approx(joint.max(), rel=1e-12)
    assert (subset["lung"], subset["tub"]) == joint.idxmax()


def test_sampling_engines_are_within_their_standard_errors(asia):
    # Gibbs sampling needs tables without zeros to move between all states (asia's "either" is
    # a deterministic OR, which stalls single-variable updates): a network fitted with a K2 prior.
    from conftest import stacking_frame

    frame = stacking_frame(5000, 4)
    smooth = pgm.fit(frame, "xOff1->onTop1,yOff1->onTop1,onTop1->onTop2,xOff2->onTop2", "bayes", "k2")
    for name, net, evidence, variable in (("lw", asia, {"xray": "yes"}, "lung"), ("gibbs", smooth, {"onTop2": 1}, "xOff1")):
        exact = pgm.InferenceEngine(net, "jt")
        exact.set_evidence(evidence)
        truth = exact.marginals()
        e = pgm.InferenceEngine(net, name, samples=100_000, seed=3, threads=1)
        e.set_evidence(evidence)
        estimates = e.marginals()
        for v, series in estimates.items():
            se = series.attrs["standard_error"]
            for state, p in series.items():
                assert abs(p - truth[v][state]) <= 4 * se[state] + 1e-12, (name, v, state)
        again = pgm.InferenceEngine(net, name, samples=100_000, seed=3, threads=2)
        again.set_evidence(evidence)
        assert again.marginal(variable).to_numpy().tolist() == estimates[variable].to_numpy().tolist()


def test_program_prints_the_same_marginals(asia, program, tmp_path):
    result = program.run(
        "query", "--model", NETWORKS / "asia.bif", "--all", "--evidence", "dysp=yes", "--digits", "17",
        "--format", "json",
    )
    printed = json.loads(result.stdout)
    assert printed["engine"] == "jt"
    e = pgm.InferenceEngine(asia, "jt")
    e.set_evidence({"dysp": "yes"})
    for variable, series in e.marginals().items():
        for state, p in series.items():
            assert printed["marginals"][variable][state] == p


def test_an_engine_takes_its_options_in_brackets(asia, program):
    sampled = pgm.InferenceEngine(asia, "lw[samples=2000,seed=5]", threads=1)
    same = pgm.InferenceEngine(asia, "lw", samples=2000, seed=5, threads=1)
    assert sampled.marginal("lung").tolist() == same.marginal("lung").tolist()
    assert pgm.InferenceEngine(asia, "auto[max_cells=4]").name == "lw"
    listing = pgm._core.engine_listing()
    assert "bp[schedule=residual,damping=0,tolerance=1e-09,max_iterations=1000]" in listing
    assert "bp[schedule=residual,damping=0,tolerance=1e-09,max_iterations=1000]" in program.run("query", "--help").stdout
    with pytest.raises(pgm.Error, match=r"unknown jt option 'samples'"):
        pgm.InferenceEngine(asia, "jt[samples=5]")
    with pytest.raises(pgm.Error, match=r"option damping of the inference engine 'bp' must be a number >= 0 and < 1"):
        pgm.InferenceEngine(asia, "bp[damping=1]")


def test_the_engines_options_have_one_default_everywhere():
    """InferenceEngine's samples, seed and burn_in show the defaults the engines declare."""
    declared = {}
    for choice in pgm._core.engine_listing():
        if "[" in choice:
            for setting in choice[choice.index("[") + 1:-1].split(","):
                key, value = setting.split("=")
                assert declared.setdefault(key, value) == value, key  # one default per option
    parameters = inspect.signature(pgm.InferenceEngine.__init__).parameters
    assert parameters["engine"].default == "auto"
    for keyword in ("samples", "seed", "burn_in"):
        assert str(parameters[keyword].default) == declared[keyword], keyword


def test_impossible_evidence_and_unknown_names(chain, asia):
    frame = pd.DataFrame({"A": [0, 0, 1, 1], "B": [0, 0, 1, 1], "C": [0, 1, 0, 1]})
    net = pgm.fit(frame, "A->B,A->C")
    e = pgm.InferenceEngine(net, "jt")
    e.set_evidence({"A": 0, "B": 1})
    with pytest.raises(pgm.Error, match="the evidence A=0, B=1 has probability 0"):
        e.marginal("C")
    assert e.log_probability_of_evidence() == -math.inf  # a probability: 0 is an answer
    assert e.probability_of_evidence() == 0.0
    with pytest.raises(pgm.Error, match="no variable 'lamp'"):
        pgm.InferenceEngine(asia, "jt").set_evidence({"lamp": "on"})
    with pytest.raises(pgm.Error, match=r"unknown inference engine 'magic' \(known: auto, bp, gibbs, jt, lw, ve\)"):
        pgm.InferenceEngine(asia, "magic")
    with pytest.raises(pgm.Error, match="2 states"):
        pgm.InferenceEngine(asia, "jt").set_soft_evidence({"lung": [0.5]})
    with pytest.raises(pgm.Error, match="does not find the most probable explanation"):
        pgm.InferenceEngine(asia, "lw").mpe()


def test_arguments_of_the_wrong_type(asia):
    with pytest.raises(TypeError, match="network must be a pgm.Network"):
        pgm.InferenceEngine("asia.bif")
    e = pgm.InferenceEngine(asia, "jt")
    with pytest.raises(TypeError, match="evidence must be a dict"):
        e.set_evidence([("dysp", "yes")])
    with pytest.raises(TypeError, match="the weights of 'lung' must be a list of numbers"):
        e.set_soft_evidence({"lung": "heavy"})
    with pytest.raises(TypeError, match="variable must be a name"):
        e.marginal(3)
    with pytest.raises(pgm.Error, match="variables is empty: name at least one variable"):
        e.joint([])
    with pytest.raises(pgm.Error, match="variables is empty"):
        pgm.query(asia, [])
