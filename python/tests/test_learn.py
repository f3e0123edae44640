"""pgm.learn_structure: PC-stable, hill climbing, tabu and the hybrid as `pgm learn-structure`, the same
DAG from the same data; pgm.score."""

import inspect
import json
import math

import numpy as np
import pandas as pd
import pytest
from conftest import stacking_frame

import pgm


@pytest.fixture
def data():
    return stacking_frame(5000, 3).drop(columns=["colourCat"])


def cli_edges(program, tmp_path, frame, *arguments):
    frame.to_csv(tmp_path / "data.csv", index=False)
    program.run("learn-structure", "--data", tmp_path / "data.csv", "--out", tmp_path / "m.json", *arguments)
    return [tuple(e) for e in json.loads((tmp_path / "m.json").read_text())["edges"]]


@pytest.mark.parametrize(
    "kwargs, arguments",
    [
        ({}, []),  # the same default test (chi2)
        ({"test": "g2"}, ["--test", "g2"]),
        ({"test": "chi2[correction=yates,min_rows_per_cell=5]"},
         ["--test", "chi2", "--correction", "yates", "--min-rows-per-cell", "5"]),
        ({"test": "g2[min_rows_per_cell=2]"}, ["--test", "g2[min_rows_per_cell=2]"]),
        ({"test": "chi2", "alpha": 0.05}, ["--test", "chi2", "--alpha", "0.05"]),
        ({"tiers": [["xOff1", "yOff1", "xOff2", "yOff2", "colour"], ["onTop1"], ["onTop2"]]},
         ["--tiers", "xOff1,yOff1,xOff2,yOff2,colour;onTop1;onTop2"]),
        ({"forbid": [("onTop1", "onTop2")], "require": "yOff2->onTop2"},
         ["--forbid", "onTop1->onTop2", "--require", "yOff2->onTop2"]),
        ({"max_cond": 1}, ["--max-cond", "1"]),
    ],
)
def test_the_programs_dag_from_the_same_data(program, tmp_path, data, kwargs, arguments):
    ours = pgm.learn_structure(data, **kwargs)
    assert ours == cli_edges(program, tmp_path, data, *arguments)


def test_the_stacking_causes_are_found(data):
    edges = set(pgm.learn_structure(data, tiers="xOff1,yOff1,xOff2,yOff2,colour;onTop1;onTop2"))
    assert {("xOff1", "onTop1"), ("yOff1", "onTop1"), ("xOff2", "onTop2")} <= edges
    assert not any("colour" in edge for edge in edges)


def test_required_edges_are_kept_and_the_result_fits(data):
    edges = pgm.learn_structure(data, require=[("colour", "onTop1")])
    assert ("colour", "onTop1") in edges
    net = pgm.fit(data, edges)
    assert set(net.edges) == set(edges)


def test_learning_errors(data):
    with pytest.raises(pgm.Error, match=r"unknown independence test .t. \(known: chi2, g2\)"):
        pgm.learn_structure(data, test="t")
    with pytest.raises(pgm.Error, match="alpha"):
        pgm.learn_structure(data, alpha=1.5)
    with pytest.raises(pgm.Error, match="continuous"):
        pgm.learn_structure(data.assign(raw=np.linspace(0, 1, len(data))))


# ---- score-based search and pgm.score ---------------------------------------------------------


@pytest.mark.parametrize(
    "kwargs, arguments",
    [
        ({"algorithm": "hc"}, ["--algorithm", "hc"]),
        ({"algorithm": "hc", "score": "bdeu[iss=10]"}, ["--algorithm", "hc", "--score", "bdeu", "--iss", "10"]),
        ({"algorithm": "hc", "score": "aic[k=3]"}, ["--algorithm", "hc", "--score", "aic[k=3]"]),
        ({"algorithm": "tabu", "score": "k2", "max_parents": 2},
         ["--algorithm", "tabu", "--score", "k2", "--max-parents", "2"]),
        ({"algorithm": "hc", "restarts": 2, "perturb": 3, "seed": 7},
         ["--algorithm", "hc", "--restarts", "2", "--perturb", "3", "--seed", "7"]),
        ({"algorithm": "mmhc", "test": "g2"}, ["--algorithm", "mmhc", "--test", "g2"]),
    ],
)
def test_score_search_gives_the_programs_dag(program, tmp_path, data, kwargs, arguments):
    assert pgm.learn_structure(data, **kwargs) == cli_edges(program, tmp_path, data, *arguments)


