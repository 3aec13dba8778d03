"""The shipped stubs hold a notebook's use of the API under `mypy --strict`
(issue 33), and that use runs: tests/typing/notebook.py is checked by mypy
and then executed."""

import pathlib
import runpy
import subprocess
import sys

import pytest

NOTEBOOK = pathlib.Path(__file__).parent / "typing" / "notebook.py"


def test_a_notebooks_calls_pass_mypy_strict_with_the_shipped_stubs():
    pytest.importorskip("mypy", reason="mypy is in the test extra: pip install './python[test]'")
    run = subprocess.run([sys.executable, "-m", "mypy", "--strict", "--no-incremental", str(NOTEBOOK)],
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "Success: no issues found" in run.stdout


def test_the_typed_notebook_runs():
    ns = runpy.run_path(str(NOTEBOOK))
    total = ns["sweep"]()  # every call answers (an error fails the test)
    assert isinstance(total, float) and total == total
