"""The one reference integrator: Arb ball quadrature (python-flint's
``acb.integral``) of an integrand compiled from SymPy, with mpmath as the
recorded fallback.

Every independent reference of the package (the verification of a closed
form against its defining integral, the claims' references, the
Maugis-Dugdale, tangential and stress checks) integrates through
:func:`integrate`.  Where Arb does it, the answer is a *rigorous enclosure*
[mid +/- rad] of the exact integral (for the exact inputs given: a Rational
is its exact value, a float its binary value), not an estimate; where it
cannot, the caller's mpmath quadrature (tanh-sinh) runs instead and the
result says so (``method == "mpmath"``).

How the integrand reaches Arb
    The SymPy expression is compiled to a function of complex balls that
    says where it is not holomorphic (:mod:`~linecontact_sym.numeric.arb_compile`).
    The break points a caller gives are hints that make the work fast; a
    switch between them is still integrated rigorously (by bisection), only
    slower.  A piece with an integrable singularity at an end point is
    transformed there (:mod:`~linecontact_sym.numeric.endpoints`: t = e + d u^q
    at a power end, the logarithms subtracted at a logarithmic one).

What Arb cannot do, and what happens then
    A function without an acb counterpart, a singularity at an end point
    that ball arithmetic cannot bound (a log singularity, a removable 0/0),
    or an integral that needs more than :data:`EVAL_LIMIT` evaluations: the
    fallback runs (``fallback()``, an mpmath quadrature of the caller's, or,
    without one, ``mpmath.quad`` of the lambdified integrand over the same
    pieces) and the result carries ``method="mpmath"`` and the reason.

Precision: python-flint's and mpmath's global precisions are never changed
(``flint.ctx.workprec``, :func:`~linecontact_sym.core.precision.workdps`).

>>> import sympy as sp, mpmath
>>> t = sp.Dummy("t")
>>> r = integrate(sp.sqrt(1 - t**2), t, [0, 1], dps=40)     # pi/4: sqrt's branch point at t = 1
>>> r.method, r.digits >= 40
('arb', True)
>>> with mpmath.workdps(50):
...     print(r.contains(mpmath.pi / 4), mpmath.nstr(r.mid, 30))
True 0.78539816339744830961566084582
"""
from __future__ import annotations

import math

import flint
import mpmath
import sympy as sp

from ..core.conversion import number, to_mpf
from ..core.errors import LineContactError
from ..core.precision import workdps
from .arb_compile import ArbUnsupported, compile_acb, compile_at, is_compiled, mpf_of_arb, nan_ball, to_acb
from .endpoints import singular_piece, value_at

__all__ = ["RefValue", "integrate", "estimate", "combine", "lincomb", "quotient_bound", "log_end_integral",
           "EVAL_LIMIT", "ARB", "MPMATH"]

#: the method names a :class:`RefValue` records
ARB = "arb"
MPMATH = "mpmath"

#: work limit of one Arb integral (integrand evaluations): past it the
#: fallback runs.  A smooth piece at 45 digits takes a few hundred.
EVAL_LIMIT = 20000


class RefValue(mpmath.mpf):
    """A reference value: an mpmath ``mpf`` (its midpoint, to every bit Arb
    or mpmath computed: arithmetic with it gives plain mpf, so a caller that
    wants a number has one) that also carries ``rad``, ``method`` and
    ``note``.

    ``method == "arb"``: the exact value lies in [mid - rad, mid + rad]
    (a rigorous enclosure).  ``method == "mpmath"``: the value is an
    estimate (tanh-sinh), ``rad`` is 0 (no guarantee is claimed) and
    ``note`` says why Arb was not used."""

    def __new__(cls, mid, rad, method, note="", ball=None):
        obj = mpmath.mpf.__new__(cls)
        obj._mpf_ = mpmath.mpf(mid)._mpf_ if not isinstance(mid, mpmath.mpf) else mid._mpf_
        obj.rad = rad if isinstance(rad, mpmath.mpf) else mpmath.mpf(rad)
        obj.method = method
        obj.note = note
        obj.ball = ball          # the acb ball itself (Arb only), for :func:`combine`
        return obj

    def __reduce__(self):
        return (_refvalue, (self._mpf_, self.rad._mpf_, self.method, self.note))

    @property
    def mid(self):
        """The midpoint as a plain mpf."""
        return _plain(self)

    @property
    def certified(self) -> bool:
        return self.method == ARB

    @property
    def digits(self) -> float:
        """Relative digits the enclosure guarantees (0 for an estimate)."""
        if not self.certified:
            return 0.0
        if self.rad == 0:
            return math.inf
        if self.mid == 0:
            return 0.0
        return max(float(-mpmath.log10(self.rad / abs(self.mid))), 0.0)

    def contains(self, value, slack=0) -> bool:
        """Does the enclosure contain ``value`` (within ``slack``, the
        uncertainty of ``value`` itself)?  For an estimate: True."""
        if not self.certified:
            return True
        with workdps(max(mpmath.mp.dps, 60)):
            return abs(mpmath.mpf(value) - self.mid) <= self.rad + abs(mpmath.mpf(slack))


