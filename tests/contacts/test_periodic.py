"""Periodic line contacts (issue 27): LineContact(f, period=L).

Every number is checked against a route that shares nothing with the
engine's map s = sin(pi x/L):

* the tan route (contacts.normal.tan_route, X = tan(pi x/L): an isolated contact
  whose profile carries the logarithm of the periodic kernel);
* the surface slope of the periodic half-plane computed here from the
  engine's pressure with the cot kernel (no map at all):
  (2/(pi E*)) (pi/L) PV int_{-a}^{a} p(t) cot(pi (x - t)/L) dt = f'(x) for |x| < a,
  and the resultant int p dx = P;
* Westergaard's (1939) printed sinusoid, and the isolated limit L -> oo.
"""
from __future__ import annotations

import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core.errors import DomainError, LineContactError, ProfileError
from linecontact_sym.contacts.normal.tan_route import TanRoute

x, a, E = lcs.x, lcs.a, lcs.E_star
h, L, R, th = sp.symbols("h L R theta", positive=True)

PROFILES = {
    "sinusoid": h * (1 - sp.cos(2 * sp.pi * x / L)),
    "sin4": h * sp.sin(sp.pi * x / L)**4,
    "parabola": x**2 / (2 * R),
    "wedge": sp.tan(th) * x,
}
#: parameter values of the checks (exact)
VALUES = {h: sp.Rational(3, 10), R: sp.Rational(7, 5), th: sp.Rational(1, 5), L: sp.Rational(13, 10),
          E: sp.Rational(17, 10)}
A_OVER_L = ("0.05", "0.2", "0.35", "0.45")
DIGITS = 20


@pytest.fixture(scope="module")
def contacts():
    return {k: lcs.LineContact(f, period=L) for k, f in PROFILES.items()}


def _vals(c, **extra):
    out = {s.name: VALUES[s] for s in c.variables}
    out.update(extra)
    return out


def _agree(u, v):
    return -mpmath.log10(abs(u - v) / abs(v)) if u != v else mpmath.inf


def _slope_from_pressure(p, A, X, Lv, Ev):
    """(2/(pi E*)) (pi/L) PV int_{-A}^{A} p(t) cot(pi (X - t)/L) dt, the
    singular point subtracted: p(X) (L/pi) ln|sin(pi (X + A)/L)/sin(pi (X - A)/L)|."""
    pX = p(X)

    def g(t):
        d = mpmath.pi * (X - t) / Lv
        return (p(t) - pX) * mpmath.cot(d) if t != X else mpmath.mpf(0)
    I = mpmath.quad(g, [-A, -X, 0, X, A] if X > 0 else [-A, X, A])
    I += pX * Lv / mpmath.pi * mpmath.log(abs(mpmath.sin(mpmath.pi * (X + A) / Lv) / mpmath.sin(mpmath.pi * (X - A) / Lv)))
    return 2 / (mpmath.pi * Ev) * mpmath.pi / Lv * I


# ---------------------------------------------------------------- the geometry and the tan route alone
@pytest.mark.slow
def test_geometry_maps_and_the_tan_route_on_westergaard():
    """The maps of Koiter's variable, and the tan route's numbers for the
    sinusoid against Westergaard's printed solution (no engine involved)."""
    from linecontact_sym.method.geometry import ISOLATED, Periodic
    from linecontact_sym.method.profile import Profile
    g = Periodic(L)
    assert g.kernel_profile(PROFILES["sinusoid"]) == 2 * h * x**2
    assert g.kernel_profile(PROFILES["sin4"]) == h * x**4
    assert sp.simplify(g.punch_ratio() - L * sp.tan(sp.pi * a / L) / sp.pi) == 0
    assert ISOLATED.punch_ratio() == a and ISOLATED.s(x) == x
    # Koiter's punch carries P per period
    Pp = sp.Symbol("P", positive=True)
    koiter = g.punch_pressure(Pp)
    with mpmath.workdps(30):
        fn = sp.lambdify(x, koiter.xreplace({Pp: 1, L: 2, a: sp.Rational(3, 5)}), "mpmath")
        assert abs(2 * mpmath.quad(fn, [0, mpmath.mpf(3) / 5]) - 1) < 1e-14   # (the edge: 1/sqrt, cancelling)
        route = TanRoute(Profile(PROFILES["sinusoid"].xreplace({h: 1, L: 2})), {E: 1}, 2)
        A, X, Xo = mpmath.mpf("0.7"), mpmath.mpf("0.3"), mpmath.mpf("0.9")
        S, s = mpmath.sin(mpmath.pi * A / 2), mpmath.sin(mpmath.pi * X / 2)
        P = route.force(A, 20)
        assert _agree(P, mpmath.pi * S**2) >= 19
        west = 2 * (P / 2) * mpmath.cos(mpmath.pi * X / 2) * mpmath.sqrt(S**2 - s**2) / S**2
        assert _agree(route.pressure(A, X, P, dps=20), west) >= 19
        assert route.gap(A, A * (1 + mpmath.mpf(10)**-20), P, dps=20) < mpmath.mpf(10)**-8   # g(a) = 0
        assert route.gap(A, Xo, P, dps=20) > 0


