"""Asymmetric line contacts (issue 39): the rows a user waits for.

    python benchmarks/asymmetric.py

* a contact state at a given load and tilt (and moment), cold (the engine's
  derivations of the even and odd parts, in a fresh cache) and warm, for a
  profile whose parts close (x^2/2 + x^3/10) and one whose pressure the
  engine leaves as an Integral (exp(x) - 1 - x, Bessel I force laws);
* the pressure at 10^6 points (float64) against the load: the trapezoidal
  integral of p over the contact must give P (the force law), and its time
  against one call of the load P(e, a);
* the flat punch at the complete/incomplete transition.

Every row states the machine's load average (the machine is shared).
"""
from __future__ import annotations

import os
import tempfile
import time

os.environ.setdefault("LINECONTACT_SYM_CACHE", tempfile.mkdtemp(prefix="asym-bench-"))

import mpmath  # noqa: E402
import numpy as np  # noqa: E402
import sympy as sp  # noqa: E402

import linecontact_sym as lcs  # noqa: E402


def row(name, seconds, extra=""):
    print(f"{name:58s} {seconds:8.3f} s  {extra}  (load {os.getloadavg()[0]:.1f})")


def main():
    x = lcs.x_real
    for label, f in (("x^2/2 + x^3/10", x**2 / 2 + x**3 / 10), ("exp(x) - 1 - x", sp.exp(x) - 1 - x)):
        t = time.perf_counter()
        c = lcs.LineContact(f, symmetric=False)
        s = c.contact_at(P=1, theta="0.1", E_star=2)
        row(f"{label}: contact_at(P=1, theta=0.1), cold", time.perf_counter() - t)
        t = time.perf_counter()
        s = c.contact_at(P=1, moment="0.05", E_star=2)
        row(f"{label}: contact_at(P=1, moment=0.05), warm", time.perf_counter() - t)
        xs = np.linspace(float(s.left), float(s.right), 10**6)
        if label.startswith("x^2"):
            s.pressure(xs[:10])                      # compile once
            t = time.perf_counter()
            p = s.pressure(xs)
            dt = time.perf_counter() - t
            n = c.core.numbers(E_star=2)
            with mpmath.workdps(15):
                n.P(s.e, s.a)                        # compile once
                t = time.perf_counter()
                n.P(s.e, s.a)
            dP = time.perf_counter() - t
            row(f"{label}: pressure at 10^6 points (float64)", dt,
                f"int p dx = {np.trapezoid(p, xs):.9f} (P = 1); one P(e, a): {dP * 1e6:.0f} us")
        else:
            t = time.perf_counter()
            with mpmath.workdps(15):
                v = s.pressure(s.e + s.a / 3)
            row(f"{label}: pressure at one point (Eq. 12 quadrature)", time.perf_counter() - t, f"p = {v}")
    punch = lcs.flat_punch(1)
    t = time.perf_counter()
    s = punch.contact_at(P=1, moment="0.5", E_star=1)
    row("flat punch at the transition M = P w/2", time.perf_counter() - t, f"{s.regime}, edges {s.edges}")


if __name__ == "__main__":
    main()