def _plain(v):
    out = mpmath.mpf.__new__(mpmath.mpf)
    out._mpf_ = v._mpf_
    return out


def _refvalue(mpf_, rad_, method, note):
    return RefValue(_plain(_Raw(mpf_)), _plain(_Raw(rad_)), method, note)


class _Raw:
    def __init__(self, t):
        self._mpf_ = t


# ----------------------------------------------------------------- integration
def _bits(dps: int) -> int:
    return int(math.ceil(dps * math.log2(10)))


def integrate(integrand, var, points, dps: int = 45, fallback=None, eval_limit: int = EVAL_LIMIT,
              crude=None, removable: bool = False, values: dict | None = None) -> RefValue:
    """int over [points[0], points[-1]] of ``integrand`` d``var``, split at
    every point given: a :class:`RefValue`.

    ``integrand``: a SymPy expression in ``var`` alone (all parameters
    already replaced by numbers, exact ones preferably), or a list of them,
    one per piece [points[k], points[k+1]] (a function whose formula
    differs between pieces, |s| written s or -s: no switch to bisect); an
    expression may also be a compiled ``f(z, analytic)`` (:func:`~.arb_compile.compile_acb`
    with the parameters' balls bound: no SymPy work per call; then
    ``fallback`` is the caller's, and no end point is substituted);
    ``points``: the end points and break points, ascending (SymPy numbers,
    ints, Rationals, mpf); ``dps``: the relative digits asked of the
    enclosure (of the sum; each piece is asked a little more);
    ``fallback``: a callable returning the mpmath estimate (mpf) when Arb
    cannot do it (default: ``mpmath.quad`` of the lambdified integrand over
    the same pieces, at ``dps`` + 10 digits).

    ``crude``: ``crude(z, analytic)``, a bound of the integrand on a ball
    where its own ball is not finite (:func:`quotient_bound`: holomorphic
    where ``analytic`` is set, as ``acb.integral`` asks); ``removable``: from 0, look for a
    removable 0/0 N(t)/t^k of the integrand and take its
    :func:`quotient_bound` (a single piece is then split at its middle: the
    bound next to 0 on one half, an end singularity on the other).

    The result is certified (``method == "arb"``) when every piece's ball
    is finite and the sum's ball is accurate to ``dps`` digits (or its
    absolute radius is below 10**-dps for a value that is 0).

    ``values`` (symbol -> number): the integrand (SymPy) and the points hold
    these parameters as symbols (the points ascending at their values): the
    integrand is compiled once with the parameters as symbols
    (:func:`~.arb_compile.bound_acb`), and the symbolic work of a singular end point (its
    substitution, the split of its logarithms) is done once per integrand
    and end point and kept (:func:`~.endpoints._log_end`), so that the same integral
    at many parameter values does it once, not at every one.  The result
    is the same enclosure's kind: only where the work is done changes."""
    if values is not None:
        if crude is not None or removable:
            raise ValueError("crude and removable are not taken with values")
        if not all(isinstance(e, sp.Basic) for e in _per_piece(integrand, points)):
            raise ValueError("with values the integrand is SymPy")
        if fallback is None:
            def fallback():
                return _mpmath_integral([e.xreplace(values) for e in _per_piece(integrand, points)], var,
                                        [value_at(p, values) for p in points], dps)
    if removable and crude is None and isinstance(integrand, sp.Basic) and points[0] == 0:
        crude = _removable_quotient(integrand, var)
        if crude is not None and len(points) == 2:
            points = [points[0], sp.sympify(points[1], strict=True) / 2, points[1]]
    try:
        ball = _arb_integral(integrand, var, points, dps, eval_limit, crude, values)
        reason = None
    except ArbUnsupported as exc:
        ball, reason = None, str(exc)
    if ball is not None:
        with flint.ctx.workprec(_bits(dps) + 64):
            mid, rad = mpf_of_arb(ball.real.mid()), mpf_of_arb(ball.real.rad())
        return RefValue(mid, rad, ARB, ball=ball)
    if fallback is None:
        def fallback():
            return _mpmath_integral(integrand, var, points, dps)
    return estimate(fallback, reason or "", dps)


