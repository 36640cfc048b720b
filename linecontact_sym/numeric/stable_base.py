"""The base of the stable rewrites: the :class:`StableRule` class and the
symbolic helpers the rules share (complements formed exactly, factored
square roots ...).  The rules are in :mod:`.stable` and
:mod:`.stable_elliptic`; :func:`~.stable.stabilize` applies them."""
from __future__ import annotations

import sympy as sp

# ====================================================================== helpers
def is_rational_in_symbols(e) -> bool:
    """True if ``e`` is a rational function of its (at least one) free symbols,
    with no function application in it (such sums are formed exactly by
    :class:`FactorDifferences`, or their error is covered by the condition number)."""
    return bool(e.free_symbols) and not e.has(sp.Function) and e.is_rational_function(*e.free_symbols)


def fix_signs(e):
    """-(x - a)*(x + a) -> (a - x)*(a + x): absorb a leading -1 into the linear
    factor that has a negative term (so differences read 'large - small')."""
    num, den = sp.fraction(e)
    if num.is_Mul and num.args[0] == -1:
        rest = list(num.args[1:])
        adds = [i for i, f in enumerate(rest) if f.is_Add]
        if adds:
            neg = [i for i in adds if any(t.could_extract_minus_sign() for t in rest[i].args)]
            i = (neg or adds)[0]
            rest[i] = sp.Add(*[-t for t in rest[i].args])
            num = sp.Mul(*rest)
    return num / den


def complement_of(z):
    """1 - z simplified symbolically and factored (1 - a**2/R**2 ->
    (R - a)*(R + a)/R**2): small where z is close to 1, and formed exactly."""
    return fix_signs(sp.factor(sp.cancel(1 - z)))


def stable_sqrt(c):
    """sqrt(c) with the sum c cancelled and factored, or None if c is not a
    rational function of the symbols (nor a number)."""
    c = sp.cancel(sp.expand(c))
    if not is_rational_in_symbols(c) and not c.is_number:
        return None
    return sp.sqrt(fix_signs(sp.factor(c)))


def n_terms(e):
    return sum(len(n.args) for n in sp.preorder_traversal(e) if n.is_Add)


def expand_around(expr, keys):
    """expand_mul only the sums on the paths to ``keys``: every other sum,
    function application and fractional power is masked first, so factored
    forms elsewhere ((a - x)*(a + x), sqrt(a - x) ...) are kept."""
    masks = {}

    def mask(e):
        if e.has(*keys):
            if e.args and not e.is_Atom:
                e = e.func(*[mask(t) for t in e.args])
            return e
        if e.is_Atom or e.is_Number:
            return e
        if e.is_Add or isinstance(e, (sp.Function, sp.Piecewise)) or (e.is_Pow and not e.exp.is_Integer):
            d = sp.Dummy("m")
            masks[d] = e
            return d
        return e.func(*[mask(t) for t in e.args])
    return sp.expand_mul(mask(expr)).xreplace(masks)


def nonneg(e):
    """Positive, or a square root (times positive factors): >= 0 wherever real."""
    if e.is_positive:
        return True
    if e.is_Pow and e.exp == sp.S.Half:
        return True
    return bool(e.is_Mul and all(nonneg(f) for f in e.args))


def has_sqrt(e):
    return any(p.is_Pow and p.exp == sp.S.Half for p in sp.preorder_traversal(e))


def is_2f1(e):
    return isinstance(e, sp.hyper) and len(e.ap) == 2 and len(e.bq) == 1 and bool(e.argument.free_symbols)


# ====================================================================== rules
class StableRule:
    """A stable rewrite: an identity, applied wherever its pattern occurs.

    ``name`` names the rule in a :class:`StableForm`'s record; ``heads`` are
    SymPy classes one of which must occur for the rule to have anything to do
    (the cheap test :meth:`applies`; empty: always tried); :meth:`apply`
    returns the rewritten expression (an equal one where nothing matched).
    """

    name: str = ""
    heads: tuple = ()

    def applies(self, expr) -> bool:
        """Cheap test: may the pattern occur in ``expr``?"""
        return not self.heads or expr.has(*self.heads)

    def apply(self, expr):
        raise NotImplementedError

    def __call__(self, expr):
        return self.apply(expr)

    def __repr__(self):
        return f"{type(self).__name__}()"
