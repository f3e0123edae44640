"""pgm.experiment: the paper's scenarios as `pgm experiment`, the same points for the same seed,
as a tidy DataFrame with the columns of points.csv; the run releases the GIL."""

import numpy as np
import pandas as pd
import pytest
from conftest import releases_the_gil

import pgm

COLUMNS = ["scenario", "target", "strategy", "w", "rows", "repetition", "metric", "value"]


def test_the_programs_points_for_the_same_seed(program, tmp_path, monkeypatch):
    released, ours = releases_the_gil(
        monkeypatch, "experiment", lambda: pgm.experiment("2-stack-sim", reps=1, seed=3, threads=1)
    )
    assert released
    program.run(
        "experiment", "--scenario", "2-stack-sim", "--reps", "1", "--seed", "3", "--threads", "1",
        "--out", tmp_path / "results",
    )
    theirs = pd.read_csv(tmp_path / "results" / "points.csv", float_precision="round_trip", dtype={"w": str})
    assert list(ours.columns) == COLUMNS
    assert len(ours) == len(theirs) > 0
    for name in ["scenario", "target", "strategy", "w", "metric"]:
        assert isinstance(ours[name].dtype, pd.CategoricalDtype), name
        assert list(ours[name].astype(str)) == list(theirs[name].astype(str)), name
    for name in ["rows", "repetition", "value"]:
        assert np.array_equal(ours[name].to_numpy(), theirs[name].to_numpy()), name
    assert set(ours["strategy"]) >= {"oracle", "mle", "direct", "cross", "minimal"}
    assert any("proposed map" in note for note in ours.attrs["notes"])


def test_unknown_scenario_names_the_known_ones():
    with pytest.raises(pgm.Error, match="2-stack-sim"):
        pgm.experiment("3-stack", reps=1)


def test_bad_distance():
    with pytest.raises(pgm.Error, match=r"unknown distance 'miles' \(known: steps, units\)"):
        pgm.experiment("2-stack-sim", reps=1, distance="miles")
