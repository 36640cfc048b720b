"""Tanh-sinh quadrature (mpmath) near difficult endpoints: the one toolkit.

Generic helpers, with no knowledge of contacts: every function takes an
mpmath callable and mpf limits (or, for :func:`relational_breakpoints`, a
SymPy expression).

* :func:`quad_substituted` -- int_e^h g(t) dt after t = e + (h - e) u**m: an
  algebraic or logarithmic singularity at the endpoint e is smoothed, so that
  tanh-sinh places nodes as close to e as the substitution makes necessary
  instead of losing the tail below its smallest node.
* :func:`quad0` -- the same with m = 4 on the first of a list of segments
  starting at 0 (the engine's reference quadratures of Eqs. 9, 10*, 12, 3/5).
* :func:`endpoint_exponent` -- the local power alpha of |g(e + h)| ~ h**alpha,
  measured at two tiny distances: alpha <= -1 means the integral diverges.
* :func:`quad_segments` -- tanh-sinh over a list of segments, with a strong
  power singularity (-1 < alpha < -1/2) at either end removed by
  :func:`quad_substituted` with m = ceil(2/(1 + alpha)).
* :class:`EndpointGuard` -- wraps an integrand for evaluation at nodes that
  crowd an endpoint (precision grows there; rounding noise is dropped).
* :func:`quad_dps` -- the working precision that gives ``dps`` good digits.
* :func:`relational_breakpoints` -- where the conditions of a ``Piecewise``
  switch inside an interval (the points to split the interval at).

and the package's one table of float64 rules (NumPy; the vectorised
quadratures of :mod:`linecontact_sym.numeric.quadrature` and of the stress
field, :mod:`linecontact_sym.contacts.stresses.field`, both read it):

* :func:`tanh_sinh_levels` -- nested tanh-sinh node sets on (0, 1).
* :func:`smoothstep_gauss` -- Gauss-Legendre rules after v = 3u^2 - 2u^3.

(The independent check of the pull-off,
:mod:`linecontact_sym.contacts.adhesion.brute_force`, keeps a rule of its own
on purpose: it shares nothing with the method it checks.)

No function here changes mpmath's global precision; callers set it with
``mpmath.workdps``.
"""
from __future__ import annotations

import math

import mpmath
import numpy as np
import sympy as sp

from .conversion import to_mpf
from .precision import extradps, workprec

#: tanh-sinh degree used throughout (mpmath's default is 6)
MAXDEGREE = 10


def quad_substituted(g, e, h, m: int, maxdegree: int = MAXDEGREE):
    """int_e^h g(t) dt computed as int_0^1 g(e + (h - e) u**m) (h - e) m u**(m-1) du.

    Definition: the substitution t = e + (h - e) u**m maps u in [0, 1] onto
    [e, h] (either orientation) and multiplies an integrand ~ |t - e|**alpha
    by u**(m (1 + alpha) - 1), which is smooth enough for tanh-sinh when
    m (1 + alpha) >= 2.  Domain: alpha > -1 at e (the integral converges);
    ``m`` a positive integer.

    >>> with mpmath.workdps(30):
    ...     v = quad_substituted(lambda t: 1 / mpmath.sqrt(t), mpmath.mpf(0), mpmath.mpf(4), 4)
    ...     print(mpmath.nstr(v, 25))
    4.0
    """
    span = h - e
    return mpmath.quad(lambda u: g(e + span * u**m) * span * m * u**(m - 1), [0, 1], maxdegree=maxdegree)


def quad0(f, pts):
    """mpmath tanh-sinh quadrature of ``f`` over the points ``pts`` (pts[0] is
    the singular end, 0 in the engine's uses), with t = pts[0] + (pts[1] -
    pts[0]) u**4 on the first segment: an algebraic or logarithmic endpoint
    singularity there (power laws with n < 1, the wedge) is then integrated to
    full precision instead of losing the tail below the smallest node.

    >>> with mpmath.workdps(30):
    ...     v = quad0(lambda t: mpmath.log(t), [mpmath.mpf(0), mpmath.mpf(1), mpmath.mpf(2)])
    ...     print(mpmath.nstr(v - (2 * mpmath.log(2) - 2), 5))
    0.0
    """
    first = quad_substituted(f, pts[0], pts[1], 4)
    rest = mpmath.quad(f, pts[1:], maxdegree=MAXDEGREE) if len(pts) > 2 else 0
    return first + rest


def quad_dps(dps: int) -> int:
    """Working precision of the quadratures that must deliver ``dps`` digits.

    Tanh-sinh nodes crowd an endpoint closer than the working precision
    resolves, so an integrand with a cancelling factor such as
    sqrt(a**2 - t**2) there is good to about half the working digits; twice
    the target plus a margin keeps >= ``dps`` digits.

    >>> quad_dps(45)
    100
    """
    return 2 * dps + 10


