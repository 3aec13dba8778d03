"""thinjkr: the approximate JKR model of adhesive contact between two thin
incompressible elastic coatings on rigid cylinders (Argatov, Mishuris &
Popov, Tribology Letters 64:12, 2016), solved in Rust.

Dimensionless variables are those of the paper's (17): ``a_bar`` (major
semi-axis ā), ``b_bar`` (b̄ = s ā), ``s`` (aspect ratio (12)), ``delta_bar``
(approach δ̄), ``force_bar`` (F̄ = F/(2R₁Δγ)); ``rho`` = R₂/R₁ (21).

Models (``models()`` lists them): ``max`` (the paper's closure (13) with
collocation (10), the default), ``apexes``, ``energy`` (Ritz, with
stability), ``apex45``, the contour family ``conformal:K`` (K = 1 … 8), and
``exact`` (the free-boundary problem (2)–(3) itself, also under
``thinjkr.exact``). A contour family of one's own (a data file under
``derive/families/`` and ``generate``, docs/guide.md) joins them without a
rebuild when the environment variable ``THINJKR_FAMILIES`` names the
generated folder before the first call.

Every call releases the GIL; array calls run on all cores.
"""

from __future__ import annotations

import json as _json
import warnings as _warnings
from typing import Any, Dict, List, Optional, Tuple

import numpy as _np

from . import _thinjkr
from ._errors import (
    InvalidInput,
    NoConvergence,
    NoState,
    ThinJkrError,
    Unavailable,
    Unresolved,
    _raise,
    ThinJkrWarning,
)
from ._state import State, States

__all__ = [
    "State",
    "States",
    "PullOff",
    "Physical",
    "Curve",
    "ThinJkrError",
    "ThinJkrWarning",
    "InvalidInput",
    "NoConvergence",
    "NoState",
    "Unavailable",
    "Unresolved",
    "solve",
    "pull_off",
    "zero_force",
    "curve",
    "models",
    "physical",
    "study",
    "Study",
    "exact",
]

__version__ = "0.1.0"

def _state_from(d: Dict[str, Any], model: Optional[str] = None) -> State:
    """A :class:`State` from its JSON: with the model's name where the JSON
    has none (an exact state), and where it has a contour series (an exact
    state), the contour sampled as ``x``, ``y`` at 256 angles."""
    fields = dict(d)
    if model is not None:
        fields.setdefault("model", model)
    if isinstance(d.get("contour"), dict):
        x, y = _call(_thinjkr.exact_contour, _json.dumps(d["contour"]), 256)
        fields["x"], fields["y"] = _np.asarray(x), _np.asarray(y)
    # the layer's states: their verdict on the branch under each control,
    # the words the command line prints (None where it judges none)
    verdicts = fields.pop("verdicts", None)
    if isinstance(verdicts, dict):
        for control in ("load", "displacement"):
            fields[f"stability_{control}"] = verdicts.get(control)
    stab = fields.pop("stability", None)
    if isinstance(stab, dict) and "displacement" in stab and "load" in stab:
        if isinstance(stab["displacement"], list):  # an exact state: unstable modes
            fields["unstable_modes_displacement"] = stab["displacement"]
            fields["unstable_modes_load"] = stab["load"]
            # zero eigenvalues (a fold or bifurcation), not counted as unstable
            fields["neutral_modes_displacement"] = stab.get("neutral_displacement", [])
            fields["neutral_modes_load"] = stab.get("neutral_load", [])
            # the verdicts above the short-wave cutoff (None: not settled)
            fields["stable_displacement"] = stab.get("stable_displacement")
            fields["stable_load"] = stab.get("stable_load")
            fields["cutoff"] = stab.get("cutoff")
            fields["shortest_wavelength"] = stab.get("shortest_wavelength")
            # the thinness h/L below which a contour mode unstable under
            # that control is resolved (None: no contour mode is unstable)
            fields["critical_thinness_displacement"] = stab.get("critical_thinness_displacement")
            fields["critical_thinness_load"] = stab.get("critical_thinness_load")
        else:
            fields["stable_displacement"] = stab["displacement"]
            fields["stable_load"] = stab["load"]
    # the neutral marks, which the JSON leaves out where there are none
    if "stable_load" in fields and "coefficients" in fields and "contour" not in fields:
        fields.setdefault("neutral_modes", [])
        fields.setdefault("neutral_modes_load", [])
    elif "xi" in fields and "stable_load" in fields:
        fields.setdefault("neutral_displacement", False)
        fields.setdefault("neutral_load", False)
    # the command line's verdict under each control, one of three
    for control, neutral in (("load", ("neutral_load", "neutral_modes_load")),
                             ("displacement", ("neutral_displacement", "neutral_modes",
                                               "neutral_modes_displacement"))):
        if f"stable_{control}" in fields:
            fields[f"stability_{control}"] = _verdict(fields[f"stable_{control}"],
                                                      any(fields.get(k) for k in neutral))
    return State(fields)


