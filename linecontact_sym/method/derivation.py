"""Derivations: a closed form (or an honest unevaluated integral) together with
how it was obtained, where it holds and how it was verified.

:func:`integrate` is the dispatcher over the rules of :mod:`.rules`;
:func:`derive` carries one transform all the way: rules under the time
budget, tidying, verification against the independent reference, and the
honest fallback (the unevaluated integral with a high-precision evaluator)
when nothing closes or a closed form fails its check.
"""
from __future__ import annotations

import contextlib
import contextvars
import functools
import math
import time
from dataclasses import KW_ONLY, dataclass, field
from typing import Callable

import sympy as sp
from sympy.core.rules import Transform
from sympy.core.traversal import bottom_up
from sympy.functions.elementary.hyperbolic import HyperbolicFunction
from sympy.functions.elementary.trigonometric import TrigonometricFunction
from sympy.functions.special.bessel import BesselBase

from ..core import symbols as S
from ..core.budget import Ahead, Deadline, checked_budget, child_left, forks, run_stages, run_with_budget
from ..core.conversion import float_values, point_value, real_mpf
from ..core.errors import BudgetExceeded, ClaimError, DivergentIntegralError, DomainError, LineContactError
from ..parsing import to_sympy
from . import store
from .rules import RULES, NotApplicable, Problem, Step
from .verification import (REQUIRED_DIGITS, VERIFY_DPS, VerificationRecord, holds, references_ahead, unfinished,
                           verify, verify_here)
from ..core.precision import held, serialized, workdps
from ..core.ranges import check_sign
from ..core.units import refuse_units

#: the rule name of a result without closed form
FALLBACK = "numeric_fallback"

#: start times of the derivations under way (innermost last), see :func:`timing`
_CLOCKS: contextvars.ContextVar = contextvars.ContextVar("derivation_clocks", default=())


@contextlib.contextmanager
def timing(new: bool = True):
    """The one place derivation times are taken: a :class:`Derivation` made
    without ``seconds`` records the time since the innermost ``timing``
    began.  :meth:`~linecontact_sym.contacts.base.Contact.derivation` opens
    one per quantity; ``new=False`` (:func:`timed`) opens one only where none
    is under way (a derivation function called on its own)."""
    clocks = _CLOCKS.get()
    if not new and clocks:
        yield
        return
    token = _CLOCKS.set(clocks + (time.perf_counter(),))
    try:
        yield
    finally:
        _CLOCKS.reset(token)


def elapsed() -> float:
    """Seconds since the innermost :func:`timing` began (0 outside any)."""
    clocks = _CLOCKS.get()
    return time.perf_counter() - clocks[-1] if clocks else 0.0


def timed(fn):
    """Decorator: ``fn`` runs under :func:`timing` ``(new=False)``."""
    @functools.wraps(fn)
    def wrapper(*args, **kw):
        with timing(new=False):
            return fn(*args, **kw)
    return wrapper


