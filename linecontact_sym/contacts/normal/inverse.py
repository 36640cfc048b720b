"""The inverse map, Eq. (9): the profile whose line contact has a given
force law."""
from __future__ import annotations

import random

import sympy as sp

from ...core import symbols as S
from ...core.budget import DEFAULT_BUDGET, checked_budget, run_with_budget
from ...core.conversion import rational
from ...core.errors import BudgetExceeded, InadmissibleProfileError, ProfileError
from ...method import transforms as T
from ...method.derivation import Derivation, derive, fallback_step, remembered, timed
from ...method.geometry import Periodic
from ...method.profile import Profile, check_depth
from ...method.rules import Problem, Step
from .tan_route import TanRoute
from ...method.verification import verify
from .equilibria import half_width_at
from .force_law import ForceLaw


@timed
def profile_from_force(force_law, params=None, budget: float = DEFAULT_BUDGET,
                       verify_points: int = 5, period=None) -> Derivation:
    """Eq. (9): the profile f(x) whose contact has the force law ``force_law``
    (a SymPy expression in ``a``), f(a) = (2a/(pi E*)) int_0^a P(s)/(s sqrt(a^2 - s^2)) ds.
    Returns a :class:`~linecontact_sym.method.derivation.Derivation` whose
    ``expr`` is f(x) (closed form, verified) or the unevaluated Eq. (9).

    >>> import linecontact_sym as lcs, sympy as sp
    >>> R = sp.Symbol("R", positive=True)
    >>> profile_from_force(sp.pi*lcs.E_star*lcs.a**2/(4*R)).expr
    x**2/(2*R)

    ``period=L``: the profile of a periodic array whose load per period is
    ``force_law`` (:func:`periodic_profile_from_force`).
    """
    if period is not None:
        return periodic_profile_from_force(force_law, period, params, budget, verify_points)
    if isinstance(force_law, str) or not isinstance(force_law, sp.Basic):
        raise ProfileError(f"the force law must be a SymPy expression in a, got {force_law!r}")
    free = force_law.free_symbols - {S.a, S.E_star}
    declared = set(params or ())
    for s in free:
        if s not in declared and not s.is_positive:
            raise ProfileError(f"force law {force_law} holds the unknown symbol {s}; declare it "
                               f"with params=[{s}] or make it positive=True")
    check_depth(force_law, "the force law")
    if S.a not in force_law.free_symbols:
        raise ProfileError(f"the force law {force_law} does not depend on a")
    psyms = tuple(sorted(free, key=lambda s: s.name))

    def sampler(rng):
        vals = {p: rational(rng.uniform(0.5, 2.5)) for p in psyms}
        vals[S.E_star] = rational(rng.uniform(0.5, 3))
        vals[S.a] = rational(rng.uniform(0.05, 1.5))
        return vals

    def reference(vals, dps):
        fixed = {k: v for k, v in vals.items() if k != S.a}
        Pf = sp.lambdify(S.a, force_law.xreplace(fixed), "mpmath")
        return T.profile_quad(Pf, [], vals, dps)
    _check_pushes(force_law, sampler)

    def reference_in_x(vals, dps):
        return reference({**vals, S.a: vals[S.x]}, dps)
    d = derive("profile", Problem("profile", force_law=force_law), reference=reference, sampler=sampler,
               fallback=T.profile_integral(force_law), budget=budget, points=verify_points,
               variables=(S.a, S.E_star) + psyms)
    variables = (S.x, S.E_star) + psyms
    if not d.closed_form:
        return Derivation("profile", expr=d.expr.subs(S.a, S.x), closed_form=False, step=d.step,
                          verification=d.verification, seconds=d.seconds, notes=d.notes, reference=reference_in_x,
                          variables=variables, attempts=d.attempts, cached=d.cached)
    sub = {S.a: S.x}  # the profile is reported in x
    step = Step(d.step.rule, d.expr.xreplace(sub), tuple(c.xreplace(sub) for c in d.conditions), d.step.notes)
    return Derivation("profile", expr=step.expr, closed_form=True, step=step, conditions=step.conditions,
                      verification=d.verification, seconds=d.seconds, notes=d.notes, reference=reference_in_x,
                      variables=variables, attempts=d.attempts, cached=d.cached)


