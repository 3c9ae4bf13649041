"""Type stub of the pegdyn Python package."""

import os
from dataclasses import dataclass
from types import SimpleNamespace
from typing import Any, Dict, Iterator, List, Mapping, NamedTuple, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str
PathLike = Union[str, "os.PathLike[str]"]
ArrayLike = npt.ArrayLike
Limits = Union[Mapping[str, Union[int, float, str]], Sequence[str], None]

class SceneError(ValueError):
    """A scene that does not parse or validate (message of ``pegdyn check``)."""

    field: Optional[str]
    value: Optional[str]
    reason: str
    errors: List[Tuple[Optional[str], Optional[str], str]]

class RunError(RuntimeError):
    """A valid scene whose run failed."""

class NonFiniteWarning(RuntimeWarning):
    """A generated function met a NaN or infinite input, or gave one from finite inputs."""

def kinds() -> List[Tuple[str, str]]: ...
def load(path: PathLike, *, limits: Limits = None) -> Scene: ...
def loads(text: str, name: str = "scene", *, limits: Limits = None) -> Scene: ...
def from_dict(d: Mapping[str, Any], name: str = "scene", *, limits: Limits = None) -> Scene: ...

class Scene:
    text: str
    name: str
    kind: str
    description: Optional[str]
    limits: Optional[Tuple[str, ...]]
    def __init__(self, text: str, name: str = "scene", *, limits: Limits = None) -> None: ...
    def describe(self) -> str: ...
    def with_values(self, values: Mapping[str, Any]) -> Scene: ...
    def run(self, out: Optional[PathLike] = None) -> Result: ...

class Event(NamedTuple):
    t: float
    name: str
    details: Dict[str, Any]
    @property
    def terminal(self) -> bool: ...

@dataclass(frozen=True)
class Outcome:
    success: bool
    stop: Optional[str] = None
    t_end: Optional[float] = None
    method: Optional[str] = None
    steps: Optional[int] = None
    rejected: Optional[int] = None
    rhs_calls: Optional[int] = None

@dataclass
class Result:
    columns: Dict[str, Union[npt.NDArray[np.float64], List[str]]]
    tables: Dict[str, Dict[str, Union[npt.NDArray[np.float64], List[str]]]]
    outcome: Outcome
    events: List[Event]
    metrics: Dict[str, float]
    units: Dict[str, str]
    summary: Dict[str, Any]
    text: str
    paths: List[str]
    kind: Optional[str] = None
    notes: Dict[str, str] = ...
    @property
    def has_replay(self) -> bool: ...
    @property
    def sensitivities(self) -> Optional[Dict[str, Any]]: ...
    def replay(self, path: PathLike) -> str: ...
    def _repr_html_(self) -> Optional[str]: ...
    def to_pandas(self, table: Optional[str] = None) -> Any: ...

class Function:
    """A generated function vectorized over points: inputs ``(N, len)``
    (or ``(1, len)``/``(len,)``, broadcast); outputs ``(N,)`` or ``(N, k)``."""

    module: str
    name: str
    inputs: List[Tuple[str, List[str]]]
    outputs: List[Tuple[str, int]]
    @property
    def path(self) -> str: ...
    def __call__(self, *inputs: ArrayLike, errors: str = "warn") -> Dict[str, Any]: ...
    def raw(self, *inputs: ArrayLike, errors: str = "warn") -> npt.NDArray[np.float64]: ...

def functions() -> List[Function]: ...
def function(module: str, name: str) -> Function: ...

generated: SimpleNamespace

class SweepResult:
    keys: List[str]
    rows: List[Dict[str, Any]]
    def __len__(self) -> int: ...
    def __iter__(self) -> Iterator[Dict[str, Any]]: ...
    @overload
    def __getitem__(self, i: int) -> Dict[str, Any]: ...
    @overload
    def __getitem__(self, i: str) -> List[Any]: ...
    @property
    def columns(self) -> List[str]: ...
    def to_pandas(self) -> Any: ...

def sweep(
    scene: Scene,
    grid: Optional[Mapping[str, Sequence[Any]]] = None,
    points: Optional[Sequence[Mapping[str, Any]]] = None,
    client: Any = None,
    batch_size: Optional[int] = None,
    threads: Optional[int] = None,
    limits: Limits = None,
) -> SweepResult: ...
