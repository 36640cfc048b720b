"""Each integration rule on its own (linecontact_sym/method/rules*.py and the
helpers they stand on, legendre.reduce_integral and hyperseries):

* ``applies`` returns None on a problem it is made for and the rule's result
  agrees with an mpmath quadrature of the defining integral written out here
  (Popov 2017: Eq. 10* force, Eq. 12 pressure, Eqs. 3/5 gap, Eq. 9 profile),
  which shares nothing with the rule (no decomposition, no Beta integral,
  no SymPy integration, no Legendre reduction);
* on a problem it is not made for, ``applies`` gives its reason (a string)
  at once, or ``run`` raises NotApplicable -- no SymPy integration is
  started.  (Time is not asserted here: benchmarks/ measures it.)
"""
from __future__ import annotations

import mpmath
import pytest
import sympy as sp

from linecontact_sym.core import symbols as S
from linecontact_sym.method.hyperseries import NotDecomposable, beta_kernel_sum, decompose
from linecontact_sym.method.legendre import NotReducible, reduce_integral
from linecontact_sym.method.profile import Profile
from linecontact_sym.method.rules import (RULES, ForcePiecewise, ForceSympy, ForceTermwise, GapSwap, GapSympy,
                                          GapTermwise, InverseMerged, InverseSympy, InverseTermwise, NotApplicable,
                                          PressureSwap, PressureSympy, PressureTermwise, Problem)

a, x, E, R, b, c, n = S.a, S.x, S.E_star, S.R, S.b, S.c, S.n
DPS = 30
#: a point of every region used below (0 < b < a < x < R)
PT = {a: sp.Rational(7, 10), x: sp.Rational(3, 10), E: sp.Rational(13, 10), R: sp.Rational(17, 10),
      b: sp.Rational(1, 5), c: sp.Rational(3, 5)}
OUT = {**PT, x: sp.Rational(6, 5)}

PARABOLA = Profile(x**2 / (2 * R))
POWER = Profile(c * x**sp.Rational(5, 2))
WORN = Profile(sp.Piecewise((0, x < b), ((x**2 - b**2) / (2 * R), True)))
COSINE = Profile(R * (1 - sp.cos(x / R)))                     # not algebraic
P_HERTZ = sp.pi * E * a**2 / (4 * R)
#: Eq. (10*) of WORN worked by hand: (E*/R) int_b^a t^2/sqrt(a^2 - t^2) dt
P_WORN = sp.Piecewise((0, a < b), (E / R * (a**2 / 2 * (sp.pi / 2 - sp.asin(b / a)) + b * sp.sqrt(a**2 - b**2) / 2),
                                   True))
_t = sp.Symbol("t", positive=True)


# ---------------------------------------------------------------- independent quadratures
def _f(expr, var, vals):
    return sp.lambdify(var, expr.xreplace({k: v for k, v in vals.items() if k != var}), "mpmath")


def force_quad(profile, vals):
    """Eq. (10*) with t = a sin(phi): E* a int_0^{pi/2} sin(phi) f'(a sin phi) dphi."""
    fp = _f(sp.diff(profile.expr, x), x, vals)
    A = mpmath.mpf(vals[a])
    kinks = [mpmath.asin(mpmath.mpf(sp.N(k.xreplace(vals), DPS + 10)) / A) for k in profile.breakpoints
             if sp.N(k.xreplace(vals)) < vals[a]]
    return mpmath.mpf(vals[E]) * A * mpmath.quad(lambda p: mpmath.sin(p) * fp(A * mpmath.sin(p)),
                                                 [0, *kinks, mpmath.pi / 2])


def _kinks(vals, lo, hi):
    """The breakpoint b of the worn profile where it lies in (lo, hi): P' is singular there."""
    B = mpmath.mpf(sp.N(vals[b], DPS + 10))
    return [B] if lo < B < hi else []


def pressure_quad(P, vals):
    """Eq. (12) with s = x cosh(u): (1/pi) int_0^{acosh(a/x)} P'(x cosh u) du."""
    dP = _f(sp.diff(P, a), a, vals)
    A, X = mpmath.mpf(vals[a]), mpmath.mpf(vals[x])
    cuts = [mpmath.acosh(k / X) for k in _kinks(vals, X, A)]
    return mpmath.quad(lambda u: dP(X * mpmath.cosh(u)), [0, *cuts, mpmath.acosh(A / X)]) / mpmath.pi


