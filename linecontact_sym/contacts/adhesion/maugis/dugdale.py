"""The Dugdale limit of the Maugis-Dugdale pull-off (sigma_0 -> 0 with w
fixed, the Maugis parameter lambda -> 0), from the package's own two
conditions, without the search of P(a).

**What the equations reduce to.**  As sigma_0 -> 0 the range h0 = w/sigma_0
grows and the cohesive zone gets wide relative to the contact, c_D >> a.
Expanded in a/c_D the gap condition (:mod:`.law`)

    g0(c; a) + (4 sigma_0/(pi E*)) (sqrt(c^2 - a^2) acosh(c/a) - c log(c/a)) = h0

becomes, at leading order, the condition of a vanishing contact (the
engine's ``zero_width_expr``, P0 -> 0, g0(c; a) -> f(c)):

    Z0(c0) = f(c0) + 4 ln 2 sigma_0 c0/(pi E*) = h0,

and the load P(a) = P0(a) - 2 sigma_0 sqrt(c_D^2 - a^2) becomes
P0(a) - 2 sigma_0 c0.  Its first correction follows from dc_D/da =
-G_a/G_c (partial derivatives of the gap condition; G_c -> Z0'(c0),
G_a -> -(2/(pi E*)) acosh(c/a) (P0'(a) + 2 sigma_0 a/c)):

    dP/da = (P0'(a) + 2 sigma_0 a/c0) (1 - eps acosh(c0/a)),   eps = 4 sigma_0/(pi E* Z0'(c0)).

So P(a) falls from P(0+) = -2 sigma_0 c0 only below a_min = 2 c0 exp(-1/eps)
(where eps log(2 c0/a) = 1) and rises beyond it: the pull-off is P(0+) up to
the depth of that minimum,

    P_min - P(0+) = -eps (P0(a_min)/n + sigma_0 a_min^2/(2 c0))   (P0 ~ a^n there),

exponentially small in 1/eps.  eps is the Dugdale-side parameter of any
profile (the zone's elastic compliance over the profile's slope at c0; for
the parabola eps = 0.354 lambda^(3/2) at R = E* = 1, w = 1/100).

**Where it answers (the switch, measured).**  The full Maugis-Dugdale
pull-off (the generic search of P(a)) against P(0+), at w = 1/100, E* = 1,
dps 15, R = b = 1, lambda from sigma0_for (relative difference measured /
estimated by :func:`estimate`):

    lambda           1                  0.5                0.3
    parabola    3.19e-3 / 3.27e-3  1.1e-7  / 1.1e-7   1.11e-15 / 1.11e-15
    x^3         1.11e-4 / 1.12e-4  1.24e-13 / 1.24e-13     (infimum)
    cosh        3.03e-3 / 3.10e-3  6.6e-8  / 6.6e-8   1.38e-16 / 1.38e-16
    rounded punch 1.92e-9 / 1.92e-9      (infimum)         (infimum)

("infimum": the full search itself reports P(0+), its minimum below 10**-21
of it; so at every lambda <= 0.2 of the four); the predicted a_min agreed
with the full search's minimum to 3 digits in every row (the parabola at
lambda = 0.5: 3.51e-4 and 3.5136e-4).  eps = 0.343, 0.125, 0.058 for the
parabola's three columns.  The limit answers where eps <= :data:`EPS_SWITCH`
(0.15: where the expansion was checked to a few per cent; no other minimum
of P(a) was found there in any of the four) and :data:`SAFETY` times the
estimate is below 10**-(dps+1): then P(0+), one root of Z0 (the engine's
closed condition), is the pull-off to the digits asked.

**The scaling.**  P_min = -2 sigma_0 c0 is degenerate as sigma_0 -> 0: where
the profile carries the gap (f(c0) ~ h0, the rigid limit f(c_r) = h0 of
:func:`.check.rigid_limit`) and f ~ x^n there, c0 ~ (w/sigma_0)^(1/n) and
P_min ~ sigma_0^(1 - 1/n) -> 0 (n > 1: the parabola sigma_0^(1/2)), a finite
limit for n = 1 (the wedge); where the profile stays below h0 the elastic
term carries it, c0 -> pi E* h0/(4 ln 2 sigma_0) and P_min -> -pi E* w/(2 ln 2 sigma_0).
The note states which, with n = c0 f'(c0)/f(c0) and the shares of f and of
the elastic term, both read from the engine's Z0 at c0.
"""
from __future__ import annotations

import mpmath
import sympy as sp

from ....core.errors import LineContactError
from ....core.precision import workdps
from ....core.roots import Outside
from ...normal.force_law import PullOff

#: the largest eps = 4 sigma_0/(pi E* Z0'(c0)) where the Dugdale limit may answer (module docstring)
EPS_SWITCH = mpmath.mpf("0.15")
#: the factor on the estimated depth of the minimum below P(0+) (the estimate within 15 % at eps <= 0.15)
SAFETY = 10


