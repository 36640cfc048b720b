"""The one converter of numbers (core.conversion.number / to_mpf) and the
parser's decimal literals: every number type a user may pass, exactly."""
from __future__ import annotations

import decimal
import fractions

import mpmath
import numpy as np
import pytest
import sympy as sp

from linecontact_sym.core.conversion import (evalf, exact_number, float_values, number, point_value, to_basic,
                                             to_mpf)
from linecontact_sym.core.errors import DomainError, LineContactError
from linecontact_sym.parsing import parse_expr, user_value

D31 = "0.3333333333333333333333333333333"


@pytest.mark.parametrize("value, exact", [
    (3, sp.Integer(3)),
    (np.int64(-4), sp.Integer(-4)),
    (0.5, sp.Rational(1, 2)),
    (0.1, sp.Rational(*(0.1).as_integer_ratio())),                  # the double's binary value
    (np.float32(0.1), sp.Rational(*np.float32(0.1).as_integer_ratio())),
    (np.array(0.375), sp.Rational(3, 8)),
    (np.array(7), sp.Integer(7)),
    (fractions.Fraction(2, 7), sp.Rational(2, 7)),
    (decimal.Decimal(D31), sp.Rational(D31)),                       # all 31 digits
    (D31, sp.Rational(D31)),
    ("-1.5e-3", sp.Rational(-3, 2000)),
    (mpmath.mpf(0.1), sp.Rational(*(0.1).as_integer_ratio())),
    (sp.sqrt(3) / 2, sp.sqrt(3) / 2),
    (sp.pi / 4, sp.pi / 4),
    (sp.E, sp.E),
])
def test_number_is_exact(value, exact):
    got = number(value)
    assert got == exact and got.is_number and not got.has(sp.Float)


def test_a_float_number_becomes_its_binary_or_decimal_value():
    f40 = sp.Float("0.7071067811865475244008443621048490392848", 40)
    assert number(f40) == sp.Rational(f40)                          # exact binary value, 40 digits
    assert abs(number(f40) - sp.Rational("0.7071067811865475244008443621048490392848")) < sp.Rational(1, 10**39)
    assert number(f40, "decimal") == sp.Rational("0.7071067811865475244008443621048490392848")
    assert number(0.1, "decimal") == exact_number(0.1) == sp.Rational(1, 10)
    assert number(np.float32(0.1), "decimal") == sp.Rational(1, 10)  # the float32's shortest decimal
    assert number(sp.Float(0.25) * sp.pi) == sp.pi / 4


@pytest.mark.parametrize("bad, err", [
    (float("nan"), DomainError), (np.float64("inf"), DomainError), (decimal.Decimal("NaN"), DomainError),
    (mpmath.inf, DomainError), (True, LineContactError), (None, LineContactError),
    ("sqrt(2)", LineContactError), ("1+1", LineContactError), (np.array([1.0, 2.0]), LineContactError),
    ([1, 2], LineContactError),
])
def test_number_refuses(bad, err):
    with pytest.raises(err):
        number(bad)


def test_text_goes_through_the_parser_elsewhere():
    assert user_value("sqrt(3)/2") == sp.sqrt(3) / 2
    assert user_value(np.float32(0.3)) == sp.Rational(3, 10)
    with pytest.raises(LineContactError):
        to_basic("sqrt(2)")


def test_to_mpf_keeps_every_digit():
    """A 31-digit Decimal, text and a 40-digit Float at 50 digits: all their
    digits arrive (never through a Python float); SymPy numbers at the working
    precision.  Reference: mpmath from the decimal text."""
    with mpmath.workdps(50):
        ref = mpmath.mpf(D31)
        for v in (decimal.Decimal(D31), D31, sp.Rational(D31), parse_expr(D31)):
            assert to_mpf(v) == ref, type(v)
        assert abs(to_mpf(sp.sqrt(3) / 2) - mpmath.sqrt(3) / 2) <= mpmath.mpf(10)**-49
        assert abs(to_mpf(sp.exp(-1)) - mpmath.exp(-1)) <= mpmath.mpf(10)**-49
        assert to_mpf(fractions.Fraction(1, 3)) == mpmath.mpf(1) / 3
        assert to_mpf(np.array(0.375)) == mpmath.mpf("0.375")
    assert mpmath.mp.dps == 15
    with pytest.raises(TypeError):
        to_mpf(sp.I)


def test_parser_keeps_a_long_literal():
    assert parse_expr(D31) == sp.Rational(D31)
    assert parse_expr("2*" + D31 + "e-2") == 2 * sp.Rational(D31) / 100
    assert parse_expr("0.1") == sp.Rational(1, 10)
    long_ = "0." + "1234567890" * 4                                  # 40 digits
    assert parse_expr(long_) == sp.Rational(long_)


def test_float_values_takes_any_exact_number():
    """The TypeError 'cannot create mpf from sqrt(3)/2' was born here."""
    x = sp.Symbol("x")
    out = float_values({x: sp.sqrt(3) / 2}, 40)
    assert out[x].is_Float and abs(out[x] - sp.sqrt(3) / 2) < sp.Float(10, 40)**-39
    assert evalf(sp.pi, 30) == sp.N(sp.pi, 30)


def test_point_value_leaves_expressions():
    a = sp.Symbol("a")
    assert point_value(a) is a
