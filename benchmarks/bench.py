"""Speed versus accuracy of every backend, per seed law (issue 5).

    python benchmarks/bench.py [--quick] [--json PATH]

For the force law P(a) of each seed law (parabola, power law n = 3/2 and 3,
wedge, worn cylinder, exact cylinder) it measures

* the NumPy float64 export (stable form; vectorised, time per point over
  10^6 points),
* a hand-written SciPy expression of the same stable formula (reference for
  the "within 1.5x" target),
* the mpmath closed form at 15 / 30 / 50 / 100 digits (per scalar call),
* mpmath quadrature of the defining integral, Eq. (10*), at 15 digits (the
  engine's own reference quadrature),
* ``scipy.integrate.quad`` of Eq. (10*) (algebraic weight for the
  1/sqrt(a - t) end point; pieces split at the profile's breakpoints),
* the python-flint Arb certified enclosure at 15 and 50 digits,
* the worst float64 error on the documented grid of extreme arguments
  (``benchmarks/extremes.py``, shared with ``tests/test_extremes.py``), in
  units of eps * max(1, kappa),

with the median time per evaluation and the correct digits (minimum over the
sample points) against a 100-digit mpmath reference (the derived closed form
evaluated with 130 digits of working precision); plus the derivation time
(cold: first derivation in a fresh process-wide contact; cached: repeated
call) and the export time (stabilise + lambdify), and the 10^6-point timing
of the pressure too.  Prints a Markdown table and saves everything as JSON:
by default to ``benchmarks/results.json`` (the tracked record of a full run);
``--quick`` runs write to a file in the temporary directory instead, so a
quick check never overwrites the record (``--json PATH`` chooses the file).
"""
from __future__ import annotations

import argparse
import json
import math
import os
import platform
import statistics
import sys
import tempfile
import time

import mpmath
import numpy as np
import scipy
import scipy.integrate as si
import scipy.special as sc
import sympy as sp

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
import linecontact_sym as lcs  # noqa: E402
from linecontact_sym.core import symbols as S  # noqa: E402
from linecontact_sym.numeric.certified import arb_callable  # noqa: E402
from linecontact_sym.numeric.accuracy import audit  # noqa: E402
from linecontact_sym.numeric.exports import lambdify_mpmath, stable_form  # noqa: E402
from linecontact_sym.numeric.functions import make_callable  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from extremes import extreme_points  # noqa: E402

E_VAL, C_VAL, TH_VAL = 1.7, 1.3, 0.3


def hand_written():
    """The stable formulas typed by hand in NumPy/SciPy (the same formulas the
    export evaluates), for the 'within 1.5x' target."""
    k32 = math.sqrt(math.pi) * math.gamma(0.25) / (4 * math.gamma(0.75))
    return {
        "parabola": lambda a, E, R: np.pi * E * a**2 / (4 * R),
        "power law n=3/2": lambda a, E, c: k32 * E * c * a**1.5,
        "power law n=3": lambda a, E, c: 2 * E * c * a**3,
        "wedge": lambda a, E, theta: E * a * np.tan(theta),
        "worn cylinder": lambda a, E, R, b: np.where(
            a <= b, 0.0, E * (a**2 * np.arctan(np.sqrt((a - b) * (a + b)) / b)
                              + b * np.sqrt((a - b) * (a + b))) / (2 * R)),
        "exact cylinder": lambda a, E, R: E * a**2 * sc.elliprd(0, (R - a) * (R + a) / R**2, 1) / (3 * R),
    }


LAWS = {
    "parabola": (lambda: lcs.parabola(), {"R": 1.0}),
    "power law n=3/2": (lambda: lcs.power_law(n=sp.Rational(3, 2)), {"c": C_VAL}),
    "power law n=3": (lambda: lcs.power_law(n=3), {"c": C_VAL}),
    "wedge": (lambda: lcs.wedge(), {"theta": TH_VAL}),
    "worn cylinder": (lambda: lcs.worn_cylinder(budget=3), {"R": 1.0}),
    "exact cylinder": (lambda: lcs.exact_cylinder(budget=3), {"R": 1.0}),
}


def sample_points(name, n, rng):
    a = np.exp(rng.uniform(np.log(1e-3), np.log(0.9), n))
    pts = {"a": a, "E_star": np.full(n, E_VAL)}
    if name in ("parabola", "worn cylinder", "exact cylinder"):
        pts["R"] = np.ones(n)
    if name.startswith("power"):
        pts["c"] = np.full(n, C_VAL)
    if name == "wedge":
        pts["theta"] = np.full(n, TH_VAL)
    if name == "worn cylinder":
        pts["b"] = a * rng.uniform(0.05, 0.95, n)
    return pts


