"""Pull-off of an adhesive line contact, for every cohesive law (:mod:`.law`):
the symbolic attempt (dP/da = 0 by ``sympy.solve``, where the law's P(a) is
one expression) and the numeric minimum, each verified by a route that
shares nothing with it.  What is specific to a law comes from its hooks
(``pull_off_conditions``, ``pull_off_compact``); the JKR example follows.

Under load control the contact separates at the minimum of P(a) (see
:mod:`.equilibria`): ``pull_off_force`` is that minimum P_min < 0 and
``adhesion_force`` is P_adh = -P_min > 0, the paper's convention in (34)-(36).
For a single power law P0 = C a**m (power-law profile c_n |x|**n: m = n,
C = E* c_n Z_n, Eq. 32) dP/da = 0 gives

    a_po  = (2 pi gamma E* / (4 m**2 C**2))**(1/(2m - 1)),
    P_adh = (2m - 1)/(2m) * ((2 pi gamma E*)**m / (2 m C))**(1/(2m - 1)),

i.e. Barquins' (3/4)(4 pi R E* gamma**2)**(1/3) for the parabola (34), the
paper's (35) for general n and pi gamma / (2 tan theta) for the wedge (36).

Existence (found here, not printed in the paper): a finite tensile pull-off
exists when P0(a)/sqrt(a) -> 0 as a -> 0 and P0(a)/sqrt(a) grows beyond
sqrt(2 pi gamma E*) at large a; for a power law both hold **iff n > 1/2**.
"""
from __future__ import annotations

import random

import mpmath
import sympy as sp

from ...core import symbols as S
from ...core.budget import run_with_budget
from ...core.conversion import float_values, real_mpf
from ...core.errors import BudgetExceeded, NoPullOffError, VerificationError
from ...method import store
from ...method.derivation import Derivation, agrees_at_random_point, remembered_many, tidy
from ...method.hyperseries import NotDecomposable, decompose
from ...method.rules import Step, special_of
from ...method.verification import (VERIFY_BUDGET, VERIFY_DPS, VerificationRecord, digits_agreeing, holds,
                                   verify_many)
from .brute_force import minimum_by_grid
from ..normal.equilibria import landscape, minimum, within_search_budget
from ..normal.force_law import PullOff
from ...core.precision import workdps


def single_power(P0):
    """P0 = C a**m (one pure power term) -> (C, m), else None."""
    if P0.has(sp.Piecewise, sp.Integral):
        return None
    try:
        terms = decompose(P0, S.a)
    except NotDecomposable:
        return None
    if len(terms) != 1 or not terms[0].is_power or terms[0].coef.has(S.a):
        return None
    return terms[0].coef, terms[0].mu


def statement(P, what, load=0):
    """What a numeric Derivation states: ``dP/da = 0`` (``what='stationary'``)
    or ``P(a) = load``; for a law whose P(a) is a system (a Tuple of
    equations in a and inner unknowns) the system with that condition added."""
    if isinstance(P, sp.Expr) and not isinstance(P, sp.Tuple):
        return sp.Eq(sp.diff(P, S.a), 0) if what == "stationary" else sp.Eq(P, load)
    Pa = sp.Function("P")(S.a)
    return sp.Tuple(*P, sp.Eq(sp.Derivative(Pa, S.a), 0) if what == "stationary" else sp.Eq(Pa, load))


def solve_stationary(P):
    return sp.solve(sp.diff(P, S.a), S.a)


def unsolvable(expr):
    """Why ``sympy.solve(expr = 0, a)`` is not worth trying, or None; a
    strategy that cannot apply says so at once.

    * ``expr`` holds a non-elementary function of a
      (:func:`~linecontact_sym.method.rules.special_of`: Bessel, elliptic,
      hypergeometric ...), which SymPy cannot invert.  It raises
      NotImplementedError then, even where the function is a factor
      ((a - 2) besselj(1, a)), after up to 5 CPU s (the Gaussian bump's
      besseli laws), or runs into the budget (the exact cylinder's elliptic
      laws).
    * A factor of a piece of ``expr`` mixes a (inverse) trigonometric
      function of a with other terms in a (:func:`mixed_trigonometric`).
      SymPy raises "multiple generators [...]: No algorithms are implemented
      to solve equation" for such an equation, also where it is one factor
      or one piece; for the worn cylinder's adhesive dP/da (asin(b/a) beside
      sqrt(a) and sqrt(a^2 - b^2)) after 9-11 CPU s."""
    f = special_of(expr, S.a)
    if f is not None:
        return f"it cannot invert {f.func.__name__} of a (not tried)"
    t = mixed_trigonometric(expr, S.a)
    if t is not None:
        return (f"{t} beside other terms in a: SymPy has no algorithm for such an equation "
                f"(it raises 'multiple generators'; not tried)")
    return None


