"""The even/odd split of a profile about a centre e (exact algebra, no contact).

A contact on [e - a, e + a] sees the profile in s = x - e.  Its parts::

    E_e(s) = (f(e + s) + f(e - s))/2 - f(e)      even, E(0) = 0
    h_e(s) = (f(e + s) - f(e - s))/2             odd
    H_e(s) = int_0^s h_e(u) du
           = (F(e + s) + F(e - s))/2 - F(e),      F' = f (an antiderivative), even, H(0) = 0

are symmetric profiles in s with e a real parameter: the engine's transforms
apply to them unchanged (written in the engine's x, which stands for |s|).
"""
from __future__ import annotations

import sympy as sp

from ...core import symbols as S
from ...core.budget import run_with_budget
from ...core.errors import BudgetExceeded, ProfileError

__all__ = ["even_part", "odd_part", "odd_integral", "antiderivative", "whole_line"]


def _tidy(expr, s=S.x):
    """A short form of a split part: expanded for polynomials and
    exponentials (exp(e + s) -> exp(e) (cosh s + sinh s), so that the engine
    sees the terms in s with coefficients in e, and the even part its
    cosh(s)), else as SymPy gives it."""
    out = sp.expand(expr, power_exp=True, mul=True, multinomial=True, log=False, trig=False)
    def linear(t):
        return isinstance(t, sp.exp) and t.args[0].has(s) and sp.diff(t.args[0], s, 2) == 0
    if any(linear(t) for t in out.atoms(sp.exp)):
        out = out.replace(linear,
                          lambda t: sp.cosh(t.args[0]) + sp.sinh(t.args[0]))
        out = sp.factor_terms(sp.collect(sp.expand(out), [v for v in out.atoms(sp.exp)]))
    # cosh, sinh, cos, sin of e +- s likewise: cosh(e) cosh(s) + sinh(e) sinh(s), terms in s that the
    # engine's termwise rule closes (left as cosh(e + s), each part's sympy.integrate spent 8 CPU s to
    # leave the integral unevaluated)
    hyp = (sp.cosh, sp.sinh, sp.cos, sp.sin)

    def shifted(t):
        return isinstance(t, hyp) and t.args[0].has(s) and sp.diff(t.args[0], s, 2) == 0 \
            and (t.args[0] - t.args[0].coeff(s) * s) != 0
    if any(shifted(t) for t in out.atoms(*hyp)):
        out = sp.expand(out.replace(shifted, lambda t: sp.expand_trig(t)))
    out = sp.piecewise_fold(out)
    return out if sp.count_ops(out) <= 2 * sp.count_ops(expr) + 20 else expr


def even_part(f, x=S.x_real, e=S.e, s=S.x):
    """E_e(s) = (f(e + s) + f(e - s))/2 - f(e), in ``s`` (the engine's x)."""
    return _tidy((f.xreplace({x: e + s}) + f.xreplace({x: e - s})) / 2 - f.xreplace({x: e}))


def odd_part(f, x=S.x_real, e=S.e, s=S.x):
    """h_e(s) = (f(e + s) - f(e - s))/2, in ``s``."""
    return _tidy((f.xreplace({x: e + s}) - f.xreplace({x: e - s})) / 2)


def _antiderivative(f, x):
    F = sp.integrate(f, x)
    if F.has(sp.Integral):
        return None
    return F


def antiderivative(f, x=S.x_real, seconds: float = 20.0):
    """An antiderivative of f in x (SymPy's ``integrate``), None where SymPy
    leaves an Integral or the budget (CPU seconds) runs out."""
    if f.is_polynomial(x):
        return sp.integrate(f, x)
    try:
        return run_with_budget(_antiderivative, f, x, seconds=seconds)
    except BudgetExceeded:
        return None


def odd_integral(f, x=S.x_real, e=S.e, s=S.x, seconds: float = 20.0):
    """H_e(s) = int_0^s h_e(u) du as the even part of an antiderivative of f,
    or None where f has no antiderivative SymPy finds under the budget.

    A Piecewise f integrates piece by piece (SymPy keeps it continuous)."""
    F = antiderivative(f, x, seconds)
    if F is None:
        return None
    H = even_part(F, x, e, s)
    if H.has(sp.nan, sp.zoo):
        raise ProfileError(f"the antiderivative {F} of {f} is undefined on the line")
    return H


def whole_line(f, x=S.x):
    """A symmetric profile f(x), x >= 0 (the engine's x, mirrored), on the
    whole line in the real x: f(x) itself where it is even in x (x^2, cosh),
    else f(|x|)."""
    fx = f.xreplace({x: S.x_real})
    try:
        even = sp.expand(fx - fx.xreplace({S.x_real: -S.x_real})) == 0
    except Exception:   # an expression SymPy cannot expand: |x| is always right
        even = False
    return fx if even else f.xreplace({x: sp.Abs(S.x_real)})
