"""Vectorised float64 quadrature of unevaluated integrals.

A derived quantity without a closed form is an unevaluated ``Integral``; its
float64 export evaluates it by vectorised fixed rules over the stable
integrand, never by a per-point adaptive mpmath call: the interval is split
at the breakpoints of a ``Piecewise`` integrand, and each piece is mapped
symbolically onto [0, 1] so that the distances to the end points (where the
integrable singularities sit) are formed exactly.  Then

1. 20- and 40-point Gauss-Legendre rules in u, v = 3u^2 - 2u^3 (the
   singularity removal: the end-point kernels (v or 1 - v)^(-1/2) become
   analytic); a point is accepted when the two agree to
   :data:`GAUSS_ACCEPT` relative (60 integrand values per point; their
   difference is the error estimate);
2. the points left (logarithmic end points, steep integrands) by nested
   tanh-sinh node sets h = 1/8 ... 1/128 on t in [-6.2, 6.2]; a point is
   accepted when two levels agree to :data:`TS_ACCEPT` relative.
"""
from __future__ import annotations

import itertools
import random

import numpy as np
import sympy as sp

from ..core.printing import lambdify
from ..core.quadrature import smoothstep_gauss, tanh_sinh_levels
from .stable import stabilize

__all__ = ["VectorQuad", "piecewise_breakpoints", "TS_ACCEPT", "GAUSS_ACCEPT"]


#: the rules: the package's one table (core.quadrature)
_TS_LEVELS = tanh_sinh_levels((8, 16, 32, 64, 128), tmax=6.2)
_GAUSS = smoothstep_gauss((20, 40))
#: relative difference of the 20- and 40-point Gauss rules below which the
#: 40-point value is accepted, with that difference as its error estimate (an
#: analytic integrand converges geometrically, far below it; a logarithmic
#: end point, e.g. acosh(x/s) P'(s) at s = 0, only algebraically -- hence the
#: strict threshold and no credit for the rate)
GAUSS_ACCEPT = 1e-13
#: relative change between two tanh-sinh levels below which the finer one is
#: accepted (the method roughly doubles the correct digits per level)
TS_ACCEPT = 1e-10


def piecewise_breakpoints(expr, var):
    """Break points in ``var`` from the conditions of Piecewise expressions."""
    out = []
    for pw in expr.atoms(sp.Piecewise):
        for _, cond in pw.args:
            for rel in (cond.atoms(sp.core.relational.Relational) if cond not in (sp.true, sp.false) else ()):
                if rel.has(var):
                    try:
                        sol = sp.solve(sp.Eq(rel.lhs, rel.rhs), var)
                    except Exception:
                        sol = []
                    out += [s_ for s_ in sol if not s_.has(var)]
    uniq = []
    for b in out:
        if b not in uniq:
            uniq.append(b)
    return uniq


