"""Maugis-Dugdale adhesion of line contacts of any profile: the JKR-to-rigid
transition (Baney & Hui 1997 for the parabola; here for any profile through
Popov's 2017 flat-punch superposition, see :mod:`.derive`).

    md = contact.maugis_dugdale(w, sigma0)
    md.conditions            # (bounded pressure, gap at c_D = h0) as SymPy equations
    md.state(a, **values)    # c_D, P, pressure and gap profiles at a half-width
    md.pull_off_at(**values) # load-control pull-off (global minimum or infimum P(0+)): the generic layer's
    md.half_width(P, **values), md.branches(P, **values), md.jump_in_half_width   # likewise
    md.model_choice(rtol, **values)   # JKR or MD, with the Maugis parameter

The two conditions (derived per profile from the engine's force law P0(a)
and adhesionless gap g0(x; a)):

    P(a, c_D)  = P0(a) - 2 sigma_0 sqrt(c_D^2 - a^2)                      (bounded pressure, K_I = 0)
    h0 = w/sigma_0 = g0(c_D; a) + (4 sigma_0/(pi E*)) (sqrt(c_D^2 - a^2) acosh(c_D/a) - c_D log(c_D/a))

Where the engine leaves g0(x; a), P0(a) or p0(x; a) as an unevaluated
Integral (R (cosh(x/R) - 1), the Gaussian bump, a user's profile), the
numeric law (:class:`.numbers.MDLaw`) evaluates those defining integrals
by quadrature inside the solve, at the digits asked (``MDState.closed`` says
which parts were closed); the cohesive zone never leaves the profile's real
domain (the exact cylinder: c_D < R, else a DomainError).

JKR limit: sigma_0 -> oo gives c_D - a -> pi E* w/(4 sigma_0^2) and
2 sigma_0 sqrt(c_D^2 - a^2) -> sqrt(2 pi a w E*), Popov's Eq. (31).

Displacement control is not defined for line contacts: the indentation
depth of a half-plane is not (Popov 2017, Eqs. 2-3: only differences of
displacements are); there is no fixed-grips pull-off here.

The Maugis parameter of any profile (``maugis_parameter``): Baney & Hui's
lambda = 4 sigma_0 (R/(pi^2 E*^2 w))^(1/3) equals, for the parabola,
sqrt(2^(5/3) a_JKR/delta) with a_JKR the JKR pull-off half-width and
delta = pi E* w/(4 sigma_0^2) the cohesive-zone length of the JKR limit
(shown in the tests); the latter form defines lambda for every profile.
"""
from __future__ import annotations

import contextlib
import time

import mpmath
import sympy as sp

from ....core import symbols as S
from ....core.conversion import float_values, point_value, rational, to_mpf
from ....core.errors import DomainError, NumericValuesRequired
from ....core.roots import Outside
from ....core.precision import workdps
from ....core.ranges import check_positive, check_tolerance
from ....method.derivation import Derivation, agrees_at_random_point, remembered
from ....method.rules import Step
from ....method.verification import verify
from ....parsing import to_sympy
from ...base import Quantity
from ..contact import AdhesiveContact
from ...normal.force_law import ScanHint
from ..law import CohesiveLaw, Parameter, on_base
from ...sampling import point_sampler
from . import choice as maugis_choice
from .choice import ModelChoice
from .derive import dugdale_parts
from .limits import HalfWidths, JKRLimit, jkr_equilibria, jkr_state, limit_model, limit_pull_off
from .numbers import MDLaw, MDState

#: ranges of sigma_0 and of c_D/a - 1 at the verification points
SIGMA0_RANGE = (0.05, 3.0)
ZONE_RANGE = (0.01, 2.0)
#: Baney & Hui's normalisation, here (parabola of radius R)
DISPLACEMENT_CONTROL = ("displacement control is not defined for line contacts: the indentation depth of a "
                        "half-plane is not (Popov 2017, Eqs. 2-3, only displacement differences are); "
                        "the pull-off here is the load-control one")


