"""Periodic line contacts: a rigid periodic profile of period L on an elastic
half-plane (a wavy surface in plane strain), ``LineContact(f, period=L)``.

The geometry (:class:`~linecontact_sym.method.geometry.Periodic`) says that
Koiter's periodic flat punch is the isolated punch in s = sin(pi x/L); so the
periodic contact of f(x) (0 <= x <= L/2, mirrored, repeated) is the isolated
contact of F(s) = f((L/pi) asin s), its *kernel twin* (``contact.kernel``, a
plain :class:`~.contact.LineContact` derived by the same engine, rules,
verification and cache), mapped back:

    P(a)    = Q(sin(pi a/L))                 load per period (Q: Eq. 10* of F)
    p(x; a) = (pi/L) cos(pi x/L) q(sin(pi x/L); sin(pi a/L))     (q: Eq. 12 of Q)
    g(x; a) = g_F(sin(pi x/L); sin(pi a/L))  a < |x| <= L/2
    P*      = Q(1)                            the load of full contact (a -> L/2)

Every mapped closed form is verified again, in x, against the tan route
(:mod:`~linecontact_sym.contacts.normal.tan_route`: X = tan(pi x/L), an isolated
contact whose profile carries the logarithm of the periodic kernel), which
shares nothing with the map.  Westergaard's (1939) sinusoid
h (1 - cos(2 pi x/L)) follows: F = 2 h s^2 is a parabola, P = pi E* h sin^2(pi a/L),
p* = pi E* h/L.  Nothing here knows a profile.
"""
from __future__ import annotations

import random

import mpmath
import sympy as sp

from ...core import symbols as S
from ...core.budget import DEFAULT_BUDGET
from ...core.conversion import rational, to_mpf
from ...core.errors import InadmissibleProfileError, LineContactError, ProfileError
from ...core.precision import workdps
from ...method import transforms as T
from ...method.derivation import Derivation, fallback_step, remembered
from ...method.geometry import Periodic
from ...method.rules import Step
from .tan_route import TanRoute
from ...method.verification import REQUIRED_DIGITS, VerificationRecord, verify
from ...parsing import to_sympy
from ..base import Quantity
from ..sampling import PERIOD_RANGE, periodic_sampler
from .contact import LineContact
from .equilibria import SEARCH_BUDGET, half_width_at, searching_until

__all__ = ["PeriodicLineContact", "full_contact_quad"]

#: quantities derived by the kernel twin and mapped back
_MAPPED = {"force": "any", "pressure": "inside", "gap": "outside"}


