"""pgm.query(do=), pgm.intervene, pgm.d_separated, pgm.backdoor_sets and pgm.check: the
interventional answer against the truncated factorisation by hand, the mutilated network, and
the program's answers on the same model and data."""

import os
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import pgm

NETWORKS = Path(os.environ.get("PGM_SOURCE_DIR", Path(__file__).resolve().parents[2])) / "tests" / "data" / "networks"


@pytest.fixture
def confounded():
    # C -> X, C -> Y, X -> Y, fitted from counts that give these tables exactly.
    rows = []
    for c, pc in ((0, 3), (1, 7)):
        for x, px in ((0, (8, 1)[c]), (1, (2, 9)[c])):
            py1 = {(0, 0): 1, (0, 1): 4, (1, 0): 5, (1, 1): 8}[(c, x)]
            for y, count in ((0, 10 - py1), (1, py1)):
                rows += [(c, x, y)] * (pc * px * count)
    frame = pd.DataFrame(rows, columns=["C", "X", "Y"])
    return pgm.fit(frame, "C->X,C->Y,X->Y")


def test_intervening_differs_from_conditioning(confounded):
    # P(Y=1 | do(X=1)) = Σ_c P(c) P(Y=1 | c, X=1) = 0.3·0.4 + 0.7·0.8 = 0.68.
    done = pgm.query(confounded, "Y", do={"X": 1})
    assert done["1"] == pytest.approx(0.68, rel=1e-12)
    seen = pgm.query(confounded, "Y", {"X": 1})
    assert abs(seen["1"] - 0.68) > 0.05
    mutilated = pgm.intervene(confounded, {"X": 1})
    assert mutilated.parents("X") == []
    assert pgm.query(mutilated, "Y", {"X": 1})["1"] == pytest.approx(0.68, rel=1e-12)
    engine = pgm.InferenceEngine(confounded, "jt")
    engine.set_interventions({"X": 1})
    assert engine.marginal("Y")["1"] == pytest.approx(0.68, rel=1e-12)
    engine.set_interventions(None)
    assert engine.marginal("Y")["1"] == pytest.approx(pgm.query(confounded, "Y")["1"], rel=1e-12)
    with pytest.raises(pgm.Error, match="both intervened on and observed"):
        pgm.query(confounded, "Y", {"X": 1}, do={"X": 0})
    with pytest.raises(pgm.Error, match="'X' is intervened on"):
        pgm.query(confounded, "X", do={"X": 0})


def test_backdoor_sets_and_d_separation(confounded):
    sets, complete = pgm.backdoor_sets(confounded, "X", "Y")
    assert complete and sets == [["C"]]
    assert not pgm.d_separated(confounded, "X", "Y", "C")
    assert pgm.d_separated(pgm.intervene(confounded, {"X": 0}), "X", "C")
    with pytest.raises(TypeError, match="network must be a pgm.Network"):
        pgm.d_separated("net.bif", "X", "Y")


def test_check_agrees_with_the_program(tmp_path, program):
    asia = pgm.read_network(NETWORKS / "asia.bif")
    rng = np.random.default_rng(1)
    # Data from a different model: smoke and bronc made independent, the rest as asia.
    frame = pd.DataFrame({v: rng.choice(asia.states(v), 3000) for v in asia.variables})
    frame.to_csv(tmp_path / "data.csv", index=False)
    table = pgm.check(asia, frame, alpha=0.01)
    assert list(table.columns) == ["x", "y", "given", "statistic", "df", "p_value", "rejected"]
    assert (table["p_value"].diff().dropna() >= 0).all()
    printed = program.run("check", "--model", NETWORKS / "asia.bif", "--data", tmp_path / "data.csv", "--alpha", "0.01",
                          "--format", "csv", "--all")
    lines = printed.stdout.strip().split("\n")[1:]
    assert len(lines) == len(table)
    first = lines[0].split(",")
    assert (first[0], first[1]) == (table["x"][0], table["y"][0])
    assert float(first[5]) == table["p_value"][0]


def test_d_separation_given_nothing_is_marginal_independence(confounded, tmp_path, program):
    # Issue 49: given=[] was refused ("given is empty"); it asks whether x and y are independent,
    # as `pgm dsep` without --given answers.
    cut = pgm.intervene(confounded, {"X": 0})
    cut.write(tmp_path / "cut.json")
    for x, y, separated in (("X", "C", True), ("C", "Y", False)):
        printed = program.run("dsep", "--model", tmp_path / "cut.json", x, y).stdout.strip()
        assert printed == f"{{{x}}} and {{{y}}} are {'d-separated' if separated else 'd-connected'} given {{}}"
        assert pgm.d_separated(cut, x, y, []) is separated
        assert pgm.d_separated(cut, x, y, ()) is separated


