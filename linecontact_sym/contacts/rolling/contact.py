"""Steady rolling with traction (Carter 1926) for any profile: the stick zone at
the leading edge, the creepage, the traction, by the reduction to the bounded
pressure of the same profile, tilted, over the stick zone.

Setting and conventions
-----------------------
* plane strain, half-plane approximation, steady state, elastically similar
  bodies (or Dundurs' beta neglected: the traction leaves the pressure
  unchanged; ``rolling(mu, beta=...)`` or ``materials=...`` have every
  result state the neglected coupling |beta| mu, else "beta = 0 assumed",
  :mod:`linecontact_sym.contacts.tangential.coupling`), Coulomb friction
  mu, constant normal load P;
* **rolling in +x**: the contact moves in +x over both bodies; in its frame
  the material flows in -x, enters at the *leading edge* (the right end c of
  the contact [-b, c]) and leaves at the trailing edge -b;
* q(x): the shear traction on body 1 (from body 2), Q = int q dx;
  u = u_1x - u_2x the relative elastic surface displacement,
  u'(x) = -(2/(pi E*)) PV int q(t)/(x - t) dt;
* **creepage** xi: the rigid creep velocity of body 2 relative to body 1
  over the rolling speed; body 1's material slips relative to body 2 with the
  velocity -V (xi + u'(x)).  Stick: xi + u' = 0, |q| <= mu p; slip:
  q = mu p sign(xi + u'), against the slip velocity.  With this sign Q and xi
  have the same sign (Kalker's creepage of body 1 relative to body 2 is -xi).

The reduction
-------------
With q = mu p in the slip zone [-b, s) and q = mu p - q* in the stick zone
[s, c], the stick condition reads (2/(pi E*)) PV int q*/(x - t) dt =
mu (f'(x) - theta_n - xi/mu): q*/mu is the pressure of the same profile,
tilted by theta* = theta_n + xi/mu, over [s, c], and it must be bounded at
both ends (q continuous at s, q -> 0 at the contact edge c).  Hence, with the
stick zone's centre e* = (s + c)/2 and half-width c_s = (c - s)/2 and the
bounded interval solution P(e, a), theta(e, a) (the asymmetric core's
``OffsetContact.force()`` and ``tilt()``, derived by the engine; at numbers
its ``numbers()`` where the force laws close, else by quadrature,
:mod:`linecontact_sym.contacts.asymmetric.interval`):

    Q  = mu [P - P(e*, c_s)]          (fixes c_s: P(e*, c_s) = P - |Q|/mu)
    xi = mu [theta(e*, c_s) - theta_n] (theta_n = 0 for a symmetric contact)
    q  = mu p(x) - mu p(x; e*, c_s)   on [s, c],   mu p(x) on [-b, s).

Carter (f = x^2/(2R)): P(e, a) = pi E* a^2/(4R), theta = e/R, so
c_s = a sqrt(1 - Q/(mu P)) and xi = mu (a - c_s)/R: the engine derives both.
Even powers close in the same way (polynomial slopes).

Admissibility (checked at every state): J*(x) >= 0 on the contact, where
p*(x) = (E*/2) sqrt(c_s^2 - (x - e*)^2) J*(x) inside and the tilted gap's
slope is -sqrt((x - e*)^2 - c_s^2) J*(x) before the stick zone (so slip runs
against the traction there), and p* <= 2 p in the stick zone (q >= -mu p).
Convex profiles pass; a flat or a dent may need more than one stick zone:
:class:`~linecontact_sym.core.errors.InadmissibleProfileError`.
"""
from __future__ import annotations

import mpmath
import numpy as np
import sympy as sp

from ...core import symbols as S
from ...core.budget import run_with_budget
from ...core.conversion import rational, to_mpf
from ...core.errors import BudgetExceeded, DomainError, InadmissibleProfileError, ProfileError
from ...core.ranges import check_points
from ...core.precision import workdps
from ...core.units import refuse_units
from ...method.derivation import Derivation, fallback_step
from ...method.rules import Step
from ...method.verification import verify
from ...numeric.functions import make_callable
from ..base import ContactOn, Quantity, checked_value
from ..sampling import point_sampler
from ..tangential import history as th
from ..tangential.contact import MU_RANGE, TangentialLineContact
from ..tangential.coupling import FrictionalCoupling
from ..tangential.states import friction_at, tidy_root
from . import state as st
from ..asymmetric.interval import E_C, X, Interval, SlopeNumbers, whole_line_breaks, whole_line_profile, whole_line_slope