@dataclass
class Derivation:
    """One derived quantity, built by keywords after the quantity's name::

        Derivation("force", expr=P, closed_form=True, step=step, conditions=conds,
                   verification=rec, reference=quad, variables=(a,) + params)

    ``seconds`` is taken by :func:`timing` unless given (a stored result's).

    Attributes
    ----------
    quantity : str      'force', 'pressure', 'gap', 'profile', 'half_width', ...
    expr : sympy.Expr   the closed form, or the unevaluated defining ``Integral``
    closed_form : bool  False when no closed form was found (``expr`` is an Integral)
    step : Step         the record of the rule that produced ``expr`` (its name,
                        ``step.rule``, and remarks, ``step.notes``); a
                        ``numeric_fallback`` step when there is no closed form
    conditions : tuple  SymPy relations under which ``expr`` holds
    verification : VerificationRecord or None
    seconds : float     derivation time (rules, tidying and verification)
    notes : tuple       remarks (e.g. where the paper's printed form differs)
    reference : callable(values: dict, dps: int) -> mpf
                        high-precision evaluation of the defining integral
    variables : tuple   the symbols a number needs (besides those of ``expr``)
    attempts : tuple    (rule, why it gave no result) for the rules tried before
    cached : str        '' (derived now), 'memory' (derived before in this
                        process) or 'disk' (the on-disk cache, :mod:`.store`);
                        ``seconds`` is then the time of the original derivation
    """

    quantity: str
    _: KW_ONLY
    expr: sp.Expr
    closed_form: bool
    step: Step
    conditions: tuple = ()
    verification: VerificationRecord | None = None
    seconds: float | None = None
    notes: tuple = ()
    reference: Callable | None = field(default=None, repr=False)
    variables: tuple = ()
    attempts: tuple = ()
    cached: str = ""

    def __post_init__(self):
        if self.seconds is None:
            self.seconds = elapsed()

    @property
    def rule(self) -> str:
        """Name of the rule (or procedure) that produced ``expr``."""
        return self.step.rule

    @property
    def method(self) -> str:
        """How ``expr`` was obtained, for people: 'rule: notes'."""
        return self.step.describe()

    def __getstate__(self):
        """Pickled without ``reference`` (a closure over the contact that made
        it): an unpickled Derivation keeps its expression, rule, conditions
        and verification; a numeric evaluation that needs the reference asks
        the contact for the derivation again."""
        state = dict(self.__dict__)
        state["reference"] = None
        return state

    def __setstate__(self, state):
        self.__dict__.update(state)

    def evalf(self, dps: int = 30, **values):
        """Evaluate at a point (keyword arguments by symbol name) with ``dps``
        digits: the closed form where there is one, else the reference
        (high-precision quadrature of the defining integral).  The mpf
        returned prints its ``dps`` digits (:class:`~linecontact_sym.core.precision.HeldDigits`)."""
        vals = values_by_name(self.variables_all, values)
        failed = [c for c, t in zip(self.point_conditions, self.point_test) if not holds((t,), vals)]
        if failed:
            raise DomainError(f"{self.quantity} holds only where {', '.join(map(str, self.point_conditions))}; "
                              f"{', '.join(map(str, failed))} fails at {values}")
        if self.closed_form:
            with workdps(dps):
                v = sp.N(self.expr.xreplace(float_values(vals, dps + 20)), dps + 5)
                return held(real_mpf(v), dps)
        if self.reference is None:
            raise LineContactError(f"this {self.quantity} derivation has no reference quadrature (it was "
                                   f"unpickled, or made without one): evaluate it through its contact")
        return held(self.reference(vals, dps), dps)

    @property
    def point_conditions(self) -> tuple:
        """The conditions a point must meet for ``expr`` to hold (a < R,
        n < 2, ...), as stated: :attr:`conditions` without the relations
        between x and a (x < a), which state the quantity's domain (inside,
        outside the contact) and are decided there, edges included.  Every
        numeric path checks them (:attr:`point_test`): :meth:`evalf` refuses
        a point where one fails, the exports give NaN there."""
        return tuple(c for c in self.conditions
                     if c is not sp.true and not (S.x in c.free_symbols and c.free_symbols <= {S.x, S.a}))

    @property
    def point_test(self) -> tuple:
        """:attr:`point_conditions` with their edges: strict inequalities as
        non-strict (c_s < a as c_s <= a), since a closed form stated on an
        open set holds at its edge as a limit, or is not finite there."""
        closure = {sp.StrictLessThan: sp.LessThan, sp.StrictGreaterThan: sp.GreaterThan}

        def edge(c):
            return c.replace(lambda e: type(e) in closure, lambda e: closure[type(e)](*e.args))
        return tuple(edge(c) for c in self.point_conditions)

    @property
    def variables_all(self):
        syms = set(self.variables) if (self.variables and not self.closed_form) \
            else self.expr.free_symbols | set(self.variables)
        return tuple(sorted(syms, key=lambda s: s.name))

    @property
    def status(self) -> str:
        """One line: closed form or not, verified or not, with the numbers
        (points, digits) -- what a reader needs before trusting ``expr``."""
        v = self.verification
        if not self.closed_form:
            what = "no closed form: unevaluated integral, evaluated by quadrature"
        elif v is None:
            what = "closed form, not verified"
        elif not v.points:
            what = "closed form, NOT verified (0 points)"
        elif not v.passed:
            what = f"closed form, FAILED verification ({v.min_digits:.1f} digits)"
        else:
            what = f"closed form, verified at {len(v.points)} points (>= {v.min_digits:.0f} digits)"
            if v.certified_points:
                what += (f", certified by Arb enclosures at {v.certified_points} of them "
                         f"(>= {min(g for g in v.guaranteed if g > 0):.0f} digits guaranteed)")
        return f"{what}; rule {self.rule}"

    def _timing(self) -> str:
        where = {"memory": ", from this session's cache", "disk": ", from the disk cache"}.get(self.cached, "")
        return f"derived in {self.seconds:.2f} s{where}"

    def __repr__(self):
        """A few lines: the formula, its status and timing (the whole record
        is :meth:`summary`; the fields are attributes)."""
        cond = f"\n  holds for: {', '.join(map(str, self.conditions))}" if self.conditions else ""
        return (f"<Derivation {self.quantity} = {self.expr}\n  {self.status}{cond}\n"
                f"  {self._timing()}>")

    def summary(self) -> str:
        lines = [f"{self.quantity}: {self.expr}",
                 f"  method: {self.method}" + ("" if self.closed_form else " (no closed form)")]
        if self.conditions:
            lines.append("  holds for: " + ", ".join(map(str, self.conditions)))
        if self.verification is not None:
            lines.append("  " + str(self.verification))
        lines.append("  " + self._timing())
        lines += ["  note: " + n for n in self.notes]
        return "\n".join(lines)

    def _sympy_(self):
        """A Derivation takes part in SymPy arithmetic as its expression."""
        return self.expr

    def _repr_latex_(self):
        """Jupyter: ``quantity = formula`` and the status, in one line of
        LaTeX (math mode only: MathJax renders it as it is)."""
        from ..core.printing import to_latex
        v = self.verification
        if not self.closed_form:
            status = r"\text{no closed form (quadrature)}"
        elif v is not None and v.passed:
            status = rf"\text{{verified at {len(v.points)} points, }}\geq {v.min_digits:.0f}\text{{ digits}}"
            if v.certified_points:
                status += rf"\text{{ (Arb-certified at {v.certified_points})}}"
        elif v is not None and v.points:
            status = rf"\text{{FAILED verification, {v.min_digits:.1f} digits}}"
        else:
            status = r"\text{not verified}"
        name = self.quantity.replace("_", r"\_")
        return (rf"$\displaystyle \mathrm{{{name}}} = {to_latex(self.expr)}"
                rf"\qquad [{status};\ {self.seconds:.2f}\,\mathrm{{s}}]$")

    def __str__(self):
        return self.summary()


