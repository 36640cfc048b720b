"""Numerically stable rewrites of derived expressions, chosen automatically.

Closed forms that are exact in exact arithmetic can be useless in float64 at
the extremes of their arguments: K(m) - E(m) cancels for small m, Gamma(n/2)
overflows for n > 343, atanh(sqrt(a^2 - x^2)/a) is atanh(1.0) = inf for
x < 1e-8 a, sqrt(a^2 - x^2) takes the square root of a rounding-negative
number, pi*x - 2*x*asin(a/x) cancels at x -> a, 2F1 at z = 1 - x^2/a^2 loses
the information that is in x^2/a^2 ...

:func:`stabilize` inspects a SymPy expression and applies, wherever its
pattern occurs, one of a small set of general rules (no profile is special
cased).  Each rule is an identity; every application is re-checked
numerically (30 digits at random admissible points) before it is kept.

Rules (in the order applied)
----------------------------
``elliptic->carlson``
    K(m) = R_F(0, m', 1), E(m) = R_F(0, m', 1) - (m/3) R_D(0, m', 1) with the
    complementary parameter m' = 1 - m simplified symbolically (so
    1 - a^2/R^2 becomes (R - a)(R + a)/R^2), then the coefficients of R_F and
    R_D collected: K - E = (m/3) R_D(0, m', 1) has no cancellation for small m
    and keeps the logarithmic divergence at m -> 1 accurate.  (The complete
    integrals R_F(0, y, 1), R_D(0, y, 1) are evaluated by the AGM, R_D as
    3 K sum 2^(n-1) c_n^2 / m with positive terms: in float64 about 5x faster
    than ``scipy.special.elliprd``; in mpmath about 15x faster than
    ``mpmath.elliprd``.)
``gamma-absorb``
    (k*g) * Gamma(g) -> k * Gamma(g + 1): removes 0 * inf (Z_n at n = 1).
``gamma-ratio``
    Gamma(u)/Gamma(v) with u - v a number -> gamma_ratio(u, v), evaluated by a
    Stirling-series difference (log1p form) for large arguments: no overflow,
    no log-gamma cancellation.
``atanh->asinh``, ``acosh->asinh``, ``asin->atan``, ``acos->atan``
    atanh(w) = asinh(w/sqrt(1 - w^2)), acosh(u) = asinh(sqrt(u^2 - 1)),
    asin(w) = atan(w/sqrt(1 - w^2)) (or pi/2 - atan(sqrt(1 - w^2)/w) when the
    pi/2 then cancels against another term, which is checked by expanding),
    acos(w) = atan(sqrt(1 - w^2)/w): with 1 - w^2 simplified symbolically these
    are accurate as w -> 1 where the original functions are ill-conditioned
    *in the rounded argument*.
``hyp2f1-connection``
    2F1(p, q; r; z) -> its connection formula about z = 1 when r - p - q is a
    non-integer number and terms of the surrounding sum then cancel exactly
    (checked by expanding), e.g. c*x**n against the (x/a)**n part of the
    power-law gap's 2F1(1/2, n/2; n/2 + 1; a**2/x**2).
``hyp2f1-complement``
    2F1(a, b; c; z) -> hyp2f1c(a, b, c, z, 1 - z) with 1 - z simplified
    symbolically; near z = 1 the evaluation uses the connection formula in the
    accurately known 1 - z (and falls back to mpmath at the points where the
    connection formula cancels, e.g. c - a - b near an integer).
``conjugate``
    u - v with u, v > 0 (one a square root) and u^2 - v^2 simpler ->
    (u^2 - v^2)/(u + v): R - sqrt(R^2 - x^2) = x^2/(R + sqrt(R^2 - x^2)).
``factor``
    Rational sums that factor (differences of squares a^2 - x^2,
    1 - x^2/a^2, x^2/a^2 - 1 ...) are replaced by their factored forms, so the
    small difference a - x is formed exactly (Sterbenz) and square roots never
    see rounding-negative arguments.

The result is a :class:`StableForm`: the rewritten expression and the list of
rules applied (with what they replaced, and any rejected by the numeric
check).  The new functions (``carlson_rf/rd/rg``, ``gamma_ratio``,
``hyp2f1c``) are SymPy functions with NumPy (:data:`NUMPY_FUNCS`), mpmath
(:data:`MPMATH_FUNCS`) and Arb (:mod:`linecontact_sym.certified`)
implementations.

The module also holds the accuracy audit used by the tests and the
benchmark: :data:`EXTREME_GRID`, :func:`extreme_points`, :func:`audit`,
:func:`condition_number`.
"""
from __future__ import annotations

import itertools
import math
import random
from dataclasses import dataclass, field

import mpmath
import numpy as np
import scipy.special as sc
import sympy as sp

__all__ = ["stabilize", "StableForm", "carlson_rf", "carlson_rd", "carlson_rg", "gamma_ratio", "hyp2f1c",
           "np_gamma_ratio", "np_hyp2f1c", "NUMPY_FUNCS", "MPMATH_FUNCS"]


# ====================================================================== primitives
class _StableFunction(sp.Function):
    """Base of the stable primitives: evaluates numerically through mpmath."""

    _mp = None

    def _eval_evalf(self, prec):
        dps = max(int(prec * 0.30103) + 1, 15)
        with mpmath.workdps(dps + 10):
            try:
                args = [mpmath.mpf(sp.N(a_, dps + 10)) for a_ in self.args]
            except TypeError:
                return None
            val = type(self)._mp(*args)
        return sp.Float(val, dps)


def _mp_agm_kd(y):
    """(K, S) for m = 1 - y by the AGM: K = R_F(0, y, 1) and
    R_D(0, y, 1) = 3 K S, S = sum_n 2^(n-1) c_n^2 / m (positive terms, with
    c_1 = m / (4 a_1): no cancellation for small m)."""
    m = 1 - y
    a_, b_ = mpmath.mpf(1), mpmath.sqrt(y)
    S = mpmath.mpf(0.5)
    d = mpmath.mpf(1)
    w = mpmath.mpf(0.5)
    tol = mpmath.eps * 4
    for _ in range(200):
        a1 = (a_ + b_) / 2
        b_ = mpmath.sqrt(a_ * b_)
        a_ = a1
        d = m * d * d / (16 * a_ * a_) if _ else m / (16 * a_ * a_)
        w *= 2
        S += w * d
        if w * d <= tol * S:
            break
    K = mpmath.pi / (a_ + b_)
    return K, S


