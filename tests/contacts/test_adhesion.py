"""JKR-adhesive line contacts (issue 3): Popov (2017) Eqs. (29)-(36).

Every closed form is compared with the paper's printed formula *and* with
numbers computed here independently of the package (mpmath quadrature, the
paper's printed force laws, root finding).
"""
from __future__ import annotations

import mpmath
import pytest
import sympy as sp
from hypothesis import given, settings, strategies as st

import linecontact_sym as lcs
from linecontact_sym.core import symbols as S
from linecontact_sym.contacts.adhesion.contact import (AdhesiveLineContact, NoEquilibriumError, NoPullOffError,
                                      NumericValuesRequired, flat_punch_force)
from linecontact_sym.contacts.normal.equilibria import minimum
from linecontact_sym.method.verification import verify
from linecontact_sym.core.errors import DomainError, LineContactError

a, x, E, g, R, n, c, th, b = S.a, S.x, S.E_star, S.gamma, S.R, S.n, S.c, S.theta, S.b
DIG = 30
HSET = settings(max_examples=12, deadline=None)

rat = st.integers(min_value=50, max_value=3000).map(lambda k: sp.Rational(k, 1000))
small_gamma = st.integers(min_value=5, max_value=500).map(lambda k: sp.Rational(k, 1000))


def mp(v, dps=60):
    return mpmath.mpf(sp.N(v, dps))


def fl(sub):
    """80-digit Floats: exact Rationals in symbolic-exponent powers make SymPy
    factor huge integers."""
    return {k: sp.Float(v, 80) for k, v in sub.items()}


def agree(x1, x2, digits=DIG):
    """x1, x2 agree to `digits` significant digits (evaluated at 60)."""
    with mpmath.workdps(60):
        x1, x2 = mp(x1) if not isinstance(x1, mpmath.mpf) else x1, \
            mp(x2) if not isinstance(x2, mpmath.mpf) else x2
        return abs(x1 - x2) <= abs(x2) * mpmath.mpf(10)**(-digits)


def Zn_paper(nv):
    """Eq. (17) as printed: (n-1) sqrt(pi) Gamma(n/2 - 1/2) / (2 Gamma(n/2))."""
    return (nv - 1) * sp.sqrt(sp.pi) * sp.gamma(nv / 2 - sp.S.Half) / (2 * sp.gamma(nv / 2))


def Padh_35(nv, cv, Ev, gv):
    """Eq. (35) as printed."""
    return ((2 * nv - 1) / (2 * nv * nv**(1 / (2 * nv - 1)))
            * (2**(nv - 1) * sp.pi**nv * gv**nv * Ev**(nv - 1) / (cv * Zn_paper(nv)))**(1 / (2 * nv - 1)))


# ---------------------------------------------------------------- fixtures
@pytest.fixture(scope="module")
def par():
    return lcs.parabola().adhesive(lcs.gamma)


@pytest.fixture(scope="module")
def pw():
    return lcs.power_law().adhesive(lcs.gamma)


@pytest.fixture(scope="module")
def wed():
    return lcs.wedge().adhesive(lcs.gamma)


def test_contract_and_types(par):
    assert isinstance(par, AdhesiveLineContact)
    assert isinstance(par.force, sp.Expr) and isinstance(par.pressure, sp.Expr)
    assert issubclass(NoPullOffError, DomainError) and issubclass(NoPullOffError, LineContactError)


