"""Every stable rewrite, and every stable special function, on its own.

For each rule of ``linecontact_sym.numeric.stable.RULES``: it fires on its
pattern (and the result is the same function: 50-digit mpmath at a random
point), it leaves a non-matching expression alone, and at an argument where
the float64 translation of the original loses digits the float64 value of
the rewritten form is accurate -- both compared with the ORIGINAL expression
evaluated by SymPy/mpmath at 50 digits at the same (exactly representable)
arguments.  For each special primitive: its float64 and mpmath
implementations against mpmath's own functions (or exact values) at high
precision.
"""
from __future__ import annotations

import math
import random

import mpmath
import numpy as np
import pytest
import sympy as sp

from linecontact_sym.numeric import stable as ST
from linecontact_sym.numeric import special
from linecontact_sym.numeric.exports import lambdify_numpy
from linecontact_sym.numeric.special import (MPMATH_FUNCS, NUMPY_FUNCS, carlson_rd, carlson_rf, carlson_rg,
                                             carlson_rj, gamma_ratio, hyp2f1c, mp_elliptic_pi, np_gamma_ratio,
                                             np_hyp2f1c, np_rd, np_rf, np_rg, np_rj)

a, x, R, n, c = sp.symbols("a x R n c", positive=True)
half = sp.S.Half
EPS = 2.0**-52


# ----------------------------------------------------------------- helpers
def reference(expr, point, dps=50):
    """``expr`` at ``point`` (symbol -> float, taken exactly) with SymPy at ``dps`` digits."""
    vals = {s: sp.Rational(v) if isinstance(v, float) else sp.sympify(v) for s, v in point.items()}
    v = sp.N(expr.xreplace(vals), dps)
    assert v.is_real and v.is_finite, f"reference of {expr} at {point} is {v}"
    with mpmath.workdps(dps):
        return mpmath.mpf(v)


def float64(expr, point):
    """The plain float64 translation of ``expr`` (no stable rewriting) at ``point``."""
    syms = list(point)
    with np.errstate(all="ignore"):
        return float(lambdify_numpy(expr, syms, stable=False)(*[point[s] for s in syms]))


def rel_error(value, ref):
    if not math.isfinite(value):
        return math.inf
    with mpmath.workdps(50):
        return float(abs((mpmath.mpf(value) - ref) / ref))


def assert_same_function(old, new, ranges, seed=3):
    """old == new at 50 digits at two random points of ``ranges`` (symbol -> (lo, hi))."""
    rng = random.Random(seed)
    for _ in range(2):
        pt = {s: rng.uniform(lo, hi) for s, (lo, hi) in ranges.items()}
        r_old, r_new = reference(old, pt), reference(new, pt)
        with mpmath.workdps(50):
            assert abs(r_new - r_old) <= mpmath.mpf(10) ** -45 * abs(r_old), (pt, r_old, r_new)


def check_rule(rule, expr, point, ranges, lost, kept, ref_point=None):
    """The rule fires on ``expr``; same function; at ``point`` the plain
    float64 of ``expr`` has a relative error above ``lost`` and that of the
    rewritten form below ``kept`` (reference: ``expr`` at 50 digits, at
    ``ref_point`` if given -- for a removable singularity, a point 1e-30 away)."""
    assert rule.applies(expr)
    new = rule.apply(expr)
    assert new != expr, f"{rule.name} did not fire on {expr}"
    assert_same_function(expr, new, ranges)
    ref = reference(expr, ref_point or point)
    err_old = rel_error(float64(expr, point), ref)
    err_new = rel_error(float64(new, point), ref)
    assert err_old > lost, f"the original does not lose digits here ({err_old:.1e}): a useless test point"
    assert err_new < kept, f"{rule.name}: rewritten form off by {err_new:.1e} (original {err_old:.1e})"
    return new


# ----------------------------------------------------------------- the rule set
def test_rules_are_named_documented_and_ordered():
    names = [r.name for r in ST.RULES]
    assert names == ["elliptic-pi/incomplete->carlson", "elliptic->carlson", "hyp2f1-connection", "gamma-absorb",
                     "gamma-ratio", "acosh-excess", "square-differences", "atanh->asinh", "acosh->asinh", "asinh-excess", "asin->atan", "acos->atan",
                     "hyp2f1-complement", "conjugate", "log-of-power", "half-angle", "exp-tail", "factor",
                     "sin-pi-reduction"]
    for r in ST.RULES:
        assert isinstance(r, ST.StableRule)
        assert type(r).__doc__ and "=" in type(r).__doc__, f"{r.name}: the docstring states no identity"


def test_rule_without_its_head_is_not_tried():
    expr = sp.sin(x) + a
    for r in ST.RULES:
        if r.heads:
            assert not r.applies(expr), r.name
        assert r.apply(expr) == expr, r.name


