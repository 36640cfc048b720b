"""The pulled flat punch of JKR adhesion (Popov 2017, Eqs. 30-31) and an
energy route to it that shares nothing with the stress-intensity route.

Near x = a the tensile stress of a flat punch pulled by Phat is
``sigma(x) ~ K_I / sqrt(2 pi (a - x))`` with K_I = Phat/sqrt(pi a) (Eq. 30);
the energy released per unit area when the edge advances is
G = K_I**2/(2 E*).  Griffith's balance G = gamma (the work of adhesion, the
paper's gamma_12) gives Phat = sqrt(2 pi a gamma E*) (Eq. 31).

The same follows from the compliance of the flat punch, Eq. (3):
C(a) = (2/(pi E*)) arccosh(L/a) for the displacement at a distant point L,
so G = (Phat**2/2) |dC/d(2a)| = Phat**2/(2 pi E* a) as L -> oo.
:func:`phat_energy` evaluates that route numerically (quadrature of the
punch displacement, numerical differentiation, root finding).
"""
from __future__ import annotations

import mpmath
import sympy as sp

from ...core import symbols as S
from ...core.conversion import to_mpf
from ...core.precision import workdps

#: range of the work of adhesion at the random verification points
GAMMA_RANGE = (0.005, 0.5)


def flat_punch_force(work_of_adhesion=S.gamma, a=S.a, E_star=S.E_star):
    """Eq. (31): Phat = sqrt(2 pi a gamma E*), the force of the pulled flat
    punch that makes the energy release rate at the edges equal to gamma
    (K_I**2/(2 E*) = gamma with K_I = Phat/sqrt(pi a), Eq. 30).

    >>> flat_punch_force()
    sqrt(2)*sqrt(pi)*sqrt(E_star)*sqrt(a)*sqrt(gamma)
    """
    return sp.sqrt(2 * sp.pi * a * work_of_adhesion * E_star)


def stress_intensity(Phat, a=S.a):
    """Eq. (30): mode-I stress-intensity factor of a flat punch pulled by Phat,
    K_I = lim_{x->a} sqrt(2 pi (a - x)) sigma(x) = Phat/sqrt(pi a)."""
    return Phat / sp.sqrt(sp.pi * a)


def energy_release_rate(K, E_star=S.E_star):
    """G = K_I**2/(2 E*) at the edge of a rigid-elastic line contact."""
    return K**2 / (2 * E_star)


def compliance_quad(A, E, dps, L):
    """Compliance of the flat punch (unit force), displacement difference
    between the punch and a distant point L, by quadrature of the
    half-plane's log kernel over the punch pressure 1/(pi sqrt(a^2 - s^2)):
    C = (2/(pi E*)) (1/pi) int_{-pi/2}^{pi/2} ln(|L - a sin phi| / |a sin phi|) dphi."""
    with workdps(max(mpmath.mp.dps, dps + 10)):  # never below a caller's (mpmath.diff) precision
        f = lambda ph: mpmath.log(abs(L - A * mpmath.sin(ph))) - mpmath.log(abs(A * mpmath.sin(ph)))  # noqa: E731
        I = mpmath.quad(f, [-mpmath.pi / 2, 0, mpmath.pi / 2]) / mpmath.pi
        return 2 * I / (mpmath.pi * E)


def phat_energy(A, gamma, E, dps, quadrature=True):
    """Phat from the energy balance G = gamma, G = (P^2/2) |dC/d(2a)| with C
    the punch compliance (Eq. 3, by quadrature or, with ``quadrature=False``,
    in its closed arccosh form): numerical differentiation + root finding."""
    with workdps(dps + 10):
        A, g, E = to_mpf(A), to_mpf(gamma), to_mpf(E)
        if g == 0:
            return mpmath.mpf(0)
        L = A * mpmath.mpf(10)**(dps + 20)
        if quadrature:
            dC = mpmath.diff(lambda u: compliance_quad(u, E, dps + 10, L), A)
        else:
            dC = mpmath.diff(lambda u: 2 * mpmath.acosh(L / u) / (mpmath.pi * E), A)
        G = lambda Pv: Pv**2 / 4 * abs(dC) - g  # noqa: E731
        guess = mpmath.sqrt(4 * g / abs(dC))
        return mpmath.findroot(G, (guess * mpmath.mpf("0.5"), guess * 2), solver="anderson")


__all__ = ["flat_punch_force", "stress_intensity", "energy_release_rate", "compliance_quad", "phat_energy",
           "GAMMA_RANGE"]
