"""Breakpoints near an evaluation point (for :mod:`.evaluate`): where a
Piecewise condition of the expression changes sign, a finite difference must
not straddle it, and a float64 quadrature whose integrand switches next to an
endpoint singularity is not trusted."""
from __future__ import annotations

import sympy as sp

from .cache import IdentityCache
from .exports import stable_form

_CACHE = IdentityCache()


def _switches(d):
    """(relation functions, names): lhs - rhs of every relation of a
    Piecewise in the derivation's expression and of its conditions, as float64 functions of its
    variables (and of the integration variables, for unevaluated integrals)."""
    cache = _CACHE.of(d)
    if "switch" not in cache:
        syms = list(d.variables_all)
        expr = stable_form(d).expr if d.closed_form else d.expr
        out = []
        # the expression's own switches, and the derivation's conditions (a <= L/2, x < a): a step
        # across the domain's edge measures what lies beyond it (the periodic wedge's
        # asinh(sin/|cos|) is even about a = L/2: a central difference across it gave kappa 19, not 2e8)
        rels = set(expr.atoms(sp.Rel)) | {c for c in (d.conditions or ()) if isinstance(c, sp.Rel)
                                          and c.free_symbols <= set(syms)}
        for rel in sorted(rels, key=sp.default_sort_key):
            g = rel.lhs - rel.rhs
            ivars = [v for v in g.free_symbols if v not in syms]
            if len(ivars) > 1:
                continue
            fn = sp.lambdify(syms + ivars, g, "math")
            lim = None
            if ivars:
                for I in expr.atoms(sp.Integral):
                    if I.limits[0][0] == ivars[0] and len(I.limits[0]) == 3:
                        lim = sp.lambdify(syms, I.limits[0][1:], "math")
            out.append((fn, bool(ivars), lim))
        cache["switch"] = (out, [s.name for s in syms])
    return cache["switch"]


#: relative distance below which a breakpoint counts as "at" a point
SWITCH_GAP = 1e-3


def safe_step(d, point, h=1e-6):
    """The relative finite-difference step of the condition number: 1e-6,
    made smaller (to at least 1e-13) until no step crosses a breakpoint of
    the expression (a Piecewise condition changing sign): a difference
    straddling a kink measures the other side's slope, not this one's
    (the worn cylinder near x = b)."""
    fns, names = _switches(d)
    base = [float(point[n]) for n in names]
    for fn, has_ivar, _ in fns:
        if has_ivar:
            continue
        try:
            g0 = fn(*base)
        except (ValueError, ZeroDivisionError, OverflowError):
            continue
        for i, v in enumerate(base):
            while h > 1e-13:
                crossed = False
                for sgn in (1, -1):
                    args = list(base)
                    args[i] = v * (1 + sgn * h)
                    try:
                        crossed |= (fn(*args) < 0) != (g0 < 0)
                    except (ValueError, ZeroDivisionError, OverflowError):
                        pass
                if not crossed:
                    break
                h /= 10
    return h


def switch_near_end(d, point):
    """A note when an unevaluated integral's integrand switches (a Piecewise
    condition in the integration variable changes sign) within
    :data:`SWITCH_GAP` of the interval's length from one of its ends: the
    integrand then has a kink or jump next to an endpoint singularity, which
    the float64 quadrature neither resolves nor sees in its own error
    estimate (the worn cylinder's pressure at x = b(1 - 1e-9): estimated
    1e-13, wrong by 2e-11); None otherwise."""
    fns, names = _switches(d)
    base = [float(point[n]) for n in names]
    for fn, has_ivar, lim in fns:
        if not has_ivar or lim is None:
            continue
        try:
            lo, hi = (float(v) for v in lim(*base))
            glo, ghi = fn(*base, lo), fn(*base, hi)
        except (ValueError, ZeroDivisionError, OverflowError, TypeError):
            continue
        if (glo < 0) == (ghi < 0):
            continue
        a, b = lo, hi
        for _ in range(80):
            m = (a + b) / 2
            if (fn(*base, m) < 0) == (glo < 0):
                a = m
            else:
                b = m
        width = abs(hi - lo)
        if min(abs(a - lo), abs(a - hi)) < SWITCH_GAP * width:
            return (f"the integrand switches at {a:.10g}, within {SWITCH_GAP:g} of the integration "
                    f"interval's length from its end: the float64 quadrature is not trusted there")
    return None


__all__ = ["SWITCH_GAP", "safe_step", "switch_near_end"]
