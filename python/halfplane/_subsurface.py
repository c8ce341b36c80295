"""Below the surface: :func:`stress` (``halfplane stress``) and :func:`fatigue`
(``halfplane fatigue``)."""

from __future__ import annotations

import math
import numbers
import warnings
from dataclasses import dataclass, field
from typing import Any, ClassVar, Dict, List, Mapping, Optional, Tuple

import numpy as np
import numpy.typing as npt
import pandas as pd

from . import _halfplane
from ._halfplane import Case
from ._records import FloatArray, Record, Units, _frame, _html_table, _num, _plain
from .errors import InputError


def _count(name: str, value: Any) -> int:
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or int(value) < 0:
        raise InputError(f"invalid {name} = {value!r}: must be a whole number")
    return int(value)


def _floats(name: str, value: Any) -> FloatArray:
    try:
        return np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise InputError(f"invalid {name}: must be numbers ({e})") from None


class StressResult:
    """The stresses of :func:`stress`: ``sxx``, ``szz``, ``syy``, ``sxz``, float64 arrays of the
    broadcast shape of ``x`` and ``z``, in the case's stress unit (MPa by default); tension is
    positive, ``sxx`` includes the bulk tension sigma, ``syy = nu (sxx + szz)`` (plane strain);
    ``x`` runs in the sense of positive Q, ``z`` is the depth, and the surface shear traction is
    the one the other body exerts on this one, positive in +x (docs/stress.md). ``step`` is the
    increment used (1-based) and ``normal``, ``shear``, ``bulk``, ``half_width`` its load and
    contact half-width, ``moment`` M and ``contact_left``, ``contact_right`` the contact's ends
    (b1, b2: ``-half_width`` and ``half_width`` without a moment on a symmetric profile); ``x``
    and ``z`` are the points, broadcast to the same shape. ``to_dict()`` gives them all, arrays
    included."""

    def __init__(
        self,
        data: Mapping[str, Any],
        shape: Tuple[int, ...],
        x: Optional[FloatArray] = None,
        z: Optional[FloatArray] = None,
    ) -> None:
        self.step: int = int(data["step"])
        self.normal: float = float(data["normal"])
        self.shear: float = float(data["shear"])
        self.bulk: float = float(data["bulk"])
        self.half_width: float = float(data["half_width"])
        self.moment: float = float(data.get("moment", 0.0))
        self.contact_left: float = float(data.get("contact_left", -self.half_width))
        self.contact_right: float = float(data.get("contact_right", self.half_width))
        self.sxx: FloatArray = data["sxx"].reshape(shape)
        self.szz: FloatArray = data["szz"].reshape(shape)
        self.syy: FloatArray = data["syy"].reshape(shape)
        self.sxz: FloatArray = data["sxz"].reshape(shape)
        nan = np.full(shape, np.nan)
        self.x: FloatArray = nan if x is None else np.asarray(x, dtype=np.float64).reshape(shape)
        self.z: FloatArray = nan if z is None else np.asarray(z, dtype=np.float64).reshape(shape)

    def to_dict(self) -> Dict[str, Any]:
        """The fields by name (the arrays are the result's own)."""
        return dict(vars(self))

    def __repr__(self) -> str:
        return (
            f"StressResult(step={self.step}, normal={self.normal}, shear={self.shear}, "
            f"bulk={self.bulk}, shape={self.sxx.shape})"
        )

    def _repr_html_(self) -> str:
        rows: List[List[str]] = [
            ["step", str(self.step)],
            ["load P, Q, σ", f"{_num(self.normal)}, {_num(self.shear)}, {_num(self.bulk)}"],
            ["contact half-width a", _num(self.half_width)],
            ["points", f"{self.sxx.size} (shape {self.sxx.shape})"],
        ]
        for name in ("sxx", "szz", "syy", "sxz"):
            values: FloatArray = getattr(self, name)
            if values.size:
                low, high = _num(float(values.min())), _num(float(values.max()))
                rows.append([f"{name} min, max", f"{low}, {high}"])
        return _html_table("StressResult", rows)