def gap_quad(profile, P, vals):
    """Eqs. (3)/(5): f(x) - (2/(pi E*)) int_0^a acosh(x/s) P'(s) ds."""
    dP = _f(sp.diff(P, a), a, vals)
    A, X = mpmath.mpf(vals[a]), mpmath.mpf(vals[x])
    f = mpmath.mpf(sp.N(profile.expr.xreplace(vals), DPS + 10))
    g = lambda s: mpmath.acosh(X / s) * dP(s)  # noqa: E731
    kinks = _kinks(vals, 0, A)
    total = mpmath.quad(g, [0, kinks[0]]) + quad_root_end(g, kinks[0], A) if kinks else mpmath.quad(g, [0, A])
    return f - 2 / (mpmath.pi * mpmath.mpf(vals[E])) * total


def quad_root_end(g, lo, hi):
    """int_lo^hi g(s) ds for g ~ 1/sqrt(s - lo) at lo (P' just above a kink of the
    profile): s = lo + (hi - lo) v^2 makes it smooth; Gauss-Legendre keeps its
    nodes away from v = 0, where s - lo would cancel."""
    return mpmath.quad(lambda v: 2 * (hi - lo) * v * g(lo + (hi - lo) * v**2), [0, 1], method="gauss-legendre")


def profile_quad(P, vals):
    """Eq. (9) with s = a sin(phi): (2/(pi E*)) int_0^{pi/2} P(a sin phi)/sin(phi) dphi."""
    Pf = _f(P, a, vals)
    A = mpmath.mpf(vals[a])
    return 2 / (mpmath.pi * mpmath.mpf(vals[E])) * mpmath.quad(
        lambda p: Pf(A * mpmath.sin(p)) / mpmath.sin(p), [0, mpmath.pi / 2])


def agree(step, vals, ref):
    """The rule's closed form at ``vals`` equals ``ref`` to 25 digits."""
    with mpmath.workdps(DPS + 10):
        got = mpmath.mpf(sp.re(sp.N(step.expr.xreplace(vals), DPS + 10)))
        assert abs(got - ref) <= abs(ref) * mpmath.mpf(10)**-25, (step.rule, got, ref)


def run(rule, problem):
    assert rule.applies(problem) is None
    step = rule.run(problem)
    assert step.rule == rule.name and not step.expr.has(sp.Integral)
    return step


def refuses(rule, problem):
    """The rule says at once that it does not apply: a reason from applies()."""
    why = rule.applies(problem)
    assert isinstance(why, str) and why


# ---------------------------------------------------------------- the registry
def test_the_hand_worked_force_laws_are_those_of_the_profiles():
    with mpmath.workdps(DPS + 10):
        for profile, P in ((PARABOLA, P_HERTZ), (WORN, P_WORN)):
            ref = force_quad(profile, PT)
            assert abs(mpmath.mpf(sp.N(P.xreplace(PT), DPS + 10)) - ref) <= ref * mpmath.mpf(10)**-28


def test_every_rule_is_tested_here():
    tested = {ForceTermwise, ForcePiecewise, ForceSympy, PressureTermwise, PressureSwap, PressureSympy,
              GapTermwise, GapSwap, GapSympy, InverseTermwise, InverseMerged, InverseSympy}
    assert {type(r) for rules in RULES.values() for r in rules} == tested
    for transform, rules in RULES.items():
        assert all(r.transform == transform and r.__doc__ for r in rules)


# ---------------------------------------------------------------- force (10*)
@pytest.mark.parametrize("profile", [PARABOLA, POWER])
def test_force_termwise(profile):
    with mpmath.workdps(DPS + 10):
        agree(run(ForceTermwise(), Problem("force", profile)), PT, force_quad(profile, PT))
    refuses(ForceTermwise(), Problem("force", WORN))


def test_force_piecewise():
    with mpmath.workdps(DPS + 10):
        step = run(ForcePiecewise(), Problem("force", WORN))
        agree(step, PT, force_quad(WORN, PT))
        assert sp.N(step.expr.xreplace({**PT, a: sp.Rational(1, 10)})) == 0     # inside the flat
    refuses(ForcePiecewise(), Problem("force", PARABOLA))