def fallback_step(why: str = "no closed form found") -> Step:
    """The step record of a result without closed form."""
    return Step(FALLBACK, sp.S.Zero, (), (why,))


def values_by_name(symbols, values):
    """THE binding of values: keyword values (by symbol name or Symbol) ->
    {Symbol: exact SymPy number}; text through the whitelisted parser, every
    number through the one converter
    (:func:`~linecontact_sym.core.conversion.point_value`: a float is its
    exact binary value, as in every evaluation path of the package); each
    checked against its symbol's sign
    (:func:`~linecontact_sym.core.ranges.check_sign`: R = -1 is refused here,
    for every path that binds values)."""
    by_name = {s.name: s for s in symbols}
    # values with units reach here only where they are not taken (a pull-off, a state): said, not misread
    refuse_units({str(k): v for k, v in values.items()}, "this result at values", S.UNITS)
    out = {}
    for k, v in values.items():
        sym = k if isinstance(k, sp.Symbol) else by_name.get(k)
        if sym is None:
            sym = sp.Symbol(k) if isinstance(k, str) else k
        try:
            out[sym] = check_sign(sym, point_value(to_sympy(v) if isinstance(v, str) else v))
        except DomainError:
            raise
        except LineContactError as exc:     # not a number (a list, an array): the user's input
            raise ClaimError(f"{sym.name}: {exc}") from None
        except (TypeError, ValueError) as exc:   # a value SymPy cannot convert (complex text, ...)
            raise DomainError(f"{sym.name} = {v!r} is not a real number ({exc})") from None
    missing = [s.name for s in symbols if s not in out]
    if missing:
        raise DomainError(f"missing values for {', '.join(missing)}")
    return out


# ------------------------------------------------------------------ tidy
def tidy(expr: sp.Expr) -> sp.Expr:
    """hyperexpand, then a moderate simplification (gamma functions, powers,
    :func:`compact`)."""
    expr = sp.hyperexpand(expr)
    if expr.has(sp.Piecewise):
        expr = sp.piecewise_fold(expr)
        if isinstance(expr, sp.Piecewise):
            return sp.Piecewise(*[(tidy(e), c) for e, c in expr.args])
    if expr.has(sp.gamma):
        expr = gammasimp_masked(expr)
    return compact(expr)


def gammasimp_masked(expr: sp.Expr) -> sp.Expr:
    """``sympy.gammasimp`` with every fractional power of a free symbol
    (a**(3/4)) held as a generic symbol of its own, restored after.

    gammasimp factors its whole argument (``sympy.factor``), and a sum of
    powers a**(p_i/q_i) is a polynomial in a**(1/lcm(q_i)) of degree up to
    lcm(q_i) max(p_i/q_i): a**(457/140) + a**(5/7) + a**(3/4), which the
    inverse map gives for f = x**(2/7) + x**(1/4) + x**(14/5) before
    tidying, is one of degree 457, and its factorization over the integers
    (Zassenhaus) took SymPy 150-300 CPU s (issue 26).  Masked, each power
    is a generator of degree 1 and the factorization is immediate.  The
    result is the same identity: whatever gammasimp proves for a generic
    symbol holds for the power put back in its place (the symbol is
    positive where the power is); what the mask hides, relations between
    powers of one symbol, is :func:`compact`'s work (``factor_terms``,
    ``powsimp``), which runs after."""
    if expr.has(sp.Integral, sp.Sum, sp.Product):     # bound symbols: not masked
        return sp.gammasimp(expr)
    free = expr.free_symbols
    powers = sorted((p for p in expr.atoms(sp.Pow) if p.base in free and p.exp.is_Rational
                     and not p.exp.is_Integer), key=sp.default_sort_key)
    masks = {p: sp.Dummy(positive=True) if p.is_positive else sp.Dummy() for p in powers}
    if not masks:
        return sp.gammasimp(expr)
    return sp.gammasimp(expr.xreplace(masks)).xreplace({m: p for p, m in masks.items()})


