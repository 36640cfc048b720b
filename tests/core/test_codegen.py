"""core/codegen.py compiles only the package's own generated functions: one
function of the allowed nodes, names and attributes, given as a tree.
Moved from tests/test_hardening.py (issue 10)."""
import ast

import pytest

from linecontact_sym.core.errors import LineContactError


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
