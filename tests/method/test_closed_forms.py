"""Closed-form pressures and gaps for piecewise and elliptic profiles, Eq. (9)
for K - E, and derivations that never wait for nothing (issue 11).

Every closed form is checked here against quadratures written in this file
(Eq. 12 after s = x cosh(u), the gap integral after s = a - v^2, the slopes
P'(s) worked out by hand), not against the package's own reference
integrals, branch by branch of its Piecewise."""
from __future__ import annotations

import mpmath
import mpmath as mp
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym import E_star, R, a, b, x
from linecontact_sym.core.errors import LineContactError
from linecontact_sym.method.legendre import NotReducible, reduce_integral

t = sp.Symbol("t", positive=True)

PUNCH = sp.Piecewise((0, x < b), ((x - b)**2 / (2 * R), True))
RWEDGE = sp.Piecewise((x**2 / (2 * R), x < b), (b**2 / (2 * R) + b / R * (x - b), True))
RANGES = {R: (3, 6), b: (0.3, 1.0)}

_contacts: dict = {}


def contact(name):
    if name not in _contacts:
        _contacts[name] = {"worn": lambda: lcs.worn_cylinder(),
                           "punch": lambda: lcs.LineContact(PUNCH, params=RANGES),
                           "rwedge": lambda: lcs.LineContact(RWEDGE, params=RANGES),
                           "cylinder": lambda: lcs.exact_cylinder()}[name]()
    return _contacts[name]


# slopes of the force laws, by hand (E* = 1): P'(s) = (1/s) int_0^s t (t f')' / sqrt(s^2 - t^2) dt
# plus b^2 [f'] / sqrt(s^2 - b^2) at a kink
def dP_worn(s, b_, R_):       # kink at b: Eq. (23) differentiated
    return 0 if s <= b_ else (s * mp.acos(b_ / s) + b_ * s / mp.sqrt(s * s - b_ * b_)) / R_


def dP_punch(s, b_, R_):      # tangent-continuous at b (issue 11): (s/R) acos(b/s)
    return 0 if s <= b_ else s * mp.acos(b_ / s) / R_


def dP_rwedge(s, b_, R_):     # Hertz below b, (s/R) asin(b/s) above
    return mp.pi * s / (2 * R_) if s <= b_ else s * mp.asin(b_ / s) / R_


def dP_cylinder(s, R_):       # d/ds R (K - E)(s^2/R^2) = s R E(m)/(R^2 - s^2), mpmath's E(m), m = k^2
    return s * R_ * mp.ellipe(s * s / R_**2) / (R_**2 - s * s)


def pressure_ref(dP, av, xv, kinks=()):
    """Eq. (12) after s = x cosh(u): (1/pi) int_0^acosh(a/x) P'(x cosh u) du;
    beyond a kink u_k (where P' ~ 1/sqrt(u - u_k)) in w = sqrt(u - u_k), at
    twice the digits."""
    with mp.workdps(2 * mp.mp.dps):
        ks = [mp.acosh(k / xv) for k in kinks if xv < k < av]
        top = mp.acosh(av / xv)
    total = mp.quad(lambda u: dP(xv * mp.cosh(u)), [0, ks[0] if ks else top])
    for lo, hi in zip(ks, ks[1:] + [top]):
        def g(w, lo=lo):
            with mp.workdps(2 * mp.mp.dps):
                return 2 * w * dP(xv * mp.cosh(lo + w * w))
        total += mp.quad(g, [0, mp.sqrt(hi - lo)])
    return total / mp.pi


def gap_ref(f, dP, av, xv, kinks=()):
    """f(x) - (2/pi) int_0^a acosh(x/s) P'(s) ds, split at the kinks, each
    piece in v with s = hi - v^2 (a 1/sqrt(s - k) at a kink is then smooth)."""
    edges = [mp.mpf(0)] + [k for k in kinks if k < av] + [av]
    total = mp.mpf(0)
    for lo, hi in zip(edges[:-1], edges[1:]):
        def g(v, lo=lo):
            with mp.workdps(2 * mp.mp.dps):
                s_ = lo + v * v
                return 2 * v * mp.acosh(xv / s_) * dP(s_) if s_ > 0 else mp.mpf(0)
        total += mp.quad(g, [0, mp.sqrt(hi - lo)])
    return f(xv) - 2 * total / mp.pi


