"""`stress`, `fatigue` and `match` give the command's numbers: compared exactly, because the
package calls the same library functions and report rows as the command (the CLI's
`commands::stress::report`, `fatigue::analyse` with `FatigueReport`, `commands::matching::compute`),
both built in the same cargo profile, and the command's numbers are parsed from their shortest
round-trip text. Bad input raises InputError (a ValueError) naming the field."""

from __future__ import annotations

import json
import os

import numpy as np
import pandas as pd
import pytest

import halfplane
from conftest import ROOT, assert_attributes_equal, assert_table_equals_the_csv, run_cli

FATIGUE = "examples/fatigue.toml"
FLAT_ROUNDED = "examples/flat-rounded.toml"


@pytest.fixture(autouse=True)
def at_root():
    before = os.getcwd()
    os.chdir(ROOT)
    yield
    os.chdir(before)


def cli_json(cli, args):
    done = run_cli(cli, args)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


POINTS_X = [-1.2, -0.4, 0.0, 0.3, 0.9, 1.5]
POINTS_Z = [0.05, 0.1, 0.2, 0.02, 0.4, 0.8]


@pytest.mark.parametrize("step", [None, 1, 25, 95])
def test_stress_equals_the_command(cli, tmp_path, step):
    points = tmp_path / "points.csv"
    points.write_text("x,z\n" + "".join(f"{x!r},{z!r}\n" for x, z in zip(POINTS_X, POINTS_Z)))
    args = ["stress", FATIGUE, "--at", str(points), "--json"]
    if step is not None:
        args += ["--step", str(step)]
    expected = cli_json(cli, args)
    got = halfplane.stress(halfplane.read_case(FATIGUE), POINTS_X, POINTS_Z, step=step)
    assert got.step == expected["step"]
    for key in ("normal", "shear", "bulk", "half_width"):
        assert getattr(got, key) == expected[key], f"the load at the increment differs: {key}"
    for key in ("sxx", "szz", "syy", "sxz"):
        want = np.array([p[key] for p in expected["points"]])
        np.testing.assert_array_equal(got.to_dict()[key], want, err_msg=f"stress {key}")


def test_stress_broadcasts_and_keeps_the_shape():
    case = halfplane.read_case(FATIGUE)
    x = np.linspace(-1.0, 1.0, 6).reshape(2, 3)
    grid = halfplane.stress(case, x, 0.25, step=40)
    flat = halfplane.stress(case, x.ravel(), np.full(6, 0.25), step=40)
    assert grid.sxx.shape == (2, 3)
    np.testing.assert_array_equal(grid.sxz.ravel(), flat.sxz)
    # Plane strain: syy = nu (sxx + szz), the identity the report documents.
    nu = case.poisson_ratio
    np.testing.assert_allclose(grid.syy, nu * (grid.sxx + grid.szz), rtol=1e-12, atol=1e-9)


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"x": 0.0, "z": -0.1}, "z"),
        ({"x": float("nan"), "z": 0.1}, "x"),
        ({"x": 0.0, "z": 0.1, "step": 0}, "step"),
        ({"x": 0.0, "z": 0.1, "step": 10**6}, "step"),
        ({"x": 0.0, "z": 0.1, "step": -3}, "step"),
        ({"x": "a", "z": 0.1}, "x"),
    ],
)
def test_stress_rejects_bad_input_naming_the_field(kwargs, field):
    with pytest.raises(halfplane.InputError, match=field) as raised:
        halfplane.stress(halfplane.read_case(FATIGUE), **kwargs)
    assert isinstance(raised.value, ValueError)


def test_fatigue_equals_the_command(cli):
    expected = cli_json(cli, ["fatigue", FATIGUE, "--json"])
    got = halfplane.fatigue(halfplane.read_case(FATIGUE))
    assert got.to_dict() == expected
    assert_attributes_equal(got, expected, skip=("parameters",))
    assert got.critical_distance == expected["critical_distance"]
    assert (got.first_step, got.last_step) == (expected["first_step"], expected["last_step"])
    done = run_cli(cli, ["fatigue", FATIGUE, "--csv"])
    assert done.returncode == 0, done.stderr
    assert_table_equals_the_csv(got.parameters, done.stdout)


