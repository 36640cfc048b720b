"""The limits of the Maugis-Dugdale law (issue 42, classes 2, 10 and 6):
the JKR limit sigma_0 -> oo reached at once with a stated bound, dP/da
right at a large Maugis parameter, the small-sigma_0 end without a runaway
precision, the gap real at the end of the cohesive zone, and every search
at numbers ending in a package error when its budget is spent.  Each
against numbers computed here: Eq. (10*) by quadrature with our own
minimisation, the rigid Dugdale limit f(c_r) = h0."""
from __future__ import annotations

import time

import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core.errors import BudgetExceeded, DomainError
from linecontact_sym.contacts.adhesion import pull_off
from linecontact_sym.contacts.adhesion.maugis import limits
from linecontact_sym.contacts.adhesion.maugis.numbers import capped_dps
from linecontact_sym.contacts.normal import equilibria

R = sp.Symbol("R", positive=True)


def _jkr_by_quadrature(f1, gamma, a0, dps=30):
    """min_a of P0(a) - sqrt(2 pi a gamma) (E* = 1), P0 by quadrature of Eq. (10*)
    P0 = a int_0^{pi/2} sin(phi) f'(a sin phi) dphi, the minimum by golden section
    on a bracket around a0 (our own search, no package code)."""
    with mpmath.workdps(dps):
        def P(a):
            return a * mpmath.quad(lambda p: mpmath.sin(p) * f1(a * mpmath.sin(p)), [0, mpmath.pi / 2]) \
                - mpmath.sqrt(2 * mpmath.pi * a * gamma)
        lo, hi = mpmath.mpf(a0) / 2, mpmath.mpf(a0) * 2
        g = (mpmath.sqrt(5) - 1) / 2
        for _ in range(60):
            m1, m2 = hi - g * (hi - lo), lo + g * (hi - lo)
            if P(m1) < P(m2):
                hi = m2
            else:
                lo = m1
        a = (lo + hi) / 2
        return P(a), a


@pytest.mark.parametrize("sigma0", [10**100, 1e300, 10**20])
def test_jkr_limit_of_the_pull_off_is_reached_at_once(sigma0):
    """before: no answer within 60 s at sigma_0 = 10**100, then -1.68157 (JKR -1.74367); after:
    the JKR limit at once, its bound stated, equal to our own JKR minimum by quadrature (at
    sigma_0 = 1e20 the force is within the bound, the half-width refined on the MD law alone)."""
    md = lcs.parabola(verify=False).maugis_dugdale()
    t0 = time.perf_counter()
    po = md.pull_off_at(15, R=1, E_star=1, gamma=1, sigma_0=sigma0)
    assert time.perf_counter() - t0 < 20
    P_ref, a_ref = _jkr_by_quadrature(lambda t: t, 1, "0.8", 20)
    assert abs(po.force - P_ref) < 1e-14 * abs(P_ref)
    assert abs(po.half_width - a_ref) < 1e-6
    assert "JKR limit" in po.note and "|P_MD,min - P_JKR,min| <=" in po.note
    assert ("refined on this law alone" in po.note) == (sigma0 == 10**20)


@pytest.mark.parametrize("profile, gamma, P0, dP0, points", [
    # P0 of Eq. (10*) by hand: a int_0^{pi/2} sin(phi) f'(a sin phi) dphi (E* = 1)
    ("parabola", 1, lambda a: mpmath.pi * a**2 / 4, lambda a: mpmath.pi * a / 2, ("0.001", "0.0032661193", "0.86")),
    ("cube", mpmath.mpf("0.01"), lambda a: 2 * a**3, lambda a: 6 * a**2, ("0.01", "0.2128")),
])
def test_slope_of_the_law_at_a_large_maugis_parameter(profile, gamma, P0, dP0, points):
    """before: dP/da at sigma_0 = 1e20 (lambda ~ 1e20) off by 30 at a = 0.001 for the parabola (17
    digits asked; 8 spurious minima, pull-off -1.605 for -1.7437), by 1e8 at a = 0.2128 for x**3 (its
    closed gap condition cancels twice as many digits); after: JKR's slope to 1e-12 there (the two
    laws differ by ~1/lambda)."""
    c = lcs.parabola(verify=False) if profile == "parabola" else lcs.LineContact(lcs.x**3, verify=False)
    extra = dict(R=1) if profile == "parabola" else {}
    law = c.maugis_dugdale().numeric_law(E_star=1, gamma=str(gamma), sigma_0=10**20, **extra)
    for A in points:
        A = mpmath.mpf(A)
        P, dP, C = law.P_and_slope(A, 17)
        with mpmath.workdps(30):
            dJ = dP0(A) - mpmath.sqrt(2 * mpmath.pi * gamma) / (2 * mpmath.sqrt(A))
            J = P0(A) - mpmath.sqrt(2 * mpmath.pi * A * gamma)
        assert abs(dP - dJ) < 1e-12 * max(abs(dJ), 1)
        assert abs(P - J) < 1e-12 * abs(J)


