"""Random verification points of a contact: parameter values, a half-width
and, for quantities defined inside or outside the contact, an x.

The one place that decides where closed forms are checked; every contact
class draws its points here.  Points are exact rationals (six decimals), so
the closed form and its reference see the same number.

Points are admissible: the parameters lie in the profile's ranges (a
default range is cut to where the profile is real and rising near x = 0,
see :meth:`~linecontact_sym.method.profile.Profile._check_real_and_rising`:
``x*tan(theta)`` is sampled at theta < pi/2 only) and satisfy its
assumptions (the case of a parameter-dependent Piecewise), and the profile
does not decrease on (0, a).
"""
from __future__ import annotations

import sympy as sp

from ..core import symbols as S
from ..core.conversion import rational

#: range of the reduced modulus at the verification points
E_STAR_RANGE = (0.5, 3.0)
#: x relative to a, by the domain of the quantity
X_RANGES = {"inside": (0.02, 0.98), "outside": (1.05, 2.5)}


def sample_half_width(profile, rng, vals):
    """A half-width inside a random piece of the profile (a single-piece
    profile: in (0.05, 1.5)), shrunk until the profile's slope is real and
    finite there and the profile does not decrease on (0, a)
    (:meth:`~linecontact_sym.method.profile.Profile.rising_on`: the
    frictionless compact contact needs it); None when no such point is found."""
    pcs = profile.pieces
    pc = pcs[rng.randrange(len(pcs))] if len(pcs) > 1 else pcs[0]
    lo = float(sp.N(pc.lo.xreplace(vals)))
    hi = float(sp.N(pc.hi.xreplace(vals))) if pc.hi != sp.oo else lo + 1.5
    if len(pcs) == 1:
        lo, hi = 0.05, 1.5
    av = rng.uniform(lo + 0.02 * (hi - lo), hi - 0.02 * (hi - lo))
    for _ in range(12):  # shrink into the profile's real domain
        try:
            fp = complex(sp.N(profile.piece_at(av, vals).derivative.xreplace(vals).subs(S.x, av)))
            if abs(fp.imag) < 1e-30 and abs(fp) < 1e30 and profile.rising_on(vals, av) is None:
                return rational(av)
        except (TypeError, ValueError):
            pass
        av *= 0.5
    return None


def point_sampler(profile, domain: str = "any", extra=None):
    """A function ``rng -> {Symbol: Rational} or None``: the profile's
    parameters, E_star, a, and x where ``domain`` is 'inside' or 'outside';
    ``extra`` maps further symbols to (low, high) ranges."""
    def sample(rng):
        vals = profile.sample_params(rng)
        vals[S.E_star] = rational(rng.uniform(*E_STAR_RANGE))
        av = sample_half_width(profile, rng, vals)
        if av is None:
            return None
        vals[S.a] = av
        if domain in X_RANGES:
            vals[S.x] = rational(float(av) * rng.uniform(*X_RANGES[domain]))
        for sym, (lo, hi) in (extra or {}).items():
            vals[sym] = rational(rng.uniform(lo, hi))
        return vals
    return sample


#: the half-width of a periodic array relative to L/2 at the verification points (a/L up to 0.46)
PERIODIC_A_RANGE = (0.04, 0.92)
#: the range of a symbolic period not in the profile
PERIOD_RANGE = (0.5, 2.5)


def periodic_sampler(profile, geometry, domain: str = "any", extra=None):
    """:func:`point_sampler` for a periodic array (``geometry`` a
    :class:`~linecontact_sym.method.geometry.Periodic`): the period's symbol
    (its profile range, or :data:`PERIOD_RANGE`), a in :data:`PERIODIC_A_RANGE`
    times L/2 where the profile does not decrease on (0, a), x inside or in
    (a, L/2) outside."""
    def sample(rng):
        vals = profile.sample_params(rng)
        for sym in geometry.symbols:
            if sym not in vals:
                vals[sym] = rational(rng.uniform(*profile.ranges.get(sym, PERIOD_RANGE)))
        vals[S.E_star] = rational(rng.uniform(*E_STAR_RANGE))
        # exact multiples of the half period (a float of L/2 overflows for a period 10**400)
        half = geometry.period.xreplace(vals) / 2
        av = half * rational(rng.uniform(*PERIODIC_A_RANGE))
        if profile.rising_on(vals, av) is not None:
            return None
        vals[S.a] = av
        if domain == "inside":
            vals[S.x] = av * rational(rng.uniform(*X_RANGES["inside"]))
        elif domain == "outside":
            vals[S.x] = av + (half - av) * rational(rng.uniform(0.05, 0.95))
        for sym, (lo, hi) in (extra or {}).items():
            vals[sym] = rational(rng.uniform(lo, hi))
        return vals
    return sample


__all__ = ["point_sampler", "periodic_sampler", "sample_half_width", "E_STAR_RANGE", "X_RANGES"]
