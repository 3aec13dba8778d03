"""States: one (:class:`State`) or many (:class:`States`, numpy arrays).

Both give JSON-ready dicts (``to_dict``: plain lists, floats, bools and
strings, so ``json.dumps(x.to_dict())`` works), an HTML table for
notebooks, and :class:`States` indexes like the arrays it holds
(``S[S.ok]``, ``S[2:5]``, ``S[i, j]``), iterates over its points in order
(one :class:`State` each) and gives a long-format pandas DataFrame
(``to_pandas``; pandas is an optional extra)."""

from __future__ import annotations

from typing import Any, Dict, Iterator, Union

import numpy as _np

# the order a person reads a state in
_FIRST = ("model", "rho", "a_bar", "b_bar", "s", "delta_bar", "force_bar")
# how a state is checked, by model: the boundary condition's error (the
# ellipse's models, exact), the closure's defect (conformal:K), the Legendre
# tail (layer), the bound on the force's relative error (layer in the plane)
_CHECKS = ("bc_error", "bc_defect", "tail", "force_error")


def _plain(v: Any) -> Any:
    """v with numpy arrays and scalars as plain Python values (JSON-ready)."""
    if isinstance(v, State):
        return v.to_dict()
    if isinstance(v, _np.ndarray):
        return v.tolist()
    if isinstance(v, _np.generic):
        return v.item()
    if isinstance(v, dict):
        return {k: _plain(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [_plain(x) for x in v]
    return v


def _html(rows) -> str:
    """An HTML table of (name, value) rows."""
    from html import escape

    body = "".join(f"<tr><th style='text-align:left'>{escape(str(k))}</th><td>{escape(str(v))}</td></tr>" for k, v in rows)
    return f"<table>{body}</table>"


def _shown(v: Any) -> str:
    if isinstance(v, float):
        return f"{v:.6g}"
    return repr(v)


def _same(a, b) -> bool:
    if isinstance(a, _np.ndarray) or isinstance(b, _np.ndarray):
        return _np.array_equal(a, b)
    return bool(a == b)


class State:
    """One contact state. Attributes carry the solver's names: ``a_bar``,
    ``b_bar``, ``s``, ``delta_bar``, ``force_bar``, ``rho``, ``model`` and
    whatever else the model's state has (``xi``, ``p0``, ``bc_error``,
    ``stable_displacement``, ``stable_load``, ``neutral_displacement``,
    ``neutral_load`` for the models of the ellipse; ``coefficients``,
    ``bc_defect``, ``unstable_modes``, ``unstable_modes_load``,
    ``neutral_modes``, ``neutral_modes_load``, ``perimeter`` for
    ``conformal:K``; ``contour``, ``bc_error``, ``truncation``, ``route``,
    ``unstable_modes_displacement``, ``unstable_modes_load``,
    ``neutral_modes_displacement``, ``neutral_modes_load``,
    ``shortest_wavelength``, ``critical_thinness_displacement``,
    ``critical_thinness_load``, ``shape`` (the part of the contour in
    undulations shorter than the cutoff: ``amplitude`` and ``departure``
    over ā, ``mode``, ``wavelength``, ``unresolved`` where that part is
    above 1 % of ā, and ``critical_thinness``, ``critical_mode``: from which
    h/L on it is), ``coatings`` (``load``, ``displacement``: the range
    ``{from, to}`` of h/L for which the state is resolved and stable above
    the cutoff, None for none) and ``warnings`` for ``exact``; for both,
    ``stable_displacement``
    and ``stable_load`` count only the contour modes above the short-wave
    cutoff ``cutoff``, 2π h/L, and an exact verdict is None where it is not
    settled). A neutral direction has a zero eigenvalue (within 1e-6 of the
    largest): the state is on a fold or bifurcation of that control, such
    as a pull-off under its own control; it does not count as unstable.
    ``stability_load`` and ``stability_displacement`` give the command
    line's verdict: ``"stable"``, ``"neutral"`` (stable but for a zero
    eigenvalue; ``stable_load`` is then True), ``"unstable"``, or None.
    Equal when every field is equal; picklable."""

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
        """The fields as a plain, JSON-ready dict (nested states as dicts,
        arrays as lists)."""
        return {k: _plain(v) for k, v in self._fields.items()}

    def _repr_html_(self) -> str:
        shown = [(k, _shown(v)) for k, v in self._fields.items() if not isinstance(v, (list, dict, State, _np.ndarray))]
        return f"<b>{type(self).__name__}</b>" + _html(shown)

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
        """The answer on the first line (the model, rho, the size, the
        approach and the force, and the control of a pull-off); on the next
        at most two, how far to trust it: the check, the route and the
        stability verdicts, then its first warning. Every field is an
        attribute, and ``to_dict()`` has them all."""
        f = self._fields

        def shown(k):
            v = f[k]
            return f"{k}={v:.6g}" if isinstance(v, float) else f"{k}={v!r}"

        head = [shown(k) for k in _FIRST + ("control",) if k in f]
        lines = [f"{type(self).__name__}({', '.join(head)})"]
        trust = [f"{k}={f[k]:.1e}" for k in _CHECKS if isinstance(f.get(k), float)]
        trust += [shown(k) for k in ("route", "method", "stability_load", "stability_displacement") if f.get(k) is not None]
        if trust:
            lines.append("  " + ", ".join(trust))
        warnings = [w for w in f.get("warnings") or [] if isinstance(w, str)]
        if warnings:
            more = f" ({len(warnings) - 1} more: .warnings)" if len(warnings) > 1 else ""
            lines.append(f"  warning: {warnings[0]}{more}")
        return "\n".join(lines)


# the arrays of a States, in the order its dict and DataFrame give them
_ARRAYS = ("rho", "a_bar", "b_bar", "s", "delta_bar", "force_bar", "bc_error", "error", "error_kind",
           "warning", "departure", "route")


class States:
    """Many states of one model: numpy arrays of the broadcast shape of the
    inputs (``rho``, ``a_bar``, ``b_bar``, ``s``, ``delta_bar``,
    ``force_bar``, ``bc_error``), NaN where a point has no state;
    ``error`` holds each point's reason ('' where it solved) and
    ``error_kind`` the solver's kind of failure; ``warning`` says why a
    point's state is doubtful ('' where it is not: a contour member's
    closure missing (3)₂ by more than 0.1, or b > a), and ``doubtful``
    marks those points; for the exact solver ``departure`` is each contour's
    largest distance from the ellipse with its half-widths (relative to ā;
    NaN for the other models) and ``route`` how the state was found (e.g.
    ``past_fold``, '' for the other models)."""

    def __init__(self, model: str, rho, arrays: Dict[str, _np.ndarray], error, error_kind):
        self.model = model
        self.rho = rho
        for k, v in arrays.items():
            setattr(self, k, v)
        for k in ("warning", "route"):
            if k not in arrays:
                setattr(self, k, _np.full(_np.shape(rho), "", dtype=object))
        if "departure" not in arrays:
            self.departure = _np.full(_np.shape(rho), _np.nan)
        self.error = error
        self.error_kind = error_kind

    @property
    def doubtful(self) -> _np.ndarray:
        """Where a state was found but carries a warning (``warning``)."""
        return self.ok & (self.warning != "")

    @property
    def shape(self):
        return self.rho.shape

    @property
    def ok(self) -> _np.ndarray:
        """Where a state was found."""
        return self.error_kind == ""

    def __len__(self) -> int:
        """The number of points (``size`` of the arrays)."""
        return self.rho.size

    def _arrays(self) -> Dict[str, _np.ndarray]:
        return {k: getattr(self, k) for k in _ARRAYS}

    def __getitem__(self, key) -> "Union[State, States]":
        """The points at ``key``, as numpy indexes the arrays (a boolean
        mask such as ``S.ok``, a slice, an index per axis): a
        :class:`States` of the selected points, or one :class:`State`
        where ``key`` selects a single point."""
        picked = {k: _np.asarray(v)[key] for k, v in self._arrays().items()}
        if picked["rho"].ndim == 0:
            return State({"model": self.model, **{k: _plain(v) for k, v in picked.items()}})
        rest = {k: v for k, v in picked.items() if k not in ("rho", "error", "error_kind")}
        return States(self.model, picked["rho"], rest, picked["error"], picked["error_kind"])

    def __iter__(self) -> Iterator[State]:
        """One :class:`State` per point, in the arrays' (C) order."""
        flat = {k: _np.asarray(v).ravel() for k, v in self._arrays().items()}
        for i in range(self.rho.size):
            yield State({"model": self.model, **{k: _plain(v[i]) for k, v in flat.items()}})

    def to_dict(self) -> Dict[str, Any]:
        """The arrays as plain, JSON-ready (nested) lists, with the model."""
        return {"model": self.model, **{k: v.tolist() for k, v in self._arrays().items()}}

    def to_pandas(self):
        """A pandas DataFrame in long format: one row per point (in the
        arrays' order), a column per quantity, and for inputs of more than
        one dimension the point's index along each axis (``i0``, ``i1``, …).
        pandas is an optional dependency (``pip install thinjkr[pandas]``)."""
        try:
            import pandas as pd
        except ImportError as e:
            raise ImportError("States.to_pandas needs pandas: pip install pandas (or thinjkr[pandas])") from e
        columns: Dict[str, Any] = {}
        if self.rho.ndim > 1:
            for axis, idx in enumerate(_np.indices(self.rho.shape).reshape(self.rho.ndim, -1)):
                columns[f"i{axis}"] = idx
        columns["model"] = [self.model] * self.rho.size
        for k, v in self._arrays().items():
            columns[k] = _np.asarray(v).ravel()
        return pd.DataFrame(columns)

    def _repr_html_(self) -> str:
        failed = int((~self.ok).sum())
        rows = [("model", self.model), ("shape", self.shape), ("solved", self.rho.size - failed), ("without a state", failed),
                ("doubtful (see warning)", int(self.doubtful.sum()))]
        return "<b>States</b>" + _html(rows)

    def __repr__(self) -> str:
        failed = int((~self.ok).sum())
        doubtful = int(self.doubtful.sum())
        more = f", {doubtful} doubtful" if doubtful else ""
        return f"States(model={self.model!r}, shape={self.shape}, {self.rho.size - failed} solved, {failed} without a state{more})"
