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
integrator's one converter (:func:`~.arb_compile.to_acb`,
:func:`~.arb_compile.mpf_of_arb`), exactly.
"""
from __future__ import annotations

import math

import flint
import mpmath
import sympy as sp

from .arb_compile import REAL, ArbUnsupported, compile_acb, mpf_of_arb, to_acb
from .special import mp_elliptic_pi

__all__ = ["MPMATH_ARB", "arb_lambdify", "lambdify_law", "SLOW_IN_MPMATH"]


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


#: values each function keeps (by arguments and working precision; cleared when full)
MEMO_SIZE = 1024


def _memo_key(args, prec):
    """(prec, the arguments' exact values) for ints and mpf, else None (not remembered)."""
    key = [prec]
    for a in args:
        if isinstance(a, mpmath.mpf):
            key.append(a._mpf_)
        elif isinstance(a, int) and not isinstance(a, bool):
            key.append(("int", a))
        else:
            return None
    return tuple(key)


def _through_arb(ball_of, mp_fn, ok=lambda *xs: True):
    """``mp_fn`` (an mpmath function of real arguments) evaluated as
    ``ball_of(*arbs)`` (module docstring); ``ok(*arbs)`` false: mpmath's.

    The value at the same arguments and working precision is remembered
    (the last :data:`MEMO_SIZE`): a closed law and its derivative call the
    same Bessel functions at the same argument (dP0/da of the Gaussian bump:
    I0, I1, I2 of a^2/(2 R^2), seven calls, and two more in P0), and a
    quadrature of P0 and one of dP0/da over the same nodes (the
    Maugis-Dugdale gap and its c-derivative in one Newton step) ask for the
    same values again.  The value is a function of (arguments, precision)
    alone, so it is the same number as computed afresh."""
    memo = {}

    def f(*args):
        prec = mpmath.mp.prec
        key = _memo_key(args, prec)
        if key is not None:
            hit = memo.get(key)
            if hit is not None:
                return hit
        with flint.ctx.workprec(prec + 20):
            xs = [_arb_of(a) for a in args]     # exact: an argument's mantissa has at most prec bits
            out = _resolved_mid(ball_of(*xs), prec) if None not in xs and ok(*xs) else None
        out = mp_fn(*args) if out is None else out
        if key is not None:
            if len(memo) >= MEMO_SIZE:
                memo.clear()
            memo[key] = out
        return out
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


def arb_lambdify(args, expr):
    """``expr`` (SymPy, real, in the symbols ``args``) as an mpmath function
    of ``args`` (mpf or int) evaluated in Arb ball arithmetic: the whole
    expression in one compiled pass (the reference integrator's compiler,
    :func:`~.arb_compile.compile_acb`, real mode) at 20 bits above mpmath's
    working precision, then (where the ball does not resolve it: a
    cancellation) once more at twice the precision plus 64 bits; the
    midpoint rounded to the working precision where the ball is finite, real
    and resolves it.  Otherwise, and for an expression the compiler does not
    take, mpmath's own lambdified function (:data:`MPMATH_ARB` for its Bessel
    and elliptic Pi) decides, as it did alone before: a value outside the
    real domain is mpmath's complex number or exception.

    The value is the exact one rounded (to within a unit in the last place),
    never less accurate than mpmath's evaluation operation by operation,
    which rounds at every step; a closed law is evaluated thousands of times
    in a root search or a quadrature of it (the Maugis-Dugdale gap of the
    Gaussian bump: dP0/da, seven Bessel I and a dozen operations, at every
    node), about ten times faster so."""
    args = list(args)
    mp_fn = _mpmath_lambdify(args, expr)
    try:
        F = compile_acb(expr, args, holomorphic=False)
    except ArbUnsupported:
        return mp_fn
    acb = flint.acb

    def f(*vals):
        prec = mpmath.mp.prec
        for bits in (prec + 20, 2 * prec + 64):
            with flint.ctx.workprec(bits):
                xs = [_arb_of(v) for v in vals]   # exact: a mantissa of at most bits bits
                if None in xs:
                    break
                try:
                    z = F(tuple(acb(x) for x in xs), REAL)
                except (ArbUnsupported, ZeroDivisionError, ValueError):
                    break
                if not z.is_finite() or not z.imag.is_zero():
                    break      # beyond the real domain, or not decided there: mpmath says what it is
                out = _resolved_mid(z.real, prec)
            if out is not None:
                return out
        return mp_fn(*vals)
    return f


#: functions whose mpmath evaluation at 20-50 digits is slow next to Arb's (Bessel I of the
#: Gaussian bump at 30 digits: 200 us in mpmath, 13 us in Arb)
SLOW_IN_MPMATH = (sp.besseli, sp.besselj, sp.besselk, sp.bessely, sp.hyper, sp.elliptic_pi)


def lambdify_law(args, expr):
    """The mpmath function of a closed form evaluated many times (a force law
    in a root search, or at every node of a quadrature): :func:`arb_lambdify`
    where the expression has a function of :data:`SLOW_IN_MPMATH` (two to four
    times faster there: dP0/da of the Gaussian bump 120 us against 310-460 us
    at 20-40 digits), else mpmath's lambdified function with
    :data:`MPMATH_ARB` (an elementary or elliptic-K/E form costs less in
    mpmath than the conversion to balls and back, about 25 us)."""
    if sp.sympify(expr, strict=True).has(*SLOW_IN_MPMATH):
        return arb_lambdify(args, expr)
    return _mpmath_lambdify(args, expr)


def _mpmath_lambdify(args, expr):
    """mpmath's lambdified function of ``expr``, its Bessel and elliptic Pi
    through Arb (:data:`MPMATH_ARB`)."""
    return sp.lambdify(list(args), expr, modules=[dict(MPMATH_ARB), "mpmath"])
