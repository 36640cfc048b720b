"""Issue 10: every input a clear package error, bounded work, no code from
strings.  Each case is one of the adversarial inputs that once hung, ran code
or raised a foreign exception."""
import ast
import re
import time
from pathlib import Path

import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core.errors import ClaimError, LineContactError

PKG = Path(lcs.__file__).parent

#: builtins that run text as code (called by their bare name), and SymPy
#: functions that evaluate strings (called either way)
_BUILTINS = {"eval", "exec", "compile", "__import__"}
_DANGEROUS = {"S", "nsimplify", "parse_expr"}


def _calls(tree):
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            f = node.func
            name = f.attr if isinstance(f, ast.Attribute) else f.id if isinstance(f, ast.Name) else None
            yield node, name


def test_no_string_can_reach_eval():
    """sympify only with strict=True; nsimplify, S(...) and SymPy's own
    parse_expr only in core/conversion.py (which refuses strings); eval and
    __import__ nowhere, exec/compile only in core/codegen.py (checked ASTs)."""
    bad = []
    for path in PKG.rglob("*.py"):
        rel = path.relative_to(PKG).as_posix()
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node, name in _calls(tree):
            if name == "sympify":
                strict = [k for k in node.keywords if k.arg == "strict"]
                if not strict or not (isinstance(strict[0].value, ast.Constant) and strict[0].value.value is True):
                    bad.append(f"{rel}:{node.lineno} sympify without strict=True")
            elif name in _BUILTINS and isinstance(node.func, ast.Name):
                # core/codegen.py compiles the package's own generated functions: an AST whose every
                # node it checks first (test_generated_code_is_checked), never text
                if not (rel == "core/codegen.py" and name in ("exec", "compile")):
                    bad.append(f"{rel}:{node.lineno} {name}(...)")
            elif name in _DANGEROUS and rel != "core/conversion.py":
                is_own_parser = name == "parse_expr" and isinstance(node.func, ast.Name)
                if not is_own_parser:
                    bad.append(f"{rel}:{node.lineno} {name}(...)")
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and node.module and "sympy_parser" in node.module:
                bad.append(f"{rel}:{node.lineno} imports sympy_parser")
    assert not bad, "\n".join(bad)


def test_generated_code_is_checked():
    """core.codegen compiles only one function made of the allowed nodes,
    names and attributes: an import, an unknown or dunder name, another
    attribute, a lambda, two functions, text instead of a tree are refused
    (a package error, nothing run); an allowed tree runs."""
    from linecontact_sym.core.codegen import compile_function

    ok = "def g(x):\n    if x.__class__ is not float:\n        return None\n    return abs(h(x))\n"
    assert compile_function(ast.parse(ok), {"h": lambda v: -2 * v}, "g")(1.5) == 3.0
    planted = []
    bad = ["def g(x):\n    import os\n    return x\n", "def g(x):\n    return open(x)\n",
           "def g(x):\n    return __import__('os')\n", "def g(x):\n    return x.__globals__\n",
           "def g(x):\n    return (lambda: x)()\n", "def g(x):\n    return x\ndef k(x):\n    return x\n",
           "def g(x):\n    return [y for y in x]\n", "def g(x):\n    return h.__builtins__\n",
           "def g(x):\n    return eval(x)\n", "def k(x):\n    return x\n"]
    for text in bad:
        with pytest.raises(LineContactError, match="generated code"):
            compile_function(ast.parse(text), {"h": planted.append}, "g")
    with pytest.raises(LineContactError):
        compile_function(ok, {"h": planted.append}, "g")
    with pytest.raises(LineContactError, match="rebinds"):
        compile_function(ast.parse(ok), {"h": planted.append, "abs": planted.append}, "g")
    assert planted == []


def test_the_scan_finds_a_planted_eval(tmp_path):
    code = "import sympy as sp\nx = sp.S('1+1')\ny = sp.sympify(s)\n"
    names = [name for _, name in _calls(ast.parse(code))]
    assert "S" in names and "sympify" in names


def test_report_rows_refuse_code_strings():
    from linecontact_sym.claims.report import power_law_rows
    with pytest.raises(LineContactError):
        power_law_rows(["__import__('os').system('id') or 2"])


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


# ---------------------------------------------------------------- physical domains
@pytest.fixture(scope="module")
def contacts():
    return {"parabola": lcs.parabola(), "power": lcs.power_law(), "cylinder": lcs.exact_cylinder()}


