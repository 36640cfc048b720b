"""The Maugis-Dugdale conditions of a line contact, derived with SymPy from
the profile through Popov's (2017) flat-punch superposition.

Model (plane strain, rigid symmetric profile f, half-plane of modulus E*):
contact on |x| < a, Dugdale (cohesive) zone a < |x| < c_D carrying the
constant tension sigma_0 while the gap is below h0 = w/sigma_0, free surface
beyond.  Any symmetric pressure on |x| < c_D is a superposition of flat
punches (Eq. 12): p(x) = (1/pi) int_|x|^c_D g(t)/sqrt(t^2 - x^2) dt with g the
density of punch forces dP/dt over the half-widths t.

* On (0, a) the displacement must follow the profile; the punches of width
  t < a alone shape u(0) - u(x) at |x| < a (Eq. 5: a wider punch moves the whole
  of |x| < t rigidly), so g = P0'(t), the density of the adhesionless contact
  (the engine's force law, Eq. 10*).
* On (a, c_D) the traction is -sigma_0: the Abel equation
  (1/pi) int_x^c_D g(t)/sqrt(t^2 - x^2) dt = -sigma_0 is inverted here
  (``G(y) = 2 int_y^c_D s p(s)/sqrt(s^2 - y^2) ds``, g = -G'), giving the
  Dugdale punches, of total force G(a).
* A flat punch of width exactly a, of force -Q, is the only term that is
  singular at x = +-a: K_I = Q/sqrt(pi a).  Maugis' condition (bounded
  pressure at the edges) is K_I = 0, so Q = 0 and

      P(a, c_D) = P0(a) + G(a)                          (bounded pressure)

* The gap at |x| > a is f(x) - (2/(pi E*)) int_0^|x| acosh(|x|/t) g(t) dt
  (Eqs. 3/5), the engine's adhesionless gap g0(x; a) plus the Dugdale
  punches' part; at x = c_D (by parts, derived here) it must equal h0:

      g0(c_D; a) + g_D(c_D; a, c_D) = w/sigma_0         (Dugdale gap)

Everything below is computed by SymPy from these definitions; nothing is
typed in from the literature (Baney & Hui 1997 are the check, in
:mod:`.check`).
"""
from __future__ import annotations

import sympy as sp

from ....core import symbols as S

_y = sp.Symbol("y", positive=True)     # lower end of the Abel inversion
_s = sp.Symbol("s", positive=True)     # traction coordinate
_t = sp.Symbol("t", positive=True)     # punch half-width
_v = sp.Symbol("v", positive=True)
_k = sp.Symbol("k", positive=True)
_l = sp.Symbol("l", positive=True)
_Q = sp.Symbol("Q", real=True)         # force of a (pulled) punch of half-width a


