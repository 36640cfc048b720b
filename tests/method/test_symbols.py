"""The user's symbols are the user's: a parameter of any name (s, pi, E,
lambda, ...) stays a parameter in every result and export, and a stick
half-width is solved in the user's own symbols.  Moved from
tests/test_trust_round3.py (issue 19, item 2).  References: mpmath quadrature
of Eq. (10*) and Eq. (12) (tests/independent_refs.py), mpmath root finding."""
from __future__ import annotations

import mpmath
import pytest
import sympy as sp
from hypothesis import given, settings, strategies as st

import linecontact_sym as lcs
from independent_refs import close, force_ref, pressure_ref
from linecontact_sym.core.errors import DomainError

x = lcs.x


NAMES = ["s", "t", "pi", "E", "I", "lambda_", "lambda", "gamma", "beta", "numpy", "sqrt", "phi", "u", "w"]


@settings(max_examples=6, deadline=None)
@given(name=st.sampled_from(NAMES), shape=st.sampled_from(["parabola", "quartic"]))
def test_a_parameter_of_any_name_is_a_parameter(name, shape):
    """before: a parameter named s turned the parabola's pressure into the
    integral Integral(E_star/(2*sqrt(s**2 - x**2)), (s, x, a)) (the engine's
    integration variable captured it); a parameter named pi made every export
    read pi*a**2/(4*pi) as a**2/4."""
    k = sp.Symbol(name, positive=True)
    prof = x**2 / (2 * k) if shape == "parabola" else x**2 / (2 * k) + x**4
    c = lcs.LineContact(prof, points=2)
    kv = sp.Rational(3, 2)

    def fp(t):
        return t / mpmath.mpf(1.5) + (4 * t**3 if shape == "quartic" else 0)

    def fpp(t):
        return 1 / mpmath.mpf(1.5) + (12 * t**2 if shape == "quartic" else 0)
    d = c.derivation("pressure")
    assert d.closed_form and not d.expr.has(sp.Integral), d.expr
    assert k in d.expr.free_symbols
    P_ref = force_ref(fp, sp.Rational(4, 5))
    p_ref = pressure_ref(fp, fpp, sp.Rational(4, 5), sp.Rational(3, 10))
    vals = {"a": sp.Rational(4, 5), name: kv, "E_star": 1}
    assert close(c.evaluate_at("force", **vals), P_ref, 1e-25 * P_ref)
    assert close(c.evaluate_at("pressure", x=sp.Rational(3, 10), **vals), p_ref, 1e-15 * p_ref)
    fl = {"a": 0.8, name: 1.5, "E_star": 1.0}
    assert close(c.to_numeric("force")(**fl), float(P_ref), 1e-13 * float(P_ref))
    assert close(c.to_numeric("force", backend="mpmath")(**vals), P_ref, 1e-25 * P_ref)
    assert close(float(c.evaluate("force", **fl).value), float(P_ref), 1e-13 * float(P_ref))
    assert close(c.to_numeric("pressure")(x=0.3, **fl), float(p_ref), 1e-12 * float(p_ref))


def test_stick_half_width_in_the_users_own_symbols():
    """before: stick_half_width(F) with a positive F returned the unsolved
    Eq(pi*E_star*c_s**2/(4*R), pi*E_star*a**2/(4*R) - F/mu)."""
    t = lcs.parabola(verify=False).tangential(sp.Symbol("m", positive=True))
    for F in (sp.Symbol("F", positive=True), sp.Symbol("Q", positive=True)):
        d = t.stick_half_width(F)
        assert d.closed_form and not isinstance(d.expr, sp.Eq) and not d.expr.has(sp.Abs), d.expr
        assert d.expr.free_symbols == {F, lcs.a, lcs.R, lcs.E_star, sp.Symbol("m", positive=True)}
        # the root of P(c) = P(a) - F/m with the quadrature force law of f = x^2/(2R), R = 1
        with mpmath.workdps(40):
            P = lambda v: force_ref(lambda s: s, v, dps=40)   # noqa: E731
            target = P(1) - mpmath.mpf("0.1") / mpmath.mpf("0.3")
            c_ref = mpmath.findroot(lambda v: P(v) - target, mpmath.mpf("0.7"))
        got = d.evalf(dps=30, **{F.name: sp.Rational(1, 10), "a": 1, "R": 1, "E_star": 1, "m": sp.Rational(3, 10)})
        assert close(got, c_ref, 1e-25)
    # an assumption-free symbol: the documented assumption (real), said in the notes
    G = sp.Symbol("G")
    d = t.stick_half_width(G)
    assert d.closed_form and d.expr.has(sp.Abs(G)) and any("taken real" in n for n in d.notes)
    with pytest.raises(DomainError, match="already mean"):
        t.stick_half_width(lcs.R)
