"""The guide's walk "Adding a family of your own", for real.

A copy of the repository gets one new data file, derive/families/sparse.toml
(a contour family on the quadratic gap whose map skips ζ⁵: powers 1, 3, 7);
`thinjkr-derive generate --root COPY` derives, checks and generates it; the
test lists every path that changed and fails on any hand-written Rust or
Python among them or any built-in file changed; then the already built
command line and Python package, pointed at the copy's generated folder by
THINJKR_FAMILIES (no rebuild), list the family, solve with it, and
`thinjkr accuracy` has its column. sparse:2 has the map of conformal:2 and
so the same Π̄: their states must agree to round-off, through two separate
derivations and the run-time tables against the compiled ones.

Runs one symbolica process (the generator) and nothing else at the same time.
"""

import json
import os
import pathlib
import shutil
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]

SPARSE = """\
kind = "conformal"
name = "sparse"
title = "a sparser map: powers 1, 3 and 7 of the disk's variable (no 5th), on the quadratic gap"
gap = "X^2/2 + mu*Y^2/2"
particular = "X^4/24 + mu*Y^4/24 - dbar*(X^2 + Y^2)/4"
powers = [1, 3, 7]
rho_min = 0.5
trace_start_a = 2.6
"""


def derive_bin():
    for cand in (os.environ.get("THINJKR_DERIVE_BIN"),
                 ROOT / "target/debug/thinjkr-derive",
                 ROOT / "target/release/thinjkr-derive"):
        if cand and pathlib.Path(cand).is_file():
            return str(cand)
    pytest.fail("no thinjkr-derive binary: build it (cargo build -p thinjkr-derive) "
                "or set THINJKR_DERIVE_BIN")


def tracked_files():
    """The repository's files as a clean clone of this work tree would have them
    (tracked, and new files git does not ignore)."""
    try:
        out = subprocess.run(["git", "ls-files", "-z", "--cached", "--others",
                              "--exclude-standard"], cwd=ROOT, check=True,
                             capture_output=True).stdout
        return [p for p in out.decode().split("\0") if p]
    except (OSError, subprocess.CalledProcessError):
        return [str(p.relative_to(ROOT)) for p in ROOT.rglob("*")
                if p.is_file() and not {"target", ".git"} & set(p.relative_to(ROOT).parts)]


def snapshot(root):
    return {str(p.relative_to(root)): p.read_bytes()
            for p in root.rglob("*") if p.is_file()}


@pytest.fixture(scope="module")
def walked(tmp_path_factory):
    copy = tmp_path_factory.mktemp("walk") / "thinjkr"
    for rel in tracked_files():
        src = ROOT / rel
        if src.is_file():
            dst = copy / rel
            dst.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(src, dst)
    before = snapshot(copy)
    (copy / "derive/families/sparse.toml").write_text(SPARSE)
    env = dict(os.environ, SYMBOLICA_HIDE_BANNER="1")
    run = subprocess.run([derive_bin(), "generate", "--root", str(copy)], env=env,
                         capture_output=True, text=True, timeout=900)
    assert run.returncode == 0, run.stderr
    after = snapshot(copy)
    changed = sorted(p for p in set(before) | set(after) if before.get(p) != after.get(p))
    return copy, changed


def test_only_the_data_file_is_hand_written_and_every_built_in_file_is_unchanged(walked):
    copy, changed = walked
    print("changed by the walk:", *changed, sep="\n  ")
    hand_written = []
    for p in changed:
        if p == "derive/families/sparse.toml":
            continue
        text = (copy / p).read_text(errors="replace") if (copy / p).exists() else ""
        generated = "@generated" in text.splitlines()[0] if text else False
        in_generated = p.startswith("solver/src/generated/")
        if not (in_generated or (p.startswith("docs/") and generated)):
            hand_written.append(p)
        elif p.endswith((".rs", ".py")) and not generated:
            hand_written.append(p)
    assert not hand_written, f"the walk changed hand-written files: {hand_written}"
    # the new family's files, and the registry that lists it
    for p in ("derive/families/sparse.toml", "solver/src/generated/registry.json",
              "solver/src/generated/registry.rs", "solver/src/generated/mod.rs",
              "solver/src/generated/sparse/tables.json", "solver/src/generated/sparse/k3.rs",
              "docs/derivation.md", "docs/codegen-accuracy.md"):
        assert p in changed, p
    # no built-in family's or model's generated file changed
    builtin = [p for p in changed if p.startswith("solver/src/generated/conformal/")
               or p in {f"solver/src/generated/{m}.rs"
                        for m in ("max", "apexes", "energy", "apex45")}]
    assert not builtin, builtin
    # the docs gained the family's sections and kept the built-in ones
    derivation = (copy / "docs/derivation.md").read_text()
    assert "## The family `sparse:K`" in derivation
    assert "## The family `conformal:K`" in derivation


