"""Stable special functions: the primitives the stable rewrites produce.

Each is a SymPy function (so a rewritten expression stays a SymPy object, and
``evalf`` works through mpmath) with a vectorised float64 implementation
(:data:`NUMPY_FUNCS`, used by :func:`~linecontact_sym.numeric.exports.lambdify_numpy`)
and an mpmath one (:data:`MPMATH_FUNCS`); the Arb translation is in
:mod:`linecontact_sym.numeric.certified`.

``carlson_rf(x, y, z)``, ``carlson_rd(x, y, z)``, ``carlson_rg(x, y, z)``
    Carlson's symmetric elliptic integrals (DLMF 19.16.1, 19.16.5, 19.23.6).
    The complete integrals with x = 0, z = 1, 0 <= y <= 1 give
    K(m) = R_F(0, 1 - m, 1), E(m) = 2 R_G(0, 1 - m, 1) and
    K(m) - E(m) = (m/3) R_D(0, 1 - m, 1) (parameter m = k^2, as SymPy's
    ``elliptic_k(m)`` and mpmath's ``ellipk(m)``).  The complete cases are
    evaluated by the AGM, R_D as 3 K sum 2^(n-1) c_n^2 / m with positive terms
    (no cancellation for small m): in float64 about 5x faster than
    ``scipy.special.elliprd``, in mpmath about 15x faster than ``mpmath.elliprd``.
``carlson_rj(x, y, z, p)``
    Carlson's integral of the third kind (DLMF 19.16.2); with the others it
    gives every incomplete integral: F(phi|m) = s R_F(c^2, d^2, 1),
    E(phi|m) = F - (m/3) s^3 R_D(c^2, d^2, 1),
    Pi(n; phi|m) = F + (n/3) s^3 R_J(c^2, d^2, 1, 1 - n s^2) (DLMF 19.25.5,
    19.25.9, 19.25.14; s = sin(phi), c = cos(phi), d^2 = 1 - m s^2).
    float64: ``scipy.special.elliprj``.
``gamma_ratio(u, v)``
    Gamma(u)/Gamma(v), for u - v moderate; float64 by a Stirling-series
    difference in log1p form for u, v >= 10 (no overflow, no cancellation of
    two large log-gammas).
``hyp2f1c(a, b, c, z, zc)``
    The Gauss function 2F1(a, b; c; z) given also zc = 1 - z formed
    accurately (e.g. symbolically as x**2/a**2 rather than 1 - (1 - x**2/a**2)):
    near z = 1 the evaluation uses zc, the connection formula about z = 1
    in float64, extra digits with z = 1 - zc formed exactly in mpmath.
``exp_tail(n, z)``
    The remainder of the exponential series, exp(z) - sum_{k<n} z^k/k!
    = z^n/n! 1F1(1; n + 1; z) (n = 1: expm1): exact where the
    difference cancels (|z| small: t - tau + tau exp(-t/tau) = tau exp_tail(2, -t/tau)
    for t << tau, the Lee-Radok force histories of a Maxwell term).  float64:
    positive-term series (for z < 0 in Kummer's form e^z 1F1(n; n + 1; -z)),
    the plain difference where it does not cancel (|z| large).

>>> import sympy as sp
>>> sp.N(carlson_rf(0, sp.Rational(1, 2), 1), 20)      # K(1/2)
1.8540746773013719184
>>> r = float(np_gamma_ratio(1001.0, 999.0))           # Gamma(1001)/Gamma(999) = 1000 * 999
>>> abs(r / 999000 - 1) < 1e-15
True
>>> float(np_gamma_ratio(1000.5, 1000.0))              # Gamma(1000.5) alone overflows
31.6188240018159...
"""
from __future__ import annotations

import functools
import math

import mpmath
import numpy as np
import sympy as sp
from ..core.conversion import to_mpf
from ..core.lazy import lazy_module
from ..core.precision import workdps, workprec

sc = lazy_module("scipy.special")     # loaded at the first float64 special function