def median_time(fn, repeat, number=1):
    ts = []
    for _ in range(repeat):
        t = time.perf_counter()
        for _ in range(number):
            fn()
        ts.append((time.perf_counter() - t) / number)
    return statistics.median(ts)


def digits(values, refs):
    worst = 0.0
    with mpmath.workdps(110):
        for v, r in zip(values, refs):
            if r == 0:
                e = 0 if v == 0 else 1
            else:
                e = float(abs((mpmath.mpf(v) - r) / r)) if not isinstance(v, mpmath.mpf) else \
                    float(abs((v - r) / r))
            worst = max(worst, e)
    return 120.0 if worst == 0 else min(120.0, -math.log10(worst))


def quad_eq10(profile, fixed):
    """scipy.integrate.quad of Eq. (10*): E* int_0^a t f'(t)/sqrt(a^2 - t^2) dt,
    as (a - t)^(-1/2) weight times t f'(t)/sqrt(a + t), split at breakpoints."""
    pieces = []
    for pc in profile.pieces:
        fp = sp.lambdify(S.x, pc.derivative.xreplace({k: v for k, v in fixed.items()}), "math")
        lo = float(pc.lo.xreplace(fixed))
        hi = float(pc.hi.xreplace(fixed)) if pc.hi != sp.oo else math.inf
        pieces.append((fp, lo, hi))

    def P(a, E):
        total = 0.0
        for fp, lo, hi in pieces:
            if lo >= a:
                continue
            top = min(hi, a)
            if top < a:
                total += si.quad(lambda t: t * fp(t) / math.sqrt(a * a - t * t), lo, top)[0]
            else:
                total += si.quad(lambda t: t * fp(t) / math.sqrt(a + t), lo, a,
                                 weight="alg", wvar=(0.0, -0.5))[0]
        return E * total
    return P