def test_score_by_node_and_against_pc(data):
    edges = pgm.learn_structure(data, algorithm="hc")
    net = pgm.fit(data, edges)
    terms = pgm.score(net, data, score="bic", by_node=True)
    assert list(terms) == list(net.variables)
    assert pgm.score(net, data) == pytest.approx(sum(terms.values()), rel=1e-12)
    for score in ("bic", "aic", "bdeu[iss=5]", "k2", "loglik"):
        value = pgm.score(net, data, score=score)
        assert np.isfinite(value)
    # Hill climbing ends no worse than the PC network, by BIC.
    pc = pgm.fit(data, pgm.learn_structure(data))
    assert pgm.score(net, data) >= pgm.score(pc, data) - 1e-9


def test_start_and_score_errors(data):
    pc = pgm.learn_structure(data)
    started = pgm.learn_structure(data, algorithm="hc", start=pc)
    assert started == pgm.learn_structure(data, algorithm="hc", start=pgm.fit(data, pc))
    with pytest.raises(pgm.Error, match="PC-stable takes no start network; hc, tabu and mmhc do"):
        pgm.learn_structure(data, start=pc)
    with pytest.raises(pgm.Error, match="unknown structure learner 'ges'"):
        pgm.learn_structure(data, algorithm="ges")
    with pytest.raises(pgm.Error, match="unknown score 'mdl'"):
        pgm.learn_structure(data, algorithm="hc", score="mdl")
    net = pgm.fit(data, pc)
    with pytest.raises(pgm.Error, match="option iss of the score 'bdeu' must be a number > 0, got '0'"):
        pgm.score(net, data, score="bdeu[iss=0]")
    with pytest.raises(pgm.Error, match="the score 'bic' takes no options, got 'iss'"):
        pgm.score(net, data, score="bic[iss=2]")
    with pytest.raises(TypeError):
        pgm.score(net, data, score="bdeu", iss=2)
    with pytest.raises(pgm.Error, match="there is no column 'onTop2'"):
        pgm.score(net, data.drop(columns=["onTop2"]))
    with pytest.raises(TypeError):
        pgm.score(pc, data)


def test_the_default_score_and_test_are_the_librarys_everywhere(program):
    declared = pgm._core.default_score
    assert declared == "bic"
    for function in (pgm.learn_structure, pgm.score):
        assert inspect.signature(function).parameters["score"].default == declared
    for command in ("score", "learn-structure"):
        assert f"NAME[KEY=VALUE,...]={declared}\n" in program.run(command, "--help").stdout
    listing = pgm._core.score_listing()
    assert "bdeu[iss=1]" in listing and declared in listing

    declared = pgm._core.default_ci_test
    assert declared == "chi2"
    for function in (pgm.learn_structure, pgm.check):
        assert inspect.signature(function).parameters["test"].default == declared
    for command in ("check", "learn-structure"):
        assert f"--test TEXT:NAME[KEY=VALUE,...]={declared}\n" in program.run(command, "--help").stdout
    assert "g2[correction=none,min_rows_per_cell=0]" in pgm._core.ci_test_listing()


