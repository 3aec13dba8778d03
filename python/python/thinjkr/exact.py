"""The exact solution of the free-boundary problem (2)–(3): states whose
contour is a Fourier series, with its independent check max|∂p̄/∂ν − 1| on a
fine grid (``bc_error``), the truncation used, the route that found it, and
the contour as numpy arrays (``x``, ``y``)."""

from __future__ import annotations

import json as _json

import numpy as _np

from . import _thinjkr
from . import _call, _control, _many, _number, _state_from, _warn, _whole, InvalidInput, PullOff, State


def _with_contour(d, points: int) -> State:
    st = _state_from(d)
    fields = {"model": "exact", **st.to_dict()}
    x, y = _call(_thinjkr.exact_contour, _json.dumps(d["contour"]), _whole("points", points, 3, _thinjkr.MAX_CURVE_POINTS))
    fields["x"] = _np.asarray(x)
    fields["y"] = _np.asarray(y)
    return State(fields)


def solve(rho, *, delta=None, force=None, points: int = 256, modes=None, thinness=None,
          gap: str = "cylinders"):
    """The exact state at approach ``delta`` (δ̄) or force ``force`` (F̄),
    its contour sampled at ``points`` angles. ``modes``: the contour series'
    length (1 … 96); by default the modes are escalated from 12 to 96 until
    the fine-grid boundary error is below 1e-9 (where none is,
    :class:`Unresolved` is raised with the smallest error reached). A given
    ``modes`` takes the exterior-map series alone; where it does not resolve
    the contour (below about ρ = 0.34) the default goes on to the arclength
    representation, which ``modes`` does not choose.
    ``thinness``: the coatings' h/L, which sets the short-wave cutoff 2π h/L
    below which unstable contour modes are not resolved by (2) (default
    0.1): ``stable_displacement`` and ``stable_load`` count only the longer
    modes (None: not settled, the series stops short of the cutoff), and
    each unstable mode says whether it is ``resolved``. A state whose shape
    has more than 1 % of ā in undulations shorter than the cutoff (``shape``)
    says so in ``warnings``, raised as a :class:`ThinJkrWarning`.
    ``gap``: the gap solved, ``"cylinders"`` (the paper's (1)) or the name of
    a contour family, built in or loaded through ``THINJKR_FAMILIES``, whose
    own gap it is (``thinjkr exact solve --gap``; an unknown name raises
    :class:`InvalidInput` listing the known ones).

    Scalars give a :class:`State`; when ``rho`` or the control is an array
    (broadcast together) the answer is a :class:`States` of that shape,
    point by point (Ctrl-C stops it), a point without a state NaN with its
    reason in ``States.error``."""
    control, value = _control(delta, force, None)
    rho, value = _number("rho", rho), _number(control, value)
    modes = _modes(modes)
    if _np.ndim(rho) > 0 or _np.ndim(value) > 0:
        r, v = _np.broadcast_arrays(_np.asarray(rho, dtype=float), _np.asarray(value, dtype=float))
        return _many(r, "exact", lambda a, b: solve(a, points=points, modes=modes, thinness=thinness,
                                                    gap=gap, **{control: b}), v)
    d = _json.loads(_call(_thinjkr.exact, rho, control, value, modes, _thinness(thinness), str(gap)))
    _warn(d)
    return _with_contour(d, points)


def zero_force(rho, *, points: int = 256, modes=None, thinness=None, gap: str = "cylinders"):
    """The exact zero-force state (an array of ``rho`` gives a
    :class:`States`, as in :func:`solve`; ``gap`` as there)."""
    return solve(rho, force=0.0, points=points, modes=modes, thinness=thinness, gap=gap)


def pull_off(rho, *, points: int = 256, modes=None, thinness=None, gap: str = "cylinders"):
    """The exact load-controlled pull-off (the first minimum of F̄ along the
    family, traced from just above the richest contour model's pull-off), a
    :class:`PullOff` with ``control`` "load", as
    ``thinjkr.pull_off(rho, model="exact")`` gives it. ``modes`` as in
    :func:`solve`: by default escalated from 12 to 96 until the fine-grid
    boundary error is below 1e-9 (at ρ = 0.3: 80 modes); ``thinness`` as
    in :func:`solve`; ``gap`` as there (on a gap no circle solves, the pull-off is
    reached by the walk in the gap from the cylinders': docs/exact.md, "A gap no
    circle solves"). An array of ``rho`` gives a :class:`States`, as in
    :func:`solve`."""
    rho = _number("rho", rho)
    modes = _modes(modes)
    if _np.ndim(rho) > 0:
        return _many(_np.asarray(rho, dtype=float), "exact",
                     lambda r: pull_off(r, points=points, modes=modes, thinness=thinness, gap=gap))
    d = _json.loads(_call(_thinjkr.exact, rho, "pull_off", 0.0, modes, _thinness(thinness), str(gap)))
    _warn(d)
    return PullOff({**_with_contour(d, points).to_dict(), "control": "load"})


def _thinness(thinness):
    """h/L: one number (the solver names its range)."""
    if thinness is None:
        return None
    t = _number("thinness", thinness)
    if _np.ndim(t) > 0:
        raise InvalidInput("parameter thinness must be one number (h/L of the coatings), not an array",
                           kind="out_of_range")
    return t


def _modes(modes):
    return None if modes is None else _whole("modes", modes, 1, _thinjkr.MAX_USER_MODES)