__all__ = ["carlson_rf", "carlson_rd", "carlson_rg", "carlson_rj", "gamma_ratio", "hyp2f1c", "exp_tail", "asinh_excess",
           "sin_pi_sum", "np_sin_pi_sum", "sin_pi_sum_scalar",
           "np_rf", "np_rd", "np_rg", "np_rj", "np_gamma_ratio", "np_hyp2f1c", "np_exp_tail", "exp_tail_scalar",
           "np_asinh_excess", "mp_elliptic_pi", "NUMPY_FUNCS", "MPMATH_FUNCS"]


class _StableFunction(sp.Function):
    """Base of the stable primitives: evaluates numerically through mpmath."""

    _mp = None

    def _eval_evalf(self, prec):
        dps = max(int(prec * 0.30103) + 1, 15)
        with workdps(dps + 10):
            try:
                args = [to_mpf(a_) for a_ in self.args]     # the one converter, at dps + 10
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


def _mp_rj(x, y, z, p):
    return mpmath.elliprj(x, y, z, p)


def mp_elliptic_pi(*args):
    """mpmath's ellippi, but for the complete integral with n > 1 > m (where
    mpmath integrates numerically, taking seconds to minutes at high
    precision) Pi(n|m) = K(m) - Pi(m/n|m) - i (pi/2) sqrt(n/((n - 1)(n - m)))
    (the principal value, DLMF 19.6.5, and mpmath's imaginary part)."""
    if len(args) == 2:
        n, m = args
        if not isinstance(n, mpmath.mpc) and not isinstance(m, mpmath.mpc) and n > 1 and m < 1:
            pv = mpmath.ellipk(m) - mpmath.ellippi(m / n, m)
            return mpmath.mpc(pv, -mpmath.pi / 2 * mpmath.sqrt(n / ((n - 1) * (n - m))))
    return mpmath.ellippi(*args)


def _mp_gamma_ratio(u, v):
    return mpmath.gammaprod([u], [v])


def _mp_hyp2f1c(a_, b_, c_, z, zc):
    """2F1 at z, using the complement zc = 1 - z where z is close to 1."""
    if z > 0.5 and zc >= 0:
        extra = int(-mpmath.log10(zc)) + 5 if zc > 0 else 5
        with workdps(mpmath.mp.dps + max(extra, 5)):
            zz = 1 - zc
            return +mpmath.hyp2f1(a_, b_, c_, zz)
    return mpmath.hyp2f1(a_, b_, c_, z)


class carlson_rf(_StableFunction):
    """Carlson's symmetric integral of the first kind (DLMF 19.16.1),
    R_F(x, y, z) = 1/2 int_0^oo dt / sqrt((t + x)(t + y)(t + z)),
    x, y, z >= 0 with at most one zero; K(m) = R_F(0, 1 - m, 1)."""
    nargs = 3
    _mp = staticmethod(_mp_rf)


class carlson_rd(_StableFunction):
    """Carlson's integral of the second kind (DLMF 19.16.5),
    R_D(x, y, z) = 3/2 int_0^oo dt / ((t + z) sqrt((t + x)(t + y)(t + z))),
    x, y >= 0 (not both zero), z > 0; K(m) - E(m) = (m/3) R_D(0, 1 - m, 1)."""
    nargs = 3
    _mp = staticmethod(_mp_rd)


class carlson_rg(_StableFunction):
    """Carlson's symmetric integral R_G(x, y, z) (DLMF 19.16.3, 19.23.6),
    x, y, z >= 0; E(m) = 2 R_G(0, 1 - m, 1)."""
    nargs = 3
    _mp = staticmethod(_mp_rg)


class carlson_rj(_StableFunction):
    """Carlson's integral of the third kind (DLMF 19.16.2),
    R_J(x, y, z, p) = 3/2 int_0^oo dt / ((t + p) sqrt((t + x)(t + y)(t + z))),
    x, y, z >= 0 (at most one zero), p > 0;
    Pi(n|m) = R_F(0, 1 - m, 1) + (n/3) R_J(0, 1 - m, 1, 1 - n)."""
    nargs = 4
    _mp = staticmethod(_mp_rj)


