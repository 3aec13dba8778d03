#!/usr/bin/env python3
"""Side-by-side comparison for thinjkr (issue: benchmarks).

Runs one sweep three ways in one run: 20 000 warm-started, displacement-
controlled solves of (19)-(20) at rho = 0.8, delta_bar from 6 down to 0.5,
each continued from the previous solution:
  (a) thinjkr's generated code and Newton (release example `peer_sweep generated`);
  (b) hand-written Rust (19)-(20) with a hand-derived Jacobian (`peer_sweep handwritten`,
      code in solver/benches/peer/handwritten.rs);
  (c) sympy-lambdified residual and Jacobian solved by scipy.optimize.fsolve.
Checks that all three reach the same solutions (|da|, |ds| <= 1e-9) and prints,
as its last line, ratio_vs_scipy=X ratio_vs_handwritten=Y with X = t(c)/t(a)
and Y = t(a)/t(b). Times are medians over repeated sweeps.

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


def scipy_sweep(start):
    a, s, d, rho = sp.symbols("a s d rho", positive=True)
    eta = 2 * (s**2 + s + 1) ** sp.Rational(3, 2) / (3 ** sp.Rational(3, 2) * s * (s + 1))
    r1 = a**3 - 2 * d * (3 * s**2 + 1) / (s**2 + 1) * a - 2 * (3 * s**4 - 2 * s**3 + 6 * s**2 + 1) / (s**2 * (s**2 + 1) * eta)
    r2 = a**3 - 2 * rho * d * (s**2 + 3) / (s**2 * (s**2 + 1)) * a - 2 * rho * (s**4 + 6 * s**2 - 2 * s + 3) / (s**3 * (s**2 + 1) * eta)
    res = sp.Matrix([r1, r2])
    jac = res.jacobian([a, s])
    f_res = sp.lambdify((a, s, d, rho), list(res), "numpy")
    f_jac = sp.lambdify((a, s, d, rho), jac.tolist(), "numpy")
    x = np.array(start)
    out = np.empty((N, 3))
    for k in range(N):
        delta = 6.0 - 5.5 * k / (N - 1)
        x = fsolve(lambda z: f_res(z[0], z[1], delta, RHO), x, fprime=lambda z: f_jac(z[0], z[1], delta, RHO), xtol=1e-14)
        out[k] = (delta, x[0], x[1])
    return out


def main():
    warnings.simplefilter("ignore", RuntimeWarning)  # fsolve: xtol at round-off
    with tempfile.TemporaryDirectory() as tmp:
        pa, pb = os.path.join(tmp, "a.txt"), os.path.join(tmp, "b.txt")
        subprocess.run(["cargo", "build", "-q", "--release", "-p", "thinjkr", "--example", "peer_sweep"], cwd=ROOT, check=True)
        ta, a0, s0 = run_rust("generated", pa)
        tb, _, _ = run_rust("handwritten", pb)
        sol_a, sol_b = load(pa), load(pb)
        times_c = []
        for _ in range(REPEATS_PY):
            t = time.perf_counter()
            sol_c = scipy_sweep((a0, s0))
            times_c.append(time.perf_counter() - t)
        tc = statistics.median(times_c)
    for name, other in (("hand-written Rust", sol_b), ("sympy+scipy", sol_c)):
        da = np.max(np.abs(sol_a[:, 1] - other[:, 1]))
        ds = np.max(np.abs(sol_a[:, 2] - other[:, 2]))
        print(f"agreement with {name}: max |da| = {da:.2e}, max |ds| = {ds:.2e}")
        if not (da <= 1e-9 and ds <= 1e-9):
            print(f"solutions differ from {name}", file=sys.stderr)
            sys.exit(1)
    print(f"(a) thinjkr generated + Newton: {ta * 1e3:.3f} ms per sweep (median of {REPEATS_RUST})")
    print(f"(b) hand-written Rust:          {tb * 1e3:.3f} ms per sweep (median of {REPEATS_RUST})")
    print(f"(c) sympy lambdify + fsolve:    {tc * 1e3:.1f} ms per sweep (median of {REPEATS_PY})")
    print(f"ratio_vs_scipy={tc / ta:.1f} ratio_vs_handwritten={ta / tb:.3f}")


if __name__ == "__main__":
    main()
