"""Eq. (9) for force laws whose hypergeometric terms diverge one by one:
merge the series first, then integrate termwise.

The exact cylinder's force law P = E* R (K(m) - E(m)), m = a^2/R^2, is the
difference of two series that both start with the constant pi/2: each alone
gives the divergent int_0^a ds / (s sqrt(a^2 - s^2)) in Eq. (9), their
difference starts with m.  :func:`merge_series` adds the terms of a
:func:`~.hyperseries.decompose` that share the series variable w x^q into
one series sum_k C_k x^(mu + q k), drops its vanishing leading coefficients
and writes what remains as one hypergeometric term: with B(k) the
coefficient of the first term, C(k) = B(k) rho(k) with rho rational in k
(the parameters of the merged series differ by integers), so
C(K0 + j) = C(K0) * prod (Pochhammer symbols in j) from the linear factors
of rho.  For K - E: C_k = (pi/2) (1/2)_k^2/k!^2 * k/(k - 1/2), K0 = 1, and
the merged term is (pi/4) m 2F1(1/2, 3/2; 2; m).
"""
from __future__ import annotations

import sympy as sp

from ..core import symbols as S
from .hyperseries import NotDecomposable, SeriesTerm, beta_kernel_sum, decompose
from .rulebase import NotApplicable, Rule, Step
from .transforms import s

__all__ = ["merge_series", "InverseMerged"]

_k = sp.Dummy("k", integer=True, nonnegative=True)
_j = sp.Dummy("j", integer=True, nonnegative=True)


def _coefficient(T: SeriesTerm, k):
    """The k-th series coefficient of T (without coef and x^mu)."""
    num = sp.Mul(*[sp.rf(u, k) for u in T.upper])
    den = sp.Mul(*[sp.rf(v, k) for v in T.lower]) * sp.factorial(k)
    return num / den * T.w**k


def _ratio(e):
    """e (a quotient of Pochhammer symbols in k) as a rational function of k, or raise."""
    r = sp.cancel(sp.gammasimp(sp.combsimp(e.rewrite(sp.gamma))))
    if not r.is_rational_function(_k):
        raise NotDecomposable(f"series coefficients differ by {r}, not a rational function of k")
    return r


def _merge_group(group):
    """One SeriesTerm equal to the sum of ``group`` (same w and q)."""
    q, w = group[0].q, group[0].w
    mu0 = min((T.mu for T in group), key=lambda m: sp.N(m) if m.is_number else 0)
    shifts = [sp.simplify((T.mu - mu0) / q) for T in group]
    if not all(sh.is_Integer and sh >= 0 for sh in shifts):
        raise NotDecomposable("exponents do not differ by multiples of q")
    base = group[shifts.index(0)]
    B = _coefficient(base, _k)
    rho = sp.S.Zero
    for T, sh in zip(group, shifts):
        term = T.coef * _coefficient(T, _k - int(sh)) * w**int(sh) if sh else T.coef * _coefficient(T, _k)
        rho += _ratio(term / B)
    rho = sp.cancel(sp.together(rho))
    if rho == 0:
        return None
    top = max(int(sh) for sh in shifts)
    K0 = None
    for kk in range(top, top + 8):
        if sp.simplify(rho.subs(_k, kk)) != 0:
            K0 = kk
            break
    if K0 is None:
        raise NotDecomposable("no nonzero coefficient among the first terms of the merged series")
    num, den = sp.fraction(rho.subs(_k, K0 + _j))
    ups, los = [u + K0 for u in base.upper], [v + K0 for v in base.lower] + [sp.Integer(K0 + 1)]
    ups.append(sp.S.One)                      # j! of the new series
    # rho(K0 + j)/rho(K0) = prod (alpha + 1)_j/(alpha)_j over the factors (j + alpha)
    # of the numerator, the reciprocal over those of the denominator
    for poly, up_side in ((sp.Poly(num, _j), True), (sp.Poly(den, _j), False)):
        roots = sp.roots(poly)
        if sum(roots.values()) != poly.degree():
            raise NotDecomposable(f"cannot factor {poly.as_expr()} over its parameters")
        for r, mult in roots.items():
            alpha = -r
            for _ in range(mult):
                (ups if up_side else los).append(alpha + 1)
                (los if up_side else ups).append(alpha)
    c0 = sp.simplify(B.subs(_k, K0) * rho.subs(_k, K0))
    return SeriesTerm(c0, mu0 + q * K0, tuple(ups), tuple(los), w, q)


def merge_series(terms):
    """Merge the terms of :func:`~.hyperseries.decompose` that share their
    series variable (see the module docstring); pure powers and lone terms
    are kept as they are."""
    out, groups = [], {}
    for T in terms:
        if T.is_power:
            out.append(T)
        else:
            groups.setdefault((T.w, T.q), []).append(T)
    for group in groups.values():
        if len(group) == 1:
            out.extend(group)
            continue
        merged = _merge_group(group)
        if merged is not None:
            out.append(merged)
    return out


class InverseMerged(Rule):
    """Eq. (9) termwise over the *merged* hypergeometric series of P(s)
    (:func:`merge_series`): f(a) = (2a/(pi E*)) sum int_0^a s^-1 (a^2 - s^2)^(-1/2) T(s) ds,
    for force laws whose terms diverge one by one (E* R (K - E))."""

    name, transform = "inverse_merged_series", "profile"

    def applies(self, problem):
        return "piecewise force law" if problem.force_law.has(sp.Piecewise) else None

    def run(self, problem):
        try:
            terms = merge_series(decompose(problem.force_law.subs(S.a, s), s))
        except NotDecomposable as exc:
            raise NotApplicable(str(exc))
        conds: list = []
        total = sp.Add(*[beta_kernel_sum(T, -1, sp.Rational(-1, 2), S.a, conds) for T in terms])
        return Step(self.name, 2 * S.a / (sp.pi * S.E_star) * total, tuple(conds),
                    ("hypergeometric series merged, then termwise (Beta kernel) + hyperexpand",))
