"""Verification: every closed form is compared with an independent
high-precision evaluation of its defining integral (or another route that
shares nothing with the derivation) at random admissible points.

A reference returns a number (an estimate: mpmath quadrature) or an
enclosure (an object with ``mid``, ``rad``, ``certified`` and ``digits``:
:class:`linecontact_sym.numeric.reference.RefValue`, Arb ball quadrature).
Against an enclosure the closed form is *certified*: its value must lie in
the ball (a wrong coefficient 1e-35 off fails even though 35 digits agree),
and the record keeps the digits each ball guarantees.

A :class:`VerificationRecord` with no points never counts as verified.
"""
from __future__ import annotations

import math
import random
from dataclasses import dataclass

import mpmath
import sympy as sp

from ..core.budget import charge_child, run_with_budget
from ..core.conversion import float_values, real_mpf
from ..core.errors import BudgetExceeded, DomainError
from ..core.precision import workdps

#: digits every closed form must reproduce at every verification point
REQUIRED_DIGITS = 30
#: working precision of the reference quadratures: the digits an Arb enclosure is asked for.  40 keeps
#: a margin of 10 over :data:`REQUIRED_DIGITS` and is still tight enough that a closed form one part in
#: 10**35 off lies outside every enclosure; 45 cost a quarter more Arb work for nothing (issue 26)
VERIFY_DPS = 40
#: budget of one verification (quadratures at all points), CPU seconds (core.budget)
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
    #: digits the reference guarantees at each point (Arb's enclosure; 0 where
    #: the point's reference is an mpmath estimate); empty: no enclosures
    guaranteed: tuple = ()
    #: number of points whose enclosure does NOT contain the closed form's value
    outside: int = 0

    @property
    def certified(self) -> bool:
        """Every point checked against a rigorous enclosure that holds the value."""
        return self.passed and bool(self.guaranteed) and len(self.guaranteed) == len(self.points) and \
            min(self.guaranteed) > 0

    @property
    def certified_points(self) -> int:
        return sum(1 for g in self.guaranteed if g > 0)

    @property
    def min_digits(self) -> float:
        return min(self.digits) if self.digits else 0.0

    @property
    def passed(self) -> bool:
        return bool(self.digits) and self.min_digits >= self.required and not self.outside

    def _how(self):
        n, k = len(self.points), self.certified_points
        if k == n:
            return f"Arb ball quadrature of {self.reference}"
        if k:
            return f"{self.reference}: Arb ball quadrature at {k} of {n} points, mpmath quadrature at the others"
        return f"mpmath quadrature of {self.reference}"

    def __str__(self):
        if not self.points:
            return (f"NOT verified: no admissible point could be checked against {self.reference} "
                    f"(a verification with 0 points never counts)")
        if self.outside:
            return (f"FAILED certification at {len(self.points)} random admissible points: at {self.outside} "
                    f"of them the closed form lies outside the enclosure of the {self._how()} "
                    f"({self.min_digits:.1f} digits agree)")
        if not self.passed:
            return (f"FAILED verification at {len(self.points)} random admissible points against "
                    f"{self._how()} ({self.dps} digits): only {self.min_digits:.1f} digits agree "
                    f"(required {self.required})")
        if self.certified:
            return (f"certified at {len(self.points)} random admissible points by {self._how()} "
                    f"({self.dps} digits): every enclosure contains the closed form's value, "
                    f">= {min(self.guaranteed):.1f} digits guaranteed, >= {self.min_digits:.1f} digits agree")
        return (f"verified at {len(self.points)} random admissible points against "
                f"{self._how()} ({self.dps} digits): >= {self.min_digits:.1f} digits agree")



def holds(conds, vals) -> bool:
    """Do all relations ``conds`` hold at the point ``vals`` (False when undecidable)?"""
    for c in conds:
        v = c.xreplace(vals)
        try:
            v = bool(v) if v in (sp.true, sp.false) else bool(sp.simplify(v))
        except TypeError:
            return False
        if not v:
            return False
    return True


def at_point(expr, vals):
    """``expr.xreplace(vals)``, where a Piecewise is first decided at the
    point: the first branch whose condition becomes True (after those that
    become False) is the one substituted, as the Piecewise of the
    substituted branches would evaluate to, without substituting into (and
    evaluating in SymPy's Float arithmetic) the branches not taken; a
    condition left undecided substitutes the whole Piecewise."""
    if isinstance(expr, sp.Piecewise):
        for e, c in expr.args:
            cv = c.xreplace(vals)
            if cv is sp.true:
                return at_point(e, vals)
            if cv is not sp.false:
                break
    return expr.xreplace(vals)


def digits_agreeing(val, ref, dps=None) -> float:
    """Agreeing significant digits of ``val`` and ``ref`` (capped at ``dps``,
    default the current working precision; a reference below 10**(-dps/2)
    is compared absolutely)."""
    dps = mpmath.mp.dps if dps is None else dps
    with workdps(dps):
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


