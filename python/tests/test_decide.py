"""pgm.query, pgm.predict and pgm.prevent: exact inference and the decisions of `pgm predict` and
`pgm prevent`, compared with known answers and with the program."""

import json
import re

import numpy as np
import pandas as pd
import pytest
from conftest import stacking_frame

import pgm

EDGES = [-3.0, -1.4, -0.4, 0.4, 1.4, 3.0]
OFFSETS = ["xOff1", "yOff1", "xOff2", "yOff2"]


@pytest.fixture
def two_stack(tmp_path):
    """A 2-Stack network on binned offsets (intervals in cm), fitted and written as JSON."""
    frame = stacking_frame(20000, 3)
    net = pgm.fit(frame, [(o, "onTop2") for o in OFFSETS], intervals={o: EDGES for o in OFFSETS})
    net.write(tmp_path / "two.json")
    return net, tmp_path / "two.json"


@pytest.fixture
def chain():
    # P(A=1) = 0.7; P(B=1 | A=0) = 1/3, P(B=1 | A=1) = 6/7.
    frame = pd.DataFrame({"A": [0] * 3 + [1] * 7, "B": [1, 0, 0] + [1] * 6 + [0]})
    return pgm.fit(frame, "A->B")


def test_query_one_variable_by_bayes_rule(chain):
    posterior = pgm.query(chain, "A", {"B": 1})
    assert list(posterior.index) == ["0", "1"]
    assert posterior.index.name == "A"
    assert posterior["0"] == pytest.approx(0.1 / 0.7, rel=1e-15)
    assert posterior.sum() == pytest.approx(1.0)


def test_query_several_variables_is_a_joint_last_fastest(chain):
    joint = pgm.query(chain, ["A", "B"])
    assert list(joint.index.names) == ["A", "B"]
    assert list(joint.index) == [("0", "0"), ("0", "1"), ("1", "0"), ("1", "1")]
    assert np.allclose(joint.to_numpy(), [0.2, 0.1, 0.1, 0.6])


def test_query_errors(chain):
    with pytest.raises(pgm.Error, match="'C'"):
        pgm.query(chain, "C")
    with pytest.raises(pgm.Error, match="both queried and observed"):
        pgm.query(chain, "A", {"A": 0})
    frame = pd.DataFrame({"A": [0, 0, 1, 1], "B": [0, 0, 1, 1], "C": [0, 1, 0, 1]})
    with pytest.raises(pgm.Error, match="the evidence A=0, B=1 has probability 0"):
        pgm.query(pgm.fit(frame, "A->B,A->C"), "C", {"A": 0, "B": 1})


def printed_probability(text, label):
    return float(re.search(label + r": ([0-9.e-]+)", text).group(1))


@pytest.mark.parametrize(
    "assign, text",
    [
        ({"xOff1": 0.1, "yOff1": -0.2, "xOff2": 0.3, "yOff2": 0.0}, "xOff1=0.1,yOff1=-0.2,xOff2=0.3,yOff2=0"),
        ({"xOff1": "@2", "yOff1": "@2", "xOff2": 2.5, "yOff2": -2}, "xOff1=@2,yOff1=@2,xOff2=2.5,yOff2=-2"),
        ("xOff1=-1,yOff1=1,xOff2=2,yOff2=2", "xOff1=-1,yOff1=1,xOff2=2,yOff2=2"),
    ],
)
def test_predict_equals_the_program(program, two_stack, assign, text):
    net, path = two_stack
    p = pgm.predict(net, assign)
    out = program.run("predict", "--model", path, "--assign", text).stdout
    assert p == pytest.approx(printed_probability(out, "predicted success probability"), rel=1e-5)
    assert p == net.cpt("onTop2").set_index(OFFSETS).loc[tuple(str(s) for s in bins_of(net, text)), "1"]


def bins_of(net, text):
    """The bins an assignment text selects, by the interval edges."""
    values = dict(piece.split("=") for piece in text.split(","))
    return [
        int(values[o][1:]) if values[o].startswith("@") else int(np.searchsorted(EDGES, float(values[o]), "right") - 1)
        for o in OFFSETS
    ]


