"""Test design: :func:`match` (``halfplane match``)."""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import Any, ClassVar, Dict, List, Mapping, Optional, Tuple

from . import _halfplane
from ._halfplane import Case
from ._records import (
    Edges,
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
)
from .errors import HalfplaneWarning, InputError


@dataclass(frozen=True, eq=False)
class Mismatch(Record):
    """A quantity of the ``prototype`` and of the ``test``, and their ``mismatch``
    (test - prototype)/|prototype| (None when the prototype's value is zero)."""

    prototype: float
    test: float
    mismatch: Optional[float]

    @classmethod
    def _from(cls, data: Mapping[str, Any]) -> Mismatch:
        return cls(_float(data["prototype"]), _float(data["test"]), _opt_float(data["mismatch"]))


@dataclass(frozen=True, eq=False)
class MatchSide(Record):
    """One contact of a match (the prototype or the test): its steady ``regime``, ``profile``,
    ``compliance`` A, ``friction`` f, the loads at its ``points`` (as given) and the contact
    ``half_width`` a at each."""

    regime: str
    profile: Profile
    compliance: float
    friction: float
    points: PerPoint[LoadPoint]
    half_width: PerPoint[float]

    @classmethod
    def _from(cls, data: Mapping[str, Any]) -> MatchSide:
        return cls(
            regime=str(data["regime"]),
            profile=Profile._from(data["profile"]),
            compliance=_float(data["compliance"]),
            friction=_float(data["friction"]),
            points=_per_point(data["points"], LoadPoint._from),
            half_width=_per_point(data["half_width"], _float),
        )


def _by_point(data: Mapping[str, Any]) -> PerPoint[Mismatch]:
    return _per_point(data, Mismatch._from)


def _by_edge_and_point(data: Mapping[str, Any]) -> Edges[PerPoint[Mismatch]]:
    return _edges(data, _by_point)


@dataclass(frozen=True, eq=False)
class MatchResult(Record):
    """The report of ``halfplane match --json`` as typed attributes (see docs/matching.md for
    every field, its unit and sign):

    - ``mode`` (``"asymptotic"`` or ``"exact"``), ``matched`` (the matched quantities in
      words) and ``matched_edge`` (``"left"`` or ``"right"``: the prototype's edge whose K_N the
      test takes, the same at both edges without a moment on a symmetric prototype);
    - ``prototype``, ``test``: each contact (:class:`MatchSide`: regime, profile, loads,
      half-widths);
    - ``normal_intensity`` (K_N at each point), ``shear_intensity`` and ``equivalent_shear``
      (K_T and S at each edge and point), ``mean_shear_intensity`` (at each edge),
      ``edge_motion`` (a2 - a1) and ``slip_zones`` (each edge and point): each a
      :class:`Mismatch` of prototype and test, e.g. ``normal_intensity.at_point2.mismatch``;
    - ``warnings`` (the command's notes) and ``units``;
    - ``test_case``: the matched test as a :class:`Case`, the case ``match -o`` writes;
    - ``test_case_text``: that file's TOML text (``Case.from_toml`` reads it back).

    ``prototype_file`` and ``test_file`` are None: the package reads and writes no files.
    ``to_dict()`` is the JSON object with those two fields None (without the test case).
    """

    _EXTRA: ClassVar[Tuple[str, ...]] = ("test_case", "test_case_text")

    mode: str
    matched: str
    matched_edge: str
    prototype_file: Optional[str]
    test_file: Optional[str]
    prototype: MatchSide
    test: MatchSide
    normal_intensity: PerPoint[Mismatch]
    shear_intensity: Edges[PerPoint[Mismatch]]
    mean_shear_intensity: Edges[Mismatch]
    equivalent_shear: Edges[PerPoint[Mismatch]]
    edge_motion: Mismatch
    slip_zones: Edges[PerPoint[Mismatch]]
    warnings: Tuple[str, ...]
    units: Units
    test_case: Case
    test_case_text: str

    @classmethod
    def _from(cls, data: Mapping[str, Any], test_case: Case, text: str) -> MatchResult:
        return cls(
            mode=str(data["mode"]),
            matched=str(data["matched"]),
            matched_edge=str(data["matched_edge"]),
            prototype_file=None,
            test_file=None,
            prototype=MatchSide._from(data["prototype"]),
            test=MatchSide._from(data["test"]),
            normal_intensity=_by_point(data["normal_intensity"]),
            shear_intensity=_by_edge_and_point(data["shear_intensity"]),
            mean_shear_intensity=_edges(data["mean_shear_intensity"], Mismatch._from),
            equivalent_shear=_by_edge_and_point(data["equivalent_shear"]),
            edge_motion=Mismatch._from(data["edge_motion"]),
            slip_zones=_by_edge_and_point(data["slip_zones"]),
            warnings=tuple(str(w) for w in data["warnings"]),
            units=Units._from(data["units"]),
            test_case=test_case,
            test_case_text=text,
        )

    def __repr__(self) -> str:
        k = self.normal_intensity
        return (
            f"MatchResult(mode={self.mode!r}, prototype={self.prototype.profile.kind!r} "
            f"({self.prototype.regime}), test={self.test.profile.kind!r} ({self.test.regime}), "
            f"K_N mismatch=({_percent(k.at_point1.mismatch)}, {_percent(k.at_point2.mismatch)}))"
        )

    def _repr_html_(self) -> str:
        u = self.units
        force = f"{u.force}/{u.length}"
        p, t = self.prototype, self.test
        rows: List[List[str]] = [
            ["profile", p.profile.kind, t.profile.kind, ""],
            ["regime", p.regime, t.regime, ""],
        ]
        for name, get in (("point1", "at_point1"), ("point2", "at_point2")):
            a, b = getattr(p.points, get), getattr(t.points, get)
            rows.append([f"{name} P, Q [{force}]", f"{_num(a.normal)}, {_num(a.shear)}",
                         f"{_num(b.normal)}, {_num(b.shear)}", ""])
            rows.append([f"{name} σ [{u.stress}]", _num(a.bulk), _num(b.bulk), ""])
        compared = [
            ("K_N at point1", self.normal_intensity.at_point1),
            ("K_N at point2", self.normal_intensity.at_point2),
            ("K_T left at point1", self.shear_intensity.left.at_point1),
            ("K_T left at point2", self.shear_intensity.left.at_point2),
            ("K_T right at point1", self.shear_intensity.right.at_point1),
            ("K_T right at point2", self.shear_intensity.right.at_point2),
            ("edge motion a2 - a1", self.edge_motion),
            ("slip zone left at point2", self.slip_zones.left.at_point2),
            ("slip zone right at point2", self.slip_zones.right.at_point2),
        ]
        for label, m in compared:
            rows.append([label, _num(m.prototype), _num(m.test), _percent(m.mismatch)])
        return _html_table(
            f"MatchResult ({self.mode}: {self.matched})",
            rows,
            header=("", "prototype", "test", "mismatch"),
        )