def endpoint_exponent(g, e, direction: int, span):
    """Local power alpha of g at the endpoint e: |g(e + direction h)| ~ h**alpha.

    Measured from two values at h = span 1e-12 and span 1e-24 (so the working
    precision must exceed about 30 digits).  Returns ``math.inf`` when g
    vanishes at both, ``-math.inf`` when only the nearer value overflows or is
    not finite, and None when g cannot be evaluated there.

    >>> with mpmath.workdps(40):
    ...     round(endpoint_exponent(lambda t: t**mpmath.mpf(-0.9), mpmath.mpf(0), 1, mpmath.mpf(1)), 6)
    -0.9
    """
    h1, h2 = span * mpmath.mpf(10) ** -12, span * mpmath.mpf(10) ** -24
    try:
        v1, v2 = abs(g(e + direction * h1)), abs(g(e + direction * h2))
    except (ZeroDivisionError, ValueError, TypeError):
        return None
    if v1 == 0 and v2 == 0:
        return math.inf
    if v1 == 0 or v2 == 0 or not (mpmath.isfinite(v1) and mpmath.isfinite(v2)):
        return None if v2 == 0 else -math.inf
    return float(mpmath.log(v2 / v1) / mpmath.log(h2 / h1))


def quad_segments(g, pts, alphas=(None, None)):
    """Tanh-sinh of g over the segments pts[0] < pts[1] < ... < pts[-1].

    ``alphas`` are the local powers of g at pts[0] and pts[-1] (see
    :func:`endpoint_exponent`; None if unknown).  A strong power singularity
    |t - e|**alpha with -1 < alpha < -1/2 at an end is first smoothed by
    :func:`quad_substituted` with m = ceil(2/(1 + alpha)) on the half of its
    segment next to it: tanh-sinh alone cannot place nodes closer to the end
    than the working precision, and the missing piece of such an integrand is
    of the order of that distance**(1 + alpha).

    >>> with mpmath.workdps(40):
    ...     v = quad_segments(lambda t: t**(-mpmath.mpf(9) / 10), [mpmath.mpf(0), mpmath.mpf(1)], (-0.9, 0.0))
    ...     print(mpmath.nstr(v, 30))
    10.0
    """
    total = mpmath.mpf(0)
    segs = list(zip(pts[:-1], pts[1:]))
    for i, (lo, hi) in enumerate(segs):
        a_lo = alphas[0] if i == 0 else None
        a_hi = alphas[1] if i == len(segs) - 1 else None
        if a_lo is not None and -1 < a_lo < -0.5:
            m = min(int(math.ceil(2 / (1 + a_lo))), 2000)
            mid = (lo + hi) / 2
            total += quad_substituted(g, lo, mid, m)
            lo = mid
        if a_hi is not None and -1 < a_hi < -0.5:
            m = min(int(math.ceil(2 / (1 + a_hi))), 2000)
            mid = (lo + hi) / 2
            total -= quad_substituted(g, hi, mid, m)
            hi = mid
        total += mpmath.quad(g, [lo, hi], maxdegree=MAXDEGREE)
    return total


def quad_piece(f, a, b, gauss: bool = True):
    """int_a^b f at the working precision for an integrand that is usually
    analytic on the closed piece [a, b] (a quadrature law's pieces between
    breakpoints, :class:`~linecontact_sym.contacts.normal.force_law.ForceLaw`):
    Gauss-Legendre first, up to about one node per working digit, and
    mpmath's tanh-sinh (its own degrees) where Gauss-Legendre's error
    estimate does not reach the working precision (an end-point singularity,
    a pole just beyond an end).  Both stop, as mpmath.quad does, when
    mpmath's error estimate (the same extrapolation for both rules) is below
    eps/8 -- here relative to max(1, |integral|): a large integral (1e11 near
    the end of a law's domain) otherwise never meets an absolute eps at the
    working precision and runs every degree.  An analytic piece takes 9-45
    integrand values at 20 digits instead of tanh-sinh's 57-115.

    Returns ``(value, by_gauss)``: whether Gauss-Legendre converged (a caller
    that integrates the same piece again may pass ``gauss=False`` where it
    did not: tanh-sinh at once).

    >>> with mpmath.workdps(30):
    ...     v, by_gauss = quad_piece(mpmath.exp, mpmath.mpf(0), mpmath.mpf(1))
    ...     print(abs(v - (mpmath.e - 1)) < 1e-29, by_gauss)
    True True
    >>> with mpmath.workdps(30):    # sqrt at an end: Gauss-Legendre's estimate fails, tanh-sinh does it
    ...     v, by_gauss = quad_piece(mpmath.sqrt, mpmath.mpf(0), mpmath.mpf(1))
    ...     print(abs(v - mpmath.mpf(2) / 3) < 1e-29, by_gauss)
    True False
    """
    ctx = mpmath.mp
    prec = ctx.prec
    if gauss:
        top = max(2, math.ceil(math.log2(max(ctx.dps, 3) / 3)) + 1)   # 3 * 2**(m - 1) >= dps nodes
        value, done = _summation(ctx._gauss_legendre, f, a, b, prec, top)
        if done:
            return value, True
    return _summation(ctx._tanh_sinh, f, a, b, prec, ctx._tanh_sinh.guess_degree(prec))[0], False


