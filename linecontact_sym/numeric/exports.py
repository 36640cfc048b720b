"""Export derived quantities as fast numeric callables.

Backends
--------
``"numpy"``  vectorised float64 (NumPy + ``scipy.special``).  By default the
             expression is first put in its *stable form*
             (:func:`linecontact_sym.numeric.stable.stabilize`: Carlson forms for
             K - E, Gamma ratios without overflow, asinh/atan forms of
             atanh/acosh/asin near 1, 2F1 with the complementary argument,
             factored differences of squares), so the export stays accurate at
             the extremes of its arguments (see ``tests/test_extremes.py`` for
             the documented grid).  Special functions map to SciPy: the Carlson
             integrals to ``elliprf/elliprd/elliprg``, elliptic_k(m) to
             ``ellipk(m)`` (both take the parameter m = k**2), 2F1/1F1/0F1 to
             ``hyp2f1``/``hyp1f1``/``hyp0f1``; anything SciPy lacks is evaluated
             point by point with mpmath at 20 digits.
             Unevaluated integrals (no closed form) are evaluated by the
             vectorised float64 tanh-sinh quadrature of
             :mod:`linecontact_sym.numeric.quadrature`.
``"mpmath"`` arbitrary precision at ``dps`` digits (``mpmath.workdps``; the
             global precision is never changed); the stable form is used too.
             Unevaluated integrals are evaluated by the derivation's reference
             quadrature (:func:`lambdify_mpmath_quad` is a faster generic
             alternative).

``stable=False`` gives the plain translation of the expression as derived.
Exports are cached per derivation (stabilising and lambdifying once) in a
cache of this module, not in the derivation (:mod:`.cache`).
Removable singularities at an argument = 0 (e.g. x**2*atanh(sqrt(a**2 -
x**2)/a) at x = 0) are patched with the symbolic limit.
"""
from __future__ import annotations

import functools
import math

import mpmath
import numpy as np
import sympy as sp

from ..core import symbols as S
from ..core.conversion import point_value, to_mpf
from ..core.errors import DomainError, LineContactError, singular_point
from ..core.ranges import NEVER_ZERO
from ..core.lazy import lazy_module
from ..core.printing import lambdify
from ..parsing import to_sympy
from .cache import IdentityCache
from .quadrature import VectorQuad, piecewise_breakpoints
from .special import MPMATH_FUNCS, NUMPY_FUNCS, NUMPY_LOGIC, mp_elliptic_pi
from .stable import is_rational_in_symbols, stabilize
from .stable_elliptic import EllipticPiToCarlson

_TO_CARLSON = EllipticPiToCarlson()
from ..core.precision import workdps

sc = lazy_module("scipy.special")     # loaded when a float64 function is first built


def _scipy_funcs() -> dict:
    """The special functions of the NumPy export, by their printed names."""
    return {"_ellipk": sc.ellipk, "_ellipe": sc.ellipe, "_hyp2f1": sc.hyp2f1,
            "_hyp1f1": sc.hyp1f1, "_hyp0f1": sc.hyp0f1, "_struve": sc.struve}


def mp_hyper_vec(*args):
    p = int(args[0])
    ap, bq, z = args[1:1 + p], args[1 + p:-1], args[-1]

    def one(*vals):
        with workdps(20):
            return float(mpmath.hyper(vals[:p], vals[p:-1], vals[-1]))
    return np.vectorize(one, otypes=[float])(*ap, *bq, z)


def to_scipy_names(expr):
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


def fold_constants(expr):
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


