"""Steady rolling with traction (contacts/rolling): Carter at CONTACT's carter2d
numbers, and the reduction to tilted bounded pressures against an independent
boundary-element solution of steady rolling (tests/contacts/rolling_bem.py:
upwind transport, an active set over stick and slip cells that assumes
nothing about where the stick zone is, its own Gauss-Chebyshev normal
pressure)."""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core import symbols as S
from linecontact_sym.core.errors import GrossSlidingError, InadmissibleProfileError

sys.path.insert(0, str(Path(__file__).resolve().parent))
from rolling_bem import CARTER2D, cell_means, normal_chebyshev, solve_rolling  # noqa: E402

R = sp.Symbol("R", positive=True)
k = sp.Symbol("k", positive=True)
ell = sp.Symbol("l", positive=True)


def bem(slope, A, E, mu, ratio, ns=(100, 200), degree=40):
    """The BEM at two cell counts: (Richardson creepage, finer solution, normal load)."""
    p, P, _ = normal_chebyshev(slope, -A, A, E, degree)
    sols = [solve_rolling(p, -A, A, E, mu, ratio * mu * P, n) for n in ns]
    return 2 * sols[1].xi - sols[0].xi, sols[1], P


def compare(state, sol, xi_bem, s_tol=2e-3, xi_tol=5e-5, q_tol=2e-2):
    """The reduction's state against the BEM: one stick zone touching the
    leading edge, its start, the creepage, the traction at the cell centres."""
    zones = sol.stick_zones()
    assert len(zones) == 1 and abs(zones[0][1] - float(state.right)) < 1e-12      # found there, not assumed
    assert abs(float(state.s) - sol.stick_start()) < s_tol
    assert abs(float(state.creepage) / xi_bem - 1) < xi_tol
    q = cell_means(state.traction, sol.edges)            # the BEM's unknowns are cell means
    assert np.max(np.abs(q - sol.q)) < q_tol * np.max(sol.mu * sol.p)


@pytest.fixture(scope="module")
def carter():
    return lcs.parabola(verify=False).rolling(CARTER2D["mu"])


def _carter2d_state(r, ratio=CARTER2D["ratio"]):
    """The carter2d state at Q = ratio mu P, exact (SymPy numbers)."""
    E = sp.Rational("113888.9")
    P = sp.pi * E / (4 * 500)
    ratio = ratio if isinstance(ratio, sp.Basic) else sp.Rational(str(ratio))
    return r.state_at(Q=ratio * sp.Rational(3, 10) * P, a=1, E_star=E, R=500)


def test_carter2d_contact_numbers(carter):
    """CONTACT's carter2d: E* = 113888.9, R = 500, a = 1, mu = 0.3, Q/(mu P) = 0.64:
    stick zone [-0.2, 1], creepage 2.4e-4 (the stick zone at the leading edge)."""
    st = _carter2d_state(carter)
    assert st.closed
    assert abs(st.stick[0] + 0.2) < 1e-14 and st.stick[1] == 1
    assert st.slip == (-1, st.stick[0])
    assert abs(st.creepage / 2.4e-4 - 1) < 1e-13
    assert float(st.c_s) == pytest.approx(0.6, abs=1e-14)
    x = np.array([-0.9, -0.2 - 1e-9, 0.0, 0.5, 0.99])
    q = st.traction(x)
    assert np.all(q > 0) and np.all(q <= 0.3 * st.normal_pressure(x) * (1 + 1e-12))
    assert q[0] == pytest.approx(0.3 * st.normal_pressure(x[:1])[0], rel=1e-14)    # slip zone: mu p


def test_carter_closed_forms_come_from_the_engine():
    """Carter's c_s = a sqrt(1 - Q/(mu P)) and xi = mu (a - c_s)/R, derived."""
    r = lcs.parabola(verify=False).rolling()
    assert sp.simplify(r.creepage - S.mu * (S.a - S.c_s) / R) == 0
    cs = r.stick_half_width().expr
    Qp = sp.Symbol("Qp", positive=True)
    P = sp.pi * S.E_star * S.a**2 / (4 * R)
    assert sp.simplify((cs**2).subs(S.Q, Qp) - S.a**2 * (1 - Qp / (S.mu * P))) == 0
    assert sp.simplify(r.tangential_force - S.mu * (P - sp.pi * S.E_star * S.c_s**2 / (4 * R))) == 0


