"""The second pull-off method, independent of :func:`.equilibria.minimum`:
a brute-force search that shares nothing with it (no dP/da, no closed form,
no subdivision, no breakpoints of the engine's split).  The closed-form
pull-offs are verified against it, and the numeric ones are reported with
the number of digits in which the two methods agree.
"""
from __future__ import annotations

import math

import mpmath

from ...core.errors import NoPullOffError, VerificationError
from ...core.roots import Outside, golden_minimum
from ..normal.equilibria import check_deadline
from ..normal.force_law import GUARD, PullOff
from ...core.precision import workdps

#: points of the brute-force grid of method B
GRID_POINTS = 241


def _float_P0(quad):
    """P0(a) of the quadrature law in float64 (Eq. 10* after t = a sin phi, a
    fixed double-exponential rule of 97 nodes per piece, the pieces cut at
    the breakpoints the profile's expression has at this point): the cheap
    function the grid of :func:`minimum_by_grid` is sampled with."""
    import numpy as np
    import sympy as sp
    from ...core import symbols as S
    base = quad.base
    if not base.geometry.is_isolated:    # another geometry: the kernel twin's P0 at S = s(a) (method.geometry)
        P0k = _float_P0(base.kernel_law)
        s_of = base.geometry.float_s(base.geometry_values)
        top = float(base.geometry.mp_a_max(base.geometry_values))

        def P0_mapped(A):
            if float(A) > top:
                raise Outside
            return P0k(s_of(A))
        return P0_mapped
    npf = quad.base.numeric_profile
    E = float(quad.base.E)
    f1 = sp.lambdify(S.x, sp.diff(npf.expr, S.x), "numpy")
    t = np.linspace(-3.0, 3.0, 97)
    u = np.tanh(np.pi / 2 * np.sinh(t))
    w = (np.pi / 2 * np.cosh(t) / np.cosh(np.pi / 2 * np.sinh(t))**2) * (t[1] - t[0])
    kinks = [float(k) for k in quad.breaks()]

    def P0(A):
        A = float(A)
        edges = [0.0] + [k for k in kinks if k < A] + [A]
        total = 0.0
        with np.errstate(all="ignore"):
            for lo, hi in zip(edges[:-1], edges[1:]):
                p0, p1 = math.asin(min(lo / A, 1.0)), math.asin(min(hi / A, 1.0))
                ph = (p0 + p1) / 2 + (p1 - p0) / 2 * u
                vals = np.sin(ph) * np.broadcast_to(np.asarray(f1(A * np.sin(ph)), dtype=complex), ph.shape)
                if np.any(np.abs(vals.imag) > 1e-9 * (np.abs(vals.real) + 1e-300)):
                    raise Outside
                v = np.where(np.isfinite(vals.real), vals.real, 0.0)
                total += (p1 - p0) / 2 * float(np.dot(w, v))
        return E * A * total
    return P0


def _float_P(quad, P0f):
    """P(a) in float64: the cohesive law's own float form on top of P0f
    (``quad.float_P``, JKR: P0 - sqrt(2 pi a gamma E*)), else the law's
    mpmath P at 17 digits (a law with an inner solve), else P0 itself."""
    if quad.float_P is not None:
        return quad.float_P(P0f)
    if quad.base is quad:
        return P0f

    def Pf(A):
        with workdps(17):
            return float(quad.P(mpmath.mpf(A)))
    return Pf