def _percent(value: Optional[float]) -> str:
    return "-" if value is None else f"{100.0 * value:+.3f}%"


_PROFILES = ("hertz", "flat-rounded", "power-law")

def match(
    prototype_case: Case,
    profile: str,
    *,
    radius: Optional[float] = None,
    flat_half_width: Optional[float] = None,
    coefficient: Optional[float] = None,
    exponent: Optional[float] = None,
    youngs_modulus: Optional[float] = None,
    poisson_ratio: Optional[float] = None,
    friction: Optional[float] = None,
    exact: bool = False,
    edge: Optional[str] = None,
) -> MatchResult:
    """The test loads that reproduce the prototype's contact-edge state, as
    ``halfplane match CASE --profile PROFILE ... --json`` (the same test contact, report and test
    case; see docs/matching.md).

    The prototype needs a ``[cycle]``. ``profile`` is the test's: ``"hertz"`` (``radius`` R > 0),
    ``"flat-rounded"`` (``flat_half_width`` b >= 0 and edge ``radius`` R > 0) or ``"power-law"``
    (``coefficient`` B > 0 and ``exponent`` 1 <= k <= 64 in g = B|x|^k); lengths in the case's
    length unit. ``youngs_modulus``, ``poisson_ratio`` and ``friction`` default to the
    prototype's. ``exact=False`` matches the asymptotic edge intensities (K_N at both points, K_T
    at both edges at both points); ``exact=True`` matches the exact slip zones at point2.
    Under a moment (or on an asymmetric prototype) K_N differs at the prototype's two edges and
    the test, without a moment, takes the K_N of ``edge`` (``"left"`` or ``"right"``; default
    None: the edge whose K_T changes more over the cycle), as ``--edge``.

    Raises :class:`InputError` for a missing or invalid test option (the message names it as the
    command's option, e.g. ``--radius``) and :class:`OutsideAnalysisError` where the prototype or
    the test is outside the analysis. Warnings and notes of the command are
    :class:`HalfplaneWarning`. The GIL is released while matching.
    """
    if profile not in _PROFILES:
        raise InputError(f"invalid profile = {profile!r}: must be one of {', '.join(_PROFILES)}")
    numbers: Dict[str, Optional[float]] = {
        "radius": radius,
        "flat_half_width": flat_half_width,
        "coefficient": coefficient,
        "exponent": exponent,
        "youngs_modulus": youngs_modulus,
        "poisson_ratio": poisson_ratio,
        "friction": friction,
    }
    for name, value in numbers.items():
        if value is not None:
            try:
                numbers[name] = float(value)
            except (TypeError, ValueError):
                raise InputError(f"invalid {name} = {value!r}: must be a number") from None
    report, test_case, toml, notes = _halfplane.match_report(
        prototype_case, profile, exact=bool(exact), edge=edge, **numbers
    )
    for note in notes:
        warnings.warn(note, HalfplaneWarning, stacklevel=2)
    return MatchResult._from(report, test_case, toml)

