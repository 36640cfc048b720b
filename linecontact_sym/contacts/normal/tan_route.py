"""The independent route of the periodic line contact: X = tan(pi x/L).

The engine solves a periodic array through the kernel variable
s = sin(pi x/L) (:mod:`.geometry`).  The numbers here share nothing with that
map: they come from the other classical reduction of the periodic kernel.
With X = tan(pi x/L), T = tan(pi t/L),

    ln|2 sin(pi (x - t)/L)| = ln|X - T| + ln cos(pi x/L) + ln cos(pi t/L) + ln 2,

so the periodic surface displacement of a load p(t) (per period P) is the
isolated one of q(T) = p(t) dt/dT in X, plus -(2P/(pi E*)) ln cos(pi x/L)
and constants.  Inside the contact u = d - f(x): the periodic contact of
half-width a is the *isolated* contact of half-width A = tan(pi a/L) of the
profile

    F2(X) = f((L/pi) atan X) + (P/(pi E*)) ln(1 + X^2),

whose load must be P again.  Eq. (10*) of F2 gives P = P_f(A) + P (1 - cos(pi a/L))
(the logarithm's share, int_0^A 2 T^2/((1 + T^2) sqrt(A^2 - T^2)) dT = pi (1 - 1/sqrt(1 + A^2))),
so

    P(a)    = P_f(A) / cos(pi a/L),     P_f(A) = E* int_0^A T F'(T)/sqrt(A^2 - T^2) dT,
    p(x; a) = (pi/L) (1 + X^2) q(X),    q: the bounded inversion of the isolated punch
                                          equation for F2 (Muskhelishvili),
    g(x; a) = -(2/(pi E*)) P acosh(X/A)
              + (2/pi) X sqrt(X^2 - A^2) int_0^A (F2(X) - F2(T))/((X^2 - T^2) sqrt(A^2 - T^2)) dT,

each one quadrature in T = A sin(phi) (the force law by the one reference
integrator, Arb's ball quadrature with mpmath as its recorded fallback; the
pressure and the gap by mpmath), split at the profile's kinks (found
numerically at the point by :class:`~.transforms.NumericProfile`) and at the
removable point T = X.  Nothing here uses sin(pi x/L) as a variable or a
superposition of punches over the half-width.
"""
from __future__ import annotations

import mpmath
import sympy as sp

from ...core import symbols as S
from ...core.conversion import point_value, to_mpf
from ...core.precision import workdps
from ...method.transforms import NumericProfile, inside
from ...numeric.reference import combine, integrate

__all__ = ["TanRoute"]

_phi = sp.Dummy("phi", positive=True)
_J = sp.Dummy("J")


