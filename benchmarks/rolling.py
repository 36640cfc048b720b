"""Steady rolling with traction (issue 40): speed and accuracy.

    python benchmarks/rolling.py [--json PATH]

Rows:

* a rolling state (``r.state_at``: the stick zone, the creepage, the
  admissibility check on 801 points) for a closed profile (Carter, x^4) and
  one with numbers only (k (cosh(x/l) - 1)), warm (the derivations done);
* the traction of that state at 10^6 points (float64);
* the creepage-force curve at 41 points;
* the extremes: the state's creepage at Q/(mu P) = 1e-12 ... 1 - 1e-12 against
  Carter's formula (mu a/R)(1 - sqrt(1 - Q/(mu P))) at 50 digits (correct
  digits), and the float64 curve against it (worst relative error).
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import time

import mpmath
import numpy as np
import sympy as sp

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
import linecontact_sym as lcs  # noqa: E402

k, ell = sp.symbols("k l", positive=True)
RATIOS = ["0", "1e-12", "1e-6", "0.5", "0.64", "1 - 1e-6", "1 - 1e-12", "1"]


def best(fn, repeat=3):
    ts = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t)
    return min(ts)


def profiles():
    return [("Carter x^2/(2R)", lcs.parabola(verify=False), dict(E_star=1, R=1)),
            ("k x^4", lcs.LineContact(k * lcs.x**4, verify=False), dict(E_star=1, k=1)),
            ("k (cosh(x/l) - 1)", lcs.LineContact(k * (sp.cosh(lcs.x / ell) - 1), verify=False, budget=2),
             dict(E_star=1, k=1, l=0.5))]


def extremes():
    """Carter (E* = 113888.9, R = 500, a = 1, mu = 0.3) at the extreme ratios."""
    r = lcs.parabola(verify=False).rolling(0.3)
    E = sp.Rational("113888.9")
    P = sp.pi * E / 2000
    rows = []
    for text in RATIOS:
        ratio = 1 - sp.Rational(text[4:]) if text.startswith("1 - ") else sp.Rational(text)
        st = r.state_at(Q=ratio * sp.Rational(3, 10) * P, a=1, E_star=E, R=500)
        exact = sp.Rational(3, 10) / 500 * (1 - sp.sqrt(1 - ratio))
        with mpmath.workdps(50):
            ref = mpmath.mpf(sp.N(exact, 60))
            got = mpmath.mpf(st.creepage)
            err = abs(got - ref)
            dig = 50.0 if err == 0 else float(-mpmath.log10(err / ref)) if ref != 0 else float(-mpmath.log10(err))
        rows.append({"Q/(mu P)": text, "creepage": mpmath.nstr(st.creepage, 20), "correct_digits": min(dig, 50.0),
                     "stick": [mpmath.nstr(v, 15) for v in st.stick]})
    q, xi = r.creepage_curve(201, a=1, E_star=113888.9, R=500)
    exact = 0.3 / 500 * (1 - np.sqrt(np.clip(1 - q, 0, None)))
    rel = np.max(np.abs(xi - exact)[1:] / exact[1:])
    return rows, float(rel)


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--json", default=os.path.join(os.path.dirname(__file__), "rolling_results.json"))
    args = ap.parse_args(argv)
    x = np.linspace(-1, 1, 10**6)
    rows = []
    for name, c, vals in profiles():
        r = c.rolling(0.3)
        t = time.perf_counter()
        P = float(r.state_at(Q=0, a=1, **vals).P)
        cold = time.perf_counter() - t
        st = r.state_at(Q=0.5 * 0.3 * P, a=1, **vals)
        t_state = best(lambda: r.state_at(Q=0.5 * 0.3 * P, a=1, **vals))
        t_q = best(lambda: st.traction(x), 2)
        t_curve = best(lambda: r.creepage_curve(41, a=1, **vals))
        rows.append({"profile": name, "closed": bool(st.closed), "first_state_s": cold, "state_s": t_state,
                     "traction_1e6_s": t_q, "curve_41_s": t_curve, "creepage_at_half": float(st.creepage)})
        print(f"| {name} | {'closed' if st.closed else 'numbers'} | {cold:.2f} s | {t_state * 1e3:.0f} ms | "
              f"{t_q:.2f} s | {t_curve * 1e3:.0f} ms |", flush=True)
    ext, rel = extremes()
    for e in ext:
        print(f"| Q/(mu P) = {e['Q/(mu P)']} | creepage {e['creepage']} | {e['correct_digits']:.1f} digits |")
    print(f"float64 creepage curve (201 points) vs Carter: worst relative error {rel:.2e}")
    with open(args.json, "w") as fh:
        json.dump({"rows": rows, "extremes": ext, "curve_float64_worst_rel": rel}, fh, indent=2)
    print(f"saved {args.json}")


if __name__ == "__main__":
    main()
