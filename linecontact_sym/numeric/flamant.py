"""The Flamant (logarithmic) kernel of the half-plane: the relative surface
displacement of an even pressure, one routine for every caller (the
checker's references of printed pressures, the Maugis-Dugdale checks).

For an even pressure p(s) on pieces [lo, hi] of s >= 0 (a contact pressure
on [0, a], a cohesive strip on [a, c], ...)::

    u_z(0) - u_z(x) = (2/(pi E*)) sum int_lo^hi p(s) ln|x^2/s^2 - 1| ds
                    = (2/(pi E*)) sum int_lo^hi p(s) [ln|x - s| + ln(x + s) - 2 ln s] ds

:func:`flamant_arb` is the certified route (the one reference integrator of
:mod:`.reference`): each logarithmic point of the kernel (s = x inside a
piece or at its end, s = 0 at the start of a piece from 0) is removed by
:func:`~.reference.log_point_integral`, the smooth rest integrated as it
stands; a pressure with a break point, or without a finite value at 0, goes
to the integrator as one integral of the kernel (its logarithmic end points
split there).  :func:`flamant_displacement` runs it first and, where Arb
cannot enclose the integral, tanh-sinh (:func:`flamant_tanh_sinh`, split at
the logarithmic points), recorded as ``method == "mpmath"`` with the reason.

>>> import sympy as sp
>>> s = sp.Symbol("s")
>>> r = flamant_displacement([(1 / (sp.pi * sp.sqrt(1 - s**2)), s, 0, 1)], sp.Rational(1, 2), 1, 40)
>>> print(r.method, abs(r) <= r.rad < 1e-40)      # the flat punch keeps |x| < a flat
arb True
"""
from __future__ import annotations

import functools

import mpmath
import sympy as sp

from ..core.conversion import to_basic, to_mpf
from ..core.errors import LineContactError
from ..core.precision import workdps
from .reference import ArbUnsupported, RefValue, bound_acb, estimate, integrate, lincomb, log_end_integral

__all__ = ["flamant_arb", "flamant_displacement", "flamant_tanh_sinh", "kernel_points", "finite_at"]


def _is_true(rel) -> bool:
    return rel == sp.true or rel is True


def kernel_points(lo, hi, inner=()):
    """lo, the points of ``inner`` strictly inside (lo, hi), hi, and the
    middle of every piece between them (so that no piece joins a
    logarithmic point to the piece's other end, where the pressure may have
    an inverse-square-root singularity); exact SymPy numbers."""
    lo, hi = to_basic(lo), to_basic(hi)
    pts = sorted({lo, hi} | {b for b in map(to_basic, inner) if _is_true(lo < b) and _is_true(b < hi)})
    out = [pts[0]]
    for a, b in zip(pts[:-1], pts[1:]):
        out += [(a + b) / 2, b]
    return out


def finite_at(p, s, v) -> bool:
    """Is the SymPy pressure p finite at s = v (False where it is not or
    SymPy cannot tell)?"""
    try:
        return bool(to_basic(p.xreplace({s: to_basic(v)})).is_finite)
    except (TypeError, ValueError, ZeroDivisionError, LineContactError):
        return False


