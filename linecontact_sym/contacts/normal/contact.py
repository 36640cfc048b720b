"""The frictionless, non-adhesive line contact (Popov 2017, Eqs. 9-12):
one object per physical system, each quantity declared once in the registry
of :mod:`.base` and derived by the engine from the profile."""
from __future__ import annotations

import dataclasses
import numbers

import mpmath
import sympy as sp

from ...core import symbols as S
from ...core.budget import DEFAULT_BUDGET, checked_budget
from ...core.conversion import to_mpf
from ...core.errors import DomainError, ProfileError
from ...method import transforms as T
from ...method.geometry import ISOLATED
from ...method.derivation import Derivation, derive, fallback_step, values_by_name
from ...method.profile import Profile
from ...numeric.exports import lambdify_numpy
from ...method.rules import Problem, Step
from ...method.verification import REQUIRED_DIGITS, verify
from ...parsing import to_sympy
from . import admissibility
from ..base import Contact, Quantity
from .equilibria import SEARCH_BUDGET, half_width_at, searching_until
from .force_law import ForceLaw
from . import reference as R
from .inverse import derive_half_width
from .cases import derive_by_case
from ..sampling import point_sampler
from ...core.precision import workdps


class LineContact(Contact):
    """Frictionless, non-adhesive contact of a rigid symmetric profile with an
    elastic half-plane (plane strain), solved by Popov's (2017) superposition
    of flat punches parametrised by the load per unit length.

    Parameters
    ----------
    profile : sympy.Expr
        f(x) for x >= 0 (mirrored to x < 0); ``Piecewise`` for flats/kinks.
    params : list or dict, optional
        Declared parameters (positive symbols are declared implicitly); a dict
        gives each a (low, high) range for the random verification points.
    budget : float
        CPU seconds allowed to the symbolic derivation of each quantity
        (:mod:`~linecontact_sym.core.budget`: rules, tidying and verification).
    period : number or positive Symbol, optional
        A periodic array of period L (f given on 0 <= x <= L/2): see
        :class:`~.periodic.PeriodicLineContact`.
    symmetric : bool
        False: f is given on the whole line in the real x (``lcs.x_real``),
        not mirrored: an :class:`~linecontact_sym.contacts.asymmetric.contact.AsymmetricLineContact`.
    verify : bool
        Check every closed form against mpmath quadrature (default True).

    Examples
    --------
    >>> import sympy as sp, linecontact_sym as lcs
    >>> R = sp.Symbol("R", positive=True)
    >>> c = lcs.LineContact(lcs.x**2/(2*R))
    >>> c.force
    pi*E_star*a**2/(4*R)
    >>> c.pressure
    E_star*sqrt(a**2 - x**2)/(2*R)
    """

    kind = "frictionless"
    #: the punches of the superposition (:mod:`~linecontact_sym.method.geometry`): the isolated
    #: half-plane here; ``LineContact(f, period=L)`` makes a periodic array (:mod:`.periodic`)
    geometry = ISOLATED
    #: the contact of the kernel variable whose results this one maps (None: this is it)
    kernel = None
    #: the contact class of each other geometry, by name (filled by the modules that define them)
    GEOMETRIES: dict = {}

    def __new__(cls, *args, period=None, symmetric=True, **kw):
        if symmetric is False and cls is LineContact:
            if period is not None:
                raise ProfileError("an asymmetric periodic array is not supported: give symmetric=False or period=L")
            # not a LineContact (its quantities are in two ends): built whole here
            return LineContact.GEOMETRIES["asymmetric"](*args, **kw)
        if symmetric is not True:
            raise ProfileError(f"symmetric must be True or False, got {symmetric!r}")
        if period is not None and cls is LineContact:
            cls = LineContact.GEOMETRIES["periodic"]
        return super().__new__(cls)

    force = Quantity("P(a)", "Eq. (10*)", "load per unit length at the half-width a (compressive positive)",
                     arguments=("a",), latex="P(a)", unit="N/m")
    pressure = Quantity("p(x; a)", "Eq. (12)", "contact pressure for |x| < a (compressive positive)",
                        arguments=("a", "x"), domain="inside", latex="p(x)", unit="Pa")
    gap = Quantity("g(x; a)", "Eqs. (3)/(5)", "surface separation f(x) - (d - u_z(x)) for |x| > a",
                   arguments=("a", "x"), domain="outside", latex="g(x)", unit="m")
    mean_pressure = Quantity("p_m(a)", "", "mean contact pressure P(a)/(2a)", arguments=("a",),
                             latex=r"\bar{p}(a)", unit="Pa")
    stiffness = Quantity("dP/da", "", "contact stiffness: the slope of the force law, load per unit length "
                         "per unit half-width", arguments=("a",), latex=r"\frac{dP}{da}", unit="N/m**2")
    half_width = Quantity("a(P)", "", "contact half-width at the load P (the inverse of the force law)",
                          arguments=("P",), method=True, latex="a(P)", nonnegative=("P",), unit="m")

    def __init__(self, profile, params=None, name: str | None = None,
                 budget: float = DEFAULT_BUDGET, verify: bool = True,
                 points: int = 5, digits: int = REQUIRED_DIGITS, period=None, symmetric=True):
        if period is not None and not isinstance(self, LineContact.GEOMETRIES["periodic"]):
            raise ProfileError("period= makes a periodic array: build it as LineContact(f, period=L)")
        self.profile = profile if isinstance(profile, Profile) else Profile(profile, params, name)
        self.budget = checked_budget(budget)
        for what, v, hi in (("points", points, 1000), ("digits", digits, 100)):
            if isinstance(v, bool) or not isinstance(v, numbers.Integral) or not 1 <= v <= hi:
                raise ProfileError(f"{what} must be an integer from 1 to {hi}, got {v!r}")
        self.verify = verify
        self.points = points
        self.digits = digits
        self._cache: dict = {}

    def __repr__(self):
        return f"LineContact({self.profile.expr})"

    @classmethod
    def from_frictionless(cls, contact):
        return contact

    def _repr_latex_(self):
        from ...core.printing import to_latex
        return f"$f(x) = {to_latex(self.profile.expr)}$"

    @property
    def params(self):
        return self.profile.params

    @property
    def variables(self):
        """The symbols a number needs besides the arguments: E_star and the profile's parameters."""
        return (S.E_star,) + tuple(self.params)

    def derivation(self, quantity: str) -> Derivation:
        """See :meth:`~.base.Contact.derivation`; switching on parameters: case by case (:mod:`.cases`)."""
        if not self.profile.cases:
            return super().derivation(quantity)
        name = self.resolve(quantity)
        cache = self._caches()
        if name not in cache:
            cache[name] = derive_by_case(self, name)
        return cache[name]

    def derive_by_case(self, on, name: str) -> Derivation:
        """``on.derivation(name)`` (a contact built on this one) case by case."""
        return derive_by_case(on, name)

    def check_point(self, values: dict) -> None:
        """See :func:`~.admissibility.check_point`."""
        admissibility.check_point(self, values)

    def _sampler(self, domain="any"):
        return point_sampler(self.profile, domain)

    def _derive(self, quantity, problem, reference, fallback, domain, notes=()):
        d = derive(quantity, problem, reference=reference, sampler=self._sampler(domain), fallback=fallback,
                   budget=self.budget, check=self.verify, points=self.points, notes=notes,
                   variables=(S.a,) + (() if domain == "any" else (S.x,)) + self.variables)
        return self._restricted(d)

    def _restricted(self, d: Derivation) -> Derivation:
        """A closed form holds where the profile's pieces do: its
        :attr:`~linecontact_sym.method.profile.Profile.assumptions` (the case
        of a parameter-dependent Piecewise, the order of breakpoints) join its
        conditions, and the notes say so (the verification points satisfy
        them, see :mod:`.sampling`)."""
        extra = tuple(r for r in self.profile.assumptions if r not in d.conditions)
        notes = tuple(self.profile.range_notes)
        if not d.closed_form or not (extra or notes):
            return d
        if extra:
            notes += (f"holds under the profile's assumptions {', '.join(map(str, extra))} (the pieces "
                      f"of its Piecewise were read there); elsewhere derive the other case",)
        conds = d.conditions + extra
        return dataclasses.replace(d, conditions=conds, step=dataclasses.replace(d.step, conditions=conds),
                                   notes=d.notes + notes)

    def force_law(self, mode: str = "closed", **values) -> ForceLaw:
        """The numeric force law at parameter values (keywords by name):
        the closed form where there is one (``mode='closed'``), else, or with
        ``mode='quad'``, the quadrature of Eq. (10*)."""
        missing = [s.name for s in self.variables if s.name not in values]
        if missing:
            raise DomainError(f"the force law needs values for {', '.join(missing)}")
        vals = values_by_name(self.variables, {s.name: values[s.name] for s in self.variables})   # signs checked
        return ForceLaw.from_contact(self, vals, mode)

    def _admissibility_fns(self):
        """(f'(x, *params), dP0/da(a, E_star, *params) or None, parameter names):
        float64 NumPy functions for the admissibility test of
        :meth:`~.base.Contact._check_admissible`, compiled once."""
        cache = self._caches()
        if "_adm_fns" not in cache:
            params = list(self.params)
            d1 = sp.diff(self.profile.expr, S.x)
            xp = sp.Dummy("x", positive=True)
            # a test that SymPy's assumptions decide for every admissible value
            # is not sampled at every call (x**2/(2R): f' = x/R >= 0 always)
            # patched at x = 0 (a = 0) only: parameters are > 0 (a limit in w cost the first Gaussian 10 s)
            fprime = None if d1.xreplace({S.x: xp}).is_nonnegative else \
                lambdify_numpy(d1, [S.x] + params, stable=False, patch=(S.x,))
            fd = self.derivation("force")
            slope = None
            if fd.closed_form and not fd.expr.has(sp.Integral):
                dP = sp.diff(fd.expr, S.a)
                if not dP.is_nonnegative:
                    # the stable form: the rounded punch's plain dP/da cancels to -8e4 at a = b + 1 ulp
                    slope = lambdify_numpy(dP, [S.a, S.E_star] + params, patch=(S.a,))
            cache["_adm_fns"] = (fprime, slope, [p.name for p in params])
        return cache["_adm_fns"]

    # --------------------------------------------------------------- derivations
    def force_reference(self, vals, dps):
        """P(a) at a point by the independent quadrature of the defining
        integral (here Eq. 10*), for the checks of the contacts built on this
        one: the certified reference (Arb ball quadrature, a RefValue; the
        mpmath quadrature where Arb cannot), as the force's own verification."""
        return R.force_reference(self.profile, vals, dps)

    def force_integral(self):
        """The unevaluated force law (Eq. 10*)."""
        return T.force_integral(self.profile)

    def _derive_force(self) -> Derivation:
        slope = self.profile.slope_at_origin
        if slope != 0:
            note = (f"f'(0+) = {slope} != 0: the paper's printed Eq. (10) drops the boundary term "
                    f"E_star*a*f'(0+) = {S.E_star * S.a * slope}; the force law here includes it (Eq. 10*)")
        else:
            note = "f'(0+) = 0: the paper's printed Eq. (10) and Eq. (10*) agree"
        prof = self.profile
        return self._derive("force", Problem("force", prof), lambda vals, dps: R.force_reference(prof, vals, dps),
                            T.force_integral(prof), "any", (note,))

    def _dP(self, vals, dps):
        """mpmath P'(s) at the parameters of ``vals``, and the breakpoints,
        located to twice the digits ``dps`` of the reference (see quad0)."""
        with workdps(2 * dps + 20):
            law = ForceLaw.from_contact(self, {k: v for k, v in vals.items() if k not in (S.a, S.x)})
            return law.dP, law.breaks()

    def _breaks(self, vals):
        """The profile's break points at the parameters of ``vals`` (exact)."""
        pv = {k: v for k, v in vals.items() if k not in (S.a, S.x)}
        return [b for b in (bp.xreplace(pv) for bp in self.profile.breakpoints) if b.is_number and b > 0]

    def _derive_pressure(self) -> Derivation:
        fd = self.derivation("force")

        def quad(vals, dps):
            dP, breaks = self._dP(vals, dps)
            with workdps(dps + 10):
                return T.pressure_quad(dP, breaks, vals, dps)

        def reference(vals, dps):
            return R.pressure_reference(fd.expr, self._breaks(vals), vals, dps, lambda: quad(vals, dps))
        fallback = T.pressure_integral(fd.expr)
        if not fd.closed_form:
            notes = ()
            if not self.profile.is_piecewise:   # one quadrature instead of Eq. (12) over a quadrature law
                reference, notes = _direct_pressure(self.profile)
            return Derivation("pressure", expr=fallback, closed_form=False,
                              step=fallback_step("force law has no closed form"), notes=notes, reference=reference,
                              variables=(S.a, S.x) + self.variables)
        return self._derive("pressure", Problem("pressure", self.profile, fd.expr), reference, fallback,
                            "inside")

    def _derive_gap(self) -> Derivation:
        fd = self.derivation("force")

        def quad(vals, dps):
            dP, breaks = self._dP(vals, dps)
            with workdps(dps + 10):
                f = self.profile.mp_callable({k: v for k, v in vals.items() if k not in (S.a, S.x)})
                return T.gap_quad(f, dP, breaks, vals, dps)

        def reference(vals, dps):
            if not fd.closed_form:
                return quad(vals, dps)
            return R.gap_reference(self.profile.expr, fd.expr, self._breaks(vals), vals, dps,
                                   lambda: quad(vals, dps))
        fallback = T.gap_integral(self.profile.expr, fd.expr)
        if not fd.closed_form:
            return Derivation("gap", expr=fallback, closed_form=False,
                              step=fallback_step("force law has no closed form"), reference=reference,
                              variables=(S.a, S.x) + self.variables)
        return self._derive("gap", Problem("gap", self.profile, fd.expr), reference, fallback, "outside")

    def _derive_from_force(self, quantity, make, reference, what):
        """A quantity built from the force law by ``make(P)`` (an identity),
        verified against an independent ``reference``."""
        fd = self.derivation("force")
        if not fd.closed_form:
            return Derivation(quantity, expr=make(fd.expr), closed_form=False,
                              step=fallback_step("force law has no closed form"), reference=reference,
                              variables=(S.a,) + self.variables)
        expr = sp.simplify(make(fd.expr))
        rec = verify(expr, reference, self._sampler(), fd.conditions, n_points=self.points,
                     reference_name=what) if self.verify else None
        if rec is not None and not rec.passed:
            note = f"closed form FAILED verification ({rec.min_digits:.1f} digits); returned unevaluated: {expr}"
            return Derivation(quantity, expr=make(self.force_integral()), closed_form=False,
                              step=fallback_step(), verification=rec, notes=(note,), reference=reference,
                              variables=(S.a,) + self.variables)
        step = Step(quantity, expr, fd.conditions, (what,))
        return Derivation(quantity, expr=expr, closed_form=True, step=step, conditions=fd.conditions, verification=rec,
                          reference=reference, variables=(S.a,) + self.variables)

    def _derive_mean_pressure(self) -> Derivation:
        """P(a)/(2a) of the closed force law, checked against the quadrature of
        Eq. (10*) divided by 2a."""
        def reference(vals, dps):
            with workdps(dps + 10):
                return self.force_reference(vals, dps) / (2 * to_mpf(vals[S.a]))
        return self._derive_from_force("mean_pressure", lambda P: P / (2 * S.a), reference,
                                       "P(a)/(2a) against the quadrature of Eq. (10*) over 2a")

    def _derive_stiffness(self) -> Derivation:
        """dP/da of the closed force law, checked against numerical
        differentiation of the quadrature of Eq. (10*)."""
        def reference(vals, dps):
            with workdps(dps + 20):
                fixed = {k: v for k, v in vals.items() if k != S.a}
                A = to_mpf(vals[S.a])
                # the quadrature runs above diff's own (raised) working precision
                return mpmath.diff(lambda u: self.force_reference({**fixed, S.a: u}, mpmath.mp.dps), A)
        return self._derive_from_force("stiffness", lambda P: sp.diff(P, S.a), reference,
                                       "dP/da against mpmath.diff of the quadrature of Eq. (10*)")

    # --------------------------------------------------------------- half-width
    def _half_width(self, load=S.P, budget=None, **values):
        """Contact half-width a at load P.  Symbolic load: the closed inverse of the force law (P(a(P)) = P checked at random points) or the
        unevaluated P(a) = load, the inversion under ``budget`` (s, default the contact's).  Numeric load and
        parameters: the number (30 digits), searched under ``budget`` (default :data:`~.equilibria.SEARCH_BUDGET`)."""
        load = to_sympy(load)
        if load.is_number:
            if load <= 0:
                raise DomainError(f"the load must be positive for a non-adhesive contact, got {load}")
            with searching_until(SEARCH_BUDGET if budget is None else checked_budget(budget)):
                return half_width_at(self.force_law(**values), load)
        cache = self._caches()
        key = ("half_width", load)
        if key not in cache or (not cache[key].closed_form and cache[key].attempts):
            cache[key] = derive_half_width(self, load, budget)
        return cache[key]

    def _derive_half_width(self, load=S.P) -> Derivation:
        """a(P), see :func:`~.inverse.derive_half_width`."""
        return derive_half_width(self, load)

    # --------------------------------------------------------------- tilt and moment
    def asymmetric(self):
        """This profile on the whole line (f(x) where it is even in x, else
        f(|x|)) as an asymmetric contact, for a tilt or a moment (built once)."""
        cache = self._caches()
        if "_asymmetric" not in cache:
            if not self.geometry.is_isolated:
                raise DomainError("a tilt or a moment of a periodic array is not supported")
            cls = LineContact.GEOMETRIES["asymmetric"]
            from_line = cls.from_symmetric
            cache["_asymmetric"] = from_line(self)
        return cache["_asymmetric"]

    def contact_at(self, P, theta=None, moment=None, **values):
        """The contact at the load ``P`` with the tilt ``theta`` or the moment
        ``moment`` about x = 0 (free rotation): an
        :class:`~linecontact_sym.contacts.asymmetric.contact.AsymmetricState`.
        theta = 0 (or M = 0, or neither given) is today's symmetric contact:
        the half-width :meth:`half_width` at P, centred."""
        return LineContact.GEOMETRIES["asymmetric"].symmetric_state(self, P, theta, moment, **values)

    # --------------------------------------------------------------- other forms
    def check_effect(self, kind: str, law: str | None = None) -> None:
        """The gate of the effects built on this contact (an adhesive
        ``kind`` with its cohesive ``law``, ``"tangential"``, ``"stress"``):
        every one is derived on an isolated contact; a periodic array
        refuses those it does not carry (:mod:`.periodic`)."""

    def adhesive(self, work_of_adhesion=S.gamma):
        """The JKR-adhesive form of this contact (Eqs. 29-36), see
        :mod:`linecontact_sym.contacts.adhesion.contact`."""
        from ..adhesion.contact import AdhesiveLineContact
        return AdhesiveLineContact(self, work_of_adhesion)

    def maugis_dugdale(self, w=S.gamma, sigma0=S.sigma_0):
        """The Maugis-Dugdale contact (tension sigma0 over h0 = w/sigma0), see :mod:`..adhesion.maugis`."""
        return self.adhesion("maugis_dugdale", w, sigma0)

    def adhesion(self, law: str = "jkr", *args, **params):
        """The adhesive form of this contact under a registered cohesive law
        (by name: ``"jkr"``, ...) with the law's parameters (positional in
        its order or by name; unset ones symbolic), see
        :mod:`linecontact_sym.contacts.adhesion`."""
        from ..adhesion.contact import adhesive_contact
        return adhesive_contact(self, law, *args, **params)

    def tangential(self, friction=S.mu, *, beta=None, materials=None):
        """The partial-slip tangential form of this contact under Coulomb
        friction mu at constant normal load (Cattaneo-Mindlin-Ciavarella-Jaeger),
        see :mod:`linecontact_sym.contacts.tangential.contact`; ``beta`` or
        ``materials=((E1, nu1), (E2, nu2))``: the two bodies, whose neglected
        coupling every result states
        (:data:`~linecontact_sym.core.materials.COUPLING_KEYWORDS`)."""
        from ..tangential.contact import TangentialLineContact
        return TangentialLineContact(self, friction, beta=beta, materials=materials)

    def rolling(self, friction=S.mu, *, beta=None, materials=None):
        """Steady rolling with traction under Coulomb friction mu (rolling in
        +x, the stick zone at the leading edge; Carter for the cylinder), see
        :mod:`linecontact_sym.contacts.rolling.contact`; ``beta`` or
        ``materials`` as for :meth:`tangential`."""
        from ..base import contact_kind   # by the registry: the rolling contact stands on the asymmetric core,
        return contact_kind("rolling")(self, friction, beta=beta, materials=materials)   # (no import cycle)

    def viscoelastic(self, material):
        """This contact on a linear viscoelastic half-plane (Lee-Radok, Ting), see
        :mod:`linecontact_sym.contacts.viscoelastic`."""
        from ..viscoelastic.contact import ViscoelasticLineContact
        return ViscoelasticLineContact(self, material)

    def stresses(self, tangential=None, **kw):
        """The subsurface stress field under this contact (plane strain), with
        an optional tangential traction: see :mod:`linecontact_sym.contacts.stresses.contact`."""
        from ..stresses.contact import SlidingStressField, StressField
        if tangential == "sliding":
            return SlidingStressField(self, **kw)
        return StressField(self, tangential, **kw)

    def check_admissible(self, dps: int = 20, **values):
        """See :func:`linecontact_sym.contacts.normal.admissibility.check_admissible`."""
        return admissibility.check_admissible(self, dps, **values)

    def admissible_range(self, a_max: float = 100.0, rtol: float = 1e-6, **values):
        """See :func:`linecontact_sym.contacts.normal.admissibility.admissible_range`."""
        return admissibility.admissible_range(self, a_max, rtol, **values)

    def report(self, quantities=("force", "pressure", "gap")) -> str:
        return super().report(quantities)


def _direct_pressure(prof):
    """(reference, notes) of the pressure of a smooth profile without closed
    force law: one quadrature of the profile (:func:`~linecontact_sym.method.transforms.pressure_direct_quad`)."""
    def reference(vals, dps):
        fixed = {k: v for k, v in vals.items() if k not in (S.a, S.x)}
        with workdps(dps + 10):
            return T.pressure_direct_quad(T.NumericProfile(prof, fixed).f1, vals, dps)
    return reference, ("numbers by one quadrature from the profile (the bounded inversion of the punch equation, "
                       "transforms.pressure_direct_quad), not Eq. (12) over the quadrature force law",)
