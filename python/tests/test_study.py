"""Issue 71, item 6: a study over crossing angle, coating thickness and
load is one call, mapped by any concurrent.futures.Executor: serial, a
thread pool, a process pool (CI), and a Dask cluster's executor (the slow
tier, where `distributed` is installed: .ci/slow installs the `dask`
extra)."""

import concurrent.futures as cf
import math
import multiprocessing as mp

import numpy as np
import pytest

import thinjkr

# coatings thin enough that no point needs the grid solver (h/L about 0.06
# to 0.12): the exact pull-off at 60 degrees, the axisymmetric layer at 90,
# energy at zero force; -1 N is below every pull-off of these contacts
CONTACT = dict(r1=0.01, r2=0.01, g1=1e6, g2=1e6, work_of_adhesion=0.05)
GRID = dict(theta_deg=[60, 90], h=[1e-5, 2e-5], force=[None, 0.0, -1.0])


def same(a, b):
    assert len(a) == len(b) == 12
    for key in ("theta_deg", "h", "load", "force", "a", "b", "delta", "estimate", "estimate_within", "estimate_a",
                "estimate_delta"):
        x, y = getattr(a, key), getattr(b, key)
        assert np.array_equal(np.isnan(x), np.isnan(y)) and np.allclose(x[~np.isnan(x)], y[~np.isnan(y)], rtol=1e-12), key
    assert a.model == b.model and a.error == b.error


@pytest.fixture(scope="module")
def serial():
    return thinjkr.study(**CONTACT, **GRID)


def test_a_study_is_every_point_of_its_grid_in_order_none_dropped(serial):
    st = serial
    assert len(st) == 2 * 2 * 3
    # the angles outermost, then the thicknesses, then the loads
    assert list(st.theta_deg[:6]) == [60] * 6 and list(st.h[:3]) == [1e-5] * 3
    assert math.isnan(st.load[0]) and st.load[1] == 0.0 and st.load[2] == -1.0
    # each answered point is physical()'s answer at that point
    for k in (0, 1, 9):
        p = thinjkr.physical(**CONTACT, theta_deg=st.theta_deg[k], h1=st.h[k], h2=st.h[k],
                             force=None if math.isnan(st.load[k]) else st.load[k])
        assert p.force == st.force[k] and p.model == st.model[k], k
    # the loads below the pull-off have no answer, with their reason, in place
    for k in range(2, 12, 3):
        assert st.answers[k] is None and math.isnan(st.force[k]) and st.model[k] is None
        assert "force" in st.error[k], st.error[k]
    assert all(e is None for k, e in enumerate(st.error) if k % 3 != 2)
    # at 90 degrees the layer of finite thickness answers the pull-off
    assert st.model[6] == "layer" and st.model[0] == "exact"
    # the layer's estimate where (2) answers the pull-off (at 60 degrees
    # the ratio of rho = 1, with no bound for these coatings), NaN elsewhere
    for k, a in enumerate(st.answers):
        e = None if a is None else a.layer_estimate
        if e is None:
            assert math.isnan(st.estimate[k]) and math.isnan(st.estimate_within[k]), k
        else:
            assert st.estimate[k] == e["force"] and math.isnan(st.estimate_within[k]) == (e["within"] is None), k
    assert [k for k in range(12) if not math.isnan(st.estimate[k])] == [0, 3]
    assert "12 points, 8 answered, 4 without an answer" in repr(st)


def test_a_study_at_a_load_carries_the_layer_s_estimated_state():
    """Near 90 degrees (83.63) with coatings below the plane's reach, a state
    at zero force is (2)'s with the layer's state estimated beside it: the
    study's estimate_a and estimate_delta are that estimate's, the pull-off
    point has none (its estimate is of a force)."""
    st = thinjkr.study(**CONTACT, theta_deg=[83.63], h=[1.5e-5], force=[None, 0.0])
    pull_off, at_zero = st.answers
    e = at_zero.layer_estimate
    assert e["by"] == "shifted_line_tension"
    assert st.estimate_a[1] == e["state"]["a"] and st.estimate_delta[1] == e["state"]["delta"]
    assert st.estimate[1] == e["force"] and st.estimate_within[1] == e["within"]
    assert pull_off.layer_estimate["state"] is None
    assert math.isnan(st.estimate_a[0]) and math.isnan(st.estimate_delta[0])


def test_a_thread_pool_and_a_process_pool_give_the_same_study(serial):
    with cf.ThreadPoolExecutor(2) as pool:
        same(thinjkr.study(**CONTACT, **GRID, executor=pool), serial)
    # (started by spawn: a forked child of a process whose solver has run
    # inherits its thread pool's locks without its threads, and hangs)
    with cf.ProcessPoolExecutor(2, mp_context=mp.get_context("spawn")) as pool:
        same(thinjkr.study(**CONTACT, **GRID, executor=pool), serial)


def test_a_study_too_large_is_refused_before_any_point():
    with pytest.raises(thinjkr.InvalidInput, match="points = 1001000"):
        thinjkr.study(**CONTACT, theta_deg=np.linspace(10, 90, 1001), h=np.full(1000, 1e-5), force=[None])
    with pytest.raises(thinjkr.InvalidInput, match="points = 0"):
        thinjkr.study(**CONTACT, theta_deg=[], h=[1e-5])


@pytest.mark.slow
def test_a_dask_cluster_runs_a_study():
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        st = thinjkr.study(**CONTACT, **GRID, executor=client.get_executor())
    same(st, thinjkr.study(**CONTACT, **GRID))
