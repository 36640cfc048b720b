"""Maugis-Dugdale on every profile (issue 28): per profile, which parts of the two
conditions the engine found in closed form, the time of a state at 30 digits and
of the pull-off (15 digits), at E* = 1, w = 1e-4, R = 1 and sigma_0 = 1/40
(Baney & Hui's lambda = 1.0 for the parabola).

    python benchmarks/maugis_everywhere.py [--sigma0 1/40] [--json PATH]

The contact's derivations (with their verification) are done first and not
timed; "state@30" is the median over a = 0.05, 0.1, 0.2 of ``md.state(a, 30)``
(law compiled once), with its digits against the state at 45 digits;
"pull-off" is ``md.pull_off_at(15)`` on a law already compiled.  Prints a
Markdown table; writes JSON (default: benchmarks/maugis_everywhere_results.json).
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import sys
import time

import mpmath
import sympy as sp

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
import linecontact_sym as lcs  # noqa: E402
from linecontact_sym.core import symbols as S  # noqa: E402
from linecontact_sym.method.verification import digits_agreeing  # noqa: E402

x, R = S.x, S.R
PROFILES = {
    "parabola": (lcs.parabola, {}),
    "exact cylinder": (lcs.exact_cylinder, {}),
    "R (cosh(x/R) - 1)": (lambda: lcs.LineContact(R * (sp.cosh(x / R) - 1), name="cosh"), {}),
    "Gaussian bump R (1 - exp(-x^2/R^2))": (lambda: lcs.LineContact(R * (1 - sp.exp(-x**2 / R**2)),
                                                                    name="Gaussian bump"), {}),
    "rounded punch (b = R/10)": (lcs.rounded_punch, {"b": sp.Rational(1, 10)}),
}
A_VALUES = ("0.05", "0.1", "0.2")


def row(name, mk, params, s0):
    md = mk().maugis_dugdale()
    vals = dict(E_star=1, gamma=sp.Rational(1, 10**4), R=1, sigma_0=s0, **params)
    t0 = time.perf_counter()
    st = md.state("0.15", 30, **vals)     # derivations and the law compiled once
    t_setup = time.perf_counter() - t0
    times, dig = [], []
    for a in A_VALUES:
        t0 = time.perf_counter()
        st = md.state(a, 30, **vals)
        times.append(time.perf_counter() - t0)
        ref = md.state(a, 45, **vals)
        with mpmath.workdps(50):
            dig.append(min(digits_agreeing(st.force, ref.force), digits_agreeing(st.c_D, ref.c_D)))
    t0 = time.perf_counter()
    po = md.pull_off_at(15, **vals)
    t_po = time.perf_counter() - t0
    closed = ", ".join(f"{k} {'closed' if v else 'quadrature'}" for k, v in st.closed.items())
    return {"profile": name, "closed": closed, "all_closed": all(st.closed.values()),
            "setup_s": round(t_setup, 1), "state30_median_s": round(statistics.median(times), 3),
            "state30_digits": round(min(dig), 1), "pull_off15_s": round(t_po, 1),
            "pull_off": mpmath.nstr(po.force, 15), "kind": po.kind, "half_width": mpmath.nstr(po.half_width, 8)}


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--sigma0", default="1/40")
    ap.add_argument("--only", default=None, help="a substring of one profile's name")
    ap.add_argument("--json", default=os.path.join(os.path.dirname(__file__), "maugis_everywhere_results.json"))
    args = ap.parse_args(argv)
    s0 = sp.Rational(args.sigma0)
    rows = [row(name, mk, p, s0) for name, (mk, p) in PROFILES.items() if args.only is None or args.only in name]
    print(f"sigma_0 = {s0}, E* = 1, w = 1e-4, R = 1; load {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    print("| profile | non-adhesive parts | state@30 median s | digits | pull-off@15 s | P_min | kind | a_po |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['profile']} | {r['closed']} | {r['state30_median_s']} | {r['state30_digits']} | "
              f"{r['pull_off15_s']} | {r['pull_off']} | {r['kind']} | {r['half_width']} |")
    meta = {"machine": platform.platform(), "python": platform.python_version(), "cpus": os.cpu_count(),
            "load": os.getloadavg(), "when": time.strftime("%Y-%m-%d %H:%M"), "sigma0": str(s0)}
    with open(args.json, "w") as fh:
        json.dump({"meta": meta, "rows": rows}, fh, indent=1)


if __name__ == "__main__":
    main()