def _mp_asinh_excess(w):
    """w sqrt(1 + w^2) - asinh(w) at the working precision: the two terms agree to
    about 2 log2(1/|w|) bits for small w (the difference is 2 w^3/3 - w^5/5 + ...),
    so they are formed with that many bits more."""
    w = mpmath.mpmathify(w)
    extra = 2 * max(0, -int(mpmath.mag(w))) + 10 if w != 0 else 0
    with workprec(mpmath.mp.prec + extra):
        v = w * mpmath.sqrt(1 + w * w) - mpmath.asinh(w)
    return +v


class asinh_excess(_StableFunction):
    """w sqrt(1 + w^2) - asinh(w) = int_0^w 2 s^2/sqrt(1 + s^2) ds (real w), without
    the cancellation of its two terms as w -> 0 (a periodic array's gap near full
    contact, or at its contact edge)."""
    nargs = 1
    _mp = staticmethod(_mp_asinh_excess)


def _mp_sin_pi_sum(L, *terms):
    return mpmath.sin(mpmath.pi * mpmath.fsum(terms) / L)


class sin_pi_sum(_StableFunction):
    """sin(pi (t_1 + ... + t_k)/L), L > 0, the sum reduced modulo L with its
    rounding error carried (float64: :func:`np_sin_pi_sum`): accurate where the
    sum comes near a nonzero multiple of L (a periodic array near full contact:
    sin(pi (a + x)/L) at a + x -> L, cos(pi x/L) = sin(pi (x + L/2)/L) at x -> L/2),
    where sin of the rounded pi (a + x)/L keeps eps pi/|sin| of its size."""
    _mp = staticmethod(_mp_sin_pi_sum)

    def _eval_rewrite_as_sin(self, L, *terms, **kwargs):
        return sp.sin(sp.pi * sp.Add(*terms) / L)

    def fdiff(self, argindex=1):
        L, terms = self.args[0], self.args[1:]
        u = sp.Add(*terms)
        c = sp.cos(sp.pi * u / L) * sp.pi
        if argindex == 1:
            return -c * u / L**2
        return c / L


class gamma_ratio(_StableFunction):
    """Gamma(u)/Gamma(v) without overflow, u, v not poles (u - v moderate for
    the float64 path)."""
    nargs = 2
    _mp = staticmethod(_mp_gamma_ratio)


class hyp2f1c(_StableFunction):
    """2F1(a, b; c; z) (DLMF 15.2.1) given also the accurately computed
    complement zc = 1 - z; real z <= 1 (the principal branch), c not a
    non-positive integer."""
    nargs = 5
    _mp = staticmethod(_mp_hyp2f1c)


def _mp_exp_tail(n, z):
    """exp(z) - sum_{k<n} z^k/k! = z^n/n! 1F1(1; n + 1; z) (mpmath's 1F1 keeps its digits)."""
    n = int(n)
    if z == 0:
        return mpmath.mpf(1) if n == 0 else mpmath.mpf(0)
    return z**n / mpmath.factorial(n) * mpmath.hyp1f1(1, n + 1, z)


class exp_tail(_StableFunction):
    """exp(z) - sum_{k<n} z^k/k!, n >= 0 an integer, z real: the tail of the
    exponential series (n = 0: exp(z); n = 1: expm1(z))."""
    nargs = 2
    _mp = staticmethod(_mp_exp_tail)

    @classmethod
    def eval(cls, n, z):
        if n.is_Integer and n == 0:
            return sp.exp(z)
        if z.is_zero and n.is_Integer and n > 0:
            return sp.S.Zero

    def fdiff(self, argindex=2):
        if argindex != 2:
            raise sp.ArgumentIndexError(self, argindex)
        return exp_tail(self.args[0] - 1, self.args[1])

    def _eval_rewrite_as_exp(self, n, z, **kwargs):
        if not n.is_Integer:
            return None
        return sp.exp(z) - sp.Add(*[z**k / sp.factorial(k) for k in range(int(n))])


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
        with workdps(20 + max(extra, 5)):
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


