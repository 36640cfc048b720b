"""Results you can trust (issue 9): equilibria that cannot be missed,
admissibility as part of every result, verification that is independent.

Each numbered test reproduces one item of the issue; the numbers it asserts
are computed here, independently of the package (closed forms worked out by
hand, mpmath quadrature and root finding, numpy polynomial roots).  The
comment "before:" gives what the code printed before the fix.
"""
from __future__ import annotations

import math

import mpmath
import pytest
import sympy as sp
from hypothesis import example, given, settings, strategies as st

import linecontact_sym as lcs
from linecontact_sym.core import symbols as S
from linecontact_sym.contacts.normal.equilibria import admissible_range, equilibria_at, landscape, minimum
from linecontact_sym.contacts.normal.force_law import ForceLaw
from linecontact_sym.method import transforms as T
from linecontact_sym.core.errors import NumericValuesRequired
from linecontact_sym.method.verification import VerificationRecord

x, a, E, R, th = S.x, S.a, S.E_star, S.R, S.theta
B3 = sp.Rational(3, 10)
#: a flat of half-width 3/10 and a parabola with a slope jump there: P(a) has
#: a kink minimum at a = 3/10 and a deeper stationary one near a = 0.854
TWO_MINIMA = sp.Piecewise((0, x < B3), (x**2 / 2 - sp.Rational(9, 200), True))


def P_two_minima(av):
    """P(a) of TWO_MINIMA with E* = gamma = 1, by hand: for a > b,
    P0 = int_b^a t^2/sqrt(a^2 - t^2) dt = (a^2/2)(pi/2 - asin(b/a)) + (b/2) sqrt(a^2 - b^2)."""
    b = mpmath.mpf(3) / 10
    P0 = 0 if av <= b else av**2 / 2 * (mpmath.pi / 2 - mpmath.asin(b / av)) + b / 2 * mpmath.sqrt(av**2 - b**2)
    return P0 - mpmath.sqrt(2 * mpmath.pi * av)


@pytest.fixture(scope="module")
def two_minima():
    return lcs.LineContact(TWO_MINIMA).adhesive(1)


# ---------------------------------------------------------------- item 1
def test_item1_pull_off_is_the_global_minimum(two_minima):
    """before: P = -1.3729 at the kink a = b, 'verified' to 30 digits;
    after: the deeper stationary minimum P = -1.75458..., both minima listed."""
    po = two_minima.pull_off_at(E_star=1)
    with mpmath.workdps(40):
        a_ref = mpmath.findroot(lambda v: mpmath.diff(P_two_minima, v), mpmath.mpf("0.85"))
        P_ref = P_two_minima(a_ref)
        assert P_ref < P_two_minima(mpmath.mpf(3) / 10)          # deeper than the kink
        assert abs(po.force - P_ref) < mpmath.mpf(10)**-28 * abs(P_ref)
        assert abs(po.half_width - a_ref) < mpmath.mpf(10)**-20
    assert po.kind == "stationary" and po.digits >= 30
    kinds = sorted((e.kind, round(float(e.half_width), 6)) for e in po.minima)
    assert kinds == [("kink", 0.3), ("stationary", round(float(a_ref), 6))]


