"""A notebook's use of the API, checked by `mypy --strict` against the
shipped stubs (test_typing.py): scalars, arrays, results, warnings as
errors, the exact solver, physical units."""

import warnings

import numpy as np

import thinjkr
import thinjkr.exact


def sweep() -> float:
    st: thinjkr.State = thinjkr.solve(0.8, force=1.0)
    a_bar: float = st.a_bar
    many = thinjkr.solve(np.linspace(0.5, 1.0, 11), delta=2.0, model="conformal:4")
    # an array gives States without a cast (issue 33 item 4): a float rho
    # with an array of forces too, and zero_force, pull_off, curve and the
    # exact solver's functions likewise
    fig7 = thinjkr.solve(0.8, force=np.linspace(-2.0, 10.0, 5))
    mean_s: float = float(fig7.s.mean())
    zfs: thinjkr.States = thinjkr.zero_force(np.array([0.8, 0.9]))
    pos: thinjkr.States = thinjkr.pull_off([0.8, 0.9])
    curves: list[thinjkr.Curve] = thinjkr.curve([0.8, 0.9], points=20)
    exact_zf: thinjkr.States = thinjkr.exact.zero_force([0.9, 1.0])
    arrays = mean_s + float(zfs.a_bar.sum() + pos.force_bar.sum() + exact_zf.a_bar.sum()) + len(curves)
    ok: np.ndarray = many.ok & ~many.doubtful
    kept = many[ok]
    for one in many:
        assert one.model == "conformal:4"
    po: thinjkr.PullOff = thinjkr.pull_off(0.8, control="displacement")
    exact_po: thinjkr.PullOff = thinjkr.exact.pull_off(0.9)
    cv: thinjkr.Curve = thinjkr.curve(0.8, points=50)
    with warnings.catch_warnings():
        warnings.simplefilter("error", thinjkr.ThinJkrWarning)
        zf = thinjkr.zero_force(0.9)
    phys = thinjkr.physical(r1=10e-3, r2=15e-3, theta_deg=60.0, h1=1e-4, h2=1e-4, g1=1e6,
                            g2=1e6, work_of_adhesion=0.05, model="energy")
    names: list[tuple[str, str]] = thinjkr.models()
    return (a_bar + po.force_bar + exact_po.force_bar + float(cv.a_bar[0]) + zf.delta_bar
            + phys.force + phys.state.force_bar + len(kept) + len(names) + arrays)
