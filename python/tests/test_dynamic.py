"""pgm.DynamicNetwork: read from pgm's JSON of "kind": "dynamic" (docs/dynamic.md's example),
unrolled into a Network whose slices follow the transition, written back the same."""

import re

import pytest
from conftest import SOURCE_DIR

import pgm

PAGE = SOURCE_DIR / "docs" / "dynamic.md"


def example(tmp_path):
    text = re.search(r"```json\n(.*?)```", PAGE.read_text(), re.S).group(1)
    path = tmp_path / "tower.json"
    path.write_text(text)
    return path


def test_read_network_returns_a_dynamic_network_that_unrolls(tmp_path):
    model = pgm.read_network(example(tmp_path))
    assert isinstance(model, pgm.DynamicNetwork)
    assert model.variables == ["a", "b"]
    assert model.states("a") == ["off", "on"]
    assert ("a@-1", "a") in model.transition_edges
    assert model.initial.variables == ["a", "b"]
    unrolled = model.unroll(3)
    assert unrolled.variables == ["a@0", "b@0", "a@1", "b@1", "a@2", "b@2"]
    # P(a@t = on) by hand: p ← 0.1 (1 − p) + 0.8 p from p = 0.7.
    p = 0.7
    engine = pgm.InferenceEngine(unrolled, "jt")
    for t in range(3):
        assert engine.marginal(f"a@{t}")["on"] == pytest.approx(p, abs=1e-15)
        p = 0.1 * (1 - p) + 0.8 * p
    model.write(tmp_path / "again.json")
    again = pgm.read_network(tmp_path / "again.json")
    assert again.unroll(2).variables == unrolled.variables[:4]


def test_bad_input_is_an_error_naming_it(tmp_path):
    model = pgm.read_network(example(tmp_path))
    with pytest.raises(pgm.Error, match="steps"):
        model.unroll(0)
    text = example(tmp_path).read_text().replace('"a@-1", "a"', '"a@+1", "a"', 1)
    (tmp_path / "later.json").write_text(text)
    with pytest.raises(pgm.Error, match=r"/transition/edges/0: the parent 'a@\+1' of 'a' lies in a later slice"):
        pgm.read_network(tmp_path / "later.json")
