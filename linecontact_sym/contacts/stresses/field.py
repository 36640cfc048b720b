"""The numeric subsurface stress field: vectorised float64 potentials and the
equivalent stresses.

The stresses follow from the complex potentials G, G' (pressure) and H, H'
(tangential traction) by :func:`.kolosov.kolosov_stresses`.  A potential is
either a closed form (lambdified once, complex NumPy: :class:`ClosedPotential`)
or a quadrature evaluated for a whole array of points at once:

:class:`PunchPotential`
    Popov's superposition of flat punches, G(zeta) = int_0^a D(t)
    (zeta^2 - t^2)^(-1/2) dt and G' = -zeta int_0^a D(t) (zeta^2 - t^2)^(-3/2) dt
    for a punch density D = P'(t) (see :mod:`.kolosov`); needs only the
    derivative of the force law as a float64 function.
:class:`CauchyPotential`
    the Cauchy transform of any traction given as a float64 function q(s),
    H(zeta) = int_{-a}^{a} q(s)/(zeta - s) ds, H' = -int q(s)/(zeta - s)^2 ds.

Near the surface the kernels peak over a width z around the point; the
substitution t = c + z sinh(u), anchored at the nearest point c of the
segment, spreads the peak (it becomes analytic in a strip of half-width pi/2
in u), and nested tanh-sinh levels in u (h = 1/4 ... 1/64, nodes out to
t = 4, on each piece between the ends, the anchor and the breakpoints of
the traction) handle the integrable end singularities of the density
(t^(n-1) at 0, (t - b)^(-1/2) at a kink).  A point is accepted when two
levels agree to :data:`LEVEL_ACCEPT`.  The distance t - end is formed from
the node position, not by subtracting two large numbers, and a density
singular at a breakpoint can be given there as a function of that distance
(``near``).  The surface (z = 0) is the limit z -> 0+: depths below
:data:`SURFACE_DEPTH` times a are evaluated at that depth.
"""
from __future__ import annotations

import numpy as np

from ...core.errors import DomainError
from ...core.quadrature import tanh_sinh_levels
from .kolosov import kolosov_stresses

#: two successive tanh-sinh levels agreeing to this (relative to the integral of the absolute
#: integrand) accept the finer one, whose error is then about its square (the error of
#: tanh-sinh roughly squares from one level to the next): ~1e-14 against mpmath in the tests
LEVEL_ACCEPT = 1e-8
#: relative depth z/a at which the surface limit z -> 0+ is evaluated
SURFACE_DEPTH = 1e-12
_CHUNK = 2048


def _ts_levels(hs=(4, 8, 16, 32, 64), tmax=4.0):
    """The package's nested tanh-sinh node sets on (0, 1)
    (:func:`~linecontact_sym.core.quadrature.tanh_sinh_levels`), per level
    with the number of nodes below 1/2 and the weights arranged for
    interleaved real/imaginary parts (a (2n, 2) matrix)."""
    out = []
    for h, v, w, phi in tanh_sinh_levels(hs, tmax):
        W = np.zeros((2 * v.size, 2))
        W[0::2, 0], W[1::2, 1] = phi, phi
        out.append((h, v, w, phi, int(np.count_nonzero(v < 0.5)), W))
    return out


_LEVELS = _ts_levels()


def _pieces(edges, c):
    """Per point the pieces [lo, hi] between fixed ``edges`` split at the
    anchor ``c`` (arrays), with the index of the fixed edge each end sits on
    (-1: the end is the anchor); a piece of zero length contributes nothing."""
    out = []
    for i, (e0, e1) in enumerate(zip(edges[:-1], edges[1:])):
        m = np.clip(c, e0, e1)
        fixed_lo, fixed_hi = np.full(c.shape, i), np.full(c.shape, i + 1)
        out.append((np.full_like(c, e0), m, fixed_lo, np.where(m == e1, i + 1, -1)))
        out.append((m, np.full_like(c, e1), np.where(m == e0, i, -1), fixed_hi))
    return out


