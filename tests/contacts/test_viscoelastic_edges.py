"""Viscoelastic line contacts at the edges of their inputs (issue 42, the hostile
sweep tools/hostile/trust_round5_new_effects.py): one test per class of defect
it found.  Each input that has no answer is a package error (never a foreign
exception, a NaN or a number); each that has one is checked against our own
hereditary integral (mpmath quadrature of P(t) = int E(t - s) dPi(a(s)), the
elastic force law by our own quadrature of Eq. 10)."""
from __future__ import annotations

import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core.errors import LineContactError

t = lcs.t
HALF = sp.Rational(1, 2)


def maxwell_parabola():
    return lcs.parabola(verify=False).viscoelastic(lcs.maxwell(E0=1, tau=1))


def pi_ref(fprime, A):
    """P(a)/E* = int_0^a f'(x) x / sqrt(a^2 - x^2) dx (Eq. 10), x = a sin(phi)."""
    return mpmath.quad(lambda ph: fprime(A * mpmath.sin(ph)) * A * mpmath.sin(ph), [0, mpmath.pi / 2])


def hereditary(E, f1, f2, a_of, da, T):
    """int_0^T E(T - s) Pi'(a(s)) a'(s) ds, a(0) = 0, a growing (Lee-Radok), our own
    quadrature; Pi'(a) = int_0^{pi/2} [f''(a sin) a sin^2 + f'(a sin) sin] dphi (Eq. 10 differentiated)."""
    def dPi(A):
        return mpmath.quad(lambda ph: f2(A * mpmath.sin(ph)) * A * mpmath.sin(ph)**2
                           + f1(A * mpmath.sin(ph)) * mpmath.sin(ph), [0, mpmath.pi / 2])
    with mpmath.workdps(16):
        return mpmath.quad(lambda s: E(T - s) * dPi(a_of(s)) * da(s), [0, T])


# ---------------------------------------------------------------- text is parsed, never evaluated
def test_text_is_parsed_never_evaluated():
    """sympify evaluated a relaxation function or a history given as text (code run
    from a string); now the whitelisted parser reads it: code is refused, a formula works."""
    with pytest.raises(LineContactError):
        lcs.Material('__import__("os").getcwd()')
    with pytest.raises(LineContactError):
        maxwell_parabola().evaluate_at("force", 1, "__import__('os').getcwd()", R=1)
    with pytest.raises(LineContactError):
        maxwell_parabola().force_history("__import__('os').getcwd()")
    m = lcs.Material("2*exp(-t)")
    assert m.relaxation == 2 * sp.exp(-t)
    got = lcs.parabola(verify=False).viscoelastic(m).evaluate_at("force", 1, "t/10", R=1, dps=15)
    ref = hereditary(lambda u: 2 * mpmath.exp(-u), lambda xv: xv, lambda xv: 1, lambda s: s / 10, lambda s: 0.1, 1)
    assert abs(got / ref - 1) < 1e-13


# ---------------------------------------------------------------- numbers where numbers go
@pytest.mark.parametrize("call", [
    lambda v: v.evaluate_at("force", float("nan"), t / 10, R=1),
    lambda v: v.evaluate_at("force", float("inf"), t / 10, R=1),
    lambda v: v.evaluate_at("force", 1j, t / 10, R=1),
    lambda v: v.evaluate_at("force", "abc", t / 10, R=1),
    lambda v: v.evaluate_at("force", None, t / 10, R=1),
    lambda v: v.evaluate_at("pressure", 1, t / 10, x=float("nan"), R=1),
    lambda v: v.evaluate_at("pressure", 1, t / 10, x="abc", R=1),
    lambda v: v.evaluate_at("force", 1, t / 10, R=-1),          # R declared positive: the profile upside down
    lambda v: v.evaluate_at("force", 1, t / 10, R=0),
    lambda v: v.evaluate_at("force", 1, t / 10, R=1, dps=0),
    lambda v: v.model_choice(t / 10, -1, 1, R=1),
    lambda v: v.model_choice(t / 10, float("nan"), 1, R=1),
    lambda v: v.model_choice(t / 10, "abc", 1, R=1),
    lambda v: v.model_choice(t / 10, 1e-3, 0, R=1),
    lambda v: v.dissipated_work(t, 1, -1, points=20, R=1),
    lambda v: v.dissipated_work(t, 1, 0, points=20, R=1),
    lambda v: v.dissipated_work(t, 0, 10, points=20, R=1),
    lambda v: v.dissipated_work(t, 1, 10, points=0, R=1),
    lambda v: v.evaluate("force", t / 10, t=1j, R=1),
], ids=["t=nan", "t=inf", "t=1j", "t=text", "t=None", "x=nan", "x=text", "R<0", "R=0", "dps=0",
        "rtol<0", "rtol=nan", "rtol=text", "t_end=0", "L<0", "L=0", "work t_end=0", "points=0",
        "evaluate t=1j"])
