"""Independent solutions of the tangential (partial-slip) line contact, to
check the Cattaneo-Mindlin-Ciavarella-Jaeger superposition of
:mod:`.tangential` by routes that do not use it.

The problem (plane strain, elastically similar bodies or Dundurs' beta
neglected, Coulomb friction mu, constant normal load): the relative tangential
displacement of the two surfaces at x is

    w(x) = delta + (2/(pi E*)) int_{-a}^{a} q(xi) ln|x - xi| dxi,          (F)

(the Flamant kernel; the same compliance 2/(pi E*) as the normal problem,
1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2), with q the shear traction (positive in
the direction of Q) and delta a rigid shift that is not defined by itself in
2-D (the logarithm needs a length unit).  Stick: w does not change; slip:
|q| = mu p(x; a) with q in the direction of the slip increment.

Two kinds of references live here.

**High-precision (mpmath) references** used as the ``reference`` of the
tangential derivations (30 digits):

* :func:`stick_traction_inversion` -- the stick-zone traction as the unique
  bounded solution of the Cauchy singular integral equation of the stick zone,
  H[q](x) = 0 for |x| < c with q = mu p(x; a) prescribed on c < |x| < a,
  inverted in closed form (Muskhelishvili) and evaluated by quadrature::

      q(x) = (2 mu/pi) sqrt(c^2 - x^2) int_0^U p(sqrt(c^2 + u^2); a) / (c^2 - x^2 + u^2) du,

  U = sqrt(a^2 - c^2).  It uses the pressure at the half-width a only, never
  the pressure at c.
* :func:`tangential_force_inversion` -- its resultant plus the slip zones::

      Q(c) = 2 mu int_0^U p(sqrt(c^2 + u^2); a) du.

* :func:`slip_flamant` -- the slip from the Flamant kernel (F) applied to a
  traction, relative to the centre of the (never slipping) stick zone.
* :func:`friction_work` -- the energy dissipated per cycle as the work of the
  friction forces in the slip zones, 8 mu^2 int_c^a p(x; a) g(x; c) dx.

The traction, the force and the friction work are also given as **Arb
enclosures** (:func:`stick_traction_enclosure`, :func:`tangential_force_enclosure`,
:func:`friction_work_enclosure`): the same integrals with the normal solutions
as SymPy expressions (every value exact), integrated by the one reference
integrator (:func:`linecontact_sym.numeric.reference.integrate`, Arb ball
quadrature; the mpmath functions above are their recorded fallbacks).  The
slip and the displacement keep mpmath: their logarithmic kernels are singular
at end points of the pieces, which ball arithmetic cannot bound.

**A direct numerical solution**, :class:`CoulombBEM`: boundary elements with
piecewise-constant tractions and analytic influence coefficients of (F),
collocation at the element midpoints, and a Coulomb active set (stick /
slip with direction) solved step by step along any load history Q(t).  It
assumes nothing about the shape of the stick zone; the normal pressure is an
input (element averages of Eq. 12 from the force-law slope P'(t)).
Accuracy (measured, Hertz, n = 200 half-elements): slip and dissipated
energy to about 4-5 digits, the traction to about 3 (the stick-zone edge is
resolved to one element).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import mpmath
import numpy as np
import sympy as sp

from ...core.errors import DomainError, LineContactError
from ...numeric.reference import integrate


# =====================================================================  mpmath
def _split(points, lo, hi):
    """Sorted unique quadrature points in [lo, hi] (mpf)."""
    pts = sorted({mpmath.mpf(lo), mpmath.mpf(hi), *(mpmath.mpf(v) for v in points if lo < v < hi)})
    return pts


def stick_traction_inversion(p, a, c, x, mu, breaks=()):
    """The stick-zone traction q(x), |x| < c, by the inversion of the stick
    condition (see the module docstring); ``p`` is an mpmath callable of the
    pressure at half-width ``a``, ``breaks`` the kinks of p (the profile's
    breakpoints).  Domain: 0 <= |x| < c < a.

    Hertz (p = sqrt(1 - x^2) for a = 1, E* = 2 R): mu [p(x; 1) - p(x; c)]

    >>> import mpmath
    >>> p = lambda t: mpmath.sqrt(1 - t**2)
    >>> q = stick_traction_inversion(p, 1, 0.5, 0.3, 0.2)
    >>> abs(q - 0.2 * (p(0.3) - mpmath.sqrt(0.25 - 0.09))) < 1e-14
    True
    """
    a, c, x, mu = (mpmath.mpf(v) for v in (a, c, x, mu))
    if not (abs(x) < c < a):
        raise DomainError(f"the inversion needs |x| < c < a, got x = {x}, c = {c}, a = {a}")
    U = mpmath.sqrt(a**2 - c**2)
    d2 = c**2 - x**2
    pts = _split([mpmath.sqrt(bv**2 - c**2) for bv in breaks if c < bv < a], 0, U)
    integral = mpmath.quad(lambda u: p(mpmath.sqrt(c**2 + u**2)) / (d2 + u**2), pts)
    return 2 * mu / mpmath.pi * mpmath.sqrt(d2) * integral


def tangential_force_inversion(p, a, c, mu, breaks=()):
    """Q(c) = 2 mu int_0^U p(sqrt(c^2 + u^2); a) du: the resultant of the
    inverted stick traction and of mu p in the slip zones.  Domain 0 <= c <= a.

    Hertz (p = sqrt(1 - x^2)): mu [P(1) - P(c)] = mu pi (1 - c^2)/2

    >>> import mpmath
    >>> Q = tangential_force_inversion(lambda t: mpmath.sqrt(1 - t**2), 1, 0.5, 0.2)
    >>> abs(Q - 0.2 * mpmath.pi * 0.75 / 2) < 1e-14
    True
    """
    a, c, mu = (mpmath.mpf(v) for v in (a, c, mu))
    if not (0 <= c <= a):
        raise DomainError(f"the stick half-width must lie in [0, a], got c = {c}, a = {a}")
    U = mpmath.sqrt(a**2 - c**2)
    pts = _split([mpmath.sqrt(bv**2 - c**2) for bv in breaks if c < bv < a], 0, U)
    return 2 * mu * mpmath.quad(lambda u: p(mpmath.sqrt(c**2 + u**2)), pts)


def slip_flamant(q, a, x, E_star, points=()):
    """Slip at x: the relative tangential displacement of the surfaces at x
    minus that at the centre x = 0 (which never slips),

        s(x) = (2/(pi E*)) int_{-a}^{a} q(xi) [ln|x - xi| - ln|xi|] dxi,

    from the Flamant kernel (F).  ``q`` is an mpmath callable of the traction
    (even in xi), ``points`` its kinks in (0, a) (stick-zone edges, profile
    breakpoints).  Positive s: the surfaces have moved in the direction of Q.

    Hertz (a = 1, c = 0.5, E* = 2, R = 1: p = sqrt(1 - x^2)): mu g(x; c)

    >>> import mpmath
    >>> p = lambda t, A=1: mpmath.sqrt(A**2 - t**2) if abs(t) < A else 0
    >>> q = lambda t: 0.2 * (p(t) - p(t, 0.5))
    >>> g = (0.8 * mpmath.sqrt(0.64 - 0.25) - 0.25 * mpmath.acosh(1.6)) / 2
    >>> abs(slip_flamant(q, 1, 0.8, 2, [0.5]) - 0.2 * g) < 1e-13
    True
    """
    a, x, E = (mpmath.mpf(v) for v in (a, x, E_star))
    x = abs(x)
    inner = {mpmath.mpf(0), x, *(mpmath.mpf(v) for v in points)}
    pos = [v for v in inner if 0 <= v < a]
    pts = sorted({*(-v for v in pos), *pos, -a, a})

    def integrand(xi):
        if xi == 0 or xi == x:
            return mpmath.mpf(0)
        return q(xi) * (mpmath.log(abs(x - xi)) - mpmath.log(abs(xi)))
    return 2 / (mpmath.pi * E) * mpmath.quad(integrand, pts)


def displacement_flamant(q, a, E_star, points=()):
    """The rigid shift with the reference length a of the Flamant kernel,
    from the stick condition at the centre, w(0) = 0:

        delta = -(2/(pi E*)) int_{-a}^{a} q(xi) ln(|xi|/a) dxi.

    (2-D leaves the rigid shift undefined; another reference length L adds
    (2 Q/(pi E*)) ln(L/a).)

    Hertz (a = 1, c = 0.5, E* = 2, R = 1), see :mod:`.tangential`:

    >>> import mpmath
    >>> p = lambda t, A=1: mpmath.sqrt(A**2 - t**2) if abs(t) < A else 0
    >>> d = displacement_flamant(lambda t: 0.2 * (p(t) - p(t, 0.5)), 1, 2, [0.5])
    >>> abs(d - 0.2 / 4 * (0.75 - 0.5 * mpmath.log(2) + 1.5 * mpmath.log(2))) < 1e-13
    True
    """
    a, E = mpmath.mpf(a), mpmath.mpf(E_star)
    inner = {mpmath.mpf(0), *(mpmath.mpf(v) for v in points if 0 < v < a)}
    pts = sorted({*(-v for v in inner), *inner, -a, a})

    def integrand(xi):
        return mpmath.mpf(0) if xi == 0 else q(xi) * mpmath.log(abs(xi) / a)
    return -2 / (mpmath.pi * E) * mpmath.quad(integrand, pts)


def friction_work(p, g, a, c, mu, breaks=()):
    """Energy dissipated per full cycle between +-Q_A, as the work of the
    friction forces: each half-cycle reverses the slip in the slip zones
    c < |x| < a by 2 mu g(x; c) under the traction mu p(x; a), so

        W = 2 half-cycles * 2 zones * int_c^a mu p(x; a) * 2 mu g(x; c) dx.

    ``p``: pressure at a, ``g``: gap at c (mpmath callables of x).

    Hertz (a = 1, c = 0.5, E* = 2, R = 1): pi E* mu^2/(8 R^2) [a^4 - c^4 - 4 a^2 c^2 ln(a/c)]

    >>> import mpmath
    >>> g = lambda x: (x * mpmath.sqrt(x**2 - 0.25) - 0.25 * mpmath.acosh(2 * x)) / 2
    >>> W = friction_work(lambda x: mpmath.sqrt(1 - x**2), g, 1, 0.5, 0.2)
    >>> abs(W - mpmath.pi * 2 * 0.04 / 8 * (1 - 0.0625 - mpmath.log(2))) < 1e-14
    True
    """
    a, c, mu = (mpmath.mpf(v) for v in (a, c, mu))
    pts = _split(breaks, c, a)
    return 8 * mu**2 * mpmath.quad(lambda xv: p(xv) * g(xv), pts)


# =====================================================================  Arb
_u = sp.Dummy("u", nonnegative=True)
_xv = sp.Dummy("x", positive=True)


def _exact_pieces(lo, hi, inner):
    """[lo, *inner in (lo, hi) ascending and distinct, hi] (exact SymPy numbers)."""
    keep = {}
    for v in inner:
        v = sp.nsimplify(v) if isinstance(v, (float, sp.Float)) else sp.sympify(v)
        if bool(lo < v) and bool(v < hi):
            keep.setdefault(sp.N(v, 50), v)
    return [lo, *(keep[k] for k in sorted(keep)), hi]


def _inside(c, a, breaks):
    """The u-points sqrt(b^2 - c^2) of the breakpoints c < b < a."""
    return [sp.sqrt(b**2 - c**2) for b in breaks if bool(c < b) and bool(b < a)]


def _checked(a, c, x=None):
    a, c = sp.sympify(a), sp.sympify(c)
    if not (bool(0 <= c) and bool(c <= a)) or (x is not None and not bool(abs(sp.sympify(x)) < c)):
        raise DomainError(f"the inversion needs |x| < c <= a, got x = {x}, c = {c}, a = {a}")
    return a, c


def stick_traction_enclosure(p, a, c, x, mu, breaks=(), dps: int = 30, fallback=None):
    """:func:`stick_traction_inversion` with ``p`` a SymPy function of one
    argument (``sp.Lambda``; the pressure at half-width ``a``, every value
    exact) and exact ``a, c, x, mu``: the whole traction
    (2 mu/pi) sqrt(c^2 - x^2) p(sqrt(c^2 + u^2))/(c^2 - x^2 + u^2) integrated
    over u in [0, sqrt(a^2 - c^2)] (a RefValue).

    >>> import sympy as sp
    >>> p = sp.Lambda(_xv, sp.sqrt(1 - _xv**2))
    >>> r = stick_traction_enclosure(p, 1, sp.Rational(1, 2), sp.Rational(3, 10), sp.Rational(1, 5))
    >>> r.method, abs(r - 0.2 * (mpmath.sqrt(0.91) - mpmath.sqrt(0.16))) < 1e-14
    ('arb', True)
    """
    a, c = _checked(a, c, x)
    d2 = c**2 - sp.sympify(x)**2
    f = 2 * mu / sp.pi * sp.sqrt(d2) * p(sp.sqrt(c**2 + _u**2)) / (d2 + _u**2)
    return integrate(f, _u, _exact_pieces(sp.S.Zero, sp.sqrt(a**2 - c**2), _inside(c, a, breaks)), dps,
                     fallback=fallback)


def tangential_force_enclosure(p, a, c, mu, breaks=(), dps: int = 30, fallback=None):
    """:func:`tangential_force_inversion` in Arb: 2 mu int_0^U p(sqrt(c^2 + u^2)) du
    (``p`` as in :func:`stick_traction_enclosure`).

    >>> import sympy as sp
    >>> p = sp.Lambda(_xv, sp.sqrt(1 - _xv**2))
    >>> r = tangential_force_enclosure(p, 1, sp.Rational(1, 2), sp.Rational(1, 5), dps=40)
    >>> with mpmath.workdps(50):                        # Hertz: mu pi (1 - c^2)/2
    ...     r.method, r.contains(mpmath.mpf(3) / 40 * mpmath.pi)
    ('arb', True)
    """
    a, c = _checked(a, c)
    f = 2 * mu * p(sp.sqrt(c**2 + _u**2))
    return integrate(f, _u, _exact_pieces(sp.S.Zero, sp.sqrt(a**2 - c**2), _inside(c, a, breaks)), dps,
                     fallback=fallback)


def friction_work_enclosure(p, g, a, c, mu, breaks=(), dps: int = 30, fallback=None):
    """:func:`friction_work` in Arb: 8 mu^2 int_c^a p(x) g(x) dx with ``p`` the
    pressure at a and ``g`` the gap at c as SymPy functions of one argument
    (``sp.Lambda``, every value exact)."""
    a, c = _checked(a, c)
    return integrate(8 * mu**2 * p(_xv) * g(_xv), _xv, _exact_pieces(c, a, breaks), dps, fallback=fallback)


# =====================================================================  BEM
def _F(u):
    """Antiderivative helper: int ln|u| du = u ln|u| - u (0 at u = 0)."""
    au = np.abs(u)
    return np.where(au > 0, u * np.log(np.where(au > 0, au, 1.0)) - u, 0.0)


def gauss_root_end(fn, lo, hi, n=24):
    """Gauss-Legendre on [lo, hi] after t = lo + (hi - lo) v^2 (removes a
    square-root endpoint behaviour at lo); vectorised over arrays lo, hi."""
    v, wts = np.polynomial.legendre.leggauss(n)
    v = 0.5 * (v + 1.0)
    wts = 0.5 * wts
    lo, hi = np.asarray(lo, float)[..., None], np.asarray(hi, float)[..., None]
    t = lo + (hi - lo) * v**2
    return np.sum(fn(t) * 2 * (hi - lo) * v * wts, axis=-1)


def element_pressures(dP, edges, a, breaks=()):
    """Mean normal pressure on each element [x1, x2] of ``edges`` (0 <= x <= a):

        int_{x1}^{x2} p dx = (1/pi) int_{x1}^{a} P'(t) [asin(min(x2, t)/t) - asin(x1/t)] dt

    (Eq. 12 integrated over the element), by Gauss-Legendre split at x2 and
    at the breakpoints.  ``dP``: numpy callable of the force-law slope.

    Hertz (P = pi a^2/4, p = sqrt(a^2 - x^2)/2): the mean over [0, 1] is pi/8

    >>> import numpy as np
    >>> bool(abs(element_pressures(lambda t: np.pi * t / 2, np.array([0.0, 1.0]), 1.0)[0] / (np.pi / 8) - 1) < 1e-12)
    True
    """
    x1, x2 = np.asarray(edges[:-1], float), np.asarray(edges[1:], float)
    cuts = sorted(float(bv) for bv in breaks if 0 < bv < a)

    def kernel(t, lo, hi):
        return dP(t) * (np.arcsin(np.minimum(hi[:, None], t) / t) - np.arcsin(np.clip(lo[:, None] / t, 0, 1)))
    total = np.zeros_like(x1)
    # [x1, x2] and [x2, a], each further split at the breakpoints
    for lo_end, hi_end in ((x1, x2), (x2, np.full_like(x2, a))):
        knots = [lo_end] + [np.clip(np.full_like(lo_end, bv), lo_end, hi_end) for bv in cuts] + [hi_end]
        for k0, k1 in zip(knots[:-1], knots[1:]):
            ok = k1 > k0
            if not ok.any():
                continue
            lo, hi = np.where(ok, k0, 0.0), np.where(ok, k1, 1.0)
            val = gauss_root_end(lambda t: kernel(t, x1, x2), lo, hi)
            total += np.where(ok, val, 0.0)
    return total / (np.pi * (x2 - x1))


def solve_dense(A, b):
    """x with A x = b by Gaussian elimination with partial pivoting in plain
    numpy array operations.  Used instead of ``numpy.linalg.solve`` because a
    multi-threaded LAPACK spends ~0.1 s per small system (n ~ 100) when the
    cores are shared; this costs ~n elementwise updates and is deterministic.

    >>> solve_dense([[2.0, 1.0], [1.0, 3.0]], [3.0, 5.0])
    array([0.8, 1.4])
    """
    A = np.array(A, dtype=float)
    b = np.array(b, dtype=float)
    n = len(b)
    for k in range(n - 1):
        piv = k + int(np.argmax(np.abs(A[k:, k])))
        if A[piv, k] == 0.0:
            raise LineContactError("singular boundary-element system")
        if piv != k:
            A[[k, piv]] = A[[piv, k]]
            b[[k, piv]] = b[[piv, k]]
        f = A[k + 1:, k] / A[k, k]
        A[k + 1:, k + 1:] -= f[:, None] * A[k, k + 1:][None, :]
        b[k + 1:] -= f * b[k]
    x = np.empty(n)
    for k in range(n - 1, -1, -1):
        x[k] = (b[k] - np.dot(A[k, k + 1:], x[k + 1:])) / A[k, k]
    return x


@dataclass
class BEMState:
    """One equilibrium state of :class:`CoulombBEM` (half mesh x >= 0).

    Q         tangential force per unit length
    q         element tractions (positive in the direction of +Q)
    w         relative tangential displacement at the midpoints, up to the
              rigid shift: the slip relative to the centre is ``w - w[0]``
    stick     True where the element sticks
    dissipated  friction work accumulated since the start of the history
    """

    Q: float
    q: np.ndarray
    w: np.ndarray
    stick: np.ndarray
    dissipated: float = 0.0
    sign: np.ndarray = field(default=None, repr=False)


class CoulombBEM:
    """Direct numerical solution of the tangential line contact along a load
    history (see the module docstring).

    Parameters
    ----------
    a, E_star, mu : float
        Half-width, plane-strain modulus E*, friction coefficient.
    pressure : array or callable
        Element-mean pressures on the half mesh, or a numpy callable P'(t)
        of the normal force law (then Eq. 12 is integrated per element).
    n : int
        Elements on 0 <= x <= a (graded towards the edge, x = a sin(theta)).
    breaks : breakpoints of the profile (for the pressure integration).
    
    Example (Hertz, E* = 2, R = 1, a = 1, mu = 0.2: Q = 0.6 mu P, c = a sqrt(0.4)):

    >>> import numpy as np
    >>> bem = CoulombBEM(1.0, 2.0, 0.2, lambda t: np.pi * t, n=60)
    >>> _ = bem.run(np.linspace(0, 0.6 * 0.2 * bem.P, 5)[1:])
    >>> bool(abs(bem.stick_half_width() - np.sqrt(0.4)) < 0.04)
    True
    """

    def __init__(self, a, E_star, mu, pressure, n=200, breaks=()):
        self.a, self.E_star, self.mu = float(a), float(E_star), float(mu)
        th = np.linspace(0.0, np.pi / 2, n + 1)
        self.edges = self.a * np.sin(th)
        self.h = np.diff(self.edges)
        self.x = 0.5 * (self.edges[:-1] + self.edges[1:])
        if callable(pressure):
            self.p = element_pressures(pressure, self.edges, self.a, breaks)
        else:
            self.p = np.asarray(pressure, float)
        if np.any(self.p < 0):
            raise DomainError("negative normal pressure on the mesh: the normal solution is not admissible")
        X, e1, e2 = self.x[:, None], self.edges[None, :-1], self.edges[None, 1:]
        K = (_F(X - e1) - _F(X - e2)) + (_F(X + e2) - _F(X + e1))   # element and its mirror image
        self.C = 2.0 / (np.pi * self.E_star) * K
        self.P = 2.0 * float(self.p @ self.h)
        self.state = BEMState(0.0, np.zeros(n), np.zeros(n), np.ones(n, bool), 0.0, np.zeros(n))

    def step(self, Q, maxit=500) -> BEMState:
        """Move quasi-statically from the current state to the load Q (one
        increment; call repeatedly along a history).  Active set: a sticking
        element that would need |q| > mu p starts to slip in the direction of
        its traction; a slipping element whose slip increment opposes its
        traction sticks again."""
        if abs(Q) > self.mu * self.P * (1 + 1e-12):
            raise LineContactError(f"|Q| = {abs(Q):.6g} exceeds mu P = {self.mu * self.P:.6g}: gross sliding")
        old = self.state
        stick, sign = old.stick.copy(), old.sign.copy()
        lim = self.mu * self.p
        for _ in range(maxit):
            S, L = np.flatnonzero(stick), np.flatnonzero(~stick)
            q = np.empty_like(lim)
            q[L] = sign[L] * lim[L]
            m = len(S)
            A = np.zeros((m + 1, m + 1))
            r = np.zeros(m + 1)
            A[:m, :m] = self.C[np.ix_(S, S)]
            A[:m, m] = 1.0
            r[:m] = old.w[S] - self.C[np.ix_(S, L)] @ q[L]
            A[m, :m] = 2.0 * self.h[S]
            r[m] = Q - 2.0 * self.h[L] @ q[L]
            if m:
                sol = solve_dense(A, r)
                q[S], delta = sol[:m], sol[m]
            else:
                delta = 0.0
            w = delta + self.C @ q
            over = S[np.abs(q[S]) > lim[S] * (1 + 1e-12)]
            if len(over):
                stick[over] = False
                sign[over] = np.sign(q[over])
                continue
            back = L[sign[L] * (w[L] - old.w[L]) < -1e-14 * max(1.0, np.abs(old.w).max())]
            if len(back):
                stick[back] = True
                continue
            slipping = ~stick
            work = 2.0 * float(np.sum(np.abs(q[slipping]) * np.abs(w[slipping] - old.w[slipping]) * self.h[slipping]))
            self.state = BEMState(float(Q), q, w, stick, old.dissipated + work, sign)
            return self.state
        raise LineContactError("the Coulomb active set did not converge")

    def run(self, loads) -> list:
        """:meth:`step` through the loads in order; the states."""
        return [self.step(float(Q)) for Q in loads]

    def slip(self, state=None) -> np.ndarray:
        """Slip at the midpoints relative to the centre (which never slips)."""
        st = state or self.state
        return st.w - st.w[0]

    def stick_half_width(self, state=None) -> float:
        """Outer edge of the outermost sticking element (resolution: one element)."""
        st = state or self.state
        idx = np.flatnonzero(st.stick)
        return float(self.edges[idx.max() + 1]) if len(idx) else 0.0


__all__ = ["stick_traction_inversion", "tangential_force_inversion", "slip_flamant", "displacement_flamant",
           "friction_work", "stick_traction_enclosure", "tangential_force_enclosure", "friction_work_enclosure",
           "element_pressures", "solve_dense", "CoulombBEM", "BEMState"]
