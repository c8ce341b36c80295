"""The base of the typed result records (:class:`Record`), the parts every report shares
(:class:`PerPoint`, :class:`Edges`, :class:`Units`, :class:`Profile`, :class:`LoadPoint`) and the
helpers that show results (a number for a table, a compact HTML table, a DataFrame of columns).

The native module converts the command's report structs to Python objects directly (no JSON or
CSV text in between); the records give them typed attributes named as the command's JSON keys,
nested as in the JSON, and ``to_dict()`` gives that JSON object back.
"""

from __future__ import annotations

import dataclasses
import math
import numbers
from dataclasses import dataclass
from html import escape
from typing import (
    TYPE_CHECKING,
    Any,
    Callable,
    ClassVar,
    Dict,
    Generic,
    Iterator,
    List,
    Mapping,
    Optional,
    Sequence,
    Tuple,
    TypeVar,
)

import numpy as np
import numpy.typing as npt
import pandas as pd

from .errors import InputError

T = TypeVar("T")
U = TypeVar("U")

#: An array of float64 values.
FloatArray = npt.NDArray[np.float64]


def _plain(value: Any) -> Any:
    """``value`` as the command's JSON holds it: records as dicts, tuples as lists, a number that
    is not finite as None (JSON has no NaN or infinity; the command writes null)."""
    if isinstance(value, Record):
        return value.to_dict()
    if isinstance(value, (tuple, list)):
        return [_plain(v) for v in value]
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


@dataclass(frozen=True, eq=False)
class Record:
    """The base of the typed, read-only result records. A record's fields are the keys of the
    command's JSON object, as attributes with types (``result.stick_zone.left``); nested objects
    are records. ``record["key"]`` and iteration over the keys work as for a dict, ``to_dict()``
    returns the JSON object (plain dicts, lists, numbers, strings and None), and two records are
    equal when their ``to_dict()`` are. Records pickle and are immutable."""

    #: Fields that the JSON leaves out when they are None.
    _OMIT_NONE: ClassVar[Tuple[str, ...]] = ()
    #: Fields that are not part of the JSON object (``to_dict()`` and iteration skip them).
    _EXTRA: ClassVar[Tuple[str, ...]] = ()

    def _keys(self) -> List[str]:
        return [
            f.name
            for f in dataclasses.fields(self)
            if f.name not in self._EXTRA
            and not (f.name in self._OMIT_NONE and getattr(self, f.name) is None)
        ]

    def __getitem__(self, key: str) -> Any:
        if key not in self._keys():
            raise KeyError(key)
        return getattr(self, key)

    def __iter__(self) -> Iterator[str]:
        return iter(self._keys())

    def keys(self) -> List[str]:
        """The JSON object's keys, in order."""
        return self._keys()

    def to_dict(self) -> Dict[str, Any]:
        """The JSON object: the fields as plain dicts, lists, numbers, strings and None (a new
        copy; a number that is not finite is None, as the command writes it)."""
        return {k: _plain(getattr(self, k)) for k in self._keys()}

    def __eq__(self, other: object) -> bool:
        if type(other) is not type(self):
            return NotImplemented
        assert isinstance(other, Record)
        return self.to_dict() == other.to_dict()

    __hash__ = None  # type: ignore[assignment]

    if not TYPE_CHECKING:
        # Only for a name that is not a field (normal lookup failed): say which fields there are.
        # Hidden from type checkers, which would otherwise accept any attribute.
        def __getattr__(self, name):
            if name.startswith("__"):
                raise AttributeError(name)
            fields = ", ".join(f.name for f in dataclasses.fields(self))
            raise AttributeError(
                f"{type(self).__name__} has no field {name!r} (fields: {fields})"
            )


def _float(value: Any) -> float:
    return float(value)


def _opt_float(value: Any) -> Optional[float]:
    return None if value is None else float(value)


@dataclass(frozen=True, eq=False)
class PerPoint(Record, Generic[T]):
    """A quantity at the cycle's two ends, as given: ``at_point1``, ``at_point2``."""

    at_point1: T
    at_point2: T


@dataclass(frozen=True, eq=False)
class Edges(Record, Generic[T]):
    """A quantity at the contact's two edges: ``left`` (x < 0) and ``right``."""

    left: T
    right: T


def _per_point(data: Mapping[str, Any], item: Callable[[Any], U]) -> PerPoint[U]:
    return PerPoint(item(data["at_point1"]), item(data["at_point2"]))


def _edges(data: Mapping[str, Any], item: Callable[[Any], U]) -> Edges[U]:
    return Edges(item(data["left"]), item(data["right"]))


@dataclass(frozen=True, eq=False)
class Units(Record):
    """The case's unit names: ``force`` (N), ``length`` (mm), ``stress`` (MPa) by default."""

    force: str
    length: str
    stress: str

    @classmethod
    def _from(cls, data: Mapping[str, Any]) -> Units:
        return cls(str(data["force"]), str(data["length"]), str(data["stress"]))