class DugdaleLimit:
    """The Dugdale limit at values (:func:`dugdale_reached`): P(0+) = -2 sigma_0 c0, the parameter eps, the
    estimated minimum a_min and its relative depth ``rel`` below P(0+), the scaling as sigma_0 -> 0."""

    model = "Dugdale limit"

    def __init__(self, c0, force, eps, a_min, rel, n_f, f_share, dps):
        self.c0, self.force, self.eps, self.a_min, self.rel = c0, force, eps, a_min, rel
        self.n_f, self.f_share, self.dps = n_f, f_share, dps

    def scaling(self):
        """How P_min behaves as sigma_0 -> 0 here (module docstring), from the shares of Z0 at c0."""
        n = self.n_f
        if self.f_share >= mpmath.mpf("0.9") and n is not None:
            if abs(n - 1) < mpmath.mpf("0.01"):
                how = "a finite limit (-2 w/f', the profile straight there: n = 1)"
            elif n > 1:
                how = f"P_min ~ sigma_0^(1 - 1/n) -> 0 (n = {mpmath.nstr(n, 5)})"
            else:
                how = f"P_min ~ sigma_0^(1 - 1/n), growing (n = {mpmath.nstr(n, 5)} < 1)"
            return (f"the profile carries the gap at c0 (f(c0) = {mpmath.nstr(self.f_share, 6)} h0, the rigid limit "
                    f"f(c_r) = h0; f ~ x^n there, n = c0 f'(c0)/f(c0)): {how}")
        if self.f_share <= mpmath.mpf("0.1"):
            return (f"the elastic term carries the gap at c0 (f(c0) = {mpmath.nstr(self.f_share, 3)} h0): c0 -> pi E* "
                    f"h0/(4 ln 2 sigma_0), P_min -> -pi E* w/(2 ln 2 sigma_0), growing as 1/sigma_0")
        return (f"both terms of Z0 carry the gap at c0 (f(c0) = {mpmath.nstr(self.f_share, 6)} h0): between the "
                f"rigid limit and the elastic one")

    def pull_off(self) -> PullOff:
        note = (f"the Dugdale limit of the Maugis-Dugdale law (eps = 4 sigma_0/(pi E* Z0'(c0)) = "
                f"{mpmath.nstr(self.eps, 6)}, maugis.dugdale): the pull-off is P(0+) = -2 sigma_0 c0 with c0 = "
                f"{mpmath.nstr(self.c0, 12)} the root of the gap condition as a/c_D -> 0, f(c0) + 4 ln 2 sigma_0 "
                f"c0/(pi E*) = h0; the minimum of P(a) lies at a ~ 2 c0 exp(-1/eps) = {mpmath.nstr(self.a_min, 3)}, "
                f"below P(0+) by ~{mpmath.nstr(self.rel, 3)} relative (estimate x {SAFETY} below the 10**-{self.dps} "
                f"asked), so no search of P(a) was run; as sigma_0 -> 0: {self.scaling()}")
        return PullOff(+self.force, -self.force, mpmath.mpf(0), "infimum", None, (), note)


def estimate(law, dps: int):
    """(c0, eps, P(0+), a_min, rel) of the numeric law ``law`` (:class:`~.numbers.MDLaw`) at dps digits:
    the zone of a vanishing contact, the parameter eps, the load P(0+) = -2 sigma_0 c0, where the minimum
    of P(a) lies and its estimated depth below P(0+), relative (module docstring); rel None where the
    estimate does not apply (Z0' <= 0, P0 not ~ a^n with n >= 1 near a_min)."""
    with workdps(dps + 15):
        c0 = law.c0(dps + 5)
        E = mpmath.mpf(sp.N(law.E, dps + 20))
        sig = mpmath.mpf(sp.N(law.sigma0, dps + 20))
        Zc = law._Z0c(c0)
        force = law._P0lim(c0)
        if not (Zc > 0 and force < 0):
            return c0, None, force, None, None
        eps = 4 * sig / (mpmath.pi * E * Zc)
        a_min = 2 * c0 * mpmath.exp(-1 / eps)
        a_r = min(c0 / 1000, a_min)
        P0r = law._P0(a_r)
        if P0r > 0:
            n = a_r * law._dP0(a_r) / P0r
            if not n >= 1:          # P0 ~ a^n with n >= 1 below a_r is what the estimate extrapolates
                return c0, eps, force, a_min, None
            t1 = P0r / n * (a_min / a_r)**n
        else:
            t1 = mpmath.mpf(0)      # a flat centre: P0 = 0 below a_r
        rel = eps * (t1 + sig * a_min**2 / (2 * c0)) / abs(force)
        return c0, eps, force, a_min, rel


def dugdale_reached(md, vals: dict, dps: int):
    """A :class:`DugdaleLimit` where the Dugdale limit gives the pull-off to ``dps`` digits (module
    docstring: eps <= EPS_SWITCH and SAFETY x the estimated depth below 10**-(dps+1)); else None."""
    try:
        law = md.numeric_law(**{s.name: v for s, v in vals.items()})
        c0, eps, force, a_min, rel = estimate(law, dps)
        if eps is None or rel is None or not eps <= EPS_SWITCH:
            return None
        with workdps(dps + 15):
            if not SAFETY * rel <= mpmath.mpf(10)**-(dps + 1):
                return None
            E = mpmath.mpf(sp.N(law.E, dps + 20))
            sig = mpmath.mpf(sp.N(law.sigma0, dps + 20))
            fc = law._f(c0)
            f1 = law._Z0c(c0) - 4 * mpmath.log(2) * sig / (mpmath.pi * E)
            n_f = c0 * f1 / fc if fc > 0 else None
            return DugdaleLimit(c0, force, eps, a_min, rel, n_f, fc / law.h0(), dps)
    except (LineContactError, Outside, ValueError, ZeroDivisionError):
        # no zone of a vanishing contact within the profile (DomainError), a value outside the law's
        # domain: not this limit; the full solve says what holds
        return None


__all__ = ["DugdaleLimit", "dugdale_reached", "estimate", "EPS_SWITCH", "SAFETY"]
