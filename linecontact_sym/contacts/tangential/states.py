"""The derivations' machinery of the tangential line contact
(:mod:`.tangential`): the verification points and the references (independent
checks, and numeric values where there is no closed form), the energy and
loop-displacement forms from the force law, and the stick half-width.  The
load histories at numbers are in :mod:`.history`."""
from __future__ import annotations

import mpmath
import sympy as sp

from ...core import symbols as S
from ...core.budget import Deadline, checked_budget, run_with_budget
from ...core.conversion import float_values, rational, to_mpf
from ...core.errors import BudgetExceeded, DomainError
from ...method import transforms as T
from ...method.derivation import Derivation, fallback_step, remembered, timed
from ...method.rules import Step
from ...method.verification import verify
from ...numeric.functions import make_callable
from ...numeric.reference import estimate, lincomb
from . import reference as ref
from ..normal.equilibria import half_width_at
from ..normal.force_law import ForceLaw
from ..sampling import point_sampler
from ...core.precision import workdps
from ...core.roots import root_in_log

#: the conditions of validity, attached to every tangential derivation
CONDITIONS = ("valid for: plane strain; elastically similar bodies or Dundurs' beta neglected; Coulomb friction "
              "mu; constant normal load (half-width a); symmetric profile, compact contact, frictionless solution "
              "admissible and force law non-decreasing on [c_s, a]; no adhesion")


# =====================================================================  numbers
def _fixed(t, vals) -> dict:
    """The values of E_star and the profile's parameters (Symbol -> number)."""
    keep = set(t.contact.variables)
    return {k: v for k, v in vals.items() if k in keep}


def friction_at(t, vals):
    return to_mpf(sp.N(t.mu.xreplace(float_values(vals, mpmath.mp.dps + 10)), mpmath.mp.dps + 5))


def _breaks(t, vals):
    return [to_mpf(sp.N(bp.xreplace(vals), mpmath.mp.dps + 5)) for bp in t.profile.breakpoints]


def force_law_at(t, vals) -> ForceLaw:
    """The numeric force law at the values (cached on the contact per values and precision)."""
    fixed = _fixed(t, vals)
    key = ("force_law_at", mpmath.mp.dps, tuple(sorted((k.name, str(v)) for k, v in fixed.items())))
    if key not in t._cache:
        t._cache[key] = ForceLaw.from_contact(t.contact, float_values(fixed, mpmath.mp.dps + 20))
    return t._cache[key]


def normal_fn(t, name, vals, A):
    """An mpmath callable X -> the normal ``name`` ('pressure' or 'gap') at the
    half-width A: the engine's closed form, else the quadrature of Eq. (12) or
    of the outside gap with the numeric force law."""
    d = t.contact.derivation(name)
    fixed = _fixed(t, vals)
    if d.closed_form:   # the package's stable form (e.g. no atanh(1.0) at x -> 0 for the wedge)
        dps = mpmath.mp.dps
        fn = make_callable(d, "mpmath", dps, {k.name: to_mpf(sp.N(v, dps + 5)) for k, v in fixed.items()})
        A = to_mpf(A)
        return lambda X: mpmath.re(fn(a=A, x=X))
    law = force_law_at(t, vals)
    brs = law.breaks()
    if name == "pressure":   # zero on and beyond the edge (rounding may put X a hair past A)
        return lambda X: T.pressure_quad(law.dP, brs, {S.a: A, S.x: X}, mpmath.mp.dps) if abs(X) < A \
            else mpmath.mpf(0)
    f = t.profile.mp_callable(float_values(fixed, mpmath.mp.dps + 20))
    E = to_mpf(sp.N(fixed[S.E_star], mpmath.mp.dps + 5))
    return lambda X: T.gap_quad(f, law.dP, brs, {S.a: A, S.x: X, S.E_star: E}, mpmath.mp.dps)


_x = sp.Dummy("x", positive=True)


