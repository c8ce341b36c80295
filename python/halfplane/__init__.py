"""halfplane: frictional contact of elastically similar bodies idealised as half-planes, under
in-phase cycles of normal load P, shear load Q and bulk tension sigma.

The same analyses as the ``halfplane`` command, with the same numbers:

- :func:`read_case`, :meth:`Case.from_toml` and the keyword constructor :class:`Case` build cases;
- :func:`steady` (``halfplane steady --json`` as a :class:`SteadyResult`), :func:`evolve`
  (``evolve --csv`` as a DataFrame), :func:`march` (``march``: steps, cycles, fields);
  results are typed, read-only records built from the command's report structs (no text in
  between), with a ``repr`` for the terminal and an HTML table for notebooks;
- :func:`stress` (``stress``: the stresses below the contact at an increment) and :func:`fatigue`
  (``fatigue``: initiation parameters over the steady cycle); :func:`crack` (``crack``: will a
  crack grow or arrest); :func:`match` (``match``: the test that reproduces a prototype's
  contact-edge state); :func:`wear` (``wear``: fretting wear over millions of cycles, its
  checkpoints as a DataFrame);
- :func:`steady_batch`: a million cases in one call on every core; :mod:`halfplane.dask` on a
  cluster.

Units are those of the numbers given (consistent units; the examples use N, mm and MPa, so loads
are N/mm per unit thickness). Sign conventions: P > 0 compresses; Q and sigma are positive as in
the paper's Figure 1 (Andresen, Hills, Barber and Vazquez, IJSS 2019); x increases towards the
edge that positive Q drives; bulk tension adds to the shear at the left edge. Errors are
:class:`HalfplaneError` subclasses (bad input is :class:`InputError`, a ValueError) whose message
names the field.
"""

from __future__ import annotations

import numbers
import warnings
from typing import Any, Optional

import pandas as pd

from . import _halfplane
from ._batch import STEADY_COLUMNS, steady_batch
from ._crack import CrackResult, crack
from ._halfplane import Case, read_case
from ._matching import MatchResult, MatchSide, Mismatch, match
from ._records import Edges, LoadPoint, PerPoint, Profile, Record, Units, _frame
from ._results import (
    Asymptotic,
    AsymptoticStickZone,
    ContactState,
    Criteria,
    EdgeIntensities,
    Estimate,
    MarchResult,
    SteadyResult,
    StickZone,
)
from ._subsurface import FatigueResult, StressResult, fatigue, stress
from ._wear import WearResult, wear
from .errors import (
    HalfplaneError,
    HalfplaneWarning,
    InputError,
    OutsideAnalysisError,
    SolverError,
)

__version__: str = _halfplane.__version__

#: The input columns of :func:`steady_batch`, in their documented order.
STEADY_INPUT_COLUMNS = list(_halfplane.STEADY_INPUT_COLUMNS)


def _count(name: str, value: Any) -> int:
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or int(value) < 0:
        raise InputError(f"invalid {name} = {value!r}: must be a whole number")
    return int(value)


def steady(case: Case) -> SteadyResult:
    """The steady state of the case's cycle, as ``halfplane steady --json``: the regime, the
    contact half-widths, the permanent stick zone [-m, n] and the slip zones, with the asymptotic
    edge description in partial slip (see :class:`SteadyResult` for the fields, units and signs).

    Raises :class:`InputError` when the case has no cycle, and :class:`OutsideAnalysisError` when
    the cycle is outside the steady-state analysis (slip reversing inside a half, a stick zone
    outside the smaller contact): :func:`march` covers those. :class:`SolverError` when its
    stick-zone equations find no root (its message points to :func:`march` too). A missing
    asymptotic estimate is a :class:`HalfplaneWarning`, as the command's note on stderr.
    """
    report, note = _halfplane.steady_report(case)
    if note is not None:
        warnings.warn(note, HalfplaneWarning, stacklevel=2)
    return SteadyResult._from(report)


def evolve(case: Case, points: int = 21) -> pd.DataFrame:
    """The stick zone along both halves of the case's cycle, as ``halfplane evolve --csv``.

    One row per point, ``points`` per half (ends included, 2 to 100,000); half 1 runs from point1
    to point2 as given, half 2 back. Columns: ``half, fraction, normal, shear, bulk, half_width,
    stick_left, stick_right, asymptotic_stick_left, asymptotic_stick_right, state`` (loads N/mm,
    sigma MPa, lengths mm with the default units; ``state`` is ``full-stick``, ``partial-slip`` or
    ``one-edge-slip``). ``DataFrame.attrs["regime"]`` holds the steady regime; the command's
    warnings are :class:`HalfplaneWarning`.
    """
    columns, regime, notes = _halfplane.evolve_report(case, _count("points", points))
    for note in notes:
        warnings.warn(note, HalfplaneWarning, stacklevel=2)
    frame = _frame(columns)
    frame.attrs["regime"] = regime
    return frame


