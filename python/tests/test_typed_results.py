"""Typed results (issue 18, part 2): the records have typed attributes built from the report
structs (no text route), behave as before (item access, iteration, to_dict, pickling, read-only),
and show their main quantities in `repr` and in the notebook's HTML table. mypy --strict sees the
types a script uses."""

from __future__ import annotations

import dataclasses
import math
import pickle
import subprocess
import sys
from html.parser import HTMLParser

import numpy as np
import pandas as pd
import pytest

import halfplane
from halfplane import _halfplane
from conftest import ROOT

REFERENCE = dict(
    youngs_modulus=200_000.0,
    poisson_ratio=0.3,
    friction=0.6,
    profile="hertz",
    radius=50.0,
    point1=(1000.0, -250.0, -20.0),
    point2=(1400.0, 250.0, 20.0),
)


class _Table(HTMLParser):
    """The rows of an HTML table as lists of cell texts, and its caption."""

    def __init__(self) -> None:
        super().__init__()
        self.rows: list = []
        self.caption = ""
        self._cell = None
        self._in_caption = False

    def handle_starttag(self, tag, attrs):
        if tag == "tr":
            self.rows.append([])
        elif tag in ("td", "th"):
            self._cell = ""
        elif tag == "caption":
            self._in_caption = True

    def handle_endtag(self, tag):
        if tag in ("td", "th"):
            self.rows[-1].append(self._cell)
            self._cell = None
        elif tag == "caption":
            self._in_caption = False

    def handle_data(self, data):
        if self._cell is not None:
            self._cell += data
        elif self._in_caption:
            self.caption += data


def table(html: str):
    parser = _Table()
    parser.feed(html)
    assert html.startswith("<table") and html.rstrip().endswith("</table>")
    return parser.caption, {row[0]: row[1:] for row in parser.rows}


def g(x: float) -> str:
    return f"{x:.6g}"


def test_the_native_module_returns_objects_not_text():
    # Failed before: steady_json/evolve_csv/fatigue_report/match_report returned JSON and CSV text.
    case = halfplane.Case(**REFERENCE)
    report, note = _halfplane.steady_report(case)
    assert isinstance(report, dict) and note is None
    assert type(report["stick_zone"]["left"]) is float
    columns, regime, _ = _halfplane.evolve_report(case, 5)
    assert regime == "partial-slip"
    assert columns["stick_left"].dtype == np.float64 and columns["half"].dtype == np.int64
    fatigue, _ = _halfplane.fatigue_report(halfplane.read_case(ROOT / "examples" / "fatigue.toml"), 32)
    assert isinstance(fatigue["parameters"]["value"], np.ndarray)


def test_steady_attributes_are_typed_records():
    result = halfplane.steady(halfplane.Case(**REFERENCE))
    assert dataclasses.is_dataclass(result)
    assert isinstance(result, halfplane.Record)
    assert isinstance(result.stick_zone, halfplane.StickZone)
    assert isinstance(result.slip_zones, halfplane.Edges)
    assert isinstance(result.slip_zones.left, halfplane.PerPoint)
    assert isinstance(result.points.at_point1, halfplane.LoadPoint)
    assert isinstance(result.criteria, halfplane.Criteria)
    assert isinstance(result.contact, halfplane.ContactState)
    assert isinstance(result.asymptotic, halfplane.Asymptotic)
    assert isinstance(result.asymptotic.slip_zones.right.at_point2, halfplane.Estimate)
    assert isinstance(result.profile, halfplane.Profile) and isinstance(result.units, halfplane.Units)
    for value in (
        result.stick_zone.left,
        result.slip_zones.left.at_point1,
        result.criteria.shear_ratio_1,
        result.contact.half_width_2,
        result.asymptotic.edges.at_point1.shear_intensity_left,
    ):
        assert type(value) is float
    assert result.profile.kinks == () and result.profile.radius == 50.0
    assert result.profile.flat_half_width is None and "flat_half_width" not in result.profile
    # A zone is consistent with its own definition: d = (m + n)/2, e = (n - m)/2 with [-m, n].
    z = result.stick_zone
    assert z.half_width == pytest.approx((z.right - z.left) / 2, rel=1e-15)
    assert z.eccentricity == pytest.approx((z.right + z.left) / 2, rel=1e-12)


def test_records_keep_item_access_iteration_and_to_dict():
    result = halfplane.steady(halfplane.Case(**REFERENCE))
    d = result.to_dict()
    assert list(result) == list(d) == result.keys()
    assert result["stick_zone"]["left"] == result.stick_zone.left == d["stick_zone"]["left"]
    assert result["slip_zones"].to_dict() == d["slip_zones"]
    with pytest.raises(KeyError):
        result["stick"]
    with pytest.raises(AttributeError, match="has no field 'stick'"):
        result.stick  # noqa: B018
    with pytest.raises(AttributeError):
        result.stick_zone.left = 0.0
    # to_dict is a copy: changing it leaves the record as it was.
    d["stick_zone"]["left"] = 0.0
    assert result.stick_zone.left != 0.0
    # JSON has no NaN: a number that is not finite is None in to_dict, as the command writes it.
    zone = halfplane.StickZone(left=math.nan, right=1.0, half_width=math.inf, eccentricity=0.0)
    assert zone.to_dict() == {"left": None, "right": 1.0, "half_width": None, "eccentricity": 0.0}