def closed(name, quantity, **vals):
    d = contact(name).derivation(quantity)
    subs = {sp.Symbol(k, positive=True): sp.Rational(v) for k, v in vals.items()}
    return mp.mpf(sp.N(d.expr.xreplace(subs), 40))


def agree(got, ref, digits=28):
    assert abs(got - ref) <= mp.mpf(10) ** -digits * max(abs(ref), mp.mpf(10) ** -30), (got, ref)


# ----------------------------------------------------------------- the reduction
@pytest.mark.parametrize("h, lo, hi, pv", [
    (t**2 / (t**2 - x**2), b, a, True),                  # elementary, principal value at t = x
    (t * (t - b) / (t**2 - x**2), b, a, False),          # odd part: atanh forms
    ((R - sp.sqrt(R**2 - t**2)) / (x**2 - t**2), 0, a, False),   # complete K, E, Pi
    (t**6 / sp.sqrt(R**2 - t**2), b, a, False),          # incomplete F, E, Legendre recurrence
])
def test_reduce_integral_against_quadrature(h, lo, hi, pv):
    vals = {a: sp.Rational(3, 2), R: sp.Rational(5, 2), b: sp.Rational(2, 5),
            x: sp.Rational(1) if pv else (sp.Rational(2) if h.has(x**2 - t**2) or h.has(-t**2 + x**2)
                                          else sp.Rational(1, 5))}
    got = reduce_integral(h, t, a, lo, hi, vals)
    with mp.workdps(40):
        g = sp.lambdify(t, (h / sp.sqrt(a**2 - t**2)).xreplace(vals), "mpmath")
        L, H = mp.mpf(sp.N(sp.sympify(lo).xreplace(vals), 50)), mp.mpf(sp.N(sp.sympify(hi).xreplace(vals), 50))
        hv = sp.lambdify(t, h.xreplace(vals), "mpmath")
        A = mp.mpf(vals[a])
        if pv:                       # symmetric excision around t = x, the rest by tanh-sinh
            X = mp.mpf(vals[x])
            d = min(X - L, H - X) / 2

            def pair(e):             # the 1/e parts cancel: formed at many more digits
                with mp.workdps(160):
                    return g(X + e) + g(X - e)
            ref = mp.quad(pair, [0, d]) + mp.quad(g, [L, X - d]) + mp.quad(g, [X + d, H])
            tol = mp.mpf(10) ** -20  # the excised pair integral keeps ~22 digits
        elif hi == a:                # t = a - v^2: sqrt(a^2 - t^2) = v sqrt(2a - v^2)
            ref = mp.quad(lambda v: 2 * hv(A - v * v) / mp.sqrt(2 * A - v * v), [0, mp.sqrt(A - L)])
            tol = mp.mpf(10) ** -25
        else:
            ref, tol = mp.quad(g, [L, H]), mp.mpf(10) ** -25
        assert abs(mp.mpf(sp.N(got.xreplace(vals), 40)) - ref) < tol * abs(ref)


def test_reduce_integral_refuses_what_it_cannot_do():
    with pytest.raises(NotReducible):
        reduce_integral(sp.exp(t), t, a, 0, a, {a: 1})
    with pytest.raises(NotReducible):
        reduce_integral(t * sp.sqrt(R**2 - (t - b)**2), t, a, 0, a, {a: 1, R: 2, b: sp.Rational(1, 2)})


# ----------------------------------------------------------------- the profiles
CASES = {
    # name: (dP(s, params), profile f(x, params) in mpmath, kinks, params, half-widths a)
    "worn": (dP_worn, lambda v, b_, R_: 0 if v < b_ else (v * v - b_ * b_) / (2 * R_)),
    "punch": (dP_punch, lambda v, b_, R_: 0 if v < b_ else (v - b_)**2 / (2 * R_)),
    "rwedge": (dP_rwedge, lambda v, b_, R_: v * v / (2 * R_) if v < b_ else b_ * b_ / (2 * R_) + b_ / R_ * (v - b_)),
}


