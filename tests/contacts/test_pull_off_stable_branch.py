"""Unloading from the stable branch (issue 42, class 3): the end of the
admissible range lies on a falling branch (unstable under load control),
so a lower value there is reported, not taken; every statement of the
answer agrees with the extrema found.  Against our own bracketed search on
an independent evaluation of P(a) = (pi/2) a J1(a) - sqrt(2 pi a gamma)
(E* = 1) for f = 1 - cos(x)."""
from __future__ import annotations

import mpmath
import sympy as sp

import linecontact_sym as lcs


def _own_P(a, gamma=1):
    # P0 = E* a int_0^{pi/2} sin(phi) sin(a sin phi) dphi = (pi/2) a J1(a)
    return mpmath.pi / 2 * a * mpmath.besselj(1, a) - mpmath.sqrt(2 * mpmath.pi * a * gamma)


def _golden(P, lo, hi, n=80):
    g = (mpmath.sqrt(5) - 1) / 2
    for _ in range(n):
        m1, m2 = hi - g * (hi - lo), lo + g * (hi - lo)
        if P(m1) < P(m2):
            hi = m2
        else:
            lo = m1
    return (lo + hi) / 2


def test_one_minus_cos_pulls_off_at_the_stable_branch_minimum():
    """before: NoPullOffError 'no minimum inside the admissible range; it decreases up to the
    range's end' although P(a) has a local minimum at a = 1.04799 (P = -1.81660); after: that
    minimum, with the lower end value -1.92608 and the maximum between them in the note."""
    ad = lcs.LineContact(1 - sp.cos(lcs.x), verify=False).adhesive()
    po = ad.pull_off_at(15, E_star=1, gamma=1)
    with mpmath.workdps(30):
        a_min = _golden(_own_P, mpmath.mpf("0.5"), mpmath.mpf("1.5"))
        a_max = _golden(lambda a: -_own_P(a), mpmath.mpf("1.5"), mpmath.mpf("2.2"))
        a_end = mpmath.besseljzero(0, 1)      # dP0/da = (pi/2) a J0(a) turns negative there
        P_min, P_max, P_end = _own_P(a_min), _own_P(a_max), _own_P(a_end)
    assert po.kind == "stationary"
    assert abs(po.force - P_min) < 1e-13 and abs(po.half_width - a_min) < 1e-7
    assert P_end < P_min                      # the end is lower, and not taken
    assert mpmath.nstr(P_end, 8) in po.note and mpmath.nstr(a_max, 8) in po.note
    assert mpmath.nstr(P_max, 8) in po.note and "unstable" in po.note
    assert "decreases up to" not in po.note
    kinds = [e.kind for e in po.minima]
    assert kinds == ["stationary", "end"]
