"""`steady_batch`: every row is the single-case analysis, errors stay in their row, columns are
checked, and the thread count changes nothing."""

from __future__ import annotations

import math
import os
import signal
import threading
import time

import numpy as np
import pandas as pd
import pytest

import halfplane

NAN = float("nan")


def mixed_table(n: int, seed: int = 1) -> pd.DataFrame:
    """n rows around the reference cycle: the three profiles, both point orders, tensions, load
    ranges that give every regime and some cycles outside the analysis."""
    rng = np.random.default_rng(seed)
    kinds = np.array(["hertz", "flat-rounded", "power-law"])[rng.integers(0, 3, n)]
    flat = kinds == "flat-rounded"
    power = kinds == "power-law"
    p1 = rng.uniform(600.0, 1400.0, n)
    p2 = rng.uniform(600.0, 1400.0, n)
    q = rng.uniform(0.0, 500.0, n)
    s = rng.uniform(0.0, 60.0, n)
    swap = rng.random(n) < 0.5
    sign = np.where(swap, -1.0, 1.0)
    return pd.DataFrame(
        {
            "youngs_modulus": rng.uniform(7e4, 2.1e5, n),
            "poisson_ratio": rng.uniform(0.25, 0.35, n),
            "friction": rng.uniform(0.3, 0.8, n),
            "profile": kinds,
            "radius": np.where(power, NAN, rng.uniform(20.0, 80.0, n)),
            "flat_half_width": np.where(flat, rng.uniform(0.1, 1.0, n), NAN),
            "coefficient": np.where(power, rng.uniform(0.005, 0.02, n), NAN),
            "exponent": np.where(power, rng.uniform(1.5, 3.0, n), NAN),
            "normal1": p1,
            "shear1": -sign * q,
            "bulk1": -sign * s,
            "normal2": p2,
            "shear2": sign * q,
            "bulk2": sign * s,
        }
    )


def case_of(row: pd.Series) -> halfplane.Case:
    params = {
        k: float(row[k])
        for k in ("radius", "flat_half_width", "coefficient", "exponent")
        if not math.isnan(row[k])
    }
    moments = (row.get("moment1", 0.0), row.get("moment2", 0.0))
    return halfplane.Case(
        youngs_modulus=float(row.youngs_modulus),
        poisson_ratio=float(row.poisson_ratio),
        friction=float(row.friction),
        profile=row.profile,
        point1=(row.normal1, row.shear1, row.bulk1, moments[0]),
        point2=(row.normal2, row.shear2, row.bulk2, moments[1]),
        **params,
    )


def test_rows_equal_single_solves():
    # The batch runs the same analysis as `steady` on the same values, so the only allowed
    # difference is none; 1e-12 relative is the stated bound and leaves room for nothing
    # but rounding.
    check_rows_against_single_solves(mixed_table(300))


@pytest.mark.filterwarnings("ignore::halfplane.HalfplaneWarning")
def test_rows_with_moments_equal_single_solves():
    # moment1, moment2: the pressure's centroid M/P within +-0.15 mm of the centre (contacts of
    # about 0.5 to 1 mm half-width), so that every regime and some cycles outside the analysis
    # occur; a table without the columns has no moment (the test above).
    table = mixed_table(200, seed=5)
    rng = np.random.default_rng(6)
    table["moment1"] = rng.uniform(-0.15, 0.15, len(table)) * table.normal1
    table["moment2"] = rng.uniform(-0.15, 0.15, len(table)) * table.normal2
    check_rows_against_single_solves(table)
    # A moment moves the contact: the batch's half-widths are those of the moved contacts.
    plain = halfplane.steady_batch(table.drop(columns=["moment1", "moment2"]))
    moved = halfplane.steady_batch(table)
    assert not np.allclose(plain.half_width_1, moved.half_width_1, equal_nan=True)


