"""Optional dependencies: matplotlib ([plot]); python-flint is a core
dependency (issue 19 item 5: an optional package may add a feature, never
change a result), its old extra [certified] an alias.

The package imports without matplotlib; plotting without it raises
MissingExtraError (a LineContactError and an ImportError) whose message says
which extra to install.  A missing module is simulated by
``sys.modules[name] = None`` (then ``import name`` raises ImportError).
"""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core.errors import LineContactError, MissingExtraError
from linecontact_sym.core.extras import require

ROOT = Path(__file__).resolve().parents[1]


def test_require_names_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "flint", None)
    with pytest.raises(MissingExtraError) as exc:
        require("certified", "flint")
    assert 'pip install "linecontact_sym[certified]"' in str(exc.value)
    assert "python-flint" in str(exc.value)
    assert isinstance(exc.value, LineContactError) and isinstance(exc.value, ImportError)


def test_certified_evaluation_needs_no_extra():
    """python-flint is imported with the package: certified evaluation and the
    ball-arithmetic pull-off landscape are one code path, always there."""
    import flint
    from linecontact_sym.numeric import certified
    from linecontact_sym.contacts.normal import equilibria
    assert certified.flint is flint and equilibria.flint is flint
    r = lcs.parabola().evaluate("force", certified=True, a=0.5, R=1.0, E_star=1.0)
    import mpmath
    with mpmath.workdps(50):
        exact = mpmath.pi / 16                      # P = pi E* a^2 / (4 R) at a = 1/2
        assert r.certified and r.enclosure[0] <= exact <= r.enclosure[1]


def test_plotting_without_matplotlib(monkeypatch):
    from linecontact_sym.views import plots
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    monkeypatch.setitem(sys.modules, "matplotlib.pyplot", None)
    monkeypatch.setitem(sys.modules, "matplotlib.figure", None)
    with pytest.raises(MissingExtraError, match=r'pip install "linecontact_sym\[plot\]"'):
        plots.figure_class()


def test_the_package_imports_without_the_extras():
    """A fresh interpreter with matplotlib blocked imports every module of the
    package (our copy: the worktree first on sys.path)."""
    code = (
        "import sys, pkgutil, importlib\n"
        f"sys.path.insert(0, {str(ROOT)!r})\n"
        "sys.modules['matplotlib'] = None\n"
        "import linecontact_sym\n"
        f"assert linecontact_sym.__file__.startswith({str(ROOT)!r}), linecontact_sym.__file__\n"
        "names = [m.name for m in pkgutil.walk_packages(linecontact_sym.__path__, 'linecontact_sym.')\n"
        "         if not m.name.endswith('__main__')]\n"
        "for name in names:\n"
        "    importlib.import_module(name)\n"
        "print(len(names))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    assert int(out.stdout.strip()) > 20


def test_pyproject_declares_the_extras():
    try:
        import tomllib
    except ModuleNotFoundError:  # Python < 3.11
        import tomli as tomllib
    meta = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    deps = " ".join(meta["dependencies"])
    assert "matplotlib" not in deps and "python-flint" in deps     # flint: core (one code path)
    extras = meta["optional-dependencies"]
    assert any(d.startswith("matplotlib") for d in extras["plot"])
    assert any(d.startswith("python-flint") for d in extras["certified"])   # the old command still works
    assert extras["all"] == ["linecontact_sym[plot,certified,units]"]   # every feature, no cluster
    assert any(d.startswith("linecontact_sym[all") for d in extras["test"])   # all (+ docs: the site is tested)
