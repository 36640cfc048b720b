"""Profiles: validation and the piecewise structure the transforms work on.

A profile is the gap z = f(x) between a rigid symmetric indenter and the
undeformed half-plane, given for x >= 0 and mirrored to x < 0.  The method of
Popov (2017) needs f(0) = 0 (the first point of contact is the origin), a
continuous profile (kinks are fine, steps are not) and, for a compact contact,
a profile that does not decrease on (0, a).
"""
from __future__ import annotations

import random
from dataclasses import dataclass
from functools import cached_property

import mpmath
import sympy as sp

from ..core import symbols as S
from ..core.errors import ProfileError, UnknownSymbolError


@dataclass(frozen=True)
class Piece:
    """One analytic piece of a profile: ``expr`` on lo <= x < hi."""

    expr: sp.Expr
    lo: sp.Expr
    hi: sp.Expr

    @property
    def derivative(self) -> sp.Expr:
        return sp.diff(self.expr, S.x)


#: the largest exponent magnitude accepted in a profile (x**n with n up to 1000
#: is still a power law people study; x**(10**10) is not, and would not end)
MAX_EXPONENT = 10**4
MAX_DERIVATIVE_ORDER = 20


def _default_range(sym: sp.Symbol) -> tuple[float, float]:
    return (0.5, 2.5)


def _sanitize(expr, params):
    """Turn user input into a SymPy expression in the standard ``x``."""
    if isinstance(expr, str):
        raise ProfileError(
            "the profile is a string; strings are not evaluated here. Pass a SymPy "
            "expression, or parse text with linecontact_sym.parse_expr(...) "
            "(a whitelisted parser)")
    if isinstance(expr, (int, float)) and not isinstance(expr, bool):
        expr = sp.sympify(expr, strict=True)  # safe: int or float only
    if not isinstance(expr, sp.Basic):
        raise ProfileError(
            f"the profile must be a SymPy expression in x, got {type(expr).__name__}: {expr!r}")
    if isinstance(expr, sp.logic.boolalg.Boolean) and not isinstance(expr, sp.Expr):
        raise ProfileError(f"the profile must be an expression, got the relation {expr}")
    if expr.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
        raise ProfileError(f"the profile {expr} is undefined (a division by zero or an infinite value: "
                           f"a parameter set to 0?)")
    if expr.has(sp.Integral):
        raise ProfileError(f"the profile {expr} holds an unevaluated Integral; give f(x) itself")
    for pw in expr.atoms(sp.Pow):
        e = pw.exp
        if e.is_number and e.is_real and abs(e) > MAX_EXPONENT:
            raise ProfileError(f"the profile {expr} has the power {pw} with exponent beyond {MAX_EXPONENT} in "
                               f"magnitude; no physical profile needs it (and evaluating it would not end)")
    for der in expr.atoms(sp.Derivative):
        order = sum(int(n) if n.is_Integer else MAX_DERIVATIVE_ORDER + 1 for _, n in der.variable_count)
        if order > MAX_DERIVATIVE_ORDER:
            raise ProfileError(f"the profile holds a derivative of order {order} > {MAX_DERIVATIVE_ORDER}")
    if expr.has(sp.Derivative):
        expr = expr.doit()
    # a user's own Symbol('x') (other assumptions) means the standard x
    subs = {s: S.x for s in expr.free_symbols if s.name == "x" and s != S.x}
    expr = expr.xreplace(subs)
    if expr.is_real is False or (expr.is_number and expr.is_real is not True):
        raise ProfileError(f"the profile {expr} is not real")
    return expr


