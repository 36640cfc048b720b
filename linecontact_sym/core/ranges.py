"""Physical ranges: the one place that says which values a physical quantity
may take, and checks them.

=========  ==================  ===============================================
name       range               why
=========  ==================  ===============================================
``nu``     -1 < nu <= 1/2      Poisson's ratio of an isotropic elastic solid
                               (1/2: incompressible; 0 and negative values are
                               valid: cork, auxetic materials)
``mu``     mu > 0              Coulomb friction coefficient of a tangential or
                               sliding contact (0 is the frictionless contact)
``c_s``    0 <= c_s <= a       the stick zone lies inside the contact
``c_r``    c_s <= c_r <= a     a reversal's stick zone holds the turning point's
``points`` integer >= 2        a load cycle needs both of its ends
=========  ==================  ===============================================

Conditions of a derived result (the exact cylinder's a < R, ...) are not
listed here: they are part of the result
(:attr:`~linecontact_sym.method.derivation.Derivation.point_conditions`)
and every numeric path checks them.

Each check takes a SymPy number, a Python/NumPy number or an array (checked
elementwise); a symbolic value is left alone (it is checked when it gets a
number).  A value outside its range raises
:class:`~linecontact_sym.core.errors.DomainError` naming the quantity, the
value and the range.
"""
from __future__ import annotations

import numbers

import numpy as np
import sympy as sp

from . import symbols as S
from .errors import DomainError

#: name -> (low, low included, high, high included, what it is)
RANGES = {
    "nu": (-1, False, sp.Rational(1, 2), True, "Poisson's ratio"),
    "mu": (0, False, sp.oo, False, "the friction coefficient"),
}

#: the symbols declared positive whose value 0 every contact refuses at its entry
#: (contacts.base: a symbol declared positive may be 0 only where it is x, the
#: depth z or a cohesive law's parameter of domain 'nonnegative', JKR's gamma):
#: the half-width, E*, the radius, the flat's half-width b, the power law's n and c,
#: the wedge angle, the stick half-widths c_s and c_r (0 would be gross slip) and the
#: Maugis-Dugdale sigma_0 and c_D (not the friction coefficient: the sliding stress
#: field takes mu = 0, the frictionless field).
#: An export seeks no removable limit at 0 for them (numeric.exports).
NEVER_ZERO = frozenset({S.a, S.E_star, S.R, S.b, S.n, S.c, S.theta, S.c_s, S.c_r, S.sigma_0, S.c_D})


def _numeric(v):
    """The value as a float array (None for a symbolic value)."""
    if isinstance(v, sp.Basic):
        if not v.is_number:
            return None
        if v.is_real is False:
            raise DomainError(f"{v} is not a real number")
        return np.asarray(float(sp.N(v, 30)))
    if isinstance(v, str):
        return None                      # text: checked once it is read as a number
    try:
        return np.asarray(v, dtype=float)
    except (TypeError, ValueError):
        return None


def check_value(name: str, value, zero_ok: bool = False) -> None:
    """``value`` lies in the physical range of ``name`` (see the module
    docstring); names without a range pass.  ``zero_ok``: the value 0 is
    accepted too (the sliding stress field's mu = 0 is the frictionless field)."""
    if name not in RANGES or value is None:
        return
    if zero_ok and _numeric(value) is not None and np.all(_numeric(value) == 0):
        return
    lo, lo_in, hi, hi_in, what = RANGES[name]
    arr = _numeric(value)
    if arr is None:
        return
    if isinstance(value, sp.Basic):
        ok = (value >= lo if lo_in else value > lo) == sp.true and \
            (hi == sp.oo or (value <= hi if hi_in else value < hi) == sp.true)
    else:
        with np.errstate(invalid="ignore"):
            ok = bool(np.all(np.isfinite(arr))) and bool(np.all(arr >= float(lo) if lo_in else arr > float(lo))) \
                and (hi == sp.oo or bool(np.all(arr <= float(hi) if hi_in else arr < float(hi))))
    if not ok:
        rng = f"{'[' if lo_in else '('}{lo}, {hi}{']' if hi_in else ')'}"
        must = "positive" if (lo, lo_in, hi) == (0, False, sp.oo) else f"in {rng}"
        raise DomainError(f"{what} must be {must}, got {name} = {value} (its physical range is {rng})")


def check_stick(a=None, c_s=None, c_r=None) -> None:
    """0 <= c_s <= c_r <= a (each where given and numeric)."""
    A, C, Cr = (_numeric(v) for v in (a, c_s, c_r))
    with np.errstate(invalid="ignore"):
        if C is not None and np.any(C < 0):
            raise DomainError(f"the stick half-width must be >= 0, got c_s = {c_s}")
        if C is not None and A is not None and np.any(C > A):
            raise DomainError(f"the stick half-width must lie in [0, a], got c_s = {c_s} > a = {a}")
        if Cr is not None and C is not None and np.any(Cr < C):
            raise DomainError(f"the reversal stick half-width must lie in [c_s, a], got c_r = {c_r} < c_s = {c_s}")
        if Cr is not None and A is not None and np.any(Cr > A):
            raise DomainError(f"the reversal stick half-width must lie in [c_s, a], got c_r = {c_r} > a = {a}")


