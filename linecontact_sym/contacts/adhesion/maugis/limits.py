"""The JKR limit of the Maugis-Dugdale pull-off (sigma_0 -> oo, the Maugis
parameter lambda -> oo), reached without the Maugis-Dugdale solve where its
error is below the digits asked, with that error bounded and stated.

With c the cohesive-zone half-width, the two laws at the same half-width a
differ only in their adhesive terms::

    P_MD(a)  = P0(a) - 2 sigma_0 sqrt(c^2 - a^2)
    P_JKR(a) = P0(a) - sqrt(2 pi a w E*)        (Popov 2017, Eq. 31)

and the gap condition g0(c; a) + (4 sigma_0 a/(pi E*)) D(c/a) = h0 = w/sigma_0,
D(m) = sqrt(m^2 - 1) acosh(m) - m log(m) increasing from D(1) = 0.  Let
delta = pi E* w/(4 sigma_0^2) (the JKR-limit zone length) and u = a/delta.

**Below** (every a): g0 >= 0 on the admissible range, so D(c/a) <= delta/a,
c <= a M(delta/a) with M the inverse of D, and

    P_MD(a) >= P_JKR(a) - 2 sigma_0 delta psi(u),  psi(u) = u sqrt(M(1/u)^2 - 1) - sqrt(2u).

psi decreases from 1/ln 2 (u -> 0+: P(0+) = -2 sigma_0 c0, c0 <= delta/ln 2)
and sqrt(u) psi(u) <= :data:`KPSI` (its supremum 0.47198 near u = 10; the
tail is sqrt(2)/3); both read off psi on a log grid of u in [1e-8, 1e8]
(:func:`zone_excess`, checked by an independent bisection in the tests).
With a1 from sqrt(2 pi a1 w E*) + 2 sigma_0 delta/ln 2 = |P_JKR,min| (below
a1 P_MD >= P0 - sqrt(2 pi a w E*) - 2 sigma_0 delta/ln 2 >= P_JKR,min, as
P0 >= 0), min P_MD >= P_JKR,min - B_lo with
B_lo = 2 sigma_0 delta KPSI sqrt(delta/a1) (relative size ~ delta/a ~ lambda^-2).

**Above** (at the JKR pull-off half-width a_J): the adhesionless gap grows
no faster than the profile beyond the contact (the depression of a
half-plane under a compressive pressure falls with the distance from it),
g0(c; a) <= f(c) - f(a) <= F1 (c - a) with F1 >= f' on [a_J, a_J + delta/ln 2]
(an Arb ball of f'), and D(1 + e) <= e; so c - a >= delta/(1 + k),
k = pi E* F1/(4 sigma_0), and

    min P_MD <= P_MD(a_J) <= P_JKR,min + B_up,  B_up = sqrt(2 pi a_J w E*) (1 - (1 + k)^(-1/2))

(relative size ~ k/2 ~ 1/lambda).  The pull-off is |P_MD,min - P_JKR,min| <=
B = max(B_lo, B_up); the half-width of the minimum moves by about
sqrt(2 (B_lo + B_up)/P_JKR''(a_J)) (a quadratic minimum; stated as an
estimate).  The limit is the answer where B <= 10**-(dps+1) |P_JKR,min| and
that estimate <= 10**-(dps+1) a_J: then the two models agree to the digits
asked and only the JKR law (a closed form where the engine has one) is
evaluated -- model only what the problem needs.  Where only the force is
within the bound, the minimum is refined on this law in the bracket
a_J +- 4 da alone (a few inner solves).  Elsewhere None: the
Maugis-Dugdale search runs (under its budget).

**One decision for every quantity.**  :func:`limit_model` decides, once per
values and digits, which model answers: the Dugdale limit (sigma_0 -> 0,
:mod:`.dugdale`), this JKR limit (:class:`JKRLimit`, reached where the bound of
the pull-off is below the digits asked), or neither.  The pull-off, the
equilibria (``half_width``, ``branches``: :func:`jkr_equilibria`, each root
moved by at most B(a)/|P_JKR'(a)|, with B(a) the two bounds above taken at a)
and the states (``state``, ``force_at``: :func:`jkr_state`, c_D enclosed by
a + delta/(1 + k) <= c_D <= a M(delta/a)) all ask it; each result says which
model answered (its note, ``HalfWidths.model``, ``MDState.model``).
"""
from __future__ import annotations

import mpmath
import sympy as sp

from ....core import symbols as S
from ....core.errors import LineContactError, NoPullOffError
from ....core.roots import Outside
from ....core.precision import workdps
from ...normal.force_law import PullOff
from .numbers import fixed_values

