"""The end-point transforms of the reference integrator (numeric/endpoints.py),
alone: the one substitution t = e + d u^q with q from the end's exponent
(substitute_end), and the piece with a singular end (singular_piece: that
substitution, or the subtraction of the logarithms at a logarithmic end),
each integrated here by Arb's acb.integral directly.

The references are independent of both: the integrand g(s) s^beta ln^k s
(s the distance to the singular end, g entire) integrated term by term of
g's Taylor series at 60 digits (int_0^h s^(n+beta) ds = h^(n+beta+1)/(n+beta+1),
int_0^1 s^n ln^k s ds = (-1)^k k!/(n+1)^(k+1)).  mpmath's tanh-sinh of the
integrands as they stand agrees, but only to 22-33 digits at 60 (its nodes
next to a singular end lose their digits), so it is checked to 20."""
from __future__ import annotations

import math

import flint
import mpmath
import pytest
import sympy as sp

from linecontact_sym.numeric import flamant
from linecontact_sym.numeric.arb_compile import ArbUnsupported, compile_acb, to_acb
from linecontact_sym.numeric.endpoints import singular_piece, substitute_end

t = sp.Dummy("t")
BITS = 200          # about 60 digits
HALF = sp.Rational(1, 2)


def _series(coef, beta, h=1, k=0):
    """int_0^h g(s) s^beta ln^k s ds for g(s) = sum_n coef(n) s^n (g entire,
    its coefficients falling like 1/n!: 100 terms are 1/100! ~ 1e-158 of it;
    k > 0 with h = 1 only).  Summed as it stands (no acceleration: nsum's
    extrapolation is misled by every other coefficient being 0)."""
    with mpmath.workdps(70):
        beta = mpmath.mpf(beta.p) / beta.q if isinstance(beta, sp.Rational) else mpmath.mpf(beta)
        h = mpmath.mpf(sp.Rational(h).p) / sp.Rational(h).q
        if k:
            return mpmath.fsum(coef(n) * (-1) ** k * math.factorial(k) / (n + beta + 1) ** (k + 1) for n in range(100))
        return mpmath.fsum(coef(n) * h ** (n + beta + 1) / (n + beta + 1) for n in range(100))


def _number(e):
    """A SymPy number at 70 digits."""
    with mpmath.workdps(70):
        return mpmath.mpf(str(sp.N(e, 70)))


def _quad(f, lo, hi):
    """mpmath's tanh-sinh of the integrand as it stands (at 60 digits)."""
    g = sp.lambdify(t, f, "mpmath")
    with mpmath.workdps(60):
        return mpmath.quad(g, [mpmath.mpf(sp.Rational(lo).p) / sp.Rational(lo).q,
                               mpmath.mpf(sp.Rational(hi).p) / sp.Rational(hi).q])


def _arb(fn, lo, hi):
    """Arb's integral of a compiled integrand over [lo, hi]: a ball (nan where it cannot)."""
    with flint.ctx.workprec(BITS):
        return flint.acb.integral(fn, to_acb(lo), to_acb(hi), rel_tol=flint.arb(2) ** -(BITS - 20),
                                  eval_limit=20000)


def _holds(ball, ref, sign=1, digits=50, slack=55):
    """The real ball (times ``sign``) is finite, at most 10^-``digits``
    relative wide, and holds ``ref`` (within 10^-``slack`` of it, its own
    rounding)."""
    with mpmath.workdps(70):
        ref = sign * ref
        mid = mpmath.mpf(ball.real.mid().str(70, radius=False))
        rad = mpmath.mpf(ball.real.rad().str(5, radius=False))
        return ball.is_finite() and rad < abs(ref) * mpmath.mpf(10) ** -digits and \
            abs(mid - ref) <= rad + abs(ref) * mpmath.mpf(10) ** -slack


def _cos_shift(a):
    """Taylor coefficients of cos(a + s) (a = +-1, 0) at s = 0."""
    return lambda n: mpmath.cos(a + n * mpmath.pi / 2) / mpmath.factorial(n)


# (integrand, piece, singular end, q, its reference, singular as it stands)
CASES = [
    # (t - e)^(-1/2): cos(t)/sqrt(1 - t) on [1/2, 1], s = 1 - t: cos(1 - s) s^(-1/2)
    (sp.cos(t) / sp.sqrt(1 - t), HALF, 1, 1, 2,
     lambda: _series(lambda n: (-1) ** n * _cos_shift(1)(n), -HALF, HALF), True),
    # (t - e)^(-2/3): e^t t^(-2/3) on [0, 1/2]: q >= 4/(1 - 2/3)
    (sp.exp(t) * t ** sp.Rational(-2, 3), 0, HALF, 0, 12,
     lambda: _series(lambda n: 1 / mpmath.factorial(n), sp.Rational(-2, 3), HALF), True),
    # a sqrt-type branch point (bounded, not holomorphic): sqrt(1 - t^2) on [0, 1], exact pi/4
    (sp.sqrt(1 - t**2), 0, 1, 1, 2, lambda: _number(sp.pi / 4), False),
]


