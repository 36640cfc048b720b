"""The work dissipated over a load cycle (``ViscoelasticLineContact.dissipated_work``)
against an independent time-stepping of the Kelvin-Voigt law, its error estimate
against the true error, and the elastic limit.

The reference, written here: a parabola (R = 1) whose half-width goes up and down
linearly, on a Kelvin-Voigt half-plane E*(t) = E + eta delta(t).  The force law is
Popov's Eq. 10, Pi(a) = int_0^a f'(x) x / sqrt(a^2 - x^2) dx = pi a^2 / (4R) for
f' = x/R (done by hand: x = a sin phi), and a flat punch of half-width b under the
force F sinks by (2 F / (pi E)) ln(2L/b) against a point at the distance L.  Each
punch b carries E Pi'(b) db plus, at the instant it enters, the dashpot's
eta dPi(a(t))/dt; after the maximum (Ting) the punches wider than a(t) are unloaded
and no punch enters, so

    P = E Pi(a) + eta dPi(a)/dt,  D = E g(a) + eta dg(a)/dt   while a grows,
    P = E Pi(a),                  D = E g(a)                  after its maximum,

g(a) = (2/pi) int_0^a Pi'(b) ln(2L/b) db (scipy's quad here), and the depth d of the
indenter obeys the Kelvin-Voigt law eta d' + E d = D (a spring and a dashpot side
by side), time-stepped with scipy's solve_ivp together with W' = P d'.  Nothing
of the package is used for the reference."""
from __future__ import annotations

import math
import pickle

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import quad, solve_ivp

import linecontact_sym as lcs
from linecontact_sym.core.errors import DomainError

t = lcs.t
HALF = sp.Rational(1, 2)
L = 10.0
CYCLE = sp.Piecewise((t / 10, t <= 1), ((2 - t) / 10, t <= 2), (0, True))     # a(t): up to 1/10 at t = 1, down to 0 at t = 2
KINKED = sp.Piecewise((t / 10, t <= HALF), (sp.Rational(1, 20) + (t - HALF) / 20, t <= 3 * HALF),   # two rates, then down
                      (sp.Rational(1, 10) - (t - 3 * HALF) / 10, t <= 5 * HALF), (0, True))


def pi_law(a):
    """Pi(a) = P/E of the parabola R = 1 (Eq. 10 by hand) and its derivative."""
    return math.pi * a * a / 4, math.pi * a / 2


def g_quad(a):
    """The elastic depth: (2/pi) int_0^a Pi'(b) ln(2L/b) db (scipy's quad)."""
    return 2 / math.pi * quad(lambda b: pi_law(b)[1] * math.log(2 * L / b), 0, a, epsabs=0, epsrel=1e-13)[0] if a > 0 else 0.0


def g(a):
    """The same by parts (R = 1): int_0^a b ln(2L/b) db = a^2/2 ln(2L/a) + a^2/4 (fast in the ODE's
    right-hand side; checked against g_quad in the test that uses it)."""
    return a * a / 2 * math.log(2 * L / a) + a * a / 4 if a > 0 else 0.0


def kv_work_reference(E, eta, pieces=((0, 1, 0.0, 0.1), (1, 2, 0.1, -0.1))):
    """W = int P dd over a piecewise-linear a(t) (``pieces``: t0, t1, a(t0), a'; growing, then
    receding) by time-stepping eta d' + E d = D (see the module docstring)."""
    def rhs(a0, t0, da):
        loading = da > 0

        def f(s, y):
            a = a0 + da * (s - t0)
            Y, dY = pi_law(a)
            dg = 2 / math.pi * dY * math.log(2 * L / a) if a > 0 else 0.0
            P = E * Y + (eta * dY * da if loading else 0.0)
            D = E * g(a) + (eta * dg * da if loading else 0.0)
            dd = (D - E * y[0]) / eta
            return [dd, P * dd]
        return f
    assert all(abs(g(a) / g_quad(a) - 1) < 1e-12 for a in (1e-3, 0.05, 0.1))
    y = [0.0, 0.0]
    for t0, t1, a0, da in pieces:
        sol = solve_ivp(rhs(a0, t0, da), (t0, t1), y, method="DOP853", rtol=1e-11, atol=1e-15)
        assert sol.success
        y = sol.y[:, -1]
        if da > 0:      # Lee-Radok: while the contact grows the depth is the elastic one (the reference checked)
            assert abs(y[0] / g(a0 + da * (t1 - t0)) - 1) < 1e-8
    return y[1]