def mixed_trigonometric(expr, var):
    """The first (inverse) trigonometric function of ``var`` that shares a
    factor of a piece of ``expr`` (the numerator over a common denominator)
    with other terms in ``var``, or None.  Such a factor is one equation in
    two unrelated generators (asin(b/a) and sqrt(a)); SymPy inverts a
    factor with trigonometric functions of ``var`` only (its trigonometric
    solver: sin(a) - cos(a)), or with one of them alone (asin(b/a) - pi/6),
    and neither is refused here.  exp, log and the hyperbolic functions are
    left to SymPy (its Lambert W route)."""
    from sympy.functions.elementary.trigonometric import InverseTrigonometricFunction, TrigonometricFunction
    folded = sp.piecewise_fold(expr) if expr.has(sp.Piecewise) else expr
    pieces = [e for e, _ in folded.args] if isinstance(folded, sp.Piecewise) else [folded]
    for piece in pieces:
        if piece.has(sp.Piecewise):
            continue
        num = sp.together(piece).as_numer_denom()[0]
        for factor in sp.Mul.make_args(sp.factor_terms(num)):
            trig = sorted((f for f in factor.atoms(TrigonometricFunction, InverseTrigonometricFunction)
                           if var in f.free_symbols), key=sp.default_sort_key)
            if trig and var in factor.xreplace({f: sp.Dummy() for f in trig}).free_symbols:
                return trig[0]
    return None


def solve_load(P, load):
    return sp.solve(sp.Eq(P, load), S.a)


# ---------------------------------------------------------------- checks at points
def sample_points(ad, conds, n=5, seed=11):
    """n random admissible points (parameters, E_star, gamma) where ``conds`` hold."""
    sample = ad._sampler()
    rng = random.Random(seed)
    out, tries = [], 0
    while len(out) < n and tries < 40 * n:
        tries += 1
        v = sample(rng)
        if v is not None and holds(conds, v):
            out.append(v)
    return out


def same_at_points(ad, e1, e2, conds) -> bool:
    """Do two expressions agree to 40 digits at random admissible points?"""
    for v in sample_points(ad, conds):
        x1 = sp.N(e1.xreplace(v), 50)
        x2 = sp.N(e2.xreplace(v), 50)
        if not (x1.is_real and x2.is_real) or abs(x1 - x2) > abs(x2) * sp.Float(10)**-40:
            return False
    return True


def tidy_checked(ad, e, conds, simplify=True):
    """``tidy`` under the budget, kept only where it agrees at points; drop
    Abs of expressions positive at every admissible point (|tan(theta)| ...)."""
    if simplify:
        try:
            cand = run_with_budget(tidy, e, seconds=min(ad.contact.budget, 15))
        except Exception:
            cand = e
        if sp.count_ops(cand) <= sp.count_ops(e) and same_at_points(ad, cand, e, conds):
            e = cand
    for ab in list(e.atoms(sp.Abs)):
        inner = ab.args[0]
        if all(sp.N(inner.xreplace(v), 30) > 0 for v in sample_points(ad, conds)):
            e2 = e.xreplace({ab: inner})
            if same_at_points(ad, e2, e, conds):
                e = e2
    return e


def pick_minimum(ad, cands, P, conds):
    """The candidate a* that is a real positive local minimum of P at
    random admissible points."""
    d1, d2 = sp.diff(P, S.a), sp.diff(P, S.a, 2)
    pts = sample_points(ad, conds)
    for cand in cands:
        if cand.has(S.a) or cand.has(sp.RootOf):
            continue
        ok = bool(pts)
        for v in pts:
            av = sp.N(cand.xreplace(v), 50)
            if not av.is_real or not av > 0:
                ok = False
                break
            sub = {**v, S.a: av}
            g1 = sp.N(d1.xreplace(sub), 50)
            g2 = sp.N(d2.xreplace(sub), 50)
            if not (abs(g1) < sp.Float(10)**-35 * (1 + abs(sp.N(P.xreplace(sub), 50)) / av) and g2 > 0):
                ok = False
                break
        if ok:
            return cand
    return None


