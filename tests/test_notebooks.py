"""The notebooks in notebooks/ run top to bottom (nbclient).  The Popov
reproduction runs its quick subset here (LINECONTACT_SYM_NOTEBOOK_QUICK=1);
the full check is the CLI's `paper` job.  Each notebook runs in a new kernel
process of its own, forked from one that has imported the kernel's and the
notebooks' modules (tests/kernel_zygote.py)."""
import json
import os
import subprocess
import sys
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


def _kernel_environment() -> dict:
    """The environment of every notebook's kernel."""
    env = dict(os.environ)
    env["LINECONTACT_SYM_NOTEBOOK_QUICK"] = "1"
    env["MPLBACKEND"] = "Agg"
    # the default budget, as a user's kernel has it: budgets are CPU seconds of the
    # derivation's own process (core/budget.py), so the suite's other workers beside
    # the kernel do not change what a notebook derives
    env.pop("LINECONTACT_SYM_BUDGET", None)
    env["PYTHONPATH"] = str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", "")
    return env


@pytest.fixture(scope="module")
def kernels(tmp_path_factory, compiled_package):
    """The kernel manager's arguments for one notebook: kernels forked from
    one process that has imported ipykernel, IPython and the notebooks'
    modules (tests/kernel_zygote.py: each notebook still gets a new kernel
    process with a fresh namespace and runs every cell, its imports included;
    about 2.5 CPU s of start-up and imports saved per notebook); the plain
    ``python3`` kernel where there is no fork."""
    env = _kernel_environment()
    with pytest.MonkeyPatch.context() as mp:
        for k in set(os.environ) - set(env):
            mp.delenv(k)
        for k, v in env.items():
            mp.setenv(k, v)
        if not hasattr(os, "fork"):
            yield {"kernel_name": "python3"}
            return
        from jupyter_client.kernelspec import KernelSpecManager
        from jupyter_client.manager import KernelManager
        tmp = tmp_path_factory.mktemp("kernels")
        sock = str(tmp / "zygote.sock")
        script = str(Path(__file__).with_name("kernel_zygote.py"))
        spec = tmp / "kernels" / "linecontact-zygote"
        spec.mkdir(parents=True)
        (spec / "kernel.json").write_text(json.dumps({
            "argv": [sys.executable, "-I", "-S", script, "client", sock, "{connection_file}"],
            "display_name": "Python 3 (forked)", "language": "python", "interrupt_mode": "signal"}))
        zygote = subprocess.Popen([sys.executable, script, "serve", sock], stdout=subprocess.PIPE, text=True)
        try:
            assert zygote.stdout.readline().strip() == "ready", "the kernel zygote did not start"
            zygote.stdout.close()
            specs = KernelSpecManager(kernel_dirs=[str(tmp / "kernels")])
            yield {"km": lambda: KernelManager(kernel_name="linecontact-zygote", kernel_spec_manager=specs)}
        finally:
            zygote.terminate()
            zygote.wait(timeout=60)


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.stem for p in NOTEBOOKS])
def test_notebook_runs(path, kernels):
    nb = nbformat.read(path, as_version=4)
    how = {"km": kernels["km"]()} if "km" in kernels else {"kernel_name": kernels["kernel_name"]}
    client = nbclient.NotebookClient(nb, timeout=240, resources={"metadata": {"path": str(ROOT)}}, **how)
    client.execute()
    errors = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
              if o.get("output_type") == "error"]
    assert not errors
    if path.stem in ("quickstart", "popov2017_reproduction", "adhesion"):
        # derived objects display as rendered formulas / tables
        mimes = {k for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
                 for k in o.get("data", {})}
        assert "text/latex" in mimes or "text/markdown" in mimes
