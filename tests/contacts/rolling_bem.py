"""An independent reference for steady rolling with traction (tests only):
a boundary-element solution of 2-D steady rolling of elastically similar
bodies, and a Gauss-Chebyshev solution of the normal problem.  Nothing here
imports the package: it shares no formula, grid or code with the reduction
to tilted bounded pressures that the package uses.

Conventions (the same as the package's rolling layer)
-----------------------------------------------------
* The contact moves in +x over both bodies (rolling in +x): in the frame of
  the contact the material of both surfaces flows in -x with speed V, enters
  at the *leading edge* (the right end) and leaves at the trailing edge.
* q(x): the shear traction on body 1 (from body 2), Q = int q dx.
* u(x) = u_1x - u_2x: the relative tangential elastic surface displacement.
  Similar materials (half-plane, plane strain): a traction q on body 1 and
  -q on body 2 give

      u'(x) = -(2/(pi E*)) PV int q(t)/(x - t) dt           (Flamant, Johnson Eq. 2.24)

* The creepage xi: the rigid creep velocity of body 2 relative to body 1
  divided by V.  A material point of body 1 slips relative to body 2 with the
  velocity  s' = -V (xi + u'(x))  (steady state, transport by -V), so

      stick:  xi + u'(x) = 0,             |q| <= mu p,
      slip:   q = mu p sign(xi + u'(x))    (q opposes the slip velocity s').

  With this sign Q and xi have the same sign (Carter: xi = mu (a - a')/R > 0
  for Q > 0); Kalker's creepage (body 1 relative to body 2) is -xi.

The discretisation: N cells, piecewise-constant tractions, collocation at
the cell midpoints; a cell [t0, t1] carrying a unit traction contributes
PV int_{t0}^{t1} dt/(x - t) = ln|(x - t0)/(x - t1)| to the Hilbert transform.
The unknowns are the cell tractions and xi (the tangential force Q is
prescribed).  Active set over stick and slip cells, starting from full stick
(no assumption about where the stick zone lies): a stick cell with |q| > mu p
slips in the direction of its traction; a slip cell whose xi + u' has the
wrong sign for its traction sticks again.

Accuracy (Carter, CONTACT's carter2d, measured): see :func:`carter2d_table`.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.polynomial import chebyshev as C
from scipy.optimize import brentq


# =====================================================================  normal problem
def normal_chebyshev(slope, left, right, E_star, degree=64):
    """The bounded pressure of a contact on [left, right] with the profile slope
    f'(x) (the contact interval is given; the bounded solution exists when the
    consistency condition holds, e.g. a symmetric profile on a centred interval).

    f'(m + h s) = sum_n c_n T_n(s) (Chebyshev interpolation), and since
    (1/pi) PV int sqrt(1 - t^2) U_{n-1}(t)/(s - t) dt = T_n(s),

        p(m + h s) = (E*/2) sqrt(1 - s^2) sum_{n>=1} c_n U_{n-1}(s),   P = pi h E* c_1/4.

    Returns (p, P, c0): p a numpy callable of x (0 outside), c0 the T_0
    coefficient (the consistency residual: 0 for a bounded solution)."""
    m, h = 0.5 * (left + right), 0.5 * (right - left)
    c = C.chebinterpolate(lambda s: slope(m + h * s), degree)
    u = c[1:]                                   # coefficients of U_0, U_1, ...

    def p(x):
        s = (np.asarray(x, float) - m) / h
        inside = np.abs(s) < 1
        sv = np.where(inside, s, 0.0)
        val = 0.5 * E_star * np.sqrt(1 - sv**2) * _chebu(u, sv)
        return np.where(inside, val, 0.0)
    return p, np.pi * h * E_star * c[1] / 4, c[0]


def _chebu(coef, s):
    """sum_k coef[k] U_k(s) (Clenshaw)."""
    b1 = np.zeros_like(s)
    b2 = np.zeros_like(s)
    for ck in coef[::-1]:
        b1, b2 = ck + 2 * s * b1 - b2, b1
    return b1


def symmetric_half_width(slope, P, E_star, a_hi, degree=64):
    """The half-width a of a symmetric profile under the load P: P(a) = P by
    Brent's method on (0, a_hi] with the Chebyshev load of :func:`normal_chebyshev`."""
    return brentq(lambda a: normal_chebyshev(slope, -a, a, E_star, degree)[1] - P, 1e-9 * a_hi, a_hi,
                  xtol=1e-15 * a_hi, rtol=4e-16)


# =====================================================================  rolling BEM
@dataclass
class RollingSolution:
    edges: np.ndarray      # cell edges
    x: np.ndarray          # midpoints
    p: np.ndarray          # cell-mean pressures
    q: np.ndarray          # cell tractions
    stick: np.ndarray      # bool per cell
    xi: float              # creepage (convention in the module docstring)
    Q: float
    mu: float
    iterations: int

    def stick_zones(self):
        """The stick zones as (start, end) intervals of cell edges."""
        zones, i, n = [], 0, len(self.stick)
        while i < n:
            if self.stick[i]:
                j = i
                while j + 1 < n and self.stick[j + 1]:
                    j += 1
                zones.append((self.edges[i], self.edges[j + 1]))
                i = j + 1
            else:
                i += 1
        return zones

    def stick_start(self):
        """The start s of the stick zone, refined below the cell size: the point
        where mu p - q (the corrective traction, zero in the slip zone, growing
        like sqrt(x - s) into the stick zone) extrapolates to zero; from its
        squares at the first two stick cells."""
        i = int(np.flatnonzero(self.stick)[0])
        d = self.mu * self.p[i:i + 2] - self.q[i:i + 2]
        y = d**2
        x0, x1 = self.x[i], self.x[i + 1]
        return x0 - y[0] * (x1 - x0) / (y[1] - y[0])