def test_force_sympy():
    with mpmath.workdps(DPS + 10):
        agree(run(ForceSympy(), Problem("force", PARABOLA)), PT, force_quad(PARABOLA, PT))
    refuses(ForceSympy(), Problem("force", WORN))


# ---------------------------------------------------------------- pressure (12)
def test_pressure_termwise():
    P = E * c * a**sp.Rational(5, 2)
    with mpmath.workdps(DPS + 10):
        agree(run(PressureTermwise(), Problem("pressure", POWER, P)), PT, pressure_quad(P, PT))
    refuses(PressureTermwise(), Problem("pressure", WORN, P_WORN))
    with pytest.raises(NotApplicable):     # not a finite sum of powers: found before any integration
        PressureTermwise().run(Problem("pressure", COSINE, E * sp.exp(a) - E))


@pytest.mark.parametrize("profile,P", [(PARABOLA, P_HERTZ), (WORN, P_WORN)])
def test_pressure_swap(profile, P):
    with mpmath.workdps(DPS + 10):
        agree(run(PressureSwap(), Problem("pressure", profile, P)), PT, pressure_quad(P, PT))
    refuses(PressureSwap(), Problem("pressure", COSINE, P_HERTZ))


def test_pressure_sympy():
    with mpmath.workdps(DPS + 10):
        agree(run(PressureSympy(), Problem("pressure", PARABOLA, P_HERTZ)), PT, pressure_quad(P_HERTZ, PT))
    refuses(PressureSympy(), Problem("pressure", PARABOLA, P_OPEN))


# ---------------------------------------------------------------- gap (3/5)
def test_gap_termwise():
    with mpmath.workdps(DPS + 10):
        agree(run(GapTermwise(), Problem("gap", PARABOLA, P_HERTZ)), OUT, gap_quad(PARABOLA, P_HERTZ, OUT))
    refuses(GapTermwise(), Problem("gap", WORN, P_WORN))


@pytest.mark.parametrize("profile,P", [(PARABOLA, P_HERTZ), (WORN, P_WORN)])
def test_gap_swap(profile, P):
    with mpmath.workdps(DPS + 10):
        agree(run(GapSwap(), Problem("gap", profile, P)), OUT, gap_quad(profile, P, OUT))
    refuses(GapSwap(), Problem("gap", COSINE, P_HERTZ))


def test_gap_sympy():
    """SymPy integrates acosh(x/s) P'(s) for none of the force laws tried (a, a^2,
    Hertz, a^3, a^(1/2)): the rule says so (NotApplicable, never a wrong form);
    with no load the gap is the profile."""
    assert GapSympy().applies(Problem("gap", PARABOLA, P_HERTZ)) is None
    with pytest.raises(NotApplicable, match="unevaluated"):
        GapSympy().run(Problem("gap", PARABOLA, P_HERTZ))
    assert GapSympy().run(Problem("gap", PARABOLA, sp.S.Zero)).expr == PARABOLA.expr
    refuses(GapSympy(), Problem("gap", WORN, P_WORN))


def test_sympy_rules_refuse_a_rational_slope_they_cannot_close():
    """The periodic wedge's kernel twin, P = atanh(a): dP/da = 1/(1 - a^2).
    PressureSympy (an even part with a pole off a = 0: an Euler substitution)
    and GapSympy (a logarithm off a = 0: dilogarithm type) say so at once;
    before, sympy.integrate spent 10 and 7 CPU s and left both unevaluated.
    What SymPy can close stays its: the odd slope of log(1 - a^2) for the
    pressure (s/((1 - s^2) sqrt(s^2 - x^2)) closes), a slope without a
    logarithmic part (a/(1 - a)) for the gap, every power law."""
    twin = E * sp.atanh(a)
    assert "Euler substitution" in PressureSympy().applies(Problem("pressure", PARABOLA, twin))
    assert "dilogarithm" in GapSympy().applies(Problem("gap", PARABOLA, twin))
    assert "Euler substitution" in PressureSympy().applies(Problem("pressure", PARABOLA, E * sp.atan(a)))
    assert "dilogarithm" in GapSympy().applies(Problem("gap", PARABOLA, E * sp.log(1 - a**2)))
    assert PressureSympy().applies(Problem("pressure", PARABOLA, E * sp.log(1 - a**2))) is None
    assert GapSympy().applies(Problem("gap", PARABOLA, E * a / (1 - a))) is None
    for P in (P_HERTZ, E * a**3 + a, E / (1 - a**2)):
        assert PressureSympy().applies(Problem("pressure", PARABOLA, P)) is None
        assert GapSympy().applies(Problem("gap", PARABOLA, P)) is None


