"""Bad input from Python gets the command line's typed answer: a NaN or an
infinite control is InvalidInput (not NoState), a count must be a whole
number in its range (no silent rounding, no OverflowError), a bool, a string
or a masked array is not a number (no silent rho = 1, no dropped mask), and
an unknown model is named with the models there are."""

import json
import math
import warnings

import numpy as np

import pytest

import thinjkr
from thinjkr import InvalidInput


@pytest.mark.parametrize("value", [float("nan"), math.inf, -math.inf])
def test_a_control_that_is_not_finite_is_invalid_input_for_the_exact_solver(value):
    with pytest.raises(InvalidInput, match="force"):
        thinjkr.exact.solve(0.8, force=value)
    with pytest.raises(InvalidInput, match="delta"):
        thinjkr.exact.solve(0.8, delta=value)
    with pytest.raises(InvalidInput, match="force"):
        thinjkr.solve(0.8, force=value, model="exact")


@pytest.mark.parametrize("model", ["max", "conformal:4"])
@pytest.mark.parametrize("value", [float("nan"), math.inf])
def test_a_control_that_is_not_finite_is_invalid_input_for_every_model(model, value):
    with pytest.raises(InvalidInput):
        thinjkr.solve(0.8, force=value, model=model)


@pytest.mark.parametrize("points", [2.5, -1, True, 0, 10**6, "7", float("nan")])
def test_a_count_must_be_a_whole_number_in_its_range(points):
    with pytest.raises(InvalidInput, match="points"):
        thinjkr.curve(0.8, points=points)


def test_a_whole_float_count_is_accepted():
    assert len(thinjkr.curve(0.8, points=20.0).states) == 20


@pytest.mark.parametrize("modes", [2.5, 0, -3, 97, False])
def test_the_exact_solvers_modes_are_a_whole_number_in_range(modes):
    with pytest.raises(InvalidInput, match="modes"):
        thinjkr.exact.zero_force(0.8, modes=modes)


def test_an_unknown_model_names_the_models_there_are():
    with pytest.raises(InvalidInput) as e:
        thinjkr.solve(0.8, force=0.0, model="foo")
    text = str(e.value)
    assert "foo" in text and "conformal:K" in text and "NaN" not in text


@pytest.mark.parametrize("rho", [True, np.bool_(True), np.array([True, False]), "0.8",
                                 np.ma.masked_array([0.8, 0.9], mask=[False, True])])
def test_rho_must_be_numbers_not_bools_strings_or_masked_arrays(rho):
    with pytest.raises(InvalidInput, match="rho"):
        thinjkr.solve(rho, force=0.0)
    if np.ndim(rho) == 0:
        with pytest.raises(InvalidInput, match="rho"):
            thinjkr.pull_off(rho)


def test_a_control_must_be_numbers_too():
    with pytest.raises(InvalidInput, match="force"):
        thinjkr.solve(0.8, force=True)
    with pytest.raises(InvalidInput, match="delta"):
        thinjkr.exact.solve(0.8, delta=False)
    # integers and integer arrays are numbers
    assert thinjkr.solve(1, force=0).rho == 1.0
    assert thinjkr.solve(np.array([1, 1]), force=0).a_bar.shape == (2,)


def test_a_rayon_num_threads_beyond_the_cap_is_capped_with_a_warning():
    """The array calls run on the solver's own pool: RAYON_NUM_THREADS far
    above what the machine should start is capped (4 per core) with a
    RuntimeWarning, where rayon's global pool would panic, and the answers
    are those of a normal run."""
    import os
    import subprocess
    import sys

    code = (
        "import json, warnings, numpy as np, thinjkr\n"
        "with warnings.catch_warnings(record=True) as w:\n"
        "    warnings.simplefilter('always')\n"
        "    S = thinjkr.solve(np.array([0.8, 0.9]), delta=2.0)\n"
        "print(json.dumps({'a': S.a_bar.tolist(), 'warnings': [str(x.message) for x in w],\n"
        "                  'kinds': [x.category.__name__ for x in w]}))\n"
    )
    env = {**os.environ, "RAYON_NUM_THREADS": "1000000"}
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    got = json.loads(out.stdout)
    assert any("RAYON_NUM_THREADS = 1000000 is more than" in m for m in got["warnings"]), got
    assert "RuntimeWarning" in got["kinds"]
    normal = thinjkr.solve(np.array([0.8, 0.9]), delta=2.0)
    assert got["a"] == normal.a_bar.tolist()