def np_rj(x, y, z, p):
    """Carlson R_J (``scipy.special.elliprj``)."""
    return sc.elliprj(x, y, z, p)


def np_rg(x, y, z):
    """Carlson R_G (``scipy.special.elliprg``)."""
    return sc.elliprg(x, y, z)


class _BroadcastLogical:
    """``numpy.logical_and`` / ``logical_or`` for lambdified code: SymPy
    prints ``And(c1, c2)`` as ``logical_and.reduce((c1, c2))``, which NumPy
    refuses when one condition is an array and another a scalar (a
    Piecewise in x with a condition on the parameters only); this ``reduce``
    broadcasts."""

    def __init__(self, ufunc):
        self.ufunc = ufunc

    def __call__(self, *args, **kw):
        return self.ufunc(*args, **kw)

    def reduce(self, operands, axis=0, **kw):
        return functools.reduce(self.ufunc, operands)


#: 2 (-1)^k C(2k, k) 4^-k / (2k + 3): w sqrt(1 + w^2) - asinh(w) = w^3 sum_k c_k w^(2k)
_ASINH_EXCESS = [2 * (-1)**k * math.comb(2 * k, k) / 4**k / (2 * k + 3) for k in range(24)]


def np_asinh_excess(w):
    """float64 w sqrt(1 + w^2) - asinh(w): its Taylor series for |w| < 1/4 (24 terms:
    (1/16)^24 below an ulp), the two terms beyond (they cancel by less than 1/16 there)."""
    w = np.asarray(w, dtype=float)
    small = np.abs(w) < 0.25
    w2 = w * w
    ser = np.zeros_like(w)
    ws = np.where(small, w2, 0.0)           # the series only where it is used (no overflow beyond)
    for c in reversed(_ASINH_EXCESS):
        ser = ser * ws + c
    with np.errstate(over="ignore", invalid="ignore"):
        direct = w * np.hypot(1.0, w) - np.arcsinh(w)
    out = np.where(small, w * w2 * ser, direct)
    return out[()] if out.ndim == 0 else out


def _two_sum(p, q):
    """(p + q rounded, its rounding error) (Knuth's TwoSum: exact in float64)."""
    s = p + q
    v = s - p
    return s, (p - (s - v)) + (q - v)


def _sin_pi_sum(L, terms, rnd, sin):
    """sin(pi (t_1 + ... + t_k)/L) on floats or arrays (``rnd``, ``sin``: round and
    sine of the one or the other): the terms summed with their rounding errors
    carried (TwoSum), the nearest multiple k L taken off the leading part (exact by
    Sterbenz's lemma where the sum is near k L, |k| <= 2: k L is exact), the sine of
    the remainder r, |r| <= L/2, with the sign (-1)^k."""
    s = err = 0.0
    for t in terms:
        s, e = _two_sum(s, t)
        err = err + e
    k = rnd((s + err) / L)
    hi, e = _two_sum(s, -k * L)
    return (1 - 2 * (k % 2)) * sin(math.pi * ((hi + (err + e)) / L))


def np_sin_pi_sum(L, *terms):
    """float64 sin(pi (t_1 + ... + t_k)/L) (:func:`_sin_pi_sum`).  Near a multiple
    of L the remainder is as accurate as the terms: sin(pi (a + x)/L) at a + x =
    L - 2e-7 keeps every digit where sin(pi*(a + x)/L) keeps 9."""
    out = np.asarray(_sin_pi_sum(np.asarray(L, dtype=float), [np.asarray(t, dtype=float) for t in terms],
                                 np.round, np.sin), dtype=float)
    return out[()] if out.ndim == 0 else out


def sin_pi_sum_scalar(L, *terms):
    """:func:`np_sin_pi_sum` for Python floats (the scalar path)."""
    return float(_sin_pi_sum(float(L), [float(t) for t in terms], round, math.sin))


