"""Result objects: :class:`SteadyResult` (the JSON of ``halfplane steady --json`` as attributes)
and :class:`MarchResult` (the tables and fields of ``halfplane march``)."""

from __future__ import annotations

import copy
from typing import Any, Dict, Iterator, List, Mapping, Optional, Tuple

import numpy as np
import pandas as pd


def _wrap(value: Any) -> Any:
    if isinstance(value, dict):
        return Record(value)
    if isinstance(value, list):
        return [_wrap(v) for v in value]
    return value


class Record:
    """A read-only view of a JSON object: its keys are attributes (nested objects are Records,
    ``null`` is None). ``to_dict()`` returns the object itself, as plain dicts and lists."""

    def __init__(self, data: Mapping[str, Any]) -> None:
        object.__setattr__(self, "_data", dict(data))

    def __getattr__(self, name: str) -> Any:
        data = self.__dict__.get("_data", {})
        if name in data:
            return _wrap(data[name])
        raise AttributeError(f"{type(self).__name__} has no field {name!r} (fields: {', '.join(data)})")

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(f"{type(self).__name__} is read-only")

    def __getitem__(self, key: str) -> Any:
        return _wrap(self._data[key])

    def __iter__(self) -> Iterator[str]:
        return iter(self._data)

    def __dir__(self) -> List[str]:
        return sorted(set(self._data) | {"to_dict"})

    def __eq__(self, other: object) -> bool:
        return type(other) is type(self) and other.to_dict() == self.to_dict()  # type: ignore[attr-defined]

    __hash__ = None  # type: ignore[assignment]

    def __reduce__(self) -> Tuple[Any, Tuple[Dict[str, Any]]]:
        return (type(self), (self._data,))

    def to_dict(self) -> Dict[str, Any]:
        """The fields as plain dicts, lists, numbers, strings and None (a deep copy)."""
        return copy.deepcopy(self._data)

    def __repr__(self) -> str:
        inner = ", ".join(f"{k}={_short(v)}" for k, v in self._data.items())
        return f"{type(self).__name__}({inner})"


def _short(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:.6g}"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{k}: {_short(v)}" for k, v in value.items()) + "}"
    if isinstance(value, list):
        return "[" + ", ".join(_short(v) for v in value) + "]"
    return repr(value)


class SteadyResult(Record):
    """The steady state of a case's cycle: every field of ``halfplane steady --json`` as an
    attribute, nested as in the JSON (``result.stick_zone.left``,
    ``result.slip_zones.right.at_point2``, ``result.criteria.shear_ratio_1``, ...).

    Main fields (lengths in the case's length unit, mm by default; loads N/mm; stresses MPa):

    - ``regime``: ``"partial-slip"``, ``"full-stick"`` or ``"gross-sliding"``;
    - ``contact.half_width_1``, ``_2``: contact half-width a at point1, point2 as given;
    - ``stick_zone.left``, ``.right``: the permanent stick zone [-m, n] (x positive in the
      direction of positive Q); ``.half_width`` d = (m + n)/2, ``.eccentricity`` e = (n - m)/2;
      None in gross sliding;
    - ``slip_zones.left.at_point1`` ... ``.right.at_point2``: slip-zone lengths a_i - m (left),
      a_i - n (right); 0 in full stick;
    - ``criteria``: |Q|/P at each point, eq. (1)'s full-stick ratio, the bulk-tension term;
    - ``asymptotic``: the edge description (K_T, S, P_K and slip-zone estimates) in partial slip;
    - ``smaller_shear_point``: which point is the analysis's point 1 (the end of smaller Q).

    Sign conventions: P > 0 compresses; Q and the bulk tension sigma are positive as in the paper's
    Figure 1; tension adds to the shear at the left edge. ``to_dict()`` equals the parsed JSON.
    """

    def __repr__(self) -> str:
        d = self._data
        zone = d.get("stick_zone")
        parts = [f"regime={d['regime']!r}"]
        c = d["contact"]
        parts.append(f"half_widths=({c['half_width_1']:.6g}, {c['half_width_2']:.6g})")
        if zone is not None:
            parts.append(f"stick_zone=[{zone['left']:.6g}, {zone['right']:.6g}]")
        slip = d.get("slip_zones")
        if slip is not None:
            parts.append(
                "slip_zones={left: (%.6g, %.6g), right: (%.6g, %.6g)}"
                % (
                    slip["left"]["at_point1"],
                    slip["left"]["at_point2"],
                    slip["right"]["at_point1"],
                    slip["right"]["at_point2"],
                )
            )
        return f"SteadyResult({', '.join(parts)})"


