"""The line contact on an interval that is not centred: Popov's superposition
of flat punches whose centre e is a second parameter (the core of
:mod:`linecontact_sym.contacts.asymmetric`).

The problem
-----------
A rigid profile f(x), given on the whole real line in the real ``x``
(:data:`~linecontact_sym.core.symbols.x_real`), tilted by theta
(:data:`~linecontact_sym.core.symbols.tilt`), pressed into an elastic
half-plane (plane strain, reduced modulus E*).  Gap: f(x) - theta x - d;
theta > 0 moves the contact to +x.  Contact on [e - a, e + a]: centre
e (:data:`~linecontact_sym.core.symbols.e`, real), half-width a > 0.
The pressure p >= 0 is compressive positive, P = int p dx the load per unit
length, M = int x p dx the moment about x = 0 (the load's line of action
is at x = M/P), M_c = int (x - e) p dx the moment about the centre.  The
contact condition is the singular integral equation

    (2/(pi E*)) PV int p(t)/(x - t) dt = f'(x) - theta,   e - a < x < e + a.

The reduction (no second engine)
--------------------------------
In s = x - e split f(e + s) = f(e) + E(s) + h(s) into its even part E and
odd part h, and let H(s) = int_0^s h (even): :mod:`.split`.  E, H and the
unit rotation profile s^2/2 are symmetric profiles in s with e a real
parameter; the engine (:class:`~linecontact_sym.contacts.normal.contact.LineContact`
of each, flagged ``auxiliary``: not an indenter, so f' >= 0 is not asked;
budget and verification as for any contact) gives their force laws (Eq. 10*),
pressures (Eq. 12) and gaps (Eqs. 3/5).  With F(s) = H(s) - theta s^2/2 and
the displacement of the derivative of a load being the derivative of its
displacement, the general solution on [e - a, e + a] is

    p(x) = p_E(s; a) + d/ds p_F(s; a) + P0 / (pi sqrt(a^2 - s^2)),    s = x - e,

with P0 the load of an extra flat punch (corners).  Hence

    P(e, a)        = P_E(a) + P0                        (the odd part carries no load)
    M_c(e, a, th)  = -P_F(a) = -(P_H(a) - th P_2(a))    (by parts: p_F = 0 at s = +-a)
    M              = e P + M_c
    theta(e, a)    = (2/(pi E* a)) dP_H/da              (dP_F/da = 0: p_F ~ (a - |s|)^(3/2))

and the coefficients of the square-root singularities,
p ~ K_+- / sqrt(a -+ s) at the right (+) and left (-) ends, are

    K_+- = (P0 -+ dP_F/da) / (pi sqrt(2 a)),    dP_F/da = dP_H/da - th pi E* a/2.

The *bounded* solution (both edges smooth) is P0 = 0, theta = theta(e, a);
one smooth edge and one corner (a punch wall) is K = 0 at the smooth edge
only; a complete flat punch has both corners.  A symmetric profile at e = 0
has H = 0, E = f: today's results.

Checks: f = x^2/(2R) gives theta = e/R (Hertz shifted by R theta);
f = x^2/2 + x^3/10 gives theta = e + 3 e^2/10 + 3 a^2/20 = (1/pi) int f'(e + a sin phi) dphi.

API (stable; extended, not renamed)
-----------------------------------
``OffsetContact(f, params=None, *, x=x_real, name=None, budget=..., verify=True, points=5, e_range=(-1, 1))``
    f a SymPy expression in ``x`` (real) on the whole line; ``params`` its
    declared parameters (list or dict symbol -> (low, high)).
    Attributes: ``f``, ``even``/``odd`` (the engine contacts of E and H, or
    None where the part is 0), ``rotation`` (the engine contact of s^2/2),
    ``parts`` = {'E': E, 'H': H} in the engine's x (standing for |s|).
Symbolic (SymPy in e, a, E_star, the profile's parameters; Integrals where
the engine finds no closed form):
    ``force()`` P(e, a) of the bounded part (P0 = 0);
    ``tilt()`` theta(e, a);
    ``odd_force()`` P_H(a); ``rotation_force()`` P_2(a) = pi E* a^2/4;
    ``moment_centre(theta=None)`` M_c (theta None: theta(e, a));
    ``moment(theta=None)`` M = e P + M_c;
    ``pressure(theta=None, punch=0)`` p(x) in x_real for e - a < x < e + a;
    ``gap(theta=None, punch=0)`` g(x) in x_real outside the contact (the
    part of the flat punch P0 taken against the contact edge: g(e +- a) = 0);
    ``edge_factors(theta=None, punch=0)`` (K_-, K_+).
Numeric: ``numbers(**values)`` -> :class:`OffsetNumbers` at E_star and the
profile's parameters (by name): ``P(e, a)``, ``P_H(e, a)``, ``dP_H(e, a)``,
``tilt(e, a)``, ``moment_centre(e, a, theta=None)``, ``moment(e, a, theta=None, punch=0)``,
``edge_factors(e, a, theta=None, punch=0)``, ``pressure(x, e, a, theta=None, punch=0)``:
mpmath numbers at the working precision (closed forms where the engine found
them, else the engine's quadrature force laws and references).
"""
from __future__ import annotations

