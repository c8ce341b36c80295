"""Maps of :mod:`halfplane.plot` in a plane: the stresses and the fatigue maxima below the
contact (x, z) and design maps of many cases over two of their inputs."""

from __future__ import annotations

import importlib
import math
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt
import pandas as pd

from .._subsurface import FatigueResult, StressResult
from ._base import (
    Floats,
    floats,
    level,
    mark,
    new_axes,
    plain,
    plain_axis,
    require_columns,
    unit_names,
)

if TYPE_CHECKING:
    from matplotlib.axes import Axes

_COMPONENTS = {"sxx": "σxx", "szz": "σzz", "syy": "σyy", "sxz": "σxz"}


def _grid(x: npt.ArrayLike, z: npt.ArrayLike, shape: tuple[int, ...]) -> tuple[Floats, Floats]:
    """x and z as 2-D arrays of ``shape`` (nz, nx): given so, or as the 1-D axes of that grid."""
    xs = np.asarray(x, dtype=np.float64)
    zs = np.asarray(z, dtype=np.float64)
    if len(shape) != 2:
        raise ValueError(
            "a map needs a 2-D grid of points (z along axis 0, x along axis 1); the result has "
            f"shape {shape}"
        )
    if xs.ndim == 1 and zs.ndim == 1:
        if (len(zs), len(xs)) != shape:
            raise ValueError(
                f"x ({len(xs)} values) and z ({len(zs)}) do not span the result's grid {shape} "
                "(z along axis 0, x along axis 1)"
            )
        gx, gz = np.meshgrid(xs, zs)
        return gx, gz
    bx, bz = np.broadcast_arrays(xs, zs)
    if bx.shape != shape:
        raise ValueError(f"x and z broadcast to {bx.shape}, but the result has shape {shape}")
    return np.asarray(bx, dtype=np.float64), np.asarray(bz, dtype=np.float64)


def _contour_field(
    ax: Axes, gx: Floats, gz: Floats, values: Floats, levels: int, label: str
) -> None:
    """Filled contours over the grid (interpolated between grid points, so no staircase), every
    second level labelled on a contour line, and a colour bar from the smallest to the largest
    value; a range of both signs gets a diverging map centred on zero."""
    mpl = importlib.import_module("matplotlib")
    ticker = importlib.import_module("matplotlib.ticker")
    low, high = float(np.nanmin(values)), float(np.nanmax(values))
    if low == high:
        high = low + max(abs(low), 1.0) * 1e-9
    bounds = np.asarray(ticker.MaxNLocator(nbins=levels).tick_values(low, high), dtype=np.float64)
    bounds = bounds[(bounds > low) & (bounds < high)]
    edges = np.concatenate([[low], bounds, [high]])
    if low < 0.0 < high:
        cmap = mpl.colormaps["RdBu_r"]
        norm: Any = mpl.colors.TwoSlopeNorm(vmin=low, vcenter=0.0, vmax=high)
    else:
        cmap = mpl.colormaps["viridis"]
        norm = mpl.colors.Normalize(vmin=low, vmax=high)
    filled = ax.contourf(gx, gz, values, levels=edges, cmap=cmap, norm=norm)
    if len(bounds):
        lines = ax.contour(gx, gz, values, levels=bounds, colors="k", linewidths=0.5, alpha=0.6)
        ax.clabel(lines, bounds[::2], inline=True, fontsize=7, fmt=level)
    figure = ax.get_figure()
    assert figure is not None
    # An inset colour bar keeps the height of the equal-aspect axes box.
    cbar = figure.colorbar(filled, cax=ax.inset_axes((1.03, 0.0, 0.035, 1.0)), label=label)
    plain_axis(cbar.ax.yaxis)


def _xz_axes(ax: Axes, length: str) -> None:
    """Equal scales, the depth downwards, labelled."""
    ax.set_aspect("equal")
    if not ax.yaxis_inverted():
        ax.invert_yaxis()
    ax.set_xlabel(f"position x ({length})")
    ax.set_ylabel(f"depth z ({length})")


