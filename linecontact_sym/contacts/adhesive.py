"""JKR-adhesive line contacts: Popov (2017), Eqs. (29)-(36).

The adhesive contact of half-width ``a`` is the non-adhesive one (force law
P0(a), Eq. 10*, pressure p0(x; a), Eq. 12) with a *pulled* rigid flat punch of
the same half-width superposed (Eq. 29):

    p(x; a) = p0(x; a) - Phat / (pi sqrt(a**2 - x**2)),            (29)
    P(a)    = P0(a) - Phat.                                         (33)

The flat-punch force ``Phat`` follows from the critical condition at the
contact edge, Eq. (30).  Near x = a the tensile stress of the punch is
``sigma(x) ~ K_I / sqrt(2 pi (a - x))`` with the stress-intensity factor

    K_I = Phat / sqrt(pi a)                                         (30)

(p0 is bounded at the edge and does not contribute), and the energy released
per unit area when the edge advances (rigid body on an elastic half-plane,
E* = E/(1 - nu**2)) is ``G = K_I**2 / (2 E*)``.  Griffith's balance G = gamma
(gamma = the paper's gamma_12, the work of adhesion) gives

    Phat = sqrt(2 pi a gamma E*).                                   (31)

The same follows from the compliance of the flat punch, Eq. (3):
C(a) = (2/(pi E*)) arccosh(L/a) for the displacement at a distant point L, so
G = (Phat**2/2) |dC/d(2a)| = Phat**2/(2 pi E* a) as L -> oo.  This energy form
is what the verification of Eq. (31) evaluates independently (quadrature of
the punch displacement, numerical differentiation, root finding).

Pull-off, Eqs. (34)-(36)
    Under load control the contact separates at the minimum of P(a):
    ``pull_off_force`` is that minimum, P_min < 0 (a tensile load), and
    ``adhesion_force`` is P_adh = -P_min > 0, the paper's convention in
    (34)-(36).  For a single power law P0 = C a**m (power-law profile
    c_n |x|**n: m = n, C = E* c_n Z_n, Eq. 32) dP/da = 0 gives

        a_po  = (2 pi gamma E* / (4 m**2 C**2))**(1/(2m - 1)),
        P_adh = (2m - 1)/(2m) * ((2 pi gamma E*)**m / (2 m C))**(1/(2m - 1)),

    i.e. Barquins' (3/4)(4 pi R E* gamma**2)**(1/3) for the parabola (34), the
    paper's (35) for general n and pi gamma / (2 tan theta) for the wedge (36).

Existence of a pull-off (found here, not printed in the paper)
    P(a) = sqrt(a) (P0(a)/sqrt(a) - sqrt(2 pi gamma E*)).  A finite tensile
    pull-off exists when P0(a)/sqrt(a) -> 0 as a -> 0 (the contact is tensile
    for small a) and P0(a)/sqrt(a) grows beyond sqrt(2 pi gamma E*) at large
    a (to oo or towards the end of the profile's domain).  For a power law
    (P0 ~ a**n) both hold **iff n > 1/2**; then the minimum is unique.

    * n > 1/2: one minimum; P(a) < 0 for a below the jump-in half-width; two
      equilibria for P_min < P < 0 (stable: larger a), one for P >= 0.
    * n = 1/2: P = (C - sqrt(2 pi gamma E*)) sqrt(a) is monotone.  For
      gamma < gamma_c = C**2/(2 pi E*) it is positive and increasing: no
      tensile load is sustained (the infimum 0 is reached only as a -> 0, a
      zero pull-off); for gamma > gamma_c it decreases to -oo: every
      equilibrium is unstable and the contact spreads without bound; at
      gamma = gamma_c P == 0 (neutral).  No finite pull-off in any case.
    * n < 1/2: the sqrt term dominates at large a; the single stationary
      point of P is a *maximum* P_max.  Stable contacts exist only for
      0 < P < P_max (small-a branch); tensile equilibria lie on the unstable
      large-a branch only, P -> -oo as a -> oo, and loads above P_max have no
      equilibrium (unbounded spreading).  No finite pull-off.

    Where no finite pull-off exists the package raises :class:`NoPullOffError`
    (a :class:`~linecontact_sym.errors.DomainError`), never a NaN.

Jump-in / jump-out (load control)
    At zero load the free surfaces snap into contact at the stable root of
    P(a) = 0, ``jump_in_half_width``; on unloading the contact jumps out
    (separates) from ``jump_out_half_width`` = ``pull_off_half_width``.

Non-adhesive limit
    gamma = 0 gives Phat = 0, so ``force`` and ``pressure`` with gamma -> 0
    are exactly the engine's ``LineContact.force`` / ``.pressure``.

Worn cylinder (Eq. 21): P0 = 0 for a <= b, so P(a) decreases on (0, b] and
the minimum may sit at the kink a = b (weak adhesion, gamma <=
2 E* b**3/(pi R**2) is sufficient), giving P_min = -sqrt(2 pi b gamma E*)
exactly; otherwise at a stationary point a > b.  The numeric search handles
both (``PullOff.kind``).
"""
from __future__ import annotations

import random
import time
from dataclasses import dataclass

import mpmath
import sympy as sp

from ..parsing import to_sympy
from ..core import symbols as S
from ..method import transforms as T
from ..core.budget import run_with_budget
from ..method.derivation import (Derivation, VERIFY_DPS, VerificationRecord, _values_by_name, tidy,
                         digits_agreeing, verify_many,
                         verify)
from ..core.errors import BudgetExceeded, DomainError, VerificationError
from ..method.hyperseries import NotDecomposable, decompose

__all__ = ["AdhesiveLineContact", "NoPullOffError", "NoEquilibriumError", "NumericValuesRequired",
           "PullOff", "flat_punch_force", "stress_intensity", "energy_release_rate",
           "GAMMA_RANGE"]

#: range of the work of adhesion at the random verification points
GAMMA_RANGE = (0.005, 0.5)
#: extra working digits of the numeric minimisation
_GUARD = 15
#: Eq. (31) derivations, shared by all contacts (the flat punch has no profile)
_PHAT_CACHE: dict = {}


# ---------------------------------------------------------------- errors
class NoPullOffError(DomainError):
    """P(a) has no finite (negative) minimum: no finite tensile pull-off."""


class NoEquilibriumError(DomainError):
    """No equilibrium half-width at the requested load (below the pull-off force)."""


class NumericValuesRequired(DomainError):
    """The quantity has no closed form; a number needs values of every parameter."""


# ---------------------------------------------------------------- Eqs. (30)/(31)
def flat_punch_force(work_of_adhesion=S.gamma, a=S.a, E_star=S.E_star):
    """Eq. (31): Phat = sqrt(2 pi a gamma E*), the force of the pulled flat
    punch that makes the energy release rate at the edges equal to gamma
    (K_I**2/(2 E*) = gamma with K_I = Phat/sqrt(pi a), Eq. 30)."""
    return sp.sqrt(2 * sp.pi * a * work_of_adhesion * E_star)


def stress_intensity(Phat, a=S.a):
    """Eq. (30): mode-I stress-intensity factor of a flat punch pulled by Phat,
    K_I = lim_{x->a} sqrt(2 pi (a - x)) sigma(x) = Phat/sqrt(pi a)."""
    return Phat / sp.sqrt(sp.pi * a)


def energy_release_rate(K, E_star=S.E_star):
    """G = K_I**2/(2 E*) at the edge of a rigid-elastic line contact."""
    return K**2 / (2 * E_star)


# ---------------------------------------------------------------- small helpers
def _rat(v):
    return sp.Rational(round(v * 10**6), 10**6)


def _fl(vals: dict, digits: int = 80) -> dict:
    """Values as 80-digit Floats: substituting exact Rationals into powers with
    symbolic exponents (``(p/q)**(1/(2n-1))``) makes SymPy factor large
    integers; Floats evaluate at once and carry more digits than checked."""
    return {k: (sp.Float(v, digits) if isinstance(v, sp.Basic) and v.is_number and not v.is_Float
                else v) for k, v in vals.items()}


def _mp(v):
    """A SymPy number (or mpf) as mpf at the current precision."""
    if isinstance(v, mpmath.mpf):
        return +v
    return mpmath.mpf(sp.N(v, mpmath.mp.dps + 10))


def _digits(x, ref):
    return digits_agreeing(x, ref)


_phi = sp.Symbol("phi", positive=True)


class _Outside(Exception):
    """Evaluation outside the profile's real domain."""


def _real(v):
    if isinstance(v, mpmath.mpc):
        if abs(v.imag) > abs(v.real) * mpmath.mpf(10)**(-mpmath.mp.dps + 5) or v.real == 0:
            raise _Outside
        v = v.real
    elif not isinstance(v, mpmath.mpf):
        try:
            v = mpmath.mpf(v)
        except (TypeError, ValueError):
            raise _Outside
    if not mpmath.isfinite(v):
        raise _Outside
    return v