def normal_lambda(t, name, vals, A):
    """The normal closed form ``name`` ('pressure' or 'gap') at the half-width
    A as a SymPy function of x >= 0 (``sp.Lambda``) with every value of
    ``vals`` exact, for the Arb references; None without a closed form."""
    d = t.contact.derivation(name)
    if not d.closed_form:
        return None
    e = d.expr.xreplace({**_fixed(t, vals), S.a: A})
    return sp.Lambda(_x, e.xreplace({S.x: _x}))


def sampler(t, domain, reversal, load, mu_range):
    """Random verification points: the profile's parameters, E_star, mu, a
    beyond the force law's last zero c0, c_s in (c0, a), c_r in (c_s, a), x in
    the contact ('inside') or in the slip zone ('slip'), Q in (0, mu P(a))."""
    base = point_sampler(t.profile, "any", {s: mu_range for s in t._msyms})
    P = t.contact.derivation("force").expr

    def sample(rng):
        vals = base(rng)
        if vals is None:
            return None
        A = float(vals[S.a])
        c0 = float(sp.N(t.c0.xreplace(vals)))
        if A <= 1.05 * c0:
            return None
        cs = rational(c0 + (A - c0) * rng.uniform(0.1, 0.9))
        vals[S.c_s] = cs
        if reversal:
            vals[S.c_r] = rational(float(cs) + (A - float(cs)) * rng.uniform(0.1, 0.9))
        if domain == "inside":
            vals[S.x] = rational(A * rng.uniform(0.02, 0.98))
        elif domain == "slip":
            vals[S.x] = rational(float(cs) + (A - float(cs)) * rng.uniform(0.02, 0.98))
        if load:
            muP = float(sp.N((t.mu * P).xreplace(vals)))
            vals[S.Q] = rational(muP * rng.uniform(0.05, 0.95))
        return vals
    return sample


