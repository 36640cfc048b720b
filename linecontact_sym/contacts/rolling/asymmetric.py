"""Steady rolling over an asymmetric contact (a profile that is not symmetric,
a tilt, a moment): ``LineContact(f, symmetric=False).rolling(mu)``.

The normal contact [left, right] and its tilt theta_n come from the
asymmetric contact's ``contact_at(P, theta=...|moment=...)`` (it must be
bounded: both edges smooth); then, as for a symmetric contact
(:mod:`.contact`), with the stick zone [s, right] at the leading edge,
centre e* = right - c_s and half-width c_s:

    P(e*, c_s) = P - |Q|/mu,     xi = sign(Q) mu [theta(e*, c_s) - theta_n],

P and theta from the asymmetric core's numbers where its force laws close,
else by quadrature of the interval integrals (:mod:`.interval`), the
traction mu p - mu p* at float64 points.  Numbers
only (the symbolic quantities in (a, c_s) are the symmetric contact's).
"""
from __future__ import annotations

import mpmath
import numpy as np
import sympy as sp

from ...core import symbols as S
from ...core.conversion import to_mpf
from ...core.errors import DomainError, InadmissibleProfileError
from ...core.precision import workdps
from ...core.ranges import check_points
from ...parsing import user_value
from ..base import checked_value
from ..tangential.coupling import read_coupling
from . import state as st
from ..asymmetric.interval import X, SlopeNumbers


class AsymmetricRolling:
    """Steady rolling in +x over an asymmetric contact (numbers)."""

    def __init__(self, contact, friction=S.mu, *, beta=None, materials=None):
        m = user_value(friction)
        if not isinstance(m, sp.Expr) or (m.is_number and not m.is_positive):
            raise DomainError(f"the friction coefficient must be positive, got {friction}")
        self.contact = contact
        self.mu = m
        self.coupling = read_coupling(m, beta, materials)   # its DomainWarning (beta != 0): once, here
        self.slope = sp.diff(contact.profile, X)
        self._cache = {}

    def __repr__(self):
        return f"rolling over {self.contact!r}, mu={self.mu}{self.coupling.keywords()}"

    @property
    def coupling_note(self):
        """What the states say about the neglected coupling (at the contact's mu)."""
        return self.coupling.note(self.mu)

    def _split(self, values):
        vals = self.coupling.values(dict(values))     # E_star from the materials where not given
        if not self.mu.is_number:
            names = {s.name for s in self.mu.free_symbols}
            mu = self.mu.xreplace({s: user_value(checked_value(s.name, vals.pop(s.name), s))
                                   for s in self.mu.free_symbols if s.name in vals})
            if not mu.is_number:
                raise DomainError(f"values needed for the friction coefficient's {sorted(names)}")
            if not mu.is_positive:
                raise DomainError(f"the friction coefficient must be positive, got mu = {mu}")
        else:
            mu = self.mu
        return mu, vals

    def _numbers(self, vals) -> SlopeNumbers:
        key = tuple(sorted((k, str(v)) for k, v in vals.items()))
        if key not in self._cache:
            subs = {p: user_value(vals[p.name]) for p in self.contact.params}
            brs = [sp.sympify(b, strict=True).xreplace(subs) for b in self.contact.core.kinks]
            E = to_mpf(sp.N(user_value(vals["E_star"]), 40))
            core = self.contact.core
            # P(e, a), theta(e, a): the core's numbers (the engine's closed force laws) where they close
            nums = core.numbers(**{v.name: vals[v.name] for v in core.variables}) if core.closed("force") else None
            self._cache[key] = SlopeNumbers(self.slope, subs, E, brs, core=nums)
        return self._cache[key]

    def state_at(self, Q, P, theta=None, moment=None, _check=True, **values):
        """The rolling state at the tangential force Q (|Q| < mu P) over the
        contact at the load P with the tilt ``theta`` (default 0) or the
        moment ``moment``: a :class:`~.state.RollingState`."""
        Q = checked_value("Q", Q, None)          # a finite real number (1j, NaN, text: DomainError)
        mu_e, vals = self._split(values)
        normal = self.contact.contact_at(P, theta=theta, moment=moment, **vals)
        if normal.regime != "bounded":
            raise InadmissibleProfileError(
                f"rolling over {self.contact!r}: the normal contact has a corner ({normal.regime}); the traction "
                f"mu p is singular there and one stick zone at the leading edge is not the solution")
        num = self._numbers(vals)
        with workdps(30):
            mu = to_mpf(sp.N(mu_e, 40))
            L, Rt, th_n = normal.left, normal.right, normal.theta
            a_n, e_n = (Rt - L) / 2, (Rt + L) / 2
            Pv = num.P(e_n, a_n)
            Qm = to_mpf(sp.N(user_value(Q), 40))
            load, at_onset = st.onset(Qm, mu, Pv)
            sign = -1 if Qm < 0 else 1
            if Qm == 0:
                c = a_n
            elif at_onset:
                c = mpmath.mpf(0)
            else:
                extra = max(0, int(-mpmath.log10(abs(Qm) / (mu * Pv)))) + 2 + st.near_full_slip_digits(load, Pv)
                with workdps(30 + extra):
                    c = st.solve_stick(num.P, Rt, a_n, Pv - abs(Qm) / mu, 30 + extra, P_float=num.P_float)
            xi = sign * mu * (num.tilt(Rt - c, c) - th_n) if Qm != 0 else mpmath.mpf(0)
            ef, cf, enf, anf = float(Rt - c), float(c), float(e_n), float(a_n)
            state = st.RollingState(Qm, Pv, mu, L, Rt, Rt - 2 * c, c, xi, False,
                                    coupling=self.coupling.note(mu_e),
                                    _normal=lambda x: num.pressure(x, enf, anf),
                                    _aux=lambda x: num.pressure(x, ef, cf))
        if _check and c > 0 and Qm != 0:
            st.check_admissible(state, lambda x: num.J(x, ef, cf), lambda x: num.pressure(x, enf, anf),
                                f"{self.contact!r}")
        return state

    def creepage_curve(self, P, points: int = 41, theta=None, moment=None, **values):
        """(Q/(mu P), xi) at ``points`` stick half-widths (float64)."""
        points = check_points(points, 2, "the creepage-force curve")
        mu_e, vals = self._split(values)
        normal = self.contact.contact_at(P, theta=theta, moment=moment, **vals)
        num = self._numbers(vals)
        L, Rt, th_n = float(normal.left), float(normal.right), float(normal.theta)
        a_n, e_n, mu = (Rt - L) / 2, (Rt + L) / 2, float(sp.N(mu_e))
        Pv = num.P_float(e_n, a_n)
        cs = np.linspace(a_n, 0.0, points)
        Qs = np.array([mu * (Pv - num.P_float(Rt - c, c)) for c in cs])
        xi = np.array([mu * (num.tilt_float(Rt - c, c) - th_n) for c in cs])
        return Qs / (mu * Pv), xi


__all__ = ["AsymmetricRolling"]