@functools.lru_cache(maxsize=4096)
def _ops(expr) -> int:
    """``count_ops`` of an expression, counted once (:func:`compact` weighs
    the same candidates again and again)."""
    return sp.count_ops(expr)


def _shortest(*choices):
    """The choice with the fewest operations (``count_ops``); the first on a tie."""
    return min(choices, key=_ops)


#: a product of a number and a sum, which ``factor_terms`` leaves "hollow": multiplied out
_HOLLOW_MUL = Transform(lambda w: sp.Mul(*w.args),
                        lambda w: w.is_Mul and len(w.args) == 2 and w.args[0].is_Number and w.args[1].is_Add)
_HANDLED = (sp.Add, sp.Mul, sp.Pow)


def compact(expr: sp.Expr) -> sp.Expr:
    """The shortest (``count_ops``) of a fixed set of rewritings of ``expr``:
    SymPy's ``simplify`` without its passes that do nothing on what the rules
    return, repeated at every level.  The arguments of every function first
    (recursively, as ``simplify`` does), then per node ``normal``, ``cancel``,
    ``together``, ``factor_terms``, ``expand_mul``, ``logcombine`` where there
    is a log, ``trigsimp``/``exptrigsimp`` only where there is a (hyperbolic)
    trigonometric function or exp, ``besselsimp`` where there is a Bessel
    function, ``powsimp`` (sqrt(a - x) sqrt(a + x) -> sqrt(a^2 - x^2)).
    Left out: ``hyperexpand`` and ``gammasimp`` (:func:`tidy` runs them once,
    not at every level of the argument recursion) and ``simplify``'s other
    passes (sums, products, Kronecker deltas, units).  Every candidate equals
    ``expr`` (each rewriting is an identity for positive symbols); never
    longer than ``expr``.  About half of ``simplify``'s CPU time on the seed
    derivations, as short or shorter (issue 26).  Four more candidates were
    dropped after they never won on the 18 seed forms (force, pressure, gap of
    six profiles: every form identical without them, a fifth less CPU): a
    ``powsimp`` before ``cancel`` (the one after ``trigsimp`` does its work),
    ``factor_terms`` of the cancelled form beside that of the shortest, and the
    second ``cancel`` and ``factor_terms`` of the final candidate."""
    if not isinstance(expr, sp.Expr) or expr.is_Atom or not expr.args:
        return expr
    original = expr
    expr = expr.replace(lambda w: isinstance(w, sp.Expr) and w.args and not isinstance(w, _HANDLED),
                        lambda w: w.func(*[compact(i) for i in w.args]), simultaneous=False)
    if not isinstance(expr, _HANDLED):
        return expr
    expr = bottom_up(expr, lambda w: getattr(w, "normal", lambda: w)())
    expr = sp.Mul(*expr.as_content_primitive())
    canc = sp.cancel(expr)
    expr1 = _shortest(canc, sp.expand_mul(sp.expand_multinomial(canc)).cancel())
    expr = _shortest(sp.together(expr, deep=True), sp.together(expr1, deep=True), expr1, expr)
    expr = sp.factor_terms(expr, sign=False)
    if expr.has(sp.log):
        expr = _shortest(sp.expand_log(expr, deep=True), sp.logcombine(expr))
    if expr.has(BesselBase):
        expr = sp.besselsimp(expr)
    if expr.has(TrigonometricFunction, HyperbolicFunction):
        expr = sp.trigsimp(expr, deep=True)
    short = _shortest(sp.powsimp(expr, combine="exp", deep=True), sp.powsimp(expr), expr) \
        if expr.has(sp.exp) else _shortest(sp.powsimp(expr), expr)
    short = _shortest(short, sp.expand_power_exp(sp.expand_mul(short)))
    if short.has(TrigonometricFunction, HyperbolicFunction, sp.exp):
        short = sp.exptrigsimp(short)
    expr = short.xreplace(_HOLLOW_MUL)
    if expr.could_extract_minus_sign():
        n, d = sp.fraction(expr)
        if d != 0:
            expr = sp.signsimp(-n / (-d))
    return _shortest(expr, original)