def stress_map(
    result: StressResult,
    x: npt.ArrayLike | None = None,
    z: npt.ArrayLike | None = None,
    component: str = "sxx",
    *,
    levels: int = 14,
    units: Mapping[str, str] | None = None,
    ax: Axes | None = None,
) -> Axes:
    """Filled contours of one stress component below the contact, as ``halfplane plot
    stress-map``: ``component`` is ``"sxx"``, ``"szz"``, ``"syy"`` or ``"sxz"`` (tension
    positive, signs as :class:`~halfplane.StressResult`), with a colour bar, labelled contour
    lines, equal scales in x and z, the depth z downwards, the contact -a <= x <= a drawn on
    the surface and the largest value marked (a star, with its value and place in the legend).

    ``result`` is :func:`halfplane.stress` on a grid (``stress(case, x=xs[None, :],
    z=zs[:, None])`` gives shape ``(len(zs), len(xs))``); the grid is the result's own points
    unless ``x``, ``z`` are given (the 1-D axes or 2-D arrays of the result's shape).
    ``levels`` is about how many colour bands. A range of both signs gets a diverging colour
    map centred on zero. Returns the Axes.
    """
    if component not in _COMPONENTS:
        raise ValueError(
            f"invalid component = {component!r}: must be one of {', '.join(_COMPONENTS)}"
        )
    if isinstance(levels, bool) or not isinstance(levels, int) or levels < 2:
        raise ValueError(f"invalid levels = {levels!r}: must be a whole number >= 2")
    values = np.asarray(getattr(result, component), dtype=np.float64)
    if (x is None) != (z is None):
        raise ValueError("give both x and z, or neither (the result's own points)")
    gx, gz = _grid(result.x if x is None else x, result.z if z is None else z, values.shape)
    _, length, stress = unit_names(units)
    name = _COMPONENTS[component]
    spans = (float(np.ptp(gx)), float(np.ptp(gz)))
    ratio = min(max(spans[1] / max(spans[0], 1e-300), 0.2), 1.0)
    ax = new_axes(ax, (7.5, 5.7 * ratio + 1.4))
    _contour_field(ax, gx, gz, values, levels, f"{name} ({stress})")
    a = result.half_width
    b1, b2 = result.contact_left, result.contact_right
    label = (
        f"contact, a = {plain(a)} {length}"
        if b1 == -b2
        else f"contact [{plain(b1)}, {plain(b2)}] {length}"
    )
    ax.plot([b1, b2], [0.0, 0.0], "-", color="k", lw=4, solid_capstyle="butt",
            label=label, zorder=4)
    peak = int(np.nanargmax(values))
    px, pz = float(gx.flat[peak]), float(gz.flat[peak])
    peak_text = (
        f"max {name} = {plain(float(values.flat[peak]))} {stress} "
        f"at x = {plain(px)}, z = {plain(pz)} {length}"
    )
    mark(ax, px, pz, peak_text)
    _xz_axes(ax, length)
    force, _, _ = unit_names(units)
    # The loads, the maximum (the star) and the contact (the bar) in the title: a legend would
    # cover the field.
    ax.set_title(
        f"{name} at step {result.step}: P = {result.normal:g} {force}, "
        f"Q = {result.shear:g} {force}, σ = {result.bulk:g} {stress}\n"
        f"★ {peak_text}; bar: contact, a = {plain(a)} {length}",
        fontsize=9,
    )
    return ax


#: Fatigue parameters measured in stress units (the others are dimensionless).
_STRESS_PARAMETERS = {"findley", "crossland", "mwcm", "mcdiarmid", "ruiz_f2"}


def _fatigue_rows(result: FatigueResult, parameters: Sequence[str] | None) -> pd.DataFrame:
    table = result.parameters
    if parameters is not None:
        unknown = [p for p in parameters if p not in set(table["parameter"])]
        if unknown:
            raise ValueError(
                f"invalid parameter {unknown[0]!r}: the result has "
                f"{', '.join(table['parameter'])}"
            )
        table = table[table["parameter"].isin(list(parameters))]
    placed = np.isfinite(floats(table, "x")) & np.isfinite(floats(table, "z"))
    if not placed.any():
        raise ValueError("no parameter with a place to draw")
    return table[placed]


