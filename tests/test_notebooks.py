"""The notebooks in notebooks/ run top to bottom.  They are executed once per
test session, by the docs build (tests/docs_site.py: MyST-NB, each notebook in
a new kernel process of its own, forked from one that has imported the
kernel's and the notebooks' modules, tests/kernel_zygote.py); these tests read
the executed notebooks it wrote.  The Popov reproduction runs its quick subset
(LINECONTACT_SYM_NOTEBOOK_QUICK=1); the full check is the CLI's `paper` job."""
from pathlib import Path

import pytest

nbformat = pytest.importorskip("nbformat")

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))

pytestmark = pytest.mark.xdist_group("docs")


def test_the_four_notebooks_exist():
    names = {p.stem for p in NOTEBOOKS}
    assert {"quickstart", "popov2017_reproduction", "adhesion", "speed_vs_accuracy"} <= names


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_runs(path, docs_site):
    out, _ = docs_site
    executed = out / "jupyter_execute" / "tutorials" / path.name
    assert executed.exists(), f"the docs build did not execute {path.name}"
    nb = nbformat.read(executed, as_version=4)
    code = [c for c in nb.cells if c.cell_type == "code"]
    # every cell of the stored notebook ran, in order, and none raised
    stored = [c.source for c in nbformat.read(path, as_version=4).cells if c.cell_type == "code"]
    assert [c.source for c in code] == stored
    assert [c.get("execution_count") for c in code] == list(range(1, len(code) + 1))
    errors = [o for c in code for o in c.get("outputs", []) if o.get("output_type") == "error"]
    assert not errors
    mimes = {k for c in code for o in c.get("outputs", []) for k in o.get("data", {})}
    if path.stem in ("quickstart", "popov2017_reproduction", "adhesion"):
        # derived objects display as rendered formulas / tables
        assert "text/latex" in mimes or "text/markdown" in mimes
    if path.stem in ("adhesion", "tangential", "wavy_surfaces", "subsurface_stresses", "maugis_dugdale"):
        # the figures show as images, not as "<Figure size ...>"
        assert "image/png" in mimes, path.stem