# =====================================================================  references
def references(t, what, terms):
    """(check, value, description) of a combination sum(k * monotone term at C):
    ``check`` shares nothing with the superposition (inversion of the stick
    condition, Flamant kernel), ``value`` evaluates the superposition by
    quadrature where the normal solution has no closed form."""
    if t.contact.verify:   # derived here, not inside the forked verification
        for name in ("force", "pressure") + (("gap",) if what == "slip" else ()):
            t.contact.derivation(name)

    def num(vals, key):
        return to_mpf(sp.N(vals[key], mpmath.mp.dps + 5))

    def q_superposed(vals):
        A = num(vals, S.a)
        pa = normal_fn(t, "pressure", vals, A)
        parts = [(k, num(vals, C), normal_fn(t, "pressure", vals, num(vals, C))) for k, C in terms]
        mu = friction_at(t, vals)

        def q(xi):
            xi = abs(xi)
            return mu * sum(k * (pa(xi) - (pc(xi) if xi < c else 0)) for k, c, pc in parts)
        return q, A, [c for _, c, _ in parts]

    def mp_term(vals, C):
        """The mpmath route of one term at C (the fallback of its enclosure)."""
        A, mu = num(vals, S.a), friction_at(t, vals)
        brs = _breaks(t, vals)
        pa = normal_fn(t, "pressure", vals, A)
        if what == "traction":
            X = num(vals, S.x)
            return ref.stick_traction_inversion(pa, A, num(vals, C), X, mu, brs) if X < num(vals, C) else mu * pa(X)
        return ref.tangential_force_inversion(pa, A, num(vals, C), mu, brs)

    def check(vals, dps):
        if what in ("traction", "force"):
            pa = normal_lambda(t, "pressure", vals, vals[S.a])
            if pa is None:
                with workdps(dps + 10):
                    return +sum(k * mp_term(vals, C) for k, C in terms)
            A, mu, X = vals[S.a], t.mu.xreplace(vals), vals.get(S.x)
            brs = [bp.xreplace(vals) for bp in t.profile.breakpoints]
            parts = []
            for k, C in terms:
                fb = (lambda C=C: mp_term(vals, C))
                if what == "force":
                    parts.append((k, ref.tangential_force_enclosure(pa, A, vals[C], mu, brs, dps, fb)))
                elif X < vals[C]:
                    parts.append((k, ref.stick_traction_enclosure(pa, A, vals[C], X, mu, brs, dps, fb)))
                else:
                    parts.append((k, mu * pa(X)))       # the slip zone: mu p(x; a), exact
            return lincomb(parts, dps)

        def flamant():
            q, A, cs = q_superposed(vals)
            E = num(vals, S.E_star)
            if what == "slip":
                return ref.slip_flamant(q, A, num(vals, S.x), E, cs + brs)
            return ref.displacement_flamant(q, A, E, cs + brs)
        with workdps(dps + 10):
            brs = _breaks(t, vals)
            return estimate(flamant, "the logarithmic Flamant kernel is singular at end points of the pieces "
                                     "(Arb cannot bound it there)", dps)

    def value(vals, dps):
        with workdps(dps + 10):
            A, mu = num(vals, S.a), friction_at(t, vals)
            if what == "traction":
                q, _, _ = q_superposed(vals)
                return +q(num(vals, S.x))
            if what == "force":
                law = force_law_at(t, vals)
                return +sum(k * mu * (law.P(A) - law.P(num(vals, C))) for k, C in terms)
            if what == "slip":
                X = num(vals, S.x)
                return +sum(k * mu * normal_fn(t, "gap", vals, num(vals, C))(X) for k, C in terms
                            if X > num(vals, C))
            return +sum(k * _delta_numeric(t, vals, num(vals, C)) for k, C in terms)
    how = {"traction": "the stick-zone traction from the inversion of the stick condition (Cauchy singular "
                       "integral equation, bounded solution) driven by mu p(x; a) in the slip zones",
           "force": "the resultant of the inverted stick traction plus mu p(x; a) in the slip zones",
           "slip": "the Flamant kernel (2/(pi E*)) int q(xi) ln|x - xi|/|xi| dxi applied to the traction",
           "displacement": "the Flamant kernel -(2/(pi E*)) int q(xi) ln(|xi|/a) dxi applied to the traction"}[what]
    return check, value, how


# =====================================================================  energy and loop
def _integrate_pair(i1, i2):
    out = []
    for integral in (i1, i2):
        out.append(sp.simplify(integral.doit()))
    return out


def energy_parts(t, tsym):
    """(W, delta, closed) in a and c_s from the force law P (see the
    :mod:`.tangential` docstring)."""
    fd = t.contact.derivation("force")
    P = fd.expr
    Pa, Pc, Pt = P, P.xreplace({S.a: S.c_s}), P.xreplace({S.a: tsym})
    I1, I2 = sp.Integral(Pt / tsym, (tsym, S.c_s, S.a)), sp.Integral(Pt**2 / tsym, (tsym, S.c_s, S.a))
    closed = fd.closed_form
    if closed:
        try:
            j1, j2 = run_with_budget(_integrate_pair, I1, I2, seconds=t.contact.budget)
            closed = not (j1.has(sp.Integral) or j2.has(sp.Integral))
            if closed:
                I1, I2 = j1, j2
        except (BudgetExceeded, NotImplementedError, ValueError, TypeError):
            closed = False
    mu, E = t.mu, S.E_star
    L = sp.log(S.a / S.c_s)
    W = 8 * mu**2 / (sp.pi * E) * ((Pa + Pc) * I1 - I2 - Pa * Pc * L)
    delta = 2 * mu / (sp.pi * E) * (Pa * sp.log(2) - Pc * (L + sp.log(2)) + I1)
    if closed:
        W, delta = _tidy_logs(W), _tidy_logs(delta)
    return W, delta, closed


def _collect_logs(e):
    logs = [sp.log(S.a / S.c_s), sp.log(2)]
    return sp.factor_terms(sp.collect(sp.expand(e, log=False, power_base=False), logs))


