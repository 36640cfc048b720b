"""Numbers and lists of numbers typed by people (``--at a=0.1:0.5:5``,
``--set R=1``, ``--set E_star=210GPa``, claims files): :func:`parse_number`
is the one reader, in this order, the same with and without pint:

1. a plain number (:func:`~linecontact_sym.core.conversion.plain_number`:
   any float notation, ``2.1e11``, ``2.1E11``, ``1e300``, or a fraction
   ``1/3``), exact;
2. a SymPy expression of numbers through the whitelisted :func:`.parse_expr`
   (``pi/4``, ``sqrt(2)*1e-3``);
3. only where the text is neither: a number with a unit (``210GPa``,
   ``5 mm``), converted to the SI unit declared for the value (the
   ``[units]`` extra, pint; :func:`~linecontact_sym.core.units.si_magnitude`).

So ``2.1e11`` is never read as 2.1 of a unit ``e11``, and an optional
package never changes what a number means.
"""
from __future__ import annotations

import re

import sympy as sp

from ..core.conversion import exact_number, plain_number
from ..core.errors import ClaimError, LineContactError
from .expressions import SYMBOLS, where_prefix, declare_symbols, parse_expr

#: a number followed by a unit (``210GPa``, ``5 mm``, ``1.5e-3 N/m``): read
#: only where the text is neither a plain number nor an expression
_WITH_UNIT = re.compile(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*"
                        r"([A-Za-z\u00b5\u03bc][A-Za-z0-9_*/^ .\u00b5\u03bc]*)\s*")

#: ``units=`` of a context that takes SI numbers only (claims files)
NO_UNITS = None


def parse_assignments(items, *, where: str = "", symbols=None, units=NO_UNITS) -> dict:
    """``["R=1", "E_star=2.5"]`` or ``"R=1,E_star=2"`` -> {Symbol: exact value}.

    Values are read by :func:`parse_number` (so ``pi/4`` and ``2.1e11``
    work); ``units`` (a dict name -> SI unit, e.g.
    :data:`linecontact_sym.core.symbols.UNITS`) lets a value carry a unit
    (``E_star=210GPa``), converted to that SI unit."""
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
            out[sym_table[name]] = parse_number(val, where=f"{where} {name}".strip(), name=name, units=units)
    return out


def split_unit(text):
    """``(number text, unit text)`` when ``text`` is a number with a unit
    (neither a plain number nor an expression of numbers: ``"210GPa"`` ->
    ``("210", "GPa")``), else None; the decision :func:`parse_number` takes."""
    text = str(text).strip()
    if plain_number(text) is not None:
        return None
    m = _WITH_UNIT.fullmatch(text)
    if m is None:
        return None
    try:
        parse_expr(text)
        return None
    except LineContactError:
        return m.group(1), m.group(2).strip()


def parse_number(text, where: str = "", name: str | None = None, units=NO_UNITS) -> sp.Expr:
    """A numeric value typed as text (see the module docstring for the
    order): exact where the text is a decimal ('0.1' -> 1/10, '2.1e11' ->
    210000000000).  ``units`` (name -> SI unit) and ``name``: a number with
    a unit is converted to ``units[name]``; without ``units`` (a context of
    SI numbers) or for a name without a declared unit it is refused,
    saying so.  Raises :class:`~linecontact_sym.core.errors.ClaimError`
    (:class:`~linecontact_sym.core.errors.DomainError` for a wrong unit)."""
    text = str(text).strip()
    value = plain_number(text)
    if value is not None:
        return value
    try:
        return _numeric(parse_expr(text, where=where), text, where)
    except ClaimError:
        pair = split_unit(text)
        if pair is None:
            raise
    number, unit_text = pair
    if re.fullmatch(r"[eE][-+]?\d*", unit_text):
        raise ClaimError(f"{where_prefix(where)}{text!r} is not a number (an exponent without digits?)") from None
    label = name or where or "the value"
    if units is NO_UNITS:
        raise ClaimError(f"{where_prefix(where)}{text!r} is a number with a unit; this place takes plain SI "
                         f"numbers") from None
    unit = units.get(name) if name is not None else None
    if unit is None:
        raise ClaimError(f"{where_prefix(where)}{label}={text}: {label} has no declared unit; give it in SI as "
                         f"a plain number") from None
    from ..core.units import si_magnitude
    return exact_number(si_magnitude(number, unit_text, unit, label))


def parse_number_list(text, where: str = "", name: str | None = None, units=NO_UNITS) -> list:
    """``"0.1,0.2,pi/4"`` -> [1/10, 1/5, pi/4]; ``"0.1:0.5:5"`` -> 5 points from 0.1 to 0.5;
    each value by :func:`parse_number` (``units``, ``name``: as there)."""
    text = str(text).strip()
    if text.count(":") == 2 and "," not in text:
        lo, hi, k = text.split(":")
        lo, hi = (parse_number(v, where, name, units) for v in (lo, hi))
        try:
            k = int(k)
        except ValueError:
            raise ClaimError(f"{where_prefix(where)}number of points {k!r} is not an integer (lo:hi:count)") from None
        if k < 1 or k > 10000:
            raise ClaimError(f"{where_prefix(where)}number of points {k} out of range 1..10000")
        if k == 1:
            return [lo]
        return [lo + (hi - lo) * sp.Rational(i, k - 1) for i in range(k)]
    out = [parse_number(p, where, name, units) for p in _split_top(text) if p.strip()]
    if not out:
        raise ClaimError(f"{where_prefix(where)}no value given (a list such as 0.1,0.2 or lo:hi:count)")
    return out


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


__all__ = ["parse_assignments", "parse_number", "parse_number_list", "split_unit", "NO_UNITS"]
