"""Viscoelastic histories at numbers (mpmath at the working precision).

One object does all of it: the **level history** Y(s) = Pi(a(s)) of the
loading phase [0, t_m] (Pi = P/E*, the engine's force law at E* = 1), with
its jump Y0 = Y(0+) (a step).  Every punch of half-width b enters when Y
reaches Pi(b) and relaxes with E*(t - t_b), so

    P(t) = E(t) min(y, Y0) + int_0^{s(y)} E(t - s) Y'(s) ds  [+ eta Y'(t) while loading],

with y = Pi(a(t)) and s(y) the loading time where Y(s) = y (s(y) = t while
loading: Lee-Radok; s(y) <= t_m after the maximum: Ting).  For a given
half-width history, Y(s) = Pi(a(s)); for a given load (creep), the loading
phase is Pi(a(s)) = X(s) = int_0^s J(s - u) dP(u) (the inverse of the
relaxation convolution) and the receding phase solves P(t) = F(y, t) for y.
"""
from __future__ import annotations

import mpmath
import sympy as sp

from ...core import symbols as S
from ...core.errors import DomainError, LineContactError
from ...core.quadrature import relational_breakpoints
from ...core.roots import Outside, golden_minimum
from ...parsing import to_sympy, user_value
from ..base import checked_value
from ..normal.equilibria import half_width_at
from ..normal.force_law import ForceLaw

#: points of the scan for the maximum of a history
SCAN = 256


class MultipleMaximaError(LineContactError, ValueError):
    """A history whose contact grows again after it has receded: Ting's
    single-maximum solution does not cover it."""


def quad_pieces(f, pts):
    pts = sorted(set(pts))
    if len(pts) < 2 or pts[-1] <= pts[0]:
        return mpmath.mpf(0)
    return mpmath.quad(f, pts)


class Numbers:
    """The force law at E* = 1 (``Pi``, ``dPi``, ``a_of``) and the material (``m``) at numbers."""

    def __init__(self, contact, material, values):
        pvals = {}
        for s in contact.variables:
            if s == S.E_star:
                continue
            if s.name not in values:
                raise DomainError(f"the profile needs a value for {s.name}")
            # a finite real number, positive where the symbol is declared so (R = -1: the profile upside down)
            pvals[s] = user_value(checked_value(s.name, values[s.name], s), s.name)
        self.pvals = pvals
        self.law = ForceLaw.from_contact(contact, {S.E_star: sp.Integer(1), **pvals})
        self.m = material.numeric(**{k: v for k, v in values.items() if k in {p.name for p in material.parameters}})

    def _law(self, f, A):
        try:
            return f(mpmath.mpf(A))
        except Outside:
            raise DomainError(f"the half-width a = {mpmath.nstr(A, 10)} is outside the range of the force law "
                              "(a periodic array: a < L/2; a condition of the profile)") from None

    def Pi(self, A):
        """P(a)/E* (>= 0: a compressive load, else no contact of half-width a without adhesion)."""
        if A <= 0:
            return mpmath.mpf(0)
        v = self._law(self.law.P, A)
        if v < 0:
            raise DomainError(f"the force law is negative at a = {mpmath.nstr(A, 10)} (P/E* = {mpmath.nstr(v, 8)}): "
                              "no compact contact of that half-width without adhesion")
        return v

    def dPi(self, A):
        """P'(a)/E*: >= 0, else the punch of half-width a pulls (the force law decreases:
        no compact contact of half-width a, and the superposition in time has a negative weight)."""
        if A <= 0:
            return mpmath.mpf(0)
        d = self._law(self.law.dP, A)
        if d < 0:
            raise DomainError(f"the force law decreases at a = {mpmath.nstr(A, 10)} (dP/da = {mpmath.nstr(d, 8)} E*): "
                              "no compact contact of that half-width; the superposition in time needs P(a) "
                              "increasing up to the largest a(t)")
        return d

    def a_of(self, y):
        """Pi^{-1}(y): the elastic half-width at the load y with E* = 1."""
        return mpmath.mpf(0) if y <= 0 else half_width_at(self.law, y, mpmath.mp.dps)


_CALLABLES = {}