def _solve_for_a(cond):
    """monomial(a) < 1  ->  a < root, for positive symbols (e.g. a**2/R**2 < 1 -> a < R)."""
    if isinstance(cond, (sp.StrictLessThan, sp.LessThan)) and cond.rhs == 1 and S.a in cond.lhs.free_symbols:
        lhs = cond.lhs.func(*cond.lhs.args) if not isinstance(cond.lhs, sp.Abs) else cond.lhs.args[0]
        coef, dep = lhs.as_independent(S.a, as_Add=False)
        base, e = dep.as_base_exp()
        if base == S.a and e.is_positive and coef.is_positive:
            return cond.func(S.a, (1 / coef)**(1 / e))
    return cond


def _simple_relation(c):
    """``sp.simplify(c)``; for a relation between two symbols whose order the
    assumptions do not decide (x < a) its canonical form at once, which is
    what ``simplify`` returns after a costly search (``equals``, linear
    coefficients): a > x."""
    if isinstance(c, sp.core.relational.Relational) and c.lhs.is_Symbol and c.rhs.is_Symbol:
        d = c.lhs - c.rhs
        if d.is_positive is None and d.is_negative is None and d.is_zero is None:
            return c.canonical
    return sp.simplify(c)


def tidy_conditions(conds) -> tuple:
    """Simplify convergence conditions, solve monomials in a for a, drop the
    true ones; a condition that never holds means the integral diverges."""
    out = []
    for c in conds:
        try:
            c2 = _solve_for_a(_simple_relation(c))
        except Exception:
            c2 = c
        if c2 == sp.true:
            continue
        if c2 == sp.false:
            raise DivergentIntegralError(f"condition {c} never holds")
        if c2 not in out:
            out.append(c2)
    return tuple(out)


# ------------------------------------------------------------------ dispatch
@functools.cache
def _build_sympy_tables():
    """Build once in this process what SymPy builds on first use and the
    forked children of :func:`integrate` all use: ``hyperexpand``'s formula
    collection (with its imports, about 0.3 CPU s).  Built here, before the
    forks, every child inherits it; built in a child, it is lost with the
    child and the next child builds it again (issue 26: 2 CPU s of the 18
    seed derivations)."""
    z = sp.Dummy("z")
    sp.hyperexpand(sp.hyper([sp.S.Half], [sp.Rational(3, 2)], -z))


def integrate(problem: Problem, budget, rules=None, deadline: Deadline | None = None):
    """Try the rules of ``problem.transform`` in order, each under what
    remains of ``budget`` CPU seconds (or of ``deadline``, shared with the rest
    of a derivation); a rule whose ``applies()`` says no is skipped at once.
    Returns ``(step, attempts)``: the tidied :class:`~.rules.Step` of the
    first success (or None) and the list of ``(rule name, reason)`` of the
    rules that gave nothing.  The tidying runs in the same time; when none
    is left the result is returned as the rule gave it.
    :class:`~linecontact_sym.core.errors.DivergentIntegralError` propagates."""
    deadline = Deadline(budget) if deadline is None else deadline
    step, attempts, _ = _integrate(problem, deadline, rules, None)
    return step, attempts


class _Stop(Exception):
    """A stage of a derivation's child that leaves the rest to the parent."""


def _tidied(step):
    """The child's second stage: the rule's result tidied (as given where
    tidying fails), its conditions tidied (None where that raises: the parent
    does it again and raises), the CPU seconds left, and the rule's name and
    notes (so that the parent need not unpickle the rule's raw result)."""
    try:
        expr = tidy(step.expr)
    except Exception:
        expr = step.expr
    try:
        conds = tidy_conditions(step.conditions)
    except Exception:
        conds = None
    return expr, conds, child_left(), step.rule, step.notes


def _checking(check):
    """The child's third stage: ``check(expr, conditions)`` (the verification,
    in the child that derived and tidied the closed form); an exception is
    sent back to be raised in the parent, as a verification's child does."""
    def stage(tidied):
        expr, conds = tidied[:2]
        if conds is None:
            raise _Stop()
        try:
            return "record", check(expr, conds)
        except Exception as exc:
            return "raised", exc
    return stage


