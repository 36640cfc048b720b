"""Stationary points, minima and equilibria of a :class:`~.force_law.ForceLaw`:
the one scan / bracket / root / minimum toolkit of the contacts layer.

Load control: a contact at load P sits at a half-width a with P(a) = P; it is
stable where dP/da > 0.  The *pull-off* of a contact pulled from a contact
larger than every local minimum of P(a) is the global minimum of P(a): the
contact follows the stable branch down to the largest-a local minimum, jumps
to a stable equilibrium at the same load at smaller a if there is one (and
continues), and separates when there is none, which happens exactly at the
global minimum.  Minima are stationary (dP/da = 0) or at a kink of the
profile (a breakpoint where dP/da jumps from negative to positive).
"""
from __future__ import annotations

import mpmath

from ..core.conversion import to_mpf
from ..core.errors import DomainError, NoPullOffError, VerificationError
from ..core.roots import UNDEFINED, domain_end, root_in_log
from .force_law import GUARD, PullOff


def scan(law):
    """Values (a, P, dP) on a geometric grid (factor 4, 2**-80 .. 2**80 times
    the law's length scale, breakpoints bracketed at 1e-10), at 20 digits,
    cut at the end of the law's real domain.  Returns ``(points, edge)``, edge
    True when the grid stops at a domain end.  Cached on the law."""
    if law._scan_cache is not None:
        return law._scan_cache
    with mpmath.workdps(20):
        grid = [law.scale * mpmath.mpf(2)**j for j in range(-80, 81, 2)]
        near = mpmath.mpf("1e-8")
        grid = [A for A in grid if all(abs(A - bv) > near * bv for bv in law.breaks())]
        for bv in law.breaks():
            grid += [bv * (1 - mpmath.mpf("1e-10")), bv * (1 + mpmath.mpf("1e-10"))]
        grid.sort()
        pts, edge, last_good = [], False, None
        for A in grid:
            try:
                pts.append((A, law.P(A), law.dP(A)))
                last_good = A
            except UNDEFINED:
                if last_good is None:
                    continue
                edge = True
                end = domain_end(lambda v: (law.P(v), law.dP(v)), last_good, A)
                for k in range(1, 40):  # approach it
                    Ak = last_good + (end - last_good) * (1 - mpmath.mpf(2)**(-k))
                    try:
                        pts.append((Ak, law.P(Ak), law.dP(Ak)))
                    except UNDEFINED:
                        break
                break
    if not pts:
        raise DomainError("the force law could not be evaluated at any half-width")
    law._scan_cache = (pts, edge)
    return law._scan_cache


def candidates(law):
    """Local minima of P located on the scan (at 20 digits):
    [(a_approx, kind, (lo, hi))]."""
    pts, _ = scan(law)
    out = []
    with mpmath.workdps(20):
        brs = law.breaks()
        for (a0, _, d0), (a1, _, d1) in zip(pts[:-1], pts[1:]):
            if not (d0 < 0 < d1):
                continue
            kink = [bv for bv in brs if a0 < bv < a1]
            if kink:
                out.append((kink[0], "kink", (a0, a1)))
                continue
            out.append((root_in_log(law.dP, a0, a1), "stationary", (a0, a1)))
    return out


def minimum(law, dps: int, scan_law=None) -> PullOff:
    """Global minimum of P(a) (the pull-off under load control) from ``law``'s
    own values; the brackets come from the scan of ``scan_law`` (default
    ``law``).  Raises :class:`NoPullOffError` where P has no finite negative
    minimum."""
    scan_law = scan_law or law
    pts, edge = scan(scan_law)
    if getattr(law, "gamma", None) == 0:
        raise NoPullOffError("no adhesion (gamma = 0): P(a) = P0(a) >= 0, no tensile pull-off")
    aN, _, dN = pts[-1]
    if dN < 0:
        where = "the end of the profile's domain" if edge else "the end of the search range"
        raise NoPullOffError(
            f"P(a) is still decreasing at a = {mpmath.nstr(aN, 6)} ({where}): P(a) has no "
            f"finite minimum, no finite pull-off (the profile grows no faster than "
            f"sqrt(x) there, so the adhesive term sqrt(2 pi a gamma E*) dominates)")
    found = []
    with mpmath.workdps(dps + GUARD):
        for approx, kind, (lo, hi) in candidates(scan_law):
            if kind == "kink":
                bv = [b for b in law.breaks() if abs(b - approx) <= abs(approx) * mpmath.mpf("1e-15")][0]
                eps = mpmath.mpf(10)**(-dps)
                if not (law.dP(bv * (1 - eps)) < 0 < law.dP(bv * (1 + eps))):
                    continue
                found.append((bv, law.P(bv), "kink", (lo, hi)))
            else:
                A = root_in_log(law.dP, to_mpf(lo), to_mpf(hi), approx=to_mpf(approx))
                found.append((A, law.P(A), "stationary", (lo, hi)))
        neg = [cnd for cnd in found if cnd[1] < 0]
        if not neg:
            raise NoPullOffError(
                "P(a) has no negative minimum: no tensile load is sustained (the infimum 0 is "
                "reached only as a -> 0); no finite pull-off")
        A, Pm, kind, br = min(neg, key=lambda cnd: cnd[1])
        po = PullOff(+Pm, -Pm, +A, kind)
        law._last_bracket = br
        return po


