"""Shared by the pytest suite of the pgm package: the built `pgm` program and test data.

ctest runs each file with PYTHONPATH=build/python, PGM_PROGRAM (the program) and
PGM_SOURCE_DIR set (python/tests/CMakeLists.txt).
"""

import os
import subprocess
from pathlib import Path

import numpy as np
import pandas as pd
import pytest


def pytest_configure(config):
    config.addinivalue_line("markers", "bullet: needs the Bullet simulator back-end")
    # scripts/test-python-package runs the suite against the package pip installed in a venv.
    venv = os.environ.get("PGM_EXPECT_INSTALLED")
    if venv:
        import pgm

        if not Path(pgm.__file__).resolve().is_relative_to(Path(venv).resolve()):
            raise pytest.UsageError(f"pgm was imported from {pgm.__file__}, not from the venv {venv}")


SOURCE_DIR = Path(os.environ.get("PGM_SOURCE_DIR", Path(__file__).resolve().parents[2]))


class Program:
    """The `pgm` program, run as a user would."""

    def __init__(self, path):
        self.path = path

    def run(self, *arguments, check=True):
        result = subprocess.run([self.path, *map(str, arguments)], capture_output=True, text=True)
        if check and result.returncode != 0:
            raise AssertionError(f"pgm {' '.join(map(str, arguments))} failed:\n{result.stderr}")
        return result


@pytest.fixture(scope="session")
def program():
    path = os.environ.get("PGM_PROGRAM")
    if not path:
        pytest.fail("PGM_PROGRAM must name the built pgm program (ctest sets it)")
    return Program(path)


def stacking_frame(rows, seed):
    """2-Stack-like discrete data: four 5-state offsets, a colour and two outcomes that depend
    on the offsets, with integer, string and categorical columns."""
    random = np.random.default_rng(seed)
    offsets = {name: random.integers(0, 5, rows) for name in ("xOff1", "yOff1", "xOff2", "yOff2")}
    far1 = np.abs(offsets["xOff1"] - 2) + np.abs(offsets["yOff1"] - 2)
    far2 = far1 + np.abs(offsets["xOff2"] - 2) + np.abs(offsets["yOff2"] - 2)
    on_top1 = (random.random(rows) < 0.95 - 0.2 * far1).astype(np.int64)
    on_top2 = ((random.random(rows) < 0.95 - 0.1 * far2) & (on_top1 == 1)).astype(np.int64)
    colours = np.array(["Red", "Blue", "Green", "Orange"])[random.integers(0, 4, rows)]
    return pd.DataFrame(
        {
            **offsets,
            "colour": colours,
            "colourCat": pd.Categorical(colours, categories=["Orange", "Red", "Green", "Blue", "Violet"]),
            "onTop1": on_top1,
            "onTop2": on_top2,
        }
    )


@pytest.fixture
def stacking():
    return stacking_frame(2000, 7)


def assert_same_network(ours, theirs):
    """Same variables, states, parents and every probability to the last bit."""
    assert ours.variables == theirs.variables
    for name in ours.variables:
        assert ours.states(name) == theirs.states(name), name
        assert ours.parents(name) == theirs.parents(name), name
        a = ours.cpt(name)
        b = theirs.cpt(name)
        assert list(a.columns) == list(b.columns), name
        for state in ours.states(name):
            assert np.array_equal(a[state].to_numpy(), b[state].to_numpy()), (name, state)


def releases_the_gil(monkeypatch, core_function, call):
    """Whether `call()` lets another Python thread run while pgm._core.`core_function` works.

    Deterministic, not timed: with a switch interval of an hour no thread is made to give up
    the GIL, so this thread, woken while the call is under way, runs before the call returns
    only if the call released the GIL itself. The call must outlast the few milliseconds the
    system takes to wake this thread; give it enough rows. Returns (released, the call's result).
    """
    import sys
    import threading

    import pgm

    original = getattr(pgm._core, core_function)
    entered = threading.Event()
    state = {"done": False}

    def entering(*arguments, **keywords):
        entered.set()
        return original(*arguments, **keywords)

    def work():
        state["result"] = call()
        state["done"] = True

    monkeypatch.setattr(pgm._core, core_function, entering)
    interval = sys.getswitchinterval()
    sys.setswitchinterval(3600)
    try:
        worker = threading.Thread(target=work)
        worker.start()
        entered.wait()
        released = not state["done"]
        worker.join()
    finally:
        sys.setswitchinterval(interval)
    assert "result" in state, "the call failed"
    return released, state["result"]


def python_blocks(document):
    """The ```python blocks of a Markdown file of the repository, in order."""
    import re

    text = (SOURCE_DIR / document).read_text(encoding="utf-8")
    return re.findall(r"^```python\n(.*?)^```$", text, flags=re.DOTALL | re.MULTILINE)