import mpmath
import sympy as sp

from ...core import symbols as S
from ...core.budget import DEFAULT_BUDGET
from ...core.conversion import to_mpf
from ...core.errors import DomainError, ProfileError
from ...core.precision import workdps
from ...method.profile import Profile
from ..normal.contact import LineContact
from ..normal.force_law import ForceLaw
from .split import even_part, odd_integral

__all__ = ["OffsetContact", "OffsetNumbers"]

#: the names reserved by the asymmetric contact (a profile may not use them)
RESERVED = (S.e, S.tilt, S.M)


def _in_s(expr, s):
    """An engine result in its x (standing for |s|, x >= 0) as a function of
    the real s: x -> s where the expression is even in x, else x -> |s|."""
    t = sp.Dummy("t", real=True)
    et = expr.xreplace({S.x: t})
    try:
        even = sp.expand(et - et.xreplace({t: -t})) == 0
    except Exception:   # an expression SymPy cannot expand: |s| is always right
        even = False
    return expr.xreplace({S.x: s if even else sp.Abs(s)})


def _d_in_s(expr, s):
    """d/ds of an engine result even in s (x standing for |s|): the
    derivative in x, odd in s."""
    d = sp.diff(expr, S.x)
    t = sp.Dummy("t", real=True)
    dt = d.xreplace({S.x: t})
    try:
        odd = sp.expand(dt + dt.xreplace({t: -t})) == 0
    except Exception:
        odd = False
    return d.xreplace({S.x: s}) if odd else sp.sign(s) * d.xreplace({S.x: sp.Abs(s)})


