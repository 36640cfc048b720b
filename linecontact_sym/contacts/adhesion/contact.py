"""Adhesive line contacts, generic over the cohesive law (:mod:`.law`).

:class:`AdhesiveContact` is an adhesive contact built on the non-adhesive one
(force law P0(a), Eq. 10*, pressure p0(x; a), Eq. 12) by a cohesive law that
says what is specific to it (JKR: the pulled flat punch, :mod:`.jkr`).
Everything else is the same for every law: the equilibria at a load and their
stability (load control: stable where dP/da > 0), the pull-off (the global
minimum of P(a) over every stationary point, kink and the end of the
admissible range, :mod:`.pull_off`; ``pull_off_force`` = P_min < 0,
``adhesion_force`` = P_adh = -P_min > 0, the paper's convention), the
jump-in (the stable root of P(a) = 0) and the branches a(P) (:mod:`.branches`).

:class:`AdhesiveLineContact` is the JKR contact of Popov (2017), Eqs. (29)-(36)
(``LineContact.adhesive(gamma)``):

    p(x; a) = p0(x; a) - Phat / (pi sqrt(a**2 - x**2)),            (29)
    P(a)    = P0(a) - Phat,                                         (33)

Phat = sqrt(2 pi a gamma E*) from Griffith's balance at the edges (Eqs. 30-31).
Existence: a power law has a finite pull-off iff n > 1/2
(:class:`~linecontact_sym.core.errors.NoPullOffError` says what happens
otherwise, never a NaN).  Non-adhesive limit: gamma = 0 gives Phat = 0.
Worn cylinder (Eq. 21): P0 = 0 for a <= b, so P(a) decreases on (0, b] and
the minimum may sit at the kink a = b (weak adhesion) or at a stationary
point a > b; the numeric search handles both (``PullOff.kind``).

Another law is registered with :func:`register_law`: it gets a contact class
of its own kind whose quantities are the generic ones plus the law's.
"""
from __future__ import annotations

import sys

import sympy as sp

from ...core import symbols as S
from ...core.budget import checked_budget
from ...core.conversion import float_values, point_value, to_mpf
from ...core.precision import workdps
from ...core.errors import (DomainError, NoEquilibriumError, NoPullOffError, NumericValuesRequired,
                           VerificationError)
from ...method.derivation import Derivation, values_by_name
from ...parsing import to_sympy
from . import branches, full_contact
from . import pull_off
from ..normal.cases import case_of
from ..base import ContactOn, Quantity
from ..normal.equilibria import SEARCH_BUDGET, equilibria, searching_until
from ..normal.force_law import PullOff, ForceLaw
from .jkr import GAMMA_RANGE, JKR, energy_release_rate, flat_punch_force, stress_intensity
from .law import CohesiveLaw
from ..sampling import point_sampler

__all__ = ["AdhesiveContact", "AdhesiveLineContact", "register_law", "LAWS", "adhesive_contact",
           "NoPullOffError", "NoEquilibriumError", "NumericValuesRequired",
           "PullOff", "flat_punch_force", "stress_intensity", "energy_release_rate", "GAMMA_RANGE"]

#: the contact class of each registered cohesive law, by the law's name
LAWS: dict = {}
_PULL_OFF = ("pull_off_force", "adhesion_force", "pull_off_half_width")


