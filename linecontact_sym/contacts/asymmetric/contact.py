"""The asymmetric line contact as a physical system: a profile on the whole
line (optionally between walls: a punch), pressed with a load P at a
prescribed tilt theta or under a prescribed moment M (free rotation).

``LineContact(f, symmetric=False)`` builds :class:`AsymmetricLineContact`;
``flat_punch(w)`` the rigid flat punch of half-width w (walls at |x| = w);
``contact_at(P=..., theta=...)`` / ``contact_at(P=..., moment=...)`` solve
for the contact [left, right] (:class:`AsymmetricState`).  Every number
comes from :class:`~.core.OffsetContact` (the engine's transforms of the
even and odd parts), see :mod:`.core` for the reduction and the signs.

The regimes (``edges``: 'smooth' where the pressure vanishes like a square
root, 'corner' at a wall where it is singular like 1/sqrt):

* bounded      both edges smooth: P(e, a) = P and theta(e, a) = theta
               (or M(e, a) = M with theta = theta(e, a));
* one corner   a free edge and a wall: K = 0 at the free edge, e +- a at the wall;
* complete     both edges at the walls: e, a fixed, the extra punch load P0
               and the tilt from P and M (or P0 from P at a given tilt).

The solution is the first of these, in this order, whose edges lie within
the walls and whose corner factors are >= 0; a flat punch passes from
complete to incomplete contact where the factor at one corner vanishes:
|M_c| = P w/2 (the load's line of action at w/2 from the centre), i.e.
|theta| = 2 P/(pi E* w).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import mpmath
import numpy as np
import sympy as sp

from ...core import symbols as S
from ...core.budget import DEFAULT_BUDGET
from ...core.conversion import to_mpf
from ...core.errors import DomainError, InadmissibleProfileError, LineContactError, NoEquilibriumError, ProfileError
from ...core.precision import checked_dps, workdps
from ...core.roots import Outside, root_in_bracket
from ...parsing import user_value
from ..base import checked_value
from .core import OffsetContact
from .split import whole_line

__all__ = ["AsymmetricLineContact", "AsymmetricState", "flat_punch", "whole_line"]

#: working digits of the state solves
STATE_DPS = 30


def _real_x(f):
    """f with its x the package's real x: a Symbol named x, real and not positive."""
    xs = [v for v in f.free_symbols if v.name == "x"]
    if not xs:
        raise ProfileError(f"the profile {f} does not depend on x; give f(x) in the real x "
                           f"(linecontact_sym.x_real, or Symbol('x', real=True))")
    if len(xs) > 1:
        raise ProfileError(f"the profile {f} holds several symbols named x ({xs}): use one, the real x")
    xv = xs[0]
    if xv.is_positive or xv.is_nonnegative:
        raise ProfileError(f"the profile {f} is in a positive x (the symmetric contact's, mirrored to x < 0); "
                           f"an asymmetric profile is given on the whole line in the real x: "
                           f"linecontact_sym.x_real or Symbol('x', real=True)")
    if xv.is_real is not True:
        raise ProfileError(f"the x of the profile {f} must be real: Symbol('x', real=True) (linecontact_sym.x_real)")
    return f.xreplace({xv: S.x_real})


