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
from ..core.quadrature import EndpointGuard, quad_dps
from .arb_compile import ArbUnsupported, bound_acb
from .endpoints import substitute_end, value_at
from .reference import RefValue, estimate, integrate, lincomb, log_end_integral

__all__ = ["flamant_arb", "flamant_displacement", "flamant_tanh_sinh", "tanh_sinh", "kernel_points", "kernel_points_at",
           "finite_at"]


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


def kernel_points_at(lo, hi, inner, values):
    """:func:`kernel_points` of ends and points that hold parameters: kept
    as expressions (the integrator makes its end forms once for them),
    ordered and taken strictly inside (lo, hi) by their numbers at
    ``values``; a point at the number of another is one point."""
    lo, hi = sp.sympify(lo, strict=True), sp.sympify(hi, strict=True)
    lo_v, hi_v = value_at(lo, values), value_at(hi, values)
    pts = [(lo_v, lo), (hi_v, hi)]
    for b in inner:
        b = sp.sympify(b, strict=True)
        bv = value_at(b, values)
        if _is_true(lo_v < bv) and _is_true(bv < hi_v) and not any(_is_true(sp.Eq(bv, v)) for v, _ in pts):
            pts.append((bv, b))
    pts.sort(key=lambda t: to_mpf(t[0]))
    out = [pts[0][1]]
    for (_, a), (_, b) in zip(pts[:-1], pts[1:]):
        out += [(a + b) / 2, b]
    return out


def finite_at(p, s, v) -> bool:
    """Is the SymPy pressure p finite at s = v (False where it is not or
    SymPy cannot tell)?"""
    try:
        return bool(to_basic(p.xreplace({s: to_basic(v)})).is_finite)
    except (TypeError, ValueError, ZeroDivisionError, LineContactError):
        return False


#: the point x, and the length d of a piece's last part (s = hi - d w^q)
_X, _D = sp.Dummy("x", positive=True), sp.Dummy("d", positive=True)


@functools.lru_cache(maxsize=64)
def _edge_form(p, s, hi):
    """p(s) ds on [hi - d, hi] in s = hi - d w^q (:func:`~.endpoints.substitute_end`,
    q from the pressure's exponent at the edge: 2 for a sqrt-type branch
    point or an inverse square root; the pressure's radicands factored, so
    that the edge s = hi becomes holomorphic in w), symbolic, once per
    pressure: (the form, w, q).  Oriented from hi: its integral over w in
    [0, 1] is minus the piece's."""
    return substitute_end(p, s, hi, -_D)


@functools.lru_cache(maxsize=64)
def _end_substituted(p, g, s, hi):
    """p(s) g(s) ds on [hi - d, hi] as (a form in w over [0, 1], w):
    :func:`_edge_form` of p times the kernel's logarithms g as they are,
    the orientation turned.  Symbolic, once per form."""
    f, w, q = _edge_form(p, s, hi)
    return -f * g.xreplace({s: hi - _D * w**q}), w


def _certified(r):
    if not r.certified:
        raise ArbUnsupported(r.note)
    return r


def _log_terms(p, s, lo, hi, c, m, smooth, values, dps):
    """[(1, RefValue)] of int_lo^hi p(s) [m ln|s - c| + smooth(s)] ds, certified (or
    :class:`~.arb_compile.ArbUnsupported`): split at c (inside) and the
    middles (:func:`kernel_points`); the logarithm at a piece's end by
    :func:`~.reference.log_end_integral`, inside the piece's integrand
    elsewhere.  ``values`` None: p, lo, hi, c numbers but for s, and the
    integrator gets SymPy forms (its end substitutions apply); a dict: the
    parameters' numbers, and it gets the forms compiled once with the
    parameters and x (``_X``, at ``values[_X]``) as symbols, the last part of
    a non-constant piece in s = hi - d u^q (the contact edge's sqrt-type
    branch point becomes holomorphic)."""
    lo_v, hi_v = value_at(lo, values), value_at(hi, values)
    inside = _is_true(lo_v < c) and _is_true(c < hi_v)
    pts = kernel_points(lo_v, hi_v, [c] if inside else [])
    c_sym = c if values is None or c == 0 else _X

    def form(e, var=s, extra=None):
        return e if values is None else bound_acb(e, var, {**values, **(extra or {})})
    terms = []
    for j, (u, v) in enumerate(zip(pts[:-1], pts[1:])):
        g = smooth
        if c == u or c == v:
            terms.append((m, log_end_integral(form(p), s, c, v if c == u else u, dps)))
        else:
            g = g + m * sp.log(c_sym - s if _is_true(v <= c) else s - c_sym)
        if g == 0:
            continue
        if values is not None and j == len(pts) - 2 and p.has(s):
            f = form(*_end_substituted(p, g, s, hi), {_D: v - u})
            terms.append((1, _certified(integrate(f, None, [0, 1], dps, fallback=lambda: mpmath.nan))))
        else:
            terms.append((1, _certified(integrate(form(p * g), s if values is None else None, [u, v], dps,
                                                  fallback=lambda: mpmath.nan))))
    return terms


