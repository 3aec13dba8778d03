"""Type stubs of thinjkr (see the module's docstring)."""

from typing import Any, Dict, Iterator, List, Literal, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

from . import exact as exact

ArrayLike = Union[float, npt.ArrayLike]
ModelName = str

class ThinJkrError(Exception):
    kind: str
    record: str
    def __init__(self, message: str, kind: str = ..., record: Optional[str] = ...) -> None: ...

class InvalidInput(ThinJkrError, ValueError): ...
class NoState(ThinJkrError): ...
class NoConvergence(ThinJkrError): ...
class Unresolved(ThinJkrError): ...
class Unavailable(ThinJkrError): ...
class ThinJkrWarning(UserWarning): ...

class State:
    model: str
    rho: float
    a_bar: float
    b_bar: float
    s: float
    delta_bar: float
    force_bar: float
    stability_load: Optional[Literal["stable", "neutral", "unstable"]]
    stability_displacement: Optional[Literal["stable", "neutral", "unstable"]]
    def __init__(self, fields: Dict[str, Any]) -> None: ...
    def __getattr__(self, name: str) -> Any: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def keys(self) -> Iterator[str]: ...
    def _repr_html_(self) -> str: ...

class PullOff(State):
    control: Literal["load", "displacement"]

class States:
    model: str
    rho: np.ndarray
    a_bar: np.ndarray
    b_bar: np.ndarray
    s: np.ndarray
    delta_bar: np.ndarray
    force_bar: np.ndarray
    bc_error: np.ndarray
    error: np.ndarray
    error_kind: np.ndarray
    warning: np.ndarray
    departure: np.ndarray
    route: np.ndarray
    @property
    def shape(self) -> Tuple[int, ...]: ...
    @property
    def ok(self) -> np.ndarray: ...
    @property
    def doubtful(self) -> np.ndarray: ...
    def __len__(self) -> int: ...
    def __getitem__(self, key: Any) -> Union[State, States]: ...
    def __iter__(self) -> Iterator[State]: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def to_pandas(self) -> Any: ...
    def _repr_html_(self) -> str: ...

class Curve:
    states: List[State]
    folds: List[Tuple[str, State]]
    a_bar: np.ndarray
    b_bar: np.ndarray
    s: np.ndarray
    delta_bar: np.ndarray
    force_bar: np.ndarray
    bc_error: np.ndarray
    beyond_size_fold: np.ndarray
    arm: np.ndarray
    end: Optional[str]
    def __len__(self) -> int: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def _repr_html_(self) -> str: ...

# A float (or numpy scalar) gives one state; an array or a sequence gives
# States of its shape (broadcast with the control), as numpy's ufuncs do.
Array = Union[npt.NDArray[Any], Sequence[float]]
Number = Union[float, Array]

@overload
def solve(rho: float, *, delta: Optional[float] = ..., force: Optional[float] = ...,
          a: Optional[float] = ..., model: ModelName = ..., all: Literal[False] = ...) -> State: ...
@overload
def solve(rho: float, *, delta: Optional[float] = ..., force: Optional[float] = ...,
          a: Optional[float] = ..., model: ModelName = ..., all: Literal[True]) -> List[State]: ...
@overload
def solve(rho: Array, *, delta: Optional[Number] = ..., force: Optional[Number] = ...,
          a: Optional[Number] = ..., model: ModelName = ...) -> States: ...
@overload
def solve(rho: Number, *, delta: Array, model: ModelName = ...) -> States: ...
@overload
def solve(rho: Number, *, force: Array, model: ModelName = ...) -> States: ...
@overload
def solve(rho: Number, *, a: Array, model: ModelName = ...) -> States: ...
@overload
def zero_force(rho: float, *, model: ModelName = ...) -> State: ...
@overload
def zero_force(rho: Array, *, model: ModelName = ...) -> States: ...
@overload
def pull_off(rho: float, *, model: ModelName = ...,
             control: Literal["load", "displacement"] = ...) -> PullOff: ...
@overload
def pull_off(rho: Array, *, model: ModelName = ...,
             control: Literal["load", "displacement"] = ...) -> States: ...
@overload
def curve(rho: float, *, model: ModelName = ..., points: int = ..., delta_start: float = ...) -> Curve: ...
@overload
def curve(rho: Array, *, model: ModelName = ..., points: int = ..., delta_start: float = ...) -> List[Curve]: ...
def models() -> List[Tuple[str, str]]: ...
def physical(*, r1: float, r2: float, theta_deg: float, h1: float, h2: float, g1: float, g2: float,
             work_of_adhesion: float, delta: Optional[float] = ..., force: Optional[float] = ...,
             model: Optional[ModelName] = ..., nu1: float = ..., nu2: float = ...) -> Physical: ...

class Physical:
    a: float
    b: float
    delta: float
    force: float
    p0: float
    h_over_a: float
    state: State
    warnings: List[str]
    model: str
    chosen_because: Optional[str]
    paper_model: Optional[State]
    thin_layer: Optional[State]
    layer_estimate: Optional[Dict[str, Any]]
    def __init__(self, fields: Dict[str, Any]) -> None: ...
    def __getattr__(self, name: str) -> Any: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def keys(self) -> Iterator[str]: ...
    def _repr_html_(self) -> str: ...

MAX_STUDY_POINTS: int

class Study:
    theta_deg: np.ndarray
    h: np.ndarray
    load: np.ndarray
    force: np.ndarray
    a: np.ndarray
    b: np.ndarray
    delta: np.ndarray
    estimate: np.ndarray
    estimate_within: np.ndarray
    estimate_a: np.ndarray
    estimate_delta: np.ndarray
    model: List[Optional[str]]
    answers: List[Optional[Physical]]
    error: List[Optional[str]]
    def __len__(self) -> int: ...

def study(*, r1: float, r2: float, g1: float, g2: float, work_of_adhesion: float,
          theta_deg: ArrayLike, h: ArrayLike, force: Sequence[Optional[float]] = ...,
          model: Optional[ModelName] = ..., nu1: float = ..., nu2: float = ...,
          executor: Any = ...) -> Study: ...