def _mp_rf(x, y, z):
    if x == 0 and z == 1 and 0 < y <= 1:
        return _mp_agm_kd(y)[0]
    return mpmath.elliprf(x, y, z)


def _mp_rd(x, y, z):
    if x == 0 and z == 1 and 0 < y <= 1:
        K, S = _mp_agm_kd(y)
        return 3 * K * S
    return mpmath.elliprd(x, y, z)


def _mp_rg(x, y, z):
    return mpmath.elliprg(x, y, z)


def _mp_gamma_ratio(u, v):
    return mpmath.gammaprod([u], [v])


def _mp_hyp2f1c(a_, b_, c_, z, zc):
    """2F1 at z, using the complement zc = 1 - z where z is close to 1."""
    if z > 0.5 and zc >= 0:
        extra = int(-mpmath.log10(zc)) + 5 if zc > 0 else 5
        with mpmath.workdps(mpmath.mp.dps + max(extra, 5)):
            zz = 1 - zc
            return +mpmath.hyp2f1(a_, b_, c_, zz)
    return mpmath.hyp2f1(a_, b_, c_, z)


class carlson_rf(_StableFunction):
    """Carlson's symmetric elliptic integral R_F(x, y, z)."""
    nargs = 3
    _mp = staticmethod(_mp_rf)


class carlson_rd(_StableFunction):
    """Carlson's symmetric elliptic integral R_D(x, y, z)."""
    nargs = 3
    _mp = staticmethod(_mp_rd)


class carlson_rg(_StableFunction):
    """Carlson's symmetric elliptic integral R_G(x, y, z)."""
    nargs = 3
    _mp = staticmethod(_mp_rg)


class gamma_ratio(_StableFunction):
    """Gamma(u)/Gamma(v) without overflow (u - v moderate)."""
    nargs = 2
    _mp = staticmethod(_mp_gamma_ratio)


class hyp2f1c(_StableFunction):
    """2F1(a, b; c; z) given also the accurately computed complement zc = 1 - z."""
    nargs = 5
    _mp = staticmethod(_mp_hyp2f1c)


# ---------------------------------------------------------------- NumPy versions
# Bernoulli-number coefficients B_2k / (2k (2k - 1)) of the Stirling series
_STIRLING = [1 / 12, -1 / 360, 1 / 1260, -1 / 1680, 1 / 1188, -691 / 360360, 1 / 156,
             -3617 / 122400]


def _stirling_tail(z):
    zi = 1.0 / z
    z2 = zi * zi
    acc = np.zeros_like(z)
    for coef in reversed(_STIRLING):
        acc = acc * z2 + coef
    return acc * zi


def np_gamma_ratio(u, v):
    """Gamma(u)/Gamma(v), vectorised float64.

    For u, v >= 10: exp(d log v + (v + d - 1/2) log1p(d/v) - d + S(u) - S(v)),
    d = u - v, S the Stirling series (8 terms, error < 1e-17): no overflow and
    no cancellation of two large log-gammas.  Otherwise the quotient of
    ``scipy.special.gamma`` (or of exp(gammaln) with signs where that overflows).
    """
    u = np.asarray(u, dtype=float)
    v = np.asarray(v, dtype=float)
    u, v = np.broadcast_arrays(u, v)
    with np.errstate(all="ignore"):
        out = sc.gamma(u) * sc.rgamma(v)
        big = (u >= 10) & (v >= 10)
        if np.any(big):
            ub, vb = u[big], v[big]
            d = ub - vb
            L = d * np.log(vb) + (vb + d - 0.5) * np.log1p(d / vb) - d \
                + _stirling_tail(ub) - _stirling_tail(vb)
            out = np.array(out, dtype=float, copy=True)
            out[big] = np.exp(L)
        bad = ~big & ~np.isfinite(out) & np.isfinite(u) & np.isfinite(v)
        if np.any(bad):
            out = np.array(out, dtype=float, copy=True)
            ub, vb = u[bad], v[bad]
            out[bad] = sc.gammasgn(ub) * sc.gammasgn(vb) * np.exp(sc.gammaln(ub) - sc.gammaln(vb))
    return out[()] if out.ndim == 0 else out


def _pair_ratio(num, dens):
    """Gamma(num)/Gamma(den_k) for the den closest to num, times 1/Gamma(other)."""
    d0, d1 = dens
    with np.errstate(all="ignore"):
        use0 = np.abs(num - d0) <= np.abs(num - d1)
        first = np.where(use0, d0, d1)
        other = np.where(use0, d1, d0)
        return np_gamma_ratio(num, first) * sc.rgamma(other)


def _series(A, B, C, Z, maxterms=50000):
    """Maclaurin sum of 2F1(A, B; C; Z), 0 <= Z <= 1/2, Kahan-summed; returns
    (sum, sum of |terms|) -- their ratio measures the cancellation.  NaN where
    not converged within ``maxterms``."""
    total = np.ones_like(Z)
    absum = np.ones_like(Z)
    comp = np.zeros_like(Z)
    term = np.ones_like(Z)
    live = np.ones(Z.shape, dtype=bool)
    k = 0
    while np.any(live) and k < maxterms:
        idx = np.flatnonzero(live)
        t = term[idx] * (A[idx] + k) * (B[idx] + k) / ((C[idx] + k) * (k + 1)) * Z[idx]
        term[idx] = t
        y = t - comp[idx]
        s_ = total[idx] + y
        comp[idx] = (s_ - total[idx]) - y
        total[idx] = s_
        absum[idx] += np.abs(t)
        k += 1
        # once the term ratio r is below 1 and falling towards Z <= 1/2 the
        # tail is below |t| r/(1 - r)
        r = np.abs((A[idx] + k) * (B[idx] + k) / ((C[idx] + k) * (k + 1)) * Z[idx])
        done = (t == 0) | ((r < 0.75) & (k > np.maximum(-A[idx], -B[idx]))
                           & (np.abs(t) * r / (1 - r) <= 1e-17 * np.abs(s_)))
        live[idx[done]] = False
    total[live] = np.nan
    return total, absum