def stress(
    case: Case,
    x: npt.ArrayLike,
    z: npt.ArrayLike,
    step: Optional[int] = None,
    cells: Optional[int] = None,
) -> StressResult:
    """The stresses below the contact at the points ``(x, z)`` at one increment of the case's
    ``[history]``, as ``halfplane stress CASE --at POINTS.csv --step STEP`` (the same march, the
    same closed forms, the same numbers).

    ``x`` runs along the surface and ``z >= 0`` is the depth into the body (length unit, mm by
    default); they are broadcast together (scalars, lists or arrays of any shape). ``step`` is the
    march increment, 1-based, by default the last; ``cells`` overrides ``[solver] cells``. Returns
    a :class:`StressResult` (signs there). Raises :class:`InputError` naming the field for a point
    that is not finite or has ``z < 0``, a surface point on a traction jump, or a ``step`` outside
    the history. The GIL is released while marching and evaluating.
    """
    xs, zs = np.broadcast_arrays(_floats("x", x), _floats("z", z))
    shape = xs.shape
    flat_x = np.ascontiguousarray(xs.ravel())
    flat_z = np.ascontiguousarray(zs.ravel())
    if step is not None:
        step = _count("step", step)
    if cells is not None:
        cells = _count("cells", cells)
    data = _halfplane.stress_points(case, flat_x, flat_z, step, cells)
    return StressResult(data, shape, flat_x, flat_z)


#: The ``fatigue --csv`` columns that are empty (NaN) where they do not apply; None in the JSON.
_OPTIONAL_PARAMETER_COLUMNS = ("plane", "point_method", "line_method", "cycles", "tilt")
#: The dtypes of the ``fatigue --csv`` columns, for a report without rows.
_PARAMETER_DTYPES = {
    "parameter": "object",
    "value": "float64",
    "x": "float64",
    "z": "float64",
    "plane": "float64",
    "step": "int64",
    "point_method": "float64",
    "line_method": "float64",
    "cycles": "float64",
    "tilt": "float64",
}


def _json_row(row: Mapping[Any, Any]) -> Dict[str, Any]:
    """A ``parameters`` row as the JSON holds it: Python numbers, None where a column does not
    apply."""
    out: Dict[str, Any] = {}
    for key, value in row.items():
        if isinstance(value, (np.integer, int)) and not isinstance(value, bool):
            out[str(key)] = int(value)
        elif isinstance(value, (np.floating, float)):
            number = float(value)
            out[str(key)] = None if math.isnan(number) else number
        else:
            out[str(key)] = value
    return out


