"""Profiles with a flat in full contact (the worn cylinder, the rounded punch
of Ciavarella, Hills & Monno 1998) and budgets that are deadlines.

Every number is checked against a reference computed here with mpmath from
the published formulas (or from the defining integrals), sharing nothing
with the engine's derivations."""
import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core import symbols as S
from linecontact_sym.core.precision import workdps
from linecontact_sym.method import store

R_, B_, E_ = sp.Integer(5), sp.Rational(1, 2), sp.Integer(1)


def ciavarella_load(a, b, R, E):
    """Ciavarella, Hills & Monno (1998): P = E* a^2/(4R) (pi - 2 phi0 - sin 2 phi0), sin phi0 = b/a."""
    if a <= b:
        return mpmath.mpf(0)
    p0 = mpmath.asin(b / a)
    return E * a**2 / (4 * R) * (mpmath.pi - 2 * p0 - mpmath.sin(2 * p0))


def ciavarella_pressure(x, a, b, R, E):
    """Their published pressure, x = a sin(phi):
    p = E* a/(2 pi R) [(pi - 2 phi0) cos phi + sin phi ln|sin(phi + phi0)/sin(phi - phi0)|
                       + sin phi0 ln|tan((phi + phi0)/2) tan((phi - phi0)/2)|]."""
    ph, p0 = mpmath.asin(x / a), mpmath.asin(b / a)
    return E * a / (2 * mpmath.pi * R) * (
        (mpmath.pi - 2 * p0) * mpmath.cos(ph)
        + mpmath.sin(ph) * mpmath.log(abs(mpmath.sin(ph + p0) / mpmath.sin(ph - p0)))
        + mpmath.sin(p0) * mpmath.log(abs(mpmath.tan((ph + p0) / 2) * mpmath.tan((ph - p0) / 2))))


@pytest.fixture(scope="module")
def punch():
    return lcs.rounded_punch()


def test_rounded_punch_force_and_pressure_against_ciavarella(punch):
    vals = dict(E_star=E_, R=R_, b=B_)
    with workdps(40):
        for a in (sp.Rational(3, 10), sp.Rational(1, 2), sp.Rational(4, 5), sp.Integer(2)):
            got = punch.derivation("force").evalf(35, a=a, **vals)
            ref = ciavarella_load(mpmath.mpf(a), mpmath.mpf(B_), mpmath.mpf(R_), mpmath.mpf(E_))
            assert abs(got - ref) <= mpmath.mpf(10)**-30 * max(abs(ref), 1)
        for a, x in ((sp.Rational(4, 5), sp.Rational(1, 5)), (sp.Rational(4, 5), sp.Rational(3, 5)),
                     (sp.Integer(2), sp.Rational(49, 100)), (sp.Integer(2), sp.Rational(19, 10))):
            got = punch.derivation("pressure").evalf(35, a=a, x=x, **vals)
            ref = ciavarella_pressure(mpmath.mpf(x), mpmath.mpf(a), mpmath.mpf(B_), mpmath.mpf(R_), mpmath.mpf(E_))
            assert abs(got - ref) <= mpmath.mpf(10)**-28 * abs(ref)
    # the flat in full contact at P = 0 (a <= b): no load, no pressure
    assert punch.evaluate("force", a=0.3, E_star=1, R=5, b=0.5).value == 0
    assert punch.evaluate("pressure", a=0.4, x=0.2, E_star=1, R=5, b=0.5).value == 0


@pytest.mark.parametrize("b", [sp.Rational(3, 10), sp.Integer(1), sp.Integer(5)])
@pytest.mark.parametrize("R", [sp.Integer(1), sp.Integer(100)])
def test_rounded_punch_half_width_at_every_load(punch, b, R):
    """b = 3/10 found no half-width at any load: the slope just past the
    flat's end cancelled to a negative number at 20 digits."""
    load = sp.Integer(1)
    a = punch.half_width(load, E_star=1, R=R, b=b)
    with workdps(40):
        ref = mpmath.findroot(lambda A: ciavarella_load(A, mpmath.mpf(b), mpmath.mpf(R), 1) - 1,
                              (mpmath.mpf(b) * (1 + mpmath.mpf(10)**-6), 10 * mpmath.mpf(b) + 100),
                              solver="anderson")
        assert abs(a - ref) <= mpmath.mpf(10)**-25 * ref
    ev = punch.evaluate("half_width", P=1, E_star=1, R=float(R), b=float(b))
    assert abs(ev.value - float(ref)) <= 1e-11 * float(ref)


