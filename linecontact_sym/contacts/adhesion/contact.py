"""JKR-adhesive line contacts: Popov (2017), Eqs. (29)-(36).

The adhesive contact of half-width ``a`` is the non-adhesive one (force law
P0(a), Eq. 10*, pressure p0(x; a), Eq. 12) with a *pulled* rigid flat punch of
the same half-width superposed (Eq. 29):

    p(x; a) = p0(x; a) - Phat / (pi sqrt(a**2 - x**2)),            (29)
    P(a)    = P0(a) - Phat,                                         (33)

Phat = sqrt(2 pi a gamma E*) from Griffith's balance at the edges (Eqs. 30-31,
:mod:`.jkr`).  The pull-off (Eqs. 34-36, :mod:`.pull_off`) is the minimum of
P(a) under load control: ``pull_off_force`` = P_min < 0, ``adhesion_force``
= P_adh = -P_min > 0 (the paper's convention).  Existence: a power law has a
finite pull-off iff n > 1/2 (:class:`~linecontact_sym.core.errors.NoPullOffError`
says what happens otherwise, never a NaN).

Jump-in / jump-out (load control): at zero load the surfaces snap into
contact at the stable root of P(a) = 0, ``jump_in_half_width``; on unloading
the contact jumps out from ``jump_out_half_width`` = ``pull_off_half_width``.

Non-adhesive limit: gamma = 0 gives Phat = 0, so ``force`` and ``pressure``
are exactly the engine's ``LineContact.force`` / ``.pressure``.

Worn cylinder (Eq. 21): P0 = 0 for a <= b, so P(a) decreases on (0, b] and
the minimum may sit at the kink a = b (weak adhesion) or at a stationary
point a > b; the numeric search handles both (``PullOff.kind``).
"""
from __future__ import annotations

import time

import sympy as sp

from ...core import symbols as S
from ...core.conversion import float_values, point_value
from ...core.errors import (DomainError, NoEquilibriumError, NoPullOffError, NumericValuesRequired,
                           VerificationError)
from ...method.derivation import Derivation, values_by_name
from ...method.rules import Step
from ...method.verification import verify
from ...parsing import to_sympy, user_value
from . import branches
from . import pull_off
from ..normal.cases import case_of
from ..base import ContactOn, Quantity
from ..normal.equilibria import equilibria
from ..normal.force_law import PullOff, ForceLaw
from .jkr import GAMMA_RANGE, energy_release_rate, flat_punch_force, phat_energy, stress_intensity
from ..sampling import point_sampler
from ...core.precision import workdps

__all__ = ["AdhesiveLineContact", "NoPullOffError", "NoEquilibriumError", "NumericValuesRequired",
           "PullOff", "flat_punch_force", "stress_intensity", "energy_release_rate", "GAMMA_RANGE"]

#: Eq. (31) derivations, shared by all contacts (the flat punch has no profile)
_PHAT_CACHE: dict = {}
_PULL_OFF = ("pull_off_force", "adhesion_force", "pull_off_half_width")


