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