@dataclass(frozen=True)
class AsymmetricState:
    """The contact at a load and a tilt or moment (numbers, mpmath).

    left, right  the ends of the contact; e, a its centre and half-width
    theta        the rigid tilt (gap f(x) - theta x - d)
    load         P = int p dx; moment M = int x p dx (about x = 0)
    punch        P0, the load of the extra flat punch (0 when both edges are smooth)
    edges        ('smooth' | 'corner', 'smooth' | 'corner') at (left, right)
    factors      (K_left, K_right): p ~ K/sqrt(distance to the edge) (0 at a smooth edge)
    regime       'bounded', 'right corner', 'left corner' or 'complete'
    """

    contact: "AsymmetricLineContact" = field(repr=False)
    left: mpmath.mpf
    right: mpmath.mpf
    e: mpmath.mpf
    a: mpmath.mpf
    theta: mpmath.mpf
    load: mpmath.mpf
    moment: mpmath.mpf
    punch: mpmath.mpf
    edges: tuple
    factors: tuple
    regime: str
    values: dict = field(repr=False, default_factory=dict)

    @property
    def moment_centre(self):
        """M_c = M - e P: the moment about the centre of the contact."""
        return self.moment - self.e * self.load

    @property
    def eccentricity(self):
        """M/P: where the load's line of action meets the surface."""
        return self.moment / self.load

    def _numbers(self):
        cache = self.contact._state_fns
        key = ("numbers", tuple(sorted((k, str(v)) for k, v in self.values.items())))
        if key not in cache:
            cache[key] = self.contact.core.numbers(**self.values)
        return cache[key]

    def _fn(self, which):
        """The closed pressure or gap at this state (its case of the centre)
        as NumPy and mpmath functions of x, or None.  The pressure of a
        bounded state is written with the tilt theta(e, a) put in and the
        terms over one denominator (SymPy's together and factor, for forms
        without Piecewise): the 1/sqrt parts of the even and odd parts cancel
        there exactly, not in floating point near the edges."""
        cache = self.contact._state_fns
        core = self.contact.core
        k = core.cases.index(self._numbers().case(self.e)[0])
        bounded = which == "pressure" and self.regime == "bounded"
        key = (which, k, bounded)
        if key not in cache:
            if not core.closed(case=k) or not core.closed(which, case=k):
                cache[key] = None
            else:
                th, P0 = sp.Symbol("theta_n", real=True), sp.Symbol("P0_n", real=True)
                if bounded:
                    expr = core.pressure(case=k)
                    if not expr.has(sp.Piecewise, sp.Integral, sp.Derivative) and sp.count_ops(expr) < 400:
                        expr = sp.factor(sp.together(expr))
                else:
                    expr = getattr(core, which)(theta=th, punch=P0, case=k)
                args = [S.x_real, S.e, S.a, th, P0, S.E_star] + list(core.params)
                cache[key] = sp.lambdify(args, expr, "numpy"), sp.lambdify(args, expr, "mpmath")
        return cache[key]

    def _flat(self) -> bool:
        """Is the profile flat in this contact (no even or odd part: a punch)?"""
        case = self._numbers().case(self.e)[0]
        return case.even is None and case.odd is None

    def _flat_pressure(self, xs, mod):
        """A punch's pressure (C0 + C1 s)/sqrt(a^2 - s^2) written with its corner factors,
        sqrt(2a) [K_+ (x - left) + K_- (right - x)] / (2a sqrt((right - x)(x - left))):
        no cancellation where a factor vanishes (the complete/incomplete transition)."""
        Kl, Kr = self.factors          # at the solve's precision; exactly 0 at a smooth edge
        a = self.a
        if mod is np:
            Kl, Kr, a, left, right = (float(v) for v in (Kl, Kr, a, self.left, self.right))
        else:
            left, right = self.left, self.right
        dl, dr = xs - left, right - xs
        return mod.sqrt(2 * a) * (Kr * dl + Kl * dr) / (2 * a * mod.sqrt(dr * dl))

    def _args(self, kind):
        conv = float if kind == "numpy" else (lambda v: v)
        vals = [self.e, self.a, self.theta, self.punch]
        par = [to_mpf(self.values[v.name]) for v in (S.E_star,) + self.contact.core.params]
        return [conv(v) for v in vals + par]

    def pressure(self, x):
        """p(x) (0 outside [left, right]): an mpf for a number, a float64
        array for an array (closed forms; the quadrature route pointwise)."""
        if isinstance(x, np.ndarray) or isinstance(x, (list, tuple)):
            xs = np.asarray(checked_value("x", np.asarray(x), None), dtype=float)
            inside = (xs > float(self.left)) & (xs < float(self.right))
            out = np.zeros_like(xs)
            if self._flat():
                out[inside] = self._flat_pressure(xs[inside], np)
                return out
            fn = self._fn("pressure")
            if fn is not None:
                try:
                    with np.errstate(all="ignore"):
                        out[inside] = np.real(fn[0](xs[inside].astype(complex), *self._args("numpy")))
                except (ValueError, TypeError):    # NumPy's select over a Piecewise of the centre: pointwise
                    out[inside] = np.nan
                # near |x - e| = eps the float64 closed form cancels: those points at mpmath
                bad = inside & ~np.isfinite(out)
                for ep in self._mirror():
                    bad |= inside & (np.abs(np.abs(xs - float(self.e)) - float(ep)) < 1e-5 * float(self.a))
                out[bad] = [float(self.pressure(v)) for v in xs[bad]]
            else:
                out[inside] = [float(self.pressure(v)) for v in xs[inside]]
            return out
        xv = x if isinstance(x, mpmath.mpf) and mpmath.isfinite(x) else to_mpf(_given("x", x))
        if not self.left < xv < self.right:
            return mpmath.mpf(0)
        if self._flat():
            return self._flat_pressure(xv, mpmath)
        fn = self._fn("pressure")
        if fn is None:
            return self._numbers().pressure(xv, self.e, self.a, self.theta, self.punch)
        return self._closed_mp(fn[1], xv)

    def _mirror(self):
        """The distances eps = |e - b| of the centre from the profile's kinks b:
        at |x - e| = eps the closed pressure's logarithms of the even and odd
        parts cancel (at the mirror image 2e - b of a kink the pressure is smooth)."""
        core = self.contact.core
        vals = {v: self.values[v.name] for v in core.params if v.name in self.values}
        out = []
        for b in core.kinks:
            bv = to_mpf(sp.N(sp.sympify(b, strict=True).xreplace(vals), mpmath.mp.dps + 10))
            out.append(abs(self.e - bv))
        return out

    def _closed_mp(self, fn, xv):
        """A closed form at x, with the digits its cancellation near |x - e| = eps
        costs added (and at that point the mean of two points beside it)."""
        dps = mpmath.mp.dps
        dist = min((abs(abs(xv - self.e) - ep) for ep in self._mirror()), default=mpmath.inf)
        if dist == 0:
            with workdps(3 * dps):
                d = mpmath.mpf(10)**(-dps) * max(abs(xv), 1)
                v = (_finite(fn(xv - d, *self._args("mp"))) + _finite(fn(xv + d, *self._args("mp")))) / 2
            return +v
        extra = 0 if dist > self.a / 1000 else min(int(-mpmath.log10(dist / self.a)) + 5, 2 * dps)
        with workdps(dps + extra):
            v = _finite(fn(xv, *self._args("mp")))
        return +v

    def evaluate(self, quantity: str, x, rtol: float = 1e-8):
        """``pressure`` or ``gap`` at x (a number or an array) to the relative
        tolerance ``rtol``: float64 (the closed form over one denominator, a
        punch by its corner factors) where rtol >= 1e-12 and x is not within
        1e4 eps |x| / rtol of an end (where float64 cannot place x relative
        to the end well enough), else mpmath at -log10(rtol) + 5 digits and
        those the closed form loses there, log10(|x|/distance to the end)."""
        if quantity not in ("pressure", "gap"):
            raise DomainError(f"evaluate: 'pressure' or 'gap', got {quantity!r}")
        if not (isinstance(rtol, (int, float)) and 0 < rtol < 1):
            raise DomainError(f"rtol must be a number in (0, 1), got {rtol!r}")
        fn = getattr(self, quantity)
        xs = np.atleast_1d(np.asarray(x, dtype=float))
        dist = np.minimum(np.abs(xs - float(self.left)), np.abs(xs - float(self.right)))
        cond = np.finfo(float).eps * np.maximum(1.0, np.abs(xs)) / np.maximum(dist, 1e-300)
        fast = rtol >= 1e-12 and bool(np.all(1e4 * cond <= rtol))
        if fast:
            out = fn(xs)
        else:
            # the digits the closed form loses near an end (x - e against a) come on top
            lost = max(0.0, math.log10(float(np.max(cond)) / np.finfo(float).eps))
            dps = int(-math.log10(rtol)) + 5 + math.ceil(lost)
            with workdps(dps):
                out = np.array([float(fn(mpmath.mpf(v))) for v in xs])
        return out if np.ndim(x) else float(out[0])

    def plot(self, ax=None, points: int = 401):
        """The pressure over [left, right] (matplotlib, the ``[plot]`` extra),
        with the ends marked (a corner dashed); returns the axes."""
        try:
            import matplotlib.pyplot as plt
        except ImportError as exc:                # the optional extra
            raise ImportError("plot needs matplotlib: pip install 'linecontact_sym[plot]'") from exc
        if ax is None:
            ax = plt.subplots(figsize=(6, 3.5))[1]
        span = float(self.right - self.left)
        xs = np.linspace(float(self.left) + 1e-4 * span, float(self.right) - 1e-4 * span, points)
        ax.plot(xs, self.pressure(xs), label=f"theta = {float(self.theta):.4g}, M = {float(self.moment):.4g}")
        for end, kind in zip((self.left, self.right), self.edges):
            ax.axvline(float(end), color="0.5", lw=0.8, ls="--" if kind == "corner" else ":")
        ax.set_xlabel("x")
        ax.set_ylabel("p(x)")
        ax.legend()
        return ax

    def gap(self, x):
        """g(x) outside the contact (0 inside); closed forms only (else
        ``NotImplementedError``)."""
        fn = self._fn("gap")
        if fn is None:
            raise NotImplementedError("the gap of a state needs the engine's closed gaps of the even and odd parts")
        if isinstance(x, np.ndarray) or isinstance(x, (list, tuple)):
            xs = np.asarray(x, dtype=float)
            out = np.zeros_like(xs)
            outside = (xs < float(self.left)) | (xs > float(self.right))
            with np.errstate(all="ignore"):
                out[outside] = np.real(fn[0](xs[outside].astype(complex), *self._args("numpy")))
            return out
        xv = to_mpf(x)
        if self.left <= xv <= self.right:
            return mpmath.mpf(0)
        v = fn[1](xv, *self._args("mp"))
        return mpmath.mpf(getattr(v, "real", v))


