"""Export derived quantities as fast numeric callables.

Backends
--------
``"numpy"``  vectorised float64 (NumPy + ``scipy.special``).  By default the
             expression is first put in its *stable form*
             (:func:`linecontact_sym.stable.stabilize`: Carlson forms for
             K - E, Gamma ratios without overflow, asinh/atan forms of
             atanh/acosh/asin near 1, 2F1 with the complementary argument,
             factored differences of squares), so the export stays accurate at
             the extremes of its arguments (see ``tests/test_extremes.py`` for
             the documented grid).  Special functions map to SciPy: the Carlson
             integrals to ``elliprf/elliprd/elliprg``, elliptic_k(m) to
             ``ellipk(m)`` (both take the parameter m = k**2), 2F1/1F1/0F1 to
             ``hyp2f1``/``hyp1f1``/``hyp0f1``; anything SciPy lacks is evaluated
             point by point with mpmath at 20 digits.
             Unevaluated integrals (no closed form) are evaluated by a
             vectorised double-exponential (tanh-sinh) quadrature in float64
             over the stable integrand: the interval is split at the
             breakpoints of a ``Piecewise`` integrand, and each piece is mapped
             symbolically onto [0, 1] so the distances to the end points (where
             the integrable singularities sit) are formed exactly.
``"mpmath"`` arbitrary precision at ``dps`` digits (``mpmath.workdps``; the
             global precision is never changed); the stable form is used too.
             Unevaluated integrals are evaluated by the derivation's reference
             quadrature (:func:`lambdify_mpmath_quad` is a faster generic
             alternative).

``stable=False`` gives the plain translation of the expression as derived.
Exports are cached on the derivation (stabilising and lambdifying once).
Removable singularities at an argument = 0 (e.g. x**2*atanh(sqrt(a**2 -
x**2)/a) at x = 0) are patched with the symbolic limit.
"""
from __future__ import annotations

import itertools
import random

import mpmath
import numpy as np
import scipy.special as sc
import sympy as sp

from ..parsing import to_sympy
from ..core.errors import DomainError
from .stable import MPMATH_FUNCS, NUMPY_FUNCS, stabilize

_SCIPY_FUNCS = {
    "_ellipk": sc.ellipk, "_ellipe": sc.ellipe, "_hyp2f1": sc.hyp2f1,
    "_hyp1f1": sc.hyp1f1, "_hyp0f1": sc.hyp0f1, "_struve": sc.struve,
}


def _mp_hyper_vec(*args):
    p = int(args[0])
    ap, bq, z = args[1:1 + p], args[1 + p:-1], args[-1]

    def one(*vals):
        with mpmath.workdps(20):
            return float(mpmath.hyper(vals[:p], vals[p:-1], vals[-1]))
    return np.vectorize(one, otypes=[float])(*ap, *bq, z)


def _to_scipy_names(expr):
    def hyp(h):
        ap, bq, z = list(h.ap), list(h.bq), h.argument
        if len(ap) == 2 and len(bq) == 1:
            return sp.Function("_hyp2f1")(*ap, *bq, z)
        if len(ap) == 1 and len(bq) == 1:
            return sp.Function("_hyp1f1")(*ap, *bq, z)
        if len(ap) == 0 and len(bq) == 1:
            return sp.Function("_hyp0f1")(*bq, z)
        return sp.Function("_mphyper")(len(ap), *ap, *bq, z)
    expr = expr.replace(lambda e: isinstance(e, sp.hyper), hyp)
    expr = expr.replace(lambda e: isinstance(e, sp.elliptic_k), lambda e: sp.Function("_ellipk")(e.args[0]))
    expr = expr.replace(lambda e: isinstance(e, sp.elliptic_e) and len(e.args) == 1,
                        lambda e: sp.Function("_ellipe")(e.args[0]))
    struve = getattr(sp, "struve", None)  # not every SymPy version has it
    if struve is not None:
        expr = expr.replace(lambda e: isinstance(e, struve), lambda e: sp.Function("_struve")(*e.args))
    return expr


def _fold_constants(expr):
    """Replace constant transcendental subexpressions (gamma(1/4), sqrt(pi) ...)
    by 20-digit Floats: the float64 export then does not recompute them."""
    def want(e):
        return (e.is_number and not e.is_Rational and not e.is_Atom and e.is_real is not False
                and not isinstance(e, sp.Float))

    def do(e):
        try:
            return sp.Float(sp.N(e, 20), 20)
        except (TypeError, ValueError):
            return e
    return expr.replace(want, do)


