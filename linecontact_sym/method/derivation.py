"""Derivations: a closed form (or an honest unevaluated integral) together with
how it was obtained, where it holds and how it was verified.
"""
from __future__ import annotations

import math
import random
import time
from dataclasses import dataclass, field
from typing import Callable

import mpmath
import sympy as sp

from ..parsing import to_sympy
from ..core import symbols as S
from ..core.budget import run_with_budget
from ..core.errors import BudgetExceeded, DivergentIntegralError, DomainError
from .rules import NotApplicable

#: digits every closed form must reproduce at every verification point
REQUIRED_DIGITS = 30
#: working precision of the reference quadratures
VERIFY_DPS = 45
#: wall-clock budget of one verification (quadratures at all points), seconds
VERIFY_BUDGET = 120.0


@dataclass(frozen=True)
class VerificationRecord:
    """Agreement of a closed form with the independent quadrature of its
    defining integral."""

    points: tuple            # parameter points (dicts of Symbol -> Rational)
    digits: tuple            # agreeing significant digits at each point
    dps: int                 # working precision of the reference
    reference: str           # how the reference was computed
    required: int = REQUIRED_DIGITS

    @property
    def min_digits(self) -> float:
        return min(self.digits) if self.digits else 0.0

    @property
    def passed(self) -> bool:
        return bool(self.digits) and self.min_digits >= self.required

    def __str__(self):
        return (f"verified at {len(self.points)} random admissible points against "
                f"{self.reference} ({self.dps} digits): >= {self.min_digits:.1f} digits agree")


@dataclass
class Derivation:
    """One derived quantity.

    Attributes
    ----------
    quantity : str      'force', 'pressure', 'gap', 'profile', 'half_width', ...
    expr : sympy.Expr   the closed form, or the unevaluated defining ``Integral``
    closed_form : bool  False when no closed form was found (``expr`` is an Integral)
    method : str        the strategy that produced ``expr``
    conditions : tuple  SymPy relations under which ``expr`` holds
    verification : VerificationRecord or None
    seconds : float     derivation time (strategies + verification)
    notes : tuple       remarks (e.g. where the paper's printed form differs)
    reference : callable(values: dict, dps: int) -> mpf
                        high-precision evaluation of the defining integral
    """

    quantity: str
    expr: sp.Expr
    closed_form: bool
    method: str
    conditions: tuple = ()
    verification: VerificationRecord | None = None
    seconds: float = 0.0
    notes: tuple = ()
    reference: Callable | None = field(default=None, repr=False)
    variables: tuple = ()

    def evalf(self, dps: int = 30, **values):
        """Evaluate at a point (keyword arguments by symbol name) with ``dps``
        digits: the closed form where there is one, else the quadrature."""
        vals = _values_by_name(self.variables_all, values)
        if self.closed_form:
            with mpmath.workdps(dps):
                v = sp.N(self.expr.xreplace(_floats(vals, dps + 20)), dps + 5)
                return _to_mpf(v)
        return self.reference(vals, dps)

    @property
    def variables_all(self):
        syms = set(self.variables) if (self.variables and not self.closed_form) \
            else self.expr.free_symbols | set(self.variables)
        return tuple(sorted(syms, key=lambda s: s.name))

    def summary(self) -> str:
        lines = [f"{self.quantity}: {self.expr}",
                 f"  method: {self.method}" + ("" if self.closed_form else " (no closed form)")]
        if self.conditions:
            lines.append("  holds for: " + ", ".join(map(str, self.conditions)))
        if self.verification is not None:
            lines.append("  " + str(self.verification))
        lines.append(f"  derived in {self.seconds:.2f} s")
        lines += ["  note: " + n for n in self.notes]
        return "\n".join(lines)

    def _sympy_(self):
        """A Derivation takes part in SymPy arithmetic as its expression."""
        return self.expr

    def _repr_latex_(self):
        from ..core.printing import to_latex
        return f"$\\displaystyle {to_latex(self.expr)}$"

    def __str__(self):
        return self.summary()


