"""Steady rolling states at numbers (:mod:`linecontact_sym.contacts.rolling`):
the stick zone, the creepage, the traction at float64 points, the
admissibility checks and the creepage-force curve."""
from __future__ import annotations

from dataclasses import dataclass, field

import mpmath
import numpy as np
import sympy as sp

from ...core.errors import DomainError, GrossSlidingError, InadmissibleProfileError
from ...core.precision import workdps
from ...core.roots import root_in_bracket, root_in_log
from ..base import checked_value

#: points of the float64 admissibility grid over the contact
CHECK_POINTS = 801
#: |Q| within this relative distance of mu P is the onset of full slip (float64 inputs)
ONSET_RTOL = mpmath.mpf("1e-14")


@dataclass
class RollingState:
    """One steady rolling state at numbers (rolling in +x; conventions in
    :mod:`linecontact_sym.contacts.rolling`).

    Q, P, mu      tangential force on body 1, normal load, friction coefficient
    left, right   the contact [left, right] (the normal problem's)
    stick         (s, right): the stick zone at the leading edge
    slip          (left, s): the slip zone at the trailing side (empty at Q = 0)
    c_s           the stick zone's half-width (right - s)/2
    creepage      xi, same sign as Q (Carter: mu (a - c_s)/R)
    closed        True where the numbers came from closed forms of the engine
    checked       what the admissibility check covered (a sentence)
    note          why closed forms were not used at this state ("" if they were or there are none)
    coupling      what the state neglects of the two bodies' mismatch: "beta = 0 assumed
                  (elastically similar bodies)", or |beta| mu where beta was given
                  (:mod:`linecontact_sym.contacts.tangential.coupling`; the numbers are the same)
    """

    Q: object
    P: object
    mu: object
    left: object
    right: object
    s: object
    c_s: object
    creepage: object
    closed: bool
    checked: str = ""
    note: str = ""
    coupling: str = ""
    _normal: object = field(default=None, repr=False)
    _aux: object = field(default=None, repr=False)

    @property
    def stick(self):
        return (self.s, self.right)

    @property
    def slip(self):
        return (self.left, self.s)

    @property
    def sign(self) -> float:
        return -1.0 if self.Q < 0 else 1.0

    def normal_pressure(self, x):
        """p(x) of the normal contact (float64, 0 outside)."""
        return self._normal(points_of(x))

    def corrective(self, x):
        """mu p*(x): the corrective traction over the stick zone (float64, 0 outside)."""
        return float(self.mu) * self._aux(points_of(x))

    def traction(self, x):
        """q(x) = sign(Q) [mu p(x) - mu p*(x)] (float64): the shear traction on
        body 1, q > 0 for Q > 0; mu p in the slip zone."""
        x = points_of(x)
        return self.sign * (float(self.mu) * self.normal_pressure(x) - self.corrective(x))

    def plot(self, points: int = 401, ax=None, title=None):
        """mu p and q over the contact with the stick zone marked
        (:func:`linecontact_sym.views.rolling_plots.traction`)."""
        from ...views import rolling_plots
        x = np.linspace(float(self.left), float(self.right), points)
        return rolling_plots.traction(x, float(self.mu) * self.normal_pressure(x), self.traction(x),
                                      (float(self.s), float(self.right)), ax=ax, title=title)


def points_of(x):
    """Points x as a user gives them (a number, a list or an array): finite
    real numbers as float64 (:func:`~linecontact_sym.contacts.base.checked_value`;
    NaN, inf, complex, text: DomainError)."""
    v = checked_value("x", np.asarray(x) if isinstance(x, (list, tuple)) else x, None)
    return np.asarray(v if isinstance(v, np.ndarray) else float(v), float)


def solve_stick(P_aux, right, a_n, load, dps=30, P_float=None):
    """The stick half-width c in (0, a_n] with P_aux(right - c, c) = load
    (0 < load < P): bracketed on (0, a_n] (the load of the stick zone's
    bounded pressure grows from 0 to P as the zone grows to the contact),
    then Anderson-Bjorck at ``dps`` digits.  With ``P_float`` (a float64
    P(e, c)) the root is first located in float64 and the bracket narrowed
    to 1e-9 around it (a few high-precision evaluations)."""
    with workdps(dps + 10):
        if P_float is not None:
            Rf, Lf = float(right), float(load)
            c0 = None
            with workdps(15):
                gf = lambda c: mpmath.mpf(P_float(Rf - float(c), float(c)) - Lf)  # noqa: E731
                if gf(0) < 0 < gf(a_n):
                    c0 = root_in_bracket(gf, mpmath.mpf(0), mpmath.mpf(a_n))
            if c0 is not None:
                g = lambda c: P_aux(right - c, c) - load  # noqa: E731
                d = mpmath.mpf("1e-9") * a_n
                lo, hi = max(mpmath.mpf(c0) - d, a_n * mpmath.mpf(10)**(-dps)), min(mpmath.mpf(c0) + d, a_n)
                if g(lo) < 0 < g(hi):
                    return root_in_bracket(g, lo, hi, width=hi - lo)
        g = lambda c: P_aux(right - c, c) - load  # noqa: E731
        hi = mpmath.mpf(a_n)
        ghi = g(hi)
        lo = hi / 2
        while g(lo) > 0:
            lo /= 2
            if lo < hi * mpmath.mpf(10)**(-dps):
                raise InadmissibleProfileError("no stick zone found at the leading edge: the load of the "
                                               "stick zone's bounded pressure does not fall to the required "
                                               f"{mpmath.nstr(load, 8)} as it shrinks")
        if ghi < 0:
            raise InadmissibleProfileError("no stick zone found at the leading edge: the stick zone's load does "
                                           "not reach the normal load as it grows to the whole contact")
        return root_in_bracket(g, lo, hi if lo < hi / 2 else hi)


