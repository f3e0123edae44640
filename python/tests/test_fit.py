"""pgm.fit: every estimator and prior transfer of `pgm fit`, with tables equal to the program's to
the last bit on the same data."""

import inspect
import re

import numpy as np
import pandas as pd
import pytest
from conftest import assert_same_network, stacking_frame

import pgm

ONE_EDGES = "xOff1->onTop1,yOff1->onTop1"
TWO_EDGES = "xOff1->onTop2,yOff1->onTop2,xOff2->onTop2,yOff2->onTop2,colour->onTop2"
MAP = "onTop2=onTop1,xOff2~xOff1,yOff2~yOff1"


@pytest.fixture
def tasks(tmp_path, program):
    """A 1-Stack prior (fitted by the program) and 2-Stack target data, as frames and files."""
    one = stacking_frame(5000, 1)[["xOff1", "yOff1", "onTop1"]]
    two = stacking_frame(300, 2)
    one.to_csv(tmp_path / "one.csv", index=False)
    two.to_csv(tmp_path / "two.csv", index=False)
    program.run("fit", "--data", tmp_path / "one.csv", "--edges", ONE_EDGES, "--out", tmp_path / "one.json")
    return one, two, tmp_path


def cli_fit(program, tmp_path, *arguments):
    program.run("fit", "--data", tmp_path / "two.csv", "--out", tmp_path / "cli.json", *arguments)
    return pgm.read_network(tmp_path / "cli.json")


@pytest.mark.parametrize(
    "kwargs, arguments",
    [
        ({}, []),
        ({"estimator": "bayes"}, ["--estimator", "bayes"]),
        ({"estimator": "bayes", "prior": "k2"}, ["--estimator", "bayes", "--prior", "k2"]),
        ({"estimator": "bayes", "prior": "bdeu", "ess": 7.5}, ["--estimator", "bayes", "--prior", "bdeu", "--ess", "7.5"]),
        ({"estimator": "bayes", "prior": "dirichlet", "alpha": 0.3}, ["--estimator", "bayes", "--prior", "dirichlet", "--alpha", "0.3"]),
    ],
)
def test_estimators_equal_the_programs_to_the_last_bit(program, tasks, kwargs, arguments):
    _, two, tmp_path = tasks
    ours = pgm.fit(two, TWO_EDGES, **kwargs)
    assert_same_network(ours, cli_fit(program, tmp_path, "--edges", TWO_EDGES, *arguments))


@pytest.mark.parametrize(
    "kwargs, arguments",
    [
        ({"strategy": "minimal", "map": MAP, "w_prior": 2}, ["--strategy", "minimal", "--map", MAP, "--w-prior", "2"]),
        ({"strategy": "direct", "map": MAP}, ["--strategy", "direct", "--map", MAP]),
        ({"strategy": "cross", "map": MAP, "w_prior": 20.5}, ["--strategy", "cross", "--map", MAP, "--w-prior", "20.5"]),
        ({"map": "auto", "w_prior": "auto"}, ["--map", "auto", "--w-prior", "auto"]),
        (
            {"estimator": "bayes", "prior": "k2", "map": MAP, "w_prior": 3, "match": "overlap"},
            ["--estimator", "bayes", "--prior", "k2", "--map", MAP, "--w-prior", "3", "--match", "overlap"],
        ),
    ],
)
def test_transferred_priors_equal_the_programs_to_the_last_bit(program, tasks, kwargs, arguments):
    _, two, tmp_path = tasks
    prior = pgm.read_network(tmp_path / "one.json")
    ours = pgm.fit(two, TWO_EDGES, prior_model=prior, **kwargs)
    theirs = cli_fit(program, tmp_path, "--edges", TWO_EDGES, "--prior-model", tmp_path / "one.json", *arguments)
    assert_same_network(ours, theirs)


def test_a_prior_fitted_in_python_is_the_programs(program, tasks):
    one, _, tmp_path = tasks
    assert_same_network(pgm.fit(one, ONE_EDGES), pgm.read_network(tmp_path / "one.json"))


