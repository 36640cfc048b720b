"""One toolkit for 1-D roots and minima of real functions on (0, oo), at the
current mpmath working precision.

Every search of the package that looks for a half-width (equilibria,
stationary points of a force law, the edge of a domain) goes through these
functions, so a fix or an improvement lands everywhere at once.

Conventions: ``fn`` maps an mpf to an mpf; it raises :class:`Outside` (or
ValueError / ZeroDivisionError) where it is undefined.  Searches for a
positive variable work in u = ln(a), which treats 1e-6 and 1e6 alike.
"""
from __future__ import annotations

import mpmath


class Outside(ValueError):
    """The function is undefined (not real, not finite) at this argument (a
    ValueError: callers that treat a ValueError as "undefined here" see it so)."""


UNDEFINED = (Outside, ValueError, ZeroDivisionError)


def real_value(v):
    """``v`` as a finite real mpf, or :class:`Outside` (complex with a
    non-negligible imaginary part, NaN, infinite, not a number)."""
    if isinstance(v, mpmath.mpc):
        if v.real == 0 or abs(v.imag) > abs(v.real) * mpmath.mpf(10)**(-mpmath.mp.dps + 5):
            raise Outside
        v = v.real
    elif not isinstance(v, mpmath.mpf):
        try:
            v = mpmath.mpf(v)
        except (TypeError, ValueError):
            raise Outside
    if not mpmath.isfinite(v):
        raise Outside
    return v


def bisect(fn, lo, hi, iters: int = 60):
    """Bisection on a sign change of ``fn`` over [lo, hi] (``fn(lo)`` and
    ``fn(hi)`` of opposite signs); returns the final bracket.  A midpoint where
    ``fn`` is no number at the working precision (a division by zero: the sign
    change is a pole or an infinite slope there, as at a kink of a force law
    whose derivative jumps to +oo) ends the bisection at that point, which is
    where bisection converges either way."""
    flo = fn(lo)
    for _ in range(iters):
        mid = (lo + hi) / 2
        try:
            fm = fn(mid)
        except (ZeroDivisionError, ValueError):
            return mid, mid
        if (fm < 0) == (flo < 0):
            lo, flo = mid, fm
        else:
            hi = mid
    return lo, hi


def root_in_bracket(g, lo, hi, width=None):
    """The root of ``g`` in the sign-change bracket [lo, hi] at the working
    precision: bisection down to a bracket of ``width`` (default 1e-3 of
    max(1, |lo|, |hi|)), then Anderson-Bjorck, checked to be a sign change
    (else bisection to the working precision).  The one bracketed root finder
    of the package (:func:`root_in_log` solves in ln a with it; the switch
    points of a Piecewise profile, :mod:`linecontact_sym.method.transforms`)."""
    width = width if width is not None else mpmath.mpf("1e-3") * max(1, abs(lo), abs(hi))
    # shrink the bracket first: Anderson-Bjorck on a bracket spanning many
    # decades may stop at a point that is not a root (verify=False)
    glo = g(lo)
    if glo == 0:
        return lo
    while hi - lo > width:
        um = (lo + hi) / 2
        gm = g(um)
        if gm == 0:
            return um
        if (gm < 0) == (glo < 0):
            lo, glo = um, gm
        else:
            hi = um
    try:
        u = mpmath.findroot(g, (lo, hi), solver="anderson", verify=False)
    except (ZeroDivisionError, ValueError):
        u = None
    try:
        bad = u is None or isinstance(u, mpmath.mpc) or not (lo <= u <= hi) or not _is_root(g, u, lo, hi)
    except (ZeroDivisionError, ValueError):      # g is no number next to u: not confirmed, bisect
        bad = True
    if bad:
        lo, hi = bisect(g, lo, hi, iters=int(3.4 * mpmath.mp.dps) + 10)
        u = (lo + hi) / 2
    return u


def root_in_log(fn, lo, hi, approx=None):
    """The root of ``fn`` in the sign-change bracket [lo, hi] (0 < lo < hi),
    solved in u = ln a at the working precision by :func:`root_in_bracket`
    (bisection down to a bracket of 1e-3 in u, then Anderson-Bjorck).  With
    ``approx`` the bracket is first narrowed around it (a cheap
    high-precision refinement of a root known to lower precision)."""
    g = lambda u: fn(mpmath.exp(u))  # noqa: E731
    ul, uh = mpmath.log(lo), mpmath.log(hi)
    if approx is not None:
        u0 = mpmath.log(approx)
        d = mpmath.mpf("1e-12")
        while d < uh - ul:
            l2, h2 = max(u0 - d, ul), min(u0 + d, uh)
            if (g(l2) < 0) != (g(h2) < 0):
                ul, uh = l2, h2
                break
            d *= 1000
    return mpmath.exp(root_in_bracket(g, ul, uh, width=mpmath.mpf("1e-3")))


def _is_root(g, u, ul, uh):
    """Does g change sign within 10**(5 - dps) (relative) of u (or vanish there)?"""
    d = mpmath.mpf(10)**(5 - mpmath.mp.dps) * max(1, abs(u))
    g0 = g(u)
    if g0 == 0:
        return True
    lo, hi = max(u - d, ul), min(u + d, uh)
    return (g(lo) < 0) != (g(hi) < 0)


def domain_end(fn, good, bad, iters: int = 60):
    """The end of the domain of ``fn`` between a point where it is defined
    (``good``) and one where it is not (``bad``): the last defined point of
    a bisection (``iters`` halvings)."""
    for _ in range(iters):
        mid = (good + bad) / 2
        try:
            fn(mid)
            good = mid
        except UNDEFINED:
            bad = mid
    return good


def golden_minimum(fn, lo, hi, tol=None):
    """Golden-section search for a minimum of a unimodal ``fn`` on [lo, hi]
    (derivative-free; ``tol`` defaults to 10**(-dps/2) relative, the
    accuracy a minimum's location can have from function values alone)."""
    invphi = (mpmath.sqrt(5) - 1) / 2
    tol = tol if tol is not None else mpmath.mpf(10)**(-mpmath.mp.dps // 2) * hi
    c, d = hi - invphi * (hi - lo), lo + invphi * (hi - lo)
    fc, fd = fn(c), fn(d)
    while hi - lo > tol:
        if fc < fd:
            hi, d, fd = d, c, fc
            c = hi - invphi * (hi - lo)
            fc = fn(c)
        else:
            lo, c, fc = c, d, fd
            d = lo + invphi * (hi - lo)
            fd = fn(d)
    return (lo + hi) / 2


__all__ = ["Outside", "UNDEFINED", "real_value", "bisect", "root_in_bracket", "root_in_log", "domain_end", "golden_minimum"]