class MaugisDugdale(CohesiveLaw):
    """The Maugis-Dugdale (cohesive-zone) law of a line contact: constant
    tension sigma_0 on a < |x| < c_D while the gap is below h0 = w/sigma_0.
    Its balance is a system in (a, c_D, P): bounded pressure at x = +-a and
    gap(c_D) = h0 (:attr:`conditions` of the contact); P(a) needs the inner
    solve for c_D(a) (:mod:`.numbers`).

    >>> MaugisDugdale().balance
    'bounded pressure at x = +-a (K_I = 0) and gap(c_D) = gamma/sigma_0'
    """

    name = "maugis_dugdale"
    kind = "maugis_dugdale"
    # its quadrature twin shares the inner solve c_D(a): no independent method B on it (the
    # independent checks are Johnson's condition and the Flamant kernel, maugis.check and the tests)
    independent_minimum = False
    title = "Maugis-Dugdale (cohesive zone; Baney & Hui 1997 for the parabola, any profile here)"
    label = "Maugis-Dugdale"
    parameters = (Parameter("work_of_adhesion", S.gamma, "positive", "the work of adhesion w", (0.05, 1.0)),
                  Parameter("sigma0", S.sigma_0, "positive", "the cohesive stress sigma_0", SIGMA0_RANGE))

    @property
    def balance(self):
        return f"bounded pressure at x = +-a (K_I = 0) and gap(c_D) = {self['work_of_adhesion'] / self['sigma0']}"

    def derive_force(self, ad) -> Derivation:
        """P(a): the two conditions as equations (no closed P(a): c_D(a) is an inner solve)."""
        return _numeric(ad, "force", sp.Tuple(*ad.conditions), lambda v, d: ad.state(v.pop("a"), d, **v).force,
                        "P(a) by the inner solve of the gap condition for c_D (maugis.numbers)", (S.a,))

    def derive_pressure(self, ad) -> Derivation:
        return _numeric(ad, "pressure", sp.Tuple(sp.Eq(sp.Symbol("p"), ad.derivation("pressure").expr),
                                                 ad.conditions[1]),
                        lambda v, d: ad.state(v.pop("a"), d, **v).pressure(v.pop("x", 0)),
                        "p(x; a) at c_D(a) from the inner solve", (S.a, S.x))

    def numeric(self, base, values):
        """P(a), dP/da at numbers on ``base``: base.P(a) - 2 sigma_0 sqrt(c_D^2 - a^2) with c_D(a) from
        the gap condition (the quadrature twin uses the quadrature P0)."""
        md = getattr(self, "on_contact", None)      # set by the contact that holds this law
        if md is None:
            raise NotImplementedError("the Maugis-Dugdale law needs its contact's closed forms: build it with "
                                      "contact.adhesion('maugis_dugdale', ...) or contact.maugis_dugdale(...)")
        law = md.numeric_law(**{k.name: v for k, v in values.items() if k in set(md.variables)})

        def build(b):
            memo = {}

            def PdP(A):
                """(P - P0, dP/da - dP0/da) of the Dugdale zone at A: one inner solve for both."""
                key = (A, mpmath.mp.dps)
                if key not in memo:
                    # at 3 digits below the working precision: c_of resolves dps + 4 (its tolerance, guard digits above)
                    try:
                        Pv, dPv, C = law.P_and_slope(A, mpmath.mp.dps - 3)
                    except DomainError:   # no cohesive zone inside the profile's domain: no state at A
                        raise Outside
                    if len(memo) > 4096:
                        memo.clear()
                    memo[key] = (Pv - law._P0(A), dPv - law._dP0(A))
                return memo[key]

            def P(A):
                if A <= 0:            # the limit a -> 0+: the Dugdale force of the zone c0
                    return law.force_zero_width(mpmath.mp.dps)
                return b.P(A) + PdP(A)[0]

            def dP(A):
                if A <= 0:
                    return mpmath.mpf(0)
                return b.dP(A) + PdP(A)[1]
            out = b.on_top(P, dP)
            # P(0+) = -2 sigma_0 c0 is not 0: the generic minimum descends towards a -> 0+ (equilibria.descent)
            out.P_zero = lambda: law.force_zero_width(mpmath.mp.dps)
            # from c0/1000, but never above the profile's own scale/1000: a bounded profile (1 - cos x) at a
            # tiny sigma_0 has c0 ~ 1e10, and a scan from 1e7 lay past the whole admissible range (a* = 2.4)
            out.scan = ScanHint(lambda: min(law.c0(15), b.scale) / 1000, 8,
                                "no Maugis-Dugdale extremum lies within 1/8 decade of another, nor above the first "
                                "a past every kink with P > 0 and dP/da > 0 (the Dugdale term's slope tends to 0 "
                                "from below as a grows, dP0/da >= 0); below c0/1000 the descent follows dP/da")
            return out
        return on_base(base, build)