def np_hyp2f1c(a_, b_, c_, z, zc):
    """2F1(a, b; c; z) in float64, with zc = 1 - z known accurately.

    ``scipy.special.hyp2f1`` is used where it is accurate (z <= 1/2 with
    moderate parameters, or c - a - b >= 1 where the function is C^1 at z = 1
    and the rounding of z costs nothing).  For z <= 1/2 and a parameter
    beyond 10 in modulus (where SciPy loses up to 4 digits) the Maclaurin
    series is summed directly where it does not cancel (sum of |terms| at most
    twice |sum|), else the positive series of the Euler transform
    (1 - z)^(c-a-b) 2F1(c-a, c-b; c; z).  For z > 1/2 the connection formula
    in zc is used (SciPy is fast and accurate at zc <= 1/2); where its two
    terms cancel (c - a - b close to an integer) or it is not finite, the
    point goes to SciPy at z if c - a - b >= 1 (then harmless), else to
    mpmath (25+ digits, with z = 1 - zc formed exactly).
    """
    a_, b_, c_, z, zc = np.broadcast_arrays(*[np.asarray(t, dtype=float) for t in (a_, b_, c_, z, zc)])
    shape = z.shape
    a_, b_, c_, z, zc = [t.ravel() for t in (a_, b_, c_, z, zc)]
    out = np.full(z.shape, np.nan)
    done = np.zeros(z.shape, dtype=bool)
    with np.errstate(all="ignore"):
        d = c_ - a_ - b_
        large = (z >= 0) & (z <= 0.5) & (np.maximum(np.maximum(np.abs(a_), np.abs(b_)), np.abs(c_)) > 10)
        if np.any(large):
            A, B, C, Z, Zc = a_[large], b_[large], c_[large], z[large], zc[large]
            direct, absum = _series(A, B, C, Z)
            vals = np.where(absum <= 2 * np.abs(direct), direct, np.nan)
            eul = np.isnan(vals) & (C - A > 0) & (C - B > 0) & (C > 0)
            if np.any(eul):
                ser, _ = _series((C - A)[eul], (C - B)[eul], C[eul], Z[eul])
                vals[eul] = Zc[eul] ** (C - A - B)[eul] * ser
            out[large] = vals
            done[large] = ~np.isnan(vals)
        # z > 1/2: the connection formula in zc (SciPy evaluates 2F1 at zc <= 1/2,
        # fast and accurate) unless c - a - b is (close to) an integer or the
        # two terms cancel
        near = (z > 0.5) & (zc >= 0)
        if np.any(near):
            A, B, C, Zc, D = a_[near], b_[near], c_[near], zc[near], d[near]
            t1 = sc.gamma(D) * _pair_ratio(C, (C - A, C - B)) * sc.hyp2f1(A, B, 1 - D, Zc)
            t2 = sc.gamma(-D) * _pair_ratio(C, (A, B)) * Zc**D * sc.hyp2f1(C - A, C - B, 1 + D, Zc)
            s_ = t1 + t2
            ok = (np.abs(D - np.round(D)) > 1e-6) & (np.abs(t1) + np.abs(t2) <= 4 * np.abs(s_)) \
                & ~np.isnan(s_)
            # a finite sum from infinite terms is meaningless; an infinite sum from one
            # infinite term (zc = 0, D < 0) is the true singularity
            ok &= np.isfinite(t1) | ~np.isfinite(t2) | np.isinf(s_)
            ok &= ~(np.isinf(t1) & np.isinf(t2))
            idx = np.flatnonzero(near)
            out[idx[ok]] = s_[ok]
            done[idx[ok]] = True
            # c - a - b < 1: the derivative is unbounded at z = 1, so z itself must
            # not be used -> mpmath with 1 - zc formed exactly; else SciPy at z
            hard = idx[~ok & (D < 1)]
            for i in hard:
                out[i] = _mp_point_hyp2f1c(a_[i], b_[i], c_[i], zc[i])
            done[hard] = True
        rest = ~done
        if np.any(rest):
            out[rest] = sc.hyp2f1(a_[rest], b_[rest], c_[rest], z[rest])
    out = out.reshape(shape)
    return out[()] if out.ndim == 0 else out


def _mp_point_hyp2f1c(A, B, C, Zc):
    extra = int(-math.log10(Zc)) + 5 if Zc > 0 else 5
    try:
        with mpmath.workdps(20 + max(extra, 5)):
            zz = 1 - mpmath.mpf(float(Zc))
            return float(mpmath.hyp2f1(float(A), float(B), float(C), zz))
    except (ZeroDivisionError, ValueError, mpmath.libmp.NoConvergence):
        return float("inf")


def _agm_steps(y):
    """AGM steps after which 2^(n-1) c_n^2 / m < 1e-18 for y = 1 - m (the
    slowest-converging point of a chunk: the smallest y)."""
    if not y > 0:
        return 64
    m = 1.0 - y
    if not m > 0:
        return 1
    a_, b_, d, w = 1.0, math.sqrt(y), 1.0, 0.5
    for n in range(1, 64):
        a_, b_ = (a_ + b_) / 2, math.sqrt(a_ * b_)
        d = m * d * d / (16 * a_ * a_) if n > 1 else m / (16 * a_ * a_)
        w *= 2
        if w * d <= 1e-18:
            return n
    return 64