# ---------------------------------------------------------------- symbolic attempt
def closed_attempt(ad):
    """The symbolic pull-off: a dict with Pmin, a_star, adh, conds, notes,
    method, unique (the law's compact form says the stationary point is the
    global minimum) -- Pmin None when there is no closed form."""
    law = ad.law
    fd = ad.contact.derivation("force")
    force = ad.derivation("force")
    notes, conds = [], list(fd.conditions)
    if law.inactive:
        raise NoPullOffError(f"{ad.profile.name!r}: {law.inactive}: P(a) = P0(a) >= 0, "
                             f"no tensile pull-off")
    a_star = Pmin = adh = method = None
    unique = timed_out = False
    if not fd.closed_form:
        notes.append("the force law P0(a) has no closed form")
    elif not ad.contact.geometry.is_isolated:
        notes.append("a periodic array: dP/da = 0 is transcendental in a (sin and tan of pi a/L); the numeric "
                     "minimum, checked by the independent grid search")
    elif not force.closed_form:
        notes.append(f"the {law.name} force law P(a) has no closed form")
    else:
        P = force.expr
        conds += law.pull_off_conditions(ad, fd)
        cands = []
        by_law = law.stationary_candidates(ad, fd)
        if by_law is not None:   # closed-form candidates of the law, checked like any (dP/da = 0, P'' > 0)
            a_star = pick_minimum(ad, by_law[0], P, conds)
            if a_star is not None:
                notes.append(by_law[1])
        why = unsolvable(sp.diff(P, S.a)) if a_star is None else None
        if why is not None:
            notes.append(f"sympy.solve(dP/da = 0): {why}")
        elif a_star is None:
            try:
                cands = run_with_budget(solve_stationary, P, seconds=ad.contact.budget)
                notes.append(f"sympy.solve(dP/da = 0) gave {len(cands)} candidate(s)")
            except BudgetExceeded:
                notes.append(f"sympy.solve(dP/da = 0) found nothing within {ad.contact.budget:g} s")
                timed_out = True
            except (NotImplementedError, ValueError, TypeError) as exc:
                notes.append(f"sympy.solve(dP/da = 0) gave up: {type(exc).__name__}")
            a_star = pick_minimum(ad, cands, P, conds)
        if a_star is None and cands:
            notes.append("none of them is a real positive minimum at every admissible sample point")
        if a_star is not None:
            method = "sympy.solve of dP/da = 0, minimum checked numerically (P'' > 0)"
            Pmin = P.xreplace({S.a: a_star})
            compact = law.pull_off_compact(ad, fd, Pmin, a_star, conds)
            if compact is not None:
                Pmin, a_star, adh, note = compact
                notes.append(note)
                unique = True
            Pmin = tidy_checked(ad, Pmin, conds, simplify=not unique)
            a_star = tidy_checked(ad, a_star, conds, simplify=not unique)
            if adh is None:
                adh = tidy_checked(ad, -Pmin, conds)
    return dict(Pmin=Pmin, a_star=a_star, adh=adh, conds=conds, notes=notes, method=method, unique=unique,
                timed_out=timed_out)


