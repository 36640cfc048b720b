"""Profiles: validation and the piecewise structure the transforms work on.

A profile is the gap z = f(x) between a rigid symmetric indenter and the
undeformed half-plane, given for x >= 0 and mirrored to x < 0.  The method of
Popov (2017) needs f(0) = 0 (the first point of contact is the origin), a
continuous profile (kinks are fine, steps are not) and, for a compact contact,
a profile that does not decrease on (0, a).
"""
from __future__ import annotations

import math
import random
from dataclasses import dataclass
from functools import cached_property

import mpmath
import sympy as sp

from ..core.conversion import exact_number, number, to_mpf
from ..core import symbols as S
from ..core.errors import InadmissibleProfileError, LineContactError, ProfileError, UnknownSymbolError
from ..core.precision import workdps
from ..core.printing import lambdify


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
#: the deepest nesting of an expression the engine takes (the whitelisted
#: parser's bound on typed text, :data:`linecontact_sym.parsing.expressions.MAX_DEPTH`,
#: for SymPy objects built in Python: sin(sin(...(x))) 300 deep would exhaust
#: Python's recursion in SymPy's own walks, a RecursionError)
MAX_EXPRESSION_DEPTH = 60


def check_depth(expr, what: str = "the profile") -> None:
    """``expr`` nested at most :data:`MAX_EXPRESSION_DEPTH` levels (counted
    without recursion), else a :class:`~linecontact_sym.core.errors.ProfileError`
    naming it; a flat sum or product of many terms is not nesting."""
    stack = [(expr, 1)]
    while stack:
        e, d = stack.pop()
        if d > MAX_EXPRESSION_DEPTH:
            raise ProfileError(f"{what} is nested more than {MAX_EXPRESSION_DEPTH} levels deep (a function of a "
                               f"function of ...); no contact problem needs it, and SymPy's recursive walks "
                               f"would not survive it")
        stack.extend((a, d + 1) for a in getattr(e, "args", ()))
#: relations of the parameters alone a Piecewise profile may switch on (each
#: combination is derived separately: 2**3 cases at most)
MAX_CASE_RELATIONS = 3


def _default_range(sym: sp.Symbol) -> tuple[float, float]:
    """The range a parameter without a declared one is drawn from, before it
    is cut to where the profile is admissible (:meth:`Profile._admissible_ranges`)."""
    return (0.5, 2.5)


#: functions that hide a breakpoint (a kink or a switch) in a profile
KINK_FUNCTIONS = (sp.Abs, sp.Min, sp.Max, sp.sign, sp.Heaviside)

#: x at which a profile is checked near its first point of contact (relative
#: to 1: f real and f' >= 0 there), log-spaced from 1e-6 to 5e-2
NEAR_ORIGIN = tuple(10.0**(-6 + 4.7 * k / 23) for k in range(24))


def expose_kinks(expr):
    """``expr`` with every Abs, Min, Max, sign and Heaviside of x rewritten as
    a Piecewise in x, so that their breakpoints are breakpoints of the
    profile (the transforms are split there) instead of kinks hidden inside
    one analytic-looking piece.

    >>> x = sp.Symbol("x", positive=True)
    >>> expose_kinks(sp.Abs(x - 1) - 1 + 2*x)
    Piecewise((3*x - 2, x >= 1), (x, True))
    """
    hidden = [e for e in expr.atoms(*KINK_FUNCTIONS) if e.has(S.x)]
    if not hidden:
        return expr
    # innermost first: a rewritten inner function must not be rewritten twice
    hidden.sort(key=lambda e: sp.count_ops(e))
    for e in hidden:
        expr = expr.xreplace({e: e.rewrite(sp.Piecewise)})
    return sp.piecewise_fold(expr)


def _uncovered(pw):
    """An x in [0, 5] (other symbols 1) where no condition of ``pw`` holds, or None."""
    ones = {s: 1 for s in pw.free_symbols if s.name != "x"}
    conds = [c.xreplace(ones) for _, c in pw.args]
    for k in range(51):
        xv = sp.Rational(k, 10)
        if not any(c.xreplace({s: xv for s in c.free_symbols}) == sp.true for c in conds):
            return xv
    return None