def _tidy_logs(e):
    """Expanded and collected in ln(a/c_s) and ln 2 (no log-combining)."""
    try:
        return run_with_budget(_collect_logs, e, seconds=15)
    except BudgetExceeded:
        return e


def _I(law, lo, hi, power, brs):
    pts = sorted({lo, hi, *(b for b in brs if lo < b < hi)})
    return mpmath.quad(lambda tv: law.P(tv)**power / tv, pts)


def _delta_numeric(t, vals, C):
    law, A, mu = force_law_at(t, vals), to_mpf(sp.N(vals[S.a], mpmath.mp.dps + 5)), friction_at(t, vals)
    E = to_mpf(sp.N(vals[S.E_star], mpmath.mp.dps + 5))
    I1 = _I(law, C, A, 1, law.breaks())
    return 2 * mu / (mpmath.pi * E) * (law.P(A) * mpmath.log(2) - law.P(C) * mpmath.log(2 * A / C) + I1)


def energy_references(t):
    """(check, value, description) of the dissipated energy: the friction work
    in the slip zones, and the force-law formula by quadrature."""
    if t.contact.verify:   # derived here, not inside the forked verification
        for name in ("force", "pressure", "gap"):
            t.contact.derivation(name)

    def nums(vals):
        return [to_mpf(sp.N(vals[k], mpmath.mp.dps + 5)) for k in (S.a, S.c_s, S.E_star)]

    def mp_check(vals):
        A, C, _ = nums(vals)
        pa, gc = normal_fn(t, "pressure", vals, A), normal_fn(t, "gap", vals, C)
        return ref.friction_work(pa, gc, A, C, friction_at(t, vals), _breaks(t, vals))

    def check(vals, dps):
        pa, gc = normal_lambda(t, "pressure", vals, vals[S.a]), normal_lambda(t, "gap", vals, vals[S.c_s])
        if pa is None or gc is None:
            with workdps(dps + 10):
                return mp_check(vals)
        brs = [bp.xreplace(vals) for bp in t.profile.breakpoints]
        return ref.friction_work_enclosure(pa, gc, vals[S.a], vals[S.c_s], t.mu.xreplace(vals), brs, dps,
                                           fallback=lambda: mp_check(vals))

    def value(vals, dps):
        with workdps(dps + 10):
            A, C, E = nums(vals)
            law, mu = force_law_at(t, vals), friction_at(t, vals)
            brs = law.breaks()
            Pa, Pc = law.P(A), law.P(C)
            W = (Pa + Pc) * _I(law, C, A, 1, brs) - _I(law, C, A, 2, brs) - Pa * Pc * mpmath.log(A / C)
            return 8 * mu**2 / (mpmath.pi * E) * W
    return check, value, "the work of the friction forces over a cycle, 8 mu^2 int_c^a p(x; a) g(x; c) dx"


# =====================================================================  stick zone
@timed
def derive_stick_half_width(t, Qv, budget=None) -> Derivation:
    """c_s(a, Q): the force law's inverse at P(a) - |Q|/mu (closed where the
    engine inverts the force law), verified against the root of the quadrature
    force law (Eq. 10*).

    ``budget`` (seconds, default the contact's) is a deadline for the whole
    derivation: the inversion and the verification share it; a closed form
    not verified in time is returned unevaluated (P(c_s) = P(a) - |Q|/mu
    with its numeric root), with a note.  Remembered in memory and on disk
    (:func:`~linecontact_sym.method.derivation.remembered`)."""
    budget = t.contact.budget if budget is None else checked_budget(budget)
    deadline = Deadline(budget)        # the force law's derivation (cached) counts too
    fd = t.contact.derivation("force")
    variables = (S.a, Qv) + t.variables
    parts = ("stick_half_width", t.profile.expr, dict(t.profile.ranges), fd.expr, t.mu, Qv, t.contact.points,
             t.contact.verify)
    return remembered(parts, lambda: _derive_stick(t, Qv, fd, deadline), budget,
                      lambda d: (_check_ref if d.closed_form else _value_ref)(t, Qv),
                      sampler=t._sampler("any", load=True) if Qv == S.Q else None)   # read from disk: re-checked