def cli_json(cli, env, *args):
    run = subprocess.run([cli, *args, "--json"], env=env, capture_output=True, text=True,
                         timeout=600)
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)


def test_the_command_line_lists_and_solves_with_the_family_without_a_rebuild(walked, cli):
    copy, _ = walked
    env = dict(os.environ, THINJKR_FAMILIES=str(copy / "solver/src/generated"))
    models = {m["name"]: m for m in cli_json(cli, env, "models")["models"]}
    for k in (1, 2, 3):
        assert models[f"sparse:{k}"]["family"] == "sparse"
        assert models[f"sparse:{k}"]["unknowns"] == k + 1
    assert models["sparse:3"]["rho_min"] == 0.5
    # without the variable the family is not there
    plain = {m["name"] for m in cli_json(cli, dict(os.environ), "models")["models"]}
    assert "sparse:3" not in plain and "conformal:8" in plain

    def state(model, *control):
        return cli_json(cli, env, "solve", "--rho", "0.8", *control, "--model", model)["state"]

    # sparse:2 is conformal:2 (the same map): the same state to round-off
    a = state("sparse:2", "--force", "0")
    b = state("conformal:2", "--force", "0")
    for key in ("a_bar", "s", "delta_bar"):
        assert abs(a[key] - b[key]) <= 1e-10 * abs(b[key]), (key, a[key], b[key])
    # sparse:3 adds ζ⁷: a state of its own, near conformal:3's
    c = state("sparse:3", "--force", "0")
    d = state("conformal:3", "--force", "0")
    assert c["model"] == "sparse:3" and len(c["coefficients"]) == 3
    assert c["coefficients"][2] != d["coefficients"][2]
    assert abs(c["a_bar"] / d["a_bar"] - 1) < 1e-2
    # a control in its range, refused below its rho_min with its words
    run = subprocess.run([cli, "solve", "--rho", "0.4", "--force", "0", "--model", "sparse:3"],
                         env=env, capture_output=True, text=True)
    assert run.returncode != 0 and "[0.5, 1] for sparse:K" in run.stderr, run.stderr


def test_python_lists_and_solves_with_the_family_without_a_rebuild(walked, cli):
    copy, _ = walked
    env = dict(os.environ, THINJKR_FAMILIES=str(copy / "solver/src/generated"))
    code = (
        "import json, thinjkr\n"
        "names = [m[0] for m in thinjkr.models()]\n"
        "st = thinjkr.solve(0.8, force=0.0, model='sparse:3')\n"
        "print(json.dumps({'names': names, 'a_bar': float(st.a_bar), 's': float(st.s)}))\n"
    )
    run = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                         timeout=300)
    assert run.returncode == 0, run.stderr
    got = json.loads(run.stdout)
    assert {"sparse:1", "sparse:2", "sparse:3"} <= set(got["names"])
    c = cli_json(cli, env, "solve", "--rho", "0.8", "--force", "0", "--model", "sparse:3")["state"]
    assert abs(got["a_bar"] - c["a_bar"]) <= 1e-12 * c["a_bar"]
    assert abs(got["s"] - c["s"]) <= 1e-12


def test_accuracy_has_the_familys_column(walked, cli, tmp_path):
    copy, _ = walked
    env = dict(os.environ, THINJKR_FAMILIES=str(copy / "solver/src/generated"))
    out = tmp_path / "accuracy.md"
    run = subprocess.run([cli, "accuracy", "--out", str(out)], env=env, capture_output=True,
                         text=True, timeout=900)
    assert run.returncode == 0, run.stderr
    text = out.read_text()
    assert "`sparse:2`" in text and "`conformal:8`" in text
    # one cell per compared member in every row of the family's table
    header = next(line for line in text.splitlines() if "`sparse:2`" in line)
    assert header.count("|") == 2 + 4 + 1, header
