"""The numbers of the bounded solution of a profile on a non-centred interval
[e - a, e + a] that the rolling layer and the sign check of asymmetric states need beyond
the asymmetric core
(:mod:`linecontact_sym.contacts.asymmetric`, whose ``force()`` and
``tilt()`` give P(e, a) and theta(e, a) symbolically, and whose
``numbers()`` give them at the working precision: :class:`SlopeNumbers`
takes them from there where the core's force laws close).  What the core
lacks stays here: the pressure in a stable closed form for polynomial
slopes (sqrt times a polynomial), float64 numbers at many points (P, theta,
J, the pressure: the traction, the admissibility grid, the creepage curve),
the defining phi-integrals by mpmath quadrature (profiles the core refuses,
more than one kink, or leaves as Integrals; the rolling derivations'
independent verification reference), and the function J that carries the
admissibility.

For a profile f on the whole line, tilt theta (gap f(x) - theta x - d) and
contact [e - a, e + a], with x = e + a sin(phi):

    theta(e, a) = (1/pi) int_{-pi/2}^{pi/2} f'(e + a sin phi) dphi                 (consistency)
    P(e, a)     = (E* a/2) int_{-pi/2}^{pi/2} f'(e + a sin phi) sin phi dphi        (load)
    p(x; e, a)  = (E*/2) sqrt(a^2 - (x - e)^2) J(x; e, a),
    g'(x)       = sign(x - e) sqrt((x - e)^2 - a^2) J(x; e, a)   outside (the gap's slope),
    J(x; e, a)  = (1/pi) int_{-pi/2}^{pi/2} [f'(t) - f'(x)]/(t - x) dphi,   t = e + a sin phi

(the T_0 and T_1 Chebyshev coefficients of f'(e + a s), and the bounded
inversion of (2/(pi E*)) PV int p(t)/(x - t) dt = f'(x) - theta).  For a
polynomial slope J is a polynomial (the phi-moments of sin^k), so the
pressure has no removable 1/sqrt terms (float64 stable up to the edges).
"""
from __future__ import annotations

import mpmath
import numpy as np
import sympy as sp

from ...core import symbols as S
from ...core.errors import ProfileError
from .split import whole_line

#: the centre of an interval and the real coordinate on the whole line (the asymmetric core's)
E_C = S.e
X = S.x_real
_phi = sp.Dummy("phi", real=True)

#: Gauss-Legendre nodes per piece of [-pi/2, pi/2] for the float64 numbers
GL_NODES = 64


def whole_line_profile(contact):
    """f(x) on the whole line (in :data:`X`) for a symmetric contact of the
    package: the asymmetric core's :func:`~linecontact_sym.contacts.asymmetric.split.whole_line`
    (f itself where it is even in x, else f(|x|))."""
    return whole_line(contact.profile.expr)


def whole_line_slope(contact):
    """f'(x) on the whole line: the derivative of :func:`whole_line_profile`
    (sign(x) f'(|x|) for a mirrored profile)."""
    return sp.diff(whole_line_profile(contact), X)


def whole_line_breaks(contact):
    """The kinks of the whole-line slope: +-(the profile's breakpoints), and 0
    where f'(0+) is not 0 (a wedge)."""
    out = []
    for bp in contact.profile.breakpoints:
        out += [bp, -bp]
    if contact.profile.slope_at_origin != 0:
        out.append(sp.S.Zero)
    return out


def _sin_moments(expr):
    """int_{-pi/2}^{pi/2} expr dphi for a polynomial in sin(phi) (the
    polynomial slopes), term by term: the moments of sin^k are 0 for odd k and
    pi (k - 1)!!/k!! for even k.  None for anything else."""
    u = sp.Dummy("u")
    g = sp.expand(expr).xreplace({sp.sin(_phi): u})
    if g.has(_phi) or not g.is_polynomial(u):
        return None
    out = sp.S.Zero
    for (kk,), coeff in sp.Poly(g, u).terms():
        if kk % 2 == 0:
            out += coeff * sp.pi * sp.factorial2(kk - 1) / sp.factorial2(kk)
    return sp.factor(out)