@dataclass(frozen=True)
class LevelState(AsymmetricState):
    """The state of a symmetric contact at theta = 0 (or M = 0): centred at
    the half-width of :meth:`~linecontact_sym.contacts.normal.contact.LineContact.half_width`,
    its pressure and gap the symmetric contact's own (today's results,
    exactly), at |x|; ``contact`` is None (no asymmetric twin is built)."""

    symmetric: object = field(repr=False, default=None)

    def _at(self, quantity, x, numeric):
        c, vals = self.symmetric, dict(self.values)
        if isinstance(x, np.ndarray) or isinstance(x, (list, tuple)):
            xs = np.abs(np.asarray(x, dtype=float))
            keep = xs < float(self.a) if quantity == "pressure" else xs > float(self.a)
            out = np.zeros_like(xs)
            fn = c.to_numeric(quantity, "numpy", check=False)
            fv = {k: float(to_mpf(user_value(v))) for k, v in vals.items()}
            with np.errstate(all="ignore"):
                out[keep] = np.real(fn(a=float(self.a), x=xs[keep], **fv))
            return out
        xv = abs(to_mpf(x))
        if (quantity == "pressure") != (xv < self.a):
            return mpmath.mpf(0)
        return numeric(xv)

    def pressure(self, x):
        return self._at("pressure", x, lambda xv: self.symmetric.evaluate_at(
            "pressure", dps=mpmath.mp.dps, a=self.a, x=xv, **self.values))

    def gap(self, x):
        return self._at("gap", x, lambda xv: self.symmetric.evaluate_at(
            "gap", dps=mpmath.mp.dps, a=self.a, x=xv, **self.values))

    def evaluate(self, quantity: str, x, rtol: float = 1e-8):
        """The symmetric contact's ``evaluate`` (the cheapest path meeting rtol) at |x|."""
        if quantity not in ("pressure", "gap"):
            raise DomainError(f"evaluate: 'pressure' or 'gap', got {quantity!r}")
        return self.symmetric.evaluate(quantity, rtol=rtol, a=float(self.a), x=np.abs(np.asarray(x, dtype=float)),
                                       **self.values)


