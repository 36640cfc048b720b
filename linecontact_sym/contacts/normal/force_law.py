"""The numeric force law: P(a) at fixed numeric parameters, with its slope,
breakpoints and domain, and the one toolkit that scans it for stationary
points, minima and equilibria.

Every numeric search on a force law in the package goes through
:class:`ForceLaw`: the half-width at a load (frictionless and adhesive), the
pull-off (the minimum of the adhesive law), the jump-in, and the checker's
independent references.

Two routes to the same law, which share nothing but the profile:

``closed``  P0 and dP0/da from the engine's (verified) closed form, lambdified
            for mpmath; where the closed form's conditions fail or it is not
            real, the quadrature route takes over.
``quad``    independent quadratures after t = a sin(phi)::

                P0(a)  = E* a int_0^{pi/2} sin(phi) f'(a sin phi) dphi           (10*)
                P0'(a) = E* int_0^{pi/2} sin(phi) h'(a sin phi) dphi
                         + E* sum_b J_b b**2 / sqrt(a**2 - b**2),   h(t) = t f'(t),

            J_b = f'(b+) - f'(b-) the slope jump at a kink b < a.

An adhesive law is a ForceLaw built on the non-adhesive one (its ``base``)
by a cohesive law (:mod:`linecontact_sym.contacts.adhesion.law`): JKR's
P(a) = P0(a) - sqrt(2 pi a gamma E*) (Eq. 33), or one whose P(a) needs an
inner solve at each a.
"""
from __future__ import annotations

from dataclasses import dataclass

import mpmath
import sympy as sp

from ...core import symbols as S
from ...core.conversion import to_basic, to_mpf
from ...core.quadrature import quad_piece
from ...core.errors import DomainError
from ...core.roots import UNDEFINED, Outside, real_value
from ...method.geometry import ISOLATED
from ...method.transforms import NumericProfile, inside
from ...numeric.arb_functions import lambdify_law
from ...core.precision import workdps

#: extra working digits of the numeric searches
GUARD = 15
#: calls of a quadrature law's piece by tanh-sinh alone after Gauss-Legendre failed there (ForceLaw.from_profile)
GAUSS_RETRY = 8


@dataclass(frozen=True)
class PullOff:
    """The pull-off under load control: the global minimum of P(a) over the
    admissible range (defined in :mod:`.equilibria`).

    force          P_min < 0 (the pull-off *load*)
    adhesion_force P_adh = -P_min > 0 (the paper's P_adh)
    half_width     a at the minimum
    kind           'stationary' (dP/da = 0), 'kink' (at a profile breakpoint),
                   'end' (the end of the admissible range) or 'infimum' (a law
                   with P(0+) < 0 decreasing to it as a -> 0+: half-width 0)
    digits         agreement of two independent methods (None if not run)
    minima         every local minimum of P over the admissible range, as
                   :class:`~.equilibria.Extremum` (half-width, force, kind)
    note           what the search covered and how (ball arithmetic or
                   adaptive subdivision), and what a kind 'end' means
    """

    force: mpmath.mpf
    adhesion_force: mpmath.mpf
    half_width: mpmath.mpf
    kind: str
    digits: float | None = None
    minima: tuple = ()
    note: str = ""


@dataclass(frozen=True)
class ScanHint:
    """How the searches of :mod:`.equilibria` scan a law without a closed form
    (an inner solve per value, no ball arithmetic): instead of the adaptive
    subdivision of the whole range (thousands of inner solves), dP/da on a
    log grid, supplied by the law (every law with an inner solve may give one).

    start       () -> mpf: the half-width the grid starts at; below it the
                descent (:func:`~.equilibria.descent`, a law with P(0+) != 0)
                or the monotone tail of P(a) (P(0+) = 0) takes over
    per_decade  grid points per decade: the law's promise that two extrema of
                P(a) are never closer than that (a sign change of dP/da
                between neighbours brackets each)
    why         the law's reason for both, said in the landscape's notes

    The grid walks up from ``start`` until P > 0 and dP/da > 0 beyond every
    breakpoint (the law's promise: P(a) keeps rising there), the end of the
    admissible range (dP0/da read at the grid points, its sign change refined:
    no search of the whole range first), or the end of the law's own real
    domain (found by bisection where P stops being real, e.g. a cohesive zone
    that would reach past the end of the profile)."""

    start: object
    per_decade: int = 8
    why: str = ""


