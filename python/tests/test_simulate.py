"""pgm.simulate: the task simulators as `pgm simulate`, the same data for the same seed."""

import numpy as np
import pandas as pd
import pytest

import pgm


def cli_simulate(program, tmp_path, *arguments):
    program.run("simulate", "--out", tmp_path / "sim.csv", *arguments)
    return pd.read_csv(tmp_path / "sim.csv", float_precision="round_trip")


def assert_same_data(ours, theirs):
    assert list(ours.columns) == list(theirs.columns)
    for name in ours.columns:
        if isinstance(ours[name].dtype, pd.CategoricalDtype):
            assert list(ours[name].astype(str)) == list(theirs[name].astype(str)), name
        else:
            assert np.array_equal(ours[name].to_numpy(), theirs[name].to_numpy()), name


@pytest.mark.parametrize(
    "task, kwargs, arguments",
    [
        ("1-stack", {}, []),
        ("2-stack", {"seed": 9}, ["--seed", "9"]),
        ("2-stack", {"variant": "reality", "seed": 2}, ["--variant", "reality", "--seed", "2"]),
        ("drop-glass", {"seed": 4}, ["--seed", "4"]),
    ],
)
def test_the_programs_data_for_the_same_seed(program, tmp_path, task, kwargs, arguments):
    ours = pgm.simulate(task, 3000, **kwargs)
    theirs = cli_simulate(program, tmp_path, "--task", task, "--rows", "3000", *arguments)
    assert len(ours) == 3000
    assert_same_data(ours, theirs)


def test_columns_by_kind_and_any_thread_count():
    data = pgm.simulate("1-stack", 5000, seed=5, threads=1)
    assert data["xOff1"].dtype == np.float64
    assert data["onTop1"].dtype == np.int64
    assert set(data["onTop1"]) == {0, 1}
    assert isinstance(data["colorUp1"].dtype, pd.CategoricalDtype)
    assert list(data["colorUp1"].cat.categories) == ["Red", "Blue", "Green", "Orange"]  # the task file's order
    assert_same_data(data, pgm.simulate("1-stack", 5000, seed=5, threads=2))
    assert not data.equals(pgm.simulate("1-stack", 5000, seed=6))


def test_simulated_data_discretizes_and_fits():
    binned, edges = pgm.discretize(pgm.simulate("1-stack", 20000, seed=1), columns=["xOff1", "yOff1"])
    net = pgm.fit(binned, "xOff1->onTop1,yOff1->onTop1", intervals=edges)
    centre = pgm.predict(net, {"xOff1": 0.0, "yOff1": 0.0})
    edge = pgm.predict(net, {"xOff1": 2.9, "yOff1": 2.9})
    assert centre > edge


def test_simulation_errors():
    with pytest.raises(pgm.Error, match="unknown task '9-stack'; did you mean '1-stack'\\? \\(known: 1-stack"):
        pgm.simulate("9-stack", 10)
    with pytest.raises(pgm.Error, match="task 'drop-glass' has no reality variant"):
        pgm.simulate("drop-glass", 10, variant="reality")
    with pytest.raises(pgm.Error, match="unknown variant 'real'"):
        pgm.simulate("1-stack", 10, variant="real")
    with pytest.raises(pgm.Error, match="rows must be positive"):
        pgm.simulate("1-stack", 0)
    with pytest.raises(pgm.Error, match="unity"):
        pgm.simulate("1-stack", 10, backend="unity")


@pytest.mark.bullet
def test_the_bullet_back_end_as_the_program(program, tmp_path):
    assert "bullet" in pgm.backends()
    ours = pgm.simulate("1-stack", 40, seed=3, backend="bullet")
    theirs = cli_simulate(program, tmp_path, "--task", "1-stack", "--rows", "40", "--seed", "3", "--backend", "bullet")
    assert_same_data(ours, theirs)