# ---------------------------------------------------------------- Westergaard as a consequence
@pytest.mark.slow
def test_westergaard_from_the_engine(contacts):
    c = contacts["sinusoid"]
    assert c.kernel.profile.expr == 2 * h * x**2          # a parabola in s = sin(pi x/L)
    S = sp.sin(sp.pi * a / L)
    assert sp.simplify(c.force - sp.pi * E * h * S**2) == 0
    # Westergaard (1939): p = 2 pbar cos(pi x/L) sqrt(S^2 - sin^2(pi x/L))/S^2, pbar = P/L
    pbar = sp.pi * E * h * S**2 / L
    west = 2 * pbar * sp.cos(sp.pi * x / L) / S**2 * sp.sqrt(S**2 - sp.sin(sp.pi * x / L)**2)
    assert sp.simplify(c.pressure - west) == 0
    assert sp.simplify(c.nominal_pressure - pbar) == 0
    assert c.full_contact_force == sp.pi * E * h
    assert sp.simplify(c.full_contact_pressure - sp.pi * E * h / L) == 0   # p* = pi E* h/L
    for q in ("force", "pressure", "gap", "full_contact_force"):
        d = c.derivation(q)
        assert d.closed_form and d.verification.passed and len(d.verification.points) == c.points


@pytest.mark.slow
def test_half_width_and_inverse_map(contacts):
    c = contacts["sinusoid"]
    d = c.derivation("half_width")
    assert d.closed_form
    assert sp.simplify(d.expr - L / sp.pi * sp.asin(sp.sqrt(lcs.P / (sp.pi * E * h)))) == 0
    av = c.half_width(sp.Rational(1, 3), h=1, L=2, E_star=1)
    assert abs(av - 2 / mpmath.pi * mpmath.asin(mpmath.sqrt(mpmath.mpf(1) / (3 * mpmath.pi)))) < 1e-14
    f = lcs.profile_from_force(sp.pi * E * h * sp.sin(sp.pi * a / L)**4, period=L)
    assert f.closed_form and f.verification.passed
    assert sp.simplify(f.expr - sp.Rational(4, 3) * h * sp.sin(sp.pi * x / L)**4) == 0


@pytest.mark.slow
def test_half_width_beyond_half_period_is_refused(contacts):
    c = contacts["sin4"]
    with pytest.raises(DomainError, match="L/2"):
        c.evaluate_at("force", a=0.7, h=1, L=1, E_star=1)
    with pytest.raises(ProfileError):
        lcs.LineContact(x**2, period=-1)
    with pytest.raises(ProfileError):
        lcs.LineContact(x**2, period=sp.Symbol("q"))
    with pytest.raises(LineContactError, match="periodic"):
        c.tangential()