def _interrupted_one_second_in(code: str, timeout: float):
    """Run `code` in a child Python that prints 'started' before its long
    call, send it SIGINT one second later, and return its output lines once
    it has exited (status 0) within `timeout` seconds of the signal."""
    import signal
    import subprocess
    import sys
    import time

    # Python's own SIGINT handler in the child, whatever this process
    # inherited: a shell that starts a job in the background without job
    # control ignores SIGINT for it, and a Python started with SIGINT ignored
    # installs no KeyboardInterrupt handler (the test asks how thinjkr answers
    # Python's handler, not how the child was started)
    code = "import signal\nsignal.signal(signal.SIGINT, signal.default_int_handler)\n" + code
    child = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        assert child.stdout.readline().strip() == "started"
        time.sleep(1.0)
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=timeout)
    finally:
        if child.poll() is None:
            child.kill()
            child.communicate()
    assert child.returncode == 0, err
    return out.split("\n")


def test_ctrl_c_interrupts_a_long_array_call_and_the_next_call_works():
    """Ctrl-C (SIGINT) one second into an array call that would run for a
    minute (10 million energy-model states) raises KeyboardInterrupt
    between chunks, long before the call would end (the child is given 30
    s in all); no partial result is returned, and the next call answers."""
    code = (
        "import numpy as np, thinjkr\n"
        "n = 10_000_000\n"
        "rho, delta = np.full(n, 0.8), np.linspace(0.5, 6.0, n)\n"
        "thinjkr.solve(0.8, delta=2.0)\n"
        "print('started', flush=True)\n"
        "try:\n"
        "    S = thinjkr.solve(rho, delta=delta, model='energy')\n"
        "    print('finished', flush=True)\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted', flush=True)\n"
        "print('next', repr(thinjkr.solve(0.8, delta=2.0).a_bar), flush=True)\n"
    )
    lines = _interrupted_one_second_in(code, timeout=30)
    assert lines[0] == "interrupted", lines
    assert lines[1] == "next " + repr(thinjkr.solve(0.8, delta=2.0).a_bar), lines


def test_ctrl_c_interrupts_one_slow_exact_solve_and_the_next_call_works():
    """Issue 33, item 6: Ctrl-C one second into a single exact solve that
    runs for more than ten seconds (rho = 0.3, F = 10: every start and
    every truncation up to 96 modes is tried, then the fold in rho of the
    family is located and the arms of larger contacts are followed; about
    40 s on the release build, longer under load) raises
    KeyboardInterrupt inside that solve's Newton iterations: the child
    answers within 8 s of the signal, less than half the call's own time;
    no partial result is returned, and the next call answers."""
    code = (
        "import thinjkr\n"
        "thinjkr.solve(0.8, delta=2.0)\n"
        "print('started', flush=True)\n"
        "try:\n"
        "    st = thinjkr.exact.solve(0.3, force=10.0)\n"
        "    print('finished', flush=True)\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted', flush=True)\n"
        "except thinjkr.ThinJkrError as e:\n"
        "    print('ended', e.kind, flush=True)\n"
        "print('next', repr(thinjkr.exact.solve(0.8, force=0.0).a_bar), flush=True)\n"
    )
    lines = _interrupted_one_second_in(code, timeout=8)
    assert lines[0] == "interrupted", lines
    assert lines[1] == "next " + repr(thinjkr.exact.solve(0.8, force=0.0).a_bar), lines


