"""Accuracy of a float64 function against a high-precision reference.

Generic tools, independent of any quantity's names: :func:`condition_number`
(componentwise relative condition number by high-precision differences of the
reference), :func:`condition_number_float` (the same by float64 differences
of the function itself), :func:`audit` (compare at a list of points, scaling
the error by eps * max(1, kappa)) and its :class:`AccuracyRecord`;
:func:`expressions_agree` (the numeric check of a symbolic identity, used by
:func:`~linecontact_sym.numeric.stable.stabilize`).  The grid
of extreme arguments that the tests and the benchmark audit lives in
``benchmarks/extremes.py``; :mod:`linecontact_sym.numeric.evaluate` uses
:func:`condition_number_float` for its float64 error estimate.

>>> import math
>>> round(condition_number_float(lambda x: x**3, {"x": 2.0}), 6)   # x f'(x)/f(x) = 3
3.0
>>> rec, = audit(lambda x: math.log1p(x), lambda x: mpmath.log(1 + x), [{"x": 1e-10}], dps=30)
>>> rec.ulps <= 1
True
"""
from __future__ import annotations

import math
import random
from dataclasses import dataclass

import mpmath
import numpy as np
import sympy as sp
from ..core.conversion import to_mpf
from ..core.precision import workdps

__all__ = ["EPS", "AccuracyRecord", "condition_number", "condition_number_float", "audit", "expressions_agree"]

EPS = float(np.finfo(float).eps)
#: the magnitudes of the arguments (nonzero) and values at which a float64
#: evaluation is trusted: a product of up to four such arguments, or their
#: quotients, stays a normal float (|v| >= 2.2e-308), so no intermediate power
#: under- or overflows and loses digits silently (pi a^2/(4 R) at a = 1e-160
#: has a^2 = 1e-320, a subnormal with 3 digits); beyond, the mpmath path
FLOAT64_SAFE = (1e-75, 1e75)
#: the smallest normal float64: a value below it holds fewer than 53 bits
FLOAT64_TINY = float(np.finfo(float).tiny)


def float64_safe(vals, v) -> bool:
    """Whether float64 at the arguments ``vals`` giving ``v`` is within its
    range (:data:`FLOAT64_SAFE`; ``v`` a normal float, not 0: an exact zero is
    confirmed by the mpmath path, an underflow is not silently 0)."""
    lo, hi = FLOAT64_SAFE
    return FLOAT64_TINY <= abs(v) < math.inf and all(v_ == 0 or lo <= abs(v_) <= hi for v_ in vals)


@dataclass
class AccuracyRecord:
    """One audited point: the float64 value, the reference, the relative error,
    the condition number kappa and the error in units of eps * max(1, kappa)."""

    point: dict
    value: float            # float64 export
    reference: object       # mpf
    rel_error: float
    kappa: float            # componentwise relative condition number
    ulps: float             # rel_error / (eps * max(1, kappa))

    def __str__(self):
        pt = ", ".join(f"{k}={v:.17g}" for k, v in self.point.items())
        return (f"[{pt}] float64={self.value!r} ref={mpmath.nstr(self.reference, 17)} "
                f"rel.err={self.rel_error:.2e} kappa={self.kappa:.2e} -> {self.ulps:.2f} eps*kappa")


