"""`halfplane.wear` gives the command's numbers (compared exactly: the same library loop and
report rows, built in the same cargo profile), takes `[wear]` fields as keywords with the
section's checks, keeps Cattaneo's stick zone unworn in partial slip, raises a part-way stop with
the checkpoints reached, and its result is a typed, pickling record whose checkpoints are a
DataFrame."""

from __future__ import annotations

import json
import math
import os
import pickle
import signal
import threading
import time

import numpy as np
import pandas as pd
import pytest

import halfplane
from conftest import ROOT, assert_attributes_equal, assert_table_equals_the_csv, run_cli

PARTIAL = ROOT / "examples" / "wear-partial-slip.toml"
SLIDING = ROOT / "examples" / "wear-sliding.toml"

# The bundled partial-slip example shortened to 1e5 cycles (of its 1e6), with five checkpoints
# spaced logarithmically: 1, 18, 316, 5623, 1e5.
SHORT = {"cycles": 100_000, "checkpoints": 5}


def written(tmp_path, source, replacements, name="case.toml"):
    """`source` with each (old, new) of `replacements` replaced once, written to `tmp_path`."""
    text = source.read_text()
    for old, new in replacements:
        assert old in text, old
        text = text.replace(old, new, 1)
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def short_file(tmp_path):
    """The case file the command runs for `SHORT`: the same fields written in `[wear]`."""
    return written(
        tmp_path,
        PARTIAL,
        [("cycles = 1000000", "cycles = 100000"), ("checkpoints = 7 ", "checkpoints = 5 ")],
    )


@pytest.fixture(scope="module")
def short():
    return halfplane.wear(halfplane.read_case(str(PARTIAL)), **SHORT)


def test_wear_equals_the_command(cli, short, tmp_path):
    path = short_file(tmp_path)
    done = run_cli(cli, ["wear", path, "--json"])
    assert done.returncode == 0, done.stderr
    expected = json.loads(done.stdout)
    assert short.to_dict() == expected
    assert_attributes_equal(short, expected, skip=("checkpoints",))
    assert [c["cycle"] for c in expected["checkpoints"]] == [1, 18, 316, 5623, 100_000]
    done = run_cli(cli, ["wear", path, "--csv"])
    assert done.returncode == 0, done.stderr
    assert_table_equals_the_csv(short.checkpoints, done.stdout)
    assert short.stopped is None and short.simulated_cycles is not None
    assert short.units.length == "mm"


def test_fields_equal_the_command_field_files(cli, short, tmp_path):
    path = short_file(tmp_path)
    fields = tmp_path / "fields"
    done = run_cli(cli, ["wear", path, "--csv", "--fields", str(fields)])
    assert done.returncode == 0, done.stderr
    cycles = list(short.checkpoints["cycle"])
    assert short.x.shape == (short.cells,)
    for name in ("depth", "depth_pad", "depth_specimen", "pressure", "traction", "slip_range"):
        assert getattr(short, name).shape == (len(cycles), short.cells), name
    for cycle in cycles:
        text = (fields / f"checkpoint_{cycle}.csv").read_text()
        assert_table_equals_the_csv(short.fields(cycle), text)
    with pytest.raises(KeyError, match="cycle 2 is not a checkpoint"):
        short.fields(2)
    for cycle in cycles:
        text = (fields / f"loop_{cycle}.csv").read_text()
        assert_table_equals_the_csv(short.fretting_loop(cycle), text)
    with pytest.raises(KeyError, match="cycle 2 is not a checkpoint"):
        short.fretting_loop(2)