def _sampling_range(sym, v):
    """``params={R: (low, high)}``: two finite real numbers, low <= high,
    not below 0 for a symbol declared positive; else a
    :class:`~linecontact_sym.core.errors.ProfileError` naming the range (text,
    NaN, infinity and a single number included)."""
    def bad(why):
        return ProfileError(f"the sampling range of {sym} must be (low, high), two finite real numbers with "
                            f"low <= high; got {v!r} ({why})")
    if not isinstance(v, (tuple, list)) or len(v) != 2:
        raise bad("not a pair")
    ends = []
    for e in v:
        if isinstance(e, (str, bytes, bool)) or e is None:
            raise bad(f"{e!r} is not a number")
        try:
            f = float(number(e))
        except (LineContactError, TypeError, ValueError, OverflowError):
            raise bad(f"{e!r} is not a finite real number") from None
        if not math.isfinite(f):
            raise bad(f"{e!r} is not finite")
        ends.append(f)
    lo, hi = ends
    if not lo <= hi:
        raise bad("low > high")
    if getattr(sym, "is_positive", False) and lo < 0:
        raise bad(f"{sym} is declared positive; sampling below 0 checks outside its domain")
    return lo, hi


def _sanitize(expr, params):
    """Turn user input into a SymPy expression in the standard ``x``."""
    if params is not None and not isinstance(params, (dict, list, tuple, set, frozenset)):
        raise ProfileError(f"params must be a list of symbols or a dict symbol -> (low, high), got {params!r}")
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
    check_depth(expr)
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
    jumps = [f for f in (sp.floor, sp.ceiling, sp.frac, sp.DiracDelta) if expr.has(f)]
    if jumps:
        raise InadmissibleProfileError(f"the profile {expr} holds {jumps[0].__name__}(...): a profile with jumps "
                                       f"(or a delta) has no contact solution of this kind; write a continuous f(x)")
    for pw in expr.atoms(sp.Piecewise):
        if pw.args[-1].cond is not sp.true and _uncovered(pw) is not None:
            raise ProfileError(f"the profile's Piecewise {pw} has no value where none of its conditions holds "
                               f"(x = {_uncovered(pw)}, parameters 1); end it with (expr, True)")
    # floats typed into a profile (x**1.5, 0.3*x**2) mean their shortest
    # decimal, as everywhere in the package: exact, so that the rules see 3/2
    floats = {f: exact_number(float(f)) for f in expr.atoms(sp.Float) if f.is_finite}
    if floats:
        expr = expr.xreplace(floats)
    # a user's own Symbol('x') (other assumptions) means the standard x
    subs = {s: S.x for s in expr.free_symbols if s.name == "x" and s != S.x}
    expr = expr.xreplace(subs)
    if expr.is_real is False or (expr.is_number and expr.is_real is not True):
        raise ProfileError(f"the profile {expr} is not real")
    return expr