def _verdict(stable: Optional[bool], neutral: bool) -> Optional[str]:
    """"stable", "neutral" (no unstable direction, and a zero eigenvalue: a
    fold or bifurcation of that control, as a pull-off under its own
    control is), "unstable", or None where the model judges none or the
    verdict is not settled: the three the command line prints."""
    if stable is None:
        return None
    if not stable:
        return "unstable"
    return "neutral" if neutral else "stable"


def _warn(d: Dict[str, Any], stacklevel: int = 3) -> None:
    """Each of a state's warnings (a doubtful state: for a contour-family
    member, (3)₂ missed by more than 0.1 on its contour, or b > a) as a
    :class:`ThinJkrWarning`, as the command line prints them."""
    for w in d.get("warnings") or ():
        _warnings.warn(w, ThinJkrWarning, stacklevel=stacklevel)


def _warn_count(doubtful: int, size: int) -> None:
    """One :class:`ThinJkrWarning` for an array call with doubtful points."""
    if doubtful:
        _warnings.warn(
            f"{doubtful} of {size} states carry warnings (doubtful states: States.warning says "
            "why, States.doubtful marks them)",
            ThinJkrWarning,
            stacklevel=4,
        )


def _call(f, *args):
    try:
        return f(*args)
    except _thinjkr.RawError as e:
        _raise(e)


def models() -> List[Tuple[str, str]]:
    """Every model the solver has, with a one-line description each: the
    models of the ellipse, every member of every contour family in the
    registry (also those loaded from ``THINJKR_FAMILIES``), and ``exact``."""
    return [(n, d) for n, d in _thinjkr.models()]


def _number(name: str, value):
    """A number or an array of numbers the user gave, as float: a bool (or
    an array of bools), a masked array, or anything not numeric is refused
    naming the parameter, not read as 1.0 or with its mask dropped. NaN and
    infinity pass here; the solver names their range."""
    if type(value) is float or type(value) is int:  # the common case, at once (a bool is neither)
        return float(value)
    if isinstance(value, (bool, _np.bool_)):
        raise InvalidInput(f"parameter {name} = {value!r} is a bool, not a number",
                           kind="out_of_range")
    if _np.ma.isMaskedArray(value):
        raise InvalidInput(f"parameter {name} is a masked array: fill it (.filled(nan)) or "
                           "drop the masked points (.compressed()) first", kind="out_of_range")
    arr = _np.asarray(value)
    if arr.dtype == bool or arr.dtype.kind not in "iuf":
        raise InvalidInput(f"parameter {name} must be a number or an array of numbers, "
                           f"got {type(value).__name__} of {arr.dtype}", kind="out_of_range")
    return float(arr) if arr.ndim == 0 else arr.astype(float)


def _whole(name: str, value, lo: int, hi: int) -> int:
    """A count the user gave: a whole number in lo ..= hi (a bool, a
    fraction or a number out of range is refused, naming the parameter)."""
    ok = not isinstance(value, bool) and isinstance(value, (int, float, _np.integer, _np.floating))
    if ok and _np.isfinite(value) and float(value) == int(value) and lo <= int(value) <= hi:
        return int(value)
    raise InvalidInput(f"parameter {name} = {value!r} is outside its allowed range: "
                       f"a whole number {lo} ..= {hi}", kind="out_of_range")