# ---------------------------------------------------------------- item 2
def test_item2_pull_off_inside_the_admissible_range():
    """before: NoPullOffError 'still decreasing at a = 1.2e24' for 1 - cos(x);
    after: the stationary minimum inside a* = j_{0,1}, and a* itself."""
    ad = lcs.LineContact(1 - sp.cos(x), verify=False).adhesive(sp.Rational(1, 100))
    po = ad.pull_off_at(E_star=1)
    with mpmath.workdps(40):
        # P0 = E* a int_0^{pi/2} sin(phi) sin(a sin phi) dphi = (pi/2) a J1(a)
        P = lambda v: mpmath.pi / 2 * v * mpmath.besselj(1, v) - mpmath.sqrt(2 * mpmath.pi * v / 100)  # noqa
        a_ref = mpmath.findroot(lambda v: mpmath.diff(P, v), mpmath.mpf("0.2"))
        assert abs(po.force - P(a_ref)) < mpmath.mpf(10)**-28 * abs(P(a_ref))
        lo, hi, end, note = admissible_range(ad._law(ad._numeric_values({"E_star": 1}), "closed"))
        assert end == "admissible" and abs(hi - mpmath.besseljzero(0, 1)) < mpmath.mpf(10)**-12
    assert [e.kind for e in po.minima] == ["stationary", "end"]
    # the Gaussian bump at small gamma: a pull-off exists inside its range
    ad = lcs.LineContact(1 - sp.exp(-x**2), verify=False).adhesive(sp.Rational(1, 1000))
    po = ad.pull_off_at(E_star=1)
    with mpmath.workdps(40):
        def Pg(v):  # Eq. (10*) by quadrature, f'(t) = 2 t exp(-t^2)
            f1 = lambda t: 2 * t * mpmath.exp(-t**2)  # noqa: E731
            return v * mpmath.quad(lambda p: mpmath.sin(p) * f1(v * mpmath.sin(p)), [0, mpmath.pi / 2]) \
                - mpmath.sqrt(2 * mpmath.pi * v / 1000)
        a_ref = mpmath.findroot(lambda v: mpmath.diff(Pg, v), po.half_width * (1 + mpmath.mpf(10)**-6))
        assert abs(po.force - Pg(a_ref)) < mpmath.mpf(10)**-25 * abs(Pg(a_ref))


# ---------------------------------------------------------------- item 3
def test_item3_every_equilibrium_at_a_load(two_minima):
    """before: half_width(-1.74) raised NoEquilibriumError and branches(-1.37)
    gave 2 of the 4 equilibria; after: all of them, each P(a) = load."""
    stable = two_minima.half_width(sp.Rational(-174, 100), E_star=1)
    assert len(stable) == 2
    br = two_minima.branches(sp.Rational(-137, 100), E_star=1)
    assert [s for _, s in br] == ["stable", "stable", "unstable", "unstable"]
    with mpmath.workdps(40):
        for av, _ in br:
            assert abs(P_two_minima(av) + mpmath.mpf("1.37")) < mpmath.mpf(10)**-25
        # stable ones at a rising P (dP/da > 0), unstable at a falling one
        for av, s in br:
            assert (mpmath.diff(P_two_minima, av) > 0) == (s == "stable")
    with pytest.raises(lcs.DomainError, match="below the pull-off"):
        two_minima.half_width(-2, E_star=1)


# ---------------------------------------------------------------- item 4
def test_item4_wedge_typed_by_hand_keeps_its_closed_form():
    """before: 'no closed form (dP/da = 0 is transcendental here)', theta
    sampled in (0.5, 2.5); after: Eq. (36), theta sampled below pi/2."""
    c = lcs.LineContact(x * sp.tan(th))
    lo, hi = c.profile.ranges[th]
    assert hi <= math.pi / 2 and abs(hi - math.pi / 2) < 1e-6
    ad = c.adhesive()
    assert sp.simplify(ad.pull_off_force + sp.pi * S.gamma / (2 * sp.tan(th))) == 0
    rec = ad.derivation("pull_off_force").verification
    assert rec.passed and all(0 < v[th] < sp.pi / 2 for v in rec.points)


