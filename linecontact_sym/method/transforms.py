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

import functools

import mpmath
import sympy as sp

from ..core import symbols as S
from ..core.quadrature import quad0
from ..core.conversion import to_mpf
from ..core.roots import root_in_bracket
from ..core.precision import workdps

# the integration variables: Dummies (they print as _t, _s), so that a user's
# parameter named t or s is never captured by an integral of the engine
t = sp.Dummy("t", positive=True)
s = sp.Dummy("s", positive=True)


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


_u = sp.Dummy("u", positive=True)


def _over_unit_interval(I: sp.Integral) -> sp.Integral:
    """int_lo^hi g(t) dt as int_0^1 g(lo + (hi - lo) u) (hi - lo) du when a limit
    depends on a (radicands factored: sqrt(a^2 - a^2 u^2) = a sqrt(1 - u^2))."""
    if len(I.limits) != 1 or len(I.limits[0]) != 3:
        return I
    v, lo, hi = I.limits[0]
    if S.a not in lo.free_symbols | hi.free_symbols:
        return I
    g = I.function.subs(v, lo + (hi - lo) * _u) * (hi - lo)
    g = g.replace(lambda e: e.is_Pow and e.exp.is_Rational and not e.exp.is_Integer,
                  lambda e: sp.Pow(sp.factor_terms(e.base), e.exp))
    return sp.Integral(g, (_u, 0, 1))


def force_slope(P: sp.Expr) -> sp.Expr:
    """dP/da.  An unevaluated force integral (Eq. 10, int_0^a ... /sqrt(a^2 - t^2)
    dt) is first written over u in [0, 1], t = a u, so that d/da acts on its
    integrand: Leibniz's rule on the limit a, where the integrand is singular,
    gave zoo times a boundary term plus a divergent integral."""
    if P.has(sp.Integral):
        P = P.replace(lambda e: isinstance(e, sp.Integral), _over_unit_interval)
    return sp.diff(P, S.a)


def pressure_integral(P: sp.Expr) -> sp.Expr:
    """The unevaluated Eq. (12) for a force law P(a)."""
    dP = force_slope(P).subs(S.a, s)
    return sp.Integral(dP / (sp.pi * sp.sqrt(s**2 - S.x**2)), (s, S.x, S.a))


def gap_integral(profile_expr: sp.Expr, P: sp.Expr) -> sp.Expr:
    """The unevaluated outside gap (Eqs. 3/5) for a force law P(a), |x| > a."""
    dP = force_slope(P).subs(S.a, s)
    return profile_expr - 2 / (sp.pi * S.E_star) * sp.Integral(sp.acosh(S.x / s) * dP, (s, 0, S.a))


def profile_integral(P: sp.Expr) -> sp.Expr:
    """The unevaluated Eq. (9): the profile f(a) that has the force law P."""
    Ps = P.subs(S.a, s)
    return 2 * S.a / (sp.pi * S.E_star) * sp.Integral(Ps / (s * sp.sqrt(S.a**2 - s**2)), (s, 0, S.a))


# --------------------------------------------------------------- quadratures
_mpf = to_mpf      # the one converter (core.conversion)


@functools.lru_cache(maxsize=128)
def _slope(expr: sp.Expr) -> sp.Expr:
    """d expr / dx, once per expression (a verification asks at every point)."""
    return sp.diff(expr, S.x)