class AdhesiveLineContact(ContactOn):
    """JKR-adhesive form of a :class:`~linecontact_sym.contacts.normal.contact.LineContact`
    (Popov 2017, Eqs. 29-36); see the module docstring.

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

    force = Quantity("P(a)", "Eq. (33)", "JKR load per unit length P0(a) - Phat (negative = tensile)",
                     aliases=("adhesive_force",), latex=r"P_{\mathrm{JKR}}(a)")
    pressure = Quantity("p(x; a)", "Eq. (29)", "JKR pressure p0 - Phat/(pi sqrt(a^2 - x^2)), |x| < a "
                        "(compressive positive; tensile and singular at the edges)", arguments=("a", "x"),
                        domain="inside", aliases=("adhesive_pressure",), latex=r"p_{\mathrm{JKR}}(x)")
    flat_punch_force = Quantity("Phat(a)", "Eq. (31)", "force of the pulled flat punch sqrt(2 pi a gamma E*)",
                                aliases=("Phat",), latex=r"\hat{P}(a)")
    pull_off_force = Quantity("P_min", "Eqs. (34)-(36)", "pull-off load under load control, the minimum of "
                              "P(a): negative (tensile)", arguments=(), latex=r"P_{\min}")
    adhesion_force = Quantity("P_adh", "Eqs. (34)-(36)", "adhesive force P_adh = -P_min > 0 (the paper's)",
                              arguments=(), latex=r"P_{\mathrm{adh}}")
    pull_off_half_width = Quantity("a_po", "", "half-width at pull-off (= jump-out half-width)", arguments=(),
                                   aliases=("jump_out_half_width",), latex=r"a_{\mathrm{po}}")
    jump_in_half_width = Quantity("a_in", "", "half-width the contact snaps to at zero load (stable root of "
                                  "P(a) = 0)", arguments=(), latex=r"a_{\mathrm{in}}")
    half_width = Quantity("a(P)", "", "equilibrium half-widths at the load P, stable branch first",
                          arguments=("P",), method=True, latex="a(P)")

    def __init__(self, contact, work_of_adhesion=S.gamma, values=None):
        if isinstance(work_of_adhesion, str):
            raise DomainError("the work of adhesion is a string; strings are not evaluated. "
                              "Pass a SymPy expression or a number (e.g. lcs.gamma)")
        g = user_value(work_of_adhesion)
        if not isinstance(g, sp.Expr):
            raise DomainError(f"the work of adhesion must be an expression, got {g!r}")
        if g.has(S.x, S.a, S.P):
            raise DomainError(f"the work of adhesion {g} may not depend on x, a or P")
        if g.is_negative:
            raise DomainError(f"the work of adhesion must be >= 0, got {g}")
        if g.is_nonnegative is not True:
            raise DomainError(f"the sign of the work of adhesion {g} is unknown; use a symbol "
                              f"created with positive=True (e.g. lcs.gamma) or a number >= 0")
        self.contact = contact
        self.gamma = g
        self._gsyms = tuple(sorted(g.free_symbols - set(contact.params) - {S.E_star}, key=lambda s: s.name))
        self._cache: dict = {}
        self._laws: dict = {}
        self.values = values_by_name(self.variables, dict(values)) if values else {}

    @classmethod
    def from_frictionless(cls, contact):
        """``contact.adhesive(gamma)`` with the symbolic work of adhesion."""
        return cls(contact, S.gamma)

    def __repr__(self):
        return f"AdhesiveLineContact({self.contact.profile.expr}, gamma={self.gamma})"

    @property
    def variables(self):
        """The symbols a number needs: E_star, the profile parameters and the
        symbols of the work of adhesion."""
        return (S.E_star,) + tuple(self.params) + self._gsyms

    def at(self, **values):
        """A copy with numeric values bound (by name): its quantities are
        numbers, and ``pull_off_force`` is a verified number even where no
        closed form exists."""
        new = AdhesiveLineContact(self.contact, self.gamma,
                                  {**{k.name: v for k, v in self.values.items()}, **values})
        new._cache, new._laws = self._cache, self._laws
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
        extra = {gs: GAMMA_RANGE for gs in self._gsyms}
        base = point_sampler(self.profile, domain, extra)
        return lambda rng: (lambda v: float_values(v, 80) if v is not None else None)(base(rng))

    def _law(self, vals: dict, mode: str) -> ForceLaw:
        """The adhesive force law at numeric values ('closed': the engine's
        closed P0 with quadrature fallback; 'quad': the quadrature route)."""
        fixed = float_values({k: to_sympy(v) for k, v in vals.items() if k in set(self.variables)}, 80)
        key = (mode, tuple(sorted((k.name, v) for k, v in fixed.items())))
        if key not in self._laws:
            g = to_sympy(self.gamma).xreplace(fixed)
            if not g.is_number:
                raise DomainError(f"the work of adhesion {self.gamma} needs a value")
            law0 = ForceLaw.from_contact(self.contact, fixed, mode)
            self._laws[key] = law0.with_adhesion(g, fixed[S.E_star])
        return self._laws[key]

    def _numeric_values(self, values):
        vals = dict(self.values)
        if values:
            vals.update(values_by_name(self.variables, values) if len(values) >= len(self.variables)
                        else {s: to_sympy(values[s.name]) for s in self.variables if s.name in values})
        missing = [s.name for s in self.variables if s not in vals]
        if missing:
            raise NumericValuesRequired(f"values needed for {', '.join(missing)}")
        for s in self.variables:
            if isinstance(vals[s], float):
                vals[s] = point_value(vals[s])
            if not to_sympy(vals[s]).is_number:
                raise DomainError(f"{s.name} = {vals[s]} is not a number")
        return vals

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

    def _require(self, rec, what):
        if rec is not None and not rec.passed:
            raise VerificationError(f"{what} of {self.profile.name!r} failed verification: "
                                    f"{rec.min_digits:.1f} digits < {rec.required}")

    # ----------------------------------------------------------- Eqs. (29), (31), (33)
    def _derive_flat_punch_force(self) -> Derivation:
        """Eq. (31), verified against the energy balance of the flat-punch
        compliance (quadrature of Eq. 3, mpmath.diff, findroot); shared by all
        contacts with the same work of adhesion."""
        key = (self.gamma, self.contact.points, self.contact.verify)
        if key not in _PHAT_CACHE:
            _PHAT_CACHE[key] = branches.derive_phat(self)
        return _PHAT_CACHE[key]

    def _derive_force(self) -> Derivation:
        """Eq. (33): P(a) = P0(a) - Phat."""
        t0 = time.perf_counter()
        fd = self.contact.derivation("force")
        expr = fd.expr - flat_punch_force(self.gamma)
        prof, gexpr = self.profile, self.gamma

        def reference(vals, dps):
            from ...method import transforms as T
            with workdps(dps + 10):
                return T.force_quad(prof, vals, dps) - phat_energy(
                    vals[S.a], gexpr.xreplace(vals), vals[S.E_star], dps, quadrature=False)
        rec = None
        if fd.closed_form and self.contact.verify:
            rec = verify(expr, reference, self._sampler(), fd.conditions, n_points=self.contact.points,
                         reference_name="quadrature of Eq. (10*) minus Phat from the energy balance of "
                                        "the flat-punch compliance (Eq. 3, mpmath.diff + findroot)")
            self._require(rec, "force")
        step = Step("jkr_superposition", expr, fd.conditions,
                    (f"Eq. (33): P0(a) of the engine ({fd.method}) minus Phat, Eq. (31)" if fd.closed_form
                     else "numeric fallback: unevaluated Eq. (10*) minus Phat",))
        return Derivation("force", expr, fd.closed_form, step, fd.conditions, rec, time.perf_counter() - t0,
                          fd.notes, reference, (S.a,) + self.variables)

    def _derive_pressure(self) -> Derivation:
        """Eq. (29): p(x) = p0(x) - Phat/(pi sqrt(a^2 - x^2))."""
        return branches.derive_pressure(self)

    # ----------------------------------------------------------- pull-off
    def _pull_off_closed(self):
        """The symbolic attempt alone (cached), see :func:`.pull_off.closed_attempt`."""
        if "_po_closed" not in self._cache:
            self._cache["_po_closed"] = pull_off.closed_attempt(self)
        return self._cache["_po_closed"]

    def _derive_pull_off(self, quantity) -> Derivation:
        if "_po" not in self._cache:
            self._cache["_po"] = dict(zip(_PULL_OFF, pull_off.derivations(self)))
        return self._cache["_po"][quantity]

    _derive_pull_off_force = lambda self: self._derive_pull_off("pull_off_force")  # noqa: E731
    _derive_adhesion_force = lambda self: self._derive_pull_off("adhesion_force")  # noqa: E731
    _derive_pull_off_half_width = lambda self: self._derive_pull_off("pull_off_half_width")  # noqa: E731

    def _pull_off_reference(self, vals, dps, mode="quad"):
        return pull_off.reference(self, vals, dps, mode)

    def _pull_off_checked(self, vals, dps) -> PullOff:
        return pull_off.checked(self, vals, dps)

    def pull_off_at(self, dps: int = 30, **values) -> PullOff:
        """The pull-off at numeric values (by name): a :class:`PullOff` with
        the force P_min < 0, P_adh = -P_min, the half-width and how the two
        independent methods agree.  Raises :class:`NoPullOffError` where no
        finite pull-off exists, :class:`VerificationError` if the methods
        disagree below ``dps`` digits."""
        case = case_of(self, values)       # a profile switching on its parameters: that case's contact
        if case is not self:
            return case.pull_off_at(dps, **values)
        return pull_off.at_values(self, self._numeric_values(values), dps)

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

    def branches(self, load, dps: int = 30, **values):
        """Like :meth:`half_width` with the stability: ((a, 'stable'|'unstable'), ...)."""
        roots = equilibria(self._law(self._numeric_values(values), "closed"), to_sympy(load), dps)
        return tuple((r, "stable" if st else "unstable") for r, st in roots)

    def report(self, quantities=("force", "flat_punch_force", "pull_off_force", "pull_off_half_width")) -> str:
        return super().report(quantities)