def fatigue_map(
    result: FatigueResult,
    parameters: Sequence[str] | None = None,
    *,
    half_width: float | None = None,
    field: str | None = None,
    levels: int = 10,
    units: Mapping[str, str] | None = None,
    ax: Axes | None = None,
) -> Axes:
    """Where each fatigue parameter peaks over the steady cycle, in the x-z plane below the
    contact (equal scales, depth downwards), over the filled contours of one parameter's field:
    the place of each maximum (a star; parameters peaking at one place share it), the critical
    plane through it (a line along the plane, at ``plane`` degrees from +x towards +z) and, when
    the critical distance L is known, the line 0 <= z <= 2L below it that the line method
    averages over. The legend gives each value in plain notation.

    ``result`` is :func:`halfplane.fatigue`; ``parameters`` picks rows of its ``parameters``
    table (default every row with a place). ``field`` names the parameter whose values over the
    ``[fatigue]`` grid (``result.maps``) are shaded, with a colour bar (default: the first
    drawn parameter that has a map; Ruiz has none); ``levels`` is about how many colour bands.
    With ``half_width`` (the largest contact half-width of the cycle) the contact is drawn on
    the surface. Returns the Axes.
    """
    table = _fatigue_rows(result, parameters)
    _, length, stress = unit_names(units)
    if field is not None and field not in result.maps:
        raise ValueError(
            f"invalid field = {field!r}: the result has maps of {', '.join(result.maps) or 'none'}"
        )
    if isinstance(levels, bool) or not isinstance(levels, int) or levels < 2:
        raise ValueError(f"invalid levels = {levels!r}: must be a whole number >= 2")
    shaded = field or next((str(p) for p in table["parameter"] if p in result.maps), None)
    ax = new_axes(ax, (8.0, 4.2))
    if shaded is not None:
        gx, gz = np.meshgrid(result.grid_x, result.grid_z)
        unit = f" ({stress})" if shaded in _STRESS_PARAMETERS else ""
        _contour_field(ax, gx, gz, result.maps[shaded], levels, f"{shaded}{unit}")
    xs, zs = floats(table, "x"), floats(table, "z")
    a = float(half_width) if half_width is not None else 0.0
    critical = result.critical_distance
    depth = 2.0 * float(critical) if critical is not None else 0.0
    # The window: around the maxima, wide enough to show the planes, the line-method line and
    # (from a tenth of the contact) where they sit on it.
    span = max(float(np.ptp(xs)), float(np.ptp(zs)), 1.5 * depth, 0.1 * a, 1e-3)
    reach = 0.5 * span
    names = [str(p) for p in table["parameter"]]
    rows = zip(names, floats(table, "value"), floats(table, "plane"), xs, zs)
    for i, (parameter, value, plane, px, pz) in enumerate(rows):
        colour = f"C{i % 10}"
        unit = f" {stress}" if parameter in _STRESS_PARAMETERS else ""
        text = f"{parameter} = {plain(float(value))}{unit}"
        if np.isfinite(plane):
            theta = math.radians(float(plane))
            dx, dz = 0.5 * reach * math.cos(theta), 0.5 * reach * math.sin(theta)
            ax.plot([px - dx, px + dx], [pz - dz, pz + dz], "-", color=colour,
                    lw=1.6, label=f"{text}, plane {plain(float(plane))}°")
        else:
            ax.plot([], [], "-", color=colour, lw=1.6, label=f"{text} (no plane)")
    places = sorted({(float(p), float(q)) for p, q in zip(xs, zs)})
    for px, pz in places:
        ax.plot([px], [pz], marker="*", ms=14, color="k", mfc="yellow", ls="none", zorder=5)
    if critical is not None:
        for px in sorted({p[0] for p in places}):
            ax.plot([px, px], [0.0, depth], ":", color="k", lw=1.2, zorder=4)
        ax.plot([], [], ":", color="k", lw=1.2,
                label=f"line method: 0 ≤ z ≤ 2L, L = {plain(float(critical))} {length}")
    if half_width is not None:
        ax.plot([-a, a], [0.0, 0.0], "-", color="0.3", lw=4, solid_capstyle="butt",
                label=f"contact, a = {plain(a)} {length}", zorder=3)
    if shaded is not None:
        # The grid's extent: the field is the picture, the maxima sit on it.
        ax.set_xlim(float(result.grid_x.min()), float(result.grid_x.max()))
        ax.set_ylim(float(result.grid_z.max()), float(result.grid_z.min()))
    else:
        middle = 0.5 * (float(xs.min()) + float(xs.max()))
        half = 0.5 * float(np.ptp(xs)) + span
        ax.set_xlim(middle - half, middle + half)
        ax.set_ylim(max(float(zs.max()), depth) + 0.5 * span, -0.2 * span)
    ax.set_aspect("equal")
    ax.set_xlabel(f"position x ({length})")
    ax.set_ylabel(f"depth z ({length})")
    ax.axhline(0.0, color="0.6", lw=0.8, zorder=0)
    over = f"; shaded: {shaded}" if shaded is not None else ""
    ax.set_title(
        f"Maxima over the steady cycle (steps {result.first_step}–{result.last_step}){over}",
        fontsize=10,
    )
    # Beside the axes, or below them when the colour bar takes the right-hand side.
    if shaded is not None:
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(0.0, -0.18), frameon=False,
                  ncol=2)
    else:
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0), frameon=False)
    return ax


