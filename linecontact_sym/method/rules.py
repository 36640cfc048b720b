"""Integration rules: each a small named object that turns one transform of
the method (an "integral to solve") into a closed form, or says at once why
it cannot.

Modelled on SymPy's ``manualintegrate``: a rule is a class whose docstring is
its formula; ``applies(problem)`` is a cheap test that returns ``None`` when
the rule may apply and otherwise the reason it does not (so a rule that
cannot work costs no budget); ``run(problem)`` returns a :class:`Step`, the
record of what was done (data, not a string), or raises
:class:`NotApplicable` when it finds out late that it does not apply.  The
dispatcher (:func:`linecontact_sym.method.derivation.integrate`) tries the
rules of a transform in order, each under what remains of the time budget.

A :class:`Problem` names the transform (Popov 2017, notation of
:mod:`~linecontact_sym.method.transforms`):

``force``     P(a) = E* int_0^a t f'(t) / sqrt(a^2 - t^2) dt            (Eq. 10*)
``pressure``  p(x; a) = (1/pi) int_x^a P'(s) / sqrt(s^2 - x^2) ds          (Eq. 12)
``gap``       g(x; a) = f(x) - (2/(pi E*)) int_0^a acosh(x/s) P'(s) ds   (Eqs. 3/5)
``profile``   f(a) = (2a/(pi E*)) int_0^a P(s) / (s sqrt(a^2 - s^2)) ds   (Eq. 9)

Adding a strategy is one class (here or in a module beside this one, e.g.
:mod:`.rules_swap`) plus its unit test, and one entry in :data:`RULES`.
"""
from __future__ import annotations

import sympy as sp

from ..core import symbols as S
from ..core.errors import DivergentIntegralError
from .hyperseries import NotDecomposable, beta_kernel_sum, decompose
from .rulebase import TRANSFORMS, NotApplicable, Problem, Rule, Step  # noqa: F401  (re-exported)
from .rules_inverse import InverseMerged
from .rules_swap import GapSwap, PressureSwap
from .transforms import s, t


# ------------------------------------------------------------------ helpers
def _no_integral(expr):
    if expr.has(sp.Integral) or expr.has(sp.nan) or expr.has(sp.zoo):
        raise NotApplicable("SymPy left the integral unevaluated")
    return expr


def _power_terms(expr, var):
    """expr = sum C_i var**m_i (finite, pure powers) -> [(C_i, m_i)]."""
    try:
        terms = decompose(expr, var)
    except NotDecomposable as exc:
        raise NotApplicable(str(exc))
    if not all(T.is_power for T in terms):
        raise NotApplicable("not a finite sum of powers")
    return [(T.coef, T.mu) for T in terms]


def _no_closed_force_law(problem):
    """The reason a rule that integrates the force law cannot start, or None."""
    P = problem.force_law
    if P is None:
        return "no force law given"
    if P.has(sp.Integral):
        return "the force law is an unevaluated integral (no closed form)"
    return None


#: functions whose definite integrals against the kernels of Eqs. (12) and
#: (3/5) SymPy may find in closed form; any other function of ``a`` in a force
#: law (Bessel, hypergeometric, elliptic, error functions ...) gives
#: ``sympy.integrate`` nothing over [x, a] but a long wait (cosh(x) - 1:
#: 20 s, then the unevaluated integral)
ELEMENTARY = (sp.exp, sp.log, sp.sin, sp.cos, sp.tan, sp.cot, sp.asin, sp.acos, sp.atan, sp.acot, sp.sinh,
              sp.cosh, sp.tanh, sp.coth, sp.asinh, sp.acosh, sp.atanh, sp.Abs, sp.sign, sp.Heaviside,
              sp.Piecewise, sp.Min, sp.Max)