def _check_ref(t, Qv):
    """The independent reference of c_s: the root of P(c) = P(a) - |Q|/mu with
    the quadrature force law of the profile (Eq. 10*), bracketed on (0, a]
    (the law is non-decreasing on [c_s, a], :data:`CONDITIONS`): located at
    17 digits, refined at the working precision."""
    prof = t.profile

    def check(vals, dps):
        with workdps(dps + 10):
            fixed = float_values(_fixed(t, vals), dps + 20)
            law = ForceLaw.from_profile(prof, fixed)
            A = to_mpf(sp.N(vals[S.a], dps + 15))
            L = law.P(A) - abs(to_mpf(sp.N(vals[Qv], dps + 15))) / friction_at(t, vals)
            return root_below(law.P, L, A)
    return check


def _value_ref(t, Qv):
    def value(vals, dps):
        with workdps(dps + 10):
            law = force_law_at(t, vals)
            A = to_mpf(sp.N(vals[S.a], dps + 15))
            return half_width_at(law, law.P(A) - abs(to_mpf(sp.N(vals[Qv], dps + 15))) / friction_at(t, vals), dps)
    return value


def root_below(P, load, A):
    """The largest c in (0, A] with P(c) = load, for P(0+) = 0 <= load <= P(A)
    and P non-decreasing on [c, A]: bisection in ln c at 17 digits, then the
    root refined at the working precision around it (a few evaluations)."""
    if load <= 0:
        raise ValueError("no positive load below P(a)")
    dps = mpmath.mp.dps
    with workdps(17):
        lo, k = A / 2, 0
        while P(lo) >= load:
            lo, k = lo / 4, k + 1
            if k > 200:
                raise ValueError("P(c) does not fall below the load as c -> 0")
        approx = root_in_log(lambda c: P(c) - load, lo, A)
    with workdps(dps):
        return root_in_log(lambda c: P(c) - load, lo, A, approx=approx)


def _derive_stick(t, Qv, fd, deadline) -> Derivation:
    load = fd.expr - sp.Abs(Qv) / t.mu
    left = deadline.left()
    inv = t.contact._half_width(S.P, budget=None if left is None else max(left, 0.05))
    conds = tuple(fd.conditions) + (sp.Lt(sp.Abs(Qv), t.mu * fd.expr),)
    check = _check_ref(t, Qv)
    variables = (S.a, Qv) + t.variables
    notes = (CONDITIONS,)
    if inv.closed_form and Qv == S.Q:
        expr = tidy_root(sp.simplify(inv.expr.xreplace({S.P: load})))
        rec = None
        if t.contact.verify:
            left = deadline.left()
            rec = verify(expr, check, t._sampler("any", load=True), conds, n_points=t.contact.points,
                         reference_name="root of P(c) = P(a) - |Q|/mu with the quadrature force law (Eq. 10*)",
                         budget=max(left, 0.05) if left is not None else None)
        if rec is None or rec.passed:
            step = Step("invert_force_law", expr, conds, ("c_s = a(P(a) - |Q|/mu), the inverse of the force law",
                                                          CONDITIONS))
            return Derivation("stick_half_width", expr=expr, closed_form=True, step=step, conditions=conds,
                              verification=rec, notes=notes, reference=check, variables=variables)
        why = ("not verified within the budget's remaining time" if not rec.points else
               f"FAILED verification ({rec.min_digits:.1f} digits)")
        notes = (f"closed form {expr} {why}; returned unevaluated",) + notes
        attempts = (("invert_force_law", f"closed form {why}" + (" (no result within the budget)"
                                                                 if not rec.points else "")),)
        return Derivation("stick_half_width", expr=sp.Eq(fd.expr.xreplace({S.a: S.c_s}), load), closed_form=False,
                          step=fallback_step("numeric root of P(c_s) = P(a) - |Q|/mu"), verification=rec, notes=notes,
                          reference=_value_ref(t, Qv), variables=variables, attempts=attempts)
    return Derivation("stick_half_width", expr=sp.Eq(fd.expr.xreplace({S.a: S.c_s}), load), closed_form=False,
                      step=fallback_step("numeric root of P(c_s) = P(a) - |Q|/mu"), notes=notes,
                      reference=_value_ref(t, Qv), variables=variables, attempts=inv.attempts)


