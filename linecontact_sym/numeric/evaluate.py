"""Ask for an accuracy, get the cheapest way to it.

:func:`evaluate` takes a contact, a quantity and the values of its
arguments, and a tolerance (``rtol``) or a demand for a certified result, and
picks the cheapest evaluation that meets it:

``model:<...>``
    "Model only what is needed": for the force law of a profile analytic at
    x = 0 (e.g. the exact cylinder), the leading terms of the series of P(a),
    obtained termwise from the profile's Taylor series (each term c_k x^(k+1)
    of f contributes E* c_k (k+1) B_k a^(k+1), B_k = int_0^1 u^(k+1)/sqrt(1-u^2)),
    when an error bound on the truncated tail meets ``rtol``.  One term is the
    force law of the profile's leading Taylor term: for the cylinder the
    parabola x^2/(2R), i.e. Hertz.  Used when the closed form needs special
    functions (or a quadrature) or when ``rtol`` is beyond float64.
``float64``
    the stable NumPy export (:mod:`linecontact_sym.numeric`), when its error
    estimate 8 eps max(1, kappa, cancellation) |value| meets ``rtol``.  kappa
    is the componentwise condition number (float64 differences); the factor 8
    is what ``tests/test_extremes.py`` checks on the extreme grid;
    "cancellation" is the largest sum(|terms|)/|sum| over the non-polynomial
    sums of the stable form at the point (it catches the documented weak
    spots, e.g. the power-law gap for n -> 0).  Quantities without a closed
    form: factor 16, plus the quadrature's own error estimate.
``mpmath@N``
    the stable closed form (or the quadrature of the defining integral) with
    mpmath at N digits, N chosen from rtol and kappa, confirmed by a second
    evaluation at N + 10 digits (raised until the two agree to rtol).
``arb``
    ``certified=True``: a python-flint Arb ball, a rigorous enclosure of the
    exact value for the inputs as given (floats are exact binary numbers;
    pass strings or Rationals for exact decimals), with ``dps`` correct digits
    (default 15, or from rtol).  Also, unasked, a quantity without closed form
    (unevaluated integrals) beyond float64: one Arb enclosure of its
    integrals (:func:`~linecontact_sym.numeric.reference.integrate`) where
    Arb evaluates the integrand, its radius the error (a true bound), in
    place of two mpmath quadratures compared (an estimate, and several
    seconds with special-function integrands); the mpmath path otherwise.
    ``certified=True`` takes the same enclosure for such a quantity (a
    :class:`~.certified.CertificationError` where Arb cannot enclose it).
    The enclosure is [mid - rad, mid + rad] exactly: its width is twice the
    error the result states, at the precision asked.

Float64 is taken only at normal values and arguments within
:data:`~.accuracy.FLOAT64_SAFE` (1e-75 .. 1e75): an underflow to 0 or a
subnormal intermediate (a^2 at a = 1e-160) is never a float64 result with a
relative error; such points take the mpmath path (the series model: its
terms in mpmath).

The returned :class:`Evaluation` says which path was taken, with the error
estimate (or the enclosure) and a note on why.

``contact.evaluate(...)`` at a point of plain Python numbers runs the same
steps from a plan found once per quantity (:func:`scalar_evaluator`: the
derivation, its scalar function, the series model, the domain check's plan,
a monomial's exact condition number), with no per-call look-ups; the note
is formatted when it is read.

    >>> import linecontact_sym as lcs
    >>> from linecontact_sym.numeric.evaluate import evaluate
    >>> c = lcs.exact_cylinder()
    >>> evaluate(c, "force", a=1e-6, R=1.0, E_star=1.0, rtol=1e-12).path
    'model:x**2/(2*R)'
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass

import mpmath
import numpy as np
import sympy as sp

from ..core import symbols as S
from ..core.conversion import number, to_mpf
from ..core.errors import DomainError, LineContactError
from ..core.printing import lambdify
from ..method.derivation import values_by_name
from .accuracy import EPS, FLOAT64_SAFE, FLOAT64_TINY, condition_number_float, float64_safe
from .cache import IdentityCache
from .certified import CertificationError, arb_callable
from .exports import (cancellation_probe, check_arguments, compile_plain_numpy, has_nested_integral, lambdify_mpmath,
                      lambdify_mpmath_quad, compile_callable, stable_form)
from .fastpath import bound_checks, inline_point, one_pass, scalar_kit, vector_float64
from .switches import safe_step, switch_near_end
from .quadrature import VectorQuad
from ..core.precision import checked_dps, held_digits, workdps

#: safety factor of the float64 error estimate (times eps * max(1, kappa, cancellation));
#: closed forms / quadratures (what tests/test_extremes.py checks on the grid)
FLOAT64_FACTOR = 8.0
FLOAT64_FACTOR_QUAD = 16.0
#: series terms generated for the model path
MODEL_TERMS = 40


class _Float64Field:
    """A field of an :class:`Evaluation` (``note``, ``details``) that a
    float64-path result builds when first read, from the terms of its
    estimate stored as ``_float64`` = (factor, kappa, cancellation,
    quadrature error): on the float64 path, formatting the note's floats and
    building the details dict cost as much as the parabola's whole
    evaluation.  Any result may set the field as usual; a note also as
    ``(format, *args)``, formatted when first read (the model path's)."""

    def __init__(self, build, default, fresh=None):
        # fresh: what a None (the dataclass default) stands for, made per result ({} for
        # details: a dict cannot be a dataclass default)
        self.build, self.default, self.fresh = build, default, fresh

    def __set_name__(self, owner, name):
        self.key = "_" + name

    def __get__(self, obj, owner=None):
        if obj is None:
            return self.default         # the dataclass field's default
        d = obj.__dict__
        try:
            v = d[self.key]
        except KeyError:
            v = d[self.key] = self.build(*d["_float64"])
            return v
        if v.__class__ is tuple:        # a note given as (format, *args): formatted when first read
            v = d[self.key] = v[0].format(*v[1:])
        return v

    def __set__(self, obj, value):
        obj.__dict__[self.key] = self.fresh() if value is None and self.fresh is not None else value


#: the note of the float64 path
_FLOAT64_NOTE = ("stable float64 export; estimate {:g} eps max(1, kappa, cancellation) |value| with "
                 "kappa = {:.3g}, cancellation = {:.3g}{}")


def _float64_note(factor, kappa, cancel, qerr):
    return _FLOAT64_NOTE.format(factor, kappa, cancel, f" + quadrature {qerr:.1e}" if qerr else "")


def _float64_details(factor, kappa, cancel, qerr):
    return {"kappa": kappa, "cancellation": cancel}


@dataclass
class Evaluation:
    """The result of :func:`evaluate`.

    value       float (float64 / model in float64) or mpmath.mpf
    path        'float64', 'mpmath@<digits>', 'arb' or 'model:<cheaper model>'
    error       absolute error estimate (arb: the radius of the enclosure)
    rtol        the tolerance that was asked for (None for certified)
    certified   True for a rigorous enclosure
    enclosure   (lower, upper) as mpf for 'arb', else None
    note        why this path, and what the estimate rests on
    seconds     wall-clock time of the evaluation (path selection included)
    unit        None, or the pint Unit of value and error (SI) when the
                arguments were given as pint quantities
    """

    quantity: str
    value: object
    path: str
    error: object
    rtol: float | None = None
    certified: bool = False
    enclosure: tuple | None = None
    note: str = _Float64Field(_float64_note, "")
    seconds: float = 0.0
    details: dict = _Float64Field(_float64_details, None, fresh=dict)
    unit: object = None

    def quantity_value(self):
        """The value as a pint quantity in :attr:`unit` (values given with
        units: ``contact.evaluate("force", a=Q_(1, "mm"), ...)``); the
        numbers of the Evaluation are SI numbers."""
        if self.unit is None:
            raise LineContactError("this evaluation was given plain numbers (SI): it has no unit")
        return self.unit._REGISTRY.Quantity(self.value, self.unit)

    @property
    def rel_error(self) -> float:
        v = abs(self.value)
        return float(abs(self.error) / v) if v != 0 else (0.0 if self.error == 0 else math.inf)

    def __float__(self):
        return float(self.value)

    def digits(self) -> int:
        """The significant digits the value holds: from its error estimate
        (the enclosure's radius for 'arb'), at most the digits of its binary
        precision; float64: 17 (its shortest repr is printed)."""
        return held_digits(self.value, self.error)

    def _value_text(self) -> str:
        v = self.value
        if isinstance(v, np.ndarray):
            return np.array2string(np.asarray(v, dtype=float), precision=6, threshold=8)
        if isinstance(v, mpmath.mpf):
            return mpmath.nstr(v, self.digits())
        return repr(v)

    def __repr__(self):
        """One line: the value with the digits it holds, the path and the error."""
        err = "" if isinstance(self.value, np.ndarray) else f", rel. error <= {self.rel_error:.1e}"
        return f"<Evaluation {self.quantity} = {self._value_text()}{self._unit_text()} via {self.path}{err}>"

    def _unit_text(self) -> str:
        return "" if self.unit is None else f" {self.unit:~P}"

    def __str__(self):
        if isinstance(self.value, np.ndarray):
            return f"{self.quantity} = {self._value_text()}{self._unit_text()}  via {self.path}: {self.note}"
        n = self.digits()
        enc = f" in [{mpmath.nstr(self.enclosure[0], n + 2)}, {mpmath.nstr(self.enclosure[1], n + 2)}]" \
            if self.enclosure else ""
        return (f"{self.quantity} = {self._value_text()}{enc}{self._unit_text()}  via {self.path}  "
                f"(error <= {_short(self.error)}, "
                f"rel {self.rel_error:.1e}){': ' + self.note if self.note else ''}")


def _short(e) -> str:
    """An error in 3 digits, also where it is beyond the float64 range (an mpf 1e-616 is not 0)."""
    f = float(e)
    return f"{f:.2e}" if (f != 0 or e == 0) and math.isfinite(f) else mpmath.nstr(e, 3)


# ----------------------------------------------------------------- helpers
#: compiled functions per Derivation (and the series model per Profile), kept
#: here and not in the contact's or derivation's __dict__ (see .cache)
_CACHE = IdentityCache()


#: plain Python numbers (neither arrays nor NumPy scalars): no conversion needed
_PLAIN = frozenset((float, int))


def _as_float(v):
    """A value as a float: +-inf where it is beyond the float range (an exact 10**400), which
    :func:`~.accuracy.float64_safe` then refuses (the mpmath path takes the exact value)."""
    try:
        return float(v) if type(v) in (float, int) else float(to_mpf(v))
    except OverflowError:
        return math.inf if v > 0 else -math.inf


_as_mpf = to_mpf      # the one converter (core.conversion), exact where the value is


def _float64_fn(d):
    cache = _CACHE.of(d)
    if "f64" not in cache:
        cache["f64"] = compile_callable(d, "numpy")
    return cache["f64"]


def _cancellation(d, point, names):
    """The largest cancellation ratio of the stable form's sums at a point
    (:func:`~.exports.cancellation_probe`)."""
    with np.errstate(all="ignore"):
        return float(np.asarray(cancellation_probe(d)(*[point[n] for n in names])))


# ----------------------------------------------------------------- model path
class SeriesModel:
    """P(a) = sum_k T_k(a), T_k = E* c_k B_k a^(k+1), from f'(x) = sum_k c_k x^k.

    ``bound(values, N)`` bounds the tail after the first N nonzero terms by
    |T_N| / (1 - r), r an upper estimate of the term ratios beyond N: the
    ratios must be nondecreasing over the computed terms and r is their
    limit extrapolated linearly in 1/k (plus a 1e-3 relative margin) -- true
    for series of hypergeometric type such as the cylinder's (term ratio
    (j + 1/2)(j + 3/2)/((j + 1)(j + 2)) (a/R)^2, increasing to (a/R)^2).  The
    model is not used if the computed terms change sign or their ratios
    decrease anywhere past N.
    """

    def __init__(self, contact, K=MODEL_TERMS):
        prof = contact.profile
        if prof.is_piecewise or prof.cases:
            raise LineContactError("no series model for a piecewise profile")
        fp = prof.pieces[0].derivative
        ser = sp.series(fp, S.x, 0, K + 1).removeO()
        poly = sp.Poly(ser, S.x) if ser.free_symbols and S.x in ser.free_symbols else None
        if poly is None or any(m[0] < 0 for m in poly.monoms()):
            raise LineContactError("the profile has no Taylor series at x = 0")
        # the slope is its own series only if it is a polynomial of degree <= K: decided
        # on the polynomial, not by simplify(fp - ser), which ran for minutes on the
        # slope of R (cosh(x/R) - 1) (trigsimp of sinh(x/R) less 20 terms)
        if fp.is_polynomial(S.x) and sp.expand(fp - ser) == 0:
            raise LineContactError("the profile is a polynomial: the closed form is the series")
        coeffs = []
        for k in range(K + 1):
            ck = poly.coeff_monomial(S.x**k)
            if ck == 0:
                continue
            Bk = sp.sqrt(sp.pi) * sp.gamma(sp.Rational(k, 2) + 1) / (2 * sp.gamma(sp.Rational(k, 2) + sp.Rational(3, 2)))
            cb = ck * Bk
            coeffs.append((k, cb if _monomial(cb) else sp.simplify(cb)))
        if len(coeffs) < 6:
            raise LineContactError("too few series terms")
        self.coeffs = coeffs
        self.args = (S.a, S.E_star) + tuple(prof.params)
        self.names = [s.name for s in self.args]
        self.name_set = frozenset(self.names)
        self.terms = [S.E_star * cb * S.a ** (k + 1) for k, cb in coeffs]
        self._mp = lambdify(list(self.args), self.terms, "mpmath")
        self._math = None
        self._names: dict = {}
        self._ratios = _ratio_plan(self.args, self.terms)
        # the profile's terms, int_0^x c_k t^k dt
        self.profile_terms = [poly.coeff_monomial(S.x**k) * S.x**(k + 1) / (k + 1) for k, _ in coeffs]

    def model_name(self, N):
        if N not in self._names:
            self._names[N] = str(sp.Add(*self.profile_terms[:N]))
        return self._names[N]

    def expr(self, N):
        return sp.Add(*self.terms[:N])

    def term_values(self, values, dps=20):
        with workdps(dps):
            return [+t for t in self._mp(*[_as_mpf(values[n]) for n in self.names])]

    def term_floats(self, values):
        """The terms in float64 (a few eps each), or None where one under- or
        overflows (then :meth:`term_values` in mpmath)."""
        if self._math is None:
            self._math = lambdify(list(self.args), self.terms, "math")
        try:
            t = [float(v) for v in self._math(*[_as_float(values[n]) for n in self.names])]
        except (ValueError, OverflowError, ZeroDivisionError):
            return None
        return t if all(v != 0 and math.isfinite(v) for v in t) else None

    def choose(self, values, rtol, t=None):
        """(N, value estimate, tail bound) for the smallest N whose tail bound is
        <= rtol/2 * |partial sum|, or None; ``t``: the terms if already known
        (floats or mpf)."""
        t = self.term_values(values) if t is None else t
        sign0 = (t[0] > 0) - (t[0] < 0)
        if any((v > 0) - (v < 0) != sign0 for v in t if v != 0):
            return None
        mags = [abs(v) for v in t]
        if any(m == 0 for m in mags):
            # exact underflow is impossible in mpmath; a zero term means a zero coefficient
            return None
        r = [mags[j + 1] / mags[j] for j in range(len(mags) - 1)]
        jl = len(r) - 1
        r_inf = r[jl] + (r[jl] - r[jl - 1]) * jl
        # rising[N]: the ratios r[N:] do not decrease (one backward pass, not one scan per N)
        rising = [True] * (len(r) + 1)
        for j in range(len(r) - 2, -1, -1):
            rising[j] = rising[j + 1] and not r[j + 1] < r[j] * (1 - 1e-12)
        rb = max(r_inf, r[-1]) * (1 + 1e-3)
        partial = 0
        for N in range(1, len(t) - 2):
            partial += t[N - 1]
            if not rising[N]:
                continue
            if rb >= 1:
                return None
            bound = mags[N] / (1 - rb)
            if bound <= rtol / 2 * abs(partial):
                return N, partial, bound, float(rb)
        return None


class _RatioPlan:
    """The series model's term ratios when they are all one monomial rho of
    the (positive) arguments times a number: t_(j+1)/t_j = q_j rho (the
    cylinder's: q_j (a/R)^2).  Then the signs of the terms, which ratios
    rise and the limit ratio q_inf are the same at every point and are found
    once, here; a call evaluates t_0 and rho, and the terms it needs as
    t_j = C_j rho**j t_0 (C_j = q_0 ... q_(j-1), exact rationals rounded
    once), not 40 terms and their 39 ratios (:meth:`choose`)."""

    def __init__(self, args, terms, mono, coeffs):
        q = [float(c) for c in coeffs]
        self.rho = lambdify(list(args), mono, "math")
        self.first = lambdify(list(args), terms[0], "math")
        C, acc = [1.0], sp.S.One
        for c in coeffs:
            acc *= c
            C.append(float(acc))
        self.C = C
        jl = len(q) - 1
        self.q_bound = max(q[jl] + (q[jl] - q[jl - 1]) * jl, q[-1]) * (1 + 1e-3)
        rising = [True] * (len(q) + 1)          # as SeriesModel.choose, from the q_j (rho > 0 scales all)
        for j in range(len(q) - 2, -1, -1):
            rising[j] = rising[j + 1] and not q[j + 1] < q[j] * (1 - 1e-12)
        self.rising = rising
        self.n_terms = len(terms)

    def choose(self, vals, tol):
        """As :meth:`SeriesModel.choose` at the floats ``vals`` (positional),
        with the ratio bound rb = q_inf rho: ``(N, partial, bound, rb,
        terms, growth)``, None (no N meets ``tol``), or False where float64
        does not hold the terms (then the general way).  Each term is within
        (4 + 2j) eps of its value (t_0, C_j, rho**j: rho's rounding grows
        j-fold); ``growth`` = 2 eps sum_j j |t_j| over the N terms summed,
        added to the model's error."""
        try:
            rho = float(self.rho(*vals))
            t0 = float(self.first(*vals))
        except (ValueError, OverflowError, ZeroDivisionError):
            return False
        rb = rho * self.q_bound
        if not (math.isfinite(rb) and t0 != 0 and math.isfinite(t0)):
            return False
        C, rising, isfinite = self.C, self.rising, math.isfinite
        t = [t0]
        append = t.append
        slack = 1 - rb
        partial, last, weighted = 0.0, t0, 0.0      # weighted: sum of j |t_j| over the terms summed
        for N in range(1, self.n_terms - 2):
            tN = C[N] * rho**N * t0
            if tN == 0 or not isfinite(tN):
                return False
            append(tN)
            partial += last
            weighted += (N - 1) * abs(last)
            last = tN
            if rising[N]:
                if rb >= 1:
                    return None
                bound = abs(tN) / slack
                if bound <= tol * abs(partial):
                    return N, partial, bound, rb, t, 2 * EPS * weighted
        return None


def _ratio_plan(args, terms):
    """A :class:`_RatioPlan` for the model's terms, or None where the ratios
    are not one monomial times positive numbers (or an argument may be <= 0)."""
    if not all(s.is_positive for s in args):
        return None
    mono, coeffs = None, []
    for lo, hi in zip(terms, terms[1:]):
        c, m = sp.powsimp(sp.expand_power_base(hi / lo, force=True), force=True).as_coeff_Mul()
        if not (c.is_Rational and c > 0) or m.free_symbols - set(args) or \
                not all(e.is_number for _, e in (f.as_base_exp() for f in sp.Mul.make_args(m))):
            return None
        if mono is None:
            mono = m
        elif m != mono:
            return None
        coeffs.append(c)
    if mono is None or len(coeffs) < 3:
        return None
    return _RatioPlan(args, terms, mono, coeffs)


def _monomial(e):
    """Whether ``e`` is a number times powers of symbols (which simplify leaves as it is)."""
    return all(f.is_Number or f.is_NumberSymbol or f.is_Symbol or (f.is_Pow and f.base.is_Symbol and f.exp.is_Number)
               for f in (e.args if e.is_Mul else (e,)))


def _model(contact):
    cache = _CACHE.of(contact.profile)   # the model depends on the profile only
    if "model" not in cache:
        try:
            cache["model"] = SeriesModel(contact)
        except Exception:  # no model for this profile
            # (not the exception: its traceback would keep the contact alive)
            cache["model"] = None
    return cache["model"]


# ----------------------------------------------------------------- main
def evaluate(contact, quantity: str, rtol: float | None = None, certified: bool = False,
             dps: int | None = None, model: bool = True, **values) -> Evaluation:
    """Evaluate ``quantity`` of ``contact`` at ``values`` (keywords by symbol
    name) to relative tolerance ``rtol`` by the cheapest path that meets it
    (see the module docstring); returns an :class:`Evaluation`.

    ``contact``: any object with ``derivation(quantity)`` returning a
    :class:`~linecontact_sym.method.derivation.Derivation`,
    ``check_domain(quantity, values)`` (the quantity's domain from the
    contact's registry: a > 0, |x| <= a for a pressure, |x| >= a for a gap,
    else :class:`~linecontact_sym.core.errors.DomainError`) and ``profile``
    (for the series model of the force).
    ``certified=True`` returns a rigorous Arb enclosure with ``dps`` digits
    (default: 15, or -log10(rtol); needs python-flint, the ``[certified]``
    extra).  ``dps`` without ``certified`` means rtol = 10**-dps.  Neither:
    rtol = 1e-12.  ``model=False`` disables the series-model path.

    >>> import linecontact_sym as lcs
    >>> c = lcs.parabola()                      # P = pi E* a^2 / (4 R), Eq. (13)
    >>> r = evaluate(c, "force", a=0.5, R=1.0, E_star=2.0, rtol=1e-12)
    >>> r.path, r.value                         # pi/8
    ('float64', 0.39269908169872414)
    >>> r = evaluate(c, "force", a=0.5, R=1.0, E_star=2.0, rtol=1e-30)
    >>> r.path.startswith("mpmath@"), mpmath.nstr(r.value, 30)
    (True, '0.39269908169872415480783042291')
    """
    t0 = time.perf_counter()
    if not (rtol.__class__ is float and 0 < rtol < 1 and dps is None):   # else the full check
        _check_tolerance(rtol, dps)
    d = contact.derivation(quantity)
    kit = scalar_kit(d)
    names = kit.names
    if values.keys() != kit.name_set:
        check_arguments(names, values, quantity)
    if _PLAIN.issuperset(map(type, values.values())):    # plain Python numbers: the common case
        arrays = None
    else:
        values = {k: v[()] if isinstance(v, np.ndarray) and v.ndim == 0 else v for k, v in values.items()}
        arrays = {k: np.asarray(v, dtype=float) for k, v in values.items()
                  if isinstance(v, (np.ndarray, list, tuple))}
    if arrays:
        if certified:
            raise LineContactError("certified evaluation takes scalars; loop over the points")
        values = {**values, **arrays}
    if not arrays and hasattr(contact, "check_domain_scalar"):
        values = contact.check_domain_scalar(quantity, values)   # the same check, plain Python for scalars
    else:
        values = contact.check_domain(quantity, values)   # the contact's one domain check (its registry)

    if certified:
        return _certified(d, quantity, values, rtol, dps, t0)
    if rtol is None:
        rtol = 10.0 ** -dps if dps is not None else 1e-12
    if not d.closed_form and not d.expr.has(sp.Integral) and d.reference is not None:
        # an equation with a numeric root (the half-width a(P) of a law that does not
        # invert, the stick half-width): no expression to compile; the root is the value
        if arrays:
            raise LineContactError(f"{quantity} is a numeric root here; evaluate it point by point")
        return _reference_path(d, quantity, values, rtol, t0)
    if arrays:
        return _evaluate_array(contact, d, quantity, names, values, rtol, model, t0,
                               getattr(values, "outside", None))

    # 1. the cheapest model that meets rtol
    if model and quantity == "force" and (kit.expensive or rtol < 1e-15):
        m = _model(contact)
        # the model is the series of the profile's Eq. (10); a force law with
        # other arguments (e.g. an adhesive one, with gamma) is not that series
        if m is not None and m.name_set == kit.name_set:
            res = _try_model(m, quantity, values, rtol, t0)
            if res is not None:
                return res
    # 2. float64
    notes = []
    kappa = 1.0
    if rtol >= 4 * EPS:
        res, kappa = _float64_step(d, kit, quantity, [_as_float(values[n]) for n in names], rtol, t0, notes)
        if res is not None:
            return res
    else:
        notes.append("rtol below float64 resolution")
    # 3. mpmath, precision from rtol and kappa, confirmed at +10 digits
    try:
        return _mpmath_path(d, quantity, values, rtol, kappa, t0, notes)
    except (KeyError, NameError, TypeError) as exc:   # a printer gap in the export of an unevaluated integral
        if d.closed_form or d.reference is None:
            raise
        return _reference_path(d, quantity, values, rtol, t0, f"no mpmath export ({type(exc).__name__}); ")


def _float64_result(quantity, v, est, rtol, factor, kappa, cancel, qerr, t0):
    # the Evaluation's fields set in one step (the dataclass __init__ with its defaults cost
    # as much as the parabola's whole float64 path); the same object as
    # Evaluation(quantity, v, "float64", est, rtol, note=..., seconds=..., details=...), whose
    # note and details are built when read (_Float64Field), and whose certified, enclosure and
    # unit are the class's defaults.  _FAST_TEMPLATE writes the same fields out in the
    # generated monomial path (test_monomial_one_pass_is_the_general_path compares the two)
    r = _new(Evaluation)
    r.__dict__ = {"quantity": quantity, "value": v, "path": "float64", "error": est, "rtol": rtol,
                  "_float64": (factor, kappa, cancel, qerr), "seconds": time.perf_counter() - t0}
    return r


_new = object.__new__


def _float64_step(d, kit, quantity, vals, rtol, t0, notes):
    """``(Evaluation or None, kappa)``: the float64 path at the floats
    ``vals`` (``kit.names`` order) when its estimate meets ``rtol``, else
    None with the reason appended to ``notes``."""
    if not float64_safe(vals, 1.0):
        notes.append(f"an argument beyond the float64-safe magnitudes {FLOAT64_SAFE[0]:g}..{FLOAT64_SAFE[1]:g} "
                     f"(an intermediate power could under- or overflow)")
        return None, 1.0
    v, kappa, cancel, why_not = _float64_value(d, kit, kit.names, vals)
    if v == v and v - v == 0 and (v == 0 or abs(v) < FLOAT64_TINY):
        # 0 or a subnormal: an underflow (or an exact zero, which the mpmath path confirms) is no
        # float64 result with its relative error
        notes.append(f"float64 gave {v!r} (below the smallest normal float {FLOAT64_TINY:.3g})")
    elif v == v and v - v == 0:          # finite
        factor = FLOAT64_FACTOR if d.closed_form else FLOAT64_FACTOR_QUAD
        est = factor * EPS * max(1.0, kappa, cancel) * abs(v)
        qerr = 0.0
        if not d.closed_form:
            qerr = _quad_error(d, dict(zip(kit.names, vals)))
            est += qerr
        if est <= rtol * abs(v):
            return _float64_result(quantity, v, est, rtol, factor, kappa, cancel, qerr, t0), kappa
        notes.append(f"float64 estimate {est / abs(v) if v else est:.1e} > rtol")
    else:
        notes.append(why_not or f"float64 gave {v}")
    return None, kappa


def scalar_evaluator(contact, quantity: str, domain):
    """:func:`evaluate` of one quantity at a point of plain Python numbers,
    planned once per quantity: ``fast(contact, rtol, values)`` returns the
    same :class:`Evaluation` as ``evaluate(contact, quantity, rtol=rtol,
    **values)``, or None where the call is not such a point (then the caller
    takes :func:`evaluate`); None where the quantity has no scalar path (no
    closed form, no scalar function).  The plan holds no reference to the
    contact (a copy of the contact, whose caches are copied, uses it as its
    own).

    Found here once, not per call: the derivation and its
    :class:`~.fastpath.ScalarKit` (the argument names, the scalar function,
    the exact kappa of a monomial), the series model of the force (or that
    there is none), and the domain check (the contact's scalar check with its
    plan, ``domain(contact, values) -> values``).  Per call, the same steps as
    :func:`evaluate`: the domain check, the model where the closed form is
    expensive, the float64 estimate, and mpmath where float64 cannot meet
    rtol.  Tolerances below 1e-14 (the model's mpmath terms), arrays,
    units and other number types take :func:`evaluate`."""
    d = contact.derivation(quantity)
    kit = scalar_kit(d)
    if not d.closed_form or kit.f is None:
        return None
    names, name_set = kit.names, kit.name_set
    m = None
    if quantity == "force" and kit.expensive:
        m = _model(contact)
        if m is not None and m.name_set != name_set:
            m = None
    plain, clock = _PLAIN, time.perf_counter
    # a monomial with no sums to probe (the parabola's pi E* a^2/(4 R)): kappa
    # (sum of |exponents|, every argument nonzero) and the cancellation (1) are
    # numbers, so the float64 estimate is c |value| with c found here
    value = kit.value
    kappa0 = kit.monomial_kappa if kit.probe is None else None
    c0 = FLOAT64_FACTOR * EPS * max(1.0, kappa0, 1.0) if kappa0 is not None else None
    # a domain check that is bounds only (``domain.bounds``, set by the contacts layer): the point
    # read and the value found in one pass (fastpath.one_pass); any other point takes the full path
    bounds = getattr(domain, "bounds", None)
    checks = bound_checks(bounds, names) if m is None and c0 is not None else None
    one = None

    def fast(contact, rtol, values):
        if rtol is None:
            rtol = 1e-12
        elif rtol.__class__ is not float or not 1e-14 <= rtol < 1:
            return None
        t0 = clock()
        if one is not None:
            # a monomial (the parabola's pi E* a^2/(4 R)): its estimate is c0 |value|
            v = one(values)
            if v:
                est = c0 * abs(v)
                if est <= rtol * abs(v):
                    return _float64_result(quantity, v, est, rtol, FLOAT64_FACTOR, kappa0, 1.0, 0.0, t0)
        return general(contact, rtol, values, t0)

    def general(contact, rtol, values, t0):
        if values.keys() != name_set:
            return None
        for v in values.values():
            if v.__class__ not in plain:
                return None
        values = domain(contact, values)
        if m is not None:
            res = _try_model(m, quantity, values, rtol, t0)
            if res is not None:
                return res
        notes = []
        vals = [v if v.__class__ is float else _as_float(v) for v in map(values.__getitem__, names)]
        if c0 is not None and 0 not in vals:
            v = value(vals)
            if v and float64_safe(vals, v):     # finite, nonzero (at 0 kappa is infinite), in range
                est = c0 * abs(v)
                if est <= rtol * abs(v) or (v == 0 and est == 0):
                    return _float64_result(quantity, v, est, rtol, FLOAT64_FACTOR, kappa0, 1.0, 0.0, t0)
        res, kappa = _float64_step(d, kit, quantity, vals, rtol, t0, notes)
        if res is not None:
            return res
        return _mpmath_path(d, quantity, values, rtol, kappa, t0, notes)
    if checks is not None:
        # the same steps as fast's, generated as one function with the law's expression in it
        # (fastpath.inline_point): the parabola's evaluate 13x -> 9.5x the law written by hand
        inlined = inline_point(checks, kit.f,
                               _FAST_TEMPLATE, "_lcs_general(_lcs_contact, _lcs_rtol, _lcs_values, _lcs_t0)",
                               {"_lcs_clock": clock, "_lcs_c0": c0, "_lcs_quantity": quantity,
                                "_lcs_general": general, "_lcs_new": _new, "_lcs_Evaluation": Evaluation,
                                "_lcs_terms": (FLOAT64_FACTOR, kappa0, 1.0, 0.0)})
        if inlined is not None:
            return inlined
        one = one_pass(bounds, names, kit.f)    # the law is not a one-line function: the loop
    return fast


#: :func:`scalar_evaluator`'s ``fast`` for a monomial, as :func:`~.fastpath.inline_point` generates it;
#: the Evaluation built as :func:`_float64_result` builds it, written out (a call costs 5 % of the path)
_FAST_TEMPLATE = """
def _lcs_pass(_lcs_contact, _lcs_rtol, _lcs_values):
    if _lcs_rtol is None:
        _lcs_rtol = 1e-12
    elif _lcs_rtol.__class__ is not float or not 1e-14 <= _lcs_rtol < 1:
        return None
    _lcs_t0 = _lcs_clock()
    CHECK
    if _lcs_v and _lcs_v - _lcs_v == 0:
        _lcs_est = _lcs_c0 * abs(_lcs_v)
        if _lcs_est <= _lcs_rtol * abs(_lcs_v):
            _lcs_r = _lcs_new(_lcs_Evaluation)
            _lcs_r.__dict__ = {"quantity": _lcs_quantity, "value": _lcs_v, "path": "float64", "error": _lcs_est,
                               "rtol": _lcs_rtol, "_float64": _lcs_terms, "seconds": _lcs_clock() - _lcs_t0}
            return _lcs_r
    return _lcs_general(_lcs_contact, _lcs_rtol, _lcs_values, _lcs_t0)
"""


def _float64_value(d, kit, names, vals):
    """``(v, kappa, cancellation, why_not)`` at a point in float64: the
    scalar fast path where it compiles, else the NumPy export; kappa and the
    cancellation ratio where v is finite (else 1).  ``why_not`` says why v is
    NaN when float64 is not to be used here (an integrand switching next to
    an endpoint; no float64 export), else None."""
    point = None
    if not d.closed_form:
        point = dict(zip(names, vals))
        near = switch_near_end(d, point)
        if near is not None:
            return math.nan, 1.0, 1.0, near
    v = kit.value(vals) if kit.f is not None else None
    if v is not None:                                   # the scalar path (fastpath): v is finite
        # kappa exact for a monomial: no step to choose
        step = safe_step(d, point or dict(zip(names, vals))) if kit.differences else None
        return v, kit.kappa(vals, v, step=step), kit.cancellation(vals), None
    point = point or dict(zip(names, vals))
    try:                                                # the NumPy export
        f64 = _float64_fn(d)
    except Exception as exc:  # noqa: BLE001 -- a SymPy printer gap: take the mpmath path
        return math.nan, 1.0, 1.0, f"no float64 export ({type(exc).__name__}: {str(exc)[:60]})"
    with np.errstate(all="ignore"):
        v = float(np.asarray(f64(**point)))
    if not math.isfinite(v):
        return v, 1.0, 1.0, None
    return v, condition_number_float(f64, point, h=safe_step(d, point), f0=v), _cancellation(d, point, names), None


def _check_tolerance(rtol, dps):
    """rtol a real number in (0, 1), dps an integer 1..MAX_DPS (or None)."""
    if rtol is not None:
        if isinstance(rtol, bool) or not isinstance(rtol, (int, float, np.floating, np.integer)) \
                or not 0 < float(rtol) < 1:
            raise DomainError(f"rtol must be a number with 0 < rtol < 1, got {rtol!r}")
    if dps is not None:
        checked_dps(dps)


def _evaluate_array(contact, d, quantity, names, values, rtol, model, t0, outside=None):
    """evaluate() at arrays of arguments: the vectorised float64 export with
    the same error estimate per point; the points where it does not meet
    ``rtol`` are evaluated one by one (model, mpmath).  ``outside``: the
    points outside the quantity's domain (the contact's domain check marked
    them and warned): NaN, path 'outside'."""
    arrays = np.broadcast_arrays(*[np.asarray(values[n], dtype=float) for n in names])
    v, kappa, cancel = vector_float64(d, names, arrays)
    if outside is not None:
        outside = np.broadcast_to(outside, v.shape)
        v = np.where(outside, np.nan, v)
    factor = FLOAT64_FACTOR if d.closed_form else FLOAT64_FACTOR_QUAD
    with np.errstate(all="ignore"):
        est = factor * EPS * np.maximum(np.maximum(1.0, kappa), cancel) * np.abs(v)
        if not d.closed_form:
            est = est + _quad_error(d, dict(zip(names, arrays)))
        # float64 only at normal values and arguments within FLOAT64_SAFE (float64_safe, per point):
        # an underflow to 0 or a subnormal is evaluated one by one (mpmath), never 0 with error 0
        lo_, hi_ = FLOAT64_SAFE
        safe = np.abs(v) >= FLOAT64_TINY
        for arr in arrays:
            m_ = np.abs(arr)
            safe = safe & ((m_ == 0) | ((m_ >= lo_) & (m_ <= hi_)))
        ok = np.isfinite(v) & (est <= rtol * np.abs(v)) & safe if rtol >= 4 * EPS \
            else np.zeros(v.shape, dtype=bool)
    if outside is not None:
        ok = ok | outside
        est = np.where(outside, np.nan, est)
    values_out = np.array(v, dtype=object if not np.all(ok) else float)
    errors = np.array(est, dtype=object if not np.all(ok) else float)
    paths = np.full(v.shape, "float64", dtype=object)
    if outside is not None:
        paths[outside] = "outside"
    for idx in zip(*np.nonzero(~ok)) if v.ndim else ([()] if not ok else []):
        point = {n: float(a[idx]) for n, a in zip(names, arrays)}
        r = evaluate(contact, quantity, rtol=rtol, model=model, **point)
        values_out[idx], errors[idx], paths[idx] = r.value, r.error, r.path
    kinds = sorted(set(paths.ravel().tolist()))
    n_out = 0 if outside is None else int(np.sum(outside))
    note = (f"{int(np.sum(ok)) - n_out} of {ok.size} points by the vectorised float64 export (estimate "
            f"{factor:g} eps max(1, kappa, cancellation) |value| per point), the rest one by one" +
            (f"; {n_out} outside the domain: NaN" if n_out else ""))
    return Evaluation(quantity, values_out, kinds[0] if len(kinds) == 1 else " + ".join(kinds), errors, rtol,
                      note=note, seconds=time.perf_counter() - t0,
                      details={"paths": paths, "kappa": kappa, "cancellation": cancel})


#: the note of the model path (formatted when read: :class:`_Note`)
_MODEL_NOTE = ("series of P(a) from the profile's Taylor series, {} term(s) (the force law of the profile {}); "
               "tail <= |next term|/(1 - r) = {:.2e} with term ratio bound r = {:.3g}")


def _try_model(m, quantity, values, rtol, t0):
    choice, growth = False, 0.0
    if rtol >= 1e-14 and m._ratios is not None:     # the ratios' structure found once per model
        vals = [values[n] for n in m.names]
        vals = [v if v.__class__ is float else _as_float(v) for v in vals]
        choice = m._ratios.choose(vals, max(rtol - 8 * EPS, rtol / 2) / 2)
        if choice:
            N, partial, bound, rb, floats, growth = choice     # growth: rho**j's rounding, see choose
    if choice is False:
        floats = m.term_floats(values) if rtol >= 1e-14 else None
        choice = m.choose(values, max(rtol - 8 * EPS, rtol / 2) if rtol >= 1e-14 else rtol, floats)
        if choice:
            N, partial, bound, rb = choice
    if choice is None:
        return None
    tv = None
    if rtol >= 1e-14:
        # the N-term model in float64, where its terms are normal floats (an underflowed term
        # is no float64 value with a relative error: then in mpmath)
        tv = floats[:N] if floats is not None else [float(t) for t in m.term_values(values, dps=17)[:N]]
        if not all(FLOAT64_TINY <= abs(t) < math.inf for t in tv) or \
                not float64_safe([_as_float(values[n]) for n in m.names], 1.0):
            tv = None
    if tv is not None:
        val = math.fsum(tv)
        err = float(bound) + 4 * N * EPS * abs(val) + growth
    else:
        digits = int(-math.log10(rtol)) + 5
        with workdps(digits):
            val = +mpmath.fsum(m.term_values(values, dps=digits)[:N])
        with workdps(digits):
            # the tail bound and the rounding of the N terms at this precision
            err = +(mpmath.mpf(bound) + (2 * N + 2) * mpmath.mpf(10)**(-digits) * abs(val))
    name = m.model_name(N)
    note = (_MODEL_NOTE, N, name, float(bound), rb)      # formatted when read
    return Evaluation(quantity, val, "model:" + name, err, rtol, note=note,
                      seconds=time.perf_counter() - t0, details={"terms": N, "ratio_bound": rb})


def _quad_error(d, point):
    """The float64 quadrature's own error estimate (for quantities without a
    closed form): re-evaluate with error output where possible."""
    cache = _CACHE.of(d)
    key = "qerr"
    if key not in cache:
        form = stable_form(d).expr
        ints = list(form.atoms(sp.Integral))
        syms = d.variables_all
        quads = [(VectorQuad(I, compile_plain_numpy, conditions=()), I) for I in ints]
        # d(form)/d(I) for the propagation of each integral's error
        coeffs = [lambdify(list(syms), sp.diff(form.xreplace({I: sp.Symbol("_I_")}), sp.Symbol("_I_"))
                              .xreplace({sp.Symbol("_I_"): 0}), "numpy") for I in ints]
        cache[key] = (quads, coeffs, [s.name for s in syms])
    quads, coeffs, names = cache[key]
    total = 0.0
    with np.errstate(all="ignore"):
        for (q, I), cf in zip(quads, coeffs):
            vals = [point[s.name] for s in q.params]
            _, e = q(*vals, with_error=True)
            total = total + np.abs(np.asarray(cf(*[point[n] for n in names]), float)) * np.asarray(e, float)
    return total if np.ndim(total) else float(total)      # per point for arrays of points


def _mpmath_fn(d):
    cache = _CACHE.of(d)
    key = "mp"
    if key not in cache:
        syms = d.variables_all
        if d.closed_form:
            f = lambdify_mpmath(stable_form(d).expr, syms, stable=False)
        else:
            f = lambdify_mpmath_quad(d.expr, syms)
        cache[key] = (f, [s.name for s in syms])
    return cache[key]


#: Arb work limit of the enclosure of a quantity without closed form (integrand
#: evaluations per integral): past it the mpmath path runs instead
ARB_QUAD_LIMIT = 5000


def _arb_quadrature(d, quantity, values, rtol, t0, notes):
    """A quantity without closed form (unevaluated integrals in a closed
    outer expression) as one rigorous Arb enclosure: each integral by
    :func:`~linecontact_sym.numeric.reference.integrate`, the outer
    expression by :func:`~linecontact_sym.numeric.reference.combine`, at the
    inputs as given (floats exactly).  The Evaluation (path 'arb', error the
    enclosure's radius, a true bound) when the enclosure is certified and
    meets ``rtol``; None otherwise (an integrand Arb cannot evaluate, the work
    limit): the mpmath path then runs."""
    from .reference import combine, integrate
    cache = _CACHE.of(d)
    if "arbq" not in cache:
        ints = sorted(d.expr.atoms(sp.Integral), key=sp.default_sort_key)
        ok = ints and not has_nested_integral(d.expr) and all(len(I.limits) == 1 and len(I.limits[0]) == 3
                                                              for I in ints)
        dums = [sp.Dummy(f"I{k}") for k in range(len(ints))]
        cache["arbq"] = (ints, dums, d.expr.xreplace(dict(zip(ints, dums)))) if ok else None
    plan = cache["arbq"]
    if plan is None:
        return None
    ints, dums, outer = plan
    try:
        exact = {q: number(values[q.name]) for q in d.variables_all}
    except (LineContactError, KeyError, TypeError):
        return None
    dps = int(math.ceil(-math.log10(rtol))) + 5
    refs = []
    for I in ints:
        s_, lo, hi = I.limits[0]
        lo_v, hi_v = lo.xreplace(exact), hi.xreplace(exact)
        try:
            if I.function.free_symbols - {s_} - set(exact) or not bool(lo_v < hi_v):
                return None
        except TypeError:          # the order of the end points not decided
            return None
        # the integrand compiled once with the parameters as symbols (values=): the next point is cheap
        r = integrate(I.function, s_, [lo, hi], dps=dps, fallback=lambda: mpmath.nan, eval_limit=ARB_QUAD_LIMIT,
                      values=exact)
        if not r.certified:
            return None
        refs.append(r)
    r = combine(outer.xreplace(exact), dums, refs, dps=dps)
    if not (r.certified and mpmath.isfinite(r.rad) and r.rad <= rtol * abs(r.mid)):
        return None
    mid, rad = r.mid, r.rad
    # the end points of the ball [mid - rad, mid + rad] exactly (as the closed forms' Enclosure gives
    # them): the ball's lower()/upper() round to python-flint's working precision, 53 bits outside a
    # workprec, an interval 1e-16 wide around a value stated to 1e-36
    lo, hi = mpmath.fsub(mid, rad, exact=True), mpmath.fadd(mid, rad, exact=True)
    note = "; ".join(notes + [f"one python-flint Arb enclosure of the integral{'s' if len(ints) > 1 else ''} "
                              f"(rigorous for the inputs as given: floats are exact binary numbers)"])
    return Evaluation(quantity, mid, "arb", rad, rtol, certified=True, enclosure=(lo, hi),
                      note=note, seconds=time.perf_counter() - t0, details={"digits": dps})


def _mpmath_path(d, quantity, values, rtol, kappa, t0, notes):
    if not d.closed_form:          # an unevaluated integral: one certified enclosure where Arb does it
        res = _arb_quadrature(d, quantity, values, rtol, t0, notes)
        if res is not None:
            return res
    f, names = _mpmath_fn(d)
    want = -math.log10(rtol)
    # kappa is infinite where the value is 0 (a flat: the pressure inside a
    # worn cylinder's flat) and NaN where it is undefined: no information on
    # the digits needed then, start from rtol alone (the +10 check decides)
    kappa = kappa if math.isfinite(kappa) else 1.0
    digits = int(math.ceil(want + 5 + math.log10(max(1.0, min(kappa, 1e300)))))
    digits = max(digits, 20)
    while True:
        with workdps(digits):
            v1 = f(*[_as_mpf(values[n]) for n in names])
        with workdps(digits + 10):
            v2 = f(*[_as_mpf(values[n]) for n in names])
            err = abs(v2 - v1)
            ok = err <= rtol * abs(v2) / 10 or (v2 == 0 and err == 0)
        if ok:
            note = "; ".join(notes + [f"confirmed against {digits + 10} digits (difference "
                                      f"{mpmath.nstr(err, 3)})"])
            with workdps(digits + 10):
                return Evaluation(quantity, +v2, f"mpmath@{digits}", err, rtol, note=note,
                                  seconds=time.perf_counter() - t0, details={"digits": digits})
        if digits > 5000:
            raise LineContactError(f"mpmath did not reach rtol = {rtol:g} within 5000 digits")
        digits *= 2


def _reference_path(d, quantity, values, rtol, t0, why=""):
    """The derivation's own numeric reference (a root of an equation) at the
    digits rtol asks plus 5, confirmed at 10 more."""
    vals = values_by_name(d.variables_all, values)
    digits = max(20, int(math.ceil(-math.log10(rtol))) + 5)
    while True:
        v1 = d.reference(vals, digits)
        with workdps(digits + 10):
            v2 = d.reference(vals, digits + 10)
            err = abs(v2 - v1)
            if err <= rtol * abs(v2) / 10 or (v2 == 0 and err == 0):
                return Evaluation(quantity, +v2, f"mpmath@{digits}", err, rtol,
                                  note=f"{why}the derivation's reference ({d.step.describe()}), confirmed "
                                       f"against {digits + 10} digits (difference {mpmath.nstr(err, 3)})",
                                  seconds=time.perf_counter() - t0, details={"digits": digits})
        if digits > 1000:
            raise LineContactError(f"the numeric root did not reach rtol = {rtol:g} within 1000 digits")
        digits *= 2


def _certified(d, quantity, values, rtol, dps, t0):
    if dps is None:
        dps = int(math.ceil(-math.log10(rtol))) if rtol else 15
    if not d.closed_form:
        # the same Arb enclosure of the integrals that evaluate(rtol) takes beyond float64: what one path
        # certifies, the other does not refuse
        res = _arb_quadrature(d, quantity, values, 10.0 ** -dps, t0, [f"certified: {dps} digits asked"])
        if res is None:
            raise CertificationError(
                f"{quantity} has no closed form and Arb does not enclose its integral here to {dps} digits "
                f"(an integrand Arb cannot evaluate, a nested integral or the work limit {ARB_QUAD_LIMIT}); "
                f"evaluate(..., rtol=...) gives the mpmath estimate")
        res.rtol = rtol
        return res
    syms = d.variables_all
    cache = _CACHE.of(d)
    if "arb" not in cache:
        cache["arb"] = arb_callable(stable_form(d).expr, syms)
    enc = cache["arb"]([values[s.name] for s in syms], dps=dps)
    lo, hi = enc.lower, enc.upper
    with workdps(dps + 10):
        mid = enc.mid
    note = (f"python-flint Arb ball at {enc.prec} bits: a rigorous enclosure of the exact value "
            f"for the inputs as given (floats are exact binary numbers)")
    return Evaluation(quantity, mid, "arb", enc.rad, rtol, certified=True, enclosure=(lo, hi),
                      note=note, seconds=time.perf_counter() - t0,
                      details={"ball": enc.ball, "prec": enc.prec, "digits": dps})
