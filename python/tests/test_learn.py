"""pgm.learn_structure: PC-stable, hill climbing, tabu and the hybrid as `pgm learn-structure`, the same
DAG from the same data; pgm.score."""

import inspect
import json

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
    with pytest.raises(pgm.Error, match="start applies to hc, tabu and mmhc, not pc"):
        pgm.learn_structure(data, start=pc)
    with pytest.raises(pgm.Error, match="unknown structure learning algorithm 'ges'"):
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
    with pytest.raises(pgm.Error, match="prior_model applies to hc, tabu and mmhc, not pc"):
        pgm.learn_structure(few, prior_model=prior)
    with pytest.raises(pgm.Error, match="map applies with prior_model"):
        pgm.learn_structure(few, algorithm="hc", map="onTop2=onTop1")
    assert pgm.learn_structure(data, algorithm="hc", start="pc") == pgm.learn_structure(
        data, algorithm="hc", start=pgm.learn_structure(data))
    with pytest.raises(pgm.Error, match="start must be"):
        pgm.learn_structure(data, algorithm="hc", start="empty")