class AdhesiveContact(ContactOn):
    """An adhesive contact: the normal contact ``contact`` with the cohesive
    law ``law`` on top (see the module docstring).  Each registered law has
    a subclass of its own kind (:func:`register_law`); the JKR one is
    :class:`AdhesiveLineContact`.

    Parameters
    ----------
    contact : LineContact
        The non-adhesive contact (profile, parameters, budget, verification).
    law : CohesiveLaw
        The cohesive law, its parameters checked.
    values : dict, optional
        Numeric values (by name or Symbol) bound to the contact; see :meth:`at`.
    """

    #: the law class of this contact kind (set by :func:`register_law`)
    law_class = None

    force = Quantity("P(a)", "", "load per unit length P(a) of the adhesive contact (negative = tensile)",
                     aliases=("adhesive_force",), latex=r"P(a)", unit="N/m")
    pressure = Quantity("p(x; a)", "", "pressure of the adhesive contact, |x| < a (compressive positive)",
                        arguments=("a", "x"), domain="inside", aliases=("adhesive_pressure",), latex=r"p(x)",
                        unit="Pa")
    pull_off_force = Quantity("P_min", "", "pull-off load under load control, the minimum of "
                              "P(a): negative (tensile)", arguments=(), latex=r"P_{\min}", unit="N/m")
    adhesion_force = Quantity("P_adh", "", "adhesive force P_adh = -P_min > 0", arguments=(),
                              latex=r"P_{\mathrm{adh}}", unit="N/m")
    pull_off_half_width = Quantity("a_po", "", "half-width at pull-off (= jump-out half-width)", arguments=(),
                                   aliases=("jump_out_half_width",), latex=r"a_{\mathrm{po}}", unit="m")
    jump_in_half_width = Quantity("a_in", "", "half-width the contact snaps to at zero load (stable root of "
                                  "P(a) = 0)", arguments=(), latex=r"a_{\mathrm{in}}", unit="m")
    half_width = Quantity("a(P)", "", "equilibrium half-widths at the load P, stable branch first",
                          arguments=("P",), method=True, latex="a(P)", unit="m")

    def viscoelastic(self, material):
        """Refused: adhesion is outside the Lee-Radok correspondence (a package error)."""
        from ..viscoelastic.contact import ViscoelasticLineContact
        return ViscoelasticLineContact(self, material)

    def rolling(self, friction=None, **bodies):
        """Refused: steady rolling with adhesion is outside the model (Carter's
        reduction needs the frictionless, non-adhesive pressure)."""
        raise DomainError("rolling with adhesion is outside the model: steady rolling (Carter's reduction) is "
                          "solved over the frictionless contact without adhesion (contact.rolling(mu) on the "
                          "LineContact itself)")

    def __init__(self, contact, law: CohesiveLaw, values=None):
        if not isinstance(law, CohesiveLaw):
            raise DomainError(f"an adhesive contact needs a CohesiveLaw, got {law!r}")
        contact.check_effect(self.kind, law.name)     # a periodic array carries JKR only (normal.periodic)
        self.contact = contact
        self.law = law
        self._lsyms = tuple(s for s in law.symbols if s not in set(contact.params) and s != S.E_star)
        self._cache: dict = {}
        self._laws: dict = {}
        self.values = values_by_name(self.variables, dict(values)) if values else {}

    @classmethod
    def from_frictionless(cls, contact):
        """This kind of contact on ``contact`` with the law's parameters symbolic."""
        return cls.with_law(contact, cls.law_class())

    @classmethod
    def with_law(cls, contact, law, values=None):
        """This kind of contact on ``contact`` with the law object ``law``
        (whatever the subclass's own constructor takes)."""
        new = object.__new__(cls)
        AdhesiveContact.__init__(new, contact, law, values)
        return new

    def __repr__(self):
        return f"{type(self).__name__}({self.contact.profile.expr}, {self.law!r})"

    @property
    def variables(self):
        """The symbols a number needs: E_star, the profile parameters and the
        symbols of the law's parameters."""
        return (S.E_star,) + tuple(self.params) + self._lsyms

    def at(self, **values):
        """A copy with numeric values bound (by name): its quantities are
        numbers, and ``pull_off_force`` is a verified number even where no
        closed form exists."""
        new = object.__new__(type(self))
        new.__dict__.update(self.__dict__)
        new.values = values_by_name(self.variables, {**{k.name: v for k, v in self.values.items()}, **values})
        return new

    def _bind(self, expr):
        return expr.xreplace(self.values) if self.values else expr

    def _value(self, name):
        if name in _PULL_OFF:
            return self._closed_or_number(name)
        if name == "jump_in_half_width":
            d = self.derivation(name)
            if d.closed_form:
                return self._bind(d.expr)
            if self.values and all(s in self.values for s in self.variables):
                return d.reference(self.values, 30)
            raise NumericValuesRequired(
                f"jump_in_half_width of {self.profile.name!r} has no closed form; use "
                f"ad.derivation('jump_in_half_width').evalf(...) or ad.at(...).jump_in_half_width")
        return self._bind(self.derivation(name).expr)

    @property
    def jump_out_half_width(self):
        """Half-width from which the contact jumps out (separates) under load
        control: the pull-off half-width."""
        return self.pull_off_half_width

    def _sampler(self, domain="any"):
        extra = {s: r for s, r in self.law.sample_ranges().items() if s in set(self._lsyms)}
        base = point_sampler(self.profile, domain, extra)
        return lambda rng: (lambda v: float_values(v, 80) if v is not None else None)(base(rng))

    def _law(self, vals: dict, mode: str) -> ForceLaw:
        """The adhesive force law at numeric values ('closed': the engine's
        closed P0 with quadrature fallback; 'quad': the quadrature route),
        built by the cohesive law on the non-adhesive one."""
        fixed = float_values({k: to_sympy(v) for k, v in vals.items() if k in set(self.variables)}, 80)
        key = (mode, tuple(sorted((k.name, v) for k, v in fixed.items())))
        if key not in self._laws:
            law0 = ForceLaw.from_contact(self.contact, fixed, mode)
            self._laws[key] = self.law.numeric(law0, fixed)
        return self._laws[key]

    def _numeric_values(self, values):
        vals = dict(self.values)
        if values:
            vals.update(values_by_name([s for s in self.variables if s.name in values],
                                       values))
        missing = [s.name for s in self.variables if s not in vals]
        if missing:
            raise NumericValuesRequired(f"values needed for {', '.join(missing)}")
        for s in self.variables:
            vals[s] = point_value(vals[s])
            if not vals[s].is_number:
                raise DomainError(f"{s.name} = {vals[s]} is not a number")
        return vals

    def _require(self, rec, what):
        if rec is not None and not rec.passed:
            raise VerificationError(f"{what} of {self.profile.name!r} failed verification: "
                                    f"{rec.min_digits:.1f} digits < {rec.required}")

    # ----------------------------------------------------------- the law's force and pressure
    def _derive_force(self) -> Derivation:
        return self.law.derive_force(self)

    def _derive_pressure(self) -> Derivation:
        return self.law.derive_pressure(self)

    # ----------------------------------------------------------- pull-off
    def _pull_off_closed(self):
        """The symbolic attempt alone (cached in memory and on disk), see
        :func:`.pull_off.closed_attempt`."""
        if "_po_closed" not in self._cache:
            self._cache["_po_closed"] = pull_off.remembered_closed_attempt(self)
        return self._cache["_po_closed"]

    def _derive_pull_off(self, quantity) -> Derivation:
        if "_po" not in self._cache:
            self._cache["_po"] = dict(zip(_PULL_OFF, pull_off.remembered_derivations(self)))
        return self._cache["_po"][quantity]

    _derive_pull_off_force = lambda self: self._derive_pull_off("pull_off_force")  # noqa: E731
    _derive_adhesion_force = lambda self: self._derive_pull_off("adhesion_force")  # noqa: E731
    _derive_pull_off_half_width = lambda self: self._derive_pull_off("pull_off_half_width")  # noqa: E731

    def _pull_off_reference(self, vals, dps, mode="quad"):
        return pull_off.reference(self, vals, dps, mode)

    def _pull_off_checked(self, vals, dps) -> PullOff:
        return pull_off.checked(self, vals, dps)

    def pull_off_at(self, dps: int = 30, budget=None, **values) -> PullOff:
        """The pull-off at numeric values (by name): a :class:`PullOff` with
        the force P_min < 0, P_adh = -P_min, the half-width and how the two
        independent methods agree.  Raises :class:`NoPullOffError` where no
        finite pull-off exists, :class:`VerificationError` if the methods
        disagree below ``dps`` digits, :class:`BudgetExceeded` when the
        numeric search outlasts ``budget`` seconds (default
        :data:`~linecontact_sym.contacts.normal.equilibria.SEARCH_BUDGET`; the
        symbolic attempt has its own, the contact's)."""
        case = case_of(self, values)       # a profile switching on its parameters: that case's contact
        if case is not self:
            return case.pull_off_at(dps, budget, **values)
        vals = self._numeric_values(values)
        budget = SEARCH_BUDGET if budget is None else checked_budget(budget)
        with searching_until(budget):
            return pull_off.at_values(self, vals, dps)

    def full_contact_at(self, dps: int = 30, budget=None, **values):
        """A periodic array (``LineContact(f, period=L)``): the load per period
        above which a partial contact snaps into full contact, the first
        maximum of P(a) after the pull-off, verified by two independent
        methods (:mod:`.full_contact`); ``force <= 0``: full contact at zero
        load.  In JKR full contact then holds any tension."""
        vals = self._numeric_values(values)
        budget = SEARCH_BUDGET if budget is None else checked_budget(budget)
        with searching_until(budget):
            return full_contact.full_contact_at(self, vals, dps)

    def pull_off_force_at(self, dps: int = 30, **values):
        """P_min (< 0) at numeric values, verified to ``dps`` digits."""
        return self.pull_off_at(dps, **values).force

    def adhesion_force_at(self, dps: int = 30, **values):
        """P_adh = -P_min (> 0) at numeric values."""
        return self.pull_off_at(dps, **values).adhesion_force

    def pull_off_half_width_at(self, dps: int = 30, **values):
        """The half-width at pull-off at numeric values."""
        return self.pull_off_at(dps, **values).half_width

    def _closed_or_number(self, quantity):
        if self._pull_off_closed()["Pmin"] is not None:
            return self._bind(self.derivation(quantity).expr)
        if self.values and all(s in self.values for s in self.variables):
            po = self.pull_off_at(30, **{s.name: v for s, v in self.values.items()})
            return {"pull_off_force": po.force, "adhesion_force": po.adhesion_force,
                    "pull_off_half_width": po.half_width}[quantity]
        why = "; ".join(self._pull_off_closed()["notes"]) or "the force law has no closed form"
        raise NumericValuesRequired(
            f"{quantity} of {self.profile.name!r} has no closed form ({why}); give numbers: "
            f"ad.{quantity}_at({', '.join(s.name + '=...' for s in self.variables)}) or ad.at(...).{quantity}")

    # ----------------------------------------------------------- equilibria
    def _derive_jump_in_half_width(self) -> Derivation:
        return branches.derive_jump_in(self)

    def _half_width(self, load=S.P, dps: int = 30, **values):
        """Equilibrium half-width(s) at the load P, **stable branch first**.

        Numeric load with numeric values (keywords by name, or bound with
        :meth:`at`): a tuple of mpf, stable ones (dP/da > 0, load control)
        first; P_min < P < 0 gives ``(a_stable, a_unstable)`` for a
        single-minimum law, P >= 0 gives ``(a_stable,)``.  Below the pull-off
        force raises :class:`NoEquilibriumError`.  Symbolic load: a tuple of two
        :class:`Derivation` s ``(stable, unstable)``."""
        load = to_sympy(load)
        if load.free_symbols:
            key = ("half_width", load)
            if key not in self._cache:
                self._cache[key] = branches.derive_half_widths(self, load)
            return self._cache[key]
        law = self._law(self._numeric_values(values), "closed")
        roots = equilibria(law, load, dps)
        if not roots:
            raise NoEquilibriumError(f"{self.profile.name!r}: no equilibrium at the load P = {load}, "
                                     f"{branches.why_no_equilibrium(law, load)}")
        return tuple(r for r, _ in roots)

    def _derive_half_width(self) -> Derivation:
        return self._half_width(S.P)[0]

    def force_at(self, a, dps: int = 15, **values):
        """P(a) at a numeric half-width and numeric values (by name), from the
        law's numeric force law: the closed P(a) evaluated, or the law's inner
        solve where P(a) is a system (Maugis-Dugdale's c_D(a)); what the
        adhesive plot samples where ``to_numeric('force')`` has no expression."""
        law = self._law(self._numeric_values(values), "closed")
        with workdps(dps + 5):
            return +law.P(to_mpf(to_sympy(a)))

    def branches(self, load, dps: int = 30, **values):
        """Like :meth:`half_width` with the stability: ((a, 'stable'|'unstable'), ...)."""
        roots = equilibria(self._law(self._numeric_values(values), "closed"), to_sympy(load), dps)
        return tuple((r, "stable" if st else "unstable") for r, st in roots)

    def report(self, quantities=None) -> str:
        return super().report(quantities or ("force",) + tuple(self.law.quantities)
                              + ("pull_off_force", "pull_off_half_width"))


