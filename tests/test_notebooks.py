"""The notebooks in notebooks/ run top to bottom (nbclient).  The Popov
reproduction runs its quick subset here (LINECONTACT_SYM_NOTEBOOK_QUICK=1);
the full check is the CLI's `paper` job."""
import os
from pathlib import Path

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))


@pytest.fixture(scope="module", autouse=True)
def compiled_package():
    """The package's bytecode, written once next to its sources (``__pycache__``,
    ignored by git) before the kernels start: where PYTHONDONTWRITEBYTECODE is
    set, every fresh kernel otherwise compiled the package's .py files again,
    about 1 CPU s of each kernel's 3.5 s of start-up and imports (the flag only
    stops writing: existing, up-to-date .pyc files are read; a stale one is
    recompiled by its source's time stamp)."""
    import compileall
    try:
        compileall.compile_dir(str(ROOT / "linecontact_sym"), quiet=2)
    except OSError:     # a read-only checkout: the kernels compile the sources, as before
        pass


def test_the_four_notebooks_exist():
    names = {p.stem for p in NOTEBOOKS}
    assert {"quickstart", "popov2017_reproduction", "adhesion", "speed_vs_accuracy"} <= names


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_runs(path, monkeypatch):
    monkeypatch.setenv("LINECONTACT_SYM_NOTEBOOK_QUICK", "1")
    monkeypatch.setenv("MPLBACKEND", "Agg")
    # the default budget, as a user's kernel has it: budgets are CPU seconds of the
    # derivation's own process (core/budget.py), so the suite's other workers beside
    # the kernel do not change what a notebook derives
    monkeypatch.delenv("LINECONTACT_SYM_BUDGET", raising=False)
    monkeypatch.setenv("PYTHONPATH", str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    nb = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(nb, timeout=240, kernel_name="python3",
                                     resources={"metadata": {"path": str(ROOT)}})
    client.execute()
    errors = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
              if o.get("output_type") == "error"]
    assert not errors
    if path.stem in ("quickstart", "popov2017_reproduction", "adhesion"):
        # derived objects display as rendered formulas / tables
        mimes = {k for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
                 for k in o.get("data", {})}
        assert "text/latex" in mimes or "text/markdown" in mimes