def _parabolic_polish(P, A, h, steps: int = 5):
    """Successive parabolic interpolation of a smooth minimum from a location
    ``A`` known to about ``h``: each step fits P at A - h, A, A + h and moves
    to the vertex; h becomes the size of the move (quadratic convergence;
    ``steps`` at least, up to 8 times as many while the moves stay large),
    but not below 10**(-dps/3) A, where rounding in P (10**-dps) starts to
    move the vertex: the location ends near 10**(-2 dps/3)."""
    for k in range(8 * steps):
        check_deadline("the parabolic polish of the pull-off (method B)")
        pm, p0, pp = P(A - h), P(A), P(A + h)
        curv = pp - 2 * p0 + pm
        if not curv > 0:
            raise VerificationError(f"P(a) is not convex near its grid minimum a = {mpmath.nstr(A, 12)}")
        step = h * (pm - pp) / (2 * curv)
        A = A + step
        floor = A * mpmath.mpf(10)**(-(mpmath.mp.dps // 3))
        h = max(abs(step), floor)
        # at least ``steps``; more while the moves are still large (a start the float64 grid
        # could not resolve: a flat maximum next to full contact)
        if k + 1 >= steps and abs(step) <= 10 * floor:
            break
    return A


def minimum_by_grid(law, dps: int) -> PullOff:
    """The second, independent pull-off: shares nothing with :func:`minimum`
    (no dP/da, no closed form, no subdivision, no breakpoints of the engine).
    On the quadrature force law (10*) with the cohesive law on top: P on a dense grid
    (:data:`GRID_POINTS` log-spaced points, 1e-8 .. 1e8 times the scale, in
    float64), cut where P0 stops increasing or stops being real (its own
    admissible range); golden-section search around the lowest grid point;
    then at full precision (mpmath quadrature) either the breakpoint the
    profile's expression has there (found numerically at this point; a kink
    minimum, confirmed by one-sided differences) or successive parabolic
    interpolation (a stationary minimum)."""
    quad, Pf, pts, cut = _grid(law)
    k = min(range(len(pts)), key=lambda i: pts[i][1])
    if quad.geometry.closes_at_end:   # a periodic array: the first local minimum from small a (equilibria)
        k = _first_local_minimum(pts)
        if k is None or pts[k][1] >= 0:
            raise NoPullOffError("P(a) has no negative local minimum before full contact on the grid")
    if pts[k][1] >= 0:
        raise NoPullOffError("P(a) is nowhere negative on the grid: no finite pull-off")
    if k == len(pts) - 1 and cut:
        # the lowest point is where the admissible range ends, P falling there (unstable under load
        # control): a contact unloaded from a stable branch separates at an interior local minimum first
        inner = [i for i in range(1, len(pts) - 1)
                 if pts[i][1] <= pts[i - 1][1] and pts[i][1] <= pts[i + 1][1] and pts[i][1] < 0]
        if inner:
            k = min(inner, key=lambda i: pts[i][1])
    if k == len(pts) - 1:
        if not cut:   # still falling where the grid ends: P has no finite minimum
            raise NoPullOffError(f"P(a) still decreases at a = {pts[k][0]:.3g} (1e8 times the length scale), "
                                 f"where the grid ends: no finite pull-off")
        kind, A = "end", pts[k][0]
    else:
        lo, hi = pts[max(k - 1, 0)][0], pts[k + 1][0]
        A = float(golden_minimum(Pf, lo, hi, tol=hi * 1e-7))
        kind = "stationary"
    # the polish runs at 3/2 of the digits: from function values alone the
    # location comes to 2/3 of the working digits (see _parabolic_polish)
    with workdps(3 * dps // 2 + GUARD):
        A = mpmath.mpf(A)
        if kind != "end":
            near = [b for b in quad.breaks() if abs(b - A) <= A * mpmath.mpf("1e-6")]
            if near:
                A = near[0]
                h = A * mpmath.mpf(10)**(-dps // 2)
                if not (quad.P(A) - quad.P(A - h) < 0 < quad.P(A + h) - quad.P(A)):
                    raise VerificationError("the kink at the grid minimum is not a minimum of the quadrature law")
                kind = "kink"
            else:
                A = _parabolic_polish(quad.P, A, A * mpmath.mpf("1e-6"))
        Pm = quad.P(A)
        return PullOff(+Pm, -Pm, +A, kind, None, (), "dense float64 grid + golden section + parabolic polish "
                                                        "on the quadrature law")


def _grid(law):
    """(quadrature law, float P, [(a, P(a))] on the grid of :func:`minimum_by_grid`, cut)."""
    quad = law.quadrature_law
    P0f = _float_P0(quad)
    Pf = _float_P(quad, P0f)
    s = float(quad.scale)
    grid = [s * 10.0**(-8 + 16 * k / (GRID_POINTS - 1)) for k in range(GRID_POINTS)]
    if quad.geometry.closes_at_end:   # a periodic array: evenly up to L/2 too, and ever closer to it
        top = float(quad.geometry.mp_a_max(quad.geometry_values))
        grid = sorted({A for A in grid if A < top} | {top * k / GRID_POINTS for k in range(1, GRID_POINTS)}
                      | {top * (1 - 10.0**(-j / 4)) for j in range(8, 48)})
    pts, last0, cut = [], None, False
    for A in grid:
        check_deadline("the grid search of the pull-off (method B)")
        try:
            p0 = P0f(A)
        except (Outside, ValueError, ZeroDivisionError):
            cut = True
            break
        # falling beyond float64 rounding (relative to P0 and to the adhesive term it is
        # weighed against): on a flat P0 = 0, and the 97-node rule over the sliver of
        # a grid point just past the flat's end may give -1e-17 (a false cut there)
        pa = Pf(A) if math.isfinite(p0) else math.nan
        noise = 1e-12 * max(abs(p0), abs(last0 or 0.0), abs(pa - p0)) if math.isfinite(pa) else 0.0
        if not math.isfinite(p0) or (last0 is not None and p0 < last0 - noise):
            cut = True
            break
        last0 = p0
        pts.append((A, pa))
    if len(pts) < 3:
        raise NoPullOffError("the quadrature force law is real and rising at fewer than 3 grid points")
    return quad, Pf, _below_grid(quad, Pf, pts), cut


def _below_grid(quad, Pf, pts):
    """Where P(0+) = 0 and P rises at the grid's first point, a weak adhesion
    may hide its minimum below the grid (JKR's moves to a ~ gamma^(1/3): at
    gamma = 1e-40 on a sinusoid array a = 1.6e-14 L, P > 0 from 1e-12 L on):
    points are added in eighth decades downwards while P rises towards the
    grid (positive: until it turns negative; negative: until it turns back up
    towards P(0+) = 0), at most 400 decades."""
    if getattr(quad, "P_zero", None) is not None or quad.inactive or not pts[1][1] > pts[0][1]:
        return pts
    A, below, last = pts[0][0], [], pts[0][1]
    step = 10.0**(-1 / 8)
    for _ in range(8 * 400):
        A *= step
        try:
            pa = Pf(A)
        except (Outside, ValueError, ZeroDivisionError, OverflowError):
            break
        if not math.isfinite(pa):
            break
        below.append((A, pa))
        if pa > last:                   # P rises again going down: the minimum is bracketed
            break
        last = pa
    else:
        return pts
    return sorted(below) + pts if below and below[-1][1] > min(p for _, p in below) else pts


def _first_local_minimum(pts):
    """The index of the first interior local minimum of the grid values, or None."""
    first = [i for i in range(1, len(pts) - 1) if pts[i][1] <= pts[i - 1][1] and pts[i][1] <= pts[i + 1][1]]
    return first[0] if first else None


def maximum_by_grid(law, dps: int) -> PullOff:
    """The first local maximum of P(a) after its first local minimum (from
    small a), by the same independent search as :func:`minimum_by_grid`
    (float64 grid of the quadrature law, golden section, parabolic polish at
    full precision): the snap into full contact of a periodic array.  With
    no minimum before it, the maximum is P(0+) = 0 (``kind='origin'``)."""
    quad, Pf, pts, cut = _grid(law)
    i0 = _first_local_minimum(pts)
    if i0 is None:
        return PullOff(mpmath.mpf(0), mpmath.mpf(0), mpmath.mpf(0), "origin", None, (),
                       "P(a) has no local minimum on the grid: its supremum is P(0+) = 0")
    tops = [i for i in range(i0 + 1, len(pts) - 1) if pts[i][1] >= pts[i - 1][1] and pts[i][1] >= pts[i + 1][1]]
    if not tops:
        raise VerificationError("P(a) has a minimum but no maximum after it on the grid")
    k = tops[0]
    lo, hi = pts[k - 1][0], pts[k + 1][0]
    A = float(golden_minimum(lambda v: -Pf(v), lo, hi, tol=(hi - lo) * 1e-7))
    with workdps(3 * dps // 2 + GUARD):
        # the polish's first step within the bracket: next to full contact (a weak adhesion's maximum
        # 1e-8 L below L/2) a step of 1e-6 a would leave the law's domain
        h = min(A * mpmath.mpf("1e-6"), (mpmath.mpf(hi) - mpmath.mpf(lo)) / 4)
        top = mpmath.mpf(quad.geometry.mp_a_max(quad.geometry_values))
        if top - A < A:
            # nearer the end than the origin: polished in the distance d = top - a, whose digits
            # (not a's) fix the maximum there (its floor of rounding is relative to d)
            d = _parabolic_polish(lambda v: -quad.P(top - v), top - A, h)
            A = top - d
        else:
            A = _parabolic_polish(lambda v: -quad.P(v), mpmath.mpf(A), h)
        Pm = quad.P(A)
        return PullOff(+Pm, -Pm, +A, "stationary", None, (), "dense float64 grid + golden section + parabolic "
                                                             "polish of -P on the quadrature law")


__all__ = ["minimum_by_grid", "maximum_by_grid", "GRID_POINTS"]