def test_fatigue_warns_about_each_parameter_it_leaves_out(cli, tmp_path):
    # Failed before: a [fatigue] section without fatemi_socie_k dropped its rows silently.
    text = open(FATIGUE).read().replace("fatemi_socie_k = 0.5", "")
    text = text.replace("nx = 60", "nx = 8").replace("nz = 30", "nz = 4")
    path = tmp_path / "case.toml"
    path.write_text(text)
    with pytest.warns(UserWarning) as caught:
        got = halfplane.fatigue(halfplane.read_case(str(path)))
    done = run_cli(cli, ["fatigue", str(path), "--csv"])
    assert done.returncode == 0, done.stderr
    assert [f"warning: {w.message}" for w in caught] == done.stderr.splitlines()
    assert len(caught) == 2 and "fatigue.fatemi_socie_k" in str(caught[0].message)
    assert "fatemi_socie" not in set(got.parameters["parameter"])


def test_fatigue_names_what_the_case_lacks(cli):
    # No [history]: the command's message, word for word.
    with pytest.raises(halfplane.InputError, match=r"\[history\]") as raised:
        halfplane.fatigue(halfplane.read_case(FLAT_ROUNDED))
    done = run_cli(cli, ["fatigue", FLAT_ROUNDED])
    assert done.returncode == 2
    assert done.stderr.splitlines()[0] == f"error: {raised.value}"
    with pytest.raises(halfplane.InputError, match="cells"):
        halfplane.fatigue(halfplane.read_case(FATIGUE), cells=-1)


def test_match_equals_the_command(cli, tmp_path):
    output = tmp_path / "test.toml"
    args = ["match", FLAT_ROUNDED, "--profile", "hertz", "--radius", "50", "--exact", "--json"]
    expected = cli_json(cli, args + ["-o", str(output)])
    got = halfplane.match(halfplane.read_case(FLAT_ROUNDED), "hertz", radius=50, exact=True)
    expected["prototype_file"] = None
    expected["test_file"] = None
    assert got.to_dict() == expected
    assert_attributes_equal(got, expected)
    written = output.read_text()
    # The text differs only in the header's prototype name (the package reads no file).
    assert got.test_case_text.splitlines()[1:] == written.splitlines()[1:]
    assert got.test_case == halfplane.Case.from_toml(written)
    assert got.test_case.profile == "hertz"
    assert halfplane.steady(got.test_case).regime == expected["test"]["regime"]


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"profile": "hertz"}, "radius"),
        ({"profile": "hertz", "radius": -1.0}, "radius"),
        ({"profile": "hertz", "radius": 50.0, "friction": -0.2}, "friction"),
        ({"profile": "hertz", "radius": 50.0, "exponent": 2.0}, "exponent"),
        ({"profile": "cylinder", "radius": 50.0}, "profile"),
        ({"profile": "hertz", "radius": "big"}, "radius"),
    ],
)
def test_match_rejects_bad_input_naming_the_field(kwargs, field):
    with pytest.raises(halfplane.InputError, match=field) as raised:
        halfplane.match(halfplane.read_case(FLAT_ROUNDED), **kwargs)
    assert isinstance(raised.value, ValueError)


def test_the_readme_example_runs(capsys):
    import re

    text = (ROOT / "README.md").read_text()
    block = next(
        b for b in re.findall(r"```python\n(.*?)```", text, flags=re.S) if "halfplane.fatigue(" in b
    )
    exec(compile("import halfplane\n" + block, "README.md", "exec"), {})
    printed = capsys.readouterr().out
    assert "swt" in printed and "findley" in printed, printed