def test_gross_sliding_and_full_stick_have_their_fields():
    sliding = halfplane.steady(
        halfplane.Case(**{**REFERENCE, "point1": (1000.0, -700.0, 0.0), "point2": (1400.0, 250.0, 0.0)})
    )
    assert sliding.regime == "gross-sliding"
    assert sliding.stick_zone is None and sliding.slip_zones is None and sliding.asymptotic is None
    _, rows = table(sliding._repr_html_())
    assert rows["stick zone [-m, n] [mm]"] == ["none (gross sliding)"]
    stuck = halfplane.steady(
        halfplane.Case(**{**REFERENCE, "point1": (1000.0, -10.0, 0.0), "point2": (1400.0, 10.0, 0.0)})
    )
    assert stuck.regime == "full-stick"
    assert stuck.slip_zones.left.at_point1 == 0.0 and stuck.asymptotic is None


def test_steady_repr_and_html_show_the_main_quantities():
    result = halfplane.steady(halfplane.Case(**REFERENCE))
    z, s, c = result.stick_zone, result.slip_zones, result.contact
    text = repr(result)
    assert text == (
        f"SteadyResult(regime='partial-slip', half_widths=({g(c.half_width_1)}, "
        f"{g(c.half_width_2)}), stick_zone=[{g(z.left)}, {g(z.right)}], slip_zones={{left: "
        f"({g(s.left.at_point1)}, {g(s.left.at_point2)}), right: ({g(s.right.at_point1)}, "
        f"{g(s.right.at_point2)})}})"
    )
    caption, rows = table(result._repr_html_())
    assert caption == "SteadyResult (hertz)"
    assert rows[""] == ["point1", "point2"]
    assert rows["regime"] == ["partial-slip"]
    assert rows["contact half-width a [mm]"] == [g(c.half_width_1), g(c.half_width_2)]
    assert rows["stick zone [-m, n] [mm]"] == [f"[{g(z.left)}, {g(z.right)}]"]
    assert rows["slip zone left [mm]"] == [g(s.left.at_point1), g(s.left.at_point2)]
    assert rows["slip zone right [mm]"] == [g(s.right.at_point1), g(s.right.at_point2)]
    assert rows["|Q|/P"] == [g(0.25), g(250.0 / 1400.0)]
    assert rows["full-stick ratio, eq. (1)"] == [g(result.criteria.full_stick_ratio)]
    assert rows["normal P [N/mm]"] == ["1000", "1400"]
    # Units follow the case's.
    metres = halfplane.steady(
        halfplane.Case(**REFERENCE, units={"force": "kN", "length": "m", "stress": "GPa"})
    )
    assert "stick zone [-m, n] [m]" in table(metres._repr_html_())[1]


def test_march_repr_and_html_show_steps_cycles_and_the_final_state():
    marched = halfplane.march(halfplane.read_case(ROOT / "examples" / "march-cycle.toml"))
    last = marched.steps.iloc[-1]
    assert repr(marched) == (
        f"MarchResult({len(marched.steps)} increments, {len(marched.x)} cells, "
        f"{len(marched.cycles)} cycles, shakedown_cycle={marched.shakedown_cycle}, "
        f"steady_converged={marched.steady_converged}, no fields)"
    )
    caption, rows = table(marched._repr_html_())
    assert caption == "MarchResult"
    assert rows["increments"] == [str(len(marched.steps))]
    assert rows["cells"] == [str(len(marched.x))]
    assert rows["cycles run"] == [str(marched.cycles_run)]
    assert rows["shakedown cycle"] == [str(marched.shakedown_cycle)]
    assert rows["final state"] == ["partial slip"]
    assert rows["final stick zone (largest)"] == [f"[{g(last.stick_left)}, {g(last.stick_right)}]"]
    assert rows["energy of the last cycle"] == [g(marched.cycles.energy.iloc[-1])]
    assert rows["fields"] == ["not recorded"]
    # The march's final stick zone is the steady one to within a cell at each end.
    steady = halfplane.steady(halfplane.read_case(ROOT / "examples" / "march-cycle.toml"))
    cell = marched.x[1] - marched.x[0]
    assert abs(last.stick_left - steady.stick_zone.left) <= cell
    with pytest.raises(AttributeError):
        marched.steps = None