def near_full_slip_digits(load, P) -> int:
    """Extra working digits near full slip: Q(c_s) flattens like c_s^2 as the
    stick zone vanishes (the creepage's condition number in Q grows like
    1/sqrt(1 - Q/(mu P)))."""
    if load <= 0:
        return 0
    return max(0, int(-mpmath.log10(load / P) / 2)) + 2


def solve_deficit(g, A, ratio=1):
    """The deficit u in (0, A] of the stick zone (its half-width c = A - u)
    where g(u) = Q(A, A - u) - |Q| changes sign (g(0+) < 0 < g(A)): solved
    in ln u, so that a tiny deficit (free rolling) keeps its relative digits.
    ``ratio`` = |Q|/(mu P): the deficit is about A ratio/2 (Q is linear in u
    at free rolling), so the bracket is sought down to A ratio 10^-dps; an
    error, not its lower end, where none is found there."""
    hi = mpmath.mpf(A)
    lo = hi / 2
    floor = hi * min(mpmath.mpf(ratio), 1) * mpmath.mpf(10)**(-mpmath.mp.dps)
    while g(lo) > 0:
        lo /= 2
        if lo < floor:
            raise InadmissibleProfileError(
                f"no stick zone found at the leading edge: the tangential force of the stick zone stays above "
                f"|Q| (|Q|/(mu P) = {mpmath.nstr(ratio, 5)}) down to a deficit a - c_s = {mpmath.nstr(lo, 5)}")
    if g(hi) < 0:
        raise InadmissibleProfileError("no stick zone found at the leading edge: the tangential force of the "
                                       "stick zone does not reach Q as the stick zone shrinks to nothing")
    return root_in_log(g, lo, hi)


def check_admissible(state, J_aux, p_n, label, points=CHECK_POINTS):
    """|q| <= mu p in the stick zone (0 <= p* <= 2 p) and slip against the
    traction in the slip zone (J* >= 0 there: the stick zone's tilted gap
    falls towards it), on a grid of ``points``; a clear error otherwise."""
    L, Rt, s = float(state.left), float(state.right), float(state.s)
    x = np.linspace(L, Rt, points)[1:-1]
    J = J_aux(x)
    scale = max(float(np.max(np.abs(J))), 1e-300)
    bad = J < -1e-9 * scale
    if bad.any():
        where = x[bad]
        zone = "slip zone (the slip would run with the traction)" if where[0] < s else \
            "stick zone (the traction would exceed mu p there)"
        raise InadmissibleProfileError(
            f"rolling with {label}: one stick zone at the leading edge is not the solution at Q = "
            f"{mpmath.nstr(state.Q, 8)}: its corrective pressure turns negative in the {zone} near x = "
            f"{where[0]:.6g}; a profile with a flat or a dent may need more than one stick zone (not solved here)")
    xs = x[x > s]
    if len(xs):
        ps, pn = state.corrective(xs) / float(state.mu), p_n(xs)
        over = ps > 2 * pn * (1 + 1e-9) + 1e-12 * max(float(np.max(pn)), 1e-300)
        if over.any():
            raise InadmissibleProfileError(
                f"rolling with {label}: the traction would exceed -mu p near x = {xs[over][0]:.6g} in the stick "
                f"zone at Q = {mpmath.nstr(state.Q, 8)}: one stick zone at the leading edge is not the solution")
    state.checked = (f"checked on {points} points of the contact: |q| <= mu p in the stick zone, slip against the "
                     f"traction in the slip zone")


def onset(Q, mu, P):
    """(load of the stick zone, at the full-slip onset?) for |Q| < mu P; an
    error beyond."""
    load = P - abs(Q) / mu
    if load < -P * ONSET_RTOL:
        raise GrossSlidingError(f"|Q| = {mpmath.nstr(abs(Q), 8)} exceeds mu P = {mpmath.nstr(mu * P, 8)}: "
                                f"the rolling contact slides as a whole")
    return load, load <= P * ONSET_RTOL


def number_of(v):
    """An mpf of a value (SymPy number, float, int, str of a number)."""
    if isinstance(v, str):
        raise DomainError(f"{v!r}: strings are not evaluated; pass a number")
    return mpmath.mpf(sp.N(sp.sympify(v, strict=True), mpmath.mp.dps + 5)) if not isinstance(v, mpmath.mpf) else v


__all__ = ["RollingState", "solve_stick", "solve_deficit", "check_admissible", "onset", "CHECK_POINTS", "points_of"]