# ----------------------------------------------------------------- one test per rule
def test_elliptic_to_carlson():
    """K(m) - E(m) = (m/3) R_D(0, 1 - m, 1), m = a^2/R^2: no cancellation at a/R = 1e-5."""
    expr = sp.elliptic_k(a**2 / R**2) - sp.elliptic_e(a**2 / R**2)
    new = check_rule(ST.EllipticToCarlson(), expr, {a: 1e-5, R: 1.0}, {a: (0.1, 0.9), R: (1.0, 1.0)},
                     lost=1e-8, kept=4 * EPS)
    assert new == a**2 * carlson_rd(0, (R - a) * (R + a) / R**2, 1) / (3 * R**2)
    # K and E alone: R_F and 2 R_G
    assert ST.EllipticToCarlson().apply(sp.elliptic_e(a**2 / R**2)) == 2 * carlson_rg(0, (R - a) * (R + a) / R**2, 1)
    # not its pattern: an incomplete integral E(phi|m)
    inc = sp.elliptic_e(x, a**2 / R**2)
    assert ST.EllipticToCarlson().apply(inc) == inc


def test_hyp2f1_connection():
    """The power-law gap's c*x**n against the x**n part of the 2F1 about z = 1:
    the connection formula makes the cancellation exact (one term left).  Its
    output is finished by FactorDifferences in stabilize(); with it, float64
    is accurate at x = a(1 + 1e-8) where the original loses 8 digits."""
    rule = ST.Hyp2f1Connection()
    expr = c * x**n - a**n * c * sp.gamma(n / 2 + half) / (sp.sqrt(sp.pi) * sp.gamma(n / 2 + 1)) \
        * sp.hyper([half, n / 2], [n / 2 + 1], a**2 / x**2)
    assert rule.applies(expr)
    new = rule.apply(expr)
    assert len(sp.Add.make_args(new)) == 1 and len(sp.Add.make_args(sp.expand(expr))) == 2
    assert_same_function(expr, new, {a: (0.5, 1.0), x: (1.2, 3.0), n: (0.5, 4.0), c: (0.5, 2.0)})
    pt = {a: 1.0, x: 1.00000001, n: 3.0, c: 1.3}
    ref = reference(expr, pt)
    assert rel_error(float64(expr, pt), ref) > 1e-10
    finished = ST.FactorDifferences().apply(new)
    assert rel_error(float64(finished, pt), ref) < 8 * EPS
    # not its pattern: c - a - b an integer (no connection formula of this form),
    # and a lone 2F1 whose connection formula cancels nothing
    for other in (sp.hyper([1, 1], [2], a / x), sp.hyper([half, sp.Rational(3, 2)], [sp.Rational(5, 2)], a**2 / x**2)):
        assert rule.apply(other) == other



def test_hyp2f1_connection_of_a_sum_of_three_powers_is_fast():
    """The gap of f = x**(2/7) + x**(1/4) + x**(14/5) (issue 26): each x**n
    cancels against its 2F1 as in the single power law.  gammasimp of the
    whole connected sum factored it over all its powers and radicals (minutes,
    the scalar gap evaluator hung); term by term it takes a fraction of a
    second.  Run under a CPU budget, so a return of the slow path fails."""
    from linecontact_sym.core.budget import run_with_budget
    ns = (sp.Rational(2, 7), sp.Rational(1, 4), sp.Rational(14, 5))

    def k(m):       # a**m Gamma((m + 1)/2)/(sqrt(pi) Gamma(m/2)), Gammas of arguments in (0, 1) as gap_termwise writes them
        return sp.expand_func(a**m * sp.gamma((m + 1) / 2) / (sp.sqrt(sp.pi) * sp.gamma(m / 2)))
    expr = sum(x**m - 2 * k(m) * sp.acosh(x / a) - 2 / m * k(m) * sp.hyper([m / 2, half], [m / 2 + 1], a**2 / x**2)
               for m in ns)
    new = run_with_budget(ST.Hyp2f1Connection().apply, expr, seconds=10)
    assert len(sp.Add.make_args(new)) == 6 and len(sp.Add.make_args(sp.expand(expr))) == 9
    assert_same_function(expr, new, {a: (0.5, 1.0), x: (1.2, 3.0)})

def test_gamma_absorb():
    """(n - 1) Gamma(n/2 - 1/2) = 2 Gamma(n/2 + 1/2): 0 * inf (NaN) at n = 1 removed."""
    rule = ST.GammaAbsorb()
    expr = (n - 1) * sp.gamma(n / 2 - half)
    new = check_rule(rule, expr, {n: 1.0}, {n: (1.5, 4.0)}, lost=1.0, kept=2 * EPS,
                     ref_point={n: sp.Integer(1) + sp.Rational(1, 10**30)})
    assert new == 2 * sp.gamma(n / 2 + half)
    other = (n + 1) * sp.gamma(n)          # (n + 1)/n is no number
    assert rule.apply(other) == other


