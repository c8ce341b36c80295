"""Test design: :func:`match` (``halfplane match``)."""

from __future__ import annotations

import json
import warnings
from typing import Any, Dict, Mapping, Optional

from . import _halfplane
from ._halfplane import Case
from ._results import Record
from .errors import HalfplaneWarning, InputError

class MatchResult(Record):
    """The report of ``halfplane match --json`` as attributes (``mode``, ``matched``,
    ``prototype``, ``test``, ``normal_intensity``, ``shear_intensity``, ...; see docs/matching.md
    for every field, its unit and sign), plus:

    - ``test_case``: the matched test as a :class:`Case`, the case ``match -o`` writes;
    - ``test_case_text``: that file's TOML text (``Case.from_toml`` reads it back).

    ``prototype_file`` and ``test_file`` are None: the package reads and writes no files.
    ``to_dict()`` is the JSON object with those two fields None.
    """

    def __init__(self, data: Mapping[str, Any], test_case: Case, text: str) -> None:
        super().__init__(data)
        object.__setattr__(self, "_test_case", test_case)
        object.__setattr__(self, "_text", text)

    @property
    def test_case(self) -> Case:
        """The matched test case (material, friction, profile, cycle; the prototype's history,
        solver and units carried over)."""
        return self.__dict__["_test_case"]

    @property
    def test_case_text(self) -> str:
        """The test case as the TOML text ``halfplane match -o`` writes."""
        return self.__dict__["_text"]

    def __reduce__(self) -> Any:
        return (type(self), (self._data, self.test_case, self.test_case_text))

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
    text, test_case, toml, notes = _halfplane.match_report(
        prototype_case, profile, exact=bool(exact), **numbers
    )
    for note in notes:
        warnings.warn(note, HalfplaneWarning, stacklevel=2)
    data = json.loads(text)
    data["prototype_file"] = None
    data["test_file"] = None
    return MatchResult(data, test_case, toml)

