"""mpmath functions evaluated by Arb, for mpmath lambdify namespaces that are
evaluated many times (a law's P(a) in a root search or a quadrature):
:data:`MPMATH_ARB` holds real Bessel I and J and the complete elliptic
Pi(n|m) with n, m < 1 (no principal value); everything else stays mpmath's.

Each returns the midpoint of an Arb ball computed 20 bits above mpmath's
working precision where the ball resolves that precision, and calls
mpmath's own function wherever Arb cannot (a complex or non-finite argument,
a ball too wide, an argument outside the domain handled here): the same
number to the working precision as mpmath's (both correct to it), several to
25 times faster.  The arguments and the result go through the reference
integrator's one converter (:func:`~.reference.to_acb`,
:func:`~.reference.mpf_of_arb`), exactly.
"""
from __future__ import annotations

import math

import flint
import mpmath

from .reference import mpf_of_arb, to_acb
from .special import mp_elliptic_pi

__all__ = ["MPMATH_ARB"]


def _arb_of(v):
    """The exact arb of a real, finite mpf, int or float; None for anything
    else (mpc, inf, nan, bool): then mpmath decides."""
    if isinstance(v, mpmath.mpf):
        ok = mpmath.isfinite(v)
    elif isinstance(v, float):
        ok = math.isfinite(v)
    else:
        ok = isinstance(v, int) and not isinstance(v, bool)
    return to_acb(v).real if ok else None


def _resolved_mid(b, prec):
    """The midpoint of the real arb ``b`` rounded to mpmath's working
    precision when the ball is finite and resolves ``prec`` bits (relative);
    else None."""
    if not b.is_finite():
        return None
    if not b.is_exact() and b.rel_accuracy_bits() < prec + 4:
        return None
    return +mpf_of_arb(b.mid())


def _through_arb(ball_of, mp_fn, ok=lambda *xs: True):
    """``mp_fn`` (an mpmath function of real arguments) evaluated as
    ``ball_of(*arbs)`` (module docstring); ``ok(*arbs)`` false: mpmath's."""
    def f(*args):
        prec = mpmath.mp.prec
        with flint.ctx.workprec(prec + 20):
            xs = [_arb_of(a) for a in args]     # exact: an argument's mantissa has at most prec bits
            out = _resolved_mid(ball_of(*xs), prec) if None not in xs and ok(*xs) else None
        return mp_fn(*args) if out is None else out
    f.__name__ = mp_fn.__name__
    return f


def _pi_complete(n, m):
    return flint.acb.elliptic_pi(flint.acb(n), flint.acb(m)).real


MPMATH_ARB = {
    "besseli": _through_arb(lambda nu, z: z.bessel_i(nu), mpmath.besseli),
    "besselj": _through_arb(lambda nu, z: z.bessel_j(nu), mpmath.besselj),
    "elliptic_pi": _through_arb(_pi_complete, mp_elliptic_pi,
                                ok=lambda *xs: len(xs) == 2 and xs[0] < 1 and xs[1] < 1),
}