# ============================================================== float64 quadrature
def _ts_levels(levels=(8, 16, 32, 64, 128), tmax=6.2):
    """Nested tanh-sinh node sets on [0, 1] for h = 1/8, 1/16, ... : for each
    level the *new* nodes (v, w = 1 - v, both to full relative precision) and
    their weights phi(t) (the level sum is h * sum phi f)."""
    out = []
    hmax = levels[-1]
    kmax = int(tmax * hmax)
    k = np.arange(-kmax, kmax + 1)
    t = k / hmax
    ps = np.pi / 2 * np.sinh(t)
    with np.errstate(over="ignore"):
        v = 1 / (1 + np.exp(-2 * ps))
        w = 1 / (1 + np.exp(2 * ps))
        phi = (np.pi / 2) * np.cosh(t) / np.cosh(ps) ** 2 / 2
    keep = (v > 0) & (w > 0) & (phi > 0)
    seen = np.zeros(k.size, dtype=bool)
    for m in levels:
        step = hmax // m
        sel = (k % step == 0) & keep & ~seen
        seen |= sel
        out.append((1.0 / m, v[sel], w[sel], phi[sel]))
    return out


_TS_LEVELS = _ts_levels()
#: relative change between two tanh-sinh levels below which the finer one is
#: accepted (the method roughly doubles the correct digits per level)
_TS_ACCEPT = 1e-10


def _relations_in(expr, var):
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


class _VectorQuad:
    """Float64 vectorised tanh-sinh quadrature of one ``Integral(f, (s, lo, hi))``.

    For every ordering case of the Piecewise breakpoints relative to (lo, hi)
    the integral is split into sub-intervals [p, q] with *symbolic* ends; on
    each the integrand's branch is resolved, s = p + (q - p) v substituted and
    1 - v named w, the result put in stable form and lambdified in
    (params, v, w).  Evaluation selects the case per point.
    """

    def __init__(self, integral, stable=True, conditions=()):
        self.integral = integral
        f = integral.function
        (s, lo, hi) = integral.limits[0]
        self.params = sorted(integral.free_symbols, key=lambda q: q.name)
        bps = [b for b in _relations_in(f, s) if b.free_symbols <= set(self.params)]
        self.bps = bps
        self.cases = []
        self.conditions = conditions
        v, w = sp.Dummy("v", positive=True), sp.Dummy("w", positive=True)
        self.v, self.w = v, w
        bp_fns = [sp.lambdify(self.params, b, "numpy") for b in bps]
        self.bp_fns = bp_fns
        self.lo_fn = sp.lambdify(self.params, lo, "numpy")
        self.hi_fn = sp.lambdify(self.params, hi, "numpy")
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
                pieces.append(lambdify_numpy(gv, list(self.params) + [v, w], stable=False))
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
            todo = np.flatnonzero(~(err <= _TS_ACCEPT * np.abs(cur)))
            todo = todo[np.isfinite(cur[todo]) | np.isnan(cur[todo])]
            if todo.size == 0:
                break
            h = _TS_LEVELS[lev][0]
            new = cur[todo] / 2 + h * level_sum(lev, todo)
            err[todo] = np.abs(new - cur[todo])
            cur[todo] = new
        rel = err / np.maximum(np.abs(cur), 1e-300)
        est = np.where(rel <= _TS_ACCEPT, 10 * err * np.minimum(rel, 1.0), err) + 4 * 2.2e-16 * np.abs(cur)
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


