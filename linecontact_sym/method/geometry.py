"""The geometry of a line contact: which flat punch the superposition is made of.

Popov's method superposes flat punches.  Its transforms (Eqs. 9, 10*, 12,
3/5 in :mod:`.transforms`) are written for the punch on an isolated
half-plane, whose pressure (P/pi)/sqrt(a^2 - x^2) is Abel's kernel in x.
A geometry is the change of variable s = s(x) in which another punch takes
that same form; the transforms are then the isolated ones in s, and a
geometry only says how to go there and back.

:data:`ISOLATED`  s = x: one punch on a half-plane (the identity map).

:class:`Periodic` (period L): Koiter's periodic flat punch, a row of punches
    of half-width a at the spacing L, each carrying P per period,

        p(x) = (P/L) cos(pi x/L) / sqrt(S^2 - s^2),   s = sin(pi x/L), S = sin(pi a/L),

    is (pi/L) cos(pi x/L) times the isolated punch (P/pi)/sqrt(S^2 - s^2) of
    half-width S in s.  The periodic kernel of the half-plane pairs up
    symmetric loads (t, -t) as

        cot(pi (x - t)/L) + cot(pi (x + t)/L) = 2 s cos(pi x/L) / (s^2 - sigma^2),

    sigma = sin(pi t/L), so the surface slope of a symmetric periodic load
    p(t) = (pi/L) cos(pi t/L) q(sigma) is ds/dx times the isolated slope of
    q in s, and the load per period is int q(sigma) d sigma.  A periodic
    profile f(x) (|x| <= L/2) is therefore the isolated profile
    F(s) = f((L/pi) asin s) (|s| < 1) in the kernel variable, with

        P(a)    = Q(S(a)),                       Q: Eq. (10*) of F, in S
        p(x; a) = (ds/dx) q(s(x); S(a)),         q: Eq. (12) of Q, in s
        g(x; a) = g_F(s(x); S(a)),               g_F: Eqs. (3)/(5) of F, in s
        f(x)    = F(s(x)),                       F: Eq. (9) of Q, in s.

    Full contact is a -> L/2, S -> 1.

A contact keeps its geometry and works in the kernel variable through a
twin contact of F (:class:`~linecontact_sym.contacts.normal.periodic.PeriodicLineContact`):
nothing of the isolated engine is copied.  The map to the kernel variable
and back is exact algebra; every mapped closed form is verified again in x
against a route that shares nothing with the map (:mod:`linecontact_sym.contacts.normal.tan_route`).
"""
from __future__ import annotations

import mpmath
import sympy as sp

from ..core import symbols as S
from ..core.conversion import to_mpf
from ..core.errors import DomainError, ProfileError
from ..core.precision import workdps
from ..parsing import user_value

__all__ = ["Geometry", "Periodic", "ISOLATED", "periodic"]