class AdhesiveLineContact(AdhesiveContact):
    """JKR-adhesive form of a :class:`~linecontact_sym.contacts.normal.contact.LineContact`
    (Popov 2017, Eqs. 29-36); see the module docstring and :class:`~.jkr.JKR`.

    Parameters
    ----------
    contact : LineContact
        The non-adhesive contact (profile, parameters, budget, verification).
    work_of_adhesion : sympy expression or number, default ``lcs.gamma``
        gamma (the paper's gamma_12) >= 0; gamma = 0 is the non-adhesive limit.
    values : dict, optional
        Numeric values (by name or Symbol) bound to the contact; see :meth:`at`.

    Examples
    --------
    >>> import linecontact_sym as lcs
    >>> ad = lcs.parabola().adhesive(lcs.gamma)
    >>> ad.force
    -sqrt(2)*sqrt(pi)*sqrt(E_star)*sqrt(a)*sqrt(gamma) + pi*E_star*a**2/(4*R)
    >>> ad.pull_off_force
    -3*2**(2/3)*pi**(1/3)*E_star**(1/3)*R**(1/3)*gamma**(2/3)/4
    """

    kind = "adhesive"
    law_class = JKR

    force = Quantity("P(a)", "Eq. (33)", "JKR load per unit length P0(a) - Phat (negative = tensile)",
                     aliases=("adhesive_force",), latex=r"P_{\mathrm{JKR}}(a)", unit="N/m")
    pressure = Quantity("p(x; a)", "Eq. (29)", "JKR pressure p0 - Phat/(pi sqrt(a^2 - x^2)), |x| < a "
                        "(compressive positive; tensile and singular at the edges)", arguments=("a", "x"),
                        domain="inside", aliases=("adhesive_pressure",), latex=r"p_{\mathrm{JKR}}(x)",
                        unit="Pa")
    flat_punch_force = JKR.quantities["flat_punch_force"]
    _derive_flat_punch_force = lambda self: self.law.derive_flat_punch_force(self)  # noqa: E731
    pull_off_force = Quantity("P_min", "Eqs. (34)-(36)", "pull-off load under load control, the minimum of "
                              "P(a): negative (tensile)", arguments=(), latex=r"P_{\min}", unit="N/m")
    adhesion_force = Quantity("P_adh", "Eqs. (34)-(36)", "adhesive force P_adh = -P_min > 0 (the paper's)",
                              arguments=(), latex=r"P_{\mathrm{adh}}", unit="N/m")

    def __init__(self, contact, work_of_adhesion=S.gamma, values=None):
        super().__init__(contact, JKR(work_of_adhesion), values)

    def __repr__(self):
        return f"AdhesiveLineContact({self.contact.profile.expr}, gamma={self.gamma})"

    @property
    def gamma(self):
        """The work of adhesion (the paper's gamma_12)."""
        return self.law.gamma

    @property
    def _gsyms(self):
        return self._lsyms

    @property
    def Phat(self) -> sp.Expr:
        """Eq. (31) Phat = sqrt(2 pi a gamma E*), see :func:`~.jkr.flat_punch_force`."""
        return self._bind(flat_punch_force(self.gamma))

    @property
    def stress_intensity(self) -> sp.Expr:
        """Eq. (30): K_I = Phat/sqrt(pi a) = sqrt(2 gamma E*) at the edges."""
        return self._bind(sp.simplify(stress_intensity(flat_punch_force(self.gamma))))

    @property
    def energy_release_rate(self) -> sp.Expr:
        """G = K_I**2/(2 E*); equals gamma at equilibrium (Griffith, Eq. 30)."""
        return self._bind(sp.simplify(energy_release_rate(stress_intensity(flat_punch_force(self.gamma)))))