# ============================================================== lambdify
def lambdify_numpy(expr, args, stable: bool = True, conditions=(), original=None, patch=None):
    """A float64 function ``f(*values)`` computing ``expr`` at ``args`` = values
    (``args`` a list of symbols; NumPy arrays broadcast).

    ``stable=True`` (default) evaluates the stable form of ``expr``
    (:func:`~linecontact_sym.numeric.stable.stabilize`, its rewrites checked
    where ``conditions`` hold); unevaluated ``Integral`` objects become
    vectorised tanh-sinh quadratures
    (:class:`~linecontact_sym.numeric.quadrature.VectorQuad`).  Removable
    singularities at an argument = 0 (e.g. x**2*atanh(...) at x = 0) are
    patched with the symbolic limit of ``original`` (default: ``expr``), for
    the arguments in ``patch`` (default: all; an argument that is never 0 in
    the quantity's domain, e.g. a or E_star, need not be tried).
    Domain: real arguments where ``expr`` is real (elsewhere NaN).

    K(m) - E(m) = (pi m/4)(1 + 3m/8 + ...) at m = 1e-10: the plain
    translation loses six digits to cancellation, the stable form none.

    >>> import sympy as sp
    >>> m = sp.Symbol("m", positive=True)
    >>> k_minus_e = sp.elliptic_k(m) - sp.elliptic_e(m)
    >>> exact = 3.141592653589793e-10 / 4 * (1 + 3e-10 / 8)
    >>> bool(abs(lambdify_numpy(k_minus_e, [m])(1e-10) / exact - 1) < 1e-15)
    True
    >>> bool(abs(lambdify_numpy(k_minus_e, [m], stable=False)(1e-10) / exact - 1) > 1e-9)
    True
    """
    original = expr if original is None else original
    if stable:
        expr = stabilize(expr, conditions).expr
    elif _TO_CARLSON.applies(expr):   # SciPy has no Pi(n|m), F(phi|m), E(phi|m): Carlson forms
        expr = _TO_CARLSON.apply(expr)
    quads = {}
    if expr.has(sp.Integral):
        if has_nested_integral(expr):
            # replace works from the inside out: the outer quadrature compiled the inner
            # one as an undefined function (a NameError at the first call)
            raise LineContactError("no float64 export of a nested integral (an integral inside an "
                                   "integrand); the mpmath export or the derivation's reference evaluates it")

        def to_quad(I):
            q = VectorQuad(I, compile_plain_numpy, stable=stable, conditions=conditions)
            name = f"_quad{len(quads)}"
            quads[name] = q
            return sp.Function(name)(*q.params)
        expr = expr.replace(lambda e: isinstance(e, sp.Integral), to_quad)
    mods = [dict(_scipy_funcs(), _mphyper=mp_hyper_vec, **NUMPY_FUNCS, **NUMPY_LOGIC, **quads), "scipy", "numpy"]
    f = lambdify(args, to_scipy_names(fold_constants(expr)), modules=mods, cse=True)
    patches = []
    for i, sym in enumerate(args):
        if patch is not None and sym not in patch:
            continue
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


def compile_plain_numpy(expr, args, patch=None):
    """:func:`lambdify_numpy` of ``expr`` as it is (no stable rewriting): the
    compiler :class:`~linecontact_sym.numeric.quadrature.VectorQuad` uses for
    the pieces of an integrand that is already in stable form (``patch``:
    the arguments whose removable limit at 0 is sought, default all)."""
    return lambdify_numpy(expr, args, stable=False, patch=patch)


def has_nested_integral(expr) -> bool:
    """Does an unevaluated Integral of ``expr`` hold another in its integrand?"""
    return any(I.function.has(sp.Integral) for I in expr.atoms(sp.Integral))


def _removable_limit(expr, sym):
    """lim_{sym -> 0+} expr if expr is undefined (nan) at sym = 0 but the limit
    is finite; else None (at once for what is not an expression: SymPy
    takes no limit of a Tuple)."""
    if not isinstance(expr, sp.Expr) or expr.has(sp.Integral) or sym not in expr.free_symbols or sp.count_ops(expr) > 300:
        return None
    return _sought_limit(expr, sym)


# each limit is sought once in this process: every new contact of a profile compiles
# the same exports (the exact cylinder's dP/da at a -> 0+, 1 CPU s, once per contact before)
@functools.lru_cache(maxsize=512)
def _sought_limit(expr, sym):
    try:
        e0 = expr.subs(sym, 0)
    except Exception:
        return None
    if not (e0.has(sp.nan) or e0 is sp.nan):
        return None
    # a limit that SymPy cannot find costs its whole budget (E* R (K(a^2/R^2) - E(a^2/R^2))
    # at R -> 0+: 10 CPU s): the failure is remembered (in this process and on
    # disk), so no export waits for it twice.  Only the failure is kept: a
    # record can at most withhold a patch (NaN at sym = 0), never plant a value.
    from ..core.budget import run_with_budget
    from ..method import store
    key = store.make_key("removable limit fails", expr, sym)
    if store.get(key) is not None:
        return None
    try:
        lim = run_with_budget(sp.limit, expr, sym, 0, "+", seconds=10.0)
    except Exception:
        lim = None
    if lim is None or lim.has(sp.oo, -sp.oo, sp.zoo, sp.nan, sp.Limit, sp.AccumBounds) or sym in lim.free_symbols:
        store.put(key, {"fails": True})
        return None
    return lim


