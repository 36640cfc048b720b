"""One reader for every number a user types (issue 42, class 1): a plain
number first (any float notation, a fraction), an expression of numbers
next, a unit only where the text is neither; the same input means the same
number with and without pint (pint absent is simulated)."""
import contextlib
import io
import sys

import pytest
import sympy as sp

from linecontact_sym import cli
from linecontact_sym.core.conversion import plain_number
from linecontact_sym.core.errors import ClaimError, DomainError, LineContactError
from linecontact_sym.core.options import read_number
from linecontact_sym.core.symbols import UNITS
from linecontact_sym.claims.fields import number_field
from linecontact_sym.parsing import parse_assignments, parse_number

ORDINARY = {"2.1e11": sp.Integer(210000000000), "2.1E11": sp.Integer(210000000000),
            "1e300": sp.Integer(10)**300, "1e-3": sp.Rational(1, 1000), ".5": sp.Rational(1, 2),
            "1/3": sp.Rational(1, 3), "2.1e11/3": sp.Integer(70000000000), "pi/4": sp.pi / 4}


@pytest.fixture(params=["with pint", "without pint"])
def pint_state(request, monkeypatch):
    if request.param == "without pint":
        monkeypatch.setitem(sys.modules, "pint", None)      # import pint now raises ImportError
    return request.param


def test_ordinary_numbers_are_numbers_with_and_without_pint(pint_state):
    for text, value in ORDINARY.items():
        assert parse_number(text, "--set E_star", "E_star", UNITS) == value, text
        assert parse_number(text) == value, text
    vals = parse_assignments(["R=0.01", "E_star=2.1e11", "sigma_0=1e300"], where="--set", units=UNITS)
    assert {k.name: v for k, v in vals.items()} == {"R": sp.Rational(1, 100), "E_star": 210 * 10**9,
                                                     "sigma_0": sp.Integer(10)**300}


def test_a_unit_only_where_the_text_is_not_a_number(pint_state):
    if pint_state == "with pint":
        assert parse_number("210GPa", "--set E_star", "E_star", UNITS) == 210 * 10**9
        assert parse_number("5 mm", "--set R", "R", UNITS) == sp.Rational(5, 1000)
        with pytest.raises(DomainError, match="not one of"):
            parse_number("5 s", "--set R", "R", UNITS)
    else:
        with pytest.raises(LineContactError, match="pint"):
            parse_number("210GPa", "--set E_star", "E_star", UNITS)
    with pytest.raises(ClaimError, match="exponent without digits"):
        parse_number("2.1e", "--set E_star", "E_star", UNITS)
    with pytest.raises(ClaimError, match="plain SI"):
        parse_number("210GPa", "claims.toml: values")          # a place of SI numbers
    with pytest.raises(ClaimError, match="no declared unit"):
        parse_number("3mm", "--set k", "k", UNITS)


def test_the_settings_and_the_claims_files_read_the_same_numbers():
    assert plain_number("1e-3") == sp.Rational(1, 1000) and plain_number("210GPa") is None
    assert read_number("2.1e11", "the budget", low=0) == 2.1e11
    assert read_number("1/2", "the budget", low=0) == 0.5           # a fraction: the same reader
    assert number_field("2.1E11", "f.toml: ranges.E_star") == 210 * 10**9
    with pytest.raises(ClaimError):
        number_field("oo", "f.toml: ranges.E_star")


def _eval(*argv):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = cli.main(["eval", "x**2/(2*R)", "force", "--at", "a=0.001", "--dps", "15", *argv])
    return code, out.getvalue(), err.getvalue()


def test_cli_set_in_exponent_notation(pint_state):
    """Before: "--set E_star=2.1e11: 'e11' is not a unit" (exit 2) with pint installed."""
    code, out, err = _eval("--set", "R=0.01", "E_star=2.1e11")
    assert code == 0, err
    # P = pi E* a**2/(4 R) = pi 2.1e11 1e-6/0.04, computed here
    assert "16493361.431346" in out and "[" not in out.splitlines()[0]     # no unit said: plain SI numbers
    code2, out2, _ = _eval("--set", "R=0.01", "E_star=2.1E11")
    assert (code2, out2) == (code, out)