def _np_agm_kd(y, chunk=32768):
    """Vectorised (K, S) for m = 1 - y, see :func:`_mp_agm_kd`; processed in
    cache-sized chunks with in-place operations, the number of steps fixed per
    chunk by its largest m (no convergence test inside the loop)."""
    y = np.asarray(y, dtype=float)
    shape = y.shape
    yf = y.ravel()
    K = np.empty_like(yf)
    S = np.empty_like(yf)
    with np.errstate(all="ignore"):
        for lo in range(0, yf.size, chunk):
            yy = yf[lo:lo + chunk]
            m16 = (1.0 - yy) * 0.0625
            pos = yy[yy > 0]
            steps = _agm_steps(float(np.min(pos))) if pos.size else 1
            a_ = np.ones_like(yy)
            b_ = np.sqrt(yy)
            s_ = np.full_like(yy, 0.5)
            d = np.ones_like(yy)
            t = np.empty_like(yy)
            w = 0.5
            for _ in range(steps + 1):
                np.multiply(a_, b_, out=t)
                np.add(a_, b_, out=a_)
                a_ *= 0.5
                np.sqrt(t, out=b_)
                # d_(n+1) = m d_n^2 / (16 a_(n+1)^2) = (m/16) (d_n / a_(n+1))^2, d_0 = 1
                d /= a_
                d *= d
                d *= m16
                w *= 2
                np.multiply(d, w, out=t)
                s_ += t
            np.add(a_, b_, out=t)
            t[yy == 0] = 0.0              # m = 1: K = R_D = infinite
            K[lo:lo + chunk] = np.pi / t
            S[lo:lo + chunk] = s_
    return K.reshape(shape), S.reshape(shape)


def _carlson_special(x, y, z):
    """True if R(x, y, z) is the complete case R(0, y, 1), 0 <= y <= 1."""
    return np.all(np.asarray(x) == 0) and np.all(np.asarray(z) == 1)


def np_rf(x, y, z):
    """Carlson R_F; the complete case R_F(0, y, 1) = K(1 - y) by the AGM."""
    if _carlson_special(x, y, z):
        return _np_agm_kd(y)[0]
    return sc.elliprf(x, y, z)


def np_rd(x, y, z):
    """Carlson R_D; the complete case R_D(0, y, 1) = 3 (K - E)/m by the AGM,
    as 3 K sum_n 2^(n-1) c_n^2/m: positive terms, no cancellation at small m,
    about 3x faster than ``scipy.special.elliprd``."""
    if _carlson_special(x, y, z):
        K, S = _np_agm_kd(y)
        return 3 * K * S
    return sc.elliprd(x, y, z)


def np_rg(x, y, z):
    return sc.elliprg(x, y, z)


NUMPY_FUNCS = {"carlson_rf": np_rf, "carlson_rd": np_rd, "carlson_rg": np_rg, "gamma_ratio": np_gamma_ratio,
               "hyp2f1c": np_hyp2f1c}
MPMATH_FUNCS = {"carlson_rf": _mp_rf, "carlson_rd": _mp_rd, "carlson_rg": _mp_rg, "gamma_ratio": _mp_gamma_ratio,
                "hyp2f1c": _mp_hyp2f1c}


# ====================================================================== rules
def _is_rational_in_symbols(e) -> bool:
    return bool(e.free_symbols) and not e.has(sp.Function) and e.is_rational_function(*e.free_symbols)


def _complement(w):
    """1 - w simplified symbolically (factored), or None if not a rational function."""
    c = sp.factor(sp.cancel(sp.expand(1 - w)))
    return c


def _one_minus_square(w):
    """sqrt(1 - w**2) in a simplified (stable) form, or None."""
    c = sp.cancel(sp.expand(1 - w**2))
    if not _is_rational_in_symbols(c) and not c.is_number:
        return None
    return sp.sqrt(_fix_signs(sp.factor(c)))


def _square_minus_one(u):
    c = sp.cancel(sp.expand(u**2 - 1))
    if not _is_rational_in_symbols(c) and not c.is_number:
        return None
    return sp.sqrt(_fix_signs(sp.factor(c)))


def _fix_signs(e):
    """-(x - a)*(x + a) -> (a - x)*(a + x): absorb a leading -1 into the linear
    factor that has a negative term (so differences read 'large - small')."""
    num, den = sp.fraction(e)
    if num.is_Mul and num.args[0] == -1:
        rest = list(num.args[1:])
        adds = [i for i, f in enumerate(rest) if f.is_Add]
        if adds:
            neg = [i for i in adds if any(t.could_extract_minus_sign() for t in rest[i].args)]
            i = (neg or adds)[0]
            rest[i] = sp.Add(*[-t for t in rest[i].args])
            num = sp.Mul(*rest)
    return num / den


def _rule_factor(expr):
    """Factor rational sums (differences of squares etc.)."""
    def want(e):
        if not e.is_Add or not _is_rational_in_symbols(e):
            return False
        return True

    def do(e):
        f = _fix_signs(sp.factor(e))
        num, _ = sp.fraction(f)
        if num.is_Mul and sum(1 for t in num.args if t.is_Add or (t.is_Pow and t.base.is_Add)) >= 1 \
                and f != e:
            return f
        if num.is_Pow and num.base.is_Add:
            return f
        return e
    return expr.replace(want, do)


def _rule_atanh(expr):
    def do(e):
        w = e.args[0]
        s = _one_minus_square(w)
        return sp.asinh(w / s) if s is not None else e
    return expr.replace(lambda e: isinstance(e, sp.atanh), do)


def _rule_acosh(expr):
    def do(e):
        u = e.args[0]
        s = _square_minus_one(u)
        return sp.asinh(s) if s is not None else e
    return expr.replace(lambda e: isinstance(e, sp.acosh), do)


def _rule_acos(expr):
    def do(e):
        w = e.args[0]
        s = _one_minus_square(w)
        if s is None or not w.is_positive:
            return e
        return sp.atan(s / w)
    return expr.replace(lambda e: isinstance(e, sp.acos), do)


def _n_terms(e):
    return sum(len(n.args) for n in sp.preorder_traversal(e) if n.is_Add)