# ---------------------------------------------------------------- four profiles, 20 digits
@pytest.mark.slow
@pytest.mark.parametrize("name", list(PROFILES))
def test_force_pressure_gap_against_the_tan_route(contacts, name):
    """P, p, g of the engine (closed form where it found one, else its
    unevaluated integral's number) against the tan route, to 20 digits at
    a/L up to 0.45."""
    c = contacts[name]
    vals = {s: VALUES[s] for s in c.variables}
    Lv = VALUES[L]
    route = TanRoute(c.profile, vals, Lv)
    for r in A_OVER_L:
        A = sp.Rational(r) * Lv
        P = c.evaluate_at("force", dps=DIGITS + 5, **_vals(c, a=A))
        # the route's pressure and gap take its own P(a) (each computed it again) and
        # DIGITS + 5 digits, as the engine's numbers (they worked at 2*30 + 20 = 80 digits)
        P_tan = P_route = route.force(A, 30)
        closed = c.derivation("force").closed_form
        if not closed:   # the engine's number is the tan route itself: compare with the kernel's s-quadrature
            P_tan = c.kernel.derivation("force").evalf(30, a=sp.sin(sp.pi * A / Lv),
                                                        **{s.name: v for s, v in vals.items() if s in
                                                           c.kernel.variables})
        assert _agree(P, P_tan) >= DIGITS, (name, r)
        for fx in ("0.3", "0.9"):
            X = sp.Rational(fx) * A
            p = c.evaluate_at("pressure", dps=DIGITS + 5, **_vals(c, a=A, x=X))
            if c.derivation("pressure").closed_form:
                assert _agree(p, route.pressure(A, X, P_route, dps=DIGITS + 5)) >= DIGITS, (name, r, fx)
        Xo = A + (Lv / 2 - A) * sp.Rational(1, 2)
        g = c.evaluate_at("gap", dps=DIGITS + 5, **_vals(c, a=A, x=Xo))
        assert g > 0
        if c.derivation("gap").closed_form:
            assert _agree(g, route.gap(A, Xo, P_route, dps=DIGITS + 5)) >= DIGITS, (name, r)


@pytest.mark.slow
@pytest.mark.parametrize("name", ["sinusoid", "sin4"])
def test_pressure_satisfies_the_periodic_half_plane(contacts, name):
    """The engine's closed pressure, put into the periodic half-plane's cot
    kernel (no map): its surface slope is f' inside the contact and its
    resultant is P(a), to 20 digits."""
    c = contacts[name]
    vals = {s: VALUES[s] for s in c.variables}
    with mpmath.workdps(35):
        Lv, Ev = mpmath.mpf(sp.N(VALUES[L], 40)), mpmath.mpf(sp.N(VALUES[E], 40))
        pfun = sp.lambdify((a, x), c.pressure.xreplace(vals), "mpmath")
        f1 = sp.lambdify(x, sp.diff(c.profile.expr, x).xreplace(vals), "mpmath")
        for r in ("0.2", "0.45"):
            A = mpmath.mpf(sp.N(sp.Rational(r) * VALUES[L], 40))
            p = lambda t: pfun(A, abs(t))  # noqa: E731
            for fx in ("0.25", "0.7"):
                X = mpmath.mpf(fx) * A
                assert _agree(_slope_from_pressure(p, A, X, Lv, Ev), f1(X)) >= DIGITS
            P = c.force.xreplace(vals).xreplace({a: sp.Rational(r) * VALUES[L]})
            assert _agree(2 * mpmath.quad(p, [0, A]), mpmath.mpf(sp.N(P, 40))) >= DIGITS


@pytest.mark.slow
def test_wedge_force_law_and_corner_crest(contacts):
    c = contacts["wedge"]
    assert sp.simplify(c.force - E * L * sp.tan(th) * sp.atanh(sp.sin(sp.pi * a / L)) / sp.pi) == 0
    assert c.full_contact_force == sp.oo        # f'(L/2) != 0: no finite full-contact load
    assert contacts["parabola"].full_contact_force == sp.oo


# ---------------------------------------------------------------- the isolated limit
@pytest.mark.slow
def test_isolated_limit_of_a_parabolic_tip():
    """L -> oo with the tip curvature 1/R held: h = L^2/(4 pi^2 R) makes
    h (1 - cos(2 pi x/L)) -> x^2/(2R); the engine's periodic force law and
    pressure go to Hertz's line contact."""
    c = lcs.LineContact(h * (1 - sp.cos(2 * sp.pi * x / L)), period=L)
    tip = {h: L**2 / (4 * sp.pi**2 * R)}
    assert sp.limit(c.force.xreplace(tip), L, sp.oo) == sp.pi * E * a**2 / (4 * R)
    assert sp.simplify(sp.limit(c.pressure.xreplace(tip), L, sp.oo) - E * sp.sqrt(a**2 - x**2) / (2 * R)) == 0