def derivations(ad):
    """(pull_off_force, adhesion_force, pull_off_half_width) Derivations:
    closed forms verified against the quadrature-only minimisation, else
    numeric ones verified by two independent methods."""
    r = ad._pull_off_closed()
    Pmin, a_star, adh, conds = r["Pmin"], r["a_star"], r["adh"], r["conds"]
    notes, method = list(r["notes"]), r["method"]
    if Pmin is None:
        return numeric_derivations(ad, ad.derivation("force").expr, notes)
    recs = {"P": None, "adh": None, "a": None}
    if ad.contact.verify:
        def reference(v, d):
            po = ad._pull_off_reference(v, d)
            return {"P": po.force, "adh": po.adhesion_force, "a": po.half_width}
        recs = verify_many(
            {"P": Pmin, "adh": adh, "a": a_star}, reference, ad._sampler(), conds, ad.contact.points,
            reference_name={"P": "global minimum of the quadrature force law (10*) with the cohesive law on top, "
                                  "over its admissible range: dense grid + golden section + parabolic polish",
                            "adh": "minus the quadrature-based global minimum of P(a)",
                            "a": "half-width of the quadrature-based global minimum of P(a)"})
        for k, what in (("P", "pull_off_force"), ("a", "pull_off_half_width"), ("adh", "adhesion_force")):
            ad._require(recs[k], what)
    note = tuple(notes) + ("load control; pull_off_force = P_min < 0, adhesion_force = -P_min (the paper's P_adh)",)
    ref_f = lambda v, d: ad._pull_off_reference(v, d).force  # noqa: E731

    def mk(q, expr, rec, ref):
        return Derivation(q, expr=expr, closed_form=True, step=Step("solve_stationary", expr, tuple(conds), (method,)),
                          conditions=tuple(conds), verification=rec, notes=note, reference=ref, variables=ad.variables)
    return (mk("pull_off_force", Pmin, recs["P"], ref_f),
            mk("adhesion_force", adh, recs["adh"], lambda v, d: mpmath.fneg(ref_f(v, d), exact=True)),
            mk("pull_off_half_width", a_star, recs["a"], lambda v, d: ad._pull_off_reference(v, d).half_width))


class NumericDerivation(Derivation):
    """A Derivation without closed form whose defining statement contains the
    half-width ``a`` as an unknown (not an input)."""

    @property
    def variables_all(self):
        return tuple(sorted(set(self.variables), key=lambda s: s.name))


def numeric_derivations(ad, P, notes):
    """No closed form: Derivations whose evalf is the numeric minimum,
    verified at random points by two independent methods."""
    notes = list(notes) + [
        "no closed form: method A = every sign change of dP/da over the admissible range by ball "
        "arithmetic on the engine's closed force law (adaptive subdivision for a quadrature law), "
        "kinks and the range's end included, then the global minimum; method B = dense grid + "
        "golden section + parabolic polish on the quadrature force law (10*) with the cohesive law on top"]
    rec = None
    if not ad.law.independent_minimum:
        notes.append(f"method B is not run: the {ad.law.name} law's quadrature twin shares its inner solve "
                     f"(CohesiveLaw.independent_minimum), so the two methods would not be independent; "
                     f"not verified here")
    elif ad.contact.verify and not ad.law.inactive:
        sample, n_points = ad._sampler(), ad.contact.points

        def work():  # in a budgeted child, like the engine's verify
            pts, digs = [], []
            rng = random.Random(2017)
            tries = 0
            while len(pts) < n_points and tries < 20 * n_points:
                tries += 1
                v = sample(rng)
                if v is None:
                    continue
                try:
                    po = ad._pull_off_checked(v, VERIFY_DPS)
                except (NoPullOffError, ZeroDivisionError, ValueError):
                    continue
                pts.append(v)
                digs.append(po.digits)
            return pts, digs
        name = "two independent minimisations (A: every stationary point and kink of the engine's law, " \
               "B: dense grid + golden section on the quadrature force law)"
        try:
            pts, digs = run_with_budget(work, seconds=VERIFY_BUDGET)
        except BudgetExceeded as exc:
            pts, digs, name = [], [], name + (f" (did not finish: {exc})" if exc.wall_guard else
                                              f" (did not finish in {VERIFY_BUDGET:g} CPU s)")
        rec = VerificationRecord(tuple(pts), tuple(digs), VERIFY_DPS, name)
        ad._require(rec, "pull_off_force")
    stat = statement(P, "stationary")
    step = Step("numeric_minimum", stat, (), ("numeric: global minimum of P(a) (no closed form)",))

    def mk(q, attr, sign=1):
        def reference(v, d):
            return mpmath.fmul(sign, getattr(ad._pull_off_checked(v, d), attr), exact=True)
        return NumericDerivation(q, expr=stat, closed_form=False, step=step, verification=rec, notes=tuple(notes),
                                 reference=reference, variables=ad.variables)
    return mk("pull_off_force", "force"), mk("adhesion_force", "force", -1), mk("pull_off_half_width", "half_width")


def _parts(ad, what):
    """What names a pull-off problem for the store: the profile with its
    parameter ranges, the force law, the work of adhesion, the checks."""
    fd = ad.contact.derivation("force")
    return (what, ad.profile.expr, dict(ad.profile.ranges), fd.expr, ad.law.name, dict(ad.law.values),
            ad.contact.points,
            ad.contact.verify)