def test_the_fretting_loop_closes_and_its_area_is_the_energy(short):
    # One steady cycle: Q returns to its start and δ to within 1e-3 of the loop's width (8.3e-5
    # of δ measured at 400 cells, converging with cells), and the work of Q round it (the loop's
    # area, trapezoidal rule) is the energy the cycle dissipates, to the rule's second-order
    # error at the example's 20 increments per half (measured 2.7e-3 at cycle 1; 1e-2 allowed).
    # Its datum only shears it: a loop measured from another datum has the same area and width
    # at Q = 0.
    first = short.fretting_loop(1)
    q, d = first["shear"].to_numpy(), first["relative_displacement"].to_numpy()
    assert q[0] == pytest.approx(q[-1], abs=1e-9 * abs(q).max())
    assert abs(d[-1] - d[0]) < 1e-3 * np.ptp(d)
    area = float(np.sum(0.5 * (q[1:] + q[:-1]) * np.diff(d)))
    energy = float(short.checkpoints["energy_per_cycle"][0])
    assert area == pytest.approx(energy, rel=1e-2)
    assert short.checkpoints["displacement_amplitude"][0] == pytest.approx(0.5 * np.ptp(d))
    other = halfplane.wear(
        halfplane.read_case(str(PARTIAL)), cycles=1, checkpoints=[1], loop_datum=3.0
    )
    assert other.loop_datum == 3.0 and short.loop_datum != 3.0
    d2 = other.fretting_loop(1)["relative_displacement"].to_numpy()
    sheared = d2 - d
    slope = np.polyfit(q, sheared, 1)
    assert np.allclose(sheared, np.polyval(slope, q), atol=1e-9 * np.ptp(d))


def test_cattaneo_stick_zone_stays_and_does_not_wear(short):
    # Cattaneo-Mindlin for a Hertz cylinder (plane strain, both bodies of E, nu): a^2 = 8 P R
    # (1 - nu^2)/(pi E) and the stick zone c = a sqrt(1 - Q/(f P)) = 0.5382 mm for P = 1000 N/mm,
    # R = 50 mm, Q = 300 N/mm, f = 0.6. The grid resolves it to a cell.
    p, r, e, nu, f, q = 1000.0, 50.0, 200_000.0, 0.3, 0.6, 300.0
    a = math.sqrt(8 * p * r * (1 - nu**2) / (math.pi * e))
    c = a * math.sqrt(1 - q / (f * p))
    assert abs(c - 0.5382) < 1e-4
    rows = short.checkpoints
    for left, right in zip(rows["stick_left"], rows["stick_right"]):
        assert abs(left + c) <= short.cell_width and abs(right - c) <= short.cell_width
    # The slip annuli wear, the stick zone does not: exactly zero depth in it, at every
    # checkpoint (cells a cell inside its ends).
    inside = np.abs(short.x) < c - short.cell_width
    assert inside.sum() > 100
    assert np.all(short.depth[:, inside] == 0.0)
    assert short.depth.max() > 0.0


def test_result_is_typed_and_pickles(short):
    frame = short.checkpoints
    assert list(frame.columns) == [
        "cycle", "wear_volume", "max_depth", "energy_per_cycle", "dissipated_energy",
        "contact_left", "contact_right", "peak_pressure", "stick_left", "stick_right",
        "slip_amplitude_max", "displacement_amplitude",
    ]
    assert frame["cycle"].dtype == np.int64
    assert all(frame[c].dtype == np.float64 for c in frame.columns[1:])
    frame.loc[0, "wear_volume"] = -1.0
    assert short.checkpoints.loc[0, "wear_volume"] > 0
    assert short["law"] == short.law == "archard"
    assert short["checkpoints"][0]["cycle"] == 1
    copy = pickle.loads(pickle.dumps(short))
    assert copy == short
    pd.testing.assert_frame_equal(copy.checkpoints, short.checkpoints)
    assert np.array_equal(copy.pressure, short.pressure)
    assert type(copy).__module__ == "halfplane"
    assert "WearResult(archard" in repr(short) and "<table" in short._repr_html_()