def test_rounded_punch_jkr_pull_off_against_independent_minimum(punch):
    gamma = sp.Rational(1, 100)
    po = punch.adhesive().pull_off_at(gamma=gamma, E_star=1, R=5, b=sp.Rational(1, 2))
    with workdps(40):
        B1 = mpmath.sqrt(2 * mpmath.pi * mpmath.mpf(gamma))

        def P(A):
            return ciavarella_load(A, mpmath.mpf("0.5"), 5, 1) - B1 * mpmath.sqrt(A)
        a_star = mpmath.findroot(lambda A: mpmath.diff(P, A), mpmath.mpf("0.95"))
        assert abs(po.half_width - a_star) <= mpmath.mpf(10)**-20
        assert abs(po.force - P(a_star)) <= mpmath.mpf(10)**-25 * abs(P(a_star))
        # below the force at the flat's end (P(b) = -B1 sqrt(b)): a stationary minimum past b
        assert po.force < P(mpmath.mpf("0.5")) and po.kind == "stationary"


def test_rounded_punch_tangential_and_gap(punch):
    """Stick zone from P(c) = P(a) - Q/mu (Ciavarella's load law), and the gap
    at the contact edge is 0 and positive outside."""
    c = punch.tangential().state(0.004, mu=0.3, a=0.8, E_star=1, R=5, b=0.5).c
    with workdps(40):
        L = ciavarella_load(mpmath.mpf("0.8"), mpmath.mpf("0.5"), 5, 1) - mpmath.mpf("0.004") / mpmath.mpf("0.3")
        ref = mpmath.findroot(lambda A: ciavarella_load(A, mpmath.mpf("0.5"), 5, 1) - L, mpmath.mpf("0.7"))
        assert abs(c - ref) <= mpmath.mpf(10)**-20
    g = punch.evaluate("gap", a=0.8, x=1.0, E_star=1, R=5, b=0.5).value
    assert g > 0


@pytest.fixture(scope="module")
def circular_corner():
    """f = R - sqrt(R^2 - (x - b)^2) beyond a flat of half-width b: no closed
    force law (its attempt runs to budget=2), one contact for the two tests below."""
    x, R, b = S.x, S.R, S.b
    return lcs.LineContact(sp.Piecewise((0, x < b), (R - sp.sqrt(R**2 - (x - b)**2), True)),
                           params={R: (2.0, 4.0), b: (0.2, 0.8)}, budget=2)


def test_circular_corner_punch_search_ends(circular_corner):
    """f = R - sqrt(R^2 - (x - b)^2) beyond the flat: no closed force law; the
    stationary-point search skips the flat (dP/da = 0 there) instead of
    subdividing it without end (20000 intervals), and the admissible range
    is not searched at all: dP0/da >= 0 is proven from the profile
    (h' = f' + t f'' >= 0, no slope jump), where the sampled search could
    exclude neither end of [b, b + R] (281 quadratures of dP0/da)."""
    from linecontact_sym.contacts.normal.equilibria import admissible_range, landscape
    from linecontact_sym.contacts.normal.force_law import ForceLaw
    c = circular_corner
    a = c.half_width(sp.Rational(1, 10), budget=600, E_star=1, R=3, b=sp.Rational(1, 2))
    with workdps(40):
        def P(A):   # Eq. (10*) by mpmath after t = A sin(phi), from the corner on
            def g(ph):
                t = A * mpmath.sin(ph)
                return t * (t - mpmath.mpf("0.5")) / mpmath.sqrt(9 - (t - mpmath.mpf("0.5"))**2)
            return mpmath.quad(g, [mpmath.asin(mpmath.mpf("0.5") / A), mpmath.pi / 2])
        assert abs(P(a) - mpmath.mpf("0.1")) <= mpmath.mpf(10)**-20
        rising = [P(mpmath.mpf(A)) for A in ("0.6", "1", "2", "3", "3.45")]
        assert all(u < v for u, v in zip(rising, rising[1:]))   # P0 rises over the range (independently)
    law = ForceLaw.from_contact(c, {S.E_star: 1, S.R: 3, S.b: sp.Rational(1, 2)})
    lo, hi, end, _ = admissible_range(law)
    assert law.rising and end == "domain" and abs(hi - mpmath.mpf("3.5")) < 1e-12
    land = landscape(law)
    assert not land.extrema and land.rising_at_end and any("rising_profile" in n for n in land.notes)