def _integrate(problem, deadline, rules, check):
    """:func:`integrate`, with ``check(expr, conditions)`` (or None) run on
    the tidied closed form in the same forked child
    (:func:`~linecontact_sym.core.budget.run_stages`: one fork for the rule,
    its tidying and its verification, each with what remains of the budget,
    as before).  Returns ``(step, attempts, checked)``: ``checked`` is
    ``("record", rec)``, ``("unfinished", budget)`` (begun, ended by the
    budget) or None (not begun: the caller verifies)."""
    attempts = []
    _build_sympy_tables()
    shown = "no limit" if deadline.budget is None else f"{deadline.budget:g} CPU s"
    stages = [None, _tidied] + ([_checking(check)] if check is not None else [])
    for rule in (RULES[problem.transform] if rules is None else rules):
        why = rule.applies(problem)
        if why is not None:
            attempts.append((rule.name, f"not applicable: {why}"))
            continue
        if deadline.expired(0.05):
            attempts.append((rule.name, "budget used up"))
            break
        seconds, cap = deadline.left(), rule.cap(problem)
        capped = cap is not None and (seconds is None or cap < seconds)
        try:
            results, started = run_stages([rule.run] + stages[1:], problem, seconds=cap if capped else seconds,
                                          lazy=True)
        except NotApplicable as exc:
            attempts.append((rule.name, f"not applicable: {exc}"))
            continue
        except BudgetExceeded as exc:
            within = f"{cap:g} CPU s (the rule's cap here)" if capped else shown
            attempts.append((rule.name, f"no result within {within}" + (f" ({exc})" if exc.wall_guard else "")))
            continue
        except DivergentIntegralError:
            raise
        except Exception as exc:  # a SymPy failure inside a rule
            attempts.append((rule.name, f"{type(exc).__name__}: {exc}"))
            continue
        conds, checked = None, None
        if len(results) > 1:      # tidied in the child: the rule's raw result is not unpickled unless needed
            expr, conds, left, name, notes = results[1].load()
            if len(results) > 2:
                checked = results[2].load()
                if checked[0] == "raised":
                    raise checked[1]
            elif started > 2:
                checked = ("unfinished", max(left, 0.05) if left is not None else math.inf)
        else:
            step = results[0].load()
            expr, name, notes = step.expr, step.rule, step.notes
            if started < 2 and not deadline.expired(0.05):
                try:
                    expr = run_with_budget(tidy, step.expr, seconds=deadline.left())
                except Exception:
                    expr = step.expr
        if conds is None:        # not tidied in the child (or it raised there): here, raising as it does
            conds, checked = tidy_conditions(results[0].load().conditions), None
        return Step(name, expr, conds, notes), attempts, checked
    return None, attempts, None


def derive(quantity: str, problem: Problem, *, reference, sampler, fallback: sp.Expr, budget,
           check: bool = True, points: int = 5, notes=(), variables=()) -> Derivation:
    """One transform carried out: :func:`integrate`, then verification of the
    closed form against ``reference`` at ``points`` points drawn by
    ``sampler`` (fewer than the required digits anywhere: the closed form is
    discarded and the note says so), else the ``fallback`` (the unevaluated
    defining integral, evaluated by ``reference``).

    Remembered (:mod:`.store`): the same problem (profile with its parameter
    ranges, force law, quantity, verification settings) is answered from the
    in-process memory or the on-disk cache, with this call's ``reference``;
    a result without closed form is derived again only under a larger
    budget than the one it ran out of.

    ``budget`` (CPU seconds > 0, or None: no limit; :mod:`~linecontact_sym.core.budget`)
    is the limit of the whole derivation: rules, tidying and verification,
    counted as the CPU time of this process and of the children doing them.  A closed form
    whose verification did not finish in what remained is not returned as
    verified: the unevaluated integral is, with a note."""
    with timing(new=False):
        return _derive_remembered(quantity, problem, reference, sampler, fallback, checked_budget(budget), check,
                           points, notes, variables)


def _derive_remembered(quantity, problem, reference, sampler, fallback, budget, check, points, notes, variables):
    deadline = Deadline(budget)
    key = store.make_key("derive", quantity, problem.transform, *_problem_parts(problem), fallback, check,
                         points, REQUIRED_DIGITS, tuple(notes), tuple(variables))
    rec = _trusted(store.get(key), reference, sampler, quantity)
    if rec is not None and _usable(rec, budget):
        return Derivation(quantity, expr=rec["expr"], closed_form=rec["closed_form"], step=rec["step"],
                          conditions=rec["conditions"], verification=rec["verification"], seconds=rec["seconds"],
                          notes=rec["notes"], reference=reference, variables=tuple(variables), attempts=rec["attempts"],
                          cached=rec["source"])
    with serialized():   # SymPy's symbolic work changes mpmath's precision (core.precision)
        d = _derive(quantity, problem, reference, sampler, fallback, deadline, check, points, notes, variables)
    store.put(key, {"expr": d.expr, "closed_form": d.closed_form, "step": d.step, "conditions": d.conditions,
                    "verification": d.verification, "seconds": d.seconds, "notes": d.notes,
                    "attempts": d.attempts, "budget": budget})
    return d


#: the re-check of a closed form read from disk: digits of the comparison, digits it must agree to
RECHECK_DPS, RECHECK_DIGITS = 20, 12
#: the fields a record of :func:`derive` holds, with their types
_RECORD_FIELDS = {"expr": sp.Basic, "closed_form": bool, "step": Step, "conditions": tuple,
                  "verification": (VerificationRecord, type(None)), "seconds": (int, float), "notes": tuple,
                  "attempts": tuple, "budget": (int, float, type(None))}


