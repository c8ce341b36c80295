"""Will the crack grow? :func:`crack` (``halfplane crack``) and its typed result."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import pandas as pd

from . import _halfplane
from ._halfplane import Case
from ._records import Record, Units, _cells, _frame, _html_table, _num, _overrides, _plain
from .errors import InputError

#: The ``crack --csv`` columns, in order (public names fixed by the issue that added them).
CRACK_COLUMNS: Tuple[str, ...] = (
    "length",
    "k1_max",
    "k1_min",
    "k2_max",
    "k2_min",
    "delta_k1",
    "delta_k2",
    "delta_k_eff",
    "threshold",
)


@dataclass(frozen=True, eq=False)
class CrackResult(Record):
    """The report of ``halfplane crack``: ``verdict`` (``"arrests"``, ``"propagates"`` or
    ``"no-growth"``), ``arrest_length`` (the first length, after the range exceeded the
    threshold, where it falls to or below it again; None unless the crack arrests), ``position``
    (the mouth's x), ``angle`` (degrees from the surface normal, positive towards +x: the angle
    taken, also when ``[crack] angle = "critical-plane"``), ``half_width`` (the largest contact
    half-width of the steady cycle), ``first_step`` and ``last_step`` (the steady cycle's
    increments, 1-based), ``units`` (:class:`Units`), ``intensity_unit`` (K's unit, e.g.
    ``"MPa sqrt(mm)"``), and ``rows``, a DataFrame with the columns of ``crack --csv``: ``length,
    k1_max, k1_min, k2_max, k2_min, delta_k1, delta_k2, delta_k_eff, threshold`` (float64; K in
    ``intensity_unit``; each access returns a copy). ``to_dict()`` is the ``--json`` object
    (``rows`` as a list of row objects). Definitions in docs/crack.md."""

    _EXTRA: ClassVar[Tuple[str, ...]] = ("_table",)

    verdict: str
    arrest_length: Optional[float]
    position: float
    angle: float
    half_width: float
    first_step: int
    last_step: int
    _table: pd.DataFrame
    units: Units
    intensity_unit: str

    @classmethod
    def _from(cls, data: Mapping[str, Any]) -> CrackResult:
        arrest = data["arrest_length"]
        return cls(
            verdict=str(data["verdict"]),
            arrest_length=None if arrest is None else float(arrest),
            position=float(data["position"]),
            angle=float(data["angle"]),
            half_width=float(data["half_width"]),
            first_step=int(data["first_step"]),
            last_step=int(data["last_step"]),
            _table=_frame(data["rows"], {c: "float64" for c in CRACK_COLUMNS}),
            units=Units._from(data["units"]),
            intensity_unit=str(data["intensity_unit"]),
        )

    @property
    def rows(self) -> pd.DataFrame:
        """One row per crack length, ascending (a copy)."""
        copy: pd.DataFrame = self._table.copy()
        return copy

    def _keys(self) -> List[str]:
        return ["rows", *super()._keys()]

    def __getitem__(self, key: str) -> Any:
        if key == "rows":
            return self.to_dict()["rows"]
        return super().__getitem__(key)

    def to_dict(self) -> Dict[str, Any]:
        """The ``crack --json`` object."""
        out: Dict[str, Any] = {}
        for key in self._keys():
            if key == "rows":
                out[key] = [
                    {str(k): float(v) for k, v in r.items()}
                    for r in self._table.to_dict("records")
                ]
            else:
                out[key] = _plain(getattr(self, key))
        return out

    def __repr__(self) -> str:
        arrest = "" if self.arrest_length is None else f" at {_num(self.arrest_length)}"
        return (
            f"CrackResult({self.verdict}{arrest}, x = {_num(self.position)}, "
            f"angle = {self.angle:.2f}, {len(self._table)} lengths)"
        )

    def _repr_html_(self) -> str:
        length, k = self.units.length, self.intensity_unit
        rows: List[List[str]] = [
            [_num(float(r["length"]))]
            + [_num(float(r[c])) for c in ("delta_k1", "delta_k2", "delta_k_eff", "threshold")]
            for r in self._table.to_dict("records")
        ]
        arrest = "" if self.arrest_length is None else f" at {_num(self.arrest_length)} {length}"
        return _html_table(
            f"CrackResult: {self.verdict}{arrest}; crack at x = {_num(self.position)} {length}, "
            f"{self.angle:.2f}° from the surface normal",
            rows,
            header=(f"length [{length}]", f"ΔK_I [{k}]", f"ΔK_II [{k}]", f"ΔK_eff [{k}]",
                    f"threshold [{k}]"),
        )


_Lengths = Union[Sequence[float], Mapping[str, float]]


def crack(
    case: Case,
    cells: Optional[int] = None,
    *,
    position: Union[None, str, float] = None,
    angle: Union[None, str, float] = None,
    lengths: Optional[_Lengths] = None,
    face_friction: Optional[float] = None,
    points: Optional[int] = None,
    effective_range: Optional[str] = None,
    initiation_parameter: Optional[str] = None,
) -> CrackResult:
    """Will a crack grow? The stress intensity factors of a straight surface-breaking crack over
    the steady (last) cycle of the case's ``[history]``, against El Haddad's short-crack threshold
    from its ``[fatigue]`` constants, as ``halfplane crack``: the same numbers as ``--json``
    (``to_dict()``) and ``--csv`` (``.rows``).

    The crack is the case's ``[crack]`` section; each keyword given replaces (or supplies) that
    field of it, with the section's meaning and checks: ``position`` (``"left-edge"``,
    ``"right-edge"`` or an x), ``angle`` (degrees from the surface normal, or
    ``"critical-plane"``), ``lengths`` (a list, or ``{"from": ..., "to": ..., "count": ...}``
    spaced geometrically), ``face_friction``, ``points``, ``effective_range`` (``"mts"`` or
    ``"quadratic"``), ``initiation_parameter``. ``cells`` overrides ``[solver] cells``. Raises
    :class:`InputError` naming the field for bad input (a length that is not positive or longer
    than the contact's largest half-width, an angle outside (-90, 90), a case without
    ``[history]``, ``[crack]`` lengths or the ``[fatigue]`` constants ``threshold`` and
    ``endurance_range``). The GIL is released while computing.
    """
    overrides = _overrides(
        "crack",
        {
            "position": position,
            "angle": angle,
            "face_friction": face_friction,
            "points": points,
            "effective_range": effective_range,
            "initiation_parameter": initiation_parameter,
        },
    )
    if lengths is not None:
        overrides["lengths"] = _lengths(lengths)
    report = _halfplane.crack_report(case, _cells(cells), overrides or None)
    return CrackResult._from(report)


def _lengths(value: _Lengths) -> Any:
    """``lengths`` as ``[crack]`` takes it: a range mapping as given, else a list of floats (from
    a list, a tuple or a numpy array)."""
    if isinstance(value, Mapping):
        return dict(value)
    try:
        return [float(v) for v in value]
    except (TypeError, ValueError):
        raise InputError(
            f"invalid crack.lengths = {value!r}: must be a list of lengths > 0 in ascending "
            "order, or {'from': ..., 'to': ..., 'count': ...}"
        ) from None