# ---------------------------------------------------------------- Eqs. (29), (31), (33)
def test_force_eq33_and_pressure_eq29_symbolic(par, pw, wed):
    Phat = sp.sqrt(2 * sp.pi * a * g * E)
    for ad in (par, pw, wed):
        c0 = ad.contact
        assert sp.simplify(ad.force - (c0.force - Phat)) == 0
        assert sp.simplify(ad.pressure - (c0.pressure - Phat / (sp.pi * sp.sqrt(a**2 - x**2)))) == 0
        for q in ("force", "pressure", "flat_punch_force"):
            d = ad.derivation(q)
            assert d.closed_form and d.verification.passed
            assert d.verification.min_digits >= DIG and len(d.verification.points) >= 5
    # the printed (33) for the power law: E* c_n Z_n a^n - sqrt(2 pi a gamma E*), (17) Z_n
    printed = E * c * Zn_paper(n) * a**n - Phat
    for nv in (sp.Rational(7, 10), sp.Rational(13, 4), 5):
        sub = fl({n: nv, c: sp.Rational(6, 5), E: sp.Rational(3, 2), g: sp.Rational(1, 7), a: sp.Rational(2, 3)})
        assert agree(pw.force.xreplace(sub), printed.xreplace(sub))


def test_pressure_integrates_to_force_and_stress_intensity(par):
    """Independent: 2 int_0^a p dx = P(a) (Eq. 33) and the edge stress
    intensity of (29) satisfies K_I^2/(2E*) = gamma (Eqs. 30/31)."""
    vals = {R: sp.Rational(3, 2), E: sp.Rational(7, 4), g: sp.Rational(1, 20), a: sp.Rational(4, 5)}
    pf = sp.lambdify(x, par.pressure.xreplace(vals), "mpmath")
    with mpmath.workdps(100):  # x close to a: a^2 - x^2 cancels 40 digits
        A = mp(vals[a], 100)
        # x = a sin(phi): the inverse-sqrt end singularity becomes bounded
        I = 2 * mpmath.quad(lambda ph: pf(A * mpmath.sin(ph)).real * A * mpmath.cos(ph),
                            [0, mpmath.pi / 4, mpmath.pi / 2 - mpmath.mpf(10)**-25])
        assert agree(I, par.force.xreplace(vals), 20)  # truncated 1e-25 of the edge
        xe = A * (1 - mpmath.mpf(10)**-40)
        K = -mpmath.sqrt(2 * mpmath.pi * (A - xe)) * pf(xe)
        assert abs(K**2 / (2 * mp(vals[E])) / mp(vals[g]) - 1) < mpmath.mpf(10)**-DIG
    assert sp.simplify(par.stress_intensity - sp.sqrt(2 * g * E)) == 0
    assert sp.simplify(par.energy_release_rate - g) == 0


def test_phat_eq31_energy_balance_independent():
    """G = (P^2/2) |dC/d(2a)| of the flat punch, C from Eq. (3) printed, = gamma."""
    for av, Ev, gv in [("0.3", "2.5", "0.07"), ("1.7", "0.6", "0.41")]:
        with mpmath.workdps(60):
            A, Ev, gv = mpmath.mpf(av), mpmath.mpf(Ev), mpmath.mpf(gv)
            L = mpmath.mpf(10)**70
            dC = mpmath.diff(lambda u: 2 * mpmath.acosh(L / u) / (mpmath.pi * Ev), A)
            Pv = mpmath.findroot(lambda p: p**2 / 4 * abs(dC) - gv, 1)
            assert agree(Pv, flat_punch_force(sp.Rational(str(gv)), sp.Rational(av), sp.Rational(str(Ev))))


def test_gamma_zero_recovers_engine(par, pw, wed):
    for ad in (par, pw, wed):
        assert ad.force.subs(g, 0) == ad.contact.force
        assert ad.pressure.subs(g, 0) == ad.contact.pressure
    zero = lcs.parabola().adhesive(0)
    assert zero.force == zero.contact.force
    with pytest.raises(NoPullOffError):
        zero.pull_off_force
    vals = dict(R=2, E_star=3)
    a_engine = zero.contact.half_width(sp.Rational(1, 2), **vals)
    (a_adh,) = zero.half_width(sp.Rational(1, 2), **vals)
    assert agree(a_adh, a_engine)