def test_the_learners_options_have_one_default_everywhere(program):
    """Each keyword argument of learn_structure that sets a learner's option shows the default
    the learner declares, and so does the program's --help."""
    declared = pgm._core.learner_defaults()
    assert pgm._core.default_learner == "pc"
    parameters = inspect.signature(pgm.learn_structure).parameters
    assert parameters["algorithm"].default == pgm._core.default_learner
    shown = program.run("learn-structure", "--help").stdout
    for keyword, option, flag in [("test", "test", "--test"), ("alpha", "alpha", "--alpha"),
                                  ("max_cond", "max_conditioning", "--max-cond"), ("score", "score", "--score"),
                                  ("max_parents", "max_parents", "--max-parents"), ("tabu", "tabu", "--tabu"),
                                  ("max_tabu", "max_tabu", "--max-tabu"), ("restarts", "restarts", "--restarts"),
                                  ("perturb", "perturb", "--perturb"), ("seed", "seed", "--seed")]:
        default = parameters[keyword].default
        text = "unlimited" if default == math.inf else str(default)
        assert text == declared[option], keyword
        line = next(line for line in shown.splitlines() if line.strip().startswith(flag + " "))
        assert line.rstrip().endswith("=" + text), (flag, line)
    assert "mmhc[test=chi2,alpha=0.01" in " ".join(pgm._core.learner_listing())


def test_a_learner_is_chosen_with_its_options(data):
    assert pgm.learn_structure(data, algorithm="hc[restarts=2,seed=3]") == pgm.learn_structure(
        data, algorithm="hc", restarts=2, seed=3)
    assert pgm.learn_structure(data, algorithm="mmhc", alpha=0.05) == pgm.learn_structure(
        data, algorithm="mmhc[alpha=0.05]")
    assert pgm.learn_structure(data, algorithm="hc", start="pc", alpha=0.05) == pgm.learn_structure(
        data, algorithm="hc[start=pc[alpha=0.05]]")
    assert pgm.learn_structure(data, algorithm="hc", max_parents=1) == pgm.learn_structure(
        data, algorithm="hc[max_parents=1]")
    assert pgm.learn_structure(data, algorithm="empty", require=[("colour", "onTop1")]) == [("colour", "onTop1")]
    with pytest.raises(pgm.Error, match="alpha: sets the option alpha, which the structure learner hc has not"):
        pgm.learn_structure(data, algorithm="hc", alpha=0.05)
    with pytest.raises(pgm.Error, match="option tabu of the structure learner 'tabu' must be a whole number from 1"):
        pgm.learn_structure(data, algorithm="tabu[tabu=0]")


def test_score_equals_the_programs(program, tmp_path, data):
    net = pgm.fit(data, pgm.learn_structure(data, algorithm="hc"))
    net.write(tmp_path / "m.json")
    data.to_csv(tmp_path / "data.csv", index=False)
    for score in ("bic", "bdeu[iss=3]", "aic[k=2.5]"):
        out = program.run("score", "--model", tmp_path / "m.json", "--data", tmp_path / "data.csv", "--score",
                          score).stdout
        total = float(out.splitlines()[0].rsplit(": ", 1)[1])
        assert pgm.score(net, data, score=score) == pytest.approx(total, rel=1e-12)


def test_structure_prior_and_start_from_pc(data):
    prior = pgm.fit(data, [("xOff1", "onTop1"), ("yOff1", "onTop1")])
    few = data.head(60)
    scratch = pgm.learn_structure(few, algorithm="hc")
    favoured = pgm.learn_structure(few, algorithm="hc", prior_model=prior, map="onTop2=onTop1,xOff2~xOff1,yOff2~yOff1",
                                   prior_weight=1000)
    assert {("xOff1", "onTop1"), ("yOff1", "onTop1")} <= set(favoured)
    assert pgm.learn_structure(few, algorithm="hc", prior_model=prior, map="onTop2=onTop1", prior_weight=0) == scratch
    with pytest.raises(pgm.Error, match="PC-stable takes no structure prior; hc, tabu and mmhc do"):
        pgm.learn_structure(few, prior_model=prior)
    with pytest.raises(pgm.Error, match="map applies with prior_model"):
        pgm.learn_structure(few, algorithm="hc", map="onTop2=onTop1")
    assert pgm.learn_structure(data, algorithm="hc", start="pc") == pgm.learn_structure(
        data, algorithm="hc", start=pgm.learn_structure(data))
    with pytest.raises(pgm.Error, match="start must be"):
        pgm.learn_structure(data, algorithm="hc", start="empty")
