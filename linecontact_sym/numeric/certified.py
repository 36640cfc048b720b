"""Certified evaluation with python-flint (Arb ball arithmetic).

:func:`arb_evaluate` evaluates a SymPy closed form on exact inputs with Arb
balls: every operation returns a ball guaranteed to contain the exact result,
so the final ball is a rigorous enclosure of the quantity (for the inputs as
given: a Python float is its exact binary value, a string or a SymPy Rational
its exact decimal/rational value).  The working precision is raised until
the ball's relative radius meets the requested number of digits.

The stable form (:mod:`linecontact_sym.numeric.stable`) is evaluated when available:
in ball arithmetic cancellation cannot produce a wrong result, only a wide
ball, so the stable form just reaches the target at a lower precision.

The translation from SymPy to Arb is the reference integrator's one
compiler (:func:`~linecontact_sym.numeric.arb_compile.compile_acb`, one
table of handlers), asked for the real function: complex balls whose
functions give a non-finite ball beyond their real domain, as Arb's real
functions do, and Arb's real asin, acos, atanh, acosh and lgamma where they
are tighter.  Supported: + - * /, powers, sqrt, exp, log, trigonometric,
hyperbolic and their inverses, gamma / loggamma, elliptic_k / elliptic_e /
elliptic_pi (complete and incomplete, elliptic_f), 2F1 (``hyper``), Bessel
J, I, K, Y (real argument), Piecewise (conditions decided on balls; where a
ball straddles a breakpoint the union of the branches is returned, which
encloses the value of a continuous piecewise function), and the stable
primitives carlson_rf, carlson_rd, carlson_rg, carlson_rj, gamma_ratio,
hyp2f1c.  Unevaluated integrals are not supported (no certified quadrature
here): :class:`CertificationError`.

The global precision of python-flint is never changed (``ctx.workprec``).
python-flint is a core dependency of the package (one code path for
numbers: no result depends on whether an optional package is installed).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import flint
import mpmath

from ..parsing import to_sympy
from ..core.errors import LineContactError
from .arb_compile import REAL, ArbUnsupported, compile_acb, mpf_of_arb, to_acb


class CertificationError(LineContactError):
    """The expression cannot be evaluated in certified ball arithmetic."""


def to_arb(v):
    """An Arb ball containing the exact value of ``v`` at the current
    python-flint precision: every number goes through the one converter of
    the reference integrator (:func:`~linecontact_sym.numeric.arb_compile.to_acb`,
    which uses the package's :func:`~linecontact_sym.core.conversion.number`):
    int, float (its binary value), Fraction, Decimal, decimal text, mpf, NumPy
    scalars and SymPy Rationals and Floats exactly; other SymPy numbers
    (``sqrt(3)/2``, ``pi/4``, ``exp(-1)``) as balls evaluated in Arb."""
    if isinstance(v, flint.arb):
        return v
    if isinstance(v, float) and not math.isfinite(v):
        raise CertificationError(f"non-finite input {v}")
    try:
        z = to_acb(v)
    except ArbUnsupported as exc:
        raise CertificationError(str(exc)) from None
    if not z.imag.is_zero():
        raise CertificationError(f"complex value {z} where a real one was expected")
    return z.real


def compile_arb(expr, args):
    """A function ``f(*balls) -> arb`` evaluating ``expr`` (real, in the
    symbols ``args``) at the current python-flint precision.

    The one SymPy-to-Arb compiler is the reference integrator's
    (:func:`~linecontact_sym.numeric.arb_compile.compile_acb`, with the
    package's stable primitives among its handlers); this asks it for the
    real function (mode :data:`~linecontact_sym.numeric.arb_compile.REAL`: a
    ball reaching beyond a function's real domain gives a non-finite ball,
    as Arb's real functions do) and returns the real part of a result whose
    imaginary part contains 0 (a value that is not real:
    :class:`CertificationError`)."""
    try:
        f = compile_acb(to_sympy(expr), list(args), holomorphic=False)
    except ArbUnsupported as exc:
        raise CertificationError(str(exc)) from None
    acb = flint.acb

    def g(*vals):
        z = f(tuple(acb(v) for v in vals), REAL)
        if not z.is_finite():
            return flint.arb("nan")
        if 0 not in z.imag:
            raise CertificationError(f"complex value {z} where a real one was expected")
        return z.real
    return g


@dataclass
class Enclosure:
    """A rigorous enclosure: ``ball`` (python-flint arb) = [mid +/- rad]."""

    ball: object
    prec: int            # bits used

    def _mp(self, ball_method, digits=None):
        """The exact binary end point / midpoint / radius as an mpmath mpf
        (exact: an mpf with enough bits holds the Arb float as it is)."""
        with flint.ctx.workprec(self.prec + 64):
            b = getattr(self.ball, ball_method)()
            if not b.is_finite():
                return mpmath.nan
        return mpf_of_arb(b)

    @property
    def mid(self):
        return self._mp("mid")

    @property
    def rad(self):
        return self._mp("rad", 20)

    @property
    def lower(self):
        """A number <= the exact value (the ball's lower end, rounded down)."""
        return self._mp("lower")

    @property
    def upper(self):
        """A number >= the exact value."""
        return self._mp("upper")

    def rel_accuracy_digits(self):
        return self.ball.rel_accuracy_bits() * math.log10(2)

    def __str__(self):
        with flint.ctx.workprec(self.prec):
            return self.ball.str(max(int(self.prec * 0.30103) - 3, 15), radius=True)


def arb_callable(expr, args):
    """``g(values, dps=15) -> Enclosure``: :func:`arb_evaluate` with the
    translation to Arb done once."""
    f = compile_arb(expr, args)

    def g(values, dps: int = 15, max_prec: int = 40000):
        return _enclose(f, values, dps, max_prec)
    return g


def arb_evaluate(expr, args, values, dps: int = 15, max_prec: int = 40000) -> Enclosure:
    """A rigorous enclosure of the exact value of ``expr`` at ``args`` = ``values``.

    ``expr``: a SymPy expression in the supported functions (module
    docstring; no unevaluated integrals); ``values``: a sequence matching
    ``args``, each taken exactly (a float is its binary value, a string such
    as ``"0.1"`` or a Rational its exact value).  The ball arithmetic runs at
    increasing precision until the ball's relative radius is below 10**-dps;
    :class:`CertificationError` if ``max_prec`` bits do not suffice or a
    function has no Arb translation.  Needs python-flint (the
    ``[certified]`` extra), else
    :class:`~linecontact_sym.core.errors.MissingExtraError`.

    sqrt(1 + 10**-22) - 1 = 5e-23 (1 - 2.5e-23 + ...): float64 gives 0, the
    ball is certain of 20 digits.

    >>> import mpmath, sympy as sp
    >>> x = sp.Symbol("x", positive=True)
    >>> enc = arb_evaluate(sp.sqrt(1 + x) - 1, [x], ["1e-22"], dps=20)
    >>> with mpmath.workdps(60):
    ...     exact = mpmath.sqrt(1 + mpmath.mpf("1e-22")) - 1
    ...     print(enc.lower <= exact <= enc.upper, mpmath.nstr(enc.mid, 5))
    True 5.0e-23
    >>> enc.rel_accuracy_digits() >= 20
    True
    """
    return _enclose(compile_arb(expr, args), values, dps, max_prec)


def _enclose(f, values, dps, max_prec):
    prec = int(dps * 3.33) + 30
    target_bits = dps * math.log2(10) + 1
    last = None
    while prec <= max_prec:
        with flint.ctx.workprec(prec):
            balls = [to_arb(v) for v in values]
            try:
                y = f(*balls)
            except (ZeroDivisionError, ValueError) as exc:
                raise CertificationError(f"ball evaluation failed: {exc}")
            last = y
            if y.is_finite() and (y.is_exact() or y.rel_accuracy_bits() >= target_bits):
                return Enclosure(y, prec)
            if y.is_finite() and y.is_zero():
                return Enclosure(y, prec)
        prec *= 2
    raise CertificationError(f"no enclosure with {dps} digits within {max_prec} bits (last: {last})")