# ---------------------------------------------------------------- Eq. (34) parabola
def test_parabola_barquins_eq34(par):
    printed = -sp.Rational(3, 4) * (4 * sp.pi * R * E * g**2)**sp.Rational(1, 3)
    assert sp.simplify(par.pull_off_force - printed) == 0
    assert sp.simplify(par.adhesion_force + printed) == 0
    assert sp.simplify(par.pull_off_half_width - (2 * R**2 * g / (sp.pi * E))**sp.Rational(1, 3)) == 0
    for q in ("pull_off_force", "adhesion_force", "pull_off_half_width", "jump_in_half_width"):
        d = par.derivation(q)
        assert d.closed_form and d.verification.min_digits >= DIG and len(d.verification.points) >= 5


@HSET
@given(Rv=rat, Ev=rat, gv=small_gamma)
def test_parabola_pull_off_independent_numbers(par, Rv, Ev, gv):
    """Minimise P(a) = pi E* a^2/(4R) - sqrt(2 pi a gamma E*) with mpmath."""
    sub = {R: Rv, E: Ev, g: gv}
    with mpmath.workdps(60):
        Pf = lambda av: mpmath.pi * mp(Ev) * av**2 / (4 * mp(Rv)) - mpmath.sqrt(2 * mpmath.pi * av * mp(gv) * mp(Ev))
        a0 = mp(par.pull_off_half_width.xreplace(sub), 20)
        a_num = mpmath.findroot(lambda av: mpmath.diff(Pf, av), a0 * mpmath.mpf("1.01"))
        assert agree(par.pull_off_half_width.xreplace(sub), a_num)
        assert agree(par.pull_off_force.xreplace(sub), Pf(a_num))
        a_in = mpmath.findroot(Pf, 3 * a_num)
        assert agree(par.jump_in_half_width.xreplace(sub), a_in)
        assert agree(par.jump_in_half_width.xreplace(sub), (32 * Rv**2 * gv / (sp.pi * Ev))**sp.Rational(1, 3))


# ---------------------------------------------------------------- Eq. (35) power law
def test_power_law_eq35_record(pw):
    d = pw.derivation("pull_off_force")
    assert d.closed_form and sp.Gt(n, sp.S.Half) in d.conditions
    assert d.verification.min_digits >= DIG and len(d.verification.points) >= 5
    assert pw.derivation("pull_off_half_width").verification.min_digits >= DIG
    assert "sympy.solve" in d.method


@HSET
@given(nv=st.integers(min_value=55, max_value=600).map(lambda k: sp.Rational(k, 100)),
       cv=rat, Ev=rat, gv=small_gamma)
def test_power_law_matches_printed_eq35(pw, nv, cv, Ev, gv):
    if nv == 1:
        nv = sp.Rational(101, 100)  # printed Z_n is 0 * Gamma(0) at n = 1
    sub = fl({n: nv, c: cv, E: Ev, g: gv})
    printed = Padh_35(*(sub[k] for k in (n, c, E, g)))
    assert agree(pw.adhesion_force.xreplace(sub), printed)
    assert agree(pw.pull_off_force.xreplace(sub), -printed)


def test_power_law_independent_minimisation(pw):
    """P(a) from the quadrature of Eq. (10*) (f = c x^n), minimised with mpmath."""
    for nv, cv, Ev, gv in [(sp.Rational(3, 4), 1, 2, sp.Rational(1, 10)), (sp.Rational(9, 2), sp.Rational(1, 3), 1, sp.Rational(3, 10))]:
        sub = fl({n: nv, c: cv, E: Ev, g: gv})
        with mpmath.workdps(50):
            nn, cc, EE, gg = mp(nv), mp(cv), mp(Ev), mp(gv)

            def P(av):
                P0 = EE * av * mpmath.quad(lambda ph: mpmath.sin(ph) * cc * nn * (av * mpmath.sin(ph))**(nn - 1),
                                           [0, mpmath.pi / 2])
                return P0 - mpmath.sqrt(2 * mpmath.pi * av * gg * EE)
            a0 = mp(pw.pull_off_half_width.xreplace(sub), 15)
            a_num = mpmath.findroot(lambda av: mpmath.diff(P, av), a0 * mpmath.mpf("1.001"))
            assert agree(a_num, pw.pull_off_half_width.xreplace(sub), 25)
            assert agree(P(a_num), pw.pull_off_force.xreplace(sub), DIG)


