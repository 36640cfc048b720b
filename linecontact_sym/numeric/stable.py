"""Numerically stable rewrites of derived expressions, chosen automatically.

Closed forms that are exact in exact arithmetic can be useless in float64 at
the extremes of their arguments: K(m) - E(m) cancels for small m, Gamma(n/2)
overflows for n > 343, atanh(sqrt(a^2 - x^2)/a) is atanh(1.0) = inf for
x < 1e-8 a, sqrt(a^2 - x^2) takes the square root of a rounding-negative
number, pi*x - 2*x*asin(a/x) cancels at x -> a, 2F1 at z = 1 - x^2/a^2 loses
the information that is in x^2/a^2 ...

:func:`stabilize` inspects a SymPy expression and applies, wherever its
pattern occurs, each rule of :data:`RULES` in turn (no profile is special
cased).  A rule is a small named object in the style of SymPy's
``manualintegrate``: its docstring states the identity, ``applies(expr)`` is
a cheap test (does the pattern's head occur at all?) and ``apply(expr)``
rewrites.  Every application is re-checked numerically (20 digits at random
admissible points, 30-digit evaluation) before it is kept.

Rules, in the order applied: :class:`EllipticPiToCarlson`, :class:`EllipticToCarlson`,
:class:`Hyp2f1Connection`, :class:`GammaAbsorb`, :class:`GammaRatio`, :class:`AcoshExcess`,
:class:`SquareDifferences`, :class:`AtanhToAsinh`, :class:`AcoshToAsinh`, :class:`AsinhExcess`, :class:`AsinToAtan`,
:class:`AcosToAtan`, :class:`Hyp2f1Complement`, :class:`Conjugate`, :class:`LogOfPower`, :class:`HalfAngle`,
:class:`ExpTail`, :class:`FactorDifferences`, :class:`SinPiReduction`.  The special functions they produce
(``carlson_rf/rd/rg/rj``, ``gamma_ratio``, ``hyp2f1c``, ``exp_tail``, ``asinh_excess``, ``sin_pi_sum``) live in
:mod:`linecontact_sym.numeric.special`.

The result is a :class:`StableForm`: the rewritten expression and the list of
rules applied (with what they replaced, and any rejected by the numeric
check).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import functools

import sympy as sp

from ..method.derivation import gammasimp_masked
from .accuracy import expressions_agree
from .special import asinh_excess, exp_tail, gamma_ratio, hyp2f1c, sin_pi_sum
from .stable_base import (StableRule, complement_of, expand_around, fix_signs, has_sqrt, is_2f1,  # noqa: F401
                          n_terms, nonneg, square_differences, stable_sqrt, is_rational_in_symbols)
from .stable_elliptic import EllipticPiToCarlson, EllipticToCarlson

__all__ = ["stabilize", "StableForm", "StableRule", "RULES", "EllipticToCarlson", "EllipticPiToCarlson",
           "Hyp2f1Connection",
           "GammaAbsorb", "GammaRatio", "AcoshExcess", "SquareDifferences", "AtanhToAsinh", "AcoshToAsinh", "AsinhExcess", "AsinToAtan", "AcosToAtan",
           "Hyp2f1Complement", "Conjugate", "LogOfPower", "HalfAngle", "ExpTail", "FactorDifferences", "SinPiReduction",
           "is_rational_in_symbols"]


class Hyp2f1Connection(StableRule):
    """2F1(p, q; r; z) = Gamma(r) Gamma(d) / (Gamma(r - p) Gamma(r - q)) 2F1(p, q; 1 - d; 1 - z)
    + (1 - z)^d Gamma(r) Gamma(-d) / (Gamma(p) Gamma(q)) 2F1(r - p, r - q; 1 + d; 1 - z),
    d = r - p - q a non-integer number (DLMF 15.8.4), with 1 - z simplified.

    Kept only when the result, after hyperexpand / expand / gammasimp of
    each term, has fewer terms than the expanded original: terms of the surrounding sum then
    cancel exactly (e.g. the profile term c*x**n of a power-law gap against
    the a**n*(x/a)**n part of 2F1(1/2, n/2; n/2 + 1; a**2/x**2)).
    """

    name = "hyp2f1-connection"
    heads = (sp.hyper,)

    def apply(self, expr):
        reps = {}
        for h in expr.atoms(sp.hyper):
            if not is_2f1(h):
                continue
            p, q = h.ap
            r, = h.bq
            d = sp.simplify(r - p - q)
            if not d.is_number or d.is_integer:
                continue
            zc = complement_of(h.argument)
            t1 = sp.gamma(r) * sp.gamma(d) / (sp.gamma(r - p) * sp.gamma(r - q)) \
                * sp.hyperexpand(sp.hyper([p, q], [1 - d], zc))
            t2 = zc**d * sp.gamma(r) * sp.gamma(-d) / (sp.gamma(p) * sp.gamma(q)) \
                * sp.hyperexpand(sp.hyper([r - p, r - q], [1 + d], zc))
            reps[h] = t1 + t2
        if not reps:
            return expr
        # gammasimp term by term (gamma products are per term): gammasimp of
        # the whole sum factors it over all its radicals and powers, minutes
        # for a sum of three powers (x**(2/7) + x**(1/4) + x**(14/5), issue 26)
        cand = sp.expand(sp.powdenest(expr.xreplace(reps), force=True))
        cand = sp.expand(sp.Add(*[gammasimp_masked(t) for t in sp.Add.make_args(cand)]))
        if len(sp.Add.make_args(cand)) < len(sp.Add.make_args(sp.expand(expr))):
            return cand
        return expr


class GammaAbsorb(StableRule):
    """(k g) Gamma(g) = k Gamma(g + 1), k a nonzero number, inside products:
    removes the 0 * inf at g = 0 (Z_n at n = 1)."""

    name = "gamma-absorb"
    heads = (sp.gamma,)

    def apply(self, expr):
        def do(e):
            factors = list(e.args)
            changed = True
            while changed:
                changed = False
                for i, f in enumerate(factors):
                    if not isinstance(f, sp.gamma):
                        continue
                    g = f.args[0]
                    for j, L in enumerate(factors):
                        if j == i or not L.is_Add or not L.free_symbols:
                            continue
                        q = sp.cancel(L / g)
                        if q.is_number and q != 0:
                            factors[i] = sp.gamma(g + 1)
                            factors[j] = q
                            changed = True
                            break
                    if changed:
                        break
            return sp.Mul(*factors)
        return expr.replace(lambda e: e.is_Mul and e.has(sp.gamma), do)


class GammaRatio(StableRule):
    """Gamma(u) / Gamma(v) = gamma_ratio(u, v) when u - v is a number (each
    numerator paired with the closest denominator): no overflow of the two
    gammas for large arguments, no cancellation of two log-gammas."""

    name = "gamma-ratio"
    heads = (sp.gamma,)

    def apply(self, expr):
        def do(e):
            num, den, rest = [], [], []
            for f in e.args:
                if isinstance(f, sp.gamma) and f.args[0].free_symbols:
                    num.append(f.args[0])
                elif f.is_Pow and isinstance(f.base, sp.gamma) and f.exp.is_Integer and f.base.args[0].free_symbols:
                    (num if f.exp > 0 else den).extend([f.base.args[0]] * abs(int(f.exp)))
                else:
                    rest.append(f)
            if not num or not den:
                return e
            pairs = []
            for u in list(num):
                best = None
                for v in den:
                    dlt = sp.simplify(u - v)
                    if dlt.is_number and (best is None or abs(dlt) < abs(best[1])):
                        best = (v, dlt)
                if best is not None:
                    den.remove(best[0])
                    num.remove(u)
                    pairs.append((u, best[0]))
            if not pairs:
                return e
            out = sp.Mul(*rest) * sp.Mul(*[gamma_ratio(u, v) for u, v in pairs])
            out *= sp.Mul(*[sp.gamma(u) for u in num]) / sp.Mul(*[sp.gamma(v) for v in den])
            return out
        return expr.replace(lambda e: e.is_Mul and e.has(sp.gamma), do)


class AtanhToAsinh(StableRule):
    """atanh(w) = asinh(w / sqrt(1 - w**2)), 1 - w**2 simplified symbolically
    (w a rational function of the symbols): accurate as w -> 1, where atanh
    is ill-conditioned in the rounded argument (atanh(1.0) = inf)."""

    name = "atanh->asinh"
    heads = (sp.atanh,)

    def apply(self, expr):
        def do(e):
            w = e.args[0]
            s = stable_sqrt(1 - w**2)
            return sp.asinh(w / s) if s is not None else e
        return expr.replace(lambda e: isinstance(e, sp.atanh), do)


class AcoshToAsinh(StableRule):
    """acosh(u) = asinh(sqrt(u**2 - 1)) for u >= 1, u**2 - 1 simplified
    symbolically: accurate as u -> 1."""

    name = "acosh->asinh"
    heads = (sp.acosh,)

    def apply(self, expr):
        def do(e):
            s = stable_sqrt(e.args[0]**2 - 1)
            return sp.asinh(s) if s is not None else e
        return expr.replace(lambda e: isinstance(e, sp.acosh), do)


#: the elementary functions a term may hold and still be compared with a target by value
_ELEMENTARY = {sp.sin, sp.cos, sp.tan, sp.sinh, sp.cosh, sp.tanh, sp.exp, sp.log, sp.asin, sp.acos,
               sp.atan, sp.asinh, sp.acosh, sp.atanh}


class AsinhExcess(StableRule):
    """T - C asinh(u) = -C (u sqrt(1 + u^2) - asinh(u)) = -C asinh_excess(u) for a
    pair of terms of a sum with T = -C u sqrt(1 + u^2) (the ratio checked at random
    points here, the rewrite by the driver): the two terms cancel to 2 u^3/3 as
    u -> 0 (a periodic array's gap near full contact: after acosh->asinh the
    sinusoid's gap is 2 h sin^2(pi a/L) (w sqrt(1 + w^2) - asinh(w))), the
    primitive :class:`~.special.asinh_excess` does not."""

    name = "asinh-excess"
    heads = (sp.asinh,)

    def apply(self, expr):
        def do(e):
            if not e.is_Add or not e.has(sp.asinh):
                return e
            terms = list(e.args)
            for i, ti in enumerate(terms):
                for h in ti.atoms(sp.asinh):
                    # C = ti/h where h is a factor of the term (a product's factors read,
                    # not cancel()ed: cancel of every term was a third of the pair search)
                    factors = list(sp.Mul.make_args(ti))
                    if h not in factors:
                        continue
                    factors.remove(h)
                    C = sp.Mul(*factors)
                    if C.has(h):
                        continue
                    u = h.args[0]
                    target = -C * u * sp.sqrt(1 + u**2)
                    known = _ELEMENTARY | {type(f) for f in target.atoms(sp.Function)}
                    for j, tj in enumerate(terms):
                        # a term holding a function the target has not (an elliptic integral,
                        # a Carlson R_J: its evalf is a quadrature) is not the target: not
                        # evaluated at 24 points at 30 digits (the exact cylinder's tangential
                        # slip spent minutes here)
                        if j == i or {type(f) for f in tj.atoms(sp.Function)} - known:
                            continue
                        if _same_value(tj, target):
                            rest = [t for k, t in enumerate(terms) if k not in (i, j)]
                            return sp.Add(*rest, -C * asinh_excess(u))
            return e
        return expr.replace(lambda e: e.is_Add and e.has(sp.asinh), do)


class AcoshExcess(StableRule):
    """R + C acosh(w) = (R + C w sqrt(w^2 - 1)) - C asinh_excess(sqrt(w^2 - 1))
    for a sum holding a term C acosh(w), w = n/d, the first part reduced
    symbolically: with n = W D, d = D (D > 0) and W = sqrt(1 + r^2), r =
    sqrt(w^2 - 1), R + C W r is a polynomial in r and sqrt(1 + r^2) whose
    cancelling terms drop out exactly; kept where it has fewer terms than R.

    The excess form of :class:`AsinhExcess` for any weights: the sin^4
    array's gap h (t S^2 s + 2 t s^3 - 3 S^4 acosh(s/S))/2 (s = sin(pi x/L),
    S = sin(pi a/L), t = sqrt(s^2 - S^2)) is h (2 s t^3 + 3 S^4
    asinh_excess(t/S))/2, no two terms cancelling as t -> 0 (full contact, or
    the contact edge); the sinusoid's pair is the case where R + C W r = 0.
    Before :class:`SquareDifferences`, which then makes s^2 - S^2 a product."""

    name = "acosh-excess"
    heads = (sp.acosh,)

    def apply(self, expr):
        def do(e):
            for term in e.args:
                for ac in term.atoms(sp.acosh):
                    new = _acosh_excess(e, term, ac)
                    if new is not None:
                        return new
            return e
        return expr.replace(lambda e: e.is_Add and e.has(sp.acosh), do)


def _acosh_excess(e, term, ac):
    """:class:`AcoshExcess` on the sum ``e`` for its term ``term`` = C ``ac``, or None."""
    C = sp.cancel(term / ac)
    if C.has(ac) or C.has(sp.acosh):
        return None
    n, d = sp.fraction(sp.together(ac.args[0]))
    if not n.free_symbols or d.is_number:
        return None
    D, W, r = sp.Dummy("D", positive=True), sp.Dummy("W", positive=True), sp.Dummy("r", positive=True)
    rest = e - term

    inner = n.free_symbols | d.free_symbols

    def in_r(v):
        """v in r, sqrt(1 + r^2) and D, or None where v is not a function of w and d alone."""
        v = v.xreplace({n: W * D, d: D})
        if v.free_symbols & inner:
            return None
        # sqrt((W D - D)(W D + D)) -> D sqrt(W^2 - 1): each half-integer power's base expanded first
        v = v.replace(lambda q: q.is_Pow and q.exp.is_Rational and q.exp.q == 2,
                      lambda q: sp.Pow(sp.factor_terms(sp.expand(q.base)), q.exp))
        v = sp.powdenest(sp.factor_terms(v), force=True)
        return sp.expand(sp.powdenest(sp.expand(v.xreplace({W: sp.sqrt(1 + r**2)})), force=True))

    R_r, T_r = in_r(rest), in_r(C * W * sp.sqrt(W**2 - 1))
    if R_r is None or T_r is None:
        return None
    diff = sp.expand(R_r + T_r)
    if diff.has(W) or (diff != 0 and len(sp.Add.make_args(diff)) >= len(sp.Add.make_args(R_r))):
        return None     # nothing cancelled: the pair is not an excess
    diff = sp.factor(diff)
    # t = sqrt(n^2 - d^2) factored (sqrt(x - a) sqrt(x + a); sin(pi (x - a)/L) sin(pi (x + a)/L))
    t = stable_sqrt(n**2 - d**2)
    if t is None:
        t = sp.sqrt(n**2 - d**2)
    back = diff.xreplace({sp.sqrt(1 + r**2): W}).xreplace({W: n / d, r: t / d, D: d})
    return back - C * asinh_excess(t / d)


@functools.lru_cache(maxsize=1024)
def _mp_function(expr, syms):
    """expr as an mpmath function of ``syms`` (SymPy's printer; None where a
    function of the expression has no mpmath translation)."""
    try:
        return sp.lambdify(syms, expr, modules="mpmath")
    except Exception:  # noqa: BLE001 - any printer failure: the slow path
        return None


@functools.lru_cache(maxsize=4096)
def _value_at(expr, point):
    """expr at the point (pairs symbol, value) to 30 digits, as a complex; None
    where it is no number there.  Remembered: the pair search of
    :class:`AsinhExcess` compares every term of a sum with every target at the
    same points.  Evaluated by the expression's mpmath translation at 30
    digits (compiled once per expression: xreplace and evalf at each point
    were most of the pair search's time, the worn cylinder's fretting test
    20 of its 30 s), else by evalf."""
    import mpmath
    from ..core.precision import workdps
    syms = tuple(s_ for s_, _ in point)
    fn = _mp_function(expr, syms)
    if fn is not None:
        try:
            with workdps(30):
                v = fn(*(mpmath.mpf(v_.p) / v_.q for _, v_ in point))
                return complex(v)
        except (TypeError, ValueError, ZeroDivisionError, OverflowError, NameError, AttributeError):
            pass
    try:
        return complex(sp.N(expr.xreplace(dict(point)), 30))
    except (TypeError, ValueError):
        return None


def _same_value(p, q, tries: int = 24, agree: int = 2):
    """p == q at ``agree`` random points where both are real and nonzero, and at
    more points than not (a filter: the points know no domain, a sign may differ
    outside it; the driver checks the rewrite under the conditions)."""
    import random
    syms = sorted(p.free_symbols | q.free_symbols, key=lambda s_: s_.name)
    rng, hits, misses = random.Random(7), 0, 0
    for _ in range(tries):
        vals = {s_: sp.Rational(rng.randint(5, 45), 100) for s_ in syms}
        vals = {s_: v * (1 + sp.Rational(k + 1, 7)) for k, (s_, v) in enumerate(vals.items())}
        key = tuple(sorted(vals.items(), key=lambda kv: kv[0].name))
        pv, qv = _value_at(p, key), _value_at(q, key)
        if pv is None or qv is None:
            continue
        if pv.imag or qv.imag or qv == 0:
            continue
        if abs(pv / qv - 1) > 1e-12:
            misses += 1
            if 2 * misses >= tries:          # hits > misses can no longer be reached
                return False
        else:
            hits += 1
    return hits >= agree and hits > misses


class AsinToAtan(StableRule):
    """asin(w) = atan(w / sqrt(1 - w**2)) = pi/2 - atan(sqrt(1 - w**2) / w), w > 0,
    1 - w**2 simplified symbolically.

    The second (complement) form is taken when the pi/2 then cancels against
    another term, i.e. when the expanded complement form has no more terms
    than the expanded plain form (e.g. pi*x - 2*x*asin(a/x) =
    2*x*atan(sqrt((x - a)*(x + a))/a)): both are accurate as w -> 1.
    """

    name = "asin->atan"
    heads = (sp.asin,)

    def apply(self, expr):
        reps, keys, pkeys = {}, {}, {}
        for e in expr.atoms(sp.asin):
            w = e.args[0]
            s_ = stable_sqrt(1 - w**2)
            if s_ is None or not w.is_positive:
                continue
            k, pk = sp.Dummy("A"), sp.Dummy("P")
            keys[k] = sp.atan(s_ / w)
            pkeys[e] = pk
            reps[e] = (sp.atan(w / s_), sp.pi / 2 - k)
        if not reps:
            return expr
        plain = expr.xreplace({e: p for e, (p, c) in reps.items()})
        comp_x = expand_around(expr.xreplace({e: c for e, (p, c) in reps.items()}), list(keys))
        plain_x = expand_around(expr.xreplace(pkeys), list(pkeys.values()))
        if n_terms(comp_x) <= n_terms(plain_x):
            return comp_x.xreplace(keys)
        return plain


class SquareDifferences(StableRule):
    """sin^2 u - sin^2 v = sin(u - v) sin(u + v) (and the cos, sinh, cosh
    pairs, and 1 - sin^2 v = cos^2 v: :func:`~.stable_base.square_differences`),
    any pair of terms of a sum, u - v factored: exact where the difference
    cancels (the periodic array's sqrt(sin^2(pi a/L) - sin^2(pi x/L)) at the
    contact edge, the kernel of Koiter's punch)."""

    name = "square-differences"
    heads = (sp.sin, sp.cos, sp.sinh, sp.cosh)

    def applies(self, expr) -> bool:
        """A squared sin, cos, sinh or cosh occurs."""
        return any(p.exp == 2 and isinstance(p.base, self.heads) for p in expr.atoms(sp.Pow))

    def apply(self, expr):
        return square_differences(expr)


class AcosToAtan(StableRule):
    """acos(w) = atan(sqrt(1 - w**2) / w), w > 0, 1 - w**2 simplified
    symbolically: accurate as w -> 1 (acos(1 - d) ~ sqrt(2 d))."""

    name = "acos->atan"
    heads = (sp.acos,)

    def apply(self, expr):
        def do(e):
            w = e.args[0]
            s = stable_sqrt(1 - w**2)
            if s is None or not w.is_positive:
                return e
            return sp.atan(s / w)
        return expr.replace(lambda e: isinstance(e, sp.acos), do)


class Hyp2f1Complement(StableRule):
    """2F1(a, b; c; z) = hyp2f1c(a, b, c, z, 1 - z), 1 - z simplified
    symbolically: near z = 1 the evaluation uses the accurately known 1 - z
    (connection formula in float64; mpmath at the points where it cancels)."""

    name = "hyp2f1-complement"
    heads = (sp.hyper,)

    def apply(self, expr):
        def do(e):
            z = e.argument
            return hyp2f1c(e.ap[0], e.ap[1], e.bq[0], z, complement_of(z))
        return expr.replace(is_2f1, do)


class Conjugate(StableRule):
    """u - v = (u**2 - v**2) / (u + v) for u, v >= 0, one of them a square root,
    when u**2 - v**2 is simpler than u**2 and v**2 (any pair of terms of a
    sum): R - sqrt(R**2 - x**2) = x**2 / (R + sqrt(R**2 - x**2)), exact where
    the difference cancels."""

    name = "conjugate"

    def apply(self, expr):
        def want(e):
            return e.is_Add and any(has_sqrt(t) for t in e.args)

        def pair(u, mv):
            v = -mv
            if not (nonneg(u) and nonneg(v)) or not (has_sqrt(u) or has_sqrt(v)):
                return None
            num = sp.expand(u**2 - v**2)
            if has_sqrt(num) or num == 0:
                return None
            if sp.count_ops(num) < sp.count_ops(sp.expand(u**2)) + sp.count_ops(sp.expand(v**2)):
                return fix_signs(sp.factor(num)) / (u + v)
            return None

        def do(e):
            terms = list(e.args)
            for i in range(len(terms)):
                for j in range(len(terms)):
                    if i == j:
                        continue
                    r = pair(terms[i], terms[j])
                    if r is not None:
                        rest = [t for k, t in enumerate(terms) if k not in (i, j)]
                        return sp.Add(r, *rest)
            return e
        return expr.replace(want, do)


class LogOfPower(StableRule):
    """log(u**p * v**q ...) = p log(u) + ... when the powers combine:
    log(b**(2b)/a**(2b)) = 2 b log(b/a) for positive b/a: the power is 1 + tiny
    for small exponents, and its logarithm would keep only the digits of the
    tiny part that survived the rounding of 1 + tiny."""

    name = "log-of-power"
    heads = (sp.log,)

    def apply(self, expr):
        def do(e):
            arg = sp.powsimp(e.args[0], force=True)
            if arg.is_Pow and not arg.exp.is_Integer and arg.base.is_positive:
                return arg.exp * sp.log(arg.base)
            return e
        return expr.replace(lambda e: isinstance(e, sp.log) and e.args[0].has(sp.Pow), do)


class HalfAngle(StableRule):
    """c cosh(u) - c = 2 c sinh(u/2)^2 and c - c cos(u) = 2 c sin(u/2)^2 (any
    pair of terms of a sum): exact where the difference cancels (u -> 0,
    e.g. the profile R (cosh(x/R) - 1) at x << R)."""

    name = "half-angle"
    heads = (sp.cosh, sp.cos)

    def apply(self, expr):
        def do(e):
            terms = list(e.args)
            for i, t_ in enumerate(terms):
                c, f = t_.as_independent(sp.cosh, sp.cos, as_Add=False)
                if not isinstance(f, (sp.cosh, sp.cos)):
                    continue
                for j, other in enumerate(terms):
                    if j != i and sp.simplify(other + c) == 0:
                        u = f.args[0]
                        half = 2 * c * (sp.sinh(u / 2)**2 if isinstance(f, sp.cosh) else -sp.sin(u / 2)**2)
                        return sp.Add(half, *[t2 for k, t2 in enumerate(terms) if k not in (i, j)])
            return e
        return expr.replace(lambda e: e.is_Add and e.has(sp.cosh, sp.cos), do)


class ExpTail(StableRule):
    """c exp(w) - c - c w - ... - c w^(n-1)/(n-1)! = c exp_tail(n, w) (any terms
    of a sum, expanded, the exponentials of a term combined; n as large as the
    terms present allow, n >= 1; c may hold an exponential exp(v) of the other
    terms: e^(w + v) - e^v (1 + w) = e^v exp_tail(2, w)): exact where the
    terms cancel (w -> 0).  The Lee-Radok force of a parabola on a Maxwell
    term at a constant rate, tau^2 (t/tau - 1 + exp(-t/tau)) =
    tau^2 exp_tail(2, -t/tau), keeps its digits for t << tau (the plain form
    cancels to nothing below t/tau ~ 1e-8), and so does Ting's receding phase
    e^(-(t - s1)/tau) (s1 - tau + tau e^(-s1/tau)); n = 1 is expm1."""

    name = "exp-tail"
    heads = (sp.exp,)
    #: the longest tail sought, and the longest sum searched
    MAX_N = 12
    MAX_TERMS = 64

    @staticmethod
    def _split(term):
        """(coefficient, combined exponent) of a term: c exp(w), w = 0 without exponential."""
        ws, rest = [], []
        for f in sp.Mul.make_args(term):
            (ws if isinstance(f, sp.exp) and f.args[0].free_symbols else rest).append(f)
        return sp.Mul(*rest), sp.expand(sp.Add(*[f.args[0] for f in ws]))

    @classmethod
    def _terms(cls, e):
        """The terms of e expanded, each as coefficient * exp(combined exponent)."""
        out = {}
        for t_ in sp.Add.make_args(sp.expand(e)):
            c, w = cls._split(t_)
            u = c * sp.exp(w) if w != 0 else c
            out[u] = out.get(u, 0) + 1
        return out

    def apply(self, expr):
        def do(e):
            terms = self._terms(e)
            if len(terms) > self.MAX_TERMS:       # each term is tried against each exponential: quadratic work
                return e
            out, changed = [], False
            for t_ in list(terms):
                if not terms.get(t_):
                    continue
                c0, wt = self._split(t_)
                if wt == 0:
                    continue
                bases = [sp.S.Zero] + sorted({self._split(u)[1] for u in terms if terms[u]} - {wt, sp.S.Zero},
                                             key=sp.default_sort_key)
                best = None
                for v in bases:
                    c, w = c0 * sp.exp(v), sp.expand(wt - v)
                    if not w.free_symbols:
                        continue
                    n, taken = 0, []
                    while n < self.MAX_N:
                        want = self._terms(-c * w**n / sp.factorial(n))
                        if not all(terms.get(u, 0) >= taken.count(u) + k for u, k in want.items()):
                            break
                        taken.extend(u for u, k in want.items() for _ in range(k))
                        n += 1
                    if n and (best is None or n > best[0]):
                        best = (n, c, w, taken)
                if best is None:
                    continue
                n, c, w, taken = best
                for u in taken + [t_]:
                    terms[u] -= 1
                out.append(c * exp_tail(n, w))
                changed = True
            if not changed:
                return e
            rest = [u for u, k in terms.items() for _ in range(k)]
            return sp.Add(*out, *rest)
        return expr.replace(lambda e: e.is_Add and e.has(sp.exp), do)


class FactorDifferences(StableRule):
    """A rational sum that factors is replaced by its factored form
    (a**2 - x**2 = (a - x)(a + x), 1 - x**2/a**2 = (a - x)(a + x)/a**2 ...):
    the small difference a - x is then formed exactly (Sterbenz) and square
    roots never see rounding-negative arguments."""

    name = "factor"

    def apply(self, expr):
        def want(e):
            return e.is_Add and is_rational_in_symbols(e)

        def do(e):
            f = fix_signs(sp.factor(e))
            num, _ = sp.fraction(f)
            if num.is_Mul and any(t.is_Add or (t.is_Pow and t.base.is_Add) for t in num.args) and f != e:
                return f
            if num.is_Pow and num.base.is_Add:
                return f
            return e
        return expr.replace(want, do)


#: the rules in the order :func:`stabilize` applies them
class SinPiReduction(StableRule):
    """sin(pi u/L) = sin_pi_sum(L, u_1, ..., u_k) and cos(pi u/L) = sin_pi_sum(L,
    u_1, ..., u_k, L/2) for u = u_1 + ... + u_k, each term a rational multiple of
    a symbol, L > 0 a symbol or a number: :class:`~.special.sin_pi_sum` takes the
    nearest multiple of L off the sum exactly.  A periodic array near full contact
    (a -> L/2) has sin(pi (a + x)/L) at a + x -> L and cos(pi x/L) at x -> L/2,
    where the sine of the rounded argument keeps only eps pi/|sin| of its size
    (2e-9 relative at a = L/2 - 1e-7 L); last, after the rules that read sines."""

    name = "sin-pi-reduction"
    heads = (sp.sin, sp.cos)

    def applies(self, expr) -> bool:
        """A sine or cosine of pi times something occurs."""
        return any(f.args[0].has(sp.pi) for f in expr.atoms(sp.sin, sp.cos))

    def apply(self, expr):
        def do(e):
            parts = _pi_fraction(e.args[0])
            if parts is None:
                return e
            L, terms = parts
            return sin_pi_sum(L, *terms, *((L / 2,) if isinstance(e, sp.cos) else ()))
        return expr.replace(lambda e: isinstance(e, (sp.sin, sp.cos)), do)


def _pi_fraction(arg):
    """(L, [u_1, ..., u_k]) for arg = pi (u_1 + ... + u_k)/L (see :class:`SinPiReduction`), else None."""
    num, den = sp.fraction(sp.together(arg / sp.pi))
    if not (den.is_positive and (den.is_Symbol or den.is_Rational)) or num.has(sp.pi):
        return None
    terms = sp.Add.make_args(sp.expand(num))
    for t in terms:
        c, v = t.as_coeff_Mul()
        if not (c.is_Rational and v.is_Symbol):
            return None
    return den, terms


RULES = (EllipticPiToCarlson(), EllipticToCarlson(), Hyp2f1Connection(), GammaAbsorb(), GammaRatio(), AcoshExcess(), SquareDifferences(),
         AtanhToAsinh(), AcoshToAsinh(), AsinhExcess(), AsinToAtan(), AcosToAtan(), Hyp2f1Complement(), Conjugate(), LogOfPower(),
         HalfAngle(), ExpTail(), FactorDifferences(), SinPiReduction())


# ====================================================================== driver
@dataclass
class StableForm:
    """A stabilised expression with the record of the rewrites."""

    original: sp.Expr
    expr: sp.Expr
    rewrites: list = field(default_factory=list)   # (rule name, detail)
    rejected: list = field(default_factory=list)   # (rule name, reason)

    def __str__(self):
        lines = [f"stable form: {self.expr}"]
        lines += [f"  {name}: {what}" for name, what in self.rewrites]
        lines += [f"  rejected {name}: {why}" for name, why in self.rejected]
        return "\n".join(lines)


def _apply_masked(rule, expr):
    """Apply ``rule`` to the integrands of unevaluated Integrals and, separately,
    to the expression around them (a rule must never move a factor that depends
    on the integration variable across the integral sign)."""
    if not expr.has(sp.Integral):
        return rule.apply(expr)
    ints, masks = {}, {}
    for I in _outermost_integrals(expr):
        # the outermost ones only: an inner integral is masked inside its integrand (masked
        # from the inside out, a nested one was left behind as its mask, undefined in an export)
        d = sp.Dummy("Int")
        ints[d] = sp.Integral(_apply_masked(rule, I.function), *I.limits)
        masks[I] = d
    return rule.apply(expr.xreplace(masks)).xreplace(ints)


def _outermost_integrals(expr):
    """The Integrals of ``expr`` that lie inside no other, each once."""
    found, todo = {}, [expr]
    while todo:
        e = todo.pop()
        if isinstance(e, sp.Integral):
            found[e] = None
        else:
            todo.extend(e.args)
    return list(found)


def stabilize(expr: sp.Expr, conditions=(), check: bool = True) -> StableForm:
    """The stable form of ``expr``: each rule of :data:`RULES` applied in turn.

    Definition: the returned ``StableForm.expr`` equals ``expr`` identically
    (each rewrite is an identity) wherever ``expr`` is real; what changes is
    how it is computed in floating point.  ``conditions`` (SymPy relations,
    e.g. ``x < a``) restrict the random points at which each rewrite is checked
    against the original (20 digits at 3 points); a rewrite that fails the
    check, or raises, is recorded in ``rejected`` and not applied.
    ``check=False`` skips the check.  Domain: any SymPy expression (integrands
    of unevaluated integrals are rewritten separately from their surroundings).

    >>> import sympy as sp
    >>> R, x = sp.symbols("R x", positive=True)
    >>> form = stabilize(R - sp.sqrt(R**2 - x**2))
    >>> form.expr
    x**2/(R + sqrt(R - x)*sqrt(R + x))
    >>> [name for name, _ in form.rewrites]
    ['conjugate', 'factor']
    """
    syms = sorted(expr.free_symbols, key=lambda s: s.name)
    conds = tuple(c for c in conditions if isinstance(c, sp.Basic) and c not in (sp.true,))
    form = StableForm(expr, expr)
    cur = expr
    for rule in RULES:
        if not rule.applies(cur):
            continue
        try:
            new = _apply_masked(rule, cur)
        except Exception as exc:  # a SymPy failure inside a rule: skip the rule
            form.rejected.append((rule.name, f"{type(exc).__name__}: {exc}"))
            continue
        if new == cur:
            continue
        if check:
            ok, why = expressions_agree(cur, new, syms, conds)
            if not ok:
                form.rejected.append((rule.name, why))
                continue
        form.rewrites.append((rule.name, _describe(cur, new)))
        cur = new
    form.expr = cur
    return form


def _describe(old, new):
    heads = {sp.elliptic_k: "K", sp.elliptic_e: "E", sp.atanh: "atanh", sp.acosh: "acosh",
             sp.asin: "asin", sp.acos: "acos", sp.gamma: "gamma", sp.hyper: "hyper"}
    gone = [nm for f, nm in heads.items() if old.has(f) and not new.has(f)]
    s = str(new)
    if len(s) > 120:
        s = s[:117] + "..."
    return (f"removed {', '.join(gone)}; " if gone else "") + f"now {s}"