class ForceLaw:
    """P(a) and dP/da at fixed numeric parameters (see the module docstring).

    Build with :meth:`from_closed_form`, :meth:`from_profile` or
    :meth:`from_contact`; ``P(a)`` and ``dP(a)`` take and return mpf at the
    working precision and raise :class:`~linecontact_sym.core.roots.Outside`
    where the law is not real.  ``breaks`` are the profile's breakpoints
    (kinks of P), ``scale`` a length scale for the scans."""

    def __init__(self, P, dP, breaks=(), mode: str = "closed", fallback=None, expr=None,
                 conditions=(), float_P=None, inactive=False):
        self._P, self._dP = P, dP
        self.breaks_exact = tuple(sorted(breaks))
        self.mode = mode
        self.fallback = fallback   # a quadrature law used where the closed form does not hold
        self.float_P = float_P     # float_P(P0f) -> P(a) in float64 from P0 in float64 (adhesive laws; optional)
        self.inactive = inactive   # an adhesive law that exerts no adhesion (JKR with gamma = 0)
        # P(0+) = lim_{a->0+} P(a) as a callable at the working precision, where it is not 0
        # (Maugis-Dugdale: the Dugdale force of the zone of a vanishing contact): the minimum
        # then follows dP/da down in decades below the search range (equilibria.descent)
        self.P_zero = None
        # a law without closed form may say how to scan it (:class:`ScanHint`, equilibria.landscape)
        self.scan = None
        self.expr = expr           # P(a) as a SymPy expression in a (closed form), else None
        self.conditions = tuple(conditions)   # where ``expr`` holds (relations in a)
        self.base = self           # the non-adhesive law P0 (admissibility is read from it)
        self.convex = False        # P0 proven convex on (0, oo) (:func:`convex_profile`)
        self.rising = False        # dP0/da >= 0 proven for every a > 0 (:func:`rising_profile`)
        self.flat = None           # the profile is 0 on [0, flat]: P0 = 0 for a <= flat (:func:`flat_end`)
        self.monotone_term = False  # (a law on top of P0) see :meth:`on_top`
        self._landscape = None
        self._balls = None
        self.geometry = ISOLATED   # the punches of the superposition (method.geometry); see mapped()

    # ----------------------------------------------------------- builders
    @classmethod
    def from_closed_form(cls, expr, values: dict, conditions=(), breaks=(), fallback=None):
        """The law of a closed-form P0(a) (SymPy, in ``a``) at ``values``;
        ``conditions`` (relations in a) say where the closed form holds."""
        pf = {k: v for k, v in values.items() if k != S.a}
        P0 = expr.xreplace(pf)
        if P0.free_symbols - {S.a}:
            raise DomainError(f"missing values for {sorted(map(str, P0.free_symbols - {S.a}))}")
        # a law is evaluated thousands of times by the root and minimum searches (and at every
        # node of the Maugis-Dugdale gap's quadrature): a form with Bessel functions in Arb, whole
        # (numeric.arb_functions.lambdify_law), the others in mpmath with Bessel and elliptic Pi
        # through Arb (MPMATH_ARB)
        fP = lambdify_law([S.a], P0)
        fdP = lambdify_law([S.a], sp.diff(P0, S.a))
        conds = [cd.xreplace(pf) for cd in conditions if cd.has(S.a)]
        ok = sp.lambdify(S.a, sp.And(*conds), "mpmath") if conds else None

        def guarded(fn, name):
            def g(A):
                try:
                    if ok is not None and not bool(ok(A)):
                        raise Outside
                    return real_value(fn(A))
                except UNDEFINED:
                    if fallback is None:
                        raise Outside
                    # the closed form may hold on part of the axis only (branch
                    # cuts): the profile's own quadrature decides the domain.
                    # It is asked at FALLBACK_DPS digits at most: callers that
                    # raise the precision to confirm a cancelling closed form
                    # (equilibria.reliable, up to 640 digits) would otherwise
                    # pay quadratures at hundreds of digits where the profile
                    # is singular (the exact cylinder at a = R: minutes)
                    with workdps(min(mpmath.mp.dps, FALLBACK_DPS)):
                        return +getattr(fallback, name)(A)
            return g
        return cls(guarded(fP, "P"), guarded(fdP, "dP"), breaks, "closed", fallback, expr=P0, conditions=conds)

    @classmethod
    def from_profile(cls, profile, values: dict):
        """The quadrature law of Eq. (10*) for a profile at ``values``
        (E_star and the profile's parameters), read from the profile's
        expression at this point (:class:`~linecontact_sym.method.transforms.NumericProfile`:
        breakpoints found numerically here, not the engine's pieces)."""
        pf = {k: v for k, v in values.items() if k not in (S.a, S.x)}
        E = to_basic_number(pf[S.E_star])
        npf = NumericProfile(profile, pf)
        f1, f2 = npf.f1, npf.f2

        def h1(t):
            return f1(t) + t * f2(t)

        def edges(A):
            return [mpmath.mpf(0)] + npf.kinks(0, A) + [A]

        # a piece where Gauss-Legendre did not converge (a singular end: the power
        # law's piece from 0) is integrated by tanh-sinh at once the next
        # GAUSS_RETRY times it comes (per integrand and start of the piece)
        retry = {}

        def over_pieces(g, A, e):
            """int_0^{pi/2} sin(phi) g(A sin phi) dphi, piece by piece between the kinks e."""
            total = mpmath.mpf(0)
            for lo, hi in zip(e[:-1], e[1:]):
                fn = inside(g, lo, hi)
                wait = retry.get((g, lo), 0)
                v, by_gauss = quad_piece(lambda ph: mpmath.sin(ph) * fn(A * mpmath.sin(ph)),
                                         mpmath.asin(lo / A), mpmath.asin(hi / A), gauss=not wait)
                retry[(g, lo)] = wait - 1 if wait else (0 if by_gauss else GAUSS_RETRY)
                total += v
            return total

        def P(A):
            return real_value(to_mpf(E) * A * over_pieces(f1, A, edges(A)))

        def dP(A):
            e = edges(A)
            total = over_pieces(h1, A, e)
            for bv in e[1:-1]:
                eps = bv * mpmath.mpf(10)**(-mpmath.mp.dps - 5)
                J = f1(bv + eps) - f1(bv - eps)
                total += J * bv**2 / mpmath.sqrt(A**2 - bv**2)
            return real_value(to_mpf(E) * total)

        def guard(fn):
            def g(A):
                # the integrands take f'(t) for 0 < t < a: where the slope at the edge is not
                # real (the exact cylinder past x = R) the law is not either -- said at once,
                # not after a quadrature of complex values
                try:
                    edge = f1(A)
                except UNDEFINED:
                    edge = None    # infinite at the edge (a = R): the quadrature decides
                if isinstance(edge, mpmath.mpc) and abs(edge.imag) > abs(edge.real) * mpmath.mpf(10)**(5 - mpmath.mp.dps):
                    raise Outside
                try:
                    return fn(A)
                except UNDEFINED:
                    raise Outside
            return g
        with workdps(80):
            found = npf.kinks(0, mpmath.mpf(10)**6)
        law = cls(guard(P), guard(dP), tuple(sp.Float(k, 80) for k in found), "quad")
        law.numeric_profile, law.E = npf, E
        return law

    @classmethod
    def from_contact(cls, contact, values: dict, mode: str = "closed"):
        """The non-adhesive law of a :class:`~.contact.LineContact` at
        ``values``: the closed form where the engine found one (``mode='closed'``,
        with the quadrature as fallback off its domain), else the quadrature."""
        kernel = getattr(contact, "kernel", None)
        if kernel is not None:     # another geometry: the law of its kernel twin, mapped (method.geometry)
            return cls.from_contact(kernel, values, mode).mapped(contact.geometry, values)
        quad = cls.from_profile(contact.profile, values)
        cache = contact._caches()
        if "_convex" not in cache:
            cache["_convex"] = convex_profile(contact.profile)
        quad.convex = cache["_convex"]
        if "_rising" not in cache:   # (a convex P0 is not searched either: no proof needed)
            cache["_rising"] = not cache["_convex"] and rising_profile(contact.profile)
        quad.rising = cache["_rising"]
        quad.flat = flat_end(contact.profile, values)
        fd = contact.derivation("force")
        if mode == "quad" or not fd.closed_form:
            return quad
        pf = {k: v for k, v in values.items() if k not in (S.a, S.x)}
        breaks = [sp.N(bp.xreplace(pf), 80) for bp in contact.profile.breakpoints]
        law = cls.from_closed_form(fd.expr, values, fd.conditions, [bp for bp in breaks if bp > 0], fallback=quad)
        law.convex, law.rising, law.flat = quad.convex, quad.rising, quad.flat
        return law

    def mapped(self, geometry, values) -> "ForceLaw":
        """This law of the kernel variable (half-width S) as a law of the
        half-width a of ``geometry`` (:mod:`~linecontact_sym.method.geometry`):
        P(a) = Q(S(a)), dP/da = Q'(S(a)) S'(a), breakpoints at x_of(s), not
        real beyond the largest half-width (L/2 for a periodic array)."""
        top = geometry.mp_a_max(values)
        kernel = self

        def law_of(route):
            def P(A):
                if A > top:
                    raise Outside
                return route.P(geometry.mp_s(A, values))

            def dP(A):
                if A > top:
                    raise Outside
                return route.dP(geometry.mp_s(A, values)) * geometry.mp_jacobian(A, values)
            xs = [geometry.x_of(b) for b in route.breaks_exact]
            pf = {k: v for k, v in values.items() if k not in (S.a, S.x)}
            out = ForceLaw(P, dP, tuple(sp.N(b.xreplace(pf), 80) for b in xs), route.mode,
                           expr=None if route.expr is None else geometry.from_kernel(route.expr, "force"),
                           conditions=[geometry.condition_from_kernel(c) for c in route.conditions])
            out.geometry, out.kernel_law, out.geometry_values = geometry, route, pf
            if route.flat is not None:
                out.flat = to_mpf(sp.N(geometry.x_of(sp.Float(route.flat, mpmath.mp.dps + 5)).xreplace(pf),
                                       mpmath.mp.dps + 5))
            return out
        law = law_of(kernel)
        if kernel.fallback is not None:
            law.fallback = law_of(kernel.fallback)
        return law

    def on_top(self, P, dP, expr=None, float_P=None, inactive=False, monotone_term=False) -> "ForceLaw":
        """A law built on this one (an adhesive law on the non-adhesive
        ``self``, its ``base``): P, dP callables of a (mpf), ``expr`` the
        closed form in ``a`` if any, ``float_P`` see the constructor;
        ``monotone_term``: the slope of P - P0 is < 0 and increasing in a
        (JKR's -B1 sqrt(a)), which the searches of :mod:`.equilibria` use
        (a convex P0, a flat)."""
        law = ForceLaw(P, dP, self.breaks_exact, self.mode, expr=expr, conditions=self.conditions,
                       float_P=float_P, inactive=inactive)
        law.base = self
        law.geometry = self.geometry
        law.geometry_values = getattr(self, "geometry_values", {})
        # what the searches may assume of P - P0 (equilibria): only a term whose slope is
        # < 0 and increasing (JKR's -B1 sqrt(a)) keeps dP/da increasing where P0 is convex
        # and leaves no stationary point on a flat
        law.monotone_term = monotone_term
        return law

    # ----------------------------------------------------------- values
    def P(self, A):
        return self._P(A)

    def dP(self, A):
        return self._dP(A)

    def breaks(self):
        """The breakpoints as mpf at the working precision."""
        return [to_mpf(b) for b in self.breaks_exact]

    @property
    def scale(self):
        """A length scale for scans: the geometric mean of the breakpoints, else
        the largest half-width where the geometry has one (a periodic array:
        L/2; a period 10**400 is searched at its own scale), else 1."""
        bps = self.breaks()
        if bps:
            return mpmath.exp(sum(mpmath.log(b) for b in bps) / len(bps))
        top = self.geometry.mp_a_max(getattr(self, "geometry_values", {})) if not self.geometry.is_isolated \
            else mpmath.inf
        return +top if mpmath.isfinite(top) else mpmath.mpf(1)

    @property
    def quadrature_law(self) -> "ForceLaw":
        """The same law by the quadrature route (for independent checks)."""
        return getattr(self, "quad", None) or (self if self.mode == "quad" else self.fallback)