#: points near the origin where a profile without parameters must be real (within the walls)
REAL_PROBES = (-sp.Rational(1, 2), -sp.Rational(1, 8), sp.Rational(1, 8), sp.Rational(1, 2))


def _check_real(f, walls):
    """A profile without parameters must be real near the origin (sqrt(x),
    log(x) are not on x < 0): a ProfileError before any derivation."""
    xs = [v for v in f.free_symbols if v.name == "x"]
    if len(f.free_symbols) != 1 or not xs:
        return
    for v in REAL_PROBES:
        if not walls[0] < v < walls[1]:
            continue
        try:
            val = complex(sp.N(f.xreplace({xs[0]: v}), 20))
        except (TypeError, ValueError):
            continue
        if not math.isfinite(val.real) or abs(val.imag) > 1e-12 * max(1.0, abs(val.real)):
            raise ProfileError(f"the profile {f} is not real at x = {v} (f = {sp.N(f.xreplace({xs[0]: v}), 6)}): "
                               f"an asymmetric profile is given real on the whole line (within the walls)")


def _given(name, v, positive=False):
    """A load, tilt, moment or point as a user gives it: a finite real number
    (:func:`~linecontact_sym.contacts.base.checked_value`: text through the
    parser, complex, NaN, inf refused), a SymPy expression with free symbols
    left as it is (the closed ends); a DomainError naming it otherwise."""
    if isinstance(v, sp.Basic) and v.free_symbols:
        return v
    val = checked_value(name, v, None)
    if isinstance(val, np.ndarray):
        raise DomainError(f"{name} = {v!r}: expected one number")
    if positive and not val > 0:
        raise DomainError(f"the load must be positive, got {name} = {v}")
    return val


def _finite(v):
    v = mpmath.mpf(v.real) if isinstance(v, mpmath.mpc) else mpmath.mpf(v)
    if not mpmath.isfinite(v):
        raise ValueError("not finite")
    return v


