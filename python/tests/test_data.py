"""DataFrame columns in: the states of a column are the values seen, in the order `pgm fit`
gives the same data read from CSV (numbers by value, other labels alphabetically)."""

import numpy as np
import pandas as pd
import pytest

import pgm


def states_in_python(column):
    frame = pd.DataFrame({"c": column, "z": np.zeros(len(column), dtype=np.int64)})
    return pgm.fit(frame, "c->z").states("c")


def states_by_cli(program, tmp_path, column):
    frame = pd.DataFrame({"c": column, "z": np.zeros(len(column), dtype=np.int64)})
    frame.to_csv(tmp_path / "data.csv", index=False)
    program.run("fit", "--data", tmp_path / "data.csv", "--edges", "c->z", "--out", tmp_path / "fit.json")
    return pgm.read_network(tmp_path / "fit.json").states("c")


@pytest.mark.parametrize(
    "column, states",
    [
        ([10, -2, 3, 10], ["-2", "3", "10"]),
        (["b", "B", "a", "b"], ["B", "a", "b"]),
        (["10", "9", "1.5", "9"], ["1.5", "9", "10"]),
        (["Red", "10", "2"], ["10", "2", "Red"]),
        ([True, False, True], ["False", "True"]),
        (pd.Categorical(["z", "a", "z"], categories=["z", "m", "a"]), ["a", "z"]),
        (pd.Categorical([3, 1, 3], categories=[3, 2, 1]), ["1", "3"]),
        (pd.array([4, 2, 4], dtype="Int64"), ["2", "4"]),
        (np.array([7, 0, 7], dtype=np.uint8), ["0", "7"]),
        (np.array([300, 2, 300], dtype=np.int64), ["2", "300"]),
    ],
)
def test_states_are_the_values_seen_in_the_clis_order(program, tmp_path, column, states):
    assert states_in_python(column) == states
    assert states_by_cli(program, tmp_path, column) == states


def test_a_number_written_two_ways_is_one_state_named_as_first_met():
    assert states_in_python(np.array(["1.0", "2", "1"], dtype=object)) == ["1.0", "2"]
    assert states_in_python(np.array(["-0", "1", "0", "1e0"], dtype=object)) == ["-0", "1"]


# Issue 28: the values are compared exactly, whichever way the column comes in.
@pytest.mark.parametrize(
    "column, states",
    [
        # One double, two integers: two states (they were merged).
        (np.array([2**53, 2**53 + 1, 2**53], dtype=np.int64), ["9007199254740992", "9007199254740993"]),
        (np.array(["9007199254740993", "9007199254740992"], dtype=object), ["9007199254740992", "9007199254740993"]),
        (np.array(["0.1", "0.10000000000000001"], dtype=object), ["0.1", "0.10000000000000001"]),
        # An object column of ints with one float: the values as written, as the CSV has them.
        (np.array([0, 1, 2, 1.5, 1], dtype=object), ["0", "1", "1.5", "2"]),
        (np.array([0, 1, None, 1.5], dtype=object)[[0, 1, 3]], ["0", "1", "1.5"]),
    ],
)
def test_numbers_are_one_state_only_when_they_are_exactly_equal(program, tmp_path, column, states):
    assert states_in_python(column) == states
    assert states_by_cli(program, tmp_path, column) == states


@pytest.mark.parametrize("dtype", [">i2", ">i4", ">i8", ">u4", "<i8"])
def test_columns_of_either_byte_order_read_the_same(dtype):
    values = np.array([1, 2, 300, 2], dtype=dtype)
    frame = pd.DataFrame({"c": values, "z": np.array([0, 1, 1, 0])})
    native = pd.DataFrame({"c": values.astype(np.int64), "z": frame["z"]})
    assert pgm.fit(frame, "c->z").states("c") == ["1", "2", "300"]
    assert pgm.fit(frame, "c->z").cpt("z").equals(pgm.fit(native, "c->z").cpt("z"))
    raw = pd.DataFrame({"x": np.array([0.5, 1.5, 2.5, 3.5], dtype=">f8")})
    assert pgm.discretize(raw, bins=2, columns="x")[1] == {"x": [0.5, 2.0, 3.5]}