def quotient_bound(numerator, var, rest, order: int = 1):
    """``crude(z, analytic)`` for :func:`integrate`: a bound of
    numerator(t)/t^k * rest(t) (k = ``order``) on a ball z (real or complex)
    next to t = 0, where the numerator has a zero of order >= k at t = 0
    (the caller must know it: the gap's P(s)/s, P(0) = 0), so that the
    quotient has a removable singularity there.

    With r >= |z| (every point of the ball), the numerator is evaluated on
    the disk |w| <= r (a box holding it) with Arb's holomorphy check: a
    finite ball M proves it holomorphic there (a numerator that is not gives
    no bound).  numerator(w)/w^k is then holomorphic on that disk, and by
    the maximum modulus principle at most M/r^k on it, at z too.  ``rest``
    is evaluated on z itself with the ``analytic`` flag given: where it is
    finite, the product is a bound of the integrand on z, and holomorphic
    there when ``analytic`` is set; so ``acb.integral`` may use it on its
    complex neighbourhoods of a piece from 0 (its Gauss-Legendre error
    bound), not only bisect towards 0 with real balls (issue 26: the exact
    cylinder's gap took about 3,200 evaluations a point, about 700 now)."""
    fn, fr = compile_acb(numerator, var), compile_acb(rest, var)

    def crude(z, analytic=False):
        r = z.abs_upper()
        if r == 0:
            return nan_ball()
        rest_z = fr(z, analytic)
        if not rest_z.is_finite():
            return nan_ball()
        disk = flint.acb(flint.arb(0, r), flint.arb(0, r))
        M = fn(disk, True)
        if not M.is_finite():
            return nan_ball()
        b = M.abs_upper() / r**order
        return flint.acb(flint.arb(0, b), flint.arb(0, b)) * rest_z
    return crude


def _removable_quotient(f, var):
    """For an integrand N(t)/(t^k D(t)) with a zero of order >= k of N at
    t = 0 (the printed Eq. (9): P(t)/(t sqrt(a^2 - t^2)); Eq. (10) of the
    exact cylinder: (f'(t)/t ...)/t^2 over a common denominator), the
    bound next to t = 0 (:func:`quotient_bound`; the order is checked
    exactly: N(0) = ... = N^(k-1)(0) = 0); None for any other integrand.
    A factor t^k of the denominator, as it stands or over a common one,
    comes from a power t^-k of the integrand: without one, None at once
    (``together`` of a large integrand was most of this test's CPU)."""
    if not any(p.base == var and p.exp.is_Integer and p.exp < 0 for p in f.atoms(sp.Pow)):
        return None
    for form in (f, None):
        if form is None:
            try:
                form = sp.together(f)
            except (TypeError, ValueError):
                return None
        num, den = sp.fraction(form)
        k = next((int(d.exp) if d.is_Pow else 1 for d in sp.Mul.make_args(den)
                  if d == var or (d.is_Pow and d.base == var and d.exp.is_Integer and d.exp > 0)), 0)
        if k == 0 or k > 4 or not num.has(var):
            continue
        try:
            if any(sp.diff(num, var, j).xreplace({var: sp.S.Zero}) != 0 for j in range(k)):
                continue
        except (TypeError, ValueError, ZeroDivisionError):
            continue
        try:
            return quotient_bound(num, var, var**k / den, order=k)
        except ArbUnsupported:
            continue
    return None


