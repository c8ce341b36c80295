"""Below the surface: :func:`stress` (``halfplane stress``) and :func:`fatigue`
(``halfplane fatigue``)."""

from __future__ import annotations

import io
import json
import numbers
import warnings
from typing import Any, Dict, Mapping, Optional, Tuple

import numpy as np
import numpy.typing as npt
import pandas as pd

from . import _halfplane
from ._halfplane import Case
from ._results import Record
from .errors import InputError

#: pandas before 3 parses CSV numbers to within an ulp unless asked for round-trip precision.
_OLD_PANDAS = int(pd.__version__.split(".")[0]) < 3


def _count(name: str, value: Any) -> int:
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or int(value) < 0:
        raise InputError(f"invalid {name} = {value!r}: must be a whole number")
    return int(value)


def _floats(name: str, value: Any) -> np.ndarray:
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
    contact half-width. ``to_dict()`` gives them all, arrays included."""

    def __init__(self, data: Mapping[str, Any], shape: Tuple[int, ...]) -> None:
        self.step: int = int(data["step"])
        self.normal: float = float(data["normal"])
        self.shear: float = float(data["shear"])
        self.bulk: float = float(data["bulk"])
        self.half_width: float = float(data["half_width"])
        self.sxx: npt.NDArray[np.float64] = data["sxx"].reshape(shape)
        self.szz: npt.NDArray[np.float64] = data["szz"].reshape(shape)
        self.syy: npt.NDArray[np.float64] = data["syy"].reshape(shape)
        self.sxz: npt.NDArray[np.float64] = data["sxz"].reshape(shape)

    def to_dict(self) -> Dict[str, Any]:
        """The fields by name (the arrays are the result's own)."""
        return dict(vars(self))

    def __repr__(self) -> str:
        return (
            f"StressResult(step={self.step}, normal={self.normal}, shear={self.shear}, "
            f"bulk={self.bulk}, shape={self.sxx.shape})"
        )


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
    return StressResult(_halfplane.stress_points(case, flat_x, flat_z, step, cells), shape)


class FatigueResult(Record):
    """The report of ``halfplane fatigue --json``: ``critical_distance`` (L, length unit, None
    when ``[fatigue]`` gives none), ``first_step`` and ``last_step`` (the steady cycle's
    increments, 1-based), ``units``, and ``parameters``, here a DataFrame with the columns of
    ``fatigue --csv``: ``parameter, value, x, z, plane, step, point_method, line_method, cycles,
    tilt`` (``plane`` in degrees from +x towards +z, ``tilt`` of the plane's normal towards +y,
    0 unless ``[fatigue] planes = "3d"``; NaN where a column does not apply).
    ``to_dict()`` is the JSON object itself."""

    def __init__(self, data: Mapping[str, Any], csv: str) -> None:
        super().__init__(data)
        # Every number is parsed exactly as the command wrote it (shortest round-trip form).
        if _OLD_PANDAS:
            frame = pd.read_csv(io.StringIO(csv), float_precision="round_trip")
        else:
            frame = pd.read_csv(io.StringIO(csv))
        object.__setattr__(self, "_parameters", frame)

    @property
    def parameters(self) -> pd.DataFrame:
        """One row per parameter: its maximum over the steady cycle and where it occurs."""
        return self.__dict__["_parameters"].copy()

    def __reduce__(self) -> Tuple[Any, Tuple[Any, ...]]:  # type: ignore[override]
        csv = self.__dict__["_parameters"].to_csv(index=False)
        return (type(self), (self._data, csv))


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
    csv, text, skipped = _halfplane.fatigue_report(case, cells)
    for line in skipped:
        warnings.warn(line, UserWarning, stacklevel=2)
    return FatigueResult(json.loads(text), csv)
