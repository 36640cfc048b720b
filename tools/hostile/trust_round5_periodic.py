"""Hostile sweep of issue 42 (round 5), the part of helper trustC: periodic
arrays, certified evaluate, budgets and float64 exports at extremes.

Run (from a checkout; the package imported from it)::

    PYTHONPATH=$PWD python tools/hostile/trust_round5_periodic.py [--group G] [--verbose]

Each case is tried as a user would, and judged against a reference computed
here (mpmath at 60 digits of the unrewritten formula, Johnson's and
Westergaard's printed equations, own quadratures): a case is ok when it
gives a right answer whose stated error holds, or, where no answer exists,
a package error (``LineContactError``) within the case's time limit.  A
foreign exception, a hang (time limit, SIGALRM), a wrong number or an error
smaller than the true one is not ok.  Prints per group: cases, ok, and the
failures; the last line ``cases N ok K``.  Groups: exports (evaluate's
stated error, and the float64 export itself within 8 eps kappa), honesty,
enclosures, periodic.  About 3-6 minutes on a loaded 2-core machine.
"""
from __future__ import annotations

import argparse

import mpmath
import numpy as np
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core.errors import LineContactError
from harness import refused, run_case  # tools/hostile/, beside this file

x, a, E = lcs.x, lcs.a, lcs.E_star
h, L, R, th = sp.symbols("h L R theta", positive=True)
EPS = 2.0**-52


def agree(u, v):
    with mpmath.workdps(60):
        u, v = mpmath.mpf(u), mpmath.mpf(v)
        return mpmath.inf if u == v else -mpmath.log10(abs(u - v) / abs(v))


# ---------------------------------------------------------------- contacts (built once)
_C = {}


def contact(name):
    if name not in _C:
        _C[name] = {
            "sinusoid": lambda: lcs.LineContact(h * (1 - sp.cos(2 * sp.pi * x / L)), period=L),
            "sin4": lambda: lcs.LineContact(h * sp.sin(sp.pi * x / L)**4, period=L),
            "wedge": lambda: lcs.LineContact(sp.tan(th) * x, period=L),
            "cosh": lambda: lcs.LineContact(sp.cosh(x) - 1),
            "parabola": lambda: lcs.parabola(),
            "cylinder": lambda: lcs.exact_cylinder(),
        }[name]()
    return _C[name]


# ---------------------------------------------------------------- references (unrewritten, 60 digits)
def ref_periodic(name, q, A, X, Lv, Ev=2.0, hv=0.3, tv=0.2):
    with mpmath.workdps(60):
        A, X, Lv, Ev, hv, tv = map(mpmath.mpf, (A, X, Lv, Ev, hv, tv))
        S, s, c = mpmath.sin(mpmath.pi * A / Lv), mpmath.sin(mpmath.pi * X / Lv), mpmath.cos(mpmath.pi * X / Lv)
        if name == "sinusoid":
            return (mpmath.pi * Ev * hv * S**2 if q == "force"
                    else 2 * mpmath.pi * Ev * hv * mpmath.sqrt(S**2 - s**2) * c / Lv)
        if name == "sin4":
            return (3 * mpmath.pi * Ev * hv * S**4 / 4 if q == "force"
                    else mpmath.pi * Ev * hv * mpmath.sqrt(S**2 - s**2) * (S**2 + 2 * s**2) * c / Lv)
        if name == "wedge":      # Eq. (10*) of the kernel twin by quadrature
            k = mpmath.tan(tv) * Lv / mpmath.pi
            return Ev * k * mpmath.quad(lambda p: S * mpmath.sin(p) / mpmath.sqrt(1 - S**2 * mpmath.sin(p)**2),
                                        [0, mpmath.pi / 2])


