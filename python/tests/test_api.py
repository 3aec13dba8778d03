"""The Python API against the command line's JSON (the same inputs, every
model), arrays against loops of scalar calls, every error class from the
input that should raise it, pickling, and threads."""

import concurrent.futures
import json
import math
import pickle
import subprocess

import numpy as np
import pytest

import thinjkr

ELLIPSE = ["max", "apexes", "energy", "apex45"]


def run_json(cli, *args):
    out = subprocess.run([cli, *args, "--json"], check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def examples_contact(theta_deg, h):
    """The examples' contact (r = 10 mm, G' = 1 MPa, work of adhesion
    0.05 J/m^2) at the crossing angle theta_deg with both coatings h thick:
    physical()'s keywords and the command line's arguments."""
    contact = dict(r1=0.01, r2=0.01, theta_deg=theta_deg, h1=h, h2=h, g1=1e6, g2=1e6, work_of_adhesion=0.05)
    args = ["physical", "--r1", "0.01", "--r2", "0.01", "--theta-deg", f"{theta_deg}", "--h1", f"{h}", "--h2", f"{h}",
            "--g1", "1e6", "--g2", "1e6", "--work-of-adhesion", "0.05"]
    return contact, args


def close(x, y, rel=1e-12):
    return math.isclose(x, y, rel_tol=rel, abs_tol=1e-12)


def assert_same_state(st, d):
    """Every number of the command line's state, to the digits it prints
    (it prints every digit of an f64: equal to round-off)."""
    for k, v in d.items():
        name = k
        if isinstance(v, float):
            assert close(getattr(st, name), v), (name, getattr(st, name), v)
        elif isinstance(v, str):
            assert getattr(st, name) == v, (name, getattr(st, name), v)


@pytest.mark.parametrize("model", ELLIPSE + ["conformal:2", "conformal:8", "slender"])
def test_solve_equals_the_command_line(cli, model):
    for args, kwargs in [
        (["--delta", "2"], {"delta": 2.0}),
        (["--force", "10"], {"force": 10.0}),
    ]:
        d = run_json(cli, "solve", "--model", model, "--rho", "0.8", *args)
        d = d.get("state", d)
        assert_same_state(thinjkr.solve(0.8, model=model, **kwargs), d)


@pytest.mark.parametrize("model", ELLIPSE + ["conformal:4", "slender"])
def test_pull_off_and_zero_force_equal_the_command_line(cli, model):
    d = run_json(cli, "pull-off", "--model", model, "--rho", "0.8")
    po = thinjkr.pull_off(0.8, model=model)
    assert_same_state(po, d["state"])
    if "basis" in d:
        assert po.basis == d["basis"]
    z = run_json(cli, "zero-force", "--model", model, "--rho", "0.8")
    assert_same_state(thinjkr.zero_force(0.8, model=model), z.get("state", z))


@pytest.mark.parametrize("model,args,kwargs", [
    ("max", ["--force", "-4"], {"force": -4.0}),
    ("max", ["--a", "2.3"], {"a": 2.3}),
    ("conformal:8", ["--force", "-4"], {"force": -4.0}),
])
def test_all_states_equal_the_command_line(cli, model, args, kwargs):
    """``solve(..., all=True)`` lists what ``thinjkr solve --all`` lists
    (issue 34: Python gave the first state only), the one ``solve`` gives
    first; conformal:8 at rho = 0.8, F = -4 has two on its curve."""
    d = run_json(cli, "solve", "--model", model, "--rho", "0.8", *args, "--all")
    want = d["states"] if "states" in d else [d["state"]]
    got = thinjkr.solve(0.8, model=model, all=True, **kwargs)
    assert len(got) == len(want) >= 2
    for st, w in zip(got, want):
        assert_same_state(st, w)
    assert got[0] == thinjkr.solve(0.8, model=model, **kwargs)
    with pytest.raises(thinjkr.InvalidInput, match="scalar"):
        thinjkr.solve([0.8, 0.9], model=model, all=True, **kwargs)


def test_a_pull_off_is_neutral_under_its_own_control_not_unstable(cli):
    """Issue 31: a pull-off sits on the fold that ends its control, where
    one eigenvalue is zero; it was counted as negative, and every pull-off
    read "unstable" under its own control. It is now neutral, apart from
    the unstable modes, in every model that judges stability."""
    e = thinjkr.pull_off(0.8, model="energy")
    assert (e.stable_load, e.neutral_load) == (True, True)
    assert (e.stable_displacement, e.neutral_displacement) == (True, False)
    c = thinjkr.pull_off(0.8, model="conformal:2", control="displacement")
    assert c.stable_displacement and c.unstable_modes == [] and c.neutral_modes == [2]
    z = thinjkr.zero_force(0.8, model="conformal:2")
    assert z.neutral_modes == [] and z.neutral_modes_load == []
    # issue 73, item 4: the command line's three verdicts, which it prints
    # ("load control: neutral"); stable_load alone read True there
    assert (e.stability_load, e.stability_displacement) == ("neutral", "stable")
    assert c.stability_displacement == "neutral"
    assert (z.stability_load, z.stability_displacement) == ("stable", "stable")
    assert "stability_load='neutral'" in repr(e)
    for st in (e, z):
        text = subprocess.run([cli, "pull-off" if st is e else "zero-force", "--rho", "0.8",
                               "--model", st.model], capture_output=True, text=True, check=True).stdout
        assert f"load control: {st.stability_load}" in text, text


def test_slender_refuses_what_it_lacks_with_the_reason():
    """The slender contact has no finite length: a state at a contact size,
    its curve and its displacement-controlled pull-off are refused, typed."""
    with pytest.raises(thinjkr.Unavailable, match="no finite length"):
        thinjkr.solve(0.1, a=2.0, model="slender")
    with pytest.raises(thinjkr.Unavailable, match="never lets go"):
        thinjkr.pull_off(0.1, model="slender", control="displacement")
    # one curve for every rho: the pull-off force scales as rho^(1/2)
    a, b = thinjkr.pull_off(0.1, model="slender"), thinjkr.pull_off(0.4, model="slender")
    assert close(b.force_bar / a.force_bar, 2.0)


def test_exact_equals_the_command_line(cli):
    d = run_json(cli, "exact", "solve", "--rho", "0.8", "--force", "10")["state"]
    st = thinjkr.exact.solve(0.8, force=10.0)
    for k in ("a_bar", "b_bar", "s", "delta_bar", "force_bar", "bc_error"):
        assert close(getattr(st, k), d[k]), k
    assert st.route == d["route"]
    # the contour arrays: ā is the largest x, b̄ the largest y
    assert close(st.x.max(), st.a_bar, 1e-9) and close(st.y.max(), st.b_bar, 1e-6)


def test_exact_takes_a_gap_by_name(cli):
    """Issue 73, item 2: gap= as the command line's --gap (a loaded family's
    own gap in the slow tier's walk, python/tests/test_walk.py)."""
    plain = thinjkr.exact.pull_off(1.0)
    assert plain.gap == "cylinders"
    for name in ("cylinders", "conformal"):
        st = thinjkr.exact.pull_off(1.0, gap=name)
        assert st.gap == "cylinders" and st.force_bar == plain.force_bar, name
    with pytest.raises(thinjkr.InvalidInput, match="unknown gap nope: the known gaps are cylinders"):
        thinjkr.exact.pull_off(1.0, gap="nope")


def test_exact_stability_counts_the_modes_above_the_cutoff(cli):
    """The circle at F = 10 (a = 3.2141) is unstable to every even n >= 10
    its series holds; n = 10 is 2 pi a / 10 = 2.019 long. With h/L = 0.1
    (the default; cutoff 2 pi h/L = 0.628) the state is unstable above the
    cutoff, with h/L = 0.5 (cutoff 3.142) stable, as the command line says."""
    thin = thinjkr.exact.solve(1.0, force=10.0, modes=12)
    assert (thin.stable_displacement, thin.stable_load) == (False, False)
    assert min(m["n"] for m in thin.unstable_modes_load if m["resolved"]) == 10
    assert close(thin.cutoff["wavelength"], 2 * np.pi * 0.1, 1e-12)
    # the critical thinness: n = 10's wavelength over 2 pi, a / 10 on the
    # circle; the state is stable above the cutoff from there on
    assert close(thin.critical_thinness_load, thin.a_bar / 10, 1e-9)
    assert close(thin.critical_thinness_displacement, thin.a_bar / 10, 1e-9)
    thick = thinjkr.exact.solve(1.0, force=10.0, modes=12, thinness=0.5)
    assert (thick.stable_displacement, thick.stable_load) == (True, True)
    assert not any(m["resolved"] for m in thick.unstable_modes_load)
    d = run_json(cli, "exact", "solve", "--rho", "1", "--force", "10", "--modes", "12",
                 "--thinness", "0.5")["state"]["stability"]
    assert (d["stable_displacement"], d["stable_load"]) == (True, True)
    with pytest.raises(thinjkr.InvalidInput) as info:
        thinjkr.exact.solve(1.0, force=10.0, thinness=-1.0)
    assert "thinness" in str(info.value)


def test_models_lists_every_model(cli):
    names = [n for n, _ in thinjkr.models()]
    assert names[:4] == ELLIPSE and "conformal:8" in names and names[-2:] == ["exact", "layer"]
    out = subprocess.run([cli, "models"], check=True, capture_output=True, text=True).stdout
    assert [line.split()[0] for line in out.splitlines()] == names


@pytest.mark.parametrize("model", ["max", "energy", "conformal:3"])
def test_arrays_equal_loops_of_scalar_calls(model):
    rho = np.array([[0.5], [0.8], [0.95]])
    delta = np.array([-10.0, 0.5, 2.0, 5.0])
    many = thinjkr.solve(rho, delta=delta, model=model)
    assert many.shape == (3, 4)
    for i in range(3):
        for j in range(4):
            try:
                st = thinjkr.solve(float(rho[i, 0]), delta=float(delta[j]), model=model)
            except thinjkr.ThinJkrError as e:
                assert math.isnan(many.a_bar[i, j]) and many.error[i, j] == str(e)
                assert many.error_kind[i, j] == e.kind
                continue
            assert many.error[i, j] == ""
            for k in ("a_bar", "b_bar", "s", "delta_bar", "force_bar"):
                assert close(getattr(many, k)[i, j], getattr(st, k)), (k, i, j)
    # delta = 2 and 5 solve everywhere; -10 lies below the paper's model's
    # displacement-controlled pull-off (the energy closure stays stable
    # and elongates, and has states there)
    assert many.ok[:, 2:].all()
    if model == "max":
        assert not many.ok[:, 0].any()


def test_force_arrays_and_scalar_broadcast():
    many = thinjkr.solve(0.8, force=np.linspace(-1.0, 10.0, 7))
    for f, a in zip(np.linspace(-1.0, 10.0, 7), many.a_bar):
        assert close(a, thinjkr.solve(0.8, force=float(f)).a_bar)


@pytest.mark.parametrize(
    "call, cls, words",
    [
        (lambda: thinjkr.solve(1.5, delta=2.0), thinjkr.InvalidInput, "rho"),
        (lambda: thinjkr.solve(0.8, force=-100.0), thinjkr.InvalidInput, "force"),
        (lambda: thinjkr.solve(0.8, delta=2.0, force=1.0), thinjkr.InvalidInput, "exactly one"),
        (lambda: thinjkr.solve(0.8, delta=2.0, model="nosuch"), thinjkr.InvalidInput, "model"),
        (lambda: thinjkr.solve(0.8, delta=-10.0), thinjkr.NoState, "delta"),
        (lambda: thinjkr.curve(0.8, model="exact"), thinjkr.Unavailable, "curve"),
        (lambda: thinjkr.pull_off(0.8, model="energy", control="displacement"), thinjkr.NoState,
         "stays stable"),
        (lambda: thinjkr.exact.solve(0.8, force=-5.0), thinjkr.NoState, "below the pull-off"),
        # the energy closure's displacement fold near the smallest rho
        # supported: Newton on the fold condition does not converge there
        (lambda: thinjkr.pull_off(1e-8, model="energy", control="displacement"),
         thinjkr.NoConvergence, "no convergence"),
        (lambda: thinjkr.exact.pull_off(0.5, modes=4), thinjkr.Unresolved, "more modes"),
        (lambda: thinjkr.exact.pull_off(0.5, modes=100), thinjkr.InvalidInput, "modes"),
        (lambda: thinjkr.physical(r1=0.01, r2=0.01, theta_deg=60, h1=1e300, h2=1e-4, g1=1e6, g2=1e6,
                                  work_of_adhesion=0.05, force=0.0), thinjkr.InvalidInput, "m computed"),
    ],
)
def test_each_error_class_from_its_input(call, cls, words):
    with pytest.raises(cls) as info:
        call()
    assert words in str(info.value)
    assert isinstance(info.value, thinjkr.ThinJkrError)
    if cls is thinjkr.InvalidInput:
        assert isinstance(info.value, ValueError)


def test_pickling_round_trips():
    for obj in [thinjkr.solve(0.8, delta=2.0), thinjkr.pull_off(0.8, model="energy"),
                thinjkr.solve(0.8, delta=2.0, model="conformal:4"), thinjkr.exact.solve(0.8, force=10.0)]:
        back = pickle.loads(pickle.dumps(obj))
        assert back == obj and type(back) is type(obj)
    e = thinjkr.NoState("no contact state: x", "no_state", "no contact state: x; the whole")
    back = pickle.loads(pickle.dumps(e))
    assert type(back) is thinjkr.NoState and str(back) == str(e) and back.kind == "no_state"
    assert back.record == "no contact state: x; the whole"


def test_an_error_says_itself_in_300_characters_and_keeps_its_record():
    """Issue 72: an exception's message is at most 300 characters, as the
    command line's error is; the whole record (an exact request's every
    route, 2,563 characters at rho = 1e-300 before its floor) is its
    ``record``. A message that fits is its own record."""
    with pytest.raises(thinjkr.NoState) as info:
        thinjkr.exact.solve(1e-300, delta=2.0)
    e = info.value
    assert len(str(e)) <= 300 and str(e).endswith("(its .record: the whole)"), str(e)
    assert len(e.record) > 300 and e.record.startswith("no contact state: no exact state at delta = 2"), e.record
    with pytest.raises(thinjkr.InvalidInput) as info:
        thinjkr.solve(2.0, delta=2.0)
    assert info.value.record == str(info.value)


def test_state_reads_and_prints():
    st = thinjkr.solve(0.8, delta=2.0)
    assert close(st.s, st.b_bar / st.a_bar)
    text = repr(st)
    # the answer first, then at most two lines on how far to trust it
    # (issue 69); every field is an attribute and in to_dict()
    assert text.startswith("State(model='max', rho=0.8, a_bar=3.21") and "force_bar=8.20631)" in text
    assert len(text.splitlines()) <= 3 and "bc_error=2.7e-03" in text.splitlines()[1]
    assert "xi" in st.to_dict() and "xi=" not in text
    for other in [thinjkr.exact.pull_off(0.8), thinjkr.solve(0.8, force=0.0, model="conformal:8"),
                  thinjkr.pull_off(1.0, model="layer"), thinjkr.solve(0.3, force=0.0)]:
        lines = repr(other).splitlines()
        assert 1 <= len(lines) <= 3 and lines[0].startswith(type(other).__name__ + "(model="), lines
    assert st.to_dict()["delta_bar"] == 2.0
    with pytest.raises(AttributeError):
        st.nosuch


def test_threads_give_the_serial_results():
    rhos = [0.5 + 0.05 * k for k in range(10)]
    serial = [thinjkr.pull_off(r, model="energy").force_bar for r in rhos]
    with concurrent.futures.ThreadPoolExecutor(4) as pool:
        threaded = list(pool.map(lambda r: thinjkr.pull_off(r, model="energy").force_bar, rhos))
    assert threaded == serial


def test_curve_marks_its_folds():
    c = thinjkr.curve(0.8, points=100)
    assert len(c) == 100 and c.s.shape == (100,)
    kinds = [k for k, _ in c.folds]
    assert "load" in kinds
    load = dict(c.folds)["load"]
    assert close(load.force_bar, thinjkr.pull_off(0.8).force_bar, 1e-9)


def test_a_conformal_curve_has_the_pull_off_on_its_second_arm():
    c = thinjkr.curve(0.8, model="conformal:8", points=60)
    assert len(c) == 60 and set(c.arm.tolist()) == {0, 1}
    assert c.end and "pull-off arm" in c.end
    least = min(st.force_bar for k, st in c.folds if k == "load")
    po = thinjkr.pull_off(0.8, model="conformal:8")
    assert close(least, po.force_bar, 1e-9)
    assert c.bc_error.shape == (60,) and c.beyond_size_fold.dtype == bool


def test_physical_units():
    # rho = 1/3, coatings (h/L = 0.18) thinner than the layer in the plane
    # reaches: the command line's warnings, among them that (2)'s state is
    # not measured against the layer there
    with pytest.warns(thinjkr.ThinJkrWarning, match="not measured against the layer"):
        st = thinjkr.physical(r1=0.01, r2=0.01, theta_deg=60, h1=1e-5, h2=1e-5, g1=1e6, g2=1e6,
                              work_of_adhesion=0.05, force=0.0)
    assert st.a > 0 and st.force == pytest.approx(0.0, abs=1e-12)
    # a state at a force, no model named: the table of defaults' energy
    assert abs(st.state.force_bar) < 1e-9 and st.state.model == "energy" and st.model == "energy"
    assert st.chosen_because.startswith("no model named: energy answers a state at a given force")
    # ten times thicker (h/L = 0.58), which the layer in the plane reaches:
    # its state, with energy's beside it (issue 71, item 4)
    thick = thinjkr.physical(r1=0.01, r2=0.01, theta_deg=60, h1=1e-4, h2=1e-4, g1=1e6, g2=1e6,
                             work_of_adhesion=0.05, force=0.0)
    assert thick.model == "layer" and thick.thin_layer.model == "energy"
    assert thick.thin_layer.relative_error > 0.5 and thick.a < thick.thin_layer.si["a"]


def test_states_index_iterate_and_export():
    """States indexes like its arrays, iterates over its points, and gives
    JSON-ready dicts and a long-format DataFrame: each path holds the same
    numbers as the arrays and as scalar calls."""
    rho = np.array([[0.8], [0.5]])
    S = thinjkr.solve(rho, delta=np.array([-10.0, 1.0, 2.0]))  # δ̄ = −10: no state
    assert S.shape == (2, 3) and len(S) == 6
    assert not S.ok[:, 0].any() and S.ok[:, 1:].all()
    solved = S[S.ok]
    assert isinstance(solved, thinjkr.States) and solved.shape == (4,)
    assert np.array_equal(solved.a_bar, S.a_bar[S.ok])
    one = S[1, 2]
    assert isinstance(one, thinjkr.State)
    ref = thinjkr.solve(0.5, delta=2.0)
    assert close(one.a_bar, ref.a_bar) and close(one.s, ref.s) and one.error == ""
    assert S[0, 1:].shape == (2,)
    points = list(S)
    assert len(points) == 6
    assert [p.rho for p in points] == [0.8, 0.8, 0.8, 0.5, 0.5, 0.5]
    assert points[0].error_kind != "" and math.isnan(points[0].a_bar)
    assert close(points[4].a_bar, S.a_bar[1, 1])
    # JSON-ready: the dicts survive json.dumps and read back to the same numbers
    d = json.loads(json.dumps(S.to_dict()))
    assert d["model"] == "max" and d["a_bar"][1][2] == S.a_bar[1, 2]
    assert json.loads(json.dumps(one.to_dict()))["a_bar"] == one.a_bar
    html = S._repr_html_()
    assert "<table>" in html and "4" in html
    pd = pytest.importorskip("pandas")
    df = S.to_pandas()
    assert isinstance(df, pd.DataFrame) and len(df) == 6
    assert list(df["i0"]) == [0, 0, 0, 1, 1, 1] and list(df["i1"]) == [0, 1, 2, 0, 1, 2]
    assert df["a_bar"].iloc[5] == S.a_bar[1, 2]
    assert df["error"].iloc[0] != "" and df["error"].iloc[5] == ""


def test_states_and_curves_with_arrays_give_json_ready_dicts():
    """A state holding arrays (the exact solver's contour) and a curve give
    dicts json.dumps takes, with the same numbers."""
    ex = thinjkr.exact.solve(0.8, force=0.0, points=16)
    assert isinstance(ex.x, np.ndarray)
    d = json.loads(json.dumps(ex.to_dict()))
    assert d["x"] == ex.x.tolist() and d["force_bar"] == ex.force_bar
    cv = thinjkr.curve(0.8, points=20)
    d = json.loads(json.dumps(cv.to_dict()))
    assert d["a_bar"] == cv.a_bar.tolist() and len(d["states"]) == len(cv) == 20
    assert [f["kind"] for f in d["folds"]] == [k for k, _ in cv.folds]
    assert "Curve" in cv._repr_html_()


@pytest.mark.parametrize("model", ["max", "conformal:2"])
def test_pull_off_and_zero_force_take_arrays(model):
    """pull_off and zero_force broadcast over an array of rho like solve:
    a States of its shape whose points equal the scalar calls, NaN with the
    reason where a point has none; a model that does not exist raises."""
    rho = np.array([[0.9, 0.8], [0.5, 2.0]])  # rho = 2 is out of range
    for call in (thinjkr.pull_off, thinjkr.zero_force):
        many = call(rho, model=model)
        assert isinstance(many, thinjkr.States) and many.shape == (2, 2)
        assert many.ok.tolist() == [[True, True], [True, False]]
        assert "rho" in many.error[1, 1] and math.isnan(many.force_bar[1, 1])
        for i in np.ndindex(2, 2):
            if many.ok[i]:
                one = call(float(rho[i]), model=model)
                assert close(many.force_bar[i], one.force_bar) and close(many.s[i], one.s)
    with pytest.raises(thinjkr.InvalidInput):
        thinjkr.pull_off(np.array([0.8, 0.9]), model="nosuch")


def test_physical_takes_a_model_and_warns_as_the_command_line(cli):
    """physical() answers through the model layer with any model, as the
    command line's physical --model does (the same numbers), and issues the
    command line's warnings as ThinJkrWarning, which can be made errors."""
    import warnings

    # theta = 60 degrees: rho = 1/3, below the paper's range, within conformal:K's
    contact, args = examples_contact(60, 1e-4)
    for model in ["max", "energy", "conformal:8", "exact"]:
        with warnings.catch_warnings(record=True) as w:
            warnings.simplefilter("always")
            st = thinjkr.physical(**contact, model=model)
        d = run_json(cli, *args, "--model", model)
        assert close(st.force, d["si"]["force"]) and close(st.a, d["si"]["a"]), model
        assert [str(x.message) for x in w if x.category is thinjkr.ThinJkrWarning] == d["warnings"]
        # the warnings are the model's: the paper's range 0.8 <= rho <= 1 is
        # the ellipse models' (issue 33 item 1), not conformal:K's (whose
        # own doubt is its boundary defect) nor the exact solution's
        ranged = any("below the paper's stated range" in m for m in d["warnings"])
        assert ranged == (model in ("max", "energy")), (model, d["warnings"])
        assert any("not thin" in m for m in d["warnings"]), model
        # a contour state's shape owes more than 1 % of a to undulations
        # shorter than these coatings' cutoff (docs/exact.md, "The shape's
        # unresolved part"); an ellipse has no such part
        shaped = any(m.startswith("the contact's shape:") for m in d["warnings"])
        assert shaped == (model in ("conformal:8", "exact")), (model, d["warnings"])
    # at 30 degrees (rho = 0.072) the two closures differ by tens of per cent
    steep = {**contact, "theta_deg": 30}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", thinjkr.ThinJkrWarning)
        assert not close(thinjkr.physical(**steep, model="max").force,
                         thinjkr.physical(**steep, model="energy").force, rel=0.1)
    # (max warns here: rho is below the paper's range; the default, the
    # layer in the plane, answers these coatings without a warning)
    with warnings.catch_warnings():
        warnings.simplefilter("error", thinjkr.ThinJkrWarning)
        with pytest.raises(thinjkr.ThinJkrWarning):
            thinjkr.physical(**contact, model="max")


def test_physical_without_a_model_is_the_command_lines_default(cli):
    """Issue 32 item 5: physical() without a model asks the table of
    defaults, as the command line without --model does: at theta = 60 deg
    (rho = 1/3) with coatings the layer in the plane does not reach (h =
    20 um, h/L = 0.12) the exact pull-off, with its reason, max beside it (the two
    differ by 9 %) and how far (2) is off the layer at rho = 1 (issue 71);
    the same numbers and words as the command line."""
    import warnings

    contact, args = examples_contact(60, 2e-5)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", thinjkr.ThinJkrWarning)
        st = thinjkr.physical(**contact)
    d = run_json(cli, *args)
    assert st.model == "exact" and st.state.model == "exact" and d["model"] == "exact"
    assert st.chosen_because == d["chosen_because"]
    assert "no model is within 0.5 %" in st.chosen_because
    assert close(st.force, d["si"]["force"], 1e-9)
    assert st.paper_model.model == "max"
    assert close(st.paper_model.force_bar, d["paper_model"]["force_bar"], 1e-12)
    assert abs(st.paper_model.force_bar / st.state.force_bar - 1) > 0.01
    assert st.warnings == d["warnings"]
    assert any(w.startswith("(2) is ") and "best estimate of the pull-off force" in w for w in st.warnings)
    # the estimate as data too, the command line's: at 60 deg rho = 1's ratio
    assert st.layer_estimate == d["layer_estimate"] and st.layer_estimate["by"] == "ratio"


def test_physical_without_a_model_answers_with_the_layer_in_the_plane(cli):
    """Issue 71: below 90 degrees, where the layer in the plane reaches the
    coatings (h/L = 0.58 at 60 degrees), physical() without a model answers
    the pull-off with it: by the sharp edge, its force within 1e-3 (the
    issue's done-when) on a ladder of three rungs, and (2)'s exact pull-off
    beside it, tens of per cent off; its repr says how far to trust it.
    (The command line's answer is held to the library's in Rust.)"""
    contact = dict(r1=0.01, r2=0.01, theta_deg=60, h1=1e-4, h2=1e-4, g1=1e6, g2=1e6, work_of_adhesion=0.05)
    st = thinjkr.physical(**contact)
    assert st.model == "layer" and st.state.model == "layer"
    assert st.chosen_because.startswith("no model named: at rho < 1 the layer of finite thickness")
    assert st.state.method == "sharp_edge" and len(st.state.rungs) == 3
    assert 0 < st.state.force_error <= 1e-3
    assert "force_error=" in repr(st.state) and "method='sharp_edge'" in repr(st.state)
    assert st.force < 0 and st.state.force_bar < 0
    t = st.thin_layer
    assert t.model == "exact" and t.relative_error > 0.2
    # the repr: the layer's force first, then how far to trust it, then
    # (2)'s beside it
    lines = repr(st).splitlines()
    assert lines[0].startswith(f"Physical(model='layer', force={st.force:.6g} N")
    assert "force_error=" in lines[1] and "method='sharp_edge'" in lines[1]
    assert lines[2] == f"  (2): model='exact', force={t.si['force']:.6g} N, {100 * t.relative_error:.3g} % off"
    assert abs(st.force) < abs(t.si["force"])


def test_physical_at_ninety_degrees_answers_with_the_layer_and_2_beside_it(cli):
    """Issue 70: at rho = 1 without a model, physical() answers with the
    layer of finite thickness where (2) is more than 0.5 % off, with (2)'s
    answer under thin_layer; the same numbers as the command line, also
    with nu1 = nu2 = 0.45."""
    contact, args = examples_contact(90, 1e-4)
    for nu, extra in [(0.5, []), (0.45, ["--nu1", "0.45", "--nu2", "0.45"])]:
        st = thinjkr.physical(**contact, nu1=nu, nu2=nu)
        d = run_json(cli, *args, *extra)
        assert st.model == "layer" and d["model"] == "layer"
        assert close(st.force, d["si"]["force"], 1e-9)
        t = st.thin_layer
        assert t.model == d["thin_layer"]["model"] and close(t.relative_error, d["thin_layer"]["relative_error"], 1e-9)
        # (2)'s pull-off is -3 pi R dgamma = -4.712389e-3 N, the layer's smaller in size
        assert close(t.si["force"], -3 * np.pi * 0.01 * 0.05, 1e-6)
        assert abs(st.force) < abs(t.si["force"]) and t.relative_error > 0.005
        assert st.state.coatings[0]["nu"] == nu


def test_every_function_of_rho_takes_arrays_and_curves_come_as_a_list():
    """Issue 33 item 4: a float rho with an array of forces gives States
    (the Fig. 7 sweep); the exact solver's functions broadcast like the
    others, point by point equal to the scalar calls; curve over an array
    of rho is a list of curves, one per rho, equal to the scalar curves."""
    fig7 = thinjkr.solve(0.8, force=np.linspace(-2.0, 10.0, 4))
    assert isinstance(fig7, thinjkr.States) and fig7.shape == (4,) and fig7.ok.all()
    assert close(fig7.s[3], thinjkr.solve(0.8, force=10.0).s)
    rho = np.array([0.9, 1.0])
    for many, one in [
        (thinjkr.exact.zero_force(rho), lambda r: thinjkr.exact.zero_force(r)),
        (thinjkr.exact.solve(rho, force=[1.0, 2.0]), None),
        (thinjkr.exact.pull_off(rho), lambda r: thinjkr.exact.pull_off(r)),
    ]:
        assert isinstance(many, thinjkr.States) and many.shape == (2,) and many.ok.all()
        assert many.model == "exact"
        for i, r in enumerate(rho):
            st = one(float(r)) if one else thinjkr.exact.solve(float(r), force=[1.0, 2.0][i])
            assert close(many.a_bar[i], st.a_bar) and close(many.force_bar[i], st.force_bar)
    curves = thinjkr.curve([0.8, 0.9], points=20)
    assert isinstance(curves, list) and len(curves) == 2
    for cv, r in zip(curves, (0.8, 0.9)):
        assert cv.to_dict() == thinjkr.curve(r, points=20).to_dict()
    with pytest.raises(thinjkr.InvalidInput, match="delta_start"):
        thinjkr.curve(0.8, delta_start=[10.0, 20.0])


def test_the_ellipse_models_flags_are_warnings_as_on_the_command_line(cli):
    """Issue 33 item 7: a state of a model of the ellipse below the paper's
    range (rho < 0.8) or beyond the contact-size fold is answered with a
    ThinJkrWarning carrying the command line's words (its brackets, and the
    JSON's `warnings`), once per call; silenced or made an error the usual
    way; an array call marks the points (States.warning, .doubtful), and a
    batch row says the same. Within the range nothing warns."""
    import warnings

    with pytest.warns(thinjkr.ThinJkrWarning, match=r"rho < 0\.8: outside the paper's stated range"):
        st = thinjkr.solve(0.5, force=0.0)
    assert st.warnings == ["rho < 0.8: outside the paper's stated range"]
    line = subprocess.run([cli, "solve", "--rho", "0.5", "--force", "0"], capture_output=True, text=True).stdout
    assert "[rho < 0.8: outside the paper's stated range]" in line
    assert run_json(cli, "solve", "--rho", "0.5", "--force", "0")["state"]["warnings"] == st.warnings
    # beyond the contact-size fold: the paper's model at rho = 0.3 and a
    # negative approach (the state on its branch there lies past the fold)
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        st = thinjkr.solve(0.3, delta=-0.5)
    words = [str(x.message) for x in w if x.category is thinjkr.ThinJkrWarning]
    assert st.beyond_size_fold and "beyond the contact-size fold" in words
    with warnings.catch_warnings():
        warnings.simplefilter("error", thinjkr.ThinJkrWarning)
        thinjkr.solve(0.9, force=0.0)  # within the range: nothing
        with pytest.raises(thinjkr.ThinJkrWarning):
            thinjkr.zero_force(0.5, model="energy")
    with pytest.warns(thinjkr.ThinJkrWarning, match=r"1 of 2 states carry warnings"):
        many = thinjkr.solve([0.5, 0.9], force=0.0)
    assert list(many.doubtful) == [True, False] and "outside the paper's stated range" in many.warning[0]
    rows = subprocess.run([cli, "batch"], input="rho,control,value\n0.5,force,0\n0.9,force,0\n",
                          capture_output=True, text=True).stdout.splitlines()
    assert rows[1].endswith('"rho < 0.8: outside the paper\'s stated range"') and rows[2].endswith(",")


def test_the_layer_takes_its_coatings_and_answers_every_verb():
    # at rho = 1 the axisymmetric layer (instant): the coatings reach it
    thick = thinjkr.pull_off(1.0, model="layer", thinness=1.0)
    thin = thinjkr.pull_off(1.0, model="layer", thinness=0.3)
    assert thick.force_bar != thin.force_bar
    softer = thinjkr.pull_off(1.0, model="layer", thinness=1.0, nu=0.45)
    assert softer.force_bar != thick.force_bar
    # under displacement control the pull-off is the smaller contact
    least = thinjkr.pull_off(1.0, model="layer", thinness=1.0, control="displacement")
    assert least.a_bar < thick.a_bar and least.delta_bar < thick.delta_bar
    # each neutral under its own control, as the command line says
    assert (thick.stability_load, thick.stability_displacement) == ("neutral", "stable")
    assert (least.stability_load, least.stability_displacement) == ("unstable", "neutral")
    # the curve passes both pull-offs, and a state at one of its sizes is
    # the curve's
    c = thinjkr.curve(1.0, model="layer", thinness=1.0, points=20)
    assert len(c) == 20 and [k for k, _ in c.folds] == ["load", "displacement"]
    assert c.folds[0][1].force_bar == pytest.approx(thick.force_bar, rel=1e-12)
    assert not c.beyond_size_fold.any()
    s = thinjkr.solve(1.0, a=float(c.a_bar[5]), model="layer", thinness=1.0)
    assert s.force_bar == pytest.approx(c.force_bar[5], rel=1e-12)
    assert thinjkr.zero_force(1.0, model="layer", thinness=1.0).force_bar == pytest.approx(0.0, abs=1e-9)
    # coatings are one number for the call, and for the layer only
    with pytest.raises(thinjkr.InvalidInput, match="one number"):
        thinjkr.solve(1.0, force=1.0, model="layer", thinness=[0.3, 1.0])
    with pytest.raises(thinjkr.InvalidInput, match="for the model layer"):
        thinjkr.solve(0.8, force=1.0, model="max", nu=0.45)


def test_the_layer_in_the_plane_answers_a_size_with_its_slopes():
    # rho = 0.8, h/L = 1 (5 s): between the two pull-offs' sizes (1.0648 and
    # 0.2591), so unstable under load control and stable under displacement
    st = thinjkr.solve(0.8, a=1.0, model="layer", thinness=1.0)
    s = st.to_dict()
    assert (s["held"], s["method"]) == ("size", "sharp_edge")
    assert s["a_bar"] == pytest.approx(1.0, rel=1e-12)
    force_slope, delta_slope = s["slopes"]
    assert force_slope < 0.0 < delta_slope
    # the verdicts the command line prints, in the repr's second line
    assert (s["stability_load"], s["stability_displacement"]) == ("unstable", "stable")
    assert "stability_load='unstable', stability_displacement='stable'" in repr(st).splitlines()[1]


def test_physical_leads_with_the_layer_s_estimate_where_it_is_nearer_than_2(cli):
    """Issue 71: thin coatings near 90 degrees (83.63 deg, h = 15 um, h/L =
    0.27), which the layer in the plane does not reach: (2) answers, and the
    layer's pull-off estimated by the line tension, within 0.21 % where (2)
    is 19.7 % off, leads the repr as it leads the command line's text; the
    estimate is the command line's JSON's."""
    import warnings

    contact, args = examples_contact(83.63, 1.5e-5)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", thinjkr.ThinJkrWarning)
        st = thinjkr.physical(**contact)
    d = run_json(cli, *args)
    e = st.layer_estimate
    assert e == d["layer_estimate"]
    assert e["by"] == "line_tension" and e["leads"] is True and e["within"] < e["thin_layer_error"]
    lines = repr(st).splitlines()
    assert lines[0] == (f"Physical(force={e['force']:.6g} N: the layer of finite thickness's pull-off, "
                        f"estimated within {100 * e['within']:.2g} % by line_tension)"), lines[0]
    assert lines[1] == f"  (2): model='conformal:8', force={st.force:.6g} N, {100 * e['thin_layer_error']:.3g} % off"
    assert lines[2].startswith("  warning: (2) is ")


def test_a_state_below_the_plane_s_reach_leads_with_the_line_tension_s_state(cli):
    """Issue 71: the same coatings at zero force. The layer's state
    estimated by the line tension at the shifted approach, within 6.0 %
    where (2) is 19.7 % off, leads the repr with its size, approach and
    force, and (2)'s state is beside it; the estimate is the command line's
    JSON's."""
    import warnings

    contact, args = examples_contact(83.63, 1.5e-5)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", thinjkr.ThinJkrWarning)
        st = thinjkr.physical(**contact, force=0.0)
    d = run_json(cli, *args, "--force", "0")
    e = st.layer_estimate
    assert e == d["layer_estimate"]
    assert e["by"] == "shifted_line_tension" and e["leads"] is True and e["within"] < e["thin_layer_error"]
    s = e["state"]
    assert s["force"] == e["force"] and 0.0 < s["b"] < s["a"]
    lines = repr(st).splitlines()
    assert lines[0] == (f"Physical(a={s['a']:.6g} m, delta={s['delta']:.6g} m, force={e['force']:.6g} N: "
                        f"the layer of finite thickness's state, estimated within {100 * e['within']:.2g} % "
                        f"by shifted_line_tension)"), lines[0]
    assert lines[1] == (f"  (2): model={st.model!r}, a={st.a:.6g} m, delta={st.delta:.6g} m, force={st.force:.6g} N, "
                        f"{100 * e['thin_layer_error']:.3g} % off"), lines[1]
    assert lines[2].startswith("  warning: (2)'s state is ")