def special_of(expr, var):
    """The first non-elementary function of ``var`` in ``expr`` (see
    :data:`ELEMENTARY`), or None."""
    for f in sorted(expr.atoms(sp.Function), key=sp.default_sort_key):
        if isinstance(f, ELEMENTARY) or isinstance(f, sp.core.function.AppliedUndef):
            continue
        if f.has(var):
            return f
    return None


def _special_law(problem):
    """Why SymPy's definite integration of a transform of the force law
    cannot apply (a special function of a in it), or None."""
    f = special_of(problem.force_law, S.a)
    if f is None:
        return None
    return (f"the force law holds the special function {f.func.__name__} of a: SymPy has no definite "
            f"integral of it against the kernel over finite symbolic limits")


def _rational_slope(problem):
    """dP/da of the force law as (numerator, denominator) Polys in a when it
    is a rational function of a (one expression, no Piecewise) with a pole
    off a = 0, else None."""
    if problem.force_law is None:
        return None
    dP = sp.diff(problem.force_law, S.a)
    if dP.has(sp.Piecewise) or not dP.has(S.a) or not dP.is_rational_function(S.a):
        return None
    num, den = sp.fraction(sp.cancel(dP))
    den = sp.Poly(den, S.a)
    return None if den.is_monomial else (sp.Poly(num, S.a), den)   # no pole off a = 0: nothing to say


def _pole_off_origin(R) -> bool:
    """Has the rational function R of a a pole other than a = 0 (its reduced
    denominator is not c a**k)?"""
    return R != 0 and not sp.Poly(sp.denom(sp.cancel(R)), S.a).is_monomial


def _euler_pressure(problem):
    """Why ``sympy.integrate`` cannot do Eq. (12) at once, or None: dP/da is
    rational in a and its even part has a pole off a = 0 (the periodic
    wedge's kernel twin, dP/da ~ 1/(1 - a^2)).  int R(s)/sqrt(s^2 - x^2) ds of
    an even R is elementary only through an Euler substitution
    (s = x cosh u, then w = e^u), which SymPy does not make: it leaves the
    integral unevaluated after 6-26 CPU s (SymPy 1.14, R = 1/(1 - s),
    1/(1 - s^2), 1/(1 + s^2), 1/(b^2 - s^2), s^2/(1 - s^2), 1/(s^2 (1 - s^2));
    mostly in ``manualintegrate``).  The odd part is no obstacle (u = s^2
    makes it rational: s/((1 - s^2) sqrt(s^2 - x^2)) closes), so it is not
    looked at."""
    R = _rational_slope(problem)
    if R is None:
        return None
    dP = R[0].as_expr() / R[1].as_expr()
    even = sp.cancel((dP + dP.subs(S.a, -S.a)) / 2)
    if not _pole_off_origin(even):
        return None
    return (f"dP/da is rational in a and its even part {even} has a pole off a = 0: the integral of Eq. (12) "
            f"needs an Euler substitution, which sympy.integrate does not make (it leaves it unevaluated)")


def _dilog_gap(problem):
    """Why ``sympy.integrate`` cannot do the gap integral at once, or None:
    dP/da is rational in a and P(a) has a logarithmic term with its branch
    point off a = 0 (dP/da has a simple-pole part c/(a - r), r != 0, after
    Hermite's reduction: the periodic wedge's atanh(a)).  By parts the gap
    then holds int log(s - r) x/(s sqrt(x^2 - s^2)) ds, a dilogarithm-type
    function, which SymPy leaves unevaluated after 1.5-8 CPU s (SymPy 1.14:
    acosh(x/s) times 1/(1 - s^2), s/(1 - s^2), 1/(1 + s), 1/(1 + s^2))."""
    from sympy.integrals.rationaltools import ratint_ratpart
    R = _rational_slope(problem)
    if R is None:
        return None
    _, logpart = ratint_ratpart(R[0], R[1], S.a)
    if not _pole_off_origin(logpart):
        return None
    return (f"P(a) has a logarithmic term off a = 0 (dP/da has the simple-pole part {sp.cancel(logpart)}): the "
            f"gap integral is then of dilogarithm type, which sympy.integrate leaves unevaluated")


