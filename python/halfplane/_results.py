"""The results of ``halfplane steady`` (:class:`SteadyResult` and its parts) and of
``halfplane march`` (:class:`MarchResult`), built on the records of :mod:`halfplane._records`."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Dict, List, Mapping, Optional

import pandas as pd

from ._records import (
    Edges,
    FloatArray,
    LoadPoint,
    PerPoint,
    Profile,
    Record,
    Units,
    _edges,
    _float,
    _html_table,
    _num,
    _opt_float,
    _per_point,
    _text,
)


@dataclass(frozen=True, eq=False)
class Criteria(Record):
    """The regime's criteria: ``shear_ratio_1``, ``_2`` (|Q|/P at point1 and point2 as given),
    ``full_stick_ratio`` ((|dQ| + pi a_max |dsigma|/4)/|dP|, eq. (1); None when dP = 0),
    ``shear_range`` dQ, ``bulk_term`` (pi a_max |dsigma|/4) and ``friction`` f."""

    shear_ratio_1: float
    shear_ratio_2: float
    full_stick_ratio: Optional[float]
    shear_range: float
    bulk_term: float
    friction: float

    @classmethod
    def _from(cls, data: Mapping[str, Any]) -> Criteria:
        return cls(
            _float(data["shear_ratio_1"]),
            _float(data["shear_ratio_2"]),
            _opt_float(data["full_stick_ratio"]),
            _float(data["shear_range"]),
            _float(data["bulk_term"]),
            _float(data["friction"]),
        )


@dataclass(frozen=True, eq=False)
class ContactState(Record):
    """The contact at point1 and point2 as given: ``half_width_1``, ``_2`` (a) and
    ``normal_intensity_1``, ``_2`` (K_N; None where the two edges' K_N differ, under a moment or on
    an asymmetric profile); the ends ``left_1``, ``right_1``, ``left_2``, ``right_2`` (signed x of
    b1 and b2), K_N at each edge (``normal_intensity_left_1`` ...), the pad's rotations
    ``rotation_1``, ``_2`` (the gap gains theta x) and whether each end lies on the flat of a
    flat-rounded pad (``on_flat_left_1`` ...)."""

    half_width_1: float
    half_width_2: float
    normal_intensity_1: Optional[float]
    normal_intensity_2: Optional[float]
    left_1: float = math.nan
    right_1: float = math.nan
    left_2: float = math.nan
    right_2: float = math.nan
    normal_intensity_left_1: float = math.nan
    normal_intensity_right_1: float = math.nan
    normal_intensity_left_2: float = math.nan
    normal_intensity_right_2: float = math.nan
    rotation_1: float = 0.0
    rotation_2: float = 0.0
    on_flat_left_1: bool = False
    on_flat_right_1: bool = False
    on_flat_left_2: bool = False
    on_flat_right_2: bool = False

    @classmethod
    def _from(cls, data: Mapping[str, Any]) -> ContactState:
        return cls(
            half_width_1=_float(data["half_width_1"]),
            half_width_2=_float(data["half_width_2"]),
            normal_intensity_1=_opt_float(data["normal_intensity_1"]),
            normal_intensity_2=_opt_float(data["normal_intensity_2"]),
            left_1=_float(data["left_1"]),
            right_1=_float(data["right_1"]),
            left_2=_float(data["left_2"]),
            right_2=_float(data["right_2"]),
            normal_intensity_left_1=_float(data["normal_intensity_left_1"]),
            normal_intensity_right_1=_float(data["normal_intensity_right_1"]),
            normal_intensity_left_2=_float(data["normal_intensity_left_2"]),
            normal_intensity_right_2=_float(data["normal_intensity_right_2"]),
            rotation_1=_float(data["rotation_1"]),
            rotation_2=_float(data["rotation_2"]),
            on_flat_left_1=bool(data["on_flat_left_1"]),
            on_flat_right_1=bool(data["on_flat_right_1"]),
            on_flat_left_2=bool(data["on_flat_left_2"]),
            on_flat_right_2=bool(data["on_flat_right_2"]),
        )


@dataclass(frozen=True, eq=False)
class StickZone(Record):
    """The permanent stick zone [-m, n]: ``left`` = -m, ``right`` = n, ``half_width``
    d = (m + n)/2 and ``eccentricity`` e = (n - m)/2 (x positive in the direction of positive
    Q)."""

    left: float
    right: float
    half_width: float
    eccentricity: float

    @classmethod
    def _from(cls, data: Mapping[str, Any]) -> StickZone:
        return cls(
            _float(data["left"]),
            _float(data["right"]),
            _float(data["half_width"]),
            _float(data["eccentricity"]),
        )


@dataclass(frozen=True, eq=False)
class AsymptoticStickZone(Record):
    """The asymptotic estimate of the stick zone, ``left`` and ``right``, and each one's
    relative difference from the exact one."""

    left: float
    right: float
    relative_difference_left: float
    relative_difference_right: float

    @classmethod
    def _from(cls, data: Mapping[str, Any]) -> AsymptoticStickZone:
        return cls(
            _float(data["left"]),
            _float(data["right"]),
            _float(data["relative_difference_left"]),
            _float(data["relative_difference_right"]),
        )


@dataclass(frozen=True, eq=False)
class EdgeIntensities(Record):
    """The edge description at one point: ``shear_intensity_left``, ``_right`` (K_T) and
    ``equivalent_shear_left``, ``_right`` (S)."""

    shear_intensity_left: float
    shear_intensity_right: float
    equivalent_shear_left: float
    equivalent_shear_right: float

    @classmethod
    def _from(cls, data: Mapping[str, Any]) -> EdgeIntensities:
        return cls(
            _float(data["shear_intensity_left"]),
            _float(data["shear_intensity_right"]),
            _float(data["equivalent_shear_left"]),
            _float(data["equivalent_shear_right"]),
        )


@dataclass(frozen=True, eq=False)
class Estimate(Record):
    """An asymptotic ``estimate`` against the ``exact`` value, and their
    ``relative_difference`` (estimate - exact)/exact."""

    estimate: float
    exact: float
    relative_difference: float

    @classmethod
    def _from(cls, data: Mapping[str, Any]) -> Estimate:
        return cls(
            _float(data["estimate"]), _float(data["exact"]), _float(data["relative_difference"])
        )


@dataclass(frozen=True, eq=False)
class Asymptotic(Record):
    """The asymptotic (edge) description in partial slip: ``stick_zone`` (estimate),
    ``stick_load`` (P_K at each edge), ``edges`` (K_T and S at each point) and ``slip_zones``
    (estimate against exact, at each edge and point)."""

    stick_zone: AsymptoticStickZone
    stick_load: Edges[float]
    edges: PerPoint[EdgeIntensities]
    slip_zones: Edges[PerPoint[Estimate]]

    @classmethod
    def _from(cls, data: Mapping[str, Any]) -> Asymptotic:
        return cls(
            AsymptoticStickZone._from(data["stick_zone"]),
            _edges(data["stick_load"], _float),
            _per_point(data["edges"], EdgeIntensities._from),
            _edges(data["slip_zones"], lambda e: _per_point(e, Estimate._from)),
        )


@dataclass(frozen=True, eq=False)
class SteadyResult(Record):
    """The steady state of a case's cycle: every field of ``halfplane steady --json`` as a typed
    attribute, nested as in the JSON (``result.stick_zone.left``,
    ``result.slip_zones.right.at_point2``, ``result.criteria.shear_ratio_1``, ...).

    Main fields (lengths in the case's length unit, mm by default; loads N/mm; stresses MPa):

    - ``regime``: ``"partial-slip"``, ``"full-stick"`` or ``"gross-sliding"``;
    - ``profile`` (:class:`Profile`), ``compliance`` A, ``friction`` f;
    - ``points``: the loads at ``at_point1`` and ``at_point2`` as given (:class:`LoadPoint`);
    - ``contact.half_width_1``, ``_2``: contact half-width a at point1, point2 as given
      (:class:`ContactState`);
    - ``stick_zone.left``, ``.right``: the permanent stick zone [-m, n] (x positive in the
      direction of positive Q); ``.half_width`` d = (m + n)/2, ``.eccentricity`` e = (n - m)/2;
      None in gross sliding (:class:`StickZone`);
    - ``slip_zones.left.at_point1`` ... ``.right.at_point2``: slip-zone lengths a_i - m (left),
      a_i - n (right); 0 in full stick; None in gross sliding;
    - ``criteria``: |Q|/P at each point, eq. (1)'s full-stick ratio, the bulk-tension term
      (:class:`Criteria`);
    - ``asymptotic``: the edge description (K_T, S, P_K and slip-zone estimates) in partial slip,
      else None (:class:`Asymptotic`);
    - ``smaller_shear_point``: which point is the analysis's point 1 (the end of smaller Q);
    - ``units``: the unit names (:class:`Units`).

    Sign conventions: P > 0 compresses; Q and the bulk tension sigma are positive as in the paper's
    Figure 1; tension adds to the shear at the left edge. ``to_dict()`` equals the command's JSON.
    """

    regime: str
    profile: Profile
    compliance: float
    friction: float
    points: PerPoint[LoadPoint]
    smaller_shear_point: str
    criteria: Criteria
    contact: ContactState
    stick_zone: Optional[StickZone]
    slip_zones: Optional[Edges[PerPoint[float]]]
    asymptotic: Optional[Asymptotic]
    units: Units

    @classmethod
    def _from(cls, data: Mapping[str, Any]) -> SteadyResult:
        zone = data["stick_zone"]
        slip = data["slip_zones"]
        asymptotic = data["asymptotic"]
        return cls(
            regime=str(data["regime"]),
            profile=Profile._from(data["profile"]),
            compliance=_float(data["compliance"]),
            friction=_float(data["friction"]),
            points=_per_point(data["points"], LoadPoint._from),
            smaller_shear_point=str(data["smaller_shear_point"]),
            criteria=Criteria._from(data["criteria"]),
            contact=ContactState._from(data["contact"]),
            stick_zone=None if zone is None else StickZone._from(zone),
            slip_zones=None if slip is None else _edges(slip, lambda e: _per_point(e, _float)),
            asymptotic=None if asymptotic is None else Asymptotic._from(asymptotic),
            units=Units._from(data["units"]),
        )

    def __repr__(self) -> str:
        c = self.contact
        parts = [
            f"regime={self.regime!r}",
            f"half_widths=({c.half_width_1:.6g}, {c.half_width_2:.6g})",
        ]
        if self.stick_zone is not None:
            z = self.stick_zone
            parts.append(f"stick_zone=[{z.left:.6g}, {z.right:.6g}]")
        if self.slip_zones is not None:
            s = self.slip_zones
            parts.append(
                f"slip_zones={{left: ({s.left.at_point1:.6g}, {s.left.at_point2:.6g}), "
                f"right: ({s.right.at_point1:.6g}, {s.right.at_point2:.6g})}}"
            )
        return f"SteadyResult({', '.join(parts)})"

    def _repr_html_(self) -> str:
        u = self.units
        force = f"{u.force}/{u.length}"
        p1, p2 = self.points.at_point1, self.points.at_point2
        first, second = self.contact.half_width_1, self.contact.half_width_2
        rows: List[List[str]] = [
            ["regime", self.regime],
            [f"normal P [{force}]", _num(p1.normal), _num(p2.normal)],
            [f"shear Q [{force}]", _num(p1.shear), _num(p2.shear)],
            [f"bulk σ [{u.stress}]", _num(p1.bulk), _num(p2.bulk)],
            [f"contact half-width a [{u.length}]", _num(first), _num(second)],
        ]
        if self.slip_zones is not None:
            s = self.slip_zones
            rows.append(
                [f"slip zone left [{u.length}]", _num(s.left.at_point1), _num(s.left.at_point2)]
            )
            rows.append(
                [f"slip zone right [{u.length}]", _num(s.right.at_point1), _num(s.right.at_point2)]
            )
        zone = self.stick_zone
        rows.append(
            [
                f"stick zone [-m, n] [{u.length}]",
                "none (gross sliding)"
                if zone is None
                else f"[{_num(zone.left)}, {_num(zone.right)}]",
            ]
        )
        c = self.criteria
        rows.append(
            [
                "|Q|/P",
                _num(c.shear_ratio_1),
                _num(c.shear_ratio_2),
            ]
        )
        rows.append(["full-stick ratio, eq. (1)", _num(c.full_stick_ratio)])
        rows.append(["friction f", _num(self.friction)])
        return _html_table(
            f"SteadyResult ({self.profile.kind})", rows, header=("", "point1", "point2")
        )


@dataclass(frozen=True, eq=False)
class MarchResult:
    """The marched history of a case (``halfplane march``).

    - ``steps``: one row per increment with the ``march --csv`` columns: ``step, normal, shear,
      bulk, half_width, stick_left, stick_right, stick_intervals, energy_increment, energy,
      passes, moment, contact_left, contact_right, relative_displacement`` (stick columns: the
      largest stick interval, NaN when none; ``stick_intervals`` every interval as
      ``"left:right"`` separated by spaces, NaN when none);
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
    - ``loop_datum``: the datum of the steps' ``relative_displacement`` (the bodies' relative
      tangential displacement, the fretting loop against ``shear``): ten times the largest
      contact half-width reached (None for a result built without it);
    - with ``fields=True``: ``pressure`` p (>= 0), ``traction`` q (positive in the direction of
      positive Q), ``slip`` (accumulated, positive in the sense positive Q drives) and
      ``slip_increment``, each of shape (increments, cells); otherwise None;
    - ``cells``, ``increments``: the grid's and the history's sizes; ``final_state``: the contact
      at the last increment in words.

    Read-only (a frozen dataclass); it pickles.
    """

    steps: pd.DataFrame
    cycles: pd.DataFrame
    shakedown_cycle: Optional[int]
    cycles_run: int
    steady_change: Optional[float]
    steady_converged: Optional[bool]
    x: FloatArray
    loop_datum: Optional[float]
    pressure: Optional[FloatArray]
    traction: Optional[FloatArray]
    slip: Optional[FloatArray]
    slip_increment: Optional[FloatArray]

    def __init__(
        self,
        steps: pd.DataFrame,
        cycles: pd.DataFrame,
        shakedown_cycle: Optional[int],
        x: FloatArray,
        fields: Optional[Mapping[str, FloatArray]] = None,
        cycles_run: Optional[int] = None,
        steady_change: Optional[float] = None,
        steady_converged: Optional[bool] = None,
        loop_datum: Optional[float] = None,
    ) -> None:
        fields = fields or {}
        values: Dict[str, Any] = {
            "steps": steps,
            "cycles": cycles,
            "shakedown_cycle": shakedown_cycle,
            "cycles_run": len(cycles) if cycles_run is None else cycles_run,
            "steady_change": steady_change,
            "steady_converged": steady_converged,
            "x": x,
            "loop_datum": loop_datum,
            "pressure": fields.get("pressure"),
            "traction": fields.get("traction"),
            "slip": fields.get("slip"),
            "slip_increment": fields.get("slip_increment"),
        }
        for name, value in values.items():
            object.__setattr__(self, name, value)

    @property
    def cells(self) -> int:
        """Number of cells."""
        return int(self.x.shape[0])

    @property
    def increments(self) -> int:
        """Number of increments."""
        return int(len(self.steps))

    @property
    def final_state(self) -> str:
        """The contact at the last increment: ``"full stick"`` when its largest stick interval
        spans the contact to within a cell at each end, ``"partial slip"`` when it is shorter,
        ``"sliding"`` when no cell sticks."""
        if self.increments == 0:
            return "no increments"
        last = self.steps.iloc[-1]
        left, right = float(last["stick_left"]), float(last["stick_right"])
        a = float(last["half_width"])
        if math.isnan(left) or math.isnan(right):
            return "sliding"
        cell = float(self.x[1] - self.x[0]) if self.cells > 1 else 0.0
        if left <= -a + cell and right >= a - cell:
            return "full stick"
        return "partial slip"

    def __repr__(self) -> str:
        fields = "with fields" if self.pressure is not None else "no fields"
        return (
            f"MarchResult({self.increments} increments, {self.cells} cells, "
            f"{len(self.cycles)} cycles, shakedown_cycle={self.shakedown_cycle}, "
            f"steady_converged={self.steady_converged}, {fields})"
        )

    def _repr_html_(self) -> str:
        rows: List[List[str]] = [
            ["increments", str(self.increments)],
            ["cells", str(self.cells)],
            ["cycles run", str(self.cycles_run)],
            ["shakedown cycle", _text(self.shakedown_cycle)],
            ["steady change (A f P_max)", _num(self.steady_change)],
            ["steady converged", _text(self.steady_converged)],
        ]
        if len(self.cycles):
            last_cycle = self.cycles.iloc[-1]
            rows.append(["energy of the last cycle", _num(float(last_cycle["energy"]))])
            rows.append(
                ["max slip amplitude (last cycle)", _num(float(last_cycle["max_slip_amplitude"]))]
            )
        if self.increments:
            last = self.steps.iloc[-1]
            rows.append(["final state", self.final_state])
            rows.append(
                [
                    "final load P, Q, σ",
                    f"{_num(float(last['normal']))}, {_num(float(last['shear']))}, "
                    f"{_num(float(last['bulk']))}",
                ]
            )
            rows.append(["final contact half-width a", _num(float(last["half_width"]))])
            left, right = float(last["stick_left"]), float(last["stick_right"])
            stick = "none" if math.isnan(left) else f"[{_num(left)}, {_num(right)}]"
            rows.append(["final stick zone (largest)", stick])
            rows.append(["energy dissipated in all", _num(float(last["energy"]))])
        rows.append(["fields", "recorded" if self.pressure is not None else "not recorded"])
        return _html_table("MarchResult", rows)


__all__ = [
    "Asymptotic",
    "AsymptoticStickZone",
    "ContactState",
    "Criteria",
    "EdgeIntensities",
    "Estimate",
    "MarchResult",
    "SteadyResult",
    "StickZone",
]