@pytest.mark.slow
def test_isolated_limit_of_the_periodic_parabola_numbers(contacts):
    """x^2/(2R) repeated with period L: P(a) -> pi E* a^2/(4R) like (a/L)^2."""
    c = contacts["parabola"]
    hertz = mpmath.pi / 4
    errs = []
    for Lv in (10, 100, 1000):
        P = c.evaluate_at("force", dps=30, a=1, R=1, L=Lv, E_star=1)
        errs.append(abs(P - hertz) / hertz)
    assert errs[0] < 0.05 and 80 < errs[0] / errs[1] < 120 and 80 < errs[1] / errs[2] < 120


# ---------------------------------------------------------------- adhesion: JKR on the array (Johnson 1995)
gam = lcs.gamma


def _johnson(alpha):
    """Johnson's (1995) P/(p* L) = sin^2 u - alpha sqrt(tan u), u = pi a/L, and
    its stationary points recomputed here (the analytic derivative
    2 sin u cos u - alpha sec^2 u/(2 sqrt(tan u)), mpmath.findroot)."""
    f = lambda u: mpmath.sin(u)**2 - alpha * mpmath.sqrt(mpmath.tan(u))  # noqa: E731
    df = lambda u: 2 * mpmath.sin(u) * mpmath.cos(u) - alpha / (2 * mpmath.cos(u)**2 * mpmath.sqrt(mpmath.tan(u)))  # noqa: E731
    return f, df


def test_compliance_of_koiters_punch_by_quadrature():
    from linecontact_sym.method.geometry import Periodic
    g = Periodic(2)
    with mpmath.workdps(30):
        for A in ("0.1", "0.95"):
            A = mpmath.mpf(A)
            assert _agree(g.mp_punch_compliance(A, 3, {}, quadrature=True), -2 * mpmath.log(mpmath.sin(mpmath.pi * A / 2))
                          / (3 * mpmath.pi)) >= 28
            # its slope, the integral differentiated under the integral sign (the
            # JKR reference's energy balance), against d/dA of the closed form
            assert _agree(g.mp_punch_compliance_slope(A, 3, {}), -mpmath.cot(mpmath.pi * A / 2) / 3) >= 28


@pytest.mark.slow
def test_johnson_force_law_and_stress_intensity(contacts):
    """JKR on Westergaard's array: the engine's P(a) is Johnson's
    P/(p* L) = sin^2(pi a/L) - alpha sqrt(tan(pi a/L)), alpha^2 = 2 w L/(pi^2 E* h^2);
    the edge of its pressure has K = pbar_hat sqrt(L cot(pi a/L)) and G = K^2/(2 E*) = w."""
    c = contacts["sinusoid"]
    ad = c.adhesive(gam)
    alpha = sp.Symbol("alpha", positive=True)
    u = sp.pi * a / L
    P = ad.force.xreplace({gam: alpha**2 * sp.pi**2 * E * h**2 / (2 * L)})
    assert sp.simplify(P / (sp.pi * E * h) - (sp.sin(u)**2 - alpha * sp.sqrt(sp.tan(u)))) == 0
    for q in ("flat_punch_force", "force", "pressure"):
        d = ad.derivation(q)
        assert d.closed_form and d.verification.passed
    # K from the engine's pressure at the edge, at 40 digits
    vals = {h: sp.Rational(1, 3), L: 2, E: sp.Rational(3, 2), gam: sp.Rational(1, 20), a: sp.Rational(7, 10)}
    p = sp.lambdify(x, ad.pressure.xreplace(vals), "mpmath")
    with mpmath.workdps(60):
        A = mpmath.mpf(7) / 10
        eps = mpmath.mpf(10)**-40
        K = -mpmath.sqrt(2 * mpmath.pi * eps) * p(A - eps)
        Phat = mpmath.mpf(sp.N(sp.sqrt(2 * gam * E * L * sp.tan(u)).xreplace(vals), 60))
        assert _agree(K, Phat / 2 * mpmath.sqrt(2 / mpmath.tan(mpmath.pi * A / 2))) >= 18
        assert _agree(K**2 / (2 * mpmath.mpf(3) / 2), mpmath.mpf(1) / 20) >= 18