def _coatings(thinness, nu) -> Tuple[Optional[float], Optional[float]]:
    """The layer's coatings as given (None: the default): each one number,
    shared by every point of the call."""
    def one(name, value):
        if value is None:
            return None
        value = _number(name, value)
        if _np.ndim(value) > 0:
            raise InvalidInput(f"parameter {name} must be one number (the coatings of the whole call)",
                               kind="usage")
        return value
    return one("thinness", thinness), one("nu", nu)


def _control(delta, force, a) -> Tuple[str, Any]:
    given = [(k, v) for k, v in (("delta", delta), ("force", force), ("a", a)) if v is not None]
    if len(given) != 1:
        raise InvalidInput(
            "give exactly one control: delta (approach δ̄), force (F̄) or a (contact size ā)",
            kind="usage",
        )
    return given[0]


def solve(rho, *, delta=None, force=None, a=None, model: str = "max", all: bool = False,
          thinness=None, nu=None):
    """The state at radii ratio ``rho`` with exactly one control: approach
    ``delta`` (δ̄), force ``force`` (F̄, the stable state on the branch down
    to pull-off) or contact size ``a`` (ā, the state before the size fold).
    With ``model="layer"``, ``thinness`` (h/L, default 0.1) and ``nu``
    (Poisson's ratio, default 0.5) are the two equal coatings'.

    Scalars give a :class:`State`. When ``rho`` or the control is an array
    (broadcast together), the answer is a :class:`States` of arrays of
    that shape, computed in Rust on all cores; a point without a state is
    NaN in the arrays and has its reason in ``States.error``.

    With ``all=True`` (scalars only) the answer is a list of every state
    at that control, the one given without it first, as ``thinjkr solve
    --all`` lists them: for a model of the ellipse each state with that
    force (or size) along its branch, for ``conformal:K`` every state at
    the control on its curve.
    """
    control, value = _control(delta, force, a)
    rho, value = _number("rho", rho), _number(control, value)
    thinness, nu = _coatings(thinness, nu)
    if all:
        if _np.ndim(rho) != 0 or _np.ndim(value) != 0:
            raise InvalidInput("all=True takes a scalar rho and control (a list of states per point)")
        ds = _json.loads(_call(_thinjkr.states, model, rho, control, value, thinness, nu))
        for d in ds:
            _warn(d)
        return [_state_from(d, model) for d in ds]
    if _np.ndim(rho) == 0 and _np.ndim(value) == 0:
        d = _json.loads(_call(_thinjkr.solve, model, rho, control, value, thinness, nu))
        _warn(d)
        return _state_from(d, model)
    r, v = _np.broadcast_arrays(_np.asarray(rho, dtype=float), _np.asarray(value, dtype=float))
    shape = r.shape
    cols, errors, warns, routes = _call(
        _thinjkr.solve_many,
        model,
        _np.ascontiguousarray(r.ravel()),
        control,
        _np.ascontiguousarray(v.ravel()),
        thinness,
        nu,
    )
    arrays = {k: _np.asarray(x).reshape(shape) for k, x in cols.items()}
    warning = _np.full(r.size, "", dtype=object)
    for i, w in warns:
        warning[i] = w
    arrays["warning"] = warning.reshape(shape)
    route = _np.full(r.size, "", dtype=object)
    for i, w in routes:
        route[i] = w
    arrays["route"] = route.reshape(shape)
    _warn_count(len(warns), r.size)
    kinds = _np.array([e[0] if e else "" for e in errors], dtype=object).reshape(shape)
    msgs = _np.array([e[1] if e else "" for e in errors], dtype=object).reshape(shape)
    return States(model=model, rho=r.copy(), arrays=arrays, error=msgs, error_kind=kinds)


def zero_force(rho, *, model: str = "max", thinness=None, nu=None) -> State:
    """The zero-force state (the paper's Section 5); ``thinness`` and ``nu``
    as for :func:`solve`."""
    return solve(rho, force=0.0, model=model, thinness=thinness, nu=nu)


