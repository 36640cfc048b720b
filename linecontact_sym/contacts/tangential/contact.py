"""Tangential line contact with Coulomb friction: partial slip, unloading and
fretting for any profile, by the Cattaneo-Mindlin-Ciavarella-Jaeger
superposition of *normal* solutions of the same profile.

Setting and conditions of validity (every result below)
-------------------------------------------------------
* plane strain, half-plane approximation, quasi-static, small strains;
* elastically similar bodies, or the Dundurs constant beta neglected
  (Goodman approximation): only then does the shear traction leave the
  pressure unchanged.  A rigid indenter on a half-plane (Popov's
  E* = E/(1 - nu^2)) is "similar" only for nu = 1/2; otherwise
  |beta| = (1 - 2 nu)/(2 (1 - nu)) (0.29 for nu = 0.3) is neglected.
  ``tangential(mu, beta=...)`` or ``materials=((E1, nu1), (E2, nu2))``
  (:data:`~linecontact_sym.core.materials.COUPLING_KEYWORDS`) have every
  result state the neglected coupling |beta| mu; without them the results
  say "beta = 0 assumed" (:mod:`.coupling`).  The numbers are the same;
* Coulomb friction with one coefficient mu (static = kinetic);
* the normal load P (half-width a) is held constant while Q varies;
* a symmetric profile and a compact contact |x| < a whose frictionless solution
  is admissible at every half-width c <= a used (p(x; c) >= 0, g(x; c) >= 0),
  and a force law that does not decrease on [c, a] (then |q| <= mu p holds in
  the stick zone and every slip zone slips in the direction of its traction);
* no adhesion (out of scope).

Which modulus
-------------
The relative tangential displacement of the surfaces obeys the Flamant
kernel with the same compliance as the normal one (Johnson 1985, Eqs.
2.19-2.25: a line load, normal or tangential, gives the surface displacement
-(2 (1 - nu^2)/(pi E)) ln|x| in its own direction):

    dw/dx = (2/(pi E*)) PV int q(xi)/(x - xi) dxi,   1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2,

i.e. **E* is exactly the plane-strain modulus of the normal problem** (Hills
& Nowell's composite compliance A = 2/E*).  In 3-D the tangential compliance
differs from the normal one (a factor (2 - nu)/(2 (1 - nu)) for similar
materials); in plane strain the two are equal, so the slip below is mu times a
normal gap with no extra factor.

Formulas (p, P, g: the engine's frictionless pressure, force law and gap of the
same profile; c_s: stick half-width; x >= 0, mirrored)
------------------------------------------------------------------------------
Monotonic loading from Q = 0 (Cattaneo 1938, Mindlin 1949; any profile:
Ciavarella 1998, Jaeger 1998)::

    q(x) = mu [p(x; a) - p(x; c_s)]   |x| < c_s   (stick)
         = mu p(x; a)                 c_s < |x| < a   (slip)
    Q    = mu [P(a) - P(c_s)],   c_s from P(c_s) = P(a) - |Q|/mu
    s(x) = mu g(x; c_s)               c_s <= |x| <= a,   0 in the stick zone

(s: slip of the surfaces relative to the stick zone, in the direction of Q).
Hertz: c_s/a = sqrt(1 - Q/(mu P)).  Gross sliding starts at |Q| = mu P,
where c_s reaches the largest zero of the force law (0, or b for the worn
cylinder, whose flat sticks up to the onset); beyond it
:class:`~linecontact_sym.core.errors.GrossSlidingError`.

Unloading from Q_max (stick c_s) to Q (Mindlin & Deresiewicz 1953): a reversed
distribution of twice the amplitude, stick half-width c_r >= c_s::

    q_u = q(x; c_s) - 2 q(x; c_r),  Q = Q_max - 2 mu [P(a) - P(c_r)],
    s_u = s(x; c_s) - 2 s(x; c_r);   reloading from -Q_max: the negatives.

Energy dissipated per full cycle between +-Q_A (c_s the stick half-width at
+-Q_A): the friction work 8 mu^2 int_c^a p(x; a) g(x; c_s) dx, equal to the
loop area, which reduces to the force law alone::

    W = (8 mu^2/(pi E*)) [ (P(a) + P(c)) I_1 - I_2 - P(a) P(c) ln(a/c) ],
    I_1 = int_c^a P(t)/t dt,  I_2 = int_c^a P(t)^2/t dt,   c = c_s.

Hertz: W = (pi E* mu^2/(8 R^2)) [a^4 - c^4 - 4 a^2 c^2 ln(a/c)]
       = (2 (mu P)^2/(pi E*)) [1 - r^2 + 2 r ln r],  r = 1 - Q_A/(mu P)
(any power law c x^n: the factor 2/n instead of 1; small amplitudes
W ~ 2 Q_A^3/(3 pi E* mu P) for the cylinder).

What 2-D does not define: the rigid-body tangential displacement (like the
indentation depth, the half-plane displacement grows like ln|x|).  The slip,
the traction and the dissipated energy are defined.  ``loop_displacement``
is the rigid shift *with a stated convention* (the Flamant kernel
ln(|x - xi|/a): reference length a)::

    delta(c) = (2 mu/(pi E*)) int_c^a P'(t) ln(2a/t) dt;

another reference length L adds (2 Q/(pi E*)) ln(L/a): it shears the fretting
loop and leaves its area W unchanged.

Independent checks: :mod:`~linecontact_sym.contacts.tangential.reference` (inversion of the stick-zone
singular integral equation, the Flamant kernel, the friction work, and a
direct boundary-element solution with a Coulomb active set).
"""
from __future__ import annotations


