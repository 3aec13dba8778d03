#!/usr/bin/env python3
"""Side-by-side comparison for thinjkr (issue: benchmarks).

Runs one sweep three ways in one run: 20 000 warm-started, displacement-
controlled solves of (19)-(20) at rho = 0.8, delta_bar from 6 down to 0.5,
each continued from the previous solution:
  (a) thinjkr's generated code and Newton (release example `peer_sweep generated`);
  (b) hand-written Rust (19)-(20) with a hand-derived Jacobian (`peer_sweep handwritten`,
      code in solver/benches/peer/handwritten.rs);
  (c) sympy-lambdified residual and Jacobian solved by scipy.optimize.fsolve;
  (g) through the model layer (`peer_sweep layer`): each state a checked state
      (F̄, stability, boundary error, pressure) continued from the one before
      by `thinjkr::registry::Choice::state_near`, as every front end gets it.
Checks that all four reach the same solutions (|da|, |ds| <= 1e-9). (a), (b)
and (g) alternate, three rounds, each a median of repeated sweeps.

Then a cold-solve sweep (issue 12): 10 000 cold solves at pseudo-random
(rho, delta_bar), rho in [0.7, 1), delta_bar in [0.5, 6] (the inputs written
by `peer_sweep cold`):
  (d) thinjkr: a new Contact and at_displacement for each (no warm start);
  (e) scipy.optimize.fsolve on the same lambdified (19)-(20), each started
      from closed forms: a_bar from the axisymmetric relation (25)_1 (derived
      form, delta = a^2/4 - 2/a, Cardano) and s from (30).
  (f) thinjkr's Newton from the same closed-form start (`peer_sweep
      cold-newton`): the algorithm of (e) in Rust, without the bracketing
      that makes (d) safe (it is not how thinjkr solves).
Counts the solves where fsolve and (f) reach thinjkr's state (|da|, |ds| <=
1e-9) and fails if fewer than 99 % do.

Prints, as its last line, ratio_vs_scipy=X ratio_vs_handwritten=Y
layer_ratio_vs_handwritten=V cold_ratio_vs_scipy=Z same_start_ratio_vs_scipy=W
with X = t(c)/t(a), Y = t(a)/t(b), V = t(g)/t(b), Z = t(e)/t(d),
W = t(e)/t(f). Times are medians over repeated sweeps.

Needs Python 3 with sympy, numpy and scipy (pip install sympy numpy scipy);
installs nothing itself. Run from anywhere:  python3 solver/benches/peer/compare.py
"""
import os
import statistics
import subprocess
import sys
import tempfile
import time
import warnings

import numpy as np
import sympy as sp
from scipy.optimize import fsolve

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
N = 20_000
RHO = 0.8
REPEATS_RUST = 9
REPEATS_PY = 3


def run_rust(variant, out):
    res = subprocess.run(
        ["cargo", "run", "-q", "--release", "-p", "thinjkr", "--example", "peer_sweep", "--", variant, out, str(REPEATS_RUST)],
        cwd=ROOT, check=True, capture_output=True, text=True,
    )
    fields = dict(kv.split("=") for kv in res.stdout.split())
    return float(fields["median_seconds"]), float(fields["start_a"]), float(fields["start_s"])


def load(path):
    return np.loadtxt(path)


def residual_functions():
    a, s, d, rho = sp.symbols("a s d rho", positive=True)
    eta = 2 * (s**2 + s + 1) ** sp.Rational(3, 2) / (3 ** sp.Rational(3, 2) * s * (s + 1))
    r1 = a**3 - 2 * d * (3 * s**2 + 1) / (s**2 + 1) * a - 2 * (3 * s**4 - 2 * s**3 + 6 * s**2 + 1) / (s**2 * (s**2 + 1) * eta)
    r2 = a**3 - 2 * rho * d * (s**2 + 3) / (s**2 * (s**2 + 1)) * a - 2 * rho * (s**4 + 6 * s**2 - 2 * s + 3) / (s**3 * (s**2 + 1) * eta)
    res = sp.Matrix([r1, r2])
    jac = res.jacobian([a, s])
    return sp.lambdify((a, s, d, rho), list(res), "numpy"), sp.lambdify((a, s, d, rho), jac.tolist(), "numpy")


def scipy_sweep(start):
    f_res, f_jac = residual_functions()
    x = np.array(start)
    out = np.empty((N, 3))
    for k in range(N):
        delta = 6.0 - 5.5 * k / (N - 1)
        x = fsolve(lambda z: f_res(z[0], z[1], delta, RHO), x, fprime=lambda z: f_jac(z[0], z[1], delta, RHO), xtol=1e-14)
        out[k] = (delta, x[0], x[1])
    return out


def closed_form_start(rho, delta):
    """a_bar from a^3 - 4 delta a - 8 = 0 (rho = 1, derived (25)_1) by Cardano; s from (30)."""
    p, q = -4.0 * delta, -8.0
    disc = (q / 2) ** 2 + (p / 3) ** 3
    if disc >= 0:
        r = np.sqrt(disc)
        a0 = np.cbrt(-q / 2 + r) + np.cbrt(-q / 2 - r)
    else:
        m = 2 * np.sqrt(-p / 3)
        a0 = m * np.cos(np.arccos(3 * q / (p * m)) / 3)
    c = 0.3 * (1 - rho)
    return a0, np.sqrt(np.sqrt(c * c + rho) - c)


