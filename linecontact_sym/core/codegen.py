"""The one place where the package compiles Python code of its own.

SymPy's ``lambdify`` compiles the code its printers write for an expression;
:func:`~linecontact_sym.numeric.fastpath.inline_point` places that code (the
expression of a one-line ``lambdify`` function, read back from the source
SymPy keeps for :mod:`inspect`) into a function of the package, so that the
scalar path of ``evaluate`` reads a point and computes the law without a
call per step.  The function comes here as an :mod:`ast` tree, never as text,
and is compiled only after :func:`checked_tree` has read every node:

* only the statements and expressions such a function needs (no imports,
  ``global``, ``lambda``, comprehensions, ``with``, ``del`` ...);
* every name read is an argument, a name the function assigns, a name of the
  namespace given (the functions ``lambdify`` put there and the package's
  helpers) or one of a few builtins (``float``, ``abs``, ``len``, ``KeyError``);
* attributes only ``__class__``, ``__dict__`` and ``get``; no name with
  two leading underscores.

User text never becomes code here: the keys of a point enter as string
constants, the symbols of a law are ``lambdify``'s renamed Dummies
(:func:`~linecontact_sym.core.printing.lambdify`).  A tree that breaks a rule
raises :class:`~linecontact_sym.core.errors.LineContactError` (a defect of the
package, not of an input).
"""
from __future__ import annotations

import ast
import builtins

from .errors import LineContactError

__all__ = ["compile_function", "checked_tree"]

_NODES = (ast.Module, ast.FunctionDef, ast.arguments, ast.arg, ast.Return, ast.If, ast.Try, ast.ExceptHandler,
          ast.Assign, ast.Compare, ast.BoolOp, ast.UnaryOp, ast.BinOp, ast.Call, ast.Name, ast.Constant,
          ast.Attribute, ast.Dict, ast.Tuple, ast.Load, ast.Store, ast.IfExp, ast.boolop, ast.operator,
          ast.unaryop, ast.cmpop, ast.Subscript)
_BUILTINS = frozenset({"float", "abs", "len", "KeyError"})
_ATTRIBUTES = frozenset({"__class__", "__dict__", "get"})


def checked_tree(tree: ast.Module, namespace: dict, name: str) -> ast.Module:
    """``tree`` if it is one function ``name`` made only of the nodes, names
    and attributes the module docstring lists, else LineContactError."""
    if not isinstance(tree, ast.Module) or len(tree.body) != 1 or not isinstance(tree.body[0], ast.FunctionDef) \
            or tree.body[0].name != name or tree.body[0].decorator_list:
        raise LineContactError(f"generated code: not one function {name!r}")
    fn = tree.body[0]
    bound = {a.arg for a in fn.args.args} | {n.id for n in ast.walk(fn) if isinstance(n, ast.Name)
                                              and isinstance(n.ctx, ast.Store)}
    for node in ast.walk(tree):
        if not isinstance(node, _NODES):
            raise LineContactError(f"generated code: {type(node).__name__} is not allowed")
        if isinstance(node, ast.Name):
            ok = node.id in bound or node.id in namespace or node.id in _BUILTINS
            if not ok or node.id.startswith("__"):
                raise LineContactError(f"generated code: the name {node.id!r} is not allowed")
        elif isinstance(node, ast.Attribute) and node.attr not in _ATTRIBUTES:
            raise LineContactError(f"generated code: the attribute {node.attr!r} is not allowed")
        elif isinstance(node, ast.ExceptHandler) and node.name is not None:
            raise LineContactError("generated code: a named except clause is not allowed")
    if any(n in namespace and getattr(builtins, n, None) is not namespace[n] for n in _BUILTINS):
        raise LineContactError("generated code: the namespace rebinds a builtin it may call")
    return tree


def compile_function(tree: ast.Module, namespace: dict, name: str):
    """The function ``name`` of the checked ``tree`` (:func:`checked_tree`),
    compiled with ``namespace`` as its globals (filled in place)."""
    code = compile(ast.fix_missing_locations(checked_tree(tree, namespace, name)),  # noqa: S102 -- an AST, checked
                   f"<linecontact_sym generated {name}>", "exec")
    exec(code, namespace)   # noqa: S102 -- a checked AST, see the module docstring
    return namespace[name]