def kv(eta):
    return lcs.parabola(verify=False).viscoelastic(lcs.kelvin_voigt(E=1, eta=eta))


@pytest.mark.parametrize("eta, rtol", [(sp.Rational(1, 2), 5e-3), (sp.Rational(1, 20), 1e-3)])
def test_kelvin_voigt_cycle_against_time_stepping(eta, rtol):
    """The dashpot's work over a load-unload cycle, 16 intervals (32 on the finer grid):
    within its own error estimate of the time-stepped reference, and the estimate small
    (eta = 1/20: the creep time eta/E below the step 1/16; P linear and J* integrated exactly
    on each step resolve it)."""
    ref = kv_work_reference(1.0, float(eta))
    W = kv(eta).dissipated_work(CYCLE, t_end=2, L=L, points=16, R=1)
    assert ref > 0 and W.points == 32
    assert abs(W.value - ref) <= W.error, (W, ref)
    assert W.error < rtol * ref


def test_error_estimate_covers_the_true_error_at_coarse_grids():
    """At 4 and 8 intervals (second order: the estimate |W(2n) - W(n)| about three times
    the error of W(2n)) the estimate covers the true error and is not vacuous (< 10x it)."""
    ref = kv_work_reference(1.0, 0.5)
    v = kv(sp.Rational(1, 2))
    errs = []
    for n in (4, 8):
        W = v.dissipated_work(CYCLE, t_end=2, L=L, points=n, R=1)
        true = abs(W.value - ref)
        assert true <= W.error < 10 * true, (n, W, ref)
        errs.append(true)
    assert 2.5 < errs[0] / errs[1] < 6          # second order: the error falls ~4x when the grid halves


def test_elastic_limit_eta_to_zero():
    """eta = 0 is elastic: no work over the closed cycle (the depth is the elastic one both
    ways); for small eta the work is linear in eta (the dashpot's share), and the time-stepped
    reference agrees at eta = 1/100, where the creep time is 1/25 of the step of the grid."""
    W0 = kv(0).dissipated_work(CYCLE, t_end=2, L=L, points=8, R=1)
    scale = pi_law(0.1)[0] * g(0.1)                 # P_max d_max
    assert abs(W0.value) <= 1e-14 * scale and W0.error <= 1e-14 * scale
    w2 = kv(sp.Rational(1, 100)).dissipated_work(CYCLE, t_end=2, L=L, points=4, R=1)
    w3 = kv(sp.Rational(1, 1000)).dissipated_work(CYCLE, t_end=2, L=L, points=4, R=1)
    assert 0 < w3 < w2 < 1e-3 * scale * 1000
    assert abs(w2 / w3 / 10 - 1) < 0.02
    ref = kv_work_reference(1.0, 0.01)
    assert abs(w2.value - ref) <= w2.error


def test_the_result_is_a_float_with_its_error():
    """Old code keeps a float: arithmetic, comparisons, pickling; the repr states the error."""
    W = kv(sp.Rational(1, 2)).dissipated_work(CYCLE, t_end=2, L=L, points=4, R=1)
    assert isinstance(W, float) and W.value == float(W) and W > 0 and 2 * W == W + W
    assert "error=" in repr(W) and W.points == 8 and 0 < W.error < abs(W)
    W2 = pickle.loads(pickle.dumps(W))
    assert (float(W2), W2.error, W2.points) == (float(W), W.error, W.points)


