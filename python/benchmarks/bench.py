"""Speed of the Python package against the Rust API, in one run (issue 22):

- a vectorised solve of 10⁶ states (the 1000 × 1000 grid of ρ ∈ [0.3, 1],
  δ̄ ∈ [−0.2, 10] of the batch benchmark, the paper's model) through
  ``thinjkr.solve`` with arrays, against ``thinjkr::batch::solve_all`` on
  the same points timed inside Rust;
- the overhead of one scalar ``thinjkr.solve`` call over the same solve
  timed inside Rust.

Medians of REPEAT runs, in seconds. Not a test: run it by hand,

    python python/benchmarks/bench.py [REPEAT]
"""

import statistics
import sys
import time

import numpy as np

import thinjkr
from thinjkr import _thinjkr

repeat = int(sys.argv[1]) if len(sys.argv) > 1 else 5
rho = np.repeat(0.3 + 0.7 * np.arange(1000) / 999.0, 1000)
delta = np.tile(-0.2 + 10.0 * np.arange(1000) / 999.0, 1000)

py_times, rust_times = [], []
for _ in range(repeat):
    t = time.perf_counter()
    out = thinjkr.solve(rho, delta=delta, model="max")
    py_times.append(time.perf_counter() - t)
    rust_times.append(_thinjkr._batch_api_seconds("max", rho, "delta", delta))
solved = int(out.ok.sum())
py, rust = statistics.median(py_times), statistics.median(rust_times)
print(f"10^6 states ({solved} solved), median of {repeat}:")
print(f"  thinjkr.solve with arrays (Python)   {py:.3f} s")
print(f"  batch::solve_all (Rust, same run)    {rust:.3f} s")
print(f"  ratio Python / Rust                  {py / rust:.3f}")

n = 20000
for model in ["max", "energy"]:
    t = time.perf_counter()
    for _ in range(n):
        thinjkr.solve(0.8, delta=2.0, model=model)
    per_py = (time.perf_counter() - t) / n
    per_rust = statistics.median(_thinjkr._scalar_seconds(model, 0.8, "delta", 2.0, n) for _ in range(3))
    print(f"one scalar solve, {model}, rho = 0.8, delta = 2: Python {per_py * 1e6:.1f} us, "
          f"Rust {per_rust * 1e6:.1f} us, overhead {(per_py - per_rust) * 1e6:.1f} us per call")
