"""The load histories of the tangential line contact (:mod:`.tangential`) at
numbers: monotonic loading, Mindlin-Deresiewicz unloading and reloading, full
fretting cycles, the onset of gross sliding, and the boundary-element solution
of the same contact; float64 evaluation of the superposition where the normal
solution has no closed form."""
from __future__ import annotations

from dataclasses import dataclass, field

import mpmath
import numpy as np
import sympy as sp

from ...core import symbols as S
from ...core.conversion import to_mpf
from ...core.errors import DomainError, GrossSlidingError, LineContactError
from ...core.ranges import check_sign, check_values
from ...core.roots import root_in_log
from ...numeric.functions import make_callable
from ...parsing import user_value
from . import reference as ref
from ..normal.equilibria import half_width_at
from .states import force_law_at, friction_at
from ...core.precision import workdps

#: |Q| within this relative distance of mu P is the onset of gross sliding (float64 inputs)
ONSET_RTOL = mpmath.mpf("1e-14")


class FloatNormal:
    """float64 normal solution of the profile at numbers, from the force law
    (for the states of a load history where the pressure or the gap has no
    closed form): Eq. (12) and the outside gap by Gauss-Legendre quadrature,
    split at the profile's breakpoints (about 10 digits)."""

    def __init__(self, t, fixed: dict):
        self.E = float(fixed["E_star"])
        self.P = _float_fn(t.contact, "force", fixed)
        self.dP = _float_fn(t.contact, "stiffness", fixed)
        params = {s: sp.Float(float(fixed[s.name]), 20) for s in t.contact.variables if s.name in fixed}
        self.f = sp.lambdify(S.x, t.profile.expr.xreplace(params), "numpy")
        self.breaks = [float(sp.N(bp.xreplace(params))) for bp in t.profile.breakpoints]

    def _pieces(self, lo, hi):
        cuts = [lo] + [b for b in self.breaks if lo < b < hi] + [hi]
        return zip(cuts[:-1], cuts[1:])

    def pressure(self, x, A):
        """p(x; A) for |x| < A (0 beyond), Eq. (12) after t = sqrt(x^2 + w^2)."""
        out = np.zeros(np.shape(x))
        for i, xv in np.ndenumerate(np.abs(np.asarray(x, float))):
            if xv >= A:
                continue
            total = 0.0
            for t0, t1 in self._pieces(xv, A):
                w0, w1 = np.sqrt(t0**2 - xv**2), np.sqrt(t1**2 - xv**2)
                total += float(ref.gauss_root_end(lambda w: self.dP(np.sqrt(xv**2 + w**2)) / np.sqrt(xv**2 + w**2),
                                          w0, w1, 48))
            out[i] = total / np.pi
        return out

    def gap(self, x, A):
        """g(x; A) = f(x) - (2/(pi E*)) int_0^A acosh(x/s) P'(s) ds for |x| >= A (0 inside)."""
        out = np.zeros(np.shape(x))
        for i, xv in np.ndenumerate(np.abs(np.asarray(x, float))):
            if xv <= A:
                continue
            total = sum(float(ref.gauss_root_end(lambda sv: np.arccosh(xv / sv) * self.dP(sv), s0, s1, 48))
                        for s0, s1 in self._pieces(0.0, A))
            out[i] = float(self.f(xv)) - 2 * total / (np.pi * self.E)
        return out

    def integral(self, lo, hi, power):
        """int_lo^hi P(t)**power / t dt."""
        return sum(float(ref.gauss_root_end(lambda tv: self.P(tv)**power / tv, t0, t1, 48)) for t0, t1 in self._pieces(lo, hi))

    def energy(self, a, c, mu):
        """W(a, c) from the force law (see :mod:`.tangential`)."""
        Pa, Pc = float(self.P(a)), float(self.P(c))
        W = (Pa + Pc) * self.integral(c, a, 1) - self.integral(c, a, 2) - Pa * Pc * np.log(a / c)
        return 8 * mu**2 / (np.pi * self.E) * W

    def displacement(self, a, c, mu):
        """delta(a, c) with the reference length a."""
        Pa, Pc = float(self.P(a)), float(self.P(c))
        I1 = self.integral(c, a, 1) if c > 0 else self.integral(1e-300, a, 1)
        Lc = np.log(2 * a / c) if c > 0 else 0.0
        return 2 * mu / (np.pi * self.E) * (Pa * np.log(2) - Pc * Lc + I1)