@pytest.mark.parametrize("which,quantity,values,match", [
    ("parabola", "force", dict(a=1, R=1, E_star=-1), "E\\* must be positive"),
    ("parabola", "force", dict(a=1, R=-1, E_star=1), "R must be positive"),
    ("power", "force", dict(a=1, n=-1, c=1, E_star=1), "n must be positive"),
    ("power", "force", dict(a=1, n=0, c=1, E_star=1), "n must be positive"),
    ("power", "force", dict(a=1, n=2, c=-1, E_star=1), "c must be positive"),
    ("parabola", "force", dict(a=0, R=1, E_star=1), "half-width a must be positive"),
    ("cylinder", "force", dict(a=2, R=1, E_star=1), "a < R"),
    ("parabola", "force", dict(a=1, R=1, E_star=1, Q=3), "'Q'"),
    ("parabola", "force", dict(a=float("nan"), R=1, E_star=1), "finite real"),
    ("parabola", "force", dict(a=float("inf"), R=1, E_star=1), "finite real"),
    ("parabola", "force", dict(a=1j, R=1, E_star=1), "finite real"),
    ("parabola", "force", dict(a=None, R=1, E_star=1), "not a number"),
    ("parabola", "pressure", dict(a=1, x=2, R=1, E_star=1), "outside the contact"),
    ("parabola", "gap", dict(a=1, x=0.5, R=1, E_star=1), "inside the contact"),
    ("parabola", "force", dict(a=[0.5, -1.0], R=1.0, E_star=1.0), "must be positive"),
])
def test_values_outside_the_domain_are_refused(contacts, which, quantity, values, match):
    c = contacts[which]
    for call in (c.evaluate_at, c.evaluate):
        if call is c.evaluate_at and isinstance(values.get("a"), list):
            continue
        with pytest.raises(lcs.DomainError, match=match):
            call(quantity, **values)


def test_values_inside_the_domain_still_evaluate(contacts):
    c = contacts["cylinder"]
    assert abs(float(c.evaluate_at("force", a=sp_half(), R=1, E_star=1)) - 0.218288145473169) < 1e-14
    assert abs(float(contacts["parabola"].evaluate("force", a=1.0, R=1.0, E_star=1.0).value) - 0.7853981633974483) < 1e-15


def sp_half():
    import sympy as sp
    return sp.Rational(1, 2)


# ---------------------------------------------------------------- claims files
def _paper(tmp_path, body):
    p = tmp_path / "c.toml"
    p.write_text(body, encoding="utf-8")
    return p


BASE = 'label = "L"\nquantity = "force"\nprofile = "x**2/(2*R)"\nformula = "pi*E_star*a**2/(4*R)"\n'


@pytest.mark.parametrize("extra,match", [
    ('symbols = "k"\n', "symbols must be a list"),
    ("points = true\n", "points must be"),
    ("assumptions = \"a < R\"\n", "assumptions must be a list"),
    ("ranges = [1, 2]\n", "ranges must be a table"),
    ("note = 3\n", "note must be a string"),
])
def test_claims_fields_of_the_wrong_type(tmp_path, extra, match):
    from linecontact_sym.claims import load_paper
    with pytest.raises(ClaimError, match=match):
        load_paper(_paper(tmp_path, "[[claims]]\n" + BASE + extra))


def test_claims_file_that_is_not_a_text_file(tmp_path):
    from linecontact_sym.claims import load_paper
    bad = tmp_path / "bin.toml"
    bad.write_bytes(b"\xff\xfe\x00[claims]")
    with pytest.raises(ClaimError, match="UTF-8"):
        load_paper(bad)
    with pytest.raises(ClaimError, match="regular file"):
        load_paper(tmp_path)
    t0 = time.perf_counter()
    with pytest.raises(ClaimError, match="regular file"):
        load_paper("/dev/zero")
    big = tmp_path / "big.toml"
    big.write_bytes(b"#" * 2_000_000)
    with pytest.raises(ClaimError, match="larger than"):
        load_paper(big)
    assert time.perf_counter() - t0 < 2


# ---------------------------------------------------------------- command line
@pytest.mark.parametrize("argv,match", [
    (["eval", "x**2/(2*R)", "force", "--at", "a=1", "--set", "R=1", "E_star=1", "--dps", "0"], "digits must be"),
    (["eval", "x**2/(2*R)", "force", "--at", "a=oo", "--set", "R=1", "E_star=1"], "finite real"),
    (["eval", "x**2/(2*R)", "force", "--at", "a=1", "--set", "R=1", "E_star=1", "Q=3"], "'Q'"),
    (["derive", "x**2/(2*R)", "--set", "Q=3", "--quantities", "force"], "no such parameter"),
    (["eval", "x**2/(2*R)", "force", "--at", "a=1", "--set", "R=-1", "E_star=1"], "R must be positive"),
])
def test_cli_refuses_bad_values(capsys, argv, match):
    from linecontact_sym import cli
    try:
        code = cli.main(argv)
    except SystemExit as exc:   # argparse type errors
        code = exc.code
    out, err = capsys.readouterr()
    assert code != 0 and re.search(match, out + err), (code, out, err)


