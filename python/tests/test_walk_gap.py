"""CI's sample of the guide's walk on a gap no circle solves (issue 73).

A copy of the repository gets one data file, derive/families/bumpy.toml (a
family of powers 1, 3, 5 on φ̄ = X²/2 + μY²/2 + X⁴/24, one cylinder's own gap
to fourth order, not radial at ρ = 1, with no trace_start_a); the already
built generator (`thinjkr-derive generate --root COPY`, no cargo: nothing is
compiled, symbolica least of all) derives, checks and generates it; the
already built command line, pointed at the copy by THINJKR_FAMILIES, gives
the exact pull-off of that gap at ρ = 1 and 0.8. Each must be the one
solver/src/exact/gap.rs holds without the family (the minimum of F̄(ā) by
Brent's method over states at fixed ā, to 1e-9) and agree to 1e-8 with
the pull-off's second route, Newton from the own contour of the family's
largest member (bumpy:3) at its pull-off (`exact pull-off
--from-model-contour`); the family's members stand beside it, nearer it
from K = 2 to 3.

The slow tier's walk (test_walk.py) does the same with powers 1, 3, 5, 7 on
three such gaps, and more. Runs one symbolica process (the generator) and
nothing else at the same time; about a minute with the debug binaries.
"""

import os
import subprocess

import pytest

from test_walk import (BUMPY, BUMPY_PULL_OFFS, bumpy_exact_pull_off, copy_of_the_repository,
                       derive_bin, snapshot)


@pytest.fixture(scope="module")
def walked_bumpy(tmp_path_factory):
    copy = copy_of_the_repository(tmp_path_factory.mktemp("walk-gap") / "thinjkr")
    before = snapshot(copy / "solver/src/generated")
    three = BUMPY.replace("powers = [1, 3, 5, 7]", "powers = [1, 3, 5]")
    assert three != BUMPY and "trace_start_a" not in three
    (copy / "derive/families/bumpy.toml").write_text(three)
    env = dict(os.environ, SYMBOLICA_HIDE_BANNER="1")
    run = subprocess.run([derive_bin(), "generate", "--root", str(copy)], env=env,
                         capture_output=True, text=True, timeout=900)
    assert run.returncode == 0, run.stderr
    # the generator ran as built: nothing was compiled
    assert "Compiling" not in run.stdout + run.stderr
    after = snapshot(copy / "solver/src/generated")
    created = sorted(p for p in after if p not in before)
    assert "bumpy/tables.json" in created and "bumpy/k3.rs" in created, created
    return copy


def test_the_exact_pull_off_of_a_loaded_gap_no_circle_solves(walked_bumpy, cli):
    env = dict(os.environ, THINJKR_FAMILIES=str(walked_bumpy / "solver/src/generated"))
    for rho, force in BUMPY_PULL_OFFS:
        doc = bumpy_exact_pull_off(cli, env, rho, force)
        members = {m["model"]: m["member"]["force_bar"] for m in doc["models"] if "member" in m}
        assert sorted(members) == ["bumpy:1", "bumpy:2", "bumpy:3"], doc["models"]
        off = [abs(members[f"bumpy:{k}"] / force - 1) for k in (2, 3)]
        assert off[1] < off[0] and off[1] < 0.01, (rho, off)