def test_unresolved_search_notes_are_true():
    """A note of the stationary-point search names a possible touching zero
    only where dP/da comes near 0.  The circular-corner punch's dP0/da grows
    like 1/sqrt(3.5 - a) at the end of its domain (about 1e10 within 1e-10 of
    it): the sampled bound cannot exclude that end at any width, and the note
    once called it "within the search resolution of 0" there."""
    import re
    from linecontact_sym.contacts.normal.equilibria import crossings

    def steep(A):      # one sign, rising without bound toward the end a = 2
        return 1 / mpmath.sqrt(2 - A) if A < 2 else mpmath.mpf(10)**30

    def touching(A):   # a double zero at a = 3/2
        return (A - mpmath.mpf(3) / 2)**2
    with workdps(20):
        for g, zero in ((steep, None), (touching, mpmath.mpf(3) / 2)):
            notes = []
            assert crossings(g, mpmath.mpf(1), mpmath.mpf(2), notes=notes) == []
            near = [mpmath.mpf(v) for n in notes
                    for v in re.findall(r"within the search resolution of 0 near a = ([0-9.e+-]+)", n)]
            for A in near:   # true where given: dP/da there is small next to its size on [1, 2]
                assert abs(g(A)) < 1e-6 * abs(g(mpmath.mpf(1))), notes
            if zero is None:
                assert not near and any("next to the end a = 2" in n and "away from 0" in n for n in notes), notes
            else:
                assert near and all(abs(A - zero) < 1e-9 for A in near), notes


# ------------------------------------------------------------------ budgets
def test_stick_half_width_budget_is_a_deadline_and_remembered():
    t = lcs.parabola(R=2).tangential()
    d = t.stick_half_width(budget=0.2)        # too little to invert and verify: honest, unevaluated
    assert not d.closed_form and d.attempts and isinstance(d.expr, sp.Eq)
    full = t.stick_half_width()
    assert full.closed_form and full.verification.passed
    with workdps(40):   # c_s = sqrt(a^2 - 4 R Q/(pi E* mu)) from Hertz, by hand
        v = full.evalf(30, a=1, Q=sp.Rational(1, 10), E_star=2, mu=sp.Rational(1, 2))
        assert abs(v - mpmath.sqrt(1 - 8 * mpmath.mpf("0.1") / (mpmath.pi * 2 * mpmath.mpf("0.5")))) < 1e-28
    store.clear_memory()
    again = lcs.parabola(R=2).tangential().stick_half_width()
    assert again.closed_form and again.cached == "disk" and again.expr == full.expr


def test_sin_profile_force_evaluates():
    """The pFq of a sin(x) profile's force law in the scalar fast path (NameError before)."""
    c = lcs.LineContact(sp.sin(S.x))
    v = c.evaluate("force", a=0.5, E_star=1).value
    with workdps(30):
        ref = mpmath.quad(lambda t: t * mpmath.cos(t) / mpmath.sqrt(mpmath.mpf("0.25") - t**2), [0, 0.5])
    assert abs(v - float(ref)) <= 1e-13 * abs(float(ref))


def test_cosh_pull_off_within_budget_against_mpmath():
    """P0 of cosh(x) - 1 is convex: one stationary point; before, the search
    subdivided up to a = 1e24 without end."""
    c = lcs.LineContact(sp.cosh(S.x) - 1, budget=10).adhesive()
    po = c.pull_off_at(budget=600, E_star=1, gamma=sp.Rational(1, 10))
    with workdps(40):
        def P(A):   # Eq. (10*) of cosh(x) - 1 by mpmath quadrature (t = A sin phi) and Eq. (31)
            P0 = A * mpmath.quad(lambda ph: mpmath.sin(ph) * mpmath.sinh(A * mpmath.sin(ph)), [0, mpmath.pi / 2])
            return P0 - mpmath.sqrt(2 * mpmath.pi * mpmath.mpf("0.1") * A)
        a_star = mpmath.findroot(lambda A: mpmath.diff(P, A), mpmath.mpf("0.39"))
        assert abs(po.half_width - a_star) < mpmath.mpf(10)**-20
        assert abs(po.force - P(a_star)) < mpmath.mpf(10)**-25


