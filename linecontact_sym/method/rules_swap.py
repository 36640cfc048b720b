"""Pressure and gap by swapping the order of integration: closed forms for
piecewise profiles (flats, kinks, rounded corners, tangent-continuous joins)
and for algebraic profiles such as the exact cylinder and the ellipse.

Eq. (12) with Eq. (10*) inserted is a double integral over the half-widths s
and the profile points t.  Swapping the order (the s-integral is elementary)
and integrating by parts in t gives one integral of the profile itself
against an algebraic kernel (Soehngen's inversion of the finite Hilbert
transform; for |x| < a the t-integral is a Cauchy principal value at t = x):

    p(x; a) = (E*/pi) sqrt(a^2 - x^2) PV int_0^a t f'(t) / ((t^2 - x^2) sqrt(a^2 - t^2)) dt

and, for the gap outside (Eqs. 3/5 integrated by parts, the same swap, and
int_0^a dt/((x^2 - t^2) sqrt(a^2 - t^2)) = pi / (2 x sqrt(x^2 - a^2)) to
bring f(x) under the integral)

    g(x; a) = -(2/(pi E*)) P(a) acosh(x/a)
              + (2/pi) x sqrt(x^2 - a^2) int_0^a (f(x) - f(t)) / ((x^2 - t^2) sqrt(a^2 - t^2)) dt,

    P(a) = E* int_0^a t f'(t) / sqrt(a^2 - t^2) dt                      (10*).

Split at the profile's breakpoints, each piece of each integral is
algebraic in t when the profile's pieces are (polynomials, sqrt(A - B x^2)),
and :func:`~.legendre.reduce_integral` evaluates it: elementary functions for
polynomial pieces, Legendre's elliptic integrals F, E, Pi (complete for
single-piece profiles) for the circle and the ellipse.  The result is a
Piecewise over the regions of a (which piece holds the contact edge) and of
x (which piece holds x).  A kink needs no special term: the formulas hold f'
and f, not f''.
"""
from __future__ import annotations

import sympy as sp

from ..core import symbols as S
from .legendre import NotReducible, reduce_integral
from .rulebase import NotApplicable, Rule, Step
from .transforms import t

__all__ = ["PressureSwap", "GapSwap", "algebraic_pieces"]


def algebraic_pieces(profile) -> str | None:
    """None if every piece of the profile is algebraic in x with square roots
    of quadratics only (what :func:`~.legendre.reduce_integral` takes), else
    the reason (cheap: a look at the expression tree)."""
    if profile is None:
        return "no profile"
    for pc in profile.pieces:
        e = pc.expr
        if any(f.has(S.x) for f in e.atoms(sp.Function)):
            return f"profile piece {e} is transcendental in x"
        for p in e.atoms(sp.Pow):
            if not p.base.has(S.x) or p.exp.is_Integer:
                continue
            if p.exp.has(S.x) or not (p.exp.is_Rational and p.exp.q == 2):
                return f"profile piece {e} has the power {p}"
            if p.base == S.x:
                return f"profile piece {e} has the power {p}"
    return None


class _Regions:
    """The intervals of the profile's breakpoints 0 = e_0 < e_1 < ... < oo, and
    a numeric point of each region (a in piece J, x in piece I)."""

    def __init__(self, profile):
        self.profile = profile
        self.params = profile.sample_params()
        self.edges = [sp.S.Zero] + list(profile.breakpoints) + [sp.oo]
        self.num = [float(e.xreplace(self.params)) if e != sp.oo else float("inf") for e in self.edges]
        self.n = len(self.edges) - 1
        scales = [float(v) for v in self.params.values()] + [v for v in self.num[1:-1]]
        self.unit = min(scales) if scales else 1.0

    def _inside(self, lo, hi, frac):
        if hi == float("inf"):
            return lo + (1 + frac) * (lo if lo > 0 else self.unit / 4)
        return lo + frac * (hi - lo)

    def sample(self, J, I=None, where="inside"):
        a_v = self._inside(self.num[J], self.num[J + 1], 0.5) if self.n > 1 else self.unit / 4
        vals = dict(self.params)
        vals[S.a] = sp.Rational(a_v).limit_denominator(10**9)
        vals[S.E_star] = sp.S.One
        if I is not None:
            if where == "inside":
                lo, hi = self.num[I], min(self.num[I + 1], a_v)
            else:
                lo, hi = max(self.num[I], a_v), self.num[I + 1]
            vals[S.x] = sp.Rational(self._inside(lo, hi, 0.5)).limit_denominator(10**9)
        return vals

    def a_condition(self, J):
        return sp.Le(S.a, self.edges[J + 1]) if J + 1 < self.n else sp.true

    def x_condition(self, I, last):
        return sp.Lt(S.x, self.edges[I + 1]) if not last else sp.true

    def pieces_below(self, J):
        """(piece, lo, hi) of the pieces over [0, a] for a in region J."""
        for j in range(J + 1):
            pc = self.profile.pieces[j]
            yield pc, self.edges[j], (self.edges[j + 1] if j < J else S.a)