def test_notes_say_what_the_transfer_chose(tasks):
    one, two, _ = tasks
    prior = pgm.fit(one, ONE_EDGES)
    fixed = pgm.fit(two, TWO_EDGES, prior_model=prior, map=MAP, w_prior=2)
    assert fixed.notes == ["'onTop2' gets the minimal prior from 'onTop1' with w = 2"]
    chosen = pgm.fit(two, TWO_EDGES, prior_model=prior, map="auto", w_prior="auto")
    assert chosen.notes[0].startswith("map='auto': onTop2=onTop1")
    assert "maximizes the marginal likelihood of the 300 target rows" in chosen.notes[1]
    assert pgm.fit(two, TWO_EDGES).notes == []


def test_weighted_prior_by_hand():
    # eq. 8: theta = (w f + M[x,u]) / (w + M[u]); the prior says P(onTop1=1 | centred) = 0.9.
    one = pd.DataFrame({"xOff1": [1] * 10 + [0] * 10, "onTop1": [1] * 9 + [0] + [1] * 2 + [0] * 8})
    prior = pgm.fit(one, "xOff1->onTop1")
    two = pd.DataFrame({"xOff1": [1, 1, 0], "xOff2": [1, 1, 1], "onTop2": [1, 0, 0]})
    net = pgm.fit(two, "xOff1->onTop2,xOff2->onTop2", prior_model=prior, strategy="direct", map="onTop2=onTop1", w_prior=2)
    table = net.cpt("onTop2").set_index(["xOff1", "xOff2"])
    assert table.loc[("1", "1"), "1"] == (2 * 0.9 + 1) / (2 + 2)
    assert table.loc[("0", "1"), "1"] == (2 * 0.2 + 0) / (2 + 1)


def test_edges_as_pairs_or_text_and_intervals_kept(tasks):
    _, two, _ = tasks
    pairs = [("xOff1", "onTop2"), ("yOff1", "onTop2"), ("xOff2", "onTop2"), ("yOff2", "onTop2"), ("colour", "onTop2")]
    assert_same_network(pgm.fit(two, pairs), pgm.fit(two, TWO_EDGES))
    edges = {"xOff1": [-3, -1.4, -0.4, 0.4, 1.4, 3]}
    net = pgm.fit(two, TWO_EDGES, intervals=edges)
    assert net.interval_edges("xOff1") == edges["xOff1"]
    assert net.interval_edges("yOff1") is None


