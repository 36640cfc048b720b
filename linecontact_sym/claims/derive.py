"""What the engine derives for a claim: the :class:`Derived` record and the one
function, :func:`derive`, that maps a claim's quantity to it.

This is the only module of the claims layer that uses the contact API
(``LineContact``, ``derivation``, ``adhesive``, ``profile_from_force``); the
rest of the layer sees :class:`Derived` records.  Quantities without an
engine route (the flat punch, the pulled punch) are built here from the
first-principles references of :mod:`.references`.
"""
from __future__ import annotations

import dataclasses
import time
from dataclasses import dataclass
from typing import Callable

import mpmath
import sympy as sp

from ..core import symbols as S
from ..core.budget import run_with_budget
from ..core.conversion import to_basic, to_mpf
from ..core.errors import ClaimError, DomainError, LineContactError
from .references import (DPS, Comparison, DerivedUndefined, Divergent, Undefined, break_value, flamant_magnitude,
                         flamant_relative_displacement, flamant_resultant, frozen_lambdify, griffith_punch_force, num_eval,
                         numeric_minimum, resolution)
from .memo import minimum_key, point_key, remember, remembered
from .results import REQUIRED_DIGITS, PointResult
from .spec import ASYMMETRIC_QUANTITIES, PLACEHOLDER_FORCE, PLACEHOLDER_P0, VISCOELASTIC, Claim, range_of
from ..core.precision import workdps


@dataclass
class Derived:
    """What the checker compares a printed formula with, for one profile."""

    expr: sp.Expr | None
    method: str
    conditions: tuple = ()
    closed_form: bool = True
    notes: tuple = ()
    seconds: float = 0.0
    verified_digits: float | None = None
    evaluator: Callable | None = None    # (vals, dps) -> mpf
    comparer: Callable | None = None     # (vals, printed_expr, dps) -> [Comparison]
    physics: Callable | None = None      # (vals, printed_expr, dps) -> [Comparison]
    profile: sp.Expr | None = None
    slope: sp.Expr | None = None         # f'(0+)
    variables: frozenset = frozenset()   # symbols the evaluation needs besides those of expr

    def value(self, vals, dps=DPS):
        """The derived value at the point ``vals`` (raises DerivedUndefined
        outside the derivation's conditions)."""
        with workdps(dps + 10):   # arithmetic on the values must not round to 15 digits
            return self._value(vals, dps)

    def _value(self, vals, dps):
        for c in self.conditions:
            try:
                ok = c.xreplace(vals)
                ok = bool(ok) if ok in (sp.true, sp.false) else bool(sp.simplify(ok))
            except TypeError:
                ok = False
            if not ok:
                raise DerivedUndefined(f"outside the derived result's conditions ({c})")
        if self.evaluator is not None:
            return self.evaluator(vals, dps)
        return num_eval(self.expr, vals, dps, what="the derived quantity", exc=DerivedUndefined)

    def compare(self, vals, printed_expr, dps=DPS, physics=False):
        """[Comparison] of the printed expression with the derived quantity at
        ``vals`` (and, with ``physics``, the first-principles checks)."""
        with workdps(dps + 10):   # arithmetic on the values must not round to 15 digits
            return self._compare(vals, printed_expr, dps, physics)

    def _compare(self, vals, printed_expr, dps, physics):
        if self.comparer is not None:
            comps = self.comparer(vals, printed_expr, dps)
        else:
            target = self.value(vals, dps)
            printed = num_eval(printed_expr, vals, dps)
            comps = [Comparison("value", printed, target)]
        if physics and self.physics is not None and not printed_expr.has(sp.Integral):
            comps += self.physics(vals, printed_expr, dps)
        return comps


#: the digits a claim must reproduce (declared in .results, where a failing point is described)
REQUIRED_DIGITS = REQUIRED_DIGITS