def test_carter2d_against_the_bem(carter):
    k2 = CARTER2D
    xi, sol, _ = bem(lambda t: t / k2["R"], k2["a"], k2["E_star"], k2["mu"], k2["ratio"], degree=4)
    compare(_carter2d_state(carter), sol, xi, s_tol=3e-4, xi_tol=2e-5)


@pytest.fixture(scope="module")
def quartic():
    return lcs.LineContact(k * S.x**4, verify=False).rolling(0.3)


@pytest.mark.parametrize("ratio", [0.3, 0.8])
def test_even_power_x4_against_the_bem(quartic, ratio):
    r = quartic
    assert not r.creepage.has(sp.Integral)        # the even power closes
    st = r.state_at(Q=ratio * 0.3 * 3 * np.pi / 4, a=1, E_star=1, k=1)   # P(a) = 3 pi E* k a^4/4
    assert st.closed
    xi, sol, P = bem(lambda t: 4 * t**3, 1.0, 1.0, 0.3, ratio)
    assert float(st.P) == pytest.approx(P, rel=1e-13)
    compare(st, sol, xi)


@pytest.mark.slow
def test_cosh_against_the_bem():
    """A non-polynomial profile, k (cosh(x/l) - 1)."""
    c = lcs.LineContact(k * (sp.cosh(S.x / ell) - 1), verify=False, budget=1)   # no closed form: the numbers
    r = c.rolling(0.3)
    xi, sol, P = bem(lambda t: 2 * np.sinh(2 * t), 1.0, 1.0, 0.3, 0.5)
    st = r.state_at(Q=0.5 * 0.3 * P, a=1, E_star=1, k=1, l=0.5)
    assert float(st.P) == pytest.approx(P, rel=1e-13)
    compare(st, sol, xi)


def test_extremes(carter):
    """Free rolling (Q = 0: all stick, no creepage), the full-slip onset
    (xi -> mu a/R), beyond it an error; Q < 0 the mirror image."""
    st0 = _carter2d_state(carter, 0)
    assert st0.stick == (-1, 1) and st0.creepage == 0
    for ratio in (sp.Rational(1, 10**12), 1 - sp.Rational(1, 10**12)):   # 30 digits at both ends
        st = _carter2d_state(carter, ratio)
        carter_xi = sp.Rational(3, 10) / 500 * (1 - sp.sqrt(1 - ratio))      # Carter, typed here
        assert abs(st.creepage / sp.N(carter_xi, 50) - 1) < 1e-29
    on = _carter2d_state(carter, 1)
    assert on.c_s == 0 and float(on.creepage) == pytest.approx(0.3 / 500, rel=1e-14)
    with pytest.raises(GrossSlidingError):
        _carter2d_state(carter, 1 + sp.Rational(1, 10**9))
    neg = _carter2d_state(carter, -0.64)
    assert neg.stick == _carter2d_state(carter).stick and float(neg.creepage) == pytest.approx(-2.4e-4, rel=1e-13)
    assert np.all(neg.traction(np.array([-0.5, 0.5])) < 0)


def test_a_leading_slip_zone_is_refused():
    """f = x^2 - x^4/6 (concave beyond x = 1): near full slip the BEM's stick
    zone leaves the leading edge, and the reduction says so instead of
    returning a traction above mu p."""
    r = lcs.LineContact(S.x**2 - S.x**4 / 6, verify=False).rolling(0.3)
    P = float(np.pi * 1.44 * (4 - 1.44) / 8)
    st = r.state_at(Q=0.5 * 0.3 * P, a=1.2, E_star=1)
    assert st.checked
    with pytest.raises(InadmissibleProfileError, match="more than one stick zone"):
        r.state_at(Q=0.95 * 0.3 * P, a=1.2, E_star=1)
    p, Pb, _ = normal_chebyshev(lambda t: 2 * t - 2 * t**3 / 3, -1.2, 1.2, 1.0, 16)
    sol = solve_rolling(p, -1.2, 1.2, 1.0, 0.3, 0.95 * 0.3 * Pb, 200)
    assert sol.stick_zones()[-1][1] < 1.2 - 0.02                  # the BEM: slip at the leading edge