def test_gamma_ratio():
    """Gamma(n/2 + 1)/Gamma(n/2 + 1/2) = gamma_ratio(...): both overflow at n = 1000."""
    rule = ST.GammaRatio()
    expr = sp.gamma(n / 2 + 1) / sp.gamma(n / 2 + half)
    new = check_rule(rule, expr, {n: 1000.0}, {n: (1.0, 30.0)}, lost=1.0, kept=4 * EPS)
    assert new == gamma_ratio(n / 2 + 1, n / 2 + half)
    other = sp.gamma(n) / sp.gamma(2 * n)   # the difference of the arguments is no number
    assert rule.apply(other) == other


def test_atanh_to_asinh():
    """atanh(sqrt(a^2 - x^2)/a) = asinh(sqrt(a^2 - x^2)/x): atanh(1.0) = inf at x = 1e-9 a."""
    rule = ST.AtanhToAsinh()
    expr = sp.atanh(sp.sqrt(a**2 - x**2) / a)
    check_rule(rule, expr, {a: 1.0, x: 1e-9}, {a: (1.0, 2.0), x: (0.1, 0.9)}, lost=1.0, kept=4 * EPS)
    other = sp.atanh(sp.exp(-x))           # 1 - exp(-2x) is not a rational function
    assert rule.apply(other) == other
    # 1 - sin^2 = cos^2 (square-differences inside stable_sqrt): the periodic wedge's atanh(sin(pi a/L))
    # at a -> L/2, where atanh(1.0) = inf
    check_rule(rule, sp.atanh(sp.sin(sp.pi * a)), {a: 0.5 - 1e-12}, {a: (0.05, 0.45)}, lost=1e-6, kept=1e-3)


def test_square_differences():
    """sin^2(pi a) - sin^2(pi x) = sin(pi (a - x)) sin(pi (a + x)): the periodic kernel's S^2 - s^2,
    which cancels at the contact edge x -> a and near full contact a -> 1/2 (a 6 % error at
    a = 1/2 - 1e-7, x = (1 - 1e-9) a in the sinusoid array's pressure)."""
    rule = ST.SquareDifferences()
    expr = sp.sqrt(sp.sin(sp.pi * a)**2 - sp.sin(sp.pi * x)**2)
    new = check_rule(rule, expr, {a: 0.5 - 1e-7, x: (0.5 - 1e-7) * (1 - 1e-9)}, {a: (0.3, 0.45), x: (0.05, 0.25)},
                     lost=1e-3, kept=1e-9)
    assert new == sp.sqrt(sp.sin(sp.pi * (a - x)) * sp.sin(sp.pi * (a + x)))
    # the other pairs, and a sum without a pair left as it is
    assert rule.apply(sp.cos(a)**2 - sp.cos(x)**2) == -sp.sin(a - x) * sp.sin(a + x)
    assert rule.apply(sp.cosh(a)**2 - sp.cosh(x)**2) == sp.sinh(a - x) * sp.sinh(a + x)
    assert rule.apply(1 - sp.sin(x)**2) == sp.cos(x)**2
    assert rule.apply(sp.sin(a)**2 + sp.sin(x)**2) == sp.sin(a)**2 + sp.sin(x)**2


def test_acosh_to_asinh():
    """acosh(a/x) = asinh(sqrt((a - x)(a + x))/x): accurate at x = a(1 - 1e-12)."""
    rule = ST.AcoshToAsinh()
    expr = sp.acosh(a / x)
    check_rule(rule, expr, {a: 1.0, x: 0.999999999999}, {a: (1.0, 2.0), x: (0.1, 0.9)},
               lost=1e-6, kept=4 * EPS)
    other = sp.acosh(sp.exp(x))
    assert rule.apply(other) == other


def test_asinh_excess():
    """s t - S^2 asinh(t/S), t = sqrt((x - a)(x + a)), S = a: the parabola's (and, in
    sines, the periodic array's) gap after acosh->asinh, whose terms cancel to
    2 t^3/(3 S) at the contact edge: at x = a (1 + 1e-14) the plain float64 keeps
    two digits, the rewritten one (asinh_excess, its series) 4 eps; a pair whose
    first term is not S^2 w sqrt(1 + w^2) is left alone."""
    rule = ST.AsinhExcess()
    t_ = sp.sqrt((x - a) * (x + a))
    expr = x * t_ - a**2 * sp.asinh(t_ / a)
    new = check_rule(rule, expr, {a: 1.0, x: 1 + 1e-14}, {a: (0.1, 0.9), x: (1.0, 2.0)}, lost=1e-3, kept=4 * EPS)
    assert new.has(ST.asinh_excess) and not new.has(sp.asinh)
    other = 2 * x * t_ - a**2 * sp.asinh(t_ / a)
    assert rule.apply(other) == other