def test_zone_excess_bounds():
    """The two bounds the JKR limit rests on: psi(u) <= 1/ln 2 and sqrt(u) psi(u) <= KPSI, psi from
    our own inverse of D (findroot in log(m - 1), not the module's bisection)."""
    with mpmath.workdps(25):
        D = limits.dugdale_D
        for k in range(-16, 17):
            u = mpmath.mpf(10)**(mpmath.mpf(k) / 2)
            t = 1 / u
            le = mpmath.findroot(lambda z: D(1 + mpmath.exp(z)) - t,
                                 mpmath.log(t) if t < 1 else mpmath.log(t * mpmath.log(2)))
            e = mpmath.exp(le)
            psi = u * mpmath.sqrt(e * (2 + e)) - mpmath.sqrt(2 * u)
            assert abs(psi - limits.zone_excess(u)) < 1e-8 * psi     # both lose ~log10(u)/2 digits to cancellation
            assert 0 < psi <= 1 / mpmath.log(2)
            assert mpmath.sqrt(u) * psi <= limits.KPSI
            assert D(1 + e) <= e     # D(1 + e) <= e, the other inequality used


def test_small_sigma0_keeps_its_precision():
    """before: the cosh profile at sigma_0 = 1e-6 asked GMP for 3.5 GB (the solve started at the
    JKR-limit zone 8e9, where cosh needs 3e9 digits) and aborted the process; after: the state,
    and P(0+) = the rigid Dugdale limit -2 sigma_0 acosh(1 + h0) to its (tiny) elastic correction."""
    md = lcs.LineContact(R * (sp.cosh(lcs.x / R) - 1), verify=False).maugis_dugdale()
    law = md.numeric_law(R=1, E_star=1, gamma="1/100", sigma_0="1e-6")
    P, dP, C = law.P_and_slope(mpmath.mpf("1e-3"), 17)
    with mpmath.workdps(20):
        rigid = -2 * mpmath.mpf("1e-6") * mpmath.acosh(1 + mpmath.mpf("1e4"))
    assert abs(law.force_zero_width(15) - rigid) < 1e-3 * abs(rigid)
    assert abs(C - mpmath.acosh(1 + mpmath.mpf("1e4"))) < 1e-3
    assert P < 0 and dP > 0
    with pytest.raises(DomainError, match="working digits"):
        capped_dps(10**6, "a test")


def test_gap_is_real_at_the_end_of_the_cohesive_zone():
    """before: the gap at x = c_D was 0.1 + 6.7e-32j for cosh (a quadrature gap); after: real, h0."""
    md = lcs.LineContact(R * (sp.cosh(lcs.x / R) - 1), verify=False).maugis_dugdale()
    st = md.state(sp.Rational(1, 2), 20, R=1, E_star=1, gamma=sp.Rational(1, 10), sigma_0=1)
    for x in (st.c_D, mpmath.mpf(st.c_D)):
        g = st.gap(x)
        assert isinstance(g, mpmath.mpf)
        assert abs(g - mpmath.mpf("0.1")) < 1e-13