# ============================================================== lambdify
def lambdify_numpy(expr, args, stable: bool = True, conditions=(), original=None):
    """A float64 NumPy/SciPy function of ``args`` for ``expr``.

    ``stable=True`` (default) evaluates the stable form of ``expr``;
    unevaluated ``Integral`` objects become vectorised tanh-sinh quadratures.
    Removable singularities at an argument = 0 (e.g. x**2*atanh(...) at x = 0)
    are patched with the symbolic limit of ``original`` (default: ``expr``)."""
    original = expr if original is None else original
    if stable:
        expr = stabilize(expr, conditions).expr
    quads = {}
    if expr.has(sp.Integral):
        def to_quad(I):
            q = _VectorQuad(I, stable=stable, conditions=conditions)
            name = f"_quad{len(quads)}"
            quads[name] = q
            return sp.Function(name)(*q.params)
        expr = expr.replace(lambda e: isinstance(e, sp.Integral), to_quad)
    mods = [dict(_SCIPY_FUNCS, _mphyper=_mp_hyper_vec, **NUMPY_FUNCS, **quads), "scipy", "numpy"]
    f = sp.lambdify(args, _to_scipy_names(_fold_constants(expr)), modules=mods, cse=True)
    patches = []
    for i, sym in enumerate(args):
        lim = _removable_limit(original, sym)
        if lim is not None:
            g = lambdify_numpy(lim, args, stable=stable, conditions=conditions)
            patches.append((i, g))
    if not patches:
        return f

    def patched(*vals):
        out = f(*vals)
        for i, g in patches:
            at0 = np.asarray(vals[i]) == 0
            if np.any(at0):
                shape = np.broadcast_shapes(*[np.shape(v) for v in vals])
                out = np.array(np.broadcast_to(out, shape), dtype=float)
                out[np.broadcast_to(at0, shape)] = np.broadcast_to(g(*vals), shape)[np.broadcast_to(at0, shape)]
                out = out[()] if out.ndim == 0 else out
        return out
    return patched


def _removable_limit(expr, sym):
    """lim_{sym -> 0+} expr if expr is undefined (nan) at sym = 0 but the limit
    is finite; else None."""
    if expr.has(sp.Integral) or sym not in expr.free_symbols or sp.count_ops(expr) > 300:
        return None
    try:
        e0 = expr.subs(sym, 0)
    except Exception:
        return None
    if not (e0.has(sp.nan) or e0 is sp.nan):
        return None
    from ..core.budget import run_with_budget
    try:
        lim = run_with_budget(sp.limit, expr, sym, 0, "+", seconds=10.0)
    except Exception:
        return None
    if lim.has(sp.oo, -sp.oo, sp.zoo, sp.nan, sp.Limit) or sym in lim.free_symbols:
        return None
    return lim


def lambdify_mpmath(expr, args, stable: bool = True, conditions=()):
    """An mpmath function of ``args`` for ``expr`` (precision: the caller's
    ``mpmath.workdps``)."""
    if stable:
        expr = stabilize(expr, conditions).expr
    return sp.lambdify(args, expr, modules=[dict(MPMATH_FUNCS), "mpmath"])


def lambdify_mpmath_quad(expr, args, stable: bool = False):
    """Like :func:`lambdify_mpmath` for expressions holding unevaluated
    ``Integral`` objects: each becomes an ``mpmath.quad`` (tanh-sinh) over
    [lo, breakpoints of a Piecewise integrand inside (lo, hi), hi] at the
    caller's precision.  The integrand is lambdified once."""
    if stable:
        expr = stabilize(expr).expr
    quads = {}

    def to_quad(I):
        (s_, lo, hi) = I.limits[0]
        params = sorted(I.free_symbols, key=lambda q: q.name)
        fI = sp.lambdify([s_] + params, I.function, modules=[dict(MPMATH_FUNCS), "mpmath"])
        lo_f = sp.lambdify(params, lo, "mpmath")
        hi_f = sp.lambdify(params, hi, "mpmath")
        bp_fs = [sp.lambdify(params, b, "mpmath") for b in _relations_in(I.function, s_)
                 if b.free_symbols <= set(params)]

        def q(*vals):
            L, H = lo_f(*vals), hi_f(*vals)
            pts = [L] + sorted({b(*vals) for b in bp_fs if L < b(*vals) < H}) + [H]
            extra = 2 * mpmath.mp.dps + 10
            total = mpmath.mpf(0)
            # each piece in two halves, each parametrised from its own end point
            # (s = p + t, t >= 0 small, formed at twice the digits): integrable
            # end-point singularities never see a node rounded onto the end
            for p_, q_ in zip(pts[:-1], pts[1:]):
                m_ = (p_ + q_) / 2

                def left(t, p_=p_):
                    with mpmath.workdps(extra):
                        return fI(p_ + t, *vals)

                def right(t, q_=q_):
                    with mpmath.workdps(extra):
                        return fI(q_ - t, *vals)
                total += mpmath.quad(left, [0, m_ - p_]) + mpmath.quad(right, [0, q_ - m_])
            return +total
        name = f"_mpquad{len(quads)}"
        quads[name] = q
        return sp.Function(name)(*params)
    expr = expr.replace(lambda e: isinstance(e, sp.Integral), to_quad)
    return sp.lambdify(args, expr, modules=[dict(MPMATH_FUNCS, **quads), "mpmath"])