# ---------------------------------------------------------------- profile (9)
P_OPEN = sp.Integral(E * _t * sp.exp(_t**3) / sp.sqrt(a**2 - _t**2), (_t, 0, a))     # a force law without closed form


@pytest.mark.parametrize("rule,other", [(InverseTermwise(), P_WORN), (InverseMerged(), P_WORN),
                                        (InverseSympy(), P_OPEN)], ids=lambda r: getattr(r, "name", ""))
def test_inverse_rules(rule, other):
    with mpmath.workdps(DPS + 10):
        step = run(rule, Problem("profile", None, P_HERTZ))
        agree(step, PT, profile_quad(P_HERTZ, PT))
    refuses(rule, Problem("profile", None, other))


def test_inverse_merged_where_termwise_diverges():
    """E* R (K(m) - E(m)), m = a^2/R^2 (the exact cylinder's force law, Eq. 19):
    its hypergeometric terms diverge one by one in Eq. (9); merged they do not."""
    m = a**2 / R**2
    P = E * R * (sp.elliptic_k(m) - sp.elliptic_e(m))
    pt = {**PT, a: sp.Rational(1, 2)}
    with mpmath.workdps(DPS + 10):
        agree(run(InverseMerged(), Problem("profile", None, P)), pt, profile_quad(P, pt))


# ---------------------------------------------------------------- the helpers
def test_decompose_and_beta_kernel_against_quadrature():
    """int_0^a t^rho (a^2 - t^2)^sigma g(t) dt for g = t^(3/2) exp(t) by the
    series terms of g, against mpmath.quad."""
    g = x**sp.Rational(3, 2) * sp.exp(-x)
    terms = decompose(g, x)
    conds: list = []
    closed = sp.Add(*[beta_kernel_sum(T, 1, sp.Rational(-1, 2), a, conds) for T in terms])
    with mpmath.workdps(DPS + 10):
        A = mpmath.mpf(7) / 10
        ref = mpmath.quad(lambda p: A * mpmath.sin(p) * (A * mpmath.sin(p))**1.5 * mpmath.exp(-A * mpmath.sin(p)),
                          [0, mpmath.pi / 2])
        # the 1F2 terms evaluated as they are (mpmath's series): sp.hyperexpand first took 16 s
        # of SymPy's cancel to rewrite them and gave the same number
        got = mpmath.mpf(sp.N(closed.xreplace({a: sp.Rational(7, 10)}), DPS + 10))
        assert abs(got - ref) <= abs(ref) * mpmath.mpf(10)**-25
    with pytest.raises(NotDecomposable):
        decompose(sp.log(1 + sp.exp(x)), x)


def test_legendre_reduction_against_quadrature():
    """int_0^a t^2/sqrt(R^2 - t^2) dt/sqrt(a^2 - t^2) (elliptic) and a principal value."""
    t = sp.Symbol("t", positive=True)
    pt = {a: sp.Rational(1, 2), R: sp.Rational(3, 2), x: sp.Rational(3, 10)}
    with mpmath.workdps(DPS + 10):
        A, Rv, X = (mpmath.mpf(sp.N(pt[s], DPS + 10)) for s in (a, R, x))
        e1 = reduce_integral(t**2 / sp.sqrt(R**2 - t**2), t, a, 0, a, pt)
        r1 = mpmath.quad(lambda p: (A * mpmath.sin(p))**2 / mpmath.sqrt(Rv**2 - (A * mpmath.sin(p))**2),
                         [0, mpmath.pi / 2])
        assert abs(mpmath.mpf(sp.N(e1.xreplace(pt), DPS + 10)) - r1) <= r1 * mpmath.mpf(10)**-25
        # a pole at t = x inside: the principal value.  Independently, in t = a sin(phi) the
        # integrand F(phi) has a simple pole at phi0 = asin(x/a); folded about it,
        # F(phi0 - u) + F(phi0 + u) is smooth (Gauss-Legendre keeps away from u = 0)
        e2 = reduce_integral(t**2 / (t**2 - x**2), t, a, 0, a, pt)
        F = lambda p: (A * mpmath.sin(p))**2 / ((A * mpmath.sin(p))**2 - X**2)  # noqa: E731
        p0 = mpmath.asin(X / A)
        pv = mpmath.quad(lambda u: F(p0 - u) + F(p0 + u), [0, p0], method="gauss-legendre") \
            + mpmath.quad(F, [2 * p0, mpmath.pi / 2])
        assert abs(mpmath.mpf(sp.N(e2.xreplace(pt), DPS + 10)) - pv) <= abs(pv) * mpmath.mpf(10)**-25
    with pytest.raises(NotReducible):
        reduce_integral(sp.exp(t), t, a, 0, a, pt)


