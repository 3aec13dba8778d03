"""The paper's Fig. 7 (aspect ratio s against force F̄ at ρ = 0.8) for every
model of the ellipse, conformal:8 and the exact solution, and the pull-off
force against ρ; drawn with matplotlib when it is installed
(``pip install ./python[plot]``), written to PNG. Paste into a notebook.

    python python/examples/fig7.py [OUTDIR]
"""

import sys

import numpy as np

import thinjkr

out = sys.argv[1] if len(sys.argv) > 1 else "."
rho = 0.8

# s against F̄ along each model's curve (past its pull-off)
curves = {m: thinjkr.curve(rho, model=m, points=300) for m in ["max", "apexes", "energy", "apex45"]}
# conformal:8 and the exact family at forces above the pull-off
forces = np.linspace(-4.0, 20.0, 25)
conf = thinjkr.solve(rho, force=forces, model="conformal:8")
exact = []
for f in forces[::4]:
    try:
        st = thinjkr.exact.solve(rho, force=float(f))
        exact.append((st.force_bar, st.s))
    except thinjkr.ThinJkrError as e:  # a band, or not resolved: said, not drawn
        print(f"exact at F = {f:.2f}: {e}")

# the pull-off force against ρ, every model
rhos = np.linspace(0.5, 1.0, 11)
pull = {m: [thinjkr.pull_off(float(r), model=m).force_bar for r in rhos]
        for m in ["max", "apexes", "energy", "apex45", "conformal:8"]}

for m, c in curves.items():
    print(f"{m:12s} pull-off at rho = {rho}: F = {thinjkr.pull_off(rho, model=m).force_bar:.6f}")

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib is not installed (pip install ./python[plot]): no figures drawn")
    sys.exit(0)

fig, ax = plt.subplots(figsize=(6, 4))
for m, c in curves.items():
    keep = ~c.beyond_size_fold
    ax.plot(c.force_bar[keep], c.s[keep], label=m)
ax.plot(conf.force_bar, conf.s, "k--", label="conformal:8")
if exact:
    f, s = zip(*exact)
    ax.plot(f, s, "ko", label="exact")
ax.set_xlabel("F̄")
ax.set_ylabel("s")
ax.set_xlim(-5, 20)
ax.set_title(f"Fig. 7: aspect ratio against force, ρ = {rho}")
ax.legend()
fig.tight_layout()
fig.savefig(f"{out}/fig7_s_vs_force.png", dpi=120)

fig, ax = plt.subplots(figsize=(6, 4))
for m, p in pull.items():
    ax.plot(rhos, p, label=m)
ax.set_xlabel("ρ")
ax.set_ylabel("pull-off F̄ (load control)")
ax.legend()
fig.tight_layout()
fig.savefig(f"{out}/pull_off_vs_rho.png", dpi=120)
print(f"wrote {out}/fig7_s_vs_force.png and {out}/pull_off_vs_rho.png")