class _Quadrature:
    """Nested tanh-sinh over u of the sinh-mapped pieces, for arrays of
    points.  Subclasses define ``edges``, ``anchor(x)`` (the point of the
    segment nearest to the kernel's peak), ``offset(x)`` (the abscissa the
    anchor is measured from: d = offset - t is formed as (offset - c) -
    z sinh(u)) and ``integrands(x, z, t, d)``: the potential's integrand f
    and the ratio df/f of the derivative's."""

    def __call__(self, x, z):
        x, z = np.broadcast_arrays(np.asarray(x, float), np.asarray(z, float))
        shape = x.shape
        xf, zf = self._fold(x.ravel()), np.maximum(z.ravel(), SURFACE_DEPTH * self.a)
        F = np.zeros(xf.size, complex)
        dF = np.zeros(xf.size, complex)
        with np.errstate(all="ignore"):
            for start in range(0, xf.size, _CHUNK):
                sl = slice(start, start + _CHUNK)
                F[sl], dF[sl] = self._chunk(xf[sl], zf[sl])
        return self._unfold(x.ravel(), F, dF, shape)

    def _fold(self, x):
        return x

    def _unfold(self, x, F, dF, shape):
        return F.reshape(shape), dF.reshape(shape)

    def _chunk(self, x, z):
        c = self.anchor(x)
        F = np.zeros(x.size, complex)
        dF = np.zeros(x.size, complex)
        for lo, hi, elo, ehi in _pieces(self.edges, c):
            idx = np.flatnonzero(hi > lo)
            if idx.size:
                f, df = self._piece(x[idx], z[idx], c[idx], lo[idx], hi[idx], elo[idx], ehi[idx])
                F[idx] += f
                dF[idx] += df
        return F, dF

    def values(self, t, dlo, dhi, elo, ehi, half):
        """The traction (or density) at the nodes t; ``dlo`` = t - lo on the
        first ``half`` columns, ``dhi`` = hi - t on the others, ``elo``/``ehi``
        the fixed edges at the ends (-1: none): a subclass may evaluate there
        from the offsets."""
        return self.fn(t)

    def _piece(self, x, z, c, lo, hi, elo, ehi):
        ul, uh = np.arcsinh((lo - c) / z), np.arcsinh((hi - c) / z)
        L = uh - ul
        off = self.offset(x) - c

        def level(lev, rows):
            h, v, w, phi, half, W = _LEVELS[lev]
            zz, LL, u0, u1 = z[rows, None], L[rows, None], ul[rows, None], uh[rows, None]
            dlo, dhi = LL * v[:half], LL * w[half:]
            u = np.concatenate([u0 + dlo, u1 - dhi], axis=1)
            eu = np.exp(u)
            emu = 1 / eu
            # t = c + z sinh(u) from the nearer end: sinh(u) - sinh(u0) = expm1(u - u0) (e^u0 + e^-u)/2,
            # so t - lo and hi - t keep their relative precision
            t = np.empty_like(u)
            d_lo = zz * np.expm1(dlo) * (np.exp(u0) + emu[:, :half]) / 2
            d_hi = zz * np.expm1(dhi) * (eu[:, half:] + np.exp(-u1)) / 2
            t[:, :half] = lo[rows, None] + d_lo
            t[:, half:] = hi[rows, None] - d_hi
            d = off[rows, None] - zz * ((eu - emu) / 2)
            Dv = self.scale * self.values(t, d_lo, d_hi, elo[rows], ehi[rows], half)
            f, ratio = self.integrands(x[rows, None], zz, t, d, Dv)
            f = f * (LL * zz * ((eu + emu) / 2))
            df = f * ratio
            sums = _sums(f, W, h), _sums(df, W, h)
            if not (np.all(np.isfinite(sums[0][0])) and np.all(np.isfinite(sums[1][0]))):
                bad = ~(np.isfinite(f) & np.isfinite(df))
                f, df = np.where(bad, 0, f), np.where(bad, 0, df)
                sums = _sums(f, W, h), _sums(df, W, h)
            (F, absF), (dF, absdF) = sums
            return F, dF, absF + z[rows] * absdF, z[rows]

        rows = np.arange(x.size)
        F, dF, A, _ = level(0, rows)
        for lev in range(1, len(_LEVELS)):
            f1, df1, a1, zr = level(lev, rows)
            newF, newdF = F[rows] / 2 + f1, dF[rows] / 2 + df1
            err = np.abs(newF - F[rows]) + zr * np.abs(newdF - dF[rows])
            F[rows], dF[rows] = newF, newdF
            A[rows] = A[rows] / 2 + a1
            rows = rows[~(err <= LEVEL_ACCEPT * A[rows])]
            if rows.size == 0:
                break
        return F, dF


def _sums(f, W, h):
    """h * sum_nodes weight * f (complex, per row) and h * sum weight (|Re f| + |Im f|),
    by one real matrix product over the interleaved real and imaginary parts."""
    fv = np.ascontiguousarray(f).view(np.float64)
    s = fv @ W
    a = np.abs(fv) @ W
    return h * (s[:, 0] + 1j * s[:, 1]), h * (a[:, 0] + a[:, 1])