def minimum_by_differences(law, dps: int, po: PullOff) -> PullOff:
    """Second, independent method: the quadrature force law (10*) minus
    Phat, differentiated numerically (mpmath.diff) and solved for
    dP/da = 0 near the first method's minimum; at a kink, one-sided
    differences confirm the minimum and P is evaluated there."""
    quad = law.quadrature_law
    with mpmath.workdps(dps + GUARD):
        if po.kind == "kink":
            A = to_mpf(po.half_width)
            h = A * mpmath.mpf(10)**(-dps // 2)
            left = quad.P(A) - quad.P(A - h)
            right = quad.P(A + h) - quad.P(A)
            if not (left < 0 < right):
                raise VerificationError("the kink at the pull-off is not a minimum of the quadrature force law")
            Pm = quad.P(A)
            return PullOff(+Pm, -Pm, A, "kink")
        lo, hi = law._last_bracket
        fn = lambda A: mpmath.diff(quad.P, A)  # noqa: E731
        A = root_in_log(fn, to_mpf(lo), to_mpf(hi), approx=to_mpf(po.half_width) * (1 + mpmath.mpf("1e-9")))
        Pm = quad.P(A)
        return PullOff(+Pm, -Pm, A, "stationary")


def equilibria(law, load, dps: int, scan_law=None):
    """All half-widths with P(a) = load: list of (a, stable), stable first
    (then by decreasing a)."""
    sl = scan_law or law
    pts, edge = scan(sl)
    with mpmath.workdps(20):
        L20 = to_mpf(load)
        pts = list(pts)
        if L20 != 0:  # below the grid: P(0+) = 0
            a0, P0v, _ = pts[0]
            k = 0
            while (P0v - L20 > 0) != (0 - L20 > 0) and k < 200:
                a0 = a0 / 16
                P0v = sl.P(a0)
                pts.insert(0, (a0, P0v, sl.dP(a0)))
                k += 1
        if not edge:  # beyond the grid (not at a domain end)
            k = 0
            while k < 200:
                aN, PN, dN = pts[-1]
                if (dN > 0 and PN < L20) or (dN < 0 and PN > L20):
                    try:
                        A = aN * 16
                        pts.append((A, sl.P(A), sl.dP(A)))
                    except UNDEFINED:
                        break
                    k += 1
                else:
                    break
        # stationary points between grid nodes: two roots close to a minimum
        # (or maximum) may both lie inside one grid interval
        extra = []
        for (a0, _, d0), (a1, _, d1) in zip(pts[:-1], pts[1:]):
            if (d0 < 0) != (d1 < 0):
                kink = [bv for bv in sl.breaks() if a0 < bv < a1]
                A = kink[0] if kink else root_in_log(sl.dP, a0, a1)
                extra.append((A, sl.P(A), sl.dP(A)))
        pts = sorted(pts + extra, key=lambda r: r[0])
        brackets = []
        for (a0, P0v, _), (a1, P1v, _) in zip(pts[:-1], pts[1:]):
            if (P0v - L20) * (P1v - L20) < 0:
                brackets.append((a0, a1, root_in_log(lambda A: sl.P(A) - L20, a0, a1)))
    with mpmath.workdps(dps + GUARD):
        L = to_mpf(load)
        out = []
        for a0, a1, approx in brackets:
            A = root_in_log(lambda A: law.P(A) - L, to_mpf(a0), to_mpf(a1), approx=to_mpf(approx))
            out.append((+A, law.dP(A) > 0))
        out.sort(key=lambda r: (not r[1], -r[0]))
        return out


def half_width_at(law, load, dps: int = 30):
    """The half-width of an increasing (non-adhesive) law at a positive load:
    bracketing from a = 1e-3 upwards, then the root."""
    with mpmath.workdps(dps + 10):
        L = to_mpf(load)
        lo, hi = mpmath.mpf(0), mpmath.mpf("1e-3")
        for _ in range(200):
            try:
                v = law.P(hi)
            except UNDEFINED:
                raise DomainError(f"no half-width found for load {load}: the force law is "
                                  f"undefined beyond a = {float(lo):.6g}")
            if v >= L:
                break
            lo, hi = hi, hi * 2
        else:
            raise DomainError(f"no half-width found for load {load}")
        root = mpmath.findroot(lambda av: law.P(av) - L, (lo, hi), solver="anderson")
        return +root


__all__ = ["scan", "candidates", "minimum", "minimum_by_differences", "equilibria", "half_width_at"]
