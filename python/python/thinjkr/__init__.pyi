"""Type stubs of thinjkr (see the module's docstring)."""

from typing import Any, Dict, Iterator, List, Literal, Optional, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

from . import exact as exact

ArrayLike = Union[float, npt.ArrayLike]
ModelName = str

class ThinJkrError(Exception):
    kind: str
    def __init__(self, message: str, kind: str = ...) -> None: ...

class InvalidInput(ThinJkrError, ValueError): ...
class NoState(ThinJkrError): ...
class NoConvergence(ThinJkrError): ...
class Unresolved(ThinJkrError): ...
class Unavailable(ThinJkrError): ...

class State:
    model: str
    rho: float
    a_bar: float
    b_bar: float
    s: float
    delta_bar: float
    force_bar: float
    def __init__(self, fields: Dict[str, Any]) -> None: ...
    def __getattr__(self, name: str) -> Any: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def keys(self) -> Iterator[str]: ...

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
    @property
    def shape(self) -> Tuple[int, ...]: ...
    @property
    def ok(self) -> np.ndarray: ...
    def __len__(self) -> int: ...
    def to_dict(self) -> Dict[str, Any]: ...

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

@overload
def solve(rho: float, *, delta: Optional[float] = ..., force: Optional[float] = ...,
          a: Optional[float] = ..., model: ModelName = ...) -> State: ...
@overload
def solve(rho: ArrayLike, *, delta: Optional[ArrayLike] = ..., force: Optional[ArrayLike] = ...,
          a: Optional[ArrayLike] = ..., model: ModelName = ...) -> Union[State, States]: ...
def zero_force(rho: float, *, model: ModelName = ...) -> State: ...
def pull_off(rho: float, *, model: ModelName = ...,
             control: Literal["load", "displacement"] = ...) -> PullOff: ...
def curve(rho: float, *, model: ModelName = ..., points: int = ..., delta_start: float = ...) -> Curve: ...
def models() -> List[Tuple[str, str]]: ...
def physical(*, r1: float, r2: float, theta_deg: float, h1: float, h2: float, g1: float, g2: float,
             work_of_adhesion: float, delta: Optional[float] = ..., force: Optional[float] = ...) -> State: ...