@pytest.mark.parametrize("name", ["worn", "punch", "rwedge"])
def test_piecewise_pressure_and_gap_every_region(name):
    """Closed forms by the order-swap rule, verified (>= 30 digits), and at a
    point of every region (a < b; a > b with x < b, x = b, x > b; gaps
    beyond) against the quadratures of this file."""
    cont = contact(name)
    for q, rule in (("pressure", "pressure_swap"), ("gap", "gap_swap")):
        d = cont.derivation(q)
        assert d.closed_form and d.rule == rule, d.notes
        assert d.verification.min_digits >= 30
        assert not d.expr.has(sp.Integral)
    dP, f = CASES[name]
    with mp.workdps(40):
        bv, Rv = mp.mpf("0.8"), mp.mpf(4)
        for av, xv in (("0.6", "0.3"), ("1.5", "0.5"), ("1.5", "1.2"), ("1.5", "0.8")):
            if name == "worn" and xv == "0.8":
                continue                 # the kink: log-infinite pressure at x = b
            got = closed(name, "pressure", a=av, x=xv, b="0.8", R=4, E_star=1)
            ref = pressure_ref(lambda s: dP(s, bv, Rv), mp.mpf(av), mp.mpf(xv), kinks=[bv])
            agree(got, ref)
        for av, xv in (("0.6", "0.7"), ("0.6", "1.3"), ("1.5", "1.7"), ("1.5", "4")):
            got = closed(name, "gap", a=av, x=xv, b="0.8", R=4, E_star=1)
            ref = gap_ref(lambda v: f(v, bv, Rv), lambda s: dP(s, bv, Rv), mp.mpf(av), mp.mpf(xv), kinks=[bv])
            agree(got, ref, 26)


def test_worn_cylinder_pressure_is_infinite_at_the_kink():
    fn = contact("worn").to_numeric("pressure")
    v = fn(a=1.5, x=0.8, b=0.8, R=4.0, E_star=1.0)
    assert v == float("inf") or v != v or v > 1e10


def test_exact_cylinder_pressure_and_gap():
    """p = E* sqrt(a^2 - x^2) Pi(x^2/R^2 | a^2/R^2)/(pi R) (parameter
    convention m = k^2), and the gap in K, E, Pi; both against this file's
    quadratures with mpmath's E(m)."""
    cont = contact("cylinder")
    d = cont.derivation("pressure")
    assert d.rule == "pressure_swap" and d.verification.min_digits >= 30
    expected = E_star * sp.sqrt(a**2 - x**2) * sp.elliptic_pi(x**2 / R**2, a**2 / R**2) / (sp.pi * R)
    assert sp.simplify(d.expr - expected) == 0
    g = cont.derivation("gap")
    assert g.rule == "gap_swap" and g.verification.min_digits >= 30 and g.expr.has(sp.elliptic_pi)
    with mp.workdps(40):
        Rv = mp.mpf(2)
        for av, xv in (("0.5", "0.2"), ("1.9", "1.899"), ("0.01", "0.005")):
            agree(closed("cylinder", "pressure", a=av, x=xv, R=2, E_star=1),
                  pressure_ref(lambda s: dP_cylinder(s, Rv), mp.mpf(av), mp.mpf(xv)))
        for av, xv in (("0.5", "0.7"), ("1.5", "1.9"), ("0.5", "0.5001")):
            agree(closed("cylinder", "gap", a=av, x=xv, R=2, E_star=1),
                  gap_ref(lambda v: Rv - mp.sqrt(Rv**2 - v * v), lambda s: dP_cylinder(s, Rv),
                          mp.mpf(av), mp.mpf(xv)), 26)


