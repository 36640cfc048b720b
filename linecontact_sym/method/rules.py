"""Integration strategies: each a small named rule that either produces a
closed form for one transform or says it does not apply.

Modelled on SymPy's ``manualintegrate``: every strategy is a frozen dataclass
with a ``name`` and a ``run`` method; :func:`derive_closed_form` (in
``derivation``) tries them in order, each under the time budget, and records
which one produced the result.

A strategy returns ``(expr, conditions, notes)``: the raw closed form, a list
of SymPy relations under which it holds, and remarks for the record.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from ..core import symbols as S
from ..core.errors import DivergentIntegralError
from .hyperseries import NotDecomposable, beta_kernel_sum, decompose
from .transforms import s, t


class NotApplicable(Exception):
    """The strategy does not apply to this input (try the next one)."""


def _no_integral(expr):
    if expr.has(sp.Integral) or expr.has(sp.nan) or expr.has(sp.zoo):
        raise NotApplicable("SymPy left the integral unevaluated")
    return expr


def _power_terms(expr, var):
    """expr = sum C_i var**m_i (finite, pure powers) -> [(C_i, m_i)]."""
    try:
        terms = decompose(expr, var)
    except NotDecomposable as exc:
        raise NotApplicable(str(exc))
    if not all(T.is_power for T in terms):
        raise NotApplicable("not a finite sum of powers")
    return [(T.coef, T.mu) for T in terms]


# ------------------------------------------------------------------ force (10*)
@dataclass(frozen=True)
class BetaTermwise:
    """Termwise Beta-kernel integration of a hypergeometric decomposition:
    power laws give Popov's Z_n (Eqs. 16-17), binomial/exponential/trig/Bessel
    factors a ``hyper`` that ``hyperexpand`` may turn into K, E, Bessel ..."""

    rho: int
    sigma: sp.Rational
    name: str = "hypergeometric termwise (Beta kernel)"

    def run(self, g, var, prefactor):
        conds: list = []
        try:
            terms = decompose(g, var)
        except NotDecomposable as exc:
            raise NotApplicable(str(exc))
        total = sp.Add(*[beta_kernel_sum(T, self.rho, self.sigma, S.a, conds) for T in terms])
        kind = "power-law termwise (Beta integrals, Z_n)" if all(T.is_power for T in terms) \
            else "hypergeometric termwise (Beta kernel) + hyperexpand"
        return prefactor * total, conds, [kind]


def force_termwise(profile):
    if profile.is_piecewise:
        raise NotApplicable("piecewise profile")
    return BetaTermwise(1, sp.Rational(-1, 2)).run(profile.pieces[0].derivative, S.x, S.E_star)


def force_piecewise(profile):
    """Eq. (10*) piece by piece with SymPy's definite integration:
    P(a) = sum over pieces below a; a Piecewise in a."""
    if not profile.is_piecewise:
        raise NotApplicable("profile is not piecewise")
    branches = []
    done = sp.S.Zero  # contribution of complete pieces
    for pc in profile.pieces:
        integrand = sp.simplify(t * pc.derivative.subs(S.x, t) / sp.sqrt(S.a**2 - t**2))
        upper = _no_integral(sp.integrate(integrand, (t, pc.lo, S.a))) if integrand != 0 else sp.S.Zero
        cond = sp.Le(S.a, pc.hi) if pc.hi != sp.oo else sp.true
        branches.append((S.E_star * (done + upper), cond))
        if pc.hi != sp.oo and integrand != 0:
            done += _no_integral(sp.integrate(integrand, (t, pc.lo, pc.hi)))
    return sp.Piecewise(*branches), [], ["piecewise, SymPy definite integrals per piece"]


def force_sympy(profile):
    if profile.is_piecewise:
        raise NotApplicable("piecewise profile")
    integrand = t * profile.pieces[0].derivative.subs(S.x, t) / sp.sqrt(S.a**2 - t**2)
    res = _no_integral(sp.integrate(integrand, (t, 0, S.a), conds="none"))
    return S.E_star * res, [], ["SymPy integrate"]


FORCE_STRATEGIES = (force_termwise, force_piecewise, force_sympy)


# ------------------------------------------------------------------ pressure (12)
def pressure_termwise(P, profile=None):
    """Each power term C a**n of P gives, by the Euler integral,
    (n C / pi) a**(n-1) sqrt(1 - xi**2) 2F1(1 - n/2, 1; 3/2; 1 - xi**2), xi = x/a."""
    if P.has(sp.Piecewise):
        raise NotApplicable("piecewise force law")
    terms = _power_terms(sp.diff(P, S.a).subs(S.a, s), s)
    xi2 = S.x**2 / S.a**2
    out = sp.Add(*[C * S.a**m * sp.sqrt(1 - xi2) * sp.hyper([(1 - m) / 2, 1], [sp.Rational(3, 2)], 1 - xi2)
                   for C, m in terms]) / sp.pi
    return out, [sp.Lt(S.x, S.a)], ["power-law termwise (Euler integral, 2F1)"]


def _segments(profile):
    """Breakpoints x_1 < x_2 < ... of the profile (symbolic)."""
    return list(profile.breakpoints) if profile is not None else []


def pressure_sympy(P, profile=None):
    """Eq. (12) by SymPy's definite integration, per (a-interval, x-interval)."""
    bps = _segments(profile)
    dP_of = sp.diff(P, S.a)
    branches = []
    edges = [sp.S.Zero] + bps + [sp.oo]
    for J in range(len(edges) - 1):  # a in [edges[J], edges[J+1])
        for I in range(J + 1):       # x in [edges[I], edges[I+1])
            total = sp.S.Zero
            for j in range(I, J + 1):
                lo = S.x if j == I else edges[j]
                hi = S.a if j == J else edges[j + 1]
                dPj = _piece_for(dP_of, j, bps).subs(S.a, s)
                if dPj == 0:
                    continue
                total += _no_integral(sp.integrate(dPj / sp.sqrt(s**2 - S.x**2), (s, lo, hi)))
            cond = sp.And(sp.Lt(S.a, edges[J + 1]) if edges[J + 1] != sp.oo else sp.true,
                          sp.Lt(S.x, edges[I + 1]) if I < J else sp.true)
            branches.append((total / sp.pi, cond))
    expr = branches[0][0] if len(branches) == 1 else sp.Piecewise(*branches)
    return expr, [sp.Lt(S.x, S.a)], ["SymPy definite integration of Eq. (12)"]