def check_points(points, least: int = 2, what: str = "a load cycle") -> int:
    """An integer number of points >= ``least``."""
    if isinstance(points, bool) or not isinstance(points, numbers.Integral) or points < least:
        raise DomainError(f"{what} needs an integer number of points >= {least}, got {points!r}")
    return int(points)


def check_tolerance(rtol, name: str = "rtol") -> float:
    """A relative tolerance: a real number > 0 (and < 1), read by the one
    reader of numeric settings (text, NumPy and SymPy numbers); negative,
    0, NaN, infinite or not a number raises :class:`DomainError`."""
    from .options import read_number
    return read_number(rtol, f"the relative tolerance {name}", low=0, low_open=True, high=1)


def check_positive(name: str, value, what: str | None = None):
    """A value that must be a finite real number > 0 (a stress, a work of
    adhesion at a point): returned as given when it is one; a symbolic
    value, a complex number, NaN, infinity, 0 or a negative number raises
    :class:`DomainError` naming it (infinity with ``what`` telling the limit
    it stands for, e.g. sigma_0 = oo: the JKR contact)."""
    what = what or name
    if isinstance(value, bool):
        raise DomainError(f"{what} must be a positive number, got {name} = {value!r}")
    v = value
    try:
        if isinstance(v, complex) or (isinstance(v, sp.Basic) and v.is_real is False):
            raise DomainError(f"{what} must be a real number, got {name} = {value} (complex)")
        if isinstance(v, sp.Basic):
            if not v.is_number:
                raise DomainError(f"{what} needs a number, got the expression {name} = {value}")
            if v.has(sp.oo, -sp.oo, sp.zoo, sp.nan):
                raise DomainError(f"{what} must be finite, got {name} = {value}")
            f = complex(sp.N(v, 30))
            if f.imag != 0:
                raise DomainError(f"{what} must be a real number, got {name} = {value} (complex)")
            f = f.real
        else:
            f = float(v)
    except (TypeError, ValueError) as exc:
        if isinstance(exc, DomainError):
            raise
        raise DomainError(f"{what} must be a positive number, got {name} = {value!r}") from None
    if f != f or f in (float("inf"), float("-inf")):
        raise DomainError(f"{what} must be a finite positive number, got {name} = {value}")
    if not f > 0:
        raise DomainError(f"{what} must be positive, got {name} = {value}")
    return value


#: symbols declared positive that take any sign: x (the profile is mirrored, f(-x) = f(x))
ANY_SIGN = frozenset({S.x})


def check_sign(sym, value):
    """A number bound to the symbol ``sym`` (where values enter,
    :func:`~linecontact_sym.method.derivation.values_by_name`): a complex
    number is refused for a real symbol; a symbol declared positive (R, E*,
    a, gamma, a user's ``k``; not x, :data:`ANY_SIGN`) refuses a negative
    number, and 0 where :data:`NEVER_ZERO` says so (R = 0, E* = 0; gamma = 0
    is the non-adhesive limit).  Returns ``value``; a symbolic value passes
    (it is checked once it is a number).  Raises :class:`DomainError`."""
    if not isinstance(value, sp.Basic) or not value.is_number or not (sym.is_real or sym.is_positive):
        return value
    if value.is_Rational:
        sign = (value.p > 0) - (value.p < 0)
    else:
        num = value.evalf(30)
        re_, im = num.as_real_imag()
        if im != 0 and abs(im) > abs(re_) * sp.Float(10)**-25:
            raise DomainError(f"{sym.name} must be a real number, got {sym.name} = {value} (complex)")
        if not re_.is_number or re_.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
            raise DomainError(f"{sym.name} must be a finite real number, got {sym.name} = {value}")
        sign = (bool(re_ > 0) - bool(re_ < 0)) if re_ != 0 else (0 if value.is_zero is not False else 1)
    if sym.is_positive and sym not in ANY_SIGN:
        if sign < 0 or (sign == 0 and sym in NEVER_ZERO):
            what = "positive" if sym in NEVER_ZERO else "positive (or 0)"
            raise DomainError(f"{sym.name} is declared positive; it must be {what}, got {sym.name} = {value}")
    return value


def check_values(values: dict, zero_ok=()) -> None:
    """Every ranged name of ``values`` (keywords by name) in its range (the
    names in ``zero_ok`` may also be 0), and the stick half-widths in order."""
    for name in RANGES:
        if name in values:
            check_value(name, values[name], zero_ok=name in zero_ok)
    if "c_s" in values or "c_r" in values:
        check_stick(values.get("a"), values.get("c_s"), values.get("c_r"))


__all__ = ["RANGES", "NEVER_ZERO", "check_value", "check_stick", "check_points", "check_values", "check_tolerance", "check_positive", "check_sign", "ANY_SIGN"]
