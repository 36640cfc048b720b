"""The independent reference of the subsurface stresses: Arb ball quadrature
(mpmath as the recorded fallback) of the Flamant integrals (Johnson 1985, Eq. 2.23) of the surface tractions
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
s = 0 for power laws, s = +-b for the worn cylinder).

:func:`flamant_enclosures` hands these integrands (SymPy, every value exact)
to the one reference integrator
(:func:`linecontact_sym.numeric.reference.integrate`): Arb ball quadrature,
a rigorous enclosure of each component; :func:`flamant_stresses` (tanh-sinh
in mpmath, of callables) is its recorded fallback and the route of tractions
that are not SymPy expressions.
"""
from __future__ import annotations

import mpmath
import sympy as sp

from ...core.errors import DomainError
from ...core.precision import workdps
from ...numeric.reference import estimate, integrate

#: evaluations per piece before Arb gives up: a piece at the contact's edge
#: (p ~ sqrt(a - s)) takes about 1700 at 45 digits; one that Arb cannot bound
#: (a log singularity, 2F1 at its branch point) wastes the whole limit
EVAL_LIMIT = 6000

#: the three components, in the order of :func:`flamant_stresses`
COMPONENTS = ("sigma_x", "sigma_z", "tau_xz")
_u = sp.Dummy("u", real=True)


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


def flamant_kernels(P, Q, u):
    """(2/pi) x the integrands of (sigma_x, sigma_z, tau_xz) in u (module
    docstring) for the tractions P = p(s), Q = q(s) at s = x + z sinh(u)."""
    ch, th = sp.cosh(u), sp.tanh(u)
    c = 2 / sp.pi
    return (c * (-P * th**2 / ch + Q * th**3),
            c * (-P / ch**3 + Q * th / ch**2),
            c * (P * th / ch**2 - Q * th**2 / ch))


def _exact_sorted(values):
    """Distinct exact values, ascending (floats taken as their binary value)."""
    out = {}
    for v in values:
        v = sp.Rational(v) if isinstance(v, float) else sp.nsimplify(v) if isinstance(v, sp.Float) else sp.sympify(v)
        key = mpmath.mpf(sp.N(v, 60)) if not v.is_Rational else mpmath.mpf(v.p) / v.q
        with workdps(60):
            key = +key
        out.setdefault(key, v)
    return [out[k] for k in sorted(out)]


def flamant_enclosures(tractions, a, x, z, breaks=(), dps: int = 30, fallback=None):
    """(sigma_x, sigma_z, tau_xz) at (x, z), z > 0, as three
    :class:`~linecontact_sym.numeric.reference.RefValue` (Arb enclosures where
    Arb can): Johnson's Eq. (2.23) after s = x + z sinh(u), each component
    integrated by :func:`~linecontact_sym.numeric.reference.integrate` over
    the u-pieces of [-a, a] split at s = x and at ``breaks``.

    ``tractions(lo, hi, s)``: (p, q) as SymPy expressions in ``s`` (every
    parameter exact), valid on the piece lo < s < hi of the surface (q may
    be 0); ``a, x, z``: exact numbers; ``fallback()``: the three mpmath
    values (:func:`flamant_stresses`), computed once if Arb cannot.

    >>> import sympy as sp
    >>> hertz = lambda lo, hi, s: (sp.sqrt(1 - s**2), 0)       # p0 = a = 1
    >>> r = flamant_enclosures(hertz, 1, 0, 1, dps=30)
    >>> [v.method for v in r], [mpmath.nstr(v, 12) for v in r[:2]], abs(r[2]) < 1e-35   # tau_xz = 0 on the axis
    (['arb', 'arb', 'arb'], ['-0.12132034356', '-0.707106781187'], True)
    """
    a, x, z = sp.sympify(a), sp.sympify(x), sp.sympify(z)
    if not z > 0:
        raise DomainError(f"the Flamant enclosures are taken below the surface (z > 0), got z = {z}")
    ss = _exact_sorted([-a, a, *(b for b in breaks if -a < b < a), *([x] if -a < x < a else [])])
    us = [sp.asinh((sv - x) / z) for sv in ss]
    sv = x + z * sp.sinh(_u)
    pieces = [flamant_kernels(*tractions(lo, hi, sv), _u) for lo, hi in zip(ss[:-1], ss[1:])]
    memo = []

    def mp(k):
        if not memo:
            memo.append(fallback())
        return memo[0][k]
    out = []
    for k in range(3):
        if out and not out[0].certified and fallback is not None:
            # the same tractions: Arb would fail again (and spend its evaluation limit)
            out.append(estimate(lambda k=k: mp(k), out[0].note, dps))
        else:
            out.append(integrate([piece[k] for piece in pieces], _u, us, dps, eval_limit=EVAL_LIMIT,
                                 fallback=None if fallback is None else (lambda k=k: mp(k))))
    return tuple(out)


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


__all__ = ["flamant_stresses", "flamant_enclosures", "flamant_kernels", "COMPONENTS", "cauchy_quad", "punch_potentials"]
