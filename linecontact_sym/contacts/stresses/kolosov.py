"""Subsurface stresses of the elastic half-plane from complex potentials.

Coordinates and signs
---------------------
x along the surface, z > 0 the depth into the body, zeta = x + i z.  The
surface carries a normal pressure p(x) (compressive positive, acting into
the body) and a tangential traction q(x) exerted on the body in the +x
direction (a slider moving in +x relative to the half-plane drags its surface
with q = +mu p).  Stresses are tensile positive; plane strain with
sigma_y = nu (sigma_x + sigma_z).

Johnson (1985), Eq. (2.23) (Flamant superposition), with w = x - s and
r^2 = w^2 + z^2::

    sigma_x = -(2z/pi) int p w^2/r^4 ds - (2/pi) int q w^3/r^4 ds
    sigma_z = -(2z^3/pi) int p /r^4 ds  - (2z^2/pi) int q w /r^4 ds
    tau_xz  = -(2z^2/pi) int p w /r^4 ds - (2z/pi) int q w^2/r^4 ds

Kolosov-Muskhelishvili form
---------------------------
With the Cauchy (Stieltjes) transforms of the tractions,

    G(zeta) = int_{-a}^{a} p(s)/(zeta - s) ds,   H(zeta) = int_{-a}^{a} q(s)/(zeta - s) ds

(analytic off the contact segment; G(zeta) ~ P/zeta at infinity), the
integrals above are real and imaginary parts of G, G', H, H'::

    pi sigma_x = Im G + z Re G' - 2 Re H + z Im H'
    pi sigma_z = Im G - z Re G'          - z Im H'
    pi tau_xz  =      - z Im G' + Im H + z Re H'

(so sigma_x + sigma_z = (2/pi) Im(G) - (2/pi) Re(H), and at the surface
Im G(x + i0) = -pi p(x): sigma_z = -p, tau_xz = -q.)

Popov's superposition of flat punches
-------------------------------------
A pressure of the method is a superposition of flat punches of half-width t
and load dP = P'(t) dt (Eq. 12).  The Cauchy transform of a flat punch,
P/(pi sqrt(t^2 - s^2)) on |s| < t, is P/sqrt(zeta^2 - t^2), so

    G(zeta) = int_0^a P'(t) (zeta^2 - t^2)^(-1/2) dt                 (*)

(principal branch for Re zeta >= 0, Im zeta > 0; for all zeta in the upper
half-plane as zeta (1 - t^2/zeta^2)^(1/2) / ...).  The same holds for a
tangential traction written as a superposition of punches, q = (1/pi)
int_{|x|}^a Q'(t)/sqrt(t^2 - x^2) dt: sliding Q' = mu P', partial slip with
a stick zone |x| < c: Q' = mu P'(t) for t > c, i.e. H = mu [G(zeta; a) -
G(zeta; c)].  (*) is one integral of the engine's kind: power-law terms of
P' give Beta integrals, hence ``hyper`` (the termwise rule below), which
``hyperexpand`` turns into elementary functions for Hertz (P' ~ t) and the
wedge (P' constant: G = E* tan(theta) asin(a/zeta)).
"""
from __future__ import annotations

import sympy as sp

from ...core import symbols as S
from ...core.budget import Deadline, run_with_budget
from ...core.errors import BudgetExceeded, DivergentIntegralError
from ...method.derivation import tidy
from ...method.hyperseries import NotDecomposable, beta_kernel_sum, decompose
from ...method.rules import NotApplicable, Rule, Step
from ...method.transforms import t  # the punch half-width, the integration variable of (*)


