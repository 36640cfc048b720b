"""The whitelisted parser for formulas and numbers typed by people (claims
files, the command line, notebooks): :mod:`.expressions` (formulas, never
evaluated as code; see its docstring for the whitelist and the size bounds)
and :mod:`.numbers` (values and lists of values)."""
from __future__ import annotations

from .expressions import CONSTANTS, FUNCTIONS, SYMBOLS, declare_symbols, parse_expr, s, t, to_sympy, user_value
from .numbers import parse_assignments, parse_number, parse_number_list

__all__ = ["parse_expr", "parse_assignments", "parse_number", "parse_number_list",
           "declare_symbols", "to_sympy", "user_value", "SYMBOLS", "FUNCTIONS", "CONSTANTS", "t", "s"]
