"""Figures of halfplane's results with matplotlib (the optional extra ``halfplane[plot]``).

Each function takes results the package returns, not files: :func:`load_space` a
:class:`~halfplane.SteadyResult` (with the :func:`~halfplane.evolve` table for the paths),
:func:`slip_map` a :func:`~halfplane.steady_batch` table and its output, :func:`evolution` the
:func:`~halfplane.evolve` table (and a :class:`~halfplane.MarchResult` to overlay),
:func:`march_fields` a :class:`~halfplane.MarchResult` with fields, :func:`stress_map` a
:class:`~halfplane.StressResult` with its grid, :func:`fatigue_map` a
:class:`~halfplane.FatigueResult`, :func:`crack_growth` a :class:`~halfplane.CrackResult`,
:func:`fretting_loops` a :class:`~halfplane.WearResult` and :func:`design_map` a table of
cases and their results. Each
draws on the Axes given (``ax=``, or ``axes=`` a pair for the two-panel figures) or on a new
figure, and returns the Axes (one panel) or the Figure (two panels), so it can be restyled or
saved with ``savefig``.

Axis labels carry units: those of a :class:`~halfplane.SteadyResult`, otherwise ``units=`` (the
names of force, length and stress, as ``Case(units=...)`` and the case file's ``[units]`` give
them; default N, mm and MPa). The numbers are drawn as given: ``units`` only labels them.
Numbers on figures are in plain notation (430.9 MPa, not 4.309e2).

matplotlib is imported when a function is first called, so ``import halfplane.plot`` works
without it; a call without it raises ImportError saying how to install it.
"""

from ._curves import (
    MAX_STEPS,
    crack_growth,
    evolution,
    fretting_loops,
    load_space,
    march_fields,
    slip_map,
)
from ._maps import design_map, fatigue_map, stress_map

__all__ = [
    "MAX_STEPS",
    "crack_growth",
    "design_map",
    "evolution",
    "fatigue_map",
    "fretting_loops",
    "load_space",
    "march_fields",
    "slip_map",
    "stress_map",
]