# ---------------------------------------------------------------- profiles
@pytest.mark.parametrize("make,err,match", [
    (lambda: lcs.x**2 / (2 * lcs.R) * 0 + lcs.x / 0, lcs.ProfileError, "undefined"),
    (lambda: lcs.x**2 / __import__("sympy").Symbol("R", negative=True), lcs.ProfileError, "non-positive"),
    (lambda: lcs.x**(10**10), lcs.ProfileError, "exponent"),
    (lambda: __import__("sympy").Derivative(__import__("sympy").sin(lcs.x), (lcs.x, 10**9)), lcs.ProfileError,
     "derivative of order"),
    (lambda: __import__("sympy").I * lcs.x**2, lcs.ProfileError, "not real"),
])
def test_profiles_refused_with_a_reason(make, err, match):
    t0 = time.perf_counter()
    with pytest.raises(err, match=match):
        lcs.LineContact(make())
    assert time.perf_counter() - t0 < 2


def test_the_profile_x_is_a_profile():
    assert lcs.LineContact(lcs.x).force == lcs.E_star * lcs.a


# ------------------------------------------------- second adversarial run (benchmarks/adversarial.py)
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


@pytest.mark.parametrize("argv, words", [
    (["eval", "x**2/(2*R)", "pressure", "--at", "a=0.1:1:10000", "x=0.1:1:10000"], "points"),
    (["eval", "x**2/(2*R)", "force", "--at", "a=", "--set", "R=1", "E_star=1"], "no value"),
    (["eval", "x**2/(2*R)", "force", "--at", "a=1:2:abc"], "not an integer"),
    (["derive", "x**2/(2*R)", "--quantities", ""], "names no quantity"),
    (["check", "--profile", "x**2/(2*R)", "--force", "pi*E_star*a**2/(4*R)", "--range", "R=-1:1"], "positive"),
])
def test_cli_refusals_exit_2(argv, words, capsys):
    from linecontact_sym.cli import main
    assert main(argv) == 2
    assert words in capsys.readouterr().err


def test_claims_file_refusals(tmp_path):
    from linecontact_sym.claims import load_paper
    p = tmp_path / "neg.toml"
    p.write_text('[[claims]]\nlabel = "x"\nquantity = "force"\nprofile = "x**2/(2*R)"\n'
                 'formula = "pi*E_star*a**2/(4*R)"\nspecial = { R = ["-1"] }\n')
    with pytest.raises(lcs.ClaimError, match="positive"):
        load_paper(str(p))
    deep = tmp_path / "deep.toml"
    deep.write_text("a = " + "[" * 3000 + "]" * 3000 + "\n")
    with pytest.raises(lcs.ClaimError, match="TOML"):
        load_paper(str(deep))


@pytest.mark.parametrize("make, match", [
    (lambda: lcs.LineContact(sp.floor(lcs.x)), "floor"),
    (lambda: lcs.LineContact(sp.Piecewise((lcs.x**2, lcs.x > 1))), "no value"),
    (lambda: lcs.parabola(R="1/0"), "undefined"),
    (lambda: lcs.parabola(R=-1), "positive"),
    (lambda: lcs.LineContact(lcs.x**2, params=5), "params"),
])
def test_profile_refusals(make, match):
    with pytest.raises(lcs.LineContactError, match=match):
        make()


def test_singular_points_and_negative_loads_are_domain_errors():
    w = lcs.wedge()
    with pytest.raises(lcs.DomainError, match="not finite|singular"):
        w.evaluate("pressure", x=0, a=1.0, theta=0.3, E_star=1.0)
    with pytest.raises(lcs.DomainError, match="not finite|singular"):
        w.to_numeric("pressure", backend="mpmath")(x=0, a=1.0, theta=0.3, E_star=1.0)
    with pytest.raises(lcs.DomainError, match="P >= 0"):
        lcs.parabola().evaluate("half_width", P=-1, R=1.0, E_star=1.0)
    with pytest.raises(lcs.DomainError, match="keyword arguments only"):
        lcs.parabola().to_numeric("force")(0.5, 1.0, 1.0)
