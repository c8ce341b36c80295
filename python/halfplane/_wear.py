"""Fretting wear over millions of cycles: :func:`wear` (``halfplane wear``) and its typed
result."""

from __future__ import annotations

import math
import numbers
import warnings
from dataclasses import dataclass
from typing import Any, ClassVar, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import pandas as pd

from . import _halfplane
from ._halfplane import Case
from ._records import (
    FloatArray,
    Record,
    Units,
    _cells,
    _frame,
    _html_table,
    _num,
    _overrides,
    _plain,
)
from .errors import HalfplaneError, InputError

#: The ``wear --csv`` columns, in order (public names fixed by the issue that added them).
WEAR_COLUMNS: Tuple[str, ...] = (
    "cycle",
    "wear_volume",
    "max_depth",
    "energy_per_cycle",
    "dissipated_energy",
    "contact_left",
    "contact_right",
    "peak_pressure",
    "stick_left",
    "stick_right",
    "slip_amplitude_max",
    "displacement_amplitude",
)

#: The fretting loop of each checkpoint, as ``wear --fields``' ``loop_<cycle>.csv`` names its
#: columns.
LOOP_COLUMNS: Tuple[str, ...] = ("shear", "relative_displacement")

#: The fields of each checkpoint, as ``wear --fields`` names its columns (after ``x``).
FIELD_NAMES: Tuple[str, ...] = (
    "depth",
    "depth_pad",
    "depth_specimen",
    "pressure",
    "traction",
    "slip_range",
)


#: The attributes holding the fretting loops, in the order of :data:`LOOP_COLUMNS`.
_LOOP_ARRAYS: Tuple[str, ...] = ("loop_shear", "loop_relative_displacement")


