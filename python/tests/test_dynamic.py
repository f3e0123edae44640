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


TOWER_EDGES = "xOff->onTop, yOff->onTop, onTop@-1->onTop, xOff@-1->onTop"


def tower_episodes(program, tmp_path, name, rows, seed):
    """The 3-stack tower's episodes in long form, offsets in 5 bins of the first call's edges."""
    raw, binned, edges = tmp_path / f"{name}-raw.csv", tmp_path / f"{name}.csv", tmp_path / "edges.json"
    program.run("simulate", "--task", "3-stack", "--rows", rows, "--seed", seed, "--long-form", "--out", raw)
    if edges.exists():
        program.run("discretize", "--in", raw, "--method", "edges", "--edges-in", edges, "--out", binned)
    else:
        program.run("discretize", "--in", raw, "--columns", "xOff,yOff", "--bins", 5, "--out", binned, "--edges-out",
                    edges)
    return binned


def test_fit_dynamic_and_update_write_what_the_program_writes(program, tmp_path):
    import pandas as pd

    monday = tower_episodes(program, tmp_path, "monday", 300, 1)
    tuesday = tower_episodes(program, tmp_path, "tuesday", 200, 2)
    program.run("simulate", "--task", "1-stack", "--rows", 2000, "--seed", 3, "--out", tmp_path / "one-raw.csv")
    program.run("discretize", "--in", tmp_path / "one-raw.csv", "--columns", "xOff1,yOff1", "--bins", 5, "--out",
                tmp_path / "one.csv")
    program.run("fit", "--data", tmp_path / "one.csv", "--edges", "xOff1->onTop1, yOff1->onTop1", "--out",
                tmp_path / "one.json")
    transfer = ["--estimator", "bayes", "--prior", "bdeu[ess=2]", "--prior-model", tmp_path / "one.json", "--strategy",
                "minimal", "--w-prior", 5, "--map", "onTop=onTop1, xOff~xOff1, yOff~yOff1, xOff@-1==xOff1, yOff1@0",
                "--initial-map", "onTop=onTop1, xOff==xOff1, yOff==yOff1", "--initial-strategy", "direct"]
    program.run("fit", "--dynamic", "--data", monday, "--edges", TOWER_EDGES, *transfer, "--keep-counts", "--out",
                tmp_path / "cli.json")
    program.run("update", "--model", tmp_path / "cli.json", "--data", tuesday, "--decay", 0.5, "--out",
                tmp_path / "cli-updated.json")

    model = pgm.fit_dynamic(
        pd.read_csv(monday), TOWER_EDGES, "bayes", "bdeu[ess=2]", prior_model=pgm.read_network(tmp_path / "one.json"),
        strategy="minimal", w_prior=5, map="onTop=onTop1, xOff~xOff1, yOff~yOff1, xOff@-1==xOff1, yOff1@0",
        initial_map="onTop=onTop1, xOff==xOff1, yOff==yOff1", initial_strategy="direct", keep_counts=True)
    assert model.has_counts
    assert any("'onTop' gets the minimal prior from 'onTop1' with w = 5" in note for note in model.notes)
    model.write(tmp_path / "python.json")
    assert (tmp_path / "python.json").read_text() == (tmp_path / "cli.json").read_text()
    updated = model.update(pd.read_csv(tuesday), decay=0.5)
    updated.write(tmp_path / "python-updated.json")
    assert (tmp_path / "python-updated.json").read_text() == (tmp_path / "cli-updated.json").read_text()
    # Read back, the counts come along: the update of the file equals the update in memory.
    again = pgm.read_network(tmp_path / "python.json").update(pd.read_csv(tuesday), decay=0.5)
    again.write(tmp_path / "again.json")
    assert (tmp_path / "again.json").read_text() == (tmp_path / "cli-updated.json").read_text()
    # A model's structure and states, refitted without a prior, as pgm fit --dynamic --model.
    program.run("fit", "--dynamic", "--data", monday, "--model", tmp_path / "cli.json", "--out", tmp_path / "mle.json")
    pgm.fit_dynamic(pd.read_csv(monday), model=model).write(tmp_path / "python-mle.json")
    assert (tmp_path / "python-mle.json").read_text() == (tmp_path / "mle.json").read_text()