def _check_pushes(force_law, sampler, points: int = 5):
    """A frictionless contact pushes: P(a) > 0 and dP/da >= 0 (the contact
    grows with the load).  A force law negative or decreasing at random
    admissible points (``-a**2``) has no profile: Eq. (9) would return a
    decreasing one (``-2 x**2/(pi E*)``), which is no contact of this law.
    Raises :class:`~linecontact_sym.core.errors.InadmissibleProfileError`
    naming the point; a point where the law is not real (outside its
    domain) or SymPy cannot evaluate it is not judged."""
    rng = random.Random(9)
    dP = sp.diff(force_law, S.a)
    real = judged = 0
    for _ in range(points):
        vals = sampler(rng)
        try:
            Pv, dv = (complex(sp.N(e.xreplace(vals), 20)) for e in (force_law, dP))
        except (TypeError, ValueError):
            continue
        judged += 1
        if abs(Pv.imag) > 1e-12 * max(1.0, abs(Pv.real)) or abs(dv.imag) > 1e-12 * max(1.0, abs(dv.real)):
            continue                  # outside the law's real domain there (the exact cylinder at a > R)
        real += 1
        if Pv.real < -1e-12 * max(1.0, abs(dv.real)) or dv.real < -1e-12 * max(1.0, abs(dv.real)):
            shown = ", ".join(f"{k} = {sp.N(v, 6)}" for k, v in sorted(vals.items(), key=lambda kv: kv[0].name))
            what = "negative" if Pv.real < 0 else "decreasing"
            raise InadmissibleProfileError(
                f"the force law P(a) = {force_law} is {what} at {shown}: a frictionless contact pushes, with "
                f"P(a) >= 0 growing with the half-width; no profile has this law (Eq. 9 would return a "
                f"profile that decreases, not a contact of it)")
    if judged and not real:
        raise InadmissibleProfileError(f"the force law P(a) = {force_law} is not real at any of {judged} random "
                                       f"points: no profile has it")


def periodic_profile_from_force(force_law, period, params=None, budget: float = DEFAULT_BUDGET,
                                verify_points: int = 5) -> Derivation:
    """Eq. (9) for a periodic array (:mod:`~linecontact_sym.method.geometry`):
    Q(S) = P((L/pi) asin S) is the force law of the kernel twin, Eq. (9)
    gives its profile F(s), and f(x) = F(sin(pi x/L)); the result is
    verified against the tan route's force law of f
    (:mod:`~linecontact_sym.contacts.normal.tan_route`) at random a in (0, 0.46 L).

    >>> import linecontact_sym as lcs, sympy as sp
    >>> h, L = sp.symbols("h L", positive=True)
    >>> profile_from_force(sp.pi*lcs.E_star*h*sp.sin(sp.pi*lcs.a/L)**2, period=L).expr
    2*h*sin(pi*x/L)**2
    """
    g = Periodic(period)
    Q = sp.simplify(force_law.xreplace({S.a: g.x_of(S.a)}))
    kd = profile_from_force(Q, params, budget, verify_points)
    variables = (S.x, S.E_star) + tuple(sorted((force_law.free_symbols | set(g.symbols)) - {S.a, S.E_star},
                                                key=lambda v: v.name))
    if not kd.closed_form:
        return Derivation("profile", expr=kd.expr.xreplace({S.x: g.s(S.x)}), closed_form=False, step=kd.step,
                          notes=kd.notes + ("the kernel twin's Eq. (9) in s = sin(pi x/L)",),
                          variables=variables, attempts=kd.attempts)
    f = kd.expr.xreplace({S.x: g.s(S.x)})
    psyms = tuple(v for v in variables if v not in (S.x, S.E_star))

    def sampler(rng):
        vals = {p: rational(rng.uniform(0.5, 2.5)) for p in psyms}
        vals[S.E_star] = rational(rng.uniform(0.5, 3))
        vals[S.a] = rational(float(sp.N(g.period.xreplace(vals))) * rng.uniform(0.02, 0.46))
        return vals

    def reference(vals, dps):
        prof = Profile(f.xreplace({p: vals[p] for p in psyms}))
        return TanRoute(prof, vals, g.period.xreplace(vals)).force(vals[S.a], dps)
    rec = verify(force_law, reference, sampler, (), n_points=verify_points,
                 reference_name="the tan route's force law of the profile found (contacts.normal.tan_route)")
    step = Step("periodic_map", f, (), (f"Eq. (9) of the kernel twin Q(S) = {Q}: {kd.method}; "
                                        f"F(s) -> F(sin(pi x/L))",))
    if not rec.passed:
        return Derivation("profile", expr=kd.expr.xreplace({S.x: g.s(S.x)}), closed_form=False,
                          step=fallback_step(f"the profile found, {f}, FAILED verification against the tan route "
                                             f"({rec.min_digits:.1f} digits)"), verification=rec,
                          variables=variables)
    return Derivation("profile", expr=f, closed_form=True, step=step, verification=rec, variables=variables,
                      notes=kd.notes)