def _integral(h, lo, hi, sample, conds):
    h = sp.cancel(sp.sympify(h, strict=True))
    if h == 0:
        return sp.S.Zero
    try:
        return reduce_integral(h, t, S.a, lo, hi, sample, conds)
    except NotReducible as exc:
        raise NotApplicable(str(exc))


def _piecewise(branches):
    return branches[0][0] if len(branches) == 1 else sp.Piecewise(*branches)


class PressureSwap(Rule):
    """p(x; a) = (E*/pi) sqrt(a^2 - x^2) PV int_0^a t f'(t)/((t^2 - x^2) sqrt(a^2 - t^2)) dt
    (Eq. 12 with Eq. 10* inserted, integrations swapped), piece by piece of
    the profile by Legendre reduction: elementary or F, E, Pi."""

    name, transform = "pressure_swap", "pressure"

    def applies(self, problem):
        return algebraic_pieces(problem.profile)

    def run(self, problem):
        reg = _Regions(problem.profile)
        branches, conds = [], [sp.Lt(S.x, S.a)]
        for J in range(reg.n):
            for I in range(J + 1):
                sample = reg.sample(J, I, "inside")
                total = sp.S.Zero
                for pc, lo, hi in reg.pieces_below(J):
                    h = t * pc.derivative.xreplace({S.x: t}) / (t**2 - S.x**2)
                    total += _integral(h, lo, hi, sample, conds)
                expr = S.E_star / sp.pi * sp.sqrt(S.a - S.x) * sp.sqrt(S.a + S.x) * total
                cond = sp.And(reg.a_condition(J), reg.x_condition(I, I == J))
                branches.append((expr, cond))
        kind = "elliptic integrals" if _has_elliptic(branches) else "elementary"
        branches = _edge_limits(branches, reg) + branches
        return Step(self.name, _piecewise(branches), tuple(conds),
                    (f"Eq. (12) after Eq. (10*), integrations swapped, Legendre reduction per piece ({kind})",))


class GapSwap(Rule):
    """g(x; a) = -(2/(pi E*)) P(a) acosh(x/a) + (2/pi) x sqrt(x^2 - a^2)
    int_0^a (f(x) - f(t))/((x^2 - t^2) sqrt(a^2 - t^2)) dt, P(a) from Eq. (10*)
    by the same reduction (Eqs. 3/5 by parts, integrations swapped)."""

    name, transform = "gap_swap", "gap"

    def applies(self, problem):
        return algebraic_pieces(problem.profile)

    def run(self, problem):
        reg = _Regions(problem.profile)
        branches, conds = [], [sp.Gt(S.x, S.a)]
        for J in range(reg.n):
            sample = reg.sample(J)
            P = S.E_star * sum((_integral(t * pc.derivative.xreplace({S.x: t}), lo, hi, sample, conds)
                                for pc, lo, hi in reg.pieces_below(J)), sp.S.Zero)
            for I in range(J, reg.n):
                sample = reg.sample(J, I, "outside")
                fx = problem.profile.pieces[I].expr
                total = sp.S.Zero
                for pc, lo, hi in reg.pieces_below(J):
                    h = (fx - pc.expr.xreplace({S.x: t})) / (S.x**2 - t**2)
                    total += _integral(h, lo, hi, sample, conds)
                expr = -2 / (sp.pi * S.E_star) * P * sp.acosh(S.x / S.a) \
                    + 2 / sp.pi * S.x * sp.sqrt(S.x - S.a) * sp.sqrt(S.x + S.a) * total
                cond = sp.And(reg.a_condition(J), reg.x_condition(I, I == reg.n - 1))
                branches.append((expr, cond))
        kind = "elliptic integrals" if _has_elliptic(branches) else "elementary"
        conds += [sp.Gt(sp.factor(p.base), 0) for e, _ in branches for p in e.atoms(sp.Pow)
                  if p.exp.is_Rational and p.exp.q == 2 and p.base.has(S.x) and not p.base.has(S.a)
                  and sp.Gt(sp.factor(p.base), 0) not in conds]
        if any(_undefined_at_edge(e) for e, _ in branches):
            # Pi(a^2/x^2|m) diverges at the edge, where the gap is 0 (g(a) = 0)
            branches.insert(0, (sp.S.Zero, sp.Eq(S.x, S.a)))
        return Step(self.name, _piecewise(branches), tuple(dict.fromkeys(conds)),
                    (f"Eqs. (3)/(5) by parts after Eq. (10*), integrations swapped, Legendre reduction "
                     f"per piece ({kind})",))