def exports_cases():
    out = []
    grid_a = [1e-8, 0.1, 0.25, 0.5 - 1e-4, 0.5 - 1e-7, 0.5 - 1e-10]
    for name in ("sinusoid", "sin4", "wedge"):
        for A in grid_a:
            qs = [("force", None)] + ([("pressure", r) for r in (0.0, 0.5, 0.999999, 1 - 1e-9)]
                                      if name != "wedge" else [])
            for q, r in qs:
                def case(name=name, A=A, q=q, r=r):
                    c = contact(name)
                    vals = {"a": A, "L": 1.0, "E_star": 2.0}
                    vals.update({"h": 0.3} if name != "wedge" else {"theta": 0.2})
                    if r is not None:
                        vals["x"] = r * A
                    res = c.evaluate(q, rtol=1e-10, **vals)
                    ref = ref_periodic(name, q, A, vals.get("x", 0.0), 1.0)
                    with mpmath.workdps(60):
                        err = abs(mpmath.mpf(res.value) - ref)
                        ok = err <= abs(res.error) * 1.001 + 1e-300 and err <= 1e-10 * abs(ref) * 1.001
                    return ok, f"value {res.value} ref {mpmath.nstr(ref, 17)} err {mpmath.nstr(err, 3)} " \
                               f"stated {float(res.error):.2e} via {res.path}"
                out.append((f"{name} {q} 2a/L={2 * A:.10g}" + (f" x/a={r}" if r is not None else ""), case, 120))

                def export(name=name, A=A, q=q, r=r):
                    """The float64 export itself: within 8 eps max(1, kappa) of the unrewritten formula
                    at 60 digits, kappa its componentwise condition number in a, x, L (60-digit differences)."""
                    from linecontact_sym.numeric.functions import make_callable
                    c = contact(name)
                    vals = {"a": A, "L": 1.0, "E_star": 2.0}
                    vals.update({"h": 0.3} if name != "wedge" else {"theta": 0.2})
                    if r is not None:
                        vals["x"] = r * A
                    v = float(np.asarray(make_callable(c.derivation(q), "numpy")(**vals)))
                    X = vals.get("x", 0.0)
                    ref = ref_periodic(name, q, A, X, 1.0)
                    with mpmath.workdps(60):
                        if ref == 0:
                            return abs(v) < 1e-290, f"{v} (ref 0)"
                        kappa = mpmath.mpf(1)
                        hh = mpmath.mpf(10)**-25
                        for arg in ("a", "x", "L"):
                            if arg == "x" and (r is None or X == 0):
                                continue
                            pt = {"a": mpmath.mpf(A), "x": mpmath.mpf(X), "L": mpmath.mpf(1)}
                            up, dn = dict(pt), dict(pt)
                            up[arg] *= 1 + hh
                            dn[arg] *= 1 - hh
                            if up["x"] > up["a"] or dn["x"] > dn["a"]:
                                up["x"] = min(up["x"], up["a"])
                                dn["x"] = min(dn["x"], dn["a"])
                            fu = ref_periodic(name, q, up["a"], up["x"], up["L"])
                            fd = ref_periodic(name, q, dn["a"], dn["x"], dn["L"])
                            kappa = max(kappa, abs((fu - fd) / (2 * hh * ref)))
                        rel = abs((mpmath.mpf(v) - ref) / ref)
                        ok = rel <= 8 * EPS * kappa
                    return ok, f"float64 {v!r} rel. error {mpmath.nstr(rel, 3)} = " \
                               f"{mpmath.nstr(rel / (EPS * kappa), 3)} eps kappa (kappa {mpmath.nstr(kappa, 3)})"
                out.append((f"export {name} {q} 2a/L={2 * A:.10g}" + (f" x/a={r}" if r is not None else ""),
                            export, 120))
    return out