@pytest.mark.parametrize("f, lo, hi, end, q, ref, singular", CASES,
                         ids=["inverse_sqrt", "power_minus_two_thirds", "sqrt_branch_point"])
def test_one_substitution_takes_its_power_from_the_end_and_arb_encloses_the_integral(f, lo, hi, end, q, ref,
                                                                                     singular):
    """substitute_end at the singular end: q from the end's exponent, an
    integrand that Arb bounds next to u = 0 (the Jacobian's power of u
    cancels the singular factor's), its integral over [0, 1] (oriented
    from the end) the piece's to 50 digits, the series' value inside;
    mpmath's tanh-sinh agrees to 20 digits."""
    other = hi if end == lo else lo
    g, w, got_q = substitute_end(f, t, end, other - end)
    assert got_q == q
    fn = compile_acb(g, w)
    with flint.ctx.workprec(BITS):
        assert fn(flint.acb(flint.arb(0).union(flint.arb(2) ** -30)), False).is_finite()
    v = _arb(fn, 0, 1)
    sign = 1 if end == lo else -1
    assert _holds(v, ref(), sign)
    assert _holds(v, _quad(f, lo, hi), sign, digits=50, slack=20)
    if singular:
        # as it stands, Arb has no finite bound next to the end (why the substitution exists)
        assert not _arb(compile_acb(f, t), lo, hi).is_finite()


def test_a_power_at_or_below_minus_one_is_refused_not_integrated():
    """(t - e)^beta, beta <= -1 rational: the integral diverges; a clear error."""
    with pytest.raises(ArbUnsupported, match="diverges"):
        substitute_end(sp.cos(t) * t ** sp.Rational(-5, 4), t, 0, 1)
    with pytest.raises(ArbUnsupported, match="diverges"):
        substitute_end((1 - t) ** sp.Rational(-3, 2), t, 1, -1)


def test_a_float_exponent_is_read_as_its_exact_binary_value():
    """A Float power -0.75 at the end: q from the exact -3/4 (16)."""
    g, w, q = substitute_end(sp.cos(t) * t ** sp.Float(-0.75), t, 0, 1)
    assert q == 16
    assert _holds(_arb(compile_acb(g, w), 0, 1), _series(_cos_shift(0), sp.Rational(-3, 4)))


def _piece(fn, lo, hi):
    v = _arb(fn, lo, hi)
    if not v.is_finite():
        raise ArbUnsupported("not enclosed")
    return v


@pytest.mark.parametrize("f, ref", [
    # ln at t = 0: sum_n c_n int_0^1 t^n ln t dt
    (sp.cos(t) * sp.log(t), lambda: _series(_cos_shift(0), 0, k=1)),
    # ln^2 at t = 1, s = 1 - t: e^(1 - s) ln^2 s
    (sp.exp(t) * sp.log(1 - t) ** 2, lambda: _series(lambda n: mpmath.e * (-1) ** n / mpmath.factorial(n), 0, k=2)),
    # 1/sqrt at one end, ln at the other: 2 - 1
    (1 / sp.sqrt(t) + sp.log(1 - t), lambda: mpmath.mpf(1)),
], ids=["log", "log_squared", "inverse_sqrt_and_log"])
def test_a_singular_piece_is_enclosed_whichever_end_is_singular(f, ref):
    """singular_piece over [0, 1]: each half with a singular end transformed
    (the power substitution, or the logarithms subtracted: ln^2 too, whose
    split (L + ln q)^2 is multiplied out), the reference inside a 50-digit
    ball."""
    with flint.ctx.workprec(BITS):
        v = singular_piece(f, t, sp.S.Zero, sp.S.One, _piece)
    assert _holds(v, ref())


def test_the_flamant_edge_takes_the_same_substitution():
    """The Flamant routines' contact edge is the same mechanism: q from the
    pressure's exponent there (2 for the inverse square root of a punch's
    edge, 12 for a power -2/3), not a fixed 2; in the Arb forms and in the
    tanh-sinh route, whose edge piece of s^2 (1 - s)^(-3/4) (q = 16) gives
    B(3, 1/4) = 128/45 to its 30 digits."""
    s = sp.Symbol("s", positive=True)
    assert flamant._edge_form(1 / sp.sqrt(1 - s**2), s, 1)[2] == 2
    assert flamant._edge_form((1 - s) ** sp.Rational(-2, 3), s, 1)[2] == 12
    v, err = flamant.tanh_sinh(s**2 * (1 - s) ** sp.Rational(-3, 4), s, 0, 1, [], 30)
    with mpmath.workdps(50):
        ref = mpmath.beta(3, mpmath.mpf(1) / 4)
        assert abs(ref - mpmath.mpf(128) / 45) < mpmath.mpf(10) ** -45
        assert abs(v - ref) < ref * mpmath.mpf(10) ** -30 and err < mpmath.mpf(10) ** -30