class PunchPotential(_Quadrature):
    """G(zeta) = int_0^a D(t)/sqrt(zeta^2 - t^2) dt and G'(zeta) for a punch
    density ``density`` (float64 function of t, e.g. P'(t)) on (0, a), with
    the density's breakpoints ``breaks``.  Evaluated at |x| (the branch
    sqrt(zeta - t) sqrt(zeta + t) there) and mirrored: the traction is even,
    so G(-conj(zeta)) = -conj(G(zeta)) and G'(-conj(zeta)) = conj(G'(zeta)).

    Hertz (p0 = a = 1, P'(t) = pi t): G = pi (zeta - sqrt(zeta^2 - 1)), at zeta = i
    pi i (1 - sqrt(2)):

    >>> G, dG = PunchPotential(lambda t: np.pi * t, 1.0)(0.0, 1.0)
    >>> bool(abs(G - np.pi * 1j * (1 - np.sqrt(2))) < 1e-15)
    True
    """

    def __init__(self, density, a, breaks=(), scale=1.0, near=None):
        self.fn, self.a, self.scale = density, float(a), scale
        inner = sorted(float(b) for b in breaks if 0 < float(b) < self.a)
        self.edges = [0.0] + inner + [self.a]
        # near[edge] = (D(edge + d), D(edge - d)) as functions of the offset d: the density
        # at nodes close to a breakpoint where it is singular, without forming t - edge
        self.near = {i: near[e_] for i, e in enumerate(self.edges) for e_ in (near or {}) if e == e_}

    def values(self, t, dlo, dhi, elo, ehi, half):
        D = self.fn(t)
        for i, (right, left) in self.near.items():
            rows = np.flatnonzero(elo == i)
            if rows.size and right is not None:
                D[rows, :half] = right(dlo[rows])
            rows = np.flatnonzero(ehi == i)
            if rows.size and left is not None:
                D[rows, half:] = left(dhi[rows])
        return D

    def _fold(self, x):
        return np.abs(x)

    def _unfold(self, x, F, dF, shape):
        neg = x < 0
        F = np.where(neg, -np.conj(F), F)
        dF = np.where(neg, np.conj(dF), dF)
        return F.reshape(shape), dF.reshape(shape)

    def anchor(self, x):
        return np.minimum(x, self.a)

    def offset(self, x):
        return x

    def integrands(self, x, z, t, d, D):
        # zeta^2 - t^2 = (zeta - t)(zeta + t) = d (x + t) - z^2 + 2i x z  (d = x - t formed without
        # cancellation; Im = 2xz >= 0 exactly, so the principal root is sqrt(zeta - t) sqrt(zeta + t))
        K2 = (d * (x + t) - z * z) + 2j * (x * z)
        inv = np.conj(K2) / (K2.real**2 + K2.imag**2)
        f = D * (np.sqrt(K2) * inv)
        return f, -(x + 1j * z) * inv


class CauchyPotential(_Quadrature):
    """H(zeta) = int_{-a}^{a} q(s)/(zeta - s) ds and H'(zeta) of a traction
    ``traction`` (float64 function of s on [-a, a], any symmetry), split at
    ``breaks``."""

    def __init__(self, traction, a, breaks=(), scale=1.0):
        self.fn, self.a, self.scale = traction, float(a), scale
        inner = sorted(float(b) for b in breaks if -self.a < float(b) < self.a)
        self.edges = [-self.a] + inner + [self.a]

    def anchor(self, x):
        return np.clip(x, -self.a, self.a)

    def offset(self, x):
        return x

    def integrands(self, x, z, t, d, q):
        k = 1 / (d + 1j * z)                       # 1/(zeta - s), d = x - s
        return q * k, -k


class ClosedPotential:
    """A closed-form potential F(zeta) and F'(zeta) as complex NumPy functions
    (``fn(zeta)`` each, parameters already bound)."""

    def __init__(self, F, dF, a):
        self.F, self.dF, self.a = F, dF, float(a)

    def __call__(self, x, z):
        zeta = np.asarray(x, float) + 1j * np.maximum(np.asarray(z, float), SURFACE_DEPTH * self.a)
        with np.errstate(all="ignore"):
            return self.F(zeta), self.dF(zeta)


# ------------------------------------------------------------------ equivalents
def principal_shear(sx, sz, txz):
    """tau_1 = sqrt(((sigma_x - sigma_z)/2)^2 + tau_xz^2), the in-plane principal shear."""
    return np.hypot((sx - sz) / 2, txz)


def principal_stresses(sx, sz, txz):
    """The in-plane principal stresses (sigma_1 >= sigma_2)."""
    m, r = (sx + sz) / 2, principal_shear(sx, sz, txz)
    return m + r, m - r


