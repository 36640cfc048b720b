"""An independent solver of the line-contact singular integral equation, for
the tests of the asymmetric contact (shares nothing with the superposition:
no force law, no even/odd split, no package code).

    (2/(pi E*)) PV int_{e-a}^{e+a} p(t)/(x - t) dt = f'(x) - theta,

mapped to t = e + a tau, x = e + a xi, solved by Gauss-Chebyshev/Jacobi
quadrature and collocation (Erdogan, Gupta & Cook 1973; Krenk 1975) with p
written as E* w(tau) phi(tau):

``bounded``   w = sqrt(1 - tau^2): nodes tau_i = cos(i pi/(N+1)), weights
              pi (1 - tau_i^2)/(N+1), collocation at xi_k = cos((2k-1) pi/(2N+2)),
              k = 1..N+1; the unknowns phi_i and theta (the tilt of the
              bounded solution).
``singular``  w = 1/sqrt(1 - tau^2) (corners at both ends): nodes
              cos((2i-1) pi/(2N)), weights pi/N, collocation at cos(k pi/N),
              k = 1..N-1, plus the load; theta given.
``right_corner`` w = sqrt((1 + tau)/(1 - tau)) (smooth left end, corner at
              the right): nodes cos((2i-1) pi/(2N+1)) (zeros of the Chebyshev
              polynomial of the third kind V_N), weights 2 pi (1 + tau_i)/(2N+1),
              collocation at cos(2k pi/(2N+1)) (zeros of W_N),
              k = 1..N; the unknowns phi_i and theta, plus the load.

All in mpmath at the caller's precision (``mpmath.workdps``).
"""
import mpmath


def _solve(nodes, weights, colloc, e, a, E, fprime, theta=None, load=None):
    """Rows: the collocated equation sum_i W_i phi_i/(xi - tau_i) (2/pi) = f'(x) - theta,
    unknowns phi_i (and theta if None), plus a load row if ``load``."""
    N = len(nodes)
    free_theta = theta is None
    rows, rhs = [], []
    for xi in colloc:
        r = [2 / mpmath.pi * w / (xi - t) for t, w in zip(nodes, weights)]
        if free_theta:
            r.append(mpmath.mpf(1))
        rows.append(r)
        rhs.append(fprime(e + a * xi) - (0 if free_theta else theta))
    if load is not None:
        r = [E * a * w for w in weights] + ([mpmath.mpf(0)] if free_theta else [])
        rows.append(r)
        rhs.append(load / 1)
    A = mpmath.matrix(rows)
    b = mpmath.matrix(rhs)
    sol = mpmath.lu_solve(A, b)
    phi = [sol[i] for i in range(N)]
    th = sol[N] if free_theta else mpmath.mpf(theta)
    return phi, th


class Solution:
    def __init__(self, nodes, weights, phi, theta, e, a, E, weight):
        self.nodes, self.weights, self.phi, self.theta = nodes, weights, phi, theta
        self.e, self.a, self.E, self.weight = mpmath.mpf(e), mpmath.mpf(a), mpmath.mpf(E), weight
        self.load = E * a * mpmath.fsum(w * f for w, f in zip(weights, phi))
        self.moment = E * a * mpmath.fsum(w * f * (e + a * t) for w, f, t in zip(weights, phi, nodes))

    def phi_at(self, tau):
        """The polynomial through (tau_i, phi_i) (Lagrange)."""
        total = mpmath.mpf(0)
        for i, ti in enumerate(self.nodes):
            L = mpmath.mpf(1)
            for j, tj in enumerate(self.nodes):
                if j != i:
                    L *= (tau - tj) / (ti - tj)
            total += L * self.phi[i]
        return total

    def pressure(self, x):
        tau = (mpmath.mpf(x) - self.e) / self.a
        return self.E * self.weight(tau) * self.phi_at(tau)


def bounded(fprime, e, a, E=1, N=24):
    """The bounded solution on [e - a, e + a]: its tilt, load, moment, pressure."""
    e, a, E = mpmath.mpf(e), mpmath.mpf(a), mpmath.mpf(E)
    nodes = [mpmath.cos(i * mpmath.pi / (N + 1)) for i in range(1, N + 1)]
    weights = [mpmath.pi * (1 - t**2) / (N + 1) for t in nodes]
    colloc = [mpmath.cos((2 * k - 1) * mpmath.pi / (2 * N + 2)) for k in range(1, N + 2)]
    phi, th = _solve(nodes, weights, colloc, e, a, E, fprime)
    return Solution(nodes, weights, phi, th, e, a, E, lambda t: mpmath.sqrt(1 - t**2))


def singular(fprime, e, a, theta, load, E=1, N=24):
    """Corners at both ends (a flat punch in complete contact), tilt and load given."""
    e, a, E = mpmath.mpf(e), mpmath.mpf(a), mpmath.mpf(E)
    nodes = [mpmath.cos((2 * i - 1) * mpmath.pi / (2 * N)) for i in range(1, N + 1)]
    weights = [mpmath.pi / N] * N
    colloc = [mpmath.cos(k * mpmath.pi / N) for k in range(1, N)]
    phi, th = _solve(nodes, weights, colloc, e, a, E, fprime, theta=theta, load=load)
    return Solution(nodes, weights, phi, th, e, a, E, lambda t: 1 / mpmath.sqrt(1 - t**2))