def _values_by_name(symbols, values):
    by_name = {s.name: s for s in symbols}
    out = {}
    for k, v in values.items():
        sym = k if isinstance(k, sp.Symbol) else by_name.get(k)
        if sym is None:
            sym = sp.Symbol(k) if isinstance(k, str) else k
        out[sym] = sp.nsimplify(v, rational=True) if isinstance(v, float) else to_sympy(v)
    missing = [s.name for s in symbols if s not in out]
    if missing:
        raise DomainError(f"missing values for {', '.join(missing)}")
    return out


def _floats(vals: dict, digits: int) -> dict:
    """Exact values as Floats of ``digits`` digits: an exact Rational under a
    symbolic exponent makes SymPy factor huge integers (minutes); a Float
    with guard digits gives the same value to the precision asked."""
    return {k: (sp.Float(v, digits) if isinstance(v, sp.Rational) and not v.is_Integer else v)
            for k, v in vals.items()}


def _to_mpf(v):
    v = complex(v) if not v.is_real and v.is_number else v
    if isinstance(v, complex):
        if abs(v.imag) > 1e-12 * max(abs(v.real), 1e-300):
            raise DomainError(f"the quantity is complex here: {v}")
        return mpmath.mpf(v.real)
    try:
        return mpmath.mpf(str(v)) if v.is_Float else mpmath.mpf(sp.N(v, mpmath.mp.dps + 5))
    except TypeError:
        re, im = sp.N(v, mpmath.mp.dps + 5).as_real_imag()
        if abs(im) > abs(re) * sp.Float(10)**(-mpmath.mp.dps + 3):
            raise DomainError(f"the quantity is complex here: {v}")
        return mpmath.mpf(str(re))


# ------------------------------------------------------------------ tidy
def tidy(expr: sp.Expr) -> sp.Expr:
    """hyperexpand, then a moderate simplification (gamma functions, powers)."""
    expr = sp.hyperexpand(expr)
    if expr.has(sp.Piecewise):
        expr = sp.piecewise_fold(expr)
        if isinstance(expr, sp.Piecewise):
            return sp.Piecewise(*[(tidy(e), c) for e, c in expr.args])
    if expr.has(sp.gamma):
        expr = sp.gammasimp(expr)
    cand = sp.simplify(expr)
    if sp.count_ops(cand) <= sp.count_ops(expr):
        expr = cand
    return expr


def _solve_for_a(cond):
    """monomial(a) < 1  ->  a < root, for positive symbols (e.g. a**2/R**2 < 1 -> a < R)."""
    if isinstance(cond, (sp.StrictLessThan, sp.LessThan)) and cond.rhs == 1 and S.a in cond.lhs.free_symbols:
        lhs = cond.lhs.func(*cond.lhs.args) if not isinstance(cond.lhs, sp.Abs) else cond.lhs.args[0]
        coef, dep = lhs.as_independent(S.a, as_Add=False)
        base, e = dep.as_base_exp()
        if base == S.a and e.is_positive and coef.is_positive:
            return cond.func(S.a, (1 / coef)**(1 / e))
    return cond


def tidy_conditions(conds) -> tuple:
    out = []
    for c in conds:
        try:
            c2 = _solve_for_a(sp.simplify(c))
        except Exception:
            c2 = c
        if c2 == sp.true:
            continue
        if c2 == sp.false:
            raise DivergentIntegralError(f"condition {c} never holds")
        if c2 not in out:
            out.append(c2)
    return tuple(out)


def try_strategies(strategies, args, budget: float):
    """Try each strategy in order, each under what remains of ``budget``.

    Returns ``(expr, conditions, notes, name)`` of the first success, or
    ``(None, (), [reasons], None)``."""
    reasons = []
    deadline = time.monotonic() + budget
    for strat in strategies:
        left = deadline - time.monotonic()
        if left <= 0.05:
            reasons.append(f"{strat.__name__}: budget used up")
            break
        try:
            expr, conds, notes = run_with_budget(strat, *args, seconds=left)
        except NotApplicable as exc:
            reasons.append(f"{strat.__name__}: {exc}")
            continue
        except BudgetExceeded:
            reasons.append(f"{strat.__name__}: no result within {budget:g} s")
            continue
        except DivergentIntegralError:
            raise
        except Exception as exc:  # a SymPy failure inside a strategy
            reasons.append(f"{strat.__name__}: {type(exc).__name__}: {exc}")
            continue
        left = max(deadline - time.monotonic(), 1.0)
        try:
            expr = run_with_budget(tidy, expr, seconds=min(left, 15.0))
        except Exception:
            expr = sp.hyperexpand(expr)
        try:
            conds = tidy_conditions(conds)
        except DivergentIntegralError:
            raise
        return expr, conds, notes, strat.__name__
    return None, (), reasons, None