class NumericProfile:
    """The profile at numeric parameter values, read from its expression and
    *not* from the engine's pieces: f, f' and f'' as mpmath callables of x,
    and :meth:`kinks`, the breakpoints in an interval found numerically at
    this point (the zeros of every switching function: each relation of a
    Piecewise, after Abs/Min/Max/sign/Heaviside are rewritten as Piecewise).

    This is what the references use: the engine splits the profile once, at
    one sample parameter point (:meth:`~.profile.Profile._split`); a reference
    that reused that split could not disagree with it where the split is
    wrong (a condition on the parameters, breakpoints in another order).

    >>> x = sp.Symbol("x", positive=True)
    >>> npf = NumericProfile(sp.Abs(x - 1) + x, {})
    >>> [mpmath.nstr(k, 15) for k in npf.kinks(0, 3)]
    ['1.0']
    """

    #: samples of each switching function per interval searched
    SAMPLES = 64

    def __init__(self, profile, values: dict):
        from .profile import expose_kinks
        expr = profile.expr if hasattr(profile, "expr") else expose_kinks(profile)
        pv = {k: v for k, v in values.items() if k not in (S.x, S.a, S.E_star)}
        e = expr.xreplace(pv)
        if e.has(sp.Piecewise):
            e = sp.piecewise_fold(e)
        self.expr = e
        self._source, self._pv = expr, pv
        rels = {r for r in e.atoms(sp.Rel) if r.has(S.x)}
        self._switches = [sp.lambdify(S.x, r.lhs - r.rhs, "mpmath") for r in rels]
        self._found: list = []
        self._searched = mpmath.mpf(0)

    # f, f', f'' as mpmath callables, made on first use (the certified force
    # reference needs none of them: a derivative and a lambdify per point)
    @functools.cached_property
    def f(self):
        return sp.lambdify(S.x, self.expr, "mpmath")

    @functools.cached_property
    def slope(self) -> sp.Expr:
        """f' at these parameters: the profile's derivative (taken once per
        profile, :func:`_slope`) with the parameters' values put in."""
        d = _slope(self._source).xreplace(self._pv)
        return sp.piecewise_fold(d) if d.has(sp.Piecewise) else d

    @functools.cached_property
    def f1(self):
        return sp.lambdify(S.x, self.slope, "mpmath")

    @functools.cached_property
    def f2(self):
        return sp.lambdify(S.x, sp.diff(self.expr, S.x, 2), "mpmath")

    def kinks(self, lo, hi):
        """The breakpoints in (lo, hi), ascending, at the working precision
        (to 80 digits, found once): sign changes of each switching function
        on a grid of the searched interval (0 or the end of the last search up
        to ``hi``: :data:`SAMPLES` evenly spaced points and 4 :data:`SAMPLES`
        log-spaced ones from 1e-15 of its end), solved by bisection + secant.
        Two zeros of one switching function between neighbouring grid points
        are not seen (they would be a switch on and off within 1.4 % of x)."""
        hi = mpmath.mpf(hi)
        if self._switches and hi > self._searched:
            with workdps(80):
                top = max(hi, 2 * self._searched)
                low = self._searched
                grid = {low + (top - low) * k / self.SAMPLES for k in range(self.SAMPLES + 1)}
                g0 = max(low, top * mpmath.mpf(10)**-15)
                grid |= {g0 * (top / g0)**(mpmath.mpf(k) / (4 * self.SAMPLES)) for k in range(4 * self.SAMPLES + 1)}
                grid = sorted(grid)
                for g in self._switches:
                    vals = []
                    for xv in grid:
                        try:
                            vals.append(mpmath.re(g(xv)))
                        except (ValueError, ZeroDivisionError):
                            vals.append(None)
                    for (x0, v0), (x1, v1) in zip(zip(grid, vals), zip(grid[1:], vals[1:])):
                        if v0 is None or v1 is None:
                            continue
                        if v1 == 0 and x1 > 0:
                            self._add(x1)
                        elif v0 * v1 < 0:
                            self._add(_sign_change(g, x0, x1))
                self._searched = top
        return [+k for k in self._found if lo < k < hi]

    def _add(self, xv):
        if xv > 0 and all(abs(xv - k) > abs(k) * mpmath.mpf(10)**-60 for k in self._found):
            self._found.append(xv)
            self._found.sort()


def inside(fn, lo, hi):
    """``fn`` restricted to the open piece (lo, hi): its argument is kept
    10**-dps (relative) inside, so a node that rounds onto a breakpoint still
    takes this piece's branch of a Piecewise (the worn cylinder's f' is 0 on
    the flat and b/R at x = b)."""
    def g(t):
        d = hi * mpmath.mpf(10)**(-mpmath.mp.dps)
        return fn(min(max(t, lo + d), hi - d))
    return g


def _sign_change(g, x0, x1):
    """A zero of g in the sign-change bracket [x0, x1]: the package's one
    bracketed root finder (:func:`~linecontact_sym.core.roots.root_in_bracket`)."""
    return root_in_bracket(lambda v: mpmath.re(g(v)), x0, x1, width=(x1 - x0) * mpmath.mpf(2)**-40)


def force_quad(profile, values: dict, dps: int = 50):
    """Eq. (10*) by tanh-sinh quadrature after t = a sin(phi):
    E* a int_0^{pi/2} sin(phi) f'(a sin(phi)) dphi, split at the breakpoints
    that :class:`NumericProfile` finds at this point (independent of the
    engine's split of the profile into pieces)."""
    with workdps(dps + 10):
        A = _mpf(values[S.a])
        E = _mpf(values.get(S.E_star, 1))
        npf = NumericProfile(profile, values)
        edges = [mpmath.mpf(0)] + npf.kinks(0, A) + [A]
        total = mpmath.mpf(0)
        for i, (lo, hi) in enumerate(zip(edges[:-1], edges[1:])):
            fn = inside(npf.f1, lo, hi)
            p0, p1 = mpmath.asin(lo / A), mpmath.asin(hi / A)
            integrand = lambda ph: mpmath.sin(ph) * fn(A * mpmath.sin(ph))  # noqa: E731
            total += quad0(integrand, [p0, p1]) if i == 0 else mpmath.quad(integrand, [p0, p1], maxdegree=10)
        return +(E * A * total)


def pressure_quad(dP, breaks, values: dict, dps: int = 50):
    """Eq. (12) after s = sqrt(x^2 + w^2): (1/pi) int_0^sqrt(a^2-x^2) P'(s)/s dw.

    ``dP`` is an mpmath callable of s (the derivative of the force law)."""
    with workdps(dps + 10):
        work = mpmath.mp.dps
        A, X = _mpf(values[S.a]), abs(_mpf(values[S.x]))
        with workdps(2 * work + 10):
            W = mpmath.sqrt(A**2 - X**2)
            inner = [mpmath.sqrt(bp**2 - X**2) for bp in breaks if X < bp < A]

        def integrand(w):
            sv = mpmath.sqrt(X**2 + w**2)
            return dP(sv) / sv
        if not inner:
            return +(quad0(integrand, [mpmath.mpf(0), W]) / mpmath.pi)
        # nodes that round past the first breakpoint would take the other branch
        total = quad0(inside(integrand, mpmath.mpf(0), inner[0]), [mpmath.mpf(0), inner[0]])
        for lo, hi in zip(inner, inner[1:] + [W]):
            total += offset_quad(integrand, lo, hi, work)
        return +(total / mpmath.pi)


