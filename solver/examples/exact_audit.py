#!/usr/bin/env python3
"""Issue 31's closing count for `exact`: N random inputs (default 200) through
`thinjkr solve --model exact --json`, each with a time limit, tallied by what
came back: a state, a typed error by its kind, or no answer within the limit.
The inputs are drawn as `random_audit` draws them (rho log-uniform in
[0.02, 1]; delta in [-3, 20], force in [-6, 60] or a in [0.3, 8] with equal
chance; `exact` takes no a, which it refuses, typed). Every state is held to
its control (delta or force to 1e-8).

usage: python3 solver/examples/exact_audit.py THINJKR_BIN [N] [SECONDS] [JOBS]
"""
import concurrent.futures
import json
import math
import random
import subprocess
import sys
import time

binary = sys.argv[1]
n = int(sys.argv[2]) if len(sys.argv) > 2 else 200
limit = float(sys.argv[3]) if len(sys.argv) > 3 else 60.0
jobs = int(sys.argv[4]) if len(sys.argv) > 4 else 2
rng = random.Random(31)
inputs = []
for _ in range(n):
    rho = math.exp(math.log(0.02) * (1.0 - rng.random()))
    pick, u = rng.random(), rng.random()
    if pick < 1 / 3:
        inputs.append((rho, "--delta", -3.0 + 23.0 * u))
    elif pick < 2 / 3:
        inputs.append((rho, "--force", -6.0 + 66.0 * u))
    else:
        inputs.append((rho, "--a", 0.3 + 7.7 * u))


def one(inp):
    rho, flag, value = inp
    args = [binary, "solve", "--model", "exact", "--rho", repr(rho), flag, repr(value), "--json"]
    t = time.time()
    try:
        out = subprocess.run(args, capture_output=True, text=True, timeout=limit)
    except subprocess.TimeoutExpired:
        return "no answer within %g s" % limit, None, time.time() - t
    try:
        doc = json.loads(out.stdout)
    except ValueError:
        return "no JSON (exit %d)" % out.returncode, out.stderr[:200], time.time() - t
    if "error" in doc:
        return "refused: " + doc["error"]["kind"], None, time.time() - t
    st = doc.get("state", doc)
    key = {"--delta": "delta_bar", "--force": "force_bar"}.get(flag)
    bad = None
    if key and abs(st[key] - value) > 1e-8 * max(1.0, abs(value)):
        bad = "rho = %g %s %g: %s = %r" % (rho, flag, value, key, st[key])
    return "state", bad, time.time() - t


tally, broken, times = {}, [], []
with concurrent.futures.ThreadPoolExecutor(jobs) as ex:
    for key, bad, dt in ex.map(one, inputs):
        tally[key] = tally.get(key, 0) + 1
        times.append(dt)
        if bad:
            broken.append(bad)
print("exact: %d inputs, %.0f s in all (median %.2f s): %s; states breaking their claims: %d" % (
    n, sum(times), sorted(times)[len(times) // 2], ", ".join("%s %d" % kv for kv in sorted(tally.items())), len(broken)))
for b in broken[:5]:
    print("  " + b)
