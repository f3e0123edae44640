"""The long calls (fit, learn_structure, simulate, discretize) release the GIL, so that other Python
threads run meanwhile (pgm.experiment: test_experiment.py). Each call is given work for a
tenth of a second or more, so that the woken thread is waiting for the GIL before it is back."""

from conftest import releases_the_gil, stacking_frame

import pgm

EDGES = "xOff1->onTop1,yOff1->onTop1,onTop1->onTop2,xOff2->onTop2,yOff2->onTop2"


def test_fit(monkeypatch):
    frame = stacking_frame(1_000_000, 1)
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