def test_pull_off_reference_has_a_budget(monkeypatch):
    """before: the grid search of a pull-off called without a deadline (a claims file) ran for
    minutes (cosh, sigma_0 = 0.25: past 200 s); after: the default search budget ends it."""
    monkeypatch.setattr(equilibria, "SEARCH_BUDGET", 0.2)
    md = lcs.LineContact(R * (sp.cosh(lcs.x / R) - 1), verify=False).maugis_dugdale()
    vals = md._numeric_values(dict(R=1, E_star=1, gamma="1/100", sigma_0="1/4"))
    with pytest.raises(BudgetExceeded):
        pull_off.reference(md, vals, 45)


# ---------------------------------------------------------------- round 5, second pass: every limit at once
PARA = dict(R=1, E_star=1, gamma=1)


@pytest.fixture(scope="module")
def md_parabola():
    return lcs.parabola(verify=False).maugis_dugdale()


def _c0_parabola(sigma0, w, dps=40):
    """The zone of a vanishing contact of x^2/2 (E* = 1), our own quadratic: c^2/2 + (4 ln2 sigma0/pi) c = w/sigma0."""
    with mpmath.workdps(dps):
        s, w = mpmath.mpf(sigma0), mpmath.mpf(w)
        b = 4 * mpmath.log(2) * s / mpmath.pi
        return -b + mpmath.sqrt(b * b + 2 * w / s)


def test_dugdale_limit_of_the_pull_off(md_parabola):
    """before: sigma_0 = 1e-300 searched P(a) (down to a = 1e-86; 57 s measured under load); after: the
    Dugdale limit P(0+) = -2 sigma_0 c0 at once, the result saying so and stating the scaling (parabola:
    sigma_0^(1/2)), equal to our own root of the quadratic."""
    po = md_parabola.pull_off_at(15, **PARA, sigma_0=1e-300)
    assert "the Dugdale limit" in po.note and "sigma_0^(1 - 1/n) -> 0 (n = 2.0" in po.note
    c0 = _c0_parabola(mpmath.mpf(1e-300), 1)
    assert abs(po.force + 2 * mpmath.mpf(1e-300) * c0) < 1e-15 * abs(po.force)
    assert po.kind == "infimum" and po.half_width == 0


def test_dugdale_limit_against_the_full_search(md_parabola):
    """At lambda = 0.2 (sigma_0 = 0.0231, w = 1/100) the limit answers and equals the full search of P(a)
    (equilibria.minimum on the law, which does not use it); at lambda = 0.5 its estimated error (1.1e-7,
    the full search's 1.1e-7) keeps the full search."""
    from linecontact_sym.contacts.adhesion.maugis.dugdale import dugdale_reached
    v = dict(R=1, E_star=1, gamma="1/100", sigma_0="0.023106628721370856")
    po = md_parabola.pull_off_at(15, **v)
    assert "the Dugdale limit" in po.note
    full = equilibria.minimum(md_parabola._law(md_parabola._numeric_values(v), "closed"), 15)
    assert "Dugdale" not in full.note
    assert abs(po.force - full.force) < 1e-15 * abs(full.force)
    vals = md_parabola._numeric_values(dict(v, sigma_0="0.05776657180342713"))
    assert dugdale_reached(md_parabola, vals, 15) is None


def _jkr_roots_parabola(load, w):
    """The two roots of pi a^2/4 - sqrt(2 pi a w) = load (E* = R = 1), by our own bisection on each side of
    the minimum a* = (2 w/pi)^(1/3) of the JKR law."""
    with mpmath.workdps(40):
        P = lambda a: mpmath.pi * a**2 / 4 - mpmath.sqrt(2 * mpmath.pi * a * w) - load   # noqa: E731
        am = (2 * mpmath.mpf(w) / mpmath.pi)**(mpmath.mpf(1) / 3)
        out = []
        for lo, hi in ((am, mpmath.mpf(100)), (mpmath.mpf(10)**-30, am)):
            for _ in range(200):
                mid = (lo + hi) / 2
                if (P(mid) > 0) == (P(hi) > 0):
                    hi = mid
                else:
                    lo = mid
            out.append((lo + hi) / 2)
        return out


