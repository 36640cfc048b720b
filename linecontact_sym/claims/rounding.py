"""Figures printed to a few digits (``rounding = "printed"`` in a claims
file): the interval a printed decimal constant stands for, and TOML floats
that keep the digits they were printed with."""
from __future__ import annotations

import re
from decimal import Decimal

DECIMAL = re.compile(r"(?<![\w.])(\d+)\.(\d+)([eE][+-]?\d+)?(?![\w.])")
#: at most this many printed constants are varied corner by corner (2**6 = 64
#: evaluations, exact for a formula monotone in each); more are varied one at
#: a time (see :func:`printed_variants`)
MAX_CORNERS = 6


def printed_variants(text: str) -> list:
    """The formula text with its decimal constants moved by half a unit in
    their last printed digit: the interval a figure printed with those digits
    stands for.  Every constant is varied.  Up to :data:`MAX_CORNERS`
    constants: every combination (the corners of the box, exact for a formula
    monotone in each constant); more: the formula as printed followed by each
    constant moved alone to each end (2k + 1 texts; :func:`printed_spread`
    says which, and the checker adds the deviations: exact for a formula
    affine in its constants, first order otherwise).  The digits are the
    printed ones: ``0.300`` has three, ``-0.08090`` five significant digits
    (read from the raw text of a TOML float, see :func:`load_paper`), and
    ``8.090e-2`` four.

    >>> printed_variants("0.300*p0")
    ['0.2995*p0', '0.3005*p0']
    >>> printed_variants("-0.08090*x")
    ['-0.080895*x', '-0.080905*x']
    """
    found = list(DECIMAL.finditer(text))

    def moved(m, sign):
        frac = len(m.group(2))
        val = Decimal(f"{m.group(1)}.{m.group(2)}") + sign * Decimal(5).scaleb(-(frac + 1))
        return f"{val:f}" + (m.group(3) or "")

    def build(choice):
        pieces, last = [], 0
        for m, sign in zip(found, choice):
            pieces.append(text[last:m.start()])
            pieces.append(m.group(0) if sign == 0 else moved(m, sign))
            last = m.end()
        return "".join(pieces) + text[last:]
    if len(found) <= MAX_CORNERS:
        return [build([1 if signs >> k & 1 else -1 for k in range(len(found))]) for signs in range(2 ** len(found))]
    out = [build([0] * len(found))]
    for k in range(len(found)):
        for sign in (-1, 1):
            out.append(build([sign if j == k else 0 for j in range(len(found))]))
    return out


def printed_spread(text: str) -> str:
    """How :func:`printed_variants` varied the constants of ``text``:
    ``"corners"`` (the variants' range is the interval) or ``"sum"`` (the
    first variant is the formula as printed; the interval adds each
    constant's largest deviation)."""
    return "corners" if len(DECIMAL.findall(text)) <= MAX_CORNERS else "sum"


class PrintedFloat(float):
    """A TOML float that remembers how it was printed: ``str()`` is its raw
    text (``-0.08090``, not Python's ``-0.0809``), so a formula given as a
    bare number keeps its printed digits; everywhere else it is the float."""

    text: str = ""

    @classmethod
    def from_toml(cls, text: str) -> "PrintedFloat":
        v = cls(text.replace("_", ""))
        v.text = text.replace("_", "")
        return v

    def __str__(self):
        return self.text or float.__repr__(self)


__all__ = ["DECIMAL", "MAX_CORNERS", "printed_variants", "printed_spread", "PrintedFloat"]
