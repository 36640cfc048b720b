"""The stick zone's bounded interval solution at numbers
(contacts/asymmetric/interval.py): P(e, a) and theta(e, a) come from the
asymmetric core's numbers where the core takes the profile and closes its
force laws, and agree there with the defining phi-integrals by quadrature
(which share only the slope with the core's Chebyshev/Bessel closed forms);
a profile the core refuses (more than one kink) keeps the quadrature."""
import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core import symbols as S
from linecontact_sym.core.precision import workdps

k, ell = sp.symbols("k l", positive=True)

# (e, a): a centred interval, two off-centre ones, a tiny stick zone at the edge
POINTS = [(0, 1), ("0.3", "0.7"), ("0.6", "0.4"), ("0.99", "0.01")]


def _numbers(contact, **vals):
    r = contact.rolling(0.3)
    return r._numbers({s: sp.sympify(vals[s.name]) for s in contact.variables})


@pytest.mark.parametrize("make, vals", [
    (lambda: lcs.parabola(verify=False), dict(E_star=1, R=1)),
    (lambda: lcs.LineContact(k * lcs.x**4, verify=False), dict(E_star=1, k=1)),
    (lambda: lcs.LineContact(k * (sp.cosh(lcs.x / ell) - 1), verify=False, budget=2),
     dict(E_star=1, k=1, l=sp.Rational(1, 2))),
], ids=["parabola", "x^4", "cosh"])
def test_core_numbers_agree_with_the_quadrature(make, vals):
    with workdps(30):
        num = _numbers(make(), **vals)
        assert num.core is not None                    # the core's closed force laws are the route
        for e, a in POINTS:
            e, a = mpmath.mpf(e), mpmath.mpf(a)
            P, Pq = num.P(e, a), num.P_quad(e, a)
            th, thq = num.tilt(e, a), num.tilt_quad(e, a)
            assert abs(P / Pq - 1) < 1e-27
            assert abs(th - thq) < 1e-27 * max(abs(thq), 1)


def test_a_profile_the_core_refuses_keeps_the_quadrature():
    """The rounded punch switches at -b, 0, b: the core refuses it; P at e = 0
    is then the quadrature's and equals the symmetric force law."""
    c = lcs.rounded_punch(verify=False, budget=1)
    with workdps(30):
        num = _numbers(c, E_star=1, R=1, b=sp.Rational(3, 10))
        assert num.core is None
        law = c.derivation("force").expr.xreplace({S.E_star: 1, sp.Symbol("R", positive=True): 1,
                                                    S.b: sp.Rational(3, 10), S.a: sp.Rational(4, 5)})
        assert abs(num.P(0, mpmath.mpf("0.8")) / mpmath.mpf(sp.N(law, 40)) - 1) < 1e-25