_POINT_NAMES = {"normal": "normal load P", "shear": "shear load Q", "bulk": "bulk stress σ"}

#: Readable names of the columns of batch and sweep tables, and the kind of their unit.
_NAMES = {
    "stick_left": ("stick zone left end −m", "length"),
    "stick_right": ("stick zone right end n", "length"),
    "half_width_1": ("contact half-width a at point 1", "length"),
    "half_width_2": ("contact half-width a at point 2", "length"),
    "slip_left_1": ("left slip zone at point 1", "length"),
    "slip_left_2": ("left slip zone at point 2", "length"),
    "slip_right_1": ("right slip zone at point 1", "length"),
    "slip_right_2": ("right slip zone at point 2", "length"),
    "energy": ("energy dissipated per cycle", "energy"),
    "max_slip_amplitude": ("largest slip amplitude", "length"),
    "final_stick_left": ("stick zone left end at the last increment", "length"),
    "final_stick_right": ("stick zone right end at the last increment", "length"),
    "shakedown_cycle": ("shakedown cycle", None),
    "cycles_run": ("cycles marched", None),
    "steady_change": ("slip-range change in the last cycle / (A f P_max)", None),
    "friction": ("friction coefficient f", None),
    "youngs_modulus": ("Young's modulus E", "stress"),
    "poisson_ratio": ("Poisson's ratio ν", None),
    "radius": ("profile radius R", "length"),
    "flat_half_width": ("flat half-width b", "length"),
    "coefficient": ("profile coefficient B", None),
    "exponent": ("profile exponent k", None),
    "cells": ("cells", None),
    "cycles": ("cycles", None),
    "steps_per_half": ("increments per half-cycle", None),
}

#: Sweep paths whose last part names a column of :data:`_NAMES`.
_SECTIONS = ("friction.", "material.", "profile.", "solver.", "history.")


def _describe(column: str, units: tuple[str, str, str]) -> str:
    """A readable name with its unit for a column of a batch or sweep table (``normal1`` and the
    sweep path ``cycle.point1.normal`` both read "normal load P at point 1 (N/mm)"); other
    columns keep their name."""
    force, length, stress = units
    energy = f"{force.split('/')[0]} {length}/{length}"
    unit_of = {"length": length, "stress": stress, "energy": energy}
    for quantity, name in _POINT_NAMES.items():
        for point in ("1", "2"):
            if column in (f"{quantity}{point}", f"cycle.point{point}.{quantity}"):
                return f"{name} at point {point} ({stress if quantity == 'bulk' else force})"
    key = column
    for section in _SECTIONS:
        if column.startswith(section):
            key = column[len(section):]
    if key == "coefficient" and column == "friction.coefficient":
        key = "friction"
    if key in _NAMES:
        name, unit = _NAMES[key]
        return name if unit is None else f"{name} ({unit_of[unit]})"
    return column


