"""Conversions between Python numbers, SymPy objects and mpmath numbers: the
one place that decides how a value crosses from one world to the other.

Strings are never converted here (they are text from people: see
:func:`linecontact_sym.parsing.to_sympy`, which parses them with the
whitelist and then calls :func:`to_basic`).
"""
from __future__ import annotations

import mpmath
import sympy as sp

from .errors import DomainError, LineContactError


def to_basic(value) -> sp.Basic:
    """A SymPy object for a non-string value: SymPy objects as they are,
    numbers (int, float, Fraction, mpmath and NumPy scalars) converted by
    ``sympify(strict=True)``, which never evaluates text.

    >>> to_basic(3)
    3
    >>> to_basic("1+1")
    Traceback (most recent call last):
    ...
    linecontact_sym.core.errors.LineContactError: got the string '1+1' where a number or SymPy expression was expected; parse text with linecontact_sym.parse_expr (whitelisted)
    """
    if isinstance(value, str):
        raise LineContactError(f"got the string {value!r} where a number or SymPy expression was expected; "
                               f"parse text with linecontact_sym.parse_expr (whitelisted)")
    if isinstance(value, sp.Basic):
        return value
    try:
        return sp.sympify(value, strict=True)  # safe: never a string here
    except sp.SympifyError:
        raise LineContactError(f"cannot use {value!r} ({type(value).__name__}) as a SymPy value") from None


def exact_number(v) -> sp.Basic:
    """A value as an exact SymPy object: a float becomes the Rational of its
    shortest decimal representation (0.1 -> 1/10, as people mean it), other
    values go through :func:`to_basic` (strings are refused).

    >>> exact_number(0.1), exact_number(3)
    (1/10, 3)
    """
    if isinstance(v, float):
        if v != v or v in (float("inf"), float("-inf")):
            raise DomainError(f"expected a finite number, got {v}")
        return sp.Rational(repr(float(v)))  # float(): NumPy 2 scalars print as np.float64(...)
    return to_basic(v)


def point_value(v) -> sp.Basic:
    """A value at which a quantity is *evaluated*, as an exact SymPy number:
    a Python float is its exact binary value (the number the float64, mpmath
    and Arb paths all see), other values go through :func:`to_basic`.
    Parameters that appear in *displayed* expressions (a work of adhesion, a
    friction coefficient) and numbers typed as text use
    :func:`exact_number` (the shortest decimal) instead.

    >>> point_value(0.5), point_value(0.1) == sp.Rational(1, 10)
    (1/2, False)
    """
    if isinstance(v, float):
        if v != v or v in (float("inf"), float("-inf")):
            raise DomainError(f"expected a finite number, got {v}")
        return sp.Rational(float(v))
    return to_basic(v)


def nsimplify_basic(e, **kw) -> sp.Basic:
    """``sympy.nsimplify`` for a value that is already a SymPy object or a
    float (never a string: ``nsimplify`` would evaluate text as code)."""
    if isinstance(e, float):
        e = sp.Float(e)
    if not isinstance(e, sp.Basic):
        raise LineContactError(f"nsimplify_basic needs a SymPy object or a float, got {type(e).__name__}")
    return sp.nsimplify(e, **kw)


def rational(v, digits: int = 6) -> sp.Rational:
    """A float rounded to ``digits`` decimals as an exact Rational (sample
    points are exact so that every method sees the same number).

    >>> rational(0.1234567)
    123457/1000000
    """
    scale = 10**digits
    return sp.Rational(round(float(v) * scale), scale)


def to_mpf(v):
    """An mpf at the current working precision: exact for int, float and mpf,
    rationals divided in mpmath (rounded like lambdified code), other SymPy
    numbers evaluated with 5 guard digits.  Raises ``TypeError`` for a value
    that is not a real number."""
    if isinstance(v, mpmath.mpf):
        return +v
    if isinstance(v, bool):
        raise TypeError("a boolean is not a number")
    if isinstance(v, (int, float)):
        return mpmath.mpf(v)
    v = to_basic(v)
    if v.is_Rational:
        return mpmath.mpf(int(v.p)) / int(v.q)
    num = v if v.is_Float else sp.N(v, mpmath.mp.dps + 5)
    if not num.is_Float:
        raise TypeError(f"{v} is not a real number")
    return mpmath.mpf(num)  # reads the Float's binary value (``_mpf_``), rounds to the context


def real_mpf(v):
    """A SymPy number (or Python complex) as a real mpf at the current
    precision; a value with a non-negligible imaginary part raises
    :class:`~linecontact_sym.core.errors.DomainError` ("complex here")."""
    if isinstance(v, complex):
        if abs(v.imag) > 1e-12 * max(abs(v.real), 1e-300):
            raise DomainError(f"the quantity is complex here: {v}")
        return mpmath.mpf(v.real)
    if isinstance(v, (mpmath.mpf, int, float)):
        return to_mpf(v)
    if isinstance(v, mpmath.mpc):
        if abs(v.imag) > abs(v.real) * mpmath.mpf(10)**(-mpmath.mp.dps + 3):
            raise DomainError(f"the quantity is complex here: {v}")
        return +v.real
    v = to_basic(v)
    num = v if v.is_Float else sp.N(v, mpmath.mp.dps + 5)
    if num.is_Float:
        return mpmath.mpf(num)
    re, im = num.as_real_imag()
    if not (re.is_Float or re == 0) or not (im.is_Float or im == 0):
        raise DomainError(f"the quantity is not a number here: {v}")
    if abs(im) > abs(re) * sp.Float(10)**(-mpmath.mp.dps + 3):
        raise DomainError(f"the quantity is complex here: {v}")
    return mpmath.mpf(re) if re != 0 else mpmath.mpf(0)


def float_values(vals: dict, digits: int) -> dict:
    """Exact non-integer numbers as Floats of ``digits`` digits, for
    substitution into expressions: an exact Rational under a symbolic exponent
    makes SymPy factor huge integers (minutes); a Float with guard digits
    gives the same value to the precision asked."""
    out = {}
    for k, v in vals.items():
        if isinstance(v, sp.Basic) and v.is_number and not v.is_Integer and not v.is_Float:
            out[k] = sp.Float(v, digits)
        else:
            out[k] = v
    return out


__all__ = ["to_basic", "exact_number", "point_value", "nsimplify_basic", "rational", "to_mpf", "real_mpf", "float_values"]