def evaluate_point(derived: Derived, printed_expr, vals, kind="random", dps=DPS, physics=False) -> PointResult:
    """Compare at one point; classify what is undefined where.

    The comparison (the printed form's value, the derived one, the
    first-principles references) is remembered in the derivation store
    (:mod:`.memo`: in this process, and on disk unless the cache is off)
    under a key of everything it depends on: the derived record (profile,
    expression, method, conditions), the printed form, the point, the digits,
    and the source of the computing modules (so a changed reference never
    meets a value of its predecessor).  A second run reads the numbers its
    first run computed independently; nothing is skipped."""
    key = point_key(derived, printed_expr, vals, dps, physics)
    pr = remembered(key, PointResult)
    if pr is not None:
        return dataclasses.replace(pr, values=vals, kind=kind)
    pr = _evaluate_point(derived, printed_expr, vals, kind, dps, physics)
    remember(key, pr)
    return pr


def _evaluate_point(derived, printed_expr, vals, kind, dps, physics) -> PointResult:
    try:
        comps = derived.compare(vals, printed_expr, dps, physics=physics)
    except Divergent as exc:
        return PointResult(vals, kind, "diverges", reason=str(exc))
    except DerivedUndefined as exc:
        try:
            num_eval(printed_expr, vals, dps)
        except Undefined:
            return PointResult(vals, kind, "both_undefined", reason=f"both undefined: {exc}")
        return PointResult(vals, kind, "derived_undefined", reason=str(exc))
    except Undefined as exc:
        return PointResult(vals, kind, "printed_undefined", reason=str(exc))
    except (LineContactError, ZeroDivisionError, ValueError, TypeError, OverflowError) as exc:
        return PointResult(vals, kind, "derived_undefined", reason=f"{type(exc).__name__}: {exc}")
    d = min(c.digits for c in comps)
    ok = all(c.digits >= c.required(REQUIRED_DIGITS) for c in comps)
    return PointResult(vals, kind, "pass" if ok else "fail", d, comps)


class Context:
    """Caches engine objects across the claims (and figures) of one run."""

    def __init__(self, budget):
        self.budget = budget
        self.contacts = {}
        self.adhesives = {}
        self.kinds = {}   # (id(contact), kind) -> the contact of that kind

    def contact(self, profile, ranges: Callable, period=None):
        """The contact of ``profile``, its parameters verified over
        ``ranges(symbol)`` (e.g. :meth:`Claim.range_of`); a periodic array
        of ``period`` (a claim's ``period`` field) where given."""
        from ..contacts.normal.contact import LineContact
        params = {}
        for sym in sorted(profile.free_symbols - {S.x}, key=lambda z: z.name):
            params[sym] = ranges(sym)
        key = (profile, tuple(sorted((k.name, v) for k, v in params.items())), period)
        if key not in self.contacts:
            self.contacts[key] = LineContact(profile, params=params or None, budget=self.budget, period=period)
        return self.contacts[key]

    def asymmetric(self, profile, ranges: Callable):
        """The asymmetric contact of ``profile`` (its x read as the real x, on the
        whole line), its parameters verified over ``ranges(symbol)``."""
        from ..contacts.asymmetric.contact import AsymmetricLineContact
        params = {sym: ranges(sym) for sym in sorted(profile.free_symbols - {S.x}, key=lambda z: z.name)}
        key = ("asymmetric", profile, tuple(sorted((k.name, v) for k, v in params.items())))
        if key not in self.contacts:
            self.contacts[key] = AsymmetricLineContact(profile.xreplace({S.x: S.x_real}), params or None,
                                                       budget=self.budget)
        return self.contacts[key]

    def punch(self, half_width):
        """The rigid flat punch of half-width ``half_width`` (a number; walls at -+ it)."""
        from ..contacts.asymmetric.contact import flat_punch
        key = ("punch", half_width)
        if key not in self.contacts:
            self.contacts[key] = flat_punch(half_width, budget=self.budget)
        return self.contacts[key]

    def adhesive(self, profile, ranges: Callable, kind: str = "adhesive", period=None):
        """The adhesive form of :meth:`contact` of the given kind (default
        JKR, work of adhesion gamma), the law's parameters symbolic."""
        from ..contacts.base import contact_kind
        c = self.contact(profile, ranges, period)
        key = (id(c), kind)
        if key not in self.adhesives:
            self.adhesives[key] = contact_kind(kind).from_frictionless(c)
        return self.adhesives[key]