@timed
def derive_half_width(contact, load=S.P, budget=None) -> Derivation:
    """The half-width a(P) of a frictionless contact: the closed-form inverse of
    the force law where ``sympy.solve`` finds one (under ``budget`` seconds,
    default the contact's), each candidate checked by substitution at random
    points (P(a(P)) = P to the contact's digits), else the unevaluated
    P(a) = P with a numeric root as reference.  Remembered in memory and on
    disk (:func:`~linecontact_sym.method.derivation.remembered`)."""
    budget = contact.budget if budget is None else checked_budget(budget)
    fd = contact.derivation("force")
    parts = ("half_width", contact.profile.expr, dict(contact.profile.ranges), fd.expr, load, contact.points,
             contact.digits)
    return remembered(parts, lambda: _derive_half_width(contact, load, fd, budget), budget,
                      lambda d: _half_width_reference(contact, load),
                      recheck=lambda d: _inverts(contact, load, fd, d.expr, random.SystemRandom().randrange(2**32),
                                                 1, 15))


def _half_width_reference(contact, load):
    def reference(vals, dps):
        fixed = {k: v for k, v in vals.items() if k != load}
        law = ForceLaw.from_contact(contact, fixed)
        return half_width_at(law, vals[load], dps)
    return reference


def _derive_half_width(contact, load, fd, budget) -> Derivation:
    expr, notes, attempts = None, [], []
    if fd.closed_form and not fd.expr.has(sp.Piecewise):
        try:
            sols = run_with_budget(_solve_for_a, fd.expr, load, seconds=budget)
        except BudgetExceeded:
            sols = []
            shown = "no limit" if budget is None else f"{budget:g} s"
            notes.append(f"sympy.solve found nothing within {shown}")
            attempts.append(("solve_force_law", f"no result within {shown}"))
        except (NotImplementedError, ValueError, TypeError) as exc:
            sols = []
            notes.append(f"sympy.solve: {exc}".splitlines()[0])
        for cand in sols:
            if _inverts(contact, load, fd, cand, 7, contact.points, contact.digits):
                expr = cand
                break
    reference = _half_width_reference(contact, load)
    variables = (load,) + contact.variables
    if expr is not None:
        step = Step("solve_force_law", expr, (), ("sympy.solve of P(a) = P, root checked by substitution "
                                                  "at random points",))
        return Derivation("half_width", expr=expr, closed_form=True, step=step, notes=tuple(notes), reference=reference,
                          variables=variables)
    return Derivation("half_width", expr=sp.Eq(fd.expr, load), closed_form=False,
                      step=fallback_step("numeric root of P(a) = P (no closed-form inverse)"), notes=tuple(notes),
                      reference=reference, variables=variables, attempts=tuple(attempts))


def _inverts(contact, load, fd, cand, seed, points, digits) -> bool:
    """Does ``cand`` = a(P) invert the force law, a(P(a)) = a to ``digits``
    digits at ``points`` random admissible points (``seed``)?  The check of a
    candidate found by ``sympy.solve``, and of a closed form read from disk."""
    sample = contact._sampler()
    rng = random.Random(seed)
    good = 0
    for _ in range(points):
        vals = sample(rng)
        if vals is None:
            continue
        Pv = sp.N(fd.expr.xreplace(vals), 60)
        av = sp.N(cand.xreplace({**vals, load: Pv}), 60)
        if av.is_real and abs(av - vals[S.a]) <= abs(vals[S.a]) * sp.Float(10)**(-digits):
            good += 1
    return good == points


def _solve_for_a(Pexpr, load):
    sols = sp.solve(sp.Eq(Pexpr, load), S.a)
    return [sp.simplify(s) for s in sols]


__all__ = ["profile_from_force", "periodic_profile_from_force", "derive_half_width"]
