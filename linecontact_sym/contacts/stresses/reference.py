"""The independent reference of the subsurface stresses: mpmath quadrature of
the Flamant integrals (Johnson 1985, Eq. 2.23) of the surface tractions
themselves, and of the Cauchy transform of the pressure.

It shares nothing with the closed forms and the numeric field of
:mod:`.kolosov` / :mod:`.field` (which integrate the punch density
P'(t) against the flat-punch potential): here the pressure p(s) and the
traction q(s) are integrated against the real Flamant kernels.

The near-surface singularity: the kernels w^k/r^4 (w = x - s, r^2 = w^2 +
z^2) peak like 1/z^(4-k) over a width z around s = x.  The substitution
s = x + z sinh(u) (ds = z cosh(u) du, w = -z sinh u, r = z cosh u) turns each
into a bounded smooth function of u::

    z w^2/r^4 ds = tanh(u)^2/cosh(u) du          z^3/r^4 ds = du/cosh(u)^3
    z^2 w/r^4 ds = -tanh(u)/cosh(u)^2 du         w^3/r^4 ds = -tanh(u)^3 du

so the integrals are taken over u, split where s crosses the ends of the
contact and the breakpoints of the tractions (where p or q is not smooth:
s = 0 for power laws, s = +-b for the worn cylinder), by tanh-sinh.
"""
from __future__ import annotations

import mpmath
from ...core.errors import DomainError
from ...core.precision import workdps


def _pieces(x, z, a, breaks):
    """u-intervals of s = x + z sinh(u) covering [-a, a], split at the
    breakpoints (and at s = x, where the kernels peak)."""
    pts = {-a, a}
    pts.update(b for b in breaks if -a < b < a)
    if -a < x < a:
        pts.add(x)
    return [mpmath.asinh((s - x) / z) for s in sorted(pts)]


def flamant_stresses(p, q, a, x, z, breaks=(), dps: int = 30):
    """(sigma_x, sigma_z, tau_xz) at (x, z), z >= 0, of the pressure ``p`` and
    the tangential traction ``q`` (mpmath callables on [-a, a], ``q`` may be
    None) by tanh-sinh quadrature of Johnson's Eq. (2.23) after
    s = x + z sinh(u).  Signs as in :mod:`.kolosov` (tensile positive,
    q acting on the body in +x).  On the surface z = 0 without tangential
    traction: sigma_z = sigma_x = -p(x), tau_xz = 0 (Johnson Eq. 2.25).

    >>> import mpmath
    >>> hertz = lambda s: mpmath.sqrt(1 - s**2)          # p0 = a = 1
    >>> [mpmath.nstr(v, 12) for v in flamant_stresses(hertz, None, 1, 0, 1)]
    ['-0.12132034356', '-0.707106781187', '0.0']
    """
    with workdps(dps + 10):
        a, x, z = mpmath.mpf(a), mpmath.mpf(x), mpmath.mpf(z)
        if z == 0:                  # the surface: the tractions themselves
            if q is not None:
                raise DomainError("the surface stresses under a tangential traction need its Hilbert transform; "
                                  "evaluate at a depth z > 0 (or use a closed form)")
            pv = p(x) if -a <= x <= a else mpmath.mpf(0)
            return (-pv, -pv, mpmath.mpf(0))
        us = _pieces(x, z, a, [mpmath.mpf(b) for b in breaks])

        def s_of(u):
            return x + z * mpmath.sinh(u)

        memo: dict = {}

        def integrand(u):
            if u in memo:
                return memo[u]
            s = s_of(u)
            if not -a <= s <= a:
                return (0, 0, 0)
            ch, th = mpmath.cosh(u), mpmath.tanh(u)
            pv = p(s)
            qv = q(s) if q is not None else 0
            sx = -pv * th**2 / ch + qv * th**3
            sz = -pv / ch**3 + qv * th / ch**2
            txz = pv * th / ch**2 - qv * th**2 / ch
            memo[u] = (sx, sz, txz)
            return memo[u]

        out = []
        for k in range(3):
            out.append(mpmath.quad(lambda u, k=k: integrand(u)[k], us))
        return tuple(+(2 * v / mpmath.pi) for v in out)


def cauchy_quad(p, a, x, z, breaks=(), dps: int = 30):
    """G(zeta) = int_{-a}^{a} p(s)/(zeta - s) ds at zeta = x + i z (z > 0),
    by tanh-sinh after s = x + z sinh(u): p(s) z cosh(u)/(z (i - sinh u)) du."""
    with workdps(dps + 10):
        a, x, z = mpmath.mpf(a), mpmath.mpf(x), mpmath.mpf(z)
        if not z > 0:               # on the surface G has a jump (a principal value): not this quadrature
            raise DomainError(f"the Cauchy transform is evaluated below the surface (z > 0), got z = {z}")
        us = _pieces(x, z, a, [mpmath.mpf(b) for b in breaks])
        j = mpmath.mpc(0, 1)

        def f(u):
            s = x + z * mpmath.sinh(u)
            if not -a <= s <= a:
                return mpmath.mpc(0)
            return p(s) * mpmath.cosh(u) / (j - mpmath.sinh(u))
        return +mpmath.quad(f, us)


def punch_potentials(dP, a, x, z, breaks=(), dps: int = 30):
    """G(zeta) = int_0^a P'(t) (zeta^2 - t^2)^(-1/2) dt and G'(zeta) at
    zeta = x + i z by tanh-sinh after t = c + z sinh(u), c = min(|x|, a),
    split at c and at the breakpoints of P' (``dP`` an mpmath callable).
    The high-precision evaluation of the field where the pressure has no
    closed form (Popov's superposition, the formula of the float64 field
    at any precision); not independent of it."""
    with workdps(dps + 10):
        a, x, z = mpmath.mpf(a), mpmath.mpf(x), mpmath.mpf(z)
        X = abs(x)
        c = min(X, a)
        pts = sorted({mpmath.mpf(0), a, c} | {mpmath.mpf(b) for b in breaks if 0 < b < a})
        us = [mpmath.asinh((t - c) / z) for t in pts]
        zeta = mpmath.mpc(X, z)
        memo: dict = {}

        def parts(u):
            if u not in memo:
                t = c + z * mpmath.sinh(u)
                if not 0 <= t <= a:
                    memo[u] = (0, 0)
                else:
                    k = mpmath.sqrt(zeta - t) * mpmath.sqrt(zeta + t)
                    f = dP(t) * z * mpmath.cosh(u) / k
                    memo[u] = (f, -zeta * f / k**2)
            return memo[u]
        G = mpmath.quad(lambda u: parts(u)[0], us)
        dG = mpmath.quad(lambda u: parts(u)[1], us)
        if x < 0:  # an even traction: G(-conj zeta) = -conj G(zeta), G'(-conj zeta) = conj G'(zeta)
            G, dG = -mpmath.conj(G), mpmath.conj(dG)
        return +G, +dG


__all__ = ["flamant_stresses", "cauchy_quad", "punch_potentials"]
