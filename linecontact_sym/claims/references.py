"""Independent numerical references of the checker.

Nothing here uses the engine's routes (no transform, rule or contact): the
printed formulas are evaluated as they stand, their integrals by tanh-sinh
quadrature with a divergence test (:func:`quad_integral`); pressures are
checked against the elasticity of the half-plane itself (the Flamant kernel:
:func:`flamant_relative_displacement`, :func:`flamant_resultant`); the
critical force of a pulled punch is derived by two physical routes
(:func:`griffith_punch_force`); the pull-off load by a plain minimum search
(:func:`numeric_minimum`).  :class:`Comparison` measures agreeing digits.

Integrals of printed formulas go to the one reference integrator first
(:func:`linecontact_sym.numeric.reference.integrate`: an Arb enclosure,
end-point powers and logarithms substituted or subtracted there; a
removable 0/0 N(t)/t^k with its maximum-modulus bound); so do the Flamant integrals
of a pressure given as a SymPy expression (the one Flamant routine,
:func:`linecontact_sym.numeric.flamant.flamant_arb`, which the
Maugis-Dugdale checks share).
Where Arb cannot enclose one, the tanh-sinh route runs, with the generic
quadrature helpers of :mod:`linecontact_sym.core.quadrature`.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import mpmath
import sympy as sp

from ..core.conversion import to_basic, to_mpf
from ..core.quadrature import EndpointGuard, endpoint_exponent, quad_dps, quad_segments, relational_breakpoints
from ..core.precision import workdps
from ..core.roots import root_in_bracket
from ..core.errors import LineContactError
from ..numeric.flamant import finite_at, flamant_arb, flamant_tanh_sinh, kernel_points, kernel_points_at, tanh_sinh
from ..numeric.arb_compile import ArbUnsupported
from ..numeric.reference import integrate

#: working precision of the comparisons (digits)
DPS = 45


class Undefined(Exception):
    """The quantity or the printed formula has no (real, finite) value here."""


class Divergent(Undefined):
    """An integral in the printed formula diverges here."""


class DerivedUndefined(Undefined):
    """The derived quantity does not exist here (outside its conditions, no
    pull-off, ...)."""


def finite_real(v, what, dps, exc=Undefined):
    """mpf of a SymPy number, or raise ``exc`` (an :class:`Undefined`) naming
    ``what`` when it is not finite or not real to ``dps - 8`` digits."""
    if v.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        raise exc(f"{what} is undefined here ({v})")
    try:
        re, im = v.as_real_imag()
        re, im = sp.N(re, dps), sp.N(im, dps)
    except Exception as err:  # noqa: BLE001
        raise exc(f"{what} cannot be evaluated here: {err}")
    if not (re.is_number and im.is_number) or not re.is_finite:
        raise exc(f"{what} cannot be evaluated here: {v}")
    if im != 0 and abs(im) > max(abs(re), sp.Float(1e-300)) * sp.Float(10) ** (-(dps - 8)):
        raise exc(f"{what} is complex here ({sp.N(v, 8)})")
    return mpmath.mpf(str(re))


def quad_integral(I: sp.Integral, dps: int = DPS):
    """Numeric value of a one-dimensional definite Integral with numeric limits.

    Tanh-sinh at :func:`~linecontact_sym.core.quadrature.quad_dps` working
    digits, split at the switching points of ``Piecewise`` conditions, with a
    divergence test at both endpoints: a local power <= -1 raises
    :class:`Divergent`; a strong integrable singularity is smoothed by a
    substitution first.  Raises :class:`Undefined` for free symbols or a
    complex integrand.

    >>> t = sp.Symbol("t", positive=True)
    >>> v = quad_integral(sp.Integral(1 / sp.sqrt(1 - t**2), (t, 0, 1)))
    >>> with workdps(50):
    ...     print(abs(v - mpmath.pi / 2) < mpmath.mpf(10) ** -40)
    True
    """
    if len(I.limits) != 1 or len(I.limits[0]) != 3:
        raise Undefined(f"only one-dimensional definite integrals are evaluated: {I}")
    var, lo, hi = I.limits[0]
    f = I.function
    if f.free_symbols - {var}:
        raise Undefined(f"the integrand has free symbols {sorted(map(str, f.free_symbols - {var}))}")
    certified = _arb_integral(f, var, lo, hi, dps)
    if certified is not None:
        return certified
    with workdps(quad_dps(dps)):
        lo_v, hi_v = to_mpf(lo), to_mpf(hi)
        if lo_v == hi_v:
            return mpmath.mpf(0)
        sign = 1
        if hi_v < lo_v:
            lo_v, hi_v, sign = hi_v, lo_v, -1
        g = EndpointGuard(sp.lambdify(var, f, "mpmath"), lo_v, hi_v)
        span = hi_v - lo_v
        alphas = []
        for e, d in ((lo_v, 1), (hi_v, -1)):
            alpha = endpoint_exponent(g, e, d, span)
            if alpha is not None and alpha <= -1 + 1e-3:
                raise Divergent(f"the integral {I} diverges at {var} = {sp.N(e, 6)} "
                                f"(integrand ~ |{var} - {sp.N(e, 6)}|^{alpha:.3g})")
            alphas.append(alpha)
        pts = [lo_v] + relational_breakpoints(f, var, lo_v, hi_v) + [hi_v]
        try:
            v = quad_segments(g, pts, alphas)
        except (ZeroDivisionError, ValueError) as exc:
            raise Undefined(f"the integral {I} cannot be evaluated: {exc}")
        if g.complex_at is not None:
            raise Undefined(f"the integrand of {I} is complex at {var} = {mpmath.nstr(g.complex_at, 8)}")
        return sign * v


def _arb_integral(f, var, lo, hi, dps):
    """The integral by the one reference integrator when Arb encloses it
    (a finite enclosure also proves the integral converges); None otherwise,
    and the tanh-sinh route with its divergence test runs."""
    try:
        lo_b, hi_b = sp.sympify(lo, strict=True), sp.sympify(hi, strict=True)
        if not (lo_b.is_real and hi_b.is_real) or lo_b == hi_b:
            return None
        sign = 1
        if (hi_b < lo_b) == sp.true:
            lo_b, hi_b, sign = hi_b, lo_b, -1
        with workdps(quad_dps(dps)):
            pts = [lo_b] + relational_breakpoints(f, var, to_mpf(lo_b), to_mpf(hi_b)) + [hi_b]
        r = integrate(f, var, pts, dps, fallback=lambda: mpmath.nan, removable=True)
    except (ArbUnsupported, TypeError, ValueError, ZeroDivisionError):
        return None
    if not r.certified:
        return None
    return r if sign == 1 else -r


def num_eval(expr: sp.Expr, vals: dict, dps: int = DPS, what: str = "the printed formula", exc=Undefined):
    """mpf value of an expression at a point; integrals by :func:`quad_integral`,
    derivatives symbolically.  Raises ``exc`` (an :class:`Undefined`) where
    the value is not real and finite.  See :func:`_numeric_values` for how
    the values are substituted.

    >>> import linecontact_sym as lcs
    >>> print(mpmath.nstr(num_eval(lcs.a**2 / 2, {lcs.a: sp.Integer(3)}), 10))
    4.5
    """
    e = expr.xreplace(_numeric_values(expr, vals, dps))
    if e.has(sp.Derivative):
        e = e.replace(lambda z: isinstance(z, sp.Derivative), lambda z: z.doit())
    if e.has(sp.Integral):
        e = e.replace(lambda z: isinstance(z, sp.Integral),
                      lambda z: sp.Float(quad_integral(z, dps), dps + 10))
    with workdps(dps + 10):
        return finite_real(sp.N(e, dps + 10), what, dps, exc)


def _numeric_values(expr, vals, dps):
    """Values to substitute: exact rationals, except for symbols that appear
    in exponents (a**n), which become Floats of 2*dps + 30 digits -- SymPy
    would factor large integers for an exact rational power.  Bases stay
    exact so that cancellations such as R - sqrt(R**2 - t**2) at t -> 0 are
    resolved by the working precision."""
    in_exponent = set()
    for pw in expr.atoms(sp.Pow):
        in_exponent |= pw.exp.free_symbols
    out = {}
    for k, v in vals.items():
        v = to_basic(v)
        if k in in_exponent and v.is_Rational and (v.q > 12 or abs(v.p) > 10**4):
            v = sp.Float(v, quad_dps(dps) + 20)
        out[k] = v
    return out


def flamant_relative_displacement(p, a, xv, E, dps=DPS, breaks=(), with_error=False, values=None):
    """u_z(0) - u_z(x) of the half-plane under the even pressure p(s) on |s| < a
    (Flamant/Boussinesq kernel; reference-free)::

        u_z(0) - u_z(x) = (2/(pi E*)) int_0^a p(s) ln|x^2/s^2 - 1| ds

    For a rigid indenter in contact on |x| < a this equals the profile f(x);
    outside it is d - u_z(x), the quantity of Eq. (3).

    ``p``: a SymPy expression in one symbol (the pressure, every parameter a
    number), or an mpmath callable; a, x, E* exact numbers or mpf.  A SymPy
    ``p`` goes to the one reference integrator first
    (:func:`~linecontact_sym.numeric.flamant.flamant_arb`: ln|x^2/s^2 - 1|
    = ln|x - s| + ln(x + s) - 2 ln s, each logarithmic point at the end of
    a piece by :func:`~linecontact_sym.numeric.reference.log_end_integral`;
    a pressure with a break point (the rounded punch's
    slope has a logarithm at the end of its flat) or unbounded at 0 (the
    wedge's acosh(a/s)) as one integral of the kernel, whose logarithmic
    end points the integrator splits; a certified enclosure).  Where Arb cannot enclose
    it, a SymPy pressure without a finite value at s = a goes to the one
    tanh-sinh Flamant routine
    (:func:`~linecontact_sym.numeric.flamant.flamant_tanh_sinh`: its last
    part in s = a - d u^q, the radicands factored).  Otherwise (or ``p`` a
    callable), tanh-sinh: s = a sin(phi) (removes the
    inverse-square-root edge singularity of flat-punch-like pressures),
    split at the logarithmic point s = x and at ``breaks`` (the profile's
    breakpoints: the pressure of a rounded punch has a logarithmic
    singularity of its slope at the end of the flat, where a quadrature
    across it keeps 7 digits).

    ``with_error``: returns ``(value, error)``: the enclosure's radius (Arb)
    or mpmath's error estimate of the quadrature (see
    :func:`flamant_magnitude` for the scale of an absolute comparison).

    ``values`` (symbol -> number): ``p`` and ``breaks`` hold these
    parameters as symbols (``p`` a SymPy expression in one more symbol, the
    pressure's variable): Arb gets the forms made once with the parameters
    as symbols (:func:`~linecontact_sym.numeric.flamant.flamant_arb`), so
    that the points of a claim share its symbolic work; where Arb cannot,
    the routes below run on ``p`` at ``values``.

    The flat punch P/(pi sqrt(a^2 - s^2)) leaves the surface flat under it:

    >>> p = lambda s: 1 / (mpmath.pi * mpmath.sqrt(1 - s**2))
    >>> with workdps(30):
    ...     print(abs(flamant_relative_displacement(p, 1, sp.Rational(1, 2), 1, 20)) < 1e-25)
    True
    >>> s = sp.Symbol("s")
    >>> v, err = flamant_relative_displacement(1 / (sp.pi * sp.sqrt(1 - s**2)), 1, sp.Rational(1, 2), 1, 40,
    ...                                        with_error=True)
    >>> print(abs(v) <= err < 1e-40, v.method)
    True arb
    """
    if values:
        ref = _flamant_arb(p, a, xv, E, dps, breaks, values)
        if ref is not None:
            return (ref, ref.rad) if with_error else ref
        p, breaks = _at_values(p, breaks, values, dps)
    if isinstance(p, sp.Expr):
        s = _pressure_symbol(p)
        # Arb needs p(0) (the log point s = 0 is removed by subtracting it)
        ref = _flamant_arb(p, a, xv, E, dps, breaks) if s is not None else None
        if ref is not None:
            return (ref, ref.rad) if with_error else ref
        pc = _callable(p)
        real_on_contact(pc, a, breaks)
        est = None if s is None or finite_at(p, s, a) else \
            flamant_tanh_sinh([(p, s, sp.S.Zero, to_basic(a))], xv, E, dps, breaks)
        if est is not None:
            return est if with_error else est[0]
        p = pc
    else:
        real_on_contact(p, a, breaks)
    with workdps(quad_dps(dps)):
        a, xv, E = to_mpf(a), to_mpf(xv), to_mpf(E)
        h, pts = _flamant_integrand(p, a, xv, breaks)
        val, err = _guarded_quad(h, pts)
        k = 2 / (mpmath.pi * E)
        return (+(k * val), +(k * err)) if with_error else +(k * val)


#: interior sample points of :func:`real_on_contact`, fractions of a
_SAMPLES = tuple(sp.Rational(k, 16) for k in range(1, 16)) + (sp.Rational(31, 32), sp.Rational(63, 64))


def real_on_contact(p, a, breaks=(), digits: int = 20):
    """Raise :class:`Undefined` at once where the pressure ``p`` (an mpmath
    callable) is not real or not finite at a sample point of the contact
    (0, a) (s = k a/16, 31a/32, 63a/64, and the middles of the pieces
    between ``breaks``; not 0 nor a break point, where a pressure may be
    unbounded and integrable: the wedge's acosh(a/s)), before any quadrature: a pressure written for
    another half-width (P/(2 pi sqrt(a^2/4 - s^2)), imaginary on (a/2, a])
    has no resultant and no Flamant displacement, and a quadrature of its
    real part would return an unconverged number.  A value found complex or
    infinite proves it; the samples prove nothing where they pass (the
    quadratures then watch every node: :func:`_guarded_quad`).

    >>> real_on_contact(lambda s: 1 / mpmath.sqrt(1 - s**2), 1)
    >>> real_on_contact(lambda s: 1 / mpmath.sqrt(mpmath.mpf(1) / 3 - s**2), 1)
    Traceback (most recent call last):
    ...
    linecontact_sym.claims.references.Undefined: the pressure is not real on the contact: p(0.625) = ...
    """
    with workdps(digits):
        a_v = to_mpf(a)
        pts = [a_v * to_mpf(q) for q in _SAMPLES]
        cuts = sorted({to_mpf(b) for b in breaks if 0 < to_mpf(b) < a_v})
        pts += [(u + v) / 2 for u, v in zip([mpmath.mpf(0)] + cuts, cuts + [a_v])]
        pts = [sv for sv in pts if sv not in cuts]
        for sv in pts:
            try:
                v = p(sv)
            except (ZeroDivisionError, ValueError, TypeError) as exc:
                raise Undefined(f"the pressure has no value at s = {mpmath.nstr(sv, 6)} on the contact "
                                f"(|s| < a = {mpmath.nstr(a_v, 8)}): {type(exc).__name__} {exc}".rstrip()) from None
            if not mpmath.isfinite(v):
                raise Undefined(f"the pressure is not finite on the contact: p({mpmath.nstr(sv, 6)}) = {v} "
                                f"(|s| < a = {mpmath.nstr(a_v, 8)})")
            if isinstance(v, mpmath.mpc) and abs(v.imag) > abs(v.real) * mpmath.mpf(10) ** (4 - digits):
                raise Undefined(f"the pressure is not real on the contact: p({mpmath.nstr(sv, 6)}) = "
                                f"{mpmath.nstr(v, 5)} (|s| < a = {mpmath.nstr(a_v, 8)})")


def _guarded_quad(h, pts):
    """mpmath.quad of the tanh-sinh route's integrand ``h`` (of phi) whose
    pressure is read through an :class:`EndpointGuard`: (value, error), or
    :class:`Undefined` where a node found the pressure complex or not
    finite away from the ends (what :func:`real_on_contact`'s samples
    missed)."""
    try:
        val, err = mpmath.quad(h, pts, maxdegree=10, error=True)
    except ZeroDivisionError as exc:
        raise Undefined(f"the pressure has no value at a node inside the contact: {exc}") from None
    guard = getattr(h, "guard", None)
    if guard is not None and guard.complex_at is not None:
        raise Undefined(f"the pressure is not real on the contact: complex at s = {mpmath.nstr(guard.complex_at, 8)}")
    if not (mpmath.isfinite(val) and mpmath.isfinite(err)):
        raise Undefined("the pressure's integral over the contact is not finite")
    return val, err


def flamant_magnitude(p, a, xv, E, breaks=()):
    """(2/(pi E*)) int_0^a |p(s) ln|x^2/s^2 - 1|| ds: the size of the terms that
    cancel to :func:`flamant_relative_displacement` (the scale of an
    absolute comparison where that value is 0, inside a flat).  A scale,
    not a value: tanh-sinh at 20 digits (``p`` SymPy or an mpmath callable).

    >>> p = lambda s: 1 / (mpmath.pi * mpmath.sqrt(1 - s**2))
    >>> print(mpmath.nstr(flamant_magnitude(p, 1, sp.Rational(1, 2), 1), 5))
    0.36026
    """
    if isinstance(p, sp.Expr):
        p = _callable(p)
    with workdps(20):
        a, xv, E = to_mpf(a), to_mpf(xv), to_mpf(E)
        h, pts = _flamant_integrand(p, a, xv, breaks)
        return +(2 / (mpmath.pi * E) * mpmath.quad(lambda ph: abs(h(ph)), pts, maxdegree=6))


def _flamant_integrand(p, a, xv, breaks):
    """The tanh-sinh route's integrand of phi (s = a sin(phi)) and its pieces."""
    pr = EndpointGuard(p, mpmath.mpf(0), a)

    def h(ph):
        sv = a * mpmath.sin(ph)
        return pr(sv) * mpmath.log(abs(xv**2 / sv**2 - 1)) * a * mpmath.cos(ph)
    h.guard = pr
    return h, _split_points(a, [xv] + [to_mpf(b) for b in breaks])


def _callable(p):
    """An mpmath callable of a SymPy pressure in (at most) one symbol."""
    syms = sorted(p.free_symbols, key=lambda z: z.name)
    if len(syms) > 1:
        raise Undefined(f"the pressure {p} has free symbols {syms}")
    f = sp.lambdify(syms or [sp.Dummy()], p, "mpmath")
    return f


def break_value(b, dps):
    """A breakpoint as an exact number where it is one (Arb splits there
    exactly), else an mpf of dps + 20 digits."""
    return b if b.is_Rational else to_mpf(sp.N(b, dps + 20))


def _at_values(p, breaks, values, dps):
    """The pressure and its break points at the parameters' values
    (:func:`break_value`)."""
    return p.xreplace(values), [break_value(to_basic(b).xreplace(values), dps) for b in breaks]


def _pressure_symbol(p, values=None):
    syms = p.free_symbols - set(values or ())
    if len(syms) > 1:
        return None
    return next(iter(syms)) if syms else sp.Dummy("s")


def _flamant_arb(p, a, xv, E, dps, breaks, values=None):
    """The Flamant displacement by Arb (see :func:`flamant_relative_displacement`):
    a certified RefValue, or None (the tanh-sinh route runs)."""
    s = _pressure_symbol(p, values)
    if s is None:
        return None
    try:
        piece = (p, s, sp.S.Zero, to_basic(a))
    except (LineContactError, TypeError, ValueError):
        return None
    return flamant_arb([piece], xv, E, dps, breaks, values)


def _split_points(a, inner):
    """0, the angles asin(s/a) of the points s strictly inside (0, a), pi/2."""
    angles = sorted({mpmath.asin(s / a) for s in inner if 0 < s < a})
    return [mpmath.mpf(0)] + angles + [mpmath.pi / 2]


def flamant_resultant(p, a, dps=DPS, breaks=(), with_error=False, values=None):
    """The resultant int_{-a}^{a} p(s) ds of an even pressure, split at
    ``breaks`` (see :func:`flamant_relative_displacement`: a SymPy ``p``
    goes to Arb, an mpmath callable or what Arb cannot enclose to
    tanh-sinh with s = a sin(phi)); ``with_error``: ``(value, error)``,
    the enclosure's radius or mpmath's error estimate; ``values``: ``p``
    and ``breaks`` hold these parameters (see
    :func:`flamant_relative_displacement`), Arb gets the forms made once.

    >>> with workdps(30):
    ...     print(mpmath.nstr(flamant_resultant(lambda s: 1 / (mpmath.pi * mpmath.sqrt(4 - s**2)), 2, 20), 15))
    1.0
    >>> s = sp.Symbol("s")
    >>> r = flamant_resultant(1 / (sp.pi * sp.sqrt(4 - s**2)), 2, 40)
    >>> print(r.method, r.contains(1), r.digits > 40)
    arb True True
    """
    if values:
        s = _pressure_symbol(p, values)
        ref = None
        if s is not None:
            try:
                ref = integrate(2 * p, s, kernel_points_at(0, to_basic(a), [to_basic(b) for b in breaks], values),
                                dps, fallback=lambda: mpmath.nan, values=dict(values))
            except (ArbUnsupported, LineContactError, TypeError, ValueError, ZeroDivisionError):
                ref = None
        if ref is not None and ref.certified:
            return (ref, ref.rad) if with_error else ref
        p, breaks = _at_values(p, breaks, values, dps)
    if isinstance(p, sp.Expr):
        s = _pressure_symbol(p)
        if s is not None:
            try:
                a_b = to_basic(a)
                ref = integrate(2 * p, s, kernel_points(0, a_b, [to_basic(b) for b in breaks]), dps,
                                fallback=lambda: mpmath.nan)
            except (ArbUnsupported, LineContactError, TypeError, ValueError, ZeroDivisionError):
                ref = None
            if ref is not None and ref.certified:
                return (ref, ref.rad) if with_error else ref
        pc = _callable(p)
        real_on_contact(pc, a, breaks)
        if s is not None:
            est = tanh_sinh(2 * p, s, 0, a, list(breaks), dps) if not finite_at(p, s, a) else None
            if est is not None:
                return est if with_error else est[0]
        p = pc
    else:
        real_on_contact(p, a, breaks)
    with workdps(quad_dps(dps)):
        a = to_mpf(a)
        pr = EndpointGuard(p, mpmath.mpf(0), a)

        def h(ph):
            return pr(a * mpmath.sin(ph)) * a * mpmath.cos(ph)
        h.guard = pr
        val, err = _guarded_quad(h, _split_points(a, [to_mpf(b) for b in breaks]))
        return (+(2 * val), +(2 * err)) if with_error else +(2 * val)


def frozen_lambdify(expr, var, dps):
    """An mpmath callable of ``expr`` in ``var`` whose subexpressions free of
    ``var`` (Z_n's gamma(n/2 - 1/2)/gamma(n/2), sqrt(pi), sqrt(2 pi gamma E*))
    are evaluated once, at ``dps`` digits, not at each of the thousands of
    calls a scan makes."""
    consts = {}

    def fold(e):
        if not e.has(var):
            if e.is_Atom or e.is_Rational:
                return e
            d = consts.get(e)
            if d is None:
                d = consts[e] = sp.Dummy()
            return d
        if e.is_Atom or not e.args:
            return e
        return e.func(*[fold(t) for t in e.args])
    folded = fold(expr)
    dummies = list(consts.values())
    with workdps(dps):
        values = [sp.lambdify([], c, "mpmath")() for c in consts]
    f = sp.lambdify([var] + dummies, folded, "mpmath")
    return lambda x: f(x, *values)


@functools.lru_cache(maxsize=8)
def _quarter_decades(scale, dps):
    """scale * 10^(k/4), k = -1200..1200, at ``dps`` digits: quarter decades
    from 1e-300 to 1e300 (near an existence bound, n -> 1/2 for a power law,
    the minimum moves out to astronomically small or large a).  Built once
    per (scale, digits): 2,401 powers cost more than a scan."""
    with workdps(dps):
        return tuple(scale * mpmath.mpf(10) ** (k / mpmath.mpf(4)) for k in range(-1200, 1201))


# TODO(registry): use contacts.force_law (the integrator replaces this third copy of a 1-D minimum finder)
def numeric_minimum(P, dP, scale, dps=DPS):
    """(a*, P(a*)) of the smallest local minimum of P(a) for a > 0, located
    from the sign change of dP/da (- to +) on a logarithmic grid (a kink of
    P(a) where dP/da jumps from - to + included); None when P has no minimum
    (the pull-off does not exist)."""
    with workdps(dps + 10):
        grid = _quarter_decades(mpmath.mpf(scale), dps + 10)
        prev = None
        for av in grid:
            try:
                d = dP(av)
            except (ZeroDivisionError, ValueError):
                prev = None
                continue
            if isinstance(d, mpmath.mpc):
                prev = None
                continue
            if prev is not None and prev[1] < 0 <= d:
                # the package's bracketed root finder: a minimum at a kink of P(a),
                # where dP/da jumps from - to + without a zero, is the limit of its
                # bisection (findroot alone raised 'Could not find root' there: a
                # pull-off claim on such a profile got 'does not hold')
                root = root_in_bracket(dP, prev[0], av)
                return root, P(root)
            prev = (av, d)
    return None


def griffith_punch_force():
    """The critical force Phat of a flat punch of half-width a pulled off the
    half-plane (Eq. 31), derived symbolically by two physical routes:

    1. energy: the compliance C(a) = (2/(pi E*)) arccosh(L/a) from Eq. (3) at
       a far point L; the energy-release rate per edge at fixed load
       G = Phat^2/2 (-dC/da)/2 = gamma;
    2. stress intensity of the pulled punch: K_I = lim sqrt(2 pi (a - xi))
       p(xi) with p = Phat/(pi sqrt(a^2 - xi^2)); G = K_I^2/(2 E*) = gamma.

    Returns (solutions of route 1, solutions of route 2, G, K_I).
    """
    from ..core import symbols as S
    Ph, L, xx = sp.symbols("Phat L xi", positive=True)
    a, E, g = S.a, S.E_star, S.gamma
    C = 2 / (sp.pi * E) * sp.acosh(L / a)
    dCda = sp.limit(sp.diff(C, a), L, sp.oo)
    G_energy = sp.simplify(Ph**2 / 2 * (-dCda) / 2)          # per contact edge
    sol1 = sp.solve(sp.Eq(G_energy, g), Ph)
    p = Ph / (sp.pi * sp.sqrt(a**2 - xx**2))
    K = sp.limit(sp.sqrt(2 * sp.pi * (a - xx)) * p, xx, a, "-")
    sol2 = sp.solve(sp.Eq(K**2 / (2 * E), g), Ph)
    return sol1, sol2, G_energy, K


def resolution(err, scale, floor: float = 10.0) -> float:
    """The digits a numeric check resolves: -log10(err/scale) less one digit of
    margin, for mpmath's error estimate ``err`` of a value of size ``scale``;
    at least ``floor`` (a check below it is not a check: it fails)."""
    with workdps(2 * DPS):
        if err == 0 or scale == 0:
            return float(DPS)
        return max(floor, min(float(DPS), float(-mpmath.log10(abs(err) / abs(scale))) - 1))


@dataclass
class Comparison:
    """A printed value against a target: ``digits`` is the number of agreeing
    significant digits, -log10(|printed - target|/scale), in [0, DPS]; the
    scale is |target| unless given (|printed| when the target is 0).

    >>> round(Comparison("x", mpmath.mpf("1.001"), mpmath.mpf(1)).digits, 6)
    3.0
    """

    what: str
    printed: object          # mpf
    target: object           # mpf
    scale: object = None     # mpf; default |target|
    resolution: float | None = None   # digits the check itself resolves (None: all of DPS)

    def required(self, digits: float) -> float:
        """The digits this comparison must show to pass when ``digits`` are
        asked: no more than the check resolves (a quadrature of a kernel
        with a logarithmic point is not good to 30 digits everywhere; its
        own error estimate says how far it is)."""
        return digits if self.resolution is None else min(digits, self.resolution)

    @property
    def digits(self) -> float:
        with workdps(2 * DPS):     # never at mpmath's default 15 digits
            err = abs(self.printed - self.target)
            scale = self.scale if self.scale is not None else abs(self.target)
            if err == 0:
                return float(DPS)
            if scale == 0:
                scale = abs(self.printed)
                if scale == 0:
                    return float(DPS)
            return max(0.0, min(float(DPS), float(-mpmath.log10(err / scale))))


__all__ = ["DPS", "Undefined", "Divergent", "DerivedUndefined", "finite_real", "quad_integral", "num_eval",
           "flamant_relative_displacement", "flamant_resultant", "flamant_magnitude", "resolution", "numeric_minimum", "frozen_lambdify", "griffith_punch_force",
           "Comparison", "break_value"]