def kolosov_stresses(G, dG, H, dH, z, re, im, pi):
    """(sigma_x, sigma_z, tau_xz) from the potentials G, G' (pressure) and
    H, H' (tangential traction) at depth ``z`` (see the module docstring).
    ``re``/``im``/``pi`` are SymPy's or NumPy's, so one formula serves the
    closed forms and the numeric field.

    >>> G = sp.pi * (S.zeta - S.zeta * sp.sqrt(1 - 1 / S.zeta**2))   # Hertz, p0 = a = 1
    >>> at = {S.zeta: sp.I}                                           # x = 0, z = 1
    >>> stresses = kolosov_stresses(G.subs(at), sp.diff(G, S.zeta).subs(at), 0, 0, 1, sp.re, sp.im, sp.pi)
    >>> [sp.N(v, 12) for v in stresses]           # 2 - 3/sqrt(2), -1/sqrt(2), 0
    [-0.121320343560, -0.707106781187, 0]
    """
    sx = (im(G) + z * re(dG) - 2 * re(H) + z * im(dH)) / pi
    sz = (im(G) - z * re(dG) - z * im(dH)) / pi
    txz = (-z * im(dG) + im(H) + z * re(dH)) / pi
    return sx, sz, txz


def punch_integral(density, lo=0, hi=S.a):
    """The unevaluated (*): Integral(density(t) / sqrt(zeta^2 - t^2), (t, lo, hi))."""
    return sp.Integral(density / sp.sqrt(S.zeta**2 - t**2), (t, lo, hi))


# ------------------------------------------------------------------ rules
class CauchyTermwise(Rule):
    """G(zeta) = sum_k C_k int_0^a t^m_k (zeta^2 - t^2)^(-1/2) dt
    = sum_k C_k a^(m_k+1)/((m_k+1) zeta) 2F1(1/2, (m_k+1)/2; (m_k+3)/2; a^2/zeta^2)
    for a punch density P'(t) = sum_k C_k t^m_k (the engine's Beta kernel with
    the binomial series of (1 - t^2/zeta^2)^(-1/2)); the principal branch of
    2F1 (cut a^2/zeta^2 in [1, oo), i.e. zeta on the contact segment) is the
    analytic continuation into the whole upper half-plane."""

    name, transform = "cauchy_termwise", "cauchy"

    def applies(self, problem):
        return "piecewise density" if problem.has(sp.Piecewise) else None

    def run(self, density):
        g = density.subs(S.a, t) * (1 - t**2 / S.zeta**2)**sp.Rational(-1, 2) / S.zeta
        try:
            terms = decompose(g, t)
        except NotDecomposable as exc:
            raise NotApplicable(str(exc))
        conds: list = []
        total = sp.Add(*[beta_kernel_sum(T, 0, 0, S.a, conds) for T in terms])
        return Step(self.name, total, (), ("Beta integrals of the binomial series of (1 - t^2/zeta^2)^(-1/2), "
                                           "continued analytically to Im zeta > 0 (principal 2F1)",))


class CauchyPiecewise(Rule):
    """G(zeta) = sum_j int_{t_j}^{t_j+1} P'_j(t) (zeta^2 - t^2)^(-1/2) dt piece
    by piece with SymPy's definite integration (a Piecewise P' in a, e.g. the
    worn cylinder's flat: P' = 0 for a < b)."""

    name, transform = "cauchy_piecewise", "cauchy"

    def applies(self, problem):
        return None

    def run(self, density):
        pieces = _density_pieces(density)
        total = sp.S.Zero
        for expr, lo, hi in pieces:
            if expr == 0:
                continue
            val = sp.integrate(sp.simplify(expr.subs(S.a, t)) / sp.sqrt(S.zeta**2 - t**2), (t, lo, hi))
            if val.has(sp.Integral) or val.has(sp.nan) or val.has(sp.zoo) or val.has(sp.Piecewise):
                raise NotApplicable("SymPy left the integral unevaluated (or conditional)")
            total += val
        return Step(self.name, total, (), ("SymPy definite integration piece by piece",))


#: the rules tried, in order
CAUCHY_RULES = (CauchyTermwise(), CauchyPiecewise())