#: the stick zone's deficit a - c_s (its centre e* for a symmetric contact)
_u = sp.Dummy("u", positive=True)

CONDITIONS = ("valid for: plane strain; steady rolling in +x; elastically similar bodies or Dundurs' beta "
              "neglected; Coulomb friction mu; constant normal load; one stick zone at the leading edge "
              "(checked at numbers: convex profiles)")


class RollingLineContact(FrictionalCoupling, ContactOn):
    """Steady rolling with traction over a frictionless
    :class:`~linecontact_sym.contacts.normal.contact.LineContact` (see the
    module docstring for the reduction and the sign conventions).

    >>> import linecontact_sym as lcs
    >>> r = lcs.parabola(verify=False).rolling()
    >>> r.creepage                       # xi(a, c_s): Carter's mu (a - c_s)/R
    mu*(a - c_s)/R
    >>> r.stick_half_width().expr
    sqrt(a**2 - 4*R*Abs(Q)/(pi*E_star*mu))
    """

    kind = "rolling"

    tangential_force = Quantity("Q(a, c_s)", "", "tangential force per unit length on body 1 in steady rolling "
                                "with the stick zone [a - 2 c_s, a] at the leading edge: mu [P(a) - P(a - c_s, c_s)]",
                                arguments=("a", "c_s"), latex="Q", unit="N/m")
    creepage = Quantity("xi(a, c_s)", "", "creepage (rigid creep velocity of body 2 relative to body 1 over the "
                        "rolling speed; same sign as Q) with the stick zone [a - 2 c_s, a]: "
                        "mu theta(a - c_s, c_s)", arguments=("a", "c_s"), latex=r"\xi",
                        unit="")
    stick_half_width = Quantity("c_s(Q)", "", "half-width of the stick zone at the leading edge at the tangential "
                                "force Q: the root of P(a - c_s, c_s) = P(a) - |Q|/mu", arguments=("a", "Q"),
                                method=True, latex=r"c_{\mathrm{s}}", unit="m")

    def __init__(self, contact, friction=S.mu, *, beta=None, materials=None):
        # the friction's and the bodies' checks (its DomainWarning where beta != 0) and the numbers' reading
        self._t = TangentialLineContact(contact, friction, beta=beta, materials=materials)
        self.contact = contact
        self.mu = self._t.mu
        self.coupling = self._t.coupling
        self._cache = {}

    @classmethod
    def from_frictionless(cls, contact, *, beta=None, materials=None):
        return cls(contact, S.mu, beta=beta, materials=materials)

    @staticmethod
    def over_asymmetric(contact, friction=S.mu, *, beta=None, materials=None):
        """Rolling over an asymmetric contact (numbers):
        :class:`~.asymmetric.AsymmetricRolling`."""
        from .asymmetric import AsymmetricRolling
        return AsymmetricRolling(contact, friction, beta=beta, materials=materials)

    def __repr__(self):
        return f"RollingLineContact({self.contact.profile.expr}, mu={self.mu}{self.coupling.keywords()})"

    @property
    def variables(self):
        return self._t.variables

    # ----------------------------------------------------------- the interval solution
    @property
    def interval(self) -> Interval:
        """The stick zone's pressure in a stable closed form (polynomial slopes)."""
        if "_interval" not in self._cache:
            self._cache["_interval"] = Interval(whole_line_slope(self.contact))
        return self._cache["_interval"]

    @property
    def offset(self):
        """The asymmetric core's contact of the same profile on the whole line
        (:class:`~linecontact_sym.contacts.asymmetric.OffsetContact`): the
        engine's P(e, a) and theta(e, a) of an interval that is not centred."""
        if "_offset" not in self._cache:
            from ..asymmetric import OffsetContact
            c = self.contact
            self._cache["_offset"] = OffsetContact(whole_line_profile(c), dict(c.profile.ranges), budget=c.budget,
                                                   verify=c.verify, points=c.points)
        return self._cache["_offset"]

    def _aux(self, what):
        """P or theta of the stick zone [a - 2 c_s, a] (e = a - c_s, half-width c_s): the
        asymmetric core's, or the defining phi-integral (unevaluated) where the core
        does not take the profile."""
        try:
            e = self.offset.force() if what == "force" else self.offset.tilt()
        except ProfileError:
            e = Interval(whole_line_slope(self.contact)).integral(what)
        return e.xreplace({E_C: S.a - S.c_s, S.a: S.c_s})

    def _core_numbers(self, fixed):
        """The asymmetric core's numbers at these values where the core takes
        the profile and its force laws close (P(e, a), theta(e, a) from the
        engine's closed forms), else None (:class:`SlopeNumbers` then takes
        the phi-quadrature)."""
        if self._cache.get("_core_refused"):
            return None
        try:
            off = self.offset
            if not off.closed("force"):
                return None
        except ProfileError:          # more than one kink (the rounded punch, the worn cylinder)
            self._cache["_core_refused"] = True
            return None
        return off.numbers(**{k.name: v for k, v in fixed.items()})

    def _numbers(self, vals) -> SlopeNumbers:
        fixed = {k: v for k, v in vals.items() if k in set(self.contact.variables)}
        key = ("_numbers", tuple(sorted((k.name, str(v)) for k, v in fixed.items())))
        if key not in self._cache:
            brs = [b.xreplace(fixed) for b in whole_line_breaks(self.contact)]
            self._cache[key] = SlopeNumbers(self.interval.slope, fixed, to_mpf(sp.N(fixed[S.E_star], 40)), brs,
                                            core=self._core_numbers(fixed))
        return self._cache[key]

    def _sampler(self):
        base = point_sampler(self.profile, "any", {s: MU_RANGE for s in self._t._msyms})

        def sample(rng):
            vals = base(rng)
            if vals is None:
                return None
            vals[S.c_s] = rational(float(vals[S.a]) * rng.uniform(0.1, 0.9))
            return vals
        return sample

    def _reference(self, what):
        """The phi-integrals by quadrature at the point (mpmath; never the
        core's closed forms, which the verified expressions come from)."""
        def ref(vals, dps):
            with workdps(dps + 10):
                num = self._numbers(vals)
                A, C = (to_mpf(sp.N(vals[k], dps + 15)) for k in (S.a, S.c_s))
                mu = friction_at(self._t, vals)
                if what == "force":
                    Pa = to_mpf(sp.N(self.contact.derivation("force").expr.xreplace(vals), dps + 15)) \
                        if self.contact.derivation("force").closed_form else num.P_quad(0, A)
                    return mu * (Pa - num.P_quad(A - C, C))
                return mu * num.tilt_quad(A - C, C)
        return ref

    def _derive_quantity(self, name, expr):
        closed = not expr.has(sp.Integral)
        conds = tuple(self.contact.derivation("force").conditions) + (sp.Lt(S.c_s, S.a),)
        ref = self._reference("force" if name == "tangential_force" else "tilt")
        how = "the phi-integrals of the stick zone's bounded pressure (split at the kinks)"
        rec, notes = None, (CONDITIONS,)
        if closed and self.contact.verify:
            rec = verify(expr, ref, self._sampler(), conds, n_points=self.contact.points, reference_name=how)
            if not rec.passed:
                notes = (f"closed form FAILED verification ({rec.min_digits:.1f} digits)",) + notes
                closed = False
        note = {"tangential_force": "mu [P(a) - P(e*, c_s)], e* = a - c_s: the engine's force law and the stick "
                                    "zone's bounded load",
                "creepage": "mu theta(e*, c_s): the tilt that keeps the stick zone's pressure bounded"}[name]
        step = Step("rolling_reduction", expr, conds, (note,)) if closed \
            else fallback_step("the stick zone's load or tilt has no closed form here")
        return Derivation(name, expr=expr, closed_form=closed, step=step, conditions=conds if closed else (),
                          verification=rec, notes=notes, reference=ref,
                          variables=(S.a, S.c_s) + tuple(self.variables))

    def _derive_tangential_force(self):
        P = self.contact.derivation("force").expr
        expr = self.mu * (P - self._aux("force"))
        if not expr.has(sp.Integral):
            expr = sp.factor(sp.simplify(expr))
        return self._derive_quantity("tangential_force", expr)

    def _derive_creepage(self):
        expr = self.mu * self._aux("tilt")
        if not expr.has(sp.Integral):
            expr = sp.factor(sp.simplify(expr))
        return self._derive_quantity("creepage", expr)

    # ----------------------------------------------------------- stick half-width
    def _stick_half_width(self, force=S.Q, **values):
        """c_s(Q): symbolic Q gives a :class:`Derivation` (closed where
        P(a - c_s, c_s) = P(a) - |Q|/mu solves: Carter's
        sqrt(a^2 - 4 R |Q|/(pi E* mu)) = a sqrt(1 - |Q|/(mu P))); a number
        with values gives the number (30 digits)."""
        Qv = th.to_sympy_number(force)
        if Qv.is_number:
            return self.state_at(Q=Qv, **values).c_s
        if "stick" not in self._cache:
            self._cache["stick"] = self._derive_stick()
        d = self._cache["stick"]
        return d if Qv == S.Q else Derivation(d.quantity, expr=d.expr.xreplace({S.Q: Qv}), closed_form=d.closed_form,
                                              step=d.step, conditions=d.conditions, notes=d.notes,
                                              variables=d.variables)

    def _derive_stick_half_width(self):
        return self._stick_half_width(S.Q)

    def _derive_stick(self):
        P = self.contact.derivation("force").expr
        Paux = self._aux("force")
        eq = Paux - (P - sp.Abs(S.Q) / self.mu)
        conds = tuple(self.contact.derivation("force").conditions) + (sp.Lt(sp.Abs(S.Q), self.mu * P),)
        variables = (S.a, S.Q) + tuple(self.variables)

        def value(vals, dps):
            with workdps(dps + 10):
                v = {k: vv for k, vv in vals.items() if k not in (S.a, S.Q)}
                names = {k.name: vv for k, vv in v.items()}
                return self.state_at(Q=vals[S.Q], a=vals[S.a], _check=False, **names).c_s
        cands = []
        if not eq.has(sp.Integral):
            try:
                sols = run_with_budget(sp.solve, eq, S.c_s, seconds=min(self.contact.budget, 20))
                cands = [tidy_root(s) for s in sols if sp.count_ops(s) < 80]
            except (BudgetExceeded, NotImplementedError, ValueError, TypeError):
                cands = []
        sampler = self._sampler_Q()
        for cand in cands:
            rec = verify(cand, value, sampler, conds, n_points=self.contact.points if self.contact.verify else 1,
                         reference_name="the root of P(a - c_s, c_s) = P(a) - |Q|/mu (the rolling state's)")
            if rec.passed:
                step = Step("solve_stick_zone", cand, conds, ("c_s solving P(a - c_s, c_s) = P(a) - |Q|/mu",))
                return Derivation("stick_half_width", expr=cand, closed_form=True, step=step, conditions=conds,
                                  verification=rec, notes=(CONDITIONS,), reference=value, variables=variables)
        return Derivation("stick_half_width", expr=sp.Eq(Paux, P - sp.Abs(S.Q) / self.mu), closed_form=False,
                          step=fallback_step("numeric root of P(a - c_s, c_s) = P(a) - |Q|/mu"),
                          notes=(CONDITIONS,), reference=value, variables=variables)

    def _sampler_Q(self):
        base = point_sampler(self.profile, "any", {s: MU_RANGE for s in self._t._msyms})
        P = self.contact.derivation("force").expr

        def sample(rng):
            vals = base(rng)
            if vals is None:
                return None
            muP = float(sp.N((self.mu * P).xreplace(vals)))
            vals[S.Q] = rational(muP * rng.uniform(0.05, 0.95))
            return vals
        return sample

    # ----------------------------------------------------------- states at numbers
    def _float_parts(self, vals):
        """float64 callables: the normal pressure p(x) (|x| folded) and the
        stick zone's pressure p(x; e, c) (closed forms where the engine has
        them, else the Gauss-Legendre numbers)."""
        num = self._numbers(vals)
        fixed = {k.name: float(v) for k, v in vals.items() if k in set(self.contact.variables)}
        pd = self.contact.derivation("pressure")
        pa = self.interval.pressure()
        closed = pd.closed_form and pa is not None
        if pd.closed_form:
            fn = make_callable(pd, "numpy", 15, fixed)   # the stable form: no atanh(1) cancellation at a kink

            def normal(x, A):
                ax = np.abs(x)
                with np.errstate(invalid="ignore", divide="ignore"):
                    v = np.real(fn(a=A, x=np.where(ax < A, ax, 0.0)))
                return np.where(ax < A, v, 0.0)
        else:
            normal = lambda x, A: num.pressure(x, 0.0, A)  # noqa: E731
        if pa is not None:
            subs = {s: sp.Float(fixed[s.name], 20) for s in self.contact.variables}
            g = sp.lambdify((X, E_C, S.a), pa.xreplace(subs), "numpy")

            def aux(x, e, c):
                r2 = c**2 - (x - e)**2
                with np.errstate(invalid="ignore"):
                    v = np.real(g(np.where(r2 > 0, x, e), e, c))
                return np.where(r2 > 0, v, 0.0)
        else:
            aux = num.pressure
        return normal, aux, num, closed

    def state_at(self, Q, _check=True, **values):
        """The steady rolling state at the tangential force Q (|Q| < mu P;
        rolling in +x) with ``a`` or ``P`` and numbers for E_star, the
        profile's parameters and mu if symbolic: a
        :class:`~.state.RollingState` (stick = (s, a) at the leading edge,
        slip, creepage, traction(x)); its admissibility checked.

        >>> import linecontact_sym as lcs
        >>> r = lcs.parabola(verify=False).rolling(0.3)
        >>> s = r.state_at(Q=0.64 * 0.3 * 178.8962657827113, a=1, E_star=113888.9, R=500)
        >>> round(float(s.stick[0]), 12), round(float(s.creepage), 12)
        (-0.2, 0.00024)
        """
        refuse_units({"Q": Q, **values}, "the rolling state", S.UNITS)
        Q = checked_value("Q", Q, None)          # a finite real number (1j, NaN, text: DomainError)
        if isinstance(Q, np.ndarray):
            raise DomainError(f"Q = {Q!r}: one tangential force per state")
        with workdps(30):
            vals, law, A = th.numbers_at(self._t, values)
            mu = friction_at(self._t, vals)
            P = law.P(A)
            Qs = th.to_sympy_number(Q)
            Qm = to_mpf(sp.N(Qs, 40))
            load, at_onset = st.onset(Qm, mu, P)
            num = self._numbers(vals)
            fP, ft = self.derivation("tangential_force"), self.derivation("creepage")
            closed = fP.closed_form and ft.closed_form
            u, xi, closed, note = self._solve(Qs, Qm, A, P, mu, load, at_onset, vals, num, closed)
            c = A - u
            normal, aux, _, fclosed = self._float_parts(vals)
            Af, cf, ef = float(A), float(c), float(u)
            state = st.RollingState(Qm, P, mu, -A, A, A - 2 * c, c, xi, closed and fclosed, note=note,
                                    coupling=th.coupling_at(self._t, vals),
                                    _normal=lambda x: normal(x, Af), _aux=lambda x: aux(x, ef, cf))
        if _check and c > 0 and Qm != 0:
            st.check_admissible(state, lambda x: num.J(x, ef, cf), lambda x: normal(x, Af),
                                f"the profile {self.profile.expr}")
        return state

    def _solve(self, Qs, Qm, A, P, mu, load, at_onset, vals, num, closed):
        """(u, xi, closed, note): the stick zone [A - 2c, A] by its deficit
        u = A - c (free rolling: u -> 0, where P - P(e*, c) cancels) and the
        creepage.  The closed Q(a, c_s) is factored, exact in u; the numbers
        get the digits the cancellation takes as extra working precision.  A
        closed result is checked against the float64 quadrature of the same
        integrals at the solution (a closed form outside the cases it covers
        falls back to the numbers, with a note)."""
        sign = -1 if Qm < 0 else 1
        if Qm == 0:
            return mpmath.mpf(0), mpmath.mpf(0), closed, ""
        note = ""
        if closed:
            fP, ft = self.derivation("tangential_force"), self.derivation("creepage")
            try:
                if at_onset:
                    u = A
                else:
                    Ql = sp.lambdify((S.a, _u), fP.expr.xreplace({S.c_s: S.a - _u}).xreplace(vals), "mpmath")
                    extra = st.near_full_slip_digits(load, P)
                    with workdps(30 + extra):   # Q(u) flattens as Q -> mu P: Q itself to more digits
                        Qx = abs(to_mpf(sp.N(Qs, 40 + extra)))
                        u = +st.solve_deficit(lambda uu: Ql(A, uu) - Qx, A, Qx / (mu * P))
                tl = sp.lambdify((S.a, _u), ft.expr.xreplace({S.c_s: S.a - _u}).xreplace(vals), "mpmath")
                xi = sign * mpmath.re(tl(A, u))
                uf, cf, muf = float(u), float(A - u), float(mu)
                q_num = muf * (float(P) - num.P_float(uf, cf))
                xi_num = sign * muf * num.tilt_float(uf, cf)
                scale = muf * max(abs(num.tilt_float(0.0, float(A) * 2)), abs(num.tilt_float(float(A), 0.0)), 1e-300)
                if not (abs(q_num - float(abs(Qm))) <= 1e-7 * muf * float(P)
                        and abs(float(xi) - xi_num) <= 1e-7 * scale):
                    raise ValueError("the closed forms disagree with the quadrature here")
                return u, xi, True, ""
            except (ValueError, TypeError, ZeroDivisionError, InadmissibleProfileError) as exc:
                note = (f"the closed forms were not used at this state ({exc}); the numbers come from the "
                        f"quadrature of the same integrals")
        # closed forms refused here: the quadrature of the integrals, not the core's closed forms again
        P_mp, tilt_mp = (num.P_quad, num.tilt_quad) if note else (num.P, num.tilt)
        if at_onset:
            u = A
        else:
            extra = max(0, int(-mpmath.log10(abs(Qm) / (mu * P)))) + 2 + st.near_full_slip_digits(load, P)
            with workdps(30 + extra):
                c = st.solve_stick(P_mp, A, A, P - abs(Qm) / mu, 30 + extra, P_float=num.P_float)
                u = A - c
        return u, sign * mu * tilt_mp(u, A - u), False, note

    def creepage_curve(self, points: int = 41, **values):
        """The creepage-force curve (Q/(mu P), xi) at ``points`` stick
        half-widths from the whole contact (free rolling) to 0 (full slip),
        float64, without root finding (both are functions of c_s)."""
        points = check_points(points, 2, "the creepage-force curve")
        with workdps(20):
            vals, law, A = th.numbers_at(self._t, values)
            mu, P = friction_at(self._t, vals), law.P(A)
        num = self._numbers(vals)
        cs = np.linspace(float(A), 0.0, points)
        fP, ft = self.derivation("tangential_force"), self.derivation("creepage")
        fixed = {k.name: float(v) for k, v in vals.items()}
        if fP.closed_form and ft.closed_form:
            Q = np.real(make_callable(fP, "numpy", 15, fixed)(a=float(A), c_s=cs))
            xi = np.real(make_callable(ft, "numpy", 15, fixed)(a=float(A), c_s=cs))
        else:
            Af, muf, Pf = float(A), float(mu), float(P)
            Q = np.array([muf * (Pf - num.P_float(Af - c, c)) for c in cs])
            xi = np.array([muf * num.tilt_float(Af - c, c) for c in cs])
        return Q / float(mu * P), xi

    def report(self, quantities=("tangential_force", "creepage")) -> str:
        return super().report(quantities)


__all__ = ["RollingLineContact", "CONDITIONS"]
