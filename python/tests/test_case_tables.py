"""Tables inside cases: a case holds its profile table and history rows inline (``data``), so it
is complete in itself, re-parses from memory and never writes a file, ``match`` included."""

from __future__ import annotations

import os
import pickle
from pathlib import Path

import numpy as np

import halfplane
from conftest import ROOT, run_cli

X = np.linspace(0.0, 2.0, 41)
TABULATED = dict(
    youngs_modulus=2e5, poisson_ratio=0.3, friction=0.6, profile="tabulated",
    table=(X, X**2 / 100.0), point1=(1000.0, -250.0), point2=(1400.0, 250.0),
)


def test_a_case_with_tables_is_complete_in_its_toml(tmp_path: Path) -> None:
    rows = [[1000.0, 0.0, 0.0], [1000.0, 200.0, 0.0], [1000.0, -100.0, 0.0]]
    case = halfplane.Case(**TABULATED, history=rows)
    text = case.to_toml()
    assert "data = " in text and "file = " not in text, text
    assert set(case.tables) == {"profile.csv", "history.csv"}
    # Read back from elsewhere, where no table file exists: the text is enough.
    here = os.getcwd()
    os.chdir(tmp_path)
    try:
        again = halfplane.Case.from_toml(text)
    finally:
        os.chdir(here)
    assert again == case and list(tmp_path.iterdir()) == []
    assert halfplane.steady(again) == halfplane.steady(case)


def test_a_file_case_and_its_inline_form_are_the_same_case() -> None:
    for name in ["tabulated.toml", "march-history.toml"]:
        from_file = halfplane.read_case(ROOT / "examples" / name)
        inline = halfplane.Case.from_toml(from_file.to_toml())
        assert inline == from_file
        assert pickle.loads(pickle.dumps(inline)) == from_file


OLD_STATE = """[material]
youngs_modulus = 200000.0
poisson_ratio = 0.3

[friction]
coefficient = 0.6

[profile]
kind = "tabulated"
file = "profile.csv"
"""


def test_pickles_with_separate_tables_still_load() -> None:
    # The state pickles held before tables were inline: the text names profile.csv, the table
    # travels beside it.
    csv = "x,g\n0.0,0.0\n1.0,0.01\n2.0,0.04\n"
    old = halfplane._halfplane._case_from_state(OLD_STATE, {"profile.csv": csv})
    new = halfplane.Case(youngs_modulus=2e5, poisson_ratio=0.3, friction=0.6,
                         profile="tabulated", table=([0.0, 1.0, 2.0], [0.0, 0.01, 0.04]))
    assert old == new and old.tables == {"profile.csv": csv}


def test_match_maps_a_history_without_writing_it(cli: Path, tmp_path: Path) -> None:
    rows = [[600.0, 0.0, 0.0], [1000.0, 0.0, 0.0], [1000.0, 200.0, 0.0], [1000.0, -150.0, 0.0]]
    prototype = halfplane.Case(**TABULATED, history=rows)
    (tmp_path / "proto.toml").write_text(prototype.to_toml())
    here = os.getcwd()
    os.chdir(tmp_path)
    try:
        got = halfplane.match(prototype, "hertz", radius=50.0)
    finally:
        os.chdir(here)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["proto.toml"]
    output = tmp_path / "test.toml"
    done = run_cli(cli, ["match", str(tmp_path / "proto.toml"), "--profile", "hertz",
                         "--radius", "50", "-o", str(output)])
    assert done.returncode == 0, done.stderr
    written = (tmp_path / "test-history.csv").read_text()
    assert got.test_case.tables["history.csv"] == written
    assert got.test_case == halfplane.Case.from_toml(output.read_text(), base_dir=tmp_path)