def test_acosh_excess_any_weights():
    """x t (a^2 + 2 x^2) - 3 a^4 acosh(x/a), t = sqrt((x - a)(x + a)): the sin^4 array's
    gap in s = x, S = a, whose three terms cancel to 2 x t^3 + 2 t^3 a at the contact
    edge (no single term is the partner of the acosh: asinh-excess's pair search finds
    none): rewritten 2 x t^3 + 3 a^4 asinh_excess(t/a); at x = a (1 + 1e-12) the plain
    float64 keeps a few digits, the rewritten one 8 eps.  The sinusoid's pair is the
    case where nothing is left besides the excess; a sum where nothing cancels is left."""
    rule = ST.AcoshExcess()
    t_ = sp.sqrt((x - a) * (x + a))
    expr = x * t_ * (a**2 + 2 * x**2) - 3 * a**4 * sp.acosh(x / a)
    new = check_rule(rule, expr, {a: 1.0, x: 1 + 1e-12}, {a: (0.1, 0.9), x: (1.0, 2.0)}, lost=1e-6, kept=8 * EPS)
    assert new.has(ST.asinh_excess) and not new.has(sp.acosh)
    assert ST.AsinhExcess().apply(ST.AcoshToAsinh().apply(expr)).has(sp.asinh)     # the pair rule alone: not
    assert rule.apply(x * t_ - a**2 * sp.acosh(x / a)) == a**2 * ST.asinh_excess(t_ / a)
    other = 2 * x * t_ - a**2 * sp.acosh(x / a)
    assert rule.apply(other) == other


def test_sin_pi_reduction():
    """sin(pi (a + x)/L) sin(pi (a - x)/L) cos(pi x/L): a periodic array's kernel near
    full contact; at a = 1/2 - 1e-7, x = (1 - 1e-9) a (L = 1) the sine of the rounded
    pi (a + x) (near pi) and the cosine near pi/2 keep ~9 digits, sin_pi_sum (the
    multiple of L taken off the exact sum) 4 eps.  An argument that is not pi times a
    sum of multiples of symbols over L is left alone."""
    L = sp.Symbol("L", positive=True)
    rule = ST.SinPiReduction()
    expr = sp.sin(sp.pi * (a + x) / L) * sp.sin(sp.pi * (a - x) / L) * sp.cos(sp.pi * x / L)
    av = 0.5 - 1e-7
    new = check_rule(rule, expr, {a: av, x: av * (1 - 1e-9), L: 1.0}, {a: (0.1, 0.4), x: (0.0, 0.1), L: (1.0, 2.0)},
                     lost=1e-10, kept=4 * EPS)
    assert not new.has(sp.sin, sp.cos) and new.has(special.sin_pi_sum)
    for other in (sp.sin(x), sp.sin(sp.pi * x**2 / L), sp.cos(sp.pi * sp.exp(x) / L)):
        assert rule.apply(other) == other


def test_sin_pi_sum_primitive():
    """np_sin_pi_sum (and the scalar path's copy of its operations) against mpmath's
    sine of the exact sum (40 digits) near every multiple of L in [-2L, 2L] and away
    from them, arrays and scalars; its mpmath version; its derivative."""
    from linecontact_sym.numeric.special import np_sin_pi_sum, sin_pi_sum_scalar
    rng = random.Random(5)
    for _ in range(200):
        k, L = rng.randint(-2, 2), rng.choice([1.0, 0.75, 3.0])
        a_ = rng.uniform(0, 1) * L
        x_ = k * L - a_ + rng.choice([1e-12, -3e-9, 1e-7, 0.3]) * L
        got = float(np_sin_pi_sum(L, a_, x_))
        assert sin_pi_sum_scalar(L, a_, x_) == got            # the scalar path: the same operations
        with mpmath.workdps(40):
            ref = mpmath.sin(mpmath.pi * (mpmath.mpf(a_) + mpmath.mpf(x_)) / mpmath.mpf(L))
            assert abs(got - ref) <= 4 * EPS * abs(ref), (k, L, a_, x_, got, ref)
            assert abs(MPMATH_FUNCS["sin_pi_sum"](mpmath.mpf(L), mpmath.mpf(a_), mpmath.mpf(x_)) - ref) < \
                mpmath.mpf(10)**-35 * max(abs(ref), mpmath.mpf(10)**-30)
    arr = np_sin_pi_sum(1.0, np.array([0.25, 0.5]), 0.5)
    assert arr.shape == (2,) and abs(arr[0] - math.sin(0.75 * math.pi)) < 4 * EPS and abs(arr[1]) < 1e-300
    L = sp.Symbol("L", positive=True)
    f = special.sin_pi_sum(L, a, x)
    assert sp.simplify(sp.diff(f, a) - sp.diff(sp.sin(sp.pi * (a + x) / L), a)) == 0
    assert sp.simplify(sp.diff(f, L) - sp.diff(sp.sin(sp.pi * (a + x) / L), L)) == 0