def figure_contacts(profiles, file_ranges: dict, budget: float) -> list:
    """Contacts of the profiles of a figure (parameters verified over the
    file's sampling ranges): objects with ``to_numeric(quantity)``."""
    ctx = Context(budget)
    return [ctx.contact(p, lambda sym: range_of(sym.name, file_ranges)) for p in profiles]


def power_law_force(budget: float):
    """The engine's :class:`~linecontact_sym.method.derivation.Derivation` of
    the force law of the power-law profile c*x**n with symbolic n (Eq. 16),
    for the tables of Z_n."""
    from ..contacts.catalogue import power_law
    return power_law(budget=budget).derivation("force")


def _from_derivation(d, profile=None, slope=None, physics=None) -> Derived:
    rec = d.verification
    return Derived(d.expr, d.method, tuple(d.conditions), d.closed_form, tuple(d.notes), d.seconds,
                   rec.min_digits if rec is not None else None,
                   evaluator=(None if d.closed_form else (lambda vals, dps, d=d: _ref_eval(d, vals, dps))),
                   physics=physics, profile=profile, slope=slope)


def _ref_eval(d, vals, dps):
    try:
        return d.reference(vals, dps)
    except (DomainError, ValueError, ZeroDivisionError) as exc:
        raise DerivedUndefined(f"the derived quantity cannot be evaluated here: {exc}")


def _pressure_physics(profile, force_fn, bps=()):
    """Flamant checks of a pressure: it reproduces the profile under the contact
    and its resultant is the load.  The quadratures are split at the
    profile's breakpoints (the end of a flat); each comparison asks no more
    digits than its quadrature resolves (mpmath's error estimate), and a
    profile value of 0 (inside a flat) is compared on the absolute scale of
    the displacement integral's terms."""
    def physics(vals, printed_expr, dps):
        # the printed pressure with its parameters as symbols and their values
        # apart: Arb's forms are made once for all the points of the claim
        # (SymPy work per point was most of this check); tanh-sinh where Arb cannot
        fixed = {k: to_basic(v) for k, v in sorted(vals.items(), key=lambda kv: kv[0].name) if k != S.x}
        E, av, xv = vals[S.E_star], vals[S.a], vals[S.x]
        with workdps(dps + 10):
            D, errD = flamant_relative_displacement(printed_expr, av, xv, E, dps, bps, with_error=True,
                                                    values=fixed)
            fx = num_eval(profile, {**vals}, dps, what="the profile", exc=DerivedUndefined)
            res, errR = flamant_resultant(printed_expr, av, dps, bps, with_error=True, values=fixed)
            Pa = force_fn(vals, dps)
            if fx != 0:
                scale = abs(fx)
            else:
                breaks = [break_value(b.xreplace(fixed), dps) for b in bps]
                scale = flamant_magnitude(printed_expr.xreplace(fixed), av, xv, E, breaks)
        return [Comparison("Flamant: u_z(0) - u_z(x) = f(x) under the contact", D, fx, scale,
                           resolution(errD, scale)),
                Comparison("Flamant: resultant = P(a)", res, Pa, None, resolution(errR, Pa))]
    return physics


def _where(claim):
    return f"{claim.source}: claim {claim.label!r}"