@pytest.mark.parametrize("dtype", [np.int8, np.int16, np.int32, np.int64, np.uint16, np.uint32, np.uint64])
def test_every_integer_width_gives_the_same_states(dtype):
    assert states_in_python(np.array([3, 0, 5, 3], dtype=dtype)) == ["0", "3", "5"]


def test_integers_far_apart_take_the_sparse_path():
    column = np.array([10**12, -(10**12), 5, 10**12], dtype=np.int64)
    assert states_in_python(column) == ["-1000000000000", "5", "1000000000000"]
    extremes = np.array([np.iinfo(np.int64).max, np.iinfo(np.int64).min, 0], dtype=np.int64)
    assert states_in_python(extremes) == [str(np.iinfo(np.int64).min), "0", str(np.iinfo(np.int64).max)]


def test_codes_follow_the_states():
    frame = pd.DataFrame({"a": ["y", "x", "y", "y"], "b": [1, 1, 0, 1]})
    table = pgm.fit(frame, "a->b").cpt("b")
    assert list(table["a"]) == ["x", "y"]
    assert list(table["1"]) == [1.0, 2 / 3]


@pytest.mark.parametrize("values", [[7, 0, 7, 7], [1, 0, 1, 1], [700, -1, 700, 700]])
def test_integer_codes_follow_the_states(values):
    # Codes 0..k-1 are copied as they are; other small values are mapped, large ones looked up.
    frame = pd.DataFrame({"a": np.array(values, dtype=np.int64), "b": [1, 1, 0, 1]})
    table = pgm.fit(frame, "a->b").cpt("b")
    assert list(table["a"]) == [str(values[1]), str(values[0])]
    assert list(table["1"]) == [1.0, 2 / 3]


def test_missing_values_are_an_error_naming_column_and_position():
    for column in (["a", None, "b"], pd.array([1, None, 2], dtype="Int64"), pd.Categorical(["a", None, "a"])):
        with pytest.raises(pgm.Error, match=r"column 'c': the value at position 1 is missing"):
            states_in_python(column)


def incomplete_frame():
    # Row 1 lacks b, row 3 lacks c, row 4 lacks a (None, NaN and pd.NA alike).
    return pd.DataFrame(
        {
            "a": ["x", "x", "y", "y", None, "x"],
            "b": pd.array([0, None, 1, 0, 1, 1], dtype="Int64"),
            "c": pd.array([1, 0, 1, None, 0, 1], dtype="Int64"),
        }
    )


def test_missing_values_follow_the_missing_keyword_as_the_cli_does(program, tmp_path):
    frame = incomplete_frame()
    with pytest.raises(pgm.Error, match=r"column 'b': the value at position 1 is missing"):
        pgm.fit(frame, "b->a,a->c")
    with pytest.raises(pgm.Error, match=r"unknown missing-value policy 'pairwise' \(known: error, drop, available, em\)"):
        pgm.fit(frame, "b->a,a->c", missing="pairwise")
    frame.to_csv(tmp_path / "m.csv", index=False)  # missing values become empty fields
    for missing in ("drop", "available"):
        out = tmp_path / f"{missing}.json"
        program.run("fit", "--data", tmp_path / "m.csv", "--edges", "b->a,a->c", "--missing", missing, "--out", out)
        by_cli = pgm.read_network(out)
        if missing == "drop":
            with pytest.warns(UserWarning, match="dropped 3 of 6 rows with a missing value"):
                fitted = pgm.fit(frame, "b->a,a->c", missing=missing)
        else:
            fitted = pgm.fit(frame, "b->a,a->c", missing=missing)
        for node in ("a", "b", "c"):
            assert fitted.states(node) == by_cli.states(node), (missing, node)
            assert fitted.cpt(node).equals(by_cli.cpt(node)), (missing, node)
    # By hand: c | a over the rows where both are present (0, 1, 2, 5).
    table = pgm.fit(frame, "b->a,a->c", missing="available").cpt("c")
    assert list(table["1"]) == [2 / 3, 1.0]
    # Whole numbers and NaN in a float column (pandas' integer column with a gap) read as integers.
    floats = frame.assign(c=[1.0, 0.0, 1.0, np.nan, 0.0, 1.0])
    fitted = pgm.fit(floats, "b->a,a->c", missing="available")
    assert fitted.states("c") == ["0", "1"]
    assert fitted.cpt("c").equals(pgm.fit(frame, "b->a,a->c", missing="available").cpt("c"))