def test_intervals_from_an_edges_file_as_the_program_takes_them(program, tasks):
    _, two, tmp_path = tasks
    raw = pd.DataFrame({"x": np.linspace(-3, 3, 300), "y": np.linspace(0, 1, 300)})
    raw.to_csv(tmp_path / "raw.csv", index=False)
    program.run("discretize", "--in", tmp_path / "raw.csv", "--columns", "x", "--bins", "5", "--out",
                tmp_path / "binned.csv", "--edges-out", tmp_path / "edges.json")
    binned = pd.read_csv(tmp_path / "binned.csv")
    binned["ok"] = two["onTop1"].to_numpy()
    binned.to_csv(tmp_path / "binned.csv", index=False)
    ours = pgm.fit(binned, "x->ok", intervals=tmp_path / "edges.json")
    program.run("fit", "--data", tmp_path / "binned.csv", "--edges", "x->ok", "--intervals", tmp_path / "edges.json",
                "--out", tmp_path / "cli.json")
    theirs = pgm.read_network(tmp_path / "cli.json")
    assert_same_network(ours, theirs)
    assert ours.interval_edges("x") == theirs.interval_edges("x")


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"estimator": "mle", "prior": "k2"}, "a prior and its options apply to the bayes estimator"),
        ({"estimator": "mle", "alpha": 2}, "a prior and its options apply to the bayes estimator"),
        ({"estimator": "bogus"}, "unknown estimator 'bogus' (known: mle, bayes)"),
        ({"estimator": "bayes", "prior": "k3"}, "unknown prior 'k3' (known: bdeu, dirichlet, k2, none)"),
        ({"estimator": "bayes", "prior": "k2", "ess": 2}, "ess: sets the option ess, which the prior k2 has not"),
        ({"estimator": "bayes", "prior": "dirichlet", "alpha": -1},
         "alpha: option alpha of the prior 'dirichlet' must be a number >= 0, got '-1.0'"),
        ({"estimator": "bayes", "prior": "dirichlet[alpha=2]", "alpha": 3},
         "alpha: sets alpha, which 'dirichlet[alpha=2]' sets already; give it once"),
        ({"map": MAP}, "strategy, map, w_prior, success and match apply with prior_model"),
        ({"empty": "sometimes"}, "unknown empty-configuration rule 'sometimes' (known: uniform, fail)"),
    ],
)
def test_bad_arguments_raise_pgm_error(tasks, kwargs, message):
    _, two, _ = tasks
    with pytest.raises(pgm.Error, match=re.escape(message)):
        pgm.fit(two, TWO_EDGES, **kwargs)


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({}, "prior_model needs map"),
        ({"map": "onTop2=onTop1,xOff3~xOff1"}, "the map's related variable 'xOff3' is not a variable of the target network"),
        ({"map": MAP, "strategy": "bogus"}, "bogus"),
        ({"map": MAP, "w_prior": -1}, "the prior weight w must be a finite number ≥ 0, got -1"),
        ({"map": MAP, "w_prior": "often"}, "w_prior must be a number >= 0 or 'auto'"),
    ],
)
def test_bad_transfers_raise_pgm_error(tasks, kwargs, message):
    one, two, _ = tasks
    with pytest.raises(pgm.Error, match=message):
        pgm.fit(two, TWO_EDGES, prior_model=pgm.fit(one, ONE_EDGES), **kwargs)


def test_a_cycle_is_an_error_naming_it():
    frame = pd.DataFrame({"a": [0, 1], "b": [1, 0]})
    with pytest.raises(pgm.Error, match="closes the cycle"):
        pgm.fit(frame, "a->b,b->a")


def test_empty_configurations_fail_when_asked():
    frame = pd.DataFrame({"a": [0, 0, 1], "b": [0, 1, 0], "c": [1, 0, 1]})
    pgm.fit(frame, "a->c,b->c")
    with pytest.raises(pgm.Error, match="no data"):
        pgm.fit(frame, "a->c,b->c", empty="fail")


def integer_frames():
    """Frames of integer codes as pgm.fit reads them straight from their buffers, and as it takes
    them the general way (negative or large values), each with `x->c,y->c,z->y` to fit."""
    random = np.random.default_rng(5)
    rows = 10_000  # the first look at the rows takes every 4th
    codes = {
        "x": random.integers(0, 5, rows),
        "y": random.choice([3, 7, 12], rows).astype(np.int8),  # gaps, and not from 0
        "z": random.integers(0, 2, rows).astype(np.uint16),
        "c": random.integers(0, 2, rows).astype(np.int32),
    }
    matrix = np.stack([codes[name] for name in "xyzc"], axis=1).astype(np.int64)
    rare = {name: values.copy() for name, values in codes.items()}
    rare["c"] = np.sort(rare["c"])
    rare["c"][1] = 300  # a value the first look at the rows misses: counted again
    return {
        "codes": pd.DataFrame(codes),
        "matrix": pd.DataFrame(matrix, columns=list("xyzc")),  # columns of a row-major matrix: strided
        "rare value": pd.DataFrame(rare),
        "negative": pd.DataFrame({**codes, "x": codes["x"] - 2}),
        "negative matrix": pd.DataFrame(matrix - 2, columns=list("xyzc")),  # strided, the data set's way
        "large": pd.DataFrame({**codes, "y": codes["y"].astype(np.int64) * 100_000}),
    }