@dataclass(frozen=True, eq=False)
class WearResult(Record):
    """The report of ``halfplane wear``: the run's settings, ``law`` (``"archard"`` or
    ``"energy"``), ``coefficient`` (k or alpha, 1/stress), ``share`` (the pad's share of the
    depth), ``cycles`` (physical cycles), ``max_depth_increment`` (the largest depth a jump adds,
    as a fraction of ``elastic_approach``), ``cells`` and ``cell_width`` (the grid),
    ``simulated_cycles`` (cycles marched, the others jumped over; None when the run stopped),
    ``elastic_approach`` (of the unworn contact, length unit), ``stopped`` (why the run stopped
    before its last cycle, else None), ``units`` (:class:`Units`), and ``checkpoints``, a
    DataFrame with the columns of ``wear --csv``: ``cycle`` (int64), ``wear_volume`` (both bodies,
    per unit thickness), ``max_depth``, ``energy_per_cycle``, ``dissipated_energy`` (cumulative),
    ``contact_left``, ``contact_right``, ``peak_pressure``, ``stick_left``, ``stick_right`` (the
    cells that did not slip in the cycle; NaN in gross sliding), ``slip_amplitude_max`` and
    ``displacement_amplitude`` (half the range of the fretting loop's relative displacement)
    (float64; each access returns a copy). ``loop_datum`` is the length the loop's relative
    displacement is measured from (docs/wear.md, "Fretting loop"). With ``fatigue=True`` the
    checkpoints add the columns of ``wear --fatigue --csv``, ``fatigue.<parameter>.<field>``
    (the parameter's maximum over the checkpoint's cycle, where, and the critical-distance
    values; NaN where the command's CSV is empty).

    The fields of every checkpoint (``wear --fields``): ``x`` (the cell centres, shape
    (cells,)) and ``depth`` (both bodies), ``depth_pad``, ``depth_specimen``, ``pressure`` and
    ``traction`` (at the end of the cycle) and ``slip_range`` (over it), each of shape
    (checkpoints, cells), row i for checkpoint i; :meth:`fields` gives one checkpoint's as the
    DataFrame of its ``checkpoint_<cycle>.csv``. Depths are positive into the bodies, traction
    positive in the direction of positive Q. The fretting loops: ``loop_shear`` (Q) and
    ``loop_relative_displacement``, each of shape (checkpoints, points), the cycle's start then
    every increment and slide; :meth:`fretting_loop` gives one checkpoint's as the DataFrame of
    its ``loop_<cycle>.csv``.

    ``to_dict()`` is the ``--json`` object (``checkpoints`` as a list of row objects, null stick
    columns in gross sliding); the fields are not part of it. Read-only; it pickles. Definitions
    in docs/wear.md."""

    _EXTRA: ClassVar[Tuple[str, ...]] = ("_table", *FIELD_NAMES, "x", *_LOOP_ARRAYS)

    law: str
    coefficient: float
    share: float
    cycles: int
    max_depth_increment: float
    cells: int
    cell_width: float
    simulated_cycles: Optional[int]
    elastic_approach: float
    loop_datum: float
    _table: pd.DataFrame
    stopped: Optional[str]
    units: Units
    x: FloatArray
    depth: FloatArray
    depth_pad: FloatArray
    depth_specimen: FloatArray
    pressure: FloatArray
    traction: FloatArray
    slip_range: FloatArray
    loop_shear: FloatArray
    loop_relative_displacement: FloatArray

    @classmethod
    def _from(cls, data: Mapping[str, Any]) -> WearResult:
        simulated = data["simulated_cycles"]
        stopped = data["stopped"]
        dtypes = {c: "float64" for c in WEAR_COLUMNS}
        dtypes["cycle"] = "int64"
        return cls(
            law=str(data["law"]),
            coefficient=float(data["coefficient"]),
            share=float(data["share"]),
            cycles=int(data["cycles"]),
            max_depth_increment=float(data["max_depth_increment"]),
            cells=int(data["cells"]),
            cell_width=float(data["cell_width"]),
            simulated_cycles=None if simulated is None else int(simulated),
            elastic_approach=float(data["elastic_approach"]),
            loop_datum=float(data["loop_datum"]),
            _table=_frame(data["checkpoints"], dtypes),
            stopped=None if stopped is None else str(stopped),
            units=Units._from(data["units"]),
            x=data["x"],
            **{name: data[name] for name in (*FIELD_NAMES, *_LOOP_ARRAYS)},
        )

    @property
    def checkpoints(self) -> pd.DataFrame:
        """One row per checkpoint reached, in cycle order (a copy)."""
        copy: pd.DataFrame = self._table.copy()
        return copy

    def fretting_loop(self, cycle: int) -> pd.DataFrame:
        """The fretting loop of the checkpoint of physical cycle ``cycle``: the columns of
        ``wear --fields``' ``loop_<cycle>.csv`` (``shear, relative_displacement``), one row per
        point. A cycle that is not a checkpoint raises :class:`KeyError` naming those that
        are."""
        i = self._index(cycle)
        return pd.DataFrame(
            {c: getattr(self, a)[i].copy() for c, a in zip(LOOP_COLUMNS, _LOOP_ARRAYS)}
        )

    def _index(self, cycle: int) -> int:
        cycles = [int(c) for c in self._table["cycle"]]
        if cycle not in cycles:
            raise KeyError(f"cycle {cycle} is not a checkpoint (checkpoints: {cycles})")
        return cycles.index(cycle)

    def fields(self, cycle: int) -> pd.DataFrame:
        """The fields at the checkpoint of physical cycle ``cycle``: the columns of
        ``wear --fields``' ``checkpoint_<cycle>.csv`` (``x, depth, depth_pad, depth_specimen,
        pressure, traction, slip_range``), one row per cell. A cycle that is not a checkpoint
        raises :class:`KeyError` naming those that are."""
        i = self._index(cycle)
        columns: Dict[str, FloatArray] = {"x": self.x.copy()}
        for name in FIELD_NAMES:
            columns[name] = getattr(self, name)[i].copy()
        return pd.DataFrame(columns)

    def _keys(self) -> List[str]:
        keys = super()._keys()
        keys.insert(keys.index("loop_datum") + 1, "checkpoints")
        return keys

    def __getitem__(self, key: str) -> Any:
        if key == "checkpoints":
            return self.to_dict()["checkpoints"]
        return super().__getitem__(key)

    def to_dict(self) -> Dict[str, Any]:
        """The ``wear --json`` object."""
        out: Dict[str, Any] = {}
        for key in self._keys():
            if key == "checkpoints":
                out[key] = [_row(r) for r in self._table.to_dict("records")]
            else:
                out[key] = _plain(getattr(self, key))
        return out

    def __eq__(self, other: object) -> bool:
        same = super().__eq__(other)
        if same is not True:
            return same
        assert isinstance(other, WearResult)
        return all(
            np.array_equal(getattr(self, n), getattr(other, n))
            for n in ("x", *FIELD_NAMES, *_LOOP_ARRAYS)
        )

    def __repr__(self) -> str:
        run = "stopped" if self.stopped else f"{self.simulated_cycles} simulated"
        return (
            f"WearResult({self.law}, {self.cycles} cycles ({run}), "
            f"{len(self._table)} checkpoints, {self.cells} cells)"
        )

    def _repr_html_(self) -> str:
        length, stress = self.units.length, self.units.stress
        rows: List[List[str]] = []
        for r in self._table.to_dict("records"):
            left, right = float(r["stick_left"]), float(r["stick_right"])
            stick = "none" if math.isnan(left) else f"[{_num(left)}, {_num(right)}]"
            rows.append(
                [str(int(r["cycle"]))]
                + [_num(float(r[c])) for c in ("wear_volume", "max_depth", "peak_pressure")]
                + [f"[{_num(float(r['contact_left']))}, {_num(float(r['contact_right']))}]", stick]
            )
        state = f"stopped: {self.stopped}" if self.stopped else f"{self.simulated_cycles} simulated"
        return _html_table(
            f"WearResult: {self.law} law, coefficient {self.coefficient:g} 1/{stress}, "
            f"{self.cycles} cycles ({state})",
            rows,
            header=("cycle", f"volume [{length}²]", f"max depth [{length}]",
                    f"peak pressure [{stress}]", f"contact [{length}]", f"stick [{length}]"),
        )