def _profile_numeric_fns(self, values):
    """(f, f') of x as mpmath callables at these parameter values (the
    profile's expression compiled once with the parameters as arguments)."""
    if "_near_fns" not in self.__dict__:
        args = [S.x] + list(self.params)
        try:
            self._near_fns = (lambdify(args, self.expr, "mpmath"),
                              lambdify(args, sp.diff(self.expr, S.x), "mpmath"))
        except Exception:  # pragma: no cover - lambdify of exotic functions
            self._near_fns = None
    if self._near_fns is None:
        return None
    with workdps(30):
        pv = [to_mpf(values[p]) for p in self.params]
    return (lambda xv: self._near_fns[0](xv, *pv)), (lambda xv: self._near_fns[1](xv, *pv))


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
    auxiliary : bool
        A linear part of another contact (see :attr:`auxiliary`), not an
        indenter: the test f' >= 0 near x = 0 is skipped.
    """

    def __init__(self, expr, params=None, name: str | None = None, auxiliary: bool = False):
        expr = _sanitize(expr, params)
        ranges = {}
        declared = set()
        if params is not None:
            if isinstance(params, dict):
                for k, v in params.items():
                    declared.add(k)
                    if v is not None:
                        ranges[k] = _sampling_range(k, v)
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
        self.original = expr
        self.expr = expose_kinks(expr)
        self.params = tuple(sorted(free, key=lambda s: s.name))
        self.declared_ranges = dict(ranges)
        self.ranges = {p: ranges.get(p, _default_range(p)) for p in self.params}
        #: relations in the parameters under which ``pieces`` hold (the cases
        #: of a parameter-dependent Piecewise, the order of the breakpoints)
        self.assumptions: tuple = ()
        self.range_notes: tuple = ()
        #: a linear part of another contact (the even and odd parts of an asymmetric
        #: profile, :mod:`linecontact_sym.contacts.asymmetric`), not a physical
        #: indenter: it may decrease or go negative, so the admissibility test of
        #: a compact contact (f' >= 0 near 0) is not made; everything else is
        self.auxiliary = bool(auxiliary)
        if not self.auxiliary:
            self._check_real_and_rising()
        self.pieces = self._split()
        self._check_f0()
        self._check_continuity()

    # ------------------------------------------------------------------ structure
    def sample_params(self, rng: random.Random | None = None) -> dict:
        """Random parameter values (exact rationals) inside the ranges (the
        declared ones, or the default cut to where the profile is admissible,
        see :meth:`_check_real_and_rising`) where the :attr:`assumptions` hold."""
        rng = rng or random.Random(12345)
        out = {}
        for _ in range(50):
            out = {}
            for p in self.params:
                lo, hi = self.ranges[p]
                out[p] = sp.Rational(round(rng.uniform(lo, hi) * 1000), 1000)
            if self.holds(out):
                return out
        return out

    def holds(self, values) -> bool:
        """Do the profile's :attr:`assumptions` hold at ``values``?"""
        for rel in self.assumptions:
            v = rel.xreplace(values)
            if v not in (sp.true, sp.false):
                try:
                    v = sp.true if bool(sp.N(rel.lhs.xreplace(values) - rel.rhs.xreplace(values), 30) > 0) \
                        == isinstance(rel, (sp.StrictGreaterThan, sp.GreaterThan)) else sp.false
                except TypeError:
                    return False
            if v != sp.true:
                return False
        return True

    # ------------------------------------------------------------------ admissibility near x = 0
    def __getstate__(self):  # pickled without the compiled functions (built again on use)
        return {k: v for k, v in self.__dict__.items() if k != "_near_fns"}

    _numeric_fns = _profile_numeric_fns

    def rising_on(self, values, a, n: int = 24):
        """None if f is real and f' >= 0 at n points evenly spread over (0, a]
        (the frictionless compact contact of half-width a needs a profile that
        does not decrease inside it), else where it fails, in words.  An
        :attr:`auxiliary` profile (a linear part, not an indenter) is only
        asked to be real."""
        fns = self._numeric_fns(values)
        rising = not getattr(self, "auxiliary", False)
        if fns is None:
            return None
        f, fp = fns
        with workdps(30):
            A = to_mpf(a)
            slopes = []
            for k in range(1, n + 1):
                xv = A * k / n
                try:
                    v, d = f(xv), fp(xv)
                except (ValueError, ZeroDivisionError, TypeError):
                    return f"f is not defined at x = {mpmath.nstr(xv, 6)}"
                if isinstance(v, mpmath.mpc) and abs(v.imag) > 1e-20 * (abs(v.real) + 1e-300):
                    return f"f is not real at x = {mpmath.nstr(xv, 6)}"
                d = d.real if isinstance(d, mpmath.mpc) else d
                slopes.append((xv, d, abs(v) / xv))
            if rising:
                # a slope of rounding size (f' = -2e-31 at the crest of 1 - cos x, period 2 pi,
                # read at 30 digits) is 0, not a decrease: the tolerance is relative to the
                # profile's own slopes
                finite = [(xv, d) for xv, d, _ in slopes if mpmath.isfinite(d)]
                scale = max([abs(d) for _, d in finite] + [r for _, _, r in slopes if mpmath.isfinite(r)],
                            default=mpmath.mpf(0))
                for xv, d in finite:
                    if d < -mpmath.mpf(10)**-20 * scale:
                        return f"f decreases at x = {mpmath.nstr(xv, 6)} (f' = {mpmath.nstr(d, 3)})"
        return None

    def _near_origin_ok(self, values) -> str | None:
        """None if f is real at the points :data:`NEAR_ORIGIN` and f' >= 0 at
        those up to 1e-4 for these parameter values, else what is wrong
        ('complex', 'decreasing')."""
        fns = self._numeric_fns(values)
        if fns is None:
            return None
        ff, ffp = fns
        bad = None
        with workdps(30):
            for xv in NEAR_ORIGIN:
                try:
                    v, d = ff(mpmath.mpf(xv)), ffp(mpmath.mpf(xv))
                except (ValueError, ZeroDivisionError, TypeError, NameError):
                    continue
                for w in (v, d):
                    if isinstance(w, mpmath.mpc) and abs(w.imag) > 1e-20 * (abs(w.real) + 1e-300):
                        return "complex"
                d = d.real if isinstance(d, mpmath.mpc) else d
                if mpmath.isfinite(d) and d < 0 and xv <= 1.01e-4:
                    bad = "decreasing"
        return bad

    def _check_real_and_rising(self):
        """See :func:`check_real_and_rising`."""
        check_real_and_rising(self)

    def _split(self) -> tuple[Piece, ...]:
        """The pieces of a Piecewise profile, ordered in x, read at one sample
        parameter point.  Every choice that depends on the parameters is
        recorded in :attr:`assumptions` (a relation true at the sample point):
        a condition free of x (``Piecewise((x**2, R < 1), (x**3, True))``
        holds for R < 1 only), the order of two breakpoints, a breakpoint's
        sign.  Results derived from the pieces hold under these assumptions."""
        expr = self.expr
        if not expr.has(sp.Piecewise):
            return (Piece(expr, sp.S.Zero, sp.oo),)
        expr = sp.piecewise_fold(expr)
        if not isinstance(expr, sp.Piecewise):
            raise ProfileError(f"profile {self.name!r}: could not bring the Piecewise to a single level")
        vals = self.sample_params()
        assumed = []

        def assume(rel):
            rel = sp.simplify(rel)
            if rel in (sp.true, sp.false) or not rel.free_symbols:
                return
            if rel.xreplace(vals) == sp.false:
                rel = rel.negated
            if rel not in assumed:
                assumed.append(rel)
        breaks = set()
        for _, cond in expr.args:
            for rel in cond.atoms(sp.Rel):
                side = rel.lhs - rel.rhs
                if not side.has(S.x):
                    assume(rel)     # a case of the parameters, not a breakpoint
                    continue
                sols = [sp.sympify(r, strict=True) for r in sp.solve(sp.Eq(side, 0), S.x)]  # safe: solve() results
                kept = []
                for r in sols:
                    try:
                        v = complex(sp.N(r.xreplace(vals)))
                    except TypeError:
                        continue
                    if abs(v.imag) < 1e-12 * (1 + abs(v.real)) and v.real > 0:
                        kept.append(r)
                        if r.free_symbols:
                            assume(sp.Gt(r, 0))
                if not kept and not sols:
                    raise ProfileError(f"profile {self.name!r}: cannot read the breakpoint of {rel}")
                breaks.update(kept)
        num = {bp: float(sp.N(bp.xreplace(vals))) for bp in breaks}
        ordered = sorted(num, key=num.get)
        for lo_bp, hi_bp in zip(ordered[:-1], ordered[1:]):
            if (lo_bp.free_symbols or hi_bp.free_symbols) and sp.simplify(hi_bp - lo_bp).is_positive is not True:
                assume(sp.Lt(lo_bp, hi_bp))
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
        self.assumptions = tuple(assumed)
        return tuple(pieces)

    @cached_property
    def cases(self) -> tuple:
        """The cases of a Piecewise that switches on the parameters alone:
        see :func:`parameter_cases`."""
        return parameter_cases(self)

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
            jump = left.expr.subs(S.x, right.lo) - right.expr.subs(S.x, right.lo)
            if jump != 0:                  # simplify only what is not plainly 0
                jump = sp.simplify(jump)
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
                with workdps(max(60, mpmath.mp.dps + 10)):     # kept for any later precision
                    breaks.append(to_mpf(p.hi.subs(values)))
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