@pytest.mark.parametrize("name", list(integer_frames()))
@pytest.mark.parametrize("arguments", [[], ["--estimator", "bayes", "--prior", "k2"]])
def test_integer_codes_equal_the_programs_to_the_last_bit(program, tmp_path, name, arguments):
    frame = integer_frames()[name]
    frame.to_csv(tmp_path / "codes.csv", index=False)
    edges = "x->c,y->c,z->y"
    program.run("fit", "--data", tmp_path / "codes.csv", "--edges", edges, "--out", tmp_path / "cli.json", *arguments)
    kwargs = {"estimator": "bayes", "prior": "k2"} if arguments else {}
    theirs = pgm.read_network(tmp_path / "cli.json")
    for threads in (1, 2):
        assert_same_network(pgm.fit(frame, edges, threads=threads, **kwargs), theirs)
    # The same values as strings take the general way, with the same states.
    assert_same_network(pgm.fit(frame.astype(str), edges, **kwargs), theirs)


# ---- missing="em" ------------------------------------------------------------------------------


def latent_class_frame(rows, seed):
    """Three yes/no indicators of a two-class cause H that no column holds, with a tenth of the
    values missing (NaN in float columns, as pandas reads gaps)."""
    random = np.random.default_rng(seed)
    h = random.random(rows) < 0.6
    frame = pd.DataFrame(
        {
            name: np.where(h, random.random(rows) < high, random.random(rows) < low).astype(float)
            for name, high, low in (("X1", 0.8, 0.1), ("X2", 0.9, 0.2), ("X3", 0.75, 0.3))
        }
    )
    return frame.mask(random.random(frame.shape) < 0.1)


def write_with_gaps(frame, path):
    """The frame as the program reads it: whole numbers without ".0", a gap where a value is missing."""
    frame.astype("Int64").to_csv(path, index=False)


def test_em_with_missing_values_equals_the_programs_to_the_last_bit(program, tmp_path):
    two = stacking_frame(400, 3)[["xOff1", "yOff1", "xOff2", "onTop1", "onTop2"]].astype(float)
    two = two.mask(np.random.default_rng(4).random(two.shape) < 0.15)
    write_with_gaps(two, tmp_path / "gaps.csv")
    edges = "xOff1->onTop1,yOff1->onTop1,onTop1->onTop2,xOff2->onTop2"
    for kwargs, arguments in (
        ({}, []),
        ({"hard": True, "estimator": "bayes", "prior": "k2"}, ["--hard", "--estimator", "bayes", "--prior", "k2"]),
    ):
        ours = pgm.fit(two, edges, missing="em", **kwargs)
        program.run("fit", "--data", tmp_path / "gaps.csv", "--edges", edges, "--missing", "em", *arguments,
                    "--out", tmp_path / "em.json")
        assert_same_network(ours, pgm.read_network(tmp_path / "em.json"))
        assert any(note.startswith("EM: ") for note in ours.notes)


def test_em_with_a_latent_variable_equals_the_programs_to_the_last_bit(program, tmp_path):
    frame = latent_class_frame(500, 6)
    write_with_gaps(frame, tmp_path / "trials.csv")
    edges = "H->X1,H->X2,H->X3"
    ours = pgm.fit(frame, edges, missing="em", latent={"H": ["low", "high"]}, restarts=3, seed=9)
    program.run("fit", "--data", tmp_path / "trials.csv", "--edges", edges, "--missing", "em",
                "--latent", "H=low,high", "--restarts", "3", "--seed", "9", "--out", tmp_path / "em.json")
    assert_same_network(ours, pgm.read_network(tmp_path / "em.json"))
    assert ours.states("H") == ["low", "high"]
    by_count = pgm.fit(frame, edges, missing="em", latent={"H": 2}, restarts=3, seed=9)
    assert by_count.states("H") == ["0", "1"]