@pytest.mark.slow
@pytest.mark.parametrize("alpha", ["0.3", "0.5", "0.6"])
def test_johnson_pull_off_and_snap_into_full_contact(contacts, alpha):
    """ad.pull_off_at and ad.full_contact_at against Johnson's (1995)
    equation recomputed independently, to 20 digits; alpha = 0.6 > 0.570:
    the array snaps into full contact at zero load."""
    ad = contacts["sinusoid"].adhesive(gam)
    with mpmath.workdps(40):
        al = mpmath.mpf(alpha)
        f, df = _johnson(al)
        u_po, u_fc = mpmath.findroot(df, 0.3), mpmath.findroot(df, 1.2)
        w = al**2 * mpmath.pi**2 / 2                    # h = L = E* = 1: p* L = pi
        values = dict(h=1, L=1, E_star=1, gamma=sp.Float(w, 40))
        po = ad.pull_off_at(dps=20, **values)
        fc = ad.full_contact_at(dps=20, **values)
        assert po.digits >= 20 and fc.digits >= 20
        assert _agree(po.force / mpmath.pi, f(u_po)) >= 20
        assert _agree(po.half_width, u_po / mpmath.pi) >= 20
        assert _agree(fc.force / mpmath.pi, f(u_fc)) >= 20
        assert _agree(fc.half_width, u_fc / mpmath.pi) >= 20
        assert fc.at_zero_load == (al > mpmath.mpf(3) / 4 / mpmath.root(3, 4))


@pytest.mark.slow
def test_strong_adhesion_closes_the_array_at_once(contacts):
    """alpha > 1.066 (4 sin^1.5 u cos^2.5 u < alpha for every u): P(a) falls
    from 0: no pull-off of a partial contact, full contact at zero load."""
    ad = contacts["sinusoid"].adhesive(gam)
    w = sp.Rational(6, 5)**2 * sp.pi**2 / 2
    with pytest.raises(lcs.NoPullOffError, match="full contact"):
        ad.pull_off_at(dps=20, h=1, L=1, E_star=1, gamma=w)
    fc = ad.full_contact_at(dps=20, h=1, L=1, E_star=1, gamma=w)
    assert fc.kind == "origin" and fc.at_zero_load


@pytest.mark.slow
def test_cli_derive_and_eval_with_a_period(capsys):
    from linecontact_sym.cli import main
    assert main(["derive", "h*(1 - cos(2*pi*x/L))", "--symbols", "h", "L", "--period", "L", "--quantities",
                 "force,full_contact_pressure", "--json", "--quiet"]) == 0
    import json
    out = json.loads(capsys.readouterr().out)
    assert sp.simplify(lcs.parse_expr(out["quantities"]["force"]["expr"], symbols=["h", "L"])
                       - sp.pi * E * h * sp.sin(sp.pi * a / L)**2) == 0
    assert out["quantities"]["full_contact_pressure"]["verified_digits"] >= 30
    assert main(["eval", "h*(1 - cos(2*pi*x/L))", "force", "--symbols", "h", "L", "--period", "L", "--at",
                 "a=0.45", "--set", "h=1", "L=1", "E_star=1", "--dps", "25", "--json"]) == 0
    row = json.loads(capsys.readouterr().out)["rows"][0]
    with mpmath.workdps(30):
        assert _agree(mpmath.mpf(row["value"]), mpmath.pi * mpmath.sin(mpmath.pi * mpmath.mpf("0.45"))**2) >= 24


@pytest.mark.slow
def test_plots_in_westergaards_and_johnsons_axes(contacts):
    """pbar/p* = sin^2(pi a/L) (Westergaard), p/p* over a period against his
    printed pressure, and Johnson's P/(p* L) = sin^2 - alpha sqrt(tan)."""
    import numpy as np
    from linecontact_sym.views.contact_plots import wavy_force_data, wavy_pressure_data
    c = contacts["sinusoid"]
    X, Y = wavy_force_data(c, {"h": 1, "L": 2})
    assert np.max(np.abs(Y - np.sin(np.pi * X)**2)) < 1e-13
    X, Ys, As = wavy_pressure_data(c, (0.25, 0.75), {"h": 1, "L": 2})
    for f, Yp, aL in zip((0.25, 0.75), Ys, As):
        S = np.sin(np.pi * aL)
        assert abs(S**2 - f) < 1e-13
        west = np.where(np.abs(X) < aL, 2 * f * np.cos(np.pi * X)
                        * np.sqrt(np.clip(S**2 - np.sin(np.pi * X)**2, 0, None)) / S**2, 0)
        assert np.max(np.abs(Yp - west)) < 1e-12
    al = 0.3
    X, Y = wavy_force_data(c.adhesive(gam), {"h": 1, "L": 1, "gamma": al**2 * np.pi**2 / 2})
    assert np.max(np.abs(Y - (np.sin(np.pi * X)**2 - al * np.sqrt(np.tan(np.pi * X))))) < 1e-12
    with pytest.raises(DomainError, match="infinite"):
        wavy_force_data(contacts["wedge"], {"theta": 0.2, "L": 1})


