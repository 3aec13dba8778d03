"""States: one (:class:`State`) or many (:class:`States`, numpy arrays)."""

from __future__ import annotations

from typing import Any, Dict, Iterator

import numpy as _np

# the order a person reads a state in
_FIRST = ("model", "rho", "a_bar", "b_bar", "s", "delta_bar", "force_bar")


def _same(a, b) -> bool:
    if isinstance(a, _np.ndarray) or isinstance(b, _np.ndarray):
        return _np.array_equal(a, b)
    return bool(a == b)


class State:
    """One contact state. Attributes carry the solver's names: ``a_bar``,
    ``b_bar``, ``s``, ``delta_bar``, ``force_bar``, ``rho``, ``model`` and
    whatever else the model's state has (``xi``, ``p0``, ``bc_error``,
    ``stable_displacement``, ``stable_load`` for the models of the
    ellipse; ``coefficients``, ``bc_defect``, ``unstable_modes`` for
    ``conformal:K``; ``contour``, ``bc_error``, ``truncation``, ``route``
    for ``exact``). Equal when every field is equal; picklable."""

    __slots__ = ("_fields",)

    def __init__(self, fields: Dict[str, Any]):
        object.__setattr__(self, "_fields", dict(fields))

    def __getattr__(self, name: str) -> Any:
        try:
            return self._fields[name]
        except KeyError:
            raise AttributeError(f"this state has no field {name!r} (it has {', '.join(self._fields)})") from None

    def __setattr__(self, name, value):
        raise AttributeError("a State is read-only")

    def __dir__(self):
        return list(self._fields) + ["to_dict"]

    def to_dict(self) -> Dict[str, Any]:
        """The fields as a plain dict (nested states as dicts)."""
        return {k: (v.to_dict() if isinstance(v, State) else v) for k, v in self._fields.items()}

    def keys(self) -> Iterator[str]:
        return iter(self._fields)

    def __eq__(self, other) -> bool:
        if type(other) is not type(self) or self._fields.keys() != other._fields.keys():
            return False
        return all(_same(self._fields[k], other._fields[k]) for k in self._fields)

    # equal states need not be one object; a State holds lists and arrays
    __hash__ = None  # type: ignore[assignment]

    def __getstate__(self):
        return self._fields

    def __setstate__(self, fields):
        object.__setattr__(self, "_fields", fields)

    def __reduce__(self):
        return (type(self), (self._fields,))

    def __repr__(self) -> str:
        parts = []
        for k in _FIRST + tuple(k for k in self._fields if k not in _FIRST):
            if k not in self._fields:
                continue
            v = self._fields[k]
            if isinstance(v, float):
                parts.append(f"{k}={v:.6g}")
            elif isinstance(v, (list, dict, State, _np.ndarray)):
                continue  # contours, arrays and coefficient lists: see to_dict()
            else:
                parts.append(f"{k}={v!r}")
        return f"{type(self).__name__}({', '.join(parts)})"


class States:
    """Many states of one model: numpy arrays of the broadcast shape of the
    inputs (``rho``, ``a_bar``, ``b_bar``, ``s``, ``delta_bar``,
    ``force_bar``, ``bc_error``), NaN where a point has no state;
    ``error`` holds each point's reason ('' where it solved) and
    ``error_kind`` the solver's kind of failure."""

    def __init__(self, model: str, rho, arrays: Dict[str, _np.ndarray], error, error_kind):
        self.model = model
        self.rho = rho
        for k, v in arrays.items():
            setattr(self, k, v)
        self.error = error
        self.error_kind = error_kind

    @property
    def shape(self):
        return self.rho.shape

    @property
    def ok(self) -> _np.ndarray:
        """Where a state was found."""
        return self.error_kind == ""

    def __len__(self) -> int:
        return self.rho.size

    def to_dict(self) -> Dict[str, Any]:
        keys = ("rho", "a_bar", "b_bar", "s", "delta_bar", "force_bar", "bc_error", "error", "error_kind")
        return {"model": self.model, **{k: getattr(self, k) for k in keys}}

    def __repr__(self) -> str:
        failed = int((~self.ok).sum())
        return f"States(model={self.model!r}, shape={self.shape}, {self.rho.size - failed} solved, {failed} without a state)"