def derive(claim: Claim, profile, ctx: Context) -> Derived:
    """The derived counterpart of ``claim.quantity`` for one profile."""
    q = claim.quantity
    if q in ("force", "pressure", "gap", "Z_n", "profile_at_a", "half_width"):
        c = ctx.contact(profile, claim.range_of, claim.period)
        slope = c.profile.slope_at_origin
        if q == "profile_at_a":
            return Derived(profile.xreplace({S.x: S.a}), "the profile itself, f(a)", profile=profile,
                           slope=slope)
        if q == "Z_n":
            d = c.derivation("force")
            if not d.closed_form:
                raise ClaimError(f"{_where(claim)}: the engine found no closed force law")
            Z = sp.simplify(sp.gammasimp(d.expr / (S.E_star * S.c * S.a**S.n)))
            if Z.free_symbols - {S.n}:
                raise ClaimError(f"{_where(claim)}: Z_n needs a power-law profile c*x**n; "
                                 f"P/(E* c a^n) = {Z} depends on {sorted(map(str, Z.free_symbols))}")
            return Derived(Z, f"P(a)/(E* c a^n) of the engine's force law ({d.method})", d.conditions,
                           True, tuple(d.notes), d.seconds,
                           d.verification.min_digits if d.verification else None, profile=profile, slope=slope)
        if q == "half_width":
            return _from_derivation(c.half_width(S.P), profile, slope)
        d = c.derivation(q)
        physics = None
        if q == "pressure" and claim.period is None:   # (the Flamant checks are the isolated half-plane's)
            fd = c.derivation("force")
            physics = _pressure_physics(profile, lambda vals, dps: _from_derivation(fd).value(vals, dps),
                                        c.profile.breakpoints)
        return _from_derivation(d, profile, slope, physics)
    if q in VISCOELASTIC:
        return _derive_viscoelastic(claim, profile, ctx)
    adhesive = adhesive_entry(q)
    if adhesive is not None:
        return _derive_adhesive(claim, profile, ctx, *adhesive)
    if q == "inverse_profile":
        from ..contacts.normal.inverse import profile_from_force
        t0 = time.perf_counter()
        d = profile_from_force(claim.force_law, budget=ctx.budget)
        out = _from_derivation(d)
        out.seconds = time.perf_counter() - t0
        return out
    if q in ASYMMETRIC_QUANTITIES:
        return _derive_asymmetric(claim, profile, ctx)
    if q == "flat_punch_pressure":
        return _flat_punch_pressure()
    if q == "flat_punch_displacement":
        return _flat_punch_displacement()
    if q == "punch_adhesion_force":
        return _punch_adhesion_force(ctx)
    return _derive_registered(claim, profile, ctx)


def _derive_viscoelastic(claim, profile, ctx) -> Derived:
    """P(t) for the half-width history a(t), or a(t) for the load history P(t)
    (creep), of the claim's profile on the claim's material: the engine's
    closed form (Popov's superposition in time), or the unevaluated one with
    the superposition's quadrature at the points."""
    from ..method.material import Material
    t0 = time.perf_counter()
    c = ctx.contact(profile, claim.range_of, claim.period)
    key = ("viscoelastic", claim.quantity, id(c), claim.material, claim.impulse, claim.history)
    if key in ctx.kinds:             # the claims of one history (its right and wrong formulas) derive it once
        return ctx.kinds[key]
    v = c.viscoelastic(Material(claim.material, claim.impulse, "the claim's material"))
    h = claim.history
    if claim.quantity == "viscoelastic_force":
        expr, what, how = v.force_history(h), "force", "Lee-Radok (Ting after the maximum) on Popov's superposition"
    else:
        expr, what, how = v.half_width_history(h), "half_width", "creep: Pi(a(t)) = int J*(t - u) dP(u)"
    closed = not expr.has(sp.Integral, sp.InverseLaplaceTransform)

    def evaluator(vals, dps):
        by = {k.name: val for k, val in vals.items() if k not in (S.t, S.x, S.a, S.P, S.E_star)}
        try:
            return v.evaluate_at(what, vals[S.t], h.xreplace({k: val for k, val in vals.items() if k != S.t}),
                                 dps=dps, **{k: val for k, val in by.items() if k in {s.name for s in v.variables}})
        except (DomainError, ValueError, ZeroDivisionError) as exc:
            raise DerivedUndefined(f"the derived quantity cannot be evaluated here: {exc}")
    ctx.kinds[key] = Derived(expr, how, closed_form=closed, seconds=time.perf_counter() - t0,
                             evaluator=None if closed else evaluator, profile=profile,
                             variables=frozenset({S.t} | h.free_symbols | set(v.variables)))
    return ctx.kinds[key]