def test_power_law_special_cases(pw):
    sub2 = {n: 2, c: 1 / (2 * R)}
    assert sp.simplify(pw.pull_off_force.xreplace(sub2)
                       + sp.Rational(3, 4) * (4 * sp.pi * R * E * g**2)**sp.Rational(1, 3)) == 0
    sub1 = {n: 1, c: sp.tan(th)}
    assert sp.simplify(pw.pull_off_force.xreplace(sub1) + sp.pi * g / (2 * sp.tan(th))) == 0


def test_wrong_formula_fails_verification(pw):
    """The reference discriminates: (35) without its n^(1/(2n-1)) fails."""
    wrong = -(2 * n - 1) / (2 * n) * (2**(n - 1) * sp.pi**n * g**n * E**(n - 1)
                                      / (c * Zn_paper(n)))**(1 / (2 * n - 1))
    good = pw.derivation("pull_off_force")
    rec = verify(wrong, good.reference, pw._sampler("force"), good.conditions, n_points=3)
    assert rec.min_digits < 3


# ---------------------------------------------------------------- existence
def test_existence_condition_power_law(pw):
    for nv in (sp.Rational(1, 3), sp.Rational(1, 2)):
        ad = lcs.power_law(n=nv).adhesive()
        with pytest.raises(NoPullOffError, match="n > 1/2"):
            ad.pull_off_force
    with pytest.raises(NoPullOffError):
        pw.pull_off_at(n=sp.Rational(2, 5), c=1, E_star=1, gamma=sp.Rational(1, 10))
    ok = pw.pull_off_at(n=sp.Rational(3, 5), c=1, E_star=1, gamma=sp.Rational(1, 10))
    assert ok.force < 0 and agree(ok.adhesion_force, Padh_35(*(sp.Float(v, 80) for v in ("0.6", 1, 1, "0.1"))))


def test_below_bound_structure():
    """n = 2/5 < 1/2: P has a maximum; small-a branch stable, large-a unstable;
    at tensile loads only the unstable branch; the numeric search agrees."""
    ad = lcs.power_law(n=sp.Rational(2, 5)).adhesive()
    vals = dict(c=1, E_star=1, gamma=sp.Rational(1, 10))
    K = mp(sp.sqrt(sp.pi) * sp.gamma(sp.Rational(7, 10)) / sp.gamma(sp.Rational(1, 5)))
    with mpmath.workdps(40):
        B = mpmath.sqrt(2 * mpmath.pi / 10)
        a_max = (B / (2 * mpmath.mpf(2) / 5 * K))**(1 / (mpmath.mpf(2) / 5 - mpmath.mpf(1) / 2))
        P_max = K * a_max**mpmath.mpf("0.4") - B * mpmath.sqrt(a_max)
    br = ad.branches(P_max / 2, **vals)
    assert [s for _, s in br] == ["stable", "unstable"] and br[0][0] < a_max < br[1][0]
    br = ad.branches(-1, **vals)
    assert [s for _, s in br] == ["unstable"]
    with pytest.raises(NoEquilibriumError):
        ad.half_width(2 * P_max, **vals)
    with pytest.raises(NoPullOffError):
        minimum(ad._law(ad._numeric_values(vals), "closed"), 30)


def test_gamma_critical_at_n_half():
    ad = lcs.power_law(n=sp.Rational(1, 2)).adhesive()
    with pytest.raises(NoPullOffError, match="gamma_c"):
        ad.pull_off_force


