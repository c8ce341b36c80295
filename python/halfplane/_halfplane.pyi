"""Type stubs of the native module (crates/halfplane-py); use the :mod:`halfplane` package."""

from os import PathLike
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt
from typing_extensions import final

__all__ = [
    "Case",
    "REGIMES",
    "SHAPE_COLUMNS",
    "STEADY_COLUMNS",
    "STEADY_INPUT_COLUMNS",
    "THREADS_VARIABLE",
    "__version__",
    "_case_from_state",
    "_error_examples",
    "crack_report",
    "evolve_report",
    "fatigue_report",
    "march_report",
    "match_report",
    "read_case",
    "steady_batch_columns",
    "steady_report",
    "stress_points",
    "wear_report",
]

REGIMES: List[str]
SHAPE_COLUMNS: List[str]
STEADY_COLUMNS: List[str]
STEADY_INPUT_COLUMNS: List[str]
THREADS_VARIABLE: str
__version__: str

_Point = Union[
    Tuple[float, float], Tuple[float, float, float], Sequence[float], Mapping[str, float]
]

@final
class Case:
    def __new__(
        cls,
        *,
        youngs_modulus: float,
        poisson_ratio: float,
        friction: float,
        profile: str,
        radius: Optional[float] = None,
        flat_half_width: Optional[float] = None,
        coefficient: Optional[float] = None,
        exponent: Optional[float] = None,
        table: Optional[Tuple[Sequence[float], Sequence[float]]] = None,
        kinks: Optional[Sequence[float]] = None,
        point1: Optional[_Point] = None,
        point2: Optional[_Point] = None,
        history: Union[None, Mapping[str, Any], Sequence[Sequence[float]], npt.ArrayLike] = None,
        cells: Optional[int] = None,
        slip_tolerance: Optional[float] = None,
        units: Optional[Mapping[str, str]] = None,
        left_radius: Optional[float] = None,
        right_radius: Optional[float] = None,
        sub_cell_boundaries: Optional[bool] = None,
    ) -> Case: ...
    @staticmethod
    def from_toml(text: str, base_dir: Union[None, str, PathLike[str]] = None) -> Case: ...
    def to_toml(self) -> str: ...
    @property
    def tables(self) -> Dict[str, str]: ...
    @property
    def profile(self) -> str: ...
    @property
    def youngs_modulus(self) -> float: ...
    @property
    def poisson_ratio(self) -> float: ...
    @property
    def friction(self) -> float: ...
    @property
    def compliance(self) -> float: ...
    @property
    def point1(self) -> Optional[Tuple[float, float, float]]: ...
    @property
    def point2(self) -> Optional[Tuple[float, float, float]]: ...
    @property
    def moments(self) -> Optional[Tuple[float, float]]: ...
    @property
    def increments(self) -> Optional[int]: ...
    @property
    def cells(self) -> int: ...
    def __eq__(self, value: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, Tuple[str, Dict[str, str]]]: ...

def read_case(path: Union[str, PathLike[str]]) -> Case: ...
def _case_from_state(text: str, files: Mapping[str, str]) -> Case: ...
def _error_examples() -> List[Tuple[str, str, BaseException]]: ...
def steady_report(case: Case) -> Tuple[Dict[str, Any], Optional[str]]: ...
def evolve_report(case: Case, points: int) -> Tuple[Dict[str, Any], str, List[str]]: ...
def march_report(
    case: Case, cells: Optional[int] = None, fields: bool = False, no_size_limit: bool = False
) -> Dict[str, Any]: ...
def steady_batch_columns(
    columns: Sequence[Optional[npt.NDArray[np.float64]]],
    profile_index: npt.NDArray[np.int64],
    profile_names: Sequence[str],
    threads: Optional[int] = None,
) -> Tuple[npt.NDArray[np.int8], npt.NDArray[np.float64], npt.NDArray[np.int64], List[str]]: ...
def stress_points(
    case: Case,
    x: npt.NDArray[np.float64],
    z: npt.NDArray[np.float64],
    step: Optional[int] = None,
    cells: Optional[int] = None,
) -> Dict[str, Any]: ...
def fatigue_report(
    case: Case, cells: Optional[int] = None
) -> Tuple[Dict[str, Any], List[str]]: ...
def crack_report(
    case: Case, cells: Optional[int] = None, overrides: Optional[Mapping[str, Any]] = None
) -> Dict[str, Any]: ...
def match_report(
    case: Case,
    profile: str,
    radius: Optional[float] = None,
    flat_half_width: Optional[float] = None,
    coefficient: Optional[float] = None,
    exponent: Optional[float] = None,
    youngs_modulus: Optional[float] = None,
    poisson_ratio: Optional[float] = None,
    friction: Optional[float] = None,
    exact: bool = False,
    edge: Optional[str] = None,
) -> Tuple[Dict[str, Any], Case, str, List[str]]: ...
def wear_report(
    case: Case,
    cells: Optional[int] = None,
    overrides: Optional[Mapping[str, Any]] = None,
    fatigue: bool = False,
) -> Tuple[Dict[str, Any], List[str], Optional[BaseException]]: ...