def remembered_closed_attempt(ad):
    """:func:`closed_attempt`, remembered (:mod:`~linecontact_sym.method.store`,
    get/put by key): sympy.solve is not run again in a new process."""
    key = store.make_key(*_parts(ad, "pull_off_closed_attempt"))
    rec = store.get(key)
    if rec is not None and "Pmin" in rec:
        return {k: v for k, v in rec.items() if k not in ("key", "version", "source")}
    r = closed_attempt(ad)
    if not r["timed_out"]:   # an attempt cut short by the clock (a loaded machine) is not an answer to keep
        store.put(key, {k: (tuple(v) if isinstance(v, list) else v) for k, v in r.items()})
    return r


def remembered_derivations(ad):
    """:func:`derivations`, remembered with their verification
    (:func:`~linecontact_sym.method.derivation.remembered_many`)."""
    def rebuild(d):
        if d.closed_form:
            if d.quantity == "pull_off_half_width":
                d.reference = lambda v, dd: ad._pull_off_reference(v, dd).half_width
            else:
                sign = 1 if d.quantity == "pull_off_force" else -1
                d.reference = lambda v, dd: mpmath.fmul(sign, ad._pull_off_reference(v, dd).force, exact=True)
            return d
        attr, sign = ("half_width", 1) if d.quantity == "pull_off_half_width" else \
            ("force", 1 if d.quantity == "pull_off_force" else -1)
        return NumericDerivation(d.quantity, expr=d.expr, closed_form=False, step=d.step, conditions=d.conditions,
                                 verification=d.verification, seconds=d.seconds, notes=d.notes,
                                 reference=lambda v, dd: mpmath.fmul(sign, getattr(ad._pull_off_checked(v, dd), attr),
                                                                    exact=True), variables=d.variables,
                                 attempts=d.attempts, cached=d.cached)
    if ad._pull_off_closed().get("timed_out"):   # cut short by the clock: derived here, not kept
        return tuple(derivations(ad))
    sampler = ad._sampler()

    def recheck(d):
        """A closed form read from disk against the minimum of the engine's force law (itself
        re-checked when read) found numerically at one random point: method A, which shares nothing
        with sympy.solve's closed form (cheap: no quadrature law)."""
        def ref(v, dd):
            po = minimum(ad._law(v, "closed"), dd)
            if d.quantity == "pull_off_half_width":
                return po.half_width
            return po.force if d.quantity == "pull_off_force" else -po.force
        return agrees_at_random_point(d, ref, sampler)
    return remembered_many(_parts(ad, "pull_off"), lambda: derivations(ad), ad.contact.budget, rebuild, recheck)


def _key(ad, vals):
    return tuple(sorted((k.name, v) for k, v in vals.items() if k in set(ad.variables)))


def reference(ad, vals, dps, mode="quad") -> PullOff:
    """The independent pull-off (method B, :func:`~.brute_force.minimum_by_grid`:
    dense grid + golden section + parabolic polish on the quadrature law),
    cached; what a closed-form pull-off is verified against."""
    key = ("po_ref", mode, dps, _key(ad, vals))
    if key not in ad._cache:
        try:
            with within_search_budget():      # a caller without a deadline (a claims file) gets the default one
                ad._cache[key] = minimum_by_grid(ad._law(vals, "quad"), dps)
        except NoPullOffError as exc:
            ad._cache[key] = exc
    res = ad._cache[key]
    if isinstance(res, Exception):
        raise res
    return res


def checked(ad, vals, dps) -> PullOff:
    """Numeric pull-off at a point by method A (every extremum of the engine's
    law by ball arithmetic / adaptive subdivision, :func:`~.equilibria.minimum`),
    checked by method B (:func:`reference`), cached.  ``digits``: their
    agreement (force; and half-width at a stationary minimum)."""
    key = ("po_checked", dps, _key(ad, vals))
    if key not in ad._cache:
        with within_search_budget():
            return _checked(ad, vals, dps, key)
    return ad._cache[key]