# ---------------------------------------------------------------- Eq. (36) wedge
def test_wedge_eq36(wed):
    assert sp.simplify(wed.pull_off_force + sp.pi * g / (2 * sp.tan(th))) == 0
    assert E not in wed.pull_off_force.free_symbols
    d = wed.derivation("pull_off_force")
    assert d.verification.min_digits >= DIG and len(d.verification.points) >= 5
    assert sp.simplify(wed.pull_off_half_width - sp.pi * g / (2 * E * sp.tan(th)**2)) == 0
    assert sp.simplify(wed.jump_in_half_width - 2 * sp.pi * g / (E * sp.tan(th)**2)) == 0


def test_wedge_branches_closed_form(wed):
    st_, un_ = wed.half_width(S.P)
    assert st_.closed_form and un_.closed_form
    assert st_.verification.min_digits >= DIG and un_.verification.min_digits >= DIG
    vals = {th: sp.Rational(1, 2), E: 2, g: sp.Rational(1, 10)}
    Pmin = wed.pull_off_force.xreplace(vals)
    L = Pmin / 3
    num = wed.half_width(L, theta=vals[th], E_star=2, gamma=vals[g])
    assert len(num) == 2 and num[0] > num[1]
    assert agree(st_.expr.xreplace({**vals, S.P: L}), num[0])
    assert agree(un_.expr.xreplace({**vals, S.P: L}), num[1])
    # both satisfy P(a) = L; stability from dP/da
    dP = sp.diff(wed.force, a)
    for av, sign in zip(num, (1, -1)):
        assert agree(wed.force.xreplace({**vals, a: sp.Float(av, 50)}), L, 28)
        assert sp.sign(dP.xreplace({**vals, a: sp.Float(av, 50)})) == sign
    with pytest.raises(NoEquilibriumError):
        wed.half_width(Pmin * 1.01, theta=vals[th], E_star=2, gamma=vals[g])


@HSET
@given(Rv=rat, Ev=rat, gv=small_gamma, frac=st.integers(min_value=-95, max_value=300))
def test_parabola_equilibria(par, Rv, Ev, gv, frac):
    """Stable first; P(a) = L at 30 digits; two roots iff P_min < L < 0."""
    Pmin = par.pull_off_force.xreplace({R: Rv, E: Ev, g: gv})
    L = -Pmin * sp.Rational(frac, 100)
    roots = par.half_width(L, R=Rv, E_star=Ev, gamma=gv)
    assert len(roots) == (2 if L < 0 else 1)
    a_po = mp(par.pull_off_half_width.xreplace({R: Rv, E: Ev, g: gv}))
    assert roots[0] > a_po and (len(roots) == 1 or roots[1] < a_po)
    with mpmath.workdps(60):
        for r in roots:
            Pv = mpmath.pi * mp(Ev) * r**2 / (4 * mp(Rv)) - mpmath.sqrt(2 * mpmath.pi * r * mp(gv) * mp(Ev))
            assert abs(Pv - mp(L)) <= mpmath.mpf(10)**-DIG * max(abs(mp(L)), abs(mp(Pmin)))


