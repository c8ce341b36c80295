"""Curves of :mod:`halfplane.plot`: the load space, the slip-zone map, the stick zone over a
cycle, the fields of a march, a crack's stress intensity ranges against its length and the
fretting loops of a wear run."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from .._batch import steady_batch
from .._crack import CrackResult
from .._results import MarchResult, SteadyResult
from .._wear import WearResult
from ._base import (
    Floats,
    floats,
    new_axes,
    new_pair,
    plain_axis,
    require_columns,
    unit_names,
)

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

#: The most increments :func:`march_fields` draws (as ``halfplane plot march-fields``): more
#: curves than this cannot be told apart.
MAX_STEPS = 20


def _equivalent_shear(shear: Floats, bulk: Floats, half_width: Floats, right: bool) -> Floats:
    """The equivalent shear force of an edge, S = Q + pi a sigma/4 at the left edge and
    S = Q - pi a sigma/4 at the right (Andresen et al. 2019, eq. (33); the package's signs:
    bulk tension adds to the shear at the left edge)."""
    term = np.pi * half_width * bulk / 4.0
    return shear - term if right else shear + term


def _friction_lines(ax: Axes, f: float, top: float, force: str) -> None:
    ax.plot([0.0, top], [0.0, f * top], "--", color="0.45", lw=1.0,
            label=f"friction lines ±fP (f = {f:g})")
    ax.plot([0.0, top], [0.0, -f * top], "--", color="0.45", lw=1.0)
    ax.axhline(0.0, color="0.8", lw=0.8, zorder=0)
    ax.set_xlim(0.0, top)
    ax.set_xlabel(f"normal load P ({force})")
    plain_axis(ax.xaxis)
    plain_axis(ax.yaxis)
    ax.grid(alpha=0.3)


def load_space(
    result: SteadyResult,
    evolution: pd.DataFrame | None = None,
    *,
    axes: Sequence[Axes] | None = None,
) -> Figure:
    """The load space of a cycle (the paper's Figure 2 and its P-S counterpart), as
    ``halfplane plot load-space``.

    Left: the P-Q trajectory from point 1 to point 2 with the friction lines Q = +/- f P (gross
    sliding outside them). Right: the trajectory of each edge's equivalent shear force,
    S = Q + pi a sigma/4 (left edge) and S = Q - pi a sigma/4 (right edge) (the paper's
    eq. (33)), against P, with the same lines. ``result`` is :func:`halfplane.steady` of the
    case; the paths of S, which follow the contact half-width a(P), are drawn through the rows
    of half 1 of ``evolution`` (:func:`halfplane.evolve` of the same case); without it only
    their ends are marked. Units are the result's. Returns the Figure (two panels; ``axes`` a
    pair to draw on).
    """
    force, _, _ = unit_names(result.units.to_dict())
    ends = [result.points.at_point1, result.points.at_point2]
    normal = np.array([p.normal for p in ends], dtype=np.float64)
    shear = np.array([p.shear for p in ends], dtype=np.float64)
    bulk = np.array([p.bulk for p in ends], dtype=np.float64)
    contact = result.contact
    half_width = np.array([contact.half_width_1, contact.half_width_2], dtype=np.float64)
    path: pd.DataFrame | None = None
    if evolution is not None:
        require_columns(evolution, ["half", "normal", "shear", "bulk", "half_width"], "evolution")
        path = evolution[evolution["half"] == 1]
        given = path[["normal", "shear", "bulk", "half_width"]].iloc[[0, -1]].to_numpy(np.float64)
        expected = np.column_stack([normal, shear, bulk, half_width])
        if not np.allclose(given, expected, rtol=1e-12, atol=0.0):
            raise ValueError(
                "evolution is not of the same cycle as result: its half 1 does not run from "
                "result's point1 to point2 with the same contact half-widths"
            )
    fig, pq, ps = new_pair(axes)
    f = float(result.friction)
    top = 1.15 * float(normal.max())
    for ax in (pq, ps):
        _friction_lines(ax, f, top, force)
    pq.plot(normal, shear, "-", color="C0", lw=1.8, label="trajectory")
    for i, marker in ((0, "o"), (1, "s")):
        pq.plot(normal[i], shear[i], marker, color=f"C{i + 1}", ms=7, label=f"point {i + 1}")
    pq.set_ylabel(f"shear load Q ({force})")
    pq.set_title(f"P–Q trajectory ({result.regime})")
    edges = ((False, "C0", "left edge S = Q + πaσ/4"), (True, "C3", "right edge S = Q − πaσ/4"))
    for right, colour, name in edges:
        s_ends = _equivalent_shear(shear, bulk, half_width, right)
        if path is not None:
            s_path = _equivalent_shear(
                floats(path, "shear"), floats(path, "bulk"), floats(path, "half_width"), right
            )
            ps.plot(floats(path, "normal"), s_path, "-", color=colour, lw=1.8, label=name)
            ps.plot(normal, s_ends, "o", color=colour, ms=5)
        else:
            ps.plot(normal, s_ends, "o", color=colour, ms=6, label=f"{name} (ends)")
    ps.set_ylabel(f"equivalent shear S ({force})")
    ps.set_title("P–S trajectories of the edges")
    for ax in (pq, ps):
        ax.legend(fontsize=8, loc="best")
    return fig


def _pick_friction(cases: pd.DataFrame, friction: float | None) -> tuple[float, np.ndarray]:
    """The friction coefficient drawn and the rows that have it."""
    values = floats(cases, "friction")
    frictions = np.unique(values)
    listed = ", ".join(f"{v:g}" for v in frictions)
    if friction is None:
        if len(frictions) != 1:
            raise ValueError(
                f"cases has {len(frictions)} friction coefficients ({listed}): "
                "give friction= to pick one"
            )
        friction = float(frictions[0])
    chosen = np.isclose(values, friction, rtol=1e-12, atol=0.0)
    if not chosen.any():
        raise ValueError(f"invalid friction = {friction!r}: cases has {listed}")
    return float(friction), chosen


def slip_map(
    cases: pd.DataFrame,
    results: pd.DataFrame,
    *,
    friction: float | None = None,
    units: Mapping[str, str] | None = None,
    ax: Axes | None = None,
) -> Axes:
    """A slip-zone map in the style of the paper's Figure 5, as ``halfplane plot slip-map``: the
    slip zone at the right edge of the smaller contact, (min(a1, a2) - n)/a0, against the shear
    range dQ/(f P0), one curve per (P2/P1, dsigma/P1), with P0 = (P1 + P2)/2, a0 = a(P0) and
    dsigma = sigma1 - sigma2 (``docs/theory.md``, "Conventions").

    ``cases`` is the input table of :func:`halfplane.steady_batch` (one in-phase cycle per row:
    ``normal1, shear1, bulk1, normal2, shear2, bulk2, friction`` and the contact's columns) and
    ``results`` its output, row for row. a0 is the library's contact half-width at P0 (a second
    :func:`~halfplane.steady_batch` call of the same contacts held at P0, so any profile
    works). Rows whose analysis failed (gross sliding, slip reversing in a half) are left out,
    which breaks a curve; full stick is y = 0. With several friction coefficients in ``cases``,
    ``friction`` picks the one drawn; ``units`` names the length unit of dsigma/P1 in the
    legend. Returns the Axes.
    """
    loads = ["normal1", "shear1", "bulk1", "normal2", "shear2", "bulk2"]
    require_columns(cases, loads + ["friction"], "cases")
    require_columns(results, ["half_width_1", "half_width_2", "stick_right"], "results")
    if len(cases) != len(results):
        raise ValueError(
            f"cases has {len(cases)} rows but results has {len(results)}: "
            "give steady_batch's output of cases"
        )
    friction, chosen = _pick_friction(cases, friction)
    rows = cases[chosen].reset_index(drop=True)
    out = results[chosen].reset_index(drop=True)
    p1, p2 = floats(rows, "normal1"), floats(rows, "normal2")
    p0 = 0.5 * (p1 + p2)
    held = rows.drop(columns=loads).assign(
        normal1=p0, shear1=0.0, bulk1=0.0, normal2=p0, shear2=0.0, bulk2=0.0
    )
    a0 = floats(steady_batch(held), "half_width_1")
    x = np.abs(floats(rows, "shear2") - floats(rows, "shear1")) / (friction * p0)
    smaller = np.minimum(floats(out, "half_width_1"), floats(out, "half_width_2"))
    y = (smaller - floats(out, "stick_right")) / a0
    ratio = np.round(p2 / p1, 12)
    tension = np.round((floats(rows, "bulk1") - floats(rows, "bulk2")) / p1, 12)
    _, length, _ = unit_names(units)
    ax = new_axes(ax)
    styles = ["-", "--", ":", "-."]
    tensions: list[float] = sorted(set(tension.tolist()))
    for i, r in enumerate(sorted(set(ratio.tolist()))):
        for j, t in enumerate(tensions):
            curve = (ratio == r) & (tension == t)
            if not curve.any():
                continue
            order = np.argsort(x[curve], kind="stable")
            ax.plot(
                x[curve][order], y[curve][order], styles[j % len(styles)], color=f"C{i % 10}",
                lw=1.6, label=f"P2/P1 = {r:g}, Δσ/P1 = {t:g}/{length}",
            )
    ax.set_xlim(0.0, 1.0)
    ax.set_ylim(bottom=0.0)
    ax.set_xlabel("shear range ΔQ/(f P0)")
    ax.set_ylabel("right slip zone at the smaller contact (min(a1, a2) − n)/a0")
    ax.set_title(f"Slip-zone map, f = {friction:g}")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    return ax


def _steps_per_cycle(march: MarchResult) -> int:
    """The increments of the march's last cycle: from the last-but-one return of the load to the
    one it ends at (a cyclic history ends each cycle where it began, and passes that load only
    at the ends of its cycles, the load running straight between the cycle's two points)."""
    loads = march.steps[["normal", "shear", "bulk"]].to_numpy(np.float64)
    scale = max(float(np.abs(loads).max()), 1.0)
    same = np.flatnonzero(np.all(np.abs(loads - loads[-1]) <= 1e-12 * scale, axis=1))
    earlier = same[same < len(loads) - 1]
    if len(earlier) == 0:
        raise ValueError(
            "the march has no complete cycle: its load never returned to where it ends "
            '(give a cyclic history, [history] kind = "cycle")'
        )
    return int(len(loads) - 1 - earlier[-1])


def _last_cycle(frame: pd.DataFrame, march: MarchResult) -> tuple[Floats, Floats, Floats]:
    """(t, left, right) of the largest stick interval at each increment of the march's last
    cycle, t = 2k/K at its k-th of K increments; ValueError unless it ends at frame's point 1."""
    per_cycle = _steps_per_cycle(march)
    last = march.steps.iloc[len(march.steps) - per_cycle:]
    start = frame[frame["half"] == 1].iloc[0]
    end = last.iloc[-1]
    scale = 1e-9 * max(1.0, abs(float(start["normal"])))
    if not all(
        math.isclose(float(end[c]), float(start[c]), rel_tol=1e-9, abs_tol=scale)
        for c in ("normal", "shear", "bulk")
    ):
        raise ValueError(
            "march does not end at frame's point 1: it is not a march of the same cycle"
        )
    k = np.arange(1, per_cycle + 1, dtype=np.float64)
    return 2.0 * k / per_cycle, floats(last, "stick_left"), floats(last, "stick_right")


def evolution(
    frame: pd.DataFrame,
    march: MarchResult | None = None,
    *,
    units: Mapping[str, str] | None = None,
    axes: Sequence[Axes] | None = None,
) -> Figure:
    """The contact and stick zone over a cycle in the style of the paper's Figure 6, as
    ``halfplane plot evolution``: the contact edge, the exact stick boundary and the asymptotic
    estimate against the time t in cycles (half 1 from point 1 to point 2: 0 to 1; half 2 back:
    1 to 2), one panel per edge so the slip zones between the lines can be read.

    ``frame`` is :func:`halfplane.evolve` of the case. With ``march`` (:func:`halfplane.march`
    of a cyclic history of the same cycle) the largest stick interval of each increment of its
    last cycle is overlaid as points, at t = 2k/K for its k-th of K increments. Returns the
    Figure (two panels; ``axes`` a pair to draw on).
    """
    require_columns(
        frame,
        ["half", "fraction", "normal", "shear", "bulk", "half_width", "stick_left",
         "stick_right", "asymptotic_stick_left", "asymptotic_stick_right"],
        "frame",
    )
    _, length, _ = unit_names(units)
    t = floats(frame, "half") - 1.0 + floats(frame, "fraction")
    marched = None if march is None else _last_cycle(frame, march)
    fig, left, right = new_pair(axes)
    for ax, side in ((left, -1.0), (right, 1.0)):
        column = "stick_right" if side > 0 else "stick_left"
        if marched is not None:
            ax.plot(marched[0], marched[2] if side > 0 else marched[1], "o", ms=3.5, color="C2",
                    label="stick boundary (time marching)", zorder=1)
        # The contact's own ends (they move apart from ±a under a moment); ±a for an older frame.
        edge = "contact_right" if side > 0 else "contact_left"
        ends = floats(frame, edge) if edge in frame else side * floats(frame, "half_width")
        ax.plot(t, ends, "-", color="0.25", lw=1.6, label="contact edge")
        ax.plot(t, floats(frame, column), "-", color="C0", lw=1.8,
                label="stick boundary (exact)")
        ax.plot(t, floats(frame, "asymptotic_" + column), "--", color="C1", lw=1.5,
                label="stick boundary (asymptotic)")
        ax.axvline(1.0, color="0.8", lw=0.8, zorder=0)
        ax.set_xlim(0.0, 2.0)
        ax.set_xlabel("time t (cycles): point 1 → 2 → 1")
        ax.set_ylabel(f"position x ({length})")
        plain_axis(ax.yaxis)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="best")
    left.set_title("left edge: −a and −m")
    right.set_title("right edge: a and n")
    return fig


