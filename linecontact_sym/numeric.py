"""Export derived quantities as fast numeric callables.

Backends
--------
``"numpy"``  vectorised float64 (NumPy + ``scipy.special``).  Special
             functions are mapped explicitly: elliptic_k(m) -> scipy's
             ``ellipk(m)`` (both take the parameter m = k**2), elliptic_e(m) ->
             ``ellipe(m)``, 2F1/1F1/0F1 -> ``hyp2f1``/``hyp1f1``/``hyp0f1``;
             anything SciPy lacks is evaluated point by point with mpmath at
             20 digits.  Accuracy: that of the formula in float64 (see the
             issue on stable numerics for the extremes).
``"mpmath"`` arbitrary precision at ``dps`` digits (``mpmath.workdps``; the
             global precision is never changed).

Unevaluated integrals (no closed form) are exported as their defining
quadrature (mpmath), vectorised over NumPy arrays.
"""
from __future__ import annotations

import numpy as np
import mpmath
import scipy.special as sc
import sympy as sp

from .errors import DomainError

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
    expr = expr.replace(lambda e: type(e).__name__ == "struve", lambda e: sp.Function("_struve")(*e.args))
    return expr


def lambdify_numpy(expr, args):
    mods = [dict(_SCIPY_FUNCS, _mphyper=_mp_hyper_vec), "scipy", "numpy"]
    return sp.lambdify(args, _to_scipy_names(expr), modules=mods)


def lambdify_mpmath(expr, args):
    return sp.lambdify(args, expr, modules="mpmath")


def make_callable(derivation, backend: str = "numpy", dps: int = 30, params: dict | None = None):
    """A callable ``fn(**values)`` for a :class:`Derivation`.

    Keyword arguments are the symbol names (``a``, ``x``, ``E_star``, ``R`` ...);
    ``params`` fixes some of them once.  With ``backend='numpy'`` the
    arguments may be arrays (broadcast); with ``'mpmath'`` scalars.
    """
    params = dict(params or {})
    syms = derivation.variables_all
    names = [s.name for s in syms]

    def collect(kw):
        merged = {**params, **kw}
        unknown = set(merged) - set(names)
        if unknown:
            raise DomainError(f"unknown argument(s) {sorted(unknown)}; expected {names}")
        missing = [n for n in names if n not in merged]
        if missing:
            raise DomainError(f"missing argument(s) {missing} for {derivation.quantity}")
        return [merged[n] for n in names]

    if backend not in ("numpy", "mpmath"):
        raise ValueError(f"unknown backend {backend!r}; use 'numpy' or 'mpmath'")
    if derivation.closed_form:
        if backend == "numpy":
            f = lambdify_numpy(derivation.expr, syms)

            def fn(**kw):
                with np.errstate(invalid="ignore", divide="ignore"):
                    vals = [np.asarray(v, dtype=float) for v in collect(kw)]
                    return f(*vals)
        else:
            f = lambdify_mpmath(derivation.expr, syms)

            def fn(**kw):
                with mpmath.workdps(dps):
                    return +f(*[mpmath.mpf(v) if not isinstance(v, mpmath.mpf) else v for v in collect(kw)])
    else:
        ref = derivation.reference

        def one(*vals, _dps):
            return ref(dict(zip(syms, (sp.Float(float(v), 20) if not isinstance(v, mpmath.mpf) else sp.Float(v, _dps) for v in vals))), _dps)

        if backend == "numpy":
            vec = np.vectorize(lambda *v: float(one(*v, _dps=17)), otypes=[float])

            def fn(**kw):
                return vec(*collect(kw))
        else:
            def fn(**kw):
                with mpmath.workdps(dps):
                    return one(*collect(kw), _dps=dps)
    fn.__doc__ = (f"{derivation.quantity} ({backend}); arguments: {', '.join(names)}.\n"
                  f"Formula: {derivation.expr}\nMethod: {derivation.method}")
    fn.arguments = tuple(names)
    return fn