def _piece_terms(p, s, lo, hi, xv, k, breaks, dps):
    """[(coef, RefValue)] of k int_lo^hi p(s) ln|x^2/s^2 - 1| ds, certified
    (or :class:`~.reference.ArbUnsupported`)."""
    inside = _is_true(lo < xv) and _is_true(xv < hi)
    pts = kernel_points(lo, hi, list(breaks) + ([xv] if inside else []))

    def integral(g):
        r = integrate(g, s, pts, dps, fallback=lambda: mpmath.nan)
        if not r.certified:
            raise ArbUnsupported(r.note)
        return r
    from_zero = lo == 0
    if p.has(s) and (breaks or (from_zero and not finite_at(p, s, 0))):
        # a break point (the end of a flat, where the pressure's slope has a
        # logarithm) or p(0) not finite (the wedge's acosh(a/s)): the kernel
        # as it stands, its logarithms and the pressure's taken by the
        # integrator's logarithmic end points, one integral
        return [(k, integral(p * sp.log(sp.Abs(xv**2 / s**2 - 1))))]
    # ln|x - s| (coefficient 1) and, on a piece from 0, ln s (-2): on a piece
    # with the point at an end, by the exponential substitution there
    # (log_end_integral); elsewhere in the smooth part of the piece's integrand
    logs = [(xv, 1)] + ([(sp.S.Zero, -2)] if from_zero else [])
    smooth, terms = [], []
    for u, v in zip(pts[:-1], pts[1:]):
        g = sp.log(xv + s) + (0 if from_zero else -2 * sp.log(s))
        for c, m in logs:
            if c == u or c == v:
                terms.append((m * k, log_end_integral(p, s, c, v if c == u else u, dps)))
            elif c == 0:
                g += m * sp.log(s)
            else:
                g += m * sp.log(xv - s if _is_true(v <= xv) else s - xv)
        smooth.append(p * g)
    terms.insert(0, (k, integral(smooth)))
    return terms


#: the point x, and the substitution s = hi - d u^2 of a piece's last part
_X, _U, _D = sp.Dummy("x", positive=True), sp.Dummy("u", positive=True), sp.Dummy("d", positive=True)


@functools.lru_cache(maxsize=64)
def _end_substituted(g, s, hi):
    """g(s) ds on [hi - d, hi] as a function of u in [0, 1], s = hi - d u^2
    (Jacobian 2 d u), the radicands factored so that the u^2 they vanish
    with at s = hi leaves the root (a sqrt-type branch point of the
    pressure there becomes holomorphic in u).  Symbolic, once per form."""
    q = g.xreplace({s: hi - _D * _U**2}) * 2 * _D * _U
    return q.replace(lambda z: z.is_Pow and z.exp.is_Rational and not z.exp.is_Integer and z.base.has(_U),
                     lambda z: sp.factor(z.base) ** z.exp)


def _piece_terms_compiled(p, s, lo, hi, xv, k, values, dps):
    """:func:`_piece_terms` for a pressure with parameters (``values``): every
    SymPy form is built with the parameters (and x) as symbols, compiled
    once and reused at every point; per point only balls are made."""
    lo_v, hi_v = to_basic(lo.xreplace(values)), to_basic(hi.xreplace(values))
    inside = _is_true(lo_v < xv) and _is_true(xv < hi_v)
    pts = kernel_points(lo_v, hi_v, [xv] if inside else [])
    from_zero = lo_v == 0
    logs = [(xv, _X, 1)] + ([(sp.S.Zero, sp.S.Zero, -2)] if from_zero else [])
    const = not p.has(s)
    terms = []

    def certified(r):
        if not r.certified:
            raise ArbUnsupported(r.note)
        return r
    pc = None
    smooth, spans = [], []
    for j, (u, v) in enumerate(zip(pts[:-1], pts[1:])):
        g = sp.log(_X + s) + (0 if from_zero else -2 * sp.log(s))
        for c, c_sym, m in logs:
            if c == u or c == v:
                if pc is None:
                    pc = bound_acb(p, s, values)
                terms.append((m * k, log_end_integral(pc, None, c, v if c == u else u, dps)))
            elif c == 0:
                g += m * sp.log(s)
            else:
                g += m * sp.log(_X - s if _is_true(v <= xv) else s - _X)
        if j == len(pts) - 2 and not const and v != xv:
            # the piece's end hi (the contact edge: a sqrt-type branch point of
            # the pressure), s = hi - d u^2
            q = _end_substituted(p * g, s, hi)
            f = bound_acb(q, _U, {_X: xv, _D: v - u, **values})
            terms.append((k, certified(integrate(f, None, [0, 1], dps, fallback=lambda: mpmath.nan))))
        else:
            smooth.append(bound_acb(p * g, s, {_X: xv, **values}))
            spans.append((u, v))
    for f, (u, v) in zip(smooth, spans):
        terms.append((k, certified(integrate(f, None, [u, v], dps, fallback=lambda: mpmath.nan))))
    return terms