def stable_form(derivation):
    """The (cached) :class:`~linecontact_sym.stable.StableForm` of a derivation."""
    cache = derivation.__dict__.setdefault("_lcs_numeric_cache", {})
    if "stable" not in cache:
        cache["stable"] = stabilize(derivation.expr, _conditions(derivation))
    return cache["stable"]


def _conditions(derivation):
    conds = [c for c in (derivation.conditions or ()) if isinstance(c, sp.Basic)]
    return tuple(conds)


def _cached_lambdify(derivation, kind, stable):
    cache = derivation.__dict__.setdefault("_lcs_numeric_cache", {})
    key = (kind, stable)
    if key not in cache:
        syms = derivation.variables_all
        expr = stable_form(derivation).expr if stable else derivation.expr
        if kind == "numpy":
            # the stable form's integrands are already stable; the quadratures keep them
            cache[key] = lambdify_numpy(expr, syms, stable=False, conditions=_conditions(derivation),
                                        original=derivation.expr if derivation.closed_form else None)
        else:
            cache[key] = lambdify_mpmath(expr, syms, stable=False)
    return cache[key]


#: long inputs are evaluated in chunks of this many points, so that the chain
#: of ufuncs of an expression runs in cache (about 2x faster on 10^6 points)
CHUNK = 32768


def _chunked(f, vals):
    sizes = [v.size for v in vals]
    if max(sizes) <= 2 * CHUNK:
        return f(*vals)
    shape = np.broadcast_shapes(*[v.shape for v in vals])
    n = int(np.prod(shape))
    flat = [np.broadcast_to(v, shape).reshape(-1) if v.size > 1 else v.reshape(()) for v in vals]
    out = np.empty(n)
    for lo in range(0, n, CHUNK):
        out[lo:lo + CHUNK] = f(*[v[lo:lo + CHUNK] if v.ndim else v for v in flat])
    return out.reshape(shape)


def check_arguments(names, values: dict, quantity: str):
    """Raise :class:`DomainError` naming unknown or missing keyword arguments."""
    unknown = set(values) - set(names)
    if unknown:
        raise DomainError(f"unknown argument(s) {sorted(unknown)}; expected {list(names)}")
    missing = [n for n in names if n not in values]
    if missing:
        raise DomainError(f"missing argument(s) {missing} for {quantity}")


def make_callable(derivation, backend: str = "numpy", dps: int = 30, params: dict | None = None,
                  stable: bool = True):
    """A callable ``fn(**values)`` for a :class:`Derivation`.

    Keyword arguments are the symbol names (``a``, ``x``, ``E_star``, ``R`` ...);
    ``params`` fixes some of them once.  With ``backend='numpy'`` the
    arguments may be arrays (broadcast); with ``'mpmath'`` scalars.
    ``stable`` (default True) evaluates the stable form
    (:mod:`linecontact_sym.stable`).
    """
    params = dict(params or {})
    syms = derivation.variables_all
    names = [s.name for s in syms]

    def collect(kw):
        merged = {**params, **kw}
        check_arguments(names, merged, derivation.quantity)
        return [merged[n] for n in names]

    if backend not in ("numpy", "mpmath"):
        raise ValueError(f"unknown backend {backend!r}; use 'numpy' or 'mpmath'")
    if backend == "numpy":
        f = _cached_lambdify(derivation, "numpy", stable)

        def fn(**kw):
            with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
                vals = [np.asarray(v, dtype=float) for v in collect(kw)]
                return _chunked(f, vals)
    elif derivation.closed_form:
        f = _cached_lambdify(derivation, "mpmath", stable)

        def fn(**kw):
            with mpmath.workdps(dps):
                return +f(*[mpmath.mpf(v) if not isinstance(v, mpmath.mpf) else v for v in collect(kw)])
    else:
        ref = derivation.reference

        def fn(**kw):
            with mpmath.workdps(dps):
                vals = dict(zip(syms, (sp.Float(v, dps) if isinstance(v, mpmath.mpf)
                                       else sp.Float(float(v), 20) if isinstance(v, float)
                                       else to_sympy(v) for v in collect(kw))))
                return ref(vals, dps)
    fn.__doc__ = (f"{derivation.quantity} ({backend}); arguments: {', '.join(names)}.\n"
                  f"Formula: {derivation.expr}\nMethod: {derivation.method}")
    fn.arguments = tuple(names)
    return fn