class OffsetContact:
    """The contact on [e - a, e + a] of a profile on the whole line: see the
    module docstring (problem, reduction, API, sign conventions)."""

    def __init__(self, f, params=None, *, x=S.x_real, name=None, budget=DEFAULT_BUDGET, verify=True,
                 points: int = 5, e_range=(-1, 1)):
        if not isinstance(f, sp.Expr):
            raise ProfileError(f"the profile must be a SymPy expression in {x}, got {f!r}")
        bad = [r for r in RESERVED if r in f.free_symbols]
        if bad:
            raise ProfileError(f"the profile {f} uses {', '.join(map(str, bad))}: the centre e, the tilt "
                               f"theta_t and the moment M are the asymmetric contact's own symbols")
        if S.x in f.free_symbols:
            raise ProfileError(f"the profile {f} is in the positive x of the symmetric contact; an asymmetric "
                               f"profile is written in the real x (linecontact_sym.x_real)")
        self.f = f.xreplace({x: S.x_real}) if x != S.x_real else f
        self.name = name or str(f)
        if isinstance(params, dict):
            declared = dict(params)
        else:
            declared = {p: None for p in (params or ())}
        self.params = tuple(sorted(self.f.free_symbols - {S.x_real}, key=lambda v: v.name))
        aux = {**declared, S.e: e_range}
        self.parts = {"E": even_part(self.f), "H": odd_integral(self.f, seconds=budget)}
        kw = dict(budget=budget, verify=verify, points=points)

        def contact(expr, what):
            if expr is None:
                raise ProfileError(f"the profile {self.name}: SymPy finds no antiderivative, needed for its "
                                   f"odd part (H(s) = int_0^s h); give a profile whose antiderivative closes")
            if not expr.has(S.x):
                if expr != 0:
                    raise ProfileError(f"the {what} part of {self.name} is a constant {expr} != 0")
                return None
            used = {p: r for p, r in aux.items() if p in expr.free_symbols}
            return LineContact(Profile(expr, used, name=f"{what} part of {self.name} about e", auxiliary=True), **kw)
        self.even = contact(self.parts["E"], "even")
        self.odd = contact(self.parts["H"], "odd-integral")
        self.rotation = LineContact(S.x**2 / 2, **kw)
        self.budget, self.verify = budget, verify
        self._memo: dict = {}

    def __repr__(self):
        return f"OffsetContact({self.f})"

    @property
    def variables(self):
        """The symbols a number needs besides e, a (and x): E_star and the profile's parameters."""
        return (S.E_star,) + self.params

    # ------------------------------------------------------------ symbolic
    def _part(self, contact, quantity):
        if contact is None:
            return sp.S.Zero
        return contact.derivation(quantity).expr

    def derivations(self):
        """{name: Derivation} of every engine result used (for the records)."""
        out = {}
        for label, c in (("E", self.even), ("H", self.odd), ("rotation", self.rotation)):
            if c is not None:
                for q in ("force", "pressure", "gap"):
                    out[f"{q}[{label}]"] = c.derivation(q)
        return out

    def closed(self) -> bool:
        """Did the engine close the force laws of E and H?"""
        return all(c is None or c.derivation("force").closed_form for c in (self.even, self.odd))

    def force(self):
        """P(e, a) = P_E(a), Eq. (10*) of the even part (the bounded part; a punch adds P0)."""
        return self._part(self.even, "force")

    def odd_force(self):
        """P_H(a): Eq. (10*) of H."""
        return self._part(self.odd, "force")

    def rotation_force(self):
        """P_2(a): Eq. (10*) of the unit rotation profile s^2/2."""
        return self._part(self.rotation, "force")

    def tilt(self):
        """theta(e, a) = (2/(pi E* a)) dP_H/da: the tilt at which the
        pressure on [e - a, e + a] is bounded at both ends."""
        if "tilt" not in self._memo:
            PH = self.odd_force()
            dPH = sp.Derivative(PH, S.a) if PH.has(sp.Integral) else sp.diff(PH, S.a)
            th = 2 * dPH / (sp.pi * S.E_star * S.a)
            self._memo["tilt"] = sp.factor_terms(sp.expand(th)) if not th.has(sp.Integral) else th
        return self._memo["tilt"]

    def _theta(self, theta):
        return self.tilt() if theta is None else sp.sympify(theta)

    def moment_centre(self, theta=None):
        """M_c = int (x - e) p dx = -(P_H - theta P_2); ``theta`` None: theta(e, a)."""
        return sp.expand(-(self.odd_force() - self._theta(theta) * self.rotation_force()))

    def moment(self, theta=None, punch=0):
        """M = int x p dx = e (P + P0) + M_c."""
        return sp.expand(S.e * (self.force() + punch) + self.moment_centre(theta))

    def edge_factors(self, theta=None, punch=0):
        """(K_-, K_+): p ~ K_-/sqrt(a + s) at the left end, K_+/sqrt(a - s) at the right."""
        # the derivative at a fixed tilt (theta(e, a) depends on a)
        PH, th = self.odd_force(), self._theta(theta)
        dPH = sp.Derivative(PH, S.a) if PH.has(sp.Integral) else sp.diff(PH, S.a)
        dPF = dPH - th * sp.diff(self.rotation_force(), S.a)
        k = sp.pi * sp.sqrt(2 * S.a)
        if PH.has(sp.Integral):
            return (punch + dPF) / k, (punch - dPF) / k
        return sp.simplify((punch + dPF) / k), sp.simplify((punch - dPF) / k)

    def pressure(self, theta=None, punch=0):
        """p(x) on e - a < x < e + a (x = x_real): p_E + d/ds p_F + P0/(pi sqrt(a^2 - s^2))."""
        s = S.x_real - S.e
        pE = _in_s(self._part(self.even, "pressure"), s)
        pF = self._part(self.odd, "pressure") - self._theta(theta) * self._part(self.rotation, "pressure")
        out = pE + _d_in_s(pF, s)
        if punch != 0:
            out += punch / (sp.pi * sp.sqrt(S.a**2 - s**2))
        return out

    def gap(self, theta=None, punch=0):
        """g(x) outside the contact (|x - e| > a): g_E + d/ds g_F - (2 P0/(pi E*)) acosh(|s|/a)."""
        s = S.x_real - S.e
        gE = _in_s(self._part(self.even, "gap"), s)
        gF = self._part(self.odd, "gap") - self._theta(theta) * self._part(self.rotation, "gap")
        out = gE + _d_in_s(gF, s)
        if punch != 0:
            out -= 2 * punch / (sp.pi * S.E_star) * sp.acosh(sp.Abs(s) / S.a)
        return out

    # ------------------------------------------------------------ numbers
    def numbers(self, **values) -> "OffsetNumbers":
        """The numeric form at E_star and the profile's parameters (by name)."""
        return OffsetNumbers(self, values)