def log_end_integral(p, var, c, other, dps: int = 45) -> RefValue:
    """int over the segment between c and ``other`` (either side of c) of
    p(t) ln|t - c| dt, for p holomorphic next to that segment and finite at
    c (its logarithmic end).  The exponential substitution
    t = c + (other - c) e^(-u), h = |other - c|, makes it

        h int_0^oo p(c + (other - c) e^(-u)) (ln h - u) e^(-u) du,

    an integrand holomorphic next to [0, oo).  Its part p(c) h (ln h - 1)
    is exact; the rest, with p(t) - p(c) in place of p(t), decays like
    u e^(-2u) for p differentiable at c: Arb integrates it on [0, U]
    (Gauss-Legendre, no bisection towards the logarithm, which a
    subtraction bounded crudely next to c would need), and the tail beyond U
    is enclosed by D h e^(-U) (|ln h| + U + 1), D an Arb bound of
    |p(t) - p(c)| on the real segment between c and c + (other - c) e^(-U)
    (U grows until that bound is below the digits asked).
    ``p``: SymPy in ``var`` alone, or compiled (``f(z, analytic)``, see
    :func:`integrate`); a certified :class:`RefValue`, or
    :class:`~.arb_compile.ArbUnsupported` (p not finite at c, or any part Arb cannot
    enclose): the caller's own route runs.

    >>> t = sp.Dummy("t")
    >>> r = log_end_integral(1 + t, t, sp.Rational(1, 3), 1, 40)
    >>> exact = sp.integrate((1 + t) * sp.log(t - sp.Rational(1, 3)), (t, sp.Rational(1, 3), 1))
    >>> with mpmath.workdps(60):
    ...     print(r.method, r.contains(to_mpf(sp.N(exact, 60))), r.digits > 40)
    arb True True
    """
    goal = _bits(dps)
    f = p if is_compiled(p) else compile_acb(p, var)
    with flint.ctx.workprec(goal + 30):
        cb, ob = to_acb(_exact(c)), to_acb(_exact(other))
        step = ob - cb
        if not (step.real.abs_lower() > 0 and step.is_finite()):
            raise ArbUnsupported("an empty or unbounded segment next to a logarithmic end")
        h = abs(step.real)
        lnh = h.log()
        try:
            pc = f(cb, False)
            if not pc.is_finite():
                raise ArbUnsupported(f"the integrand has no finite value at its logarithmic end {c}")
            # the size of the integral, to bound the absolute error of the pieces by
            size = ((pc.abs_upper() + 1) * h * (abs(lnh) + 1)).abs_upper()
            tol = flint.arb(2) ** -(goal + 8)
            U, tail = int(math.ceil(((goal + 20) * math.log(2) + math.log(1 + abs(float(lnh.mid())))) / 2)), None
            for _ in range(4):
                end = (cb + step * flint.arb(-U).exp()).real
                D = f(flint.acb(end.union(cb.real)), False) - pc
                tail = D.abs_upper() * h * flint.arb(-U).exp() * (abs(lnh) + U + 1)
                if tail.is_finite() and tail < tol * size:
                    break
                U = U * 3 // 2

            def g(u, an):
                e = (-u).exp()
                return (f(cb + step * e, an) - pc) * (lnh - u) * h * e
            v = flint.acb.integral(g, 0, U, rel_tol=tol, abs_tol=tol * size, eval_limit=EVAL_LIMIT)
        except (ZeroDivisionError, ValueError, TypeError) as exc:
            raise ArbUnsupported(f"Arb could not evaluate the integrand: {exc}") from None
        if not (v.is_finite() and tail is not None and tail.is_finite()):
            raise ArbUnsupported("Arb could not enclose the integral next to a logarithmic end")
        if 0 not in v.imag:
            raise ArbUnsupported(f"the integral is not real: {v}")
        exact = pc * h * (lnh - 1)
        if 0 not in exact.imag:
            raise ArbUnsupported(f"the integrand is not real at its logarithmic end: {pc}")
        total = v.real + exact.real + flint.arb(0, tail.abs_upper())
        if total.rel_accuracy_bits() < goal and total.rad() > flint.arb(2) ** -goal:
            raise ArbUnsupported(f"enclosure too wide: {total.rel_accuracy_bits()} of {goal} bits")
        ball = flint.acb(total)
    with flint.ctx.workprec(goal + 64):
        return RefValue(mpf_of_arb(total.mid()), mpf_of_arb(total.rad()), ARB, ball=ball)