def verify_here(expr, reference, sampler, conditions=(), n_points: int = 5, seed: int = 2017,
                dps: int = VERIFY_DPS, reference_name: str = "mpmath quadrature", ahead=None) -> VerificationRecord:
    """:func:`verify` in this process, under whatever budget bounds it (a
    derivation's forked child, :func:`~linecontact_sym.core.budget.run_stages`,
    which verifies in the child that derived and tidied the closed form).
    ``ahead``: the references done ahead by :func:`references_ahead` with the
    same ``reference``, ``sampler``, ``n_points``, ``seed`` and ``dps``
    (a :class:`~linecontact_sym.core.budget.Ahead`), taken instead of
    computed here (their CPU time charged to this budget): the same record."""
    return _verify({"_": expr}, lambda vals, d: {"_": reference(vals, d)}, sampler, conditions, n_points, seed,
                   dps, lambda k: reference_name, _Taken(ahead) if ahead is not None else None)["_"]


def references_ahead(reference, sampler, n_points: int = 5, seed: int = 2017, dps: int = VERIFY_DPS):
    """The work of a :class:`~linecontact_sym.core.budget.Ahead` for
    :func:`verify_here`: ``reference(values, dps)`` at the candidate points
    in the order the verification draws them (the sampler's, from the same
    seed; the points do not depend on the closed form), until ``n_points``
    gave a usable reference.  Yields ``(k, values, reference or None)``: k
    the candidate's number, None where the reference raised one of the
    errors that make the verification skip a point.  The closed form's
    conditions may exclude some of these points; the verification then
    computes the references of the further points itself.  The CPU time
    charged for an item is that of producing it: the reference and the
    sampler's draw (a few ms, which the verification spends again drawing
    the same point: a charge a little above the work it replaces)."""
    def produce():
        rng = random.Random(seed)
        usable = 0
        for k in range(20 * n_points):
            if usable >= n_points:
                return
            vals = sampler(rng)
            if vals is None:
                continue
            try:
                ref = reference(vals, dps)
            except (ZeroDivisionError, ValueError, DomainError):
                ref = None
            yield k, vals, ref
            usable += ref is not None and _usable({"_": ref})
    return produce


class _Taken:
    """The verification's side of the references done ahead: the one for
    candidate k (None: not done ahead, computed here).  A reference taken is
    charged to this process's budget (:func:`~linecontact_sym.core.budget.charge_child`);
    those of candidates the conditions excluded are passed over uncharged,
    as the verification would not have computed them."""

    def __init__(self, ahead):
        self.ahead, self.next = ahead, None

    def get(self, k, vals):
        while True:
            if self.next is None:
                self.next = self.ahead.take()
                if self.next is None:
                    return None
            (j, jvals, ref), secs = self.next
            if j > k:
                return None
            self.next = None
            if j == k:
                if jvals != vals:
                    return None
                charge_child(secs)
                return ("skip",) if ref is None else ("ok", {"_": ref})


def _usable(refs) -> bool:
    mids = [getattr(r, "mid", r) for r in refs.values()]
    return not any(not mpmath.isfinite(r) or isinstance(r, mpmath.mpc) for r in mids)


def unfinished(dps: int, reference_name: str, budget) -> VerificationRecord:
    """The record of a verification that did not finish in ``budget`` CPU s
    (no points: never counts as verified)."""
    return VerificationRecord((), (), dps, reference_name + f" (did not finish in {budget:g} CPU s)")


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
        return {k: unfinished(dps, name(k), budget) for k in exprs}


def _verify(exprs, reference, sampler, conditions, n_points, seed, dps, name, taken=None):
    rng = random.Random(seed)
    points, digits = [], {k: [] for k in exprs}
    guaranteed, outside = {k: [] for k in exprs}, {k: 0 for k in exprs}
    tries = 0
    while len(points) < n_points and tries < 20 * n_points:
        tries += 1
        vals = sampler(rng)
        if vals is None or not holds(conditions, vals):
            continue
        got = taken.get(tries - 1, vals) if taken is not None else None
        if got is not None:
            if got[0] == "skip":
                continue
            refs = got[1]
        else:
            try:
                refs = reference(vals, dps)
            except (ZeroDivisionError, ValueError, DomainError):
                continue
        if not _usable(refs):
            continue
        mids = {k: getattr(r, "mid", r) for k, r in refs.items()}
        points.append(vals)
        fvals = float_values(vals, dps + 30)
        for k, expr in exprs.items():
            with workdps(dps + 10):
                try:
                    val = real_mpf(sp.N(at_point(expr, fvals), dps + 10))
                except (DomainError, TypeError, ValueError):
                    val = mpmath.mpf("nan")
            with workdps(dps):
                digits[k].append(digits_agreeing(val, mids[k], dps))
            ref = refs[k]
            if getattr(ref, "certified", False):
                guaranteed[k].append(min(ref.digits, float(dps)))    # capped as the agreement is
                # the closed form's own value is good to dps + 10 digits (sp.N)
                slack = abs(val) * mpmath.mpf(10) ** -(dps + 5) if mpmath.isfinite(val) else 0
                if not mpmath.isfinite(val) or not ref.contains(val, slack):
                    outside[k] += 1
            else:
                guaranteed[k].append(0.0)
    return {k: VerificationRecord(tuple(points), tuple(digits[k]), dps, name(k), REQUIRED_DIGITS,
                                  tuple(guaranteed[k]), outside[k]) for k in exprs}