def test_em_arguments_are_checked():
    frame = latent_class_frame(50, 1)
    edges = "H->X1,H->X2,H->X3"
    with pytest.raises(pgm.Error, match='latent applies with missing="em"'):
        pgm.fit(frame.dropna(), edges, latent={"H": 2})
    with pytest.raises(pgm.Error, match=r"unknown missing-value policy 'EM' \(known: error, drop, available, em\)"):
        pgm.fit(frame, edges, missing="EM")
    with pytest.raises(pgm.Error, match="'Z' is in no edge"):
        pgm.fit(frame, edges, missing="em", latent={"H": 2, "Z": 2})
    with pytest.raises(pgm.Error, match="'X1' is declared latent but is a column"):
        pgm.fit(frame, edges, missing="em", latent={"H": 2, "X1": 2})
    with pytest.raises(TypeError, match="latent\\['H'\\] must be a number of states"):
        pgm.fit(frame, edges, missing="em", latent={"H": 2.5})
    with pytest.raises(pgm.Error, match="restarts must be a whole number from 1 to 1000, got 0"):
        pgm.fit(frame, edges, missing="em", latent={"H": 2}, restarts=0)
    with pytest.raises(pgm.Error, match="tolerance must be a number >= 0"):
        pgm.fit(frame, edges, missing="em", latent={"H": 2}, tolerance=float("nan"))
    with pytest.raises(pgm.Error, match="H"):
        pgm.fit(frame, edges, missing="em")  # H is in no column and not declared latent


# ---- keep_counts and Network.update ----------------------------------------------------------


@pytest.mark.parametrize(
    "kwargs",
    [{}, {"estimator": "bayes", "prior": "k2"}, {"estimator": "bayes", "prior": "bdeu", "ess": 4.0}],
)
def test_an_update_equals_fitting_all_the_rows_to_the_last_bit(kwargs):
    first = stacking_frame(600, 11)
    second = stacking_frame(300, 12)
    fitted = pgm.fit(first, TWO_EDGES, keep_counts=True, **kwargs)
    assert fitted.has_counts
    updated = fitted.update(second)
    assert_same_network(updated, pgm.fit(pd.concat([first, second], ignore_index=True), TWO_EDGES, **kwargs))
    assert updated.has_counts
    assert not pgm.fit(first, TWO_EDGES).has_counts


def test_an_update_with_a_transferred_prior_keeps_its_weight(tasks):
    one, two, tmp_path = tasks
    prior = pgm.read_network(tmp_path / "one.json")
    more = stacking_frame(200, 13)
    arguments = {"prior_model": prior, "map": MAP, "w_prior": 7}
    updated = pgm.fit(two, TWO_EDGES, keep_counts=True, **arguments).update(more)
    assert_same_network(updated, pgm.fit(pd.concat([two, more], ignore_index=True), TWO_EDGES, **arguments))


def test_the_counts_go_through_a_json_file_and_equal_pgm_update(program, tmp_path):
    first = stacking_frame(500, 14)
    second = stacking_frame(250, 15)
    first.to_csv(tmp_path / "first.csv", index=False)
    second.to_csv(tmp_path / "second.csv", index=False)
    pgm.fit(first, ONE_EDGES, estimator="bayes", prior="k2", keep_counts=True).write(tmp_path / "py.json")
    read = pgm.read_network(tmp_path / "py.json")
    assert read.has_counts
    ours = read.update(second, decay=0.5)
    program.run("fit", "--data", tmp_path / "first.csv", "--edges", ONE_EDGES, "--estimator", "bayes", "--prior",
                "k2", "--keep-counts", "--out", tmp_path / "cli.json")
    program.run("update", "--model", tmp_path / "cli.json", "--data", tmp_path / "second.csv", "--decay", "0.5",
                "--out", tmp_path / "cli2.json")
    assert_same_network(ours, pgm.read_network(tmp_path / "cli2.json"))
    # BIF, XMLBIF and NET keep them too, in a property other tools ignore.
    for name in ("counts.bif", "counts.xml", "counts.net"):
        ours.write(tmp_path / name)
        read = pgm.read_network(tmp_path / name)
        assert read.has_counts, name
        assert_same_network(read.update(second), ours.update(second))