def _float_fn(contact, name, fixed):
    """A float64 callable of the half-width for the normal ``name`` ('force',
    'stiffness') at the parameter values: the package's numeric export in
    its stable form (elliptic integrals as Carlson forms; a force law with a
    kink, the rounded punch's at a = b, keeps its digits beside it)."""
    exp = make_callable(contact.derivation(name), "numpy", 15, {k: v for k, v in fixed.items() if k != "mu"})

    def value(tv):
        with np.errstate(invalid="ignore", divide="ignore"):   # numpy evaluates every Piecewise branch
            return np.broadcast_to(np.real(exp(a=np.asarray(tv, float))), np.shape(tv))
    return value


def _float_normal(t, fixed) -> FloatNormal:
    key = ("_float", tuple(sorted(fixed.items())))
    if key not in t._cache:
        t._cache[key] = FloatNormal(t, fixed)
    return t._cache[key]


@dataclass
class TangentialState:
    """One state of a tangential load history at numbers.

    branch  'loading' (from Q = 0), 'unloading' (from Q_max), 'reloading'
            (from -Q_max) or 'gross sliding onset' (|Q| = mu P)
    Q, P, a, mu   tangential force, normal load, half-width, friction coefficient
    c       stick half-width of the monotone part (at the turning point on a reversal)
    c_r     stick half-width of the reversal (None on the loading branch)
    Q_max   the turning point (None on the loading branch)
    coupling  what the state neglects of the two bodies' mismatch: "beta = 0
            assumed (elastically similar bodies)", or |beta| mu where beta
            was given (:mod:`.coupling`; the numbers are Goodman's either way)
    """

    branch: str
    Q: object
    P: object
    a: object
    mu: object
    c: object
    c_r: object = None
    Q_max: object = None
    values: dict = field(default_factory=dict, repr=False)
    contact: object = field(default=None, repr=False)
    coupling: str = ""

    @property
    def terms(self):
        """(coefficient, stick half-width) of the monotone (Cattaneo) terms
        whose sum is this state."""
        if self.branch == "unloading":
            return ((1, self.c), (-2, self.c_r))
        if self.branch == "reloading":
            return ((-1, self.c), (2, self.c_r))
        return ((-1 if self.Q < 0 else 1, self.c),)

    def _eval(self, quantity, x):
        t = self.contact
        xs = np.abs(np.asarray(x, dtype=float))
        fixed = {k: float(v) for k, v in self.values.items()}
        name = quantity if self.branch not in ("unloading", "reloading") else "unloading_" + quantity
        d = t.derivation(name)
        if d.closed_form:
            args = {"a": float(self.a), "c_s": float(self.c)}
            if self.c_r is not None:
                args["c_r"] = float(self.c_r)
            sign = -1.0 if (self.branch == "reloading" or (self.c_r is None and self.Q < 0)) else 1.0
            # the stable form (no atanh(1) cancellation at a kink), compiled once per
            # contact and parameters: the half-widths are arguments, not constants
            # folded in (each state compiled its own, most of a fretting test's time)
            fn = make_callable(d, "numpy", 15, fixed)
            return sign * np.real(fn(x=xs, **args))
        fl, A, mu = _float_normal(t, fixed), float(self.a), float(self.mu)
        out = np.zeros(xs.shape)
        for k, C in self.terms:
            C = float(C)
            if quantity == "traction":
                out += k * mu * (fl.pressure(xs, A) - np.where(xs < C, fl.pressure(xs, C), 0.0))
            else:
                out += k * mu * np.where(xs > C, fl.gap(xs, C), 0.0)
        return out

    def traction(self, x):
        """The shear traction at x (float64 array), positive in the direction of +Q."""
        return self._eval("traction", x)

    def slip(self, x):
        """The accumulated slip at x relative to the stick zone (float64 array)."""
        return self._eval("slip", x)