class Geometry:
    """The isolated half-plane: the kernel variable is x itself (identity).

    s(x), x_of(s), jacobian(x) = ds/dx as SymPy expressions; ``mp_*`` their
    mpmath twins at numeric parameter values; :meth:`punch_ratio` the ratio
    S(a)/S'(a) that the edge of a pulled punch sees (JKR: the stress
    intensity K = K_s sqrt(S'(a)) of the punch of half-width S in s)."""

    name = "isolated"
    period = None
    #: does the end of the range of half-widths close the contact (a periodic
    #: array at a = L/2: full contact, which holds any tension in JKR) rather
    #: than end the model?  The first minimum of P(a) from small a is then
    #: the pull-off of a partial contact, and the maximum beyond it the load
    #: of the snap into full contact.
    closes_at_end = False
    #: the symbols of the geometry a number needs (the period, when symbolic)
    symbols: tuple = ()

    def __repr__(self):
        return "Geometry('isolated')"

    def __eq__(self, other):
        return type(self) is type(other) and self.period == other.period

    def __hash__(self):
        return hash((type(self).__name__, self.period))

    @property
    def is_isolated(self) -> bool:
        return self.period is None

    def s(self, x):
        """The kernel variable of x."""
        return x

    def x_of(self, s):
        """x of the kernel variable s."""
        return s

    def jacobian(self, x):
        """ds/dx."""
        return sp.S.One

    def a_max(self):
        """The largest half-width (symbolic): oo, or L/2 for a periodic array."""
        return sp.oo

    def punch_ratio(self, a=S.a):
        """S(a)/S'(a): a for the isolated punch."""
        return a

    # ------------------------------------------------------------ numbers
    def mp_s(self, xv, values):
        return xv

    def mp_jacobian(self, xv, values):
        return mpmath.mpf(1)

    def mp_a_max(self, values):
        return mpmath.inf

    def check_half_width(self, values) -> None:
        """Refuse a half-width beyond :meth:`a_max` (values by Symbol or name)."""

    def punch_pressure(self, Phat, x=S.x, a=S.a):
        """The pressure of the flat punch of half-width a carrying Phat:
        ds/dx Phat/(pi sqrt(S^2 - s^2)) (isolated: Phat/(pi sqrt(a^2 - x^2)), Eq. 1)."""
        return self.jacobian(x) * Phat / (sp.pi * sp.sqrt(self.s(a)**2 - self.s(x)**2))

    def mp_punch_ratio(self, A, values):
        """S(A)/S'(A) and its slope d/dA, at numbers."""
        return A, mpmath.mpf(1)

    def float_punch_ratio(self, values):
        """S(a)/S'(a) as a float64 function of a (the fast path of an adhesive law)."""
        return float

    def float_s(self, values):
        """s(x) as a float64 function (the independent grid searches)."""
        return float

    def mp_punch_compliance(self, A, E, values, far, quadrature=False):
        """The compliance of the punch of half-width A (its displacement per
        unit load, up to a constant that does not depend on A): isolated,
        against a distant point ``far`` (Eq. 3), (2/(pi E*)) acosh(far/A)."""
        return 2 * mpmath.acosh(far / A) / (mpmath.pi * E)


