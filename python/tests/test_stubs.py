"""The type stubs match the installed package (mypy's stubtest), and the public API is typed."""

from __future__ import annotations

import subprocess
import sys


def test_stubtest_finds_no_mismatch():
    done = subprocess.run(
        [sys.executable, "-m", "mypy.stubtest", "halfplane"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 0, done.stdout + done.stderr