def _pieces(pieces, values):
    """The pieces as SymPy (p, s, lo, hi), the parameters' values as SymPy
    numbers; None where a pressure has a symbol without a value."""
    out = []
    for p, s, lo, hi in pieces:
        p, lo, hi = (sp.sympify(q, strict=True) for q in (p, lo, hi))
        if p.free_symbols - {s} - set(values or ()):
            return None
        out.append((p, s, lo, hi) if values is not None else (p, s, to_basic(lo), to_basic(hi)))
    return out


def flamant_arb(pieces, x, E, dps: int, breaks=(), values=None):
    """u_z(0) - u_z(x) (module docstring) as a certified :class:`~.reference.RefValue`,
    or None where Arb cannot enclose it.  ``pieces``: [(p, s, lo, hi)], ``p``
    SymPy in the one symbol ``s`` (every parameter a number, exact or a
    Float), 0 <= lo < hi; ``x``, ``E`` numbers; ``breaks``: break points of
    the pressures (the profile's), where a piece is split.  ``x`` a list:
    the list of displacements (None for each where Arb cannot), the term
    of u_z(0), -2 int p(s) ln s ds, integrated once for all.

    ``values``: the pressures and piece ends may hold parameters (symbols
    -> numbers here): every form is then compiled once, with the
    parameters and x as symbols, and each call only makes balls (no SymPy
    work per point: the Maugis-Dugdale checks).  ``breaks`` may then hold
    the parameters too: a pressure split at a break point goes to the
    integrator as one integral of the kernel with x a symbol, its points
    expressions (:func:`kernel_points_at`), so that the integrator's
    symbolic work at its logarithmic end points is made once for all the
    points of a claim (``integrate(values=...)``)."""
    several = isinstance(x, (list, tuple))
    xs = list(x) if several else [x]
    out = [None] * len(xs)
    try:
        E = to_basic(E)
        k = 2 / (sp.pi * E)
        vals = None if values is None else {q: to_basic(v) for q, v in values.items()}
        ps = _pieces(pieces, vals)
        if ps is None:
            return out if several else None
        inner = [to_basic(b) for b in breaks]
        whole = [(p, s, lo, hi) for p, s, lo, hi in ps if p.has(s) and
                 (inner or (lo == 0 and not finite_at(p if vals is None else p.xreplace(vals), s, 0)))]
        xvs = [abs(to_basic(q)) for q in xs]
        at_zero = []
        if any(xv != 0 for xv in xvs):
            # u_z(0): -2 int p(s) ln s ds, the same for every x, first: where Arb cannot enclose it, no
            # displacement can be (each sums it), and none is tried (a thin cohesive zone: each piece
            # next to it would run to the evaluation limit again, per x, only to be discarded)
            try:
                for p, s, lo, hi in ps:
                    if (p, s, lo, hi) not in whole:
                        at_zero += [(-2 * k * m, r) for m, r in _log_terms(p, s, lo, hi, sp.S.Zero, 1, sp.S.Zero,
                                                                             vals, dps)]
            except (ArbUnsupported, LineContactError, TypeError, ValueError, ZeroDivisionError):
                xvs = [xv if xv == 0 else None for xv in xvs]
        for i, xv in enumerate(xvs):
            if xv is None:
                continue
            if xv == 0:
                out[i] = RefValue(mpmath.mpf(0), mpmath.mpf(0), "arb")
                continue
            try:
                terms = []
                for p, s, lo, hi in ps:
                    if (p, s, lo, hi) in whole:
                        # a break point (the end of a flat, where the pressure's slope
                        # has a logarithm) or p(0) not finite (the wedge's acosh(a/s)):
                        # the kernel as it stands, its logarithms and the pressure's
                        # taken by the integrator's logarithmic end points, one integral
                        if vals is None:
                            pts = kernel_points(lo, hi, inner + [xv])
                            terms.append((k, _certified(integrate(p * sp.log(sp.Abs(xv**2 / s**2 - 1)), s, pts, dps,
                                                                  fallback=lambda: mpmath.nan))))
                        else:
                            at = {**vals, _X: xv}
                            pts = kernel_points_at(lo, hi, inner + [_X], at)
                            terms.append((k, _certified(integrate(p * sp.log(sp.Abs(_X**2 / s**2 - 1)), s, pts, dps,
                                                                  fallback=lambda: mpmath.nan, values=at))))
                        continue
                    at = None if vals is None else {**vals, _X: xv}
                    terms += [(k * m, r) for m, r in _log_terms(p, s, lo, hi, xv, 1, sp.log((xv if at is None else _X)
                                                                                             + s), at, dps)]
                ref = lincomb(terms + at_zero, dps)
                out[i] = ref if ref.certified else None
            except (ArbUnsupported, LineContactError, TypeError, ValueError, ZeroDivisionError):
                out[i] = None
    except (ArbUnsupported, LineContactError, TypeError, ValueError, ZeroDivisionError):
        pass
    return out if several else out[0]


