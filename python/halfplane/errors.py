"""Exceptions and warnings of :mod:`halfplane`.

Every error the library can raise is a :class:`HalfplaneError`. Its message is the one the
``halfplane`` command prints and names the field (as the case file spells it, or the batch
column) with its value and what would be valid. ``variant`` is the library error's stable name
(``"InvalidInput"``, ``"SlipReversesInHalf"``, ``"MomentOutsideTable"``, ...: every variant has
its own), ``"TooLarge"`` for a run refused by its size estimate (see :func:`halfplane.march`), or
None for case-file checks. The class is the library's kind of the error: bad input
(:class:`InputError`), a valid case outside what the analysis covers
(:class:`OutsideAnalysisError`), or a numerical failure (:class:`SolverError`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Optional

if TYPE_CHECKING:
    from ._wear import WearResult


class HalfplaneError(Exception):
    """Base class of the errors :mod:`halfplane` raises. ``result`` holds what a run that
    stopped part way reached before the error (:func:`halfplane.wear`'s checkpoints, as the
    command prints them before its error), else None."""

    variant: Optional[str] = None
    result: Optional[WearResult] = None


class InputError(HalfplaneError, ValueError):
    """Bad input: a missing or invalid field, value, column or table. The message names it."""


class OutsideAnalysisError(HalfplaneError, ValueError):
    """A valid case outside what the analysis covers: gross sliding where partial slip is needed,
    a stick zone outside the smaller contact, slip reversing inside a half-cycle (the
    steady-state analysis assumes it does not; :func:`halfplane.march` has no such restriction),
    an asymmetric profile where symmetry is assumed, or no test that matches the prototype."""


class SolverError(HalfplaneError, RuntimeError):
    """A numerical solve did not converge or settle, a march did not reach a steady cycle, or the
    worker threads could not be started."""


class HalfplaneWarning(UserWarning):
    """What the command prints on stderr as a note or warning (e.g. no asymptotic estimate)."""


__all__ = [
    "HalfplaneError",
    "HalfplaneWarning",
    "InputError",
    "OutsideAnalysisError",
    "SolverError",
]