class AsymmetricLineContact:
    """A rigid profile on the whole line (optionally between walls) on an
    elastic half-plane, frictionless, under a load and a tilt or a moment.

    Parameters
    ----------
    profile : sympy.Expr
        f(x) in the real x (``linecontact_sym.x_real`` or ``Symbol('x', real=True)``),
        not mirrored; a Piecewise or Abs for different flanks.
    params : list or dict, optional
        Declared parameters (positive symbols count as declared).
    walls : (left, right), optional
        The punch's walls: the contact stays within [left, right] (a corner
        where it reaches one); default the whole line.
    """

    kind = "asymmetric"

    def __init__(self, profile, params=None, name: str | None = None, walls=None,
                 budget: float = DEFAULT_BUDGET, verify: bool = True, points: int = 5, symmetric=False):
        f = user_value(profile) if not isinstance(profile, sp.Basic) else profile
        if isinstance(f, (int, float)) and not isinstance(f, bool):
            f = sp.sympify(f, strict=True)
        if not isinstance(f, sp.Expr):
            raise ProfileError(f"the profile must be a SymPy expression in the real x, got {profile!r}")
        if f.has(sp.I) or f.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
            raise ProfileError(f"the profile {f} is not a real finite expression")
        if walls is None:
            f = _real_x(f)
            self.walls = (-sp.oo, sp.oo)
        else:
            f = _real_x(f) if f.has(sp.Symbol) and any(v.name == "x" for v in f.free_symbols) else f
            lo, hi = (sp.sympify(w, strict=True) for w in walls)
            if not (lo.is_real and hi.is_real and bool(hi > lo)):
                raise ProfileError(f"the walls must be real numbers left < right, got {walls!r}")
            self.walls = (lo, hi)
        _check_real(f, self.walls)
        self.name = name or str(f)
        self.core = OffsetContact(f, params, name=self.name, budget=budget, verify=verify, points=points)
        self.profile = f
        self._state_fns: dict = {}

    def __repr__(self):
        w = "" if self.walls == (-sp.oo, sp.oo) else f", walls={self.walls}"
        return f"LineContact({self.profile}, symmetric=False{w})"

    @property
    def params(self):
        return self.core.params

    def rolling(self, friction=S.mu, *, beta=None, materials=None):
        """Steady rolling with traction over this contact (issue 40):
        :class:`~linecontact_sym.contacts.rolling.asymmetric.AsymmetricRolling`
        (through the kind registry: the rolling layer stands on this package);
        ``beta`` or ``materials``: the two bodies
        (:data:`~linecontact_sym.core.materials.COUPLING_KEYWORDS`)."""
        from ..base import contact_kind
        return contact_kind("rolling").over_asymmetric(self, friction, beta=beta, materials=materials)

    def viscoelastic(self, material):
        """Refused: a viscoelastic asymmetric contact (tilt, moment, punch) is
        not solved; the viscoelastic contacts are the symmetric ones
        (``LineContact(f).viscoelastic(material)``)."""
        raise DomainError(f"{self.name}: viscoelastic contacts are solved for symmetric profiles without walls "
                          f"(LineContact(f).viscoelastic(material)); an asymmetric contact, a tilt, a moment or "
                          f"a flat punch with walls is not supported on a viscoelastic half-plane")

    @classmethod
    def from_symmetric(cls, contact) -> "AsymmetricLineContact":
        """The symmetric contact's profile on the whole line (:func:`whole_line`)."""
        prof = contact.profile
        params = {p: prof.declared_ranges.get(p) for p in prof.params}
        return cls(whole_line(prof.original), params, name=prof.name, budget=contact.budget,
                   verify=contact.verify, points=contact.points)

    @classmethod
    def symmetric_state(cls, contact, P, theta=None, moment=None, dps: int = STATE_DPS, **values):
        """``contact.contact_at``: at theta = 0 or M = 0 the symmetric contact's own half-width at P
        (:meth:`~linecontact_sym.contacts.normal.contact.LineContact.half_width`), centred; else
        the state of :meth:`from_symmetric`."""
        level = all(v is None or user_value(v) == 0 for v in (theta, moment))
        if not level:
            return contact.asymmetric().contact_at(P, theta, moment, dps=dps, **values)
        if theta is not None and moment is not None:
            raise DomainError("give the tilt theta or the moment M, not both (a tilt fixes the moment)")
        with workdps(dps + 10):
            Pv = to_mpf(user_value(P))
            a = to_mpf(contact.half_width(P, **values))
            zero = mpmath.mpf(0)
            return LevelState(None, -a, a, zero, a, zero, Pv, zero, zero, ("smooth", "smooth"), (zero, zero),
                              "bounded", dict(values), symmetric=contact)

    # ------------------------------------------------------------------ closed ends
    def ends(self, load=S.P, theta=None, moment=None, budget: float | None = None, **values):
        """The ends of the bounded contact (both edges smooth) in closed form:
        SymPy solves P(e, a) = load with theta(e, a) = theta (default the
        symbol theta_t) or M(e, a) = moment, under the budget (CPU s), a(e)
        from the load first, as dicts {e, a, left, right}; an empty list where
        SymPy finds none in time or a part is not closed.

        Which branches: where P(e, a) is even in a its roots a(e) come in
        pairs +-r, and only the one that is positive where real is kept; of
        the rest every branch SymPy cannot show to be complex or to have
        a <= 0 (a cubic profile: the three roots of a cubic in e, whose
        admissible one changes with the parameters).  With ``values`` (E_star
        and the profile's parameters by name; load and theta or moment
        numbers) only the branches admissible there are returned: e and a
        real, a > 0 and the bounded pressure >= 0 across the contact (21
        points), each dict with its numbers ``e_value``, ``a_value`` (the one
        :meth:`contact_at` finds).

        >>> import sympy as sp, linecontact_sym as lcs
        >>> R = sp.Symbol("R", positive=True)
        >>> lcs.LineContact(lcs.x_real**2/(2*R), symmetric=False).ends()[0]["e"]
        R*theta_t
        """
        if theta is not None and moment is not None:
            raise DomainError("give the tilt theta or the moment M, not both")
        core = self.core
        load = _given("P", load)
        theta = None if theta is None else sp.sympify(_given("theta", theta), strict=True)
        moment = None if moment is None else sp.sympify(_given("moment", moment), strict=True)
        target = (core.tilt(), S.tilt if theta is None else theta) if moment is None else (core.moment(), moment)
        eqs = [sp.Eq(core.force(), load), sp.Eq(*target)]
        if any(q.has(sp.Integral, sp.Derivative, sp.Piecewise) for q in (eqs[0].lhs, eqs[1].lhs)):
            return []
        from ...core.budget import BudgetExceeded, run_with_budget
        try:
            sols = run_with_budget(_solve_ends, eqs, seconds=budget or core.budget)
        except BudgetExceeded:
            return []
        out = [{"e": e_, "a": a_, "left": _tidy(e_ - a_), "right": _tidy(e_ + a_)} for e_, a_ in sols]
        return _admissible_ends(core, out, values) if values else out

    # ------------------------------------------------------------------ states
    def contact_at(self, P, theta=None, moment=None, dps: int = STATE_DPS, **values) -> AsymmetricState:
        """The contact at the load ``P`` > 0 with the tilt ``theta``
        (default 0) or the moment ``moment`` about x = 0 (free rotation):
        see the module docstring for the regimes."""
        if theta is not None and moment is not None:
            raise DomainError("give the tilt theta or the moment M, not both (a tilt fixes the moment)")
        dps = checked_dps(dps)
        Pv = _given("P", P, positive=True)
        given = ("moment", _given("moment", moment)) if moment is not None else \
            ("theta", _given("theta", 0 if theta is None else theta))
        with workdps(dps + 10):
            Pv = to_mpf(Pv)
            n = self.core.numbers(**values)
            given = (given[0], to_mpf(given[1]))
            try:
                state = _solve(self, n, Pv, given, values)
                _check_compressive(state)
            except Outside:
                raise ProfileError(f"the profile {self.profile} is not real (or not finite) over the contact the "
                                   f"load {P} needs: give a profile real on the whole line") from None
        return state