#: what a value that is not finite has in it
_INFINITE = (sp.nan, sp.zoo, sp.oo, -sp.oo)


def _edge_limits(branches, reg):
    """Branches for x at an interior breakpoint e where the formula is 0/0 or
    inf - inf but the pressure is finite (a tangent-continuous join: the log
    singularities of the two sides cancel): the limit x -> e-.  At a kink
    the pressure is infinite there, and the formula says so: a jump D != 0
    of f' at e puts (E*/pi) D log|x - e| / 2 into p (Eq. 12: the principal
    value of a step), so no limit is taken where the jump is provably not 0
    (the worn cylinder: 2 CPU s of gruntz for an infinite limit)."""
    out = []
    k = 0
    for J in range(reg.n):
        for I in range(J + 1):
            e, cond = branches[k]
            k += 1
            if I == J:
                continue
            edge = reg.edges[I + 1]
            at = e.xreplace({S.x: edge})
            if not at.has(*_INFINITE):
                continue
            pieces = reg.profile.pieces
            jump = sp.cancel((pieces[I + 1].derivative - pieces[I].derivative).xreplace({S.x: edge}))
            if jump.is_zero is False:     # a kink: the pressure is infinite at e
                continue
            lim = _join_limit(e, edge, reg.sample(J))
            if lim is not None:
                lim = _logs_expanded_above(lim, reg.edges[J])
            if lim is None:
                try:
                    lim = sp.limit(e, S.x, edge, "-")
                except (NotImplementedError, ValueError, TypeError):
                    continue
            if not lim.has(*_INFINITE, sp.Limit):
                out.append((lim, sp.And(sp.Gt(S.a, reg.edges[J]), reg.a_condition(J), sp.Eq(S.x, edge))))
    return out


#: the functions of x a branch may hold for :func:`_join_limit`: log and atanh (expanded at the
#: join where singular) and functions continuous wherever their argument is finite and real
_CONTINUOUS = (sp.log, sp.atanh, sp.asin, sp.acos, sp.atan, sp.asinh, sp.acosh)


def _value_at(expr, values):
    """``expr`` at exact sample values, as a complex number of 30 digits (None: not finite)."""
    v = sp.N(expr.xreplace(values), 30)
    if v.has(*_INFINITE) or not v.is_number:
        return None
    return complex(v)


def _is_zero(expr) -> bool:
    """Provably 0 (``cancel``, else ``simplify``)."""
    return sp.cancel(expr) == 0 or sp.simplify(expr) == 0


def _taylor_lead(u, edge, values, kmax=4):
    """u(x) - u(e) = c (x - e)^m + O((x - e)^(m+1)): (m, c) with c != 0 (c's
    derivatives' values at the sample are not 0, so c is not identically 0;
    those before it are proven 0), or None."""
    d = u
    for m in range(1, kmax + 1):
        d = d.diff(S.x)
        c = d.xreplace({S.x: edge}) / sp.factorial(m)
        if c.has(*_INFINITE):
            return None
        v = _value_at(c, values)
        if v is None:
            return None
        if abs(v) > 1e-20:
            return m, c
        if not _is_zero(c):
            return None
    return None