class VectorQuad:
    """Float64 vectorised tanh-sinh quadrature of one ``Integral(f, (s, lo, hi))``.

    For every ordering case of the Piecewise breakpoints relative to (lo, hi)
    the integral is split into sub-intervals [p, q] with *symbolic* ends; on
    each the integrand's branch is resolved, s = p + (q - p) v substituted and
    1 - v named w, the result put in stable form and compiled in
    (params, v, w) by ``compile_fn(expr, args, patch)`` (a float64 exporter
    such as ``lambdify_numpy(..., stable=False)``: passed in, since the
    exporter in turn uses this class for the integrals it meets; ``patch``:
    the arguments that may be 0 where it is evaluated, the parameters, not
    v and w: the nodes never reach 0 (:func:`~linecontact_sym.core.quadrature.tanh_sinh_levels`
    drops a node that underflows, the Gauss nodes are inside (0, 1)), so no
    removable limit at v = 0 or w = 0 is sought).  Evaluation selects the
    case per point; ``q(*params)`` gives the values, ``q(*params,
    with_error=True)`` also an error estimate.
    """

    def __init__(self, integral, compile_fn, stable=True, conditions=()):
        self.integral = integral
        f = integral.function
        (s, lo, hi) = integral.limits[0]
        self.params = sorted(integral.free_symbols, key=lambda q: q.name)
        bps = [b for b in piecewise_breakpoints(f, s) if b.free_symbols <= set(self.params)]
        self.bps = bps
        self.cases = []
        self.conditions = conditions
        v, w = sp.Dummy("v", positive=True), sp.Dummy("w", positive=True)
        self.v, self.w = v, w
        bp_fns = [lambdify(self.params, b, "numpy") for b in bps]
        self.bp_fns = bp_fns
        self.lo_fn = lambdify(self.params, lo, "numpy")
        self.hi_fn = lambdify(self.params, hi, "numpy")
        # each breakpoint lies below lo (-1), inside (lo, hi) (0) or above hi (+1)
        for where in itertools.product((-1, 0, 1), repeat=len(bps)):
            ins = [b for b, w_ in zip(bps, where) if w_ == 0]
            sample = self._sample_case(lo, hi, bps, where)
            if sample is None:
                continue
            ends = [lo] + self._order(ins, sample) + [hi]
            pieces = []
            for p, q in zip(ends[:-1], ends[1:]):
                g = self._branch(f, s, p, q, sample)
                if g is None or g == 0:
                    continue
                gv = (g.xreplace({s: p + (q - p) * v}) * (q - p))
                gv = sp.factor_terms(gv)
                if stable:
                    gv = stabilize(gv, check=False).expr
                gv = gv.xreplace({1 - v: w, v - 1: -w, -v + 1: w})
                pieces.append(compile_fn(gv, list(self.params) + [v, w], tuple(self.params)))
            self.cases.append((where, pieces))

    def _sample_case(self, lo, hi, bps, where):
        rng = random.Random(5)
        for _ in range(3000):
            vals = {p: sp.Rational(rng.randint(1, 400), 100) for p in self.params}
            try:
                L, H = float(lo.xreplace(vals)), float(hi.xreplace(vals))
                if not L < H:
                    continue
                pos = [float(b.xreplace(vals)) for b in bps]
                if all((w_ == -1 and p_ < L) or (w_ == 0 and L < p_ < H) or (w_ == 1 and p_ > H)
                       for p_, w_ in zip(pos, where)) and \
                        all(bool(c.xreplace(vals)) for c in self.conditions):
                    return vals
            except (TypeError, ValueError):
                continue
        return None

    @staticmethod
    def _order(ins, sample):
        if sample is None or len(ins) < 2:
            return list(ins)
        return sorted(ins, key=lambda b: float(b.xreplace(sample)))

    @staticmethod
    def _branch(f, s, p, q, sample):
        if not f.has(sp.Piecewise):
            return f
        if sample is None:
            return None
        mid = ((p + q) / 2).xreplace(sample)

        def pick(pw):
            for e, c in pw.args:
                cv = c.xreplace({s: mid, **sample}) if c not in (sp.true,) else sp.true
                if cv == sp.true or (cv != sp.false and bool(cv)):
                    return e
            return sp.nan
        return f.replace(lambda e: isinstance(e, sp.Piecewise), pick)

    def _integrate(self, pieces, args):
        """Adaptive-level tanh-sinh over [0, 1] of sum(pieces) for the points
        in ``args`` (columns); returns (value, error estimate)."""
        npts = args[0].shape[0]
        # 1. fixed Gauss rules on the smoothstep variable: most points end here
        gv, gw, gwt, k = _GAUSS
        a_ = list(args) + [gv[None, :], gw[None, :]]
        tot = np.zeros((npts, gv.size))
        for piece in pieces:
            tot = tot + np.broadcast_to(piece(*a_), (npts, gv.size))
        with np.errstate(all="ignore"):
            small, large = tot[:, :k] @ gwt[:k], tot[:, k:] @ gwt[k:]
            gerr = np.abs(large - small)
            grel = gerr / np.maximum(np.abs(large), 1e-300)
            good = grel <= GAUSS_ACCEPT
        if np.all(good):
            return large, gerr + 4 * 2.2e-16 * np.abs(large)
        # 2. the rest by the nested tanh-sinh levels
        ts_val, ts_err = self._tanh_sinh(pieces, [t[~good] for t in args])
        val = np.where(good, large, 0.0)
        est = np.where(good, gerr + 4 * 2.2e-16 * np.abs(large), 0.0)
        val[~good], est[~good] = ts_val, ts_err
        return val, est

    def _tanh_sinh(self, pieces, args):
        npts = args[0].shape[0]

        def level_sum(lev, rows):
            h, v, w, phi = _TS_LEVELS[lev]
            a_ = [t[rows] for t in args] + [v[None, :], w[None, :]]
            tot = np.zeros(rows.size)
            for piece in pieces:
                fv = np.broadcast_to(piece(*a_), (rows.size, v.size))
                tot += fv @ phi
            return tot
        rows = np.arange(npts)
        prev = level_sum(0, rows) / 8
        cur = prev / 2 + level_sum(1, rows) / 16
        err = np.abs(cur - prev)
        for lev in range(2, len(_TS_LEVELS)):
            todo = np.flatnonzero(~(err <= TS_ACCEPT * np.abs(cur)))
            todo = todo[np.isfinite(cur[todo]) | np.isnan(cur[todo])]
            if todo.size == 0:
                break
            h = _TS_LEVELS[lev][0]
            new = cur[todo] / 2 + h * level_sum(lev, todo)
            err[todo] = np.abs(new - cur[todo])
            cur[todo] = new
        rel = err / np.maximum(np.abs(cur), 1e-300)
        est = np.where(rel <= TS_ACCEPT, 10 * err * np.minimum(rel, 1.0), err) + 4 * 2.2e-16 * np.abs(cur)
        return cur, est

    def __call__(self, *vals, with_error=False):
        vals = np.broadcast_arrays(*[np.asarray(t, dtype=float) for t in vals])
        shape = vals[0].shape
        flat = [t.ravel() for t in vals]
        npts = flat[0].size
        out = np.zeros(npts)
        err = np.zeros(npts)
        lo, hi = np.broadcast_to(self.lo_fn(*flat), (npts,)), np.broadcast_to(self.hi_fn(*flat), (npts,))
        bpv = [np.broadcast_to(fn(*flat), (npts,)) for fn in self.bp_fns]
        with np.errstate(all="ignore"):
            for where, pieces in self.cases:
                if not pieces:
                    continue
                mask = np.ones(npts, dtype=bool)
                for w_, b in zip(where, bpv):
                    mask &= np.where(b <= lo, -1, np.where(b >= hi, 1, 0)) == w_
                idx = np.flatnonzero(mask)
                for start in range(0, idx.size, 2048):
                    sel = idx[start:start + 2048]
                    val, est = self._integrate(pieces, [t[sel][:, None] for t in flat])
                    out[sel] += val
                    err[sel] += est
        out = out.reshape(shape)
        err = err.reshape(shape)
        if with_error:
            return (out[()], err[()]) if out.ndim == 0 else (out, err)
        return out[()] if out.ndim == 0 else out