def estimate(fallback, reason: str, dps: int = 45) -> RefValue:
    """The mpmath route, recorded: ``fallback()`` (an mpf) at ``dps`` + 10
    digits as a :class:`RefValue` with ``method == "mpmath"`` and ``reason``."""
    with workdps(dps + 10):
        val = fallback()
        val = val.mid if isinstance(val, RefValue) else +mpmath.mpf(val)
    return RefValue(val, mpmath.mpf(0), MPMATH, reason)


def combine(expr, sym, ref, dps: int = 45) -> RefValue:
    """``expr`` (SymPy, in the symbol ``sym``, or in the list of symbols
    ``sym``; every other value exact) at ``sym`` = the reference ``ref`` (a
    :class:`RefValue`, or a list of them matching the list of symbols):
    rigorous in Arb when every reference is an enclosure (the terms of a
    reference outside its integral: the gap's f(x) - (2/(pi E*)) [P(a)
    acosh(x/a) + x J]; a stress made from the three Flamant components, von
    Mises or the principal shear), else in mpmath, with the first reason a
    reference gives why not."""
    several = isinstance(sym, (list, tuple))
    syms, refs = (list(sym), list(ref)) if several else ([sym], [ref])
    if len(syms) != len(refs):
        raise ValueError(f"{len(refs)} references for {len(syms)} symbols")
    why = next((r.note for r in refs if not r.certified), None)
    note = why if why is not None else next((r.note for r in refs if r.note), "")
    if why is None and all(r.ball is not None for r in refs):
        try:
            with flint.ctx.workprec(_bits(dps) + 64):
                f = compile_acb(expr, syms if several else sym)
                b = f(tuple(r.ball for r in refs) if several else ref.ball, False)
                if b.is_finite() and 0 in b.imag:
                    return RefValue(mpf_of_arb(b.real.mid()), mpf_of_arb(b.real.rad()), ARB, note, ball=b)
        except ArbUnsupported:
            pass
    from .exports import lambdify_mpmath
    with workdps(dps + 10):
        val = mpmath.re(lambdify_mpmath(expr, syms)(*[r.mid for r in refs]))
    return RefValue(+val, mpmath.mpf(0), MPMATH, note or "outer terms not in Arb")


def lincomb(terms, dps: int = 45, note: str = "") -> RefValue:
    """sum(coef * value) for ``terms`` [(coef, value)]: ``coef`` an exact
    number, ``value`` a :class:`RefValue` or an exact SymPy number (a closed
    term beside the integrals: mu p(x) outside the stick zone).  Rigorous in
    Arb when every RefValue is an enclosure, else an mpmath estimate that
    keeps the first reason why not."""
    refs = [v for _, v in terms if isinstance(v, RefValue)]
    why = next((r.note for r in refs if not r.certified), None)
    if why is None and all(r.ball is not None for r in refs):
        try:
            with flint.ctx.workprec(_bits(dps) + 64):
                b = flint.acb(0)
                for c, v in terms:
                    b += to_acb(c) * (v.ball if isinstance(v, RefValue) else to_acb(v))
            if b.is_finite() and 0 in b.imag:
                return RefValue(mpf_of_arb(b.real.mid()), mpf_of_arb(b.real.rad()), ARB, note, ball=b)
        except ArbUnsupported as exc:
            why = str(exc)
    with workdps(dps + 10):
        val = mpmath.fsum(to_mpf(c) * (v.mid if isinstance(v, RefValue) else to_mpf(v)) for c, v in terms)
    return RefValue(val, mpmath.mpf(0), MPMATH, why or note)


def _per_piece(integrand, points):
    """The integrand of each piece (one expression for all, or a list)."""
    if isinstance(integrand, (list, tuple)):
        if len(integrand) != len(points) - 1:
            raise ValueError(f"{len(integrand)} integrands for {len(points) - 1} pieces")
        return list(integrand)
    return [integrand] * (len(points) - 1)