def parameter_cases(profile) -> tuple:
    """The cases of a Piecewise whose conditions hold relations free of x
    (``Piecewise((x**2/(2*R), R < 1), (x**2, True))``): a tuple of
    ``(condition, expression)``, one per combination of those relations
    that SymPy cannot prove impossible, the expression being the profile
    with the relations decided (the last condition is ``True``); ``()``
    for a profile without such relations.  :attr:`pieces` are read in one
    case only (see :meth:`_split`); the contacts derive every case
    (:meth:`~linecontact_sym.contacts.normal.contact.LineContact.derivation`),
    so that a result holds for every parameter value, not only in the
    case the pieces were read in.  More than :data:`MAX_CASE_RELATIONS`
    such relations raise :class:`ProfileError`."""
    expr = sp.piecewise_fold(profile.expr) if profile.expr.has(sp.Piecewise) else profile.expr
    rels = []
    for pw in expr.atoms(sp.Piecewise):
        for _, cond in pw.args:
            for r in cond.atoms(sp.Rel):
                if not r.has(S.x) and r.free_symbols:
                    c = r.canonical
                    if c not in rels and c.negated.canonical not in rels:
                        rels.append(c)
    if not rels:
        return ()
    if len(rels) > MAX_CASE_RELATIONS:
        raise ProfileError(f"profile {profile.name!r}: its Piecewise switches on {len(rels)} relations of the "
                           f"parameters ({', '.join(map(str, rels))}); at most {MAX_CASE_RELATIONS} are "
                           f"derived case by case: give the cases as separate profiles")
    out = []
    for k in range(2**len(rels)):
        truth = [bool(k >> i & 1) for i in range(len(rels))]
        cond = sp.And(*[r if t else r.negated for r, t in zip(rels, truth)])
        try:
            if sp.simplify(cond) == sp.false:
                continue
        except Exception:
            pass
        sub = {}
        for pw in expr.atoms(sp.Piecewise):
            for _, c in pw.args:
                for r in c.atoms(sp.Rel):
                    for rel, t in zip(rels, truth):
                        if r.canonical == rel:
                            sub[r] = sp.true if t else sp.false
                        elif r.canonical == rel.negated.canonical:
                            sub[r] = sp.false if t else sp.true
        out.append((cond, expr.xreplace(sub)))
    if not out:
        return ()
    # the same expression in two cases: one case
    merged: list = []
    for cond, e in out:
        for i, (c0, e0) in enumerate(merged):
            if e0 == e:
                merged[i] = (sp.Or(c0, cond), e0)
                break
        else:
            merged.append((cond, e))
    if len(merged) == 1:
        return ()
    merged[-1] = (sp.true, merged[-1][1])
    return tuple(merged)


