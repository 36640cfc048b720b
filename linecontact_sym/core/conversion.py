"""Conversions between Python numbers, SymPy objects and mpmath numbers: the
one place that decides how a value crosses from one world to the other.

Strings are never converted here (they are text from people: see
:func:`linecontact_sym.parsing.to_sympy`, which parses them with the
whitelist and then calls :func:`to_basic`).
"""
from __future__ import annotations

import re
from decimal import Decimal
from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp

from .errors import DomainError, LineContactError
from .precision import workdps


_DECIMAL = re.compile(r"[+-]?(\d[\d_]*\.?[\d_]*|\.\d[\d_]*)([eE][+-]?\d+)?")
_FRACTION = re.compile(r"([+-]?(?:\d[\d_]*\.?[\d_]*|\.\d[\d_]*)(?:[eE][+-]?\d+)?)\s*/\s*"
                       r"(\+?(?:\d[\d_]*\.?[\d_]*|\.\d[\d_]*)(?:[eE][+-]?\d+)?)")

#: the longest text read as a plain number (characters)
MAX_NUMBER_TEXT = 1000


def plain_number(text):
    """THE reader of a number typed as text, before anything else looks at
    it: a decimal in any float notation (``2.1e11``, ``2.1E11``, ``1e300``,
    ``.5``, ``1_000``) or a fraction of two (``1/3``, ``2.1e11/3``), as an
    exact SymPy Rational of its digits; None for any other text (an
    expression, a number with a unit, a word), which the caller then reads
    its own way (:func:`linecontact_sym.parsing.parse_number`: the
    whitelisted parser, then a unit).  Never evaluates anything; a
    zero denominator is not a plain number (None).

    >>> plain_number("2.1e11"), plain_number(" 1/3 "), plain_number("1e-3"), plain_number("210GPa")
    (210000000000, 1/3, 1/1000, None)
    """
    if not isinstance(text, str):
        return None
    t = text.strip()
    if not t or len(t) > MAX_NUMBER_TEXT:
        return None
    if _DECIMAL.fullmatch(t):
        return sp.Rational(t.replace("_", ""))
    m = _FRACTION.fullmatch(t)
    if m:
        num, den = (sp.Rational(g.replace("_", "")) for g in m.groups())
        return num / den if den != 0 else None
    return None


def number(v, floats: str = "binary") -> sp.Basic:
    """THE converter of the package: any number a user may pass, as an exact
    SymPy number (every other conversion of a value goes through here).

    ========================  ==============================================
    int, NumPy integer        Integer
    float, NumPy floating     its exact binary value (``floats="binary"``,
                              the number float64, mpmath and Arb all see)
                              or the Rational of its shortest decimal
                              (``floats="decimal"``: 0.1 -> 1/10, for
                              parameters shown in formulas)
    fractions.Fraction        Rational
    decimal.Decimal           Rational of its digits (never through float)
    decimal text ('0.1e-3')   Rational of its digits (other text: parse it
                              with :func:`linecontact_sym.parse_expr`)
    mpmath mpf                Rational of its binary value
    0-d NumPy array           its element, as above
    SymPy number              as it is (``sqrt(3)/2``, ``pi/4``, ``E``);
                              a Float becomes the Rational of its binary
                              value (``"binary"``) or of its printed digits
                              (``"decimal"``), so that a low-precision
                              Float never caps the precision of a result
    ========================  ==============================================

    NaN and infinities raise :class:`~linecontact_sym.core.errors.DomainError`;
    what is not a number (a bool, None, a list) raises
    :class:`~linecontact_sym.core.errors.LineContactError`.

    >>> import decimal, fractions
    >>> number(0.5), number(0.1, "decimal"), number(fractions.Fraction(1, 3))
    (1/2, 1/10, 1/3)
    >>> number(decimal.Decimal("0.3333333333333333333333333333333"))
    3333333333333333333333333333333/10000000000000000000000000000000
    >>> number(sp.sqrt(3) / 2)
    sqrt(3)/2
    """
    if isinstance(v, sp.Basic):
        if v.is_Float:
            return _float_rational(v, floats)
        if v.has(sp.Float):
            return v.xreplace({f: _float_rational(f, floats) for f in v.atoms(sp.Float)})
        return v
    if isinstance(v, (bool, np.bool_)) or v is None:
        raise LineContactError(f"{v!r} is not a number")
    if isinstance(v, (int, np.integer)):
        return sp.Integer(int(v))
    if isinstance(v, np.ndarray):
        if v.ndim != 0:
            raise LineContactError(f"expected one number, got an array of shape {v.shape}")
        return number(v[()], floats)
    if isinstance(v, (float, np.floating)):
        if not np.isfinite(v):
            raise DomainError(f"expected a finite number, got {v}")
        if floats == "decimal":
            return sp.Rational(repr(float(v)) if type(v) is float or isinstance(v, np.float64)
                               else str(v))  # NumPy 2 reprs are np.float32(...)
        return sp.Rational(*v.as_integer_ratio())
    if isinstance(v, Fraction):
        return sp.Rational(v.numerator, v.denominator)
    if isinstance(v, Decimal):
        if not v.is_finite():
            raise DomainError(f"expected a finite number, got {v}")
        return sp.Rational(*v.as_integer_ratio())
    if isinstance(v, mpmath.mpf):
        if not mpmath.isfinite(v):
            raise DomainError(f"expected a finite number, got {v}")
        sign, man, exp, _ = v._mpf_
        man = -int(man) if sign else int(man)
        return sp.Integer(man) * sp.Integer(2)**exp
    if isinstance(v, str):
        text = v.strip()
        if _DECIMAL.fullmatch(text) and len(text) <= MAX_NUMBER_TEXT:
            return sp.Rational(text.replace("_", ""))
        raise LineContactError(f"got the string {v!r} where a number or SymPy expression was expected; "
                               f"parse text with linecontact_sym.parse_expr (whitelisted)")
    try:
        return number(sp.sympify(v, strict=True), floats)  # safe: never a string here
    except sp.SympifyError:
        raise LineContactError(f"cannot use {v!r} ({type(v).__name__}) as a number") from None


