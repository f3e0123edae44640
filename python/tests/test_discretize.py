"""pgm.discretize: binning as `pgm discretize`, the same codes and edges from the same data."""

import json

import numpy as np
import pandas as pd
import pytest

import pgm


@pytest.fixture
def raw():
    random = np.random.default_rng(1)
    return pd.DataFrame(
        {
            "x": random.normal(0, 1.6, 500),
            "n": random.integers(0, 100, 500),
            "ok": random.integers(0, 2, 500),
            "colour": np.array(["Red", "Blue"])[random.integers(0, 2, 500)],
        }
    )


def cli_discretize(program, tmp_path, frame, *arguments):
    frame.to_csv(tmp_path / "raw.csv", index=False)
    program.run("discretize", "--in", tmp_path / "raw.csv", "--out", tmp_path / "binned.csv", "--edges-out",
                tmp_path / "edges.json", *arguments)
    binned = pd.read_csv(tmp_path / "binned.csv", float_precision="round_trip")
    document = json.loads((tmp_path / "edges.json").read_text())
    return binned, {v["name"]: v["edges"] for v in document["variables"]}


@pytest.mark.parametrize(
    "kwargs, arguments",
    [
        ({}, []),
        ({"bins": 3, "method": "width"}, ["--bins", "3", "--method", "width"]),
        ({"columns": ["x"]}, ["--columns", "x"]),
        ({"columns": "ok", "bins": 2}, ["--columns", "ok", "--bins", "2"]),
    ],
)
def test_the_programs_codes_and_edges(program, tmp_path, raw, kwargs, arguments):
    ours, edges = pgm.discretize(raw, **kwargs)
    theirs, their_edges = cli_discretize(program, tmp_path, raw, *arguments)
    assert edges == their_edges
    assert list(ours.columns) == list(theirs.columns)
    for name in ours.columns:
        assert list(ours[name]) == list(theirs[name]), name
    for name in edges:
        assert ours[name].dtype == np.int64


def test_saved_edges_bin_new_data_the_same_way(program, tmp_path, raw):
    _, edges = pgm.discretize(raw, columns=["x"])
    new = raw.assign(x=raw["x"] * 1.5)
    again, used = pgm.discretize(new, edges=edges)
    assert used == edges
    raw.to_csv(tmp_path / "first.csv", index=False)
    program.run("discretize", "--in", tmp_path / "first.csv", "--columns", "x", "--out", tmp_path / "b.csv",
                "--edges-out", tmp_path / "edges.json")
    from_file, _ = pgm.discretize(new, edges=tmp_path / "edges.json")
    theirs, _ = cli_discretize(program, tmp_path, new, "--method", "edges", "--edges-in", tmp_path / "edges.json")
    assert list(again["x"]) == list(from_file["x"]) == list(theirs["x"])
    assert again["x"].min() == 0 and again["x"].max() == 4  # outside values go to the outer bins


def test_the_input_is_left_alone(raw):
    before = raw.copy()
    binned, _ = pgm.discretize(raw)
    pd.testing.assert_frame_equal(raw, before)
    assert binned["colour"].equals(raw["colour"])


def test_binned_data_fits_with_its_intervals(raw):
    binned, edges = pgm.discretize(raw, columns=["x"])
    net = pgm.fit(binned, "x->ok", intervals=edges)
    assert net.interval_edges("x") == edges["x"]
    assert net.states("x") == ["0", "1", "2", "3", "4"]


def test_discretize_errors(raw):
    with pytest.raises(pgm.Error, match="no numeric column has more than 600 distinct values"):
        pgm.discretize(raw, bins=600)
    with pytest.raises(pgm.Error, match="'colour' is discrete, not numeric"):
        pgm.discretize(raw, columns=["colour"])
    with pytest.raises(pgm.Error, match="'edges' has no edges for 'n'"):
        pgm.discretize(raw, columns=["n"], edges={"x": [0.0, 1.0]})
    with pytest.raises(pgm.Error, match="unknown binning method"):
        pgm.discretize(raw, method="kmeans")
    with pytest.raises(pgm.Error, match=r"DataFrame: there is no column 'y' \(columns: x, n, ok, colour\)"):
        pgm.discretize(raw, columns=["y"])