def tanh_sinh(g, s, lo, hi, inner, dps: int, edge: bool = True, real_part: bool = False):
    """(value, error) of int_lo^hi g(s) ds by tanh-sinh at
    :func:`~linecontact_sym.core.quadrature.quad_dps` working digits, for a
    SymPy integrand (every parameter a number) whose pressure may have an
    inverse-square-root singularity at s = hi: split as
    :func:`kernel_points` (at ``inner`` and the middles), the last piece, with
    ``edge``, in s = hi - d u^q (:func:`~.endpoints.substitute_end`: q from
    the exponent at hi, 2 for an inverse square root) with the radicands
    factored (the u^q they vanish with leaves the root exactly, so no digits
    cancel in hi^2 - s^2, as they do in hi sin(phi)); logarithmic points (s = 0, x, a break) are
    piece ends, where tanh-sinh converges.  None where the integrand cannot
    be prepared or is complex on a piece (the caller's route runs);
    ``real_part``: the real part of a complex value is taken instead."""
    try:
        lo, hi = to_basic(lo), to_basic(hi)
        pts = kernel_points(lo, hi, [to_basic(b) for b in inner])
        pieces = []
        for a, b in zip(pts[:-1], pts[1:]):
            if edge and b == hi:
                # s = hi - (hi - a) u^q, oriented from hi (the form's integral is minus the piece's);
                # mpmath evaluates point by point: no branch needs deciding on balls
                h, u, _ = substitute_end(g, s, hi, a - hi, branches=False)
                pieces.append((sp.lambdify(u, -h, "mpmath"), [sp.S.Zero, sp.S.One]))
            else:
                pieces.append((sp.lambdify(s, g, "mpmath"), [a, b]))
    except (TypeError, ValueError, ZeroDivisionError, LineContactError):
        return None
    with workdps(quad_dps(dps)):
        total, err = mpmath.mpf(0), mpmath.mpf(0)
        try:
            for f, (a, b) in pieces:
                a_v, b_v = to_mpf(a), to_mpf(b)
                gf = EndpointGuard(f, a_v, b_v)
                v, e = mpmath.quad(gf, [a_v, b_v], maxdegree=10, error=True)
                if real_part:
                    v = mpmath.re(v)
                elif gf.complex_at is not None or isinstance(v, mpmath.mpc):
                    return None
                total, err = total + v, err + e
        except (TypeError, ValueError, ZeroDivisionError):
            return None
        return +total, +err


def flamant_tanh_sinh(pieces, x, E, dps: int, breaks=(), real_part: bool = False):
    """u_z(0) - u_z(x) (module docstring) by tanh-sinh, (value, error):
    ``pieces`` [(p, s, lo, hi)] with ``p`` SymPy in ``s`` (every parameter a
    number), the kernel ln|x^2/s^2 - 1| as it stands, each piece split at
    x and ``breaks`` by :func:`tanh_sinh` (its last part in s = hi - d u^q
    where p has no finite value at hi: the inverse square root of a contact
    edge).  None where a piece cannot be prepared (or, but with
    ``real_part``, is complex)."""
    xb = abs(to_basic(x))
    total, err = mpmath.mpf(0), mpmath.mpf(0)
    for p, s, lo, hi in pieces:
        p = sp.sympify(p, strict=True)
        est = tanh_sinh(p * sp.log(sp.Abs(xb**2 / s**2 - 1)), s, lo, hi, [xb] + list(breaks), dps,
                        edge=not finite_at(p, s, hi), real_part=real_part)
        if est is None:
            return None
        total, err = total + est[0], err + est[1]
    with workdps(quad_dps(dps)):
        k = 2 / (mpmath.pi * to_mpf(E))
        return +(k * total), +(k * err)


def flamant_displacement(pieces, x, E, dps: int, breaks=(), values=None):
    """u_z(0) - u_z(x) (module docstring): :func:`flamant_arb` (certified),
    else :func:`flamant_tanh_sinh` of the pieces at ``values``, recorded
    (``method == "mpmath"``).  ``pieces``, ``x`` (a number or a list: a
    RefValue or a list of them) and ``values`` as for :func:`flamant_arb`."""
    refs = flamant_arb(pieces, x, E, dps, breaks, values)
    several = isinstance(x, (list, tuple))
    xs, refs = (list(x), refs) if several else ([x], [refs])
    vals = values or {}

    def fallback(xv):
        est = flamant_tanh_sinh([(sp.sympify(p, strict=True).xreplace(vals), s, value_at(lo, vals),
                                  value_at(hi, vals)) for p, s, lo, hi in pieces], xv, E, dps,
                                [value_at(b, vals) for b in breaks],
                                real_part=True)
        if est is None:
            raise LineContactError("neither Arb nor tanh-sinh could evaluate the Flamant integral")
        return est[0]
    out = [r if r is not None else estimate(lambda xv=xv: fallback(xv), "Arb could not enclose the Flamant integral",
                                            dps) for xv, r in zip(xs, refs)]
    return out if several else out[0]