def _has_piecewise(problem):
    return any(e is not None and e.has(sp.Piecewise)
               for e in (problem.force_law, problem.profile.expr if problem.profile is not None else None))


def beta_termwise(g, var, rho, sigma, prefactor, rule) -> Step:
    """prefactor * int_0^a var**rho (a^2 - var^2)**sigma g(var) dvar, termwise
    over the hypergeometric decomposition of g (see :mod:`.hyperseries`)."""
    conds: list = []
    try:
        terms = decompose(g, var)
    except NotDecomposable as exc:
        raise NotApplicable(str(exc))
    total = sp.Add(*[beta_kernel_sum(T, rho, sigma, S.a, conds) for T in terms])
    kind = "power-law termwise (Beta integrals, Z_n)" if all(T.is_power for T in terms) \
        else "hypergeometric termwise (Beta kernel) + hyperexpand"
    return Step(rule, prefactor * total, tuple(conds), (kind,))


# ------------------------------------------------------------------ force (10*)
class ForceTermwise(Rule):
    """P(a) = E* sum_k int_0^a t (a^2 - t^2)^(-1/2) T_k(t) dt over the terms
    T_k = c x^mu pFq(w x^q) of f'(x): each a Beta integral, so a ``hyper``
    with Gauss-multiplied parameters; power laws give Popov's Z_n (Eqs. 16-17),
    binomials/exp/trig/Bessel factors what ``hyperexpand`` finds (K, E, I_1 ...)."""

    name, transform = "force_termwise", "force"

    def applies(self, problem):
        return "piecewise profile" if problem.profile.is_piecewise else None

    def run(self, problem):
        return beta_termwise(problem.profile.pieces[0].derivative, S.x, 1, sp.Rational(-1, 2), S.E_star, self.name)


class ForcePiecewise(Rule):
    """Eq. (10*) piece by piece with SymPy's definite integration: for a in
    the J-th piece, P(a) = E* [sum_{j<J} int_{x_j}^{x_{j+1}} + int_{x_J}^a]
    t f_j'(t)/sqrt(a^2 - t^2) dt; the result is a Piecewise in a."""

    name, transform = "force_piecewise", "force"

    def applies(self, problem):
        return None if problem.profile.is_piecewise else "profile is not piecewise"

    def run(self, problem):
        branches = []
        done = sp.S.Zero  # contribution of complete pieces
        for pc in problem.profile.pieces:
            integrand = sp.simplify(t * pc.derivative.subs(S.x, t) / sp.sqrt(S.a**2 - t**2))
            upper = _no_integral(sp.integrate(integrand, (t, pc.lo, S.a))) if integrand != 0 else sp.S.Zero
            cond = sp.Le(S.a, pc.hi) if pc.hi != sp.oo else sp.true
            branches.append((S.E_star * (done + upper), cond))
            if pc.hi != sp.oo and integrand != 0:
                done += _no_integral(sp.integrate(integrand, (t, pc.lo, pc.hi)))
        return Step(self.name, sp.Piecewise(*branches), (), ("piecewise, SymPy definite integrals per piece",))


#: CPU seconds of SymPy's integrate on a linear part of an asymmetric contact (:meth:`ForceSympy.cap`)
AUXILIARY_SYMPY_SECONDS = 4.0