# ---------------------------------------------------------------- item 5
def test_item5_parameter_case_of_a_piecewise_is_a_condition():
    """before: P = 2 E* a^3 for every R, verified to 45 digits; round 2: the
    closed form carried R >= 1 and R < 1 was refused; after (issue 19, item
    3): every case is derived, P = 2 E* a^3 where R >= 1 and pi E* a^2/2
    where R < 1, each verified at points of its own case, and the reference
    (which reads the profile at the point) agrees with both."""
    c = lcs.LineContact(sp.Piecewise((x**2, R < 1), (x**3, True)))
    d = c.derivation("force")
    assert isinstance(d.expr, sp.Piecewise) and d.closed_form
    assert sp.simplify(d.expr.subs(R, 2) - 2 * E * a**3) == 0
    assert sp.simplify(d.expr.subs(R, sp.Rational(1, 2)) - sp.pi * E * a**2 / 2) == 0
    assert d.verification.passed
    with mpmath.workdps(40):
        for Rv, want in ((sp.Rational(1, 2), mpmath.pi / 8), (2, mpmath.mpf(1) / 4)):   # pi a^2/2, 2 a^3 at a = 1/2
            ref = T.force_quad(c.profile, {a: sp.Rational(1, 2), R: Rv, E: 1}, 30)
            assert abs(ref - want) < mpmath.mpf(10)**-28
            assert abs(c.evaluate_at("force", a=sp.Rational(1, 2), R=Rv, E_star=1) - want) < mpmath.mpf(10)**-28


# ---------------------------------------------------------------- item 6
@pytest.mark.parametrize("profile, a_value, exact", [
    (sp.Abs(x - 1) - 1 + 2 * x, 2, 2 + 2 * sp.sqrt(3)),     # f' = 1 | 3: P = a + 2 sqrt(a^2 - 1)
    (sp.Min(x**2, x), 2, 2 * sp.pi / 3),                     # f' = 2t | 1, integrated by hand
])
def test_item6_hidden_kinks_are_breakpoints(profile, a_value, exact):
    """before: 5.46404536... and 2.09442284... printed to 30 digits (4-5
    right), a NameError for the pressure; after: 30 correct digits."""
    c = lcs.LineContact(profile, verify=False)
    assert c.profile.is_piecewise
    got = c.evaluate_at("force", dps=30, a=a_value, E_star=1)
    with mpmath.workdps(40):
        assert abs(got - mpmath.mpf(sp.N(exact, 40))) < mpmath.mpf(10)**-29


def test_item6_pressure_behind_abs_and_oscillation_refused():
    c = lcs.LineContact(sp.Abs(x - 1) - 1 + 2 * x, verify=False)
    with mpmath.workdps(40):
        # P'(s) = 1 (s < 1), 1 + 2 s/sqrt(s^2 - 1) (s > 1); Eq. (12) by hand at a = 2, x = 1/2
        exact = (mpmath.acosh(4) + 2 * mpmath.log((mpmath.sqrt(3) + mpmath.sqrt(mpmath.mpf(15) / 4))
                                                   / mpmath.sqrt(mpmath.mpf(3) / 4))) / mpmath.pi
        got = c.evaluate_at("pressure", dps=30, a=2, x=sp.Rational(1, 2), E_star=1)
        assert abs(got - exact) < mpmath.mpf(10)**-28
    with pytest.raises(lcs.InadmissibleProfileError, match="decreases arbitrarily close"):
        lcs.LineContact(x * sp.sin(1 / x))


# ---------------------------------------------------------------- item 7
def test_item7_error_estimate_covers_the_error_next_to_a_kink():
    """before: float64 with estimated error 1.2e-13, actual 2.1e-11; after:
    the float64 quadrature is not trusted next to the integrand's switch."""
    c = lcs.worn_cylinder(verify=False)
    b = 0.5
    X = b * (1 - 1e-9)
    ref = c.evaluate_at("pressure", dps=40, a=1.0, x=X, R=5.0, b=b, E_star=1.0)
    r = c.evaluate("pressure", a=1.0, x=X, R=5.0, b=b, E_star=1.0, rtol=1e-10)
    assert abs(r.value - ref) <= r.error <= 1e-10 * abs(ref)


# ---------------------------------------------------------------- item 8
def test_item8_message_says_what_happened():
    """before: '(dP/da = 0 is transcendental here)'; after: what sympy.solve did.
    (Two power terms: one, c x**4, is now solved without sympy.solve, issue 22.)"""
    c = lcs.LineContact(S.c * x**4 + x**2 / 2)
    c.derivation("force")
    c.budget = 1e-3
    with pytest.raises(NumericValuesRequired) as exc:
        c.adhesive().pull_off_force
    assert "transcendental" not in str(exc.value) and "within 0.001 s" in str(exc.value)