def _density_pieces(density):
    """[(expr, lo, hi)] of a density P'(a) given for 0 < a (a Piecewise with
    conditions a <= b / True, as the engine's force laws are)."""
    if not isinstance(density, sp.Piecewise):
        return [(density, sp.S.Zero, S.a)]
    out, lo = [], sp.S.Zero
    for expr, cond in density.args:
        if cond == sp.true:
            out.append((expr, lo, S.a))
            break
        rel = cond
        if isinstance(rel, (sp.LessThan, sp.StrictLessThan)) and rel.lhs == S.a and not rel.rhs.has(S.a):
            out.append((expr, lo, rel.rhs))
            lo = rel.rhs
            continue
        if isinstance(rel, (sp.GreaterThan, sp.StrictGreaterThan)) and rel.rhs == S.a and not rel.lhs.has(S.a):
            out.append((expr, lo, rel.lhs))
            lo = rel.lhs
            continue
        raise NotApplicable(f"condition {cond} is not a <= const")
    return out


def density_breakpoints(density) -> tuple:
    """The half-widths t in (0, a) where the density P'(t) changes piece."""
    try:
        return tuple(hi for _, _, hi in _density_pieces(density)[:-1])
    except NotApplicable:
        return ()


def cauchy_transform(density, budget: float):
    """G(zeta) of (*) for the punch density P'(a) (an expression in a): the
    rules of :data:`CAUCHY_RULES` in order under ``budget`` CPU seconds, the
    result tidied (hyperexpand, simplify).  Returns ``(step or None,
    attempts)`` like :func:`linecontact_sym.method.derivation.integrate`."""
    attempts = []
    deadline = Deadline(budget)
    for rule in CAUCHY_RULES:
        why = rule.applies(density)
        if why is not None:
            attempts.append((rule.name, f"not applicable: {why}"))
            continue
        left = deadline.left()
        if left is not None and left <= 0.05:
            attempts.append((rule.name, "budget used up"))
            break
        try:
            step = run_with_budget(rule.run, density, seconds=left)
        except (NotApplicable, DivergentIntegralError) as exc:
            attempts.append((rule.name, f"not applicable: {exc}"))
            continue
        except BudgetExceeded as exc:
            attempts.append((rule.name, f"no result within {budget:g} CPU s" + (f" ({exc})" if exc.wall_guard else "")))
            continue
        except Exception as exc:  # a SymPy failure inside a rule
            attempts.append((rule.name, f"{type(exc).__name__}: {exc}"))
            continue
        try:
            expr = run_with_budget(tidy, step.expr, seconds=15.0 if deadline.budget is None else max(min(deadline.left(), 15.0), 1.0))
        except Exception:
            expr = sp.hyperexpand(step.expr)
        return Step(step.rule, expr, step.conditions, step.notes), attempts
    return None, attempts


def symbolic_stresses(G, H=sp.S.Zero):
    """(sigma_x, sigma_z, tau_xz) as SymPy expressions in x, z from the
    potentials G(zeta), H(zeta) (expressions in ``zeta``), with ``re``/``im``
    of the potentials at zeta = x + i z kept unevaluated (numbers come from
    evaluating them; SymPy's eager expansion into atan2 forms is slow and long)."""
    at = {S.zeta: S.x + sp.I * S.z}
    dG = sp.diff(G, S.zeta)
    dH = sp.diff(H, S.zeta) if H != 0 else sp.S.Zero

    # re/im unevaluated: SymPy would expand them into atan2 forms of x and z
    def re(e):
        return sp.re(e, evaluate=False) if e != 0 else sp.S.Zero

    def im(e):
        return sp.im(e, evaluate=False) if e != 0 else sp.S.Zero
    return kolosov_stresses(G.xreplace(at), dG.xreplace(at), sp.sympify(H, strict=True).xreplace(at), sp.sympify(dH, strict=True).xreplace(at),
                            S.z, re, im, sp.pi)


__all__ = ["kolosov_stresses", "punch_integral", "cauchy_transform", "symbolic_stresses", "CAUCHY_RULES",
           "CauchyTermwise", "CauchyPiecewise", "density_breakpoints", "t"]