def test_keywords_replace_the_sections_fields(cli, tmp_path):
    # The energy law, a pad share and explicit checkpoints, as the command on the same fields
    # written in [wear]; the energy law wears alpha f p |slip| where Archard wears k p |slip|.
    path = written(
        tmp_path,
        PARTIAL,
        [
            ('law = "archard"', 'law = "energy"'),
            ("cycles = 1000000", "cycles = 1000"),
            ("checkpoints = 7 ", "checkpoints = [1, 10, 100] "),
            ("share = 0.5 ", "share = 0.3\nmax_depth_increment = 0.05 "),
        ],
    )
    done = run_cli(cli, ["wear", path, "--json", "--cells", "200"])
    assert done.returncode == 0, done.stderr
    got = halfplane.wear(
        halfplane.read_case(str(PARTIAL)),
        cells=200,
        law="energy",
        cycles=1000,
        checkpoints=np.array([1, 10, 100]),
        share=0.3,
        max_depth_increment=0.05,
    )
    assert got.to_dict() == json.loads(done.stdout)
    assert list(got.checkpoints["cycle"]) == [1, 10, 100, 1000]
    assert got.cells == 200 and got.share == 0.3


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"law": "oops"}, "wear.law"),
        ({"coefficient": -1.0}, "wear.coefficient = -1"),
        ({"coefficient": 0.0}, "wear.coefficient = 0"),
        ({"coefficient": float("nan")}, "wear.coefficient"),
        ({"share": 2.0}, "wear.share = 2"),
        ({"cycles": 0}, "wear.cycles = 0"),
        ({"checkpoints": [5, 3]}, "wear.checkpoints[1]"),
        ({"checkpoints": "many"}, "wear.checkpoints"),
        ({"max_depth_increment": 2.0}, "wear.max_depth_increment = 2"),
        ({"span": 0.5}, "wear.span = 0.5"),
        ({"cells": -3}, "cells"),
        ({"cells": 7}, "cells = 7"),
    ],
)
def test_bad_input_names_the_field(kwargs, field):
    with pytest.raises(halfplane.InputError, match=field.replace(".", r"\.").replace("[", r"\[")):
        halfplane.wear(halfplane.read_case(str(PARTIAL)), **kwargs)


@pytest.mark.parametrize(
    "old, new, message",
    [
        ("share = 0.5 ", "share = -0.1 ", "wear.share = -0.1"),
        ("cycles = 1000000", "cycle = 3", "unknown field wear.cycle"),
        ('law = "archard"', 'law = "adhesive"', "invalid wear.law"),
    ],
)
def test_a_bad_wear_section_raises_as_the_command(cli, tmp_path, old, new, message):
    path = written(tmp_path, PARTIAL, [(old, new)])
    done = run_cli(cli, ["wear", path])
    assert done.returncode == 2
    with pytest.raises(halfplane.InputError) as raised:
        halfplane.wear(halfplane.read_case(path))
    assert message in str(raised.value)
    assert done.stderr.splitlines()[0] == f"error: {raised.value}"


def test_a_case_without_wear_section(cli, tmp_path):
    text = PARTIAL.read_text()
    path = tmp_path / "case.toml"
    path.write_text(text[: text.index("\n[wear]")] + text[text.index("\n[solver]"):])
    with pytest.raises(halfplane.InputError, match=r"missing section \[wear\]"):
        halfplane.wear(halfplane.read_case(str(path)))
    assert run_cli(cli, ["wear", str(path)]).returncode == 2


def test_wear_needs_one_cycle_of_history(tmp_path):
    path = written(tmp_path, PARTIAL, [("cycles = 1 ", "cycles = 2 ")])
    with pytest.raises(halfplane.InputError, match="history.cycles = 2"):
        halfplane.wear(halfplane.read_case(path))


def test_a_part_way_stop_raises_with_the_checkpoints_reached(cli, tmp_path):
    # A sliding scar outgrows a grid 1.2 times the unworn contact within a few thousand cycles:
    # the command prints the checkpoints reached, then the error (exit 2); Python raises the
    # same error with them attached.
    path = written(
        tmp_path, SLIDING, [("cycles = 100000", "cycles = 10000"), ("span = 6.0", "span = 1.2")]
    )
    done = run_cli(cli, ["wear", path, "--json"])
    assert done.returncode == 2
    with pytest.raises(halfplane.InputError) as raised:
        halfplane.wear(halfplane.read_case(path))
    error = raised.value
    assert error.variant == "WearStopped"
    assert "wear stopped at cycle" in str(error) and "wear.span" in str(error)
    assert done.stderr.splitlines()[-1] == f"error: {error}"
    result = error.result
    assert isinstance(result, halfplane.WearResult)
    assert result.to_dict() == json.loads(done.stdout)
    assert result.stopped == str(error) and result.simulated_cycles is None
    assert 0 < len(result.checkpoints) < 6
    # Gross sliding: no cell sticks, the stick columns are NaN (null in the JSON).
    assert result.checkpoints[["stick_left", "stick_right"]].isna().all().all()
    assert result.to_dict()["checkpoints"][0]["stick_left"] is None
    assert result.depth.shape == (len(result.checkpoints), result.cells)