def _flamant_compiled(pieces, xv, k, dps, values):
    values = {q: to_basic(v) for q, v in values.items()}
    terms = []
    for p, s, lo, hi in pieces:
        p = sp.sympify(p, strict=True)
        if p.free_symbols - {s} - set(values):
            return None
        terms += _piece_terms_compiled(p, s, sp.sympify(lo, strict=True), sp.sympify(hi, strict=True), xv, k, values, dps)
    return terms


def flamant_arb(pieces, x, E, dps: int, breaks=(), values=None):
    """u_z(0) - u_z(x) (module docstring) as a certified :class:`~.reference.RefValue`,
    or None where Arb cannot enclose it.  ``pieces``: [(p, s, lo, hi)], ``p``
    SymPy in the one symbol ``s`` (every parameter a number, exact or a
    Float), 0 <= lo < hi; ``x``, ``E`` numbers; ``breaks``: break points of
    the pressures (the profile's), where a piece is split.

    ``values``: the pressures and piece ends may hold parameters (symbols
    -> numbers here): every form is then compiled once, with the
    parameters and x as symbols, and each call only makes balls (no SymPy
    work per point: the Maugis-Dugdale checks); the last part of a
    non-constant piece is integrated in s = hi - d u^2 (a sqrt-type branch
    point of the pressure at its end, the contact edge, becomes
    holomorphic).  ``breaks`` are not taken then."""
    if values is not None and breaks:
        raise ValueError("breaks are not taken with values")
    try:
        xv, E = abs(to_basic(x)), to_basic(E)
        if xv == 0:
            return RefValue(mpmath.mpf(0), mpmath.mpf(0), "arb")
        k = 2 / (sp.pi * E)
        if values is not None:
            terms = _flamant_compiled(pieces, xv, k, dps, values)
            if terms is None:
                return None
            pieces = ()
        else:
            terms = []
        for p, s, lo, hi in pieces:
            p = sp.sympify(p, strict=True)
            if p.free_symbols - {s}:
                return None
            terms += _piece_terms(p, s, to_basic(lo), to_basic(hi), xv, k, [to_basic(b) for b in breaks], dps)
    except (ArbUnsupported, LineContactError, TypeError, ValueError, ZeroDivisionError):
        return None
    ref = lincomb(terms, dps)
    return ref if ref.certified else None


def flamant_tanh_sinh(pieces, x, E):
    """u_z(0) - u_z(x) (module docstring) by tanh-sinh at the working
    precision: ``pieces`` [(p, lo, hi)] with ``p`` an mpmath callable, split
    at the logarithmic points s = x and 0.  An estimate (mpf)."""
    xv, E = abs(to_mpf(x)), to_mpf(E)

    def ker(t):
        return mpmath.log(abs(xv - t)) + mpmath.log(xv + t) - 2 * mpmath.log(t)
    total = mpmath.mpf(0)
    for p, lo, hi in pieces:
        lo, hi = to_mpf(lo), to_mpf(hi)
        pts = sorted({lo, hi} | ({xv} if lo < xv < hi else set()))
        total += mpmath.re(mpmath.quad(lambda t: p(t) * ker(t), pts))
    return 2 / (mpmath.pi * E) * total


def flamant_displacement(pieces, x, E, dps: int, breaks=(), values=None) -> RefValue:
    """u_z(0) - u_z(x) (module docstring): :func:`flamant_arb` (certified),
    else :func:`flamant_tanh_sinh` of the lambdified pieces at ``dps`` + 15
    digits, recorded (``method == "mpmath"``).  ``pieces`` as for
    :func:`flamant_arb`."""
    ref = flamant_arb(pieces, x, E, dps, breaks, values)
    if ref is not None:
        return ref
    vals = values or {}

    def fallback():
        with workdps(dps + 15):
            fs = [(sp.lambdify(s, sp.sympify(p, strict=True).xreplace(vals), "mpmath"), sp.sympify(lo, strict=True).xreplace(vals),
                   sp.sympify(hi, strict=True).xreplace(vals)) for p, s, lo, hi in pieces]
            return flamant_tanh_sinh(fs, x, E)
    return estimate(fallback, "Arb could not enclose the Flamant integral", dps)