@pytest.mark.slow
def test_claims_of_westergaard_and_johnson(tmp_path):
    """The shipped claims file wavy1995 holds; a misprinted pressure (cos
    for sin under the root) does not."""
    from linecontact_sym.claims.batch import check_file
    from linecontact_sym.claims.results import FAILS, HOLDS
    res = check_file("wavy1995", budget=300)
    assert [r.status for r in res.results] == [HOLDS] * 3
    assert all(r.digits >= 30 for r in res.results)
    from linecontact_sym.claims.spec import resolve_paper
    text = resolve_paper("wavy1995").read_text()
    wrong = text.replace("sqrt(sin(pi*a/L)**2 - sin(pi*x/L)**2)\"", "sqrt(sin(pi*a/L)**2 - sin(pi*x/L)**2)*cos(pi*a/L)\"")
    assert wrong != text
    f = tmp_path / "wrong.toml"
    f.write_text(wrong)
    res = check_file(f, budget=300, only={"Westergaard (1939): pressure"})
    assert [r.status for r in res.results] == [FAILS]


# ---------------------------------------------------------------- at the limits (issue 42, classes 9 and 10)
@pytest.mark.parametrize("profile, period", [
    (h * (1 - sp.cos(4 * sp.pi * x / L)), L),           # two troughs per period: a negative gap at the second
    (1 - sp.cos(2 * sp.pi * x), 1000),                  # a profile of period 1 declared with period 1000
    (R - sp.sqrt(R**2 - x**2), 4 * R),                  # not real beyond x = R = L/4
])
def test_one_compact_contact_per_period_or_a_clear_refusal(profile, period):
    import time
    t0 = time.perf_counter()
    with pytest.raises(lcs.InadmissibleProfileError, match="half period"):
        lcs.LineContact(profile, period=period)
    assert time.perf_counter() - t0 < 10          # the period-1000 case ran past 10 minutes


def test_half_width_at_the_full_contact_load_is_half_the_period(contacts):
    c = contacts["sinusoid"]
    P = c.evaluate_at("force", a=sp.Rational(1, 2), h=1, L=1, E_star=1)
    assert c.half_width(P, h=1, L=1, E_star=1) == mpmath.mpf(1) / 2
    # and just below it, Westergaard's a = (L/pi) asin(sqrt(P/(pi E* h))) recomputed here
    with mpmath.workdps(30):
        Pb = mpmath.pi * (1 - mpmath.mpf(10)**-12)
        ref = mpmath.asin(mpmath.sqrt(Pb / mpmath.pi)) / mpmath.pi
        assert _agree(c.half_width(sp.Float(Pb, 30), h=1, L=1, E_star=1), ref) >= 12


def test_full_contact_at_holds_the_digits_its_record_states(contacts):
    """full_contact_at(dps=30) returned a 53-bit number with 'digits = 30': checked against
    Johnson's equation (own findroot at 50 digits), alpha = 0.5."""
    ad = contacts["sinusoid"].adhesive(gam)
    # called at mpmath's default precision, as a user does
    fc = ad.full_contact_at(dps=30, h=1, L=1, E_star=1, gamma=sp.Rational(1, 8) * sp.pi**2)
    assert fc.digits >= 30 and fc.force._mpf_[3] >= 100          # the mantissa holds 30 digits
    with mpmath.workdps(50):
        al = mpmath.mpf(1) / 2
        f, df = _johnson(al)
        u_fc = mpmath.findroot(df, 1.2)
        assert _agree(fc.force, mpmath.pi * f(u_fc)) >= 29