def _expand_around(expr, keys):
    """expand_mul only the sums on the paths to ``keys``: every other sum,
    function application and fractional power is masked first, so factored
    forms elsewhere ((a - x)*(a + x), sqrt(a - x) ...) are kept."""
    masks = {}

    def mask(e):
        if e.has(*keys):
            if e.args and not e.is_Atom:
                e = e.func(*[mask(t) for t in e.args])
            return e
        if e.is_Atom or e.is_Number:
            return e
        if e.is_Add or isinstance(e, (sp.Function, sp.Piecewise)) or (e.is_Pow and not e.exp.is_Integer):
            d = sp.Dummy("m")
            masks[d] = e
            return d
        return e.func(*[mask(t) for t in e.args])
    return sp.expand_mul(mask(expr)).xreplace(masks)


def _rule_asin(expr):
    """asin(w) -> atan(w/sqrt(1-w^2)); or pi/2 - atan(sqrt(1-w^2)/w) if the pi/2
    cancels after expanding (e.g. pi*x - 2*x*asin(a/x)): the expanded
    complement form then has fewer terms than the expanded plain form."""
    if not expr.has(sp.asin):
        return expr
    reps, keys, pkeys = {}, {}, {}
    for e in expr.atoms(sp.asin):
        w = e.args[0]
        s_ = _one_minus_square(w)
        if s_ is None or not w.is_positive:
            continue
        k, pk = sp.Dummy("A"), sp.Dummy("P")
        keys[k] = sp.atan(s_ / w)
        pkeys[e] = pk
        reps[e] = (sp.atan(w / s_), sp.pi / 2 - k)
    if not reps:
        return expr
    plain = expr.xreplace({e: p for e, (p, c) in reps.items()})
    comp_x = _expand_around(expr.xreplace({e: c for e, (p, c) in reps.items()}), list(keys))
    plain_x = _expand_around(expr.xreplace(pkeys), list(pkeys.values()))
    if _n_terms(comp_x) <= _n_terms(plain_x):
        return comp_x.xreplace(keys)
    return plain


def _rule_elliptic(expr):
    """alpha*K(m) + beta*E(m) -> Carlson forms with the complementary parameter
    m' = 1 - m simplified: alpha + beta = 0 gives alpha*(m/3)*R_D(0, m', 1) (no
    cancellation as m -> 0), beta = 0 gives alpha*R_F(0, m', 1), alpha = 0 gives
    2*beta*R_G(0, m', 1) (no cancellation as m -> 1), otherwise
    (alpha + beta)*R_F - beta*(m/3)*R_D."""
    ells = [e for e in expr.atoms(sp.elliptic_k, sp.elliptic_e) if len(e.args) == 1]
    if not ells:
        return expr
    args = sorted({e.args[0] for e in ells}, key=sp.default_sort_key)
    subs, info = {}, {}
    for i, m in enumerate(args):
        mc = _fix_signs(sp.factor(sp.cancel(1 - m)))
        Kd, Ed = sp.Dummy(f"K{i}"), sp.Dummy(f"E{i}")
        subs[sp.elliptic_k(m)] = Kd
        subs[sp.elliptic_e(m)] = Ed
        info[(Kd, Ed)] = (m, mc)
    e2 = expr.xreplace(subs)
    marks = [d for pair in info for d in pair]

    def simp(cf):
        return sp.factor(sp.cancel(cf)) if cf != 0 else sp.S.Zero

    def combine(e):
        ex = sp.expand(e)
        parts = sp.collect(ex, marks, evaluate=False)
        out = parts.pop(sp.S.One, sp.S.Zero)
        for (Kd, Ed), (m, mc) in info.items():
            al = simp(parts.pop(Kd, sp.S.Zero))
            be = simp(parts.pop(Ed, sp.S.Zero))
            if al == 0 and be == 0:
                continue
            rf, rd, rg = carlson_rf(0, mc, 1), carlson_rd(0, mc, 1), carlson_rg(0, mc, 1)
            s_ = simp(al + be)
            if s_ == 0:
                out += al * m / 3 * rd
            elif be == 0:
                out += al * rf
            elif al == 0:
                out += 2 * be * rg
            else:
                out += s_ * rf - be * m / 3 * rd
        for k, cf in parts.items():   # anything else (should not occur)
            out += cf * k
        return out
    def walk(e):  # top-down: combine at the outermost sum holding K or E
        if not e.has(*marks) or e.is_Atom:
            return e
        if e.is_Add:
            return combine(e)
        return e.func(*[walk(t) for t in e.args])
    e3 = walk(e2)
    if e3.has(*marks):
        e3 = combine(e3)
    return e3.xreplace(
        {Kd: carlson_rf(0, mc, 1) for (Kd, Ed), (m, mc) in info.items()}).xreplace(
        {Ed: 2 * carlson_rg(0, mc, 1) for (Kd, Ed), (m, mc) in info.items()})


def _rule_gamma_absorb(expr):
    """(k*g) * Gamma(g) -> k * Gamma(g + 1) inside products (removes 0*inf)."""
    def want(e):
        return e.is_Mul and e.has(sp.gamma)

    def do(e):
        factors = list(e.args)
        changed = True
        while changed:
            changed = False
            for i, f in enumerate(factors):
                if not (isinstance(f, sp.gamma)):
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
    return expr.replace(want, do)


def _rule_gamma_ratio(expr):
    """Gamma(u)/Gamma(v) with u - v a number -> gamma_ratio(u, v)."""
    def want(e):
        return e.is_Mul and e.has(sp.gamma)

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
    return expr.replace(want, do)


def _nonneg(e):
    """Positive, or a square root (times positive factors): >= 0 wherever real."""
    if e.is_positive:
        return True
    if e.is_Pow and e.exp == sp.S.Half:
        return True
    return bool(e.is_Mul and all(_nonneg(f) for f in e.args))


def _has_sqrt(e):
    return any(p.is_Pow and p.exp == sp.S.Half for p in sp.preorder_traversal(e))