class DugdaleParts:
    """The Dugdale strip's contributions, derived (see the module docstring).

    density      g_D(t), the force density of the Dugdale punches, a < t < c_D
    force        G(a) = int_a^c_D g_D dt, their total force
    pressure     their pressure inside the contact, |x| < a
    gap_at_c     their part of the gap at x = c_D
    zero_width   lim_{a->0+} gap_at_c (the cohesive zone of a vanishing contact)
    steps        what was done, for the derivation record
    """

    def __init__(self, sigma0=S.sigma_0, E_star=S.E_star):
        c, a, x = S.c_D, S.a, S.x
        steps = []
        # 1. Abel inversion of the constant traction -sigma0 on (y, c_D)
        # (elementary: SymPy's Meijer-G route, tried first by default, finds the same antiderivative
        # in ten times the CPU)
        G = sp.integrate(2 * _s * (-sigma0) / sp.sqrt(_s**2 - _y**2), (_s, _y, c), conds="none", meijerg=False)
        G = sp.simplify(G)
        g = sp.simplify(-sp.diff(G, _y))
        steps.append(f"Abel inversion of p = -sigma_0 on (y, c_D): int_y^c_D g = {G}, g(t) = {g.subs(_y, _t)}")
        self.density = g.subs(_y, _t)
        self.force = G.subs(_y, a)
        # 2. pressure inside |x| < a: (1/pi) int_a^c g(t)/sqrt(t^2 - x^2) dt, t^2 = x^2 + v^2
        #    (t dt = v dv: an elementary integrand in v, from l = sqrt(a^2 - x^2) to k = sqrt(c^2 - x^2);
        #    in v = t^2 - x^2 it took SymPy's Meijer-G route, ten times the CPU for the same result)
        h = (self.density / _t).subs(_t, sp.sqrt(_v**2 + x**2)) / sp.pi
        hv = sp.simplify(h.subs(c, sp.sqrt(_k**2 + x**2)))
        Iv = sp.integrate(hv, (_v, _l, _k), conds="none")
        Iv = _drop_unreachable(Iv, sp.Gt(_k, _l))
        self.pressure = sp.simplify(Iv.subs({_k: sp.sqrt(c**2 - x**2), _l: sp.sqrt(a**2 - x**2)}))
        steps.append(f"their pressure inside: (1/pi) int_a^c_D g/sqrt(t^2-x^2) dt (t^2 = x^2 + v^2) = {self.pressure}")
        # 3. gap at x = c: -(2/(pi E*)) int_a^c acosh(c/t) g(t) dt, by parts with the antiderivative of g
        Gt = sp.integrate(self.density, _t)
        K = sp.acosh(c / _t)
        boundary = sp.limit(K * Gt, _t, c, "-") - (K * Gt).subs(_t, a)
        rest = sp.integrate(sp.simplify(sp.diff(K, _t) * Gt), (_t, a, c), conds="none")
        I = sp.expand_log(boundary - rest, force=True)
        gap = sp.simplify(-2 / (sp.pi * E_star) * I)
        self.gap_at_c = _collect_log(gap, c, a)
        steps.append(f"their gap at c_D: -(2/(pi E*)) int_a^c_D acosh(c_D/t) g dt (by parts) = {self.gap_at_c}")
        self.zero_width = sp.simplify(sp.limit(self.gap_at_c, a, 0, "+"))
        steps.append(f"a -> 0+: {self.zero_width}")
        # 4. the singular punch: K_I of -Q/(pi sqrt(a^2 - x^2)) at x -> a
        p_Q = -_Q / (sp.pi * sp.sqrt(a**2 - x**2))
        K_I = sp.simplify(sp.limit(sp.sqrt(2 * sp.pi * (a - x)) * (-p_Q), x, a, "-"))
        K_D = sp.limit(sp.sqrt(a - x) * self.pressure, x, a, "-")
        self.stress_intensity = K_I
        steps.append(f"the only term singular at x = a is a punch of width a and force -Q: K_I = {K_I}; "
                     f"the Dugdale part gives sqrt(a - x) p -> {K_D}; bounded pressure <=> Q = 0")
        self.edge_pressure = sp.simplify(sp.limit(self.pressure, x, a, "-"))
        steps.append(f"their pressure at x -> a-: {self.edge_pressure} (continuous with the Dugdale zone)")
        self.steps = tuple(steps)


def _drop_unreachable(e, cond):
    """A Piecewise from sympy.integrate: the branch whose condition is ``cond``
    (true by construction: c_D > a), else the expression itself."""
    if isinstance(e, sp.Piecewise):
        for expr, c in e.args:
            if c == cond or c is sp.true:
                return expr
        return e.args[0][0]
    return e


def _collect_log(e, c, a):
    """log(c) - log(a) written as log(c/a) (one logarithm, no cancellation)."""
    e = sp.expand(sp.expand_log(e, force=True))
    k, kk = e.coeff(sp.log(c)), e.coeff(sp.log(a))
    if k != 0 and sp.simplify(k + kk) == 0:
        e = e - k * sp.log(c) - kk * sp.log(a) + k * sp.log(c / a)
    return sp.factor_terms(e)


_PARTS: dict = {}


def dugdale_parts(sigma0=S.sigma_0) -> DugdaleParts:
    """The Dugdale parts for a cohesive tension expression (cached)."""
    if sigma0 not in _PARTS:
        _PARTS[sigma0] = DugdaleParts(sigma0)
    return _PARTS[sigma0]


__all__ = ["DugdaleParts", "dugdale_parts"]