#: Colours of the regimes, and of rows whose analysis failed (""), on a regime map.
_REGIME_COLOURS = {
    "full-stick": "#4c72b0",
    "partial-slip": "#55a868",
    "gross-sliding": "#c44e52",
    "": "#bbbbbb",
}
# A crack sweep's verdict (``analysis = "crack"``), as ``halfplane plot design-map``.
_VERDICT_COLOURS = {
    "no-growth": "#55a868",
    "arrests": "#4c72b0",
    "propagates": "#c44e52",
    "": "#bbbbbb",
}
# The text columns drawn as categories: their colours, the title and the name of rows without one.
_CATEGORIES = {
    "regime": (_REGIME_COLOURS, "regime", "outside the analysis"),
    "crack.verdict": (_VERDICT_COLOURS, "crack verdict", "no value"),
}


def _cell_edges(centres: Floats) -> Floats:
    """Edges of cells centred on sorted ``centres``: midway between neighbours, half a spacing
    beyond the ends."""
    if len(centres) == 1:
        return np.array([centres[0] - 0.5, centres[0] + 0.5])
    mid = 0.5 * (centres[1:] + centres[:-1])
    return np.concatenate([[2 * centres[0] - mid[0]], mid, [2 * centres[-1] - mid[-1]]])


def _select(frame: pd.DataFrame, x: str, y: str, where: Mapping[str, float]) -> pd.DataFrame:
    """The rows with the ``where`` values, one per (x, y) point (ValueError otherwise)."""
    rows = frame
    for name, value in where.items():
        require_columns(rows, [name], "frame")
        keep = np.isclose(floats(rows, name), float(value), rtol=1e-9, atol=0.0)
        if not keep.any():
            values = np.unique(floats(rows, name))
            shown = ", ".join(plain(float(v)) for v in values[:12])
            raise ValueError(
                f"invalid where {name} = {value!r}: the column has {shown}"
                + (" ..." if len(values) > 12 else "")
            )
        rows = rows[keep]
    if rows[[x, y]].duplicated().any():
        outputs = set(_NAMES) - {"friction", "youngs_modulus", "poisson_ratio", "radius",
                                 "flat_half_width", "coefficient", "exponent"}
        varying = [
            str(c) for c in rows.columns
            if c not in (x, y, "regime", "error") and str(c) not in outputs
            and pd.api.types.is_numeric_dtype(rows[c]) and rows[c].nunique() > 1
        ]
        raise ValueError(
            f"several rows share a point ({x}, {y}): pick one value of each other varied "
            f"column with where= ({', '.join(varying) or 'none found'})"
        )
    return rows


def _category_codes(rows: pd.DataFrame, column: str,
                    colours: Mapping[str, str]) -> tuple[Floats, np.ndarray]:
    values = rows[column].fillna("").astype(str).to_numpy()
    if "error" in rows.columns:
        failed = rows["error"].fillna("").astype(str).to_numpy() != ""
        values = np.where(failed, "", values)
    names = list(colours)
    codes = np.array([names.index(r) if r in names else len(names) - 1 for r in values],
                     dtype=np.float64)
    return codes, values


