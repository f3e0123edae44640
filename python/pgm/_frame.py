"""pandas DataFrames to and from the column buffers of pgm._core (internal).

A column crosses as one NumPy array, never as one Python object per row:

* integer columns as their values ("int"); their states are the values seen, by value;
* categorical, string, object and boolean columns as integer codes into their distinct labels
  ("coded"); the states are the labels seen, numbers by value and other text alphabetically;
* float columns as doubles ("float"): continuous, to be binned by pgm.discretize.

These are the states `pgm fit` takes from the same data written as CSV.
"""

import warnings

import numpy as np
import pandas as pd

from . import _core
from ._checks import _choice


def _label(value):
    return str(value)


def _require_frame(data):
    if not isinstance(data, pd.DataFrame):
        raise TypeError(f"data must be a pandas DataFrame, got {type(data).__name__}")


def column_names(data):
    """The frame's column names, which must be strings, each once."""
    _require_frame(data)
    names = []
    for column in data.columns:
        if not isinstance(column, str):
            raise TypeError(f"column names must be strings, got {column!r}")
        names.append(column)
    if len(set(names)) < len(names):
        from . import Error

        twice = next(name for name in names if names.count(name) > 1)
        raise Error(f"data: the column name '{twice}' is given {names.count(twice)} times; name each column once")
    return names


def _coded(name, series):
    with warnings.catch_warnings():
        # pandas 1.5 warns that it will stop reading an object column of numbers as numbers;
        # either way each value is labelled as written below.
        warnings.simplefilter("ignore", FutureWarning)
        codes, uniques = pd.factorize(series, use_na_sentinel=True)
    if series.dtype == object and uniques.dtype.kind == "f":
        # pandas factorizes an object column of numbers as floats (1 becomes 1.0); the labels are
        # the values as they are written, as a CSV file of them has them (1 and 1.5).
        codes, uniques = pd.factorize(series.map(_label, na_action="ignore"), use_na_sentinel=True)
    return (name, "coded", np.ascontiguousarray(codes), [_label(u) for u in uniques])


def discrete_column(name, series):
    """The (name, kind, array, labels) of a column whose values are states."""
    dtype = series.dtype
    if isinstance(dtype, pd.CategoricalDtype):
        return (name, "coded", np.ascontiguousarray(series.cat.codes.to_numpy()), [_label(c) for c in dtype.categories])
    if pd.api.types.is_bool_dtype(dtype):
        return _coded(name, series)
    if pd.api.types.is_integer_dtype(dtype):
        if isinstance(dtype, np.dtype):  # read in place, strided or not
            return (name, "int", series.to_numpy(), None)
        if not series.isna().any():  # a nullable integer column without missing values
            return (name, "int", series.to_numpy(dtype="int64"), None)
        return _coded(name, series)
    if pd.api.types.is_float_dtype(dtype):
        values = series.to_numpy(dtype="float64", na_value=np.nan)
        present = values[~np.isnan(values)]
        if len(present) < len(values) and np.all(np.floor(present) == present):
            # An integer column with a missing value, which pandas stores as floats: its states
            # are the integers, as a CSV file gives them.
            return _coded(name, series.astype("Int64"))
        return (name, "float", values, None)
    return _coded(name, series)


def is_number_column(series):
    """Whether the column holds numbers (booleans are states)."""
    dtype = series.dtype
    return pd.api.types.is_numeric_dtype(dtype) and not pd.api.types.is_bool_dtype(dtype)


def numeric_column(name, series):
    """The column as numbers (a continuous column) if it holds numbers, else as states."""
    dtype = series.dtype
    if is_number_column(series):
        if isinstance(dtype, np.dtype):
            return (name, "float", np.ascontiguousarray(series.to_numpy()), None)
        return (name, "float", series.to_numpy(dtype="float64", na_value=np.nan), None)
    return discrete_column(name, series)


_MISSING = tuple(_core.missing_policies)  # the library's: error, drop, available


def with_missing(data, names, missing):
    """The frame under the missing-value rule of the CLI's --missing, over the columns `names`:
    "error" raises naming the first missing value's row and column, "drop" leaves out the rows
    with one (and says how many), "available" keeps them (each family, or test, is then counted
    over the rows where its variables are present). NaN, None and pd.NA are missing."""
    from . import Error  # the package's error type, from pgm._core

    _choice(missing, "missing", _MISSING, "missing-value policy")
    if missing == "available":
        return data
    wanted = set(names)
    # NumPy integer and boolean columns hold no missing value: they are not looked at (no copy).
    read = [
        name
        for name in column_names(data)
        if name in wanted and not (isinstance(data[name].dtype, np.dtype) and data[name].dtype.kind in "iub")
    ]
    read = [name for name in read if data[name].isna().any()]
    if not read:
        return data
    absent = data[read].isna()
    if missing == "error":
        rows = absent.any(axis=1).to_numpy().nonzero()[0]
        row = int(rows[0])
        column = next(name for name in read if absent[name].iat[row])
        raise Error(
            f"DataFrame: column '{column}': the value at position {row} is missing (index {data.index[row]!r}; "
            'choose missing="drop" or missing="available" to read incomplete rows)'
        )
    kept = data[~absent.any(axis=1).to_numpy()]
    if len(kept) == 0:
        raise Error(f"DataFrame: every one of the {len(data)} rows has a missing value, so dropping them leaves none")
    warnings.warn(f"pgm: dropped {len(data) - len(kept)} of {len(data)} rows with a missing value", stacklevel=3)
    return kept


def columns_of(data, names, kind=discrete_column):
    """The buffers of the named columns, in the frame's order."""
    wanted = set(names)
    return [kind(name, data[name]) for name in column_names(data) if name in wanted]


def _as_integers(labels):
    """The labels as integers if each is an integer's own text ("3", "-1"), else None."""
    try:
        values = [int(label) for label in labels]
    except ValueError:
        return None
    if any(str(v) != label for v, label in zip(values, labels)):
        return None
    return np.array(values, dtype=np.int64)


def series_of(kind, array, labels):
    """A column from pgm._core: doubles, integers (states that are integers) or a categorical."""
    if kind == "float":
        return array
    values = _as_integers(labels)
    missing = array >= len(labels)  # pgm's code of a missing value (missing="available")
    if missing.any():
        present = np.where(missing, 0, array)
        if values is not None:
            result = pd.array(values[present], dtype="Int64")
            result[missing] = pd.NA
            return result
        return pd.Categorical.from_codes(np.where(missing, -1, array).astype(np.int32), categories=labels)
    if values is not None:
        return values[array]
    return pd.Categorical.from_codes(array.astype(np.int32, copy=False), categories=labels)


def frame_of(columns):
    """A DataFrame of the columns pgm._core returns."""
    return pd.DataFrame({name: series_of(kind, array, labels) for name, kind, array, labels in columns})
