"""Moment-loaded and asymmetric contacts from Python: the keywords reach the analyses, the typed
results carry the contact's ends, K_N per edge and rotation, and Python gives the command's
numbers (the same library code through the same case reader, so equal to the last digit)."""

from __future__ import annotations

import json
import pickle

import pytest

import halfplane
from conftest import ROOT, run_cli

DOVETAIL = ROOT / "examples" / "dovetail.toml"


def test_the_dovetail_example_gives_the_commands_numbers(cli):
    case = halfplane.read_case(DOVETAIL)
    assert case.moments == (200.0, 350.0)
    result = halfplane.steady(case)
    expected = json.loads(run_cli(cli, ["steady", str(DOVETAIL), "--json"]).stdout)
    c, e = result.contact, expected["contact"]
    for key in (
        "left_1",
        "right_1",
        "left_2",
        "right_2",
        "normal_intensity_left_1",
        "normal_intensity_right_2",
        "rotation_1",
        "rotation_2",
    ):
        assert getattr(c, key) == e[key], key
    assert c.normal_intensity_1 is None and e["normal_intensity_1"] is None
    assert result.stick_zone.left == expected["stick_zone"]["left"]
    assert result.points.at_point2.moment == 350.0
    assert result.profile.left_radius == 10.0 and result.profile.right_radius == 25.0
    assert result.profile.radius is None


def test_keywords_build_the_same_case_as_the_file():
    case = halfplane.Case(
        youngs_modulus=115000.0,
        poisson_ratio=0.32,
        friction=0.5,
        profile="flat-rounded",
        flat_half_width=1.0,
        left_radius=10.0,
        right_radius=25.0,
        point1=(1800.0, -200.0, 100.0, 200.0),
        point2={"normal": 2400.0, "shear": 600.0, "bulk": 150.0, "moment": 350.0},
    )
    from_file = halfplane.steady(halfplane.read_case(DOVETAIL))
    here = halfplane.steady(case)
    assert here.stick_zone == from_file.stick_zone
    assert "left_radius=10.0" in repr(case) and "moments=(200.0, 350.0)" in repr(case)
    copy = pickle.loads(pickle.dumps(case))
    assert copy == case and copy.moments == (200.0, 350.0)


def test_a_symmetric_contact_reports_centred_ends_and_one_intensity():
    case = halfplane.Case(
        youngs_modulus=200_000.0,
        poisson_ratio=0.3,
        friction=0.6,
        profile="hertz",
        radius=50.0,
        point1=(1000.0, -250.0, -20.0),
        point2=(1400.0, 250.0, 20.0),
    )
    c = halfplane.steady(case).contact
    assert c.left_1 == -c.right_1 == -c.half_width_1
    assert c.normal_intensity_1 == c.normal_intensity_left_1 == c.normal_intensity_right_1
    assert c.rotation_1 == 0.0 and case.moments == (0.0, 0.0)


def test_march_rows_carry_the_moment_and_both_ends():
    case = halfplane.read_case(DOVETAIL)
    result = halfplane.march(case, cells=200)
    steps = result.steps
    last = steps.iloc[-1]
    assert last.moment == 200.0
    # Off centre, towards +x (M > 0), with the half-width between the ends.
    assert last.contact_left + last.contact_right > 0.0
    assert last.contact_right - last.contact_left == pytest.approx(2 * last.half_width, rel=1e-14)


def test_history_rows_may_carry_a_moment_column():
    rows = [(500.0, 0.0, 0.0, 40.0), (1000.0, 0.0, 0.0, 80.0), (1000.0, 300.0, 0.0, 80.0)]
    case = halfplane.Case(
        youngs_modulus=200_000.0,
        poisson_ratio=0.3,
        friction=0.6,
        profile="hertz",
        radius=50.0,
        history=rows,
    )
    steps = halfplane.march(case, cells=100).steps
    # Hertz: the contact under M = e P is the symmetric one moved by e = 0.08.
    centre = 0.5 * (steps.contact_left + steps.contact_right)
    assert list(centre) == pytest.approx([0.08] * 3, rel=1e-12)
    with pytest.raises(halfplane.InputError, match="history row 2"):
        halfplane.Case(
            youngs_modulus=200_000.0,
            poisson_ratio=0.3,
            friction=0.6,
            profile="hertz",
            radius=50.0,
            history=[(500.0, 0.0, 0.0, 40.0), (1000.0, 0.0, 0.0)],
        )


def test_a_moment_outside_a_table_is_an_input_error_naming_the_point():
    x = [-1.0 + 0.05 * i for i in range(41)]
    g = [t * t / 100.0 for t in x]
    case = halfplane.Case(
        youngs_modulus=200_000.0,
        poisson_ratio=0.3,
        friction=0.6,
        profile="tabulated",
        table=(x, g),
        point1=(1000.0, -250.0, -20.0, 0.0),
        point2=(1400.0, 250.0, 20.0, 900.0),
    )
    with pytest.raises(halfplane.HalfplaneError) as error:
        halfplane.steady(case)
    assert "cycle.point2.moment" in str(error.value) and "900" in str(error.value)


def test_match_takes_the_chosen_edge():
    case = halfplane.read_case(DOVETAIL)
    results = {
        edge: halfplane.match(case, "hertz", radius=80.0, edge=edge)
        for edge in ("left", "right")
    }
    for edge, result in results.items():
        assert result.matched_edge == edge
    left, right = results["left"], results["right"]
    assert left.normal_intensity.at_point1.test != right.normal_intensity.at_point1.test
    with pytest.raises(halfplane.InputError, match="edge"):
        halfplane.match(case, "hertz", radius=80.0, edge="middle")