#: sup_u sqrt(u) psi(u) (0.47198 at u ~ 10, sqrt(2)/3 = 0.47140 as u -> oo), rounded up
KPSI = mpmath.mpf("0.48")


def dugdale_D(m):
    """D(m) = sqrt(m^2 - 1) acosh(m) - m log(m), the Dugdale gap at c_D over 4 sigma_0 a/(pi E*)."""
    return mpmath.sqrt(m * m - 1) * mpmath.acosh(m) - m * mpmath.log(m)


def zone_excess(u):
    """psi(u) = u sqrt(M(1/u)^2 - 1) - sqrt(2u), M the inverse of :func:`dugdale_D` (bisection in
    m - 1; at the working precision): the Dugdale force in excess of JKR's at a = u delta, over
    2 sigma_0 delta, where the adhesionless gap is neglected (its largest value)."""
    u = mpmath.mpf(u)
    e = _dugdale_excess(1 / u, mpmath.mpf(1))
    return u * mpmath.sqrt(e * (2 + e)) - mpmath.sqrt(2 * u)


def _dugdale_excess(t, hi):
    """The e > 0 with D(1 + e) = t (:func:`dugdale_D` increasing), by bisection
    to the working precision from the bracket [0, hi] (doubled until it holds
    the root); the upper end of the final bracket (D(1 + e) >= t)."""
    lo = mpmath.mpf(0)
    while dugdale_D(1 + hi) < t:
        hi *= 2
    for _ in range(mpmath.mp.prec + 20):
        mid = (lo + hi) / 2
        if dugdale_D(1 + mid) < t:
            lo = mid
        else:
            hi = mid
    return hi


def _slope_bound(md, vals, lo, width):
    """An upper bound of f' on [lo, lo + width] (an Arb ball, the width added in Arb: it may be far
    below lo's last digit), or None where Arb cannot evaluate it."""
    import flint
    from ....numeric.certified import compile_arb, to_arb
    pf = {k: v for k, v in vals.items() if k != S.E_star}
    f1 = sp.diff(md.profile.expr, S.x).xreplace(pf)
    if f1.free_symbols - {S.x}:
        return None
    try:
        g = compile_arb(f1, [S.x])
        with flint.ctx.workprec(128):
            y = g(to_arb(lo).union(to_arb(lo) + to_arb(width)))
    except Exception:   # CertificationError: no ball translation of f' (a piecewise, a user function)
        return None
    if not y.is_finite():
        return None
    return max(mpmath.mpf(y.upper().str(30, radius=False)), mpmath.mpf(0))


class JKRLimit:
    """The JKR limit of one Maugis-Dugdale contact at values, once it is reached (:func:`limit_model`):
    what every Maugis-Dugdale quantity needs to answer from the JKR law with a stated bound --
    the JKR pull-off ``po``, the zone length ``delta``, the Maugis parameter ``lam``, the bound ``B``
    of the pull-off (module docstring) and, at any half-width, :meth:`force_bound` and :meth:`zone`."""

    model = "JKR limit"

    def __init__(self, md, vals, dps, po, E, w, sig):
        self.md, self.vals, self.dps, self.po = md, vals, dps, po
        self.fixed = fixed_values(vals)
        self.E, self.w, self.sig = E, w, sig
        self.delta = mpmath.pi * E * w / (4 * sig**2)
        self.B_lo = self.B_up = self.B = None       # the bounds of the pull-off, set by _reached
        self.lam = mpmath.sqrt(mpmath.mpf(2)**(mpmath.mpf(5) / 3) * po.half_width / self.delta)

    @property
    def jkr_law(self):
        """The JKR force law at these values (the package's JKR layer: its closed form where the engine has one)."""
        return self.md.jkr._law({s: v for s, v in self.vals.items() if s in set(self.md.jkr.variables)}, "closed")

    def _k(self, A):
        F1 = _slope_bound(self.md, self.fixed, A, self.delta / mpmath.log(2) * (1 + mpmath.mpf(10)**-3))
        return None if F1 is None else mpmath.pi * self.E * F1 / (4 * self.sig)

    def above(self, A):
        """B_up(A) = sqrt(2 pi a w E*) (1 - (1 + k)^(-1/2)) >= P_MD(a) - P_JKR(a) (module docstring), or None."""
        k = self._k(A)
        if k is None:
            return None
        jt = mpmath.sqrt(2 * mpmath.pi * A * self.w * self.E)
        return jt * k / ((1 + mpmath.sqrt(1 + k)) * mpmath.sqrt(1 + k))   # jt (1 - (1 + k)^(-1/2)), no cancellation

    def force_bound(self, A):
        """|P_MD(a) - P_JKR(a)| <= this at the half-width A (module docstring: below, 2 sigma_0 delta psi(a/delta)
        with psi <= min(1/ln 2, KPSI sqrt(delta/a)); above, sqrt(2 pi a w E*) (1 - (1 + k)^(-1/2)) with k from an
        Arb bound of f' on [a, a + delta/ln 2]); None where Arb cannot bound f'."""
        with workdps(self.dps + 15):
            A = mpmath.mpf(A)
            up = self.above(A)
            if up is None:
                return None
            return max(2 * self.sig * self.delta * min(1 / mpmath.log(2), KPSI * mpmath.sqrt(self.delta / A)), up)

    def zone(self, A):
        """(c_lo, c_hi) enclosing c_D at the half-width A: c_D - a >= delta/(1 + k) (above) and
        D(c_D/a) <= delta/a (g0 >= 0), i.e. c_D <= a M(delta/a); None where Arb cannot bound f'."""
        with workdps(self.dps + 15 + max(0, int(mpmath.log10(mpmath.mpf(A) / self.delta)))):
            A = mpmath.mpf(A)
            k = self._k(A)
            if k is None:
                return None
            t = self.delta / A
            hi = _dugdale_excess(t, 2 * t)          # D(1 + e) >= e - e^2/6 > t at e = 2 t (t small)
            return A + self.delta / (1 + k), A * (1 + hi)

    def describe(self):
        return (f"the JKR limit of the Maugis-Dugdale law (lambda = {mpmath.nstr(self.lam, 6)}, zone length delta = "
                f"pi E* w/(4 sigma_0^2) = {mpmath.nstr(self.delta, 6)}; maugis.limits)")