def test_missing_values_in_structure_learning_and_discretization():
    frame = incomplete_frame()
    with pytest.raises(pgm.Error, match=r"column 'c': the value at position 3 is missing"):
        pgm.learn_structure(frame[["a", "c"]])
    edges = pgm.learn_structure(frame, missing="available")  # each test over its present rows
    assert all(parent in frame.columns and child in frame.columns for parent, child in edges)
    raw = pd.DataFrame({"u": [0.5, np.nan, 2.5, 1.5, 3.5, 0.1, 0.2], "v": [0, 1, 0, 1, 0, 1, 0]})
    with pytest.raises(pgm.Error, match=r"column 'u': the value at position 1 is missing"):
        pgm.discretize(raw, bins=2, columns="u")
    binned, edges = pgm.discretize(raw, bins=2, columns="u", missing="available")
    assert list(edges["u"]) == [0.1, 1.0, 3.5]
    assert binned["u"].isna().tolist() == [False, True, False, False, False, False, False]
    assert binned["u"].dropna().tolist() == [0, 1, 1, 1, 0, 0]


def test_numbers_that_are_not_finite_are_an_error():
    with pytest.raises(pgm.Error, match=r"position 1, 'inf', is not a finite number"):
        states_in_python(np.array(["1", "inf"], dtype=object))


def test_float_columns_must_be_binned_first():
    frame = pd.DataFrame({"x": [0.5, 1.5], "y": [0, 1]})
    with pytest.raises(pgm.Error, match=r"column 'x' holds continuous values; discretize it first"):
        pgm.fit(frame, "x->y")


def test_errors_are_value_errors_with_the_librarys_message():
    assert issubclass(pgm.Error, ValueError)
    frame = pd.DataFrame({"a": [0, 1], "b": [1, 0]})
    with pytest.raises(ValueError, match=r"DataFrame: there is no column 'c' \(columns: a, b\)"):
        pgm.fit(frame, "a->c")


def test_only_data_frames_with_string_column_names():
    with pytest.raises(TypeError, match="pandas DataFrame"):
        pgm.fit({"a": [0, 1]}, "a->b")
    with pytest.raises(TypeError, match="column names must be strings"):
        pgm.fit(pd.DataFrame({0: [0, 1], "b": [1, 0]}), "b->b2")
    twice = pd.DataFrame([[0, 1, 1], [1, 0, 0]], columns=["a", "b", "a"])
    for call in (
        lambda: pgm.fit(twice, "a->b"),
        lambda: pgm.learn_structure(twice),
        lambda: pgm.discretize(twice, bins=2),
    ):
        with pytest.raises(pgm.Error, match="data: the column name 'a' is given 2 times; name each column once"):
            call()


def test_integer_columns_cross_without_a_copy_per_row():
    # 10^6 rows of int64 codes: a per-row Python object would show as a large peak here.
    import tracemalloc

    frame = pd.DataFrame({"a": np.arange(1_000_000, dtype=np.int64) % 5, "b": np.arange(1_000_000) % 2})
    tracemalloc.start()
    pgm.fit(frame, "a->b")
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    assert peak < 1_000_000  # Python allocations only; the C++ side does not count


def test_missing_suggests_the_rule_meant_in_every_function():
    # Issue 49: missing= had no "did you mean"; it has the library's message for an unknown name.
    frame = pd.DataFrame({"x": [0.5, 1.5, 2.5, 3.5], "y": [0, 1, 0, 1]})
    net = pgm.fit(frame.astype({"x": int}), "x->y")
    message = r"^unknown missing-value policy 'avialable'; did you mean 'available'\? \(known: error, drop, available\)$"
    for call in (
        lambda: pgm.discretize(frame, bins=2, missing="avialable"),
        lambda: pgm.learn_structure(frame[["y"]], missing="avialable"),
        lambda: pgm.score(net, frame.astype({"x": int}), missing="avialable"),
    ):
        with pytest.raises(pgm.Error, match=message):
            call()
