"""The transforms of Popov (2017) as integrals: symbolic definitions and
independent high-precision quadratures.

Notation: profile f(x) (x >= 0, mirrored), half-width a, load per unit length
P, reduced modulus E* (``E_star``).

Force law, Eq. (10)
    The paper prints P(a) = E* a^2 int_0^a (f(t)/t)' / sqrt(a^2 - t^2) dt.  It
    is the Abel inversion of Eq. (9) *without* its boundary term: the complete
    inversion is

        P(a) = E* a f'(0+) + E* a^2 int_0^a (f(t)/t)' / sqrt(a^2 - t^2) dt
             = E* int_0^a t f'(t) / sqrt(a^2 - t^2) dt.          (10*)

    The printed form holds exactly when f'(0+) = 0; for the wedge it gives 0
    instead of E* a tan(theta) (Eq. 19), and for power laws with n < 1 its
    integral diverges.  The engine uses the last form (10*), which holds for
    every admissible profile (the wedge included) and needs no limit.

Pressure, Eq. (12)
    p(x; a) = (1/pi) int_|x|^a P'(s) / sqrt(s^2 - x^2) ds.

Gap outside the contact, from Eqs. (3)/(5)
    For |x| > a the surface separation is
        g(x) = f(x) - (2/(pi E*)) int_0^a arccosh(|x|/s) P'(s) ds,
    the reference-free difference f(x) - (d - u_z(x)); g(a) = 0.

Inverse map, Eq. (9)
    f(a) = (2 a/(pi E*)) int_0^a P(s) / (s sqrt(a^2 - s^2)) ds.

The ``*_quad`` functions evaluate each defining integral with mpmath at a
given precision, with the endpoint singularities removed by substitution
(t = a sin(phi); s = sqrt(x^2 + w^2)) and the interval split at the profile's
breakpoints.  They are the independent reference every closed form is
checked against.
"""
from __future__ import annotations

import mpmath
import sympy as sp

from ..core import symbols as S

# dummy integration variables: the defining Integrals print with these
t = sp.Symbol("t", positive=True)
s = sp.Symbol("s", positive=True)


def force_integrand(fprime: sp.Expr) -> sp.Expr:
    """Integrand of (10*) in t: E* t f'(t) / sqrt(a^2 - t^2)."""
    return S.E_star * t * fprime.subs(S.x, t) / sp.sqrt(S.a**2 - t**2)


def force_integral(profile) -> sp.Expr:
    """The unevaluated Eq. (10*) for a profile (a sum over its pieces)."""
    parts = []
    for pc in profile.pieces:
        lo = pc.lo
        hi = S.a if pc.hi == sp.oo else sp.Min(pc.hi, S.a)
        if lo != 0:
            lo = sp.Min(lo, S.a)
        parts.append(sp.Integral(force_integrand(pc.derivative), (t, lo, hi)))
    return sp.Add(*parts)


def pressure_integral(P: sp.Expr) -> sp.Expr:
    """The unevaluated Eq. (12) for a force law P(a)."""
    dP = sp.diff(P, S.a).subs(S.a, s)
    return sp.Integral(dP / (sp.pi * sp.sqrt(s**2 - S.x**2)), (s, S.x, S.a))


def gap_integral(profile_expr: sp.Expr, P: sp.Expr) -> sp.Expr:
    """The unevaluated outside gap (Eqs. 3/5) for a force law P(a), |x| > a."""
    dP = sp.diff(P, S.a).subs(S.a, s)
    return profile_expr - 2 / (sp.pi * S.E_star) * sp.Integral(sp.acosh(S.x / s) * dP, (s, 0, S.a))


def profile_integral(P: sp.Expr) -> sp.Expr:
    """The unevaluated Eq. (9): the profile f(a) that has the force law P."""
    Ps = P.subs(S.a, s)
    return 2 * S.a / (sp.pi * S.E_star) * sp.Integral(Ps / (s * sp.sqrt(S.a**2 - s**2)), (s, 0, S.a))


# --------------------------------------------------------------- quadratures
def _mpf(v):
    return mpmath.mpf(sp.N(v, mpmath.mp.dps + 10)) if not isinstance(v, mpmath.mpf) else v


def quad0(f, pts):
    """mpmath tanh-sinh quadrature over the points ``pts`` (pts[0] == 0), with
    u**4 = t on the first interval: an algebraic or logarithmic endpoint
    singularity at 0 (power laws with n < 1, the wedge) is then integrated to
    full precision instead of losing the tail below the smallest node.  Each
    later interval [p, q] is integrated in u = sqrt(t - p) (t = p + u**2),
    with the integrand at twice the working digits: beyond a kink p the
    integrand may behave like 1/sqrt(t - p) (the slope of a force law, Eq. 12
    and the gap), whose tail below the smallest tanh-sinh node would otherwise
    cost half the digits, and whose terms lose half the digits to the
    rounding of t - p.  For the same reason the breakpoints must be given to
    about twice the working digits: a split point off the integrand's
    singularity by d loses about sqrt(d)."""
    first = mpmath.quad(lambda u: 4 * u**3 * f(u**4), [0, mpmath.root(pts[1], 4)], maxdegree=10)
    rest = mpmath.mpf(0)
    extra = 2 * mpmath.mp.dps
    for p, q in zip(pts[1:-1], pts[2:]):
        def g(u, p=p):
            with mpmath.workdps(extra):
                tv = p + u * u
                # u below 10**(-extra/2): a node whose weight times any
                # integrable 2u f is below the working precision
                return 2 * u * f(tv) if tv != p else mpmath.mpf(0)
        rest += mpmath.quad(g, [0, mpmath.sqrt(q - p)], maxdegree=10)
    return first + rest