def check_real_and_rising(profile):
    """Refuse a profile that is not real, or that decreases arbitrarily
    close to x = 0 for every parameter value tried (``-x**2``,
    ``x*sin(1/x)``: no compact contact exists for any half-width); cut the
    default range of each undeclared parameter to the longest run of the
    24 values tried (others at their range midpoints) where f is real at
    :data:`NEAR_ORIGIN` and f' >= 0 at those up to 1e-4, its ends found by bisection
    (``x*tan(theta)``: theta < pi/2).  A declared range is the user's
    word and is kept."""
    mids = {p: sp.Rational(round((lo + hi) / 2 * 1000), 1000) for p, (lo, hi) in profile.ranges.items()}
    why = profile._near_origin_ok(mids)
    free = [p for p in profile.params if p not in profile.declared_ranges]
    notes = []
    for p in free:
        lo, hi = profile.ranges[p]
        grid = [lo + (hi - lo) * k / 23 for k in range(24)]
        oks = [profile._near_origin_ok({**mids, p: sp.Rational(round(v * 10**6), 10**6)}) is None for v in grid]
        runs, start = [], None
        for k, ok in enumerate(oks + [False]):
            if ok and start is None:
                start = k
            if not ok and start is not None:
                runs.append((start, k - 1))
                start = None
        if not runs:
            continue
        i0, i1 = max(runs, key=lambda r: r[1] - r[0])
        if (i0, i1) == (0, 23):
            continue
        new_lo, new_hi = grid[i0], grid[i1]
        for end, outside in ((0, i0 - 1), (1, i1 + 1)):
            if not 0 <= outside < 24:
                continue
            good, bad = (grid[i0], grid[outside]) if end == 0 else (grid[i1], grid[outside])
            for _ in range(24):
                m = (good + bad) / 2
                if profile._near_origin_ok({**mids, p: sp.Rational(round(m * 10**9), 10**9)}) is None:
                    good = m
                else:
                    bad = m
            if end == 0:
                new_lo = good
            else:
                new_hi = good
        profile.ranges[p] = (new_lo, new_hi)
        mids[p] = sp.Rational(round((new_lo + new_hi) / 2 * 1000), 1000)
        notes.append(f"{p} sampled in ({new_lo:.6g}, {new_hi:.6g}): outside it the profile is "
                     f"not real or decreases near x = 0 (default range ({lo:g}, {hi:g}))")
    profile.range_notes = tuple(notes)
    why = profile._near_origin_ok(mids)
    if why == "complex":
        raise ProfileError(f"profile {profile.name!r} is not real near x = 0 (at x = 1e-6 .. 5e-2 and the "
                           f"parameter values tried): a gap must be a real function")
    if why == "decreasing":
        raise InadmissibleProfileError(
            f"profile {profile.name!r} decreases arbitrarily close to x = 0 (f'(x) < 0 at some x in "
            f"(1e-6, 1e-4) for every parameter value tried): no compact contact exists for any "
            f"half-width; the method needs f' >= 0 on (0, a)")


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
