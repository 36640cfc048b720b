"""Where the material yields first: the maxima of the equivalent stresses in
the body and on its surface, and the friction coefficient at which the
maximum moves to the surface.

A maximum is found in two independent ways and both are reported:

1. search: the criterion on a coarse grid of (x, z) (and along the surface),
   its grid maxima refined by Nelder-Mead in (x, z) (Brent along the
   surface);
2. check: a root of the gradient from the same grid point by a different
   algorithm: Powell's hybrid method (``scipy.optimize.root``) on the
   central-difference gradient, or, on the axis of a symmetric contact, a
   bracketed root (Brent) of d f/dz at x = 0; along the surface a bracketed
   root of d f/dx.

``digits`` is the number of significant digits on which the two values
agree.  A grid argmax is never returned as the answer.  Where the surface
traction is singular (the wedge's tip, a kink of the profile: a logarithmic
pressure) the equivalent stress grows without bound towards that surface
point; the maximum is then reported as unbounded (value inf), detected by
comparing the surface value with the value at depth 1e-6 a.

The critical friction mu_c of a sliding contact is the smallest mu at which
the largest value of the criterion lies on the surface; two ways again: a
root (Brent) of D(mu) = (surface maximum) - (interior maximum, tracked in mu)
where a surface value overtakes the interior maximum (or, where the interior
maximum rises into the surface, the zero of its depth^2 extrapolated
linearly), and a bisection on the predicate "the global maximum lies at
z = 0" from the full search at each mu.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...core.errors import LineContactError
from ...core.lazy import lazy_module

optimize = lazy_module("scipy.optimize")     # loaded at the first search

#: the grid of the coarse search, in units of a: x in [-X_SPAN, X_SPAN], z in (0, Z_SPAN]
X_SPAN, Z_SPAN = 2.0, 2.0
GRID = (161, 101)
#: depth (in units of a) below which a maximum counts as on the surface
SURFACE_Z = 1e-6
#: depth (in units of a) at which a surface maximum is probed for a singularity
UNBOUNDED_PROBE = 1e-6


@dataclass(frozen=True)
class StressMaximum:
    """The largest value of an equivalent stress and where it is.

    value, x, z        the maximum (z = 0: on the surface), by the search
    check, check_x, check_z   the same by the independent check (NaN: not checked)
    digits             significant digits on which value and check agree
    on_surface         True when the global maximum lies on the surface
    interior           (value, x, z) of the largest interior maximum or None
    surface            (value, x) of the largest value along the surface
    plateau            True when the surface value is constant over an interval
                       (its x is then the first point of the plateau found)
    unbounded          True when the criterion grows without bound towards the
                       surface point (x, 0) (a singular traction: the wedge's
                       tip, a kink of the profile); value is then inf
    """

    criterion: str
    value: float
    x: float
    z: float
    check: float
    check_x: float
    check_z: float
    digits: float
    on_surface: bool
    interior: tuple | None
    surface: tuple
    plateau: bool = False
    unbounded: bool = False

    def __str__(self):
        if self.unbounded:
            return (f"max {self.criterion} is unbounded: it grows without limit towards the surface point "
                    f"x = {self.x:.6g} (a singular surface traction)")
        where = "on the surface" if self.on_surface else "below the surface"
        return (f"max {self.criterion} = {self.value:.6g} at x = {self.x:.6g}, z = {self.z:.6g} ({where}); "
                f"check {self.check:.6g} at ({self.check_x:.6g}, {self.check_z:.6g}): {self.digits:.1f} digits agree")


def _agree(u, v):
    if u == v:
        return 16.0
    return max(0.0, min(16.0, -math.log10(abs(u - v) / max(abs(u), abs(v), 1e-300))))


def _interior_search(f, a, starts):
    """Nelder-Mead in (x, z) (z reflected at the surface) from each start;
    the results deeper than SURFACE_Z a."""
    out = []
    for x0, z0 in starts:
        r = optimize.minimize(lambda p: -f(p[0], abs(p[1])), [x0, z0], method="Nelder-Mead",
                              options={"xatol": 1e-11 * a, "fatol": 1e-15, "maxiter": 4000, "maxfev": 8000})
        xz = (float(r.x[0]), abs(float(r.x[1])))
        if xz[1] > SURFACE_Z * a:
            out.append((-float(r.fun), *xz))
    return out


def _gradient_root(f, a, x0, z0, symmetric):
    """The check of an interior maximum: a root of the gradient from the grid point."""
    h = 1e-5 * a
    if symmetric and abs(x0) < 0.05 * a:
        def dfdz(zv):
            return (f(0.0, zv + h) - f(0.0, zv - h)) / (2 * h)
        lo, hi = z0 * 0.7, z0 * 1.3
        for _ in range(20):
            if dfdz(lo) > 0 > dfdz(hi):
                zr = optimize.brentq(dfdz, lo, hi, xtol=1e-13 * a)
                return f(0.0, zr), 0.0, zr
            lo, hi = lo * 0.8, hi * 1.2
    def grad(p):
        xv, zv = p
        zv = max(zv, 2 * h)
        return [(f(xv + h, zv) - f(xv - h, zv)) / (2 * h), (f(xv, zv + h) - f(xv, zv - h)) / (2 * h)]
    r = optimize.root(grad, [x0, z0], method="hybr", options={"xtol": 1e-13})
    xv, zv = float(r.x[0]), float(r.x[1])
    return f(xv, zv), xv, zv


def _surface(fs, a, x_span=1.5, n=1501, check=True):
    """Largest value along the surface by a grid refined with bounded Brent,
    the check by a bracketed root of df/dx; the plateau flag."""
    X = np.linspace(-x_span * a, x_span * a, n)
    V = fs(X)
    k = int(np.argmax(V))
    step = X[1] - X[0]
    lo, hi = X[max(k - 2, 0)], X[min(k + 2, n - 1)]
    r = optimize.minimize_scalar(lambda xv: -fs(np.array([xv]))[0], bounds=(lo, hi), method="bounded",
                                 options={"xatol": 1e-12 * a})
    val, xb = -float(r.fun), float(r.x)
    plateau = int(np.count_nonzero(V >= V[k] - 1e-9 * abs(V[k]))) > 2
    h = 1e-6 * a

    def dfdx(xv):
        return (fs(np.array([xv + h]))[0] - fs(np.array([xv - h]))[0]) / (2 * h)
    if not check:
        return val, xb, math.nan, math.nan, plateau
    check, cx = val, xb
    if not plateau and lo < xb < hi:
        try:
            cx = optimize.brentq(dfdx, max(xb - step, X[0]), min(xb + step, X[-1]), xtol=1e-13 * a)
            check = float(fs(np.array([cx]))[0])
        except ValueError:  # a kink (no sign change of a smooth derivative): the grid bracket's best
            check, cx = float(V[k]), float(X[k])
    return val, xb, check, cx, plateau


def find_maximum(criterion_fn, a, name="criterion", symmetric=False, starts=None, check=True) -> StressMaximum:
    """The maximum of ``criterion_fn(x, z)`` (vectorised float64, z >= 0) for a
    contact of half-width ``a``: see the module docstring.  ``symmetric``: the
    field is even in x (frictionless), so a maximum on the axis is checked by
    the axis root of d f/dz.  ``starts``: extra starting points (x, z).
    ``check=False`` (a search that uses only where the maximum is and the
    interior and surface values, as :func:`critical_friction` does): the
    gradient-root check of an interior maximum is skipped (check, check_x,
    check_z and digits are NaN then); everything else is the same.

    >>> import numpy as np
    >>> m = find_maximum(lambda x, z: z * np.exp(-x**2 - z**2), 1.0, "test", symmetric=True)
    >>> bool(abs(m.value - np.exp(-0.5) / np.sqrt(2)) < 1e-14), round(m.z, 8), m.digits > 10
    (True, 0.70710678, True)
    """
    a = float(a)

    def f(xv, zv):
        return float(criterion_fn(np.array([xv]), np.array([zv]))[0])

    xs = np.linspace(-X_SPAN * a, X_SPAN * a, GRID[0])
    zs = np.linspace(0, Z_SPAN * a, GRID[1])[1:]
    Xg, Zg = np.meshgrid(xs, zs)
    V = criterion_fn(Xg, Zg)
    if not np.all(np.isfinite(V)):
        raise LineContactError(f"the {name} is not finite on the search grid")
    core = V[1:-1, 1:-1]
    peak = np.ones_like(core, dtype=bool)
    for di in (-1, 0, 1):
        for dj in (-1, 0, 1):
            if di or dj:
                peak &= core >= V[1 + di:V.shape[0] - 1 + di, 1 + dj:V.shape[1] - 1 + dj]
    ii, jj = np.nonzero(peak)
    order = np.argsort(-core[ii, jj])[:3]
    grid_starts = [(float(Xg[i + 1, j + 1]), float(Zg[i + 1, j + 1])) for i, j in zip(ii[order], jj[order])]
    interior = _interior_search(f, a, grid_starts + list(starts or ()))
    sval, sx, scheck, scx, plateau = _surface(lambda X: criterion_fn(X, np.zeros_like(X)), a, check=check)
    best = max(interior) if interior else None
    if best is not None and best[0] > sval:
        if not check:
            return StressMaximum(name, best[0], best[1], best[2], math.nan, math.nan, math.nan, math.nan, False,
                                 best, (sval, sx), plateau)
        gs = min(grid_starts + list(starts or ()), key=lambda p: (p[0] - best[1])**2 + (p[1] - best[2])**2)
        cval, cx, cz = _gradient_root(f, a, gs[0], gs[1], symmetric)
        if not (abs(cx - best[1]) < 1e-3 * a and abs(cz - best[2]) < 1e-3 * a):
            cval, cx, cz = _gradient_root(f, a, best[1], best[2], symmetric)
        return StressMaximum(name, best[0], best[1], best[2], cval, cx, cz, _agree(best[0], cval), False,
                             best, (sval, sx), plateau)
    # a singular traction: the surface value (at depth SURFACE_DEPTH a) exceeds the one a little deeper
    # by far more than a smooth field allows (a log singularity grows by ~50 % from 1e-6 a to 1e-12 a)
    deeper = f(sx, UNBOUNDED_PROBE * a)
    if sval > deeper + 0.05 * abs(deeper) + 1e-300:
        return StressMaximum(name, math.inf, sx, 0.0, math.inf, scx, 0.0, 0.0, True, best, (math.inf, sx),
                             plateau, True)
    return StressMaximum(name, sval, sx, 0.0, scheck, scx, 0.0, _agree(sval, scheck) if check else math.nan,
                         True, best, (sval, sx), plateau)


def critical_friction(criterion_at, a, mu_max=1.0, step=0.05, xtol=1e-9):
    """The smallest friction coefficient mu in (0, mu_max] at which the global
    maximum of the criterion lies on the surface.  ``criterion_at(mu)`` gives
    the vectorised criterion f(x, z) of the contact sliding with friction mu.
    Returns ``(mu_c, check, digits, kind)``: ``kind`` is 'crossing' (a surface
    value overtakes the interior maximum) or 'merge' (the interior maximum
    rises to the surface)."""
    a = float(a)

    def state(mu, starts=None):       # where the maximum is: its gradient-root check is not needed
        return find_maximum(criterion_at(mu), a, starts=starts, check=False)

    mus = np.arange(step, mu_max + step / 2, step)
    prev_mu, prev = 0.0, state(0.0)
    if prev.on_surface:
        raise LineContactError("the maximum lies on the surface already without friction")
    for mu in mus:
        cur = state(float(mu), [(prev.x, prev.z)])
        if cur.on_surface:
            break
        prev_mu, prev = float(mu), cur
    else:
        raise LineContactError(f"the maximum stays below the surface up to mu = {mu_max}")
    lo, hi, track = prev_mu, float(mu), (prev.x, prev.z)

    def deficit(mu, start):
        """surface maximum - interior maximum (tracked from ``start``), or None
        when the interior maximum has gone (merged into the surface)."""
        m = find_maximum(criterion_at(mu), a, starts=[start], check=False)
        if m.interior is None:
            return None, start
        return m.surface[0] - m.interior[0], (m.interior[1], m.interior[2])

    # a bracket of the crossing D(mu) = 0, both ends with an interior maximum
    blo, bhi, start, kind = lo, hi, track, "merge"
    for _ in range(40):
        d_hi, _s = deficit(bhi, start)
        if d_hi is not None and d_hi > 0:
            kind = "crossing"
            break
        mid = (blo + bhi) / 2
        d_mid, s_mid = deficit(mid, start)
        if d_mid is None or d_mid > 0:
            bhi = mid
        else:
            blo, start = mid, s_mid
        if bhi - blo < 1e-9:
            break
    # the check: bisection on the predicate "the global maximum is on the surface"
    plo, phi_, ptrack = lo, hi, track
    while phi_ - plo > 1e-8:
        mid = (plo + phi_) / 2
        m = state(mid, [ptrack])
        if m.on_surface:
            phi_ = mid
        else:
            plo, ptrack = mid, (m.x, m.z)
    check = (plo + phi_) / 2
    if kind == "crossing":
        muc = optimize.brentq(lambda mu: deficit(mu, start)[0], blo, bhi, xtol=xtol)
    else:  # merge: the depth of the interior maximum extrapolated to zero (z^2 is linear in mu there)
        mus = [blo - k * (bhi - blo + 1e-3) for k in (0, 1, 2)]
        zs2 = []
        for m_ in mus:
            mm = find_maximum(criterion_at(m_), a, starts=[start], check=False)
            zs2.append(mm.interior[2]**2 if mm.interior else np.nan)
        coef = np.polyfit(mus, zs2, 1)
        muc = float(-coef[1] / coef[0])
    return muc, check, _agree(muc, check), kind


__all__ = ["StressMaximum", "find_maximum", "critical_friction", "SURFACE_Z"]