def _many(rho: _np.ndarray, model: str, one, value: Optional[_np.ndarray] = None) -> States:
    """``one(ρ)`` (or ``one(ρ, v)`` with ``value`` of the same shape) at
    every point of ``rho`` as a :class:`States`: a point's error is NaN with
    its reason; an error in the call itself (a model or control that does
    not exist) is raised."""
    keys = ("a_bar", "b_bar", "s", "delta_bar", "force_bar", "bc_error", "departure")
    arrays = {k: _np.full(rho.shape, _np.nan) for k in keys}
    kinds = _np.full(rho.shape, "", dtype=object)
    msgs = _np.full(rho.shape, "", dtype=object)
    warning = _np.full(rho.shape, "", dtype=object)
    route = _np.full(rho.shape, "", dtype=object)
    for i in _np.ndindex(rho.shape):
        try:
            with _warnings.catch_warnings():
                _warnings.simplefilter("ignore", ThinJkrWarning)
                st = one(float(rho[i])) if value is None else one(float(rho[i]), float(value[i]))
            warning[i] = "; ".join(st.to_dict().get("warnings") or ())
            route[i] = st.to_dict().get("route") or ""
        except ThinJkrError as e:
            if e.kind == "usage":
                raise
            kinds[i], msgs[i] = e.kind, str(e)
            continue
        fields = st.to_dict()
        # every state carries its boundary error (bc_defect for conformal:K)
        if "bc_error" not in fields:
            fields["bc_error"] = fields["bc_defect"]
        fields.setdefault("departure", fields.get("deviation_from_ellipse", _np.nan))
        for k in keys:
            arrays[k][i] = fields[k]
    arrays["warning"] = warning
    arrays["route"] = route
    _warn_count(int((warning != "").sum()), rho.size)
    return States(model=model, rho=rho.copy(), arrays=arrays, error=msgs, error_kind=kinds)


class PullOff(State):
    """A pull-off: a :class:`State` with ``control`` ("load" or
    "displacement") and, for the models of the ellipse, ``basis`` (what
    ends the branch there) and ``basis_words``."""


def pull_off(rho, *, model: str = "max", control: str = "load", thinness=None, nu=None):
    """The pull-off under load control (the minimum of F̄ along the branch,
    the paper's Section 6) or under displacement control (the end of the
    branch in δ̄); ``thinness`` and ``nu`` as for :func:`solve`.

    A scalar ``rho`` gives a :class:`PullOff`. An array gives a
    :class:`States` of that shape (point by point, so that Ctrl-C stops it
    between points); a point without a pull-off is NaN with its reason in
    ``States.error``, as in :func:`solve`."""
    rho = _number("rho", rho)
    thinness, nu = _coatings(thinness, nu)
    if _np.ndim(rho) > 0:
        return _many(rho, model, lambda r: pull_off(r, model=model, control=control,
                                                    thinness=thinness, nu=nu))
    d = _json.loads(_call(_thinjkr.pull_off, model, rho, control, thinness, nu))
    _warn(d["state"])
    st = _state_from(d["state"], model)
    fields = st.to_dict()
    fields["control"] = control
    for k in ("basis", "basis_words"):
        if k in d:
            fields[k] = d[k]
    return PullOff(fields)