def test_asinh_excess_primitive_against_the_plain_form():
    """float64 asinh_excess(w) (series below 1/4, the two terms above) and the mpmath
    one against w sqrt(1 + w^2) - asinh(w) at 400 digits, w from 1e-100 to 1e10."""
    from linecontact_sym.numeric.special import np_asinh_excess
    ws = [1e-100, 1e-20, 1e-8, 1e-3, 0.1, 0.2499999, 0.25, 0.5, 1.0, 3.0, 1e3, 1e10]
    got = np_asinh_excess(np.array(ws))
    for w, g in zip(ws, got):
        with mpmath.workdps(400):          # the plain form keeps 400 - 2 log10(1/w) digits
            W = mpmath.mpf(w)
            ref = W * mpmath.sqrt(1 + W * W) - mpmath.asinh(W)
            assert abs(g / ref - 1) < 4 * EPS, (w, g, ref)
        assert abs(float(np_asinh_excess(-w)) + g) <= 4 * EPS * abs(g)         # odd
        with mpmath.workdps(30):
            assert abs(MPMATH_FUNCS["asinh_excess"](mpmath.mpf(w)) / ref - 1) < mpmath.mpf(10)**-29


def test_asin_to_atan():
    """asin(x/a) = atan(x/sqrt((a - x)(a + x))): accurate at x = a(1 - 1e-12),
    where the rounding of x/a costs asin five digits (a = 3: x/a is not exact)."""
    rule = ST.AsinToAtan()
    expr = sp.asin(x / a)
    new = check_rule(rule, expr, {a: 3.0, x: 3 * (1 - 1e-12)}, {a: (1.0, 2.0), x: (0.1, 0.9)},
                     lost=1e-12, kept=4 * EPS)
    assert new.has(sp.atan) and not new.has(sp.pi)
    other = sp.asin(sp.sin(x))
    assert rule.apply(other) == other


def test_asin_to_atan_complement_form():
    """pi x - 2 x asin(a/x) = 2 x atan(sqrt((x - a)(x + a))/a): the pi/2 cancels
    exactly; at x = a(1 + 1e-12), a = 3, the original loses five digits to the
    cancellation of pi/2 against asin(1 - 1e-12) ~ pi/2 - 1.4e-6."""
    rule = ST.AsinToAtan()
    expr = sp.pi * x - 2 * x * sp.asin(a / x)
    new = check_rule(rule, expr, {a: 3.0, x: 3 * (1 + 1e-12)}, {a: (0.2, 1.0), x: (1.1, 3.0)},
                     lost=1e-11, kept=4 * EPS)
    assert not new.has(sp.pi) and len(sp.Add.make_args(new)) == 1


def test_acos_to_atan():
    """acos(x/a) = atan(sqrt((a - x)(a + x))/x): accurate at x = a(1 - 1e-12),
    where the rounding of x/a (a = 3) costs acos ~ sqrt(2e-12) five digits."""
    rule = ST.AcosToAtan()
    expr = sp.acos(x / a)
    check_rule(rule, expr, {a: 3.0, x: 3 * (1 - 1e-12)}, {a: (1.0, 2.0), x: (0.1, 0.9)},
               lost=1e-6, kept=4 * EPS)
    other = sp.acos(sp.sin(x))
    assert rule.apply(other) == other


def test_hyp2f1_complement():
    """2F1(1/2, 1/2; 3/2; 1 - x^2/a^2) = asin(w)/w, w = sqrt(1 - x^2/a^2): at
    x = 1e-9 a the argument rounds to 1 and the original loses 9 digits;
    hyp2f1c receives 1 - z = x^2/a^2 exactly."""
    rule = ST.Hyp2f1Complement()
    expr = sp.hyper([half, half], [sp.Rational(3, 2)], 1 - x**2 / a**2)
    new = check_rule(rule, expr, {a: 1.0, x: 1e-9}, {a: (1.0, 2.0), x: (0.1, 0.9)},
                     lost=1e-11, kept=4 * EPS)
    assert new == hyp2f1c(half, half, sp.Rational(3, 2), 1 - x**2 / a**2, x**2 / a**2)
    other = sp.hyper([half, half], [sp.Rational(3, 2)], sp.Rational(1, 2))   # a number, no symbol
    assert rule.apply(other) == other


def test_conjugate():
    """R - sqrt(R^2 - x^2) = x^2/(R + sqrt(R^2 - x^2)): 0 instead of 5e-19 at x = 1e-9 R."""
    rule = ST.Conjugate()
    expr = R - sp.sqrt(R**2 - x**2)
    new = check_rule(rule, expr, {R: 1.0, x: 1e-9}, {R: (1.0, 2.0), x: (0.1, 0.9)}, lost=0.5, kept=4 * EPS)
    assert new == x**2 / (R + sp.sqrt(R**2 - x**2))
    other = R + sp.sqrt(R**2 - x**2)       # a sum, nothing cancels
    assert rule.apply(other) == other