@dataclass(frozen=True, eq=False)
class Profile(Record):
    """The indenter's profile: ``kind`` (``"hertz"``, ``"flat-rounded"``, ``"power-law"`` or
    ``"tabulated"``), its parameters (``radius`` R, or the edge radius of a flat-rounded punch;
    ``left_radius`` and ``right_radius`` instead for a flat-rounded punch whose edge radii
    differ; ``flat_half_width`` b; ``coefficient`` B and ``exponent`` k of g = B|x|^k; ``rows``
    of a table), None where the kind has none (and then absent from ``to_dict()``), and
    ``kinks`` (the x of slope discontinuities: their |x| for a symmetric profile)."""

    _OMIT_NONE: ClassVar[Tuple[str, ...]] = (
        "radius",
        "flat_half_width",
        "coefficient",
        "exponent",
        "rows",
        "left_radius",
        "right_radius",
    )

    kind: str
    radius: Optional[float]
    flat_half_width: Optional[float]
    coefficient: Optional[float]
    exponent: Optional[float]
    rows: Optional[int]
    kinks: Tuple[float, ...]
    left_radius: Optional[float] = None
    right_radius: Optional[float] = None

    @classmethod
    def _from(cls, data: Mapping[str, Any]) -> Profile:
        rows = data.get("rows")
        return cls(
            kind=str(data["kind"]),
            radius=_opt_float(data.get("radius")),
            flat_half_width=_opt_float(data.get("flat_half_width")),
            coefficient=_opt_float(data.get("coefficient")),
            exponent=_opt_float(data.get("exponent")),
            rows=None if rows is None else int(rows),
            kinks=tuple(float(k) for k in data["kinks"]),
            left_radius=_opt_float(data.get("left_radius")),
            right_radius=_opt_float(data.get("right_radius")),
        )


@dataclass(frozen=True, eq=False)
class LoadPoint(Record):
    """A load: ``normal`` P (> 0 compresses), ``shear`` Q, ``bulk`` tension sigma and ``moment`` M
    (the pressure's moment about x = 0; its resultant acts at x = M/P)."""

    normal: float
    shear: float
    bulk: float
    moment: float = 0.0

    @classmethod
    def _from(cls, data: Mapping[str, Any]) -> LoadPoint:
        return cls(
            _float(data["normal"]),
            _float(data["shear"]),
            _float(data["bulk"]),
            _float(data.get("moment", 0.0)),
        )


def _num(value: Optional[float]) -> str:
    """A number for a table: six significant digits, "-" for None."""
    if value is None:
        return "-"
    return f"{value:.6g}"


def _text(value: object) -> str:
    """A value for a table: its ``str``, "-" for None."""
    return "-" if value is None else str(value)


def _html_table(caption: str, rows: Sequence[Sequence[str]], header: Sequence[str] = ()) -> str:
    """A compact HTML table: the caption, an optional header row, then one row per entry whose
    first cell is its label; a row shorter than the header spans its last cell to the end."""
    width = max([len(header)] + [len(r) for r in rows])
    out = [
        '<table class="halfplane-result">',
        f'<caption style="text-align: left">{escape(caption)}</caption>',
    ]
    if header:
        out.append("<tr>" + "".join(f"<th>{escape(h)}</th>" for h in header) + "</tr>")
    for row in rows:
        cells = [f'<th style="text-align: left">{escape(row[0])}</th>']
        for i, cell in enumerate(row[1:], start=1):
            span = width - i if i == len(row) - 1 and len(row) < width else 1
            attribute = f' colspan="{span}"' if span > 1 else ""
            cells.append(f"<td{attribute}>{escape(cell)}</td>")
        out.append("<tr>" + "".join(cells) + "</tr>")
    out.append("</table>")
    return "\n".join(out)


def _cells(value: Optional[int]) -> Optional[int]:
    """The ``cells`` keyword as the native module takes it: None, or a whole number >= 0 (the
    solver's own check names the valid range)."""
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < 0:
        raise InputError(f"invalid cells = {value!r}: must be a whole number")
    return int(value)


def _overrides(section: str, given: Mapping[str, Any]) -> Dict[str, Any]:
    """The fields of ``[section]`` given as keywords (those not None), for the native module to
    put into the case's section; a float that is not finite is refused naming the field."""
    out: Dict[str, Any] = {}
    for key, value in given.items():
        if value is None:
            continue
        if isinstance(value, float) and not math.isfinite(value):
            raise InputError(f"invalid {section}.{key} = {value}: must be a finite number")
        out[key] = value
    return out


def _frame(columns: Mapping[str, Any], dtypes: Optional[Mapping[str, str]] = None) -> pd.DataFrame:
    """A DataFrame of the native module's columns (numpy arrays, or lists of strings), in their
    order; ``dtypes`` fixes the type of columns that may be empty."""
    frame: pd.DataFrame = pd.DataFrame(dict(columns))
    if dtypes and len(frame) == 0:
        typed: pd.DataFrame = frame.astype(dict(dtypes))
        return typed
    return frame


__all__ = ["Edges", "LoadPoint", "PerPoint", "Profile", "Record", "Units"]