@dataclass(frozen=True, eq=False)
class FatigueResult(Record):
    """The report of ``halfplane fatigue``: ``critical_distance`` (L, length unit, None
    when ``[fatigue]`` gives none), ``first_step`` and ``last_step`` (the steady cycle's
    increments, 1-based), ``units`` (:class:`Units`), and ``parameters``, a DataFrame with the
    columns of ``fatigue --csv``: ``parameter, value, x, z, plane, step, point_method,
    line_method, cycles, tilt`` (``plane`` in degrees from +x towards +z, ``tilt`` of the plane's
    normal towards +y, 0 unless ``[fatigue] planes = "3d"``; NaN where a column does not apply;
    each access returns a copy). ``to_dict()`` is the ``--json`` object (``parameters`` as a
    list of row objects, None where a column does not apply).

    The fields behind the maxima, over the ``[fatigue]`` grid: ``grid_x`` and ``grid_z`` (its
    axes, float64) and ``maps``, each grid parameter's name (``"swt"``, ``"mwcm"``, ... as in
    ``parameters``; Ruiz is a surface quantity and has none) to its values over the steady
    cycle, a float64 array of shape ``(len(grid_z), len(grid_x))``: what ``halfplane plot
    fatigue-map`` contours. They are not part of ``to_dict()``."""

    _EXTRA: ClassVar[Tuple[str, ...]] = ("_table", "grid_x", "grid_z", "maps")

    critical_distance: Optional[float]
    first_step: int
    last_step: int
    _table: pd.DataFrame
    units: Units
    grid_x: FloatArray = field(default_factory=lambda: np.empty(0))
    grid_z: FloatArray = field(default_factory=lambda: np.empty(0))
    maps: Mapping[str, FloatArray] = field(default_factory=dict)

    @classmethod
    def _from(cls, data: Mapping[str, Any]) -> FatigueResult:
        distance = data["critical_distance"]
        return cls(
            critical_distance=None if distance is None else float(distance),
            first_step=int(data["first_step"]),
            last_step=int(data["last_step"]),
            _table=_frame(data["parameters"], _PARAMETER_DTYPES),
            units=Units._from(data["units"]),
            grid_x=np.asarray(data["grid_x"], dtype=np.float64),
            grid_z=np.asarray(data["grid_z"], dtype=np.float64),
            maps={
                name: np.asarray(values, dtype=np.float64).reshape(
                    len(data["grid_z"]), len(data["grid_x"])
                )
                for name, values in data["maps"].items()
            },
        )

    @property
    def parameters(self) -> pd.DataFrame:
        """One row per parameter: its maximum over the steady cycle and where it occurs (a
        copy)."""
        copy: pd.DataFrame = self._table.copy()
        return copy

    def _keys(self) -> List[str]:
        keys = super()._keys()
        keys.insert(keys.index("units"), "parameters")
        return keys

    def __getitem__(self, key: str) -> Any:
        if key == "parameters":
            return self.to_dict()["parameters"]
        return super().__getitem__(key)

    def to_dict(self) -> Dict[str, Any]:
        """The ``fatigue --json`` object."""
        out: Dict[str, Any] = {}
        for key in self._keys():
            if key == "parameters":
                records = self._table.to_dict("records")
                out[key] = [_json_row(r) for r in records]
            else:
                out[key] = _plain(getattr(self, key))
        return out

    def __repr__(self) -> str:
        best = ", ".join(
            f"{r['parameter']}={_num(float(r['value']))}"
            for r in self._table.to_dict("records")
        )
        return (
            f"FatigueResult(steps {self.first_step}-{self.last_step}, "
            f"critical_distance={self.critical_distance}, {best})"
        )

    def _repr_html_(self) -> str:
        length = self.units.length
        rows: List[List[str]] = []
        for r in self._table.to_dict("records"):
            plane = float(r["plane"])
            rows.append(
                [
                    str(r["parameter"]),
                    _num(float(r["value"])),
                    _num(float(r["x"])),
                    _num(float(r["z"])),
                    "-" if math.isnan(plane) else f"{plane:.2f}",
                    str(r["step"]),
                    _num(_finite(r["cycles"])),
                ]
            )
        distance = (
            "not given"
            if self.critical_distance is None
            else f"{_num(self.critical_distance)} {length}"
        )
        return _html_table(
            f"FatigueResult: steady cycle steps {self.first_step} to {self.last_step}, "
            f"critical distance L {distance}",
            rows,
            header=(
                "parameter",
                "value",
                f"x [{length}]",
                f"z [{length}]",
                "plane [°]",
                "step",
                "cycles",
            ),
        )


def _finite(value: Any) -> Optional[float]:
    number = float(value)
    return None if math.isnan(number) else number


def fatigue(case: Case, cells: Optional[int] = None) -> FatigueResult:
    """Fretting-fatigue initiation parameters over the steady (last) cycle of the case's
    ``[history]``, with the constants of its ``[fatigue]`` section, as ``halfplane fatigue``:
    the same numbers as ``--json`` (``to_dict()``) and ``--csv`` (``.parameters``).

    ``cells`` overrides ``[solver] cells``. Raises :class:`InputError` naming the field when the
    case has no ``[fatigue]`` or ``[history]`` or a constant is invalid. Each parameter left out
    for want of its constants gives a ``UserWarning`` naming it and the fields it lacks (the
    command's stderr lines). The GIL is released while computing.
    """
    if cells is not None:
        cells = _count("cells", cells)
    report, skipped = _halfplane.fatigue_report(case, cells)
    for line in skipped:
        warnings.warn(line, UserWarning, stacklevel=2)
    return FatigueResult._from(report)