class Interval:
    """The stick zone's bounded pressure p(x; e, a) in closed form where the
    slope is a polynomial (in :data:`X`, with :data:`E_C`); ``pressure()``
    None otherwise."""

    def __init__(self, slope):
        self.slope = slope
        self._cache = {}

    def integral(self, what):
        """The defining phi-integral of P(e, a) (``what='force'``) or of
        theta(e, a), unevaluated (where the asymmetric core does not take the profile)."""
        g = self.slope.xreplace({X: E_C + S.a * sp.sin(_phi)})
        if what == "force":
            return S.E_star * S.a / 2 * sp.Integral(g * sp.sin(_phi), (_phi, -sp.pi / 2, sp.pi / 2))
        return sp.Integral(g, (_phi, -sp.pi / 2, sp.pi / 2)) / sp.pi

    def pressure(self):
        """p(x; e, a) for |x - e| < a, in :data:`X` (None where J has no closed form)."""
        if "p" not in self._cache:
            t = sp.Dummy("t", real=True)
            dd = sp.cancel((self.slope.xreplace({X: t}) - self.slope) / (t - X))
            out = None
            if dd.is_polynomial(t, X):
                Jc = _sin_moments(dd.xreplace({t: E_C + S.a * sp.sin(_phi)}))
                if Jc is not None:
                    out = S.E_star / 2 * sp.sqrt(S.a**2 - (X - E_C)**2) * sp.factor(Jc / sp.pi)
            self._cache["p"] = out
        return self._cache["p"]