# ---------------------------------------------------------------- item 9
def test_item9_inadmissible_profiles_and_values_refused():
    """before: -x**2 and x**2 - x**4 'verified to 45 digits' for negative
    loads, I*x**2 'verified at 0 points', x**2 + I*x an unevaluated Integral."""
    with pytest.raises(lcs.InadmissibleProfileError, match="decreases"):
        lcs.LineContact(-x**2)
    for bad in (sp.I * x**2, x**2 + sp.I * x):
        with pytest.raises(lcs.ProfileError, match="not real"):
            lcs.LineContact(bad)
    c = lcs.LineContact(x**2 - x**4)
    rec = c.derivation("force").verification
    assert rec.passed and all(v[a] <= 1 / sp.sqrt(2) for v in rec.points)
    with pytest.raises(lcs.InadmissibleProfileError, match="decreases"):
        c.evaluate_at("force", a=1, E_star=1)
    with pytest.raises(lcs.DomainError, match="declared positive"):
        lcs.parabola().evaluate_at("force", a=1, R=-1, E_star=1)
    # 1 - cos(x) is rising up to pi, but dP0/da < 0 beyond j_{0,1}: tensile edge pressure
    with pytest.raises(lcs.InadmissibleProfileError, match="tensile"):
        lcs.LineContact(1 - sp.cos(x), verify=False).evaluate_at("force", a=sp.Rational(26, 10), E_star=1)
    empty = VerificationRecord((), (), 45, "a quadrature")
    assert not empty.passed and str(empty).startswith("NOT verified")


# ---------------------------------------------------------------- item 10
def test_item10_inside_the_flat_is_zero_not_overflow():
    """before: OverflowError (kappa = inf where the pressure is 0)."""
    c = lcs.worn_cylinder(verify=False)
    r = c.evaluate("pressure", a=0.4, x=0.1, R=5.0, b=0.5, E_star=1.0, rtol=1e-10)
    assert r.value == 0 and r.error == 0


# ---------------------------------------------------------------- item 11
def test_item11_pressure_of_a_piecewise_profile_to_30_digits():
    """Rounded wedge f = x^2/(2R) (x < R tan th), x tan th - R tan^2 th / 2:
    before: 28.6 correct digits of 30 at x = 3/10 (the quadrature lost
    digits next to the breakpoint); after: 30."""
    f = sp.Piecewise((x**2 / (2 * R), x < R * sp.tan(th)), (x * sp.tan(th) - R * sp.tan(th)**2 / 2, True))
    c = lcs.LineContact(f, params={R: (0.5, 2), th: (0.1, 0.6)}, verify=False)
    got = c.evaluate_at("pressure", dps=30, a=1, x=sp.Rational(3, 10), R=1, theta=sp.Rational(1, 2), E_star=1)
    with mpmath.workdps(60):
        # by hand: P'(s) = E* int_0^{pi/2} sin(p) h'(s sin p) dp, h = t f'(t): h' = 2t/R (t < b), tan th
        # (f' is continuous: no slope-jump term); Eq. (12) after s = sqrt(x^2 + w^2).  With R = 1,
        # b = tan th: P'(s) = pi s/2 for s <= b, else (sin p0 = b/s, the integral split at p0)
        # 2s int_0^p0 sin^2 + b int_p0^{pi/2} sin = s (p0 - sin p0 cos p0) + b cos p0
        # (this equals the Gauss-Legendre quadrature of the integral over p to 40 digits, at 1/40 of its CPU)
        b, X = mpmath.tan(mpmath.mpf(1) / 2), mpmath.mpf(3) / 10

        def dP(sv):
            if sv <= b:
                return mpmath.pi * sv / 2
            p0 = mpmath.asin(b / sv)
            return sv * (p0 - mpmath.sin(p0) * mpmath.cos(p0)) + b * mpmath.cos(p0)
        wb, W = mpmath.sqrt(b**2 - X**2), mpmath.sqrt(1 - X**2)
        g = lambda w: dP(mpmath.sqrt(X**2 + w**2)) / mpmath.sqrt(X**2 + w**2)  # noqa: E731
        ref = (mpmath.quad(g, [0, wb]) + mpmath.quad(lambda t: 2 * t * g(wb + t * t), [0, mpmath.sqrt(W - wb)])) \
            / mpmath.pi
        assert abs(got - ref) < mpmath.mpf(10)**-30 * abs(ref)