def _reached(md, vals: dict, dps: int):
    """:class:`JKRLimit` where the bound of the pull-off (module docstring) is below 10**-(dps+1) of it; else None."""
    fixed = fixed_values(vals)
    try:
        jv = {s.name: v for s, v in vals.items() if s in set(md.jkr.variables)}
        po = md.jkr.pull_off_at(dps + 5, **jv)
    except NoPullOffError:
        return None
    if po.kind == "infimum" or not po.force < 0:
        return None
    with workdps(dps + 15):
        E = mpmath.mpf(sp.N(fixed[S.E_star], dps + 20))
        w = mpmath.mpf(sp.N(md.w.xreplace(fixed), dps + 20))
        sig = mpmath.mpf(sp.N(md.sigma0.xreplace(fixed), dps + 20))
        lim = JKRLimit(md, vals, dps, po, E, w, sig)
        two_sd = 2 * sig * lim.delta
        PJ, aJ = po.force, po.half_width
        r = -PJ - two_sd / mpmath.log(2)
        if not r > 0:
            return None
        a1 = r**2 / (2 * mpmath.pi * w * E)
        B_lo = two_sd * KPSI * mpmath.sqrt(lim.delta / a1)
        B_up = lim.above(aJ)
        if B_up is None or not max(B_lo, B_up) <= mpmath.mpf(10)**-(dps + 1) * abs(PJ):
            return None
        lim.B_lo, lim.B_up, lim.B = B_lo, B_up, max(B_lo, B_up)
        return lim


def limit_model(md, vals: dict, dps: int):
    """THE decision, for every Maugis-Dugdale quantity at values (pull-off, half_width, branches, states,
    force_at), whether a limit model answers to ``dps`` digits: a :class:`JKRLimit` (sigma_0 -> oo) or a
    :class:`DugdaleLimit` (sigma_0 -> 0, :mod:`.dugdale`), else None (the full Maugis-Dugdale solve).
    Decided once per values and digits (cached on the contact)."""
    cache = md._caches()
    key = ("_limit_model", tuple(sorted((k.name, str(v)) for k, v in vals.items())), dps)
    if key not in cache:
        from .dugdale import dugdale_reached
        lim = dugdale_reached(md, vals, dps)
        cache[key] = lim if lim is not None else (_reached(md, vals, dps) if _may_reach(md, vals, dps) else None)
    return cache[key]