def test_a_variable_in_two_arguments_is_named_with_both(confounded):
    # Issue 49: named with the arguments it is in (the library names it with the sets: pgm dsep).
    with pytest.raises(pgm.Error, match=r"^'X' is both the treatment \(x\) and the outcome \(y\)$"):
        pgm.backdoor_sets(confounded, "X", "X")
    with pytest.raises(pgm.Error, match=r"^'C' is both the treatment \(x\) and the outcome \(y\)$"):
        pgm.backdoor_sets(confounded, ["X", "C"], ["Y", "C"])
    with pytest.raises(pgm.Error, match="^'X' is in both x and y: d-separation needs disjoint sets$"):
        pgm.d_separated(confounded, "X", "X")
    with pytest.raises(pgm.Error, match="^'C' is in both x and given: d-separation needs disjoint sets$"):
        pgm.d_separated(confounded, ["X", "C"], "Y", "C")
    with pytest.raises(pgm.Error, match="^'C' is in both y and given: d-separation needs disjoint sets$"):
        pgm.d_separated(confounded, "X", ["Y", "C"], ["C"])


def test_check_refuses_an_unknown_test_in_the_librarys_words(confounded):
    # Issue 49: check's test had no "did you mean"; its message is now learn_structure's (the
    # library's pgm::unknown_name), word for word, suggestion included, after the option of the
    # learner it was given to.
    frame = pd.DataFrame({"C": [0, 1, 1, 0], "X": [1, 0, 1, 1], "Y": [0, 0, 1, 1]})
    with pytest.raises(pgm.Error, match=r"^unknown independence test 'chi'; did you mean 'chi2'\? \(known: chi2, g2\)$"):
        pgm.check(confounded, frame, test="chi")
    for word in ("chi", "ch2", "hci2", "chi22", "g", "G2", "g3", "x2", "pearson"):
        with pytest.raises(pgm.Error) as by_library:
            pgm.learn_structure(frame, test=word)
        with pytest.raises(pgm.Error) as ours:
            pgm.check(confounded, frame, test=word)
        assert str(by_library.value) == "test: option test of the structure learner 'pc': " + str(ours.value), word


TOWER = """{"format": "pgm-model", "version": 1, "kind": "structural",
  "variables": [{"name": "xOff1", "states": ["0", "1", "2"]}, {"name": "onTop1", "states": ["0", "1"]}],
  "equations": [
    {"variable": "xOff1", "parents": [], "noise": [0.25, 0.25, 0.5], "values": [["0", "1", "2"]]},
    {"variable": "onTop1", "parents": ["xOff1"], "noise": [0.5, 0.3, 0.2],
     "values": [["1", "1", "0"], ["1", "1", "0"], ["1", "0", "0"]]}]}"""


def test_a_counterfactual_on_a_structural_model_is_the_programs(tmp_path):
    # docs/causal.md's tower: it fell at offset 2, so its noise was 1 or 2 (0.3 : 0.2), and at
    # offset 0 noise 1 stands.
    path = tmp_path / "tower.json"
    path.write_text(TOWER)
    answer = pgm.counterfactual(path, "onTop1", {"xOff1": 2, "onTop1": 0}, do={"xOff1": 0})
    assert list(answer.index) == ["0", "1"]
    assert answer["1"] == pytest.approx(0.6, abs=1e-15)
    assert answer.attrs["evidence_probability"] == pytest.approx(0.25, abs=1e-15)
    both = pgm.counterfactual(str(path), ["onTop1", "xOff1"], {"xOff1": 2, "onTop1": 0}, do={"xOff1": 0})
    assert both[("1", "0")] == pytest.approx(0.6, abs=1e-15)
    assert both[("1", "2")] == 0.0
    with pytest.raises(pgm.Error, match="needs no assume"):
        pgm.counterfactual(path, "onTop1", do={"xOff1": 0}, assume="monotone")


def test_a_network_answers_a_counterfactual_only_as_monotone(confounded, tmp_path):
    with pytest.raises(pgm.Error, match="does not determine counterfactuals"):
        pgm.counterfactual(confounded, "Y", {"X": 1, "Y": 0}, do={"X": 0})
    with pytest.raises(pgm.Error, match="unknown assumption 'monotonic'; did you mean 'monotone'"):
        pgm.counterfactual(confounded, "Y", {"X": 1, "Y": 0}, do={"X": 0}, assume="monotonic")
    with pytest.raises(pgm.Error, match="do: name what had been set"):
        pgm.counterfactual(confounded, "Y", {"X": 1, "Y": 0}, do={}, assume="monotone")
    # Given C, Y = 1 iff its noise ≥ P(Y = 0 | C, X): a unit with Y = 1 at X = 0 keeps it at X = 1,
    # where Y = 1 is likelier, so P(Y_{X=1} = 1 | C = 0, X = 0, Y = 1) = 1; one with Y = 0 at
    # X = 0 (noise < 0.9) has Y = 1 at X = 1 when its noise ≥ 0.6: (0.9 − 0.6) / 0.9.
    up = pgm.counterfactual(confounded, "Y", {"C": 0, "X": 0, "Y": 1}, do={"X": 1}, assume="monotone")
    assert up["1"] == pytest.approx(1.0, abs=1e-12)
    down = pgm.counterfactual(confounded, "Y", {"C": 0, "X": 0, "Y": 0}, do={"X": 1}, assume="monotone")
    assert down["1"] == pytest.approx(0.3 / 0.9, abs=1e-12)
    path = tmp_path / "confounded.bif"
    confounded.write(path)
    from_file = pgm.counterfactual(path, "Y", {"C": 0, "X": 0, "Y": 0}, do={"X": 1}, assume="monotone")
    assert from_file["1"] == pytest.approx(0.3 / 0.9, abs=1e-12)