# ---------------------------------------------------------------------- solves
#: the size (count_ops) up to which the ends are simplified (a root of a cubic by
#: Cardano's formula, some 80 operations, took SymPy's simplify 3 s each and stays as long)
TIDY_OPS = 60


def _tidy(expr):
    """SymPy's simplify for a short closed end (the parabola's), else the expression as solved."""
    return sp.simplify(expr) if sp.count_ops(expr) <= TIDY_OPS else expr


def _positive_of_pairs(roots):
    """Of roots coming in pairs +-r (of an equation even in the unknown),
    the member of each pair that is positive where real (no extractable minus sign)."""
    out = []
    for r in roots:
        partner = any(sp.simplify(r + q) == 0 for q in roots if q is not r)
        if partner and r.could_extract_minus_sign():
            continue
        out.append(r)
    return out


def _admissible_ends(core, branches, values, dps: int = 30):
    """The branches of :meth:`AsymmetricLineContact.ends` admissible at the numbers
    ``values``: e, a real (imaginary parts below 10^-(dps - 10) of their size),
    a > 0 and the bounded pressure >= 0 at 21 points across [e - a, e + a]."""
    subs = {v: user_value(values[v.name]) for v in core.variables if v.name in values}
    n = core.numbers(**values)
    out = []
    with workdps(dps + 10):
        for br in branches:
            e_, a_ = (sp.sympify(br[k], strict=True) for k in ("e", "a"))
            free = sorted((e_.free_symbols | a_.free_symbols) - set(subs), key=lambda v: v.name)
            if free:
                raise DomainError(f"ends: values for {', '.join(map(str, free))} are needed to tell the "
                                  f"admissible branches")
            # numbers put in by mpmath, whose principal branches are SymPy's (SymPy's own
            # substitution into a root of a cubic by Cardano's formula evaluates for minutes)
            args = sorted(subs, key=lambda v: v.name)
            ev, av = (mpmath.mpmathify(sp.lambdify(args, z, "mpmath")(*(to_mpf(subs[v]) for v in args)))
                      for z in (e_, a_))
            tiny = mpmath.mpf(10)**(10 - dps)
            if any(abs(mpmath.im(z)) > tiny * (1 + abs(z)) for z in (ev, av)):
                continue
            ev, av = mpmath.re(ev), mpmath.re(av)
            if not av > 0:
                continue
            ps = [n.pressure(ev + av * mpmath.mpf(k) / 11, ev, av) for k in range(-10, 11)]
            if any(p < -tiny * max(abs(q) for q in ps) for p in ps):
                continue
            out.append({**br, "e_value": ev, "a_value": av})
    return out


#: interior points of the contact where a state's pressure must be >= 0: (closed forms, quadrature)
CHECK_POINTS = (101, 21)


def _check_compressive(state, points=CHECK_POINTS):
    """p >= 0 inside the contact (no adhesion here: a tensile pressure means
    the one-interval solution is not the contact, e.g. a profile not convex
    over it that touches in two places); InadmissibleProfileError otherwise.
    A flat punch's pressure is its corner factors' (checked by the regimes).
    Closed forms: float64 at 101 points; the quadrature route (a quadrature
    per point): 21 points at 15 digits (the sign only)."""
    if state._flat():
        return
    closed = state._fn("pressure") is not None
    L, Rt = float(state.left), float(state.right)
    fast = None if closed else _bounded_pressure_float(state)
    xs = np.linspace(L, Rt, points[0 if closed or fast is not None else 1] + 2)[1:-1]
    if fast is not None:
        p = fast(xs)
    else:
        with workdps(15):
            p = state.pressure(xs)
    scale = max(float(np.max(np.abs(p))), 1e-300)
    bad = ~(p >= -1e-9 * scale)
    if bad.any():
        xb = xs[bad][0]
        raise InadmissibleProfileError(
            f"{state.contact.name} at P = {mpmath.nstr(state.load, 8)}: the one-interval contact "
            f"[{mpmath.nstr(state.left, 8)}, {mpmath.nstr(state.right, 8)}] has a tensile pressure near x = {xb:.6g} "
            f"(p = {float(p[bad][0]):.4g}); without adhesion the profile must be convex enough over the contact "
            f"(a dent or a flat: it touches in more than one interval, or the contact runs along the flat; not solved)")


