"""The long calls (fit, learn_structure, simulate, discretize) release the GIL, so that other Python
threads run meanwhile (pgm.experiment: test_experiment.py). Each call is given work for a
tenth of a second or more, so that the woken thread is waiting for the GIL before it is back."""

import numpy as np
import pandas as pd
from conftest import releases_the_gil, stacking_frame

import pgm

EDGES = "xOff1->onTop1,yOff1->onTop1,onTop1->onTop2,xOff2->onTop2,yOff2->onTop2"
EDGE_NAMES = ["xOff1", "yOff1", "onTop1", "xOff2", "yOff2", "onTop2"]


def test_fit(monkeypatch):
    frame = stacking_frame(1_000_000, 1)
    edges = EDGES + ",colour->onTop2"  # a column of strings: the data set's way
    released, net = releases_the_gil(monkeypatch, "fit", lambda: pgm.fit(frame, edges, threads=1))
    assert released
    assert net.parents("onTop2") == ["onTop1", "xOff2", "yOff2", "colour"]


def test_fit_counting_integer_codes_in_place(monkeypatch):
    # Counted straight from the buffers, about 2 ns a row: 10^7 rows of byte codes.
    random = np.random.default_rng(3)
    frame = pd.DataFrame({name: random.integers(0, 5, 10_000_000, dtype=np.int8) for name in EDGE_NAMES})
    released, net = releases_the_gil(monkeypatch, "fit", lambda: pgm.fit(frame, EDGES, threads=1))
    assert released
    assert net.parents("onTop2") == ["onTop1", "xOff2", "yOff2"]


def test_learn_structure(monkeypatch):
    frame = stacking_frame(300_000, 2)[["xOff1", "yOff1", "xOff2", "yOff2", "onTop1", "onTop2"]]
    released, edges = releases_the_gil(monkeypatch, "learn_structure", lambda: pgm.learn_structure(frame, threads=1))
    assert released
    assert ("xOff1", "onTop1") in edges


def test_simulate(monkeypatch):
    released, frame = releases_the_gil(monkeypatch, "simulate", lambda: pgm.simulate("2-stack", 100_000, threads=1))
    assert released
    assert len(frame) == 100_000


def test_discretize(monkeypatch):
    frame = pgm.simulate("1-stack", 100_000, seed=3)
    released, (binned, edges) = releases_the_gil(monkeypatch, "discretize", lambda: pgm.discretize(frame, bins=5))
    assert released
    assert set(edges) <= set(frame.columns)
    assert len(binned) == 100_000
