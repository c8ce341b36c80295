"""Ctrl-C interrupts a long ``halfplane.march`` (a real SIGINT, as a terminal sends)."""

from __future__ import annotations

import os
import signal
import threading
import time

import pytest

import halfplane
from conftest import ROOT


def test_ctrl_c_interrupts_a_long_march():
    # 1,000 cycles of 90 increments on 1,000 cells take minutes; SIGINT after 0.5 s must end the
    # call at the next signal check (every 50 ms, between increments of ~1 ms) with
    # KeyboardInterrupt, well within the 10 s allowed for a loaded machine.
    text = (ROOT / "examples" / "march-cycle.toml").read_text()
    case = halfplane.Case.from_toml(text.replace("cycles = 3", "cycles = 1000"))
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        halfplane.march(case, cells=1000)
    elapsed = time.monotonic() - start
    timer.cancel()
    assert elapsed < 10.0, f"interrupt seen only after {elapsed:.1f} s"
    # The interrupted call left nothing behind: the same case still marches to the end.
    short = halfplane.Case.from_toml(text)
    assert len(halfplane.march(short).steps) == 300