def design_map(
    frame: pd.DataFrame,
    x: str,
    y: str,
    color: str = "regime",
    *,
    where: Mapping[str, float] | None = None,
    units: Mapping[str, str] | None = None,
    ax: Axes | None = None,
) -> Axes:
    """A design map of many cases over two of their inputs, as ``halfplane plot design-map``:
    the regime of each case (``color="regime"``, with rows whose analysis failed in grey), a
    crack sweep's verdict (``color="crack.verdict"``: no-growth, arrests, propagates) or any
    numeric column as colour, with a colour bar, contour lines and its largest value marked.

    ``frame`` has one row per case with its inputs and results: a sweep's output
    (``pd.read_csv`` or ``pd.read_parquet`` of ``halfplane sweep``, columns named by dotted
    path) or a :func:`~halfplane.steady_batch` table beside its output
    (``pd.concat([table, halfplane.steady_batch(table)], axis=1)``). ``x`` and ``y`` name the
    columns of the axes, labelled by a readable name and unit (``cycle.point2.shear`` and
    ``shear2`` both read "shear load Q at point 2 (N/mm)"). When the table varies more columns
    than those two, ``where`` keeps the rows with the value given of each of the others. Rows
    on a full grid of (x, y) are drawn as cells centred on their values (no interpolation: a
    cell is a case); scattered rows (random or Latin-hypercube samples) as points. Cells
    without a value (gross sliding has no stick zone) are left blank. Returns the Axes.
    """
    require_columns(frame, [x, y, color], "frame")
    rows = _select(frame, x, y, where or {})
    if color not in _CATEGORIES and not pd.api.types.is_numeric_dtype(rows[color]):
        raise ValueError(
            f"invalid color {color!r}: it must be 'regime', 'crack.verdict' or a numeric column"
        )
    names = unit_names(units)
    xs, ys = floats(rows, x), floats(rows, y)
    ux, uy = np.unique(xs), np.unique(ys)
    grid = len(ux) * len(uy) == len(rows) and len(ux) > 1 and len(uy) > 1
    cells = np.full((len(uy), len(ux)), np.nan)
    index = (np.searchsorted(uy, ys), np.searchsorted(ux, xs))
    ax = new_axes(ax, (7.0, 5.0))
    mpl = importlib.import_module("matplotlib")
    if color in _CATEGORIES:
        colours, title, blank = _CATEGORIES[color]
        codes, category = _category_codes(rows, color, colours)
        cmap = mpl.colors.ListedColormap(list(colours.values()))
        bounds = np.arange(len(colours) + 1) - 0.5
        norm = mpl.colors.BoundaryNorm(bounds, len(colours))
        if grid:
            cells[index] = codes
            ax.pcolormesh(_cell_edges(ux), _cell_edges(uy), cells, cmap=cmap, norm=norm)
        else:
            ax.scatter(xs, ys, c=codes, cmap=cmap, norm=norm, s=14)
        handles = [
            mpl.patches.Patch(color=c, label=n or blank)
            for n, c in colours.items() if (category == n).any()
        ]
        ax.legend(handles=handles, fontsize=8, loc="best", framealpha=0.9)
    else:
        values = floats(rows, color)
        if not np.isfinite(values).any():
            raise ValueError(f"column {color!r} has no finite value to draw")
        mesh: Any
        if grid:
            cells[index] = values
            masked = np.ma.masked_invalid(cells)
            mesh = ax.pcolormesh(_cell_edges(ux), _cell_edges(uy), masked, cmap="viridis")
            if np.isfinite(cells).sum() >= 4:
                lines = ax.contour(ux, uy, masked, levels=8, colors="w", linewidths=0.7)
                ax.clabel(lines, inline=True, fontsize=7, fmt=level)
        else:
            mesh = ax.scatter(xs, ys, c=values, cmap="viridis", s=14, plotnonfinite=False)
        figure = ax.get_figure()
        assert figure is not None
        title = _describe(color, names)
        plain_axis(figure.colorbar(mesh, ax=ax, label=title).ax.yaxis)
        k = int(np.nanargmax(values))
        mark(ax, float(xs[k]), float(ys[k]),
             f"max {plain(float(values[k]))} at ({plain(float(xs[k]))}, {plain(float(ys[k]))})")
        ax.legend(fontsize=8, loc="best", framealpha=0.9)
    ax.set_xlabel(_describe(x, names))
    ax.set_ylabel(_describe(y, names))
    plain_axis(ax.xaxis)
    plain_axis(ax.yaxis)
    shown = ", ".join(
        f"{_describe(k, names)} = {plain(float(v))}" for k, v in (where or {}).items()
    )
    ax.set_title(title + (f"\n{shown}" if shown else ""), fontsize=10)
    return ax