def _rule_conjugate(expr):
    """u - v with u, v >= 0 (one a square root) and u**2 - v**2 simpler than
    u**2 + v**2 -> (u**2 - v**2)/(u + v): R - sqrt(R**2 - x**2) becomes
    x**2/(R + sqrt(R**2 - x**2)), exact where the difference cancels.  Any
    pair of terms of a sum is tried."""
    def want(e):
        return e.is_Add and any(_has_sqrt(t) for t in e.args)

    def pair(u, mv):
        v = -mv
        if not (_nonneg(u) and _nonneg(v)) or not (_has_sqrt(u) or _has_sqrt(v)):
            return None
        num = sp.expand(u**2 - v**2)
        if _has_sqrt(num) or num == 0:
            return None
        if sp.count_ops(num) < sp.count_ops(sp.expand(u**2)) + sp.count_ops(sp.expand(v**2)):
            return _fix_signs(sp.factor(num)) / (u + v)
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


def _rule_hyp2f1_connection(expr):
    """2F1(p, q; r; z) -> its connection formula about z = 1 (in 1 - z
    simplified), when r - p - q is a non-integer number and the result, after
    hyperexpand/gammasimp, cancels terms of the surrounding sum (e.g. the
    profile term c*x**n of a power-law gap against the a**n*(x/a)**n part of
    2F1(1/2, n/2; n/2 + 1; a**2/x**2)): the cancellation is then done exactly."""
    hs = [h for h in expr.atoms(sp.hyper) if len(h.ap) == 2 and len(h.bq) == 1 and h.argument.free_symbols]
    if not hs:
        return expr
    reps = {}
    for h in hs:
        p, q = h.ap
        r, = h.bq
        d = sp.simplify(r - p - q)
        if not d.is_number or d.is_integer:
            continue
        z = h.argument
        zc = _fix_signs(sp.factor(sp.cancel(1 - z)))
        t1 = sp.gamma(r) * sp.gamma(d) / (sp.gamma(r - p) * sp.gamma(r - q)) \
            * sp.hyperexpand(sp.hyper([p, q], [1 - d], zc))
        t2 = zc**d * sp.gamma(r) * sp.gamma(-d) / (sp.gamma(p) * sp.gamma(q)) \
            * sp.hyperexpand(sp.hyper([r - p, r - q], [1 + d], zc))
        reps[h] = t1 + t2
    if not reps:
        return expr
    cand = sp.expand(sp.powdenest(sp.gammasimp(expr.xreplace(reps)), force=True))
    before = sp.expand(expr)
    if len(sp.Add.make_args(cand)) < len(sp.Add.make_args(before)):
        return cand
    return expr


def _rule_hyp2f1(expr):
    def want(e):
        return isinstance(e, sp.hyper) and len(e.ap) == 2 and len(e.bq) == 1 and e.argument.free_symbols

    def do(e):
        z = e.argument
        zc = _fix_signs(sp.factor(sp.cancel(1 - z)))
        return hyp2f1c(e.ap[0], e.ap[1], e.bq[0], z, zc)
    return expr.replace(want, do)


RULES = (
    ("elliptic->carlson", _rule_elliptic),
    ("hyp2f1-connection", _rule_hyp2f1_connection),
    ("gamma-absorb", _rule_gamma_absorb),
    ("gamma-ratio", _rule_gamma_ratio),
    ("atanh->asinh", _rule_atanh),
    ("acosh->asinh", _rule_acosh),
    ("asin->atan", _rule_asin),
    ("acos->atan", _rule_acos),
    ("hyp2f1-complement", _rule_hyp2f1),
    ("conjugate", _rule_conjugate),
    ("factor", _rule_factor),
)


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


def _sample_point(syms, conditions, rng, tries=200):
    for _ in range(tries):
        vals = {s: sp.Rational(rng.randint(5, 300), 100) for s in syms}
        ok = True
        for c in conditions:
            try:
                if not bool(c.xreplace(vals)):
                    ok = False
                    break
            except TypeError:
                ok = False
                break
        if ok:
            return vals
    return None


def _mp_value(expr, vals, dps=30):
    with mpmath.workdps(dps):
        v = sp.N(expr.xreplace(vals), dps)
        v = complex(v) if not v.is_real else v
        if isinstance(v, complex):
            return mpmath.mpc(v.real, v.imag)
        return mpmath.mpf(str(v)) if v.is_Float else mpmath.mpf(sp.N(v, dps))


def _agree(e1, e2, syms, conditions, n=3, seed=11) -> tuple[bool, str]:
    """Do e1 and e2 agree to 20 digits at n random points where conditions hold?"""
    if e1.has(sp.Integral) or e2.has(sp.Integral):
        e1 = e1.replace(lambda e: isinstance(e, sp.Integral), lambda e: e.function)
        e2 = e2.replace(lambda e: isinstance(e, sp.Integral), lambda e: e.function)
        syms = sorted(e1.free_symbols | e2.free_symbols, key=lambda s: s.name)
        conditions = ()
    rng = random.Random(seed)
    checked = 0
    for _ in range(n * 4):
        vals = _sample_point(syms, conditions, rng)
        if vals is None:
            break
        try:
            v1 = _mp_value(e1, vals)
        except (TypeError, ValueError, ZeroDivisionError):
            continue
        if isinstance(v1, mpmath.mpc) or not mpmath.isfinite(v1):
            continue  # outside the real domain of the original
        try:
            v2 = _mp_value(e2, vals)
        except (TypeError, ValueError, ZeroDivisionError) as exc:
            return False, f"rewritten form fails at {vals}: {exc}"
        if abs(v1 - v2) > mpmath.mpf(10)**-20 * max(abs(v1), mpmath.mpf(10)**-10):
            return False, f"values differ at {vals}: {v1} vs {v2}"
        checked += 1
        if checked >= n:
            break
    if checked == 0:
        return True, "not checked (no admissible sample point)"
    return True, f"checked at {checked} points"