def test_elliptic_pi_to_carlson():
    """Pi(n|m) = R_F(0, 1 - m, 1) + (n/3) R_J(0, 1 - m, 1, 1 - n) (no SciPy
    ellippi: the plain translation has nothing to call); the incomplete
    integrals with s = sin(phi) = x/a: F, E, Pi against mpmath at 50 digits."""
    rule = ST.EllipticPiToCarlson()
    expr = sp.elliptic_pi(x**2 / R**2, a**2 / R**2)
    new = rule.apply(expr)
    assert new == carlson_rf(0, (R - a) * (R + a) / R**2, 1) \
        + x**2 * carlson_rj(0, (R - a) * (R + a) / R**2, 1, (R - x) * (R + x) / R**2) / (3 * R**2)
    assert_same_function(expr, new, {x: (0.1, 0.4), a: (0.5, 0.9), R: (1.0, 1.5)})
    # near m = 1 (a = R (1 - 1e-12)): float64 of the Carlson form to a few eps
    pt = {x: 0.5, a: 1 - 1e-12, R: 1.0}
    assert rel_error(float64(new, pt), reference(expr, pt)) < 8 * EPS
    for inc in (sp.elliptic_f(sp.asin(x / a), R**2 / a**2 / 4), sp.elliptic_e(sp.asin(x / a), R**2 / a**2 / 4),
                sp.elliptic_pi(x**2 / a**2 / 2, sp.asin(x / a), R**2 / a**2 / 4)):
        new = rule.apply(inc)
        assert not new.has(sp.elliptic_f, sp.elliptic_e, sp.elliptic_pi)
        assert_same_function(inc, new, {x: (0.1, 0.9), a: (1.0, 1.0), R: (0.5, 1.5)})
        pt = {x: 1 - 1e-12, a: 1.0, R: 1.0}            # phi -> pi/2: cos(phi)^2 formed exactly
        assert rel_error(float64(new, pt), reference(inc, pt)) < 8 * EPS
    assert rule.apply(sp.elliptic_k(a)) == sp.elliptic_k(a)


def test_log_of_power():
    """log(b**(2b)/a**(2b)) = 2 b log(b/a): at b = 1e-12 a the power is
    1 - 5.5e-11 and its logarithm keeps 5 digits; the rewritten form all."""
    rule = ST.LogOfPower()
    bb = sp.Symbol("b", positive=True)
    expr = sp.log(bb**(2 * bb) / a**(2 * bb))
    new = check_rule(rule, expr, {bb: 1e-12, a: 1.0}, {bb: (0.1, 0.9), a: (1.0, 2.0)}, lost=1e-8, kept=4 * EPS)
    assert sp.simplify(new - 2 * bb * sp.log(bb / a)) == 0
    other = sp.log(a + bb)
    assert rule.apply(other) == other


def test_half_angle():
    """R (cosh(x/R) - 1) = 2 R sinh(x/(2R))^2: every digit at x = 1e-9 R (the
    plain form has none)."""
    rule = ST.HalfAngle()
    expr = R * (sp.cosh(x / R) - 1)
    new = check_rule(rule, sp.expand(expr), {R: 1.0, x: 1e-9}, {R: (1.0, 2.0), x: (0.1, 0.9)}, lost=1e-3,
                     kept=4 * EPS)
    assert new == 2 * R * sp.sinh(x / (2 * R))**2
    assert rule.apply(1 - sp.cos(x)) == 2 * sp.sin(x / 2)**2
    other = sp.cosh(x) + 1                   # nothing cancels
    assert rule.apply(other) == other


def test_exp_tail():
    """c tau^2 (t/tau - 1 + exp(-t/tau)) = c tau^2 exp_tail(2, -t/tau) (the Lee-Radok force of a
    parabola on a Maxwell term): every digit at t = 1e-9 tau (the plain form has none);
    the longest run of series terms present is taken (n = 3 here), and expm1 is n = 1."""
    rule = ST.ExpTail()
    w = -x / R
    expr = sp.expand(c * R**2 * (x / R - 1 + sp.exp(-x / R)))
    new = check_rule(rule, expr, {R: 1.0, x: 1e-9, c: 1.0}, {R: (1.0, 2.0), x: (0.1, 0.9), c: (1.0, 2.0)},
                     lost=1e-3, kept=4 * EPS)
    assert new == c * R**2 * special.exp_tail(2, w)
    three = sp.expand(c * (sp.exp(w) - 1 - w - w**2 / 2)) + a
    assert rule.apply(three) == a + c * special.exp_tail(3, w)
    assert rule.apply(sp.exp(x) - 1) == special.exp_tail(1, x)
    other = sp.exp(x) + 1                    # nothing cancels
    assert rule.apply(other) == other