# ---------------------------------------------------------------- numeric pull-off
def test_exact_cylinder_numeric_pull_off():
    ad = lcs.exact_cylinder().adhesive()
    with pytest.raises(NumericValuesRequired, match="pull_off_force_at"):
        ad.pull_off_force
    kw = dict(R=1, E_star=1, gamma=sp.Rational(1, 100))
    po = ad.pull_off_at(**kw)
    assert po.digits >= DIG and po.kind == "stationary"
    # independent: Eq. (26) printed, P = E* R [K(k) - E(k)], k = a/R (mpmath m = k^2)
    with mpmath.workdps(50):
        P = lambda av: mpmath.ellipk(av**2) - mpmath.ellipe(av**2) - mpmath.sqrt(2 * mpmath.pi * av / 100)
        a_num = mpmath.findroot(lambda av: mpmath.diff(P, av), mpmath.mpf("0.18"))
        assert agree(po.half_width, a_num, 25) and agree(po.force, P(a_num))
    assert agree(ad.at(**kw).pull_off_force, po.force)
    # gamma -> 0: approaches Barquins' parabola (relative correction O(a/R)^2)
    tiny = ad.pull_off_at(R=1, E_star=1, gamma=sp.Rational(1, 10**9))
    barq = -sp.Rational(3, 4) * (4 * sp.pi * sp.Rational(1, 10**9)**2)**sp.Rational(1, 3)
    assert abs(tiny.force / mp(barq) - 1) < 1e-4
    # both branches and the jump-in half-width
    (a_s, a_u) = ad.half_width(po.force / 2, **kw)
    assert a_u < po.half_width < a_s
    assert agree(ad.at(**kw).jump_in_half_width, ad.half_width(0, **kw)[0])


def test_worn_cylinder_kink_and_stationary():
    ad = lcs.worn_cylinder().adhesive()
    # weak adhesion (gamma < 2 E* b^3/(pi R^2)): minimum at the kink a = b,
    # P_min = -sqrt(2 pi b gamma E*) exactly
    po = ad.pull_off_at(R=5, b=1, E_star=1, gamma=sp.Rational(1, 100))
    assert po.kind == "kink" and agree(po.half_width, 1)
    # dP/da = 0 mixes asin(b/a) with sqrt(a) and sqrt(a^2 - b^2): not given to sympy.solve
    assert any("asin(b/a) beside other terms in a" in n for n in ad._pull_off_closed()["notes"])
    assert agree(po.force, -sp.sqrt(2 * sp.pi * sp.Rational(1, 100)))
    # strong adhesion: stationary minimum beyond the flat; independent check
    # with the printed Eq. (23)
    po = ad.pull_off_at(R=5, b=1, E_star=1, gamma=20)
    assert po.kind == "stationary" and po.half_width > 1 and po.digits >= DIG
    with mpmath.workdps(50):
        def P(av):
            r = 1 / av
            return (av**2 / 10 * (mpmath.pi / 2 - mpmath.asin(r) + r * mpmath.sqrt(1 - r**2))
                    - mpmath.sqrt(40 * mpmath.pi * av))
        a_num = mpmath.findroot(lambda av: mpmath.diff(P, av), po.half_width * (1 + mpmath.mpf(10)**-8))
        assert agree(po.half_width, a_num, 25) and agree(po.force, P(a_num))
    d = ad.derivation("pull_off_force")
    assert not d.closed_form and d.verification.min_digits >= DIG and len(d.verification.points) >= 5


def test_solve_is_not_tried_where_it_cannot_invert():
    """sympy.solve has no inverse of a Bessel or elliptic function of a: it
    raises NotImplementedError (after up to 5 CPU s for the Gaussian bump's
    besseli law, or runs into the budget for the exact cylinder's elliptic
    laws), so the pull-off and the branches do not ask it; an elementary law
    is still its."""
    from linecontact_sym.contacts.adhesion.pull_off import unsolvable
    bump = sp.pi * E * a * sp.besselj(1, a) / 2 - sp.sqrt(2 * sp.pi * g * E * a)
    assert "besselj" in unsolvable(sp.diff(bump, a))
    assert "elliptic_k" in unsolvable(a * sp.elliptic_k(a**2) - 1)
    assert unsolvable(sp.pi * E * a**2 / (4 * R) - sp.sqrt(2 * sp.pi * g * E * a)) is None
    for e in ((a - 2) * sp.besselj(1, a), sp.besselj(1, a) - sp.Rational(1, 2)):   # what the precheck stands on
        with pytest.raises(NotImplementedError):
            sp.solve(e, a)


