"""Stable rewrites of elliptic integrals into Carlson's symmetric forms.

Complete and incomplete integrals of the three kinds (parameter m = k^2, as
SymPy's ``elliptic_k(m)``, ``elliptic_f(phi, m)``, ``elliptic_pi(n, phi, m)``)
become R_F, R_D, R_G, R_J with the complements 1 - m, 1 - n, cos(phi)^2 ...
formed symbolically: no cancellation where m, n or phi approach their ends.
"""
from __future__ import annotations

import sympy as sp

from .special import carlson_rd, carlson_rf, carlson_rg, carlson_rj
from .stable_base import StableRule, complement_of

__all__ = ["EllipticToCarlson", "EllipticPiToCarlson"]


class EllipticToCarlson(StableRule):
    """K(m) = R_F(0, m', 1), E(m) = 2 R_G(0, m', 1) = R_F(0, m', 1) - (m/3) R_D(0, m', 1),
    m' = 1 - m simplified symbolically (1 - a**2/R**2 -> (R - a)(R + a)/R**2).

    In each sum the coefficients alpha of K(m) and beta of E(m) are collected:
    alpha + beta = 0 gives alpha (m/3) R_D(0, m', 1) (K - E without
    cancellation as m -> 0, log divergence kept at m -> 1), beta = 0 gives
    alpha R_F, alpha = 0 gives 2 beta R_G (no cancellation as m -> 1),
    otherwise (alpha + beta) R_F - beta (m/3) R_D.
    """

    name = "elliptic->carlson"
    heads = (sp.elliptic_k, sp.elliptic_e)

    def apply(self, expr):
        ells = [e for e in expr.atoms(sp.elliptic_k, sp.elliptic_e) if len(e.args) == 1]
        if not ells:
            return expr
        args = sorted({e.args[0] for e in ells}, key=sp.default_sort_key)
        subs, info = {}, {}
        for i, m in enumerate(args):
            Kd, Ed = sp.Dummy(f"K{i}"), sp.Dummy(f"E{i}")
            subs[sp.elliptic_k(m)] = Kd
            subs[sp.elliptic_e(m)] = Ed
            info[(Kd, Ed)] = (m, complement_of(m))
        marks = [d for pair in info for d in pair]

        def simp(cf):
            return sp.factor(sp.cancel(cf)) if cf != 0 else sp.S.Zero

        def combine(e):
            parts = sp.collect(sp.expand(e), marks, evaluate=False)
            out = parts.pop(sp.S.One, sp.S.Zero)
            for (Kd, Ed), (m, mc) in info.items():
                al = simp(parts.pop(Kd, sp.S.Zero))
                be = simp(parts.pop(Ed, sp.S.Zero))
                if al == 0 and be == 0:
                    continue
                rf, rd, rg = carlson_rf(0, mc, 1), carlson_rd(0, mc, 1), carlson_rg(0, mc, 1)
                s_ = simp(al + be)
                if s_ == 0:
                    out += al * m / 3 * rd
                elif be == 0:
                    out += al * rf
                elif al == 0:
                    out += 2 * be * rg
                else:
                    out += s_ * rf - be * m / 3 * rd
            for k, cf in parts.items():   # anything else (should not occur)
                out += cf * k
            return out

        def walk(e):  # top-down: combine at the outermost sum holding K or E
            if not e.has(*marks) or e.is_Atom:
                return e
            if e.is_Add:
                return combine(e)
            return e.func(*[walk(t) for t in e.args])
        e3 = walk(expr.xreplace(subs))
        if e3.has(*marks):
            e3 = combine(e3)
        return e3.xreplace(
            {Kd: carlson_rf(0, mc, 1) for (Kd, Ed), (m, mc) in info.items()}).xreplace(
            {Ed: 2 * carlson_rg(0, mc, 1) for (Kd, Ed), (m, mc) in info.items()})


class EllipticPiToCarlson(StableRule):
    """Pi(n|m) = R_F(0, m', 1) + (n/3) R_J(0, m', 1, n'), and the incomplete
    integrals with s = sin(phi), c^2 = 1 - s^2, d^2 = 1 - m s^2:
    F(phi|m) = s R_F(c^2, d^2, 1), E(phi|m) = s R_F(c^2, d^2, 1) - (m/3) s^3 R_D(c^2, d^2, 1),
    Pi(n; phi|m) = s R_F(c^2, d^2, 1) + (n/3) s^3 R_J(c^2, d^2, 1, 1 - n s^2)
    (DLMF 19.25.5, 19.25.9, 19.25.14; 0 <= phi <= pi/2, n s^2 < 1), every
    complement simplified symbolically (m' = 1 - m, n' = 1 - n ...).  Terms
    of equal sign: no cancellation."""

    name = "elliptic-pi/incomplete->carlson"
    heads = (sp.elliptic_pi, sp.elliptic_f, sp.elliptic_e)

    def applies(self, expr) -> bool:
        return expr.has(sp.elliptic_pi, sp.elliptic_f) or \
            any(len(e.args) == 2 for e in expr.atoms(sp.elliptic_e))

    def apply(self, expr):
        def incomplete(phi, m):
            s_ = sp.sin(phi)
            c2, d2 = complement_of(s_**2), complement_of(m * s_**2)
            return s_, c2, d2

        def pi_(e):
            if len(e.args) == 2:
                n, m = e.args
                mc = complement_of(m)
                return carlson_rf(0, mc, 1) + n / 3 * carlson_rj(0, mc, 1, complement_of(n))
            n, phi, m = e.args
            s_, c2, d2 = incomplete(phi, m)
            return s_ * carlson_rf(c2, d2, 1) + n / 3 * s_**3 * carlson_rj(c2, d2, 1, complement_of(n * s_**2))

        def f_(e):
            s_, c2, d2 = incomplete(*e.args)
            return s_ * carlson_rf(c2, d2, 1)

        def e_(e):
            phi, m = e.args
            s_, c2, d2 = incomplete(phi, m)
            return s_ * carlson_rf(c2, d2, 1) - m / 3 * s_**3 * carlson_rd(c2, d2, 1)
        expr = expr.replace(lambda e: isinstance(e, sp.elliptic_pi), pi_)
        expr = expr.replace(lambda e: isinstance(e, sp.elliptic_f), f_)
        return expr.replace(lambda e: isinstance(e, sp.elliptic_e) and len(e.args) == 2, e_)