def bench_law(name, quick, rng, results):
    make, fixed_num = LAWS[name]
    row = {"law": name}
    t = time.perf_counter()
    c = make()
    d = c.derivation("force")
    row["derive_cold_s"] = time.perf_counter() - t
    row["derive_cached_s"] = median_time(lambda: c.derivation("force"), 5, 1000)
    t = time.perf_counter()
    f64 = make_callable(d, "numpy")
    row["export_s"] = time.perf_counter() - t
    row["formula"] = str(d.expr)
    row["stable_formula"] = str(stable_form(d).expr)
    names = [s.name for s in d.variables_all]

    npts = 200 if not quick else 60
    pts = sample_points(name, npts, rng)
    ref_f = lambdify_mpmath(d.expr, d.variables_all, stable=False)
    refs = []
    with mpmath.workdps(130):   # 100 correct digits even where the raw closed form cancels
        for i in range(npts):
            refs.append(ref_f(*[mpmath.mpf(float(pts[n][i])) for n in names]))
    scalar_pts = [{n: float(pts[n][i]) for n in names} for i in range(npts)]
    rows = []

    # float64 export, vectorised
    big = 10**6 if not quick else 10**5
    bp = sample_points(name, big, rng)
    bargs = {n: bp[n] for n in names}
    hw = hand_written()[name]
    order = {"parabola": ["a", "E_star", "R"], "power law n=3/2": ["a", "E_star", "c"],
             "power law n=3": ["a", "E_star", "c"], "wedge": ["a", "E_star", "theta"],
             "worn cylinder": ["a", "E_star", "R", "b"], "exact cylinder": ["a", "E_star", "R"]}[name]
    hargs = [bp[n] for n in order]
    f64(**bargs)
    hw(*hargs)
    # interleaved, so that both see the same machine load; the ratio is the
    # median of the per-pair ratios
    tvs, ths = [], []
    for _ in range(9 if not quick else 3):
        tvs.append(median_time(lambda: f64(**bargs), 1))
        ths.append(median_time(lambda: hw(*hargs), 1))
    tv, th = statistics.median(tvs), statistics.median(ths)
    vals = f64(**{n: pts[n] for n in names})
    rows.append(("NumPy float64 export (vectorised)", tv / big, digits(vals, refs)))
    row["float64_1e6_points_s"] = tv * (10**6 / big)
    rows.append(("hand-written SciPy, same stable formula", th / big,
                 digits(hw(*[pts[n] for n in order]), refs)))
    row["float64_over_handwritten"] = statistics.median([a_ / b_ for a_, b_ in zip(tvs, ths)])

    # mpmath closed form
    reps = 60 if not quick else 15
    sub = scalar_pts[:reps]
    for dps in (15, 30, 50, 100):
        fm = make_callable(d, "mpmath", dps=dps)
        tm = median_time(lambda: [fm(**p) for p in sub], 3) / len(sub)
        vals = [fm(**p) for p in scalar_pts[:40]]
        rows.append((f"mpmath closed form, {dps} digits", tm, min(digits(vals, refs[:40]), dps + 0.0)))
        row[f"mpmath_{dps}_s"] = tm

    # mpmath quadrature of the defining integral (engine's reference), 15 digits
    qs = scalar_pts[:8 if not quick else 3]

    def mpq(p):
        return d.reference({s: sp.Float(p[s.name], 20) for s in d.variables_all}, 15)
    tq = median_time(lambda: [mpq(p) for p in qs], 1) / len(qs)
    rows.append(("mpmath quadrature of Eq. (10*), 15 digits", tq,
                 digits([mpq(p) for p in qs], refs[:len(qs)])))

    # scipy.integrate.quad of Eq. (10*)
    fixed_syms = {s: sp.Float(v) for s, v in ((sym, fixed_num.get(sym.name)) for sym in c.params) if v is not None}
    if name == "worn cylinder":
        fixed_syms = {}
    qsub = scalar_pts[:reps]
    if name == "worn cylinder":
        def spq(p):
            prof = c.profile
            return quad_eq10(prof, {S.R: p["R"], S.b: p["b"]})(p["a"], p["E_star"])
    else:
        Pq = quad_eq10(c.profile, fixed_syms)

        def spq(p):
            return Pq(p["a"], p["E_star"])
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        tsq = median_time(lambda: [spq(p) for p in qsub], 3) / len(qsub)
        sqv = [spq(p) for p in scalar_pts]
    rows.append(("scipy.integrate.quad of Eq. (10*)", tsq, digits(sqv, refs)))
    row["scipy_quad_s"] = tsq

    # arb certified
    g = arb_callable(stable_form(d).expr, d.variables_all)
    for dps in (15, 50):
        ta = median_time(lambda: [g([p[n] for n in names], dps=dps) for p in sub], 3) / len(sub)
        encs = [g([p[n] for n in names], dps=dps) for p in scalar_pts[:40]]
        with mpmath.workdps(110):
            contained = all(e.lower <= r <= e.upper for e, r in zip(encs, refs[:40]))
        dg = digits([e.mid for e in encs], refs[:40])
        rows.append((f"Arb certified, {dps} digits" + ("" if contained else " (NOT CONTAINED)"), ta,
                     min(dg, 120.0)))
        row[f"arb_{dps}_s"] = ta

    # the documented grid of extreme arguments: worst error / (eps * max(1, kappa))
    fm0 = lambdify_mpmath(d.expr, d.variables_all, stable=False)
    grid = extreme_points(names, "force", "small" if quick else "full")
    recs = audit(f64, lambda **kw: fm0(*[kw[n] for n in names]), grid, dps=100, kappa="mp")
    worst = max(recs, key=lambda r: r.ulps)
    row["extreme_grid_points"] = len(recs)
    row["extreme_grid_worst_eps_kappa"] = worst.ulps
    row["extreme_grid_worst_at"] = worst.point

    row["float64_digits"] = rows[0][2]
    row["scipy_quad_digits"] = digits(sqv, refs)
    row["float64_speedup_vs_quad"] = tsq / (tv / big)
    row["rows"] = [{"backend": b, "seconds_per_eval": t_, "correct_digits": dg} for b, t_, dg in rows]

    # pressure: 10^6 points of the export (closed form or quadrature)
    dp = c.derivation("pressure")
    fp64 = make_callable(dp, "numpy")
    np_pts = big if dp.closed_form else (10**4 if not quick else 2000)
    pp = sample_points(name, np_pts, rng)
    pp["x"] = pp["a"] * rng.uniform(0, 1, np_pts)
    pargs = {s.name: pp[s.name] for s in dp.variables_all}
    fp64(**pargs)
    tpp = median_time(lambda: fp64(**pargs), 3 if dp.closed_form else 1)
    row["pressure_closed_form"] = dp.closed_form
    row["pressure_1e6_points_s"] = tpp * (10**6 / np_pts)
    results[name] = row
    return row