def test_exp_tail_primitive():
    """float64 exp_tail(n, z) against mpmath's exp(z) - sum z^k/k! at 60 digits
    over z in +-[1e-300, 700], n = 0..6: within 8 eps (sign changes of z: the
    Kummer series for z < 0, the plain difference for |z| large)."""
    worst = 0.0
    zs = [s_ * 10.0**e for e in np.linspace(-300, 2.8, 90) for s_ in (1, -1)]
    for n_ in range(7):
        got = special.np_exp_tail(n_, np.array(zs))
        assert all(special.exp_tail_scalar(n_, z_) == pytest.approx(g, rel=4 * EPS, abs=1e-300)
                   for z_, g in zip(zs[::7], got[::7]) if np.isfinite(g))     # the scalar path's twin
        for z_, g in zip(zs, got):
            # the plain difference at enough digits to absorb its cancellation (~ n |log10 z| for |z| < 1)
            with mpmath.workdps(60 + int(n_ * max(0.0, -math.log10(abs(z_))))):
                zz = mpmath.mpf(z_)
                ref = mpmath.exp(zz) - mpmath.fsum(zz**k / mpmath.factorial(k) for k in range(n_))
            if ref == 0 or not (1e-300 < abs(ref) < 1e300):
                continue
            worst = max(worst, float(abs((g - ref) / ref)) / EPS)
    assert worst < 8, worst
    assert float(special.np_exp_tail(2, -1e-10)) == pytest.approx(5e-21 * (1 - 1e-10 / 3), rel=1e-15)
    assert sp.diff(special.exp_tail(3, x), x) == special.exp_tail(2, x)
    e8 = sp.Rational(1, 10**8)                # evalf through mpmath: exp(-e8) - 1 + e8 = e8^2/2 - e8^3/6 + ...
    series = sum((-e8)**k / sp.factorial(k) for k in range(2, 6))
    assert abs(sp.N(special.exp_tail(2, -e8), 30) / series - 1) < 1e-28


def test_factor_differences():
    """sqrt(a^2 - x^2) = sqrt(a - x) sqrt(a + x): at x = a(1 - 1e-12), a = 7.5,
    the rounded squares leave 4 digits."""
    rule = ST.FactorDifferences()
    expr = sp.sqrt(a**2 - x**2)
    xv = 7.5 * (1 - 1e-12)
    new = check_rule(rule, expr, {a: 7.5, x: xv}, {a: (1.0, 2.0), x: (0.1, 0.9)}, lost=1e-8, kept=4 * EPS)
    assert new == sp.sqrt(a - x) * sp.sqrt(a + x)
    for other in (a + x, sp.sqrt(a**2 + x**2)):   # nothing to factor
        assert rule.apply(other) == other


def test_stabilize_chains_the_rules_and_records_them():
    expr = sp.atanh(sp.sqrt(a**2 - x**2) / a) + R - sp.sqrt(R**2 - x**2)
    form = ST.stabilize(expr, conditions=(x < a, a < R))
    assert [nm for nm, _ in form.rewrites] == ["atanh->asinh", "conjugate", "factor"]
    assert not form.rejected
    assert form.expr == x**2 / (R + sp.sqrt(R - x) * sp.sqrt(R + x)) + sp.asinh(sp.sqrt(a - x) * sp.sqrt(a + x) / x)


def test_stabilize_rejects_a_rewrite_that_is_not_an_identity(monkeypatch):
    """The numeric re-check can fail: a bogus rule is recorded as rejected, not applied."""
    class Bogus(ST.StableRule):
        """sin(x) = x (false)."""
        name = "bogus"
        heads = (sp.sin,)

        def apply(self, expr):
            return expr.replace(lambda e: isinstance(e, sp.sin), lambda e: e.args[0])
    monkeypatch.setattr(ST, "RULES", (Bogus(),))
    form = ST.stabilize(sp.sin(x) + a)
    assert form.expr == sp.sin(x) + a and not form.rewrites
    assert [nm for nm, _ in form.rejected] == ["bogus"] and "values differ" in form.rejected[0][1]


# ----------------------------------------------------------------- the special primitives
@pytest.mark.parametrize("args", [(0.0, 1e-12, 1.0), (0.0, 0.3, 1.0), (0.0, 1 - 1e-10, 1.0), (0.0, 1.0, 1.0),
                                  (0.5, 1.2, 2.0), (1e-3, 4.0, 0.25)])
def test_carlson_against_mpmath(args):
    with mpmath.workdps(50):
        ref = {"rf": mpmath.elliprf(*args), "rd": mpmath.elliprd(*args), "rg": mpmath.elliprg(*args)}
        for key, f64, sym in (("rf", np_rf, carlson_rf), ("rd", np_rd, carlson_rd), ("rg", np_rg, carlson_rg)):
            got = float(f64(*[np.float64(t) for t in args]))
            assert abs(got - ref[key]) <= 4 * EPS * abs(ref[key]), (key, args, got, ref[key])
            mp = MPMATH_FUNCS[f"carlson_{key}"](*[mpmath.mpf(t) for t in args])
            assert abs(mp - ref[key]) <= mpmath.mpf(10) ** -45 * abs(ref[key]), (key, args)
            ev = sp.N(sym(*[sp.Rational(t) for t in args]), 40)
            assert abs(mpmath.mpf(ev) - ref[key]) <= mpmath.mpf(10) ** -38 * abs(ref[key]), (key, args)