class ForceSympy(Rule):
    """Eq. (10*) by ``sympy.integrate`` (a single analytic piece)."""

    name, transform = "force_sympy", "force"

    def applies(self, problem):
        return "piecewise profile" if problem.profile.is_piecewise else None

    def cap(self, problem):
        """On a linear part of an asymmetric contact (``Profile.auxiliary``: the
        even part and the odd part's integral about a centre e, a parameter)
        SymPy's integrate gets :data:`AUXILIARY_SYMPY_SECONDS`: the parts that
        close do so by the termwise rules before it, and where it cannot close
        them (the Gaussian bump's exp(-s^2) cosh(2 e s)) it spent the whole
        budget twice, 40 of a first contact_at's 45 s."""
        return AUXILIARY_SYMPY_SECONDS if getattr(problem.profile, "auxiliary", False) else None

    def run(self, problem):
        integrand = t * problem.profile.pieces[0].derivative.subs(S.x, t) / sp.sqrt(S.a**2 - t**2)
        res = _no_integral(sp.integrate(integrand, (t, 0, S.a), conds="none"))
        return Step(self.name, S.E_star * res, (), ("SymPy integrate",))


# ------------------------------------------------------------------ pressure (12)
class PressureTermwise(Rule):
    """Each power term C a^n of P gives, by the Euler integral,
    (n C / pi) a^(n-1) sqrt(1 - xi^2) 2F1(1 - n/2, 1; 3/2; 1 - xi^2), xi = x/a."""

    name, transform = "pressure_termwise", "pressure"

    def applies(self, problem):
        return "piecewise force law" if problem.force_law.has(sp.Piecewise) else None

    def run(self, problem):
        terms = _power_terms(sp.diff(problem.force_law, S.a).subs(S.a, s), s)
        xi2 = S.x**2 / S.a**2
        out = sp.Add(*[C * S.a**m * sp.sqrt(1 - xi2) * sp.hyper([(1 - m) / 2, 1], [sp.Rational(3, 2)], 1 - xi2)
                       for C, m in terms]) / sp.pi
        return Step(self.name, out, (sp.Lt(S.x, S.a),), ("power-law termwise (Euler integral, 2F1)",))


class PressureSympy(Rule):
    """Eq. (12) by SymPy's definite integration, per (a-interval, x-interval)
    of the profile's breakpoints x_1 < x_2 < ...: a Piecewise in a and x."""

    name, transform = "pressure_sympy", "pressure"

    def applies(self, problem):
        return _no_closed_force_law(problem) or _special_law(problem) or _euler_pressure(problem)

    def run(self, problem):
        bps = list(problem.profile.breakpoints) if problem.profile is not None else []
        dP_of = sp.diff(problem.force_law, S.a)
        branches = []
        edges = [sp.S.Zero] + bps + [sp.oo]
        for J in range(len(edges) - 1):  # a in [edges[J], edges[J+1])
            for I in range(J + 1):       # x in [edges[I], edges[I+1])
                total = sp.S.Zero
                for j in range(I, J + 1):
                    lo = S.x if j == I else edges[j]
                    hi = S.a if j == J else edges[j + 1]
                    dPj = _piece_for(dP_of, j, bps).subs(S.a, s)
                    if dPj == 0:
                        continue
                    total += _no_integral(sp.integrate(dPj / sp.sqrt(s**2 - S.x**2), (s, lo, hi)))
                cond = sp.And(sp.Lt(S.a, edges[J + 1]) if edges[J + 1] != sp.oo else sp.true,
                              sp.Lt(S.x, edges[I + 1]) if I < J else sp.true)
                branches.append((total / sp.pi, cond))
        expr = branches[0][0] if len(branches) == 1 else sp.Piecewise(*branches)
        return Step(self.name, expr, (sp.Lt(S.x, S.a),), ("SymPy definite integration of Eq. (12)",))


def _piece_for(expr, J, bps):
    """The branch of a Piecewise-in-a expression valid for a in interval J."""
    if not expr.has(sp.Piecewise) or not bps:
        return expr
    edges = [sp.S.Zero] + bps
    lo = edges[J]
    hi = bps[J] if J < len(bps) else lo + 1
    probe = (lo + hi) / 2
    expr = sp.piecewise_fold(expr)
    for e, cond in expr.args:
        c = cond.subs(S.a, probe)
        c = sp.simplify(c) if c not in (sp.true, sp.false) else c
        if c == sp.true:
            return e
    raise NotApplicable("could not select the branch of the force law")