def fmt_time(t):
    if t < 1e-6:
        return f"{t * 1e9:.0f} ns"
    if t < 1e-3:
        return f"{t * 1e6:.1f} us"
    if t < 1:
        return f"{t * 1e3:.2f} ms"
    return f"{t:.2f} s"


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="fewer points and repetitions")
    ap.add_argument("--json", default=None,
                    help="output file (default: benchmarks/results.json; with --quick a file in the "
                         "temporary directory, so the tracked record is not overwritten)")
    ap.add_argument("--laws", nargs="*", default=list(LAWS))
    args = ap.parse_args(argv)
    if args.json is None:
        args.json = os.path.join(tempfile.gettempdir(), "linecontact_sym_bench_quick.json") if args.quick \
            else os.path.join(os.path.dirname(__file__), "results.json")
    rng = np.random.default_rng(2017)
    results = {}
    lines = []
    for name in args.laws:
        row = bench_law(name, args.quick, rng, results)
        lines.append(f"\n### {name}\n")
        lines.append(f"P(a) = `{row['formula']}`  \nstable form: `{row['stable_formula']}`  \n"
                     f"derivation: cold {row['derive_cold_s']:.2f} s, cached {fmt_time(row['derive_cached_s'])}; "
                     f"export (stabilise + lambdify) {row['export_s']:.2f} s; "
                     f"extreme grid ({row['extreme_grid_points']} points): worst float64 error "
                     f"{row['extreme_grid_worst_eps_kappa']:.2f} eps*max(1, kappa)\n")
        lines.append("| backend | median time / evaluation | correct digits |")
        lines.append("|---|---:|---:|")
        for r in row["rows"]:
            dg = r["correct_digits"]
            lines.append(f"| {r['backend']} | {fmt_time(r['seconds_per_eval'])} | "
                         f"{'all' if dg >= 120 else f'{dg:.1f}'} |")
        print("\n".join(lines[-(len(row['rows']) + 4):]), flush=True)

    # targets
    tg = []
    speed = {k: v["float64_speedup_vs_quad"] for k, v in results.items()}
    more_digits = {k: v["float64_digits"] > v["scipy_quad_digits"] for k, v in results.items()}
    t1 = all(s >= 300 for s in speed.values()) and all(more_digits.values())
    tg.append(("float64 export >= 300x faster per point than scipy.integrate.quad of Eq. (10), "
               "with more correct digits", t1,
               ", ".join(f"{k}: {s:,.0f}x, {results[k]['float64_digits']:.1f} vs "
                         f"{results[k]['scipy_quad_digits']:.1f} digits" for k, s in speed.items())))
    ratio = {k: v["float64_over_handwritten"] for k, v in results.items()}
    tg.append(("float64 export within 1.5x of a hand-written SciPy expression of the same stable formula",
               all(r <= 1.5 for r in ratio.values()),
               ", ".join(f"{k}: {r:.2f}x" for k, r in ratio.items())))
    m50 = {k: v["mpmath_50_s"] for k, v in results.items()}
    tg.append(("50-digit closed-form evaluation under 1 ms per point", all(t < 1e-3 for t in m50.values()),
               ", ".join(f"{k}: {fmt_time(t)}" for k, t in m50.items())))
    t6 = {k: v["float64_1e6_points_s"] for k, v in results.items()}
    tg.append(("10^6 points of any seed law (force) in under 1 s", all(t < 1 for t in t6.values()),
               ", ".join(f"{k}: {t:.3f} s" for k, t in t6.items())))
    p6 = {k: (v["pressure_1e6_points_s"], v["pressure_closed_form"]) for k, v in results.items()}
    tg.append(("10^6 points of the pressure in under 1 s", all(t < 1 for t, _ in p6.values()),
               ", ".join(f"{k}: {t:.3f} s{'' if cf else ' (quadrature, no closed form)'}"
                         for k, (t, cf) in p6.items())))
    out = ["\n### Targets (issue 5)\n", "| target | status | measured |", "|---|---|---|"]
    for txt, ok, det in tg:
        out.append(f"| {txt} | {'met' if ok else 'NOT met'} | {det} |")
    print("\n".join(out))
    env = {"python": platform.python_version(), "numpy": np.__version__, "scipy": scipy.__version__,
           "sympy": sp.__version__, "mpmath": mpmath.__version__, "machine": platform.machine(),
           "processor": platform.processor(), "quick": args.quick}
    with open(args.json, "w") as fh:
        json.dump({"environment": env, "laws": results,
                   "targets": [{"target": t_, "met": ok, "measured": det} for t_, ok, det in tg],
                   "table_markdown": "\n".join(lines + out)}, fh, indent=2, default=str)
    print(f"\nsaved {args.json}")


if __name__ == "__main__":
    main()
