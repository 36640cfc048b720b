"""The certified references of the normal problem: the defining integrals of
Popov (2017) handed to the one reference integrator
(:func:`linecontact_sym.numeric.reference.integrate`, Arb ball quadrature,
mpmath as the recorded fallback).

Each integrand is the one of :mod:`linecontact_sym.method.transforms`, after
the same substitutions that make it smooth at the ends, written as a SymPy
expression in the integration variable with every parameter replaced by its
(exact) value, so that Arb encloses the integral rigorously:

* Eq. (10*), t = a sin(phi):  P(a) = E* a int_0^{pi/2} sin(phi) f'(a sin phi) dphi,
  split at the profile's breakpoints (found numerically at the point, by
  :class:`~linecontact_sym.method.transforms.NumericProfile`: hints for speed,
  the Piecewise is decided on the balls themselves);
* Eq. (12), s = sqrt(x^2 + w^2): p(x; a) = (1/pi) int_0^{sqrt(a^2 - x^2)} P'(s)/s dw;
* the gap (Eqs. 3/5) integrated by parts, which moves the logarithmic end
  point of acosh(x/s) into a closed term (P(0) = 0):
  g(x) = f(x) - (2/(pi E*)) [P(a) acosh(x/a) + x int_0^a P(s) / (s sqrt(x^2 - s^2)) ds].

The mpmath fallbacks are the ``*_quad`` functions of
:mod:`~linecontact_sym.method.transforms` (what every reference was before).
Each function returns a :class:`~linecontact_sym.numeric.reference.RefValue`
(an mpf that carries its radius and the method used).
"""
from __future__ import annotations

import mpmath
import sympy as sp

from ...core import symbols as S
from ...core.conversion import to_mpf
from ...core.errors import DomainError
from ...core.precision import workdps
from ...method import transforms as T
from ...numeric.reference import combine, estimate, integrate, quotient_bound

_phi = sp.Dummy("phi", positive=True)
_w = sp.Dummy("w", nonnegative=True)
_s = sp.Dummy("s", positive=True)
_J = sp.Dummy("J")


def _params(vals):
    return {k: v for k, v in vals.items() if k not in (S.a, S.x)}


def force_reference(profile, vals: dict, dps: int):
    """Eq. (10*) at ``vals`` (which hold a and every parameter)."""
    A = vals[S.a]
    E = vals.get(S.E_star, 1)
    npf = T.NumericProfile(profile, vals)
    f1 = npf.slope
    integrand = E * A * sp.sin(_phi) * f1.xreplace({S.x: A * sp.sin(_phi)})
    with workdps(dps + 30):
        Am = to_mpf(A)
        pts = [0] + [mpmath.asin(k / Am) for k in npf.kinks(0, Am)] + [sp.pi / 2]
    return integrate(integrand, _phi, pts, dps, fallback=lambda: T.force_quad(profile, vals, dps))


def pressure_reference(force_law, breaks, vals: dict, dps: int, fallback):
    """Eq. (12) at ``vals`` for the closed force law ``force_law`` (SymPy, in a)
    with break points ``breaks`` (numbers at these parameters)."""
    A, X = vals[S.a], abs(vals[S.x])
    dP = sp.diff(force_law, S.a).xreplace(_params(vals))
    sv = sp.sqrt(X**2 + _w**2)
    integrand = dP.xreplace({S.a: sv}) / (sp.pi * sv)
    inner = sorted((sp.sqrt(b**2 - X**2) for b in breaks if (X < b) == sp.true and (b < A) == sp.true),
                   key=lambda v: to_mpf(v))
    return integrate(integrand, _w, [0, *inner, sp.sqrt(A**2 - X**2)], dps, fallback=fallback)


def gap_reference(profile_expr, force_law, breaks, vals: dict, dps: int, fallback):
    """The outside gap (|x| > a) at ``vals``, by parts (module docstring).
    :class:`~linecontact_sym.core.errors.DomainError` where the profile is
    not real at x (the exact cylinder's R - sqrt(R^2 - x^2) past x = R):
    no gap there (a verification passes over such a point)."""
    A, X = vals[S.a], abs(vals[S.x])
    E = vals.get(S.E_star, 1)
    pv = _params(vals)
    f_x = profile_expr.xreplace(pv).xreplace({S.x: X})
    if f_x.is_extended_real is False:     # before the quadrature (a second, in vain, then an mpmath estimate)
        raise DomainError(f"the profile is not real at x = {X} (here {f_x}): the gap is not defined there")
    P = force_law.xreplace(pv)
    root = sp.sqrt(X**2 - _s**2)
    integrand = P.xreplace({S.a: _s}) / (_s * root)
    crude = quotient_bound(P.xreplace({S.a: _s}), _s, 1 / root)    # P(0) = 0: P(s)/s is removable at 0
    with workdps(dps + 30):
        inner = sorted(to_mpf(b) for b in breaks if 0 < to_mpf(b) < to_mpf(A))
    J = integrate(integrand, _s, [0, *inner, A], dps + 5, fallback=lambda: mpmath.nan, crude=crude)
    if not J.certified:
        return estimate(fallback, J.note, dps)
    outer = f_x - 2 / (sp.pi * E) * (
        P.xreplace({S.a: A}) * sp.acosh(X / A) + X * _J)
    return combine(outer, _J, J, dps)
