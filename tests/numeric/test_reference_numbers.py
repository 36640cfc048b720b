"""The reference integrator's numbers and the extensions its ported users
need: exact balls of negative and long numbers, one integrand per piece,
sums of enclosures (numeric/reference.py)."""
import flint
import mpmath
import pytest
import sympy as sp

from linecontact_sym.numeric.arb_compile import compile_acb, to_acb
from linecontact_sym.numeric.reference import ARB, MPMATH, RefValue, integrate, lincomb

t = sp.Dummy("t")


def test_negative_numbers_keep_their_sign():
    # mpf.man_exp drops the sign: a negative number must not become positive
    assert to_acb(mpmath.mpf(-0.7)).real < 0
    assert compile_acb(sp.Float(-0.7, 30), None)(flint.acb(0), False).real < 0
    r = integrate(sp.Float(-1.5, 30) * t, t, [0, 1], dps=30)          # -3/4
    with mpmath.workdps(50):
        assert r.method == ARB and r.contains(mpmath.mpf(-3) / 4) and not r.contains(mpmath.mpf(3) / 4)


def test_a_long_float_is_not_rounded_to_mpmaths_precision():
    """A SymPy Float of 80 digits is its own exact value in the ball, at any
    mpmath precision (mpmath.mpf(_mpf_) would round it to 15 digits)."""
    f = sp.sqrt(sp.Float(2, 80))               # SymPy evaluates it to a 269-bit Float
    r = integrate(f + 0 * t, t, [0, 1], dps=60)
    with mpmath.workdps(90):
        assert r.method == ARB and r.contains(mpmath.mpf(f._mpf_))
        assert abs(r.mid - mpmath.sqrt(2)) < mpmath.mpf(10) ** -65     # not 1e-16


def test_one_integrand_per_piece():
    """|t| on [-1, 1] as -t and t on the two pieces: no switch to bisect."""
    r = integrate([-t, t], t, [-1, 0, 1], dps=40)
    with mpmath.workdps(60):
        assert r.method == ARB and r.contains(1) and not r.contains(1 + mpmath.mpf(10) ** -38)
    with pytest.raises(ValueError):
        integrate([t], t, [-1, 0, 1], dps=20)
    # the mpmath route also takes one integrand per piece
    m = integrate([-t, t], t, [-1, 0, 1], dps=20, eval_limit=1)   # a limit no piece meets: the fallback
    with mpmath.workdps(30):
        assert m.method == MPMATH and abs(m - 1) < mpmath.mpf(10) ** -18


def test_lincomb_of_enclosures_and_exact_terms():
    a = integrate(sp.sqrt(1 - t**2), t, [0, 1], dps=40)       # pi/4
    b = integrate(sp.exp(t), t, [0, 1], dps=40)                # e - 1
    s = lincomb([(4, a), (-2, b), (sp.Rational(1, 3), sp.sqrt(2))], dps=40)
    with mpmath.workdps(60):
        exact = mpmath.pi - 2 * (mpmath.e - 1) + mpmath.sqrt(2) / 3
        assert s.method == ARB and s.contains(exact) and s.digits > 38
        assert not s.contains(exact * (1 + mpmath.mpf(10) ** -38))
    est = RefValue(mpmath.mpf(1), 0, MPMATH, "an estimate")
    m = lincomb([(1, a), (1, est)], dps=40)
    with mpmath.workdps(50):
        assert m.method == MPMATH and m.note == "an estimate" and abs(m - (mpmath.pi / 4 + 1)) < mpmath.mpf(10) ** -38


def test_max_and_min_of_several_balls():
    """Max/Min on balls (compile_acb with several symbols): the certain
    extremum where one is, the union of the candidates where none is, not
    holomorphic there; a Max of three radicals compiles (SymPy's rewrite
    to Piecewise recursed without end on it)."""
    x, y = sp.symbols("x y", real=True)
    f = compile_acb(sp.Max(sp.sqrt(x), sp.Abs(y - 1), 2 * sp.sqrt(x) - sp.sqrt(y)), [x, y])
    with flint.ctx.workprec(100):
        v = f((flint.acb(flint.fmpq(1, 4)), flint.acb(flint.fmpq(1, 9))), False)       # 1/2, 8/9, 2/3
        assert v.real.contains(flint.arb(flint.fmpq(8, 9))) and v.real.rad() < flint.arb(2) ** -90
        g = compile_acb(sp.Min(x, y), [x, y])
        wide = (flint.acb(flint.arb("0.3 +/- 0.1")), flint.acb(flint.arb("0.35")))
        u = g(wide, False)
        assert u.real.contains(flint.arb("0.2")) and u.real.contains(flint.arb("0.35"))
        assert not g(wide, True).is_finite()
        assert g((flint.acb(1), flint.acb(2)), True).real == 1
