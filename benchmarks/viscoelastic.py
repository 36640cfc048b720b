"""Timings of the viscoelastic line contact (issue 41): a closed force
history, a numeric one (a profile whose history integral has no closed form)
and creep (a step load, and Ting's receding phase under a load cycle).

    PYTHONPATH=. python benchmarks/viscoelastic.py

Prints one row per case: what, seconds (cold: derivation included; warm:
the evaluation alone), the value.  Digits: the numbers are tanh-sinh
quadratures at dps + 10 of positive integrands; the tests check them against
independent quadrature (12 digits) and a boundary-element solution.
"""
from __future__ import annotations

import time

import sympy as sp

import linecontact_sym as lcs

t = lcs.t


def timed(fn):
    t0 = time.perf_counter()
    v = fn()
    return time.perf_counter() - t0, v


def main():
    cycle = sp.Piecewise((t / 10, t <= 1), ((2 - t) / 10, t <= 2), (0, True))
    rows = []
    v = lcs.parabola(verify=False).viscoelastic(lcs.maxwell(E0=2, tau=1))
    dt, F = timed(lambda: v.force_history(cycle))
    rows.append(("closed force history (parabola, Maxwell, ramp-recede): derive", dt, str(F)[:60]))
    dt, val = timed(lambda: sp.N(F.xreplace({t: sp.Rational(3, 2), lcs.R: 1}), 30))
    rows.append(("  ... evaluated at t = 1.5, 30 digits (SymPy evalf)", dt, val))
    cyl = lcs.exact_cylinder(verify=False).viscoelastic(lcs.standard_linear_solid(E0=3, E_inf=1, tau=sp.Rational(1, 2)))
    dt, F = timed(lambda: cyl.force_history(cycle))
    rows.append(("exact cylinder, SLS: force history (Integral left)", dt, F.has(sp.Integral)))
    dt, val = timed(lambda: cyl.evaluate_at("force", sp.Rational(3, 2), cycle, dps=30, R=1))
    rows.append(("  ... evaluate_at t = 1.5, 30 digits (cold)", dt, val))
    dt, val = timed(lambda: cyl.evaluate_at("force", sp.Rational(7, 5), cycle, dps=30, R=1))
    rows.append(("  ... evaluate_at t = 1.4, 30 digits (warm)", dt, val))
    s = lcs.parabola(verify=False).viscoelastic(lcs.standard_linear_solid(E0=3, E_inf=1, tau=sp.Rational(1, 2)))
    dt, a_t = timed(lambda: s.half_width_history(sp.Integer(2)))
    rows.append(("creep, step load (parabola, SLS): a(t) closed form", dt, a_t))
    dt, val = timed(lambda: s.half_width_at(2, sp.Integer(2), dps=30, R=1))
    rows.append(("  ... half_width_at t = 2, 30 digits", dt, val))
    m = lcs.parabola(verify=False).viscoelastic(lcs.maxwell(E0=1, tau=1))
    load = sp.Piecewise((t, t <= 1), (1 - 3 * (t - 1), True))
    dt, val = timed(lambda: m.half_width_at(sp.Rational(6, 5), load, dps=15, R=1))
    rows.append(("creep, Ting receding phase (Maxwell, load cycle), t = 1.2, 15 digits", dt, val))
    # accuracy on request (v.evaluate): float64 / mpmath / Arb by rtol, the Arb enclosure of an
    # unevaluated history integral beyond float64 (issue 41 follow-up)
    tau, r = sp.symbols("tau r", positive=True)
    sym = lcs.parabola(verify=False).viscoelastic(lcs.maxwell(E0=2, tau=tau))
    pt = dict(t=1e-9, tau=1.0, r=0.1, R=1.0)
    sym.evaluate("force", r * t, rtol=1e-12, **pt)      # derive and compile once
    for label, kw in (("rtol 1e-12", dict(rtol=1e-12)), ("rtol 1e-30", dict(rtol=1e-30)),
                      ("certified, 25 digits", dict(certified=True, dps=25))):
        dt, ev = timed(lambda kw=kw: sym.evaluate("force", r * t, **kw, **pt))
        rows.append((f"  evaluate force at t/tau = 1e-9, {label} (warm)", dt, f"{ev.value} via {ev.path}"))
    gauss = lcs.parabola(verify=False).viscoelastic(lcs.Material(2 * sp.exp(-(t / tau)**2)))
    dt, ev = timed(lambda: gauss.evaluate("force", t / 10, rtol=1e-20, t=0.7, tau=1.0, R=1.0))
    rows.append(("Gaussian relaxation (no closed history): evaluate rtol 1e-20 (cold)", dt, f"{ev.value} via {ev.path}"))
    for what, sec, value in rows:
        print(f"{what:72s} {sec:8.3f} s   {value}")


if __name__ == "__main__":
    main()
