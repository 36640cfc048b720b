"""The viscoelastic line contact: a frictionless :class:`~..normal.contact.LineContact`
on a linear viscoelastic half-plane (a :class:`~linecontact_sym.method.material.Material`),
by Popov's superposition in time (see the package docstring for the formulas).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import random

import mpmath
import sympy as sp

from ...core import symbols as S
from ...core.budget import run_with_budget
from ...core.errors import BudgetExceeded, DomainError, LineContactError
from ...core.precision import checked_dps, workdps
from ...core.ranges import check_points, check_tolerance
from ..base import checked_value
from ...method.material import Material
from . import history as H
from .history import MultipleMaximaError

#: CPU seconds for one symbolic integration of a history
HISTORY_BUDGET = 20.0
_s = sp.Dummy("s", positive=True)    # loading time of a punch (integration variable)
_u = sp.Dummy("u", positive=True)    # upper limit of the loading integral
_b = sp.Dummy("b", positive=True)    # punch half-width


def _integrate(f, var, lo, hi, budget):
    """int_lo^hi f d var by SymPy under ``budget`` CPU seconds; the unevaluated
    Integral where SymPy finds nothing (or runs out of time)."""
    try:
        r = run_with_budget(sp.integrate, f, (var, lo, hi), seconds=budget)
    except BudgetExceeded:
        return sp.Integral(f, (var, lo, hi))
    if r.has(sp.Integral):
        return sp.Integral(f, (var, lo, hi))
    return r


def _number(name, value, dps, positive=False):
    """A time, a point or a length as the user gives it: a finite real number
    (text by the whitelisted parser), > 0 where ``positive``; an mpf at dps + 15 digits."""
    v = checked_value(name, value, None)
    if not isinstance(v, (int, float, sp.Basic)):
        raise DomainError(f"{name} must be one number, got {value!r}")
    v = sp.sympify(v, strict=True) if isinstance(v, (int, float)) else v       # a plain number (never text here)
    if positive and not v > 0:
        raise DomainError(f"{name} must be positive, got {value}")
    return mpmath.mpf(sp.N(v, dps + 15))


def _bound(cond):
    """c of a Piecewise condition t < c / t <= c (None for True)."""
    if cond is sp.true:
        return None
    if isinstance(cond, (sp.StrictLessThan, sp.LessThan)) and cond.lhs == S.t:
        return cond.rhs
    if isinstance(cond, (sp.StrictGreaterThan, sp.GreaterThan)) and cond.rhs == S.t:
        return cond.lhs
    raise DomainError(f"a history condition must read t < c or t <= c (in order), got {cond}; "
                      "evaluate_at takes any history at numbers")


@dataclass
class Phases:
    """A history split into its loading piece (one expression on [0, t_m])
    and the receding pieces after the maximum ((expression, condition) pairs)."""

    loading: sp.Expr
    t_m: object
    receding: list = field(default_factory=list)
    loading_cond: object = sp.true


def phases(history) -> Phases:
    """Split a(t) (SymPy, Piecewise for load-then-unload) at its single maximum,
    deciding the sign of a'(t) piece by piece from SymPy's assumptions."""
    h = H.history_expr(history, "half-width")
    pieces = list(h.args) if isinstance(h, sp.Piecewise) else [(h, sp.true)]
    signs = []
    for e, cond in pieces:
        d = sp.simplify(sp.diff(e, S.t))
        if d.is_nonnegative:
            signs.append(1 if not d.is_zero else 0)
        elif d.is_nonpositive:
            signs.append(-1)
        else:
            raise DomainError(f"cannot decide the sign of a'(t) = {d} on the piece {e} of the history: "
                              "give it in monotone pieces, or numbers to evaluate_at")
    if signs[0] <= 0:
        raise DomainError("the closed form needs a history whose first piece grows (one loading piece); "
                          "evaluate_at gives numbers for any history")
    if any(sg > 0 for sg in signs[1:]):
        raise MultipleMaximaError("the half-width grows again after its first piece: more than one loading piece "
                                  "(or maximum) is outside the closed form (Ting: one loading phase, one receding "
                                  "phase); evaluate_at gives numbers for a history that grows in several pieces")
    t_m = _bound(pieces[0][1]) if len(pieces) > 1 else None
    # the pieces after the maximum (a plateau included) load no new punch: Ting's rule
    return Phases(pieces[0][0], t_m, list(pieces[1:]), pieces[0][1])


class ViscoelasticLineContact:
    """A line contact on a linear viscoelastic half-plane: Lee-Radok while the
    contact grows, Ting when it recedes, on Popov's superposition of flat
    punches (see :mod:`linecontact_sym.contacts.viscoelastic`).

    >>> import sympy as sp, linecontact_sym as lcs
    >>> v = lcs.parabola(verify=False).viscoelastic(lcs.maxwell(E0=2, tau=1))
    >>> v.force_history(sp.Rational(1, 10) * lcs.t)          # a(t) = t/10
    (pi*t - pi)/(100*R) + pi*exp(-t)/(100*R)
    """

    def __init__(self, contact, material):
        from ..base import ContactOn
        if isinstance(contact, ContactOn):
            raise DomainError(f"a viscoelastic material is defined on the frictionless contact, not on a "
                              f"{type(contact).__name__}: adhesion (JKR, Maugis-Dugdale) is outside Lee-Radok's "
                              "correspondence (the cohesive zone and the energy release rate of a growing crack "
                              "are rate dependent; Lee-Radok and Ting hold only for a frictionless, adhesionless contact)")
        if not isinstance(material, Material):
            raise DomainError(f"expected a Material (lcs.maxwell(...), lcs.kelvin_voigt(...), lcs.standard_linear_solid(...), "
                              f"lcs.prony(...), lcs.Material(expr)), got {type(material).__name__}")
        self.contact, self.material = contact, material
        d = contact.derivation("force")
        Pi = sp.cancel(d.expr / S.E_star) if d.closed_form else d.expr.xreplace({S.E_star: 1})
        if d.closed_form and Pi.has(S.E_star):
            raise DomainError(f"the force law {d.expr} is not linear in E*: no viscoelastic superposition")
        self.Pi = Pi
        self._cache = {}

    def __repr__(self):
        return f"ViscoelasticLineContact({self.contact!r}, {self.material!r})"

    @property
    def variables(self):
        return tuple(sorted((set(self.contact.variables) - {S.E_star}) | set(self.material.parameters),
                            key=lambda s: s.name))

    # ------------------------------------------------------------ closed forms
    def _loading_integral(self, a1, budget, closed: bool = True):
        """int_0^u E_reg(t - s) Pi'(a1(s)) a1'(s) ds as a function of the upper limit u,
        term by term of E_reg as given (one budget for all the terms); ``closed=False``:
        the unevaluated integrals."""
        key = ("load", a1, closed)
        if key not in self._cache:
            m = self.material
            a1s = a1.subs(S.t, _s)
            dPi = sp.diff(self.Pi, S.a).subs(S.a, a1s)
            integrand = sp.expand_power_base(sp.powsimp(dPi * sp.diff(a1s, _s)))
            terms = sp.Add.make_args(m.relaxation)
            out = []
            for tm in terms:
                f = sp.powsimp(tm.subs(S.t, S.t - _s) * integrand)
                out.append(_integrate(f, _s, 0, _u, budget / len(terms)) if closed else sp.Integral(f, (_s, 0, _u)))
            self._cache[key] = sp.Add(*out)
        return self._cache[key]

    def _checked(self, F, a_t, build):
        """F if it agrees with the quadrature of the superposition (:meth:`evaluate_at`)
        at one point of each phase, with the parameters drawn in [1/2, 1]; else the
        unevaluated form ``build()`` (a closed form SymPy got wrong is never returned)."""
        if not F.has(sp.Integral) and not F.has(sp.nan, sp.zoo):
            syms = sorted(F.free_symbols - {S.t}, key=lambda s: s.name)
            rng = random.Random(41)
            vals = {s_: sp.Rational(rng.randint(6, 12), 12) for s_ in syms}
            ph = phases(a_t)
            t_m = ph.t_m.xreplace(vals) if ph.t_m is not None else sp.Integer(1)
            for tv in (t_m / 2, t_m * sp.Rational(5, 4)) if ph.t_m is not None else (t_m / 2,):
                try:
                    ref = self.evaluate_at("force", tv, a_t.xreplace(vals), dps=15,
                                           **{k.name: v for k, v in vals.items()})
                except (LineContactError, ValueError, ZeroDivisionError):
                    continue                    # outside a domain at these numbers: not checked here
                got = sp.N(F.xreplace({**vals, S.t: tv}), 20)
                if not got.is_number or not got.is_finite or abs(complex(got) - complex(ref)) > 1e-9 * abs(ref) + 1e-300:
                    return build()
        return F

    def _entry_time(self, a1, level, t_m):
        """s with a1(s) = level on the loading piece (SymPy solve; the root
        that gives t_m at the top)."""
        sols = sp.solve(sp.Eq(a1.subs(S.t, _s), level), _s)
        if not sols:
            raise DomainError(f"SymPy cannot invert the loading history a(t) = {a1}; evaluate_at gives numbers")
        if len(sols) > 1 and t_m is not None:
            top = a1.subs(S.t, t_m)
            ok = [so for so in sols if sp.simplify(so.subs(level, top) - t_m) == 0] if level.is_Symbol else []
            sols = ok or sols
        return sols[0]

    def force_history(self, a_t, budget: float = HISTORY_BUDGET):
        """P(t) per unit length for the half-width history ``a_t`` (SymPy in
        ``lcs.t``; a Piecewise t < t1 / t < t2 / ... for load-then-unload):

            P(t) = E(t) Pi(a(0+)) + int_0^{s1} E(t - s) d Pi(a(s)) [+ eta dPi(a(t))/dt while loading],

        s1 = t while a grows (Lee-Radok), s1 the loading time with
        a(s1) = a(t) after the maximum (Ting).  Closed where SymPy integrates,
        else an unevaluated Integral (numbers: :meth:`evaluate_at`)."""
        from ...method import store
        key = store.make_key("viscoelastic force history", self.Pi, self.material.relaxation, self.material.impulse,
                             H.history_expr(a_t, "half-width"))
        rec = store.get(key)
        if rec is not None and "expr" in rec:       # a checked closed form of an earlier process
            return rec["expr"]
        F = self._force_history(a_t, budget, True)
        F = self._checked(F, H.history_expr(a_t, "half-width"), lambda: self._force_history(a_t, budget, False))
        if not F.has(sp.Integral):                  # an unevaluated form may be a loaded machine's timeout: not kept
            try:
                store.put(key, {"expr": F})
            except TypeError:
                pass
        return F

    def _force_history(self, a_t, budget, closed):
        ph = phases(a_t)
        m, a1 = self.material, ph.loading
        a0 = sp.limit(a1, S.t, 0, "+")
        I = self._loading_integral(a1, budget, closed)
        step = m.relaxation * self.Pi.subs(S.a, a0) if a0 != 0 else sp.S.Zero
        load = step + I.subs(_u, S.t)
        if m.impulse != 0:
            load += m.impulse * sp.diff(self.Pi, S.a).subs(S.a, a1) * sp.diff(a1, S.t)
        if ph.t_m is None:
            return load
        out = [(load, S.t <= ph.t_m)]
        lvl = sp.Dummy("level", positive=True)
        s_of = self._entry_time(a1, lvl, ph.t_m)
        for e, cond in ph.receding:
            rec = step + I.subs(_u, s_of.subs(lvl, e))
            if a0 != 0:
                rec = sp.Piecewise((m.relaxation * self.Pi.subs(S.a, e), e <= a0), (rec, True))
            out.append((rec, cond))
        return sp.Piecewise(*out)

    def pressure_history(self, a_t, budget: float = HISTORY_BUDGET / 10):
        """p(x, t) for |x| < a(t) (0 beyond): the punches b in (|x|, a(t)) each
        with E*(t - t_b),  p = (1/pi) int_|x|^a(t) Pi'(b) E(t - t_b)/sqrt(b^2 - x^2) db
        [+ eta Pi'(a) a'(t)/(pi sqrt(a^2 - x^2)) while loading]; t_b the entry time of
        the punch b (Eq. 12 with each punch relaxed)."""
        ph = phases(a_t)
        m, a1 = self.material, ph.loading
        a0 = sp.limit(a1, S.t, 0, "+")
        tb = self._entry_time(a1, _b, ph.t_m)
        if a0 != 0:
            tb = sp.Piecewise((0, _b <= a0), (tb, True))
        integrand = sp.diff(self.Pi, S.a).subs(S.a, _b) * m.relaxation.subs(S.t, S.t - tb) / sp.sqrt(_b**2 - S.x**2)

        body = _integrate(integrand, _b, S.x, _u, budget) / sp.pi      # integrated once, the upper limit u

        def p_at(top, loading):
            v = body.subs(_u, top)
            if loading and m.impulse != 0:
                v += m.impulse * sp.diff(self.Pi, S.a).subs(S.a, top) * sp.diff(top, S.t) / (sp.pi * sp.sqrt(top**2 - S.x**2))
            return sp.Piecewise((v, S.x < top), (0, True))      # no pressure outside the contact
        if ph.t_m is None:
            return p_at(a1, True)
        return sp.Piecewise((p_at(a1, True), S.t <= ph.t_m), *[(p_at(e, False), c) for e, c in ph.receding])

    def creep_level(self, P_t, budget: float = HISTORY_BUDGET):
        """X(t) = int_0^t J*(t - u) dP(u) (with the jump P(0+) J*(t)): the elastic
        'load at E* = 1' whose half-width is a(t) while the contact grows."""
        P_t = H.history_expr(P_t, "load")
        key = ("creep", P_t)
        if key not in self._cache:
            J = self.material.creep()
            P0 = H.start_value(P_t)
            X = P0 * J if P0 != 0 else sp.S.Zero
            dP = sp.diff(P_t, S.t)
            if dP != 0:
                X += _integrate(sp.expand(J.subs(S.t, S.t - _s)) * dP.subs(S.t, _s), _s, 0, S.t, budget)
            self._cache[key] = X
        return self._cache[key]

    def half_width_history(self, P_t, budget: float = HISTORY_BUDGET):
        """a(t) under the load history ``P_t`` while the contact grows (Lee-Radok:
        Pi(a(t)) = X(t), :meth:`creep_level`): the engine's elastic a(P) at
        E* = 1 and P = X(t).  After the maximum of X the contact recedes by
        Ting's rule, which has no closed form: numbers from :meth:`half_width_at`."""
        h = H.history_expr(P_t, "load")
        for e, _ in (h.args if isinstance(h, sp.Piecewise) else [(h, sp.true)]):
            d = sp.simplify(sp.diff(e, S.t))
            if not d.is_nonnegative:
                raise DomainError(f"the load {h} may decrease (dP/dt = {d} on a piece): then the contact recedes "
                                  "by Ting's rule, which has no closed form; half_width_at gives numbers "
                                  "(a closed a(t) is built for a load that never decreases: step, ramp, hold)")
        X = self.creep_level(P_t, budget)
        aP = self.contact.half_width(S.P).expr
        return aP.xreplace({S.P: X, S.E_star: sp.Integer(1)})

    # ------------------------------------------------------------ numbers
    def _numbers(self, values):
        key = ("num", tuple(sorted((k, str(v)) for k, v in values.items())))
        if key not in self._cache:
            self._cache[key] = H.Numbers(self.contact, self.material, values)
        return self._cache[key]

    def evaluate_at(self, quantity: str, t, history, x=None, dps: int = 30, **values):
        """The value at time ``t`` (mpf, ``dps`` digits) of ``"force"`` or
        ``"pressure"`` (at ``x``) for a half-width history, or ``"half_width"``
        for a load history (creep; Ting after the maximum), at the parameter
        ``values``: tanh-sinh quadrature of the superposition at dps + 10
        digits (positive integrands: no cancellation).

        Not certified: the integrands hold the entry time t_b (an inverse of
        a(t), found by root finding at numbers), the creep level and Ting's
        loading time (roots of quadratures), which Arb's integrator
        (:func:`~linecontact_sym.numeric.reference.integrate`, an integrand
        compiled from a SymPy expression) cannot enclose.  Where the
        history's form is a SymPy expression (closed, or an unevaluated
        Integral with t_b solved symbolically), :meth:`evaluate` gives an Arb
        enclosure: ``certified=True`` for a closed form, and beyond float64
        for an unevaluated integral (one enclosure of it)."""
        if quantity not in ("force", "pressure", "half_width"):
            raise DomainError(f"unknown quantity {quantity!r}: one of force, pressure, half_width")
        dps = checked_dps(dps)
        with workdps(dps + 10):
            tv = _number("t", t, dps)
            if tv < 0:
                raise DomainError(f"the time must be >= 0, got t = {t}")
            num = self._numbers(values)
            if quantity == "half_width":
                X = None
                try:
                    X = self.creep_level(history)
                except LineContactError:
                    pass
                hist = H.LoadHistory(num, history, X, values, tv)
                v = hist.half_width(tv)
            else:
                hist = H.HalfWidthHistory(num, history, values, tv)
                if quantity == "force":
                    v = hist.force(tv)
                else:
                    if x is None:
                        raise DomainError("the pressure needs x")
                    v = hist.pressure(_number("x", x, dps), tv)
        with workdps(dps):
            return +v

    def history_quantities(self, a_t):
        """The force and pressure histories of the half-width history ``a_t`` as
        quantities of the package's ``evaluate`` (see :mod:`.accuracy`)."""
        from .accuracy import HistoryQuantities
        key = ("hq", H.history_expr(a_t, "half-width"))
        if key not in self._cache:
            self._cache[key] = HistoryQuantities(self, a_t)
        return self._cache[key]

    def to_numeric(self, quantity: str, history, backend: str = "numpy", dps: int = 30, **params):
        """A callable ``fn(t=..., [x=...,] **parameters)`` of ``"force"`` (P(t))
        or ``"pressure"`` (p(x, t)) for the half-width history ``history``:
        ``backend='numpy'`` vectorised float64 of the stable form (the Maxwell
        terms' exp tails as ``exp_tail``: accurate for t << tau, t >> tau and
        tau from 1e-6 to 1e6 at t/tau from 1e-12 to 1e12, see
        ``benchmarks/extremes.py``), ``'mpmath'`` at ``dps`` digits; keywords
        given here are fixed once.  No domain check (NaN outside it)."""
        from ...numeric.functions import make_callable
        from .accuracy import history_quantity
        q = history_quantity(quantity)
        return make_callable(self.history_quantities(history).derivation(q), backend, dps, params)

    def evaluate(self, quantity: str, history, rtol: float | None = None, certified: bool = False,
                 dps: int | None = None, **values):
        """``"force"`` (P(t)) or ``"pressure"`` (p(x, t)) of the half-width
        history ``history``, or ``"half_width"`` (a(t)) of the load history
        ``history`` (creep, a load that never decreases: the closed form of
        :meth:`half_width_history`), at ``values`` (t, x, the parameters) to the
        tolerance ``rtol`` by the cheapest path that meets it: the stable
        float64 export of the closed form when its error estimate does, mpmath
        at the digits rtol asks otherwise, an Arb ball with ``certified=True``
        (an :class:`~linecontact_sym.numeric.evaluate.Evaluation`; see
        :func:`~linecontact_sym.numeric.evaluate.evaluate`).

        >>> import sympy as sp, linecontact_sym as lcs
        >>> v = lcs.parabola(verify=False).viscoelastic(lcs.maxwell(E0=2, tau=sp.Symbol("tau", positive=True)))
        >>> r = v.evaluate("force", lcs.t / 10, t=1e-9, tau=1.0, R=1.0, rtol=1e-12)
        >>> r.path, round(r.value / (2 * 3.141592653589793e-20 / 4), 6)   # E0 pi a(t)^2/(4 R) at t << tau, a = t/10
        ('float64', 1.0)
        """
        from ...numeric.evaluate import evaluate
        from .accuracy import history_quantity
        q = history_quantity(quantity)
        return evaluate(self.history_quantities(history), q, rtol=rtol, certified=certified, dps=dps, **values)

    def half_width_at(self, t, load, dps: int = 30, **values):
        """a(t) under the load history ``load`` (creep), see :meth:`evaluate_at`."""
        return self.evaluate_at("half_width", t, load, dps=dps, **values)

    def model_choice(self, history, rtol, t_end, points: int = 12, dps: int = 20, **values) -> "ModelChoice":
        """Which model the half-width ``history`` needs on (0, t_end] at ``rtol``:
        the elastic law with E*(0) (fast loading), with E*(oo) (slow loading), or
        the viscoelastic one; the error of each is max |P_model - P| / max |P| over
        ``points`` times (the viscoelastic P by :meth:`evaluate_at`)."""
        rtol = check_tolerance(rtol)
        points, dps = check_points(points, 1, "model_choice"), checked_dps(dps)
        num = self._numbers(values)
        with workdps(dps):
            T = _number("t_end", t_end, dps, positive=True)
            ts = [T * k / points for k in range(1, points + 1)]
            hist = H.HalfWidthHistory(num, history, values, T)
            P = [hist.force(tv) for tv in ts]
            Pe = [num.Pi(hist.a(tv)) for tv in ts]
            scale = max(abs(p) for p in P)
            errs = {}
            for name, E in (("elastic E*(0)", num.m.E0), ("elastic E*(oo)", num.m.E_inf)):
                errs[name] = (mpmath.inf if E == mpmath.inf else max(abs(E * pe - p) for pe, p in zip(Pe, P)) / scale)
            errs["viscoelastic"] = mpmath.mpf(0)
            choice = next(k for k in ("elastic E*(0)", "elastic E*(oo)", "viscoelastic") if errs[k] <= rtol)
            return ModelChoice(choice, {k: float(v) for k, v in errs.items()}, [float(tv) for tv in ts])

    def history_data(self, history, t_end, points: int = 101, dps: int = 15, **values) -> dict:
        """Arrays over (0, t_end]: t, a(t), P(t), and the elastic limits
        E*(0) Pi(a(t)), E*(oo) Pi(a(t)) (float64; the numbers by :meth:`evaluate_at`'s quadrature)."""
        import numpy as np
        points, dps = check_points(points, 1, "history_data"), checked_dps(dps)
        num = self._numbers(values)
        with workdps(dps):
            T = _number("t_end", t_end, dps, positive=True)
            hist = H.HalfWidthHistory(num, history, values, T)
            ts = [T * k / points for k in range(1, points + 1)]
            a = [hist.a(tv) for tv in ts]
            Pe = [num.Pi(av) for av in a]
            E0, Ei = num.m.E0, num.m.E_inf
            return {"t": np.array([float(v) for v in ts]), "a": np.array([float(v) for v in a]),
                    "P": np.array([float(hist.force(tv)) for tv in ts]),
                    "P_E0": np.array([float(E0 * p) if E0 != mpmath.inf else np.inf for p in Pe]),
                    "P_Einf": np.array([float(Ei * p) for p in Pe])}

    def plot(self, history, t_end, what: str = "history", path=None, points: int = 101, **values):
        """``what='history'``: P(t) with its elastic limits over a(t); ``'hysteresis'``:
        the loop P(a) of a cycle (see :mod:`linecontact_sym.views.viscoelastic_plots`)."""
        from ...views.viscoelastic_plots import history_figure, hysteresis_figure
        data = self.history_data(history, t_end, points, **values)
        if what == "history":
            return history_figure(data, path, title=self.material.name)
        if what == "hysteresis":
            return hysteresis_figure(data, path, title=self.material.name)
        raise DomainError(f"unknown plot {what!r}: 'history' or 'hysteresis'")

    def _creep_integral(self, m, h, n):
        """(J1, J2): J1(x) = int_0^x J*(u) du and J2(x) = int_0^x J1 at the numbers of ``m``,
        as functions (x, k) with k the grid index when x = k h (else None), 0 for x <= 0:
        SymPy's antiderivatives of the creep function where it finds them (checked against
        quadrature at x = n h), else quadrature step by step on the grid (mpf at the working precision)."""
        m.J(h)                                  # the creep function derived (m.creep_expr)
        key = ("J12", m.creep_expr)
        if key not in self._cache:
            F = _creep_integral_expr(m.creep_expr, HISTORY_BUDGET / 8)
            G = _creep_integral_expr(F, HISTORY_BUDGET / 8) if F is not None else None
            self._cache[key] = None if G is None else (sp.lambdify(S.t, F, "mpmath"), sp.lambdify(S.t, G, "mpmath"))
        FG = self._cache[key]
        X = h * n
        tol = mpmath.mpf(10)**(-mpmath.mp.dps // 2)
        if FG is not None:
            F, G = FG
            r1 = mpmath.quad(m.J, [0, X])
            r2 = mpmath.quad(lambda u: (X - u) * m.J(u), [0, X])
            if abs(F(X) - r1) <= abs(r1) * tol and abs(G(X) - r2) <= abs(r2) * tol:
                return (lambda x, k: mpmath.re(F(x)) if x > 0 else mpmath.mpf(0),
                        lambda x, k: mpmath.re(G(x)) if x > 0 else mpmath.mpf(0))
        c1, c2 = [mpmath.mpf(0)], [mpmath.mpf(0)]
        for k in range(1, n + 1):        # J2(kh) = J2((k-1)h) + h J1((k-1)h) + int (kh - u) J(u) du over the step
            c2.append(c2[-1] + h * c1[-1] + mpmath.quad(lambda u: (h * k - u) * m.J(u), [h * (k - 1), h * k]))
            c1.append(c1[-1] + mpmath.quad(m.J, [h * (k - 1), h * k]))

        def split(x):
            k0 = min(int(mpmath.floor(x / h)), n)
            return k0, x - h * k0

        def J1(x, k):
            if x <= 0:
                return mpmath.mpf(0)
            if k is not None:
                return c1[k]
            k0, r = split(x)
            return c1[k0] + (mpmath.quad(m.J, [h * k0, x]) if r > 0 else 0)

        def J2(x, k):
            if x <= 0:
                return mpmath.mpf(0)
            if k is not None:
                return c2[k]
            k0, r = split(x)
            return c2[k0] + r * c1[k0] + (mpmath.quad(lambda u: (x - u) * m.J(u), [h * k0, x]) if r > 0 else 0)
        return J1, J2

    def dissipated_work(self, a_t, t_end, L, points: int = 200, **values) -> "DissipatedWork":
        """The work per unit length done by the indenter over (0, t_end],
        W = int P dd, the depth d(t) measured from a point at the distance L
        (2-D: the depth of a half-plane is defined only with a reference length,
        and so is the dissipation, which grows like ln L).

        d = J* o dD with the 'elastic depth' D(t) = (2/pi) sum over the punches b
        in contact at t of their force E*(t - t_b) Pi'(b) db times ln(2L/b) (the
        depth of a flat punch of half-width b under a unit force, E* = 1); while
        the contact grows d = (2/pi) int_0^a(t) Pi'(b) ln(2L/b) db, the elastic
        depth (Lee-Radok), after the maximum it lags (Ting).  A Kelvin-Voigt
        material (E*(t) = E + eta delta(t)) is the same formula with the Dirac
        term taken at s = t: while the contact grows the punch entering at t adds
        eta Y'(t) to P and eta Y'(t) ln(2L/a(t)) to D (Y = Pi(a(t))); both drop at
        the maximum, where D jumps and d (J*(0) = 0) does not.

        Numbers: P and D by quadrature at each knot (a uniform grid of ``points``
        intervals on (0, t_end], plus the breakpoints of the history and its
        maximum, both sides of them where they jump); between knots D and P are
        linear and everything else exact: d = J* o dD with J* integrated once
        (J1) and int P dd with it integrated twice (J2), SymPy's antiderivatives
        of J* or quadrature, so a creep time far below the step (Kelvin-Voigt
        with a small eta) costs no accuracy: a second-order rule.  It runs
        on ``points`` and on 2 ``points`` intervals (nested knots): the result is
        the finer value with ``error`` = |W(2 points) - W(points)|, about three
        times its true error for a second-order rule (a float: old code keeps
        working; see :class:`DissipatedWork`)."""
        import numpy as np
        points = check_points(points, 2, "the dissipated work")
        num = self._numbers(values)
        with workdps(20):
            T = _number("t_end", t_end, 20, positive=True)
            Lm = _number("the reference length L", L, 20, positive=True)
            hist = H.HalfWidthHistory(num, a_t, values, T)
            m = num.m
            jumps = m.eta != 0          # the Dirac term: P and D jump where a'(t) does and at the maximum
            if jumps and hist.a0 > 0:
                raise DomainError(f"the half-width history starts with a step a(0+) = {mpmath.nstr(hist.a0, 8)}: on a "
                                  "Kelvin-Voigt material the dashpot takes an infinite force at the step and the depth "
                                  "cannot follow it, so the work is undefined; give the rise as a ramp")

            def log_w(b):
                return mpmath.log(2 * Lm / b)
            n2 = 2 * points
            h = T / n2
            cuts = sorted({c for c in list(hist.breaks) + ([hist.t_m] if hist.t_m is not None else []) if 0 < c < T})
            # knots: (time, uniform index or None, side); the coarse set: even uniform indices and every cut
            knots = [(h * k, k, 0) for k in range(n2 + 1)]
            for c in cuts:
                if not jumps and abs(c / h - mpmath.nint(c / h)) < mpmath.mpf(10)**-12:
                    continue                      # already a knot of the grid
                knots += [(c, None, -1), (c, None, 1)] if jumps else [(c, None, 0)]
            knots.sort(key=lambda kn: (kn[0], kn[2]))
            eps = T * mpmath.mpf(10)**-12
            vals = []
            for tv, k, side in knots:
                te = tv + side * eps              # a side of a jump: just before / after it
                vals.append(hist.force_and_depth_level(te, log_w, loading=hist.loading(te)))
            J1, J2 = self._creep_integral(m, h, n2)
            Jc = {}

            def J(i, j):
                """J*(t_i - t_j)."""
                if (i, j) not in Jc:
                    Jc[(i, j)] = m.J(knots[i][0] - knots[j][0])
                return Jc[(i, j)]

            def Jk(f, i, j):
                """J1 or J2 (``f``) at t_i - t_j (mpf, remembered: index differences on the grid)."""
                ki, kj = knots[i][1], knots[j][1]
                key = (f, ki - kj) if None not in (ki, kj) else (f, i, j)
                if key not in Jc:
                    Jc[key] = f(knots[i][0] - knots[j][0], None if len(key) == 3 else ki - kj)
                return Jc[key]

            def weight(i, j0, j1):
                """(1/(t_j1 - t_j0)) int_{t_j0}^{t_j1} J*(t_i - s) ds (D linear on the step, J* integrated
                exactly: a creep time far below the step costs no accuracy); J*(t_i - t_j1) for a jump."""
                length = knots[j1][0] - knots[j0][0]
                if length == 0:
                    return float(J(i, j1))
                return float((Jk(J1, i, j0) - Jk(J1, i, j1)) / length)

            def mean_depth(a, b, sel, D):
                """(1/(t_b - t_a)) int_{t_a}^{t_b} d(t) dt, d = J* o dD with D linear between the knots
                ``sel`` (up to b): the step responses integrated once more (J2), no quadrature."""
                hab = knots[b][0] - knots[a][0]
                out = (Jk(J1, b, sel[0]) - Jk(J1, a, sel[0])) * D[0]
                for k in range(1, len(sel)):
                    lo, hi = sel[k - 1], sel[k]
                    if knots[hi][0] > knots[b][0]:
                        break
                    dD = D[k] - D[k - 1]
                    if dD == 0:
                        continue
                    hj = knots[hi][0] - knots[lo][0]
                    if hj == 0:
                        out += dD * (Jk(J1, b, hi) - Jk(J1, a, hi))
                    else:
                        out += dD / hj * (Jk(J2, b, lo) - Jk(J2, a, lo) - Jk(J2, b, hi) + Jk(J2, a, hi))
                return out / hab
            Pv = [p for p, _ in vals]
            Dv = [d for _, d in vals]

            def work(sel):
                """W on the knots ``sel`` (indices, in time order): d_n = J*(t_n) D(0+) + sum over the
                steps of dD times the mean of J*(t_n - s) over the step (D linear on each step); on each
                step P linear, int P dd = P_k d_k - P_{k-1} d_{k-1} - (P_k - P_{k-1}) mean(d) (exact for a
                linear P, whatever d does inside the step: a creep time far below the step)."""
                D = np.array([float(Dv[i]) for i in sel])
                d = np.zeros(len(sel))
                dD = np.diff(D)
                for n, i in enumerate(sel):
                    w = [weight(i, sel[k - 1], sel[k]) for k in range(1, n + 1)]
                    d[n] = float(J(i, sel[0])) * D[0] + np.dot(w, dD[:n])
                Dm = [Dv[i] for i in sel]
                P = [float(Pv[i]) for i in sel]
                W = 0.0
                for k in range(1, len(sel)):
                    dP = P[k] - P[k - 1]
                    if knots[sel[k]][0] == knots[sel[k - 1]][0] or dP == 0:
                        W += 0.5 * (P[k] + P[k - 1]) * (d[k] - d[k - 1])
                    else:
                        W += P[k] * d[k] - P[k - 1] * d[k - 1] - dP * float(mean_depth(sel[k - 1], sel[k], sel, Dm))
                return W
            fine = list(range(len(knots)))
            coarse = [i for i, kn in enumerate(knots) if kn[1] is None or kn[1] % 2 == 0]
            Wf, Wc = work(fine), work(coarse)
        return DissipatedWork(Wf, abs(Wf - Wc), n2)


def _creep_integral_expr(J, budget):
    """int_0^t J(u) du as a SymPy expression in t (None where SymPy finds none)."""
    if J.has(sp.InverseLaplaceTransform, sp.LaplaceTransform):
        return None
    r = _integrate(J.subs(S.t, _s), _s, 0, S.t, budget)
    return None if r.has(sp.Integral) else r


class DissipatedWork(float):
    """The dissipated work of :meth:`ViscoelasticLineContact.dissipated_work`: a
    float (the value on the finer grid) with ``error``, the difference to the
    value on the grid of half as many intervals (an estimate: about three times
    the true error for the second-order rule once it converges), and
    ``points``, the intervals of the finer grid."""

    def __new__(cls, value, error, points):
        obj = super().__new__(cls, value)
        obj.error, obj.points = float(error), int(points)
        return obj

    @property
    def value(self) -> float:
        return float(self)

    def __repr__(self):
        return f"DissipatedWork({float(self)!r}, error={self.error:.2g}, points={self.points})"

    def __reduce__(self):
        return (DissipatedWork, (float(self), self.error, self.points))


@dataclass
class ModelChoice:
    """``model``: the simplest that meets the tolerance ('elastic E*(0)',
    'elastic E*(oo)' or 'viscoelastic'); ``errors``: the relative error of each."""

    model: str
    errors: dict
    times: list = field(repr=False, default_factory=list)


__all__ = ["ViscoelasticLineContact", "ModelChoice", "DissipatedWork", "Phases", "phases", "HISTORY_BUDGET", "MultipleMaximaError"]
