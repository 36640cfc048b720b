"""Derivations of an adhesive contact beyond the law's force and pressure,
for every cohesive law (:mod:`.law`): the jump-in half-width and the
equilibrium branches a(P), each verified by a route that shares nothing with
the one that produced it; the equilibrium check of a pressure."""
from __future__ import annotations

import random

import mpmath
import sympy as sp

from ...core import symbols as S
from ...core.budget import run_with_budget
from ...core.conversion import rational, real_mpf, to_mpf
from ...core.errors import BudgetExceeded, DomainError, NoEquilibriumError, NoPullOffError
from ...method.derivation import Derivation, timed
from ...method.transforms import mean_quad
from ...method.rules import Step
from ...method.verification import VERIFY_DPS, VerificationRecord, digits_agreeing, verify
from ...numeric.reference import integrate
from ..normal.equilibria import equilibria, landscape, minimum
from .pull_off import NumericDerivation, sample_points, solve_load, statement, tidy_checked, unsolvable
from ...core.precision import workdps

_phi = sp.Dummy("phi", positive=True)   # an integration variable: never a user's phi
#: Arb's evaluations per piece in the equilibrium check (a smooth piece takes
#: a few hundred; an end point Arb cannot bound, the wedge's log at x = 0,
#: spends the whole limit before mean_quad runs)
EQUILIBRIUM_EVAL_LIMIT = 4000


def equilibrium_digits(ad, pexpr) -> float:
    """min digits of int_{-a}^{a} p dx = P(a) at random points."""
    fexpr = ad.derivation("force").expr
    sample = ad._sampler()
    rng = random.Random(29)
    worst = float(VERIFY_DPS)
    done = 0
    while done < ad.contact.points:
        vals = sample(rng)
        if vals is None:
            continue
        with workdps(VERIFY_DPS + 10):
            A = to_mpf(vals[S.a])
            # x = a sin(phi), sqrt(a^2 - x^2) = a cos(phi) (no cancellation at the edge)
            e = pexpr.replace(lambda z: z.is_Pow and z.base == S.a**2 - S.x**2,
                              lambda z: (S.a * sp.cos(_phi))**(2 * z.exp))
            e = e.xreplace({S.x: S.a * sp.sin(_phi)})
            e = e.xreplace({k: v for k, v in vals.items() if k != S.x})
            pf = sp.lambdify(_phi, e, "mpmath")
            # Arb where it encloses it (the edge's 1/cos(phi) cancels in SymPy), mean_quad otherwise
            I = integrate(sp.expand_mul(2 * vals[S.a] * e * sp.cos(_phi)), _phi, [0, sp.pi / 2], VERIFY_DPS,
                          fallback=lambda: 2 * A * mean_quad(pf), eval_limit=EQUILIBRIUM_EVAL_LIMIT)
            ref = real_mpf(sp.N(fexpr.xreplace(vals), VERIFY_DPS + 10))
            with workdps(VERIFY_DPS):
                worst = min(worst, digits_agreeing(I, ref))
        done += 1
    return worst


