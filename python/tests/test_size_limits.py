"""A march that cannot finish, or whose fields cannot fit in memory, is refused before it starts
(``InputError`` with variant ``"TooLarge"``, naming the estimate and the limit), unless
``no_size_limit=True``."""

from __future__ import annotations

import os
import signal
import threading
import time

import pytest

import halfplane
from conftest import ROOT

CYCLE = (ROOT / "examples" / "march-cycle.toml").read_text()


def test_a_million_cells_with_fields_is_refused_at_once():
    case = halfplane.Case.from_toml(CYCLE)
    start = time.monotonic()
    with pytest.raises(halfplane.InputError) as raised:
        halfplane.march(case, cells=10**6, fields=True)
    elapsed = time.monotonic() - start
    message = str(raised.value)
    # 1e12 cells² x 300 increments x 5e-10 s = 1.5e5 s: the time limit is met first.
    for part in ("cells=1000000 with 300 increments", "41.7 hours", "limit of 8.0 hours", "no_size_limit=True"):
        assert part in message, message
    assert raised.value.variant == "TooLarge"
    # Refused before any solving (measured in milliseconds; the margin is for a loaded machine).
    assert elapsed < 10.0, elapsed


def test_fields_too_large_for_memory_are_refused():
    # 1000 cycles of 90 increments and a ramp of 30 (90,030 increments) on 2000 cells: the march
    # is 4e6 x 90,030 x 5e-10 s = 180 s, but the fields need 32 bytes x 2000 x 90,030 = 5.8 GB.
    case = halfplane.Case.from_toml(CYCLE.replace("cycles = 3", "cycles = 1000"))
    with pytest.raises(halfplane.InputError) as raised:
        halfplane.march(case, cells=2000, fields=True)
    message = str(raised.value)
    for part in ("cells=2000 with fields recorded at 90030 increments", "5.8 GB", "limit of 4.0 GB"):
        assert part in message, message


def test_no_size_limit_lets_a_refused_march_start():
    # The march refused above starts with no_size_limit=True (its 5.8 GB are reserved, and
    # filled only as it goes), and Ctrl-C ends it like any march.
    case = halfplane.Case.from_toml(CYCLE.replace("cycles = 3", "cycles = 1000"))
    # Python's own Ctrl-C handler: importing dask_jobqueue (the Slurm recipe's test) replaces it
    # with one that exits, which would make the outcome depend on the test order.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            halfplane.march(case, cells=2000, fields=True, no_size_limit=True)
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)
