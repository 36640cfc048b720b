"""The whitelisted formula parser: what it accepts, what it refuses, and how
it says so."""
import time

import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core.errors import ClaimError
from linecontact_sym.parsing import (parse_assignments, parse_expr, parse_number, parse_number_list, t)


@pytest.mark.parametrize("text, expected", [
    ("pi*E_star*a**2/(4*R)", sp.pi * lcs.E_star * lcs.a**2 / (4 * lcs.R)),
    ("x^2/(2*R)", lcs.x**2 / (2 * lcs.R)),
    ("0.1*x", lcs.x / 10),                                   # decimals are exact
    ("sqrt(2*pi*a*gamma*E_star)", sp.sqrt(2 * sp.pi * lcs.a * lcs.gamma * lcs.E_star)),
    ("elliptic_k(a**2/R**2)", sp.elliptic_k(lcs.a**2 / lcs.R**2)),
    ("asin(b/a)", sp.asin(lcs.b / lcs.a)),
    ("hyper((1, 2), (3,), x)", sp.hyper((1, 2), (3,), lcs.x)),
    ("Rational(1, 3)*x", lcs.x / 3),
    ("E", sp.E),
])
def test_accepts_formulas(text, expected):
    assert sp.simplify(parse_expr(text) - expected) == 0


def test_gamma_is_symbol_or_function():
    e = parse_expr("gamma*gamma(n/2)")
    assert e == lcs.gamma * sp.gamma(lcs.n / 2)
    assert lcs.gamma in e.free_symbols


def test_standard_symbols_keep_their_assumptions():
    e = parse_expr("x + a + E_star + theta")
    assert e.free_symbols == {lcs.x, lcs.a, lcs.E_star, lcs.theta}
    assert all(s.is_positive for s in e.free_symbols)


def test_piecewise_integral_derivative():
    pw = parse_expr("Piecewise((0, x < b), ((x**2 - b**2)/(2*R), True))")
    assert isinstance(pw, sp.Piecewise)
    integral = parse_expr("Integral(t**(n-2)/sqrt(a**2 - t**2), (t, 0, a))")
    assert isinstance(integral, sp.Integral) and integral.limits[0][0] == t
    f = sp.Function("f")
    d = parse_expr("Derivative(f(t)/t, t)", placeholders={"f": f})
    assert d.has(sp.Derivative) and d.has(f(t))


def test_declared_symbols_and_definitions():
    k = parse_expr("k*x**2", symbols=["k"])
    (ks,) = k.free_symbols - {lcs.x}
    assert ks.name == "k" and ks.is_positive
    Z = parse_expr("n + 1")
    assert parse_expr("c*Z_n", definitions={"Z_n": Z}) == lcs.c * (lcs.n + 1)


def test_relations_only_where_allowed():
    assert parse_expr("a < R", allow_relational=True) == sp.Lt(lcs.a, lcs.R)
    with pytest.raises(ClaimError, match="relation"):
        parse_expr("a < R")
    with pytest.raises(ClaimError, match="expected a relation"):
        parse_expr("a + R", allow_relational=True)


@pytest.mark.parametrize("text, problem", [
    ("__import__('os').system('echo hi')", "attribute"),
    ("__import__('os')", "dunder"),
    ("x.func", "attribute"),
    ("(1).__class__", "attribute"),
    ("lambda: 1", "lambda"),
    ("open('/etc/passwd')", "open"),
    ("eval('1')", "eval"),
    ("exec('1')", "not allowed"),
    ("getattr(x, 'func')", "getattr"),
    ("x[0]", "subscripts"),
    ("[x for x in ()]", "comprehensions"),
    ("'abc'", "strings"),
    ("sqrt(x, evaluate=False)", "keyword"),
    ("x if a else b", "Piecewise"),
    ("x and a", "&"),
    ("9**9**9", "too large"),
    ("10**100000", "too large"),
    ("k*x", "unknown name 'k'"),
    ("K(a/R)", "elliptic_k"),
    ("E(a/R)", "elliptic_e"),
    ("Symbol('x')", "Symbol"),
    ("sympify('x')", "sympify"),
    ("x ===", "not a valid formula"),
    ("", "empty"),
    ("(" * 300 + "x" + ")" * 300, "nested"),
    ("1/0", "undefined"),
    ("(1, 2)", "tuple"),
    ("_x + 1", "private"),
])
def test_refuses_unsafe_or_malformed(text, problem):
    with pytest.raises(ClaimError) as info:
        parse_expr(text, where="my.toml: claim 'Eq. (1)': formula")
    msg = str(info.value)
    assert problem.lower() in msg.lower()
    assert "my.toml: claim 'Eq. (1)': formula" in msg