def von_mises(sx, sy, sz, txz):
    """sqrt(((s_x - s_y)^2 + (s_y - s_z)^2 + (s_z - s_x)^2)/2 + 3 tau_xz^2)."""
    return np.sqrt(((sx - sy)**2 + (sy - sz)**2 + (sz - sx)**2) / 2 + 3 * txz**2)


def tresca(sx, sy, sz, txz):
    """The largest difference of the three principal stresses (sigma_y is
    one of them in plane strain): 2 x the largest shear stress."""
    s1, s2 = principal_stresses(sx, sz, txz)
    return np.maximum.reduce([s1 - s2, np.abs(s1 - sy), np.abs(s2 - sy)])


#: the equivalent stresses, by name
CRITERIA = {"principal_shear": "tau_1", "von_mises": "sigma_vM", "tresca": "sigma_T"}


class Scaled:
    """A potential times a constant: ``Scaled(potential, w)(x, z) = (w F, w F')``."""

    def __init__(self, potential, weight):
        self.potential, self.weight, self.a = potential, float(weight), potential.a

    def __call__(self, x, z):
        Fv, dFv = self.potential(x, z)
        return self.weight * Fv, self.weight * dFv


class FieldEvaluator:
    """sigma_x, sigma_z, tau_xz, sigma_y and the equivalent stresses of a
    normal potential G and a tangential one H = friction * G + tangential
    (each potential a callable (x, z) -> (F, F'); ``tangential`` may be
    None) at arrays of points; ``nu`` Poisson's ratio (plane strain);
    ``mean_pressure`` P/(2a), a scale for plots."""

    def __init__(self, normal, tangential=None, nu=0.3, friction=0.0, mean_pressure=1.0):
        self.normal, self.tangential, self.nu = normal, tangential, float(nu)
        self.mu, self.mean_pressure = float(friction), float(mean_pressure)
        self.a = normal.a

    def components(self, x, z):
        """sigma_x, sigma_z, tau_xz, sigma_y at the points (x, z), z >= 0."""
        x, z = np.asarray(x, float), np.asarray(z, float)
        if x.shape != z.shape:
            x, z = np.broadcast_arrays(x, z)
        if (z < 0).any():
            raise DomainError("the depth z must be >= 0 (z > 0 into the body)")
        G, dG = self.normal(x, z)
        H, dH = self.mu * G, self.mu * dG
        if self.tangential is not None:
            Ht, dHt = self.tangential(x, z)
            H, dH = H + Ht, dH + dHt
        zz = np.maximum(z, SURFACE_DEPTH * self.normal.a)
        sx, sz, txz = kolosov_stresses(G, dG, H, dH, zz, np.real, np.imag, np.pi)
        # float arrays of the points' shape (a constant term broadcast); results already so are kept
        sx, sz, txz = (v if type(v) is np.ndarray and v.shape == x.shape and v.dtype == np.float64
                       else np.broadcast_to(v, x.shape).astype(float) for v in (sx, sz, txz))
        return {"sigma_x": sx, "sigma_z": sz, "tau_xz": txz, "sigma_y": self.nu * (sx + sz)}

    #: the equivalent stresses from the components (one place for __call__)
    _EQUIVALENTS = {"principal_shear": lambda c: principal_shear(c["sigma_x"], c["sigma_z"], c["tau_xz"]),
                    "von_mises": lambda c: von_mises(c["sigma_x"], c["sigma_y"], c["sigma_z"], c["tau_xz"]),
                    "tresca": lambda c: tresca(c["sigma_x"], c["sigma_y"], c["sigma_z"], c["tau_xz"])}

    def __call__(self, x, z, quantity="all"):
        if quantity != "all" and quantity not in self._EQUIVALENTS and quantity not in self._COMPONENTS:
            raise DomainError(f"unknown stress quantity {quantity!r}; one of "
                              f"{', '.join(self._COMPONENTS + tuple(self._EQUIVALENTS))}")
        c = self.components(x, z)
        if quantity == "all":
            for k, fn in self._EQUIVALENTS.items():
                c[k] = fn(c)
            return c
        if quantity in self._EQUIVALENTS:        # only the one asked for (a search calls this per point)
            return self._EQUIVALENTS[quantity](c)
        return c[quantity]

    _COMPONENTS = ("sigma_x", "sigma_z", "tau_xz", "sigma_y")


__all__ = ["PunchPotential", "CauchyPotential", "ClosedPotential", "Scaled", "FieldEvaluator", "principal_shear",
           "principal_stresses", "von_mises", "tresca", "CRITERIA", "LEVEL_ACCEPT", "SURFACE_DEPTH"]