def _may_reach(md, vals, dps):
    """False where the JKR limit cannot hold dps digits, decided without the JKR pull-off: at the zone c0 of a
    vanishing contact (one root of the engine's zero-width condition) k0 = pi E* f'(c0)/(4 sigma_0) is the k of
    the upper bound (module docstring) there; B_up/sqrt(2 pi a w E*) ~ k/2 at a_J, and c0 ~ delta/ln 2 << a_J
    with f' rising (f convex near the contact: every profile of the tests) gives k0 <= k(a_J); so k0 above
    10**(2-dps) (a margin of 1000 on the 10**-(dps+1) asked) leaves the JKR pull-off unsearched.  True where
    c0 cannot be had (the decision then falls to the bound itself)."""
    try:
        law = md.numeric_law(**{s.name: v for s, v in vals.items()})
        with workdps(30):
            c0 = law.c0(15)
            E = mpmath.mpf(sp.N(law.E, 30))
            sig = mpmath.mpf(sp.N(law.sigma0, 30))
            f1 = law._Z0c(c0) - 4 * mpmath.log(2) * sig / (mpmath.pi * E)
            return mpmath.pi * E * f1 / (4 * sig) <= mpmath.mpf(10)**(2 - dps)
    except (LineContactError, Outside, ValueError, ZeroDivisionError):
        return True


class HalfWidths(tuple):
    """The equilibrium half-widths of a Maugis-Dugdale contact at a load (a tuple, as ``half_width`` gives
    everywhere: stable first), with ``model`` (which model answered: 'Maugis-Dugdale' or 'JKR limit')
    and ``note`` (how, and the bound where a limit answered)."""

    def __new__(cls, roots, model, note=""):
        out = super().__new__(cls, roots)
        out.model, out.note = model, note
        return out


def jkr_equilibria(lim: JKRLimit, load, dps: int):
    """The equilibria [(a, stable)] of the Maugis-Dugdale law at ``load`` from the JKR law's (the package's
    JKR layer), with a note, where the JKR limit ``lim`` places each within 10**-(dps+1) a of JKR's:
    |P_MD - P_JKR| <= B(a) (:meth:`JKRLimit.force_bound`) moves a root by at most B/|P_JKR'| (both laws
    continuous: P_JKR -+ B bracket a root of P_MD), and the load is clear of every JKR extremum by more
    than twice its bound and of the MD law's P(0+) in [-2 sigma_0 delta/ln 2, 0) (where the two laws could
    differ in their number of roots); else None (then the full Maugis-Dugdale solve)."""
    from ...normal.equilibria import equilibria, landscape
    jlaw = lim.jkr_law
    roots = equilibria(jlaw, load, dps)
    if not roots:
        return None
    tol = mpmath.mpf(10)**-(dps + 1)
    worst = mpmath.mpf(0)
    with workdps(dps + 15):
        L = mpmath.mpf(sp.N(load, dps + 20))
        if abs(L) <= 4 * lim.sig * lim.delta / mpmath.log(2):
            return None
        for a, _ in roots:
            B, d = lim.force_bound(a), abs(jlaw.dP(a))
            if B is None or not d > 0 or not B / d <= tol * a:
                return None
            worst = max(worst, B / d / a)
        for e in landscape(jlaw).extrema:
            B = lim.force_bound(e.half_width)
            if B is None or not abs(e.force - L) > 2 * B:
                return None
    note = (f"{lim.describe()}: each half-width is JKR's, moved by at most B(a)/|dP_JKR/da| <= "
            f"{mpmath.nstr(worst, 3)} a (|P_MD - P_JKR| <= B(a), the bounds of the cohesive zone); below the "
            f"10**-{dps} asked, so only the JKR law was evaluated")
    return roots, note


def jkr_state(lim: JKRLimit, law, A, dps: int):
    """The :class:`~.numbers.MDState` at the half-width A from the JKR limit ``lim``: P and dP/da of the JKR
    law, c_D the middle of the zone's enclosure (:meth:`JKRLimit.zone`), where the force bound is below
    10**-(dps+1) |P| and the enclosure of c_D - a below 10**-(dps+1) of it (the pressure and the gap then
    hold dps digits: they depend on c_D - a); else None (the inner solve)."""
    tol = mpmath.mpf(10)**-(dps + 1)
    B, z = lim.force_bound(A), lim.zone(A)
    if B is None or z is None:
        return None
    jlaw = lim.jkr_law
    with workdps(dps + 15 + max(0, int(mpmath.log10(mpmath.mpf(A) / lim.delta)))):
        A = mpmath.mpf(A)
        c_lo, c_hi = z
        P, dP = jlaw.P(A), jlaw.dP(A)
        scale = abs(P) + mpmath.sqrt(2 * mpmath.pi * A * lim.w * lim.E)
        if not (B <= tol * scale and c_hi - c_lo <= tol * (c_lo - A)):
            return None
        C = (c_lo + c_hi) / 2
        note = (f"{lim.describe()}: P and dP/da of the JKR law, |P_MD - P_JKR| <= {mpmath.nstr(B, 3)}; c_D - a in "
                f"[{mpmath.nstr(c_lo - A, 12)}, {mpmath.nstr(c_hi - A, 12)}] (bounds of the cohesive zone from the "
                f"gap condition), dP/da within O(1/lambda) relative; below the 10**-{dps} asked, no inner solve")
        return law.state_at(A, C, +P, +dP, dps, "JKR limit", note)