@timed
def derive_jump_in(ad) -> Derivation:
    """Stable root of P(a) = 0: the half-width the contact snaps to at zero
    load; verified against the stable root of the quadrature law."""
    fd = ad.contact.derivation("force")
    force = ad.derivation("force")
    P = force.expr
    expr, notes = None, []
    conds = list(fd.conditions)
    closed = ad.law.jump_in_candidates(ad, fd) if force.closed_form else None
    if closed is not None:
        conds += closed[2]
    method = "sympy.solve of P(a) = 0, stable root"

    def reference(vals, dps):
        # the pull-off half-width that separates the branches: method B's, or (a law without an
        # independent method B, CohesiveLaw.independent_minimum) the law's own minimum
        po = ad._pull_off_reference(vals, dps) if ad.law.independent_minimum else \
            minimum(ad._law(vals, "closed"), dps)
        roots = [r for r, st in equilibria(ad._law(vals, "quad"), 0, dps, scan_law=ad._law(vals, "closed"))
                 if st and r > po.half_width]
        if not roots:
            raise NoEquilibriumError("no stable equilibrium at zero load")
        return roots[0]
    if force.closed_form and not P.has(sp.Piecewise) and not ad.law.inactive:
        if closed is not None:
            cands, method = closed[0], closed[1]
        else:
            cands = []
            why = unsolvable(P)
            try:
                if why is not None:
                    notes.append(f"sympy.solve(P = 0): {why}")
                else:
                    cands = run_with_budget(solve_load, P, 0, seconds=ad.contact.budget)
            except (BudgetExceeded, NotImplementedError, ValueError, TypeError) as exc:
                notes.append(f"sympy.solve(P = 0): {type(exc).__name__}")
        for cand in cands:
            if cand.has(S.a) or cand.has(sp.RootOf):
                continue
            try:
                good = all(abs(sp.N(P.xreplace({**v, S.a: cand.xreplace(v)}), 50)) < sp.Float(10)**-35
                           and sp.N(cand.xreplace(v), 50) > 0
                           and sp.N(sp.diff(P, S.a).xreplace({**v, S.a: cand.xreplace(v)}), 30) > 0
                           for v in sample_points(ad, conds))
            except TypeError:
                good = False
            if good:
                expr = tidy_checked(ad, cand, conds, simplify=closed is None)
                break
    if expr is None:
        stmt = statement(P, "load", 0)
        step = Step("numeric_root", stmt, (), ("numeric: stable root of P(a) = 0",))
        return NumericDerivation("jump_in_half_width", expr=stmt, closed_form=False, step=step, notes=tuple(notes),
                                 reference=reference, variables=ad.variables)
    rec = None
    if ad.contact.verify:
        rec = verify(expr, reference, ad._sampler(), conds, n_points=ad.contact.points,
                     reference_name="stable root of the quadrature force law P(a) = 0")
        ad._require(rec, "jump_in_half_width")
    return Derivation("jump_in_half_width", expr=expr, closed_form=True,
                      step=Step("solve_load", expr, tuple(conds), (method,)), conditions=tuple(conds), verification=rec,
                      notes=tuple(notes), reference=reference, variables=ad.variables)


def why_no_equilibrium(law, load) -> str:
    """Why P(a) = load has no root over the admissible range, in words."""
    land = landscape(law)
    with workdps(20):
        values = [e.force for e in land.extrema] + [law.P(land.lo), law.P(land.hi)]
        if to_mpf(load) <= min(values):
            return "below the pull-off force (the minimum of P(a)): the surfaces separate"
        if land.end == "admissible":
            return (f"above the loads reached for a <= a* = {mpmath.nstr(land.hi, 12)}, the end of the "
                    f"admissible range (dP0/da < 0 beyond: tensile edge pressure)")
        if land.end == "domain":
            return (f"above the loads reached for a <= {mpmath.nstr(land.hi, 12)}, within "
                    f"1e-12 of the end of the profile's domain")
        if not land.rising_at_end:
            return ("above the maximum of P(a) (P decreases at large a, e.g. a power law with "
                    "n < 1/2): the contact would spread without bound")
        return f"above the loads reached on the search range a <= {mpmath.nstr(land.hi, 6)}"