def _apply_masked(rule, expr):
    """Apply ``rule`` to the integrands of unevaluated Integrals and, separately,
    to the expression around them (a rule must never move a factor that depends
    on the integration variable across the integral sign)."""
    if not expr.has(sp.Integral):
        return rule(expr)
    ints = {}

    def mask(I):
        d = sp.Dummy("Int")
        ints[d] = sp.Integral(_apply_masked(rule, I.function), *I.limits)
        return d
    masked = expr.replace(lambda e: isinstance(e, sp.Integral), mask)
    return rule(masked).xreplace(ints)


def stabilize(expr: sp.Expr, conditions=(), check: bool = True) -> StableForm:
    """The stable form of ``expr`` (see the module docstring for the rules).

    ``conditions`` (SymPy relations, e.g. ``x < a``) restrict the random
    points at which each rewrite is checked against the original."""
    syms = sorted(expr.free_symbols, key=lambda s: s.name)
    conds = tuple(c for c in conditions if isinstance(c, sp.Basic) and c not in (sp.true,))
    form = StableForm(expr, expr)
    cur = expr
    for name, rule in RULES:
        try:
            new = _apply_masked(rule, cur)
        except Exception as exc:  # a SymPy failure inside a rule: skip the rule
            form.rejected.append((name, f"{type(exc).__name__}: {exc}"))
            continue
        if new == cur:
            continue
        if check:
            ok, why = _agree(cur, new, syms, conds)
            if not ok:
                form.rejected.append((name, why))
                continue
        form.rewrites.append((name, _describe(cur, new)))
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


# ====================================================================== accuracy audit
#: The documented grid of extreme arguments (dimensionless ratios).  Used by
#: ``tests/test_extremes.py`` and ``benchmarks/bench.py``.
EXTREME_GRID = {
    # a/R (cylinders, parabola): from 1e-12 to 1 - 1e-12
    "a_over_R": [1e-12, 1e-8, 1e-4, 1e-2, 0.1, 0.5, 0.9, 0.99, 1 - 1e-4, 1 - 1e-8, 1 - 1e-12],
    # x/a inside the contact (pressure), edge included
    "x_in": [0.0, 1e-12, 1e-8, 1e-4, 0.1, 0.5, 0.9, 0.999, 1 - 1e-8, 1 - 1e-12, 1.0],
    # x/a outside the contact (gap), edge included
    "x_out": [1.0, 1 + 1e-12, 1 + 1e-8, 1 + 1e-4, 1.01, 1.5, 3.0, 10.0, 1e3, 1e6],
    # power-law exponent n, with exactly 1 and 1 +- 1e-9
    "n": [1e-3, 0.01, 0.1, 0.5, 1 - 1e-9, 1.0, 1 + 1e-9, 1.5, 2.0, 2.5, 3.0, 5.0, 10.0, 33.3,
          100.0, 333.0, 1000.0],
    # b/a (worn cylinder flat half-width over contact half-width)
    "b_over_a": [1e-12, 1e-6, 0.1, 0.5, 0.9, 1 - 1e-6, 1 - 1e-12, 1.0, 1.5],
    # absolute scales the ratios are applied at
    "a": [1e-3, 1.0, 7.5],
}

EPS = float(np.finfo(float).eps)


@dataclass
class AccuracyRecord:
    point: dict
    value: float            # float64 export
    reference: object       # mpf
    rel_error: float
    kappa: float            # componentwise relative condition number
    ulps: float             # rel_error / (eps * max(1, kappa))

    def __str__(self):
        pt = ", ".join(f"{k}={v:.17g}" for k, v in self.point.items())
        return (f"[{pt}] float64={self.value!r} ref={mpmath.nstr(self.reference, 17)} "
                f"rel.err={self.rel_error:.2e} kappa={self.kappa:.2e} -> {self.ulps:.2f} eps*kappa")