@dataclass(frozen=True)
class PullOff:
    """Result of a numeric pull-off computation (load control).

    force          P_min < 0, the minimum of P(a) (the pull-off *load*)
    adhesion_force P_adh = -P_min > 0 (the paper's P_adh)
    half_width     a at pull-off
    kind           'stationary' (dP/da = 0) or 'kink' (at a profile breakpoint)
    digits         agreement of the two independent methods (None if not run)
    """

    force: mpmath.mpf
    adhesion_force: mpmath.mpf
    half_width: mpmath.mpf
    kind: str
    digits: float | None = None


class _NumericDerivation(Derivation):
    """A Derivation without closed form whose defining statement contains the
    half-width ``a`` as an unknown (not an input)."""

    @property
    def variables_all(self):
        return tuple(sorted(set(self.variables), key=lambda s: s.name))


# ---------------------------------------------------------------- the numeric law
class _Law:
    """P(a) = P0(a) - sqrt(2 pi a gamma E*) at fixed numeric parameters.

    ``mode='closed'``: P0 and dP0/da from the engine's (verified) closed form.
    ``mode='quad'``  : independent quadratures, t = a sin(phi):
        P0(a)  = E* a int_0^{pi/2} sin(phi) f'(a sin phi) dphi           (10*)
        P0'(a) = E* int_0^{pi/2} sin(phi) h'(a sin phi) dphi
                 + E* sum_b J_b b**2 / sqrt(a**2 - b**2),   h(t) = t f'(t),
    J_b = f'(b+) - f'(b-) the slope jump at a kink b < a.
    """

    def __init__(self, ad, fixed: dict, mode: str = "closed"):
        self.fixed = dict(fixed)
        prof = ad.contact.profile
        self.profile = prof
        g = to_sympy(ad.gamma).xreplace(fixed)
        if not g.is_number:
            raise DomainError(f"the work of adhesion {ad.gamma} needs a value")
        if g.is_negative:
            raise DomainError(f"the work of adhesion must be >= 0, got {g}")
        self.gamma = g
        self.E = to_sympy(fixed[S.E_star])
        bps = [sp.N(bp.xreplace(fixed), 80) for bp in prof.breakpoints]
        self.breaks_sym = sorted(bps)
        fd = ad.contact.derivation("force")
        self.mode = "closed" if (mode == "closed" and fd.closed_form) else "quad"
        pf = {k: v for k, v in fixed.items() if k != S.a}
        if self.mode == "closed":
            P0 = fd.expr.xreplace(pf)
            if P0.free_symbols - {S.a}:
                raise DomainError(f"missing values for {P0.free_symbols - {S.a}}")
            self._P0 = sp.lambdify(S.a, P0, "mpmath")
            self._dP0 = sp.lambdify(S.a, sp.diff(P0, S.a), "mpmath")
            # where the closed form holds (e.g. a < 1 beyond a branch cut)
            conds = [cd.xreplace(pf) for cd in fd.conditions if cd.has(S.a)]
            self._holds_at = (sp.lambdify(S.a, sp.And(*conds), "mpmath") if conds else None)
        else:
            self._f1 = [sp.lambdify(S.x, sp.diff(pc.expr, S.x).xreplace(pf), "mpmath")
                        for pc in prof.pieces]
            self._f2 = [sp.lambdify(S.x, sp.diff(pc.expr, S.x, 2).xreplace(pf), "mpmath")
                        for pc in prof.pieces]
        self.scale = (mpmath.mpf(1) if not bps else
                      mpmath.exp(sum(mpmath.log(_mp(b)) for b in bps) / len(bps)))
        self._scan_cache = None
        self.scan_source = None

    # ----------------------------------------------------------- values
    def breaks(self):
        return [_mp(b) for b in self.breaks_sym]

    def B1(self):
        """sqrt(2 pi gamma E*): Phat = B1 sqrt(a)."""
        return mpmath.sqrt(2 * mpmath.pi * _mp(self.gamma) * _mp(self.E))

    def _pieces(self, A):
        edges = [mpmath.mpf(0)] + [b for b in self.breaks() if b < A] + [A]
        return list(zip(range(len(edges) - 1), edges[:-1], edges[1:]))

    def _closed_ok(self, A):
        if self._holds_at is None:
            return True
        try:
            return bool(self._holds_at(A))
        except (TypeError, ValueError):
            return False

    def P0(self, A):
        if self.mode == "closed" and not self._closed_ok(A):
            return self._quad_law().P0(A)
        if self.mode == "closed":
            try:
                return _real(self._P0(A))
            except (_Outside, ValueError, ZeroDivisionError):
                # the closed form may hold on part of the axis only (branch
                # cuts): the profile's own quadrature decides the domain
                return self._quad_law().P0(A)
        total = mpmath.mpf(0)
        for i, lo, hi in self._pieces(A):
            fn = self._f1[i]
            total += mpmath.quad(lambda ph: mpmath.sin(ph) * fn(A * mpmath.sin(ph)),
                                 [mpmath.asin(lo / A), mpmath.asin(hi / A)])
        return _real(_mp(self.E) * A * total)

    def dP0(self, A):
        if self.mode == "closed" and not self._closed_ok(A):
            return self._quad_law().dP0(A)
        if self.mode == "closed":
            try:
                return _real(self._dP0(A))
            except (_Outside, ValueError, ZeroDivisionError):
                return self._quad_law().dP0(A)
        total = mpmath.mpf(0)
        for i, lo, hi in self._pieces(A):
            f1, f2 = self._f1[i], self._f2[i]

            def integrand(ph):
                t = A * mpmath.sin(ph)
                return mpmath.sin(ph) * (f1(t) + t * f2(t))
            total += mpmath.quad(integrand, [mpmath.asin(lo / A), mpmath.asin(hi / A)])
        brs = self.breaks()
        for i, bv in enumerate(brs):
            if bv < A:
                J = self._f1[i + 1](bv) - self._f1[i](bv)
                total += J * bv**2 / mpmath.sqrt(A**2 - bv**2)
        return _real(_mp(self.E) * total)

    def P(self, A):
        return self.P0(A) - self.B1() * mpmath.sqrt(A)

    def dP(self, A):
        return self.dP0(A) - self.B1() / (2 * mpmath.sqrt(A))

    def P_quad_only(self, A):
        """P(a) with P0 from the quadrature (used by the second method)."""
        return self._quad_law().P(A)

    def _quad_law(self):
        if self.mode == "quad":
            return self
        if not hasattr(self, "_qlaw"):
            self._qlaw = _Law.__new__(_Law)
            self._qlaw.__dict__.update(self.__dict__)
            self._qlaw.mode = "quad"
            pf = {k: v for k, v in self.fixed.items() if k != S.a}
            self._qlaw._f1 = [sp.lambdify(S.x, sp.diff(pc.expr, S.x).xreplace(pf), "mpmath")
                              for pc in self.profile.pieces]
            self._qlaw._f2 = [sp.lambdify(S.x, sp.diff(pc.expr, S.x, 2).xreplace(pf), "mpmath")
                              for pc in self.profile.pieces]
        return self._qlaw

    # ----------------------------------------------------------- scan
    def scan(self):
        """Values (a, P, dP) on a geometric grid (factor 4, 2**-80 .. 2**80
        times the length scale, breakpoints bracketed at 1e-10), at 20
        digits, cut at the end of the profile's real domain.  Returns
        ``(points, edge)`` with edge True when the grid stops at a domain end.

        A quadrature law with a closed-form sibling (``scan_source``) scans
        with the sibling: the scan only *locates* brackets; every root and
        value is then computed from this law's own quadratures."""
        if self.scan_source is not None and self.scan_source is not self:
            return self.scan_source.scan()
        if self._scan_cache is not None:
            return self._scan_cache
        with mpmath.workdps(20):
            grid = [self.scale * mpmath.mpf(2)**j for j in range(-80, 81, 2)]
            near = mpmath.mpf("1e-8")
            grid = [A for A in grid if all(abs(A - bv) > near * bv for bv in self.breaks())]
            for bv in self.breaks():
                grid += [bv * (1 - mpmath.mpf("1e-10")), bv * (1 + mpmath.mpf("1e-10"))]
            grid.sort()
            pts = []
            edge = False
            last_good = None
            for A in grid:
                try:
                    pts.append((A, self.P(A), self.dP(A)))
                    last_good = A
                except (_Outside, ValueError, ZeroDivisionError):
                    if last_good is None:
                        continue
                    edge = True
                    lo, hi = last_good, A
                    for _ in range(60):  # locate the domain end
                        mid = (lo + hi) / 2
                        try:
                            self.P(mid), self.dP(mid)
                            lo = mid
                        except (_Outside, ValueError, ZeroDivisionError):
                            hi = mid
                    for k in range(1, 40):  # approach it
                        Ak = last_good + (lo - last_good) * (1 - mpmath.mpf(2)**(-k))
                        try:
                            pts.append((Ak, self.P(Ak), self.dP(Ak)))
                        except (_Outside, ValueError, ZeroDivisionError):
                            break
                    break
        if not pts:
            raise DomainError("the force law could not be evaluated at any half-width")
        self._scan_cache = (pts, edge)
        return self._scan_cache

    def _scan_law(self):
        return self.scan_source if self.scan_source is not None else self

    # ----------------------------------------------------------- refinement
    @staticmethod
    def _root(fn, lo, hi, approx=None):
        """Root of fn on [lo, hi] (sign change), solved in u = ln a at the
        current precision.  With ``approx`` the bracket is first narrowed
        around it (cheap high-precision refinement)."""
        g = lambda u: fn(mpmath.exp(u))
        ul, uh = mpmath.log(lo), mpmath.log(hi)
        if approx is not None:
            u0 = mpmath.log(approx)
            d = mpmath.mpf("1e-12")
            while d < uh - ul:
                l2, h2 = max(u0 - d, ul), min(u0 + d, uh)
                gl, gh = g(l2), g(h2)
                if (gl < 0) != (gh < 0):
                    ul, uh = l2, h2
                    break
                d *= 1000
        try:
            u = mpmath.findroot(g, (ul, uh), solver="anderson", verify=False)
        except (ZeroDivisionError, ValueError):
            u = None
        if u is None or isinstance(u, mpmath.mpc) or not (ul <= u <= uh):
            gl = g(ul)
            for _ in range(45):  # bisection, then secant
                um = (ul + uh) / 2
                gm = g(um)
                if (gm < 0) == (gl < 0):
                    ul, gl = um, gm
                else:
                    uh = um
            u = mpmath.findroot(g, (ul, uh), solver="secant", verify=False)
        return mpmath.exp(u)

    def _candidates(self):
        """Local minima of P located on the scan (at 20 digits):
        [(a_approx, kind, (lo, hi))]."""
        pts, edge = self.scan()
        sl = self._scan_law()
        out = []
        with mpmath.workdps(20):
            brs = sl.breaks()
            for (a0, _, d0), (a1, _, d1) in zip(pts[:-1], pts[1:]):
                if not (d0 < 0 < d1):
                    continue
                kink = [bv for bv in brs if a0 < bv < a1]
                if kink:
                    out.append((kink[0], "kink", (a0, a1)))
                    continue
                out.append((sl._root(sl.dP, a0, a1), "stationary", (a0, a1)))
        return out

    def minimum(self, dps: int) -> PullOff:
        """Global minimum of P(a) (load control) from this law's own values."""
        pts, edge = self.scan()
        if self.gamma == 0:
            raise NoPullOffError("no adhesion (gamma = 0): P(a) = P0(a) >= 0, no tensile pull-off")
        aN, PN, dN = pts[-1]
        if dN < 0:
            where = "the end of the profile's domain" if edge else "the end of the search range"
            raise NoPullOffError(
                f"P(a) is still decreasing at a = {mpmath.nstr(aN, 6)} ({where}): P(a) has no "
                f"finite minimum, no finite pull-off (the profile grows no faster than "
                f"sqrt(x) there, so the adhesive term sqrt(2 pi a gamma E*) dominates)")
        cands = []
        with mpmath.workdps(dps + _GUARD):
            for approx, kind, (lo, hi) in self._candidates():
                if kind == "kink":
                    bv = [b for b in self.breaks() if abs(b - approx) <= abs(approx) * mpmath.mpf("1e-15")][0]
                    eps = mpmath.mpf(10)**(-dps)
                    if not (self.dP(bv * (1 - eps)) < 0 < self.dP(bv * (1 + eps))):
                        continue
                    cands.append((bv, self.P(bv), "kink", (lo, hi)))
                else:
                    A = self._root(self.dP, _mp(lo), _mp(hi), approx=_mp(approx))
                    cands.append((A, self.P(A), "stationary", (lo, hi)))
            neg = [cnd for cnd in cands if cnd[1] < 0]
            if not neg:
                raise NoPullOffError(
                    "P(a) has no negative minimum: no tensile load is sustained (the infimum 0 is "
                    "reached only as a -> 0); no finite pull-off")
            A, Pm, kind, br = min(neg, key=lambda cnd: cnd[1])
            self._last_bracket = br
            return PullOff(+Pm, -Pm, +A, kind)

    def minimum_by_differences(self, dps: int, po: PullOff) -> PullOff:
        """Second, independent method: the quadrature force law (10*) minus
        Phat, differentiated numerically (mpmath.diff) and solved for
        dP/da = 0 near the first method's minimum; at a kink, one-sided
        differences confirm the minimum and P is evaluated there."""
        with mpmath.workdps(dps + _GUARD):
            if po.kind == "kink":
                A = _mp(po.half_width)
                h = A * mpmath.mpf(10)**(-dps // 2)
                left = (self.P_quad_only(A) - self.P_quad_only(A - h))
                right = (self.P_quad_only(A + h) - self.P_quad_only(A))
                if not (left < 0 < right):
                    raise VerificationError("the kink at the pull-off is not a minimum of the "
                                            "quadrature force law")
                Pm = self.P_quad_only(A)
                return PullOff(+Pm, -Pm, A, "kink")
            lo, hi = self._last_bracket
            fn = lambda A: mpmath.diff(self.P_quad_only, A)
            A = self._root(fn, _mp(lo), _mp(hi), approx=_mp(po.half_width) * (1 + mpmath.mpf("1e-9")))
            Pm = self.P_quad_only(A)
            return PullOff(+Pm, -Pm, A, "stationary")

    def equilibria(self, load, dps: int):
        """All half-widths with P(a) = load: list of (a, stable), stable first."""
        pts, edge = self.scan()
        sl = self._scan_law()
        with mpmath.workdps(20):
            L20 = _mp(load)
            pts = list(pts)
            # below the grid: P(0+) = 0
            if L20 != 0:
                a0, P0v, _ = pts[0]
                k = 0
                while (P0v - L20 > 0) != (0 - L20 > 0) and k < 200:
                    a0 = a0 / 16
                    P0v = sl.P(a0)
                    pts.insert(0, (a0, P0v, sl.dP(a0)))
                    k += 1
            # beyond the grid (not at a domain end)
            if not edge:
                k = 0
                while k < 200:
                    aN, PN, dN = pts[-1]
                    if (dN > 0 and PN < L20) or (dN < 0 and PN > L20):
                        try:
                            A = aN * 16
                            pts.append((A, sl.P(A), sl.dP(A)))
                        except (_Outside, ValueError, ZeroDivisionError):
                            break
                        k += 1
                    else:
                        break
            # stationary points between grid nodes: two roots close to a
            # minimum (or maximum) may both lie inside one grid interval
            extra = []
            for (a0, _, d0), (a1, _, d1) in zip(pts[:-1], pts[1:]):
                if (d0 < 0) != (d1 < 0):
                    kink = [bv for bv in sl.breaks() if a0 < bv < a1]
                    A = kink[0] if kink else sl._root(sl.dP, a0, a1)
                    extra.append((A, sl.P(A), sl.dP(A)))
            pts = sorted(pts + extra, key=lambda r: r[0])
            brackets = []
            for (a0, P0v, _), (a1, P1v, _) in zip(pts[:-1], pts[1:]):
                if (P0v - L20) * (P1v - L20) < 0:
                    brackets.append((a0, a1, sl._root(lambda A: sl.P(A) - L20, a0, a1)))
        with mpmath.workdps(dps + _GUARD):
            L = _mp(load)
            out = []
            for a0, a1, approx in brackets:
                A = self._root(lambda A: self.P(A) - L, _mp(a0), _mp(a1), approx=_mp(approx))
                out.append((+A, self.dP(A) > 0))
            out.sort(key=lambda r: (not r[1], -r[0]))
            return out


# ---------------------------------------------------------------- energy reference
def _compliance_quad(A, E, dps, L):
    """Compliance of the flat punch (unit force), displacement difference
    between the punch and a distant point L = a 10**(dps + 20), by quadrature
    of the half-plane's log kernel over the punch pressure 1/(pi sqrt(a^2 - s^2)):
    C = (2/(pi E*)) (1/pi) int_{-pi/2}^{pi/2} ln(|L - a sin phi| / |a sin phi|) dphi."""
    with mpmath.workdps(max(mpmath.mp.dps, dps + 10)):  # never below a caller's (mpmath.diff) precision
        f = lambda ph: mpmath.log(abs(L - A * mpmath.sin(ph))) - mpmath.log(abs(A * mpmath.sin(ph)))
        I = mpmath.quad(f, [-mpmath.pi / 2, 0, mpmath.pi / 2]) / mpmath.pi
        return 2 * I / (mpmath.pi * E)


def _phat_energy(A, gamma, E, dps, quadrature=True):
    """Phat from the energy balance G = gamma, G = (P^2/2) |dC/d(2a)| with C
    the punch compliance (Eq. 3): numerical differentiation + root finding."""
    with mpmath.workdps(dps + 10):
        A, g, E = _mp(A), _mp(gamma), _mp(E)
        if g == 0:
            return mpmath.mpf(0)
        if quadrature:
            L = A * mpmath.mpf(10)**(dps + 20)
            dC = mpmath.diff(lambda u: _compliance_quad(u, E, dps + 10, L), A)
        else:
            L = A * mpmath.mpf(10)**(dps + 20)
            dC = mpmath.diff(lambda u: 2 * mpmath.acosh(L / u) / (mpmath.pi * E), A)
        G = lambda Pv: Pv**2 / 4 * abs(dC) - g
        guess = mpmath.sqrt(4 * g / abs(dC))
        return mpmath.findroot(G, (guess * mpmath.mpf("0.5"), guess * 2), solver="anderson")


# ---------------------------------------------------------------- verification
def _verify_multi(exprs: dict, reference, sampler, conditions, n_points, dps, reference_name,
                  seed: int = 2017) -> dict:
    """Several closed forms against one shared reference (the engine's
    :func:`~linecontact_sym.derivation.verify_many`)."""
    return verify_many(exprs, reference, sampler, conditions, n_points, seed, dps, reference_name)


# ---------------------------------------------------------------- symbolic helpers
def _solve_stationary(P):
    return sp.solve(sp.diff(P, S.a), S.a)


def _solve_load(P, load):
    return sp.solve(sp.Eq(P, load), S.a)


def _single_power(P0):
    """P0 = C a**m (one pure power term) -> (C, m), else None."""
    if P0.has(sp.Piecewise, sp.Integral):
        return None
    try:
        terms = decompose(P0, S.a)
    except NotDecomposable:
        return None
    if len(terms) != 1 or not terms[0].is_power or terms[0].coef.has(S.a):
        return None
    return terms[0].coef, terms[0].mu


# ---------------------------------------------------------------- the contact
class AdhesiveLineContact:
    """JKR-adhesive form of a :class:`~linecontact_sym.contact.LineContact`
    (Popov 2017, Eqs. 29-36).

    Parameters
    ----------
    contact : LineContact
        The non-adhesive contact (profile, parameters, budget, verification).
    work_of_adhesion : sympy expression or number, default ``lcs.gamma``
        gamma (the paper's gamma_12) >= 0; gamma = 0 is the non-adhesive limit.
    values : dict, optional
        Numeric values (by name or Symbol) bound to the contact; see :meth:`at`.

    Quantities (SymPy expressions, each with a :meth:`derivation` record):

    * ``force``      P(a) = P0(a) - sqrt(2 pi a gamma E*), Eq. (33)
    * ``pressure``   p0(x; a) - Phat/(pi sqrt(a**2 - x**2)), Eq. (29)
    * ``flat_punch_force``  Phat = sqrt(2 pi a gamma E*), Eq. (31) (the
      energy-release-rate balance K_I**2/(2 E*) = gamma at the edge with
      K_I = Phat/sqrt(pi a), Eq. 30)
    * ``pull_off_force``  P_min, the minimum of P(a) under load control, a
      *negative* load (Eqs. 34-36 print P_adh = -P_min); ``adhesion_force``
      is P_adh = -P_min > 0
    * ``pull_off_half_width`` (= ``jump_out_half_width``), ``jump_in_half_width``

    Examples
    --------
    >>> import linecontact_sym as lcs
    >>> ad = lcs.parabola().adhesive(lcs.gamma)
    >>> ad.force
    -sqrt(2)*sqrt(pi)*sqrt(E_star)*sqrt(a)*sqrt(gamma) + pi*E_star*a**2/(4*R)
    >>> ad.pull_off_force
    -3*2**(2/3)*pi**(1/3)*E_star**(1/3)*R**(1/3)*gamma**(2/3)/4
    """

    QUANTITIES = ("force", "pressure", "flat_punch_force", "pull_off_force", "adhesion_force",
                  "pull_off_half_width", "jump_in_half_width")

    def __init__(self, contact, work_of_adhesion=S.gamma, values=None):
        if isinstance(work_of_adhesion, str):
            raise DomainError("the work of adhesion is a string; strings are not evaluated. "
                              "Pass a SymPy expression or a number (e.g. lcs.gamma)")
        g = sp.nsimplify(work_of_adhesion, rational=True) if isinstance(work_of_adhesion, float) \
            else to_sympy(work_of_adhesion)
        if not isinstance(g, sp.Expr):
            raise DomainError(f"the work of adhesion must be an expression, got {g!r}")
        if g.has(S.x, S.a, S.P):
            raise DomainError(f"the work of adhesion {g} may not depend on x, a or P")
        if g.is_negative:
            raise DomainError(f"the work of adhesion must be >= 0, got {g}")
        if g.is_nonnegative is not True:
            raise DomainError(f"the sign of the work of adhesion {g} is unknown; use a symbol "
                              f"created with positive=True (e.g. lcs.gamma) or a number >= 0")
        self.contact = contact
        self.gamma = g
        self._gsyms = tuple(sorted(g.free_symbols - set(contact.params) - {S.E_star},
                                   key=lambda s: s.name))
        self._cache: dict = {}
        self._laws: dict = {}
        self.values = {}
        if values:
            self.values = _values_by_name(self.variables, dict(values))

    # ----------------------------------------------------------- plumbing
    def __repr__(self):
        return f"AdhesiveLineContact({self.contact.profile.expr}, gamma={self.gamma})"

    @property
    def profile(self):
        return self.contact.profile

    @property
    def params(self):
        return self.contact.params

    @property
    def variables(self):
        """The symbols a number needs: E_star, the profile parameters and the
        symbols of the work of adhesion."""
        return (S.E_star,) + tuple(self.params) + self._gsyms

    def at(self, **values):
        """A copy with numeric values bound (by name): its quantities are
        numbers, and ``pull_off_force`` is a verified number even where no
        closed form exists."""
        new = AdhesiveLineContact(self.contact, self.gamma, {**{k.name: v for k, v in self.values.items()},
                                                           **values})
        new._cache, new._laws = self._cache, self._laws
        return new

    def derivation(self, quantity: str) -> Derivation:
        """The :class:`Derivation` of ``'force'`` (33), ``'pressure'`` (29),
        ``'flat_punch_force'`` (31), ``'pull_off_force'``, ``'adhesion_force'``,
        ``'pull_off_half_width'`` (34-36) or ``'jump_in_half_width'``."""
        if quantity not in self._cache:
            maker = {"force": self._derive_force, "pressure": self._derive_pressure,
                     "flat_punch_force": self._derive_phat, "Phat": self._derive_phat,
                     "pull_off_force": lambda: self._derive_pull_off("pull_off_force"),
                     "adhesion_force": lambda: self._derive_pull_off("adhesion_force"),
                     "pull_off_half_width": lambda: self._derive_pull_off("pull_off_half_width"),
                     "jump_out_half_width": lambda: self._derive_pull_off("pull_off_half_width"),
                     "jump_in_half_width": self._derive_jump_in}.get(quantity)
            if maker is None:
                raise ValueError(f"unknown quantity {quantity!r}; choose one of {self.QUANTITIES}")
            self._cache[quantity] = maker()
        return self._cache[quantity]

    def _bind(self, expr):
        return expr.xreplace(self.values) if self.values else expr

    def _sampler(self, kind: str):
        base = self.contact._sampler(kind)
        gsyms = self._gsyms

        def sample(rng):
            vals = base(rng)
            if vals is None:
                return None
            for gs in gsyms:
                vals[gs] = _rat(rng.uniform(*GAMMA_RANGE))
            return _fl(vals)
        return sample

    def _law(self, vals: dict, mode: str) -> _Law:
        fixed = _fl({k: to_sympy(v) for k, v in vals.items() if k in set(self.variables)})
        key = (mode, tuple(sorted((k.name, v) for k, v in fixed.items())))
        if key not in self._laws:
            law = _Law(self, fixed, mode)
            if mode == "quad" and self.contact.derivation("force").closed_form:
                law.scan_source = self._law(vals, "closed")
            self._laws[key] = law
        return self._laws[key]

    def _numeric_values(self, values):
        vals = dict(self.values)
        if values:
            vals.update(_values_by_name(self.variables, values) if len(values) >= len(self.variables)
                        else {s: to_sympy(values[s.name]) for s in self.variables if s.name in values})
        missing = [s.name for s in self.variables if s not in vals]
        if missing:
            raise NumericValuesRequired(f"values needed for {', '.join(missing)}")
        for s in self.variables:
            v = vals[s]
            if isinstance(v, float):
                vals[s] = sp.nsimplify(v, rational=True)
            if not to_sympy(vals[s]).is_number:
                raise DomainError(f"{s.name} = {vals[s]} is not a number")
        return vals

    @property
    def Phat(self) -> sp.Expr:
        """Eq. (31) Phat = sqrt(2 pi a gamma E*), see :func:`flat_punch_force`."""
        return self._bind(flat_punch_force(self.gamma))

    @property
    def stress_intensity(self) -> sp.Expr:
        """Eq. (30): K_I = Phat/sqrt(pi a) = sqrt(2 gamma E*) at the edges."""
        return self._bind(sp.simplify(stress_intensity(flat_punch_force(self.gamma))))

    @property
    def energy_release_rate(self) -> sp.Expr:
        """G = K_I**2/(2 E*); equals gamma at equilibrium (Griffith, Eq. 30)."""
        return self._bind(sp.simplify(energy_release_rate(stress_intensity(flat_punch_force(self.gamma)))))

    # ----------------------------------------------------------- Eqs. (29), (31), (33)
    def _derive_phat(self) -> Derivation:
        """Eq. (31), verified against the energy balance computed from the
        flat-punch compliance by quadrature (Eq. 3), numerical
        differentiation and root finding.  Profile-independent: shared by
        all contacts with the same work of adhesion."""
        key = (self.gamma, self.contact.points, self.contact.verify)
        if key not in _PHAT_CACHE:
            _PHAT_CACHE[key] = self._derive_phat_uncached()
        return _PHAT_CACHE[key]

    def _derive_phat_uncached(self) -> Derivation:
        t0 = time.perf_counter()
        expr = flat_punch_force(self.gamma)
        gsyms = self._gsyms
        gexpr = self.gamma

        def sampler(rng):
            vals = {S.a: _rat(rng.uniform(0.05, 2.0)), S.E_star: _rat(rng.uniform(0.5, 3.0))}
            for gs in gsyms:
                vals[gs] = _rat(rng.uniform(*GAMMA_RANGE))
            return _fl(vals)

        def reference(vals, dps):
            return _phat_energy(vals[S.a], gexpr.xreplace(vals), vals[S.E_star], dps, quadrature=True)
        rec = None
        if self.contact.verify and self.gamma != 0:
            rec = verify(expr, reference, sampler, (), n_points=self.contact.points, dps=VERIFY_DPS,
                         reference_name="energy release rate G = (Phat^2/2)|dC/d(2a)| = gamma of the "
                                        "flat punch, compliance C by quadrature of Eq. (3), mpmath.diff + "
                                        "findroot")
            self._require(rec, "flat_punch_force")
        return Derivation("flat_punch_force", expr, True,
                          "Eq. (31): Griffith balance K_I^2/(2 E*) = gamma at the edge, K_I = Phat/sqrt(pi a) "
                          "(Eq. 30)", (), rec, time.perf_counter() - t0,
                          ("K_I = Phat/sqrt(pi*a) = sqrt(2*gamma*E_star); G = K_I^2/(2 E*) = Phat^2/(2 pi a E*)",),
                          lambda vals, dps: _phat_energy(vals[S.a], gexpr.xreplace(vals), vals[S.E_star], dps),
                          (S.a, S.E_star) + tuple(sorted(gexpr.free_symbols, key=lambda s: s.name)))

    def _require(self, rec, what):
        if rec is not None and not rec.passed:
            raise VerificationError(f"{what} of {self.profile.name!r} failed verification: "
                                    f"{rec.min_digits:.1f} digits < {rec.required}")

    def _derive_force(self) -> Derivation:
        """Eq. (33): P(a) = P0(a) - Phat."""
        t0 = time.perf_counter()
        fd = self.contact.derivation("force")
        Phat = flat_punch_force(self.gamma)
        expr = fd.expr - Phat
        prof = self.profile
        gexpr = self.gamma

        def reference(vals, dps):
            with mpmath.workdps(dps + 10):
                return T.force_quad(prof, vals, dps) - _phat_energy(
                    vals[S.a], gexpr.xreplace(vals), vals[S.E_star], dps, quadrature=False)
        rec = None
        if fd.closed_form and self.contact.verify:
            rec = verify(expr, reference, self._sampler("force"), fd.conditions,
                         n_points=self.contact.points, dps=VERIFY_DPS,
                         reference_name="quadrature of Eq. (10*) minus Phat from the energy balance of "
                                        "the flat-punch compliance (Eq. 3, mpmath.diff + findroot)")
            self._require(rec, "force")
        method = ("Eq. (33): P0(a) of the engine (" + fd.method + ") minus Phat, Eq. (31)"
                  if fd.closed_form else "numeric fallback: unevaluated Eq. (10*) minus Phat")
        return Derivation("force", expr, fd.closed_form, method, fd.conditions, rec,
                          time.perf_counter() - t0, fd.notes, reference,
                          (S.a, S.E_star) + self.params + self._gsyms)

    def _derive_pressure(self) -> Derivation:
        """Eq. (29): p(x) = p0(x) - Phat/(pi sqrt(a^2 - x^2))."""
        t0 = time.perf_counter()
        pd = self.contact.derivation("pressure")
        Phat = flat_punch_force(self.gamma)
        expr = pd.expr - Phat / (sp.pi * sp.sqrt(S.a**2 - S.x**2))
        gexpr = self.gamma

        def reference(vals, dps):
            with mpmath.workdps(dps + 10):
                A, X = _mp(vals[S.a]), _mp(vals[S.x])
                ph = _phat_energy(A, gexpr.xreplace(vals), vals[S.E_star], dps, quadrature=False)
                return pd.reference(vals, dps) - ph / (mpmath.pi * mpmath.sqrt(A**2 - X**2))
        rec, notes = None, list(pd.notes)
        if pd.closed_form and self.contact.verify:
            rec = verify(expr, reference, self._sampler("pressure"), pd.conditions,
                         n_points=self.contact.points, dps=VERIFY_DPS,
                         reference_name="Eq. (12) quadrature of p0 minus the flat punch (Eq. 1) with Phat "
                                        "from the energy balance (mpmath.diff + findroot)")
            self._require(rec, "pressure")
            eq = self._equilibrium_check(expr)
            notes.append(f"equilibrium: 2 int_0^a p dx (quadrature of Eq. 29) = P(a) of Eq. (33) to "
                         f">= {eq:.1f} digits at {self.contact.points} random points")
        method = ("Eq. (29): p0 of the engine (" + pd.method + ") minus the pulled flat punch"
                  if pd.closed_form else "numeric fallback: unevaluated Eq. (12) minus the flat punch")
        return Derivation("pressure", expr, pd.closed_form, method, pd.conditions, rec,
                          time.perf_counter() - t0, tuple(notes), reference,
                          (S.a, S.x, S.E_star) + self.params + self._gsyms)

    def _equilibrium_check(self, pexpr) -> float:
        """min digits of int_{-a}^{a} p dx = P(a) at random points."""
        fexpr = self.derivation("force").expr
        sample = self._sampler("force")
        rng = random.Random(29)
        worst = float(VERIFY_DPS)
        done = 0
        while done < self.contact.points:
            vals = sample(rng)
            if vals is None:
                continue
            with mpmath.workdps(VERIFY_DPS + 10):
                A = _mp(vals[S.a])
                # x = a sin(phi), sqrt(a^2 - x^2) = a cos(phi) (no cancellation at the edge)
                e = pexpr.replace(lambda z: z.is_Pow and z.base == S.a**2 - S.x**2,
                                  lambda z: (S.a * sp.cos(_phi))**(2 * z.exp))
                e = e.xreplace({S.x: S.a * sp.sin(_phi)})
                e = e.xreplace({k: v for k, v in vals.items() if k != S.x})
                pf = sp.lambdify(_phi, e * sp.cos(_phi), "mpmath")
                tiny = mpmath.mpf(10)**-20

                def integrand(ph):
                    try:  # doubled precision: cos(phi) -> 1 cancels near phi = 0 (wedge: atanh(cos phi))
                        with mpmath.workdps(2 * mpmath.mp.dps + 10):
                            v = _real(pf(ph))
                        return +v
                    except (_Outside, ZeroDivisionError, ValueError):
                        # integrable end-point singularity (e.g. the wedge's log at x = 0)
                        # met at a node within 1e-20 of the end: its share is negligible
                        if ph < tiny or mpmath.pi / 2 - ph < tiny:
                            return mpmath.mpf(0)
                        raise
                I = 2 * A * mpmath.quad(integrand, [0, mpmath.pi / 2])
                ref = _mp(sp.N(fexpr.xreplace(vals), VERIFY_DPS + 10))
                with mpmath.workdps(VERIFY_DPS):
                    worst = min(worst, _digits(I, ref))
            done += 1
        return worst

    # ----------------------------------------------------------- pull-off
    def _existence(self, C, m, vals=None):
        """Raise NoPullOffError for a single power law P0 = C a**m, m <= 1/2."""
        mv = m.xreplace(vals) if vals else m
        if not mv.is_number:
            return
        if self.gamma.xreplace(vals or {}) == 0:
            raise NoPullOffError(f"{self.profile.name!r}: no adhesion (gamma = 0), no tensile pull-off")
        if mv > sp.S.Half:
            return
        name = self.profile.name
        if mv < sp.S.Half:
            raise NoPullOffError(
                f"{name!r}: P0 ~ a**({mv}) grows slower than the adhesive term sqrt(2 pi a gamma E*) "
                f"(exponent {mv} < 1/2): P(a) has a maximum, not a minimum; tensile equilibria are "
                f"all unstable and P -> -oo as a -> oo, loads above the maximum have no equilibrium. "
                f"No finite pull-off exists for n < 1/2 (it needs n > 1/2).")
        gc = sp.simplify(C**2 / (2 * sp.pi * S.E_star))
        raise NoPullOffError(
            f"{name!r}: exponent n = 1/2 is the borderline: P = (C - sqrt(2 pi gamma E*)) sqrt(a) with "
            f"C = {C} is monotone. For gamma < gamma_c = {gc} no tensile load is sustained (zero "
            f"pull-off, reached only as a -> 0); for gamma > gamma_c P -> -oo, every equilibrium "
            f"is unstable and the contact spreads without bound. No finite pull-off (needs n > 1/2).")

    def _pull_off_reference(self, vals, dps, mode="quad"):
        key = ("po_ref", mode, dps, tuple(sorted((k.name, v) for k, v in vals.items()
                                                 if k in set(self.variables))))
        if key not in self._cache:
            try:
                self._cache[key] = self._law(vals, mode).minimum(dps)
            except NoPullOffError as exc:
                self._cache[key] = exc
        res = self._cache[key]
        if isinstance(res, Exception):
            raise res
        return res

    def _derive_pull_off(self, quantity) -> Derivation:
        if "_po" not in self._cache:
            self._cache["_po"] = self._pull_off_symbolic()
        force_d, adh_d, hw_d = self._cache["_po"]
        return {"pull_off_force": force_d, "adhesion_force": adh_d,
                "pull_off_half_width": hw_d}[quantity]

    def _pull_off_closed(self):
        """The symbolic attempt alone (cached): a dict with Pmin, a_star, adh,
        conds, notes, method, t0 -- Pmin None when there is no closed form."""
        if "_po_closed" not in self._cache:
            self._cache["_po_closed"] = self._pull_off_closed_uncached()
        return self._cache["_po_closed"]

    def _pull_off_symbolic(self):
        """Closed forms verified against the quadrature-only minimisation;
        else numeric Derivations verified by two independent methods."""
        r = self._pull_off_closed()
        Pmin, a_star, adh, conds = r["Pmin"], r["a_star"], r["adh"], r["conds"]
        notes, method, t0 = list(r["notes"]), r["method"], r["t0"]
        P = self.derivation("force").expr
        variables = self.variables
        variables_all = variables
        if Pmin is None:
            return self._pull_off_numeric(P, notes, t0)
        recP = recA = recAdh = None
        ref_f = lambda v, d: self._pull_off_reference(v, d).force
        ref_h = lambda v, d: self._pull_off_reference(v, d).half_width
        if self.contact.verify:
            def reference(v, d):
                po = self._pull_off_reference(v, d)
                return {"P": po.force, "adh": po.adhesion_force, "a": po.half_width}
            recs = _verify_multi(
                {"P": Pmin, "adh": adh, "a": a_star}, reference, self._sampler("force"), conds,
                self.contact.points, VERIFY_DPS,
                {"P": "global minimisation of the quadrature force law (10*) minus Phat: scan + "
                      "findroot of the quadrature dP/da",
                 "adh": "minus the quadrature-based minimum of P(a)",
                 "a": "half-width of the quadrature-based minimum of P(a)"})
            recP, recAdh, recA = recs["P"], recs["adh"], recs["a"]
            self._require(recP, "pull_off_force")
            self._require(recA, "pull_off_half_width")
            self._require(recAdh, "adhesion_force")
        dt = time.perf_counter() - t0
        note = tuple(notes) + ("load control; pull_off_force = P_min < 0, adhesion_force = -P_min "
                               "(the paper's P_adh)",)
        return (Derivation("pull_off_force", Pmin, True, method, tuple(conds), recP, dt, note, ref_f,
                           variables_all),
                Derivation("adhesion_force", adh, True, method, tuple(conds), recAdh, dt, note,
                           lambda v, d: mpmath.fneg(ref_f(v, d), exact=True), variables_all),
                Derivation("pull_off_half_width", a_star, True, method, tuple(conds), recA, dt, note,
                           ref_h, variables_all))

    def _pull_off_closed_uncached(self):
        t0 = time.perf_counter()
        fd = self.contact.derivation("force")
        P = self.derivation("force").expr
        notes, conds = [], list(fd.conditions)
        single = _single_power(fd.expr) if fd.closed_form else None
        if self.gamma == 0:
            raise NoPullOffError(f"{self.profile.name!r}: no adhesion (gamma = 0): P(a) = P0(a) >= 0, "
                                 f"no tensile pull-off")
        a_star = Pmin = adh = None
        method = None
        if fd.closed_form and self.gamma != 0:
            if single is not None:
                C, m = single
                self._existence(C, m)
                if not m.is_number:
                    conds.append(sp.Gt(m, sp.S.Half))
            cands = []
            try:
                cands = run_with_budget(_solve_stationary, P, seconds=self.contact.budget)
                notes.append(f"sympy.solve(dP/da = 0) gave {len(cands)} candidate(s)")
            except BudgetExceeded:
                notes.append("sympy.solve(dP/da = 0) ran out of budget")
            except (NotImplementedError, ValueError, TypeError) as exc:
                notes.append(f"sympy.solve(dP/da = 0): {type(exc).__name__}")
            a_star = self._pick_minimum(cands, P, conds)
            if a_star is not None:
                method = "sympy.solve of dP/da = 0, minimum checked numerically (P'' > 0)"
                compact, adh = False, None
                Pmin = P.xreplace({S.a: a_star})
                if single is not None:
                    C, m = single
                    compact_P = -(2 * m - 1) / (2 * m) * ((2 * sp.pi * self.gamma * S.E_star)**m
                                                          / (2 * m * C))**(1 / (2 * m - 1))
                    compact_a = (2 * sp.pi * self.gamma * S.E_star / (4 * m**2 * C**2))**(1 / (2 * m - 1))
                    if self._same(compact_P, Pmin, conds) and self._same(compact_a, a_star, conds):
                        Pmin, a_star, compact = compact_P, compact_a, True
                        adh = (2 * m - 1) / (2 * m) * ((2 * sp.pi * self.gamma * S.E_star)**m
                                                       / (2 * m * C))**(1 / (2 * m - 1))
                        notes.append("single power term P0 = C a**m: P_min = -(2m-1)/(2m) "
                                     "((2 pi gamma E*)**m/(2 m C))**(1/(2m-1)) (equal to the solve "
                                     "result at 5 points to 40 digits)")
                Pmin = self._tidy(Pmin, conds, simplify=not compact)
                a_star = self._tidy(a_star, conds, simplify=not compact)
                if adh is None:
                    adh = self._tidy(-Pmin, conds)
        return dict(Pmin=Pmin, a_star=a_star, adh=adh, conds=conds, notes=notes, method=method, t0=t0)

    def _points(self, conds, n=5, seed=11):
        sample = self._sampler("force")
        rng = random.Random(seed)
        from ..method.derivation import _holds
        out, tries = [], 0
        while len(out) < n and tries < 40 * n:
            tries += 1
            v = sample(rng)
            if v is not None and _holds(conds, v):
                out.append(v)
        return out

    def _same(self, e1, e2, conds) -> bool:
        for v in self._points(conds):
            x1 = sp.N(e1.xreplace(v), 50)
            x2 = sp.N(e2.xreplace(v), 50)
            if not (x1.is_real and x2.is_real) or abs(x1 - x2) > abs(x2) * sp.Float(10)**-40:
                return False
        return True

    def _tidy(self, e, conds, simplify=True):
        if simplify:
            try:
                cand = run_with_budget(tidy, e, seconds=min(self.contact.budget, 15))
            except Exception:
                cand = e
            if sp.count_ops(cand) <= sp.count_ops(e) and self._same(cand, e, conds):
                e = cand
        # |tan(theta)| etc. are positive on admissible profiles: drop the Abs
        for ab in list(e.atoms(sp.Abs)):
            inner = ab.args[0]
            if all(sp.N(inner.xreplace(v), 30) > 0 for v in self._points(conds)):
                e2 = e.xreplace({ab: inner})
                if self._same(e2, e, conds):
                    e = e2
        return e

    def _pick_minimum(self, cands, P, conds):
        """The candidate a* that is a real positive local minimum of P at
        random admissible points."""
        d1, d2 = sp.diff(P, S.a), sp.diff(P, S.a, 2)
        pts = self._points(conds)
        for cand in cands:
            if cand.has(S.a) or cand.has(sp.RootOf):
                continue
            ok = bool(pts)
            for v in pts:
                av = sp.N(cand.xreplace(v), 50)
                if not av.is_real or not av > 0:
                    ok = False
                    break
                sub = {**v, S.a: av}
                g1 = sp.N(d1.xreplace(sub), 50)
                g2 = sp.N(d2.xreplace(sub), 50)
                if not (abs(g1) < sp.Float(10)**-35 * (1 + abs(sp.N(P.xreplace(sub), 50)) / av)
                        and g2 > 0):
                    ok = False
                    break
            if ok:
                return cand
        return None

    def _pull_off_numeric(self, P, notes, t0):
        """No closed form: Derivations whose evalf is the numeric minimum,
        verified at random points by two independent methods."""
        notes = list(notes) + [
            "no closed form: method A = scan + findroot of dP/da from the engine's force law "
            "(closed form if any, else the quadrature P0'(a) with kink terms); method B = "
            "mpmath.diff of the quadrature force law (10*) + findroot (kinks: one-sided differences)"]
        rec = None
        if self.contact.verify and self.gamma != 0:
            sample = self._sampler("force")
            n_points = self.contact.points

            def work():  # in a budgeted child, like the engine's verify
                pts, digs = [], []
                rng = random.Random(2017)
                tries = 0
                while len(pts) < n_points and tries < 20 * n_points:
                    tries += 1
                    v = sample(rng)
                    if v is None:
                        continue
                    try:
                        po = self._pull_off_checked(v, VERIFY_DPS)
                    except (NoPullOffError, ZeroDivisionError, ValueError):
                        continue
                    pts.append(v)
                    digs.append(po.digits)
                return pts, digs
            name = ("two independent minimisations (A: analytic dP/da, B: numerical "
                    "differentiation of the quadrature force law)")
            try:
                from ..method.derivation import VERIFY_BUDGET as budget
            except ImportError:
                budget = 120.0
            try:
                pts, digs = run_with_budget(work, seconds=budget)
            except BudgetExceeded:
                pts, digs, name = [], [], name + f" (did not finish in {budget:g} s)"
            rec = VerificationRecord(tuple(pts), tuple(digs), VERIFY_DPS, name)
            self._require(rec, "pull_off_force")
        stat = sp.Eq(sp.diff(P, S.a), 0)
        dt = time.perf_counter() - t0
        variables = self.variables
        mk = lambda q, attr, sign=1: _NumericDerivation(
            q, stat, False, "numeric: global minimum of P(a) (no closed form)", (), rec, dt,
            tuple(notes), lambda v, d: mpmath.fmul(sign, getattr(self._pull_off_checked(v, d), attr), exact=True), variables)
        return (mk("pull_off_force", "force"), mk("adhesion_force", "force", -1),
                mk("pull_off_half_width", "half_width"))

    def _pull_off_checked(self, vals, dps) -> PullOff:
        """Numeric pull-off at a point by method A, checked by method B."""
        key = ("po_checked", dps, tuple(sorted((k.name, v) for k, v in vals.items()
                                               if k in set(self.variables))))
        if key in self._cache:
            return self._cache[key]
        law = self._law(vals, "closed")
        po = law.minimum(dps)
        po_b = law.minimum_by_differences(dps, po)
        with mpmath.workdps(dps):
            d = min(_digits(po.force, po_b.force), _digits(po.half_width, po_b.half_width)
                    if po.kind == "stationary" else float(dps))
        res = PullOff(po.force, po.adhesion_force, po.half_width, po.kind, d)
        self._cache[key] = res
        return res

    def pull_off_at(self, dps: int = 30, **values) -> PullOff:
        """The pull-off at numeric values (by name): a :class:`PullOff` with
        the force P_min < 0, P_adh = -P_min, the half-width and how the two
        independent methods agree.  Raises :class:`NoPullOffError` where no
        finite pull-off exists, :class:`VerificationError` if the methods
        disagree below ``dps`` digits."""
        vals = self._numeric_values(values)
        if self._pull_off_closed()["Pmin"] is not None:
            fd = self.derivation("pull_off_force")
            from ..method.derivation import _holds
            single = _single_power(self.contact.derivation("force").expr)
            if single is not None:
                self._existence(single[0], single[1], vals)
            if not _holds(fd.conditions, vals):
                raise NoPullOffError(f"{self.profile.name!r}: the pull-off conditions "
                                     f"{fd.conditions} fail at {values}: no finite pull-off")
            fv = _fl(vals)
            with mpmath.workdps(dps + 10):
                Pm = _mp(sp.N(fd.expr.xreplace(fv), dps + 10))
                A = _mp(sp.N(self.derivation("pull_off_half_width").expr.xreplace(fv), dps + 10))
                return PullOff(Pm, -Pm, A, "stationary", None)
        po = self._pull_off_checked(vals, dps)
        if po.digits < dps:
            raise VerificationError(f"pull-off of {self.profile.name!r}: the two methods agree to "
                                    f"{po.digits:.1f} < {dps} digits at {values}")
        return po

    def pull_off_force_at(self, dps: int = 30, **values):
        """P_min (< 0) at numeric values, verified to ``dps`` digits."""
        return self.pull_off_at(dps, **values).force

    def adhesion_force_at(self, dps: int = 30, **values):
        """P_adh = -P_min (> 0) at numeric values."""
        return self.pull_off_at(dps, **values).adhesion_force

    def pull_off_half_width_at(self, dps: int = 30, **values):
        return self.pull_off_at(dps, **values).half_width

    def _closed_or_number(self, quantity):
        if self._pull_off_closed()["Pmin"] is not None:
            return self._bind(self.derivation(quantity).expr)
        if self.values and all(s in self.values for s in self.variables):
            po = self.pull_off_at(30, **{s.name: v for s, v in self.values.items()})
            return {"pull_off_force": po.force, "adhesion_force": po.adhesion_force,
                    "pull_off_half_width": po.half_width}[quantity]
        raise NumericValuesRequired(
            f"{quantity} of {self.profile.name!r} has no closed form (dP/da = 0 is transcendental "
            f"here); give numbers: ad.{quantity}_at({', '.join(s.name + '=...' for s in self.variables)})"
            f" or ad.at(...).{quantity}")

    # ----------------------------------------------------------- jump-in
    def _derive_jump_in(self) -> Derivation:
        """Stable root of P(a) = 0: the half-width the contact snaps to at zero load."""
        t0 = time.perf_counter()
        fd = self.contact.derivation("force")
        P = self.derivation("force").expr
        expr, notes = None, []
        conds = list(fd.conditions)
        single = _single_power(fd.expr) if fd.closed_form else None
        if single is not None and not single[1].is_number:
            conds.append(sp.Gt(single[1], sp.S.Half))
        method = "sympy.solve of P(a) = 0, stable root"

        def reference(vals, dps):
            law = self._law(vals, "quad")
            po = self._pull_off_reference(vals, dps)
            roots = [r for r, st in law.equilibria(0, dps) if st and r > po.half_width]
            if not roots:
                raise NoEquilibriumError("no stable equilibrium at zero load")
            return roots[0]
        if fd.closed_form and not P.has(sp.Piecewise) and self.gamma != 0:
            if single is not None:
                C, m = single
                cands = [(2 * sp.pi * self.gamma * S.E_star / C**2)**(1 / (2 * m - 1))]
                method = "P(a) = 0 for the single power term P0 = C a**m: a_in = (2 pi gamma E*/C**2)**(1/(2m-1))"
            else:
                cands = []
                try:
                    cands = run_with_budget(_solve_load, P, 0, seconds=self.contact.budget)
                except (BudgetExceeded, NotImplementedError, ValueError, TypeError) as exc:
                    notes.append(f"sympy.solve(P = 0): {type(exc).__name__}")
            for cand in cands:
                if cand.has(S.a) or cand.has(sp.RootOf):
                    continue
                try:
                    good = all(abs(sp.N(P.xreplace({**v, S.a: cand.xreplace(v)}), 50))
                               < sp.Float(10)**-35 and sp.N(cand.xreplace(v), 50) > 0
                               and sp.N(sp.diff(P, S.a).xreplace({**v, S.a: cand.xreplace(v)}), 30) > 0
                               for v in self._points(conds))
                except TypeError:
                    good = False
                if good:
                    expr = self._tidy(cand, conds, simplify=single is None)
                    break
        if expr is None:
            return _NumericDerivation("jump_in_half_width", sp.Eq(P, 0), False,
                                      "numeric: stable root of P(a) = 0", (), None,
                                      time.perf_counter() - t0, tuple(notes), reference, self.variables)
        rec = None
        if self.contact.verify:
            rec = verify(expr, reference, self._sampler("force"), conds, n_points=self.contact.points,
                         dps=VERIFY_DPS, reference_name="stable root of the quadrature force law P(a) = 0")
            self._require(rec, "jump_in_half_width")
        return Derivation("jump_in_half_width", expr, True, method,
                          tuple(conds), rec, time.perf_counter() - t0, tuple(notes), reference,
                          self.variables)

    # ----------------------------------------------------------- equilibria
    def half_width(self, load=S.P, dps: int = 30, **values):
        """Equilibrium half-width(s) at the load P, **stable branch first**.

        Numeric load with numeric values (keywords by name, or bound with
        :meth:`at`): a tuple of mpf, stable ones (dP/da > 0, load control)
        first; for a single-minimum law P_min < P < 0 gives
        ``(a_stable, a_unstable)``, P >= 0 gives ``(a_stable,)``.  Below the
        pull-off force raises :class:`NoEquilibriumError`.

        Symbolic load: a tuple of two :class:`Derivation` s ``(stable,
        unstable)`` -- closed forms from sympy.solve (under the budget) where
        found and checked at random points on each branch, else the
        unevaluated P(a) = P with a numeric ``evalf``.
        """
        load = to_sympy(load)
        if load.free_symbols:
            key = ("half_width", load)
            if key not in self._cache:
                self._cache[key] = self._derive_half_widths(load)
            return self._cache[key]
        vals = self._numeric_values(values)
        law = self._law(vals, "closed")
        roots = law.equilibria(load, dps)
        if not roots:
            pts, edge = law.scan()
            with mpmath.workdps(20):
                lo = min(Pv for _, Pv, _ in pts)
                if _mp(load) <= lo:
                    why = ("below the pull-off force (the minimum of P(a)): the surfaces separate")
                elif edge:
                    why = (f"above the loads reached for a <= {mpmath.nstr(pts[-1][0], 12)}, within "
                           f"1e-12 of the end of the profile's domain")
                elif pts[-1][2] < 0:
                    why = ("above the maximum of P(a) (P decreases at large a, e.g. a power law with "
                           "n < 1/2): the contact would spread without bound")
                else:
                    why = f"above the loads reached on the search range a <= {mpmath.nstr(pts[-1][0], 6)}"
            raise NoEquilibriumError(f"{self.profile.name!r}: no equilibrium at the load P = {load}, {why}")
        return tuple(r for r, _ in roots)

    def branches(self, load, dps: int = 30, **values):
        """Like :meth:`half_width` with the stability: ((a, 'stable'|'unstable'), ...)."""
        vals = self._numeric_values(values)
        roots = self._law(vals, "closed").equilibria(to_sympy(load), dps)
        return tuple((r, "stable" if st else "unstable") for r, st in roots)

    def _derive_half_widths(self, load):
        t0 = time.perf_counter()
        fd = self.contact.derivation("force")
        P = self.derivation("force").expr
        notes = []
        cands = []
        if fd.closed_form and not P.has(sp.Piecewise) and self.gamma != 0:
            try:
                cands = run_with_budget(_solve_load, P, load, seconds=self.contact.budget)
            except BudgetExceeded:
                notes.append(f"sympy.solve(P(a) = {load}) ran out of its {self.contact.budget:g} s budget")
            except (NotImplementedError, ValueError, TypeError) as exc:
                notes.append(f"sympy.solve(P(a) = {load}): {type(exc).__name__}")
        variables = (load,) + self.variables

        def ref(stable):
            def reference(vals, dps):
                law = self._law(vals, "closed")
                roots = [r for r, st in law.equilibria(vals[load], dps) if st == stable]
                if not roots:
                    raise NoEquilibriumError(f"no {'stable' if stable else 'unstable'} equilibrium")
                return roots[0]
            return reference
        out = []
        conds_po = self.derivation("pull_off_force")
        for stable in (True, False):
            samples = self._branch_samples(load, stable) if cands else []
            chosen, rec = None, None
            for cand in cands:
                digs = []
                for v, av in samples:
                    try:
                        with mpmath.workdps(VERIFY_DPS):
                            val = _mp(sp.N(cand.xreplace(v), VERIFY_DPS + 10))
                            digs.append(_digits(val, _mp(av)))
                    except (TypeError, ValueError):
                        digs.append(0.0)
                if samples and min(digs) >= self.contact.digits:
                    chosen = cand
                    rec = VerificationRecord(tuple(v for v, _ in samples), tuple(digs), VERIFY_DPS,
                                             f"the sampled half-width on the {'stable' if stable else 'unstable'}"
                                             f" branch, load = P(a) from the verified Eq. (33)")
                    break
            q = "half_width_stable" if stable else "half_width_unstable"
            cond = []
            if conds_po.closed_form:
                cond.append(sp.Gt(load, conds_po.expr))
            if not stable:
                cond.append(sp.Lt(load, 0))
            if chosen is not None:
                out.append(Derivation(q, self._tidy(chosen, []) if sp.count_ops(chosen) < 80 else chosen,
                                      True, "sympy.solve of P(a) = P, branch identified at random points",
                                      tuple(cond), rec, time.perf_counter() - t0, tuple(notes),
                                      ref(stable), variables))
            else:
                out.append(Derivation(q, sp.Eq(P, load), False,
                                      f"numeric root of P(a) = P on the {'stable' if stable else 'unstable'} "
                                      f"branch (no closed form)", tuple(cond), None,
                                      time.perf_counter() - t0, tuple(notes), ref(stable), variables))
        return tuple(out)

    def _branch_samples(self, load, stable):
        """(values incl. the load, half-width) on one branch: a = a_po*u."""
        sample = self._sampler("force")
        rng = random.Random(31 if stable else 37)
        out, tries = [], 0
        while len(out) < self.contact.points and tries < 20 * self.contact.points:
            tries += 1
            v = sample(rng)
            if v is None:
                continue
            try:
                po = self._law(v, "closed").minimum(VERIFY_DPS)
            except (NoPullOffError, DomainError):
                continue
            u = rng.uniform(1.2, 3.0) if stable else rng.uniform(0.1, 0.9)
            with mpmath.workdps(VERIFY_DPS + 10):
                av = _rat(float(po.half_width) * u)
                law = self._law(v, "closed")
                if (law.dP(_mp(av)) > 0) != stable:
                    continue
                v = {k: w for k, w in v.items() if k != S.a}
                av = sp.Float(av, 80)
                Lv = sp.N(self.derivation("force").expr.xreplace({**v, S.a: av}), VERIFY_DPS + 20)
            out.append(({**v, load: Lv}, av))
        return out

    # ----------------------------------------------------------- properties
    @property
    def force(self) -> sp.Expr:
        """Eq. (33): P(a) = P0(a) - sqrt(2 pi a gamma E*) (load per unit
        length; negative = tensile)."""
        return self._bind(self.derivation("force").expr)

    @property
    def pressure(self) -> sp.Expr:
        """Eq. (29): p(x; a) = p0(x; a) - Phat/(pi sqrt(a**2 - x**2)), |x| < a,
        Phat from Eq. (31) (compressive positive; tensile and
        inverse-square-root singular at the edges)."""
        return self._bind(self.derivation("pressure").expr)

    @property
    def flat_punch_force(self) -> sp.Expr:
        """Eq. (31), see :attr:`Phat`."""
        return self.Phat

    @property
    def pull_off_force(self):
        """P_min, the minimum of P(a) under load control: a **negative**
        (tensile) load, Eqs. (34)-(36) with P_min = -P_adh.  Closed form where
        dP/da = 0 solves symbolically; else a verified number when values are
        bound (:meth:`at`), else :class:`NumericValuesRequired` (use
        :meth:`pull_off_force_at`).  :class:`NoPullOffError` where no finite
        pull-off exists (power law n <= 1/2, gamma = 0)."""
        return self._closed_or_number("pull_off_force")

    @property
    def adhesion_force(self):
        """P_adh = -P_min > 0, the paper's adhesive force in Eqs. (34)-(36)."""
        return self._closed_or_number("adhesion_force")

    @property
    def pull_off_half_width(self):
        """Half-width at pull-off (load control), where P(a) is minimal."""
        return self._closed_or_number("pull_off_half_width")

    @property
    def jump_out_half_width(self):
        """Half-width from which the contact jumps out (separates) under load
        control: the pull-off half-width."""
        return self.pull_off_half_width

    @property
    def jump_in_half_width(self):
        """Half-width the contact snaps to at zero load (stable root of P = 0)."""
        d = self.derivation("jump_in_half_width")
        if d.closed_form:
            return self._bind(d.expr)
        if self.values and all(s in self.values for s in self.variables):
            return d.reference(self.values, 30)
        raise NumericValuesRequired(
            f"jump_in_half_width of {self.profile.name!r} has no closed form; use "
            f"ad.derivation('jump_in_half_width').evalf(...) or ad.at(...).jump_in_half_width")

    def report(self) -> str:
        out = []
        for q in ("force", "flat_punch_force", "pull_off_force", "pull_off_half_width"):
            out.append(self.derivation(q).summary())
        return "\n".join(out)