def _row(record: Mapping[Any, Any]) -> Dict[str, Any]:
    """A checkpoint row as the ``--json`` object holds it: the cycle an int, NaN stick ends
    null, the ``fatigue.<parameter>.<field>`` columns nested as ``fatigue`` objects without the
    fields a parameter does not have."""
    out: Dict[str, Any] = {}
    fatigue: Dict[str, Dict[str, float]] = {}
    for key, value in record.items():
        name = str(key)
        if name.startswith("fatigue."):
            _, parameter, field = name.split(".", 2)
            if not math.isnan(float(value)):
                fatigue.setdefault(parameter, {})[field] = float(value)
        else:
            out[name] = int(value) if name == "cycle" else _plain(float(value))
    if fatigue:
        out["fatigue"] = fatigue
    return out


_Checkpoints = Union[int, Sequence[int]]


def wear(
    case: Case,
    cells: Optional[int] = None,
    *,
    law: Optional[str] = None,
    coefficient: Optional[float] = None,
    share: Optional[float] = None,
    cycles: Optional[int] = None,
    checkpoints: Optional[_Checkpoints] = None,
    max_depth_increment: Optional[float] = None,
    span: Optional[float] = None,
    loop_datum: Optional[float] = None,
    fatigue: bool = False,
) -> WearResult:
    """Fretting wear: the worn profiles, pressure and stick zone over ``[wear] cycles`` load
    cycles of the case's ``[history]`` (one cycle, kind ``cycle`` or ``harmonic``, or kind
    ``sliding`` for gross sliding), as ``halfplane wear``: the same numbers as ``--json``
    (``to_dict()``), ``--csv`` (``.checkpoints``) and ``--fields`` (:meth:`WearResult.fields`).
    Each simulated cycle is marched over the current worn gap and its wear extrapolated over as
    many cycles as keep the largest depth added below ``max_depth_increment`` times the elastic
    approach (docs/wear.md).

    The wear settings are the case's ``[wear]`` section; each keyword given replaces (or
    supplies) that field of it, with the section's meaning and checks: ``law`` (``"archard"``
    or ``"energy"``), ``coefficient`` (k or alpha > 0, in 1/stress), ``share`` (the pad's share
    of the depth, 0 to 1), ``cycles`` (physical cycles), ``checkpoints`` (a list of cycles in
    increasing order, or a count spaced logarithmically), ``max_depth_increment``, ``span`` (the
    grid's width over the unworn contact's), ``loop_datum`` (the length the fretting loop's
    relative displacement is measured from). ``fatigue=True`` is ``--fatigue``: the case's
    ``[fatigue]`` parameters over each checkpoint's cycle, on the ``[fatigue]`` grid of the
    unworn contact, as checkpoint columns (a parameter the constants leave out is warned about,
    as the command does; a case whose ``[fatigue]`` gives no constant raises
    :class:`InputError`). ``cells`` overrides ``[solver] cells``. Bad input
    raises :class:`InputError` naming the field.

    The GIL is released while the wear runs; Ctrl-C interrupts it between cycles (checked every
    50 ms) with KeyboardInterrupt. A run that stops part way (the contact opens entirely or
    reaches the end of its grid: ``variant`` ``"WearStopped"``, naming the cycle) raises the
    error with the checkpoints reached attached as its ``result`` (a :class:`WearResult` whose
    ``stopped`` holds the message and whose ``simulated_cycles`` is None; None when the run
    stopped before its first checkpoint), as the command prints them before its error.
    """
    overrides = _overrides(
        "wear",
        {
            "law": law,
            "coefficient": coefficient,
            "share": share,
            "cycles": cycles,
            "max_depth_increment": max_depth_increment,
            "span": span,
            "loop_datum": loop_datum,
        },
    )
    if checkpoints is not None:
        overrides["checkpoints"] = _checkpoints(checkpoints)
    report, skipped, error = _halfplane.wear_report(
        case, _cells(cells), overrides or None, bool(fatigue)
    )
    for line in skipped:
        warnings.warn(line, UserWarning, stacklevel=2)
    result = WearResult._from(report)
    if error is not None:
        if isinstance(error, HalfplaneError):
            error.result = result
        raise error
    return result


def _checkpoints(value: _Checkpoints) -> Any:
    """``checkpoints`` as ``[wear]`` takes it: a count as given, else a list (from a list, a
    tuple or a numpy array of whole numbers); ``[wear]``'s checks judge the values."""
    if isinstance(value, numbers.Integral) and not isinstance(value, bool):
        return int(value)
    if isinstance(value, (Sequence, np.ndarray)) and not isinstance(value, str):
        return [int(v) if isinstance(v, numbers.Integral) else v for v in value]
    raise InputError(
        f"invalid wear.checkpoints = {value!r}: must be a list of cycles in increasing order, "
        "or a count"
    )