def history_callable(expr, values, what):
    """(expression, f, f', f(0+)) of a history expression in t at numbers
    (remembered: an evaluation at many times or points builds them once)."""
    expr = history_expr(expr, what)
    key = (expr, tuple(sorted((k, str(v)) for k, v in values.items())), what, mpmath.mp.prec)
    if key not in _CALLABLES:
        if len(_CALLABLES) > 256:
            _CALLABLES.clear()
        _CALLABLES[key] = _history_callable(expr, values, what)
    return _CALLABLES[key]


def history_expr(expr, what="history"):
    """A history as the user gives it: a SymPy expression of ``lcs.t`` (text by the
    whitelisted parser, never eval; a number is a constant history)."""
    e = to_sympy(expr, f"the {what} history")
    if not isinstance(e, sp.Expr) or e.has(sp.nan, sp.zoo, sp.oo, -sp.oo, sp.I):
        raise DomainError(f"the {what} history must be a real expression of t, got {expr!r}")
    return e


def _real_finite(f, what):
    """f(t) checked: a finite real number at every time it is asked (a complex, infinite or
    undefined value of a history is an input error, never a number)."""
    def g(tv):
        try:
            v = f(tv)
        except (ZeroDivisionError, ValueError, TypeError, OverflowError):
            v = mpmath.nan
        if isinstance(v, mpmath.mpc):
            v = v.real if v.imag == 0 else mpmath.nan
        if not isinstance(v, mpmath.mpf):
            v = mpmath.mpf(v) if isinstance(v, (int, float)) else mpmath.nan
        if not mpmath.isfinite(v):
            raise DomainError(f"the {what} history is not a finite real number at t = {mpmath.nstr(tv, 10)}")
        return v
    return g


