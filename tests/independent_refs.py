"""Test helper: independent references typed here, sharing nothing with the
package: Eq. (10*) and Eq. (12) by mpmath quadrature, Eq. (13) in closed
form, and a comparison decided at 50 digits (tests of the contacts' numbers,
symbols, cases and ranges)."""
from __future__ import annotations

import mpmath
import numpy as np

from linecontact_sym.core.precision import workdps


def close(value, ref, tol):
    """|value - ref| < tol, decided at 50 digits (mpf results carry 30+)."""
    if isinstance(value, (np.ndarray, np.floating)):
        value = float(value)
    with mpmath.workdps(50):
        return abs(mpmath.mpf(value) - mpmath.mpf(ref)) < tol


def force_ref(fprime, A, E=1, dps=30):
    """Eq. (10*) by quadrature after t = a sin(phi)."""
    with mpmath.workdps(dps + 10):
        A = mpmath.mpf(A)
        return +(E * A * mpmath.quad(lambda ph: mpmath.sin(ph) * fprime(A * mpmath.sin(ph)), [0, mpmath.pi / 2]))


def pressure_ref(fprime, fsecond, A, X, E=1, dps=20):
    """Eq. (12), p(x) = (1/pi) int_x^a P'(s)/sqrt(s^2 - x^2) ds with s = x cosh(u),
    P'(s) = E int_0^{pi/2} [sin(phi) f'(s sin phi) + s sin^2(phi) f''(s sin phi)] dphi
    (f' and f'' analytic on [0, a] for every profile here: Gauss-Legendre, 30x faster than
    tanh-sinh in this inner integral)."""
    with mpmath.workdps(dps + 10):
        A, X = mpmath.mpf(A), mpmath.mpf(X)

        def dP(s):
            return E * mpmath.quad(lambda ph: mpmath.sin(ph) * fprime(s * mpmath.sin(ph))
                                   + s * mpmath.sin(ph)**2 * fsecond(s * mpmath.sin(ph)), [0, mpmath.pi / 2],
                                   method="gauss-legendre")
        return +(mpmath.quad(lambda u: dP(X * mpmath.cosh(u)), [0, mpmath.acosh(A / X)]) / mpmath.pi)


def parabola_force(a, R, E, dps):
    """Eq. (13) typed here, at dps digits."""
    with workdps(dps + 10):
        return mpmath.pi * mpmath.mpf(E) * mpmath.mpf(a) ** 2 / (4 * mpmath.mpf(R))
