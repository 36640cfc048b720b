"""Physical ranges checked in one place (core/ranges.py): Poisson's ratio,
the friction coefficient, the stick half-widths, the surface z = 0, the
edges of the strict conditions accepted as limits.  Moved from
tests/test_trust_round3.py (issue 19, item 4) and tests/test_trust_round4.py
(issue 29).  References: closed forms of the Hertz contact typed here."""
from __future__ import annotations

import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from independent_refs import close
from linecontact_sym.core.errors import DomainError


@pytest.fixture(scope="module")
def par():
    return lcs.parabola(verify=False)


def test_physical_ranges_in_one_place():
    c = lcs.parabola(verify=False)
    H = dict(a=1, R=1, E_star=1)
    sf = c.stresses()
    # nu = 0 and nu = 1/2 are valid: sigma_y = nu (sigma_x + sigma_z) = -2 nu p(x) on the surface,
    # p(x) = E* sqrt(a^2 - x^2)/(2R): at x = 1/10, -nu sqrt(0.99)
    for nu in (0, sp.Rational(1, 2), -sp.Rational(1, 2)):
        got = sf.evaluate_at("sigma_y", dps=20, x=sp.Rational(1, 10), z=0, nu=nu, **H)
        with mpmath.workdps(30):
            assert close(got, -mpmath.mpf(nu) * mpmath.sqrt(mpmath.mpf("0.99")), 1e-15), (nu, got)
        c.stresses(nu=nu)
    for bad in (0.7, -1, 1, sp.Rational(1, 2) + sp.Rational(1, 10**30)):
        with pytest.raises(DomainError, match="Poisson"):
            c.stresses(nu=bad)
        with pytest.raises(DomainError, match="Poisson"):
            sf.evaluate_at("sigma_y", x=0.1, z=0.3, nu=bad, **H)
    t = c.tangential()
    for bad in (0, -0.3):
        with pytest.raises(DomainError, match="positive"):
            c.tangential(bad)
        with pytest.raises(DomainError, match="positive"):
            t.evaluate_at("tangential_force", a=1, c_s=0.5, mu=bad, R=1, E_star=1)
        with pytest.raises(DomainError, match="positive"):
            t.state(0.1, mu=bad, **H)
    with pytest.raises(DomainError, match="stick half-width"):
        t.evaluate_at("tangential_force", a=1, c_s=1.5, mu=0.3, R=1, E_star=1)
    with pytest.raises(DomainError, match="reversal stick"):
        t.evaluate_at("unloading_force", a=1, c_s=0.5, c_r=0.3, mu=0.3, R=1, E_star=1)
    for bad in (1, 0, 2.5, True):
        with pytest.raises(DomainError, match="points >= 2"):
            t.cycle(0.1, points=bad, mu=0.3, **H)
    with pytest.raises(DomainError, match="stick half-width"):
        c.stresses("partial_slip", stick=2, mu=0.3).field(**H)
    # the edges of the strict conditions c_s < c_r < a are limits, accepted: Q_u = Q(c_s) - 2 Q(c_r) is
    # Q at the turning point (c_r = a) and -Q at the full reversal (c_r = c_s)
    kw = dict(a=1, c_s=sp.Rational(1, 2), mu=sp.Rational(3, 10), R=1, E_star=1)
    Q = t.evaluate_at("tangential_force", **kw)
    with mpmath.workdps(40):
        assert close(Q, mpmath.mpf(3) / 10 * mpmath.pi / 4 * (1 - mpmath.mpf(1) / 4), 1e-25)   # mu (P(a) - P(c_s))
    assert close(t.evaluate_at("unloading_force", c_r=1, **kw), Q, 1e-25)
    with mpmath.workdps(40):
        assert close(t.evaluate_at("unloading_force", c_r=sp.Rational(1, 2), **kw), -Q, 1e-25)
    # z = 0 is the surface: sigma_z = -p(x) = -E* sqrt(a^2 - x^2)/(2R)
    got = sf.evaluate_at("sigma_z", x=sp.Rational(1, 10), z=0, **H)
    with mpmath.workdps(40):
        assert close(got, -mpmath.sqrt(mpmath.mpf("0.99")) / 2, 1e-25)
    with pytest.raises(DomainError):
        sf.evaluate_at("sigma_z", x=0.1, z=-0.1, **H)


@pytest.mark.slow
def test_partial_slip_stick_beyond_a_refused(par):
    c = sp.Symbol("c", positive=True)
    for sf, extra in ((par.stresses("partial_slip", stick=c, mu=0.3), {"c": sp.Rational(3, 2)}),
                      (par.stresses("partial_slip", stick=sp.Rational(3, 2), mu=0.3), {})):
        with pytest.raises(DomainError, match="stick half-width"):
            sf.evaluate_at("sigma_x", x=sp.Rational(1, 10), z=sp.Rational(1, 5), a=1, R=1, E_star=1, **extra)