def test_exact_cylinder_float64_exports_at_small_a_over_r():
    """The gap's closed form cancels terms of size R (float64 alone: every
    digit lost at a/R = 1e-8); the guarded export recomputes those points."""
    import numpy as np
    fg = contact("cylinder").to_numeric("gap")
    with mp.workdps(60):
        Rv = mp.mpf(10)**8
        ref = gap_ref(lambda v: v * v / (Rv + mp.sqrt(Rv**2 - v * v)), lambda s: dP_cylinder(s, Rv), mp.mpf(1),
                      mp.mpf(3))
    got = fg(a=np.array([1.0]), x=np.array([3.0]), R=1e8, E_star=1.0)[0]
    assert abs(got - ref) <= 1e-14 * abs(ref)


# ----------------------------------------------------------------- Eq. (9) for K - E
def test_inverse_map_of_k_minus_e_merges_the_series():
    from linecontact_sym.method.hyperseries import decompose
    from linecontact_sym.method.rules_inverse import merge_series
    from linecontact_sym.method.transforms import s
    P = E_star * R * (sp.elliptic_k(a**2 / R**2) - sp.elliptic_e(a**2 / R**2))
    merged = merge_series(decompose(P.subs(a, s), s))
    assert len(merged) == 1 and merged[0].mu == 2          # the constants pi/2 cancelled
    d = lcs.profile_from_force(P, verify_points=3)
    assert d.closed_form and d.rule == "inverse_merged_series"
    assert sp.simplify(d.expr - (R - sp.sqrt(R**2 - x**2))) == 0
    assert d.verification.min_digits >= 30


# ----------------------------------------------------------------- never wait for nothing
def test_cache_on_disk_and_in_memory(tmp_path, monkeypatch):
    from linecontact_sym.method import store
    monkeypatch.setenv(store.CACHE_ENV, str(tmp_path))
    store.clear_memory()
    prof = x**2 / (2 * R) + x**4 / R**3
    d1 = lcs.LineContact(prof, points=3).derivation("pressure")
    assert d1.cached == "" and d1.closed_form
    files = list(tmp_path.rglob("*.json"))
    assert files, "nothing written to the cache directory"
    d2 = lcs.LineContact(prof, points=3).derivation("pressure")
    assert d2.cached == "memory" and d2.expr == d1.expr
    store.clear_memory()
    d3 = lcs.LineContact(prof, points=3).derivation("pressure")
    assert d3.cached == "disk" and d3.expr == d1.expr and d3.step == d1.step
    assert d3.verification == d1.verification
    # the reference is rebuilt: it evaluates the defining integral
    assert abs(d3.evalf(dps=20, a=0.5, x=0.25, R=1, E_star=1)
               - d3.reference({a: sp.Rational(1, 2), x: sp.Rational(1, 4), R: 1, E_star: 1}, 20)) < 1e-15
    # corrupt entries are recomputed, never trusted
    for f in tmp_path.rglob("*.json"):
        f.write_bytes(f.read_bytes()[:-7] + b"garbage")
    store.clear_memory()
    d4 = lcs.LineContact(prof, points=3).derivation("pressure")
    assert d4.cached == "" and d4.expr == d1.expr


def test_cache_off_and_stale_versions(tmp_path, monkeypatch):
    from linecontact_sym.method import store
    monkeypatch.setenv(store.CACHE_ENV, "off")
    store.clear_memory()
    assert store.cache_dir() is None and not store.enabled()
    monkeypatch.setenv(store.CACHE_ENV, str(tmp_path))
    key = store.make_key("test", x**2)
    store.put(key, {"value": 1})
    store.clear_memory()
    assert store.get(key)["value"] == 1
    monkeypatch.setitem(store._state, "version", "0.0.0+other")   # another code version
    store.clear_memory()
    assert store.get(key) is None
    assert store.make_key("test", x**2) != key


def test_failure_is_remembered_not_retried(tmp_path, monkeypatch):
    from linecontact_sym.method import store
    # a cache of its own: another test of this worker (test_engine's same profile, the default
    # budget) may have stored this force law on disk, which d1 would then read instead of deriving
    monkeypatch.setenv(store.CACHE_ENV, str(tmp_path))
    store.clear_memory()
    f = x**2 * sp.exp(x) * sp.cos(x)          # no closed force law
    d1 = lcs.LineContact(f, budget=1).derivation("force")
    assert not d1.closed_form
    d2 = lcs.LineContact(f, budget=1).derivation("force")
    assert d2.cached and not d2.closed_form and d2.attempts == d1.attempts, (d1.attempts, d2.attempts, d2.cached)
    from linecontact_sym.method.derivation import _budget_limited
    if _budget_limited(d1.attempts):
        # it ran out of time: a larger budget tries again
        d3 = lcs.LineContact(f, budget=2).derivation("force")
        assert d3.cached == ""


