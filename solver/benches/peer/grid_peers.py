#!/usr/bin/env python3
"""thinjkr's grid solver beside tamaas and ContactMechanics (issue 71, item 5).

The problem all three solve: a rigid sphere (R = 1) on an elastic half-space
(contact modulus E* = 1), work of adhesion w = 1/2, on an N x N grid over the
square of half width W. JKR's pull-off is -3*pi*w*R/2 = -3*pi/4.

The laws:
  * rfs: thinjkr's own, Rose-Ferrante-Smith's p = -(w/r0^2) g exp(-g/r0) for
    g >= 0, continued for g < 0 by its cubic Taylor polynomial (a smooth
    repulsion, no hard wall). thinjkr solves it by Newton-GMRES;
    ContactMechanics solves the very same law (written below as an
    Adhesion potential) by L-BFGS-B on SmoothContactSystem.
  * exp: tamaas's and ContactMechanics's shared law, the exponential
    potential -w exp(-g/re) with a hard wall (g >= 0), re = e*r0 so that its
    greatest tension w/re is the rfs law's w/(e r0). tamaas solves it by
    Polonsky-Keer-Rey with its adhesion functional on a periodic cell,
    ContactMechanics by L-BFGS-B with bounds on a free (zero-padded) grid.

Each tool follows the same unloading sweep (the approaches DELTAS, each state
warm from the last) and then finds the pull-off under load control (the
least force): thinjkr by its own walk and secant on dF/dd, the others by
Brent's minimum of F(d) on the bracket their sweep found. tamaas controls the
mean gap of its periodic cell, not the approach: it sweeps the mean gaps
-delta - mean(surface) (its cell's elastic displacement has mean zero), and
its periodic images are 2W away (it is also run on a cell twice as wide, 2N
cells, the same cell size).

Every result is one JSON line in target/peer/grid_peers.jsonl; the table
docs/performance.md quotes is printed at the end.

usage: python3 solver/benches/peer/grid_peers.py [--n 256 512] [--tools ...]
  (creates target/peer-venv with tamaas, contactmechanics and Adhesion on
  first use and re-runs itself there)
"""

import argparse
import json
import math
import os
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
VENV = os.path.join(ROOT, "target", "peer-venv")
OUT = os.path.join(ROOT, "target", "peer", "grid_peers.jsonl")
PINS = ["numpy", "scipy", "tamaas==2.9.0", "contactmechanics==1.8.3", "Adhesion==0.93"]

W_WORK = 0.5  # work of adhesion
R0 = 0.05  # the rfs law's range
RE = math.e * R0  # the exponential law's range, the same greatest tension
HALF_WIDTH = 2.0
DELTAS = [0.5, 0.4, 0.3, 0.2, 0.1, 0.0, -0.1]
JKR = -0.75 * math.pi
# each tool's stopping rule: thinjkr's every cell's gap residual below 1e-10
# of the range (solver/src/layer/grid/mod.rs, GAP_TOL); these the peers'
TAMAAS_TOL = 1e-12  # Polonsky-Keer-Rey's relative error
CM_GTOL = 1e-10  # L-BFGS-B's projected gradient, per grid point


def ensure_venv():
    python = os.path.join(VENV, "bin", "python")
    if os.path.abspath(sys.prefix) == os.path.abspath(VENV):
        return
    if not os.path.exists(python):
        subprocess.run([sys.executable, "-m", "venv", VENV], check=True)
        subprocess.run([python, "-m", "pip", "install", "-q"] + PINS, check=True)
    os.execv(python, [python] + sys.argv)


def emit(record, sink):
    line = json.dumps(record)
    print(line, flush=True)
    sink.write(line + "\n")
    sink.flush()