def honesty_cases():
    """evaluate's stated error at the edges of float64 (force of the parabola and the cylinder)."""
    out = []
    pts = [(1e-300, 1.0), (1e-200, 1.0), (1e-160, 1e-20), (1e-160, 1.0), (1e-100, 1e100), (1e80, 1e90),
           (1e-40, 1e-30), (0.5, 1.0)]
    for name in ("parabola", "cylinder"):
        for A, Rv in pts:
            if name == "cylinder" and not A < Rv:
                continue
            for rtol in (1e-12, 1e-30):
                def case(name=name, A=A, Rv=Rv, rtol=rtol):
                    res = contact(name).evaluate("force", a=A, R=Rv, E_star=1.0, rtol=rtol)
                    with mpmath.workdps(60):
                        Am, Rm = mpmath.mpf(A), mpmath.mpf(Rv)
                        ref = (mpmath.pi * Am**2 / (4 * Rm) if name == "parabola" else
                               Am**2 / Rm * mpmath.quad(lambda p: mpmath.sin(p)**2 / mpmath.sqrt(1 - (Am / Rm)**2
                                                                                           * mpmath.sin(p)**2),
                                                        [0, mpmath.pi / 2]))    # (scaled: quad's tolerance is absolute)
                        err = abs(mpmath.mpf(res.value) - ref)
                        ok = res.value != 0 and err <= abs(mpmath.mpf(res.error)) * 1.001 and err <= rtol * ref
                    return ok, f"value {mpmath.nstr(mpmath.mpf(res.value), 8)} ref {mpmath.nstr(ref, 8)} " \
                               f"stated error {mpmath.nstr(mpmath.mpf(res.error), 3)} via {res.path}"
                out.append((f"{name} force a={A:g} R={Rv:g} rtol={rtol:g}", case, 120))
    # the pressure at the edge: an exact zero stays 0
    for name in ("parabola", "cylinder"):
        def case(name=name):
            res = contact(name).evaluate("pressure", a=0.5, x=0.5, R=1.0, E_star=1.0)
            return res.value == 0, f"{res.value} via {res.path}"
        out.append((f"{name} pressure at x = a", case, 60))
    return out


def _cosh_pressure(A, Xn, Xd):
    """Eq. (12) over the series of Eq. (10) for cosh(x) - 1 (E* = 1), x = Xn/Xd exactly."""
    with mpmath.workdps(60):
        A, X = mpmath.mpf(A), mpmath.mpf(Xn) / Xd
        W = [mpmath.sqrt(mpmath.pi) * mpmath.gamma((n + 1) / mpmath.mpf(2)) / (2 * mpmath.gamma(n / mpmath.mpf(2) + 1))
             for n in range(90)]
        coef = [(2 * j + 2) * W[2 * j + 2] / mpmath.factorial(2 * j + 1) for j in range(44)]
        dP = lambda s: mpmath.fsum(cf * s**(2 * j + 1) for j, cf in enumerate(coef))  # noqa: E731
        return mpmath.quad(lambda u: dP(X * mpmath.cosh(u)), [0, mpmath.acosh(A / X)]) / mpmath.pi


def enclosure_cases():
    out = []
    for (A, Xn, Xd) in [(1, 1, 3), (1, 1, 2), (sp.Rational(3, 2), 1, 5)]:
        for kind in ("rtol=1e-20", "rtol=1e-25", "rtol=1e-30", "certified dps=15", "certified dps=25"):
            def case(A=A, Xn=Xn, Xd=Xd, kind=kind):
                c = contact("cosh")
                X = sp.Rational(Xn, Xd)
                if kind.startswith("rtol"):
                    res = c.evaluate("pressure", a=A, x=X, E_star=1, rtol=float(kind.split("=")[1]))
                else:
                    res = c.evaluate("pressure", a=A, x=X, E_star=1, certified=True, dps=int(kind.split("=")[1]))
                ref = _cosh_pressure(A, Xn, Xd)
                with mpmath.workdps(60):
                    if res.enclosure is None:
                        err = abs(mpmath.mpf(res.value) - ref)
                        return err <= abs(res.error), f"no enclosure; err {mpmath.nstr(err, 3)} stated " \
                                                      f"{mpmath.nstr(mpmath.mpf(res.error), 3)}"
                    lo, hi = res.enclosure
                    width_ok = hi - lo <= 2 * abs(res.error) * (1 + mpmath.mpf(10)**-9)
                    return (lo <= ref <= hi and width_ok,
                            f"in [{mpmath.nstr(lo, 30)}, {mpmath.nstr(hi, 30)}] width {mpmath.nstr(hi - lo, 3)} "
                            f"stated error {mpmath.nstr(mpmath.mpf(res.error), 3)} ref {mpmath.nstr(ref, 30)}")
            out.append((f"cosh pressure a={A} x={Xn}/{Xd} {kind}", case, 120))
    return out