def _derive_registered(claim, profile, ctx) -> Derived:
    """Any quantity of any contact kind, by its registry name ('tangential.slip'):
    the kind is built on the frictionless contact of the profile."""
    from ..contacts.base import contact_kind, qualified_quantities
    entry = qualified_quantities().get(claim.quantity)
    if entry is None:
        raise ClaimError(f"{_where(claim)}: quantity {claim.quantity!r} is not implemented")
    kind, name, quantity = entry
    t0 = time.perf_counter()
    c = ctx.contact(profile, claim.range_of, claim.period)
    contact = ctx.kinds.get((id(c), kind))
    if contact is None:
        contact = ctx.kinds[(id(c), kind)] = contact_kind(kind).from_frictionless(c)
    if quantity.method:   # a(P), c_s(Q): the symbolic form is the method's default
        d = getattr(contact, name)()
        d = d[0] if isinstance(d, tuple) else d
    else:
        d = contact.derivation(name)
    out = _from_derivation(d, profile, c.profile.slope_at_origin)
    out.seconds = time.perf_counter() - t0
    return out


def placeholder_laws(claim: Claim, profile, ctx: Context):
    """(P_0, p_0): the engine's closed-form force law and pressure of
    ``profile`` where the claim's forms use the placeholders force(.) and p0
    (None where unused or not closed)."""
    dforce = dpress = None
    if not claim.general:
        return dforce, dpress
    c = ctx.contact(profile, claim.range_of, claim.period)
    if any(f.expr.has(PLACEHOLDER_FORCE) for f in claim.forms):
        fd = c.derivation("force")
        dforce = fd.expr if fd.closed_form else None
    if any(f.expr.has(PLACEHOLDER_P0) for f in claim.forms):
        pd = c.derivation("pressure")
        dpress = pd.expr if pd.closed_form else None
    return dforce, dpress


# ---------------------------------------------------------------- adhesion
def _adhesion_item(ad, name):
    if hasattr(ad, "derivation"):
        try:
            return ad.derivation(name)
        except (KeyError, ValueError, AttributeError, TypeError):
            pass
    return getattr(ad, name)


def _as_derived(obj, method) -> Derived:
    from ..method.derivation import Derivation
    if isinstance(obj, Derivation):
        return _from_derivation(obj)
    return Derived(to_basic(obj), method)


#: the quantities of every adhesive contact kind that the checker derives with
#: its own checks (the pressure's physics, an independent minimum)
ADHESIVE_QUANTITIES = ("force", "pressure", "pull_off_force", "adhesion_force", "pull_off_half_width")


def adhesive_entry(q):
    """(kind, name) when ``q`` names a generic quantity of an adhesive contact
    kind (any cohesive law: 'pull_off_force', 'adhesive_force' for JKR,
    '<kind>.pull_off_force' for another law), else None."""
    from ..contacts.base import contact_kind, qualified_quantities
    entry = qualified_quantities().get(q)
    if entry is None:
        return None
    kind, name, _ = entry
    if name not in ADHESIVE_QUANTITIES or getattr(contact_kind(kind), "law_class", None) is None:
        return None
    return kind, name


def _derive_adhesive(claim, profile, ctx, kind="adhesive", q=None) -> Derived:
    t0 = time.perf_counter()
    q = q or claim.quantity
    ad = ctx.adhesive(profile, claim.range_of, kind, claim.period)
    slope = ctx.contact(profile, claim.range_of, claim.period).profile.slope_at_origin
    force = _as_derived(_adhesion_item(ad, "force"), f"adhesive force law (engine, {ad.law.title})")
    if q == "force":
        out = force
    elif q == "pressure":
        out = _as_derived(_adhesion_item(ad, "pressure"), f"adhesive pressure (engine, {ad.law.title})")
        if claim.period is None:     # (the Flamant checks are the isolated half-plane's)
            out.physics = _pressure_physics(profile, force.value, ad.profile.breakpoints)
    elif q == "pull_off_half_width":
        out = _as_derived(_adhesion_item(ad, "pull_off_half_width"), "half-width at pull-off (engine)")
    else:
        return _derive_pull_off(q, ad, force, profile, slope, t0)
    out.profile, out.slope = profile, slope
    out.seconds = time.perf_counter() - t0
    return out