def _piece_for(expr, J, bps):
    """The branch of a Piecewise-in-a expression valid for a in interval J."""
    if not expr.has(sp.Piecewise) or not bps:
        return expr
    edges = [sp.S.Zero] + bps
    lo = edges[J]
    hi = bps[J] if J < len(bps) else lo + 1
    probe = (lo + hi) / 2
    expr = sp.piecewise_fold(expr)
    for e, cond in expr.args:
        c = cond.subs(S.a, probe)
        c = sp.simplify(c) if c not in (sp.true, sp.false) else c
        if c == sp.true:
            return e
    raise NotApplicable("could not select the branch of the force law")


PRESSURE_STRATEGIES = (pressure_termwise, pressure_sympy)


# ------------------------------------------------------------------ gap (3/5)
def gap_termwise(P, profile_expr):
    """Each power term C a**n of P gives, after integrating by parts,
    (2C/(pi E*)) [a**n acosh(x/a) + (a**n/n) 2F1(1/2, n/2; n/2 + 1; a**2/x**2)]."""
    if P.has(sp.Piecewise) or profile_expr.has(sp.Piecewise):
        raise NotApplicable("piecewise")
    terms = _power_terms(P, S.a)
    inner = sp.Add(*[C * (S.a**m * sp.acosh(S.x / S.a)
                          + S.a**m / m * sp.hyper([sp.S.Half, m / 2], [m / 2 + 1], S.a**2 / S.x**2))
                     for C, m in terms])
    return profile_expr - 2 / (sp.pi * S.E_star) * inner, [sp.Gt(S.x, S.a)], \
        ["power-law termwise (integration by parts, 2F1)"]


def gap_sympy(P, profile_expr):
    if P.has(sp.Piecewise):
        raise NotApplicable("piecewise force law")
    dP = sp.diff(P, S.a).subs(S.a, s)
    I = _no_integral(sp.integrate(sp.acosh(S.x / s) * dP, (s, 0, S.a)))
    return profile_expr - 2 / (sp.pi * S.E_star) * I, [sp.Gt(S.x, S.a)], ["SymPy integrate"]


GAP_STRATEGIES = (gap_termwise, gap_sympy)


# ------------------------------------------------------------------ inverse (9)
def inverse_termwise(P):
    if P.has(sp.Piecewise):
        raise NotApplicable("piecewise force law")
    g = P.subs(S.a, s)
    try:
        expr, conds, notes = BetaTermwise(-1, sp.Rational(-1, 2)).run(g, s, 2 * S.a / (sp.pi * S.E_star))
    except DivergentIntegralError as exc:
        lead = sp.limit(P, S.a, 0, "+")
        if lead != 0:
            raise DivergentIntegralError(
                f"Eq. (9) diverges for the force law {P}: P(0+) = {lead}, but P(a) must vanish "
                f"as a -> 0 ({exc})")
        raise NotApplicable(f"termwise split diverges although the sum converges ({exc})")
    return expr, conds, notes


def inverse_sympy(P):
    Ps = P.subs(S.a, s)
    I = _no_integral(sp.integrate(Ps / (s * sp.sqrt(S.a**2 - s**2)), (s, 0, S.a), conds="none"))
    return 2 * S.a / (sp.pi * S.E_star) * I, [], ["SymPy integrate"]


INVERSE_STRATEGIES = (inverse_termwise, inverse_sympy)