def run_thinjkr(n, sink):
    subprocess.run(
        ["cargo", "build", "--release", "-q", "-p", "thinjkr", "--features",
         "bench-internals", "--example", "grid_peer"],
        cwd=ROOT, check=True)
    exe = os.path.join(ROOT, "target", "release", "examples", "grid_peer")
    args = [exe, str(n), str(HALF_WIDTH), str(R0)] + [str(d) for d in DELTAS]
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    for line in out.splitlines():
        record = json.loads(line)
        record["law"] = "rfs"
        emit(record, sink)


class Peers:
    """The peers' side, imported only inside the venv."""

    def __init__(self):
        import numpy as np
        from Adhesion.Interactions import Potential

        self.np = np

        class RoseFerranteSmith(Potential):
            """thinjkr's law (solver/src/layer/grid/law.rs) as an Adhesion
            potential: V(g) = -w(1 + x)e^(-x), x = g/r0, for g >= 0, and for
            g < 0 the integral of the cubic continuation,
            -w + w(x^2/2 - x^3/3 + x^4/8)."""

            name = "rose-ferrante-smith"

            def __init__(self, w, r0):
                self.w, self.r0 = w, r0
                Potential.__init__(self)

            def __repr__(self):
                return f"RoseFerranteSmith(w={self.w}, r0={self.r0})"

            @property
            def r_min(self):
                return None

            @property
            def r_infl(self):
                return self.r0

            @property
            def max_tensile(self):
                return -self.w / (math.e * self.r0)

            def evaluate(self, gap, potential=True, gradient=False, curvature=False, mask=None):
                x = np.asarray(gap) / self.r0
                pos = x >= 0
                e = np.exp(-np.where(pos, x, 0.0))
                w, r = self.w, self.r0
                V = np.where(pos, -w * (1 + x) * e, -w + w * (x**2 / 2 - x**3 / 3 + x**4 / 8))
                dV = np.where(pos, w / r * x * e, w / r * (x - x**2 + x**3 / 2))
                ddV = np.where(pos, w / r**2 * (1 - x) * e, w / r**2 * (1 - 2 * x + 1.5 * x**2))
                return (V if potential else None, dV if gradient else None,
                        ddV if curvature else None)

        self.RoseFerranteSmith = RoseFerranteSmith

    def contact_mechanics(self, n, law, sink):
        from SurfaceTopography import make_sphere
        from ContactMechanics import FreeFFTElasticHalfSpace
        from Adhesion.System import SmoothContactSystem, BoundedSmoothContactSystem
        from Adhesion.Interactions import Exponential
        from scipy.optimize import minimize_scalar

        size = 2 * HALF_WIDTH
        substrate = FreeFFTElasticHalfSpace((n, n), 1.0, (size, size))
        surface = make_sphere(1.0, (n, n), (size, size), kind="paraboloid")
        if law == "rfs":
            system = SmoothContactSystem(substrate, self.RoseFerranteSmith(W_WORK, R0), surface)
            bounds = None
        else:
            system = BoundedSmoothContactSystem(substrate, Exponential(W_WORK, RE), surface)
            bounds = "auto"
        solved = {}

        def solve(delta, gtol=CM_GTOL, start=None):
            # warm from `start`, else from the nearest state solved so far
            if start is None and solved:
                start = solved[min(solved, key=lambda d: abs(d - delta))]
            clock = time.perf_counter()
            result = system.minimize_proxy(
                offset=delta, initial_displacements=start, lbounds=bounds,
                options=dict(gtol=gtol, ftol=0.0, maxiter=100000, maxcor=10))
            seconds = time.perf_counter() - clock
            if not result.success:
                raise RuntimeError(f"ContactMechanics at delta = {delta}: {result.message}")
            solved[delta] = system.disp.copy()
            force = float(system.compute_normal_force())
            return force, seconds, int(result.nit)

        forces = {}
        for d in DELTAS:
            force, seconds, nit = solve(d)
            forces[d] = force
            emit(dict(tool="ContactMechanics", law=law, kind="state", n=n, delta=d,
                      force=force, states=1, iterations=nit, seconds=seconds), sink)
        # the sweep's last step again, from the state before it, with the
        # tolerance 100 times tighter and 100 times looser: how far the
        # force moves (relative), and what the step costs
        base, before = forces[DELTAS[-1]], solved[DELTAS[-2]].copy()
        for factor in (1e-2, 1e2):
            force, seconds, nit = solve(DELTAS[-1], CM_GTOL * factor, before)
            emit(dict(tool="ContactMechanics", law=law, kind="tolerance", n=n, factor=factor,
                      change=(force - base) / abs(base), iterations=nit, seconds=seconds), sink)
        solve(DELTAS[-1])
        self.pull_off("ContactMechanics", law, n, solve, forces, sink, minimize_scalar)

    def pull_off(self, tool, law, n, solve, forces, sink, minimize_scalar, **extra):
        """Steps of 0.1 down from the sweep until the force rises, then
        Brent's minimum on the bracket, to 1e-4 in the approach."""
        d = min(forces)
        count, clock = [0], time.perf_counter()

        def f(x):
            count[0] += 1
            return solve(float(x))[0]

        try:
            while not (len(forces) >= 3 and forces[d] > forces[round(d + 0.1, 10)]):
                d = round(d - 0.1, 10)
                forces[d] = solve(d)[0]
            result = minimize_scalar(f, bounds=(d, d + 0.2), method="bounded",
                                     options=dict(xatol=1e-4))
        except RuntimeError as failed:
            emit(dict(tool=tool, law=law, kind="pull-off", n=n, failed=str(failed),
                      states=count[0], seconds=time.perf_counter() - clock, **extra), sink)
            return
        emit(dict(tool=tool, law=law, kind="pull-off", n=n, delta=float(result.x),
                  force=float(result.fun), states=count[0],
                  seconds=time.perf_counter() - clock, **extra), sink)

    def tamaas(self, n, half_width, sink):
        import tamaas as tm
        from scipy.optimize import minimize_scalar

        tm.set_log_level(tm.LogLevel.warning)

        np = self.np
        size = 2 * half_width
        model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [size, size], [n, n])
        model.E, model.nu = 1.0, 0.0
        x = (np.arange(n) + 0.5) * size / n - half_width
        X, Y = np.meshgrid(x, x, indexing="ij")
        surface = -(X**2 + Y**2) / 2.0
        solver = tm.PolonskyKeerRey(model, surface, TAMAAS_TOL, tm.PolonskyKeerRey.gap,
                                    tm.PolonskyKeerRey.gap)
        adhesion = tm.ExponentialAdhesionFunctional(surface)
        adhesion.parameters = {"rho": RE, "surface_energy": W_WORK}
        solver.addFunctionalTerm(adhesion)
        mean_surface = float(surface.mean())

        def solve(gbar):
            clock = time.perf_counter()
            solver.solve(gbar)
            seconds = time.perf_counter() - clock
            force = float(model.traction.mean()) * size * size
            return force, seconds

        # The periodic cell's elastic displacement has mean zero (its k = 0
        # term is a rigid shift), so the mean gap is -delta - mean(surface)
        # for the cell's approach delta. It differs from an isolated
        # contact's approach by a shift proportional to the force (the
        # images'), which moves F(delta) along delta but leaves its least
        # value, the pull-off, to the images' non-uniform part.
        forces = {}
        for d in DELTAS:
            gbar = -d - mean_surface
            force, seconds = solve(gbar)
            forces[d] = force
            emit(dict(tool="tamaas", law="exp", kind="state", n=n, half_width=half_width,
                      tolerance=TAMAAS_TOL, delta=d, mean_gap=gbar, force=force, states=1,
                      seconds=seconds), sink)

        def solve_at(d):
            return solve(-d - mean_surface)

        # the sweep's last step again, from the state before it, with the
        # tolerance 100 times tighter and 100 times looser: how far the
        # force moves (relative), and what the step costs
        base = forces[DELTAS[-1]]
        for factor in (1e-2, 1e2):
            solve_at(DELTAS[-2])
            solver.tolerance = TAMAAS_TOL * factor
            force, seconds = solve_at(DELTAS[-1])
            emit(dict(tool="tamaas", law="exp", kind="tolerance", n=n, half_width=half_width,
                      factor=factor, change=(force - base) / abs(base), seconds=seconds), sink)
            solver.tolerance = TAMAAS_TOL
        solve_at(DELTAS[-1])

        self.pull_off("tamaas", "exp", n, solve_at, forces, sink, minimize_scalar,
                      half_width=half_width, tolerance=TAMAAS_TOL)