def condition_number(fmp, point: dict, dps: int = 100):
    """The componentwise relative condition number sum_i |x_i df/dx_i| / |f| of
    the mpmath function ``fmp(**point)`` at ``point`` (central differences with
    step 10^-(dps/3) relative, at ``dps`` digits; one-sided at a domain edge);
    NaN if f = 0 or is not finite."""
    with workdps(dps):
        base = {k: mpmath.mpf(v) for k, v in point.items()}
        f0 = fmp(**base)
        if f0 == 0 or not mpmath.isfinite(f0):
            return float("nan")
        total = mpmath.mpf(0)
        h = mpmath.mpf(10) ** (-(dps // 3))
        for k, v in base.items():
            if v == 0:
                continue
            vals = []
            for sgn in (1, -1):
                try:
                    fv = fmp(**{**base, k: v * (1 + sgn * h)})
                    vals.append(fv if (not isinstance(fv, mpmath.mpc) and mpmath.isfinite(fv)) else None)
                except (ValueError, ZeroDivisionError, TypeError):
                    vals.append(None)
            d = _difference(vals, f0, h)
            if d is not None:
                total += abs(d)
        return float(total / abs(f0))


def _difference(vals, f0, h):
    """d/dt of f(x (1 + t)) at t = 0 from ``vals`` = [f(x (1 + h)), f(x (1 - h))]
    (None where not finite): central, else one-sided with ``f0`` = f(x); None
    where neither side is finite."""
    up, down = vals
    if up is not None and down is not None:
        return (up - down) / (2 * h)
    if up is not None:
        return (up - f0) / h
    if down is not None:
        return (f0 - down) / h
    return None


def condition_number_float(f64, point: dict, h: float = 1e-6, f0: float | None = None):
    """The componentwise relative condition number sum_i |x_i df/dx_i| / |f|
    estimated by float64 central differences of ``f64`` itself (step
    ``h`` relative to each nonzero argument, one-sided where one side is not
    finite), for quantities whose reference is too slow to differentiate at
    high precision.  ``f0``: the value at ``point`` if already known.
    Infinite where f = 0, NaN where f is not finite."""
    with np.errstate(all="ignore"):
        if f0 is None:
            f0 = float(np.asarray(f64(**point)))
        if not math.isfinite(f0):
            return float("nan")
        if f0 == 0:
            return math.inf
        total = 0.0
        for k, v in point.items():
            if v == 0:
                continue
            vals = []
            for sgn in (1, -1):
                fv = float(np.asarray(f64(**{**point, k: v * (1 + sgn * h)})))
                vals.append(fv if math.isfinite(fv) else None)
            d = _difference(vals, f0, h)
            if d is not None:
                total += abs(d)
        return total / abs(f0)


def _real_or_none(r, dps):
    if isinstance(r, mpmath.mpc):
        if abs(r.imag) <= abs(r.real) * mpmath.mpf(10) ** (-dps // 2):
            return r.real
        return None
    if not mpmath.isfinite(r):
        return None
    return r


def _reference(fmp, pt, dps):
    """(value, singular) of fmp at pt.  Where the formula is singular
    (removable: 0*inf, 0/0 ...) the limit approached from a point displaced by
    10^-(dps/2) in one argument (singular=True); NaN outside the real domain."""
    with workdps(dps):
        args = {k: mpmath.mpf(x) for k, x in pt.items()}
        try:
            r0 = fmp(**args)
            r = _real_or_none(r0, dps)
            if r is None and isinstance(r0, mpmath.mpc) and mpmath.isfinite(r0):
                return mpmath.nan, False          # complex: outside the domain
        except (ZeroDivisionError, ValueError):
            r = None
        if r is not None:
            return r, False
        def displaced(k, x, h):
            for cand in ((x * (1 + h), x * (1 - h)) if x != 0 else (h,)):
                try:
                    r = _real_or_none(fmp(**{**args, k: cand}), dps)
                except (ZeroDivisionError, ValueError):
                    r = None
                if r is not None:
                    return r
            return None
        h = mpmath.mpf(10) ** (-(dps // 2))
        for k, x in args.items():
            r = displaced(k, x, h)
            if r is not None:
                # a limit approached like a power of the displacement (e.g.
                # sqrt(a - x) at x = a): a displacement h**(3/2) shows it
                r2 = displaced(k, x, h * mpmath.sqrt(h))
                if r2 is not None and abs(r2) < abs(r) * mpmath.mpf(10) ** (-(dps // 16)):
                    return mpmath.mpf(0), True
                return r, True
        return mpmath.inf, True


def audit(f64, fmp, points, dps: int = 100, kappa: str = "mp", kappa_dps: int = 40):
    """Compare a float64 function with an mpmath reference at ``points``
    (dicts name -> float).  Returns the list of :class:`AccuracyRecord`.

    ``kappa``: 'mp' (condition number by differences of the reference at
    ``kappa_dps`` digits -- it only scales the tolerance),
    'float' (by float64 differences of ``f64``), or None (taken as 1).
    Where the reference formula is singular the limit is used (approached
    from a displaced point); a float64 value of +-inf passes where that
    limit is infinite or beyond the float64 range, and a zero reference (or a
    limit below 1e-30) requires |value| < 1e-290; an exact float64 zero
    passes against a reference below 10^-(dps/2) (noise of a formula that
    cancels to zero, e.g. a gap at x = a)."""
    out = []
    for pt in points:
        with np.errstate(all="ignore"):
            v = float(np.asarray(f64(**pt)))
        r, singular = _reference(fmp, pt, dps)
        if mpmath.isnan(r):
            continue                               # outside the real domain: not audited
        if singular and math.isinf(v):
            out.append(AccuracyRecord(pt, v, r, 0.0, 1.0, 0.0))
            continue
        if mpmath.isinf(r) or abs(r) > 1e300:
            ok = math.isinf(v) or abs(v) > 1e300
            out.append(AccuracyRecord(pt, v, r, 0.0 if ok else math.inf, 1.0, 0.0 if ok else math.inf))
            continue
        if r == 0 or abs(r) < 1e-300 or (singular and abs(r) < 1e-30) or \
                (v == 0 and abs(r) < mpmath.mpf(10) ** (-(dps // 2))):
            # a zero (the last case: an exact float64 zero where the reference
            # is rounding noise of a cancelling formula, e.g. a gap at x = a)
            ok = abs(v) < 1e-290
            out.append(AccuracyRecord(pt, v, r, 0.0 if ok else math.inf, 1.0, 0.0 if ok else math.inf))
            continue
        rel = float(abs((mpmath.mpf(v) - r) / r)) if math.isfinite(v) else math.inf
        if kappa == "mp" and not singular:
            k = condition_number(fmp, pt, kappa_dps)
        elif kappa in ("mp", "float"):
            k = condition_number_float(f64, pt)
        else:
            k = 1.0
        k = 1.0 if not math.isfinite(k) else k
        out.append(AccuracyRecord(pt, v, r, rel, k, rel / (EPS * max(1.0, k))))
    return out


# ---------------------------------------------------------------- symbolic identities
def _sample_point(syms, conditions, rng, tries=200):
    for _ in range(tries):
        vals = {s: sp.Rational(rng.randint(5, 300), 100) for s in syms}
        ok = True
        for c in conditions:
            try:
                if not bool(c.xreplace(vals)):
                    ok = False
                    break
            except TypeError:
                ok = False
                break
        if ok:
            return vals
    return None


def _mp_value(expr, vals, dps=30):
    with workdps(dps):
        v = sp.N(expr.xreplace(vals), dps)
        if v.is_Float or v.is_Rational:
            return to_mpf(v)                       # the one converter
        re_, im = (sp.N(t, dps) for t in v.as_real_imag())
        if (re_.is_Float or re_.is_zero) and (im.is_Float or im.is_zero):
            return mpmath.mpc(to_mpf(re_), to_mpf(im))   # all dps digits, not a Python complex
        v = complex(v) if not v.is_real else v
        if isinstance(v, complex):
            return mpmath.mpc(v.real, v.imag)
        return mpmath.mpf(str(v)) if v.is_Float else mpmath.mpf(sp.N(v, dps))


def _outside_elliptic_domain(e, vals) -> bool:
    """True if an elliptic integral of ``e`` has its parameter m (or its
    characteristic n) >= 1 at ``vals``, or a Carlson integral a negative
    argument: there they are complex, and mpmath takes seconds to minutes to
    say so."""
    from .special import carlson_rd, carlson_rf, carlson_rg, carlson_rj

    def value(p):
        try:
            return float(p.xreplace(vals))
        except (TypeError, ValueError):
            return float("nan")
    for f in e.atoms(sp.elliptic_k, sp.elliptic_e, sp.elliptic_f, sp.elliptic_pi):
        params = [f.args[-1]] + ([f.args[0]] if isinstance(f, sp.elliptic_pi) else [])
        if not all(value(p) < 1 for p in params):
            return True
    for f in e.atoms(carlson_rf, carlson_rd, carlson_rg, carlson_rj):   # real for arguments >= 0
        if not all(value(p) >= 0 for p in f.args):
            return True
    return False


def expressions_agree(e1, e2, syms, conditions=(), n=3, seed=11) -> tuple[bool, str]:
    """(ok, why): do the SymPy expressions e1 and e2 agree to 20 digits
    (30-digit evaluation) at ``n`` random rational points of ``syms`` in
    [0.05, 3] where ``conditions`` hold?  Points where e1 is not real and
    finite are skipped (outside its domain); if none is left the answer is
    (True, "not checked ...").  Integrals are compared by their integrands."""
    if e1.has(sp.Integral) or e2.has(sp.Integral):
        e1 = e1.replace(lambda e: isinstance(e, sp.Integral), lambda e: e.function)
        e2 = e2.replace(lambda e: isinstance(e, sp.Integral), lambda e: e.function)
        syms = sorted(e1.free_symbols | e2.free_symbols, key=lambda s: s.name)
        conditions = ()
    rng = random.Random(seed)
    checked = 0
    for _ in range(n * 4):
        vals = _sample_point(syms, conditions, rng)
        if vals is None:
            break
        if _outside_elliptic_domain(e1, vals):
            continue  # a parameter n or m >= 1: complex, and slow in mpmath
        try:
            v1 = _mp_value(e1, vals)
        except (TypeError, ValueError, ZeroDivisionError):
            continue
        if isinstance(v1, mpmath.mpc) or not mpmath.isfinite(v1):
            continue  # outside the real domain of the original
        try:
            v2 = _mp_value(e2, vals)
        except (TypeError, ValueError, ZeroDivisionError) as exc:
            return False, f"rewritten form fails at {vals}: {exc}"
        if abs(v1 - v2) > mpmath.mpf(10)**-20 * max(abs(v1), mpmath.mpf(10)**-10):
            return False, f"values differ at {vals}: {v1} vs {v2}"
        checked += 1
        if checked >= n:
            break
    if checked == 0:
        return True, "not checked (no admissible sample point)"
    return True, f"checked at {checked} points"