def np_exp_tail(n, z):
    """float64 exp(z) - sum_{k<n} z^k/k! (``n`` a scalar integer): where the
    difference cancels (-max(30, 4n) < z < max(40, 2n + 20)) the series
    z^n/n! sum_k c_k of positive terms, c_k = z^k/((n + 1)_k) for z >= 0 and
    (Kummer) e^z n/(n + k) (-z)^k/k! for z < 0; elsewhere the plain
    difference (its terms then do not cancel: e^z dominates, or the
    polynomial does with relative spread 1 + O(n/|z|))."""
    n = int(n)
    z = np.asarray(z, dtype=float)
    if n == 0:
        return np.exp(z)
    with np.errstate(over="ignore", invalid="ignore", under="ignore"):
        poly = np.ones_like(z)
        for k in range(n - 1, 0, -1):       # Horner: sum_{k<n} z^k/k! = 1 + z (1 + z/2 (1 + ... z/(n-1)))
            poly = 1.0 + z / k * poly
        out = np.exp(z) - poly
        lo, hi = -max(30.0, 4.0 * n), max(40.0, 2.0 * n + 20)
        near = (z > lo) & (z < hi) & np.isfinite(z)
        if np.any(near):
            zz = z[near]
            neg = zz < 0
            u = np.abs(zz)
            term = np.ones_like(zz)
            total = np.ones_like(zz)
            for k in range(1, 400):
                # positive terms: z >= 0: u/(n + k); z < 0: (n + k - 1)/(n + k) u/k
                term = term * np.where(neg, (n + k - 1.0) / (n + k) * u / k, u / (n + k))
                total = total + term
                if np.all(term <= 1e-17 * total):
                    break
            lead = u**n / float(math.factorial(n)) * np.where(neg, (-1.0)**n * np.exp(zz), 1.0)
            res = lead * total
            res = np.where(zz == 0, 0.0, res)
            out = np.array(out, dtype=float)
            out[near] = res
    return out[()] if out.ndim == 0 else out


def exp_tail_scalar(n, z) -> float:
    """:func:`np_exp_tail` for one Python float (the scalar float64 path: no
    NumPy overhead per call), the same series and thresholds."""
    n, z = int(n), float(z)
    if n == 0:
        return math.exp(z)
    if not (-max(30.0, 4.0 * n) < z < max(40.0, 2.0 * n + 20)):
        poly = 1.0
        for k in range(n - 1, 0, -1):
            poly = 1.0 + z / k * poly
        try:
            return math.exp(z) - poly
        except OverflowError:
            return math.inf
    if z == 0:
        return 0.0
    u, neg = abs(z), z < 0
    term = total = 1.0
    for k in range(1, 400):
        term *= (n + k - 1.0) / (n + k) * u / k if neg else u / (n + k)
        total += term
        if term <= 1e-17 * total:
            break
    lead = u**n / float(math.factorial(n))
    return lead * total * ((-1.0)**n * math.exp(z) if neg else 1.0)


#: the logical operators of every NumPy lambdify of the package
NUMPY_LOGIC = {"logical_and": _BroadcastLogical(np.logical_and), "logical_or": _BroadcastLogical(np.logical_or)}

NUMPY_FUNCS = {"carlson_rf": np_rf, "carlson_rd": np_rd, "carlson_rg": np_rg, "carlson_rj": np_rj,
               "gamma_ratio": np_gamma_ratio,
               "hyp2f1c": np_hyp2f1c, "exp_tail": np_exp_tail, "asinh_excess": np_asinh_excess,
               "sin_pi_sum": np_sin_pi_sum}
MPMATH_FUNCS = {"carlson_rf": _mp_rf, "carlson_rd": _mp_rd, "carlson_rg": _mp_rg, "carlson_rj": _mp_rj,
                "gamma_ratio": _mp_gamma_ratio,
                "hyp2f1c": _mp_hyp2f1c, "exp_tail": _mp_exp_tail, "asinh_excess": _mp_asinh_excess,
                "sin_pi_sum": _mp_sin_pi_sum}