@timed
def derive_half_widths(ad, load):
    """(stable, unstable) Derivations of a(P): closed forms from sympy.solve
    (under the budget), each identified with its branch at random points,
    else the unevaluated P(a) = P with a numeric evalf."""
    force = ad.derivation("force")
    P = force.expr
    notes, cands = [], []
    if force.closed_form and not P.has(sp.Piecewise) and not ad.law.inactive:
        why = unsolvable(P)
        try:
            if why is not None:
                notes.append(f"sympy.solve(P(a) = {load}): {why}")
            else:
                cands = run_with_budget(solve_load, P, load, seconds=ad.contact.budget)
        except BudgetExceeded:
            notes.append(f"sympy.solve(P(a) = {load}) found nothing within {ad.contact.budget:g} s")
        except (NotImplementedError, ValueError, TypeError) as exc:
            notes.append(f"sympy.solve(P(a) = {load}): {type(exc).__name__}")
    variables = (load,) + ad.variables

    def ref(stable):
        def reference(vals, dps):
            roots = [r for r, st in equilibria(ad._law(vals, "closed"), vals[load], dps) if st == stable]
            if not roots:
                raise NoEquilibriumError(f"no {'stable' if stable else 'unstable'} equilibrium")
            return roots[0]
        return reference
    out = []
    po_d = ad.derivation("pull_off_force")
    for stable in (True, False):
        samples = branch_samples(ad, load, stable) if cands else []
        chosen, rec = None, None
        for cand in cands:
            digs = []
            for v, av in samples:
                try:
                    with workdps(VERIFY_DPS):
                        digs.append(digits_agreeing(real_mpf(sp.N(cand.xreplace(v), VERIFY_DPS + 10)), to_mpf(av)))
                except (TypeError, ValueError, DomainError):
                    digs.append(0.0)
            if samples and min(digs) >= ad.contact.digits:
                chosen = cand
                rec = VerificationRecord(tuple(v for v, _ in samples), tuple(digs), VERIFY_DPS,
                                         f"the sampled half-width on the {'stable' if stable else 'unstable'}"
                                         f" branch, load = P(a) from the verified Eq. (33)")
                break
        q = "half_width_stable" if stable else "half_width_unstable"
        cond = [sp.Gt(load, po_d.expr)] if po_d.closed_form else []
        if not stable:
            cond.append(sp.Lt(load, 0))
        if chosen is not None:
            expr = tidy_checked(ad, chosen, []) if sp.count_ops(chosen) < 80 else chosen
            step = Step("solve_load", expr, tuple(cond), ("sympy.solve of P(a) = P, branch identified at random "
                                                          "points",))
            out.append(Derivation(q, expr=expr, closed_form=True, step=step, conditions=tuple(cond), verification=rec,
                                  notes=tuple(notes), reference=ref(stable), variables=variables))
        else:
            step = Step("numeric_root", statement(P, "load", load), (), (f"numeric root of P(a) = P on the "
                                                             f"{'stable' if stable else 'unstable'} branch "
                                                             f"(no closed form)",))
            out.append(Derivation(q, expr=statement(P, "load", load), closed_form=False, step=step,
                                  conditions=tuple(cond), notes=tuple(notes), reference=ref(stable),
                                  variables=variables))
    return tuple(out)


def branch_samples(ad, load, stable):
    """(values incl. the load, half-width) on one branch: a = a_po * u."""
    sample = ad._sampler()
    rng = random.Random(31 if stable else 37)
    out, tries = [], 0
    while len(out) < ad.contact.points and tries < 20 * ad.contact.points:
        tries += 1
        v = sample(rng)
        if v is None:
            continue
        try:
            po = minimum(ad._law(v, "closed"), VERIFY_DPS)
        except (NoPullOffError, DomainError):
            continue
        u = rng.uniform(1.2, 3.0) if stable else rng.uniform(0.1, 0.9)
        with workdps(VERIFY_DPS + 10):
            av = rational(float(po.half_width) * u)
            if (ad._law(v, "closed").dP(to_mpf(av)) > 0) != stable:
                continue
            v = {k: w for k, w in v.items() if k != S.a}
            av = sp.Float(av, 80)
        with workdps(VERIFY_DPS + 20):
            Lv = sp.Float(ad._law(v, "closed").P(to_mpf(av)), VERIFY_DPS + 20)
        out.append(({**v, load: Lv}, av))
    return out


__all__ = ["derive_jump_in", "derive_half_widths", "why_no_equilibrium",
           "equilibrium_digits", "branch_samples"]