def test_refusal_runs_no_code(tmp_path, monkeypatch):
    marker = tmp_path / "pwned"
    monkeypatch.chdir(tmp_path)
    for text in (f"__import__('pathlib').Path('{marker}').touch()",
                 f"open('{marker}', 'w')",
                 "().__class__.__bases__[0].__subclasses__()"):
        with pytest.raises(ClaimError):
            parse_expr(text)
    assert not marker.exists()


def test_non_string_input():
    assert parse_expr(2) == 2
    with pytest.raises(ClaimError, match="expected a formula string"):
        parse_expr(["x"])


def test_numbers_and_assignments():
    assert parse_number("0.1") == sp.Rational(1, 10)
    assert parse_number("pi/4") == sp.pi / 4
    assert parse_number_list("0.1, 0.2") == [sp.Rational(1, 10), sp.Rational(1, 5)]
    assert parse_number_list("0:1:3") == [0, sp.Rational(1, 2), 1]
    vals = parse_assignments(["R=1", "E_star=2.5"])
    assert vals == {lcs.R: 1, lcs.E_star: sp.Rational(5, 2)}
    with pytest.raises(ClaimError, match="NAME=VALUE"):
        parse_assignments(["R"])
    with pytest.raises(ClaimError, match="expected a number"):
        parse_number("x + 1")


@pytest.mark.parametrize("text,what", [
    ("gamma(10**7)", "gamma"), ("gamma(10**30)", "gamma"), ("binomial(10**12, 10**6)", "binomial"),
    ("sqrt(4)**(10**10)", "exponent"), ("x**(10**10)", "exponent"),
    ("Derivative(sin(x), (x, 10**9))", "derivative order"),
    ("sin(" * 150 + "x" + ")" * 150, "nested"), ("-" * 200 + "x", "nested"),
    ("2**(2**(2**10))", "too large"),
])
def test_parser_bounds_sizes_before_building(text, what):
    t0 = time.perf_counter()
    with pytest.raises(ClaimError, match=what):
        lcs.parse_expr(text)
    assert time.perf_counter() - t0 < 2.0


def test_long_flat_sums_are_not_nesting():
    assert lcs.parse_expr("x" + "+x" * 390) == 391 * lcs.x
    assert lcs.parse_expr("x^2/(2*R)") == lcs.x**2 / (2 * lcs.R)
    assert lcs.parse_expr("0.1*x") == lcs.x / 10


@pytest.mark.parametrize("text", ["gamma(gamma(20))", "binomial(gamma(30), 3)", "Derivative(sin(x), x, 10**9)"])
def test_parser_bounds_nested_and_bare_orders(text):
    from linecontact_sym.parsing import parse_expr
    with pytest.raises(lcs.ClaimError, match="astronomically|derivative order"):
        parse_expr(text)


def test_parser_values_and_lists():
    from linecontact_sym.parsing import parse_expr, parse_number_list, to_sympy
    assert parse_expr("Derivative(sin(x), x, 2)") == sp.Derivative(sp.sin(lcs.x), (lcs.x, 2))
    with pytest.raises(lcs.ClaimError, match="finite"):
        to_sympy(float("nan"))
    with pytest.raises(lcs.ClaimError, match="not an integer"):
        parse_number_list("1:2:abc")
    with pytest.raises(lcs.ClaimError, match="no value"):
        parse_number_list("")
    assert parse_number_list("0.1:0.3:3") == [sp.Rational(1, 10), sp.Rational(1, 5), sp.Rational(3, 10)]
