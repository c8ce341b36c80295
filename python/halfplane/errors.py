"""Exceptions and warnings of :mod:`halfplane`.

Every error the library can raise is a :class:`HalfplaneError`. Its message is the one the
``halfplane`` command prints and names the field (as the case file spells it, or the batch
column) with its value and what would be valid. ``variant`` is the library's error variant
(``"InvalidInput"``, ``"SlipReversesInHalf"``, ...), ``"TooLarge"`` for a run refused by its
size estimate (see :func:`halfplane.march`), or None for case-file checks.
"""

from __future__ import annotations

from typing import Optional


class HalfplaneError(Exception):
    """Base class of the errors :mod:`halfplane` raises."""

    variant: Optional[str] = None


class InputError(HalfplaneError, ValueError):
    """Bad input: a missing or invalid field, value, column or table. The message names it."""


class OutsideAnalysisError(HalfplaneError, ValueError):
    """A valid case outside what the analysis covers: gross sliding where partial slip is needed,
    a stick zone outside the smaller contact, or slip reversing inside a half-cycle (the
    steady-state analysis assumes it does not; :func:`halfplane.march` has no such restriction)."""


class SolverError(HalfplaneError, RuntimeError):
    """A numerical solve did not converge, or the worker threads could not be started."""


class HalfplaneWarning(UserWarning):
    """What the command prints on stderr as a note or warning (e.g. no asymptotic estimate)."""


__all__ = [
    "HalfplaneError",
    "HalfplaneWarning",
    "InputError",
    "OutsideAnalysisError",
    "SolverError",
]