class Curve:
    """A traced curve: numpy arrays along the branch (``a_bar``, ``b_bar``,
    ``s``, ``delta_bar``, ``force_bar``, ``bc_error``, ``beyond_size_fold``,
    ``arm``) and ``folds``, a list of (kind, State) with kind
    "displacement", "load" or "contact_size". ``bc_error`` is the model's
    quantity (14) for the models of the ellipse and max |∂p̄/∂ν − 1| on the
    contour for ``conformal:K``. ``arm`` is 0 along one branch; a
    ``conformal:K`` curve for ρ < 1 may have a second arm (1), the one that
    carries the load-controlled pull-off, and ``end`` says how each arm
    ended (None for the models of the ellipse). A field a model's states
    lack is NaN (the axisymmetric layer's, at ρ = 1, carry no ``b_bar``,
    ``s`` or ``bc_error``)."""

    def __init__(
        self,
        states: List[State],
        folds: List[Tuple[str, State]],
        arm: Optional[List[int]] = None,
        beyond_size_fold: Optional[List[bool]] = None,
        end: Optional[str] = None,
    ):
        self.states = states
        self.folds = folds
        self.end = end
        # (a field a model's states lack is NaN: the axisymmetric layer's,
        # circles, carry no b_bar or s)
        for k in ("a_bar", "b_bar", "s", "delta_bar", "force_bar"):
            setattr(self, k, _np.array([st.to_dict().get(k, _np.nan) for st in states], dtype=float))
        # (the layer's states have neither: NaN, and no size fold)
        self.bc_error = _np.array(
            [st.bc_error if "bc_error" in st.keys()
             else st.bc_defect if "bc_defect" in st.keys() else _np.nan for st in states],
            dtype=float,
        )
        if beyond_size_fold is None:
            beyond_size_fold = [st.to_dict().get("beyond_size_fold", False) for st in states]
        self.beyond_size_fold = _np.array(beyond_size_fold, dtype=bool)
        self.arm = _np.array(arm if arm is not None else [0] * len(states), dtype=int)

    def __len__(self) -> int:
        return len(self.states)

    def to_dict(self) -> Dict[str, Any]:
        """The curve as a plain, JSON-ready dict: its arrays as lists, its
        states and folds as dicts, and how its arms ended."""
        arrays = ("a_bar", "b_bar", "s", "delta_bar", "force_bar", "bc_error", "beyond_size_fold", "arm")
        return {
            **{k: getattr(self, k).tolist() for k in arrays},
            "states": [st.to_dict() for st in self.states],
            "folds": [{"kind": kind, "state": st.to_dict()} for kind, st in self.folds],
            "end": self.end,
        }

    def _repr_html_(self) -> str:
        from html import escape

        folds = ", ".join(f"{kind} at F̄ = {st.force_bar:.6g}" for kind, st in self.folds) or "none"
        return f"<b>Curve</b>: {len(self.states)} states; folds: {escape(folds)}"

    def __repr__(self) -> str:
        return f"Curve({len(self.states)} states, folds: {[k for k, _ in self.folds]})"


def curve(rho, *, model: str = "max", points: int = 200, delta_start: float = 20.0,
          thinness=None, nu=None):
    """The curve of a model of the ellipse or of ``conformal:K`` at ``rho``
    from δ̄ = ``delta_start`` past pull-off and its folds, ``points`` states
    evenly spaced in arclength (the paper's Figs. 6–8). For ``model="layer"``
    (``thinness`` and ``nu`` as for :func:`solve`) the states are evenly
    spaced in size from δ̄ = ``delta_start`` down to 3 % of it, both
    pull-offs its folds (at ρ < 1 seconds a point).

    A scalar ``rho`` gives a :class:`Curve`; an array (or list) of ρ gives
    a list of curves, one per ρ in the array's order (flattened), since
    curves differ in length. A ρ without a curve raises, as for a scalar."""
    points = _whole("points", points, 2, _thinjkr.MAX_CURVE_POINTS)
    rho = _number("rho", rho)
    thinness, nu = _coatings(thinness, nu)
    delta_start = _number("delta_start", delta_start)
    if _np.ndim(delta_start) > 0:
        raise InvalidInput("parameter delta_start must be one number (the curves of an array of rho "
                           "share their start)", kind="usage")
    if _np.ndim(rho) > 0:
        return [_curve(float(r), model, points, delta_start, thinness, nu)
                for r in _np.asarray(rho).ravel()]
    return _curve(rho, model, points, delta_start, thinness, nu)


