"""The one reader of a numeric setting: a budget, a number of worker
processes, a tolerance, the environment's ``LINECONTACT_SYM_BUDGET``, the
command line's ``--jobs``, ``--budget``, ``--rtol``.  One rule for all:

* a Python, NumPy or SymPy real number, a ``Decimal`` or ``Fraction``, or
  text (surrounding spaces ignored; read by the one reader of typed
  numbers, :func:`~linecontact_sym.core.conversion.plain_number`: any
  float notation or a fraction, never evaluated); ``inf`` / ``infinity`` / ``none`` mean "no limit" where a
  setting allows it (a number too large for a float counts as infinite);
* never a bool, a complex number, NaN, or text that is not a number;
* an integer setting takes whole numbers only (``2`` and ``2.0``, not ``2.5``);
* the bounds of the setting checked;

anything else raises the package's error (:class:`DomainError`, or the
class the caller names, e.g. :class:`BudgetError`) naming the setting, the
value and what it takes.

>>> read_number(" 5 ", "the budget", low=0), read_number("inf", "the budget", low=0, allow_inf=True)
(5.0, inf)
>>> read_number("abc", "--jobs", integer=True, low=1)
Traceback (most recent call last):
...
linecontact_sym.core.errors.DomainError: --jobs must be a whole number >= 1, got 'abc'
"""
from __future__ import annotations

import math
import numbers

from .conversion import plain_number
from .errors import DomainError

__all__ = ["read_number"]

_NO_LIMIT = ("inf", "+inf", "infinity", "+infinity", "none", "unlimited")


def _describe(integer, low, low_open, high, allow_inf, what=None):
    what = what or ("a whole number" if integer else "a number")
    if low is not None:
        what += f" {'>' if low_open else '>='} {low:g}" if not integer else f" {'>' if low_open else '>='} {low}"
    if high is not None:
        what += f" and <= {high:g}"
    if allow_inf:
        what += " (or 'inf' for no limit)"
    return what


def read_number(value, name: str, *, integer: bool = False, low=None, low_open: bool = False, high=None,
                allow_inf: bool = False, error=DomainError, what: str | None = None):
    """``value`` read as the setting ``name`` (see the module docstring):
    a float (``math.inf`` for "no limit" when ``allow_inf``), or an int
    when ``integer``.  ``low`` (excluded when ``low_open``) and ``high``
    bound it; ``what`` names the kind of value in messages ("a number of seconds")."""
    def bad(why=""):
        return error(f"{name} must be {_describe(integer, low, low_open, high, allow_inf, what)}, got {value!r}{why}")

    v = value
    if isinstance(v, bool) or v is None:
        raise bad()
    if isinstance(v, (str, bytes)):
        text = (v.decode("ascii", "replace") if isinstance(v, bytes) else v).strip().replace("_", "")
        if text.lower() in _NO_LIMIT:
            if not allow_inf:
                raise bad()
            return math.inf
        q = plain_number(text)               # the one reader of typed numbers (core.conversion)
        if q is None:
            raise bad()
        if integer and q.is_Integer and abs(q) < 2**63:
            v = int(q)
        else:
            try:
                v = float(q)
            except OverflowError:            # 1e400: larger than any float
                v = math.inf
    elif isinstance(v, numbers.Integral):
        v = int(v)
    elif isinstance(v, numbers.Real) or hasattr(v, "__float__"):
        if getattr(v, "is_real", True) is False or isinstance(v, complex):
            raise bad(" (not a real number)")
        try:
            if getattr(v, "is_Integer", False):      # a SymPy Integer: exactly
                v = int(v)
            else:
                v = float(v)
        except (TypeError, ValueError, OverflowError):
            raise bad() from None
    else:
        raise bad()
    if isinstance(v, float):
        if math.isnan(v):
            raise bad()
        if integer:
            if math.isinf(v) or not v.is_integer():
                if math.isinf(v) and allow_inf:
                    return math.inf
                raise bad()
            v = int(v)
    elif not integer:                                # an int for a real setting
        try:
            v = float(v)
        except OverflowError:                        # 10**400: larger than any float
            v = math.inf
    if isinstance(v, float) and math.isinf(v):
        if v < 0 or not allow_inf:
            raise bad()
        return math.inf
    if low is not None and (v <= low if low_open else v < low):
        raise bad()
    if high is not None and v > high:
        raise bad()
    return v