def _float_rational(f, floats):
    if not f.is_finite:
        raise DomainError(f"expected a finite number, got {f}")
    return sp.Rational(str(f)) if floats == "decimal" else sp.Rational(f)


def to_basic(value) -> sp.Basic:
    """A SymPy object for a non-string value: SymPy objects as they are, a
    Python float as a SymPy Float, other numbers (int, Fraction, Decimal,
    mpmath and NumPy scalars, 0-d arrays) exactly by :func:`number`.

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
    if type(value) is float:
        return sp.Float(value)
    try:
        return number(value)
    except DomainError:
        raise
    except LineContactError:
        raise LineContactError(f"cannot use {value!r} ({type(value).__name__}) as a SymPy value") from None


def exact_number(v) -> sp.Basic:
    """A value as an exact SymPy object: a float becomes the Rational of its
    shortest decimal representation (0.1 -> 1/10, as people mean it):
    :func:`number` with ``floats="decimal"`` (strings other than decimals
    are refused).

    >>> exact_number(0.1), exact_number(3)
    (1/10, 3)
    """
    if isinstance(v, sp.Basic) and not v.is_number:
        return v
    return number(v, "decimal")


def point_value(v) -> sp.Basic:
    """A value at which a quantity is *evaluated*, as an exact SymPy number:
    a float is its exact binary value (the number the float64, mpmath and
    Arb paths all see): :func:`number` with ``floats="binary"``.
    Parameters that appear in *displayed* expressions (a work of adhesion, a
    friction coefficient) and numbers typed as text use
    :func:`exact_number` (the shortest decimal) instead.

    >>> point_value(0.5), point_value(0.1) == sp.Rational(1, 10)
    (1/2, False)
    """
    if isinstance(v, sp.Basic) and not v.is_number:
        return v
    return number(v, "binary")


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
    """An mpf at the current working precision, through :func:`number`:
    exact for int, float, mpf, Fraction, Decimal and decimal text (rationals
    divided in mpmath, rounded like lambdified code), other SymPy numbers
    (``sqrt(3)/2``, ``pi/4``) evaluated with 5 guard digits.  Raises
    ``TypeError`` for a value that is not a real number."""
    if isinstance(v, mpmath.mpf):
        return +v
    if isinstance(v, (bool, np.bool_)):
        raise TypeError("a boolean is not a number")
    if type(v) in (int, float):
        return mpmath.mpf(v)
    try:
        v = number(v)
    except LineContactError as exc:
        raise TypeError(str(exc)) from None
    if v.is_Rational:
        return mpmath.mpf(int(v.p)) / int(v.q)
    num = evalf(v, mpmath.mp.dps + 5)
    if not num.is_Float:
        raise TypeError(f"{v} is not a real number")
    return mpmath.mpf(num)  # reads the Float's binary value (``_mpf_``), rounds to the context


def evalf(expr, n):
    """``sympy.N(expr, n)`` under the package's precision lock: SymPy
    evaluates many functions (elliptic_k, hyper, ...) inside
    ``mpmath.workprec``, which changes mpmath's global precision for a moment;
    outside the lock another thread's ``workdps`` could restore the wrong one
    (:mod:`linecontact_sym.core.precision`)."""
    with workdps(mpmath.mp.dps):
        return sp.N(expr, n)


def real_mpf(v):
    """A SymPy number (or Python complex) as a real mpf at the current
    precision; a value with a non-negligible imaginary part raises
    :class:`~linecontact_sym.core.errors.DomainError` ("complex here")."""
    if isinstance(v, complex):
        if abs(v.imag) > 1e-12 * max(abs(v.real), 1e-300):
            raise DomainError(f"the quantity is complex here: {v}")
        return mpmath.mpf(v.real)
    if isinstance(v, mpmath.mpc):
        if abs(v.imag) > abs(v.real) * mpmath.mpf(10)**(-mpmath.mp.dps + 3):
            raise DomainError(f"the quantity is complex here: {v}")
        return +v.real
    if not isinstance(v, sp.Basic) or v.is_Rational:
        return to_mpf(v)
    num = v if v.is_Float else evalf(v, mpmath.mp.dps + 5)
    if num.is_Float:
        return mpmath.mpf(num)
    re_, im = num.as_real_imag()
    if not (re_.is_Float or re_ == 0) or not (im.is_Float or im == 0):
        raise DomainError(f"the quantity is not a number here: {v}")
    if abs(im) > abs(re_) * sp.Float(10)**(-mpmath.mp.dps + 3):
        raise DomainError(f"the quantity is complex here: {v}")
    return mpmath.mpf(re_) if re_ != 0 else mpmath.mpf(0)


def float_values(vals: dict, digits: int) -> dict:
    """Exact non-integer numbers as Floats of ``digits`` digits, for
    substitution into expressions: an exact Rational under a symbolic exponent
    makes SymPy factor huge integers (minutes); a Float with guard digits
    gives the same value to the precision asked."""
    out = {}
    for k, v in vals.items():
        if isinstance(v, sp.Basic) and v.is_number and not v.is_Integer and not v.is_Float:
            out[k] = sp.Float(v, digits) if v.is_Rational else evalf(v, digits)
        else:
            out[k] = v
    return out


__all__ = ["number", "plain_number", "evalf", "to_basic", "exact_number", "point_value", "nsimplify_basic", "rational", "to_mpf", "real_mpf", "float_values"]
