"""A time-stepping boundary-element solution of the viscoelastic line contact
under a given load history, for the tests of :mod:`linecontact_sym.contacts.viscoelastic`.

Shares nothing with the package: a uniform grid of piecewise-constant
pressure elements on the half-plane surface, the plane-strain Flamant
kernel (2/pi) ln(L/|x - xi|) integrated over each element in closed form,
the creep compliance J(t) given by the caller as a float function, the
hereditary integral w(t_n) = sum_k J(t_n - t') K dp(t') with p linear in
time inside a step (trapezoidal weights), and an active set at every step:
p >= 0 in contact, gap >= 0 outside, sum p h = P(t_n).  The contact
half-width is read from the active set (resolution: half an element).
"""
from __future__ import annotations

import numpy as np


def flamant_matrix(xc, h, L=10.0):
    """K[i, j] = (2/pi) int over element j of ln(L/|x_i - xi|) dxi."""
    u1 = xc[:, None] - (xc[None, :] - h / 2)
    u0 = xc[:, None] - (xc[None, :] + h / 2)

    def F(u):  # antiderivative of ln|u|
        au = np.abs(u)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(au > 0, u * np.log(np.where(au > 0, au, 1.0)) - u, 0.0)
    int_ln = F(u1) - F(u0)          # int ln|x_i - xi| dxi over the element
    return (2 / np.pi) * (h * np.log(L) - int_ln)


def creep_bem(f, J, P, times, half_length, n=300):
    """Half-widths a(t_n) (from the active set) and the pressures for the load
    history P(t) (P(0+) may be a step), compliance J, profile f (vectorised).
    ``times`` starts at 0 (the state just after the step)."""
    h = 2 * half_length / n
    xc = -half_length + h * (np.arange(n) + 0.5)
    K = flamant_matrix(xc, h)
    fx = f(np.abs(xc))
    dps = []                           # pressure increments
    tk = []                            # their times
    p_prev = np.zeros(n)
    active = np.abs(xc) < 2 * h
    out_a, out_p = [], []
    for i, tn in enumerate(times):
        # history: increments before this step, trapezoidal weights
        hist = np.zeros(n)
        if dps:
            wgt = np.array([J(tn - t0) if t0 == t1 else 0.5 * (J(tn - t0) + J(tn - t1)) for t0, t1 in tk])
            hist = wgt @ np.array(dps)
        Kh = K @ hist
        Kp = K @ p_prev
        t_prev = times[i - 1] if i else tn
        c = J(tn - t_prev) if i == 0 else 0.5 * (J(tn - t_prev) + J(0.0))
        Pn = P(tn)
        for _ in range(200):
            A = np.where(active)[0]
            m = len(A)
            M = np.zeros((m + 1, m + 1))
            M[:m, :m] = c * K[np.ix_(A, A)]
            M[:m, m] = -1.0
            M[m, :m] = h
            rhs = np.zeros(m + 1)
            rhs[:m] = -fx[A] - Kh[A] + c * Kp[A]
            rhs[m] = Pn
            sol = np.linalg.solve(M, rhs)
            p = np.zeros(n)
            p[A] = sol[:m]
            d = sol[m]
            w = c * (K @ p - Kp) + Kh
            gap = fx - d + w
            changed = False
            neg = active & (p < 0)
            if neg.any():
                active &= ~neg
                changed = True
            pen = (~active) & (gap < -1e-14 * max(1.0, abs(d)))
            if pen.any() and not changed:
                active |= pen
                changed = True
            if not changed:
                break
        dps.append(p - p_prev)
        tk.append((t_prev, tn))
        p_prev = p
        A = np.where(active)[0]
        out_a.append(np.max(np.abs(xc[A])) + h / 2 if len(A) else 0.0)
        out_p.append(p.copy())
    return np.array(out_a), xc, out_p, h
