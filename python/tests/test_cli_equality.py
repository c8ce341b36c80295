"""Every bundled example gives the command's numbers: `steady --json`, `evolve --csv` and
`march --csv`/`--json`, compared exactly (the package runs the same parser, solver and report rows,
converted to Python objects without text; the command's numbers are parsed from its shortest
round-trip text, which reads back to the same float). The typed attributes are compared, not only
`to_dict()`. Where the command fails (exit 2), the package raises with the command's message."""

from __future__ import annotations

import json
import os

import numpy as np
import pandas as pd
import pytest

import halfplane
from conftest import (
    EXAMPLES,
    ROOT,
    assert_attributes_equal,
    assert_table_equals_the_csv,
    read_csv,
    run_cli,
)

IDS = [p.name for p in EXAMPLES]


@pytest.fixture(autouse=True)
def at_root():
    # Relative paths, as the command is given them, so that messages match word for word.
    before = os.getcwd()
    os.chdir(ROOT)
    yield
    os.chdir(before)


def relative(path):
    return str(path.relative_to(ROOT))


def cli_error(done):
    assert done.returncode == 2, done.stderr
    first = done.stderr.splitlines()[0]
    assert first.startswith("error: ")
    return first[len("error: "):]


def test_there_are_examples_of_every_kind():
    assert len(EXAMPLES) >= 9, "the bundled examples went missing"


@pytest.mark.parametrize("path", EXAMPLES, ids=IDS)
def test_steady_equals_the_command(cli, path):
    done = run_cli(cli, ["steady", relative(path), "--json"])
    case = halfplane.read_case(relative(path))
    if done.returncode == 0:
        result = halfplane.steady(case)
        assert result.to_dict() == json.loads(done.stdout)
        assert_attributes_equal(result, json.loads(done.stdout))
    else:
        with pytest.raises(halfplane.HalfplaneError) as raised:
            halfplane.steady(case)
        assert str(raised.value).startswith(cli_error(done))


@pytest.mark.parametrize("path", EXAMPLES, ids=IDS)
def test_evolve_equals_the_command(cli, path):
    done = run_cli(cli, ["evolve", relative(path), "--points", "9", "--csv"])
    case = halfplane.read_case(relative(path))
    if done.returncode == 0:
        frame = halfplane.evolve(case, points=9)
        assert_table_equals_the_csv(frame, done.stdout)
    else:
        with pytest.raises(halfplane.HalfplaneError) as raised:
            halfplane.evolve(case, points=9)
        assert str(raised.value).startswith(cli_error(done))


@pytest.mark.parametrize("path", EXAMPLES, ids=IDS)
def test_march_equals_the_command(cli, path):
    csv = run_cli(cli, ["march", relative(path), "--csv"])
    case = halfplane.read_case(relative(path))
    if csv.returncode != 0:
        with pytest.raises(halfplane.HalfplaneError) as raised:
            halfplane.march(case)
        assert str(raised.value).startswith(cli_error(csv))
        return
    result = halfplane.march(case, fields=True)
    assert_table_equals_the_csv(result.steps, csv.stdout)
    report = json.loads(run_cli(cli, ["march", relative(path), "--json"]).stdout)
    assert result.cycles.to_dict("records") == report["cycles"]
    assert result.shakedown_cycle == report["shakedown_cycle"]
    assert result.cycles_run == report["cycles_run"]
    assert result.steady_change == report["steady_change"]
    assert result.steady_converged == report["steady_converged"]
    assert result.loop_datum == report["loop_datum"]
    assert list(result.steps["relative_displacement"]) == [
        s["relative_displacement"] for s in report["steps"]
    ]
    assert result.cells == report["cells"]
    assert result.x[1] - result.x[0] == report["cell_width"]
    increments = len(report["steps"])
    for name in ("pressure", "traction", "slip", "slip_increment"):
        assert getattr(result, name).shape == (increments, result.cells)


def test_march_fields_equal_the_command_field_files(cli, tmp_path):
    # `march --fields DIR` writes x, pressure, traction, slip, slip_increment per increment.
    path = "examples/march-history.toml"
    done = run_cli(cli, ["march", path, "--fields", str(tmp_path), "--csv"])
    assert done.returncode == 0, done.stderr
    result = halfplane.march(halfplane.read_case(path), fields=True)
    for step in (1, result.increments // 2, result.increments):
        table = read_csv((tmp_path / f"step_{step:05d}.csv").read_text())
        assert np.array_equal(table["x"].to_numpy(), result.x)
        for name in ("pressure", "traction", "slip", "slip_increment"):
            assert np.array_equal(table[name].to_numpy(), getattr(result, name)[step - 1]), name


def test_cells_override_as_the_command(cli):
    path = "examples/march-cycle.toml"
    done = run_cli(cli, ["march", path, "--cells", "64", "--csv"])
    result = halfplane.march(halfplane.read_case(path), cells=64)
    assert_table_equals_the_csv(result.steps, done.stdout)
    bad = run_cli(cli, ["march", path, "--cells", "7"])
    with pytest.raises(halfplane.InputError) as raised:
        halfplane.march(halfplane.read_case(path), cells=7)
    # The same message, naming the keyword the Python caller wrote instead of the flag.
    assert str(raised.value) == cli_error(bad).replace("--cells", "cells")
    assert "--cells" not in str(raised.value)