def test_a_doubtful_state_is_answered_with_a_warning_not_in_silence():
    """Issue 31, item 2: conformal:8 at rho = 0.515, F = 10 is 3.4 % off the
    exact state (its closure misses (3)2 by 0.21); the command line prints a
    warning, and Python issues it as a ThinJkrWarning, with the state still
    answered (its `warnings` say why). A state near the exact one warns of
    nothing; an array call warns once, counting the doubtful points."""
    with pytest.warns(thinjkr.ThinJkrWarning, match=r"misses the boundary condition \(3\)2 by up to 0\.20667"):
        st = thinjkr.solve(0.515, force=10.0, model="conformal:8")
    assert st.bc_defect > 0.1 and st.warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error", thinjkr.ThinJkrWarning)
        good = thinjkr.solve(0.8, force=0.0, model="conformal:8")
    assert "warnings" not in good.to_dict()
    # conformal:2's displacement-controlled pull-off misses (3)2 by 0.29 and
    # 0.60 at rho = 0.5 and 0.3: doubtful at both points, answered with one
    # warning
    with pytest.warns(thinjkr.ThinJkrWarning, match=r"2 of 2 states carry warnings"):
        po = thinjkr.pull_off([0.5, 0.3], model="conformal:2", control="displacement")
    assert po.doubtful.all() and all("(3)2" in w for w in po.warning)
    # conformal:8's (issue 31, item 1: it moved with K and missed (3)2 by
    # 0.2) is no pull-off: its branch is already unstable under displacement
    # control to modes above the short-wave cutoff, and the reason names them
    many = thinjkr.pull_off([0.9, 0.5], model="conformal:8", control="displacement")
    assert np.isnan(many.force_bar).all()
    assert all("no displacement-controlled pull-off" in e and "cos 8θ" in e for e in many.error)
    # an array of solve: the doubtful point is marked and says why, the rest not
    with pytest.warns(thinjkr.ThinJkrWarning, match=r"1 of 2 states carry warnings"):
        many = thinjkr.solve([0.515, 0.8], force=[10.0, 0.0], model="conformal:8")
    assert list(many.doubtful) == [True, False]
    assert "by up to 0.20667" in many.warning[0] and many.warning[1] == ""
    assert many[0].warning == many.warning[0]
    assert "warning" in many.to_pandas().columns if _has_pandas() else True
    # pull-offs whose defect lies under conformal:8's line (0.0031,
    # derive/families/conformal.toml): 1e-4 at rho = 0.8 and 8e-4 at 0.7
    # (at 0.5 its 0.012 is above the line: warned, though 0.11 % off)
    with warnings.catch_warnings():
        warnings.simplefilter("error", thinjkr.ThinJkrWarning)
        thinjkr.pull_off([0.8, 0.7], model="conformal:8")


def _has_pandas():
    try:
        import pandas  # noqa: F401
        return True
    except ImportError:
        return False


def test_an_exact_answer_has_the_same_shape_whichever_way_it_is_asked():
    """Issue 33, item 8: pull_off(rho, model="exact") names its model and
    carries its contour, and thinjkr.exact.pull_off is a PullOff (control
    "load") like it, with the same numbers."""
    a = thinjkr.pull_off(0.9, model="exact")
    b = thinjkr.exact.pull_off(0.9)
    assert isinstance(a, thinjkr.PullOff) and isinstance(b, thinjkr.PullOff)
    assert a.model == b.model == "exact"
    assert a.control == b.control == "load"
    assert a.force_bar == b.force_bar and a.a_bar == b.a_bar
    assert len(a.x) == len(a.y) == 256 and np.allclose(a.x, b.x)
    st = thinjkr.solve(0.9, force=0.0, model="exact")
    assert st.model == "exact" and len(st.x) == 256