def right_corner(fprime, e, a, load, E=1, N=24):
    """Smooth (bounded) left end, corner at the right end; the load given, the tilt found."""
    e, a, E = mpmath.mpf(e), mpmath.mpf(a), mpmath.mpf(E)
    nodes = [mpmath.cos((2 * i - 1) * mpmath.pi / (2 * N + 1)) for i in range(1, N + 1)]
    weights = [2 * mpmath.pi * (1 + t) / (2 * N + 1) for t in nodes]
    colloc = [mpmath.cos(2 * k * mpmath.pi / (2 * N + 1)) for k in range(1, N + 1)]
    phi, th = _solve(nodes, weights, colloc, e, a, E, fprime, load=load)
    return Solution(nodes, weights, phi, th, e, a, E, lambda t: mpmath.sqrt((1 + t) / (1 - t)))


def displacement_difference(sol, x1, x0):
    """u(x1) - u(x0) of the collocated pressure, u(x) = -(2/(pi E*)) int p(t) ln|x - t| dt
    (u positive into the body; x1, x0 outside the contact or at its ends), by
    tanh-sinh quadrature of the interpolated pressure in tau."""
    def g(tau):
        xt = sol.e + sol.a * tau
        return sol.weight(tau) * sol.phi_at(tau) * (mpmath.log(abs(x1 - xt)) - mpmath.log(abs(x0 - xt)))
    total = mpmath.quad(g, [-1, 0, 1])
    return -2 / mpmath.pi * sol.a * total     # p = E* w phi: E* cancels


def bounded_float(fprime, e, a, E=1.0, N=400):
    """:func:`bounded` in float64 (NumPy), for profiles whose slope jumps (a
    wedge): the collocation then converges slowly, so many nodes are cheap
    only in float64.  Returns (theta, load, moment, pressure(x))."""
    import numpy as np
    i = np.arange(1, N + 1)
    nodes = np.cos(i * np.pi / (N + 1))
    weights = np.pi * (1 - nodes**2) / (N + 1)
    k = np.arange(1, N + 2)
    colloc = np.cos((2 * k - 1) * np.pi / (2 * N + 2))
    A = np.empty((N + 1, N + 1))
    A[:, :N] = 2 / np.pi * weights[None, :] / (colloc[:, None] - nodes[None, :])
    A[:, N] = 1.0
    rhs = np.array([fprime(e + a * xi) for xi in colloc])
    sol = np.linalg.solve(A, rhs)
    phi, theta = sol[:N], sol[N]
    load = E * a * np.sum(weights * phi)
    moment = E * a * np.sum(weights * phi * (e + a * nodes))

    def pressure(x):
        # phi(tau) by the discrete Chebyshev (second kind) expansion through the nodes
        tau = (x - e) / a
        j = np.arange(N)
        th_i = i * np.pi / (N + 1)
        U = np.sin((j[:, None] + 1) * th_i[None, :]) / np.sin(th_i)[None, :]
        c = 2 / (N + 1) * (U * (np.sin(th_i)**2 * phi)[None, :]).sum(axis=1)
        t = np.arccos(np.clip(tau, -1, 1))
        Ut = np.sin((j + 1) * t) / np.sin(t)
        return E * np.sqrt(1 - tau**2) * float(np.dot(c, Ut))
    return theta, load, moment, pressure


def chebyshev_moments(fprime, e, a, E=1, kinks=()):
    """(theta, P, M) of the bounded solution on [e - a, e + a] from the
    Chebyshev expansion of f'(e + a cos(phi)) that the collocation converges
    to (p = E* sqrt(1 - tau^2) sum c_k U_k(tau), 2 c_k the T_{k+1}
    coefficient of f' - theta):

        theta = (1/pi) int_0^pi f'(e + a cos phi) dphi
        P     = (E* a/2) int_0^pi f'(e + a cos phi) cos(phi) dphi
        M_c   = (E* a^2/4) int_0^pi f'(e + a cos phi) cos(2 phi) dphi,   M = e P + M_c

    by tanh-sinh quadrature split where e + a cos(phi) meets a kink: the
    independent reference for slopes that jump (the wedge), where collocation
    converges like 1/N."""
    e, a, E = mpmath.mpf(e), mpmath.mpf(a), mpmath.mpf(E)
    pts = [mpmath.mpf(0)] + sorted(mpmath.acos((mpmath.mpf(b) - e) / a) for b in kinks if abs(b - e) < a) + [mpmath.pi]

    def q(w):
        return mpmath.quad(lambda ph: fprime(e + a * mpmath.cos(ph)) * w(ph), pts)
    theta = q(lambda ph: 1) / mpmath.pi
    P = E * a / 2 * q(mpmath.cos)
    Mc = E * a**2 / 4 * q(lambda ph: mpmath.cos(2 * ph))
    return theta, P, e * P + Mc


def inversion_pressure(fprime, left, right, x, kinks=()):
    """The bounded pressure at x by the inversion of the singular integral
    equation (Muskhelishvili), p(x) = (E*/(2 pi)) sqrt((r - x)(x - l))
    PV int_l^r (f'(t) - f'(x)) / (sqrt((r - t)(t - l)) (t - x)) dt (E* = 1; the
    subtracted f'(x) integrates to 0), split at x and the kinks."""
    l, r, x = mpmath.mpf(left), mpmath.mpf(right), mpmath.mpf(x)
    fx = fprime(x)

    def h(t):
        if t == x:
            return mpmath.mpf(0)
        return (fprime(t) - fx) / (mpmath.sqrt((r - t) * (t - l)) * (t - x))
    pts = sorted([l, x, r] + [mpmath.mpf(b) for b in kinks if l < b < r])
    return mpmath.sqrt((r - x) * (x - l)) / (2 * mpmath.pi) * mpmath.quad(h, pts)