def test_update_arguments_are_checked():
    frame = stacking_frame(100, 16)
    with pytest.raises(pgm.Error, match="carries no counts"):
        pgm.fit(frame, ONE_EDGES).update(frame)
    kept = pgm.fit(frame, ONE_EDGES, keep_counts=True)
    with pytest.raises(pgm.Error, match="decay must be in \\(0, 1\\]"):
        kept.update(frame, decay=0)
    with pytest.raises(pgm.Error, match="there is no column 'yOff1'|yOff1"):
        kept.update(frame.drop(columns=["yOff1"]))
    with pytest.raises(pgm.Error, match="keep_counts does not apply"):
        pgm.fit(frame, ONE_EDGES, missing="em", keep_counts=True)


def test_states_named_are_states_also_before_any_row_has_them():
    frame = pd.DataFrame({"x": [0, 1, 1], "onTop": [0, 0, 0]})
    net = pgm.fit(frame, "x->onTop", states={"onTop": [0, 1]}, keep_counts=True)
    assert net.states("onTop") == ["0", "1"]
    table = net.cpt("onTop")
    assert table["0"].tolist() == [1.0, 1.0] and table["1"].tolist() == [0.0, 0.0]
    later = net.update(pd.DataFrame({"x": [1], "onTop": [1]}))
    assert later.cpt("onTop")["1"].tolist() == [0.0, 1 / 3]
    assert pgm.fit(frame, "x->onTop", states={"x": ["1", "0", "2"]}).states("x") == ["1", "0", "2"]
    with pytest.raises(pgm.Error, match="'2'"):
        pgm.fit(frame.assign(onTop=[0, 2, 0]), "x->onTop", states={"onTop": [0, 1]})
    with pytest.raises(pgm.Error, match="states: 'y' is in no edge"):
        pgm.fit(frame, "x->onTop", states={"y": [0, 1]})
    with pytest.raises(pgm.Error, match="must name each state once"):
        pgm.fit(frame, "x->onTop", states={"onTop": [0, 0]})
    with pytest.raises(TypeError, match="must be a list of states"):
        pgm.fit(frame, "x->onTop", states={"onTop": "01"})


def _wide_frame(parents, rows, seed):
    """y (3 states) under `parents` binary columns p0, p1, ..., drawn at random."""
    random = np.random.default_rng(seed)
    frame = pd.DataFrame({f"p{p}": random.integers(0, 2, rows) for p in range(parents)})
    frame.insert(0, "y", random.integers(0, 3, rows))
    return frame


def test_a_family_past_the_dense_limit_is_fitted_sparse_as_by_the_program(program, tmp_path):
    """y under 26 binary parents: 2^26 configurations, past the limit of a dense table. The fit
    keeps the configurations seen, as `pgm fit` does; a table this large is no DataFrame, but
    sampling engines answer queries on it."""
    frame = _wide_frame(26, 2000, 3)
    edges = ",".join(f"p{p}->y" for p in range(26))
    net = pgm.fit(frame, edges)
    frame.to_csv(tmp_path / "wide.csv", index=False)
    program.run("fit", "--data", tmp_path / "wide.csv", "--edges", edges, "--out", tmp_path / "wide.json")
    net.write(tmp_path / "python.json")
    assert (tmp_path / "python.json").read_text() == (tmp_path / "wide.json").read_text()
    with pytest.raises(pgm.Error, match="more than pgm's limit"):
        net.cpt("y")
    p = pgm.query(net, "y", {"p0": 1}, engine="lw")
    assert abs(p.sum() - 1) < 1e-12
    with pytest.raises(pgm.Error, match="the sampling engines"):
        pgm.query(net, "y", {"p0": 1}, engine="ve")