def _arb_integral(integrand, var, points, dps, eval_limit, crude=None, values=None):
    goal = _bits(dps)
    prec = _bits(dps) + 30 if crude is None else 2 * goal + 40

    def compiled(expr):
        main = expr if is_compiled(expr) else compile_at(expr, var, values)
        if crude is None:
            return main

        def f(z, an):
            v = main(z, an)
            return v if v.is_finite() else crude(z, an)
        return f
    fs = {}
    for e in _per_piece(integrand, points):
        if e not in fs:
            fs[e] = compiled(e)
    with flint.ctx.workprec(prec):
        exact = [_exact(p) if values is None else value_at(p, values) for p in points]
        ends = exact if values is None else [sp.sympify(p, strict=True) for p in points]
        total = flint.acb(0)
        tol = flint.arb(2) ** -(goal + 8)

        def piece(fn, lo, hi):
            lo_b, hi_b = to_acb(lo), to_acb(hi)
            _ends_bounded(fn, lo_b, hi_b)
            try:
                v = flint.acb.integral(fn, lo_b, hi_b, rel_tol=tol, eval_limit=eval_limit)
            except (ZeroDivisionError, ValueError, TypeError) as exc:
                raise ArbUnsupported(f"Arb could not evaluate the integrand: {exc}") from None
            if not v.is_finite():
                raise ArbUnsupported("Arb could not bound a piece (a singularity at an end point that "
                                     "ball arithmetic cannot enclose, or the evaluation limit)")
            return v
        for e, lo, hi, lo_s, hi_s in zip(_per_piece(integrand, points), exact[:-1], exact[1:], ends[:-1], ends[1:]):
            try:
                total += piece(fs[e], lo, hi)
            except ArbUnsupported:
                # ``crude`` bounds the integrand next to t = 0 only: a piece from 0 has no other remedy
                if (crude is not None and lo == 0) or not (isinstance(lo, sp.Basic) and isinstance(hi, sp.Basic)) \
                        or not isinstance(e, sp.Basic):
                    raise
                total += singular_piece(e, var, lo_s, hi_s, piece, values)
        if 0 not in total.imag:
            raise ArbUnsupported(f"the integral is not real: {total}")
        re_ = total.real
        if not re_.is_finite():
            raise ArbUnsupported("non-finite enclosure")
        if re_.rel_accuracy_bits() < goal and re_.rad() > flint.arb(2) ** -goal:
            raise ArbUnsupported(f"enclosure too wide: {re_.rel_accuracy_bits()} of {goal} bits")
        return total


def _exact(p):
    """A break point as an exact SymPy number where it is one (an mpf is its
    binary value); as given where it is not."""
    try:
        q = number(p) if not isinstance(p, sp.Basic) else p
    except LineContactError:
        return p
    return q if q.is_number and q.is_real is not False else p


def _ends_bounded(f, lo, hi):
    """Fail at once where Arb would spend its evaluation limit in vain: the
    integrand must have a finite ball on a short segment at each end of the
    piece (an integrable 1/sqrt or log singularity there has none; a
    removable one with a ``crude`` bound, a sqrt-type branch point, a
    Piecewise decided next to its switch have one)."""
    eps = (hi - lo) * flint.arb(2) ** -30
    for end in ((lo).union(lo + eps), (hi - eps).union(hi)):
        try:
            v = f(flint.acb(end.real), False)
        except (ZeroDivisionError, ValueError, TypeError):
            v = nan_ball()
        if not v.is_finite():
            raise ArbUnsupported("Arb cannot bound the integrand next to an end point of a piece (an integrable "
                                 "singularity such as 1/sqrt or log there: ball arithmetic has no finite bound)")


def _mpmath_integral(integrand, var, points, dps):
    from .exports import lambdify_mpmath
    pts = [to_mpf(p) for p in points]
    pieces = _per_piece(integrand, points)
    if all(e is pieces[0] for e in pieces):
        pieces, spans = pieces[:1], [pts]
    else:
        spans = [pts[k:k + 2] for k in range(len(pieces))]
    total = 0
    for e, span in zip(pieces, spans):
        g = lambdify_mpmath(e, [var])

        def h(t, g=g):
            v = g(t)
            return mpmath.re(v) if isinstance(v, mpmath.mpc) and abs(mpmath.im(v)) < mpmath.eps * abs(v) else v
        total += mpmath.quad(h, span)
    return total
