"""The notebook python/examples/tour.ipynb runs from a clean kernel (issue 33,
item 9): every cell executes without an error; its outputs are not
committed (the file in the repository has none)."""

import json
import pathlib

import pytest

TOUR = pathlib.Path(__file__).resolve().parents[1] / "examples" / "tour.ipynb"


def test_the_committed_notebook_has_no_outputs():
    nb = json.loads(TOUR.read_text())
    for cell in nb["cells"]:
        if cell["cell_type"] == "code":
            assert not cell.get("outputs") and cell.get("execution_count") is None


def test_the_tour_notebook_runs_from_a_clean_kernel():
    nbformat = pytest.importorskip("nbformat", reason="in the test extra")
    nbclient = pytest.importorskip("nbclient", reason="in the test extra")
    pytest.importorskip("matplotlib", reason="in the test extra")
    nb = nbformat.read(TOUR, as_version=4)
    client = nbclient.NotebookClient(nb, timeout=600, kernel_name="python3",
                                     resources={"metadata": {"path": str(TOUR.parent)}})
    client.execute()
    errors = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
              if o.get("output_type") == "error"]
    assert not errors, errors
