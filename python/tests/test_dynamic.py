"""pgm.DynamicNetwork: read from pgm's JSON of "kind": "dynamic" (docs/dynamic.md's example),
unrolled into a Network whose slices follow the transition, written back the same."""

import math
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


def test_filter_and_smooth_equal_the_unrolled_networks_engine(tmp_path):
    import pandas as pd

    model = pgm.read_network(example(tmp_path))
    data = pd.DataFrame({"episode": ["e"] * 4, "t": [0, 1, 2, 3], "a": [None, "on", None, None],
                         "b": ["high", None, None, "low"]})
    observed = [(t, v, s) for t, row in data.iterrows() for v, s in (("a", row["a"]), ("b", row["b"])) if s]
    unrolled = model.unroll(6)
    engine = pgm.InferenceEngine(unrolled, "jt")
    filtered = model.filter(data, predict=2)
    smoothed = model.smooth(data)
    assert filtered.attrs["log_evidence_probability"] == pytest.approx(smoothed.attrs["log_evidence_probability"])
    for answer, smooth in ((filtered, False), (smoothed, True)):
        assert list(answer.columns) == ["t", "variable", "state", "probability"]
        assert not any((t, v) == (o[0], o[1]) for o in observed for t, v in zip(answer["t"], answer["variable"]))
        for t, variable, state, p in answer.itertuples(index=False):
            known = {f"{v}@{u}": s for u, v, s in observed if smooth or u <= t}
            engine.set_evidence(known)
            assert p == pytest.approx(engine.marginal(f"{variable}@{t}")[state], abs=1e-12)
    assert sorted(set(filtered["t"])) == [0, 1, 2, 3, 4, 5]
    engine.set_evidence({f"{v}@{u}": s for u, v, s in observed})
    assert filtered.attrs["log_evidence_probability"] == pytest.approx(engine.log_probability_of_evidence(), abs=1e-12)
    # do() at a step: that variable leaves the answer there, its table left out.
    moved = model.filter(data, predict=2, do={"a@4": "off"})
    assert not ((moved["t"] == 4) & (moved["variable"] == "a")).any()
    assert moved[(moved["t"] == 5) & (moved["variable"] == "a") & (moved["state"] == "off")]["probability"].item() == (
        pytest.approx(0.9)
    )


def test_filter_refuses_what_it_cannot_read(tmp_path):
    import pandas as pd

    model = pgm.read_network(example(tmp_path))
    with pytest.raises(TypeError, match="DataFrame"):
        model.filter([{"a": "on"}])
    with pytest.raises(pgm.Error, match="column 'c' is neither episode, t nor a variable of the model"):
        model.filter(pd.DataFrame({"c": ["on"]}))
    with pytest.raises(pgm.Error, match="one episode at a time"):
        model.filter(pd.DataFrame({"episode": ["x", "y"], "a": ["on", "off"]}))
    with pytest.raises(pgm.Error, match="row 1 has t = 2"):
        model.filter(pd.DataFrame({"t": [0, 2], "a": ["on", "off"]}))
    with pytest.raises(pgm.Error, match="no state 'maybe'"):
        model.filter(pd.DataFrame({"a": ["maybe"]}))
    with pytest.raises(pgm.Error, match="the step must be from 0 to 0"):
        model.filter(pd.DataFrame({"a": ["on"]}), do={"a@3": "on"})


def test_the_most_probable_sequence_is_the_unrolled_networks_most_probable_explanation(tmp_path):
    import pandas as pd

    model = pgm.read_network(example(tmp_path))
    data = pd.DataFrame({"a": [None, "on", None, None, None], "b": ["high", None, None, "low", None]})
    best = model.most_probable_sequence(data)
    engine = pgm.InferenceEngine(model.unroll(5), "jt")
    engine.set_evidence({"b@0": "high", "a@1": "on", "b@3": "low"})
    states, probability = engine.mpe()
    assert {f"{v}@{t}": s for t, v, s in best.itertuples(index=False)} == states
    # ln P(x*, e) = ln P(x* | e) + ln P(e)
    expected = math.log(probability) + engine.log_probability_of_evidence()
    assert best.attrs["log_probability"] == pytest.approx(expected, abs=1e-12)