class Profile:
    """A validated symmetric profile f(x), x >= 0.

    Parameters
    ----------
    expr : sympy.Expr
        f(x) for x >= 0 (a ``Piecewise`` in x for profiles with flats or kinks).
    params : iterable of Symbol or dict, optional
        Declared parameters; a dict maps each to a (low, high) range used when
        picking random admissible points for verification.  Symbols created
        with ``positive=True`` count as declared.
    """

    def __init__(self, expr, params=None, name: str | None = None):
        expr = _sanitize(expr, params)
        ranges = {}
        declared = set()
        if params is not None:
            if isinstance(params, dict):
                for k, v in params.items():
                    declared.add(k)
                    if v is not None:
                        ranges[k] = (float(v[0]), float(v[1]))
            else:
                declared.update(params)
        for s in declared:
            if not isinstance(s, sp.Symbol):
                raise ProfileError(f"declared parameter {s!r} is not a SymPy Symbol")
        self.name = name or str(expr)
        free = expr.free_symbols - {S.x}
        for s in free:
            if s in S.RESERVED or s.name in {r.name for r in S.RESERVED}:
                raise ProfileError(
                    f"profile {self.name!r} uses the reserved symbol {s}; "
                    f"{', '.join(map(str, S.RESERVED))} are the half-width, load and modulus")
            if s.is_positive is False or s.is_nonpositive:
                raise ProfileError(
                    f"profile {self.name!r}: the symbol {s} is declared non-positive; the parameters of a "
                    f"profile are lengths, slopes, exponents: declare them positive (Symbol('{s}', positive=True))")
            if s not in declared and not s.is_positive:
                raise UnknownSymbolError(
                    f"profile {self.name!r} holds the unknown symbol {s!r}. Declare it: "
                    f"LineContact(expr, params=[{s}]) or create it with Symbol('{s}', positive=True)")
        if S.x not in expr.free_symbols:
            raise ProfileError(f"profile {self.name!r} does not depend on x")
        self.expr = expr
        self.params = tuple(sorted(free, key=lambda s: s.name))
        self.ranges = {p: ranges.get(p, _default_range(p)) for p in self.params}
        self.pieces = self._split()
        self._check_f0()
        self._check_continuity()

    # ------------------------------------------------------------------ structure
    def sample_params(self, rng: random.Random | None = None) -> dict:
        """Random parameter values (exact rationals) inside the declared ranges."""
        rng = rng or random.Random(12345)
        out = {}
        for p in self.params:
            lo, hi = self.ranges[p]
            out[p] = sp.Rational(round(rng.uniform(lo, hi) * 1000), 1000)
        return out

    def _split(self) -> tuple[Piece, ...]:
        expr = self.expr
        if not expr.has(sp.Piecewise):
            return (Piece(expr, sp.S.Zero, sp.oo),)
        expr = sp.piecewise_fold(expr)
        if not isinstance(expr, sp.Piecewise):
            raise ProfileError(f"profile {self.name!r}: could not bring the Piecewise to a single level")
        breaks = set()
        for _, cond in expr.args:
            for rel in cond.atoms(sp.Rel):
                side = rel.lhs - rel.rhs
                if not side.has(S.x):
                    continue
                sol = sp.solve(sp.Eq(side, 0), S.x)
                if len(sol) != 1:
                    raise ProfileError(f"profile {self.name!r}: cannot read the breakpoint of {rel}")
                breaks.add(sp.sympify(sol[0], strict=True))  # safe: a solve() result
        vals = self.sample_params()
        num = {}
        for bp in breaks:
            v = float(bp.subs(vals))
            if v > 0:
                num[bp] = v
        ordered = sorted(num, key=num.get)
        edges = [sp.S.Zero] + ordered + [sp.oo]
        pieces = []
        for lo, hi in zip(edges[:-1], edges[1:]):
            lo_v = float(lo.subs(vals))
            hi_v = float(hi.subs(vals)) if hi != sp.oo else lo_v + 1.0 + abs(lo_v)
            mid = sp.Rational(round((lo_v + hi_v) / 2 * 10**6), 10**6)
            chosen = None
            for e, cond in expr.args:
                val = cond.subs(vals).subs(S.x, mid)
                if val == sp.true:
                    chosen = e
                    break
            if chosen is None:
                raise ProfileError(f"profile {self.name!r} is undefined between {lo} and {hi}")
            if pieces and pieces[-1].expr == chosen:
                pieces[-1] = Piece(chosen, pieces[-1].lo, hi)
            else:
                pieces.append(Piece(chosen, lo, hi))
        return tuple(pieces)

    @property
    def is_piecewise(self) -> bool:
        return len(self.pieces) > 1

    @property
    def breakpoints(self) -> tuple:
        return tuple(p.lo for p in self.pieces[1:])

    def _check_f0(self):
        first = self.pieces[0].expr
        f0 = first.subs(S.x, 0)
        if f0.has(sp.nan, sp.zoo, sp.oo, -sp.oo) or f0 is sp.nan:
            f0 = sp.limit(first, S.x, 0, "+")
        f0 = sp.simplify(f0)
        if f0 != 0:
            raise ProfileError(
                f"profile {self.name!r}: f(0) = {f0}, but the method needs f(0) = 0 "
                f"(first contact at x = 0). Subtract f(0) from the profile.")

    def _check_continuity(self):
        for left, right in zip(self.pieces[:-1], self.pieces[1:]):
            jump = sp.simplify(left.expr.subs(S.x, right.lo) - right.expr.subs(S.x, right.lo))
            if jump != 0:
                raise ProfileError(
                    f"profile {self.name!r} jumps by {jump} at x = {right.lo}; a step in the "
                    f"profile is not admissible (kinks are). Make the profile continuous.")

    @cached_property
    def slope_at_origin(self) -> sp.Expr:
        """f'(0+), the term the paper's printed Eq. (10) drops (see transforms)."""
        d = self.pieces[0].derivative
        v = d.subs(S.x, 0)
        if v.has(sp.nan, sp.zoo) or v is sp.nan:
            try:
                v = sp.limit(d, S.x, 0, "+")
            except (NotImplementedError, ValueError):
                v = _power_limit(d)
        return sp.simplify(v)

    def piece_at(self, xv, values) -> Piece:
        for p in self.pieces:
            hi = p.hi if p.hi == sp.oo else p.hi.subs(values)
            if hi == sp.oo or xv < hi:
                return p
        return self.pieces[-1]

    # ------------------------------------------------------------------ numerics
    def mp_functions(self, values: dict, derivative: int = 0):
        """mpmath callables of f (or its derivative) for given parameter values,
        with the numeric breakpoints: ``(funcs, breaks)``."""
        fns, breaks = [], []
        for p in self.pieces:
            e = p.expr if derivative == 0 else sp.diff(p.expr, S.x, derivative)
            e = e.subs(values)
            fns.append(sp.lambdify(S.x, e, "mpmath"))
            if p.hi != sp.oo:
                breaks.append(mpmath.mpf(sp.N(p.hi.subs(values), 60)))
        return fns, breaks

    def mp_callable(self, values: dict, derivative: int = 0):
        """One mpmath callable of f (or f', f'') valid on x >= 0."""
        fns, breaks = self.mp_functions(values, derivative)

        def f(xv):
            for fn, bp in zip(fns, breaks):
                if xv < bp:
                    return fn(xv)
            return fns[-1](xv)
        f.breaks = breaks
        return f

    def __repr__(self):
        return f"Profile({self.expr})"


def _power_limit(d):
    """lim_{x->0+} of C*x**mu with a symbolic exponent, as a Piecewise in mu."""
    from .hyperseries import NotDecomposable, decompose
    try:
        terms = decompose(d, S.x)
    except NotDecomposable:
        return sp.Limit(d, S.x, 0, "+")
    if len(terms) != 1:
        return sp.Limit(d, S.x, 0, "+")
    T = terms[0]
    lead = T.coef * (sp.S.One if T.is_power else sp.S.One)
    return sp.Piecewise((0, T.mu > 0), (lead, sp.Eq(T.mu, 0)), (sp.oo, True))