def march(
    case: Case, cells: Optional[int] = None, fields: bool = False, no_size_limit: bool = False
) -> MarchResult:
    """Numerical time marching through the case's load history (``[history]``), as
    ``halfplane march``: any history (out of phase, harmonic, from rows), any profile.

    ``cells`` overrides the case's ``[solver] cells`` (8 to 1,000,000; default 400) across the
    largest contact of the history. Returns a :class:`MarchResult` with ``steps`` (the
    ``march --csv`` columns, ``relative_displacement`` among them: the fretting loop against
    ``shear``, at the datum ``loop_datum``), ``cycles`` (energy and largest slip amplitude per
    cycle), ``shakedown_cycle``, ``cycles_run``, ``steady_change`` and ``steady_converged``.

    With ``cycles = "steady"`` in the case's ``[history]`` the last cycle is repeated until no
    cell's slip range changes by more than ``steady_tolerance`` (default 1e-10) x A f P_max
    between consecutive cycles, at most ``max_cycles`` (default 1000) cycles; otherwise a
    ``SolverError`` (variant ``NotSteady``) names the last change.

    With ``fields=True`` it also holds ``pressure``, ``traction``, ``slip`` and ``slip_increment``
    of every increment, each a float64 array of shape (increments, cells): memory is
    4 x 8 bytes x increments x cells, e.g. 3.8 MB for 300 increments of 400 cells and 1 GB for
    100,000 increments of 320 cells (a MemoryError is raised if that cannot be allocated).

    The GIL is released while marching; Ctrl-C interrupts the march between increments (it is
    checked every 50 ms) with KeyboardInterrupt.

    A march estimated to take more than 8 hours of one core (cells² x increments x 5e-10 s), or
    whose fields would need more than 4 GB, raises :class:`InputError` (``variant`` is
    ``"TooLarge"``) before it starts, naming the estimate and the limit; ``no_size_limit=True``
    runs it anyway.
    """
    if cells is not None:
        cells = _count("cells", cells)
    out = _halfplane.march_report(case, cells, bool(fields), bool(no_size_limit))
    cycles = _frame(out["cycles"]).astype(
        {"index": "int64", "energy": "float64", "max_slip_amplitude": "float64"}
    )
    recorded = (
        {k: out[k] for k in ("pressure", "traction", "slip", "slip_increment")} if fields else None
    )
    return MarchResult(
        steps=_frame(out["steps"]),
        cycles=cycles,
        shakedown_cycle=out["shakedown_cycle"],
        x=out["x"],
        fields=recorded,
        cycles_run=out["cycles_run"],
        steady_change=out["steady_change"],
        steady_converged=out["steady_converged"],
        loop_datum=out["loop_datum"],
    )


__all__ = [
    "Asymptotic",
    "AsymptoticStickZone",
    "Case",
    "ContactState",
    "CrackResult",
    "Criteria",
    "EdgeIntensities",
    "Edges",
    "Estimate",
    "FatigueResult",
    "HalfplaneError",
    "HalfplaneWarning",
    "InputError",
    "LoadPoint",
    "MarchResult",
    "MatchResult",
    "MatchSide",
    "Mismatch",
    "OutsideAnalysisError",
    "PerPoint",
    "Profile",
    "Record",
    "STEADY_COLUMNS",
    "STEADY_INPUT_COLUMNS",
    "SolverError",
    "SteadyResult",
    "StickZone",
    "StressResult",
    "Units",
    "WearResult",
    "crack",
    "evolve",
    "fatigue",
    "march",
    "match",
    "read_case",
    "steady",
    "steady_batch",
    "stress",
    "wear",
]

# The result classes and their parts are known by their public path (halfplane.StickZone, not
# halfplane._results.StickZone): in the API reference, in reprs of types and in new pickles (old
# pickles name the private modules, which still hold the classes).
for _name in __all__:
    _object = globals()[_name]
    if isinstance(_object, type) and _object.__module__.startswith("halfplane._"):
        _object.__module__ = __name__