@pytest.mark.slow
def test_weak_adhesion_pull_off_below_the_scan_and_snap_next_to_full_contact(contacts):
    """gamma = 1e-40 (h = L = E* = 1): the pull-off at a ~ 3e-15 (the scan started at 1e-12: 'no
    pull-off') and the snap into full contact 1.3e-9 below L/2 at about pi E* h (was 0.0, 'full
    contact at zero load'), against Johnson's equation recomputed here (alpha^2 = 2 gamma/pi^2)."""
    ad = contacts["sinusoid"].adhesive(gam)
    g = sp.Float("1e-40", 40)
    with mpmath.workdps(60):
        al = mpmath.sqrt(2 * mpmath.mpf("1e-40")) / mpmath.pi
        f, df = _johnson(al)
        u_po = mpmath.findroot(df, (al / 4)**(mpmath.mpf(2) / 3))      # 2u ~ alpha/(2 sqrt(u)) at small u
        u_fc = mpmath.findroot(df, mpmath.pi / 2 - mpmath.mpf("4e-9"))
        po = ad.pull_off_at(dps=20, h=1, L=1, E_star=1, gamma=g)
        assert _agree(po.force, mpmath.pi * f(u_po)) >= 18 and _agree(po.half_width, u_po / mpmath.pi) >= 15
        fc = ad.full_contact_at(dps=20, h=1, L=1, E_star=1, gamma=g)
        assert fc.kind == "stationary" and not fc.at_zero_load
        assert _agree(fc.force, mpmath.pi * f(u_fc)) >= 20


def test_no_adhesion_closes_the_array_at_the_full_contact_load(contacts):
    """gamma = 0 at the point: P(a) = pi E* h sin^2(pi a/L) rises to P* = pi E* h at a = L/2
    (was the internal exception Outside)."""
    fc = contacts["sinusoid"].adhesive(gam).full_contact_at(dps=20, h=1, L=1, E_star=1, gamma=0)
    assert fc.kind == "end" and fc.half_width == mpmath.mpf(1) / 2
    with mpmath.workdps(30):
        assert _agree(fc.force, +mpmath.pi) >= 20


def test_kernel_condition_is_mapped_not_copied(contacts):
    """The wedge array's kernel holds for S = sin(pi a/L) < 1; carried over as a < 1 it refused
    every a in [1, L/2).  P(a) at a = 1.5, L = 4 against Eq. (10*) of the kernel twin
    F(s) = tan(theta) (L/pi) asin(s), quadrature here: Q(S) = E* int_0^S s F'(s)/sqrt(S^2 - s^2) ds."""
    c = contacts["wedge"]
    assert sp.Lt(a, 1) not in c.derivation("force").conditions
    r = c.evaluate("force", a=1.5, theta=0.2, L=4, E_star=1, rtol=1e-12)
    with mpmath.workdps(30):
        S = mpmath.sin(mpmath.pi * mpmath.mpf(1.5) / 4)
        k = mpmath.tan(mpmath.mpf(0.2)) * 4 / mpmath.pi
        # s = S sin(phi): Q = E* k int_0^(pi/2) S sin(phi) / sqrt(1 - S^2 sin^2(phi)) dphi
        Q = k * mpmath.quad(lambda p: S * mpmath.sin(p) / mpmath.sqrt(1 - S**2 * mpmath.sin(p)**2), [0, mpmath.pi / 2])
        assert _agree(r.value, Q) >= 13


def test_an_exact_period_beyond_float64():
    """period 10**400 (was OverflowError): Westergaard's P = pi E* h sin^2(pi a/L), h = 1 (f = 2 sin^2)."""
    c = lcs.LineContact(1 - sp.cos(2 * sp.pi * x / 10**400), period=10**400)
    with mpmath.workdps(30):
        ref = mpmath.pi * mpmath.sin(mpmath.pi / 10)**2
        assert _agree(c.evaluate_at("force", a=10**399, E_star=1), ref) >= 25
        assert _agree(c.evaluate("force", a=10**399, E_star=1, rtol=1e-15).value, ref) >= 15
        assert _agree(c.half_width(sp.Float(ref, 30), E_star=1), mpmath.mpf(10)**399) >= 20