@pytest.mark.parametrize("args", [(0.0, 1e-12, 1.0, 0.5), (0.0, 0.3, 1.0, 1e-10), (0.5, 1.2, 2.0, 3.0),
                                  (0.0, 1 - 1e-10, 1.0, 1.0)])
def test_carlson_rj_against_mpmath(args):
    with mpmath.workdps(50):
        ref = mpmath.elliprj(*args)
        got = float(np_rj(*[np.float64(t) for t in args]))
        assert abs(got - ref) <= 4 * EPS * abs(ref), (args, got, ref)
        assert abs(MPMATH_FUNCS["carlson_rj"](*[mpmath.mpf(t) for t in args]) - ref) <= mpmath.mpf(10) ** -45 * ref
        ev = sp.N(carlson_rj(*[sp.Rational(t) for t in args]), 40)
        assert abs(mpmath.mpf(ev) - ref) <= mpmath.mpf(10) ** -38 * abs(ref)


def test_mp_elliptic_pi_beyond_one_is_fast_and_equal():
    """Pi(n|m) for n > 1 by its principal value and mpmath's imaginary part
    (mpmath's ellippi integrates numerically there: seconds at 30 digits)."""
    import time
    with mpmath.workdps(30):
        n_, m_ = mpmath.mpf("2.5"), mpmath.mpf("0.3")
        t0 = time.perf_counter()
        got = mp_elliptic_pi(n_, m_)
        assert time.perf_counter() - t0 < 0.5
        with mpmath.workdps(20):
            ref = mpmath.ellippi(2.5, 0.3)
        assert abs(got - ref) < 1e-14 * abs(ref)


def test_carlson_complete_case_is_vectorised():
    y = np.array([1e-12, 1e-6, 0.1, 0.5, 0.9, 1 - 1e-9, 1.0])
    got = np_rd(np.zeros_like(y), y, np.ones_like(y))
    with mpmath.workdps(40):
        for yi, gi in zip(y, got):
            r = mpmath.elliprd(0, yi, 1)
            assert abs(gi - r) <= 4 * EPS * r


@pytest.mark.parametrize("u,v", [(1000.5, 1000.0), (1e6 + 0.5, 1e6), (171.5, 170.0), (3.5, 2.0), (12.25, 10.0),
                                 (0.5, 2.5)])
def test_gamma_ratio_against_mpmath(u, v):
    with mpmath.workdps(50):
        ref = mpmath.gammaprod([u], [v])
        got = float(np_gamma_ratio(u, v))
        assert abs(got - ref) <= 8 * EPS * abs(ref), (u, v, got, ref)
        assert abs(MPMATH_FUNCS["gamma_ratio"](mpmath.mpf(u), mpmath.mpf(v)) - ref) <= mpmath.mpf(10)**-45 * ref


def test_gamma_ratio_exact_for_integers():
    """Gamma(k + 2)/Gamma(k) = k (k + 1) exactly, for arguments where both gammas overflow."""
    for k in (200, 1000, 10**5):
        got = float(np_gamma_ratio(float(k + 2), float(k)))
        assert abs(got / (k * (k + 1)) - 1) <= 8 * EPS
    assert abs(sp.N(gamma_ratio(1002, 1000), 30) - 1001 * 1000) < 1e-20


@pytest.mark.parametrize("abc", [(0.5, 0.5, 1.5), (0.5, 1.5, 2.5), (1.0, 2.0, 1.5), (0.25, 0.5, 1.0),
                                 (0.5, 0.5, 1.0), (1.5, 2.0, 3.0)])
@pytest.mark.parametrize("zc", [1e-14, 1e-8, 1e-3, 0.3])
def test_hyp2f1c_near_one(abc, zc):
    """2F1(a, b; c; 1 - zc) for zc down to 1e-14 (z itself rounds to 1 - zc
    with an error of up to 1e-16, i.e. 100% of zc): against mpmath at z = 1 - zc exactly."""
    A, B, C = abc
    with mpmath.workdps(60):
        ref = mpmath.hyp2f1(A, B, C, 1 - mpmath.mpf(zc))
        got = float(np_hyp2f1c(A, B, C, 1 - zc, zc))
        tol = 16 * EPS * max(1.0, float(abs(mpmath.log(zc))))
        assert abs(got - ref) <= tol * abs(ref), (abc, zc, got, ref)
        mp = MPMATH_FUNCS["hyp2f1c"](*[mpmath.mpf(t) for t in (A, B, C, 1 - zc, zc)])
        assert abs(mp - ref) <= mpmath.mpf(10) ** -40 * abs(ref)


def test_numpy_and_mpmath_tables_cover_every_primitive():
    assert set(NUMPY_FUNCS) == set(MPMATH_FUNCS) == {"carlson_rf", "carlson_rd", "carlson_rg", "carlson_rj",
                                                      "gamma_ratio", "hyp2f1c", "exp_tail", "asinh_excess", "sin_pi_sum"}