def _join_limit(e, edge, values):
    """lim_{x -> e-} of a branch whose logarithms (log, atanh) are singular at
    x = e, exactly, without ``sympy.limit`` (gruntz on atanh's leading terms
    took 6 of the 12 CPU s of a rounded wedge's pressure): each singular
    log(u), u ~ c (x - e)^m, is log(c (-1)^m) + m L + o(1), and each
    atanh(u) with u(e) = s = +-1, 1 - s u ~ d (e - x)^m (d > 0: |u| < 1 left of
    e, where atanh(u) = (log(1 + u) - log(1 - u))/2 holds), is
    s (log 2 - log d - m L)/2 + o(1), with L = log(e - x).  The branch is then
    F(x) + C(x) L + o(1); where C(e) = 0 (proven: the log coefficients of the
    two sides cancel, a tangent-continuous join), C' is finite at e (so
    C(x) L -> 0) and F is continuous at e (no denominator, log or atanh
    argument of F vanishes there identically: not 0 at the sample values),
    the limit is F(e).  None where any of this does not hold (the caller
    takes ``sympy.limit``).  ``values``: exact values of the parameters and
    of a in the branch's region, only to tell a non-zero coefficient (which
    is then not identically 0) and the sign of d.  Only for branches whose
    functions of x are log, atanh and the continuous inverse functions
    (:data:`_CONTINUOUS`)."""
    if any(f.has(S.x) and not isinstance(f, _CONTINUOUS) for f in e.atoms(sp.Function)):
        return None                         # elliptic Pi(n|m) (infinite at n = 1), Piecewise ...: sympy.limit
    L = sp.Dummy("L")
    at = {S.x: edge}
    rep = {}
    for A in e.atoms(sp.atanh, sp.log):
        u = A.args[0]
        u0 = u.xreplace(at)
        v0 = _value_at(u0, values)
        if v0 is None:
            return None
        target = 0 if isinstance(A, sp.log) else (1 if v0.real > 0 else -1)
        if abs(v0 - target) > 1e-20:
            continue                        # not singular at e (u(e) != target at the sample)
        if not _is_zero(u0 - target):
            return None
        lead = _taylor_lead(u, edge, values)
        if lead is None:
            return None
        m, c = lead
        if isinstance(A, sp.log):
            rep[A] = sp.log(c * (-1)**m) + m * L
            continue
        d = -target * c * (-1)**m               # 1 - s u = -s c (x - e)^m = d (e - x)^m
        dv = _value_at(d, values)
        if dv is None or abs(dv.imag) > 1e-20 or dv.real <= 0:
            return None
        rep[A] = target * (sp.log(2) - sp.log(d) - m * L) / 2
    if not rep:
        return None
    f = e.xreplace(rep)
    C = f.diff(L)
    if C.has(L) or not _is_zero(C.xreplace(at)) or C.diff(S.x).xreplace(at).has(*_INFINITE):
        return None
    F = f.xreplace({L: 0})
    lim = F.xreplace(at)
    if lim.has(*_INFINITE):
        return None
    for w in F.atoms(sp.Pow, sp.log, sp.atanh):
        z = w.base if isinstance(w, sp.Pow) else w.args[0]
        if isinstance(w, sp.Pow) and not (w.exp.is_negative or not w.exp.is_Integer):
            continue
        if not z.has(S.x):
            continue
        v = _value_at(z.xreplace(at), values)
        if v is None or abs(v) < 1e-20 or (isinstance(w, sp.atanh) and abs(abs(v) - 1) < 1e-20):
            return None
    return lim


def _logs_expanded_above(expr, lower):
    """``expr`` with each logarithm expanded over the factors of its argument
    where a > ``lower`` (the region of the branch): with a = lower + t,
    t > 0, SymPy sees the sign of factors such as a - b and a + b, and
    splits the log only over factors it proves positive (no ``force``).
    :func:`_join_limit`'s logs of derivatives at the join
    (b log(1/(a - b)) - b log(1/(a^2 - b^2)) + ...) then cancel to what the
    tidying writes as log(b^(2b)/a^(2b)), as ``sympy.limit``'s result did."""
    t = sp.Dummy("t", positive=True)

    def split(L):
        inner = sp.factor(L.args[0].xreplace({S.a: lower + t}))
        return sp.expand_log(sp.log(inner), deep=True).xreplace({t: S.a - lower})
    logs = {L: split(L) for L in expr.atoms(sp.log) if L.has(S.a)}
    return sp.expand_mul(expr.xreplace(logs)) if logs else expr


def _undefined_at_edge(e):
    """Is the branch 0 * infinity at x = a (a Pi(1|m))?"""
    v = e.xreplace({S.x: S.a})
    return v.has(sp.nan, sp.zoo) or any(sp.simplify(p.args[0] - 1) == 0 for p in v.atoms(sp.elliptic_pi))


def _has_elliptic(branches):
    return any(e.has(sp.elliptic_k, sp.elliptic_e, sp.elliptic_f, sp.elliptic_pi) for e, _ in branches)