def _curve(rho: float, model: str, points: int, delta_start: float, thinness=None, nu=None) -> Curve:
    d = _json.loads(_call(_thinjkr.curve, model, rho, points, delta_start, thinness, nu))
    states = [_state_from(s) for s in d["states"]]
    folds = [(f["kind"], _state_from(f["state"])) for f in d["folds"]]
    # one warning for the call: how many states carry warnings and the
    # first one's words (each state's `warnings` say the rest); the stretch
    # past the contact-size fold is part of the curve asked for
    # (Curve.beyond_size_fold marks it), not a doubt
    doubtful = [s["warnings"] for s in d["states"]
                if s.get("warnings") and not s.get("beyond_size_fold")]
    if doubtful:
        _warnings.warn(f"{len(doubtful)} of {len(states)} states along the curve carry warnings "
                       f"(each state's `warnings` say why), the first: {doubtful[0][0]}",
                       ThinJkrWarning, stacklevel=3)
    return Curve(states, folds, d.get("arm"), d.get("beyond_size_fold"), d.get("end"))


_CYLINDER_KEYS = ("r1", "r2", "theta_deg", "h1", "h2", "g1", "g2", "work_of_adhesion")


def physical(
    *,
    r1: float,
    r2: float,
    theta_deg: float,
    h1: float,
    h2: float,
    g1: float,
    g2: float,
    work_of_adhesion: float,
    delta: Optional[float] = None,
    force: Optional[float] = None,
    model: Optional[str] = None,
    nu1: float = 0.5,
    nu2: float = 0.5,
) -> State:
    """A contact in SI units (the command line's ``physical``, any model as
    with ``--model``; without a model, the one the table of defaults gives
    for this ρ and question, named in ``model`` with the reason in
    ``chosen_because``, and the paper's ``max`` under ``paper_model`` where
    the two differ by more than 1 %): cylinder
    radii r1, r2 (m), crossing angle theta_deg (degrees), coating
    thicknesses h1, h2 (m), out-of-plane shear moduli g1, g2 (Pa), work of
    adhesion (J/m²); at approach ``delta`` (m), at ``force`` (N), or the
    pull-off when neither is given. The answer carries the SI values
    (``a``, ``b``, ``delta``, ``force``, ``p0``, ``h_over_a``) and the
    dimensionless state under ``state``, and ``warnings``: each one is
    also issued as a :class:`ThinJkrWarning` (an input outside the paper's
    stated range, coatings not thin against the contact), the same words
    as the command line's warnings. ``nu1``, ``nu2`` are the coatings'
    Poisson's ratios in [0, 0.5], which the layer of finite thickness reads
    (model ``layer``; without a model it answers wherever (2) is more than
    0.5 % off, at ρ = 1 and, for the pull-off, at ρ < 1 where the layer
    in the plane reaches the coatings (h/L from 0.3 to 10: the sharp edge,
    else the grid solver), with (2)'s answer
    under ``thin_layer``: its ``model``, ``state``, ``si`` and
    ``relative_error``)."""
    answer = _physical(dict(r1=r1, r2=r2, theta_deg=theta_deg, h1=h1, h2=h2, g1=g1, g2=g2,
                            work_of_adhesion=work_of_adhesion, nu1=nu1, nu2=nu2), delta, force, model)
    for w in answer.warnings:
        _warnings.warn(w, ThinJkrWarning, stacklevel=2)
    return answer


def _physical(cyl: Dict[str, Any], delta, force, model) -> "Physical":
    """:func:`physical` without issuing its warnings (they are in the
    answer's ``warnings``)."""
    for k, v in cyl.items():
        if not isinstance(v, (int, float)):
            raise InvalidInput(f"parameter {k} must be a number, got {type(v).__name__}", kind="out_of_range")
        if not _np.isfinite(v):
            raise InvalidInput(f"parameter {k} = {v} is outside its allowed range finite and > 0",
                               kind="out_of_range")
    d = _json.loads(_call(_thinjkr.physical, _json.dumps(cyl),
                          None if delta is None else float(delta),
                          None if force is None else float(force), model))
    d["state"] = _state_from(d.pop("state"), d["model"])
    if d.get("paper_model") is not None:
        d["paper_model"] = _state_from(d["paper_model"], "max")
    if d.get("thin_layer") is not None:
        t = d["thin_layer"]
        t["state"] = _state_from(t["state"], t["model"])
        d["thin_layer"] = State(t)
    return Physical(d)