def _deriver(q):
    def derive(self) -> Derivation:
        return getattr(self.law, "derive_" + q)(self)
    return derive


def register_law(law_class, contact_class=None):
    """Register a cohesive law: its contact class (of kind ``law_class.kind``,
    with the generic quantities and the law's own) is made here unless given.
    Returns the contact class; ``LAWS[law_class.name]`` holds it."""
    if contact_class is None:
        ns = {"kind": law_class.kind, "law_class": law_class, "__doc__": law_class.__doc__,
              **law_class.quantities,
              **{f"_derive_{q}": _deriver(q) for q in law_class.quantities}}
        name = f"{law_class.__name__}Contact"
        contact_class = type(name, (AdhesiveContact,), ns)
        # pickled by reference like a hand-written class: an attribute of the law's module
        contact_class.__module__ = law_class.__module__
        contact_class.__qualname__ = name
        setattr(sys.modules[law_class.__module__], name, contact_class)
    LAWS[law_class.name] = contact_class
    return contact_class


def adhesive_contact(contact, law: str = "jkr", *args, **params):
    """The adhesive form of ``contact`` under the registered law ``law``
    (by name) with its parameters (positional in the law's order, or by name)."""
    try:
        cls = LAWS[law]
    except KeyError:
        raise DomainError(f"unknown cohesive law {law!r}; registered: {', '.join(LAWS)}") from None
    return cls.with_law(contact, cls.law_class(*args, **params))