def test_a_large_table_from_few_rows_is_sparse_with_the_dense_values():
    """20 binary parents (3·2^20 cells, within the limit) from 3,000 rows, a table kept sparse:
    its DataFrame has every configuration, a seen one's column the counts' MLE, the others
    uniform."""
    frame = _wide_frame(20, 3000, 5)
    net = pgm.fit(frame, ",".join(f"p{p}->y" for p in range(20)))
    table = net.cpt("y")
    assert len(table) == 2**20
    parents = [f"p{p}" for p in range(20)]
    counts = frame.groupby(parents)["y"].value_counts().unstack(fill_value=0)
    row = counts.index[0]
    index = sum(int(row[p]) << (19 - p) for p in range(20))
    mle = counts.loc[row].to_numpy() / counts.loc[row].sum()
    assert list(table.loc[index, ["0", "1", "2"]].to_numpy()) == list(mle)
    unseen = table[["0", "1", "2"]].to_numpy().max(axis=1) == 1 / 3
    assert unseen.sum() >= 2**20 - 3000


def test_missing_and_w_prior_suggest_the_choice_meant():
    # Issue 49: missing="dorp" listed the choices without the "did you mean" of every other choice.
    frame = pd.DataFrame({"a": [0, 1, 1], "b": [1, 0, 1]})
    known = r"\(known: error, drop, available, em\)"
    with pytest.raises(pgm.Error, match=rf"^unknown missing-value policy 'dorp'; did you mean 'drop'\? {known}$"):
        pgm.fit(frame, "a->b", missing="dorp")
    with pytest.raises(pgm.Error, match=r"unknown missing-value policy 'avalable'; did you mean 'available'\?"):
        pgm.fit(frame, "a->b", missing="avalable")
    with pytest.raises(TypeError, match="^missing must be one of error, drop, available, em, got NoneType$"):
        pgm.fit(frame, "a->b", missing=None)
    prior = pgm.fit(frame, "a->b")
    with pytest.raises(pgm.Error, match=r"^w_prior must be a number >= 0 or 'auto', got 'atuo'; did you mean 'auto'\?$"):
        pgm.fit(frame, "a->b", prior_model=prior, map="a=a,b=b", w_prior="atuo")


def test_the_priors_options_have_one_default_everywhere(program):
    """prior, alpha and ess show the defaults the registry declares, and so does `pgm fit --help`."""
    declared = pgm._core.prior_defaults()
    parameters = inspect.signature(pgm.fit).parameters
    assert parameters["prior"].default == pgm._core.default_prior == "bdeu"
    shown = program.run("fit", "--help").stdout
    assert "--prior TEXT:NAME[KEY=VALUE,...]=bdeu\n" in shown
    for keyword in ("alpha", "ess"):
        assert parameters[keyword].default == float(declared[keyword]), keyword
        line = next(line for line in shown.splitlines() if line.strip().startswith(f"--{keyword} "))
        assert f"--{keyword} FLOAT:a number >= 0={declared[keyword]}" in line, line
    assert pgm._core.prior_listing() == ["bdeu[ess=1]", "dirichlet[alpha=1]", "k2", "none"]


def test_a_prior_is_chosen_by_its_text_or_by_its_keyword(tasks):
    _, two, _ = tasks
    by_text = pgm.fit(two, TWO_EDGES, estimator="bayes", prior="dirichlet[alpha=2.5]")
    by_keyword = pgm.fit(two, TWO_EDGES, estimator="bayes", prior="dirichlet", alpha=2.5)
    assert_same_network(by_text, by_keyword)
    bdeu = pgm.fit(two, TWO_EDGES, estimator="bayes", ess=4)
    assert_same_network(bdeu, pgm.fit(two, TWO_EDGES, estimator="bayes", prior="bdeu[ess=4]"))
    assert not bdeu.cpt("onTop2").equals(by_text.cpt("onTop2"))