# ------------------------------------------------------------------ gap (3/5)
class GapTermwise(Rule):
    """Each power term C a^n of P gives, after integrating by parts,
    (2C/(pi E*)) [a^n acosh(x/a) + (a^n/n) 2F1(1/2, n/2; n/2 + 1; a^2/x^2)]."""

    name, transform = "gap_termwise", "gap"

    def applies(self, problem):
        return "piecewise" if _has_piecewise(problem) else None

    def run(self, problem):
        terms = _power_terms(problem.force_law, S.a)
        inner = sp.Add(*[C * (S.a**m * sp.acosh(S.x / S.a)
                              + S.a**m / m * sp.hyper([sp.S.Half, m / 2], [m / 2 + 1], S.a**2 / S.x**2))
                         for C, m in terms])
        expr = problem.profile.expr - 2 / (sp.pi * S.E_star) * inner
        return Step(self.name, expr, (sp.Gt(S.x, S.a),), ("power-law termwise (integration by parts, 2F1)",))


class GapSympy(Rule):
    """The gap integral by ``sympy.integrate`` (an analytic force law)."""

    name, transform = "gap_sympy", "gap"

    def applies(self, problem):
        if problem.force_law.has(sp.Piecewise):
            return "piecewise force law"
        return _special_law(problem) or _dilog_gap(problem)

    def run(self, problem):
        dP = sp.diff(problem.force_law, S.a).subs(S.a, s)
        I = _no_integral(sp.integrate(sp.acosh(S.x / s) * dP, (s, 0, S.a)))
        expr = problem.profile.expr - 2 / (sp.pi * S.E_star) * I
        return Step(self.name, expr, (sp.Gt(S.x, S.a),), ("SymPy integrate",))


# ------------------------------------------------------------------ inverse (9)
class InverseTermwise(Rule):
    """Eq. (9) termwise: f(a) = (2a/(pi E*)) sum_k int_0^a s^-1 (a^2 - s^2)^(-1/2)
    T_k(s) ds over the hypergeometric terms T_k of P(s) (Beta integrals)."""

    name, transform = "inverse_termwise", "profile"

    def applies(self, problem):
        return "piecewise force law" if problem.force_law.has(sp.Piecewise) else None

    def run(self, problem):
        P = problem.force_law
        try:
            return beta_termwise(P.subs(S.a, s), s, -1, sp.Rational(-1, 2), 2 * S.a / (sp.pi * S.E_star), self.name)
        except DivergentIntegralError as exc:
            lead = sp.limit(P, S.a, 0, "+")
            if lead != 0:
                raise DivergentIntegralError(
                    f"Eq. (9) diverges for the force law {P}: P(0+) = {lead}, but P(a) must vanish "
                    f"as a -> 0 ({exc})")
            raise NotApplicable(f"termwise split diverges although the sum converges ({exc})")


class InverseSympy(Rule):
    """Eq. (9) by ``sympy.integrate``."""

    name, transform = "inverse_sympy", "profile"

    def applies(self, problem):
        return _no_closed_force_law(problem)

    def run(self, problem):
        Ps = problem.force_law.subs(S.a, s)
        I = _no_integral(sp.integrate(Ps / (s * sp.sqrt(S.a**2 - s**2)), (s, 0, S.a), conds="none"))
        return Step(self.name, 2 * S.a / (sp.pi * S.E_star) * I, (), ("SymPy integrate",))


#: the rules of each transform, in the order they are tried
RULES = {
    "force": (ForceTermwise(), ForcePiecewise(), ForceSympy()),
    "pressure": (PressureTermwise(), PressureSwap(), PressureSympy()),
    "gap": (GapTermwise(), GapSwap(), GapSympy()),
    "profile": (InverseTermwise(), InverseMerged(), InverseSympy()),
}