@pytest.mark.parametrize("profile", [sp.cosh(S.x) - 1, 1 - sp.cos(S.x), 1 - sp.exp(-S.x**2)])
def test_smooth_pressure_refuses_at_once_and_gives_a_number(profile):
    c = lcs.LineContact(profile)
    fd = c.derivation("force")
    d = c.derivation("pressure")
    assert not d.closed_form
    assert all(why.startswith("not applicable") for _, why in d.attempts)
    fP = sp.lambdify(S.a, sp.diff(fd.expr, S.a).subs(S.E_star, 1), "mpmath")
    with workdps(40):   # Eq. (12) by mpmath, from the force law's derivative, s = sqrt(x^2 + v^2)
        x, a = mpmath.mpf(1) / 5, mpmath.mpf(1) / 2
        ref = mpmath.quad(lambda v: fP(mpmath.sqrt(x**2 + v**2)) / mpmath.sqrt(x**2 + v**2),
                          [0, mpmath.sqrt(a**2 - x**2)]) / mpmath.pi
        got = d.evalf(30, a=sp.Rational(1, 2), x=sp.Rational(1, 5), E_star=1)
        assert abs(got - ref) <= mpmath.mpf(10)**-25 * abs(ref)


def test_quartic_pull_off_closed_and_remembered():
    K = sp.Symbol("K", positive=True)
    ad = lcs.LineContact(K * S.x**4).adhesive()
    d = ad.derivation("pull_off_force")
    assert d.closed_form and d.verification.passed
    with workdps(40):   # P = (3 pi/4) E* K a^4 - sqrt(2 pi gamma E* a): Z_4 = 3 pi/4 (Table 1)
        def P(A):
            return 3 * mpmath.pi / 4 * A**4 - mpmath.sqrt(2 * mpmath.pi * mpmath.mpf("0.1") * A)
        a_star = mpmath.findroot(lambda A: mpmath.diff(P, A), mpmath.mpf("0.4"))
        assert abs(d.evalf(30, K=1, E_star=1, gamma=sp.Rational(1, 10)) - P(a_star)) < mpmath.mpf(10)**-25
    store.clear_memory()
    again = lcs.LineContact(K * S.x**4).adhesive().derivation("pull_off_force")
    assert again.cached == "disk" and again.expr == d.expr


def test_numeric_search_stops_at_its_budget(circular_corner):
    """The circular-corner punch's numeric pull-off needs tens of seconds of
    quadratures: with budget=1 it raises BudgetExceeded (a deadline checked
    between evaluations), instead of running to the end."""
    from linecontact_sym.core.errors import BudgetExceeded
    ad = circular_corner.adhesive()
    with pytest.raises(BudgetExceeded, match="budget of 1 CPU s"):
        ad.pull_off_at(budget=1, E_star=1, R=3, b=sp.Rational(1, 2), gamma=sp.Rational(1, 100))


def test_rounded_punch_pull_off_where_the_grid_crossed_the_flat_end(punch):
    """R = 5.834, b = 1.305: a grid point of the independent method fell just
    past the flat's end, where float64 rounding made P0 -1e-17 < 0 = P0 on
    the flat: it cut its range there ('end' at a = 1.119) and the pull-off
    failed its own verification (0 digits)."""
    v = dict(R=sp.Rational(5834, 1000), b=sp.Rational(1305, 1000), E_star=sp.Rational(787922, 10**6),
             gamma=sp.Rational(265831, 10**6))
    po = punch.adhesive().pull_off_at(**v)
    with workdps(40):
        R, b, E, g = (mpmath.mpf(v[k].p) / v[k].q for k in ("R", "b", "E_star", "gamma"))

        def P(A):
            return ciavarella_load(A, b, R, E) - mpmath.sqrt(2 * mpmath.pi * g * E * A)
        a_star = mpmath.findroot(lambda A: mpmath.diff(P, A), mpmath.mpf("2.5"))
        assert po.kind == "stationary" and po.digits >= 30
        assert abs(po.force - P(a_star)) < mpmath.mpf(10)**-25