def test_solve_is_not_tried_where_trigonometric_and_algebraic_terms_mix():
    """An (inverse) trigonometric function of a beside other terms in a, in
    one factor of one piece (the worn cylinder's adhesive dP/da: asin(b/a),
    sqrt(a), sqrt(a^2 - b^2)): sympy.solve raises 'multiple generators'
    (after 9-11 CPU s for the worn cylinder), so it is not asked; one
    generator alone, or trigonometric functions only, are still its."""
    from linecontact_sym.contacts.adhesion.pull_off import unsolvable
    b = sp.Symbol("b", positive=True)
    mixed = (sp.acos(b / a) - sp.sqrt(a**2 - b**2) / b, sp.sin(a) - a / 2, (a - 2) * (sp.sin(a) - a / 2),
             sp.Piecewise((1 / a, a <= 1), (sp.atan(a) - a / 2, True)))
    for e, name in zip(mixed, ("acos", "sin", "sin", "atan")):
        assert name in unsolvable(e), e
        with pytest.raises(NotImplementedError, match="multiple generators"):   # what the precheck stands on
            sp.solve(e, a)
    for e, roots in ((sp.asin(b / a) - sp.pi / 6, [2 * b]), (a * (sp.asin(b / a) - sp.pi / 6), [2 * b]),
                     (sp.sin(a) - sp.cos(a), [sp.pi / 4]), (sp.exp(a) - 3, [sp.log(3)])):
        assert unsolvable(e) is None, e
        assert sp.solve(e, a) == roots


# ---------------------------------------------------------------- input errors
def test_input_errors():
    cp = lcs.parabola()
    with pytest.raises(DomainError):
        cp.adhesive("gamma")
    with pytest.raises(DomainError):
        cp.adhesive(-1)
    with pytest.raises(DomainError):
        cp.adhesive(sp.Symbol("w"))  # sign unknown
    w = sp.Symbol("w", positive=True)
    ad = cp.adhesive(2 * w)
    assert sp.simplify(ad.force - (cp.force - 2 * sp.sqrt(sp.pi * a * w * E))) == 0


def test_global_precision_untouched(par):
    before = mpmath.mp.dps
    par.pull_off_at(R=1, E_star=1, gamma=sp.Rational(1, 10))
    par.half_width(sp.Rational(-1, 100), R=1, E_star=1, gamma=sp.Rational(1, 10))
    assert mpmath.mp.dps == before


def test_user_profile_numeric_pull_off():
    """f = x^2 + x^4: closed force law, no closed pull-off; both methods and an
    independent minimisation of the quadrature of Eq. (10*) agree."""
    ad = lcs.LineContact(x**2 + x**4).adhesive()
    po = ad.pull_off_at(E_star=2, gamma=sp.Rational(1, 5))
    assert po.digits >= DIG and po.force < 0
    with mpmath.workdps(50):
        def P(av):  # f'(t) = 2t + 4t^3, t = a sin(phi)
            P0 = 2 * av * mpmath.quad(lambda ph: mpmath.sin(ph) * (2 * av * mpmath.sin(ph)
                                                                   + 4 * (av * mpmath.sin(ph))**3),
                                      [0, mpmath.pi / 2])
            return P0 - mpmath.sqrt(2 * mpmath.pi * av * mpmath.mpf(2) / 5)
        a_num = mpmath.findroot(lambda av: mpmath.diff(P, av), po.half_width * (1 + mpmath.mpf(10)**-6))
        assert agree(po.half_width, a_num, 25) and agree(po.force, P(a_num))
    stable, unstable = ad.branches(po.force / 2, E_star=2, gamma=sp.Rational(1, 5))
    assert stable[1] == "stable" and unstable[1] == "unstable" and unstable[0] < po.half_width < stable[0]


def test_bound_values(par):
    bound = par.at(R=2, E_star=3, gamma=sp.Rational(1, 10))
    assert bound.pull_off_force == par.pull_off_force.xreplace({R: 2, E: 3, g: sp.Rational(1, 10)})
    assert bound.force.free_symbols == {a}