#: the most digits at which a closed law's quadrature fallback is evaluated
#: (it decides the domain where the closed form's conditions fail)
FALLBACK_DPS = 40


def flat_end(profile, values):
    """b (mpf, at the working precision) where the profile is 0 on 0 <= x < b
    (a flat in full contact: the worn cylinder, the rounded punch), else None.
    There f' = 0, so P0(a) = 0 and dP0/da = 0 for a <= b exactly: no sign
    change of dP0/da (nor of dP/da = -B1/(2 sqrt(a)) with adhesion) is there
    to find, and a search that cannot exclude an interval where the slope is
    0 (the sampled bound) need not look."""
    if not profile.is_piecewise or profile.pieces[0].expr != 0:
        return None
    pf = {k: v for k, v in values.items() if k not in (S.a, S.x)}
    b = profile.pieces[0].hi.xreplace(pf)
    if not b.is_number:
        return None
    return to_mpf(sp.N(b, mpmath.mp.dps + 20))


def convex_profile(profile) -> bool:
    """Is P0(a) convex on (0, oo), proven from the profile?  With h(t) = t f'(t),
    P0''(a) = E* int_0^{pi/2} sin(phi)**2 h''(a sin phi) dphi, so P0 is convex
    where h'' = 2 f2 + t f3 >= 0 for every t > 0 (f2, f3 the second and third
    derivatives of f); SymPy's assumptions decide it (t and the parameters
    positive) for a profile of one analytic piece (x**2/(2R), c x**n with
    n >= 1, cosh(x) - 1 ...).  A kink adds J b**2/sqrt(a**2 - b**2) to P0',
    which falls: piecewise profiles are not taken.  False when undecided."""
    if profile.is_piecewise:
        return False
    tp = sp.Dummy("t", positive=True)
    f = profile.expr
    try:
        h2 = (2 * sp.diff(f, S.x, 2) + S.x * sp.diff(f, S.x, 3)).xreplace({S.x: tp})
        return bool(h2.is_nonnegative)
    except Exception:   # an assumption query SymPy cannot answer
        return False