class OffsetNumbers:
    """P, theta, M_c, K_+-, p at numbers (mpmath, the working precision) for
    one set of E_star and profile parameters; e and a are arguments.

    Closed forms are lambdified once; where the engine left a force law as
    an Integral, the engine's quadrature law (:class:`~..normal.force_law.ForceLaw`)
    at that e is used (built once per e)."""

    def __init__(self, core: OffsetContact, values):
        self.core = core
        missing = [v.name for v in core.variables if v.name not in values]
        if missing:
            raise DomainError(f"the asymmetric contact needs values for {', '.join(missing)}")
        self.values = {v: sp.nsimplify(values[v.name]) if isinstance(values[v.name], float) else
                       sp.sympify(values[v.name]) for v in core.variables}
        self.E = to_mpf(self.values[S.E_star])
        self._laws: dict = {}
        self._fns: dict = {}

    # -- force laws of the parts at (e, a)
    def _law(self, contact, ev):
        key = (id(contact), ev)
        if key not in self._laws:
            vals = {S.e: sp.Float(ev, mpmath.mp.dps + 10), **self.values}
            used = {k: v for k, v in vals.items() if k in contact.variables or k == S.e}
            self._laws[key] = ForceLaw.from_contact(contact, used)
        return self._laws[key]

    def _closed_fn(self, contact, quantity, derivative=False):
        key = (id(contact), quantity, derivative)
        if key not in self._fns:
            expr = contact.derivation(quantity).expr
            if derivative:
                expr = sp.diff(expr, S.a)
            expr = expr.xreplace({k: v for k, v in self.values.items()})
            self._fns[key] = sp.lambdify([S.e, S.a, S.x], expr, "mpmath")
        return self._fns[key]

    def _P(self, contact, e, a, derivative=False):
        if contact is None:
            return mpmath.mpf(0)
        if contact.derivation("force").closed_form:
            return mpmath.mpf(self._closed_fn(contact, "force", derivative)(e, a, 0).real)
        law = self._law(contact, e)
        return law.dP(a) if derivative else law.P(a)

    def P(self, e, a):
        """P(e, a) = P_E(a) (the bounded part)."""
        return self._P(self.core.even, mpmath.mpf(e), mpmath.mpf(a))

    def P_H(self, e, a):
        return self._P(self.core.odd, mpmath.mpf(e), mpmath.mpf(a))

    def dP_H(self, e, a):
        return self._P(self.core.odd, mpmath.mpf(e), mpmath.mpf(a), derivative=True)

    def P_2(self, a):
        return self._P(self.core.rotation, 0, mpmath.mpf(a))

    def dP_2(self, a):
        return self._P(self.core.rotation, 0, mpmath.mpf(a), derivative=True)

    def tilt(self, e, a):
        """theta(e, a) = (2/(pi E* a)) dP_H/da."""
        return 2 * self.dP_H(e, a) / (mpmath.pi * self.E * mpmath.mpf(a))

    def _th(self, e, a, theta):
        return self.tilt(e, a) if theta is None else mpmath.mpf(theta)

    def moment_centre(self, e, a, theta=None):
        return -(self.P_H(e, a) - self._th(e, a, theta) * self.P_2(a))

    def moment(self, e, a, theta=None, punch=0):
        return mpmath.mpf(e) * (self.P(e, a) + punch) + self.moment_centre(e, a, theta)

    def edge_factors(self, e, a, theta=None, punch=0):
        """(K_-, K_+), see :meth:`OffsetContact.edge_factors`."""
        dPF = self.dP_H(e, a) - self._th(e, a, theta) * self.dP_2(a)
        k = mpmath.pi * mpmath.sqrt(2 * mpmath.mpf(a))
        return (punch + dPF) / k, (punch - dPF) / k

    def pressure(self, xv, e, a, theta=None, punch=0):
        """p(x) at a point of the contact (closed pressures lambdified; an
        Integral's reference otherwise, its s-derivative by mpmath.diff)."""
        e, a, xv = mpmath.mpf(e), mpmath.mpf(a), mpmath.mpf(xv)
        s = xv - e
        if abs(s) >= a:
            raise DomainError(f"x = {xv} is outside the contact [{e - a}, {e + a}]")
        th = self._th(e, a, theta)
        core = self.core
        pE = self._p(core.even, e, a, abs(s))
        dH = self._dp(core.odd, e, a, s)
        d2 = self._dp(core.rotation, e, a, s)
        return pE + dH - th * d2 + mpmath.mpf(punch) / (mpmath.pi * mpmath.sqrt((a - s) * (a + s)))

    def _p(self, contact, e, a, t):
        if contact is None:
            return mpmath.mpf(0)
        d = contact.derivation("pressure")
        if d.closed_form:
            return mpmath.mpf(self._closed_fn(contact, "pressure")(e, a, t).real)
        vals = {**self.values, S.e: e, S.a: a, S.x: t}
        with workdps(mpmath.mp.dps + 10):
            return d.reference({k: v for k, v in vals.items()}, mpmath.mp.dps)

    def _dp(self, contact, e, a, s):
        """d/ds p(|s|) of a part."""
        if contact is None:
            return mpmath.mpf(0)
        d = contact.derivation("pressure")
        sign = 1 if s >= 0 else -1
        if d.closed_form:
            key = (id(contact), "dpressure")
            if key not in self._fns:
                expr = sp.diff(d.expr, S.x).xreplace(self.values)
                self._fns[key] = sp.lambdify([S.e, S.a, S.x], expr, "mpmath")
            return sign * mpmath.mpf(self._fns[key](e, a, abs(s)).real)
        with workdps(mpmath.mp.dps + 15):
            return sign * mpmath.diff(lambda t: self._p(contact, e, a, t), abs(s))
