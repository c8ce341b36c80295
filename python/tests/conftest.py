"""Shared fixtures: the repository, its bundled examples and the `halfplane` command to compare
with (HALFPLANE_CLI, else target/debug/halfplane, built on demand)."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path
from typing import List

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
