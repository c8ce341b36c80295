"""Shared fixtures: the repository, its bundled examples and the `halfplane` command to compare
with (HALFPLANE_CLI, else target/debug/halfplane, built on demand)."""

from __future__ import annotations

import io
import os
import subprocess
from pathlib import Path
from typing import List

import numpy as np
import pandas as pd
import pytest

ROOT = Path(__file__).resolve().parents[2]
#: The bundled case files; sweep specifications (a case template plus a `[sweep]` table, read by
#: `halfplane sweep`, not by the case parser) are not cases.
EXAMPLES = sorted(
    p for p in (ROOT / "examples").glob("*.toml") if "\n[sweep]" not in "\n" + p.read_text()
)


@pytest.fixture(scope="session")
def cli() -> Path:
    """The command, built with the same cargo profile as the extension (scripts/test builds both
    in the dev profile): numbers are compared exactly, and a differently optimised build may
    differ in the last bit."""
    given = os.environ.get("HALFPLANE_CLI")
    if given:
        return Path(given)
    subprocess.run(
        ["cargo", "build", "--quiet", "-p", "halfplane-cli"], cwd=ROOT, check=True
    )
    return ROOT / "target" / "debug" / "halfplane"


def run_cli(cli: Path, args: List[str]) -> subprocess.CompletedProcess:
    """Runs the command from the repository root (so paths in messages match)."""
    return subprocess.run(
        [str(cli), *args], cwd=ROOT, capture_output=True, text=True, check=False
    )


def read_csv(text):
    exact = {"float_precision": "round_trip"} if int(pd.__version__.split(".")[0]) < 3 else {}
    return pd.read_csv(io.StringIO(text), **exact)


#: Columns of whole numbers (counts, indices); every other numeric column is float64.
INTEGER_COLUMNS = {"half", "step", "passes", "index", "cycle"}


def assert_table_equals_the_csv(frame, text):
    """`frame` holds the command's CSV `text` exactly, column by column, with typed columns:
    int64 for counts, float64 for every other number (the CSV reader makes a column int64 when
    all its numbers happen to be whole, e.g. loads of 1000; the typed frame does not)."""
    expected = read_csv(text)
    assert list(frame.columns) == text.splitlines()[0].split(",")
    for name in frame.columns:
        if name in INTEGER_COLUMNS:
            assert frame[name].dtype == np.int64, name
        elif pd.api.types.is_numeric_dtype(expected[name]):
            assert frame[name].dtype == np.float64, name
            expected[name] = expected[name].astype(np.float64)
    pd.testing.assert_frame_equal(frame, expected, check_exact=True)


def assert_attributes_equal(record, expected, path="result", skip=()):
    """Every key of the command's JSON object `expected` (but those in `skip`) is an attribute of
    `record` holding the same value (nested objects as records, lists as tuples, null as None),
    and a number is a Python float or int, not a string."""
    assert [k for k in record if k not in skip] == [k for k in expected if k not in skip], path
    for key, want in expected.items():
        if key in skip:
            continue
        got = getattr(record, key)
        where = f"{path}.{key}"
        if isinstance(want, dict):
            assert_attributes_equal(got, want, where)
        elif isinstance(want, list):
            assert list(got) == want, where
        elif isinstance(want, bool) or want is None or isinstance(want, str):
            assert got == want and type(got) is type(want), where
        else:
            assert isinstance(got, (int, float)) and got == want, where