def _chosen_steps(march: MarchResult, steps: Sequence[int] | None) -> list[int]:
    """The increments march_fields draws: as given, or the quarters of the last cycle (the
    command's default), or the last increment of a history without cycles."""
    count = march.increments
    if steps is not None:
        chosen = [int(s) for s in steps]
    else:
        try:
            per_cycle = _steps_per_cycle(march)
            chosen = [count - per_cycle + q * per_cycle // 4 for q in range(1, 5)]
        except ValueError:
            chosen = [count]
    if not chosen or len(chosen) > MAX_STEPS:
        raise ValueError(f"invalid steps: {len(chosen)} given, 1 to {MAX_STEPS} can be drawn")
    bad = [s for s in chosen if not 1 <= s <= count]
    if bad:
        raise ValueError(f"invalid steps value {bad[0]}: the march has increments 1 to {count}")
    return chosen


def march_fields(
    march: MarchResult,
    steps: Sequence[int] | None = None,
    *,
    friction: float | None = None,
    units: Mapping[str, str] | None = None,
    axes: Sequence[Axes] | None = None,
) -> Figure:
    """The shear traction q and the accumulated slip along x at chosen increments of a march,
    as ``halfplane plot march-fields`` (q positive in +x, slip positive in the sense positive Q
    drives).

    ``march`` is :func:`halfplane.march` with ``fields=True``. ``steps`` are increments,
    1-based (at most 20); by default a quarter, a half, three quarters and the end of the last
    cycle of a cyclic history, else the last increment. With ``friction`` (the case's f) the
    friction limits +/- f p of each increment are drawn dashed. Returns the Figure (two panels;
    ``axes`` a pair to draw on).
    """
    traction, slip, pressure = march.traction, march.slip, march.pressure
    if traction is None or slip is None or pressure is None:
        raise ValueError("march has no fields: run halfplane.march(case, fields=True)")
    chosen = _chosen_steps(march, steps)
    _, length, stress = unit_names(units)
    fig, top, bottom = new_pair(axes)
    for i, step in enumerate(chosen):
        colour = f"C{i % 10}"
        top.plot(march.x, traction[step - 1], "-", color=colour, lw=1.6, label=f"q, step {step}")
        if friction is not None:
            limit = float(friction) * pressure[step - 1]
            top.plot(march.x, limit, "--", color=colour, lw=0.9, label=f"±f p, step {step}")
            top.plot(march.x, -limit, "--", color=colour, lw=0.9)
        bottom.plot(march.x, slip[step - 1], "-", color=colour, lw=1.6, label=f"slip, step {step}")
    top.set_ylabel(f"shear traction q ({stress})")
    top.set_title("shear traction")
    bottom.set_ylabel(f"accumulated slip ({length})")
    bottom.set_title("accumulated slip")
    for ax in (top, bottom):
        ax.set_xlabel(f"position x ({length})")
        ax.axhline(0.0, color="0.8", lw=0.8, zorder=0)
        plain_axis(ax.yaxis)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="best")
    return fig