def in_terms_of(t, d: Derivation, Qv) -> Derivation:
    """The stick half-width derived for the package's Q, written for the
    user's own tangential force ``Qv`` (a symbol such as a positive ``F``,
    or an expression in such symbols): the same closed form with Q -> Qv
    (|Q| becomes Qv for a positive Qv), its conditions and its reference
    rewritten alike.  ``Qv`` must be real (a symbol without assumptions is
    taken as real, and the notes say so) and may not use the profile's
    parameters, E_star, a, mu's symbols or the stick half-widths."""
    Qv = sp.sympify(Qv, strict=True)  # safe: a SymPy expression already (the caller converted it)
    taken = set(t.contact.params) | {S.E_star, S.a, S.x, S.c_s, S.c_r, S.P} | set(t.mu.free_symbols)
    clash = Qv.free_symbols & taken
    if clash:
        raise DomainError(f"the tangential force {Qv} uses {', '.join(sorted(map(str, clash)))}, which already mean "
                          f"something here; use a symbol of its own (e.g. lcs.Q or Symbol('F', positive=True))")
    if Qv.is_real is False or Qv.is_extended_real is False:
        raise DomainError(f"the tangential force {Qv} is not real")
    notes = d.notes
    if Qv.is_real is None:
        notes += (f"the tangential force {Qv} has no assumptions: it is taken real (the formula holds for real "
                  f"{Qv}; declare it Symbol(..., real=True) or positive=True)",)
        Qr = sp.Dummy("Q", real=True)
        expr = d.expr.xreplace({S.Q: Qr}).xreplace({Qr: Qv})
    else:
        expr = d.expr.xreplace({S.Q: Qv})
    conds = tuple(c.xreplace({S.Q: Qv}) for c in d.conditions)

    def translated(fn):
        if fn is None:
            return None

        def g(vals, dps):
            q = Qv.xreplace(vals)
            return fn({**{k: v for k, v in vals.items() if k not in Qv.free_symbols}, S.Q: q}, dps)
        return g
    variables = []
    for v in d.variables:
        for w in ((v,) if v != S.Q else tuple(sorted(Qv.free_symbols, key=lambda q: q.name))):
            if w not in variables:
                variables.append(w)
    step = Step(d.step.rule, expr, conds, d.step.notes)
    return Derivation("stick_half_width", expr=expr, closed_form=d.closed_form, step=step, conditions=conds,
                      verification=d.verification, seconds=d.seconds, notes=notes, reference=translated(d.reference),
                      variables=tuple(variables), attempts=d.attempts, cached=d.cached)


def tidy_root(e):
    """sqrt(u)/sqrt(v) -> sqrt(expand(u/v)) for a non-negative square root
    (a half-width): c_s = sqrt(a**2 - 4 R |Q|/(pi E* mu)) for Hertz."""
    sq = e**2
    if e.is_nonnegative is not False and not sq.has(sp.sqrt(sp.Wild("w"))) and sp.count_ops(sq) < 40:
        cand = sp.sqrt(sp.expand(sp.powsimp(sq, force=True)))
        if sp.count_ops(cand) < sp.count_ops(e):
            return cand
    return e


__all__ = ["CONDITIONS", "normal_fn", "sampler", "references", "energy_parts", "energy_references",
           "derive_stick_half_width", "in_terms_of", "tidy_root"]