import sympy as sp

from ...core import symbols as S
from ...core.units import refuse_units
from ...core.errors import DomainError
from ...method.derivation import Derivation, fallback_step
from ...method.rules import Step
from ...method.verification import verify
from ...core.ranges import check_points, check_value
from ...parsing import user_value
from . import history
from . import states
from .coupling import FrictionalCoupling, read_coupling
from ..base import ContactOn, Quantity

#: range of the friction coefficient at the verification points
MU_RANGE = (0.1, 1.0)
_t = sp.Dummy("t", positive=True)   # an integration variable: never a user's t
#: symbols the tangential quantities take besides the profile's
_OWN = (S.mu, S.Q, S.c_s, S.c_r)

#: how each quantity is built from the engine's normal solution (the step record)
STEP_NOTES = {
    "traction": "mu [p(x; a) - p(x; c_s)] in the stick zone, mu p(x; a) in the slip zones (engine's pressure)",
    "tangential_force": "mu [P(a) - P(c_s)] (engine's force law)",
    "slip": "mu g(x; c_s) in the slip zones (engine's gap at the half-width c_s)",
    "loop_displacement": "(2 mu/(pi E*)) int_c^a P'(t) ln(2a/t) dt, integrated by parts over the engine's force law",
    "dissipated_energy": "(8 mu^2/(pi E*)) [(P(a) + P(c)) I_1 - I_2 - P(a) P(c) ln(a/c)] over the engine's force law",
    "unloading_traction": "q(x; c_s) - 2 q(x; c_r) (Mindlin-Deresiewicz)",
    "unloading_force": "Q(c_s) - 2 Q(c_r) (Mindlin-Deresiewicz)",
    "unloading_slip": "s(x; c_s) - 2 s(x; c_r) (Mindlin-Deresiewicz)",
}

#: the Mindlin-Deresiewicz reversal: (coefficient, stick half-width) of each monotone term
LOADING = ((1, S.c_s),)
UNLOADING = ((1, S.c_s), (-2, S.c_r))