def numbers_at(t, values):
    """Keyword values -> (Symbol -> exact number) for the contact's variables,
    plus the half-width a (given, or from the normal load P)."""
    from ..base import checked_value      # the one reading of a user's value: 1j, NaN, text refused
    values = t.coupling.values(values)          # E_star from the materials where not given (a contradiction refused)
    by_name = {s.name: s for s in t.variables}
    vals = {}
    for k, v in values.items():
        if k in ("a", "P"):
            checked_value(k, v, None)
            continue
        if k not in by_name:
            raise DomainError(f"unknown value {k!r}; expected {sorted(by_name)} and a or P")
        vals[by_name[k]] = check_sign(by_name[k], to_sympy_number(checked_value(k, v, None)))  # 1j, NaN, text; then R = -1 (core.ranges)
    missing = [s.name for s in t.variables if s not in vals]
    if missing:
        raise DomainError(f"values needed for {', '.join(missing)}")
    if ("a" in values) == ("P" in values):
        raise DomainError("give either the half-width a or the normal load P")
    check_values({s.name: v for s, v in vals.items()})          # mu > 0 (core.ranges)
    if "a" in values:                                           # where the normal solution holds (a < R, ...)
        t.contact.check_point({**vals, S.a: check_sign(S.a, to_sympy_number(values["a"]))})
    with workdps(30):
        law = force_law_at(t, vals)
        if "a" in values:
            A = to_mpf(to_sympy_number(values["a"]))
            c0 = to_mpf(sp.N(t.c0.xreplace(vals), 30))
            if not A > c0:
                raise DomainError(f"the half-width must exceed {mpmath.nstr(c0, 8)} (where the force law starts "
                                  f"to grow), got a = {values['a']}")
        else:
            if not to_mpf(to_sympy_number(values["P"])) > 0:
                raise DomainError(f"the normal load must be positive, got P = {values['P']}")
            A = half_width_at(law, to_mpf(to_sympy_number(values["P"])))
    return vals, law, A


