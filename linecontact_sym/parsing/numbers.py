"""Numbers and lists of numbers typed by people (``--at a=0.1:0.5:5``,
``--set R=1``, claims files): through the whitelisted :func:`.parse_expr`,
decimals exact."""
from __future__ import annotations

import sympy as sp

from ..core.errors import ClaimError
from .expressions import MAX_DIGITS, SYMBOLS, where_prefix, declare_symbols, parse_expr


def parse_assignments(items, *, where: str = "", symbols=None) -> dict:
    """``["R=1", "E_star=2.5"]`` or ``"R=1,E_star=2"`` -> {Symbol: exact value}.

    Values are parsed with :func:`parse_expr` (so ``pi/4`` works) and must be
    numbers; floats become exact rationals of their decimal text."""
    if isinstance(items, str):
        items = [items]
    out = {}
    sym_table = dict(SYMBOLS)
    sym_table.update(declare_symbols(symbols, where) if not isinstance(symbols, dict) else symbols)
    for item in items or ():
        for part in _split_top(item):
            if "=" not in part:
                raise ClaimError(f"{where_prefix(where)}expected NAME=VALUE, got {part!r}")
            name, val = (p.strip() for p in part.split("=", 1))
            if name not in sym_table:
                if not name.isidentifier() or name.startswith("_"):
                    raise ClaimError(f"{where_prefix(where)}{name!r} is not a symbol name")
                sym_table[name] = sp.Symbol(name, positive=True)
            out[sym_table[name]] = parse_number(val, where=f"{where} {name}".strip())
    return out


def parse_number(text, where: str = "") -> sp.Expr:
    """A numeric value (exact where the text is a decimal: '0.1' -> 1/10)."""
    text = str(text).strip()
    try:
        return sp.Rational(text) if _is_decimal(text) else _numeric(parse_expr(text, where=where), text, where)
    except (TypeError, ValueError):
        return _numeric(parse_expr(text, where=where), text, where)


def parse_number_list(text, where: str = "") -> list:
    """``"0.1,0.2,pi/4"`` -> [1/10, 1/5, pi/4]; ``"0.1:0.5:5"`` -> 5 points from 0.1 to 0.5."""
    text = str(text).strip()
    if text.count(":") == 2 and "," not in text:
        lo, hi, k = text.split(":")
        lo, hi = parse_number(lo, where), parse_number(hi, where)
        try:
            k = int(k)
        except ValueError:
            raise ClaimError(f"{where_prefix(where)}number of points {k!r} is not an integer (lo:hi:count)") from None
        if k < 1 or k > 10000:
            raise ClaimError(f"{where_prefix(where)}number of points {k} out of range 1..10000")
        if k == 1:
            return [lo]
        return [lo + (hi - lo) * sp.Rational(i, k - 1) for i in range(k)]
    out = [parse_number(p, where) for p in _split_top(text) if p.strip()]
    if not out:
        raise ClaimError(f"{where_prefix(where)}no value given (a list such as 0.1,0.2 or lo:hi:count)")
    return out


def _is_decimal(text):
    try:
        float(text)
        return len(text) <= MAX_DIGITS
    except ValueError:
        return False


def _numeric(expr, text, where):
    if expr.free_symbols:
        raise ClaimError(f"{where_prefix(where)}expected a number, got {text!r}")
    if expr.has(sp.oo, -sp.oo, sp.zoo, sp.nan) or expr.is_real is False:
        raise ClaimError(f"{where_prefix(where)}expected a finite real number, got {text!r}")
    return expr


def _split_top(text):
    """Split at commas that are not inside parentheses."""
    parts, depth, cur = [], 0, []
    for ch in text:
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
        if ch == "," and depth == 0:
            parts.append("".join(cur).strip())
            cur = []
        else:
            cur.append(ch)
    if "".join(cur).strip():
        parts.append("".join(cur).strip())
    return [p for p in parts if p]


__all__ = ["parse_assignments", "parse_number", "parse_number_list"]