def _log_influence(edges, x):
    """L[i, j] = int over cell j of ln|x_i - t| dt = F(x_i - t0) - F(x_i - t1),
    F(y) = y ln|y| - y (F(0) = 0)."""
    def F(y):
        ay = np.abs(y)
        return np.where(ay > 0, y * np.log(np.where(ay > 0, ay, 1.0)) - y, 0.0)
    X = x[:, None]
    return F(X - edges[None, :-1]) - F(X - edges[None, 1:])


def cell_means(p, edges, order=8):
    """Cell averages of a callable by Gauss-Legendre on each cell."""
    g, w = np.polynomial.legendre.leggauss(order)
    t0, t1 = edges[:-1, None], edges[1:, None]
    pts = 0.5 * (t0 + t1) + 0.5 * (t1 - t0) * g[None, :]
    return (p(pts) * w[None, :]).sum(axis=1) / 2


def solve_rolling(p, left, right, E_star, mu, Q, n=400, mesh="uniform", maxit=400):
    """Steady rolling in +x at the tangential force Q (0 <= |Q| < mu P) with
    the pressure ``p`` (a numpy callable, zero outside [left, right]) on
    ``n`` cells over the contact [left, right] (``mesh``: 'uniform' or
    'cosine', refined at both ends).  Returns a :class:`RollingSolution`.

    The slip velocity of cell i is the upwind difference of the transport
    (the material comes from cell i + 1, one cell downstream of the flow's
    source): w_i = xi + (u_{i+1} - u_i)/(x_{i+1} - x_i), u_i = u(x_i) from
    the log kernel (exact cell integrals), x_n = right + h_{n-1}/2 just ahead
    of the contact.  This is the steady state of Kalker's time stepping with
    one cell per step (CONTACT's scheme); it makes the linear system of a
    stick set square, where the midpoint-collocated Hilbert kernel is
    singular (the stick zone's general solution has a free 1/sqrt term)."""
    if mesh == "uniform":
        edges = np.linspace(left, right, n + 1)
    else:
        edges = 0.5 * (left + right) - 0.5 * (right - left) * np.cos(np.linspace(0, np.pi, n + 1))
    h = np.diff(edges)
    x = 0.5 * (edges[:-1] + edges[1:])
    xe = np.append(x, right + 0.5 * h[-1])                   # the points u is taken at
    pc = cell_means(p, edges)
    lim = mu * pc
    U = -2.0 / (np.pi * E_star) * _log_influence(edges, xe)  # u(xe_k) = sum_j U_kj q_j
    D = (U[1:] - U[:-1]) / np.diff(xe)[:, None]              # upwind u' at cell i
    stick = np.ones(n, bool)
    sign = np.zeros(n)
    for it in range(1, maxit + 1):
        S, L = np.flatnonzero(stick), np.flatnonzero(~stick)
        q = np.zeros(n)
        q[L] = sign[L] * lim[L]
        m = len(S)
        # unknowns q_S and xi: xi + D_SS q_S = -D_SL q_L ;  h_S . q_S = Q - h_L . q_L
        A = np.zeros((m + 1, m + 1))
        r = np.zeros(m + 1)
        A[:m, :m] = D[np.ix_(S, S)]
        A[:m, m] = 1.0
        r[:m] = -D[np.ix_(S, L)] @ q[L]
        A[m, :m] = h[S]
        r[m] = Q - h[L] @ q[L]
        sol = np.linalg.solve(A, r)
        q[S], xi = sol[:m], sol[m]
        w = xi + D @ q                                          # xi + u'(x): 0 in the stick cells
        over = S[np.abs(q[S]) > lim[S]]
        back = L[sign[L] * w[L] < 0]
        if not len(over) and not len(back):
            return RollingSolution(edges, x, pc, q, stick, float(xi), float(Q), float(mu), it)
        stick[over] = False
        sign[over] = np.sign(q[over])
        stick[back] = True
    raise RuntimeError("rolling BEM: active set did not converge")


# =====================================================================  Carter (for the table)
CARTER2D = dict(E_star=113888.9, R=500.0, a=1.0, mu=0.3, ratio=0.64)   # CONTACT's carter2d case


def carter2d(n=400, mesh="uniform"):
    """CONTACT's carter2d case with the Hertz pressure of the Chebyshev
    normal solver (a = 1 given): the BEM solution."""
    k = CARTER2D
    p, P, _ = normal_chebyshev(lambda t: t / k["R"], -k["a"], k["a"], k["E_star"], degree=8)
    return solve_rolling(p, -k["a"], k["a"], k["E_star"], k["mu"], k["ratio"] * k["mu"] * P, n, mesh), P


def carter2d_table(ns=(100, 200, 400, 800, 1600), mesh="uniform"):
    """(n, stick start s, its error vs -0.2, creepage, its relative error vs 2.4e-4, iterations)."""
    rows = []
    for n in ns:
        sol, _ = carter2d(n, mesh)
        s = sol.stick_start()
        rows.append((n, s, s + 0.2, sol.xi, sol.xi / 2.4e-4 - 1, sol.iterations))
    return rows


if __name__ == "__main__":   # python tests/contacts/rolling_bem.py: the accuracy table
    import time
    for mesh in ("uniform", "cosine"):
        t0 = time.time()
        for row in carter2d_table(mesh=mesh):
            print(mesh, "n=%5d s=%.6f ds=%+.2e xi=%.6e rel=%+.2e it=%d" % row)
        print("  %.2f s" % (time.time() - t0))
