"""pgm.learn_structure: PC-stable as `pgm learn-structure`, the same DAG from the same data."""

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
        ({}, ["--test", "g2"]),
        ({"test": "chi2", "alpha": 0.05}, ["--test", "chi2", "--alpha", "0.05"]),
        ({"tiers": [["xOff1", "yOff1", "xOff2", "yOff2", "colour"], ["onTop1"], ["onTop2"]]},
         ["--test", "g2", "--tiers", "xOff1,yOff1,xOff2,yOff2,colour;onTop1;onTop2"]),
        ({"forbid": [("onTop1", "onTop2")], "require": "yOff2->onTop2"},
         ["--test", "g2", "--forbid", "onTop1->onTop2", "--require", "yOff2->onTop2"]),
        ({"max_cond": 1}, ["--test", "g2", "--max-cond", "1"]),
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