def _derive_pull_off(q, ad, force, profile, slope, t0) -> Derived:
    """P_min < 0 (``pull_off_force``) or P_adh = -P_min > 0 (``adhesion_force``):
    the engine's closed form, and an independent numeric minimum of the
    engine's force law P(a) over a."""
    sign = 1 if q == "pull_off_force" else -1      # the claimed value is sign * min_a P(a)
    engine = _as_derived(_adhesion_item(ad, q), f"{q} (engine)")
    Pexpr = force.expr
    if not force.closed_form:   # P(a) is a system (an inner solve): the contact's method B minimum
        from ..contacts.adhesion.pull_off import reference as pull_off_reference
        def minimum(vals, dps):
            # computed once per law and point (remembered as the points' comparisons are,
            # :mod:`.memo`): the same minimum serves every printed form compared with it
            key = minimum_key(engine, profile, vals, dps)
            m = remembered(key, mpmath.mpf)
            if m is None:
                try:
                    # a law whose grid search shares its inner solve (Maugis-Dugdale: a quadrature inside
                    # a quadrature at every grid point, past 200 s for cosh) gains nothing from it: the
                    # contact's own search (with its limits, under the search budget), labelled so
                    m = (pull_off_reference(ad, vals, dps) if ad.law.independent_minimum
                         else ad._pull_off_checked(vals, dps)).force
                except LineContactError as exc:
                    raise DerivedUndefined(f"P(a) has no minimum over a > 0: {exc}")
                if isinstance(m, mpmath.mpf):
                    remember(key, m)
            return sign * m
        label = None if ad.law.independent_minimum else \
            "numeric, the contact's own search (the law has no independent second minimisation: not independent)"
        return _pull_off_derived(q, ad, engine, minimum, sign, profile, slope, t0, Pexpr, label)
    dPexpr = sp.diff(Pexpr, S.a)

    def minimum(vals, dps):
        fixed = {k: v for k, v in vals.items() if k != S.a}
        Pf = sp.lambdify(S.a, Pexpr.xreplace(fixed), "mpmath")
        dPf = frozen_lambdify(dPexpr.xreplace(fixed), S.a, dps + 10)     # thousands of calls in the scan
        m = numeric_minimum(Pf, dPf, 1, dps)
        if m is None:
            raise DerivedUndefined("P(a) of Eq. (33) has no minimum over a > 0: no pull-off force exists")
        return sign * m[1]
    return _pull_off_derived(q, ad, engine, minimum, sign, profile, slope, t0, Pexpr)


def _pull_off_derived(q, ad, engine, minimum, sign, profile, slope, t0, Pexpr, label=None) -> Derived:
    what = "min_a P(a)" if sign == 1 else "-min_a P(a)"
    label = label or "numeric (independent)"

    def comparer(vals, printed_expr, dps):
        printed = num_eval(printed_expr, vals, dps)
        comps = [Comparison(f"{what}, {label}", printed, minimum(vals, dps))]
        try:
            ev = engine.value(vals, dps)
        except (Undefined, LineContactError) as exc:
            raise DerivedUndefined(f"the engine's {q} is undefined here: {exc}")
        comps.insert(0, Comparison(f"engine {q}", printed, ev))
        return comps

    note = (f"{q} = {'P_min = min_a P(a) < 0' if sign == 1 else 'P_adh = -min_a P(a) > 0'}; the minimum of "
            f"the engine's P(a) over a is also located numerically")
    return Derived(engine.expr, engine.method + "; independent: numeric minimum of P(a)", engine.conditions,
                   engine.closed_form, tuple(engine.notes) + (note,), time.perf_counter() - t0,
                   engine.verified_digits, evaluator=minimum, comparer=comparer, profile=profile, slope=slope,
                   variables=frozenset(ad.variables) if not isinstance(Pexpr, sp.Expr) else
                   frozenset(Pexpr.free_symbols - {S.a}))