class TanRoute:
    """The periodic contact of a profile at numeric parameter values, by
    the tan map (module docstring).  ``profile``: the Profile of f(x)
    (|x| <= L/2); ``values``: the parameters, E_star and the period L
    (``period``, a number at these values)."""

    def __init__(self, profile, values: dict, period):
        pv = {k: v for k, v in values.items() if k not in (S.x, S.a)}
        self.npf = NumericProfile(profile, pv)
        self.E = pv[S.E_star]
        self.L = period

    # ------------------------------------------------------------ pieces
    def _setup(self, a):
        L = to_mpf(self.L)
        A = mpmath.tan(mpmath.pi * to_mpf(a) / L)
        kinks = [mpmath.tan(mpmath.pi * k / L) for k in self.npf.kinks(0, to_mpf(a))]
        return L, A, kinks

    def _Fp(self, L):
        """F'(T) = f'(t) dt/dT, t = (L/pi) atan T."""
        f1 = self.npf.f1

        def Fp(T):
            return f1(L / mpmath.pi * mpmath.atan(T)) * L / (mpmath.pi * (1 + T**2))
        return Fp

    def _phis(self, A, kinks, extra=()):
        pts = {mpmath.mpf(0), mpmath.pi / 2}
        pts |= {mpmath.asin(k / A) for k in list(kinks) + list(extra) if 0 < k < A}
        return sorted(pts)

    def _quad(self, g, pts):
        """int g over the pieces pts, each piece's branch of a Piecewise kept
        inside it (:func:`~.transforms.inside`)."""
        return mpmath.fsum(mpmath.quad(inside(g, lo, hi), [lo, hi]) for lo, hi in zip(pts[:-1], pts[1:]))

    # ------------------------------------------------------------ force
    def force(self, a, dps: int = 45):
        """P(a) = (E*/cos(pi a/L)) int_0^{pi/2} A sin(phi) F'(A sin phi) dphi:
        the integral by the one reference integrator (Arb's ball quadrature,
        :func:`linecontact_sym.numeric.reference.integrate`), the mpmath
        quadrature of :meth:`force_mpmath` its recorded fallback."""
        a_ex, L = point_value(a), point_value(self.L)        # exact: an mpf by its binary value
        A = sp.tan(sp.pi * a_ex / L)
        T = A * sp.sin(_phi)
        f1 = sp.diff(self.npf.expr, S.x).xreplace({S.x: L / sp.pi * sp.atan(T)})
        integrand = T * f1 * L / (sp.pi * (1 + T**2))
        with workdps(dps + 30):
            Am = to_mpf(A)
            kinks = [mpmath.tan(mpmath.pi * k / to_mpf(L)) for k in self.npf.kinks(0, to_mpf(a_ex))]
            pts = [0] + [mpmath.asin(k / Am) for k in kinks if 0 < k < Am] + [sp.pi / 2]
        r = integrate(integrand, _phi, pts, dps, fallback=lambda: self.force_mpmath(a, dps) * mpmath.cos(
            mpmath.pi * to_mpf(a_ex) / to_mpf(L)) / to_mpf(self.E))
        # E*/cos(pi a/L) times the integral: in Arb too where the integral is an enclosure
        return combine(point_value(self.E) * _J / sp.cos(sp.pi * a_ex / L), _J, r, dps)

    def force_mpmath(self, a, dps: int = 45):
        """:meth:`force` by mpmath's tanh-sinh quadrature."""
        with workdps(dps + 15):
            L, A, kinks = self._setup(a)
            Fp = self._Fp(L)
            E = to_mpf(self.E)
            I = self._quad(lambda ph: A * mpmath.sin(ph) * Fp(A * mpmath.sin(ph)), self._phis(A, kinks))
            return +(E * I / mpmath.cos(mpmath.pi * to_mpf(a) / L))

    # ------------------------------------------------------------ pressure
    def pressure(self, a, x, P=None, dps: int = 45):
        """p(x; a) = (pi/L)(1 + X^2) q(X), q = (E*/pi) sqrt(A^2 - X^2)
        int_0^{pi/2} [G(A sin phi) - G(X)]/(A^2 sin^2 phi - X^2) dphi,
        G(T) = T F2'(T); the load P (default: :meth:`force`) enters F2."""
        P = self.force(a, dps) if P is None else P
        with workdps(2 * dps + 20):
            L, A, kinks = self._setup(a)
            X = mpmath.tan(mpmath.pi * abs(to_mpf(x)) / L)
            E = to_mpf(self.E)
            Fp = self._Fp(L)
            c = to_mpf(P) / (mpmath.pi * E)

            def G(T):
                return T * (Fp(T) + c * 2 * T / (1 + T**2))
            GX = G(X)

            def g(ph):
                T = A * mpmath.sin(ph)
                den = T**2 - X**2
                return (G(T) - GX) / den if den != 0 else mpmath.mpf(0)
            I = self._quad(g, self._phis(A, kinks, (X,)))
            q = E / mpmath.pi * mpmath.sqrt(A**2 - X**2) * I
            return +(mpmath.pi / L * (1 + X**2) * q)

    # ------------------------------------------------------------ gap
    def gap(self, a, x, P=None, dps: int = 45):
        """g(x; a) for a < |x| < L/2 (module docstring)."""
        P = self.force(a, dps) if P is None else P
        with workdps(2 * dps + 20):
            L, A, kinks = self._setup(a)
            xv = abs(to_mpf(x))
            X = mpmath.tan(mpmath.pi * xv / L)
            E = to_mpf(self.E)
            Pm = to_mpf(P)
            c = Pm / (mpmath.pi * E)
            f = self.npf.f

            def F2(T, t=None):
                t = L / mpmath.pi * mpmath.atan(T) if t is None else t
                return f(t) + c * mpmath.log(1 + T**2)
            F2X = F2(X, xv)

            def g(ph):
                T = A * mpmath.sin(ph)
                return (F2X - F2(T)) / (X**2 - T**2)
            I = self._quad(g, self._phis(A, kinks))
            return +(-2 * Pm / (mpmath.pi * E) * mpmath.acosh(X / A)
                     + 2 / mpmath.pi * X * mpmath.sqrt(X**2 - A**2) * I)