def test_kelvin_voigt_step_is_refused():
    """A step of the half-width on a Kelvin-Voigt material: infinite dashpot force, no work."""
    with pytest.raises(DomainError, match="step"):
        kv(sp.Rational(1, 2)).dissipated_work(sp.Rational(1, 10) + 0 * t, t_end=1, L=L, points=4, R=1)


def maxwell_work_reference(E0, tau):
    """W for a Maxwell material E*(t) = E0 exp(-t/tau) over the cycle, by an identity derived
    here: D(t) = (2/pi) int_0^{a(t)} E(t - t_b) Pi'(b) ln(2L/b) db (t_b = 10 b, the entry time
    of the punch b; Ting: the punches wider than a(t) dropped), so D' + D/tau =
    (2/pi) E(t - t_a) Pi'(a) ln(2L/a) a'(t) (Leibniz; E' = -E/tau), and the Maxwell law
    (spring E0 in series with a dashpot E0 tau) gives E0 d' = D' + D/tau: W = int P d' dt,
    with P(t) = int_0^{a(t)} E(t - t_b) Pi'(b) db.  scipy's quad, nested."""
    E = lambda s: E0 * math.exp(-s / tau)                                       # noqa: E731

    def integrand(s, loading):
        a, da = (s / 10, 0.1) if loading else ((2 - s) / 10, -0.1)
        P = quad(lambda b: E(s - 10 * b) * pi_law(b)[1], 0, a, epsabs=0, epsrel=1e-12)[0]
        return P * 2 / math.pi * E(s - 10 * a) * pi_law(a)[1] * math.log(2 * L / a) * da / E0
    up = quad(integrand, 0, 1, args=(True,), epsabs=0, epsrel=1e-11)[0]
    down = quad(integrand, 1, 2, args=(False,), epsabs=0, epsrel=1e-11, limit=200)[0]
    return up + down


def test_maxwell_cycle_against_its_depth_identity():
    """The general path (no Dirac term): Maxwell over the cycle, 16 intervals, within its
    error estimate of the identity of maxwell_work_reference, the estimate < 2 %."""
    ref = maxwell_work_reference(2.0, 1.0)
    W = lcs.parabola(verify=False).viscoelastic(lcs.maxwell(E0=2, tau=1)).dissipated_work(
        CYCLE, t_end=2, L=L, points=16, R=1)
    assert ref > 0 and abs(W.value - ref) <= W.error < 2e-2 * ref, (W, ref)


def test_kelvin_voigt_rate_change_while_loading():
    """a(t) grows at two rates, then recedes: the dashpot's force and D jump at the kink
    (t = 1/2) as well as at the maximum; both sides are knots.  Against the time-stepping."""
    ref = kv_work_reference(1.0, 0.25, ((0, 0.5, 0.0, 0.1), (0.5, 1.5, 0.05, 0.05), (1.5, 2.5, 0.1, -0.1)))
    W = kv(HALF / 2).dissipated_work(KINKED, t_end=5 * HALF, L=L, points=8, R=1)
    assert abs(W.value - ref) <= W.error < 1e-2 * ref, (W, ref)


def test_quadrature_fallback_agrees_with_the_antiderivatives(monkeypatch):
    """Where SymPy finds no antiderivative of J* (a creep function without a closed form),
    J1 and J2 come from quadrature on the grid: the same work (KV, a kink and a maximum off the grid)."""
    from linecontact_sym.contacts.viscoelastic import contact as vc
    closed = kv(HALF).dissipated_work(KINKED, t_end=5 * HALF, L=L, points=4, R=1)
    monkeypatch.setattr(vc, "_creep_integral_expr", lambda J, budget: None)
    quad_ = kv(HALF).dissipated_work(KINKED, t_end=5 * HALF, L=L, points=4, R=1)
    assert abs(quad_ / closed - 1) < 1e-12 and abs(quad_.error / closed.error - 1) < 1e-9