# ---------------------------------------------------------------- asymmetric contacts
def _claim_symbol(claim, name):
    """The claim's symbol ``name`` (declared in its ``symbols``, or standard)."""
    from ..parsing import SYMBOLS
    sym = claim.symbols.get(name) or SYMBOLS.get(name)
    if sym is None:
        raise ClaimError(f"{_where(claim)}: quantity {claim.quantity!r} uses the symbol {name}: "
                         f"declare it (symbols = [\"{name}\"])")
    return sym


def _by_name(vals):
    return {k.name: v for k, v in vals.items()}


def _derive_asymmetric(claim, profile, ctx) -> Derived:
    """The asymmetric contact's quantities (:data:`~.spec.ASYMMETRIC_QUANTITIES`):
    P, theta, M of the bounded contact as functions of the centre e and the
    half-width a (the engine's symbolic results, the claim's e for the real
    e), the ends at a load and a tilt (the engine's state, solved at the
    claim's digits), and the flat punch under a load and a moment."""
    q = claim.quantity
    t0 = time.perf_counter()
    if q.startswith("punch."):
        return _derive_punch(claim, ctx, t0)
    c = ctx.asymmetric(profile, claim.range_of)
    params = frozenset(c.params)
    if q in ("asymmetric.force", "asymmetric.tilt", "asymmetric.moment"):
        what = q.split(".")[1]
        e = _claim_symbol(claim, "e")
        expr = {"force": c.core.force, "tilt": c.core.tilt, "moment": c.core.moment}[what]()
        method = f"{what} of the bounded contact on [e - a, e + a]: the engine's even/odd parts (OffsetContact)"
        closed = not expr.has(sp.Integral, sp.Derivative, sp.Piecewise)
        if closed:
            return Derived(expr.xreplace({S.e: e}), method, profile=profile, seconds=time.perf_counter() - t0,
                           variables=frozenset({S.a, S.E_star, e}) | params)
        attr = {"force": "P", "tilt": "tilt", "moment": "moment"}[what]

        def numbers(vals, dps):
            v = _by_name(vals)
            n = c.core.numbers(**{k: v[k] for k in v if k not in ("e", "a")})
            return getattr(n, attr)(to_mpf(v["e"]), to_mpf(v["a"]))
        return Derived(None, method + " (quadrature)", closed_form=False, evaluator=numbers, profile=profile,
                       seconds=time.perf_counter() - t0, variables=frozenset({S.a, S.E_star, e}) | params)
    what = q.split(".")[1]

    def state(vals, dps):
        v = _by_name(vals)
        rest = {k: v[k] for k in v if k not in ("P", "theta", "x")}
        st = c.contact_at(v["P"], theta=v["theta"], dps=dps, **rest)
        return st.e if what == "centre" else st.a
    return Derived(None, f"{what} of the contact at the load P and the tilt theta (engine state, contact_at)",
                   closed_form=False, evaluator=state, profile=profile, seconds=time.perf_counter() - t0,
                   variables=frozenset({S.P, S.theta, S.E_star}) | params)