def _checked(ad, vals, dps, key) -> PullOff:
    if key not in ad._cache and not ad.law.independent_minimum:
        po = minimum(ad._law(vals, "closed"), dps)
        ad._cache[key] = PullOff(po.force, po.adhesion_force, po.half_width, po.kind, None, po.minima,
                                 po.note + f"; method A only (digits None): the {ad.law.name} law's quadrature "
                                           f"twin shares its inner solve, a second minimisation on it would not "
                                           f"be independent")
    if key not in ad._cache:
        law = ad._law(vals, "closed")
        po = minimum(law, dps)
        po_b = reference(ad, vals, dps)
        with workdps(dps):
            d = min(digits_agreeing(po.force, po_b.force),
                    digits_agreeing(po.half_width, po_b.half_width) if po.kind == "stationary" else float(dps))
            if po.kind != po_b.kind:
                d = 0.0
        note = po.note + f"; method B ({po_b.note}) agrees to {d:.1f} digits"
        ad._cache[key] = PullOff(po.force, po.adhesion_force, po.half_width, po.kind, d, po.minima, note)
    return ad._cache[key]


def at_values(ad, vals, dps) -> PullOff:
    """The pull-off at numeric values: the closed form where there is one
    (conditions and existence checked), else the checked numeric minimum."""
    if ad._pull_off_closed()["Pmin"] is not None:
        fd = ad.derivation("pull_off_force")
        ad.law.pull_off_conditions(ad, ad.contact.derivation("force"), vals)
        if not holds(fd.conditions, vals):
            raise NoPullOffError(f"{ad.profile.name!r}: the pull-off conditions "
                                 f"{fd.conditions} fail at {vals}: no finite pull-off")
        fv = float_values(vals, 80)
        with workdps(dps + 10):
            Pm = real_mpf(sp.N(fd.expr.xreplace(fv), dps + 10))
            A = real_mpf(sp.N(ad.derivation("pull_off_half_width").expr.xreplace(fv), dps + 10))
            adh = -Pm
        if ad._pull_off_closed()["unique"]:   # the law's compact form: one stationary point, the global minimum
            return PullOff(Pm, adh, A, "stationary", None, (), "closed form (single power term)")
        # the closed form is one stationary point: is it the global minimum here?
        land = landscape(ad._law(vals, "closed"))
        with workdps(20):
            best = min(land.minima, key=lambda e: e.force, default=None)
            if best is not None and best.kind == "stationary" and digits_agreeing(best.half_width, A, 20) >= 8:
                return PullOff(Pm, adh, A, "stationary", None, land.minima, land.describe())
    return checked_or_fail(ad, vals, dps)


def checked_or_fail(ad, vals, dps) -> PullOff:
    """:func:`checked`, raising :class:`VerificationError` when the two
    methods agree to fewer than ``dps`` digits (a law without an independent
    second method: method A's pull-off, ``digits`` None)."""
    po = checked(ad, vals, dps)
    if po.digits is None:      # one method only (CohesiveLaw.independent_minimum): nothing to compare
        return po
    if po.digits < dps and po.kind == "end" and reference(ad, vals, dps).kind == "end":
        # both methods: P(a) still decreases where the admissible range ends (dP0/da < 0 beyond: the
        # compact-contact solution ends there), their ends differ; no minimum inside the range
        inner = [e for e in po.minima if e.kind != "end"]
        seen = ("the extrema found: " + ", ".join(f"{e.kind} minimum at a = {mpmath.nstr(e.half_width, 8)}"
                                                  for e in po.minima)) if po.minima else "no extremum found"
        raise NoPullOffError(f"pull-off of {ad.profile.name!r} at {vals}: P(a) has no "
                             f"{'negative ' if inner else ''}minimum inside the admissible "
                             f"range ({seen}); it falls to the range's end (a = {mpmath.nstr(po.half_width, 8)}, "
                             f"P = {mpmath.nstr(po.force, 8)}), beyond which dP0/da < 0 and the compact-contact "
                             f"solution no longer holds: the load-control pull-off is not determined by this model "
                             f"here (a smaller work of adhesion may move a minimum inside the range)")
    if po.digits < dps:
        raise VerificationError(f"pull-off of {ad.profile.name!r}: the two methods agree to "
                                f"{po.digits:.1f} < {dps} digits at {vals}")
    return po


__all__ = ["reference", "checked", "at_values", "remembered_derivations", "remembered_closed_attempt", "single_power",
           "closed_attempt", "derivations", "numeric_derivations",
           "NumericDerivation", "pick_minimum", "tidy_checked", "sample_points", "same_at_points",
           "solve_stationary", "solve_load", "unsolvable", "statement"]