def test_march_final_state_says_full_stick_when_nothing_slips():
    case = halfplane.Case(
        **{**REFERENCE, "point1": (1000.0, -10.0, 0.0), "point2": (1000.0, 10.0, 0.0)},
        history={"kind": "cycle", "cycles": 1, "steps_per_half": 10, "ramp_steps": 5},
        cells=64,
    )
    marched = halfplane.march(case)
    assert marched.steps.energy.iloc[-1] == 0.0
    assert marched.final_state == "full stick"


def test_fatigue_result_is_typed_and_shows_its_parameters():
    got = halfplane.fatigue(halfplane.read_case(ROOT / "examples" / "fatigue.toml"), cells=64)
    assert dataclasses.is_dataclass(got) and isinstance(got.units, halfplane.Units)
    assert isinstance(got.parameters, pd.DataFrame)
    assert got.parameters["value"].dtype == np.float64 and got.parameters["step"].dtype == np.int64
    # .parameters is a copy: changing it leaves the result as it was.
    frame = got.parameters
    frame.loc[0, "value"] = -1.0
    assert got.parameters.loc[0, "value"] != -1.0
    assert got["first_step"] == got.first_step and "parameters" in list(got)
    assert got["parameters"] == got.to_dict()["parameters"]
    copy = pickle.loads(pickle.dumps(got))
    assert copy == got and copy.parameters.equals(got.parameters)
    caption, rows = table(got._repr_html_())
    assert f"steps {got.first_step} to {got.last_step}" in caption
    for r in got.parameters.itertuples():
        assert rows[r.parameter][:3] == [g(r.value), g(r.x), g(r.z)]
    first = got.parameters.iloc[0]
    assert f"{first.parameter}={g(first.value)}" in repr(got)


def test_match_result_is_typed_pickles_and_shows_the_mismatches():
    got = halfplane.match(halfplane.read_case(ROOT / "examples" / "flat-rounded.toml"), "hertz", radius=50.0)
    assert isinstance(got.normal_intensity.at_point2, halfplane.Mismatch)
    assert isinstance(got.prototype, halfplane.MatchSide)
    assert type(got.test.half_width.at_point1) is float
    assert "test_case" not in got.to_dict() and "test_case" not in list(got)
    copy = pickle.loads(pickle.dumps(got))
    assert copy == got and copy.test_case == got.test_case
    caption, rows = table(got._repr_html_())
    assert caption.startswith("MatchResult (asymptotic")
    assert rows["profile"][:2] == ["flat-rounded", "hertz"]
    k = got.normal_intensity.at_point2
    assert rows["K_N at point2"] == [g(k.prototype), g(k.test), f"{100 * k.mismatch:+.3f}%"]
    assert "mode='asymptotic'" in repr(got)


def test_stress_html_shows_the_increment_and_the_ranges():
    got = halfplane.stress(halfplane.read_case(ROOT / "examples" / "fatigue.toml"), [0.0, 0.5], 0.1, step=30)
    caption, rows = table(got._repr_html_())
    assert rows["step"] == ["30"]
    assert rows["sxx min, max"] == [f"{g(got.sxx.min())}, {g(got.sxx.max())}"]


def mypy(tmp_path, source):
    script = tmp_path / "script.py"
    script.write_text(source)
    return subprocess.run(
        [sys.executable, "-m", "mypy", "--strict", "--no-incremental", str(script)],
        capture_output=True,
        text=True,
        check=False,
        cwd=tmp_path,
    )


def test_mypy_strict_sees_the_attribute_types(tmp_path):
    good = mypy(
        tmp_path,
        "import halfplane\n"
        "r = halfplane.steady(halfplane.read_case('case.toml'))\n"
        "zone = r.stick_zone\n"
        "left: float = zone.left if zone is not None else 0.0\n"
        "ratio: float = r.criteria.shear_ratio_1\n"
        "slip = r.slip_zones.left.at_point1 if r.slip_zones is not None else 0.0\n"
        "m = halfplane.march(halfplane.read_case('case.toml'))\n"
        "n: int = m.cells + m.increments\n"
        "w = halfplane.wear(halfplane.read_case('case.toml'))\n"
        "k: int = w.cells + w.cycles + w.depth.shape[0]\n"
        "marched = w.simulated_cycles if w.simulated_cycles is not None else 0\n",
    )
    assert good.returncode == 0, good.stdout + good.stderr
    bad = mypy(
        tmp_path,
        "import halfplane\n"
        "r = halfplane.steady(halfplane.read_case('case.toml'))\n"
        "a: str = r.criteria.shear_ratio_1\n"
        "b = r.stick_zone.left\n"
        "c = r.no_such_field\n",
    )
    assert bad.returncode == 1
    assert 'Incompatible types in assignment (expression has type "float"' in bad.stdout
    assert "Item \"None\" of \"StickZone | None\" has no attribute \"left\"" in bad.stdout or (
        'Item "None" of "Optional[StickZone]" has no attribute "left"' in bad.stdout
    )
    assert '"SteadyResult" has no attribute "no_such_field"' in bad.stdout