def test_the_exact_pull_off_at_rho_0_3_answers_with_its_default_escalation():
    """Issue 33, item 3: exact.pull_off(0.3) raised NoState after 5.5 s (the
    escalation stopped at 16 modes, too few to follow a contour 11 % off the
    ellipse) while modes=48 answered; by default it now escalates to the
    truncation that converges (80 modes, boundary error below 1e-9) and
    answers the value modes=48 gives (-2.42586, found independently)."""
    po = thinjkr.exact.pull_off(0.3)
    assert abs(po.force_bar - (-2.42586)) < 1e-5, po.force_bar
    assert po.bc_error <= 1e-9
    forty_eight = thinjkr.exact.pull_off(0.3, modes=48)
    assert abs(po.force_bar - forty_eight.force_bar) < 1e-8
    # its shape's part in undulations shorter than the cutoff (docs/exact.md,
    # "The shape's unresolved part"): below 0.01 % of a with h/L = 0.1, the
    # default; 3.46 % in mode 6 with h/L = 0.5, where the shape is unresolved
    assert po.shape["unresolved"] is False and po.shape["amplitude"] < 1e-4
    assert not po.to_dict().get("warnings")
    # no coating makes it a contact (2) resolves (docs/exact.md, "Coatings
    # for which a state is resolved and stable"): below h/L = 0.353 it is
    # unstable to n = 6, from there on its undulations from n = 6 on pass 1 %
    assert po.coatings == {"load": None, "displacement": None}
    assert po.shape["critical_mode"] == 6 and abs(po.shape["critical_thinness"] - 0.353) < 5e-4
    with pytest.warns(thinjkr.ThinJkrWarning, match=r"the contact's shape: .* up to 3\.46 % of a"):
        thick = thinjkr.exact.pull_off(0.3, thinness=0.5)
    assert thick.shape["unresolved"] is True and thick.shape["mode"] == 6
    assert abs(thick.shape["amplitude"] - 0.0346) < 5e-5
    # the same warning per point in the arrays, the point marked doubtful
    with pytest.warns(thinjkr.ThinJkrWarning, match=r"1 of 1 states carry warnings"):
        S = thinjkr.exact.pull_off([0.3], thinness=0.5)
    assert S.doubtful[0] and S.warning[0] == thick.warnings[0]


def test_the_exact_model_s_pull_offs_warn_where_their_shape_is_unresolved():
    """The model layer judges an exact state with the default thinness
    h/L = 0.1 (docs/exact.md, "The shape's unresolved part"): the pull-off
    at rho = 0.05 has 4.35 % of a in undulations shorter than the cutoff
    (n = 18) and says so, in its warnings and per point in the arrays; the
    one at rho = 0.8 has less than 0.01 % and does not."""
    with pytest.warns(thinjkr.ThinJkrWarning, match=r"1 of 2 states carry warnings"):
        S = thinjkr.pull_off([0.05, 0.8], model="exact")
    assert list(S.doubtful) == [True, False]
    assert S.warning[0].startswith("the contact's shape:") and "n = 18" in S.warning[0]
    assert S.warning[1] == ""


def test_an_exact_sweep_says_per_point_how_each_state_was_found():
    """Issue 33, item 2: in the Fig. 7 sweep of the exact solver the state at
    F = -2.4 lies past the fold of the mode-6 band (3.7 % off the ellipse,
    route past_fold) between near-elliptic ones; the arrays say so per
    point (route, departure), as the scalar result does. Models of the
    ellipse have no route ('') and no departure (NaN)."""
    S = thinjkr.solve(0.8, force=[-2.4, 0.0], model="exact")
    one = thinjkr.solve(0.8, force=-2.4, model="exact")
    assert list(S.route) == [one.route, thinjkr.solve(0.8, force=0.0, model="exact").route]
    assert S.route[0] == "past_fold", S.route
    assert S.departure[0] == one.deviation_from_ellipse and S.departure[0] > 3 * S.departure[1]
    M = thinjkr.solve(0.8, force=[-2.4, 0.0])
    assert list(M.route) == ["", ""] and np.isnan(M.departure).all()
    assert "route" in S.to_pandas().columns if _has_pandas() else True