def _bounded_pressure_float(state):
    """p(x) of a bounded state (both edges smooth, no punch) in float64 where
    its pressure has no closed form: (E*/2) sqrt(a^2 - (x - e)^2) J(x; e, a),
    J the phi-mean of the divided difference of f' (:mod:`.interval`,
    Gauss-Legendre split at the profile's kinks; the tilt cancels in it).
    One quadrature of f' per point, not the engine's nested quadrature of the
    parts' force laws (the Gaussian bump's check took 100 s for its 21 points).
    None for any other state (a corner, a punch) or a profile whose slope is
    not a function of x at the values."""
    if state.regime != "bounded" or state.punch != 0:
        return None
    from .interval import SlopeNumbers
    contact = state.contact
    cache = contact._state_fns          # one per parameter values, beside the core's numbers (the slope compiled once)
    key = ("slope numbers", tuple(sorted((k, str(v)) for k, v in state.values.items())))
    if key not in cache:
        core = contact.core
        try:
            vals = {v: state.values[v.name] for v in core.params if v.name in state.values}
            cache[key] = SlopeNumbers(sp.diff(contact.profile, S.x_real), vals, state.values["E_star"],
                                      [sp.sympify(b, strict=True).xreplace(vals) for b in core.kinks])
        except (LineContactError, KeyError, TypeError, ValueError):
            cache[key] = None
    numbers = cache[key]
    if numbers is None:
        return None
    e, a = state.e, state.a
    return lambda xs: numbers.pressure(xs, e, a)


def _solve_ends(eqs):
    """(e, a) solutions of the two equations with a > 0 (where SymPy can tell):
    a(e) from the load first (of a pair +-r of roots of a load even in a, the
    positive one), then e from the tilt or moment."""
    out = []
    roots = sp.solve(eqs[0], S.a)
    P = eqs[0].lhs
    if sp.expand(P.xreplace({S.a: -S.a}) - P) == 0:
        roots = _positive_of_pairs(roots)
    for a_e in roots:
        if a_e.is_positive is False:
            continue
        second = eqs[1].lhs.xreplace({S.a: a_e}) - eqs[1].rhs
        for e_ in sp.solve(second, S.e):
            if e_.is_real is False:
                continue
            a_ = _tidy(a_e.xreplace({S.e: e_}))
            if a_.is_positive is False:
                continue
            out.append((e_, a_))
    return out


def _bracket_root(fn, x0, step, lo=-mpmath.inf, hi=mpmath.inf, tries=80):
    """A root of an increasing (or decreasing) fn, bracketed by stepping
    out from x0 by doubling steps, then refined (Anderson-Bjorck)."""
    f0 = fn(x0)
    if f0 == 0:
        return x0
    left, right = x0, x0
    s = step
    for _ in range(tries):
        # step towards the sign change, both ways when unsure
        cand = []
        if right + s < hi:
            cand.append(right + s)
        if left - s > lo:
            cand.append(left - s)
        if not cand:
            break
        for c in cand:
            fc = fn(c)
            if fc == 0:
                return c
            if (fc > 0) != (f0 > 0):
                a_, b_ = (x0, c) if c > x0 else (c, x0)
                return root_in_bracket(fn, a_, b_)
        right, left = right + s, left - s
        s *= 2
    raise NoEquilibriumError("no root found by stepping out (the load or tilt is out of reach of this profile)")


def _bracket_positive(fn, a0, amax=mpmath.inf):
    """A root a in (0, amax] of fn, increasing in a: halve/double from a0."""
    lo, hi = a0, a0
    flo = fn(lo)
    k = 0
    while flo > 0 and k < 200:
        hi, lo = lo, lo / 2
        flo = fn(lo)
        k += 1
    fhi = fn(hi) if hi != lo else flo
    while fhi < 0 and k < 400:
        if hi >= amax:
            raise NoEquilibriumError("the contact reaches the end of its range")
        lo, hi = hi, min(2 * hi, amax)
        fhi = fn(hi)
        k += 1
    if flo > 0 or fhi < 0:
        raise NoEquilibriumError("no half-width found for this load")
    if fhi == 0:
        return hi
    return root_in_bracket(fn, lo, hi)


def _state(contact, n, e, a, theta, P0, regime, P, values):
    Kl, Kr = n.edge_factors(e, a, theta, P0)
    smooth_l = regime in ("bounded", "right corner")
    smooth_r = regime in ("bounded", "left corner")
    M = n.moment(e, a, theta, P0)
    load = n.P(e, a) + P0
    return AsymmetricState(contact, e - a, e + a, e, a, theta, load, M, P0,
                           ("smooth" if smooth_l else "corner", "smooth" if smooth_r else "corner"),
                           (mpmath.mpf(0) if smooth_l else Kl, mpmath.mpf(0) if smooth_r else Kr),
                           regime, dict(values))