def test_creepage_curve_is_carters(carter):
    q, xi = carter.creepage_curve(21, a=1, E_star=113888.9, R=500)
    assert q[0] == 0 and q[-1] == pytest.approx(1, rel=1e-14)
    assert np.allclose(xi, 0.3 / 500 * (1 - np.sqrt(1 - q)), rtol=1e-12, atol=1e-18)


def test_tilted_parabola_is_carter_shifted():
    """The parabola tilted by theta (Hertz shifted by R theta, asymmetric
    contact): the stick zone [right - 2 c_s, right] and Carter's creepage."""
    R = sp.Symbol("R", positive=True)
    r = lcs.LineContact(lcs.x_real**2 / (2 * R), symmetric=False, verify=False).rolling(0.3)
    st = r.state_at(Q=0.64 * 0.3 * np.pi / 4, P=np.pi / 4, theta=0.2, E_star=1, R=1)
    assert (float(st.left), float(st.right)) == pytest.approx((-0.8, 1.2), abs=1e-14)
    assert float(st.s) == pytest.approx(0.0, abs=1e-14)
    assert float(st.creepage) == pytest.approx(0.3 * 0.4, rel=1e-14)


def test_asymmetric_profile_under_a_moment_against_the_bem():
    """x^2/2 + x^3/10 under the moment M = 0.1 (free rotation): the BEM on the
    contact the asymmetric core found (whose tilt the Chebyshev solution's
    consistency coefficient confirms)."""
    r = lcs.LineContact(lcs.x_real**2 / 2 + lcs.x_real**3 / 10, symmetric=False, verify=False).rolling(0.3)
    st = r.state_at(Q=0.5 * 0.3, P=1, moment=0.1, E_star=1)
    L, Rt = float(st.left), float(st.right)
    p, P, t0 = normal_chebyshev(lambda t: t + 3 * t**2 / 10, L, Rt, 1.0, 8)
    assert P == pytest.approx(1, rel=1e-12)
    sols = [solve_rolling(p, L, Rt, 1.0, 0.3, 0.15, n) for n in (100, 200)]
    compare(st, sols[1], 2 * sols[1].xi - sols[0].xi, xi_tol=1e-4)
    # the creepage is mu (theta(e*, c_s) - theta_n): theta_n from the Chebyshev T_0 coefficient
    e_s, c_s = float(st.right - st.c_s), float(st.c_s)
    _, _, t_star = normal_chebyshev(lambda t: t + 3 * t**2 / 10, e_s - c_s, e_s + c_s, 1.0, 8)
    assert float(st.creepage) == pytest.approx(0.3 * (t_star - t0), rel=1e-12)


@pytest.mark.slow
def test_carter_claims_hold():
    """claims/data/carter1926.toml (stick zone, creepage, tangential force) by
    the package's checker, which reads the rolling quantities from the registry."""
    from linecontact_sym.claims import check_paper, load_paper
    result = check_paper(load_paper("carter1926"), budget=20)
    assert [r.status for r in result.results] == ["holds"] * 3
    assert min(r.digits for r in result.results) >= 25


def test_state_from_the_load_and_the_curve_of_a_quartic(quartic):
    """P given instead of a (the normal half-width from the force law), and the
    creepage-force curve through the state's point."""
    st = quartic.state_at(Q=0.5 * 0.3 * 3 * np.pi / 4, P=3 * np.pi / 4, E_star=1, k=1)
    assert float(st.right) == pytest.approx(1, rel=1e-13)
    q, xi = quartic.creepage_curve(401, P=3 * np.pi / 4, E_star=1, k=1)
    assert np.interp(0.5, q, xi) == pytest.approx(float(st.creepage), rel=1e-4)
    assert np.all(np.diff(q) > 0) and np.all(np.diff(xi) > 0)


@pytest.mark.slow
def test_rounded_punch_against_the_bem():
    """A profile with kinks (a flat of half-width b = 0.3 with parabolic
    corners, R = 1, a = 0.8): numbers only (the asymmetric core does not take
    |x| profiles); the BEM's Chebyshev pressure converges slowly at the kinks,
    hence the looser tolerances."""
    r = lcs.rounded_punch(verify=False, budget=1).rolling(0.3)
    slope = lambda t: np.sign(t) * np.clip(np.abs(t) - 0.3, 0, None)  # noqa: E731
    xi, sol, P = bem(slope, 0.8, 1.0, 0.3, 0.5, degree=200)
    st = r.state_at(Q=0.5 * 0.3 * float(r.state_at(Q=0, a=0.8, E_star=1, R=1, b=0.3).P), a=0.8, E_star=1, R=1,
                    b=0.3)
    assert not st.closed and float(st.P) == pytest.approx(P, rel=3e-5)
    compare(st, sol, xi, s_tol=2e-3, xi_tol=1e-4)


