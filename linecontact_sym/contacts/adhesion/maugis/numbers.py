"""Numbers of a Maugis-Dugdale line contact at given parameter values: the
cohesive-zone half-width c_D(a) (unique, bracketed), the load P(a), its
total derivative dP/da, the state (pressure, gap) and the limit a -> 0+
(the zone c0 of a vanishing contact, P(0+) = -2 sigma_0 c0).

Closed or not: the two conditions are lambdified where the engine found P0,
g0 and p0 in closed form; otherwise P0 and dP0/da come from the normal
contact's ForceLaw (closed with its quadrature fallback, or Eq. 10* by
quadrature) and g0(c; a) with its partial derivatives from :class:`QuadGap`
(the defining integral, by parts, in s = c sin(theta)), at the working
precision of the solve plus the digits its cancellation costs.  The root
c_D stays inside the profile's real domain (:func:`profile_end`).

Uniqueness of c_D(a): the Dugdale part of the gap at c_D,
(4 sigma_0/(pi E*)) (sqrt(c^2 - a^2) acosh(c/a) - c log(c/a)), has the
c-derivative (4 sigma_0/(pi E*)) (c acosh(c/a)/sqrt(c^2 - a^2) - log(c/a)) > 0
(acosh(c/a) >= log(c/a), c > sqrt(c^2 - a^2)), rising from 0 at c = a to oo;
the adhesionless gap g0(c; a) rises from 0 wherever the profile is admissible
(f rising): one root, found from a bracket [a + s_lo, a + s_hi] with
gap(s_lo) < h0 < gap(s_hi) by safeguarded Newton in s = c_D - a (never leaves
the bracket, so never a wrong branch).

The pull-off, the equilibria and the jump-in are the generic layer's
(:mod:`~linecontact_sym.contacts.normal.equilibria` over the ForceLaw that
:meth:`.law.MaugisDugdale.numeric` builds on this law, with its scan hint).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import mpmath
import sympy as sp

from ....core import symbols as S
from ....core.conversion import float_values, number
from ....core.errors import DomainError, NoPullOffError, VerificationError
from ....core.precision import workdps
from ....core.roots import UNDEFINED, Outside, domain_end, real_value
from ....method.transforms import inside
from ....numeric.arb_functions import lambdify_law

@dataclass
class MDState:
    """The Maugis-Dugdale contact at one half-width a.

    a, c_D     contact and cohesive-zone half-widths (c_D > a)
    force      P(a) per unit length (negative = tensile)
    dP_da      the total derivative along c_D(a)
    h0         the range of the Dugdale law, w/sigma_0
    m          c_D/a (Baney & Hui's m)
    pressure   x -> p(x) (compressive positive; -sigma_0 in the Dugdale zone, 0 beyond)
    gap        x -> surface separation (0 in the contact, h0 at x = c_D)
    closed     which non-adhesive parts the engine found in closed form
               ({'P0(a)': True, 'g0(c_D; a)': False, ...}); the others are
               evaluated by quadrature inside the solve, at the digits asked
    gap_check  where g0 is not closed: the gap at c_D recomputed through the one
               reference integrator (a RefValue: an Arb enclosure where Arb can,
               ``gap_check.method``), to compare with h0; else None
    model      which model answered: 'Maugis-Dugdale' (the inner solve) or 'JKR limit'
               (:func:`.limits.limit_model`: force and slope from the JKR law, c_D from the
               bounds of the zone, each within 10**-(dps+1) by the bound ``note`` states)
    note       how the state was obtained
    """

    a: mpmath.mpf
    c_D: mpmath.mpf
    force: mpmath.mpf
    dP_da: mpmath.mpf
    h0: mpmath.mpf
    pressure: object = field(repr=False, default=None)
    gap: object = field(repr=False, default=None)
    closed: dict = field(repr=False, default_factory=dict)
    gap_check: object = field(repr=False, default=None)
    model: str = "Maugis-Dugdale"
    note: str = field(repr=False, default="")

    @property
    def m(self):
        return self.c_D / self.a


def fixed_values(vals, digits=80):
    """{Symbol: Float} of numeric values given exactly, as expressions (pi**(2/3)/4 ...) or as
    Python/mpmath numbers: the package's converter, then Floats for substitution."""
    return float_values({k: v if isinstance(v, sp.Basic) else number(v) for k, v in vals.items()}, digits)


def profile_kinks(profile, fixed):
    """The profile's breakpoints (kinks of P(a)) at numeric parameters, ascending."""
    out = []
    for pc in profile.pieces:
        if pc.lo != 0:
            v = sp.N(pc.lo.xreplace(fixed), 40)
            if v.is_number and v > 0:
                out.append(mpmath.mpf(str(v)))
    return sorted(set(out))


def _lam(expr, args):
    """``expr`` as an mpmath function of ``args`` (a form with Bessel functions in Arb, the
    others with Bessel and elliptic Pi through Arb: the law is evaluated thousands of times
    in a pull-off search; :func:`~linecontact_sym.numeric.arb_functions.lambdify_law`)."""
    return lambdify_law(args, expr)


def _real(fn):
    """``fn`` returning a finite real mpf, else :class:`~linecontact_sym.core.roots.Outside`."""
    def g(*args):
        try:
            return real_value(fn(*args))
        except UNDEFINED:
            raise Outside
    return g


def profile_end(f):
    """Where the profile f stops being real (mpf at 50 digits; the exact
    cylinder R - sqrt(R^2 - x^2) at x = R), or None when it is real on
    (0, 2**200): a cohesive zone cannot reach past it."""
    with workdps(50):
        good = None
        for k in range(-60, 201):
            X = mpmath.mpf(2)**k
            try:
                f(X)
                good = X
            except UNDEFINED:
                if good is None:
                    continue
                return domain_end(f, good, X, iters=200)
        return None


def profile_rise_end(f1):
    """Where the profile stops rising: the first x at which f' turns negative (mpf at 30 digits;
    1 - cos(x) at x = pi), found on the doubling grid 2**k, k = -60..200, and refined by bisection
    of the sign of f'; None where f' >= 0 at every grid point.  A cohesive zone ending beyond it
    would leave the uniqueness of c_D (module docstring: g0 rises where f does): the gap condition
    has a root in every rise of the profile, and a zone reaching over a trough (where the profile
    comes back towards the other surface) is not one Dugdale zone."""
    with workdps(30):
        good = None
        for k in range(-60, 201):
            X = mpmath.mpf(2)**k
            try:
                v = f1(X)
            except (Outside, *UNDEFINED):
                continue
            if v < 0:
                if good is None:
                    return None       # falling from the start: not a contact profile, refused elsewhere
                lo, hi = good, X
                for _ in range(120):
                    mid = (lo + hi) / 2
                    try:
                        falling = f1(mid) < 0
                    except (Outside, *UNDEFINED):
                        falling = True
                    lo, hi = (lo, mid) if falling else (mid, hi)
                return lo
            good = X
        return None


def _rounded(n):
    """``n`` working digits rounded up to a multiple of 10: mpmath's Gauss-Legendre nodes are cached per
    precision, and a solve whose digits vary with c_D by one or two would recompute them at each call."""
    return -(-int(n) // 10) * 10


class QuadGap:
    """The adhesionless gap g0(c; a) = f(c) - (2/(pi E*)) int_0^a acosh(c/s) P0'(s) ds
    (Eqs. 3/5; :func:`~linecontact_sym.method.transforms.gap_integral`) and its
    partial derivatives at numbers, where the engine has no closed form.  By
    parts, int_0^a acosh(c/s) P0'(s) ds = acosh(c/a) P0(a) + int_0^a c P0(s)/(s sqrt(c^2 - s^2)) ds,
    and s = c sin(theta) leaves int_0^theta_a P0(c sin theta)/sin(theta) dtheta:
    analytic on [0, theta_a] for an analytic profile (P0 ~ s^2 at 0) however close
    c is to a, so Gauss-Legendre converges fast; likewise
    dg0/dc = f'(c) - (2/(pi E*)) int_0^theta_a P0'(c sin theta) dtheta.  A profile
    with breakpoints below a is split there (tanh-sinh on each piece: P0 has a
    (s - b)^(3/2) point).  Each integral runs at the working precision plus the
    digits lost to the cancellation f(c) - (...) relative to h0, the size of the
    gap that matters."""

    def __init__(self, f, f1, P0, dP0, breaks, E, h0):
        self.f, self.f1, self.P0, self.dP0, self.breaks = f, f1, P0, dP0, list(breaks)
        self.E, self.h0 = E, h0
        # E* at each working precision and |h0| at 15 digits, made once (SymPy's evalf, not per call)
        self._E_at, self._h15 = {}, None

    def _pieces(self, A, C):
        """theta at the breakpoints below A and at A (the last one without asin(A/C) near 1)."""
        ends = [mpmath.asin(b / C) for b in self.breaks if b < A]
        ends.append(mpmath.atan2(A, mpmath.sqrt((C - A) * (C + A))))
        return [mpmath.mpf(0)] + ends

    def _integral(self, g, A, C):
        """int_0^theta_a g(theta) dtheta, split at the breakpoints."""
        pts = self._pieces(A, C)
        if len(pts) == 2:
            return mpmath.quad(g, pts, method="gauss-legendre")
        total = mpmath.mpf(0)
        for lo, hi in zip(pts[:-1], pts[1:]):
            total += mpmath.quad(inside(g, lo, hi), [lo, hi])
        return total

    def _extra(self, C):
        with workdps(15):
            fC = abs(self.f(mpmath.mpf(C)))
            if self._h15 is None:
                self._h15 = abs(mpmath.mpf(sp.N(self.h0, 15)))
            h = self._h15
            extra = 6 + (int(mpmath.log10(fC / h)) if fC > h else 0)
        capped_dps(mpmath.mp.dps + extra, f"the adhesionless gap g0(c; a) at c = {mpmath.nstr(C, 8)} (f(c) = "
                   f"{mpmath.nstr(fC, 5)} cancels down to h0 = {mpmath.nstr(h, 5)})")
        return extra

    def _E(self):
        key = mpmath.mp.prec
        if key not in self._E_at:
            self._E_at[key] = mpmath.mpf(sp.N(self.E, mpmath.mp.dps + 5))
        return self._E_at[key]

    def g(self, A, C):
        """g0(C; A)."""
        with workdps(_rounded(mpmath.mp.dps + self._extra(C))):
            A, C = mpmath.mpf(A), mpmath.mpf(C)
            def integrand(th):
                sin = mpmath.sin(th)
                return self.P0(C * sin) / sin
            I = mpmath.acosh(C / A) * self.P0(A) + self._integral(integrand, A, C)
            v = self.f(C) - 2 * I / (mpmath.pi * self._E())
        return +v

    def g_c(self, A, C):
        """dg0/dc = f'(c) - (2/(pi E*)) int_0^a P0'(s)/sqrt(c^2 - s^2) ds."""
        with workdps(_rounded(mpmath.mp.dps + self._extra(C))):
            A, C = mpmath.mpf(A), mpmath.mpf(C)
            I = self._integral(lambda th: self.dP0(C * mpmath.sin(th)), A, C)
            v = self.f1(C) - 2 * I / (mpmath.pi * self._E())
        return +v

    def g_a(self, A, C):
        """dg0/da = -(2/(pi E*)) acosh(c/a) P0'(a)."""
        return -2 / (mpmath.pi * self._E()) * mpmath.acosh(C / A) * self.dP0(A)


#: the most digits a Maugis-Dugdale solve may work at (a cancellation needing more is refused, never
#: handed to GMP: the cosh profile at sigma_0 = 1e-6 once asked for 3.5 GB)
WORK_DPS_CAP = 3000


def capped_dps(n, what):
    """``n`` working digits, or a :class:`DomainError` naming ``what`` needs them when above
    :data:`WORK_DPS_CAP`."""
    if n > WORK_DPS_CAP:
        raise DomainError(f"{what}: it needs {int(n)} working digits, more than the cap of {WORK_DPS_CAP} of the "
                          f"Maugis-Dugdale solve; the parameters are too extreme for it (at a large Maugis "
                          f"parameter the JKR law, contact.adhesive(w), is the model; at a small one the rigid "
                          f"Dugdale limit, maugis.check.rigid_limit)")
    return int(n)


#: relative Newton step at which the working-precision estimate of c_D - a stops (c_of)
ESTIMATE_TOL = mpmath.mpf(10)**-7


class MDLaw:
    """P(a, c_D) and the gap condition at numeric values (closed forms
    lambdified for mpmath; their partial derivatives by SymPy)."""

    def __init__(self, md, vals: dict):
        fixed = fixed_values(vals)
        self.md = md
        a, c, x = S.a, S.c_D, S.x
        sig = md.sigma0.xreplace(fixed)
        w = md.w.xreplace(fixed)
        if not (sig.is_number and w.is_number):
            raise DomainError("sigma_0 and the work of adhesion need values")
        if not sig > 0:
            raise DomainError(f"sigma_0 must be positive, got {sig}")
        if not w > 0:
            raise NoPullOffError("no adhesion (w = 0): no Dugdale zone, no tensile pull-off")
        self.fixed = fixed
        self.sigma0 = sig
        self.h0expr = w / sig
        E = fixed[S.E_star]
        self.E = E
        d = md.dugdale
        # which parts of the two conditions the engine found in closed form (the rest by quadrature here)
        fd, gd, pd = (md.contact.derivation(q) for q in ("force", "gap", "pressure"))
        self.closed_parts = {"P0(a)": fd.closed_form, "g0(c_D; a)": gd.closed_form, "p0(x; a)": pd.closed_form}
        self.closed = all(self.closed_parts.values())
        pf = {k: v for k, v in fixed.items() if k != S.E_star}
        self._f = _real(_lam(md.profile.expr.xreplace(pf), (x,)))
        self.x_end = profile_end(self._f)
        self.x_rise = profile_rise_end(_real(_lam(sp.diff(md.profile.expr.xreplace(pf), x), (x,))))
        if self.x_rise is not None and (self.x_end is None or self.x_rise < self.x_end):
            self.x_end, self.end_kind = self.x_rise, "rise"
        else:
            self.end_kind = "domain"
        if self.closed:
            P = md.force_expr.xreplace(fixed)
            G = md.gap_c_expr.xreplace(fixed) - self.h0expr
            self._P = _lam(P, (a, c))
            P0 = fd.expr.xreplace(fixed)
            self._P0, self._dP0 = _lam(P0, (a,)), _lam(sp.diff(P0, a), (a,))
            self._Pa = _lam(sp.diff(P, a), (a, c))
            self._Pc = _lam(sp.diff(P, c), (a, c))
            self._G = _lam(G, (a, c))
            self._Ga = _lam(sp.diff(G, a), (a, c))
            self._Gc = _lam(sp.diff(G, c), (a, c))
            self._p_in = _lam(md.pressure_expr.xreplace(fixed), (x, a, c))
            self._g0 = _lam(gd.expr.xreplace(fixed), (x, a))
        else:
            self._numeric_parts(fixed, fd, gd, pd)
        z0 = md.zero_width_expr.xreplace(fixed) - self.h0expr   # gap condition of a vanishing contact, in c_D
        self._Z0, self._Z0c = _lam(z0, (c,)), _lam(sp.diff(z0, c), (c,))
        self._P0lim = _lam(md.force_zero_width_expr.xreplace(fixed), (c,))
        self.kinks = profile_kinks(md.profile, fixed)
        self._warm = None
        self._c0_15 = None

    def _numeric_parts(self, fixed, fd, gd, pd):
        """P(a, c_D), the gap condition and their partial derivatives where the
        engine left P0, g0 or p0 as an Integral: the Dugdale parts (always closed)
        plus the non-adhesive ones at numbers -- P0 and dP0/da from the normal
        contact's ForceLaw (the closed form, or Eq. 10* by quadrature), the gap
        g0(c; a) = f(c) - (2/(pi E*)) int_0^a acosh(c/s) P0'(s) ds and its
        c-derivative f'(c) - (2/(pi E*)) int_0^a P0'(s)/sqrt(c^2 - s^2) ds by
        quadrature after s = c sin(theta) (both integrands smooth at s = a however
        close c_D is to a; acosh(c/s) = log(cot(theta/2)) keeps its digits there),
        and dg0/da = -(2/(pi E*)) acosh(c/a) P0'(a) (closed in P0')."""
        from ...normal.force_law import ForceLaw
        from ....method import transforms as T
        md = self.md
        a, c, x = S.a, S.c_D, S.x
        d = md.dugdale
        pf = {k: v for k, v in fixed.items() if k != S.E_star}
        base = ForceLaw.from_contact(md.contact, fixed, "closed")
        self.base = base
        P0, dP0 = base.P, base.dP
        self._P0, self._dP0 = P0, dP0
        D = d.force.xreplace(fixed)
        fD, fDa, fDc = _lam(D, (a, c)), _lam(sp.diff(D, a), (a, c)), _lam(sp.diff(D, c), (a, c))
        gD = d.gap_at_c.xreplace(fixed)
        hDf = _lam(gD - self.h0expr, (a, c))
        gDa, gDc = _lam(sp.diff(gD, a), (a, c)), _lam(sp.diff(gD, c), (a, c))
        pD = _lam(d.pressure.xreplace(fixed), (x, a, c))
        f1 = _real(_lam(sp.diff(md.profile.expr.xreplace(pf), x), (x,)))
        breaks = [mpmath.mpf(str(sp.N(b, 60))) for b in base.breaks_exact]
        gap = QuadGap(self._f, f1, P0, dP0, breaks, self.E, self.h0expr)
        self._P0_expr = fd.expr.xreplace(fixed) if fd.closed_form else None
        self._gD_expr = gD
        self.quad_gap = gap
        self._P = lambda A, C: P0(A) + fD(A, C)
        self._Pa = lambda A, C: dP0(A) + fDa(A, C)
        self._Pc = fDc
        self._G = lambda A, C: gap.g(A, C) + hDf(A, C)
        self._Ga = lambda A, C: gap.g_a(A, C) + gDa(A, C)
        self._Gc = lambda A, C: gap.g_c(A, C) + gDc(A, C)
        if pd.closed_form:
            p0 = _lam(pd.expr.xreplace(fixed), (x, a))
        else:
            def p0(X, A):
                return T.pressure_quad(dP0, [b for b in breaks if b < A], {S.a: A, S.x: X}, mpmath.mp.dps)
        self._p_in = lambda X, A, C: p0(X, A) + pD(X, A, C)
        self._g0 = lambda X, A: gap.g(A, X)

    # ------------------------------------------------------------ c_D(a)
    def h0(self):
        return mpmath.mpf(sp.N(self.h0expr, mpmath.mp.dps + 5))

    def _s_max(self, A):
        """The largest c_D - a the profile allows (its real domain ends at x_end), or None."""
        if self.x_end is None:
            return None
        if not A < self.x_end:
            what = "the crest where the profile stops rising" if self.end_kind == "rise" else \
                "the end of the profile's real domain"
            raise DomainError(f"the half-width a = {mpmath.nstr(A, 8)} reaches {what}, x = "
                              f"{mpmath.nstr(self.x_end, 8)}: no cohesive zone beyond it")
        return (self.x_end - A) * (1 - mpmath.mpf(10)**-(mpmath.mp.dps - 5))

    def _beyond_end(self, where):
        """The message of a cohesive zone that would have to reach past :attr:`x_end`."""
        if self.end_kind == "rise":
            return (f"the cohesive zone would need to reach past x = {mpmath.nstr(self.x_end, 10)}, where the profile "
                    f"stops rising (f' < 0 beyond, f there = {mpmath.nstr(self._f(self.x_end), 6)}){where}: the gap "
                    f"there is still below h0 = w/sigma_0 = {mpmath.nstr(self.h0(), 6)}; beyond a crest the gap "
                    f"condition has a root in every rise of the profile and one Dugdale zone no longer describes "
                    f"the contact (a larger sigma_0 or a smaller work of adhesion keeps the zone before the crest)")
        return (f"the cohesive zone would need to reach past x = {mpmath.nstr(self.x_end, 10)}, beyond which "
                f"the profile is not real{where}: the gap there is still below h0 = w/sigma_0 "
                f"(a larger sigma_0 or a smaller work of adhesion keeps it inside)")

    def _solve_s(self, F, dF, s0, tol, s_max=None, A=None, with_slope=False, near=False):
        """Root of the increasing F on 0 < s < s_max from the guess s0: bracket
        by doubling / halving (never past s_max, where the profile stops being
        real: a :class:`DomainError` when F < 0 still there, i.e. the cohesive
        zone would have to reach past the profile's end), then Newton kept
        inside the bracket.  F and dF are evaluated once per point (the guess
        is both the first end of the bracket and Newton's start).
        ``near``: s0 is an estimate within quadratic reach of the root (c_of's
        solve at the working precision): the second end of the bracket is first
        probed just beyond the Newton step from s0 (past it by the larger of
        tol s0 / 4 and 1000 step**2 / s0, far more than that step's own error),
        where F has the other sign when s0 is that close; only if it has not,
        the doubling / halving from s0.  Newton then starts at the probe.
        ``with_slope``: (s, dF at the last Newton point, within tol s of s,
        or None where there was none)."""
        F_real, seen, slopes = _real(F), {}, {}

        def F(v):
            if v not in seen:
                seen[v] = F_real(v)
            return seen[v]

        def slope(v):
            if v not in slopes:
                try:
                    slopes[v] = real_value(dF(v))
                except UNDEFINED:
                    slopes[v] = None
            return slopes[v]
        if s_max is not None and not s0 < s_max:
            s0 = s_max / 2
        lo = hi = s0
        n = 0
        start = s0
        probed = False
        if near:
            f0, d0 = F(s0), slope(s0)
            if d0 is not None and d0 > 0 and f0 != 0:
                step = -f0 / d0
                past = max(tol * s0 / 4, 1000 * step * step / s0)
                probe = s0 + step + (past if step > 0 else -past)
                if probe > 0 and (s_max is None or probe < s_max) and (F(probe) > 0) != (f0 > 0):
                    lo, hi = (s0, probe) if probe > s0 else (probe, s0)
                    start, probed = probe, True
        if probed:
            pass
        elif F(s0) <= 0:
            lo = s0
            hi = s0 * 2 if s_max is None else min(s0 * 2, s_max)
            while F(hi) <= 0:
                if s_max is not None and hi >= s_max:
                    where = f" at a = {mpmath.nstr(A, 8)}" if A is not None else " as a -> 0+"
                    raise DomainError(self._beyond_end(where))
                lo, hi = hi, hi * 4 if s_max is None else min(hi * 4, s_max)
                n += 1
                if n > 2000:
                    raise DomainError("no cohesive-zone half-width found: the gap never reaches h0")
        else:
            hi = s0
            lo = s0 / 2
            while F(lo) >= 0:
                lo, hi = lo / 4, lo
                n += 1
                if n > 4000:
                    raise DomainError("no cohesive-zone half-width found: the gap exceeds h0 at c_D -> a")
        s = start if lo <= start <= hi else (lo + hi) / 2   # a good guess stays the start
        d = None
        for _ in range(200):
            f = F(s)
            if f > 0:
                hi = s
            else:
                lo = s
            d = slope(s)
            s_new = s - f / d if d is not None and d > 0 else None
            if s_new is None or not lo < s_new < hi:
                s_new = mpmath.sqrt(lo * hi) if hi / lo > 4 else (lo + hi) / 2
            if abs(s_new - s) <= tol * s:
                return (s_new, d) if with_slope else s_new
            s = s_new
            if (hi - lo) <= tol * lo:
                break
            d = None      # the slope was at the previous point
        return (s, d) if with_slope else s

    def c_of(self, A, dps: int):
        """c_D at the half-width A (mpf), to dps digits."""
        C, guard, _ = self._c_and_slope(A, dps)
        return C, guard

    def _c_and_slope(self, A, dps: int):
        """(c_D, the guard digits, dG/dc of the gap condition at the last Newton point, within
        10**-(dps+4) (c_D - a) of c_D, or None) at the half-width A: :meth:`c_of`, and the slope
        :meth:`P_and_slope` needs for dc_D/da without one more quadrature."""
        with workdps(15):   # c_D - a is at least of the order of the JKR-limit zone: digits to resolve it
            extra = max(0, int(mpmath.log10(mpmath.mpf(A) / self._s_guess(A))))
        with workdps(25 + extra):
            A25 = mpmath.mpf(A)
            guess = self._warm_guess(A25)
            # the estimate stops at a Newton step below ESTIMATE_TOL: quadratic convergence leaves it
            # about ESTIMATE_TOL**2 off, and the solve at dps + guard digits below corrects it anyway
            s_est = self._solve_s(lambda s: self._G(A25, A25 + s), lambda s: self._Gc(A25, A25 + s),
                                  guess, ESTIMATE_TOL, self._s_max(A25), A25)
            self._warm = (self._warm or [])[-1:] + [(A25, s_est)]
            # acosh(c/a) near c = a loses log10(a/s) digits; at small a, terms of size c/a cancel in
            # the partial derivatives down to dP/da ~ a: 2 log10(c/a) digits
            r = mpmath.log10(A25 / s_est)
            # a closed gap condition may hold terms ~ (c^2 - a^2)^(-1/2) that cancel (x**3: 2 a c^3/sqrt(c^2 - a^2)
            # - 2 a^3 c/sqrt(c^2 - a^2)); in dG/dc they grow to the power 3/2 and dP/da = Pa + Pc dc_D/da
            # cancels by a/(c - a) again: 2 log10(a/s) digits (dP/da was off by 1e8 at sigma_0 = 1e20 with one);
            # the quadrature gap (QuadGap, in theta) is smooth at c -> a and needs one
            guard = 14 + ((2 if self.closed else 1) * int(r) if r > 0 else 2 * int(-r))
        with workdps(capped_dps(dps + guard, f"c_D at a = {mpmath.nstr(A, 8)} (c_D - a = {mpmath.nstr(s_est, 5)})")):
            A = mpmath.mpf(A)
            s, slope = self._solve_s(lambda s: self._G(A, A + s), lambda s: self._Gc(A, A + s),
                                     mpmath.mpf(s_est), mpmath.mpf(10)**-(dps + 4), self._s_max(A), A,
                                     with_slope=True, near=True)
            return A + s, guard, slope

    def _warm_guess(self, A):
        """The start of the estimate of s = c_D - a at A from the last two solutions (scans, root
        searches and the descent move smoothly): s(a) extrapolated as a power law between them
        where A lies within a factor 4 of both, else c_D kept from the last one (where it lies
        above A), else the JKR-limit zone.  Only the work depends on it: the bracket decides."""
        h = self._warm or []
        if len(h) == 2 and all(A / 4 < a < 4 * A for a, _ in h):
            (a1, s1), (a2, s2) = h
            span = mpmath.log(a2 / a1)
            # extrapolated at most twice the span of the two (two nearly equal half-widths of a root
            # search would amplify the estimates' own errors), and within a factor 4 of s2
            if abs(span) > mpmath.mpf(10)**-4 and abs(mpmath.log(A / a2)) <= 2 * abs(span):
                g = s2 * (s2 / s1)**(mpmath.log(A / a2) / span)
                if mpmath.isfinite(g) and s2 / 4 < g < 4 * s2:
                    return g
        if h and h[-1][0] + h[-1][1] > A:
            return h[-1][0] + h[-1][1] - A
        return self._s_guess(A)

    def _delta(self):
        # the Dugdale gap is ~ 4 sigma0 s/(pi E*) for s << a: s ~ pi E* h0/(4 sigma0), the JKR-limit zone
        return mpmath.pi * mpmath.mpf(sp.N(self.E, 30)) * self.h0() / (4 * mpmath.mpf(sp.N(self.sigma0, 30)))

    def _s_guess(self, A):
        """The start of c_D - a: the JKR-limit zone delta, but at most the zone c0 of a vanishing contact
        (at a small Maugis parameter delta is far beyond where the profile alone reaches h0: the cosh
        profile at sigma_0 = 1e-6 has delta = 8e9 where c0 = 9.9, and its gap at 8e9 needs 3e9 digits)."""
        d = self._delta()
        if self._c0_15 is None:
            self._c0_15 = self.c0(15)
        return min(d, self._c0_15)

    def c0(self, dps: int):
        """The cohesive-zone half-width of a vanishing contact (a -> 0+)."""
        with workdps(dps + 15):
            return self._solve_s(self._Z0, self._Z0c, self._delta(), mpmath.mpf(10)**-(dps + 4),
                                 None if self.x_end is None else self.x_end * (1 - mpmath.mpf(10)**-(dps + 10)))

    def force_zero_width(self, dps: int):
        """P(0+), the limit of P(a) as a -> 0+ (the Dugdale force of the zone c0)."""
        with workdps(dps + 15):
            return +self._P0lim(self.c0(dps))

    def P_and_slope(self, A, dps: int):
        """(P, dP/da, c_D) at A, each to about dps digits."""
        C, guard, Gc = self._c_and_slope(A, dps)
        with workdps(dps + guard):
            A = mpmath.mpf(A)
            # dG/dc at the last Newton point: c_D moved by at most 10**-(dps+4) (c_D - a) from it, a
            # relative change of that order in dc_D/da (G is smooth in c on the scale c_D - a)
            Ga, Pa, Pc = self._Ga(A, C), self._Pa(A, C), self._Pc(A, C)
            dc = -Ga / (self._Gc(A, C) if Gc is None else Gc)
            dP = Pa + Pc * dc
            if Gc is not None and abs(Pc * dc) * mpmath.mpf(10)**-(dps + 3) > \
                    mpmath.mpf(10)**-dps * max(abs(dP), abs(self._dP0(A))):
                # the slope at the last Newton point is off by ~10**-(dps+4) relative; Pc dc_D/da cancels
                # against Pa down to dP/da by a factor ~ (c_D - a)/a (the JKR limit, lambda >> 1): the
                # error would exceed 10**-dps of dP/da there, so dG/dc is taken at c_D itself
                dc = -Ga / self._Gc(A, C)
                dP = Pa + Pc * dc
            P = self._P(A, C)
            return +P, +dP, +C

    def certified_gap(self, A, C, dps: int):
        """The gap at c_D, g0(c_D; a) + (the Dugdale part), where g0 has no closed form, with the
        integral int_0^theta_a P0(c sin t)/sin(t) dt (see :class:`QuadGap`) through the one reference
        integrator: an Arb enclosure where P0 is closed and Arb can (RefValue, method 'arb'), else
        its mpmath estimate; None where the engine's g0 is closed (no integral to certify)."""
        if self.closed_parts["g0(c_D; a)"] or self._P0_expr is None:
            return None
        from ....numeric.reference import RefValue, integrate
        th = sp.Dummy("theta", positive=True)
        with workdps(dps + 20):
            A, C = mpmath.mpf(A), mpmath.mpf(C)
            Cs = sp.Float(mpmath.nstr(C, dps + 20), dps + 20)
            top = mpmath.atan2(A, mpmath.sqrt((C - A) * (C + A)))
            pts = [mpmath.mpf(0)] + sorted(mpmath.asin(b / C) for b in self.quad_gap.breaks if b < A) + [top]
            integrand = self._P0_expr.xreplace({S.a: Cs * sp.sin(th)}) / sp.sin(th)
            r = integrate(integrand, th, pts, dps + 5)
            E = mpmath.mpf(sp.N(self.E, dps + 20))
            rest = self.quad_gap.f(C) - 2 * mpmath.acosh(C / A) * self._P0(A) / (mpmath.pi * E) \
                + sp.lambdify((S.a, S.c_D), self._gD_expr, "mpmath")(A, C)
            k = 2 / (mpmath.pi * E)
            return RefValue(rest - k * r.mid, k * r.rad, r.method, r.note)

    def checked_P_and_slope(self, A, dps: int):
        """:meth:`P_and_slope` confirmed at 10 more digits (and 10 more, up to 4 times) until two
        levels agree to dps + 1 digits in P (relative to |P| + |P0|) and c_D: a closed form that
        cancels where the guard digits do not foresee it (the rounded punch at a = b lost 5.6 of
        30 digits) is caught here and answered from the higher level."""
        P, dP, C = self.P_and_slope(A, dps)
        for k in range(1, 5):
            P2, dP2, C2 = self.P_and_slope(A, dps + 10 * k)
            with workdps(dps + 10 * k + 5):
                scale = abs(P2) + abs(self._P0(mpmath.mpf(A)))
                tol = mpmath.mpf(10)**-(dps + 1)
                if abs(P - P2) <= tol * scale and abs(C - C2) <= tol * abs(C2):
                    return P2, dP2, C2
            P, dP, C = P2, dP2, C2
        raise VerificationError(f"the Maugis-Dugdale state at a = {mpmath.nstr(A, 10)} does not settle to {dps} digits "
                          f"(two levels of working precision up to {dps + 40} disagree)")

    def state(self, A, dps: int) -> MDState:
        P, dP, C = self.checked_P_and_slope(A, dps)
        return self.state_at(A, C, P, dP, dps, check=True)

    def state_at(self, A, C, P, dP, dps: int, model="Maugis-Dugdale", note="", check=False) -> MDState:
        """The :class:`MDState` of the half-widths A and C = c_D with the load P and slope dP; its pressure and
        gap evaluated at dps + 10 digits plus those that c_D - a costs (a zone 1e-200 of a wide at sigma_0 =
        10**100: c_D^2 - a^2 vanished at dps + 10 digits and the pressure was the adhesionless one).
        ``check``: the gap at c_D recomputed by the reference integrator where g0 is not closed."""
        with workdps(dps + 10):
            A = mpmath.mpf(A)
            h0 = self.h0()
        zone = mpmath.fsub(C, A, exact=True)      # c_D - a without rounding: it may be 1e-200 of c_D
        with workdps(30):
            lost = max(0, int(mpmath.log10(C / zone))) if zone > 0 else 0
        work = dps + 10 + lost
        law, sig = self, mpmath.mpf(sp.N(self.sigma0, work + 10))

        def pressure(x):
            with workdps(work):
                x = abs(mpmath.mpf(x))
                if x < A:
                    return +law._p_in(x, A, C)
                return -sig if x <= C else mpmath.mpf(0)

        def gap(x):
            with workdps(work):
                x = abs(mpmath.mpf(x))
                if x <= A:
                    return mpmath.mpf(0)
                if abs(x - C) <= C * mpmath.mpf(10)**-(dps + 5):
                    x = C       # x = c_D given at fewer digits than c_D is held: the end of the zone itself
                top = min(x, C)
                # Dugdale punches of width t in (a, min(x, c_D)): -(2/(pi E*)) int acosh(x/t) g_D(t) dt,
                # t = c_D sin(phi) removes the endpoint singularity of g_D at c_D; x/t >= 1 on the whole
                # range (t <= min(x, c_D)): a ratio rounded below 1 at the end is 1 (the real branch of acosh)
                E = mpmath.mpf(sp.N(law.E, work + 10))
                lo, hi = mpmath.asin(A / C), mpmath.asin(top / C)

                def integrand(ph):
                    t = C * mpmath.sin(ph)
                    return mpmath.acosh(max(x / t, 1)) * (-2 * sig * t)
                I = mpmath.quad(integrand, [lo, hi])
                return +(law._g0(x, A) - 2 / (mpmath.pi * E) * I)
        return MDState(A, C, P, dP, h0, pressure, gap, dict(self.closed_parts),
                       self.certified_gap(A, C, dps) if check else None, model, note)


__all__ = ["MDLaw", "MDState"]