def test_half_width_and_state_at_the_jkr_limit(md_parabola):
    """before: half_width at sigma_0 = 10**100 scanned the MD law (24 s measured; cosh 160 s), and the state's
    pressure was the adhesionless one (c_D^2 - a^2 vanished at 25 digits: p(0) = 0.25 for JKR's -0.878);
    after: the JKR roots and state from the one limit decision, saying so, against our own JKR numbers."""
    v = dict(PARA, sigma_0=10**100)
    hw = md_parabola.half_width(-1, 30, **v)
    assert hw.model == "JKR limit" and "JKR limit" in hw.note
    for got, ref in zip(hw, _jkr_roots_parabola(-1, 1)):
        assert abs(got - ref) < 1e-28 * ref
    br = md_parabola.branches(-1, 30, **v)
    assert br.model == "JKR limit" and [s for _, s in br] == ["stable", "unstable"]
    st = md_parabola.state(sp.Rational(1, 2), 15, **v)
    assert st.model == "JKR limit"
    with mpmath.workdps(30):
        a, x = mpmath.mpf(1) / 2, mpmath.mpf("0.3")
        # JKR: Hertz pressure minus the adhesive flat punch of load sqrt(2 pi a w) (Popov Eq. 31)
        p_ref = mpmath.sqrt(a * a - x * x) / 2 - mpmath.sqrt(2 * mpmath.pi * a) / (mpmath.pi * mpmath.sqrt(a * a - x * x))
        P_ref = mpmath.pi * a * a / 4 - mpmath.sqrt(2 * mpmath.pi * a)
        assert abs(st.pressure(x) - p_ref) < 1e-14 * abs(p_ref)
        assert abs(st.force - P_ref) < 1e-14 * abs(P_ref)
        assert abs((st.c_D - a) - mpmath.pi / (4 * mpmath.mpf(10)**200)) < 1e-14 * (st.c_D - a)
    assert md_parabola.force_at("0.5", 15, **v) == st.force


def test_state_pressure_keeps_its_digits_at_a_large_maugis_parameter(md_parabola):
    """The full solve (sigma_0 = 10**12: lambda ~ 2e12, JKR not within 15 digits): the pressure inside the
    contact is JKR's to ~1/lambda; before, c_D^2 - a^2 ~ 1e-24 was taken at 25 digits (p(0) was off)."""
    st = md_parabola.state(sp.Rational(1, 2), 15, **PARA, sigma_0=10**12)
    assert st.model == "Maugis-Dugdale"
    with mpmath.workdps(30):
        a = mpmath.mpf(1) / 2
        p_ref = a / 2 - mpmath.sqrt(2 * mpmath.pi * a) / (mpmath.pi * a)
        assert abs(st.pressure(0) - p_ref) < 1e-9 * abs(p_ref)


def test_cohesive_zone_stops_at_the_crest():
    """before: 1 - cos(x) at sigma_0 = 1e-6 (h0 = 1e6, the profile at most 2) solved the gap condition at
    c ~ 1e12, where it has a root in every period: 15-65 s, and the pull-off differed from run to run in the
    7th digit (-2266180.07, -2266175.88); after: a DomainError naming the crest x = pi at once."""
    from linecontact_sym.contacts.adhesion.maugis.numbers import profile_rise_end
    with mpmath.workdps(30):
        assert abs(profile_rise_end(lambda t: mpmath.sin(t)) - mpmath.pi) < 1e-25
    assert profile_rise_end(lambda t: t) is None
    md = lcs.LineContact(1 - sp.cos(lcs.x), verify=False).maugis_dugdale()
    with pytest.raises(DomainError, match="stops rising"):
        md.pull_off_at(15, E_star=1, gamma=1, sigma_0="1e-6")
    # the rigid limit f(c_r) = h0 (maugis.check) doubled its bracket for ever on this bounded profile
    from linecontact_sym.contacts.adhesion.maugis.check import rigid_limit
    with pytest.raises(DomainError, match="stays below h0"):
        rigid_limit(md, 15, E_star=1, gamma=1, sigma_0="1e-6")