def _distrust(quantity, why):
    import warnings
    warnings.warn(f"linecontact_sym: the cached {quantity} record {why}; it is dropped and derived afresh",
                  store.UntrustedCacheWarning, stacklevel=5)
    return None


def _trusted(rec, reference, sampler, quantity):
    """A stored record of :func:`derive`, or None (derived afresh) when it is
    not one (a field missing or of another type), or when it was read from
    disk and its closed form, at one random admissible point, disagrees with
    this call's independent reference (a record whose number was changed and
    its checksum recomputed: the checksum only detects damage).  One point at
    :data:`RECHECK_DPS` digits: a quadrature, not a derivation."""
    if rec is None:
        return None
    for name, kind in _RECORD_FIELDS.items():
        if name not in rec or not isinstance(rec[name], kind):
            return _distrust(quantity, f"is not a record of a derivation ({name!r} missing or of another type)")
    if rec.get("source") != "disk" or not rec["closed_form"] or reference is None or sampler is None:
        return rec
    import random
    check = verify(rec["expr"], reference, sampler, rec["conditions"], n_points=1,
                   seed=random.SystemRandom().randrange(2**32), dps=RECHECK_DPS,
                   reference_name="re-check of a cached record", budget=60.0)
    if not check.points:
        return _distrust(quantity, "could not be re-checked against the independent reference "
                                   "(no admissible point, or out of time)")
    if check.min_digits < RECHECK_DIGITS:
        return _distrust(quantity, f"disagrees with the independent reference at {dict(check.points[0])} "
                                   f"({check.min_digits:.1f} digits agree): it was changed after it was written")
    return rec


def agrees_at_random_point(d, reference, sampler) -> bool:
    """Does a derivation read from disk agree with the independent
    ``reference`` at one random admissible point of ``sampler``
    (:data:`RECHECK_DIGITS` of :data:`RECHECK_DPS`)?  The checksum of a
    record only detects damage: a record whose closed form was changed (and
    its checksum recomputed) is dropped and derived afresh.  One point: a
    quadrature (or the reference's own search), not a derivation."""
    import random
    if reference is None:
        return True
    check = verify(d.expr, reference, sampler, d.conditions, n_points=1, seed=random.SystemRandom().randrange(2**32),
                   dps=RECHECK_DPS, reference_name="re-check of a cached record", budget=60.0)
    return bool(check.points) and check.min_digits >= RECHECK_DIGITS


def remembered(parts, make, budget, reference, recheck=None, sampler=None) -> Derivation:
    """A derivation made by ``make()`` once per key (:mod:`.store`: in this
    process and on disk), for quantities derived outside :func:`derive`
    (the half-width, the tangential stick half-width ...).  ``parts`` name
    the problem completely (the key adds the code version); ``budget`` is
    the caller's (a result that ran out of time is made again under a
    larger one); ``reference(derivation)`` rebuilds the numeric reference
    of a stored derivation (closures are not stored); ``recheck(derivation)``
    (optional) tells whether a closed form read from disk agrees with an
    independent check at a random point (else it is dropped and made
    afresh, with a warning: see :func:`_trusted`); without one, ``sampler``
    (random admissible points) makes it :func:`agrees_at_random_point` with
    the rebuilt reference, so that every closed form read from disk is
    re-checked, as the README says."""
    def rebuild(d):
        d.reference = reference(d)
        return d
    return remembered_many(parts, lambda: (make(),), budget, rebuild, recheck, sampler)[0]


def remembered_many(parts, make, budget, rebuild, recheck=None, sampler=None) -> tuple:
    """:func:`remembered` for derivations made together (the three pull-off
    quantities): ``make()`` returns a tuple of them; ``rebuild(d)`` returns
    a stored one ready for use (its reference set, its class restored);
    ``recheck(d)`` or ``sampler`` as in :func:`remembered`, for each closed
    form read from disk."""
    if recheck is None and sampler is not None:
        def recheck(d):
            return agrees_at_random_point(d, d.reference, sampler)
    key = store.make_key("remembered", *parts)
    rec = store.get(key)
    if rec is not None and not _derivations_record(rec):
        rec = _distrust("derivations", "is not a record of derivations")
    if rec is not None and "derivations" in rec and all(_usable({**r, "source": rec["source"]}, budget)
                                                            for r in rec["derivations"]):
        ds = tuple(rebuild(Derivation(r["quantity"], expr=r["expr"], closed_form=r["closed_form"], step=r["step"],
                                      conditions=r["conditions"], verification=r["verification"],
                                      seconds=r["seconds"], notes=r["notes"], variables=r["variables"],
                                      attempts=r["attempts"], cached=rec["source"]))
                   for r in rec["derivations"])
        bad = [d.quantity for d in ds if rec["source"] == "disk" and recheck is not None and d.closed_form
               and not recheck(d)]
        if not bad:
            return ds
        _distrust(", ".join(bad), "disagrees with its independent check at a random point: it was changed "
                                  "after it was written")
    ds = tuple(make())
    store.put(key, {"derivations": tuple(
        {"quantity": d.quantity, "expr": d.expr, "closed_form": d.closed_form, "step": d.step,
         "conditions": tuple(d.conditions), "verification": d.verification, "seconds": d.seconds,
         "notes": tuple(d.notes), "variables": tuple(d.variables), "attempts": tuple(d.attempts),
         "budget": checked_budget(budget)} for d in ds)})
    return ds