def table(path):
    rows = [json.loads(line) for line in open(path)]
    for r in rows:
        # (records of an earlier version named the cell in the tool)
        if "(W = " in r["tool"]:
            r["tool"], w = r["tool"].split(" (W = ")
            r["half_width"] = float(w.rstrip(")"))
        r.setdefault("half_width", HALF_WIDTH)
        r.setdefault("tolerance", {"tamaas": 1e-12, "ContactMechanics": CM_GTOL}.get(r["tool"]))
    print("\n| tool | law | cells | half width | cell | tolerance | median s per warm state | "
          "pull-off F (states) | against JKR |")
    print("|---|---|---|---|---|---|---|---|---|")
    keys = []
    for r in rows:
        key = (r["tool"], r["law"], r["n"], r["half_width"], r["tolerance"])
        if key not in keys:
            keys.append(key)
    for key in keys:
        mine = [r for r in rows
                if (r["tool"], r["law"], r["n"], r["half_width"], r["tolerance"]) == key]
        # the sweep's warm states (its first is solved from no guess)
        states = sorted([r["seconds"] for r in mine if r["kind"] == "state"][1:])
        median = states[len(states) // 2] if states else float("nan")
        po = [r for r in mine if r["kind"] == "pull-off"]
        tool, law, n, w, tol = key
        head = (f"| {tool} | {law} | {n}² | {w:g} | {2 * w / n:.4f} | "
                f"{'its rule' if tol is None else f'{tol:g}'} | {median:.3g} |")
        if po and "failed" in po[-1]:
            print(f"{head} failed: {po[-1]['failed']} | |")
        elif po:
            p = po[-1]
            print(f"{head} {p['force']:.6f} ({p['states']}) | {p['force'] / JKR - 1:+.2%} |")
        else:
            print(f"{head} | |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, nargs="+", default=[256, 512])
    parser.add_argument("--tools", nargs="+",
                        default=["thinjkr", "tamaas", "tamaas-wide", "cm-rfs", "cm-exp"])
    parser.add_argument("--table-only", action="store_true")
    parser.add_argument("--tamaas-tol", type=float, default=1e-12,
                        help="tamaas's stopping tolerance (its relative error)")
    args = parser.parse_args()
    if args.table_only:
        table(OUT)
        return
    ensure_venv()
    globals()["TAMAAS_TOL"] = args.tamaas_tol
    os.makedirs(os.path.dirname(OUT), exist_ok=True)
    peers = Peers()
    with open(OUT, "a") as sink:
        for n in args.n:
            for tool in args.tools:
                if tool == "thinjkr":
                    run_thinjkr(n, sink)
                elif tool == "cm-rfs":
                    peers.contact_mechanics(n, "rfs", sink)
                elif tool == "cm-exp":
                    peers.contact_mechanics(n, "exp", sink)
                elif tool == "tamaas":
                    peers.tamaas(n, HALF_WIDTH, sink)
                elif tool == "tamaas-wide":
                    peers.tamaas(2 * n, 2 * HALF_WIDTH, sink)
    table(OUT)


if __name__ == "__main__":
    main()