# ---------------------------------------------------------------- property test
def _poly_law(roots, k, rigorous):
    """A force law with dP/da = k prod(a - r_i): minima at roots[0], [2], ..."""
    p = k * sp.Mul(*[(a - r) for r in roots])
    P = sp.integrate(p, (a, 0, a))
    if rigorous:
        law = ForceLaw.from_closed_form(P, {})
    else:
        fP, fdP = sp.lambdify(a, P, "mpmath"), sp.lambdify(a, p, "mpmath")
        law = ForceLaw(fP, fdP)
    law.base = ForceLaw(lambda A: A, lambda A: mpmath.mpf(1), expr=a)   # admissible everywhere
    return law, P


roots_strategy = st.lists(st.integers(min_value=50, max_value=20000), min_size=3, max_size=5, unique=True) \
    .filter(lambda r: len(r) % 2 == 1).map(lambda r: [sp.Rational(v, 1000) for v in sorted(r)])


def _check(roots, k, load_frac, rigorous):
    law, P = _poly_law(roots, k, rigorous)
    land = landscape(law)
    mins = sorted(e.half_width for e in land.minima)
    assert len(mins) == (len(roots) + 1) // 2
    for got, want in zip(mins, roots[0::2]):
        assert abs(got - mpmath.mpf(want.p) / want.q) < mpmath.mpf(10)**-12 * want
    po = minimum(law, 20)
    exact = min(P.subs(a, r) for r in roots[0::2])
    if exact < 0:
        assert abs(po.force - mpmath.mpf(sp.N(exact, 30))) < mpmath.mpf(10)**-15 * (1 + abs(po.force))
    # equilibria at a load against the exact real roots of the polynomial P(a) - load
    vals = [P.subs(a, r) for r in roots]
    load = min(vals) + (max(vals) - min(vals)) * sp.Rational(round(load_frac * 1000), 1000)
    want = [sp.N(r, 30) for r in sp.real_roots(sp.Poly(P - load, a)) if r > 0]
    got = sorted(e.half_width for e in equilibria_at(law, load, 20))
    assert len(got) == len(want)
    for g, w in zip(got, want):
        assert abs(g - mpmath.mpf(w)) < mpmath.mpf(10)**-12 * mpmath.mpf(w)


@settings(max_examples=15, deadline=None)
@given(roots_strategy, st.integers(min_value=1, max_value=50), st.floats(0.05, 0.95))
def test_property_every_minimum_found_ball(roots, k, frac):
    """Random force laws with 2 or 3 minima at known places (some a few per
    mille apart: the narrow dips a sparse scan misses): every one found by
    the ball-arithmetic search, the global one as the pull-off, and every
    equilibrium at a load."""
    _check(roots, sp.Rational(k, 10), frac, True)


@settings(max_examples=5, deadline=None)
@given(roots_strategy, st.integers(min_value=1, max_value=50), st.floats(0.05, 0.95))
@example([sp.Rational(13, 50), sp.Rational(1811, 1000), sp.Rational(387, 200)], 1, 0.5)
@example([sp.Rational(v, 1000) for v in (2554, 2713, 4168, 4193, 7001)], 20, 0.719)
def test_property_every_minimum_found_adaptive(roots, k, frac):
    """The same for a law without closed form (adaptive subdivision).  The
    examples: a narrow dip between the minimum at 1.935 and the maximum at
    1.811 hid between the three samples of an interval (ends and midpoint),
    found by CI; a second one like it, found by a biased random run."""
    _check(roots, sp.Rational(k, 10), frac, False)
