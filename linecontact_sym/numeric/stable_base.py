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
    rational function of the symbols (nor a number) and no difference of
    squared sines, cosines or hyperbolic functions (:func:`square_differences`)
    makes it a product."""
    c = sp.cancel(sp.expand(c))
    if not is_rational_in_symbols(c) and not c.is_number:
        num, den = sp.fraction(c)
        num2 = square_differences(num)
        if num2 == num or any(e.is_Add and _has_square_pair(e) for e in sp.preorder_traversal(num2)):
            return None
        return sp.sqrt(num2 / den)
    return sp.sqrt(fix_signs(sp.factor(c)))


#: F(u)**2 - G(v)**2 as a product of two factors in u - v and u + v (no
#: cancellation where u -> v): (F, G) -> (sign, f of u - v, g of u + v)
_SQUARE_PAIRS = {
    (sp.sin, sp.sin): (1, sp.sin, sp.sin),          # sin^2 u - sin^2 v = sin(u - v) sin(u + v)
    (sp.cos, sp.cos): (-1, sp.sin, sp.sin),         # cos^2 u - cos^2 v = -sin(u - v) sin(u + v)
    (sp.cos, sp.sin): (1, sp.cos, sp.cos),          # cos^2 u - sin^2 v = cos(u - v) cos(u + v)
    (sp.sin, sp.cos): (-1, sp.cos, sp.cos),         # sin^2 u - cos^2 v = -cos(u - v) cos(u + v)
    (sp.sinh, sp.sinh): (1, sp.sinh, sp.sinh),      # sinh^2 u - sinh^2 v = sinh(u - v) sinh(u + v)
    (sp.cosh, sp.cosh): (1, sp.sinh, sp.sinh),      # cosh^2 u - cosh^2 v = sinh(u - v) sinh(u + v)
}
#: 1 - F(v)**2 (a number c against -c F(v)**2): c G(v)**2
_ONE_MINUS = {sp.sin: (1, sp.cos), sp.cos: (1, sp.sin), sp.cosh: (-1, sp.sinh)}
_SQUARED_HEADS = (sp.sin, sp.cos, sp.sinh, sp.cosh)


def _square_term(t):
    """(c, F, u) for a term c*F(u)**2 (F sin, cos, sinh, cosh), (t, None, None)
    for a term without them, else None."""
    c, f = t.as_independent(*_SQUARED_HEADS, as_Add=False)
    if f == 1:
        return t, None, None
    if f.is_Pow and f.exp == 2 and isinstance(f.base, _SQUARED_HEADS) and f.base.args[0].free_symbols:
        return c, f.base.func, f.base.args[0]
    return None


def _pair(ti, tj):
    """ti + tj as a product where ti = c F(u)^2 and tj = -c G(v)^2 (or one of
    them the number c), else None."""
    (ci, Fi, ui), (cj, Fj, uj) = ti, tj
    if sp.expand(ci + cj) != 0 or (Fi is None and Fj is None):
        return None
    if Fi is None or Fj is None:                 # c - c F(v)^2 = c G(v)^2
        c, F, v = (ci, Fj, uj) if Fi is None else (cj, Fi, ui)
        if F not in _ONE_MINUS:
            return None
        sign, G = _ONE_MINUS[F]
        return sign * c * G(v)**2
    if (Fi, Fj) not in _SQUARE_PAIRS or ui == uj:
        return None
    sign, f, g = _SQUARE_PAIRS[(Fi, Fj)]
    return sign * ci * f(fix_signs(sp.factor(ui - uj))) * g(sp.factor(ui + uj))


def _terms(e):
    return [_square_term(t) for t in e.args]


def _has_square_pair(e):
    ts = _terms(e)
    return any(ti is not None and tj is not None and _pair(ti, tj) is not None
               for i, ti in enumerate(ts) for tj in ts[i + 1:])


def square_differences(expr):
    """Every pair c F(u)^2 - c G(v)^2 of terms of a sum (F, G sin or cos, or
    both sinh or cosh) as the product c f(u - v) g(u + v) of
    :data:`_SQUARE_PAIRS` (sin^2 u - sin^2 v = sin(u - v) sin(u + v)), u - v
    factored (pi a/L - pi x/L -> pi (a - x)/L, formed exactly); c - c sin^2 v
    as c cos^2 v.  The difference of squares cancels where u -> v (the
    periodic kernel's S^2 - s^2 = sin^2(pi a/L) - sin^2(pi x/L) at the contact
    edge), the product does not."""
    def want(e):
        return e.is_Add and e.has(*_SQUARED_HEADS) and _has_square_pair(e)

    def do(e):
        ts, rest = _terms(e), list(e.args)
        out = []
        used = set()
        for i, ti in enumerate(ts):
            if i in used or ti is None:
                continue
            for j in range(i + 1, len(ts)):
                if j in used or ts[j] is None:
                    continue
                r = _pair(ti, ts[j])
                if r is not None:
                    out.append(r)
                    used |= {i, j}
                    break
        return sp.Add(*out, *[t for k, t in enumerate(rest) if k not in used])
    return expr.replace(want, do)


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