def check_rows_against_single_solves(table: pd.DataFrame) -> None:
    out = halfplane.steady_batch(table)
    assert list(out.columns) == halfplane.STEADY_COLUMNS
    regimes = set()
    for i, row in table.iterrows():
        got = out.loc[i]
        try:
            r = halfplane.steady(case_of(row))
        except halfplane.HalfplaneError as e:
            assert got.error == str(e).split(" (halfplane.march")[0], i
            assert got.regime == "" and np.isnan(got[2:9].astype(float)).all()
            regimes.add("error")
            continue
        regimes.add(r.regime)
        assert got.regime == r.regime and got.error == ""
        expected = [r.contact.half_width_1, r.contact.half_width_2]
        assert got.half_width_1 == pytest.approx(expected[0], rel=1e-12, abs=0)
        assert got.half_width_2 == pytest.approx(expected[1], rel=1e-12, abs=0)
        if r.stick_zone is None:
            assert np.isnan([got.stick_left, got.stick_right, got.slip_left_1]).all()
            continue
        pairs = [
            (got.stick_left, r.stick_zone.left),
            (got.stick_right, r.stick_zone.right),
            (got.slip_left_1, r.slip_zones.left.at_point1),
            (got.slip_left_2, r.slip_zones.left.at_point2),
            (got.slip_right_1, r.slip_zones.right.at_point1),
            (got.slip_right_2, r.slip_zones.right.at_point2),
        ]
        for batch_value, single in pairs:
            assert batch_value == pytest.approx(single, rel=1e-12, abs=1e-12 * expected[0]), i
    assert regimes >= {"partial-slip", "full-stick", "gross-sliding", "error"}, regimes


def test_bad_rows_carry_their_error_and_do_not_stop_the_batch():
    table = mixed_table(8)
    table["profile"] = "hertz"
    table[["flat_half_width", "coefficient", "exponent"]] = NAN
    table["radius"] = 50.0
    table.loc[1, "youngs_modulus"] = -2.0
    table.loc[2, "radius"] = NAN
    table.loc[3, "flat_half_width"] = 0.5
    table.loc[4, "profile"] = "cylinder"
    table.loc[5, "profile"] = None
    table.loc[6, "normal2"] = 0.0
    out = halfplane.steady_batch(table)
    expected = {
        1: "invalid youngs_modulus = -2",
        2: "invalid radius = NaN",
        3: "flat_half_width = 0.5 is not used by profile kind \"hertz\"",
        4: "invalid profile = \"cylinder\"",
        5: "invalid profile = \"\"",
        6: "invalid normal2 = 0",
    }
    for row, start in expected.items():
        assert out.error[row].startswith(start), (row, out.error[row])
        assert out.regime[row] == ""
        assert out.iloc[row, 1:9].isna().all()
    good = [i for i in range(8) if i not in expected]
    assert (out.error[good] == "").all() and (out.regime[good] != "").all()


def test_input_forms_and_index():
    table = mixed_table(50)
    table.index = pd.Index(np.arange(50) * 10 + 3, name="case")
    out = halfplane.steady_batch(table)
    assert out.index.equals(table.index)
    as_dict = {k: table[k].to_numpy() for k in table.columns}
    as_dict["profile"] = list(table.profile)
    from_dict = halfplane.steady_batch(as_dict)
    assert isinstance(from_dict.index, pd.RangeIndex)
    pd.testing.assert_frame_equal(from_dict, out.reset_index(drop=True), check_exact=True)
    categorical = table.assign(profile=table.profile.astype("category"))
    pd.testing.assert_frame_equal(halfplane.steady_batch(categorical), out, check_exact=True)
    # Columns no row uses may be absent; integer columns are numbers.
    hertz = table[table.profile == "hertz"].drop(columns=["flat_half_width", "coefficient", "exponent"])
    hertz = hertz.assign(normal1=hertz.normal1.round().astype("int64"))
    assert (halfplane.steady_batch(hertz).error == "").sum() > 0
    assert len(halfplane.steady_batch(table.iloc[:0])) == 0


@pytest.mark.parametrize(
    "change, column",
    [
        (lambda t: t.drop(columns=["friction"]), "friction"),
        (lambda t: t.drop(columns=["profile"]), "profile"),
        (lambda t: t.drop(columns=["bulk2"]), "bulk2"),
        (lambda t: t.assign(youngs_modulus=["200000"] * len(t)), "youngs_modulus"),
        (lambda t: t.assign(shear1=[True] * len(t)), "shear1"),
        (lambda t: t.assign(profile=np.arange(len(t))), "profile"),
        (lambda t: {**{k: t[k] for k in t.columns}, "normal2": np.ones(3)}, "normal2"),
    ],
)
def test_a_missing_or_wrong_column_is_a_value_error_naming_it(change, column):
    with pytest.raises(ValueError) as raised:
        halfplane.steady_batch(change(mixed_table(10)))
    assert f"'{column}'" in str(raised.value)
    assert isinstance(raised.value, halfplane.InputError)