def _numeric(ad, name, expr, fn, what, args):
    from ..pull_off import NumericDerivation
    step = Step("numeric", expr, (), (what,))
    return NumericDerivation(name, expr=expr, closed_form=False, step=step, seconds=0.0, notes=(what,),
                             reference=lambda vals, dps: fn({k.name: v for k, v in vals.items()}, dps),
                             variables=args + ad.variables)


class MaugisDugdaleContact(AdhesiveContact):
    """Maugis-Dugdale adhesive form of a frictionless line contact; see the
    module docstring.  The generic :class:`~..contact.AdhesiveContact` (its
    pull-off, ``half_width(P)``, ``branches``, jump-in, ``force_at``, ``at``)
    plus what only this law has: its conditions and their closed parts, the
    state at a half-width, the numeric law, the Maugis parameter and the
    model choice.

    >>> import linecontact_sym as lcs
    >>> md = lcs.parabola().maugis_dugdale()
    >>> md.zone_force
    pi*E_star*a**2/(4*R) - 2*sigma_0*sqrt(-a**2 + c_D**2)
    """

    kind = "maugis_dugdale"

    force = Quantity("P(a)", "", "load per unit length at the half-width a, c_D(a) solved from the gap "
                     "condition (negative = tensile); numeric: its expression is the two conditions",
                     aliases=("md_force",), latex=r"P_{\mathrm{MD}}(a)", unit="N/m")
    zone_force = Quantity("P(a, c_D)", "bounded pressure", "load per unit length P0(a) - 2 sigma_0 sqrt(c_D^2 - a^2) "
                          "at the half-widths a and c_D (negative = tensile)", arguments=("a", "c_D"),
                          aliases=("md_zone_force",), latex=r"P_{\mathrm{MD}}(a, c_{\mathrm{D}})", unit="N/m")
    cohesive_gap = Quantity("g(c_D; a)", "Dugdale gap", "surface separation at the end of the cohesive zone; "
                            "equals h0 = w/sigma_0 at equilibrium", arguments=("a", "c_D"),
                            aliases=("gap_at_c",), latex=r"g(c_{\mathrm{D}})", unit="m")
    pressure = Quantity("p(x; a, c_D)", "Eq. (12) + Dugdale", "pressure in the contact |x| < a (compressive "
                        "positive; -sigma_0 at the edges, bounded)", arguments=("a", "c_D", "x"), domain="inside",
                        aliases=("md_pressure",), latex=r"p_{\mathrm{MD}}(x)", unit="Pa")
    dugdale_force = Quantity("P_D(a, c_D)", "", "force of the Dugdale punches, -2 sigma_0 sqrt(c_D^2 - a^2)",
                             arguments=("a", "c_D"), latex=r"P_{\mathrm{D}}", unit="N/m")

    pull_off_force = Quantity("P_min", "", "load-control pull-off: the global minimum of P(a) (or its infimum "
                              "P(0+) as a -> 0+), negative (tensile); numeric", arguments=(),
                              aliases=("md_pull_off_force",), latex=r"P_{\min}^{\mathrm{MD}}", unit="N/m")
    adhesion_force = Quantity("P_adh", "", "adhesion force -P_min > 0; numeric", arguments=(),
                              aliases=("md_adhesion_force",), latex=r"P_{\mathrm{adh}}^{\mathrm{MD}}",
                              unit="N/m")
    pull_off_half_width = Quantity("a_po", "", "half-width at pull-off (0 where the pull-off is the infimum "
                                   "P(0+)); numeric", arguments=(), latex=r"a_{\mathrm{po}}^{\mathrm{MD}}",
                                   unit="m")
    maugis_lambda = Quantity("lambda", "", "Maugis parameter sqrt(2^(5/3) a_JKR/delta), delta = pi E* w/(4 sigma_0^2) "
                             "(Baney & Hui's 4 sigma_0 (R/(pi^2 E*^2 w))^(1/3) for the parabola); numeric",
                             arguments=(), aliases=("maugis_parameter",), latex=r"\lambda", unit="")

    law_class = MaugisDugdale

    def __init__(self, contact, w=S.gamma, sigma0=S.sigma_0, values=None):
        super().__init__(contact, MaugisDugdale(w, sigma0), values)   # the parameters checked
        self.law.on_contact = self      # the law's numbers need this contact's closed forms
        self.w, self.sigma0 = self.law["work_of_adhesion"], self.law["sigma0"]

    @classmethod
    def with_law(cls, contact, law, values=None):
        """The contact of the law object ``law`` (the generic layer's constructor)."""
        return cls(contact, law["work_of_adhesion"], law["sigma0"], values)

    def __repr__(self):
        return f"MaugisDugdaleContact({self.contact.profile.expr}, w={self.w}, sigma0={self.sigma0})"

    @property
    def h0(self):
        """The range of the Dugdale law, h0 = w/sigma_0 (w = sigma_0 h0)."""
        return self.w / self.sigma0

    def _value(self, name):
        if name in ("pull_off_force", "adhesion_force", "pull_off_half_width", "jump_in_half_width"):
            return super()._value(name)
        d = self.derivation(name)
        if not d.closed_form and d.reference is not None and self.values and \
                all(s in self.values for s in self.variables):
            return d.reference(self.values, 30)      # a numeric quantity at bound values: the number (as JKR's)
        return self._bind(d.expr)

    # ------------------------------------------------------------ the derivation
    @property
    def dugdale(self):
        return dugdale_parts(self.sigma0)

    @property
    def force_expr(self):
        return self.derivation("zone_force").expr

    @property
    def gap_c_expr(self):
        return self.derivation("cohesive_gap").expr

    @property
    def pressure_expr(self):
        return self.derivation("pressure").expr

    @property
    def zero_width_expr(self):
        """The gap condition's left side as a -> 0+ (P0 -> 0, g0(c; a) -> f(c)): f(c_D) + 4 ln2 sigma_0 c_D/(pi E*)."""
        return self.profile.expr.subs(S.x, S.c_D) + self.dugdale.zero_width

    @property
    def force_zero_width_expr(self):
        """lim_{a->0+} P(a, c_D) = -2 sigma_0 c_D (the Dugdale force; P0(0) = 0)."""
        return sp.limit(self.dugdale.force, S.a, 0, "+")

    @property
    def conditions(self):
        """The two Maugis-Dugdale conditions as SymPy equations: bounded
        pressure at x = +-a (solved for P) and the gap at c_D equal to h0."""
        return (sp.Eq(S.P, self.zone_force), sp.Eq(self.cohesive_gap, self.h0))

    def _sampler(self, domain="any"):
        base = point_sampler(self.profile, domain, {s: SIGMA0_RANGE for s in self._lsyms})

        def sample(rng):
            v = base(rng)
            if v is None:
                return None
            v[S.c_D] = v[S.a] * rational(1 + rng.uniform(*ZONE_RANGE))
            return float_values(v, 80)
        return sample

    def _record(self, name, expr, closed, steps, reference, t0, conditions=()):
        """The derivation of ``name``: ``expr`` verified against ``reference``; remembered
        (:func:`~linecontact_sym.method.derivation.remembered`, in memory and on disk, keyed by
        the profile, the expression, its conditions and the verification settings: another
        contact of the same profile and law, in this process or another, does not verify it
        again).  A closed form read from disk is re-checked against this contact's
        independent reference at one random point (:func:`~linecontact_sym.method.derivation.agrees_at_random_point`)."""
        sampler = self._sampler("inside" if name == "pressure" else "any")

        def make():
            rec = None
            if closed and self.contact.verify and reference is not None:
                rec = verify(expr, reference, sampler, conditions, n_points=self.contact.points,
                             reference_name=_REFERENCE_NAMES[name])
                if not rec.passed:
                    from ....core.errors import VerificationError
                    raise VerificationError(f"{name} of the Maugis-Dugdale contact of {self.profile.name!r}: {rec}")
            step = Step("maugis_dugdale", expr, tuple(conditions), tuple(steps))
            return Derivation(name, expr=expr, closed_form=closed, step=step, conditions=tuple(conditions),
                              verification=rec, notes=tuple(steps), reference=reference,
                              variables=(S.a, S.c_D) + self.variables)
        parts = ("maugis_dugdale", name, self.profile.expr, dict(self.profile.ranges), self.w, self.sigma0,
                 expr, closed, tuple(conditions), tuple(steps), reference is not None, self.contact.verify,
                 self.contact.points, (S.a, S.c_D) + self.variables)
        return remembered(parts, make, self.contact.budget, lambda d: reference,
                          recheck=lambda d: agrees_at_random_point(d, reference, sampler))

    def _derive_force(self):
        return self.law.derive_force(self)

    def _derive_zone_force(self):
        from . import check as chk
        t0 = time.perf_counter()
        fd = self.contact.derivation("force")
        d = self.dugdale
        expr = fd.expr + d.force
        steps = (f"P0(a) of the engine ({fd.method})",) + d.steps[:1] + d.steps[-2:] + (
            "P = P0(a) + (force of the Dugdale punches); the punch of width a carries no force (K_I = 0)",)
        return self._record("zone_force", expr, fd.closed_form, steps, chk.force_reference(self), t0, fd.conditions)

    def _derive_dugdale_force(self):
        t0 = time.perf_counter()
        d = self.dugdale
        return self._record("dugdale_force", d.force, True, d.steps[:1], None, t0)

    def _derive_cohesive_gap(self):
        from . import check as chk
        t0 = time.perf_counter()
        gd = self.contact.derivation("gap")
        d = self.dugdale
        expr = gd.expr.subs(S.x, S.c_D) + d.gap_at_c
        conds = tuple(c.subs(S.x, S.c_D) for c in gd.conditions)
        steps = (f"g0(c_D; a) of the engine ({gd.method})",) + d.steps[:1] + d.steps[2:3]
        return self._record("cohesive_gap", expr, gd.closed_form, steps, chk.gap_reference(self), t0, conds)

    def _derive_pressure(self):
        from . import check as chk
        t0 = time.perf_counter()
        pd = self.contact.derivation("pressure")
        d = self.dugdale
        expr = pd.expr + d.pressure
        steps = (f"p0(x; a) of the engine ({pd.method})",) + d.steps[:2] + d.steps[-1:]
        return self._record("pressure", expr, pd.closed_form, steps, chk.pressure_reference(self), t0,
                            pd.conditions)

    def _numeric_derivation(self, name, fn, what):
        """A Derivation without closed form whose evalf is ``fn(values, dps)``."""
        from ..pull_off import NumericDerivation
        stat = sp.Function(name)(*self.variables)     # a number of the variables, no closed form
        step = Step("numeric", stat, (), (what,))
        return NumericDerivation(name, expr=stat, closed_form=False, step=step, seconds=0.0,
                                 notes=(what, DISPLACEMENT_CONTROL),
                                 reference=lambda vals, dps: fn({k.name: v for k, v in vals.items()}, dps),
                                 variables=self.variables)

    def _derive_maugis_lambda(self):
        return self._numeric_derivation("maugis_lambda", lambda v, d: self.maugis_parameter(d, **v),
                                        "numeric: from the JKR pull-off half-width of the profile")

    # ------------------------------------------------------------ numbers
    def _numeric_values(self, values):
        from ....core.units import refuse_units
        refuse_units(values, "the Maugis-Dugdale contact's numeric results", S.UNITS)
        vals = dict(self.values)
        for s in self.variables:
            if s.name in values:
                vals[s] = to_sympy(values[s.name]) if not isinstance(values[s.name], float) \
                    else point_value(values[s.name])
        unknown = set(values) - {s.name for s in self.variables}
        if unknown:
            raise DomainError(f"unknown value(s) {sorted(unknown)}; the Maugis-Dugdale contact takes "
                              f"{', '.join(s.name for s in self.variables)}")
        missing = [s.name for s in self.variables if s not in vals]
        if missing:
            raise NumericValuesRequired(f"values needed for {', '.join(missing)}")
        for s in self.variables:     # a finite positive real number each (core.ranges)
            check_positive(s.name, to_sympy(vals[s]), _LIMITS.get(s.name))
        return vals

    def numeric_law(self, **values) -> MDLaw:
        """The numeric law (c_D(a), P(a), dP/da, states, pull-off) at values."""
        vals = self._numeric_values(values)
        key = tuple(sorted((k.name, str(v)) for k, v in vals.items()))
        if key not in self._laws:
            self._laws[key] = MDLaw(self, vals)
        return self._laws[key]

    def state(self, a, dps: int = 30, **values) -> MDState:
        """The contact at the half-width a: c_D (unique root of the gap
        condition, bracketed), P, dP/da, h0 and the pressure and gap
        profiles (callables of x), to ``dps`` digits."""
        law = self.numeric_law(**values)
        e = a if isinstance(a, mpmath.mpf) else to_sympy(a)
        if isinstance(e, sp.Tuple):
            raise DomainError(f"the half-width a must be one real number, got {a!r} "
                              f"(half_width(P) gives a tuple: one a per branch)")
        check_positive("a", e, "the half-width a")
        if isinstance(e, mpmath.mpf):
            A = e
        else:
            with workdps(dps + 10):
                A = mpmath.mpf(sp.N(e, dps + 20))
        st = self._limit_state(law, A, dps, values)
        if st is not None:
            return st
        with _real_profile(self, values):
            return law.state(A, dps)

    def _limit_state(self, law, A, dps, values):
        """The state at A from the JKR limit (:func:`.limits.jkr_state`) where :func:`.limits.limit_model` says it
        is reached and its bounds hold at A; else None.  Tried only where the zone length delta is below
        10**-(dps+1) a (nothing to decide otherwise: the JKR law cannot hold dps digits)."""
        with workdps(20):
            if not law._delta() <= mpmath.mpf(10)**-(dps + 1) * A:
                return None
        lim = limit_model(self, self._numeric_values(values), dps)
        return jkr_state(lim, law, A, dps) if isinstance(lim, JKRLimit) else None

    # ------------------------------------------------------------ equilibria: the JKR limit first
    def _equilibria(self, load, dps, values):
        """([(a, stable)], model, note) at a numeric load: from the JKR law where :func:`.limits.limit_model`
        says the JKR limit is reached and :func:`.limits.jkr_equilibria` bounds every root; else the generic
        search on this law."""
        from ...normal.equilibria import equilibria
        vals = self._numeric_values(values)
        lim = limit_model(self, vals, dps)
        if isinstance(lim, JKRLimit):
            got = jkr_equilibria(lim, load, dps)
            if got is not None:
                return got[0], "JKR limit", got[1]
        return equilibria(self._law(vals, "closed"), load, dps), "Maugis-Dugdale", \
            "the equilibria of the Maugis-Dugdale law (inner solve of c_D at each a)"

    def _half_width(self, load=S.P, dps: int = 30, **values):
        """Equilibrium half-widths at the load P, stable first (the generic :meth:`AdhesiveContact._half_width`);
        at a numeric load a :class:`.limits.HalfWidths` (a tuple of mpf) whose ``model`` says which model
        answered: the JKR limit (sigma_0 = 10**100: JKR's roots at once, with the bound) or the full law."""
        e = to_sympy(load)
        if e.free_symbols:
            return super()._half_width(load, dps, **values)
        from ....core.errors import NoEquilibriumError
        from .. import branches as br
        roots, model, note = self._equilibria(e, dps, values)
        if not roots:
            raise NoEquilibriumError(f"{self.profile.name!r}: no equilibrium at the load P = {e}, "
                                     f"{br.why_no_equilibrium(self._law(self._numeric_values(values), 'closed'), e)}")
        return HalfWidths([r for r, _ in roots], model, note)

    def branches(self, load, dps: int = 30, **values):
        """Like :meth:`half_width` with the stability: ((a, 'stable'|'unstable'), ...), a
        :class:`.limits.HalfWidths` saying which model answered."""
        roots, model, note = self._equilibria(to_sympy(load), dps, values)
        return HalfWidths([(r, "stable" if st else "unstable") for r, st in roots], model, note)

    def force_at(self, a, dps: int = 15, **values):
        """P(a) at a numeric half-width: the JKR law's where the JKR limit holds it to ``dps`` digits
        (:meth:`_limit_state`), else the generic :meth:`AdhesiveContact.force_at` (the inner solve)."""
        law = self.numeric_law(**values)
        A = to_mpf(to_sympy(a))
        st = self._limit_state(law, A, dps, values) if A > 0 else None
        return st.force if st is not None else super().force_at(a, dps, **values)

    # ------------------------------------------------------------ pull-off: the JKR limit first
    def pull_off_at(self, dps: int = 30, budget=None, **values):
        """The generic pull-off (:meth:`AdhesiveContact.pull_off_at`), except where a limit model
        answers to ``dps`` digits (:func:`.limits.limit_model`, the one decision of every MD quantity):
        the JKR limit, where the Maugis parameter is so large that the JKR pull-off agrees with this
        law's by a stated bound (sigma_0 = 10**100 or 1e300: the JKR pull-off, at once), or the Dugdale
        limit P(0+) (:mod:`.dugdale`: sigma_0 = 1e-300); the note says which."""
        from ...normal.cases import case_of
        if case_of(self, values) is self:
            from ....core.budget import checked_budget
            from ...normal.equilibria import SEARCH_BUDGET, searching_until
            vals = self._numeric_values(values)
            with searching_until(SEARCH_BUDGET if budget is None else checked_budget(budget)):
                lim = limit_pull_off(self, vals, dps)
            if lim is not None:
                return lim
        return super().pull_off_at(dps, budget, **values)

    def _pull_off_checked(self, vals, dps):
        from ...normal.equilibria import within_search_budget
        with within_search_budget():
            lim = limit_pull_off(self, vals, dps)
        return lim if lim is not None else super()._pull_off_checked(vals, dps)

    def displacement_control(self):
        """Not defined for line contacts: raises with the reason."""
        raise DomainError(DISPLACEMENT_CONTROL)

    @property
    def jkr(self):
        """The JKR contact of the same work of adhesion (this package's law): one per contact, so
        that its pull-offs at values (the Maugis parameter, the model choice) are searched once."""
        cache = self._caches()
        if "_jkr" not in cache:
            cache["_jkr"] = self.contact.adhesive(self.w)
        return cache["_jkr"]

    def _jkr_values(self, values):
        vals = self._numeric_values(values)
        keep = {s.name: v for s, v in vals.items() if s in set(self.jkr.variables)}
        return keep

    def maugis_parameter(self, dps: int = 20, **values):
        """lambda at values, see :func:`.choice.maugis_parameter`."""
        return maugis_choice.maugis_parameter(self, dps, **values)

    def sigma0_for(self, lam, dps: int = 20, **values):
        """sigma_0 giving the Maugis parameter ``lam``, see :func:`.choice.sigma0_for`."""
        return maugis_choice.sigma0_for(self, lam, dps, **values)

    def model_choice(self, rtol=0.05, dps: int = 15, **values):
        """'JKR' or 'MD' for a tolerance (> 0, :func:`~linecontact_sym.core.ranges.check_tolerance`),
        see :func:`.choice.model_choice`."""
        return maugis_choice.model_choice(self, check_tolerance(rtol), dps, **values)

    def adhesion_map(self, values: dict, lambdas=(0.1, 0.5, 1, 3, 10), path=None, **kw):
        """The adhesion map (needs the ``[plot]`` extra): P(a) for several
        Maugis parameters with the JKR law, and the pull-off against lambda
        with its JKR and rigid limits; see :mod:`~linecontact_sym.views.adhesion_map`.
        ``values``: E_star, the work of adhesion, the profile's parameters."""
        from ....views.adhesion_map import adhesion_map_data, plot_adhesion_map
        from .check import rigid_limit
        rigid = lambda s0: rigid_limit(self, 15, **values, **{self.sigma0.name: s0})  # noqa: E731
        data = adhesion_map_data(self, values, lambdas, rigid=rigid, **kw)
        return plot_adhesion_map(data, path, title=f"Maugis-Dugdale line contact, f(x) = {self.profile.expr}")

    def report(self, quantities=("zone_force", "cohesive_gap", "pressure")) -> str:
        return super().report(quantities) + "\n" + DISPLACEMENT_CONTROL