def test_cli_no_cache_writes_nothing(tmp_path, monkeypatch):
    from linecontact_sym import cli
    from linecontact_sym.method import store
    monkeypatch.setenv(store.CACHE_ENV, str(tmp_path))
    store.clear_memory()
    try:
        assert cli.main(["derive", "x**3", "--quantities", "force", "--no-cache"]) == 0
    finally:
        store.set_enabled(True)
    assert not list(tmp_path.rglob("*.json"))


# ----------------------------------------------------------------- evaluate: arrays, and the scalar path
def test_evaluate_arrays_and_scalars_agree():
    import numpy as np
    from linecontact_sym.numeric.evaluate import evaluate
    cont = contact("cylinder")
    xs = np.array([0.0, 0.1, 0.3, 0.49])
    r = evaluate(cont, "pressure", rtol=1e-12, a=0.5, x=xs, R=1.0, E_star=1.0)
    assert r.path == "float64" and r.value.shape == xs.shape
    for xv, v in zip(xs, r.value):
        s = evaluate(cont, "pressure", rtol=1e-12, a=0.5, x=float(xv), R=1.0, E_star=1.0)
        assert s.path == "float64" and abs(s.value - v) <= 4e-16 * abs(v)
        with mp.workdps(40):
            ref = pressure_ref(lambda u: dP_cylinder(u, mp.mpf(1)), mp.mpf("0.5"), mp.mpf(float(xv))) \
                if xv > 0 else None
        if ref is not None:
            assert abs(v - ref) <= 1e-12 * abs(ref)
    # a point beyond float64 goes its own way within the same call
    r = evaluate(cont, "pressure", rtol=1e-20, a=0.5, x=[0.1, 0.2], R=1.0, E_star=1.0)
    assert all(p.startswith("mpmath@") for p in r.details["paths"])


@pytest.mark.slow
def test_unevaluated_pressure_and_gap_are_true_integrals():
    """A force law without closed form (the profile asin(x)^2: SymPy leaves
    Eq. 10's integral unevaluated) gave the pressure and the gap as Leibniz's
    rule makes them on that integral's limit a, where its integrand is
    singular: zoo times a boundary term plus a divergent inner integral (and a
    KeyError 'ComplexInfinity' from the export).  Now int_0^a dt is written
    over u in [0, 1] first, and the nested integrals returned are finite: the
    returned expression, computed by nested mpmath quadrature (the mpmath
    export), equals the package's number (one quadrature of the profile,
    transforms.pressure_direct_quad for the pressure) to 10 digits.  The float64
    export refuses a nested integral by name (it had compiled the inner one as
    an undefined function: a NameError at the first call)."""
    c = lcs.LineContact(sp.asin(x)**2, budget=3)
    assert not c.derivation("force").closed_form
    for q, xv in (("pressure", sp.Rational(1, 5)), ("gap", sp.Rational(7, 10))):
        d = c.derivation(q)
        assert not d.closed_form and not d.expr.has(sp.zoo, sp.nan, sp.oo)
        assert any(I.function.has(sp.Integral) for I in d.expr.atoms(sp.Integral))    # nested
        got = c.to_numeric(q, backend="mpmath", dps=12)(a=0.5, x=float(xv), E_star=1.0)
        want = c.evaluate_at(q, dps=15, a=sp.Rational(1, 2), x=xv, E_star=1)
        assert abs(got - want) <= mpmath.mpf(10)**-10 * abs(want), (q, got, want)
        with pytest.raises(LineContactError, match="nested integral"):
            c.to_numeric(q)(a=0.5, x=float(xv), E_star=1.0)