def rising_profile(profile) -> bool:
    """Is dP0/da >= 0 for every a > 0 (where the law is real), proven from the
    profile?  With h(t) = t f'(t), P0(a) = E* int_0^{pi/2} h(a sin phi) dphi
    (Eq. 10* after t = a sin phi), so

        dP0/da = E* int_0^{pi/2} sin(phi) h'(a sin phi) dphi + E* sum_b J_b b^2 / (a sqrt(a^2 - b^2)),

    the sum over the breakpoints b < a where f' jumps by J_b (f continuous
    there: a step of f adds a falling term, and is not taken).  It is >= 0
    where h' = f' + t f'' >= 0 on every piece and every J_b >= 0: then the
    first a where dP0/da turns negative (the admissible range's end a*) does
    not exist, and no search for it is needed (the circular-corner punch:
    the sampled search could not exclude either end of its range, 281
    quadratures of dP0/da).  On a piece lo < x < hi, x = lo + u with u > 0
    (beyond hi too: a stronger statement), the parameters positive; a
    power with a half-integer exponent (a square root) is real and >= 0
    wherever the law is real (its f' at every t < a is, or P0 is not), and
    is replaced by a positive symbol to that power.  SymPy's assumptions
    decide; False when undecided.

    >>> from linecontact_sym.method.profile import Profile
    >>> x, R, b = S.x, S.R, S.b
    >>> rising_profile(Profile(sp.Piecewise((0, x < b), (R - sp.sqrt(R**2 - (x - b)**2), True))))
    True
    >>> rising_profile(Profile(x**2 / (2 * R) - x**4 / R**3))   # P0 rises, then falls
    False
    """
    try:
        u = sp.Dummy("u", positive=True)
        pieces = profile.pieces
        slopes = [sp.diff(p.expr, S.x) for p in pieces]
        for p, d1 in zip(pieces, slopes):
            h1 = (d1 + S.x * sp.diff(d1, S.x)).xreplace({S.x: p.lo + u})
            if not _nonnegative_where_real(h1):
                return False
        for q, p, left, right in zip(pieces, pieces[1:], slopes, slopes[1:]):
            # a step of f itself adds -(its size) b/sqrt(a^2 - b^2) to P0 (falling): continuity is asked
            if sp.simplify(p.expr.xreplace({S.x: p.lo}) - q.expr.xreplace({S.x: p.lo})) != 0:
                return False
            if not _nonnegative_where_real(sp.simplify(right.xreplace({S.x: p.lo}) - left.xreplace({S.x: p.lo}))):
                return False
        return True
    except Exception:   # an assumption query SymPy cannot answer
        return False


def _nonnegative_where_real(e) -> bool:
    """Is ``e`` >= 0 by SymPy's assumptions once each square root (a power
    with a half-integer exponent) is a positive symbol to that power?"""
    roots = {}

    def root(z):
        w = roots.get(z.base)
        if w is None:
            w = roots[z.base] = sp.Dummy("w", positive=True)
        return w ** (2 * z.exp)
    e = e.replace(lambda z: z.is_Pow and z.exp.is_Rational and z.exp.q == 2, root)
    return bool(e.is_nonnegative)


def to_basic_number(v):
    """A SymPy number for a value (exact where given exactly)."""
    v = to_basic(v)
    if not v.is_number:
        raise DomainError(f"{v} needs a numeric value")
    return v


__all__ = ["ForceLaw", "PullOff", "ScanHint", "GUARD", "convex_profile", "rising_profile", "flat_end"]