class Physical(State):
    """A contact in SI units (:func:`physical`): ``a``, ``b`` (m),
    ``delta`` (m), ``force`` (N), ``p0`` (Pa), ``h_over_a``, the
    dimensionless ``state`` and the ``warnings`` in words; where the layer
    of finite thickness answered by default, ``thin_layer`` (None
    otherwise); where (2) answered coatings the layer does not answer at
    this angle, ``layer_estimate``: the best estimate of the layer's
    pull-off, or of its state at the force or approach asked, a dict of
    ``force`` (N), ``state`` (for a state: a dict of ``a``, ``b`` and
    ``delta`` in m; None for a pull-off), ``within`` (relative, None where
    not measured), ``by`` ("line_tension", "shifted_line_tension",
    "first_order" or "ratio") and ``thin_layer_error`` and ``leads`` (None
    otherwise)."""

    def __repr__(self) -> str:
        """The answer on the first line: the force in N with the model that
        gave it, or, where the layer's estimate is nearer the layer than (2)
        (``layer_estimate["leads"]``), that estimate with its bound; next
        how far to trust the state, and (2)'s answer with its error where the
        layer measured it; then the first warning, as the command line
        prints them."""
        f = self._fields
        estimate = f.get("layer_estimate")
        thin = f.get("thin_layer")
        if isinstance(estimate, dict) and estimate.get("leads"):
            state = estimate.get("state")
            if isinstance(state, dict):
                answer = (f"a={state['a']:.6g} m, delta={state['delta']:.6g} m, force={estimate['force']:.6g} N: "
                          f"the layer of finite thickness's state")
                beside = f"a={f['a']:.6g} m, delta={f['delta']:.6g} m, force={f['force']:.6g} N"
            else:
                answer = f"force={estimate['force']:.6g} N: the layer of finite thickness's pull-off"
                beside = f"force={f['force']:.6g} N"
            lines = [f"Physical({answer}, estimated within {100 * estimate['within']:.2g} % by {estimate['by']})",
                     f"  (2): model={f['model']!r}, {beside}, "
                     f"{100 * estimate['thin_layer_error']:.3g} % off"]
        else:
            lines = [f"Physical(model={f['model']!r}, force={f['force']:.6g} N, a={f['a']:.6g} m, "
                     f"delta={f['delta']:.6g} m)"]
            trust = repr(f["state"]).split("\n")[1:2]
            lines += [t for t in trust if not t.startswith("  warning: ")]
            if isinstance(thin, State):
                lines.append(f"  (2): model={thin.model!r}, force={thin.si['force']:.6g} N, "
                             f"{100 * thin.relative_error:.3g} % off")
        warnings = [w for w in f.get("warnings") or [] if isinstance(w, str)]
        if warnings:
            more = f" ({len(warnings) - 1} more: .warnings)" if len(warnings) > 1 else ""
            lines.append(f"  warning: {warnings[0]}{more}")
        return "\n".join(lines)


#: The most points a :func:`study` takes (its grid is built before any is
#: solved).
MAX_STUDY_POINTS = 1_000_000


