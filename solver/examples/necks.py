#!/usr/bin/env python3
"""The necks of the stored exact pull-offs (docs/exact.md, "The stored
pull-offs"): for each pull-off in solver/data/exact_pull_offs.json, the
contour z(theta) = A e^{i theta} + sum b_j e^{-(2j+1) i theta}
+ sum c_j e^{(2j+3) i theta} is sampled on its upper right quarter, and the
neck is the smallest Y at a local minimum of Y(X) on the upper flank (X > 0,
away from the end of the contour); "none" where the flank has no such
minimum. Prints a markdown table: rho, F, a, s, the neck's X and
half-width, Y at X = 0, the modes.

usage: python3 solver/examples/necks.py [FILE] [EVERY]
(EVERY: print every EVERY-th pull-off and the last; default 1)
"""
import cmath
import json
import math
import sys

path = sys.argv[1] if len(sys.argv) > 1 else "solver/data/exact_pull_offs.json"
every = int(sys.argv[2]) if len(sys.argv) > 2 else 1
table = json.load(open(path))


def point(contour, theta):
    z = contour["a"] * cmath.exp(1j * theta)
    for j, b in enumerate(contour["b"]):
        z += b * cmath.exp(-(2 * j + 1) * 1j * theta)
    for j, c in enumerate(contour.get("c", [])):
        z += c * cmath.exp((2 * j + 3) * 1j * theta)
    return z


def neck(contour, samples=4000):
    # theta from 0 (the end on the X axis) to pi/2 (the top, X = 0)
    zs = [point(contour, 0.5 * math.pi * i / samples) for i in range(samples + 1)]
    best = None
    for i in range(1, samples):
        y0, y1, y2 = zs[i - 1].imag, zs[i].imag, zs[i + 1].imag
        # a local minimum of Y along the flank, away from the end (Y > 0, X > 0)
        if y1 < y0 and y1 <= y2 and zs[i].real > 0 and y1 > 0:
            if best is None or y1 < best.imag:
                best = zs[i]
    return best, zs[-1].imag


print("| ρ | F̄ | ā | s | neck: X, half-width | Y at X = 0 | modes |")
print("|---|---|---|---|---|---|---|")
rows = table["pull_offs"]
for k, p in enumerate(rows):
    if k % every and k != len(rows) - 1:
        continue
    n, top = neck(p["contour"])
    where = "none" if n is None else f"{n.real:.3f}, {n.imag:.4f}"
    print(
        f"| {p['rho']:.5g} | {p['force_bar']:.5f} | {p['a_bar']:.4f} | {p['s']:.4f} "
        f"| {where} | {top:.4f} | {p['truncation']['modes']} |"
    )
print(f"\nreached rho = {table['reached']:.6g}: {table['why_stopped']}")