def test_numbers_at_the_entry_are_checked(call):
    """A time, a point, a tolerance, a length, a count or a profile value outside its
    range was a TypeError, ZeroDivisionError, StopIteration, NaN or a negative load."""
    with pytest.raises(LineContactError):
        call(maxwell_parabola())


# ---------------------------------------------------------------- materials
@pytest.mark.parametrize("make", [
    lambda: lcs.maxwell(E0=1, tau=0),                                  # exp(-t/0): gave NaN
    lambda: lcs.standard_linear_solid(E0=2, E_inf=1, tau=0),
    lambda: lcs.prony(E_inf=1, terms=[(1,)]),                          # a term not a pair: ValueError
    lambda: lcs.prony(E_inf=1, terms="ab"),
    lambda: lcs.prony(E_inf=1, terms=[(1, 0)]),
    lambda: lcs.Material(2 + 3 * sp.sin(t)),                           # negative at t ~ 4..5.5: gave 0.6735
    lambda: lcs.Material(sp.exp(t)),                                   # grows without bound
    lambda: lcs.Material(2 - sp.exp(-t)),                              # grows (bounded): no relaxation
], ids=["maxwell tau=0", "sls tau=0", "prony (1,)", "prony text", "prony tau=0", "2+3sin", "exp(t)", "2-exp(-t)"])
def test_a_relaxation_modulus_relaxes(make):
    """A relaxation time 0, a malformed Prony series, a modulus negative at some time
    or growing gave NaN, a ValueError, or a number."""
    with pytest.raises(LineContactError):
        lcs.parabola(verify=False).viscoelastic(make()).evaluate_at("force", 5, t / 10, R=1, dps=15)


# ---------------------------------------------------------------- histories
@pytest.mark.parametrize("hist", [-t, sp.I * t, sp.nan * t, 1 / (1 - t), sp.oo * t],
                         ids=["a<0", "complex", "nan", "pole", "oo"])
def test_a_history_is_a_real_finite_half_width(hist):
    """a(t) = -t gave P = 0, a complex, NaN, infinite or singular history a
    TypeError, ZeroDivisionError or the internal Outside."""
    with pytest.raises(LineContactError):
        maxwell_parabola().evaluate_at("force", 2, hist, R=1, dps=15)


def test_a_jump_after_t0_is_refused_a_step_at_t0_is_exact():
    """a(t) = t/2 then 1 from t = 1 gave 0.0531 where the punches loaded at the jump
    make 0.2698 (the jump has no rate: it was lost); the same for a load jump (creep).
    A step at t = 0 is built: P = E*(t) Pi(a0)."""
    v = maxwell_parabola()
    with pytest.raises(LineContactError, match="jumps up"):
        v.evaluate_at("force", 2, sp.Piecewise((t / 2, t < 1), (1, True)), R=1, dps=15)
    with pytest.raises(LineContactError, match="jumps up"):
        lcs.parabola(verify=False).viscoelastic(lcs.maxwell(E0=2, tau=1)).half_width_at(
            2, sp.Piecewise((1, t < 1), (2, True)), R=1, dps=15)
    got = v.evaluate_at("force", 2, sp.Integer(1), R=1, dps=20)
    with mpmath.workdps(30):
        ref = mpmath.exp(-2) * pi_ref(lambda xv: xv, mpmath.mpf(1))
    assert abs(got / ref - 1) < 1e-15


def test_a_force_law_that_decreases_is_refused_where_it_does():
    """x^2 - x^4: P(a) decreases beyond a = 1/sqrt(3) and is negative beyond sqrt(2/3);
    a(t) = t to t = 1 gave P = -0.2889.  Below the turn the number is right."""
    v = lcs.LineContact(lcs.x**2 - lcs.x**4, verify=False).viscoelastic(lcs.maxwell(E0=1, tau=1))
    with pytest.raises(LineContactError, match="force law"):
        v.evaluate_at("force", 1, t, dps=15)
    with pytest.raises(LineContactError, match="force law"):
        v.evaluate_at("force", sp.Rational(7, 10), t, dps=15)
    got = v.evaluate_at("force", 1, t / 2, dps=15)
    ref = hereditary(lambda u: mpmath.exp(-u), lambda xv: 2 * xv - 4 * xv**3, lambda xv: 2 - 12 * xv**2,
                     lambda s: s / 2, lambda s: mpmath.mpf(1) / 2, 1)
    assert abs(got / ref - 1) < 1e-12


def test_a_periodic_history_past_half_the_period_is_a_package_error():
    """a(t) beyond L/2 on an array raised the internal Outside."""
    v = lcs.LineContact(1 - sp.cos(2 * sp.pi * lcs.x), period=1, verify=False).viscoelastic(lcs.maxwell(E0=1, tau=1))
    with pytest.raises(LineContactError, match="outside the range"):
        v.evaluate_at("force", 1, t, dps=15)
