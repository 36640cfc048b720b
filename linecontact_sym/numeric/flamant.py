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
:func:`~.reference.log_end_integral` (an exponential substitution at the
piece's end), the smooth rest integrated as it stands; a pressure with a
break point, or without a finite value at 0, goes to the integrator as one
integral of the kernel (its logarithmic end points split there).  :func:`flamant_displacement` runs it first and, where Arb
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


def _piece_terms(p, s, lo, hi, xv, k, breaks, values, dps):
    """[(coef, RefValue)] of k int_lo^hi p(s) ln|x^2/s^2 - 1| ds, certified
    (or :class:`~.reference.ArbUnsupported`).  ``values`` None: ``p``, lo,
    hi are numbers but for s, and the integrator gets SymPy forms (its end
    substitutions apply); a dict: the parameters' numbers, and it gets the
    forms compiled once with the parameters and x as symbols."""
    lo_v, hi_v = (lo, hi) if values is None else (to_basic(lo.xreplace(values)), to_basic(hi.xreplace(values)))
    inside = _is_true(lo_v < xv) and _is_true(xv < hi_v)
    pts = kernel_points(lo_v, hi_v, list(breaks) + ([xv] if inside else []))

    def certified(r):
        if not r.certified:
            raise ArbUnsupported(r.note)
        return r
    from_zero = lo_v == 0
    if values is None and p.has(s) and (breaks or (from_zero and not finite_at(p, s, 0))):
        # a break point (the end of a flat, where the pressure's slope has a
        # logarithm) or p(0) not finite (the wedge's acosh(a/s)): the kernel
        # as it stands, its logarithms and the pressure's taken by the
        # integrator's logarithmic end points, one integral
        g = p * sp.log(sp.Abs(xv**2 / s**2 - 1))
        return [(k, certified(integrate(g, s, pts, dps, fallback=lambda: mpmath.nan)))]
    # ln|x - s| (coefficient 1) and, on a piece from 0, ln s (-2): on a piece
    # with the point at an end, by the exponential substitution there
    # (log_end_integral); elsewhere in the smooth part of the piece's integrand
    logs = [(xv, 1)] + ([(sp.S.Zero, -2)] if from_zero else [])
    at = {**(values or {}), _X: xv}
    pc = p if values is None else bound_acb(p, s, values)
    smooth, terms = [], []
    for j, (u, v) in enumerate(zip(pts[:-1], pts[1:])):
        g = sp.log(_X + s) + (0 if from_zero else -2 * sp.log(s))
        for c, m in logs:
            if c == u or c == v:
                terms.append((m * k, log_end_integral(pc, s, c, v if c == u else u, dps)))
            elif c == 0:
                g += m * sp.log(s)
            else:
                g += m * sp.log(_X - s if _is_true(v <= xv) else s - _X)
        if values is None:
            smooth.append((p * g).xreplace(at))
        elif j == len(pts) - 2 and p.has(s) and v != xv:
            # the piece's end hi (the contact edge: a sqrt-type branch point of
            # the pressure), s = hi - d u^2, the substituted form made once
            f = bound_acb(_end_substituted(p * g, s, hi), _U, {**at, _D: v - u})
            terms.append((k, certified(integrate(f, None, [0, 1], dps, fallback=lambda: mpmath.nan))))
        else:
            terms.append((k, certified(integrate(bound_acb(p * g, s, at), None, [u, v], dps,
                                                 fallback=lambda: mpmath.nan))))
    if smooth:
        terms.insert(0, (k, certified(integrate(smooth, s, pts, dps, fallback=lambda: mpmath.nan))))
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
        vals = None if values is None else {q: to_basic(v) for q, v in values.items()}
        terms = []
        for p, s, lo, hi in pieces:
            p, lo, hi = (sp.sympify(q, strict=True) for q in (p, lo, hi))
            if p.free_symbols - {s} - set(vals or ()):
                return None
            if vals is None:
                lo, hi = to_basic(lo), to_basic(hi)
            terms += _piece_terms(p, s, lo, hi, xv, k, [to_basic(b) for b in breaks], vals, dps)
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
            fs = [(sp.lambdify(s, sp.sympify(p, strict=True).xreplace(vals), "mpmath"),
                   sp.sympify(lo, strict=True).xreplace(vals), sp.sympify(hi, strict=True).xreplace(vals))
                  for p, s, lo, hi in pieces]
            return flamant_tanh_sinh(fs, x, E)
    return estimate(fallback, "Arb could not enclose the Flamant integral", dps)
