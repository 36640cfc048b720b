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
from ...parsing import user_value
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


#: the positive distance of the centre from a kink of the profile, the parameter
#: of the parts in one case (e = b + eps or e = b - eps)
EPS = sp.Symbol("epsilon_e", positive=True)


def kinks(f, x=S.x_real) -> list:
    """The points b where a Piecewise (or Abs, Min, Max, sign, Heaviside) of
    f switches in x, as expressions in the parameters."""
    g = f
    for k in [t for t in f.atoms(sp.Abs, sp.Min, sp.Max, sp.sign, sp.Heaviside) if t.has(x)]:
        g = g.xreplace({k: k.rewrite(sp.Piecewise)})
    found = []
    for pw in g.atoms(sp.Piecewise):
        for _, cond in pw.args:
            for rel in cond.atoms(sp.core.relational.Relational):
                if not rel.has(x):
                    continue
                sol = sp.solve(sp.Eq(rel.lhs, rel.rhs), x)
                if len(sol) != 1:
                    raise ProfileError(f"cannot read the breakpoint of {rel} in the profile {f}")
                if not any(sp.simplify(sol[0] - b) == 0 for b in found):
                    found.append(sol[0])
    return found


class _Case:
    """The parts of the profile about the centre where e is on one side of the
    profile's kink b (or everywhere: no kink): E, H and s^2/2 as engine contacts,
    in the parameter ``par`` (e itself, or eps = sign (e - b) > 0)."""

    def __init__(self, f, condition, par, centre, aux, kw, name, budget, kink=None, sign=1):
        self.condition, self.par, self.centre = condition, par, centre
        #: the kink b and the side: eps = sign (e - b) >= 0 in this case (None: no kink)
        self.kink, self.sign = kink, sign
        #: the centre e in terms of the case's parameter, and back
        self.back = {} if par == S.e else {par: sp.expand((S.e - centre.xreplace({par: 0})) /
                                                         sp.diff(centre, par))}
        self.parts = {"E": even_part(f, e=centre), "H": odd_integral(f, e=centre, seconds=budget)}

        def contact(expr, what):
            if expr is None:
                raise ProfileError(f"the profile {name}: SymPy finds no antiderivative, needed for its "
                                   f"odd part (H(s) = int_0^s h); give a profile whose antiderivative closes")
            expr = sp.piecewise_fold(expr)
            if not expr.has(S.x):
                if sp.simplify(expr) != 0:
                    raise ProfileError(f"the {what} part of {name} is a constant {expr} != 0")
                return None
            used = {p: r for p, r in aux.items() if p in expr.free_symbols}
            return LineContact(Profile(expr, used, name=f"{what} part of {name} about e", auxiliary=True), **kw)
        self.even = contact(self.parts["E"], "even")
        self.odd = contact(self.parts["H"], "odd-integral")

    def expr(self, contact, quantity):
        """An engine result of a part in e (the case's parameter mapped back)."""
        if contact is None:
            return sp.S.Zero
        return contact.derivation(quantity).expr.xreplace(self.back)


