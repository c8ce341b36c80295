"""``steady_batch``: the steady state of many cases, one per row of a table."""

from __future__ import annotations

import importlib
from typing import Any, List, Mapping, Optional, Tuple, Union

import numpy as np
import pandas as pd

from . import _halfplane
from .errors import InputError

#: The numeric input columns, in the order the native solver takes them: the documented input
#: columns without ``profile`` (passed as codes).
_NUMERIC = [c for c in _halfplane.STEADY_INPUT_COLUMNS if c != "profile"]
#: Profile parameters (a column no row uses may be absent) and the moments (0 when absent).
_OPTIONAL = set(_halfplane.SHAPE_COLUMNS) | {"moment1", "moment2"}

#: Output columns, in order (``regime`` first, ``error`` last).
STEADY_COLUMNS: List[str] = list(_halfplane.STEADY_COLUMNS)

_REGIMES = np.array(list(_halfplane.REGIMES) + [""], dtype=object)

Table = Union[pd.DataFrame, Mapping[str, Any]]


def _bad(message: str) -> InputError:
    error = InputError(message)
    return error


def _get(table: Table, name: str) -> Any:
    if isinstance(table, pd.DataFrame):
        return table[name] if name in table.columns else None
    return table.get(name)


def _one_dimensional(name: str, values: Any) -> np.ndarray:
    is_pandas = isinstance(values, (pd.Series, pd.Index))
    array = values.to_numpy() if is_pandas else np.asarray(values)
    if array.ndim != 1:
        raise _bad(f"column {name!r} must be one-dimensional, found shape {array.shape}")
    return array


def _native(values: Any, dtype: Any) -> np.ndarray:
    """``values`` as the native solver reads them: C-contiguous and aligned, of ``dtype``. Copies
    only an array that is not already so: a strided view, another dtype, or a buffer that is not
    aligned (a partition that travelled between Dask processes may arrive in one). A copy is one
    memory pass per column: measured 0.06 ms for 2 x 10^5 misaligned float64 values (1 ms for a
    stride-2 view), so under 1 ms for the 13 columns, against about 0.5 s to solve 2 x 10^5
    flat-rounded rows on one core (2.3 us each, BENCHMARKS.md); an aligned contiguous float64
    column is passed as it is."""
    return np.require(values, dtype=dtype, requirements=["C_CONTIGUOUS", "ALIGNED"])


def _numbers(name: str, values: Any) -> np.ndarray:
    """The column as contiguous, aligned float64, NaN for missing values; ValueError naming it if it
    does not hold numbers (strings, booleans, dates)."""
    if isinstance(values, pd.Series):
        dtype = values.dtype
        if pd.api.types.is_bool_dtype(dtype) or not (
            pd.api.types.is_numeric_dtype(dtype) or pd.api.types.is_object_dtype(dtype)
        ):
            raise _bad(f"column {name!r} must hold numbers; it has dtype {dtype}")
        if pd.api.types.is_numeric_dtype(dtype):
            return _native(values.to_numpy(dtype=np.float64, na_value=np.nan), np.float64)
    array = _one_dimensional(name, values)
    if array.dtype.kind in "fiu":
        return _native(array, np.float64)
    if array.dtype == object:
        kind = pd.api.types.infer_dtype(array, skipna=True)
        if kind in ("floating", "integer", "mixed-integer-float", "decimal", "empty"):
            return _native(
                pd.to_numeric(pd.Series(array), errors="raise").to_numpy(
                    dtype=np.float64, na_value=np.nan
                ),
                np.float64,
            )
        raise _bad(f"column {name!r} must hold numbers; it holds {kind} values")
    raise _bad(f"column {name!r} must hold numbers; it has dtype {array.dtype}")


#: The profile names a row may give, in the order of the codes :func:`_arrow_profiles` returns.
_KINDS = ["hertz", "flat-rounded", "power-law"]


def _arrow_profiles(values: pd.Series) -> Optional[Tuple[np.ndarray, List[str]]]:
    """Codes of a column of pandas' Arrow-backed strings (pandas >= 3's default for text) by one
    hash lookup per row into the three valid names, or None when it is not such a column or holds
    another name (then :func:`pd.factorize` gives the names for the messages)."""
    if not isinstance(values.array, pd.arrays.ArrowStringArray):
        return None
    try:  # imported by name: pyarrow ships no type information
        pa = importlib.import_module("pyarrow")
        pc = importlib.import_module("pyarrow.compute")
    except ImportError:  # pragma: no cover - Arrow-backed strings need pyarrow
        return None
    strings = pa.array(values.array)
    codes = pc.index_in(strings, value_set=pa.array(_KINDS, type=strings.type))
    if codes.null_count != strings.null_count:
        return None
    return _native(codes.fill_null(-1).to_numpy(), np.int64), list(_KINDS)