class PeriodicLineContact(LineContact):
    """A periodic array of line contacts (period L), see the module
    docstring.  Build it as ``LineContact(f, period=L)``.

    >>> import sympy as sp, linecontact_sym as lcs
    >>> h, L = sp.symbols("h L", positive=True)
    >>> c = lcs.LineContact(h*(1 - sp.cos(2*sp.pi*lcs.x/L)), period=L)
    >>> c.kernel.profile.expr
    2*h*x**2
    """

    nominal_pressure = Quantity("pbar(a)", "", "nominal pressure P(a)/L: the load per period over the period "
                                "(the literature's mean pressure pbar)", arguments=("a",), latex=r"\bar{p}(a)",
                                unit="Pa")
    full_contact_force = Quantity("P*", "", "load per period at which the contact becomes full (a -> L/2)",
                                  arguments=(), latex="P^{*}", unit="N/m")
    full_contact_pressure = Quantity("p*", "", "nominal pressure of full contact P*/L (Westergaard's p*)",
                                     arguments=(), latex="p^{*}", unit="Pa")

    def __init__(self, profile, params=None, name: str | None = None,
                 budget: float = DEFAULT_BUDGET, verify: bool = True,
                 points: int = 5, digits: int = REQUIRED_DIGITS, period=None):
        if period is None:
            raise ProfileError("a periodic contact needs its period: LineContact(f, period=L)")
        self.geometry = Periodic(period)
        super().__init__(profile, params, name, budget, verify, points, digits, period=None)
        L = self.geometry.period
        if self.profile.cases:
            raise ProfileError(f"profile {self.profile.name!r} switches on its parameters alone; a periodic "
                               f"array of it is not derived case by case: give each case as its own profile")
        self._check_one_trough()
        F = self.geometry.kernel_profile(self.profile.expr)
        syms = F.free_symbols - {S.x}
        ranges = dict(self.profile.declared_ranges)
        kparams = {p: ranges.get(p) for p in syms}
        self.kernel = LineContact(F, params=kparams, name=f"{self.profile.name} in s = sin(pi*x/{L})",
                                  budget=budget, verify=verify, points=points, digits=digits)

    def __repr__(self):
        return f"LineContact({self.profile.expr}, period={self.geometry.period})"

    #: points at which the profile is read over the half period (a prime: no grid in step with the profile)
    TROUGH_POINTS = 97

    def _check_one_trough(self):
        """The array is one compact contact per period about x = 0: f real and
        not decreasing over the whole half period [0, L/2] (its crest at
        L/2, where the full-contact load closes the gap last).  Read at
        :attr:`TROUGH_POINTS` points, at parameter values sampled as the
        verification samples them, before any symbolic work: a profile of
        period L/2 given with period L (h (1 - cos(4 pi x/L)): its second
        trough at L/2 touches, the gap there is negative), a period that is
        not the profile's (1 - cos(2 pi x) with period 1000: the kernel twin
        cos(2000 asin s) would be expanded for minutes) or a profile not real
        beyond L/4 is an :class:`InadmissibleProfileError` at once."""
        rng = random.Random(11)
        vals = self.profile.sample_params(rng)
        for sym in self.geometry.symbols:
            if sym not in vals:
                vals[sym] = rational(rng.uniform(*self.profile.ranges.get(sym, PERIOD_RANGE)))
        half = self.geometry.period.xreplace(vals) / 2
        why = self.profile.rising_on(vals, half, n=self.TROUGH_POINTS)
        if why is not None:
            shown = ", ".join(f"{k} = {v}" for k, v in sorted(vals.items(), key=lambda kv: kv[0].name))
            raise InadmissibleProfileError(
                f"profile {self.profile.name!r} with period {self.geometry.period}: {why} within the half period "
                f"(0, L/2]{' at ' + shown if shown else ''}; a periodic array is one compact contact per period "
                f"about x = 0, so f must be real and not decrease up to its crest at x = L/2 (a second trough "
                f"in the period is a second contact: is the profile's own period shorter than the one given?)")

    @property
    def period(self):
        return self.geometry.period

    @property
    def params(self):
        """The profile's parameters and the period's symbol (sorted by name)."""
        return tuple(sorted(set(self.profile.params) | set(self.geometry.symbols), key=lambda v: v.name))

    def _sampler(self, domain="any"):
        return periodic_sampler(self.profile, self.geometry, domain)

    # --------------------------------------------------------------- references (the tan route)
    def _tan(self, vals):
        L = self.geometry.period.xreplace(vals)
        return TanRoute(self.profile, vals, L)

    def force_reference(self, vals, dps):
        """P(a) by the tan route (:mod:`~linecontact_sym.contacts.normal.tan_route`)."""
        return self._tan(vals).force(vals[S.a], dps)

    def _reference(self, quantity):
        if quantity == "force":
            return self.force_reference
        if quantity == "pressure":
            return lambda vals, dps: self._tan(vals).pressure(vals[S.a], vals[S.x], dps=dps)
        return lambda vals, dps: self._tan(vals).gap(vals[S.a], vals[S.x], dps=dps)

    def force_integral(self):
        return self.geometry.from_kernel(self.kernel.force_integral(), "force")

    def _kernel_integral(self, quantity):
        """The unevaluated defining integral of a kernel quantity, mapped."""
        k = self.kernel
        if quantity == "force":
            e = k.force_integral()
        else:
            Q = k.derivation("force").expr
            e = T.pressure_integral(Q) if quantity == "pressure" else T.gap_integral(k.profile.expr, Q)
        return self.geometry.from_kernel(e, quantity)

    # --------------------------------------------------------------- derivations
    def _derive_force(self):
        return self._mapped("force")

    def _derive_pressure(self):
        return self._mapped("pressure")

    def _derive_gap(self):
        return self._mapped("gap")

    def _mapped(self, quantity) -> Derivation:
        kd = self.kernel.derivation(quantity)
        parts = ("periodic", quantity, self.profile.expr, dict(self.profile.ranges), self.geometry.period,
                 kd.expr, kd.closed_form, self.points, self.digits, self.verify)
        return remembered(parts, lambda: self._make_mapped(quantity, kd), self.budget,
                          lambda d: self._reference(quantity), sampler=self._sampler(_MAPPED[quantity]))

    def _make_mapped(self, quantity, kd) -> Derivation:
        g, domain = self.geometry, _MAPPED[quantity]
        variables = (S.a,) + ((S.x,) if domain != "any" else ()) + self.variables
        reference = self._reference(quantity)
        how = f"the kernel twin F(s) = {self.kernel.profile.expr}, s = sin(pi x/L): {kd.method}"
        if not kd.closed_form:
            return Derivation(quantity, expr=self._kernel_integral(quantity), closed_form=False,
                              step=fallback_step(f"no closed form in s ({how})"), notes=kd.notes,
                              reference=reference, variables=variables, attempts=kd.attempts)
        expr = g.from_kernel(kd.expr, quantity)
        # the gap's formula holds for a < x <= L/2 (the next contact begins at L - a; the
        # stable rewrites are checked on that range: asinh-excess needs sin(pi x/L) > 0)
        conds = tuple(dict.fromkeys([g.condition_from_kernel(c) for c in kd.conditions]
                                    + [sp.Le(S.a, g.a_max())] + ([sp.Le(S.x, g.a_max())] if quantity == "gap" else [])))
        rec = None
        if self.verify:
            rec = verify(expr, reference, self._sampler(domain), conds, n_points=self.points,
                         reference_name=f"the tan route X = tan(pi x/L) ({quantity}, contacts.normal.tan_route)")
            if not rec.passed:
                note = (f"the mapped closed form {expr} FAILED verification against the tan route "
                        f"({rec.min_digits:.1f} digits); returned unevaluated")
                return Derivation(quantity, expr=self._kernel_integral(quantity), closed_form=False,
                                  step=fallback_step(note), verification=rec, notes=(note,) + kd.notes,
                                  reference=reference, variables=variables)
        step = Step("periodic_map", expr, conds, (how, "mapped back: a -> sin(pi a/L), x -> sin(pi x/L)"
                                                  + (", times ds/dx = (pi/L) cos(pi x/L)" if quantity == "pressure"
                                                     else "")))
        return Derivation(quantity, expr=expr, closed_form=True, step=step, conditions=conds, verification=rec,
                          notes=kd.notes, reference=reference, variables=variables)

    def _derive_nominal_pressure(self) -> Derivation:
        """P(a)/L, checked against the tan route's P(a) over L."""
        L = self.geometry.period

        def reference(vals, dps):
            with workdps(dps + 10):
                return self.force_reference(vals, dps) / to_mpf(L.xreplace(vals))
        return self._derive_from_force("nominal_pressure", lambda P: P / L, reference,
                                       "P(a)/L against the tan route's P(a) over L")

    def _derive_full_contact_force(self) -> Derivation:
        """P* = Q(1) (a -> L/2), checked against the full-contact route
        (:func:`full_contact_quad`)."""
        parts = ("periodic", "full_contact_force", self.profile.expr, dict(self.profile.ranges),
                 self.geometry.period, self.points, self.verify)
        return remembered(parts, self._make_full_contact, self.budget, lambda d: self._full_reference,
                          sampler=self._sampler("any"))

    def _full_reference(self, vals, dps):
        return full_contact_quad(self.profile, vals, self.geometry.period.xreplace(vals), dps)

    def _crest_slope(self):
        """f'(L/2-), the slope of the profile at the crest (SymPy), or None."""
        L = self.geometry.period
        d = sp.diff(self.profile.pieces[-1].expr if self.profile.is_piecewise else self.profile.expr, S.x)
        try:
            v = sp.simplify(d.xreplace({S.x: L / 2}))
            if v.has(sp.nan, sp.zoo):
                v = sp.limit(d, S.x, L / 2, "-")
        except Exception:   # a limit SymPy cannot take: undecided
            return None
        return v

    def _make_full_contact(self) -> Derivation:
        kd = self.kernel.derivation("force")
        variables = self.variables
        crest = self._crest_slope()
        if crest is not None and crest.is_positive:
            note = (f"f'(L/2-) = {crest} > 0: the crest is a corner; near full contact P(a) ~ "
                    f"-(E* L f'(L/2)/pi) ln(L/2 - a) -> oo (the integrand of E* int_0^(L/2) f'(t) tan(pi t/L) dt "
                    f"is ~ f'(L/2) L/(pi (L/2 - t))): full contact needs an infinite load")
            return Derivation("full_contact_force", expr=sp.oo, closed_form=True,
                              step=Step("periodic_full_contact", sp.oo, (), (note,)), notes=(note,),
                              reference=self._full_reference, variables=variables)
        if not kd.closed_form:
            return Derivation("full_contact_force", expr=self.force_integral().xreplace({S.a: self.period / 2}),
                              closed_form=False, step=fallback_step("the force law has no closed form"),
                              reference=self._full_reference, variables=variables)
        Q = kd.expr
        at = Q.xreplace({S.a: 1})
        if at.has(sp.nan, sp.zoo) or not at.is_finite:
            at = sp.limit(Q, S.a, 1, "-")
        at = sp.simplify(at)
        if at in (sp.oo, sp.zoo) or at.has(sp.oo):
            note = ("P(a) -> oo as a -> L/2: full contact needs an infinite load (the profile's crest at "
                    "x = L/2 is not smooth: f'(L/2) != 0)")
            return Derivation("full_contact_force", expr=sp.oo, closed_form=True,
                              step=Step("periodic_full_contact", sp.oo, (), (note,)), notes=(note,),
                              reference=self._full_reference, variables=variables)
        rec = None
        if self.verify:
            rec = verify(at, self._full_reference, self._sampler(), (), n_points=self.points,
                         reference_name="E* int_0^{L/2} f'(t) tan(pi t/L) dt: the load at which the "
                                        "full-contact pressure p = pbar - (E*/2) H[f'] vanishes at the crest")
        step = Step("periodic_full_contact", at, (), ("Q(1) of the kernel twin: a -> L/2 is s -> 1",))
        return Derivation("full_contact_force", expr=at, closed_form=True, step=step, verification=rec,
                          reference=self._full_reference, variables=variables)

    def _derive_full_contact_pressure(self) -> Derivation:
        d = self.derivation("full_contact_force")
        L = self.geometry.period
        ref = d.reference

        def reference(vals, dps):
            return ref(vals, dps) / to_mpf(L.xreplace(vals))
        return Derivation("full_contact_pressure", expr=d.expr / L, closed_form=d.closed_form,
                          step=Step("periodic_full_contact", d.expr / L, (), ("P*/L",)), verification=d.verification,
                          notes=d.notes, reference=reference, variables=d.variables)

    # --------------------------------------------------------------- half-width
    def _half_width(self, load=S.P, budget=None, **values):
        """a(P): a number at numeric values (the force law's root on (0, L/2]),
        or the kernel twin's S(P) mapped, a = (L/pi) asin(S(P)), checked by
        substitution P(a(P)) = P at random points."""
        load = to_sympy(load)
        if load.is_number:
            return super()._half_width(load, budget, **values)
        cache = self._caches()
        key = ("half_width", load)
        if key not in cache:
            cache[key] = self._derive_half_width(load, budget)
        return cache[key]

    def _derive_half_width(self, load=S.P, budget=None) -> Derivation:
        kd = self.kernel._half_width(load, budget)
        fd = self.derivation("force")
        variables = (load,) + self.variables

        def reference(vals, dps):
            fixed = {k: v for k, v in vals.items() if k != load}
            return half_width_at(self.force_law(**{k.name: v for k, v in fixed.items()}), vals[load], dps)
        if not kd.closed_form or not fd.closed_form:
            return Derivation("half_width", expr=sp.Eq(fd.expr, load), closed_form=False,
                              step=fallback_step("numeric root of P(a) = P"), reference=reference,
                              variables=variables)
        expr = self.geometry.x_of(kd.expr)
        rng = random.Random(7)
        sample = self._sampler()
        points, digits, tried = [], [], 0
        while len(points) < self.points and tried < 20 * self.points:
            tried += 1
            vals = sample(rng)
            if vals is None:
                continue
            Pv = sp.N(fd.expr.xreplace(vals), 60)
            av = sp.N(expr.xreplace({**vals, load: Pv}), 60)
            err = abs(av - vals[S.a]) / abs(vals[S.a]) if av.is_real else sp.oo
            if not err <= sp.Float(10)**(-self.digits):
                return Derivation("half_width", expr=sp.Eq(fd.expr, load), closed_form=False,
                                  step=fallback_step(f"the mapped inverse {expr} fails P(a(P)) = P"),
                                  reference=reference, variables=variables)
            points.append({**vals, load: Pv})
            digits.append(min(55.0, float(-sp.log(err, 10))) if err > 0 else 55.0)
        rec = VerificationRecord(tuple(points), tuple(digits), 60, "P(a(P)) = P: the force law at the half-width "
                                 "it gives, at 60 digits", required=self.digits)
        step = Step("periodic_map", expr, (), (f"a = (L/pi) asin(S(P)), S(P) of the kernel twin ({kd.method}); "
                                               f"P(a(P)) = P checked at {len(points)} random points",))
        return Derivation("half_width", expr=expr, closed_form=True, step=step, verification=rec,
                          reference=reference, variables=variables)

    # --------------------------------------------------------------- admissibility
    def check_point(self, values: dict) -> None:
        """The kernel's point conditions, and a <= L/2."""
        super().check_point(values)
        self.geometry.check_half_width(values)

    # --------------------------------------------------------------- effects not yet periodic
    def check_effect(self, kind: str, law: str | None = None) -> None:
        """The one gate of the effects built on this contact (every route:
        ``c.adhesion(...)``, ``c.maugis_dugdale()``, ``Kind.from_frictionless(c)``
        of the CLI and the claims checker): JKR adhesion is derived on an
        array; the other cohesive laws, the tangential contact and the
        subsurface stresses are not yet, and are refused here, the same way."""
        if kind == "tangential":
            raise LineContactError("the tangential contact of a periodic array is not derived yet (its layer reads "
                                   "the isolated half-plane's kernel); see docs/architecture.md")
        if kind in ("stress", "sliding_stress"):
            raise LineContactError("the subsurface stresses of a periodic array are not derived yet (the Kolosov "
                                   "potentials of the layer are those of one contact)")
        if law is not None and law != "jkr":
            raise LineContactError(f"the {law} law on a periodic array is not derived yet; JKR is "
                                   f"(LineContact(f, period=L).adhesive(gamma))")