def test_an_error_of_another_analysis_has_no_result():
    with pytest.raises(halfplane.InputError) as raised:
        halfplane.wear(halfplane.read_case(str(PARTIAL)), cells=7)
    assert raised.value.result is None


def test_the_gil_is_released_while_wearing():
    # A Python thread keeps running while wear computes: it would be held up for the whole run
    # if the call kept the GIL (a handful of ticks). Its loop of 2 ms sleeps runs once per 2 ms
    # of the run at best; a tenth of that leaves room for a loaded machine.
    ticks = [0]
    done = threading.Event()

    def tick():
        while not done.is_set():
            time.sleep(0.002)
            ticks[0] += 1

    thread = threading.Thread(target=tick)
    start = time.monotonic()
    thread.start()
    try:
        halfplane.wear(halfplane.read_case(str(PARTIAL)))
    finally:
        done.set()
        thread.join()
    elapsed = time.monotonic() - start
    assert ticks[0] >= elapsed / 0.002 / 10, (ticks[0], elapsed)


def test_ctrl_c_interrupts_a_long_run():
    # 1e6 sliding cycles take far longer than 10 s (the bundled 1e5 take about 10 s); SIGINT
    # after 0.5 s ends the call at the next check between cycles (every 50 ms) with
    # KeyboardInterrupt, well within 10 s.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            halfplane.wear(halfplane.read_case(str(SLIDING)), cycles=1_000_000)
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)
    elapsed = time.monotonic() - start
    assert elapsed < 10.0, f"interrupt seen only after {elapsed:.1f} s"



FATIGUE = """
[fatigue]
findley_k = 0.25
crossland_alpha = 0.4
threshold = 160.0
endurance_range = 700.0
nx = 31
nz = 16
"""


def test_fatigue_columns_equal_the_commands(cli, tmp_path):
    # `fatigue=True` is `--fatigue`: the same maxima over each checkpoint's cycle, as the
    # command's JSON objects and its CSV columns `fatigue.<parameter>.<field>`; the parameters
    # the constants leave out are warned about as the command's stderr names them.
    path = tmp_path / "case.toml"
    path.write_text(
        PARTIAL.read_text()
        .replace("cycles = 1000000", "cycles = 100", 1)
        .replace("checkpoints = 7 ", "checkpoints = [1, 100] ", 1)
        + FATIGUE
    )
    with pytest.warns(UserWarning, match="mcdiarmid not reported"):
        result = halfplane.wear(halfplane.read_case(str(path)), cells=100, fatigue=True)
    done = run_cli(cli, ["wear", str(path), "--cells", "100", "--fatigue", "--json"])
    assert done.returncode == 0, done.stderr
    assert result.to_dict() == json.loads(done.stdout)
    assert "mcdiarmid not reported" in done.stderr
    done = run_cli(cli, ["wear", str(path), "--cells", "100", "--fatigue", "--csv"])
    assert done.returncode == 0, done.stderr
    assert_table_equals_the_csv(result.checkpoints, done.stdout)
    assert "fatigue.findley.max" in result.checkpoints.columns
    # Without constants: the command's error, as InputError.
    bare = tmp_path / "bare.toml"
    bare.write_text(path.read_text().replace(FATIGUE, ""))
    with pytest.raises(halfplane.InputError, match="--fatigue needs material constants"):
        halfplane.wear(halfplane.read_case(str(bare)), cells=100, fatigue=True)