def _stick(t, law, load, vals, A):
    """The stick half-width where P(c) = load (0 <= load <= P(A)): the force
    law's last zero c0 at load 0, else the root in (c0, A), where the law
    does not decrease: bracketed by halving from A (a narrow bracket: the
    Anderson step of :func:`~linecontact_sym.core.roots.root_in_log` may
    stop short of the root in a wide one), then solved and checked."""
    c0 = to_mpf(sp.N(t.c0.xreplace(vals), mpmath.mp.dps + 5))
    if load <= 0:
        return c0
    with workdps(mpmath.mp.dps + 10):
        A = to_mpf(A)
        hi, lo = A, A / 2
        floor = c0 if c0 > 0 else A * mpmath.mpf(10)**-30
        while lo > floor and law.P(lo) >= load:
            hi, lo = lo, lo / 2
        lo = max(lo, floor)
        if law.P(lo) >= load:
            return lo
        c = root_in_log(lambda cv: law.P(cv) - load, lo, hi)
        if abs(law.P(c) - load) > law.P(A) * mpmath.mpf(10)**(-mpmath.mp.dps // 2):
            raise LineContactError(f"no stick half-width found for P(c) = {mpmath.nstr(load, 10)}")
        return c


def stick_half_width_at(t, Qv, values) -> TangentialState:
    """The monotonic-loading state at the tangential force Q (numbers)."""
    with workdps(30):
        vals, law, A = numbers_at(t, values)
        Pa, mu = law.P(A), friction_at(t, vals)
        Qm = to_mpf(sp.N(Qv, 40))
        load = Pa - abs(Qm) / mu
        tol = Pa * ONSET_RTOL   # |Q| = mu P to float64 rounding is the onset
        if load < -tol:
            raise GrossSlidingError(f"|Q| = {mpmath.nstr(abs(Qm), 8)} exceeds the Coulomb limit mu P = "
                                    f"{mpmath.nstr(mu * Pa, 8)}: the contact slides as a whole (no partial slip)")
        branch = "loading" if load > tol else "gross sliding onset"
        return TangentialState(branch, Qm, Pa, A, mu, _stick(t, law, load if load > tol else 0, vals, A),
                               values={s.name: v for s, v in vals.items()}, contact=t,
                               coupling=coupling_at(t, vals))


def coupling_at(t, vals):
    """The coupling note of a state of ``t`` at the values (mu as a number)."""
    return t.coupling.note(t.mu.xreplace(vals))


def reversal(t, Q_max, Q, values, branch) -> TangentialState:
    """Mindlin-Deresiewicz: the state at Q on the unloading branch from +Q_max
    or the reloading branch from -Q_max."""
    top = stick_half_width_at(t, abs(to_sympy_number(Q_max)), values)
    with workdps(30):
        Qm = to_mpf(sp.N(to_sympy_number(Q), 40))
        Qx = top.Q
        if not -Qx <= Qm <= Qx:
            raise DomainError(f"Q = {mpmath.nstr(Qm, 8)} lies outside [-Q_max, Q_max] = +-{mpmath.nstr(Qx, 8)}")
        dQ = Qx - Qm if branch == "unloading" else Qx + Qm
        vals, law, _ = numbers_at(t, values)
        c_r = _stick(t, law, top.P - dQ / (2 * top.mu), vals, top.a)
        return TangentialState(branch, Qm, top.P, top.a, top.mu, top.c, c_r, Qx, top.values, t, top.coupling)


def to_sympy_number(v):
    """An exact SymPy number for a value (floats as the rational of their
    shortest decimal): :func:`~linecontact_sym.parsing.user_value`, the one
    reading of a parameter value."""
    return user_value(v)


@dataclass
class FrettingCycle:
    """A full cycle between +-Q_amplitude at constant normal load.

    c          stick half-width at the extremes
    W          energy dissipated per unit length per cycle
    Q, delta   the closed loop (unloading then reloading branch); delta is the
               rigid shift with reference length a (a convention: another
               reference length shears the loop, its area stays W)
    coupling   the neglected coupling of the two bodies (as
               :class:`TangentialState`'s)
    """

    Q_amplitude: object
    P: object
    a: object
    mu: object
    c: object
    W: object
    Q: np.ndarray
    delta: np.ndarray
    coupling: str = ""

    @property
    def loop_area(self) -> float:
        """Area enclosed by the (Q, delta) polygon (a numerical check of W)."""
        q, d = self.Q, self.delta
        return 0.5 * abs(float(np.dot(d, np.roll(q, -1)) - np.dot(q, np.roll(d, -1))))


def cycle(t, Q_amplitude, points, values) -> FrettingCycle:
    """The fretting loop and the energy per cycle (see :class:`FrettingCycle`)."""
    top = stick_half_width_at(t, to_sympy_number(Q_amplitude), values)
    vals, law, A = numbers_at(t, values)
    fixed = {s.name: float(v) for s, v in vals.items()}
    with workdps(30):
        QA = abs(top.Q)
        Qs = [QA - 2 * QA * k / (points - 1) for k in range(points)]
        crs = [_stick(t, law, top.P - (QA - q) / (2 * top.mu), vals, A) for q in Qs]

    def evaluate(name, cs):
        d = t.derivation(name)
        if d.closed_form:
            fn = make_callable(d, "numpy", 15, fixed)
            return np.real(fn(a=float(A), c_s=np.array([float(c) for c in cs])))
        fl = _float_normal(t, fixed)
        what = fl.energy if name == "dissipated_energy" else fl.displacement
        return np.array([what(float(A), float(c), float(top.mu)) for c in cs])
    d_top = evaluate("loop_displacement", [top.c])[0]
    down = d_top - 2 * evaluate("loop_displacement", crs)
    Qd = np.array([float(q) for q in Qs])
    Q = np.concatenate([Qd, -Qd[1:-1]])
    delta = np.concatenate([down, -down[1:-1]])
    W = evaluate("dissipated_energy", [top.c])[0]
    return FrettingCycle(QA, top.P, A, top.mu, top.c, float(W), Q, delta, top.coupling)


def bem(t, n, values):
    """A :class:`~.reference.CoulombBEM` of this contact at numbers."""
    vals, law, A = numbers_at(t, values)
    fixed = {s.name: float(v) for s, v in vals.items() if s in set(t.contact.variables)}
    brs = [float(b) for b in law.breaks()]
    with workdps(30):
        mu = float(friction_at(t, vals))
    return ref.CoulombBEM(float(A), fixed["E_star"], mu, _float_fn(t.contact, "stiffness", fixed), n, brs)


__all__ = ["numbers_at", "ONSET_RTOL", "FloatNormal", "TangentialState", "FrettingCycle", "stick_half_width_at", "reversal",
           "cycle", "bem", "to_sympy_number", "coupling_at"]
