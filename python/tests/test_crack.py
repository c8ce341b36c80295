"""`halfplane.crack` gives the command's numbers (compared exactly: the same library analysis and
report rows, built in the same cargo profile), takes `[crack]` fields as keywords with the
section's checks, and its result is a typed, pickling record whose rows are a DataFrame."""

from __future__ import annotations

import json
import pickle

import numpy as np
import pandas as pd
import pytest

import halfplane
from conftest import ROOT, assert_attributes_equal, assert_table_equals_the_csv, run_cli

CRACK = str(ROOT / "examples" / "crack.toml")


def cli_json(cli, args):
    done = run_cli(cli, args)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


@pytest.fixture(scope="module")
def example():
    return halfplane.crack(halfplane.read_case(CRACK))


def test_crack_equals_the_command(cli, example):
    expected = cli_json(cli, ["crack", CRACK, "--json"])
    assert example.to_dict() == expected
    assert_attributes_equal(example, expected, skip=("rows",))
    assert example.verdict in ("arrests", "propagates", "no-growth")
    assert (example.arrest_length is None) == (example.verdict != "arrests")
    done = run_cli(cli, ["crack", CRACK, "--csv"])
    assert done.returncode == 0, done.stderr
    assert_table_equals_the_csv(example.rows, done.stdout)
    assert example.intensity_unit == "MPa sqrt(mm)"
    assert example.units.length == "mm"


def test_rows_are_a_typed_frame_and_a_copy(example):
    rows = example.rows
    assert isinstance(rows, pd.DataFrame)
    assert list(rows.columns) == [
        "length", "k1_max", "k1_min", "k2_max", "k2_min",
        "delta_k1", "delta_k2", "delta_k_eff", "threshold",
    ]
    assert all(rows[c].dtype == np.float64 for c in rows.columns)
    assert (rows["k1_min"] >= 0).all()
    rows.loc[0, "length"] = -1.0
    assert example.rows.loc[0, "length"] > 0
    assert example["verdict"] == example.verdict
    assert example["rows"][0]["length"] == example.rows.loc[0, "length"]


def test_results_pickle(example):
    copy = pickle.loads(pickle.dumps(example))
    assert copy == example
    pd.testing.assert_frame_equal(copy.rows, example.rows)
    assert type(copy).__module__ == "halfplane"
    assert "CrackResult(" in repr(example) and "<table" in example._repr_html_()


def test_keywords_replace_the_sections_fields(cli, tmp_path):
    # The same as the command on a case file with those fields written in [crack].
    text = open(CRACK).read().replace(
        "lengths = { from = 0.002, to = 0.3, count = 20 }", "lengths = [0.01, 0.05]"
    ).replace("face_friction = 0.0", "face_friction = 0.3\nposition = \"right-edge\"")
    path = tmp_path / "case.toml"
    path.write_text(text)
    expected = cli_json(cli, ["crack", str(path), "--json"])
    got = halfplane.crack(
        halfplane.read_case(CRACK),
        lengths=np.array([0.01, 0.05]),
        face_friction=0.3,
        position="right-edge",
    )
    assert got.to_dict() == expected
    assert got.position > 0


def test_critical_plane_angle_from_python():
    got = halfplane.crack(
        halfplane.read_case(CRACK),
        lengths=[0.01],
        position=-0.7,
        angle="critical-plane",
        initiation_parameter="swt",
    )
    assert -90 < got.angle < 90 and got.angle != 0.0


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"lengths": [0.0]}, "crack.lengths = 0"),
        ({"lengths": [0.01, -0.02]}, "crack.lengths = -0.02"),
        ({"lengths": [0.01, 5.0]}, "crack.lengths = 5"),
        ({"lengths": ["short"]}, "crack.lengths"),
        ({"angle": 95.0}, "crack.angle = 95"),
        ({"angle": float("nan")}, "crack.angle"),
        ({"position": "middle"}, "crack.position"),
        ({"face_friction": -1.0}, "crack.face_friction = -1"),
        ({"initiation_parameter": "swt"}, "crack.initiation_parameter"),
        ({"cells": -3}, "cells"),
    ],
)
def test_bad_input_names_the_field(kwargs, field):
    with pytest.raises(halfplane.InputError, match=field.replace(".", r"\.")) as raised:
        halfplane.crack(halfplane.read_case(CRACK), **kwargs)
    assert isinstance(raised.value, ValueError)


def test_a_case_without_the_threshold_constants(cli, tmp_path):
    text = open(CRACK).read()
    cut = text[: text.index("[fatigue]")] + text[text.index("[crack]"):]
    path = tmp_path / "case.toml"
    path.write_text(cut)
    with pytest.raises(halfplane.InputError, match="fatigue.threshold and fatigue.endurance_range"):
        halfplane.crack(halfplane.read_case(str(path)))
    done = run_cli(cli, ["crack", str(path)])
    assert done.returncode == 2