# ---------------------------------------------------------------- the limit at a tangent-continuous join
def test_join_limit_against_sympy_limit_and_its_refusals():
    """rules_swap._join_limit (the pressure's branch at a join x = b where
    the log singularities of two sides cancel) against sympy.limit on hand-made
    branches of the rounded punch's kind; where the logs do not cancel, or a
    function it does not expand appears (elliptic Pi), it gives None and the
    caller takes sympy.limit.  _logs_expanded_above then writes the logs of
    the derivatives at the join so that they cancel where a > b."""
    from linecontact_sym.method.rules_swap import _join_limit, _logs_expanded_above
    at = {a: 3, b: 1, E: 1, R: 2}
    sq = sp.sqrt(a**2 - b**2) / sp.sqrt(a**2 - x**2)
    cancel = -2 * b * sp.atanh(sq) + 2 * x * sp.atanh(x * sq / b) - 2 * sp.sqrt(a**2 - x**2) * sp.asin(b / a)
    logs = b * sp.log(b - x) - x * sp.log(b**2 - x**2) + sp.log(b + x) * x
    for e in (cancel, logs):
        lim = _join_limit(e, b, at)
        assert lim is not None and not lim.has(x)
        near = sp.N(e.xreplace({**at, x: 1 - sp.Rational(1, 10**40)}), 80)   # the branch next to the join
        assert abs(sp.N(lim.xreplace(at), 80) - near) < 1e-35
        tidy = _logs_expanded_above(lim, b)
        assert abs(sp.N((tidy - lim).xreplace(at), 40)) < 1e-35
    def singular_at_a_equal_b(e):
        return [L for L in e.atoms(sp.log) if L.args[0].xreplace({a: b}) in (0, sp.zoo)]
    assert singular_at_a_equal_b(_join_limit(cancel, b, at))                             # log(1/(a - b)) ...
    assert not singular_at_a_equal_b(_logs_expanded_above(_join_limit(cancel, b, at), b))    # ... cancelled
    assert _join_limit(b * sp.log(b - x), b, at) is None                       # an infinite limit: not cancelling
    assert _join_limit(sp.log(b - x) * sp.elliptic_pi(x / a, b / a) - sp.log(b - x), b, at) is None


def test_sympy_integrate_on_a_linear_part_of_an_asymmetric_contact_is_capped(monkeypatch):
    """ForceSympy gets AUXILIARY_SYMPY_SECONDS on an auxiliary profile (the even
    part or the odd part's integral of an asymmetric contact), the whole budget
    on an indenter; a derivation whose integrate does not end says which cap
    ended it (a busy integrate stands in for SymPy's failing one on the
    Gaussian bump's parts, 20 s of CPU each before the cap)."""
    import time
    import linecontact_sym.method.rules as R
    from linecontact_sym.method.derivation import integrate
    e = sp.Symbol("e", real=True)
    part = Profile(sp.exp(-e**2) - sp.exp(-e**2 - S.x**2) * sp.cosh(2 * e * S.x), {e: (-1, 1)},
                   name="even part", auxiliary=True)
    indenter = Profile(1 - sp.exp(-S.x**2))
    assert ForceSympy().cap(Problem("force", part)) == R.AUXILIARY_SYMPY_SECONDS
    assert ForceSympy().cap(Problem("force", indenter)) is None

    def busy(*args, **kw):
        t = time.process_time() + 60
        while time.process_time() < t:
            pass
    monkeypatch.setattr(R.sp, "integrate", busy)
    monkeypatch.setattr(R, "AUXILIARY_SYMPY_SECONDS", 0.5)
    step, attempts = integrate(Problem("force", part), 20, rules=[ForceSympy()])
    assert step is None
    assert attempts == [("force_sympy", "no result within 0.5 CPU s (the rule's cap here)")], attempts
