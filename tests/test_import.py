"""``import linecontact_sym`` loads what a plain import needs (SymPy, the
symbols, the errors) and nothing else: the public names load on first use
(module __getattr__), SciPy's special functions and optimisers when a float64
function is built or a stress extremum searched; every public name works."""
import json
import os

import pytest
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

_PROBE = """
import json, sys, time
t = time.process_time()
import linecontact_sym as lcs
cpu = time.process_time() - t
loaded = sorted(m for m in sys.modules)
step = {}
lcs.LineContact, lcs.parabola, lcs.StressField
step["contacts"] = sorted(m for m in sys.modules)
from linecontact_sym import *
star = sorted(k for k in dir() if not k.startswith("_"))
print(json.dumps({"cpu": cpu, "plain": loaded, "contacts": step["contacts"], "star": star}))
"""

HEAVY = ("scipy.special._ufuncs", "scipy.optimize._optimize", "matplotlib", "pint", "dask", "pygments",
         "linecontact_sym.claims", "linecontact_sym.cli", "linecontact_sym.views", "argparse")


def _probe():
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    out = subprocess.run([sys.executable, "-c", _PROBE], env=env, capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr[-2000:]
    return json.loads(out.stdout)


@pytest.mark.slow
def test_plain_import_loads_only_the_symbols_and_errors():
    r = _probe()
    ours = {m for m in r["plain"] if m.startswith("linecontact_sym")}
    assert ours == {"linecontact_sym", "linecontact_sym.core", "linecontact_sym.core.errors",
                    "linecontact_sym.core.symbols"}, ours
    for m in HEAVY + ("numpy", "scipy", "linecontact_sym.contacts"):
        assert m not in r["plain"], m
    # the contact classes do not need SciPy's special functions, its optimisers, plots or claims either
    for m in HEAVY:
        assert m not in r["contacts"], m
    assert r["cpu"] < 5.0          # SymPy's ~0.5 CPU s here; generous against a slow machine
    import linecontact_sym as lcs
    assert set(lcs.__all__) <= set(r["star"])       # from linecontact_sym import * gives every public name


@pytest.mark.slow
def test_every_public_name_resolves():
    import linecontact_sym as lcs
    for name in lcs.__all__:
        assert getattr(lcs, name) is not None, name
    assert set(lcs.__all__) <= set(dir(lcs))
    assert lcs.catalogue.parabola is lcs.parabola
    assert lcs.claims.check_claim and lcs.cli.main     # subpackages as attributes
    try:
        lcs.no_such_name
    except AttributeError as exc:
        assert "no_such_name" in str(exc)
    else:
        raise AssertionError("an unknown attribute must raise AttributeError")