def _profiles(values: Any) -> Tuple[np.ndarray, List[str]]:
    """Codes into a list of distinct names (-1 where missing); ValueError if not strings."""
    if isinstance(values, pd.Series):
        arrow = _arrow_profiles(values)
        if arrow is not None:
            return arrow
    if isinstance(values, pd.Series) and isinstance(values.dtype, pd.CategoricalDtype):
        names = list(values.cat.categories)
        if not all(isinstance(n, str) for n in names):
            raise _bad("column 'profile' must hold profile names such as 'hertz'")
        return _native(values.cat.codes.to_numpy(dtype=np.int64), np.int64), names
    text = isinstance(values, pd.Series) and pd.api.types.is_string_dtype(values.dtype)
    if text and values.dtype != object:
        labels, distinct = pd.factorize(values, use_na_sentinel=True)
        return _native(labels, np.int64), [str(u) for u in distinct]
    if isinstance(values, pd.Series):
        array = values.to_numpy(dtype=object)
    else:
        array = _one_dimensional("profile", values)
    if array.dtype.kind != "U":
        kind = pd.api.types.infer_dtype(array, skipna=True)
        if kind not in ("string", "empty"):
            raise _bad(
                "column 'profile' must hold profile names (\"hertz\", \"flat-rounded\", "
                f"\"power-law\"); it holds {kind} values"
            )
    codes, uniques = pd.factorize(array, use_na_sentinel=True)
    return _native(codes, np.int64), [str(u) for u in uniques]


def steady_batch(table: Table, threads: Optional[int] = None) -> pd.DataFrame:
    """The steady state of every row of ``table``, solved in Rust on all cores.

    ``table`` is a DataFrame or a dict of equal-length arrays with the columns

    - ``youngs_modulus`` E (stress unit, MPa with N and mm), ``poisson_ratio`` nu (0 <= nu < 0.5),
      ``friction`` f (> 0);
    - ``profile``: ``"hertz"`` (uses ``radius`` R), ``"flat-rounded"`` (``flat_half_width`` b and
      the edge ``radius`` R) or ``"power-law"`` (g = B|x|^k: ``coefficient`` B, ``exponent`` k);
      parameters a row's profile does not use must be NaN, or the column absent;
    - ``normal1, shear1, bulk1, normal2, shear2, bulk2``: P (> 0) and Q per unit thickness
      (N/mm) and the bulk tension sigma (MPa) at the cycle's two ends, in either order;
    - optional ``moment1, moment2``: the moment M of the contact pressure about x = 0 at each end
      (N mm/mm; the pressure's resultant acts at x = M/P), 0 where the column is absent.

    Signs as in the case files: P > 0 compresses; Q and sigma positive as in the paper's Figure 1;
    x positive in the direction of positive Q.

    Returns one row per input row, in order (a DataFrame keeps its index), with the columns
    ``regime, stick_left, stick_right, half_width_1, half_width_2, slip_left_1, slip_left_2,
    slip_right_1, slip_right_2, error``: the regime (``"partial-slip"``, ``"full-stick"``,
    ``"gross-sliding"``), the stick zone [-m, n] (NaN when sliding), the contact half-widths at the
    two points as given, and the slip-zone lengths at the left and right edges at each point (0 in
    full stick, NaN when sliding). Each row is exactly :func:`halfplane.steady` of the same case.
    A row whose analysis fails (an invalid value, a cycle outside the analysis) has NaN numbers, an
    empty regime and its message in ``error`` (``""`` otherwise); it never stops the batch.

    ``threads`` sizes the worker pool (default: the environment variable
    ``HALFPLANE_NUM_THREADS``, else every core); results do not depend on it. The GIL is released
    while solving, and Ctrl-C interrupts the call (between chunks of 16,384 rows).

    Raises ValueError (:class:`halfplane.InputError`) naming a missing required column or a column
    of the wrong type (text where numbers belong, numbers in ``profile``), or columns of unequal
    length.
    """
    if not isinstance(table, (pd.DataFrame, Mapping)):
        raise TypeError(
            f"table must be a pandas DataFrame or a dict of columns, not {type(table).__name__}"
        )
    whole = isinstance(threads, (int, np.integer)) and not isinstance(threads, bool)
    if threads is not None and (not whole or threads < 1):
        raise _bad(f"invalid threads = {threads!r}: must be a whole number from 1 to 4096, or None")
    profile = _get(table, "profile")
    if profile is None:
        raise _bad("missing column 'profile': give 'hertz', 'flat-rounded' or 'power-law' per row")
    codes, names = _profiles(profile)
    rows = len(codes)
    columns: List[Optional[np.ndarray]] = []
    for name in _NUMERIC:
        values = _get(table, name)
        if values is None:
            if name in _OPTIONAL:
                columns.append(None)
                continue
            raise _bad(f"missing column {name!r}")
        column = _numbers(name, values)
        if len(column) != rows:
            raise _bad(f"column {name!r} has {len(column)} rows, but 'profile' has {rows}")
        columns.append(column)
    regime_codes, numbers, failed_rows, messages = _halfplane.steady_batch_columns(
        columns, codes, names, None if threads is None else int(threads)
    )
    index: pd.Index = table.index if isinstance(table, pd.DataFrame) else pd.RangeIndex(rows)
    # Text columns are object arrays of shared str objects: building pandas' string dtype from a
    # million of them would cost more than solving the rows. `numbers` is (8, rows): its transpose
    # is one float block of the frame, not copied.
    error = np.full(rows, "", dtype=object)
    if len(messages):
        text = np.empty(len(messages), dtype=object)
        text[:] = messages
        error[failed_rows] = text
    frame: pd.DataFrame = pd.DataFrame(
        numbers.T, index=index, columns=STEADY_COLUMNS[1:-1], copy=False
    )
    regimes = pd.Series(_REGIMES[regime_codes], index=index, dtype=object, copy=False)
    frame.insert(0, "regime", regimes)
    frame["error"] = pd.Series(error, index=index, dtype=object, copy=False)
    return frame