class OffsetContact:
    """The contact on [e - a, e + a] of a profile on the whole line: see the
    module docstring (problem, reduction, API, sign conventions).

    A profile with a kink b (one Piecewise switch, an Abs) splits into two
    cases, e > b and e < b: in each the parts are Piecewise in s with their
    switch at |e - b| (the parameter eps = |e - b| > 0 of the engine); the
    symbolic results are Piecewise in e, the numbers pick the case of e.
    More than one kink is refused (a ProfileError naming the switches and
    why): the worn cylinder and the rounded punch on the whole line switch at
    -b, 0 (their |x|) and b.  Reading them needs the cases of the order of the
    distances |e - b_i| (each a positive parameter of the engine, with their
    differences' signs known): not done."""

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
        kw = dict(budget=budget, verify=verify, points=points)
        bs = kinks(self.f)
        if len(bs) > 1:
            raise ProfileError(
                f"the profile {self.name} switches at {len(bs)} points ({', '.join(map(str, sorted(bs, key=sp.default_sort_key)))}; a switch of "
                f"an Abs counts, even where the profile is smooth across it): a tilt or a moment is refused. "
                f"The asymmetric contact splits the centre e at one switch b into two cases (e >= b, e < b; "
                f"its even and odd parts then switch at |e - b| alone); with several switches the parts switch "
                f"at several distances |e - b_i| whose order changes with e, which the case split does not "
                f"read. Level contacts (theta = 0 or M = 0) of a symmetric profile are the symmetric "
                f"contact's (LineContact(f).contact_at(P)); a profile with one switch (one Piecewise "
                f"condition or one Abs, e.g. the flank the contact stays on) is read")
        if not bs:
            self.cases = (_Case(self.f, sp.true, S.e, S.e, {**declared, S.e: e_range}, kw, self.name, budget),)
        else:
            b = bs[0]
            self.cases = tuple(_Case(self.f, cond, EPS, b + sign * EPS, {**declared, EPS: None}, kw, self.name,
                                     budget, kink=b, sign=sign)
                               for cond, sign in ((S.e >= b, 1), (S.e < b, -1)))
        self.kinks = tuple(bs)
        self.rotation = LineContact(S.x**2 / 2, **kw)
        self.budget, self.verify = budget, verify
        self._memo: dict = {}

    def __repr__(self):
        return f"OffsetContact({self.f})"

    @property
    def even(self):
        """The engine contact of E (one case; with a kink the case e >= b)."""
        return self.cases[0].even

    @property
    def odd(self):
        """The engine contact of H (one case; with a kink the case e >= b)."""
        return self.cases[0].odd

    @property
    def parts(self):
        return self.cases[0].parts

    @property
    def variables(self):
        """The symbols a number needs besides e, a (and x): E_star and the profile's parameters."""
        return (S.E_star,) + self.params

    # ------------------------------------------------------------ symbolic
    def _combine(self, make, case=None):
        """make(case) for every case, as a Piecewise in e where there are two
        (``case``: the index of one case, its expression alone)."""
        if case is not None:
            return make(self.cases[case])
        if len(self.cases) == 1:
            return make(self.cases[0])
        return sp.Piecewise(*[(make(c), c.condition) for c in self.cases[:-1]], (make(self.cases[-1]), True))

    def derivations(self):
        """{name: Derivation} of every engine result used (for the records)."""
        out = {}
        for k, case in enumerate(self.cases):
            for label, c in (("E", case.even), ("H", case.odd)):
                if c is not None:
                    for q in ("force", "pressure", "gap"):
                        out[f"{q}[{label}{'' if len(self.cases) == 1 else k}]"] = c.derivation(q)
        for q in ("force", "pressure", "gap"):
            out[f"{q}[rotation]"] = self.rotation.derivation(q)
        return out

    def closed(self, quantity: str = "force", case=None) -> bool:
        """Did the engine close ``quantity`` of every part (of one case)?"""
        cases = self.cases if case is None else (self.cases[case],)
        return all(c is None or c.derivation(quantity).closed_form
                   for cs in cases for c in (cs.even, cs.odd))

    def force(self):
        """P(e, a) = P_E(a), Eq. (10*) of the even part (the bounded part; a punch adds P0)."""
        return self._combine(lambda c: c.expr(c.even, "force"))

    def odd_force(self):
        """P_H(a): Eq. (10*) of H."""
        return self._combine(lambda c: c.expr(c.odd, "force"))

    def rotation_force(self):
        """P_2(a): Eq. (10*) of the unit rotation profile s^2/2."""
        return self.rotation.derivation("force").expr

    def _d_odd(self, case):
        PH = case.expr(case.odd, "force")
        return sp.Derivative(PH, S.a) if PH.has(sp.Integral) else sp.diff(PH, S.a)

    def tilt(self):
        """theta(e, a) = (2/(pi E* a)) dP_H/da: the tilt at which the
        pressure on [e - a, e + a] is bounded at both ends."""
        if "tilt" not in self._memo:
            def one(case):
                th = 2 * self._d_odd(case) / (sp.pi * S.E_star * S.a)
                return sp.factor_terms(sp.expand(th)) if not th.has(sp.Integral, sp.Derivative) else th
            self._memo["tilt"] = self._combine(one)
        return self._memo["tilt"]

    def _theta(self, theta):
        return self.tilt() if theta is None else sp.sympify(user_value(theta), strict=True)

    def moment_centre(self, theta=None):
        """M_c = int (x - e) p dx = -(P_H - theta P_2); ``theta`` None: theta(e, a)."""
        return sp.expand(-(self.odd_force() - self._theta(theta) * self.rotation_force()))

    def moment(self, theta=None, punch=0):
        """M = int x p dx = e (P + P0) + M_c."""
        return sp.expand(S.e * (self.force() + punch) + self.moment_centre(theta))

    def edge_factors(self, theta=None, punch=0):
        """(K_-, K_+): p ~ K_-/sqrt(a + s) at the left end, K_+/sqrt(a - s) at the right."""
        k = sp.pi * sp.sqrt(2 * S.a)
        th = self._theta(theta)
        d2 = sp.diff(self.rotation_force(), S.a)

        def one(case, side):
            # the derivative at a fixed tilt (theta(e, a) depends on a)
            dPF = self._d_odd(case) - th * d2
            out = (punch + side * dPF) / k
            return out if out.has(sp.Integral, sp.Derivative) else sp.simplify(out)
        return self._combine(lambda c: one(c, 1)), self._combine(lambda c: one(c, -1))

    def _recombined(self, quantity, theta, case):
        """Eq. (12) or Eqs. (3)/(5) of E at |s| plus the s-derivative of those of F = H - theta s^2/2."""
        s = S.x_real - S.e
        th = self._theta(theta)
        rot = self.rotation.derivation(quantity).expr

        def one(c):
            even = _in_s(c.expr(c.even, quantity), s)
            return even + _d_in_s(c.expr(c.odd, quantity) - th * rot, s)
        return self._combine(one, case)

    def pressure(self, theta=None, punch=0, case=None):
        """p(x) on e - a < x < e + a (x = x_real): p_E + d/ds p_F + P0/(pi sqrt(a^2 - s^2))
        (``case``: the index of one case of the centre, its expression alone)."""
        out = self._recombined("pressure", theta, case)
        if punch != 0:
            out += punch / (sp.pi * sp.sqrt(S.a**2 - (S.x_real - S.e)**2))
        return out

    def gap(self, theta=None, punch=0, case=None):
        """g(x) outside the contact (|x - e| > a): g_E + d/ds g_F - (2 P0/(pi E*)) acosh(|s|/a)."""
        out = self._recombined("gap", theta, case)
        if punch != 0:
            out -= 2 * punch / (sp.pi * S.E_star) * sp.acosh(sp.Abs(S.x_real - S.e) / S.a)
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
    at that e is used (built once per e).  With a kink, each number e picks its case."""

    def __init__(self, core: OffsetContact, values):
        self.core = core
        missing = [v.name for v in core.variables if v.name not in values]
        if missing:
            raise DomainError(f"the asymmetric contact needs values for {', '.join(missing)}")
        self.values = {v: user_value(values[v.name]) for v in core.variables}
        self.E = to_mpf(self.values[S.E_star])
        self._laws: dict = {}
        self._fns: dict = {}
        pv = {k: v for k, v in self.values.items()}
        self._kinks = [None if c.kink is None else sp.N(sp.sympify(c.kink, strict=True).xreplace(pv), 60) for c in core.cases]

    def case(self, e):
        """(case, its parameter value) at the number e: eps = sign (e - b) >= 0, or e itself."""
        for c, b in zip(self.core.cases, self._kinks):
            if b is None:
                return c, e
            ep = c.sign * (e - to_mpf(b))
            if ep > 0 or (ep == 0 and c.sign > 0):
                return c, ep
        raise DomainError(f"e = {e} is in no case of {self.core.name}")

    # -- force laws of the parts at (e, a)
    def _law(self, case, contact, ev):
        pv = self.case(ev)[1]
        key = (id(contact), pv)
        if key not in self._laws:
            vals = {case.par: sp.Float(pv, mpmath.mp.dps + 10), **self.values}
            used = {k: v for k, v in vals.items() if k in contact.variables or k == case.par}
            self._laws[key] = ForceLaw.from_contact(contact, used)
        return self._laws[key]

    def _closed_fn(self, case, contact, quantity, derivative=False):
        key = (id(contact), quantity, derivative)
        if key not in self._fns:
            expr = contact.derivation(quantity).expr
            if derivative:
                expr = sp.diff(expr, S.a if quantity == "force" else S.x)
            expr = expr.xreplace(self.values)
            self._fns[key] = sp.lambdify([case.par, S.a, S.x], expr, "mpmath")
        return self._fns[key]

    def _P(self, part, e, a, derivative=False):
        e, a = mpmath.mpf(e), mpmath.mpf(a)
        case, pv = self.case(e)
        contact = getattr(case, part)
        if contact is None:
            return mpmath.mpf(0)
        if contact.derivation("force").closed_form:
            return _real(self._closed_fn(case, contact, "force", derivative)(pv, a, 0))
        law = self._law(case, contact, e)
        return law.dP(a) if derivative else law.P(a)

    def P(self, e, a):
        """P(e, a) = P_E(a) (the bounded part)."""
        return self._P("even", e, a)

    def P_H(self, e, a):
        return self._P("odd", e, a)

    def dP_H(self, e, a):
        return self._P("odd", e, a, derivative=True)

    def _rot(self, a, derivative=False):
        case = self.core.cases[0]
        return _real(self._closed_fn(case, self.core.rotation, "force", derivative)(0, mpmath.mpf(a), 0))

    def P_2(self, a):
        return self._rot(a)

    def dP_2(self, a):
        return self._rot(a, True)

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
        case = self.case(e)[0]
        pE = self._p(case, case.even, e, a, abs(s))
        dH = self._dp(case, case.odd, e, a, s)
        d2 = self._dp(self.core.cases[0], self.core.rotation, e, a, s)
        return pE + dH - th * d2 + mpmath.mpf(punch) / (mpmath.pi * mpmath.sqrt((a - s) * (a + s)))

    def _dPk(self, case, contact, e, r, k):
        """d^k P/da^k of a part at the half-width r (k = 1, 2): the closed force
        law differentiated, else the engine's quadrature law (dP, and mpmath.diff of it)."""
        pv = self.case(e)[1] if contact is not self.core.rotation else 0
        if contact.derivation("force").closed_form:
            key = (id(contact), "force", k)
            if key not in self._fns:
                expr = sp.diff(contact.derivation("force").expr, S.a, k).xreplace(self.values)
                self._fns[key] = sp.lambdify([case.par, S.a, S.x], expr, "mpmath")
            return _real(self._fns[key](pv, r, 0))
        law = self._law(case, contact, e)
        return law.dP(r) if k == 1 else mpmath.diff(law.dP, r)

    def _p(self, case, contact, e, a, t):
        """Eq. (12) of a part at |s| = t: lambdified where closed, else
        (1/pi) int_0^W P'(r)/r dw, r = sqrt(t^2 + w^2), W = sqrt(a^2 - t^2)
        (Eq. 12 in t = sqrt(x^2 + w^2): a smooth integrand, also at t = 0)."""
        if contact is None:
            return mpmath.mpf(0)
        d = contact.derivation("pressure")
        if d.closed_form:
            pv = self.case(e)[1] if contact is not self.core.rotation else 0
            return _real(self._closed_fn(case, contact, "pressure")(pv, a, t))
        W = mpmath.sqrt((a - t) * (a + t))
        with workdps(mpmath.mp.dps + 10):
            def g(w):
                r = mpmath.sqrt(t**2 + w**2)
                return self._dPk(case, contact, e, r, 1) / r
            return mpmath.quad(g, [0, W]) / mpmath.pi

    def _dp(self, case, contact, e, a, s):
        """d/ds p(|s|) of a part: lambdified where closed, else Eq. (12)
        differentiated under the integral (see :meth:`_p`):
        (1/pi) [int_0^W (P''(r)/r - P'(r)/r^2) (t/r) dw - P'(a) t/(a W)], t = |s|."""
        if contact is None:
            return mpmath.mpf(0)
        d = contact.derivation("pressure")
        sign = 1 if s >= 0 else -1
        t = abs(s)
        if d.closed_form:
            pv = self.case(e)[1] if contact is not self.core.rotation else 0
            return sign * _real(self._closed_fn(case, contact, "pressure", True)(pv, a, t))
        W = mpmath.sqrt((a - t) * (a + t))
        with workdps(mpmath.mp.dps + 10):
            def g(w):
                r = mpmath.sqrt(t**2 + w**2)
                return (self._dPk(case, contact, e, r, 2) / r - self._dPk(case, contact, e, r, 1) / r**2) * t / r
            inner = mpmath.quad(g, [0, W])
            edge = self._dPk(case, contact, e, a, 1) * t / (a * W)
            return sign * (inner - edge) / mpmath.pi


def _real(v):
    return mpmath.mpf(v.real) if isinstance(v, mpmath.mpc) else mpmath.mpf(v)
