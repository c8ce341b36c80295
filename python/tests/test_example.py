"""examples/python/fig5_slip_map.py: its map against the Hertz closed form, and the script run
end to end (when matplotlib is installed)."""

from __future__ import annotations

import runpy
import subprocess
import sys

import numpy as np
import pytest

from conftest import ROOT

SCRIPT = ROOT / "examples" / "python" / "fig5_slip_map.py"


def test_the_map_follows_the_hertz_closed_form():
    # With P2 = P1 and no tension the stick zone is centred with d^2 = (AR/pi)(2 P0 - dQ/f)
    # (paper eq. (30)) and a0^2 = 2 P0 A R/pi, so y = 1 - sqrt(1 - x/2): an independent check of
    # the batch through the script's own arithmetic (1e-12: rounding of a few operations).
    points = runpy.run_path(str(SCRIPT))["slip_map"]()
    plain = points[(points.ratio == 1.0) & (points.tension == 0.0)]
    assert len(plain) == 2 * 59 and (plain.error == "").all()
    expected = 1.0 - np.sqrt(1.0 - plain.x / 2.0)
    assert np.allclose(plain.y, expected, rtol=1e-12, atol=1e-12)
    # With tension the curves stop before the full-stick limit (slip would reverse in a half).
    tension = points[points.tension == 0.05]
    assert (tension.error != "").any() and (tension.error == "").any()


def test_the_script_draws_the_figure(tmp_path):
    pytest.importorskip("matplotlib")
    output = tmp_path / "figure5.png"
    done = subprocess.run(
        [sys.executable, str(SCRIPT), "-o", str(output)], capture_output=True, text=True, check=False
    )
    assert done.returncode == 0, done.stderr
    assert output.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and output.stat().st_size > 20_000


def test_the_script_writes_into_target_unless_told(tmp_path):
    # Run from a copy of the layout: its default output must land in target/, never in the
    # directory it runs from (it used to write figure5-slip-map.png into the repository root).
    pytest.importorskip("matplotlib")
    done = subprocess.run(
        [sys.executable, str(SCRIPT)], capture_output=True, text=True, check=False, cwd=tmp_path
    )
    assert done.returncode == 0, done.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["target"]
    assert (tmp_path / "target" / "figure5-slip-map.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