class Periodic(Geometry):
    """A periodic array of period L (a positive number or a positive
    symbol): s = sin(pi x/L), see the module docstring."""

    name = "periodic"
    closes_at_end = True

    def __init__(self, period):
        L = user_value(period)
        if not isinstance(L, sp.Expr) or L.has(S.x, S.a, S.P, S.E_star):
            raise ProfileError(f"the period must be a positive number or a positive symbol, got {period!r}")
        if L.is_positive is not True:
            raise ProfileError(f"the period {L} must be positive (a number > 0, or a Symbol created with "
                               f"positive=True)")
        if L.is_number and not L.is_finite:
            raise ProfileError(f"the period must be finite, got {L}")
        self.period = L
        self.symbols = tuple(sorted(L.free_symbols, key=lambda v: v.name))

    def __repr__(self):
        return f"Periodic({self.period})"

    def s(self, x):
        return sp.sin(sp.pi * x / self.period)

    def x_of(self, s):
        return self.period / sp.pi * sp.asin(s)

    def jacobian(self, x):
        return sp.pi / self.period * sp.cos(sp.pi * x / self.period)

    def a_max(self):
        return self.period / 2

    def punch_ratio(self, a=S.a):
        """S/S' = (L/pi) tan(pi a/L)."""
        return self.period / sp.pi * sp.tan(sp.pi * a / self.period)

    def mp_period(self, values):
        L = self.period.xreplace(values) if self.symbols else self.period
        if not L.is_number:
            raise ProfileError(f"the period {self.period} needs a value")
        return to_mpf(L)

    def mp_s(self, xv, values):
        return mpmath.sin(mpmath.pi * xv / self.mp_period(values))

    def mp_jacobian(self, xv, values):
        L = self.mp_period(values)
        return mpmath.pi / L * mpmath.cos(mpmath.pi * xv / L)

    def mp_a_max(self, values):
        return self.mp_period(values) / 2

    def check_half_width(self, values) -> None:
        """A :class:`~linecontact_sym.core.errors.DomainError` where a > L/2
        (values by Symbol or name; arrays and missing values are left to the
        conditions a <= L/2 of the results)."""
        by = {(k.name if isinstance(k, sp.Symbol) else k): v for k, v in values.items()}
        if "a" not in by or any(v.name not in by for v in self.symbols):
            return
        try:
            A = sp.sympify(by["a"], strict=True) if not isinstance(by["a"], sp.Basic) else by["a"]
            top = self.period.xreplace({v: by[v.name] for v in self.symbols}) / 2
            beyond = bool(sp.N(A - top, 30) > 0)
        except (TypeError, ValueError, sp.SympifyError):
            return
        if beyond:
            raise DomainError(f"a = {by['a']} > L/2 = {top}: the contacts of neighbouring periods would overlap; "
                              f"the contact of a periodic array is full at a = L/2")

    def mp_punch_ratio(self, A, values):
        L = self.mp_period(values)
        u = mpmath.pi * A / L
        return L / mpmath.pi * mpmath.tan(u), 1 / mpmath.cos(u)**2

    def float_punch_ratio(self, values):
        import math
        L = float(self.mp_period(values))
        return lambda A: L / math.pi * math.tan(math.pi * float(A) / L)

    def float_s(self, values):
        import math
        L = float(self.mp_period(values))
        return lambda A: math.sin(math.pi * float(A) / L)

    def mp_punch_compliance(self, A, E, values, far=None, quadrature=False):
        """-(2/(pi E*)) ln sin(pi A/L): the displacement of Koiter's punch
        (unit load per period) under the periodic Green's function
        -(2/(pi E*)) ln|2 sin(pi x/L)|, whose mean over a period is 0 (the
        uniform part of the load adds a constant that does not depend on A).
        ``quadrature=True``: the defining integral
        -(2/(pi E*)) (2/L) int_0^A cos(pi t/L) ln|2 sin(pi t/L)| / sqrt(S^2 - sin^2(pi t/L)) dt
        by quadrature in t = A sin(phi), S^2 - sin^2 as a product of sines (no cancellation at the edge)."""
        L = self.mp_period(values)
        if not quadrature:
            return -2 * mpmath.log(mpmath.sin(mpmath.pi * A / L)) / (mpmath.pi * E)
        with workdps(mpmath.mp.dps + 10):
            def g(ph):
                t = A * mpmath.sin(ph)
                gap = 2 * A * mpmath.sin(mpmath.pi / 4 - ph / 2)**2      # A - t, without cancellation
                st = mpmath.sin(mpmath.pi * t / L)
                # S^2 - sin^2(pi t/L) = sin(pi (A - t)/L) sin(pi (A + t)/L)
                den = mpmath.sin(mpmath.pi * gap / L) * mpmath.sin(mpmath.pi * (A + t) / L)
                if den <= 0:    # a node that rounds onto the edge (tanh-sinh weight ~ 0 there)
                    return mpmath.mpf(0)
                return mpmath.cos(mpmath.pi * t / L) * mpmath.log(2 * st) * A * mpmath.cos(ph) / mpmath.sqrt(den)
            I = 2 / L * mpmath.quad(g, [0, mpmath.pi / 2])
        return +(-2 * I / (mpmath.pi * E))

    def mp_punch_compliance_slope(self, A, E, values):
        """dC/dA of :meth:`mp_punch_compliance`'s defining integral,
        differentiated under the integral sign (in t = A sin(phi) the
        integrand G(phi, A) is smooth in A; one quadrature at the working
        precision, where a finite difference of the quadrature needs two at
        twice the digits).  With k = pi/L, theta = k A sin(phi), alpha =
        k (A - t) = 2 k A sin^2(pi/4 - phi/2), beta = k (A + t) and
        G = A cos(phi) cos(theta) ln(2 sin theta)/sqrt(sin alpha sin beta)::

            A dG/dA = G (1 - (alpha cot alpha + beta cot beta)/2)
                      + A cos(phi) theta (cos^2 theta/sin theta - sin theta ln(2 sin theta))
                        / sqrt(sin alpha sin beta)

        (alpha, beta, theta are proportional to A: d/dA = (1/A) x d/dx on
        each), every term bounded but the logarithm at phi = 0."""
        L = self.mp_period(values)
        with workdps(mpmath.mp.dps + 10):
            k = mpmath.pi / L

            def dg(ph):
                th = k * A * mpmath.sin(ph)
                al = 2 * k * A * mpmath.sin(mpmath.pi / 4 - ph / 2)**2      # k (A - t), without cancellation
                be = k * A + th
                den = mpmath.sin(al) * mpmath.sin(be)
                if den <= 0 or th <= 0:   # a node that rounds onto an end (tanh-sinh weight ~ 0 there)
                    return mpmath.mpf(0)
                root = mpmath.sqrt(den)
                st, ct = mpmath.sin(th), mpmath.cos(th)
                lg = mpmath.log(2 * st)
                G = A * mpmath.cos(ph) * ct * lg / root
                xcot = lambda z: z * mpmath.cos(z) / mpmath.sin(z)  # noqa: E731
                return (G * (1 - (xcot(al) + xcot(be)) / 2)
                        + A * mpmath.cos(ph) * th * (ct**2 / st - st * lg) / root) / A
            dI = 2 / L * mpmath.quad(dg, [0, mpmath.pi / 2])
        return +(-2 * dI / (mpmath.pi * E))

    # ------------------------------------------------------------ the maps
    def kernel_profile(self, f):
        """F(s) = f((L/pi) asin s), written in the standard x (standing for
        s), simplified where that makes it shorter (2 sin(pi x/L)**2 -> 2 x**2)."""
        F = f.xreplace({S.x: self.x_of(S.x)})
        cands = [F]
        for how in (sp.simplify, lambda e: sp.simplify(sp.expand_trig(e))):
            try:
                cands.append(how(F))
            except Exception:   # a simplification SymPy cannot do: keep the plain substitution
                pass
        return min(cands, key=sp.count_ops)

    def from_kernel(self, expr, quantity: str):
        """A result of the kernel twin (in s standing as x, S as a) in x and
        a: the force law P(a) = Q(S(a)), the pressure times ds/dx, the gap,
        the profile of the inverse map (in x)."""
        sub = {S.x: self.s(S.x), S.a: self.s(S.a)}
        out = expr.xreplace(sub)
        if quantity == "pressure":
            out = self.jacobian(S.x) * out
        return out

    def condition_from_kernel(self, cond):
        """A condition of a kernel result in x and a: the relations between s
        and S alone (s < S, s > S, |s| < S) are those between x and a (sin is
        increasing on [0, L/2]); the others (S < 1, a number or a parameter on
        one side) are mapped by substitution."""
        if isinstance(cond, sp.core.relational.Relational) and \
                all(side in (S.x, S.a) or (isinstance(side, sp.Abs) and side.args[0] in (S.x, S.a))
                    for side in (cond.lhs, cond.rhs)):
            return cond
        # any other condition is one on s and S (the kernel's S < 1 is sin(pi a/L) < 1, not a < 1)
        return cond.xreplace({S.x: self.s(S.x), S.a: self.s(S.a)})


def periodic(period) -> Geometry:
    """The geometry of a contact: :data:`ISOLATED` for ``period=None``."""
    return ISOLATED if period is None else Periodic(period)


#: the isolated half-plane
ISOLATED = Geometry()