def refuse_jumps(f, breaks, scale, what):
    """A history that jumps up at a time t > 0 (a Piecewise whose pieces do not meet):
    refused.  The superposition in time reads its rate; a jump has none (the punches
    it loads at once would be lost: a wrong number), a jump at t = 0 is the step it
    takes.  A jump down is the receding phase's business (a(t) alone counts there)."""
    for b in breaks:
        if b <= 0:
            continue
        d = b * mpmath.mpf(10)**(-(mpmath.mp.dps * 2) // 3)
        lo, hi = f(b - d), f(b + d)
        if hi - lo > (abs(scale) + abs(hi)) * mpmath.mpf(10)**(-mpmath.mp.dps // 3):
            raise DomainError(f"the {what} history jumps up at t = {mpmath.nstr(b, 10)} ({mpmath.nstr(lo, 8)} -> "
                              f"{mpmath.nstr(hi, 8)}): a step is built at t = 0 only; give the rise as a steep ramp")


def start_value(expr):
    """lim_{t -> 0+} of a history (of its first Piecewise piece: SymPy's limit of
    a whole Piecewise goes through its sets, slowly)."""
    e = history_expr(expr)
    if isinstance(e, sp.Piecewise):
        tiny = sp.Rational(1, 10**40)
        for piece, cond in e.args:
            if cond is sp.true or bool(cond.subs(S.t, tiny)):
                e = piece
                break
    return sp.limit(e, S.t, 0, "+")


def _history_callable(expr, values, what):
    expr = history_expr(expr, what)             # a plain number is a step history (text parsed, never eval)
    sub = {sym: user_value(values[sym.name], sym.name) for sym in expr.free_symbols - {S.t} if sym.name in values}
    e = history_expr(expr, what).xreplace(sub)
    if e.free_symbols - {S.t}:
        raise DomainError(f"the {what} history needs values for {sorted(map(str, e.free_symbols - {S.t}))}")
    f = _real_finite(sp.lambdify(S.t, e, "mpmath"), what)
    df = _real_finite(sp.lambdify(S.t, sp.diff(e, S.t), "mpmath"), f"rate of the {what}")
    try:
        start = mpmath.mpf(sp.N(start_value(e), mpmath.mp.dps + 5))
    except (NotImplementedError, ValueError, TypeError):   # SymPy's limit fails (Min, ...): the value just after 0
        start = mpmath.re(f(mpmath.mpf(10)**(-mpmath.mp.dps - 5)))
    return e, f, df, start


def scan_maximum(f, lo, hi, breaks, what, least=None):
    """The time of the single maximum of f on [lo, hi] (None when f does not
    decrease there); :class:`MultipleMaximaError` when f grows again after
    it (seen on a scan of :data:`SCAN` points plus the breakpoints);
    a :class:`DomainError` where f < ``least`` on the scan (a half-width < 0)."""
    grid = sorted(set([lo + (hi - lo) * k / SCAN for k in range(SCAN + 1)] + [b for b in breaks if lo < b < hi]))
    vals = [f(g) for g in grid]
    if least is not None:
        k = next((k for k, v in enumerate(vals) if v < least), None)
        if k is not None:
            raise DomainError(f"the {what} is {mpmath.nstr(vals[k], 8)} < {mpmath.nstr(least, 8)} at t = "
                              f"{mpmath.nstr(grid[k], 8)}: a half-width is >= 0 at every time")
    scale = max(abs(v) for v in vals) or 1
    tol = scale * mpmath.mpf(10)**(-mpmath.mp.dps // 2)
    i = next((k for k in range(len(vals) - 1) if vals[k + 1] < vals[k] - tol), None)
    if i is None:
        return None
    for k in range(i + 1, len(vals) - 1):
        if vals[k + 1] > vals[k] + tol:
            raise MultipleMaximaError(
                f"the {what} grows again at t = {mpmath.nstr(grid[k], 6)} after its maximum near "
                f"t = {mpmath.nstr(grid[i], 6)}: more than one maximum is outside Ting's solution "
                "(one loading phase, one receding phase)")
    # refine the maximum on [grid[i-1], grid[i+1]]: golden section (a breakpoint there is a candidate)
    a_, b_ = grid[max(i - 1, 0)], grid[i + 1]
    cands = [g for g in (grid[i],) + tuple(b for b in breaks if a_ <= b <= b_)]
    # the location to half the bits (all that values near a maximum fix): the value to all of them
    tol = (b_ - a_) * mpmath.mpf(2)**(-(mpmath.mp.prec // 2))
    cands.append(golden_minimum(lambda v: -f(v), a_, b_, tol=tol))
    return max(cands, key=f)


def invert_increasing(f, target, lo, hi):
    """s in [lo, hi] with f(s) = target, f increasing: Illinois on the
    bracket (a few evaluations of an f that may be a quadrature), bisection
    where it leaves the bracket."""
    flo, fhi = f(lo) - target, f(hi) - target
    if flo >= 0:
        return lo
    if fhi <= 0:
        return hi
    side = 0
    for _ in range(mpmath.mp.prec + 10):
        # regula falsi with the Illinois halving, kept inside the bracket
        mid = hi - fhi * (hi - lo) / (fhi - flo) if fhi != flo else (lo + hi) / 2
        if not lo < mid < hi:
            mid = (lo + hi) / 2
        fm = f(mid) - target
        if abs(fm) <= (abs(target) + abs(fhi)) * mpmath.mpf(2)**(-mpmath.mp.prec + 6):
            return mid
        if fm < 0:
            lo, flo = mid, fm
            if side == -1:
                fhi /= 2
            side = -1
        else:
            hi, fhi = mid, fm
            if side == 1:
                flo /= 2
            side = 1
        if hi - lo <= (abs(hi) + abs(lo)) * mpmath.mpf(2)**(-mpmath.mp.prec + 6):
            break
    return (lo + hi) / 2


class Level:
    """The loading phase Y(s), Y'(s) on [0, t_m], its jump Y0 at s = 0+, and
    F(y, t) (see the module docstring)."""

    def __init__(self, num, Y, dY, Y0, t_m, breaks):
        self.num, self.Y, self.dY, self.Y0, self.t_m, self.breaks = num, Y, dY, Y0, t_m, list(breaks)
        self.inv_cache = {}

    def points(self, hi):
        return [mpmath.mpf(0)] + [b for b in self.breaks if 0 < b < hi] + [hi]

    def entry_time(self, y):
        """s(y): the loading time where Y reaches y (0 for y <= Y0)."""
        if y <= self.Y0:
            return mpmath.mpf(0)
        return invert_increasing(self.Y, y, mpmath.mpf(0), self.t_m)

    def F(self, y, t, loading: bool):
        """The force at time t with level y (Pi(a(t)) = y)."""
        m = self.num.m
        Et = m.E(t)
        out = Et * min(y, self.Y0)
        if y > self.Y0:
            s1 = t if loading else self.entry_time(y)
            out += quad_pieces(lambda s: m.E(t - s) * self.dY(s), self.points(s1))
        if loading and m.eta != 0:
            out += mpmath.mpf(sp.N(m.eta, mpmath.mp.dps + 5)) * self.dY(t)
        return out

    def G(self, s1, t):
        """F at the level Y(s1) in the receding phase (increasing in s1)."""
        m = self.num.m
        return m.E(t) * self.Y0 + quad_pieces(lambda s: m.E(t - s) * self.dY(s), self.points(s1))


# ---------------------------------------------------------------- half-width given: force, pressure
class HalfWidthHistory:
    """a(t) given: the level Y(s) = Pi(a(s)) and the single maximum of a."""

    def __init__(self, num, a_expr, values, t_end):
        self.num = num
        self.expr, self.a, self.da, self.a0 = history_callable(a_expr, values, "half-width")
        if self.a0 < 0:
            raise DomainError(f"the half-width history starts at a(0+) = {mpmath.nstr(self.a0, 8)} < 0")
        self.breaks = relational_breakpoints(self.expr, S.t, 0, t_end * 2) if self.expr.has(sp.Piecewise) else []
        refuse_jumps(self.a, self.breaks, self.a0, "half-width")
        self.t_m = scan_maximum(self.a, mpmath.mpf(0), mpmath.mpf(t_end), self.breaks, "half-width a(t)",
                                least=mpmath.mpf(0))
        t_m = self.t_m if self.t_m is not None else mpmath.mpf(t_end)
        self.level = Level(num, lambda s: num.Pi(self.a(s)), lambda s: num.dPi(self.a(s)) * self.da(s),
                           num.Pi(self.a0), t_m, self.breaks)

    def loading(self, t):
        return self.t_m is None or t <= self.t_m

    def force(self, t):
        A = self.a(t)
        if A <= 0:
            return mpmath.mpf(0)
        if self.loading(t):
            self.num.dPi(A)        # the edge's punch must push: P(a) increasing at a(t) (refused otherwise)
            return self.level.F(self.num.Pi(A), t, True)
        if A <= self.a0:
            return self.num.m.E(t) * self.num.Pi(A)
        s1 = invert_increasing(self.a, A, mpmath.mpf(0), self.level.t_m)
        return self.level.G(s1, t)

    def force_and_depth_level(self, t, log_w, loading=None):
        """(P(t), D(t)): the force and the 'elastic depth' D(t) = (2/pi) sum over the
        punches in contact at t of their force (E* units) times log_w(b), the depth
        weight of a flat punch of half-width b (one inversion of a(t) for both);
        ``loading`` forces the phase (the two sides of the maximum).  The Dirac part
        eta delta(t) of E*(t) (Kelvin-Voigt) adds eta Y'(t) to the force and
        eta Y'(t) log_w(a(t)) to D while the contact grows: the punch entering at t
        (Y' = dPi(a(t))/dt), the limit of E*(t - s) -> eta delta(t - s) at s = t."""
        num, m, lev = self.num, self.num.m, self.level
        A = self.a(t)
        if A <= 0:
            return mpmath.mpf(0), mpmath.mpf(0)
        loading = self.loading(t) if loading is None else loading
        if loading:
            num.dPi(A)                  # the edge's punch must push (refused otherwise), as in force()
        Et = m.E(t)
        P = Et * min(num.Pi(A), lev.Y0)
        top = min(A, self.a0)
        D = Et * mpmath.quad(lambda b: num.dPi(b) * log_w(b), [0, top]) if top > 0 else mpmath.mpf(0)
        if A > self.a0:
            s1 = t if loading else invert_increasing(self.a, A, mpmath.mpf(0), lev.t_m)
            pts = lev.points(s1)
            P += quad_pieces(lambda s: m.E(t - s) * lev.dY(s), pts)
            D += quad_pieces(lambda s: m.E(t - s) * lev.dY(s) * log_w(self.a(s)) if self.a(s) > 0 else mpmath.mpf(0),
                             pts)
            if loading and m.eta != 0:
                w = mpmath.mpf(sp.N(m.eta, mpmath.mp.dps + 5)) * lev.dY(t)
                P += w
                D += w * log_w(A)
        return P, 2 * D / mpmath.pi

    def pressure(self, x, t):
        """p(x, t): the punches b in (|x|, a(t)), each with E*(t - t_b)."""
        num, m = self.num, self.num.m
        x = abs(mpmath.mpf(x))
        A = self.a(t)
        if x >= A:
            return mpmath.mpf(0)
        loading = self.loading(t)
        out = mpmath.mpf(0)
        top = min(A, self.a0)
        if x < top:   # the punches of the step, all entered at t = 0
            out += m.E(t) * mpmath.quad(lambda b: num.dPi(b) / mpmath.sqrt(b * b - x * x), [x, top])
        if A > self.a0:
            s1 = t if loading else invert_increasing(self.a, A, mpmath.mpf(0), self.level.t_m)
            sx = invert_increasing(self.a, x, mpmath.mpf(0), s1) if x > self.a0 else mpmath.mpf(0)
            pts = [sx] + [b for b in self.breaks if sx < b < s1] + [s1]
            def g(s):
                A2 = self.a(s)**2 - x * x
                return m.E(t - s) * num.dPi(self.a(s)) * self.da(s) / mpmath.sqrt(A2) if A2 > 0 else mpmath.mpf(0)
            out += quad_pieces(g, pts)
            if loading and m.eta != 0:
                out += mpmath.mpf(sp.N(m.eta, mpmath.mp.dps + 5)) * num.dPi(A) * self.da(t) / mpmath.sqrt(A * A - x * x)
        return out / mpmath.pi


# ---------------------------------------------------------------- load given: creep
class LoadHistory:
    """P(t) given: the loading phase Pi(a(s)) = X(s) = (J * dP)(s) (X, X' from
    the closed form ``X_expr`` when there is one, else by quadrature) and the
    receding phase by Ting's rule."""

    def __init__(self, num, P_expr, X_expr, values, t_end):
        self.num = num
        self.expr, self.P, self.dP, self.P0 = history_callable(P_expr, values, "load")
        self.breaks = relational_breakpoints(self.expr, S.t, 0, t_end * 2) if self.expr.has(sp.Piecewise) else []
        m = num.m
        if X_expr is not None and not X_expr.has(sp.Integral, sp.InverseLaplaceTransform):
            _, self.X, self.dX, _ = history_callable(X_expr, values, "creep level")
        else:
            def X(s):
                return self.P0 * m.J(s) + quad_pieces(lambda u: m.J(s - u) * self.dP(u), [0] + [b for b in self.breaks if b < s] + [s])

            def dX(s, h=None):
                h = s * mpmath.mpf(10)**(-mpmath.mp.dps // 3)
                return mpmath.diff(X, s, h=h) if s > h else (X(s + h) - X(s)) / h
            self.X, self.dX = X, dX
        refuse_jumps(self.P, self.breaks, self.P0, "load")
        self.t_m = scan_maximum(self.X, mpmath.mpf(0), mpmath.mpf(t_end), self.breaks, "creep level J*dP (so a(t))")
        t_m = self.t_m if self.t_m is not None else mpmath.mpf(t_end)
        self.level = Level(num, self.X, self.dX, self.P0 * m.J(0), t_m, self.breaks)

    def half_width(self, t):
        if self.t_m is None or t <= self.t_m:
            return self.num.a_of(self.X(t))
        Pt, lev, m = self.P(t), self.level, self.num.m
        if Pt < 0:
            raise DomainError(f"the load is tensile at t = {mpmath.nstr(t, 8)} (P = {mpmath.nstr(Pt, 8)}): "
                              "no contact without adhesion")
        top = lev.G(lev.t_m, t)
        if Pt > top * (1 + mpmath.mpf(10)**(-mpmath.mp.dps // 2)):
            raise MultipleMaximaError(
                f"at t = {mpmath.nstr(t, 8)} the load {mpmath.nstr(Pt, 8)} exceeds what the largest contact carries "
                f"({mpmath.nstr(top, 8)}): the contact would grow again after receding (more than one maximum)")
        if Pt <= m.E(t) * lev.Y0:
            return self.num.a_of(Pt / m.E(t))
        s1 = invert_increasing(lambda s: lev.G(s, t), Pt, mpmath.mpf(0), lev.t_m)
        return self.num.a_of(self.X(s1))


__all__ = ["Numbers", "Level", "quad_pieces", "start_value", "history_expr", "refuse_jumps", "HalfWidthHistory", "LoadHistory", "MultipleMaximaError", "scan_maximum",
           "invert_increasing", "history_callable", "SCAN"]