def force_quad(profile, values: dict, dps: int = 50):
    """Eq. (10*) by tanh-sinh quadrature after t = a sin(phi), split at the
    breakpoints: E* a int_0^{pi/2} sin(phi) f'(a sin(phi)) dphi."""
    with mpmath.workdps(dps + 10):
        A = _mpf(values[S.a])
        E = _mpf(values.get(S.E_star, 1))
        fns, breaks = profile.mp_functions(values, derivative=1)
        edges = [mpmath.mpf(0)] + [bp for bp in breaks if bp < A] + [A]
        total = mpmath.mpf(0)
        for i, (lo, hi) in enumerate(zip(edges[:-1], edges[1:])):
            fn = fns[i]
            p0, p1 = mpmath.asin(lo / A), mpmath.asin(hi / A)
            integrand = lambda ph, fn=fn: mpmath.sin(ph) * fn(A * mpmath.sin(ph))  # noqa: E731
            total += quad0(integrand, [p0, p1]) if i == 0 else mpmath.quad(integrand, [p0, p1], maxdegree=10)
        return +(E * A * total)


def pressure_quad(dP, breaks, values: dict, dps: int = 50):
    """Eq. (12) after s = sqrt(x^2 + w^2): (1/pi) int_0^sqrt(a^2-x^2) P'(s)/s dw.

    ``dP`` is an mpmath callable of s (the derivative of the force law)."""
    with mpmath.workdps(dps + 10):
        A, X = _mpf(values[S.a]), abs(_mpf(values[S.x]))
        W = mpmath.sqrt(A**2 - X**2)
        with mpmath.workdps(2 * mpmath.mp.dps):   # as exact as the breakpoints are (see quad0)
            inner = [mpmath.sqrt(bp**2 - X**2) for bp in breaks if X < bp < A]
        pts = [mpmath.mpf(0)] + inner + [W]

        def integrand(w):
            sv = mpmath.sqrt(X**2 + w**2)
            return dP(sv) / sv
        return +(quad0(integrand, pts) / mpmath.pi)


def gap_quad(f, dP, breaks, values: dict, dps: int = 50):
    """Outside gap f(x) - (2/(pi E*)) int_0^a acosh(x/s) P'(s) ds, x > a."""
    with mpmath.workdps(dps + 10):
        A, X = _mpf(values[S.a]), abs(_mpf(values[S.x]))
        E = _mpf(values.get(S.E_star, 1))
        pts = [mpmath.mpf(0)] + [bp for bp in breaks if bp < A] + [A]
        I = quad0(lambda sv: mpmath.acosh(X / sv) * dP(sv), pts)
        return +(f(X) - 2 * I / (mpmath.pi * E))


def profile_quad(Pfn, breaks, values: dict, dps: int = 50):
    """Eq. (9) after s = a sin(phi): (2/(pi E*)) int_0^{pi/2} P(a sin phi)/sin(phi) dphi."""
    with mpmath.workdps(dps + 10):
        A = _mpf(values[S.a])
        E = _mpf(values.get(S.E_star, 1))
        pts = [mpmath.mpf(0)] + [mpmath.asin(bp / A) for bp in breaks if bp < A] + [mpmath.pi / 2]
        I = quad0(lambda ph: Pfn(A * mpmath.sin(ph)) / mpmath.sin(ph), pts)
        return +(2 * I / (mpmath.pi * E))


def mean_quad(p_of_phi, undefined=(ValueError, ZeroDivisionError)):
    """(1/A) int_0^A p(x) dx for a pressure-like p after x = A sin(phi):
    int_0^{pi/2} p(A sin phi) cos(phi) dphi, which removes an
    inverse-square-root edge singularity.  ``p_of_phi`` is the mpmath callable
    phi -> p(A sin phi); it is evaluated at doubled precision (cos(phi) -> 1
    cancels in sqrt(A^2 - x^2) forms near phi = 0), and a node within 1e-20 of
    an end where it is undefined (an integrable log singularity, e.g. the
    wedge at x = 0) contributes 0."""
    tiny = mpmath.mpf(10)**-20

    def integrand(ph):
        try:
            with mpmath.workdps(2 * mpmath.mp.dps + 10):
                v = p_of_phi(ph) * mpmath.cos(ph)
                if isinstance(v, mpmath.mpc) or not mpmath.isfinite(v):
                    raise ValueError("not finite")
            return +v
        except undefined:
            if ph < tiny or mpmath.pi / 2 - ph < tiny:
                return mpmath.mpf(0)
            raise
    return mpmath.quad(integrand, [0, mpmath.pi / 2])