def test_fit_dynamic_by_em_writes_what_the_program_writes(program, tmp_path):
    import numpy as np
    import pandas as pd

    data = pd.read_csv(tower_episodes(program, tmp_path, "gaps", 150, 5))
    holes = np.random.default_rng(5).random(len(data)) < 0.2
    data["onTop"] = data["onTop"].astype("Int64").mask(holes)
    data.to_csv(tmp_path / "gaps.csv", index=False, na_rep="")
    program.run("fit", "--dynamic", "--missing", "em", "--data", tmp_path / "gaps.csv", "--edges", TOWER_EDGES,
                "--estimator", "bayes", "--prior", "bdeu[ess=2]", "--out", tmp_path / "cli.json")
    model = pgm.fit_dynamic(data, TOWER_EDGES, "bayes", "bdeu[ess=2]", missing="em")
    assert any(note.startswith("EM: ") and "(converged)" in note for note in model.notes)
    model.write(tmp_path / "python.json")
    assert (tmp_path / "python.json").read_text() == (tmp_path / "cli.json").read_text()

    # A hidden Markov model: the state in no column, its two states named.
    hidden = pgm.fit_dynamic(data[["episode", "t", "onTop"]].fillna(0), "H->onTop, H@-1->H",
                             missing="em", latent={"H": ["low", "high"]}, restarts=2, seed=3)
    assert [v for v in hidden.variables] == ["onTop", "H"]
    with pytest.raises(pgm.Error, match='keep_counts does not apply with missing="em"'):
        pgm.fit_dynamic(data, TOWER_EDGES, missing="em", keep_counts=True)
    with pytest.raises(pgm.Error, match='latent applies with missing="em"'):
        pgm.fit_dynamic(data, TOWER_EDGES, latent={"H": 2})
    with pytest.raises(pgm.Error, match="the latent variable 'Z' is in no edge"):
        pgm.fit_dynamic(data, TOWER_EDGES, missing="em", latent={"Z": 2})


def test_fit_dynamic_refuses_what_it_cannot_do(program, tmp_path):
    import pandas as pd

    data = pd.read_csv(tower_episodes(program, tmp_path, "few", 20, 4))
    with pytest.raises(pgm.Error, match="give the structure as edges"):
        pgm.fit_dynamic(data)
    with pytest.raises(pgm.Error, match="'drop' would leave gaps in the episodes"):
        pgm.fit_dynamic(data, TOWER_EDGES, missing="drop")
    with pytest.raises(pgm.Error, match="apply with prior_model"):
        pgm.fit_dynamic(data, TOWER_EDGES, map="onTop=onTop1")
    with pytest.raises(pgm.Error, match="ends in another slice"):
        pgm.fit_dynamic(data, "xOff->onTop@-1")
    model = pgm.fit_dynamic(data, TOWER_EDGES)
    assert not model.has_counts
    with pytest.raises(pgm.Error, match="carries no counts to add the episodes to"):
        model.update(data)
    counted = pgm.fit_dynamic(data, TOWER_EDGES, keep_counts=True)
    with pytest.raises(pgm.Error, match="holds the value '7', which is not a state"):
        counted.update(data.assign(xOff=7))
    with pytest.raises(pgm.Error, match="has two rows with t = 0"):
        pgm.fit_dynamic(data.assign(t=0), TOWER_EDGES)


def test_a_simulated_tower_fits_from_python_alone():
    long = pgm.simulate("3-stack", 400, seed=6, long_form=True)
    assert list(long.columns[:3]) == ["episode", "t", "xOff"]
    assert len(long) == 1200 and list(long["t"][:4]) == [0, 1, 2, 0]
    wide = pgm.simulate("3-stack", 400, seed=6)
    assert (long["xOff"].to_numpy()[1::3] == wide["xOff2"].to_numpy()).all()
    binned, _ = pgm.discretize(long, bins=5, columns=["xOff", "yOff"])
    model = pgm.fit_dynamic(binned, TOWER_EDGES)
    # A tower that fell stays fallen: below a fallen one, the tied table has a cube stand only
    # where no episode reached that configuration (uniform), never from data.
    table = model.unroll(2).cpt("onTop@1")
    fallen = table[table["onTop@0"] == "0"]
    assert set(fallen["1"]) <= {0.0, 0.5} and (fallen["1"] == 0.0).sum() > 100
    with pytest.raises(pgm.Error, match="task 'drop-glass' has no numbered variables"):
        pgm.simulate("drop-glass", 10, long_form=True)