def pressure_direct_quad(f1, values: dict, dps: int = 50):
    """p(x; a) of a smooth profile from the profile alone, one quadrature
    (the bounded inversion of the Cauchy equation of a rigid punch,
    Muskhelishvili; the same p as Eq. (12) with P(a) of Eq. (10*))::

        p(x) = (E*/pi) sqrt(a^2 - x^2) int_0^{pi/2} [G(a sin phi) - G(x)] / (a^2 sin^2 phi - x^2) dphi,

    G(t) = t f'(t), t = a sin(phi); the principal value of the kernel alone is
    0, so subtracting G(x) leaves a removable point at t = |x| (split there;
    the working precision is doubled for the cancellation next to it).  For
    a profile of one analytic piece (``f1`` = f', an mpmath callable):
    Eq. (12) of a force law without closed form is a double quadrature
    (60 s at 30 digits for x**2 exp(x)/2), this a single one.

    >>> import sympy as sp
    >>> v = pressure_direct_quad(lambda t: t, {S.a: 1, S.x: sp.Rational(1, 2), S.E_star: 2}, 30)
    >>> mpmath.nstr(v, 30)            # Hertz, R = 1: E* sqrt(a^2 - x^2)/(2R) = sqrt(3)/2 = 0.86602540378443864676...
    '0.866025403784438646763723170753'
    """
    with workdps(2 * dps + 20):
        A, X, E = _mpf(values[S.a]), abs(_mpf(values[S.x])), _mpf(values[S.E_star])
        GX = X * f1(X) if X != 0 else mpmath.mpf(0)

        def g(ph):
            t = A * mpmath.sin(ph)
            den = t**2 - X**2
            return (t * f1(t) - GX) / den if den != 0 else mpmath.mpf(0)
        pts = [mpmath.mpf(0)] + ([mpmath.asin(X / A)] if 0 < X < A else []) + [mpmath.pi / 2]
        val = mpmath.quad(g, pts)
        return +(E / mpmath.pi * mpmath.sqrt(A**2 - X**2) * val)


def offset_quad(fn, lo, hi, work):
    """int_lo^hi fn over a piece that starts at a breakpoint, where the
    integrand may be singular like 1/sqrt(w - lo) (a slope jump of the
    profile): integrated in the offset v = w - lo = t**2, with lo held to twice the
    working precision and fn evaluated there, so that nodes within 10**-dps
    of lo still fall on the right side of the singularity (before: the
    pressure behind a kink to 20 of 30 digits)."""
    with workdps(2 * work + 10):
        width = hi - lo
    top = width * (1 - mpmath.mpf(10)**(-work))

    def g(t):   # v = t**2: a 1/sqrt(v) singularity becomes smooth
        with workdps(2 * work + 10):
            val = 2 * t * fn(lo + min(t * t, top))
        return +val
    return mpmath.quad(g, [0, mpmath.sqrt(width)], maxdegree=10)


def gap_quad(f, dP, breaks, values: dict, dps: int = 50):
    """Outside gap f(x) - (2/(pi E*)) int_0^a acosh(x/s) P'(s) ds, x > a."""
    with workdps(dps + 10):
        A, X = _mpf(values[S.a]), abs(_mpf(values[S.x]))
        E = _mpf(values.get(S.E_star, 1))
        work = mpmath.mp.dps
        inner = [bp for bp in breaks if bp < A]

        def integrand(sv):
            return mpmath.acosh(X / sv) * dP(sv)
        first = inner[0] if inner else A
        I = quad0(inside(integrand, mpmath.mpf(0), first) if inner else integrand, [mpmath.mpf(0), first])
        for lo, hi in zip(inner, inner[1:] + [A]):
            I += offset_quad(integrand, lo, hi, work)
        return +(f(X) - 2 * I / (mpmath.pi * E))


def profile_quad(Pfn, breaks, values: dict, dps: int = 50):
    """Eq. (9) after s = a sin(phi): (2/(pi E*)) int_0^{pi/2} P(a sin phi)/sin(phi) dphi."""
    with workdps(dps + 10):
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
            with workdps(2 * mpmath.mp.dps + 10):
                v = p_of_phi(ph) * mpmath.cos(ph)
                if isinstance(v, mpmath.mpc) or not mpmath.isfinite(v):
                    raise ValueError("not finite")
            return +v
        except undefined:
            if ph < tiny or mpmath.pi / 2 - ph < tiny:
                return mpmath.mpf(0)
            raise
    return mpmath.quad(integrand, [0, mpmath.pi / 2])