#: the mpmath namespace of the exports: the stable primitives, and Pi(n|m) for
#: n > 1 by its principal value (mpmath's own integrates numerically there)
_MP_MODULE = dict(MPMATH_FUNCS, elliptic_pi=mp_elliptic_pi)


def lambdify_mpmath(expr, args, stable: bool = True, conditions=()):
    """An mpmath function ``f(*values)`` computing ``expr`` at ``args`` = values,
    at the caller's precision (``mpmath.workdps``; the global precision is
    never changed).

    ``stable=True`` (default) evaluates the stable form (rewrites checked where
    ``conditions`` hold): fewer digits are lost to cancellation, so a given
    accuracy needs a lower working precision.  The stable primitives map to
    :data:`~linecontact_sym.numeric.special.MPMATH_FUNCS`.  Domain: scalar
    arguments where ``expr`` is defined; complex results are returned as
    ``mpc``.  No unevaluated integrals (see :func:`lambdify_mpmath_quad`).

    >>> import mpmath, sympy as sp
    >>> m = sp.Symbol("m", positive=True)
    >>> f = lambdify_mpmath(sp.elliptic_k(m) - sp.elliptic_e(m), [m])
    >>> with workdps(30):
    ...     print(f(mpmath.mpf("1e-10")))
    7.85398163426900740744905934376e-11
    """
    if stable:
        expr = stabilize(expr, conditions).expr
    return lambdify(args, expr, modules=[_MP_MODULE, "mpmath"])


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
        fI = lambdify([s_] + params, I.function, modules=[dict(MPMATH_FUNCS), "mpmath"])
        lo_f = lambdify(params, lo, "mpmath")
        hi_f = lambdify(params, hi, "mpmath")
        bp_fs = [lambdify(params, b, "mpmath") for b in piecewise_breakpoints(I.function, s_)
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
                    with workdps(extra):
                        return fI(p_ + t, *vals)

                def right(t, q_=q_):
                    with workdps(extra):
                        return fI(q_ - t, *vals)
                total += mpmath.quad(left, [0, m_ - p_]) + mpmath.quad(right, [0, q_ - m_])
            return +total
        name = f"_mpquad{len(quads)}"
        quads[name] = q
        return sp.Function(name)(*params)
    expr = expr.replace(lambda e: isinstance(e, sp.Integral), to_quad)
    return lambdify(args, expr, modules=[dict(MPMATH_FUNCS, **quads), "mpmath"])


#: stable forms and compiled functions per Derivation, kept here, not in the
#: derivation (see :mod:`linecontact_sym.numeric.cache`)
_CACHE = IdentityCache()


def stable_form(derivation):
    """The (cached) :class:`~linecontact_sym.numeric.stable.StableForm` of a
    derivation's expression, its rewrites checked under its conditions."""
    cache = _CACHE.of(derivation)
    if "stable" not in cache:
        cache["stable"] = stabilize(derivation.expr, _conditions(derivation))
    return cache["stable"]


def _conditions(derivation):
    conds = [c for c in (derivation.conditions or ()) if isinstance(c, sp.Basic)]
    return tuple(conds)


def _zero_in_domain(derivation):
    """The arguments that may be 0 in the quantity's domain (where a removable
    singularity needs its limit): not those every contact refuses at 0
    (:data:`~linecontact_sym.core.ranges.NEVER_ZERO`: a, E*, R, ...), and not
    x for a gap (|x| >= a > 0).  Each limit tried costs up to seconds of SymPy
    (the exact cylinder's at R -> 0+ fails after 1-3 CPU s)."""
    never = NEVER_ZERO | ({S.x} if derivation.quantity == "gap" else set())
    return tuple(s for s in derivation.variables_all if s not in never)


def _cached_lambdify(derivation, kind, stable):
    cache = _CACHE.of(derivation)
    key = (kind, stable)
    if key not in cache:
        syms = derivation.variables_all
        expr = stable_form(derivation).expr if stable else derivation.expr
        if kind == "numpy":
            # the stable form's integrands are already stable; the quadratures keep them
            cache[key] = lambdify_numpy(expr, syms, stable=False, conditions=_conditions(derivation),
                                        original=derivation.expr if derivation.closed_form else None,
                                        patch=_zero_in_domain(derivation))
        else:
            cache[key] = lambdify_mpmath(expr, syms, stable=False)
    return cache[key]


def cancellation_sums(derivation):
    """The sums of the stable form that are not rational functions of the
    symbols (those are formed exactly, or their error is covered by the
    condition number), as (sum of |terms|, sum) pairs of expressions: their
    ratio at a point is the amplification of rounding errors by cancellation."""
    cache = _CACHE.of(derivation)
    if "cancel_sums" not in cache:
        expr = stable_form(derivation).expr
        syms = set(derivation.variables_all)
        pairs = []
        for node in sp.preorder_traversal(expr):
            if isinstance(node, sp.Integral):
                continue
            if node.is_Add and not is_rational_in_symbols(node) and not node.is_number \
                    and node.free_symbols <= syms:
                pairs.append((sp.Add(*[sp.Abs(t) for t in node.args]), node))
        cache["cancel_sums"] = pairs
    return cache["cancel_sums"]


def cancellation_probe(derivation):
    """A vectorised float64 function of the arguments (``variables_all``
    order) giving the largest cancellation ratio sum(|terms|)/|sum| over
    :func:`cancellation_sums` (1 where there is none or it is not finite)."""
    cache = _CACHE.of(derivation)
    if "cancel_probe" not in cache:
        pairs = cancellation_sums(derivation)
        syms = derivation.variables_all
        if not pairs:
            cache["cancel_probe"] = lambda *vals: np.ones(np.broadcast_shapes(*[np.shape(v) for v in vals]))
        else:
            # no removable-limit patch: SymPy takes no limit of a Tuple (it raised
            # after seconds of work per argument), and a ratio that is NaN at a
            # point is skipped below anyway
            g = lambdify_numpy(sp.Tuple(*[e for pair in pairs for e in pair]), syms, stable=False, patch=())

            def probe(*vals):
                with np.errstate(all="ignore"):
                    out = [np.asarray(v, dtype=float) for v in g(*vals)]
                    worst = np.ones(np.broadcast_shapes(*[o.shape for o in out] + [np.shape(v) for v in vals]))
                    for A, Sm in zip(out[::2], out[1::2]):
                        r = A / np.abs(Sm)          # inf: the sum cancelled to 0 exactly
                        worst = np.where(~np.isnan(r) & (r > worst), r, worst)
                return worst
            cache["cancel_probe"] = probe
    return cache["cancel_probe"]


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


#: cancellation ratio above which a guarded export recomputes a point with mpmath
GUARD_RATIO = 16.0


#: rules whose closed forms are known to cancel beyond the condition number
GUARDED_RULES = ("gap_swap", "pressure_swap")


def is_guarded(derivation) -> bool:
    """Closed forms that can cancel beyond what the condition number allows:
    those with elliptic integrals of the third kind (Pi(n|m) diverges as
    n -> 1; the exact cylinder's gap cancels terms of size R to O(a^2/R)) and
    the results of the order-swap rules (gaps: sums of O(1) terms near the
    edge, where the gap is O((x - a)^(3/2)), and at large x; pressures: the
    limit at a tangent-continuous join)."""
    if not derivation.closed_form:
        return False
    from .special import carlson_rj
    return derivation.rule in GUARDED_RULES or stable_form(derivation).expr.has(carlson_rj)


def _guard(f, probe, fmp):
    """f, but points whose sums cancel by more than :data:`GUARD_RATIO`
    (:func:`cancellation_probe`) are recomputed by mpmath with
    20 + log10(ratio) digits."""
    def guarded(*vals):
        out = np.asarray(f(*vals), dtype=float)
        ratio = np.asarray(probe(*vals), dtype=float)
        bad = ratio > GUARD_RATIO
        if not np.any(bad):
            return out
        shape = np.broadcast_shapes(out.shape, ratio.shape, *[np.shape(v) for v in vals])
        out = np.array(np.broadcast_to(out, shape), dtype=float)
        full = [np.broadcast_to(np.asarray(v, dtype=float), shape) for v in vals]
        rb = np.broadcast_to(ratio, shape)
        for idx in np.argwhere(np.broadcast_to(bad, shape)):
            idx = tuple(idx)
            out[idx] = _mp_confirmed(fmp, [float(t[idx]) for t in full], rb[idx])
        return out[()] if out.ndim == 0 else out
    return guarded


def _mp_confirmed(fmp, args, ratio):
    """fmp at ``args`` to float64 accuracy: 20 + log10(ratio) digits (40 where
    the sum cancelled to 0), raised until two precisions 20 digits apart agree."""
    digits = 40 if not math.isfinite(ratio) else 20 + int(math.ceil(math.log10(ratio)))
    prev = None
    for _ in range(6):
        with workdps(digits):
            try:
                v = fmp(*[mpmath.mpf(t) for t in args])
            except (ValueError, ZeroDivisionError, TypeError):
                return np.nan
            if isinstance(v, mpmath.mpc):
                return np.nan
        if prev is not None and abs(v - prev) <= 1e-17 * abs(v):
            return float(v)
        prev = v
        digits += 20
    return float(prev)


def check_arguments(names, values: dict, quantity: str):
    """Raise :class:`DomainError` naming unknown or missing keyword arguments."""
    unknown = set(values) - set(names)
    if unknown:
        raise DomainError(f"unknown argument(s) {sorted(unknown)}; expected {list(names)}")
    missing = [n for n in names if n not in values]
    if missing:
        raise DomainError(f"missing argument(s) {missing} for {quantity}")


def compile_callable(derivation, backend="numpy", dps=30, params=None, stable=True):
    """The closure behind a :class:`~.functions.NumericFunction` (holds no reference to
    the derivation: the package caches it per derivation, weakly keyed)."""
    params = dict(params or {})
    syms = derivation.variables_all
    names = [s.name for s in syms]
    quantity = derivation.quantity   # the closures below must not hold the derivation

    def collect(kw):
        merged = {**params, **kw}
        check_arguments(names, merged, quantity)
        return [merged[n] for n in names]

    # where the result does not hold (a < R fails, ...) the value is NaN, never the formula's number
    conds = tuple(getattr(derivation, "point_test", ()))
    holds_at = lambdify(list(syms), sp.And(*conds), [NUMPY_LOGIC, "numpy"]) if conds else None
    if backend == "numpy":
        f = _cached_lambdify(derivation, "numpy", stable)
        if stable and is_guarded(derivation):
            f = _guard(f, cancellation_probe(derivation), _cached_lambdify(derivation, "mpmath", True))

        def fn(**kw):
            with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
                vals = [np.asarray(v, dtype=float) for v in collect(kw)]
                out = _chunked(f, vals)
                if holds_at is not None:
                    ok = np.asarray(holds_at(*vals), dtype=bool)
                    if not np.all(ok):
                        out = np.where(ok, out, np.nan)
                return out[()] if isinstance(out, np.ndarray) and out.ndim == 0 else out
    elif derivation.closed_form:
        f = _cached_lambdify(derivation, "mpmath", stable)

        def fn(**kw):
            with workdps(dps):
                args = [to_mpf(to_sympy(v) if isinstance(v, str) else v) for v in collect(kw)]
                if holds_at is not None and not bool(holds_at(*[float(v) for v in args])):
                    return mpmath.mpf("nan")
                return +f(*args)
    else:
        ref = derivation.reference

        def fn(**kw):
            with workdps(dps):
                vals = dict(zip(syms, (point_value(to_sympy(v) if isinstance(v, str) else v)
                                       for v in collect(kw))))
                return ref(vals, dps)
    return fn