class MarchResult:
    """The marched history of a case (``halfplane march``).

    - ``steps``: one row per increment with the ``march --csv`` columns: ``step, normal, shear,
      bulk, half_width, stick_left, stick_right, stick_intervals, energy_increment, energy,
      passes`` (stick columns: the largest stick interval, NaN when none; ``stick_intervals``
      every interval as ``"left:right"`` separated by spaces);
    - ``cycles``: one row per load cycle (cyclic histories): ``index, energy,
      max_slip_amplitude`` (energy per unit thickness, N mm/mm by default; amplitude is half the
      peak-to-peak slip, in the length unit);
    - ``shakedown_cycle``: the first cycle that the next one repeats, or None;
    - ``cycles_run``: the cycles marched (all of the history's, or, with ``cycles = "steady"``,
      those it took for the cycle to repeat);
    - ``steady_change``: the largest change of a cell's peak-to-peak slip range between the last
      two cycles, as a fraction of A f P_max (None with fewer than two cycles);
    - ``steady_converged``: whether that change is within ``history.steady_tolerance``
      (default 1e-10), or None with fewer than two cycles;
    - ``x``: cell centres (length unit), shape (cells,);
    - with ``fields=True``: ``pressure`` p (>= 0), ``traction`` q (positive in the direction of
      positive Q), ``slip`` (accumulated, positive in the sense positive Q drives) and
      ``slip_increment``, each of shape (increments, cells); otherwise None.
    """

    steps: pd.DataFrame
    cycles: pd.DataFrame
    shakedown_cycle: Optional[int]
    cycles_run: int
    steady_change: Optional[float]
    steady_converged: Optional[bool]
    x: np.ndarray
    pressure: Optional[np.ndarray]
    traction: Optional[np.ndarray]
    slip: Optional[np.ndarray]
    slip_increment: Optional[np.ndarray]

    def __init__(
        self,
        steps: pd.DataFrame,
        cycles: pd.DataFrame,
        shakedown_cycle: Optional[int],
        x: np.ndarray,
        fields: Optional[Mapping[str, np.ndarray]] = None,
        cycles_run: Optional[int] = None,
        steady_change: Optional[float] = None,
        steady_converged: Optional[bool] = None,
    ) -> None:
        self.steps = steps
        self.cycles = cycles
        self.shakedown_cycle = shakedown_cycle
        self.cycles_run = len(cycles) if cycles_run is None else cycles_run
        self.steady_change = steady_change
        self.steady_converged = steady_converged
        self.x = x
        fields = fields or {}
        self.pressure = fields.get("pressure")
        self.traction = fields.get("traction")
        self.slip = fields.get("slip")
        self.slip_increment = fields.get("slip_increment")

    @property
    def cells(self) -> int:
        """Number of cells."""
        return int(self.x.shape[0])

    @property
    def increments(self) -> int:
        """Number of increments."""
        return int(len(self.steps))

    def __repr__(self) -> str:
        fields = "with fields" if self.pressure is not None else "no fields"
        return (
            f"MarchResult({self.increments} increments, {self.cells} cells, "
            f"{len(self.cycles)} cycles, shakedown_cycle={self.shakedown_cycle}, "
            f"steady_converged={self.steady_converged}, {fields})"
        )