def _derive_punch(claim, ctx, t0) -> Derived:
    """The rigid flat punch of half-width a at the load P and the moment M:
    its pressure and tilt from the engine's state (complete contact, or an
    edge lifted), and the moment at which a corner factor of the complete
    contact vanishes (the engine's corner factors, solved by SymPy)."""
    q = claim.quantity
    M = _claim_symbol(claim, "M")
    if q == "punch.lift_off_moment":
        core = ctx.punch(1).core          # its symbolic results are in the centre e and the half-width a
        th = sp.Dummy("theta", real=True)
        at_centre = {S.e: 0}
        tilt = sp.solve(sp.Eq(core.moment_centre(theta=th).xreplace(at_centre), M), th)
        if len(tilt) != 1:
            raise ClaimError(f"{_where(claim)}: the punch's tilt under a moment is not one solution: {tilt}")
        factors = core.edge_factors(theta=tilt[0], punch=S.P - core.force())
        roots = [r for K in factors for r in sp.solve(K.xreplace(at_centre), M)]
        # a positive moment (the claim's M): the root positive at positive P, a, E*
        roots = [sp.simplify(r) for r in roots if r.xreplace({v: 1 for v in r.free_symbols}).is_positive]
        if len(roots) != 1:
            raise ClaimError(f"{_where(claim)}: no single positive lift-off moment among {roots}")
        return Derived(roots[0], "a corner factor K of the complete contact (engine) = 0, solved for M",
                       seconds=time.perf_counter() - t0)
    what = q.split(".")[1]

    def state(vals, dps):
        v = _by_name(vals)
        st = ctx.punch(v["a"]).contact_at(v["P"], moment=v["M"], dps=dps, E_star=v["E_star"])
        return st.theta if what == "tilt" else st.pressure(to_mpf(v["x"]))
    variables = {S.P, S.a, S.E_star, M} | ({S.x} if what == "pressure" else set())
    return Derived(None, f"{what} of the flat punch at the load P and the moment M (engine state, contact_at)",
                   closed_form=False, evaluator=state, seconds=time.perf_counter() - t0,
                   variables=frozenset(variables))


# ---------------------------------------------------------------- first principles
def _flat_punch_pressure() -> Derived:
    """Eq. (1) is checked, not compared: the printed pressure must carry the load
    (resultant P) and leave the surface flat under the punch (Flamant)."""
    def comparer(vals, printed_expr, dps):
        fixed = {k: v for k, v in vals.items() if k != S.x}
        p = printed_expr.xreplace(fixed)   # SymPy, in x alone: Arb where it can, tanh-sinh where not
        av, xv, E, Pv = (vals[s] for s in (S.a, S.x, S.E_star, S.P))
        with workdps(dps + 10):
            res = flamant_resultant(p, av, dps)
            Pv, E = to_mpf(Pv), to_mpf(E)
            D = flamant_relative_displacement(p, av, xv, E, dps)
            scale = 2 * Pv / (mpmath.pi * E)
        return [Comparison("resultant int p dx = P", res, Pv),
                Comparison("flat base: u_z(0) - u_z(x) = 0 under the punch (Flamant)", D, mpmath.mpf(0), scale)]
    return Derived(None, "first principles: resultant and Flamant displacement of the printed pressure",
                   comparer=comparer)


def _flat_punch_displacement() -> Derived:
    """d - u_z(x) outside the punch from the Flamant kernel applied to the
    flat-punch pressure P/(pi sqrt(a^2 - x^2)) (whose correctness is claim Eq. (1))."""
    def evaluator(vals, dps):
        av, xv, E, Pv = (to_basic(vals[s]) for s in (S.a, S.x, S.E_star, S.P))
        s_ = sp.Dummy("s")
        return flamant_relative_displacement(Pv / (sp.pi * sp.sqrt(av**2 - s_**2)), av, xv, E, dps)
    return Derived(None, "Flamant kernel applied to the flat-punch pressure P/(pi sqrt(a^2 - x^2))",
                   closed_form=False, evaluator=evaluator)


def _punch_adhesion_force(ctx) -> Derived:
    t0 = time.perf_counter()
    sol1, sol2, G, K = run_with_budget(griffith_punch_force, seconds=max(ctx.budget, 30))
    if len(sol1) != 1 or len(sol2) != 1 or sp.simplify(sol1[0] - sol2[0]) != 0:
        raise ClaimError(f"Griffith derivation of Eq. (31) inconclusive: {sol1} vs {sol2}")
    note = (f"energy route: G = Phat^2/(2 pi a E*) from the compliance of Eq. (3); stress-intensity route: "
            f"K_I = {K}, G = K_I^2/(2E*); both give Phat = {sol1[0]}")
    return Derived(sol1[0], "energy-release rate of the pulled flat punch (Griffith), two routes",
                   notes=(note,), seconds=time.perf_counter() - t0)


__all__ = ["Derived", "Context", "derive", "evaluate_point", "REQUIRED_DIGITS", "adhesive_entry", "ADHESIVE_QUANTITIES", "placeholder_laws", "figure_contacts", "power_law_force"]