class TangentialLineContact(FrictionalCoupling, ContactOn):
    """Partial-slip tangential line contact (Coulomb friction, constant normal
    load) built from a frictionless :class:`~.contact.LineContact`; see
    the module docstring for the formulas and their conditions.

    Parameters
    ----------
    contact : LineContact
    friction : sympy expression or number, default ``lcs.mu``
        Coulomb coefficient mu > 0.
    beta, materials : keyword-only, optional
        the two bodies (Dundurs' beta, or ((E1, nu1), (E2, nu2))), see
        :data:`~linecontact_sym.core.materials.COUPLING_KEYWORDS`: the
        numbers stay Goodman's (beta neglected); every result states the
        neglected coupling |beta| mu (a DomainWarning here where beta != 0),
        or "beta = 0 assumed" where neither is given.

    Examples
    --------
    >>> import linecontact_sym as lcs
    >>> t = lcs.parabola(verify=False).tangential()   # verify=False: no 30-digit checks in this example
    >>> t.tangential_force
    pi*E_star*mu*(a**2 - c_s**2)/(4*R)
    >>> t.stick_half_width().expr
    sqrt(a**2 - 4*R*Abs(Q)/(pi*E_star*mu))
    """

    kind = "tangential"

    traction = Quantity("q(x; a, c_s)", "", "shear traction under monotonic loading, positive in the direction "
                        "of Q: mu [p(x; a) - p(x; c_s)] in the stick zone |x| < c_s, mu p(x; a) in the slip zones",
                        arguments=("a", "c_s", "x"), domain="inside", latex="q(x)", unit="Pa")
    tangential_force = Quantity("Q(a, c_s)", "", "tangential force per unit length mu [P(a) - P(c_s)]",
                                arguments=("a", "c_s"), latex="Q", unit="N/m")
    stick_half_width = Quantity("c_s(Q)", "", "stick half-width at the tangential force Q: the root of "
                                "P(c_s) = P(a) - |Q|/mu", arguments=("a", "Q"), method=True, latex=r"c_{\mathrm{s}}",
                                unit="m")
    slip = Quantity("s(x; a, c_s)", "", "slip of the surfaces relative to the stick zone, in the direction of Q: "
                    "mu g(x; c_s) for c_s <= |x| <= a, 0 in the stick zone", arguments=("a", "c_s", "x"),
                    domain="inside", latex="s(x)", unit="m")
    loop_displacement = Quantity("delta(a, c_s)", "", "rigid tangential shift with the reference length a of the "
                                 "Flamant kernel (a convention: 2-D defines it only up to a term proportional to Q)",
                                 arguments=("a", "c_s"), latex=r"\delta", unit="m")
    dissipated_energy = Quantity("W(a, c_s)", "", "energy dissipated per unit length in one full cycle between "
                                 "+-Q_A, c_s the stick half-width at +-Q_A", arguments=("a", "c_s"),
                                 aliases=("energy_per_cycle",), latex="W", unit="J/m")
    unloading_traction = Quantity("q_u(x; a, c_s, c_r)", "", "traction after unloading from the turning point "
                                  "(stick c_s) with the reversal stick half-width c_r: q(x; c_s) - 2 q(x; c_r)",
                                  arguments=("a", "c_s", "c_r", "x"), domain="inside", latex=r"q_{\mathrm{u}}(x)",
                                  unit="Pa")
    unloading_force = Quantity("Q_u(a, c_s, c_r)", "", "tangential force on the unloading branch "
                               "Q(c_s) - 2 Q(c_r)", arguments=("a", "c_s", "c_r"), latex=r"Q_{\mathrm{u}}",
                               unit="N/m")
    unloading_slip = Quantity("s_u(x; a, c_s, c_r)", "", "slip on the unloading branch s(x; c_s) - 2 s(x; c_r)",
                              arguments=("a", "c_s", "c_r", "x"), domain="inside", latex=r"s_{\mathrm{u}}(x)",
                              unit="m")

    def __init__(self, contact, friction=S.mu, *, beta=None, materials=None):
        contact.check_effect(self.kind)             # not on a periodic array yet (normal.periodic)
        if isinstance(friction, str):
            raise DomainError("the friction coefficient is a string; strings are not evaluated. "
                              "Pass a SymPy expression or a number (e.g. lcs.mu)")
        m = user_value(friction)
        if not isinstance(m, sp.Expr) or m.has(S.x, S.a, S.P, S.Q, S.c_s, S.c_r):
            raise DomainError(f"the friction coefficient {m} must be an expression free of x, a, P, Q, c_s, c_r")
        check_value("mu", m)
        if m.is_positive is not True:
            raise DomainError(f"the friction coefficient must be positive, got {m} (use a number > 0 or a "
                              f"symbol created with positive=True, e.g. lcs.mu)")
        clash = set(contact.params) & set(_OWN)
        if clash:
            raise DomainError(f"the profile uses {sorted(map(str, clash))}, reserved by the tangential contact")
        self.contact = contact
        self.mu = m
        self.coupling = read_coupling(m, beta, materials)   # its DomainWarning (beta != 0): once, here
        self._msyms = tuple(sorted(m.free_symbols - set(contact.params) - {S.E_star}, key=lambda s: s.name))
        self._cache: dict = {}

    @classmethod
    def from_frictionless(cls, contact, *, beta=None, materials=None):
        """``contact.tangential(mu)`` with the symbolic friction coefficient
        (and the two bodies, if given)."""
        return cls(contact, S.mu, beta=beta, materials=materials)

    def __repr__(self):
        return f"TangentialLineContact({self.contact.profile.expr}, mu={self.mu}{self.coupling.keywords()})"

    @property
    def variables(self):
        """The symbols a number needs besides the arguments: the friction
        coefficient's, E_star and the profile's parameters."""
        return self._msyms + (S.E_star,) + tuple(self.params)

    @property
    def c0(self) -> sp.Expr:
        """The largest zero of the force law: where the stick zone ends at the
        onset of gross sliding (0; the flat's half-width for a profile that
        starts with a flat, f = 0 on [0, b))."""
        first = self.profile.pieces[0]
        return first.hi if (len(self.profile.pieces) > 1 and sp.simplify(first.expr) == 0) else sp.S.Zero

    # ----------------------------------------------------------- building blocks
    def _normal(self, name) -> Derivation:
        return self.contact.derivation(name)

    def _monotone(self, what, C):
        """One monotone (Cattaneo) term with stick half-width C, as an expression."""
        mu = self.mu
        if what == "traction":
            p = self._normal("pressure").expr
            return sp.Piecewise((mu * (p - p.xreplace({S.a: C})), S.x < C), (mu * p, True))
        if what == "force":
            P = self._normal("force").expr
            return mu * (P - P.xreplace({S.a: C}))
        if what == "slip":
            g = self._normal("gap").expr
            return sp.Piecewise((0, S.x <= C), (mu * g.xreplace({S.a: C}), True))
        return self._energy_parts()[1].xreplace({S.c_s: C})   # "displacement"

    def _closed(self, what) -> bool:
        if what == "displacement":
            return self._energy_parts()[2]
        need = {"traction": "pressure", "force": "force", "slip": "gap"}[what]
        return self._normal(need).closed_form

    def _sampler(self, domain="any", reversal=False, load=False):
        return states.sampler(self, domain, reversal, load, MU_RANGE)

    def _variables(self, *args):
        return tuple(args) + self.variables

    def _finish(self, quantity, expr, closed, conditions, check, value, how, variables, sampler,
                needs=("pressure",)):
        """Verify a closed form against ``check`` (30 digits at random points);
        a failed check or no closed form leaves a numeric derivation evaluated
        by ``value``.  The checks integrate the normal solutions ``needs``; where
        one of them has no closed form the check (nested quadratures) is not
        run and a note says so."""
        rec, notes = None, ()
        missing = [n for n in needs if not self._normal(n).closed_form] if closed and self.contact.verify else []
        if missing:
            notes = (f"not verified here: the independent check integrates the {' and '.join(missing)}, which "
                     f"has no closed form for this profile (nested quadratures); the same identity is verified "
                     f"at 30 digits on profiles with a closed pressure and against the direct solution "
                     f"(reference.CoulombBEM)",)
        elif closed and self.contact.verify:
            rec = verify(expr, check, sampler, conditions, n_points=self.contact.points, reference_name=how)
            if not rec.passed:
                notes = (f"closed form FAILED verification ({rec.min_digits:.1f} digits): evaluated numerically",)
                closed = False
        step = Step("cattaneo_mindlin", expr, conditions, (STEP_NOTES[quantity],)) if closed \
            else fallback_step("the normal solution it is built from has no closed form here")
        return Derivation(quantity, expr=expr, closed_form=closed, step=step, conditions=conditions if closed else (),
                          verification=rec, notes=notes + (states.CONDITIONS,), reference=check if closed else value,
                          variables=variables)

    def _combination(self, quantity, what, terms, domain):
        expr = sum(k * self._monotone(what, C) for k, C in terms)
        if what == "force":
            expr = sp.factor_terms(expr)
        closed = self._closed(what)
        conds = tuple(self._normal("force").conditions) + tuple(sp.Lt(C, S.a) for _, C in terms) \
            + ((sp.Lt(self.c0, S.c_s),) if self.c0 != 0 else ())
        if len(terms) > 1:
            conds += (sp.Lt(S.c_s, S.c_r),)
        if domain == "inside":
            conds += (sp.Lt(S.x, S.a),)
        check, value, how = states.references(self, what, terms)
        args = (S.a,) + tuple(C for _, C in terms) + ((S.x,) if domain == "inside" else ())
        return self._finish(quantity, expr, closed, conds, check, value, how, self._variables(*args),
                            self._sampler("slip" if what == "slip" else domain, len(terms) > 1))

    # ----------------------------------------------------------- derivations
    def _derive_traction(self):
        return self._combination("traction", "traction", LOADING, "inside")

    def _derive_tangential_force(self):
        return self._combination("tangential_force", "force", LOADING, "any")

    def _derive_slip(self):
        return self._combination("slip", "slip", LOADING, "inside")

    def _derive_loop_displacement(self):
        return self._combination("loop_displacement", "displacement", LOADING, "any")

    def _derive_unloading_traction(self):
        return self._combination("unloading_traction", "traction", UNLOADING, "inside")

    def _derive_unloading_force(self):
        return self._combination("unloading_force", "force", UNLOADING, "any")

    def _derive_unloading_slip(self):
        return self._combination("unloading_slip", "slip", UNLOADING, "inside")

    def _energy_parts(self):
        """(W, delta, closed): the dissipated energy and the loop displacement
        in a and c_s from the force law: closed where SymPy integrates
        int P(t)/t dt and int P(t)^2/t dt, else with those integrals left
        unevaluated."""
        if "_energy" not in self._cache:
            self._cache["_energy"] = states.energy_parts(self, _t)
        return self._cache["_energy"]

    def _derive_dissipated_energy(self):
        W, _, closed = self._energy_parts()
        conds = tuple(self._normal("force").conditions) + (sp.Lt(S.c_s, S.a),) \
            + ((sp.Lt(self.c0, S.c_s),) if self.c0 != 0 else ())
        check, value, how = states.energy_references(self)
        return self._finish("dissipated_energy", W, closed, conds, check, value, how,
                            self._variables(S.a, S.c_s), self._sampler("any"), ("pressure", "gap"))

    # ----------------------------------------------------------- stick zone
    def _stick_half_width(self, force=S.Q, budget=None, **values):
        """Stick half-width at the tangential force Q (|Q| <= mu P).

        Symbolic Q: a :class:`Derivation` of c_s(a, Q) -- closed where the force
        law inverts (Hertz: sqrt(a^2 - 4 R |Q|/(pi E* mu)), i.e. c_s/a =
        sqrt(1 - |Q|/(mu P))), else P(c_s) = P(a) - |Q|/mu solved numerically;
        ``budget`` (seconds, default the contact's) is a deadline for the
        inversion and its verification together; remembered on disk.
        Numeric Q with numbers for the parameters, and ``a`` or the normal load
        ``P``: the number (30 digits).  |Q| > mu P raises
        :class:`~linecontact_sym.core.errors.GrossSlidingError`."""
        Qv = history.to_sympy_number(force)
        if Qv.is_number:
            return history.stick_half_width_at(self, Qv, values).c
        key = ("stick_half_width", Qv)
        if key not in self._cache or (not self._cache[key].closed_form and self._cache[key].attempts):
            # derived for the package's Q, then written in the user's own symbol
            self._cache[key] = states.derive_stick_half_width(self, S.Q, budget) if Qv == S.Q else \
                states.in_terms_of(self, self._stick_half_width(S.Q, budget), Qv)
        return self.noted(self._cache[key])

    def _derive_stick_half_width(self):
        return self._stick_half_width(S.Q)

    # ----------------------------------------------------------- load histories (numbers)
    def state(self, Q, **values):
        """The partial-slip state after monotonic loading from 0 to Q (numbers:
        ``a`` or ``P``, E_star, the profile's parameters, mu if symbolic); a
        :class:`~.history.TangentialState`.

        >>> import linecontact_sym as lcs
        >>> t = lcs.parabola(verify=False).tangential()
        >>> st = t.state(0.1, E_star=1, R=1, mu=0.4, a=0.8)   # c/a = sqrt(1 - Q/(mu P)), P = pi a^2/4
        >>> round(float(st.c / st.a), 12)
        0.708971651646
        >>> bool(abs(t.unload(0.1, -0.1, E_star=1, R=1, mu=0.4, a=0.8).c_r - st.c) < 1e-25)
        True
        """
        refuse_units({'Q': Q, **values}, 'the tangential state', S.UNITS)
        return history.stick_half_width_at(self, history.to_sympy_number(Q), values)

    def unload(self, Q_max, Q, **values):
        """Mindlin-Deresiewicz: the state at Q after loading to Q_max and
        unloading (-Q_max <= Q <= Q_max)."""
        refuse_units({'Q': Q, 'Q_max': Q_max, **values}, 'the tangential unload', S.UNITS)
        return history.reversal(self, Q_max, Q, values, "unloading")

    def reload(self, Q_max, Q, **values):
        """The state at Q on the reloading branch from -Q_max (after a full
        unloading to -Q_max)."""
        refuse_units({'Q': Q, 'Q_max': Q_max, **values}, 'the tangential reload', S.UNITS)
        return history.reversal(self, Q_max, Q, values, "reloading")

    def cycle(self, Q_amplitude, points: int = 41, **values):
        """A full fretting cycle between +-Q_amplitude: the loop (Q, delta),
        the stick half-width at the extremes and the energy dissipated per
        cycle; a :class:`~.history.FrettingCycle`."""
        refuse_units({'Q': Q_amplitude, **values}, 'the tangential cycle', S.UNITS)
        return history.cycle(self, Q_amplitude, check_points(points), values)

    def bem(self, elements: int = 200, **values):
        """The independent direct solution on this contact's normal pressure
        (:class:`~.reference.CoulombBEM`) at numbers (``a`` or
        ``P``, E_star, parameters, mu)."""
        refuse_units(values, 'the tangential bem', S.UNITS)
        return history.bem(self, elements, values)

    def report(self, quantities=("traction", "tangential_force", "slip", "dissipated_energy")) -> str:
        return super().report(quantities)


__all__ = ["TangentialLineContact", "LOADING", "UNLOADING", "MU_RANGE"]