def hertz_table(n: int, seed: int = 2) -> pd.DataFrame:
    """n Hertz rows (cheap: many chunks of 16,384 rows in a fraction of a second)."""
    table = mixed_table(n, seed)
    table["profile"] = "hertz"
    table["radius"] = 50.0
    table[["flat_half_width", "coefficient", "exponent"]] = NAN
    return table


def test_one_thread_and_all_threads_give_identical_results():
    # Several chunks of Hertz rows, then every profile and regime (power-law rows cost ~0.5 ms).
    table = pd.concat([hertz_table(50_000), mixed_table(3_000, seed=7)], ignore_index=True)
    one = halfplane.steady_batch(table, threads=1)
    every = halfplane.steady_batch(table)
    three = halfplane.steady_batch(table, threads=3)
    pd.testing.assert_frame_equal(one, every, check_exact=True)
    pd.testing.assert_frame_equal(one, three, check_exact=True)


def test_thread_counts_are_checked(monkeypatch):
    table = mixed_table(4)
    for bad in (0, -1, 2.5, True):
        with pytest.raises(halfplane.InputError, match="threads"):
            halfplane.steady_batch(table, threads=bad)
    monkeypatch.setenv("HALFPLANE_NUM_THREADS", "lots")
    with pytest.raises(halfplane.InputError, match="HALFPLANE_NUM_THREADS"):
        halfplane.steady_batch(table)
    monkeypatch.setenv("HALFPLANE_NUM_THREADS", "1")
    pd.testing.assert_frame_equal(
        halfplane.steady_batch(table), halfplane.steady_batch(table, threads=2), check_exact=True
    )


def test_ctrl_c_interrupts_a_long_batch():
    # 1e6 power-law rows (every regime) take seconds on one core in a release build (up to 7 µs
    # each), far longer in a debug build; SIGINT after 0.5 s must end the call at the next chunk
    # boundary (16,384 rows, about 0.1 s) with KeyboardInterrupt. (Flat-rounded rows, 3 µs,
    # would leave too little margin in a release build.)
    n = 1_000_000
    table = mixed_table(n)
    table["profile"] = "power-law"
    table["coefficient"] = 0.01
    table["exponent"] = 2.5
    table[["radius", "flat_half_width"]] = NAN
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        halfplane.steady_batch(table, threads=1)
    elapsed = time.monotonic() - start
    timer.cancel()
    assert elapsed < 10.0, f"interrupt seen only after {elapsed:.1f} s"


def misaligned(values: np.ndarray) -> np.ndarray:
    """A copy of ``values`` in a buffer offset by one byte: not aligned for its dtype, as a
    partition's columns may arrive after travelling between processes."""
    raw = bytearray(values.nbytes + 1)
    out = np.frombuffer(raw, dtype=values.dtype, count=len(values), offset=1)
    out[...] = values
    assert not out.flags.aligned
    return out


def test_misaligned_and_strided_columns_give_the_same_rows():
    # Issue 17: a misaligned float64 column was "not contiguous or is misaligned" (ValueError).
    table = mixed_table(600, seed=5)
    serial = halfplane.steady_batch(table)
    numeric = [c for c in table.columns if c != "profile"]
    arrays = {c: table[c].to_numpy() for c in numeric}
    shifted = {c: misaligned(v) for c, v in arrays.items()}
    strided = {c: np.repeat(v, 2)[::2] for c, v in arrays.items()}
    assert not strided["friction"].flags.c_contiguous
    for layout in (shifted, strided):
        columns = {**layout, "profile": table["profile"].to_numpy()}
        pd.testing.assert_frame_equal(halfplane.steady_batch(columns), serial, check_exact=True)
        series = {c: pd.Series(v, copy=False) for c, v in columns.items()}
        pd.testing.assert_frame_equal(halfplane.steady_batch(series), serial, check_exact=True)