def crack_growth(result: CrackResult, *, ax: Axes | None = None) -> Axes:
    """A crack's stress intensity ranges against its length with the short-crack threshold, on
    log-log axes, as ``halfplane plot crack``: the effective range ``delta_k_eff`` (the
    verdict's), ``delta_k1`` and ``delta_k2``, and El Haddad's threshold (dashed); where the
    crack arrests, a vertical line at the arrest length. ``result`` is :func:`halfplane.crack`'s.
    Lengths and ranges not above zero (a range of zero: the tip never opens) are left out of
    the logarithmic axes. Returns the Axes."""
    rows = result.rows
    ax = new_axes(ax)
    length = floats(rows, "length")
    k = result.intensity_unit
    for column, style, colour, label in (
        ("delta_k_eff", "-o", "C0", "ΔK effective"),
        ("delta_k1", "-", "C1", "ΔK_I"),
        ("delta_k2", "-", "C2", "ΔK_II"),
        ("threshold", "--", "0.2", "threshold ΔK_th(l) (El Haddad)"),
    ):
        values = floats(rows, column)
        keep = (values > 0.0) & (length > 0.0)
        ax.plot(length[keep], values[keep], style, color=colour, ms=3.5, lw=1.6, label=label)
    if result.arrest_length is not None:
        ax.axvline(result.arrest_length, color="C3", lw=1.0,
                   label=f"arrests at {result.arrest_length:.4g} {result.units.length}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(f"crack length l ({result.units.length})")
    ax.set_ylabel(f"stress intensity range ΔK ({k})")
    ax.set_title(f"Crack at x = {result.position:.4g} {result.units.length}, "
                 f"{result.angle:.1f}° from the normal: {result.verdict}")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8, loc="best")
    return ax


def fretting_loops(
    result: WearResult, *, cycles: Sequence[int] | None = None, ax: Axes | None = None
) -> Axes:
    """The fretting loops of a wear run, as the last panel of ``halfplane plot wear``: Q
    against the bodies' relative displacement (measured from ``result.loop_datum``), one curve
    per checkpoint of ``cycles`` (default all). ``result`` is :func:`halfplane.wear`'s; a cycle
    that is not a checkpoint raises KeyError naming those that are. Returns the Axes."""
    ax = new_axes(ax)
    chosen = [int(c) for c in result.checkpoints["cycle"]] if cycles is None else list(cycles)
    for k, cycle in enumerate(chosen):
        loop = result.fretting_loop(cycle)
        ax.plot(floats(loop, "relative_displacement"), floats(loop, "shear"), "-",
                color=f"C{k % 10}", lw=1.4, label=f"cycle {cycle}")
    units = result.units
    ax.set_xlabel(f"relative displacement δ ({units.length}), "
                  f"datum {result.loop_datum:.4g} {units.length}")
    ax.set_ylabel(f"shear load Q ({units.force}/{units.length})")
    ax.set_title("Fretting loops")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="best")
    return ax
