"""Every subcommand's --json output validates against the committed JSON
Schema (docs/schema.json, derived from the Rust types by `thinjkr
schema`; solver/tests/cli.rs fails when it is stale), errors included."""

import json
import pathlib
import subprocess

import jsonschema
import pytest

SCHEMA = json.loads((pathlib.Path(__file__).resolve().parents[2] / "docs/schema.json").read_text())

P = ["--r1", "0.01", "--r2", "0.02", "--theta-deg", "90", "--h1", "1e-5", "--h2", "1e-5",
     "--g1", "1e6", "--g2", "1e6", "--work-of-adhesion", "0.05"]

COMMANDS = [
    ["solve", "--rho", "0.8", "--delta", "2"],
    ["solve", "--rho", "0.8", "--force", "1", "--model", "energy"],
    ["solve", "--rho", "0.8", "--a", "2.4"],
    ["solve", "--rho", "0.8", "--a", "2.34"],
    ["solve", "--rho", "0.8", "--force", "10", "--model", "conformal:4"],
    ["solve", "--rho", "0.8", "--force", "10", "--model", "exact"],
    ["pull-off", "--rho", "0.8"],
    ["pull-off", "--rho", "0.8", "--control", "displacement"],
    ["pull-off", "--rho", "0.8", "--model", "conformal:4"],
    ["pull-off", "--rho", "0.8", "--model", "exact"],
    ["zero-force", "--rho", "0.9", "--model", "apex45"],
    ["exact", "solve", "--rho", "0.8", "--delta", "2"],
    ["exact", "zero-force", "--rho", "0.8"],
    ["exact", "pull-off", "--rho", "0.9", "--modes", "8"],
    ["models"],
    ["physical", *P, "--force", "0"],
    ["physical", *P, "--model", "conformal:4"],
    ["physical", *P, "--delta", "1e-7", "--model", "energy"],
    # errors are documents too
    ["solve", "--rho", "1.5", "--delta", "2"],
    ["pull-off", "--rho", "0.8", "--model", "energy", "--control", "displacement"],
    ["exact", "solve", "--rho", "0.8", "--force", "-5"],
]


@pytest.mark.parametrize("args", COMMANDS, ids=lambda a: " ".join(a[:4]))
def test_json_output_validates(cli, args):
    run = subprocess.run([cli, *args, "--json"], capture_output=True, text=True)
    doc = json.loads(run.stdout)
    jsonschema.validate(doc, SCHEMA)
    assert ("error" in doc) == (run.returncode != 0)


def test_curve_json_validates(cli):
    run = subprocess.run([cli, "curve", "--rho", "0.8", "--points", "30", "--format", "json"],
                         capture_output=True, text=True, check=True)
    jsonschema.validate(json.loads(run.stdout), SCHEMA)


@pytest.mark.parametrize("name", ["exact_windows.jsonl", "exact_reach.jsonl", "exact_bands.jsonl"])
def test_committed_json_lines_validate(name):
    """The committed maps (`thinjkr exact reach/bands --json`) are documents of the schema."""
    path = pathlib.Path(__file__).resolve().parents[2] / "docs/data" / name
    lines = [line for line in path.read_text().splitlines() if line.strip()]
    assert lines
    validator = jsonschema.validators.validator_for(SCHEMA)(SCHEMA)
    for line in lines:
        validator.validate(json.loads(line))