def _summation(rule, f, a, b, prec, top):
    """(value, converged): mpmath's summation of one interval by ``rule`` at
    degrees 1 .. ``top`` (QuadratureRule.summation), stopping at an error
    estimate below eps/8 times max(1, |value|)."""
    ctx = mpmath.mp
    eps = ctx.eps / 8
    results = []
    with workprec(prec + 20):
        for degree in range(1, top + 1):
            nodes = rule.get_nodes(a, b, degree, prec)
            results.append(rule.sum_next(f, nodes, degree, prec, results))
            if degree > 1 and rule.estimate_error(results, prec, eps) <= eps * max(1, abs(results[-1])):
                return +results[-1], True
    return +results[-1], False


def _decades_below(r) -> int:
    """int(-log10(r)) for 0 < r < 1, the logarithm taken at 53 bits (the
    working precision's logarithm costs a fifth of a quadrature near the
    ends); recomputed at the working precision in the rare case that the
    53-bit value lies within 1e-9 of an integer, so the result is exact."""
    with workprec(53):
        v = float(-mpmath.log10(r))
    k = int(v)
    if min(v - k, k + 1 - v) < 1e-9:
        return int(-mpmath.log10(r))
    return k


class EndpointGuard:
    """An integrand g on [lo, hi] wrapped for tanh-sinh nodes near the ends.

    * Precision grows with the closeness of a node to an end (one digit per
      decade, up to twice the working precision): forms such as
      (R - sqrt(R**2 - t**2))/t**2 cancel catastrophically as t -> 0, and the
      nodes crowd there.
    * Imaginary parts from rounding at the very ends (sqrt of -1 ulp at t = a)
      are dropped; a significant imaginary part elsewhere is remembered in
      ``complex_at`` (the first such node) for the caller to report.
    * A non-finite value (or a division by zero) at a node closer to an end
      than the precision resolves (atanh(1.0)) counts as 0: its weight is
      negligible.

    Create it inside the ``mpmath.workdps`` of the quadrature: its tolerances
    are read from the working precision then.

    >>> with mpmath.workdps(30):
    ...     g = EndpointGuard(lambda t: 1 / mpmath.sqrt(1 - t**2), mpmath.mpf(0), mpmath.mpf(1))
    ...     print(g(mpmath.mpf(1)), abs(mpmath.quad(g, [0, 1]) - mpmath.pi / 2) < 1e-15)
    0.0 True
    """

    def __init__(self, g, lo, hi):
        self.g, self.lo, self.hi = g, lo, hi
        self.span = hi - lo
        self.tol = mpmath.mpf(10) ** (-(mpmath.mp.dps // 2))
        self.cap = mpmath.mp.dps
        self.near = self.span * mpmath.mpf(10) ** -5
        self.complex_at = None

    def near_end(self, tv) -> bool:
        """Is ``tv`` closer to an end than half the working digits resolve?"""
        return min(abs(tv - self.lo), abs(tv - self.hi)) <= self.tol * self.span

    def _eval(self, tv):
        dist = min(abs(tv - self.lo), abs(tv - self.hi))
        extra = 0
        if dist < self.near:
            extra = self.cap if dist == 0 else min(self.cap, _decades_below(dist / self.span))
        if extra:
            with extradps(extra):
                return self.g(tv)
        return self.g(tv)

    def __call__(self, tv):
        try:
            v = self._eval(tv)
        except ZeroDivisionError:
            if self.near_end(tv):
                return mpmath.mpf(0)
            raise
        if not mpmath.isfinite(v) and self.near_end(tv):
            return mpmath.mpf(0)
        if isinstance(v, mpmath.mpc):
            if v.imag and abs(v.imag) > abs(v.real) * mpmath.mpf(10) ** (-mpmath.mp.dps + 10):
                if not self.near_end(tv) and self.complex_at is None:
                    self.complex_at = tv
            return +v.real
        return +v


def relational_breakpoints(expr, var, lo, hi) -> list:
    """Sorted mpf points strictly inside (lo, hi) where a relational of
    ``expr`` in ``var`` (a ``Piecewise`` condition such as t < b) changes its
    truth value: the points to split a quadrature at.

    Linear conditions are solved exactly (keeping the full precision of Float
    coefficients); others with ``sympy.solve``; unsolvable ones are skipped.
    Values are mpf at the current working precision.

    >>> t = sp.Symbol("t", positive=True)
    >>> f = sp.Piecewise((0, t < sp.Rational(1, 3)), (t, True))
    >>> with mpmath.workdps(20):
    ...     print([mpmath.nstr(v, 15) for v in relational_breakpoints(f, t, mpmath.mpf(0), mpmath.mpf(1))])
    ['0.333333333333333']
    """
    found = set()
    for rel in expr.atoms(sp.Rel):
        d = rel.lhs - rel.rhs
        if var not in d.free_symbols:
            continue
        try:
            poly = sp.Poly(d, var)
            if poly.degree() == 1:
                c1, c0 = poly.all_coeffs()
                roots = [-c0 / c1]
            else:
                roots = sp.solve(sp.Eq(d, 0), var, rational=False)
        except Exception:  # noqa: BLE001 -- a condition SymPy cannot solve gives no breakpoint
            continue
        for r in roots:
            try:
                rv = to_mpf(r)
            except (TypeError, ValueError):
                continue
            if lo < rv < hi:
                found.add(rv)
    return sorted(found)


__all__ = ["MAXDEGREE", "quad_substituted", "quad0", "quad_piece", "quad_dps", "endpoint_exponent", "quad_segments",
           "EndpointGuard", "relational_breakpoints", "tanh_sinh_levels", "smoothstep_gauss"]


# ------------------------------------------------------------ float64 rules
def tanh_sinh_levels(levels=(8, 16, 32, 64, 128), tmax: float = 6.2):
    """Nested tanh-sinh node sets on (0, 1) for the step sizes h = 1/levels[0],
    1/levels[1], ... (each a power-of-two refinement of the one before): per
    level ``(h, v, w, phi)``, the nodes *new* at that level, v = 1/(1 +
    exp(-pi sinh t)) and w = 1 - v (both formed to full relative precision,
    so that distances to either end are exact), and the weights phi(t) =
    pi/4 cosh t / cosh^2(pi/2 sinh t); the estimate at level j is h_j * the
    sum of phi f over the nodes of levels 0..j.  Nodes out to |t| = ``tmax``;
    nodes where v, w or phi underflow are dropped.

    >>> levels = tanh_sinh_levels((2, 4), tmax=3.0)
    >>> [(h, len(v)) for h, v, w, phi in levels]
    [(0.5, 13), (0.25, 12)]
    >>> h = levels[-1][0]; v = np.concatenate([l[1] for l in levels])
    >>> phi = np.concatenate([l[3] for l in levels])
    >>> round(float(h * np.sum(phi * 3 * v**2)), 9)     # int_0^1 3 v^2 dv = 1
    1.0
    """
    hmax = levels[-1]
    kmax = int(tmax * hmax)
    k = np.arange(-kmax, kmax + 1)
    t = k / hmax
    ps = np.pi / 2 * np.sinh(t)
    with np.errstate(over="ignore"):
        v = 1 / (1 + np.exp(-2 * ps))
        w = 1 / (1 + np.exp(2 * ps))
        phi = np.pi / 4 * np.cosh(t) / np.cosh(ps) ** 2
    keep = (v > 0) & (w > 0) & (phi > 0)
    seen = np.zeros(k.size, dtype=bool)
    out = []
    for m in levels:
        sel = (k % (hmax // m) == 0) & keep & ~seen
        seen |= sel
        out.append((1.0 / m, v[sel], w[sel], phi[sel]))
    return out


def smoothstep_gauss(sizes=(20, 40)):
    """Gauss-Legendre rules on u in [0, 1] after v = 3u^2 - 2u^3 (the
    smoothstep: dv/du = 6u(1 - u) vanishes at both ends, so an end-point
    singularity (v or 1 - v)^(-1/2) becomes analytic; w = 1 - v = (1 - u)^2
    (1 + 2u) is formed exactly): ``(v, w, weights)`` of the rules side by side
    and the index where the second rule starts.

    >>> v, w, wt, k = smoothstep_gauss((20, 40))
    >>> k, round(float(np.sum(wt[:k] / np.sqrt(v[:k]))), 6)   # int_0^1 v^-1/2 dv = 2
    (20, 2.0)
    """
    out = []
    for n in sizes:
        t, wt = np.polynomial.legendre.leggauss(n)
        u = (t + 1) / 2
        out.append((u * u * (3 - 2 * u), (1 - u) ** 2 * (1 + 2 * u), wt / 2 * 6 * u * (1 - u)))
    return (np.concatenate([o[0] for o in out]), np.concatenate([o[1] for o in out]),
            np.concatenate([o[2] for o in out]), sizes[0])