def test_prevent_equals_the_program(program, two_stack):
    net, path = two_stack
    assign = {"xOff1": 0.1, "yOff1": -0.2, "xOff2": 2.5, "yOff2": -2.0}
    result = pgm.prevent(net, assign, controllable=["xOff2", "yOff2"])
    out = program.run(
        "prevent", "--model", path, "--assign", "xOff1=0.1,yOff1=-0.2,xOff2=2.5,yOff2=-2", "--controllable", "xOff2,yOff2"
    ).stdout
    assert result["success"] == "onTop2=1"
    assert result["failure_predicted"]
    assert result["predicted"] == pytest.approx(printed_probability(out, "predicted success probability"), rel=1e-5)
    assert result["predicted_after"] == pytest.approx(
        printed_probability(out, "predicted success after prevention"), rel=1e-5
    )
    assert result["predicted_after"] > 0.8
    for name in ("xOff2", "yOff2"):
        printed = float(re.search(rf"  {name} = ([-0-9.e]+) ", out).group(1))
        assert result["suggestion"][name] == pytest.approx(printed, rel=1e-5)
    assert result["responsible"] and set(result["responsible"]) <= {"xOff2", "yOff2"}
    assert result["steps"] >= len(result["responsible"])


def test_prevent_keeps_a_plan_predicted_to_succeed(two_stack):
    net, _ = two_stack
    assign = {"xOff1": 0.0, "yOff1": 0.0, "xOff2": 0.0, "yOff2": 0.0}
    result = pgm.prevent(net, assign)
    assert not result["failure_predicted"]
    assert result["predicted_after"] == result["predicted"]
    assert result["suggestion"] == assign
    assert result["responsible"] == []


def test_prevent_defaults_to_every_parent_and_moves_labels():
    frame = pd.DataFrame({"grip": ["soft", "hard"] * 10, "ok": [0, 1] * 10})
    net = pgm.fit(frame, "grip->ok")
    result = pgm.prevent(net, {"grip": "soft"})
    assert result["suggestion"] == {"grip": "hard"}
    assert result["responsible"] == ["grip"]
    assert result["predicted_after"] == 1.0
    assert pgm.prevent(net, "grip=soft", controllable="grip", epsilon=0.5)["suggestion"] == {"grip": "hard"}


def test_decision_errors(two_stack):
    net, _ = two_stack
    with pytest.raises(pgm.Error, match="no value is given for the controllable variable 'xOff2'"):
        pgm.prevent(net, {"xOff1": 0.0, "yOff1": 0.0, "yOff2": 0.0}, controllable=["xOff2"])
    with pytest.raises(pgm.Error, match="xOff2"):
        pgm.predict(net, {"xOff1": 0.0, "yOff1": 0.0, "yOff2": 0.0})
    assert 0 <= pgm.predict(net, {"xOff1": 0.0, "yOff1": 0.0, "yOff2": 0.0}, marginalize=True) <= 1
    with pytest.raises(pgm.Error, match="not of the form variable=state"):
        pgm.predict(net, {"xOff1": 0.0}, success="onTop2")
    with pytest.raises(pgm.Error, match="epsilon"):
        pgm.prevent(net, {"xOff1": 0.0, "yOff1": 0.0, "xOff2": 0.0, "yOff2": 0.0}, epsilon=2)
    with pytest.raises(TypeError, match="assign must be a dict"):
        pgm.predict(net, 3)


def test_prevent_with_a_reward_equals_the_program_and_weighs_costs(program, two_stack):
    net, path = two_stack
    assign = {"xOff1": 0.1, "yOff1": -0.2, "xOff2": 2.5, "yOff2": -2.0}
    costs = {"xOff2": 5.0, "yOff2": 5.0}
    result = pgm.prevent(net, assign, controllable=["xOff2", "yOff2"], reward=100, move_cost=costs)
    out = program.run(
        "prevent", "--model", path, "--assign", "xOff1=0.1,yOff1=-0.2,xOff2=2.5,yOff2=-2", "--controllable",
        "xOff2,yOff2", "--reward", "100", "--move-cost", "xOff2=5,yOff2=5", "--format", "json",
    ).stdout
    printed = json.loads(out)
    assert result["expected_utility"] == printed["expected_utility"]
    assert result["cost"] == printed["cost"]
    assert result["predicted_after"] == printed["success_probability"]
    assert sorted(result["responsible"]) == sorted(printed["moves"])
    assert result["expected_utility"] == pytest.approx(100 * result["predicted_after"] - result["cost"])
    # Costs above the whole reward: nothing is worth moving.
    stay = pgm.prevent(net, assign, controllable=["xOff2", "yOff2"], reward=100, move_cost={"xOff2": 1e3, "yOff2": 1e3})
    assert stay["responsible"] == [] and stay["cost"] == 0
    assert stay["expected_utility"] == pytest.approx(100 * stay["predicted"])
    with pytest.raises(pgm.Error, match="not a controllable parent"):
        pgm.prevent(net, assign, controllable=["xOff2"], reward=100, move_cost={"yOff2": 1})
    with pytest.raises(pgm.Error, match=r"unknown cost unit 'unit'; did you mean 'units'\?"):
        pgm.prevent(net, assign, per="unit")