class Study:
    """A study's points (:func:`study`), in the order of its grid: the
    angles outermost, then the thicknesses, then the loads. Arrays of one
    entry a point: ``theta_deg``, ``h`` (m), ``load`` (the force asked for,
    N; NaN for the pull-off), and the answer's ``force`` (N), ``a``, ``b``,
    ``delta`` (m), NaN where the point has none; lists ``model`` (the model
    that answered, None where none did), ``answers`` (each point's
    :class:`Physical`, or None) and ``error`` (why a point has no answer, in
    words, else None); where (2) answered coatings the layer does not reach,
    ``estimate`` holds the best estimate of the layer's pull-off force (N)
    (of the state's force, at a load) and ``estimate_within`` its bound,
    relative (:class:`Physical`'s ``layer_estimate``; NaN where there is
    none, or no bound is measured); at a load, ``estimate_a`` and
    ``estimate_delta`` hold the estimated state's a and delta (m; NaN
    where there is none).
    No point is dropped."""

    def __init__(self, points, outcomes):
        self.theta_deg = _np.array([p[0] for p in points], dtype=float)
        self.h = _np.array([p[1] for p in points], dtype=float)
        self.load = _np.array([_np.nan if p[2] is None else p[2] for p in points], dtype=float)
        self.answers = [o if isinstance(o, Physical) else None for o in outcomes]
        self.error = [None if isinstance(o, Physical) else o for o in outcomes]

        def si(key):
            return _np.array([_np.nan if a is None else getattr(a, key) for a in self.answers], dtype=float)

        self.force, self.a, self.b, self.delta = si("force"), si("a"), si("b"), si("delta")

        def estimated(key):
            values = [None if a is None or a.layer_estimate is None else a.layer_estimate[key]
                      for a in self.answers]
            return _np.array([_np.nan if v is None else v for v in values], dtype=float)

        self.estimate, self.estimate_within = estimated("force"), estimated("within")

        def estimated_state(key):
            states = [None if a is None or a.layer_estimate is None else a.layer_estimate.get("state")
                      for a in self.answers]
            return _np.array([_np.nan if s is None else s[key] for s in states], dtype=float)

        self.estimate_a, self.estimate_delta = estimated_state("a"), estimated_state("delta")
        self.model = [None if a is None else a.model for a in self.answers]

    def __len__(self) -> int:
        return len(self.answers)

    def __repr__(self) -> str:
        failed = sum(e is not None for e in self.error)
        return f"Study({len(self)} points, {len(self) - failed} answered, {failed} without an answer)"


def _study_point(job):
    """One point of a :func:`study`: its :class:`Physical`, or why it has
    none (a :class:`ThinJkrError`'s words). Module-level, so that a process
    pool or a Dask cluster can pickle it."""
    cyl, load, model = job
    try:
        return _physical(cyl, None, load, model)
    except ThinJkrError as e:
        return f"{type(e).__name__}: {e}"


def study(*, r1: float, r2: float, g1: float, g2: float, work_of_adhesion: float,
          theta_deg, h, force=(None,), model: Optional[str] = None,
          nu1: float = 0.5, nu2: float = 0.5, executor=None) -> Study:
    """:func:`physical` over every combination of the crossing angles
    ``theta_deg`` (degrees), the coating thicknesses ``h`` (m, both
    coatings alike) and the loads ``force`` (N; None: the pull-off under
    load control, the default), the rest of the contact as in
    :func:`physical`. Each point is one :func:`physical` call, mapped by
    ``executor.map``: any :class:`concurrent.futures.Executor` — a thread
    pool (each call releases the GIL), a process pool started by ``spawn``
    (``mp_context=multiprocessing.get_context("spawn")``: a child forked
    from a process whose solver has run hangs on its thread pool), or a
    Dask cluster's ``Client.get_executor()`` for studies beyond one
    machine. Without one
    the points are solved here, one after another. A point without an
    answer keeps its place with its reason (``Study.error``); the warnings
    of each answer are in its ``warnings``, not issued."""
    angles = [float(x) for x in _np.atleast_1d(_np.asarray(theta_deg, dtype=float))]
    thick = [float(x) for x in _np.atleast_1d(_np.asarray(h, dtype=float))]
    loads = [None if f is None else float(f) for f in (force if _np.ndim(force) else [force])]
    count = len(angles) * len(thick) * len(loads)
    if count == 0 or count > MAX_STUDY_POINTS:
        raise InvalidInput(
            f"parameter points = {count} is outside its allowed range 1 to {MAX_STUDY_POINTS} "
            "(the angles times the thicknesses times the loads)", kind="out_of_range")
    points = [(t, hh, f) for t in angles for hh in thick for f in loads]
    jobs = [(dict(r1=r1, r2=r2, theta_deg=t, h1=hh, h2=hh, g1=g1, g2=g2,
                  work_of_adhesion=work_of_adhesion, nu1=nu1, nu2=nu2), f, model)
            for t, hh, f in points]
    outcomes = list(map(_study_point, jobs) if executor is None else executor.map(_study_point, jobs))
    return Study(points, outcomes)


from . import exact  # noqa: E402  (uses the helpers above)
