"""No code from strings, checked on the package's source (no import is
executed): sympify only with strict=True, no eval, exec, compile or
__import__ but core/codegen.py's compile of a checked tree, SymPy's string
evaluators only in core/conversion.py.  Moved from tests/test_hardening.py
(issue 10)."""
import ast
from pathlib import Path

import linecontact_sym as lcs

PKG = Path(lcs.__file__).parent


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


def test_the_scan_finds_a_planted_eval(tmp_path):
    code = "import sympy as sp\nx = sp.S('1+1')\ny = sp.sympify(s)\n"
    names = [name for _, name in _calls(ast.parse(code))]
    assert "S" in names and "sympify" in names
