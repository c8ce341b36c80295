"""What the figures of :mod:`halfplane.plot` share: matplotlib imported on first use, new axes,
unit names for the labels, numbers in plain notation and column checks."""

from __future__ import annotations

import importlib
import math
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt
import pandas as pd

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

Floats = npt.NDArray[np.float64]


def pyplot() -> Any:
    """matplotlib.pyplot, imported on first use; ImportError saying how to install it."""
    try:
        return importlib.import_module("matplotlib.pyplot")
    except ImportError as e:
        raise ImportError(
            "halfplane.plot needs matplotlib: install it with the package's plot extra, "
            'pip install "./python[plot]" (or pip install matplotlib)'
        ) from e


def new_axes(ax: Axes | None, size: tuple[float, float] = (6.4, 4.6)) -> Axes:
    """``ax``, or the Axes of a new pyplot figure (so notebooks and the gallery show it)."""
    if ax is not None:
        return ax
    _, new = pyplot().subplots(figsize=size, layout="constrained")
    return new  # type: ignore[no-any-return]


def new_pair(axes: Sequence[Axes] | None) -> tuple[Figure, Axes, Axes]:
    """The two Axes given and their figure, or a new figure of two panels side by side."""
    if axes is not None:
        if len(axes) != 2:
            raise ValueError(f"axes must be two Axes, one per panel; {len(axes)} given")
        figure = axes[0].get_figure()
        if figure is None:  # pragma: no cover - an Axes always belongs to a figure
            raise ValueError("the Axes given belong to no figure")
        return figure, axes[0], axes[1]  # type: ignore[return-value]
    fig, pair = pyplot().subplots(1, 2, figsize=(11.0, 4.4), layout="constrained")
    return fig, pair[0], pair[1]


def unit_names(units: Mapping[str, str] | None) -> tuple[str, str, str]:
    """(force per length, length, stress) names for axis labels from ``{"force", "length",
    "stress"}`` names (default N, mm, MPa: "N/mm", "mm", "MPa")."""
    given = dict(units or {})
    unknown = sorted(set(given) - {"force", "length", "stress"})
    if unknown:
        raise ValueError(f"invalid units key(s) {unknown}: the keys are force, length and stress")
    length = given.get("length", "mm")
    return f"{given.get('force', 'N')}/{length}", length, given.get("stress", "MPa")


def plain(value: float, digits: int = 4) -> str:
    """``value`` to ``digits`` significant figures in plain notation (430.9, 0.006065, 90201)."""
    if not math.isfinite(value) or value == 0.0:
        return f"{value:g}"
    decimals = digits - 1 - math.floor(math.log10(abs(value)))
    return f"{value:.{min(max(decimals, 0), 12)}f}"


def level(value: float) -> str:
    """A contour level's label: 3 significant figures in plain notation, trailing zeros off."""
    text = plain(float(value), 3)
    return text.rstrip("0").rstrip(".") if "." in text else text


def plain_axis(axis: Any) -> None:
    """Tick labels of ``axis`` in plain notation: no offset, no scientific factor."""
    formatter = importlib.import_module("matplotlib.ticker").ScalarFormatter(useOffset=False)
    formatter.set_scientific(False)
    axis.set_major_formatter(formatter)


def require_columns(frame: pd.DataFrame, names: Sequence[str], what: str) -> None:
    """ValueError naming the columns of ``names`` that ``frame`` lacks, and those it has."""
    missing = [n for n in names if n not in frame.columns]
    if missing:
        raise ValueError(
            f"{what} lacks column(s) {', '.join(map(repr, missing))}; it has "
            f"{', '.join(map(str, frame.columns))}"
        )


def mark(ax: Axes, x: float, y: float, text: str) -> None:
    """A star at (x, y), with ``text`` as its legend entry."""
    ax.plot(
        [x], [y], marker="*", ms=13, color="k", mfc="yellow", mew=1.0, ls="none", label=text,
        zorder=5,
    )


def floats(frame: pd.DataFrame, column: str) -> Floats:
    """A column as a float64 array."""
    return np.asarray(frame[column].to_numpy(np.float64), dtype=np.float64)