def _johnson(al):
    f = lambda u: mpmath.sin(u)**2 - al * mpmath.sqrt(mpmath.tan(u))  # noqa: E731
    df = lambda u: 2 * mpmath.sin(u) * mpmath.cos(u) - al / (2 * mpmath.cos(u)**2 * mpmath.sqrt(mpmath.tan(u)))  # noqa: E731
    return f, df


def _log_bisect(g, lo, hi, n=400):
    """A sign change of g on [lo, hi] (0 < lo < hi), bisected at the geometric mean."""
    glo = g(lo)
    for _ in range(n):
        mid = mpmath.sqrt(lo * hi)
        if (g(mid) < 0) == (glo < 0):
            lo = mid
        else:
            hi = mid
    return mpmath.sqrt(lo * hi)


def periodic_cases():
    out = []
    # refusals: no compact contact per period (quickly)
    for nm, prof, per in [("two troughs h(1 - cos(4 pi x/L))", h * (1 - sp.cos(4 * sp.pi * x / L)), L),
                          ("two troughs numeric", 1 - sp.cos(4 * sp.pi * x), 1),
                          ("period 1 declared 1000", 1 - sp.cos(2 * sp.pi * x), 1000),
                          ("period 1 declared 7", 1 - sp.cos(2 * sp.pi * x), 7),
                          ("not real beyond L/4", R - sp.sqrt(R**2 - x**2), 4 * R),
                          ("decreasing sin(pi x/L)^2 cos", h * sp.sin(2 * sp.pi * x / L)**2, L)]:
        out.append((f"refuse {nm}", refused(lambda prof=prof, per=per: lcs.LineContact(prof, period=per)), 30))

    def hw_full():
        c = contact("sinusoid")
        P = c.evaluate_at("force", a=sp.Rational(1, 2), h=1, L=1, E_star=1)
        got = c.half_width(P, h=1, L=1, E_star=1)
        return abs(got - mpmath.mpf(1) / 2) < 1e-25, f"half_width(P*) = {got}"
    out.append(("half_width at the full-contact load", hw_full, 120))

    def hw_above():
        c = contact("sinusoid")
        got = c.half_width(sp.Float("3.2"), h=1, L=1, E_star=1)
        return abs(got - mpmath.mpf(1) / 2) < 1e-25, f"half_width(P > P*) = {got}"
    out.append(("half_width above the full-contact load (full contact)", hw_above, 120))

    for al_txt in ("0.3", "0.5"):
        def fc_digits(al_txt=al_txt):
            ad = contact("sinusoid").adhesive(lcs.gamma)
            with mpmath.workdps(50):
                al = mpmath.mpf(al_txt)
                f, df = _johnson(al)
                u = mpmath.findroot(df, 1.2)
                fc = ad.full_contact_at(dps=30, h=1, L=1, E_star=1, gamma=sp.Float(al**2 * mpmath.pi**2 / 2, 50))
                d = agree(fc.force, mpmath.pi * f(u))
                return d >= 29 and fc.digits >= 30, f"force agrees to {float(d):.1f} digits, record {fc.digits}"
        out.append((f"full_contact_at(dps=30) alpha={al_txt}", fc_digits, 120))

    for g_txt in ("1e-40", "1e-20", "1e-12"):
        def po_weak(g_txt=g_txt):
            ad = contact("sinusoid").adhesive(lcs.gamma)
            with mpmath.workdps(60):
                al = mpmath.sqrt(2 * mpmath.mpf(g_txt)) / mpmath.pi
                f, df = _johnson(al)
                u = _log_bisect(df, mpmath.mpf(10)**-50, mpmath.mpf("0.3"))
                po = ad.pull_off_at(dps=20, h=1, L=1, E_star=1, gamma=sp.Float(g_txt, 40))
                d = agree(po.force, mpmath.pi * f(u))
                return d >= 18, f"pull-off {mpmath.nstr(po.force, 8)} at {mpmath.nstr(po.half_width, 5)}; " \
                                f"Johnson {mpmath.nstr(mpmath.pi * f(u), 8)} at {mpmath.nstr(u / mpmath.pi, 5)}"
        out.append((f"pull_off_at gamma={g_txt}", po_weak, 120))

        def fc_weak(g_txt=g_txt):
            ad = contact("sinusoid").adhesive(lcs.gamma)
            with mpmath.workdps(60):
                al = mpmath.sqrt(2 * mpmath.mpf(g_txt)) / mpmath.pi
                f, df = _johnson(al)
                u = mpmath.pi / 2 - _log_bisect(lambda d: df(mpmath.pi / 2 - d), mpmath.mpf(10)**-50,
                                                mpmath.mpf("0.3"))
                fc = ad.full_contact_at(dps=20, h=1, L=1, E_star=1, gamma=sp.Float(g_txt, 40))
                d = agree(fc.force, mpmath.pi * f(u))
                return d >= 19, f"full contact {mpmath.nstr(fc.force, 20)} ({fc.kind}); Johnson " \
                                f"{mpmath.nstr(mpmath.pi * f(u), 20)}"
        out.append((f"full_contact_at gamma={g_txt}", fc_weak, 120))

    for g in (0, 0.0):
        def fc_zero(g=g):
            fc = contact("sinusoid").adhesive(lcs.gamma).full_contact_at(dps=20, h=1, L=1, E_star=1, gamma=g)
            with mpmath.workdps(30):
                return agree(fc.force, +mpmath.pi) >= 19, f"{fc.force} ({fc.kind})"
        out.append((f"full_contact_at gamma={g!r}", fc_zero, 60))

    for A, Lv in [(1.5, 4.0), (1.0, 2.5), (3.0, 8.0), (0.4, 1.0)]:
        def wedge(A=A, Lv=Lv):
            r = contact("wedge").evaluate("force", a=A, theta=0.2, L=Lv, E_star=1, rtol=1e-12)
            ref = ref_periodic("wedge", "force", A, 0, Lv, Ev=1.0)
            return agree(r.value, ref) >= 11, f"{r.value} ref {mpmath.nstr(ref, 17)}"
        out.append((f"wedge array force a={A} L={Lv}", wedge, 60))

    big = 10**400

    def big_at():
        c = lcs.LineContact(1 - sp.cos(2 * sp.pi * x / big), period=big)
        with mpmath.workdps(40):
            ref = mpmath.pi * mpmath.sin(mpmath.pi / 10)**2
            v1 = c.evaluate_at("force", a=big // 10, E_star=1)
            v2 = c.evaluate("force", a=big // 10, E_star=1).value
            v3 = c.half_width(sp.Float(ref, 40), E_star=1)
            ok = agree(v1, ref) >= 25 and agree(v2, ref) >= 11 and agree(v3, mpmath.mpf(big) / 10) >= 20
        return ok, f"{mpmath.nstr(v1, 10)}, {mpmath.nstr(v2, 10)}, a = {mpmath.nstr(v3, 10)}"
    out.append(("period 10**400", big_at, 120))
    return out


GROUPS = {"exports": exports_cases, "honesty": honesty_cases, "enclosures": enclosure_cases,
          "periodic": periodic_cases}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--group", choices=list(GROUPS), action="append")
    ap.add_argument("--verbose", action="store_true")
    args = ap.parse_args()
    total = good = 0
    for g in args.group or list(GROUPS):
        cases = GROUPS[g]()
        n_ok, bad = 0, []
        for name, fn, limit in cases:
            ok, why, secs = run_case(fn, limit)
            n_ok += ok
            if not ok:
                bad.append((name, why, secs))
            if args.verbose:
                print(f"  {'ok ' if ok else 'BAD'} {secs:6.1f}s {name}: {why}", flush=True)
        print(f"{g}: cases {len(cases)} ok {n_ok}", flush=True)
        for name, why, secs in bad:
            print(f"   BAD {name} ({secs:.1f} s): {why}", flush=True)
        total += len(cases)
        good += n_ok
    print(f"cases {total} ok {good}")


if __name__ == "__main__":
    np.seterr(all="ignore")
    main()