# ------------------------------------------------------------------ verification
def _holds(conds, vals) -> bool:
    for c in conds:
        v = c.xreplace(vals)
        try:
            v = bool(v) if v in (sp.true, sp.false) else bool(sp.simplify(v))
        except TypeError:
            return False
        if not v:
            return False
    return True


def digits_agreeing(val, ref, dps=None) -> float:
    """Agreeing significant digits of ``val`` and ``ref`` (capped at ``dps``,
    default the current working precision; a reference below 10**(-dps/2)
    is compared absolutely)."""
    dps = mpmath.mp.dps if dps is None else dps
    with mpmath.workdps(dps):
        err = abs(val - ref)
        if err == 0:
            return float(dps)
        scale = max(abs(ref), mpmath.mpf(10)**(-dps // 2))
        d = float(-mpmath.log10(err / scale))
    return 0.0 if math.isnan(d) else min(d, float(dps))


def verify(expr, reference, sampler, conditions=(), n_points: int = 5, seed: int = 2017,
           dps: int = VERIFY_DPS, reference_name: str = "mpmath quadrature",
           budget: float = VERIFY_BUDGET) -> VerificationRecord:
    """Compare ``expr`` with ``reference(values, dps)`` at ``n_points`` points
    drawn by ``sampler(rng)`` (dicts Symbol -> Rational) where ``conditions`` hold.

    Runs under ``budget`` seconds; a verification that does not finish is
    returned as a record with no points (``passed`` is False)."""
    return verify_many({"_": expr}, lambda vals, d: {"_": reference(vals, d)}, sampler, conditions,
                       n_points, seed, dps, reference_name, budget)["_"]


def verify_many(exprs: dict, reference, sampler, conditions=(), n_points: int = 5, seed: int = 2017,
                dps: int = VERIFY_DPS, reference_name="mpmath quadrature",
                budget: float = VERIFY_BUDGET) -> dict:
    """:func:`verify` for several closed forms sharing one (expensive)
    reference: ``reference(values, dps)`` returns a dict name -> mpf; the
    same points are used for all.  ``reference_name`` may be a dict too.
    Returns name -> :class:`VerificationRecord`."""
    def name(k):
        return reference_name[k] if isinstance(reference_name, dict) else reference_name
    try:
        return run_with_budget(_verify, exprs, reference, sampler, conditions, n_points, seed, dps,
                               name, seconds=budget)
    except BudgetExceeded:
        return {k: VerificationRecord((), (), dps, name(k) + f" (did not finish in {budget:g} s)")
                for k in exprs}


def _verify(exprs, reference, sampler, conditions, n_points, seed, dps, name):
    rng = random.Random(seed)
    points, digits = [], {k: [] for k in exprs}
    tries = 0
    while len(points) < n_points and tries < 20 * n_points:
        tries += 1
        vals = sampler(rng)
        if vals is None or not _holds(conditions, vals):
            continue
        try:
            refs = reference(vals, dps)
        except (ZeroDivisionError, ValueError, DomainError):
            continue
        if any(not mpmath.isfinite(r) or isinstance(r, mpmath.mpc) for r in refs.values()):
            continue
        points.append(vals)
        fvals = _floats(vals, dps + 30)
        for k, expr in exprs.items():
            with mpmath.workdps(dps):
                try:
                    val = _to_mpf(sp.N(expr.xreplace(fvals), dps + 10))
                except (DomainError, TypeError, ValueError):
                    val = mpmath.mpf("nan")
                digits[k].append(digits_agreeing(val, refs[k], dps))
    return {k: VerificationRecord(tuple(points), tuple(digits[k]), dps, name(k)) for k in exprs}