@contextlib.contextmanager
def _real_profile(md, values):
    """The numeric law's searches compare real numbers; where the cohesive
    zone would reach past the profile's real domain (the exact cylinder's
    |x| > R) they meet complex values: a DomainError saying so, not a
    TypeError of mpmath."""
    try:
        yield
    except TypeError as exc:
        if "complex" not in str(exc):
            raise
        raise DomainError(f"no Maugis-Dugdale state of f(x) = {md.profile.expr} at {values}: the cohesive zone "
                          f"would reach where the profile is not real (e.g. |x| > R of the exact cylinder); "
                          f"a smaller work of adhesion or a larger sigma_0 keeps it inside") from None


#: what an infinite value of a parameter stands for (said when one is given)
_LIMITS = {"sigma_0": "the cohesive stress sigma_0 (sigma_0 -> oo with w fixed is the JKR limit: "
                      "use contact.adhesive(w) for it)"}

_REFERENCE_NAMES = {
    "zone_force": "Johnson's bounded-solution condition P = (E*/2) int_-a^a s phi'(s)/sqrt(a^2-s^2) ds on the effective "
             "profile phi = f + u_D (u_D' of the Dugdale strip from the Flamant log kernel), minus 2 sigma_0 (c_D - a), "
             "by the one reference integrator (Arb; tanh-sinh where it cannot)",
    "cohesive_gap": "the engine's quadrature of the adhesionless gap plus the Flamant (log-kernel) displacement "
                    "difference u(c_D) - u(0) of the Dugdale sub-problem, its pressure first checked to make the "
                    "contact displacement uniform (numeric.flamant: Arb; tanh-sinh where it cannot)",
    "pressure": "the engine's Eq. (12) quadrature of p0 plus a direct quadrature of the Dugdale punches "
                "(1/pi) int_a^c_D g_D(t)/sqrt(t^2 - x^2) dt (t = c_D sin(phi), Arb); the Flamant substitution check of "
                "this pressure is part of the cohesive_gap reference",
}


__all__ = ["MaugisDugdale", "MaugisDugdaleContact", "ModelChoice", "MDState", "DISPLACEMENT_CONTROL"]