def test_pressure_without_closed_force_law_is_one_quadrature():
    """x**2 exp(x)/2: no closed force law (SymPy gives up); the pressure's
    number comes from one quadrature of the profile (0.4 s, was Eq. (12)
    over a quadrature law: 60 s at 30 digits).  The formula is checked on
    cosh(x) - 1 against Eq. (12) with the Bessel force law P = pi E* a I_1(a)/2
    written here by hand."""
    from linecontact_sym.method import transforms as T
    c = lcs.LineContact(S.x**2 * sp.exp(S.x) / 2, budget=3)
    d = c.derivation("pressure")
    assert not d.closed_form and isinstance(d.expr, sp.Integral)
    got = d.evalf(30, a=sp.Rational(1, 2), x=sp.Rational(1, 5), E_star=1)
    ev = c.evaluate("pressure", a=0.5, x=0.2, E_star=1, rtol=1e-20)
    with workdps(40):   # (the float 0.2 is its binary value, not 1/5)
        assert abs(ev.value - d.evalf(30, a=0.5, x=0.2, E_star=1)) < mpmath.mpf(10)**-20
        x, a = mpmath.mpf(1) / 5, mpmath.mpf(1) / 2

        def dP(s):   # d/da of pi a I_1(a)/2
            return mpmath.pi / 2 * (mpmath.besseli(1, s) + s * (mpmath.besseli(0, s) + mpmath.besseli(2, s)) / 2)
        eq12 = mpmath.quad(lambda v: dP(mpmath.sqrt(x**2 + v**2)) / mpmath.sqrt(x**2 + v**2),
                           [0, mpmath.sqrt(a**2 - x**2)]) / mpmath.pi
        direct = T.pressure_direct_quad(mpmath.sinh, {S.a: sp.Rational(1, 2), S.x: sp.Rational(1, 5), S.E_star: 1}, 35)
        assert abs(direct - eq12) < mpmath.mpf(10)**-30
        # and the x**2 exp(x)/2 value against the same formula written out by hand
        f1 = lambda t: t * mpmath.exp(t) + t**2 * mpmath.exp(t) / 2   # noqa: E731
        ph0 = mpmath.asin(x / a)
        g = lambda ph: (a * mpmath.sin(ph) * f1(a * mpmath.sin(ph)) - x * f1(x)) / (a**2 * mpmath.sin(ph)**2 - x**2)  # noqa: E731
        with workdps(90):
            by_hand = mpmath.sqrt(a**2 - x**2) / mpmath.pi * mpmath.quad(g, [0, ph0, mpmath.pi / 2])
        assert abs(got - by_hand) < mpmath.mpf(10)**-25
        # the evaluation's error is a true bound: its enclosure (Arb, one quadrature) holds the
        # same formula by hand at its (binary) x = 0.2, and it meets rtol
        xb = mpmath.mpf(0.2)
        gb = lambda ph: (a * mpmath.sin(ph) * f1(a * mpmath.sin(ph)) - xb * f1(xb)) / (a**2 * mpmath.sin(ph)**2 - xb**2)  # noqa: E731
        with workdps(90):
            by_hand_b = mpmath.sqrt(a**2 - xb**2) / mpmath.pi * mpmath.quad(gb, [0, mpmath.asin(xb / a), mpmath.pi / 2])
            assert ev.certified and ev.error <= 1e-20 * abs(ev.value)
            assert ev.enclosure[0] - mpmath.mpf(10)**-60 <= by_hand_b <= ev.enclosure[1] + mpmath.mpf(10)**-60


def test_rounded_punch_float64_beside_the_flat_end(punch):
    """At |x| = b (the kink of the profile) and within rounding of it, the
    float64 traction and the admissibility test keep
    their digits: the plain translation evaluated atanh(z) with z = 1 - (a
    rounding error) there (inf, NaN, or 33 % off at x = 0.1*3 with b = 0.3)
    and dP0/da = -8e4 at a = b + 1 ulp (the punch refused as tensile).
    Reference: mu [p(x; a) - p(x; c)] from Ciavarella's published pressure
    at the float's exact value, 50 digits."""
    import numpy as np
    b, mu, E, R = 0.3, 0.5, 1, 4
    t = punch.tangential()
    xs = [0.1 * 3, b, float(np.nextafter(b, 0)), float(np.nextafter(b, 1)), b * (1 + 1e-13), b * (1 - 1e-13)]

    def ciav(x, A):      # continuous at x = b, where the published form is 0 * inf: its limit from 1e-40 off
        X = mpmath.mpf(x) + (mpmath.mpf(10)**-40 if x == b else 0)
        return ciavarella_pressure(X, mpmath.mpf(A), mpmath.mpf(b), R, E) if x < A else 0

    st = t.state(0.02, mu=mu, a=1.0, E_star=E, R=R, b=b)       # (unloading takes the same export path)
    got = st.traction(np.array(xs))
    with workdps(50):
        for x, g in zip(xs, got):
            ref = mu * (ciav(x, 1.0) - ciav(x, st.c))
            assert abs(g - ref) <= 1e-12 * abs(ref), (x, g, ref)
    # a = b + 1 ulp is admissible: P(a) > 0 tiny, the pressure of order 1e-26
    A = 0.1 * 3
    ev = punch.evaluate("pressure", a=A, x=0.1, E_star=E, R=R, b=b)
    with workdps(50):
        ref = ciavarella_pressure(mpmath.mpf("0.1"), mpmath.mpf(A), mpmath.mpf(b), R, E)
        assert abs(ev.value - ref) <= mpmath.mpf(10)**-10 * ref