def limit_pull_off(md, vals: dict, dps: int):
    """The pull-off from the limit model :func:`limit_model` picks (its note says which), or None."""
    lim = limit_model(md, vals, dps)
    if lim is None:
        return None
    return jkr_limit(md, vals, dps) if isinstance(lim, JKRLimit) else lim.pull_off()


def jkr_limit(md, vals: dict, dps: int):
    """The pull-off of the Maugis-Dugdale contact ``md`` at ``vals`` ({Symbol: value}) as its JKR
    limit, a :class:`PullOff` whose note states the bound, where :func:`limit_model` says the JKR
    limit is reached; else None."""
    lim = limit_model(md, vals, dps)
    if not isinstance(lim, JKRLimit):
        return None
    po, B = lim.po, lim.B
    with workdps(dps + 15):
        PJ, aJ = po.force, po.half_width
        tol = mpmath.mpf(10)**-(dps + 1)
        if po.kind == "stationary":    # the minimum moves by ~ sqrt(2 (B_lo + B_up)/P'')
            law = lim.jkr_law
            h = aJ * mpmath.mpf(10)**-((dps + 15) // 3)
            P2 = (law.dP(aJ + h) - law.dP(aJ - h)) / (2 * h)
            if not P2 > 0:
                return None
            da = mpmath.sqrt(2 * (lim.B_lo + lim.B_up) / P2)
        else:                          # a kink or the range's end: the same half-width (P_MD, P_JKR share P0's kinks)
            da = mpmath.mpf(0)
        lam = lim.lam
        if not da <= tol * aJ:
            return _refined(md, vals, dps, po, B, da, lam)
        note = (f"the JKR limit of the Maugis-Dugdale law (lambda = {mpmath.nstr(lam, 6)}): |P_MD,min - P_JKR,min| "
                f"<= {mpmath.nstr(B, 3)} (relative {mpmath.nstr(B / abs(PJ), 3)}; bounds of the cohesive zone from "
                f"the gap condition, maugis.limits), the half-width within about {mpmath.nstr(da, 3)}; below the "
                f"10**-{dps} asked, so only the JKR law was evaluated: {po.note}")
        return PullOff(+PJ, -PJ, +aJ, po.kind, None, po.minima, note)


def _refined(md, vals, dps, po, B, da, lam):
    """The force is within its bound but the half-width is not: the Maugis-Dugdale minimum is the
    root of this law's dP/da next to a_J (within a few da, where P_JKR rises by more than the bound),
    found in that bracket alone -- a few inner solves, not the search of the whole range; None when
    the bracket holds no sign change (then the whole search)."""
    if po.kind != "stationary":
        return None
    from ....core.roots import root_in_log
    from ...normal.force_law import GUARD
    law = md._law(vals, "closed")
    aJ = po.half_width
    lo, hi = aJ - 4 * da, aJ + 4 * da
    if not lo > 0:
        return None
    with workdps(20):
        if not law.dP(lo) < 0 < law.dP(hi):
            return None
    with workdps(dps + GUARD):
        A = root_in_log(law.dP, mpmath.mpf(lo), mpmath.mpf(hi), approx=aJ)
        Pm = law.P(A)
    note = (f"the JKR limit of the Maugis-Dugdale law (lambda = {mpmath.nstr(lam, 6)}) bounds the pull-off: "
            f"|P_MD,min - P_JKR,min| <= {mpmath.nstr(B, 3)} (relative {mpmath.nstr(B / abs(po.force), 3)}, "
            f"maugis.limits), its half-width within about {mpmath.nstr(da, 3)} of JKR's a = "
            f"{mpmath.nstr(aJ, 10)}; the minimum then refined on this law alone in [a_J - 4 da, a_J + 4 da] "
            f"(dP/da = 0 there; any other local minimum lies within the bound of it): {po.note}")
    return PullOff(+Pm, -Pm, +A, "stationary", None, po.minima, note)


__all__ = ["jkr_limit", "limit_model", "limit_pull_off", "jkr_equilibria", "jkr_state", "HalfWidths", "JKRLimit", "zone_excess", "dugdale_D", "KPSI"]