class SlopeNumbers:
    """The numbers of the bounded interval solution for a whole-line slope at
    fixed parameter values.

    * ``P(e, a)``, ``tilt(e, a)`` (mpmath, the working precision): the
      asymmetric core's numbers (``core``, an
      :class:`~linecontact_sym.contacts.asymmetric.core.OffsetNumbers`: the
      engine's closed force laws of the even part and the odd-part integral)
      where the core takes the profile and closes them, else the defining
      phi-integrals by quadrature (``P_quad``, ``tilt_quad``).
    * ``P_quad``, ``tilt_quad``: those phi-integrals by mpmath quadrature,
      split at the slope's kinks: the route for a profile the core refuses
      (more than one kink: the rounded punch, the worn cylinder) or leaves as
      Integrals (there the core's numbers build the engine's quadrature force
      law at every centre e, measured 5-15x slower per (e, a) than this), and
      the independent reference the rolling derivations are verified against.
    * float64 (``P_float``, ``tilt_float``, ``J``, ``pressure``): Gauss-Legendre
      in phi split at the kinks, at many points (the traction, the
      admissibility grid, the creepage-force curve, the cross-check of a closed
      state); the core has no float64 route."""

    def __init__(self, slope, values: dict, E_star, breaks=(), core=None):
        s = slope.xreplace(values)
        if s.free_symbols - {X}:
            raise ProfileError(f"values needed for {sorted(map(str, s.free_symbols - {X}))}")
        self.mp = sp.lambdify(X, s, "mpmath")
        self.np = sp.lambdify(X, s, "numpy")
        self.E = E_star
        self.Ef = float(E_star)
        self.breaks = sorted(float(b) for b in breaks)
        self.mp_breaks = [mpmath.mpf(sp.N(b, 40)) for b in breaks]
        #: the asymmetric core's numbers (None: the quadrature)
        self.core = core

    def _cuts(self, e, a, brs):
        """phi where e + a sin(phi) crosses a kink, inside (-pi/2, pi/2)."""
        out = []
        for b in brs:
            u = (b - e) / a
            if -1 < u < 1:
                out.append(mpmath.asin(u) if isinstance(u, mpmath.mpf) else np.arcsin(u))
        return sorted(out)

    def _quad(self, fn, e, a):
        e, a = mpmath.mpf(e), mpmath.mpf(a)
        pts = [-mpmath.pi / 2] + self._cuts(e, a, self.mp_breaks) + [mpmath.pi / 2]
        return mpmath.quad(fn, pts)

    def tilt_quad(self, e, a):
        """theta(e, a) by quadrature of its phi-integral (mpmath)."""
        e, a = mpmath.mpf(e), mpmath.mpf(a)
        return self._quad(lambda p: mpmath.re(self.mp(e + a * mpmath.sin(p))), e, a) / mpmath.pi

    def P_quad(self, e, a):
        """P(e, a) by quadrature of its phi-integral (mpmath)."""
        e, a = mpmath.mpf(e), mpmath.mpf(a)
        return mpmath.mpf(self.E) * a / 2 * self._quad(
            lambda p: mpmath.re(self.mp(e + a * mpmath.sin(p))) * mpmath.sin(p), e, a)

    def tilt(self, e, a):
        """theta(e, a) (mpmath): the core's where given, else :meth:`tilt_quad`."""
        return self.core.tilt(e, a) if self.core is not None else self.tilt_quad(e, a)

    def P(self, e, a):
        """P(e, a) (mpmath): the core's where given, else :meth:`P_quad`."""
        return self.core.P(e, a) if self.core is not None else self.P_quad(e, a)

    # ------------------------------------------------------------ float64
    def _nodes(self, e, a):
        g, w = np.polynomial.legendre.leggauss(GL_NODES)
        cuts = [-np.pi / 2] + self._cuts(float(e), float(a), self.breaks) + [np.pi / 2]
        phis, ws = [], []
        for lo, hi in zip(cuts[:-1], cuts[1:]):
            phis.append(0.5 * (lo + hi) + 0.5 * (hi - lo) * g)
            ws.append(0.5 * (hi - lo) * w)
        return np.concatenate(phis), np.concatenate(ws)

    def P_float(self, e, a):
        """P(e, a) in float64 (Gauss-Legendre, split at the kinks)."""
        if a <= 0:
            return 0.0
        phi, w = self._nodes(e, a)
        ft = np.broadcast_to(np.asarray(self.np(float(e) + float(a) * np.sin(phi)), float), phi.shape)
        return 0.5 * self.Ef * float(a) * float(ft * np.sin(phi) @ w)

    def tilt_float(self, e, a):
        """theta(e, a) in float64 (Gauss-Legendre, split at the kinks)."""
        if a <= 0:
            return float(np.asarray(self.np(float(e)), float))
        phi, w = self._nodes(e, a)
        ft = np.broadcast_to(np.asarray(self.np(float(e) + float(a) * np.sin(phi)), float), phi.shape)
        return float(ft @ w) / np.pi

    def J(self, x, e, a, chunk=20000):
        """J(x; e, a) at float64 points (any shape).  Accuracy: machine
        precision for smooth slopes; within |x -+ b| << a of a kink b of the
        slope the divided difference has a layer of that width beside b and
        the rule loses digits (measured: 1.5e-5 relative in p at |x - b| = 1e-4 a
        for the rounded punch), as the admissibility check's grid tolerates."""
        x = np.asarray(x, float)
        phi, w = self._nodes(e, a)
        t = float(e) + float(a) * np.sin(phi)
        ft = np.broadcast_to(np.asarray(self.np(t), float), t.shape)
        flat = x.ravel()
        out = np.empty(flat.shape)
        for i in range(0, flat.size, chunk):
            xs = flat[i:i + chunk, None]
            fx = np.broadcast_to(np.asarray(self.np(xs), float), xs.shape)
            d = t[None, :] - xs
            with np.errstate(divide="ignore", invalid="ignore"):
                dd = (ft[None, :] - fx) / d
            # a node within rounding of x: the divided difference is the local slope of f'
            bad = np.abs(d) < 1e-7 * max(float(a), 1e-300)
            if bad.any():
                h = 1e-6 * float(a)
                fp = (np.asarray(self.np(xs + h), float) - np.asarray(self.np(xs - h), float)) / (2 * h)
                dd = np.where(bad, np.broadcast_to(fp, dd.shape), dd)
            out[i:i + chunk] = dd @ w / np.pi
        return out.reshape(x.shape)

    def pressure(self, x, e, a):
        """p(x; e, a), zero outside (float64)."""
        x = np.asarray(x, float)
        r2 = float(a)**2 - (x - float(e))**2
        return np.where(r2 > 0, 0.5 * self.Ef * np.sqrt(np.clip(r2, 0, None)) * self.J(x, e, a), 0.0)


__all__ = ["Interval", "SlopeNumbers", "whole_line_profile", "whole_line_slope", "whole_line_breaks", "E_C", "X", "GL_NODES"]