def _solve(contact, n, P, given, values):
    lo, hi = (to_mpf(w) if w.is_finite else (mpmath.inf if w > 0 else -mpmath.inf) for w in contact.walls)
    core = contact.core
    kind, g = given
    tried = []
    scale = (hi - lo) / 4 if mpmath.isfinite(hi - lo) else mpmath.mpf(1)
    if core.even is not None:
        try:
            st = _bounded(contact, n, P, kind, g, values, scale)
            if st.left >= lo and st.right <= hi:
                return st
            tried.append(f"bounded [{mpmath.nstr(st.left, 8)}, {mpmath.nstr(st.right, 8)}] passes a wall")
        except NoEquilibriumError as err:
            tried.append(f"bounded: {err}")
    for side in ("right", "left"):
        wall = hi if side == "right" else lo
        if not mpmath.isfinite(wall):
            continue
        try:
            st = _one_corner(contact, n, P, kind, g, values, side, lo, hi)
        except NoEquilibriumError as err:
            tried.append(f"{side} corner: {err}")
            continue
        K = st.factors[1] if side == "right" else st.factors[0]
        if st.left >= lo and st.right <= hi and K >= 0:
            return st
        tried.append(f"{side} corner: [{mpmath.nstr(st.left, 8)}, {mpmath.nstr(st.right, 8)}], K = {mpmath.nstr(K, 5)}")
    if mpmath.isfinite(lo) and mpmath.isfinite(hi):
        st = _complete(contact, n, P, kind, g, values, lo, hi)
        if min(st.factors) >= 0:
            return st
        tried.append(f"complete: corner factors {mpmath.nstr(st.factors[0], 5)}, {mpmath.nstr(st.factors[1], 5)}")
    raise NoEquilibriumError(f"no contact state of {contact.name} at P = {mpmath.nstr(P, 10)}, {kind} = "
                             f"{mpmath.nstr(g, 10)}: " + "; ".join(tried))


def _bounded(contact, n, P, kind, g, values, scale):
    """Both edges smooth: for each centre e the half-width a(e) of P(e, a) = P
    (P rises with a), then theta(e, a(e)) = theta or M(e, a(e)) = M for e
    (stepping out from e = 0, or from the line of action M/P)."""
    memo = {}

    def half_width(e):
        if e not in memo:
            memo[e] = _bracket_positive(lambda a: n.P(e, a) - P, memo.get("last", scale))
            memo["last"] = memo[e]
        return memo[e]

    if kind == "theta":
        def residual(e):
            return n.tilt(e, half_width(e)) - g
        e0 = mpmath.mpf(0)
    else:
        def residual(e):
            return n.moment(e, half_width(e)) - g
        e0 = g / P
    e = _bracket_root(residual, e0, half_width(e0) / 4)
    a = half_width(e)
    return _state(contact, n, e, a, n.tilt(e, a), mpmath.mpf(0), "bounded", P, values)


def _one_corner(contact, n, P, kind, g, values, side, lo, hi):
    """A smooth free edge and a corner at the wall ``side``: K = 0 at the free edge."""
    sgn = 1 if side == "right" else -1        # e = wall - sgn a
    wall = hi if side == "right" else lo
    amax = (hi - lo) / 2 if mpmath.isfinite(hi - lo) else mpmath.inf

    def at(a):
        e = wall - sgn * a
        # K_free = 0: P0 = -sgn (dP_H - theta dP_2); load: P_E + P0 = P
        if kind == "theta":
            th = g
        else:   # theta from the load equation
            th = (sgn * (P - n.P(e, a)) + n.dP_H(e, a)) / n.dP_2(a)
        P0 = -sgn * (n.dP_H(e, a) - th * n.dP_2(a))
        return e, th, P0

    def residual(a):
        e, th, P0 = at(a)
        if kind == "theta":
            return n.P(e, a) + P0 - P
        return n.moment(e, a, th, P0) - g
    # theta given: the load rises with a; moment given: M falls as the contact spreads from the wall
    fn = residual if kind == "theta" else (lambda a: -sgn * residual(a))
    a = _bracket_positive(fn, amax / 2 if mpmath.isfinite(amax) else mpmath.mpf(1), amax * (1 + mpmath.eps * 8))
    e, th, P0 = at(a)
    return _state(contact, n, e, a, th, P0, f"{side} corner", P, values)


def _complete(contact, n, P, kind, g, values, lo, hi):
    e, a = (lo + hi) / 2, (hi - lo) / 2
    P0 = P - n.P(e, a)
    if kind == "theta":
        th = g
    else:   # M = e P + M_c, M_c = -(P_H - theta P_2)
        th = (g - e * P + n.P_H(e, a)) / n.P_2(a)
    return _state(contact, n, e, a, th, P0, "complete", P, values)


def flat_punch(w=S.b, **kw) -> AsymmetricLineContact:
    """The rigid flat punch of half-width w (walls at x = -w and x = w),
    tilted or under a moment: complete contact with corners at both ends
    while |M_c| <= P w/2, then one edge lifts (the bounded end).

    >>> import linecontact_sym as lcs
    >>> s = lcs.flat_punch(1).contact_at(P=1, theta=0, E_star=1)
    >>> s.edges
    ('corner', 'corner')
    """
    wv = user_value(w)
    wv = sp.sympify(wv, strict=True) if not isinstance(wv, sp.Basic) else wv
    if not (wv.is_number and wv.is_positive):
        raise ProfileError(f"the half-width of a flat punch must be a positive number, got {w!r}")
    return AsymmetricLineContact(sp.S.Zero, walls=(-wv, wv), name=f"flat punch of half-width {wv}", **kw)