# ---------------------------------------------------------------- the two bodies (issue 39, item 4)
def test_rolling_states_the_coupling_and_keeps_its_numbers():
    """carter2d (mu = 0.3, c_s = 0.6): without the bodies the state says
    "beta = 0 assumed"; with beta = -2/7 (a rigid roller on nu = 0.3:
    -(1 - 2 nu)/(2 (1 - nu)) by hand) one DomainWarning for the contact,
    the note |beta| mu = 0.3 * 2/7 on every state and derivation, and the
    same numbers."""
    import warnings
    from linecontact_sym.core.errors import DomainWarning
    c = lcs.parabola(verify=False)
    kw = dict(a=1, E_star=113888.9, R=500)
    Q = 0.64 * 0.3 * 178.8962657827113
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        plain = c.rolling(0.3)
        s0 = plain.state_at(Q=Q, **kw)
    assert s0.coupling.startswith("beta = 0 assumed (elastically similar bodies)") and "beta = 0 assumed" in repr(s0)
    nu = 0.3
    beta = -(1 - 2 * nu) / (2 * (1 - nu))
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        r = c.rolling(0.3, beta=beta)
        states = [r.state_at(Q=q, **kw) for q in (Q, Q / 2, -Q)]
        curve = r.creepage_curve(points=5, **kw)
    assert len([w for w in seen if issubclass(w.category, DomainWarning)]) == 1
    for st in states:
        assert float(st.coupling.size) == pytest.approx(abs(beta) * 0.3, rel=1e-14) and "0.0857" in repr(st)
    assert r.derivation("creepage").notes[0] == r.coupling_note and "beta=" in repr(r)
    s1 = states[0]
    assert (s1.c_s, s1.s, s1.creepage, s1.P) == (s0.c_s, s0.s, s0.creepage, s0.P)
    xs = np.linspace(-1, 1, 11)
    assert np.array_equal(s1.traction(xs), s0.traction(xs))
    assert all(np.array_equal(u, v) for u, v in zip(curve, plain.creepage_curve(points=5, **kw)))
    assert r.creepage == plain.creepage


def test_asymmetric_rolling_takes_the_materials():
    """The tilted parabola (Hertz shifted by R theta) rolling with a rigid
    roller on an incompressible body (beta = 0 exactly: no warning) and on
    nu = 0.25 (E* = E/(1 - nu^2) filled from the materials, by hand)."""
    import warnings
    from linecontact_sym.core.errors import DomainError, DomainWarning
    R = sp.Symbol("R", positive=True)
    c = lcs.LineContact(lcs.x_real**2 / (2 * R), symmetric=False, verify=False)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r0 = c.rolling(0.3, materials=((float("inf"), 0), (0.75, 0.5)))      # E* = 0.75/(1 - 1/4) = 1
        st0 = r0.state_at(Q=0.64 * 0.3 * np.pi / 4, P=np.pi / 4, theta=0.2, R=1)
    assert "uncouple exactly" in st0.coupling and st0.coupling.size == 0
    assert float(st0.creepage) == pytest.approx(0.3 * 0.4, rel=1e-14)          # Carter at E* = 1 (as above)
    with pytest.warns(DomainWarning, match="neglected"):
        r1 = c.rolling(0.3, materials=((float("inf"), 0), (0.9375, 0.25)))   # E* = 0.9375/(1 - 1/16) = 1
    st1 = r1.state_at(Q=0.64 * 0.3 * np.pi / 4, P=np.pi / 4, theta=0.2, R=1)
    assert float(st1.coupling.size) == pytest.approx(0.3 * 0.5 / 1.5, rel=1e-14)   # (1 - 2 nu)/(2 (1 - nu)) mu
    assert (st1.s, st1.creepage) == (st0.s, st0.creepage)
    with pytest.raises(DomainError, match="contradicts the materials"):
        r1.state_at(Q=0.1, P=np.pi / 4, theta=0.2, R=1, E_star=2)