def scipy_cold(inputs, f_res, f_jac):
    out = np.empty((len(inputs), 2))
    for k, (rho, delta) in enumerate(inputs):
        x = fsolve(lambda z: f_res(z[0], z[1], delta, rho), closed_form_start(rho, delta),
                   fprime=lambda z: f_jac(z[0], z[1], delta, rho), xtol=1e-14)
        out[k] = x
    return out


def main():
    warnings.simplefilter("ignore", RuntimeWarning)  # fsolve: xtol at round-off
    with tempfile.TemporaryDirectory() as tmp:
        pa, pb = os.path.join(tmp, "a.txt"), os.path.join(tmp, "b.txt")
        subprocess.run(["cargo", "build", "-q", "--release", "-p", "thinjkr", "--example", "peer_sweep"], cwd=ROOT, check=True)
        pg = os.path.join(tmp, "g.txt")
        rounds = {"generated": [], "handwritten": [], "layer": []}
        for _ in range(3):
            for variant, path in (("generated", pa), ("handwritten", pb), ("layer", pg)):
                t, a0, s0 = run_rust(variant, path)
                rounds[variant].append(t)
        ta, tb, tg = (statistics.median(rounds[v]) for v in ("generated", "handwritten", "layer"))
        sol_a, sol_b, sol_g = load(pa), load(pb), load(pg)
        times_c = []
        for _ in range(REPEATS_PY):
            t = time.perf_counter()
            sol_c = scipy_sweep((a0, s0))
            times_c.append(time.perf_counter() - t)
        tc = statistics.median(times_c)
    for name, other in (("hand-written Rust", sol_b), ("sympy+scipy", sol_c), ("the model layer", sol_g)):
        da = np.max(np.abs(sol_a[:, 1] - other[:, 1]))
        ds = np.max(np.abs(sol_a[:, 2] - other[:, 2]))
        print(f"agreement with {name}: max |da| = {da:.2e}, max |ds| = {ds:.2e}")
        if not (da <= 1e-9 and ds <= 1e-9):
            print(f"solutions differ from {name}", file=sys.stderr)
            sys.exit(1)
    print(f"(a) thinjkr generated + Newton: {ta * 1e3:.3f} ms per sweep (median of {REPEATS_RUST})")
    print(f"(b) hand-written Rust:          {tb * 1e3:.3f} ms per sweep (median of {REPEATS_RUST})")
    print(f"(c) sympy lambdify + fsolve:    {tc * 1e3:.1f} ms per sweep (median of {REPEATS_PY})")
    print(f"(g) the model layer, checked:   {tg * 1e3:.3f} ms per sweep (median of 3 rounds of {REPEATS_RUST})")
    # cold solves
    def cold_rust(variant):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "cold.txt")
            res = subprocess.run(
                ["cargo", "run", "-q", "--release", "-p", "thinjkr", "--example", "peer_sweep", "--", variant, path, str(REPEATS_RUST)],
                cwd=ROOT, check=True, capture_output=True, text=True,
            )
            return float(res.stdout.split("=")[1]), load(path)

    td, sol_d = cold_rust("cold")
    tf, sol_f = cold_rust("cold-newton")
    f_res, f_jac = residual_functions()
    inputs = sol_d[:, :2]
    times_e = []
    for _ in range(REPEATS_PY):
        t = time.perf_counter()
        sol_e = scipy_cold(inputs, f_res, f_jac)
        times_e.append(time.perf_counter() - t)
    te = statistics.median(times_e)
    for name, other in (("fsolve", sol_e), ("Newton from the same start", sol_f[:, 2:])):
        agree = (np.abs(other[:, 0] - sol_d[:, 2]) <= 1e-9) & (np.abs(other[:, 1] - sol_d[:, 3]) <= 1e-9)
        print(f"cold solves: {name} reaches thinjkr's state (|da|, |ds| <= 1e-9) in {agree.sum()} of {len(agree)}")
        if agree.mean() < 0.99:
            print(f"{name} from the closed-form start misses thinjkr's state too often", file=sys.stderr)
            sys.exit(1)
    n = len(inputs)
    print(f"(d) thinjkr cold solves:        {td / n * 1e6:.2f} us per solve (median of {REPEATS_RUST} sweeps of {n})")
    print(f"(e) fsolve from closed forms:   {te / n * 1e6:.1f} us per solve (median of {REPEATS_PY} sweeps of {n})")
    print(f"(f) Newton from the same start: {tf / n * 1e6:.3f} us per solve (median of {REPEATS_RUST} sweeps of {n})")
    print(f"ratio_vs_scipy={tc / ta:.1f} ratio_vs_handwritten={ta / tb:.3f} layer_ratio_vs_handwritten={tg / tb:.3f} cold_ratio_vs_scipy={te / td:.1f} same_start_ratio_vs_scipy={te / tf:.1f}")


if __name__ == "__main__":
    main()