def _derivations_record(rec) -> bool:
    """Does a stored record of :func:`remembered_many` hold a non-empty tuple
    of derivation records with every field of its expected type?"""
    ds = rec.get("derivations")
    if not isinstance(ds, tuple) or not ds:
        return False
    fields = {**_RECORD_FIELDS, "quantity": str, "variables": tuple}
    return all(isinstance(r, dict) and all(n in r and isinstance(r[n], k) for n, k in fields.items())
               for r in ds)


def _problem_parts(problem):
    prof = problem.profile
    if prof is None:
        return (None, None, problem.force_law)
    return (prof.expr, dict(prof.ranges), problem.force_law)


def _budget_limited(attempts) -> bool:
    return any("no result within" in why or "budget used up" in why or "did not finish" in why
               for _, why in attempts)


def _guard_fired(attempts) -> bool:
    return any("wall-clock guard" in why for _, why in attempts)


def _usable(rec, budget) -> bool:
    """A stored result answers a call unless it gave up for lack of time and
    this call allows more.  Budgets are CPU seconds (:mod:`~linecontact_sym.core.budget`),
    so how far a rule gets does not depend on the machine's load, and a
    result cut short by its budget is carried across processes like any
    other.  The one exception is a step stopped by the wall-clock guard
    against a hang: that may depend on the load, so such a result is not
    taken from the disk (a new process tries again; within one process
    nothing waits twice)."""
    if rec["closed_form"]:
        return True
    timed_out = _budget_limited(rec["attempts"]) or (
        rec["verification"] is not None and not rec["verification"].points)
    if _guard_fired(rec["attempts"]) and rec.get("source") == "disk":
        return False
    more = budget is None if rec["budget"] is not None else False
    return not (timed_out and (more or (budget is not None and budget > rec["budget"])))


def _derive(quantity, problem, reference, sampler, fallback, deadline, check, points, notes, variables):
    name = f"the defining integral ({quantity})"
    # the references at the verification points do not depend on the closed form: a second child
    # computes them while the rules run (core.budget.Ahead: their CPU time charged when taken)
    ahead = Ahead(references_ahead(reference, sampler, points), deadline.left()) \
        if check and reference is not None and sampler is not None and forks(deadline.left()) else None

    def checking(expr, conds):
        return verify_here(expr, reference, sampler, conds, n_points=points, reference_name=name, ahead=ahead)
    try:
        step, attempts, checked = _integrate(problem, deadline, None, checking if check else None)
    finally:
        if ahead is not None:
            ahead.close()
    rec = None
    extra = []
    if step is not None and check:
        if checked is None:       # not begun in the rule's child: here, with what remains
            left = deadline.left()
            rec = verify(step.expr, reference, sampler, step.conditions, n_points=points, reference_name=name,
                         budget=max(left, 0.05) if left is not None else None)
        elif checked[0] == "unfinished":
            rec = unfinished(VERIFY_DPS, name, checked[1])
        else:
            rec = checked[1]
        if not rec.passed and not rec.points:
            attempts.append((step.rule, f"closed form not verified: the verification did not finish in "
                                        f"the budget's remaining time: {step.expr}"))
            extra.append(f"closed form from {step.rule} found but not verified within the budget; "
                         f"returned unevaluated (a larger budget verifies it): {step.expr}")
            step = None
        elif not rec.passed:
            attempts.append((step.rule, f"closed form FAILED verification ({rec.min_digits:.1f} digits): "
                                        f"{step.expr}"))
            extra.append(f"closed form from {step.rule} FAILED verification ({rec.min_digits:.1f} digits); "
                         f"returned unevaluated: {step.expr}")
            step = None
    if step is None:
        reasons = tuple(f"{r}: {why}" for r, why in attempts)
        return Derivation(quantity, expr=fallback, closed_form=False, step=fallback_step(), verification=rec,
                          notes=tuple(extra) + reasons + tuple(notes), reference=reference, variables=tuple(variables),
                          attempts=tuple(attempts))
    return Derivation(quantity, expr=step.expr, closed_form=True, step=step, conditions=step.conditions,
                      verification=rec, notes=tuple(notes), reference=reference, variables=tuple(variables),
                      attempts=tuple(attempts))