def condition_number(fmp, point: dict, dps: int = 100):
    """sum_i |x_i df/dx_i| / |f| at ``point`` (central differences at ``dps``
    digits, one-sided at a domain edge); NaN if f = 0."""
    with mpmath.workdps(dps):
        base = {k: mpmath.mpf(v) for k, v in point.items()}
        f0 = fmp(**base)
        if f0 == 0 or not mpmath.isfinite(f0):
            return float("nan")
        total = mpmath.mpf(0)
        h = mpmath.mpf(10) ** (-(dps // 3))
        for k, v in base.items():
            if v == 0:
                continue
            vals = []
            for sgn in (1, -1):
                try:
                    fv = fmp(**{**base, k: v * (1 + sgn * h)})
                    vals.append(fv if (not isinstance(fv, mpmath.mpc) and mpmath.isfinite(fv)) else None)
                except (ValueError, ZeroDivisionError, TypeError):
                    vals.append(None)
            if vals[0] is not None and vals[1] is not None:
                d = (vals[0] - vals[1]) / (2 * h)
            elif vals[0] is not None:
                d = (vals[0] - f0) / h
            elif vals[1] is not None:
                d = (f0 - vals[1]) / h
            else:
                continue
            total += abs(d)
        return float(total / abs(f0))


def condition_number_float(f64, point: dict, h: float = 1e-6):
    """The componentwise relative condition number estimated by float64
    central differences of ``f64`` itself (for quantities whose reference is
    too slow to differentiate at high precision)."""
    with np.errstate(all="ignore"):
        f0 = float(np.asarray(f64(**point)))
        if f0 == 0 or not math.isfinite(f0):
            return float("nan")
        total = 0.0
        for k, v in point.items():
            if v == 0:
                continue
            vals = []
            for sgn in (1, -1):
                fv = float(np.asarray(f64(**{**point, k: v * (1 + sgn * h)})))
                vals.append(fv if math.isfinite(fv) else None)
            if vals[0] is not None and vals[1] is not None:
                d = (vals[0] - vals[1]) / (2 * h)
            elif vals[0] is not None:
                d = (vals[0] - f0) / h
            elif vals[1] is not None:
                d = (f0 - vals[1]) / h
            else:
                continue
            total += abs(d)
        return total / abs(f0)


def _real_or_none(r, dps):
    if isinstance(r, mpmath.mpc):
        if abs(r.imag) <= abs(r.real) * mpmath.mpf(10) ** (-dps // 2):
            return r.real
        return None
    if not mpmath.isfinite(r):
        return None
    return r


def _reference(fmp, pt, dps):
    """(value, singular) of fmp at pt.  Where the formula is singular
    (removable: 0*inf, 0/0 ...) the limit approached from a point displaced by
    10^-(dps/2) in one argument (singular=True); NaN outside the real domain."""
    with mpmath.workdps(dps):
        args = {k: mpmath.mpf(x) for k, x in pt.items()}
        try:
            r0 = fmp(**args)
            r = _real_or_none(r0, dps)
            if r is None and isinstance(r0, mpmath.mpc) and mpmath.isfinite(r0):
                return mpmath.nan, False          # complex: outside the domain
        except (ZeroDivisionError, ValueError):
            r = None
        if r is not None:
            return r, False
        h = mpmath.mpf(10) ** (-(dps // 2))
        for k, x in args.items():
            for cand in ((x * (1 + h), x * (1 - h)) if x != 0 else (h,)):
                try:
                    r = _real_or_none(fmp(**{**args, k: cand}), dps)
                except (ZeroDivisionError, ValueError):
                    r = None
                if r is not None:
                    return r, True
        return mpmath.inf, True


def audit(f64, fmp, points, dps: int = 100, kappa: str = "mp", kappa_dps: int = 40):
    """Compare a float64 function with an mpmath reference at ``points``
    (dicts name -> float).  Returns the list of :class:`AccuracyRecord`.

    ``kappa``: 'mp' (condition number by differences of the reference at
    ``kappa_dps`` digits -- it only scales the tolerance),
    'float' (by float64 differences of ``f64``), or None (taken as 1).
    Where the reference formula is singular the limit is used (approached
    from a displaced point); a float64 value of +-inf passes where that
    limit is infinite or beyond the float64 range, and a zero reference (or a
    limit below 1e-30) requires |value| < 1e-290; an exact float64 zero
    passes against a reference below 10^-(dps/2) (noise of a formula that
    cancels to zero, e.g. a gap at x = a)."""
    out = []
    for pt in points:
        with np.errstate(all="ignore"):
            v = float(np.asarray(f64(**pt)))
        r, singular = _reference(fmp, pt, dps)
        if mpmath.isnan(r):
            continue                               # outside the real domain: not audited
        if singular and math.isinf(v):
            out.append(AccuracyRecord(pt, v, r, 0.0, 1.0, 0.0))
            continue
        if mpmath.isinf(r) or abs(r) > 1e300:
            ok = math.isinf(v) or abs(v) > 1e300
            out.append(AccuracyRecord(pt, v, r, 0.0 if ok else math.inf, 1.0, 0.0 if ok else math.inf))
            continue
        if r == 0 or abs(r) < 1e-300 or (singular and abs(r) < 1e-30) or \
                (v == 0 and abs(r) < mpmath.mpf(10) ** (-(dps // 2))):
            # a zero (the last case: an exact float64 zero where the reference
            # is rounding noise of a cancelling formula, e.g. a gap at x = a)
            ok = abs(v) < 1e-290
            out.append(AccuracyRecord(pt, v, r, 0.0 if ok else math.inf, 1.0, 0.0 if ok else math.inf))
            continue
        rel = float(abs((mpmath.mpf(v) - r) / r)) if math.isfinite(v) else math.inf
        if kappa == "mp" and not singular:
            k = condition_number(fmp, pt, kappa_dps)
        elif kappa in ("mp", "float"):
            k = condition_number_float(f64, pt)
        else:
            k = 1.0
        k = 1.0 if not math.isfinite(k) else k
        out.append(AccuracyRecord(pt, v, r, rel, k, rel / (EPS * max(1.0, k))))
    return out


def extreme_points(names, quantity: str, size: str = "full"):
    """Points of :data:`EXTREME_GRID` for a quantity with arguments ``names``
    (symbol names).  Ratios are applied to the half-width ``a``: R = a/(a/R),
    b = (b/a) a, x = (x/a) a.  Other parameters get one generic value
    (E_star = 2, c = 1.3, theta = 0.3).  ``size='small'`` thins the grid (for
    quantities that only have a quadrature)."""
    G = EXTREME_GRID
    thin = (lambda L, k: L[::k] if size == "small" else L)
    lists = {}
    lists["a"] = G["a"][1:] if quantity != "force" else G["a"]
    if size == "small":
        lists["a"] = [1.0]
    if "R" in names:
        lists["a/R"] = G["a_over_R"] if quantity == "force" else [1e-8, 0.5, 1 - 1e-8]
        if size == "small":
            lists["a/R"] = [1e-4, 0.5, 0.99]
    if "b" in names:
        lists["b/a"] = G["b_over_a"] if size != "small" else [1e-6, 0.5, 1 - 1e-6, 1.5]
    if "n" in names:
        lists["n"] = G["n"] if quantity == "force" else [n for n in G["n"] if n not in (0.01, 2.5, 33.3)]
    if "x" in names:
        lists["x/a"] = thin(G["x_in"] if quantity == "pressure" else G["x_out"], 2)
    if quantity != "force" and "R" not in names and "b" not in names:
        lists["a"] = [1.0]
    keys = list(lists)
    pts = []
    for combo in itertools.product(*[lists[k] for k in keys]):
        d = dict(zip(keys, combo))
        a_ = d["a"]
        pt = {"a": a_}
        if "a/R" in d:
            pt["R"] = a_ / d["a/R"]
        if "b/a" in d:
            pt["b"] = d["b/a"] * a_
        if "n" in d:
            pt["n"] = d["n"]
        if "x/a" in d:
            pt["x"] = d["x/a"] * a_
        for nm, val in (("E_star", 2.0), ("c", 1.3), ("theta", 0.3)):
            if nm in names:
                pt[nm] = val
        pts.append({k: pt[k] for k in names if k in pt})
    return pts
