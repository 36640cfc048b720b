"""The asymmetric line contact (issue 39) against an independent
Gauss-Chebyshev collocation of the singular integral equation
(:mod:`sie_collocation`, written for these tests: no force law, no split)."""
import os
import sys

import mpmath
import pytest
import sympy as sp

from linecontact_sym.core import symbols as S
from linecontact_sym.contacts.asymmetric import OffsetContact

sys.path.insert(0, os.path.dirname(__file__))
import sie_collocation as C  # noqa: E402

X = S.x_real


def digits(u, v):
    u, v = mpmath.mpf(u), mpmath.mpf(v)
    if u == v:
        return 99
    return float(-mpmath.log10(abs(u - v) / max(abs(v), mpmath.mpf(10)**-40)))


@pytest.fixture(scope="module")
def cubic():
    return OffsetContact(X**2 / 2 + X**3 / 10)


def test_cubic_symbolic_forms(cubic):
    e, a = S.e, S.a
    assert sp.simplify(cubic.force() - sp.pi * S.E_star * a**2 * (3 * e + 5) / 20) == 0
    assert sp.expand(cubic.tilt() - (e + 3 * e**2 / 10 + 3 * a**2 / 20)) == 0
    # the tilt is the mean slope over the contact: (1/pi) int f'(e + a sin phi) dphi
    ph = sp.Symbol("phi", real=True)
    mean = sp.integrate((X + 3 * X**2 / 10).subs(X, e + a * sp.sin(ph)), (ph, -sp.pi / 2, sp.pi / 2)) / sp.pi
    assert sp.expand(cubic.tilt() - mean) == 0
    assert cubic.edge_factors() == (0, 0)


@pytest.mark.parametrize("ev, av", [("0.3", "0.7"), ("-1.1", "0.4")])
def test_cubic_bounded_against_collocation(cubic, ev, av):
    with mpmath.workdps(40):
        e, a = mpmath.mpf(ev), mpmath.mpf(av)
        n = cubic.numbers(E_star=2)
        sol = C.bounded(lambda x: x + 3 * x**2 / 10, e, a, E=2, N=16)
        assert digits(n.tilt(e, a), sol.theta) > 30
        assert digits(n.P(e, a), sol.load) > 30
        assert digits(n.moment(e, a), sol.moment) > 30
        for xv in (e - a / 2, e + a / 3, e + 9 * a / 10):
            assert digits(n.pressure(xv, e, a), sol.pressure(xv)) > 28


def test_parabola_is_hertz_shifted():
    R = sp.Symbol("R", positive=True)
    c = OffsetContact(X**2 / (2 * R))
    assert sp.simplify(c.tilt() - S.e / R) == 0
    assert c.moment_centre() == 0
    assert sp.simplify(c.pressure() - S.E_star * sp.sqrt(S.a**2 - (X - S.e)**2) / (2 * R)) == 0


def test_exponential_bounded_against_collocation():
    c = OffsetContact(sp.exp(X) - 1 - X)
    assert c.closed()      # Bessel I force laws of E = e^e (cosh s - 1) and H
    with mpmath.workdps(30):
        e, a = mpmath.mpf("0.3"), mpmath.mpf("0.7")
        n = c.numbers(E_star=2)
        sol = C.bounded(lambda x: mpmath.exp(x) - 1, e, a, E=2, N=24)
        assert digits(n.tilt(e, a), sol.theta) > 25
        assert digits(n.P(e, a), sol.load) > 25
        assert digits(n.moment(e, a), sol.moment) > 25