def full_contact_quad(profile, values: dict, period, dps: int = 45):
    """P* = E* int_0^{L/2} f'(t) tan(pi t/L) dt: the load per period at which
    the contact closes.  In full contact u' = -f' everywhere, so
    p(x) = pbar - (E*/2) H[f'](x) with the periodic Hilbert transform
    H[g](x) = (1/L) PV int g(t) cot(pi (x - t)/L) dt over a period; the
    gap closes last at the crest x = L/2, where cot(pi (L/2 - t)/L) = tan(pi t/L),
    and p(L/2) = 0 gives pbar = P*/L.  One quadrature of the profile,
    after t = (L/2)(1 - u^2) near the crest, split at the profile's kinks."""
    with workdps(dps + 15):
        pv = {k: v for k, v in values.items() if k not in (S.x, S.a)}
        npf = T.NumericProfile(profile, pv)
        L = to_mpf(period)
        E = to_mpf(pv[S.E_star])
        half = L / 2
        edges = [mpmath.mpf(0)] + npf.kinks(0, half) + [half]
        total = mpmath.mpf(0)
        for lo, hi in zip(edges[:-1], edges[1:]):
            fn = T.inside(npf.f1, lo, hi)
            # t = hi - (hi - lo) u^2: the 1/(L/2 - t) of tan is tamed where f'(L/2) = 0
            w = hi - lo
            total += mpmath.quad(lambda u: fn(hi - w * u**2) * mpmath.tan(mpmath.pi * (hi - w * u**2) / L)
                                 * 2 * w * u, [0, 1])
        return +(E * total)
