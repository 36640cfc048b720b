"""The documentation site, built once per test session: the one execution of
every notebook (tests/test_docs.py reads its pages, tests/test_notebooks.py
the executed notebooks).

The build is ``python -m sphinx -E -b html docs OUT/html`` with a jupyter-cache
of its own (``OUT/jupyter_cache``, empty at the start: a session never reuses
outputs of an earlier one, which a change of the package could have made
wrong).  MyST-NB writes the executed notebooks to ``OUT/jupyter_execute``.
The notebooks' kernels are forked from one process that has imported the
kernel's and the notebooks' modules (tests/kernel_zygote.py): the build's
kernel ``python3`` is that forked kernel (a kernelspec of that name first on
``JUPYTER_PATH``); where there is no fork, the plain one.
"""
from __future__ import annotations

import compileall
import json
import os
import subprocess
import sys
from contextlib import contextmanager
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
ZYGOTE = Path(__file__).with_name("kernel_zygote.py")


def environment() -> dict:
    """The environment of the build and of every kernel: this tree's package
    first on the path and the notebooks' quick path, as docs/conf.py would set
    them (set here already, so that the forked kernels' zygote has the same)."""
    env = dict(os.environ)
    env["LINECONTACT_SYM_NOTEBOOK_QUICK"] = "1"
    # the figures are the inline backend's (a kernel's default): no Agg
    env.pop("MPLBACKEND", None)
    # the default budget, as a user's kernel has it: budgets are CPU seconds of the
    # derivation's own process (core/budget.py), so the suite's other workers beside
    # the kernel do not change what a notebook derives
    env.pop("LINECONTACT_SYM_BUDGET", None)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(ROOT), os.environ.get("PYTHONPATH")) if p)
    return env


def compile_package() -> None:
    """The package's bytecode, written once next to its sources (``__pycache__``,
    ignored by git) before the kernels start: where PYTHONDONTWRITEBYTECODE is
    set, every fresh kernel otherwise compiled the package's .py files again,
    about 1 CPU s of each kernel's 3.5 s of start-up and imports."""
    try:
        compileall.compile_dir(str(ROOT / "linecontact_sym"), quiet=2)
    except OSError:     # a read-only checkout: the kernels compile the sources, as before
        pass


@contextmanager
def forked_kernels(tmp: Path, env: dict):
    """Set ``env`` up so that the kernel ``python3`` is forked from a zygote
    started with ``env`` (on systems without fork: unchanged)."""
    if not hasattr(os, "fork"):
        yield env
        return
    sock = str(tmp / "zygote.sock")
    spec = tmp / "jupyter" / "kernels" / "python3"
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-I", "-S", str(ZYGOTE), "client", sock, "{connection_file}"],
        "display_name": "Python 3", "language": "python", "interrupt_mode": "signal"}))
    zygote = subprocess.Popen([sys.executable, str(ZYGOTE), "serve", sock], stdout=subprocess.PIPE, text=True,
                              env=env)
    try:
        assert zygote.stdout.readline().strip() == "ready", "the kernel zygote did not start"
        zygote.stdout.close()
        yield dict(env, JUPYTER_PATH=os.pathsep.join(
            p for p in (str(tmp / "jupyter"), env.get("JUPYTER_PATH")) if p))
    finally:
        zygote.terminate()
        zygote.wait(timeout=60)


def build(out: Path) -> subprocess.CompletedProcess:
    """Build the site into ``out/html``, executing every notebook once."""
    compile_package()
    env = environment()
    env["LINECONTACT_SYM_DOCS_CACHE"] = str(out / "jupyter_cache")
    with forked_kernels(out, env) as env:
        return subprocess.run([sys.executable, "-m", "sphinx", "-q", "-E", "-b", "html", str(DOCS), str(out / "html")],
                              capture_output=True, text=True, timeout=900, cwd=ROOT, env=env)
