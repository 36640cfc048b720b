"""The asymmetric line contact (issue 39) against an independent
Gauss-Chebyshev collocation of the singular integral equation
(:mod:`sie_collocation`, written for these tests: no force law, no split)."""
import os
import sys

import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core import symbols as S

sys.path.insert(0, os.path.dirname(__file__))
import sie_collocation as C  # noqa: E402

X = S.x_real


def digits(u, v):
    u, v = mpmath.mpf(u), mpmath.mpf(v)
    if u == v:
        return 99
    return float(-mpmath.log10(abs(u - v) / max(abs(v), mpmath.mpf(10)**-40)))


# the engine's own verification of each part is skipped where the test compares with the
# independent collocation anyway (it costs a quadrature per part and point); test_engine_records keeps it
FAST = dict(verify=False)


@pytest.fixture(scope="module")
def cubic_line():
    return lcs.LineContact(X**2 / 2 + X**3 / 10, symmetric=False, **FAST)


@pytest.fixture(scope="module")
def cubic(cubic_line):
    return cubic_line.core


R_ = sp.Symbol("R", positive=True)


@pytest.fixture(scope="module")
def hertz():
    """The symmetric parabola and its twin on the whole line (one set of derivations)."""
    c = lcs.LineContact(lcs.x**2 / (2 * R_), **FAST)
    return c, c.asymmetric()


@pytest.fixture(scope="module")
def exponential():
    return lcs.LineContact(sp.exp(X) - 1 - X, symmetric=False, **FAST)


def test_cubic_symbolic_forms(cubic):
    e, a = S.e, S.a
    assert sp.simplify(cubic.force() - sp.pi * S.E_star * a**2 * (3 * e + 5) / 20) == 0
    assert sp.expand(cubic.tilt() - (e + 3 * e**2 / 10 + 3 * a**2 / 20)) == 0
    # the tilt is the mean slope over the contact: (1/pi) int f'(e + a sin phi) dphi
    ph = sp.Symbol("phi", real=True)
    mean = sp.integrate((X + 3 * X**2 / 10).subs(X, e + a * sp.sin(ph)), (ph, -sp.pi / 2, sp.pi / 2)) / sp.pi
    assert sp.expand(cubic.tilt() - mean) == 0
    assert cubic.edge_factors() == (0, 0)


@pytest.mark.parametrize("ev, av", [("0.3", "0.7"), ("-1.1", "0.4")])
def test_cubic_bounded_against_collocation(cubic, ev, av):
    with mpmath.workdps(40):
        e, a = mpmath.mpf(ev), mpmath.mpf(av)
        n = cubic.numbers(E_star=2)
        sol = C.bounded(lambda x: x + 3 * x**2 / 10, e, a, E=2, N=16)
        assert digits(n.tilt(e, a), sol.theta) > 30
        assert digits(n.P(e, a), sol.load) > 30
        assert digits(n.moment(e, a), sol.moment) > 30
        for xv in (e - a / 2, e + a / 3, e + 9 * a / 10):
            assert digits(n.pressure(xv, e, a), sol.pressure(xv)) > 28


def test_parabola_is_hertz_shifted(hertz):
    R = R_
    c = hertz[1].core
    assert sp.simplify(c.tilt() - S.e / R) == 0
    assert c.moment_centre() == 0
    assert sp.simplify(c.pressure() - S.E_star * sp.sqrt(S.a**2 - (X - S.e)**2) / (2 * R)) == 0


def test_tilted_parabola_ends_in_closed_form(hertz):
    """Hertz shifted by R theta, found by solving the engine's P(e, a) and theta(e, a)."""
    R = R_
    c = hertz[1]
    (sol,) = c.ends()
    assert sol["e"] == R * S.tilt
    assert sp.simplify(sol["a"]**2 - 4 * S.P * R / (sp.pi * S.E_star)) == 0
    (sol,) = c.ends(moment=S.M)
    assert sol["e"] == S.M / S.P


def test_exponential_bounded_against_collocation(exponential):
    c = exponential.core
    assert c.closed()      # Bessel I force laws of E = e^e (cosh s - 1) and H
    with mpmath.workdps(30):
        e, a = mpmath.mpf("0.3"), mpmath.mpf("0.7")
        n = c.numbers(E_star=2)
        sol = C.bounded(lambda x: mpmath.exp(x) - 1, e, a, E=2, N=24)
        assert digits(n.tilt(e, a), sol.theta) > 25
        assert digits(n.P(e, a), sol.load) > 25
        assert digits(n.moment(e, a), sol.moment) > 25


# ---------------------------------------------------------------- states: contact_at
from linecontact_sym.contacts.asymmetric import flat_punch  # noqa: E402
from linecontact_sym.core.errors import DomainError, ProfileError  # noqa: E402


@pytest.fixture(scope="module")
def punch():
    return flat_punch(1)


def test_flat_punch_complete_against_collocation(punch):
    with mpmath.workdps(30):
        s = punch.contact_at(P=1, theta="1/10", E_star=2)
        assert s.regime == "complete" and s.edges == ("corner", "corner")
        assert (s.left, s.right) == (-1, 1)
        sol = C.singular(lambda x: 0, 0, 1, theta=mpmath.mpf(1) / 10, load=1, E=2, N=8)
        assert digits(s.moment, sol.moment) > 28
        for xv in ("-0.9", "0.2", "0.95"):
            assert digits(s.pressure(mpmath.mpf(xv)), sol.pressure(mpmath.mpf(xv))) > 28
        assert min(s.factors) > 0


def test_flat_punch_incomplete_against_collocation(punch):
    with mpmath.workdps(30):
        s = punch.contact_at(P=1, theta="2/5", E_star=2)
        assert s.regime == "right corner" and s.edges == ("smooth", "corner")
        assert s.right == 1 and s.factors[0] == 0 and s.factors[1] > 0
        sol = C.right_corner(lambda x: 0, s.e, s.a, load=1, E=2, N=8)
        assert digits(sol.theta, mpmath.mpf(2) / 5) > 28
        assert digits(s.moment, sol.moment) > 28
        for xv in ("-0.5", "0.2", "0.95"):
            assert digits(s.pressure(mpmath.mpf(xv)), sol.pressure(mpmath.mpf(xv))) > 28


def test_flat_punch_transition_is_at_eccentricity_half_the_width(punch):
    # the load's line of action at w/2: complete contact with a vanishing factor at the lifting corner
    s = punch.contact_at(P=3, moment="3/2", E_star=1)
    assert abs(s.factors[0]) < 1e-25 and s.left == -1
    below = punch.contact_at(P=3, moment="1.49", E_star=1)
    above = punch.contact_at(P=3, moment="1.51", E_star=1)
    assert below.regime == "complete" and above.regime == "right corner" and above.left > -1
    # tilt at the transition: 2 P/(pi E* w)
    assert digits(s.theta, 6 / mpmath.pi) > 25


def test_cubic_rotation_locked_against_collocation(cubic_line):
    with mpmath.workdps(30):
        s = cubic_line.contact_at(P=1, theta="0.2", E_star=2)
        assert s.edges == ("smooth", "smooth") and s.regime == "bounded"
        sol = C.bounded(lambda x: x + 3 * x**2 / 10, s.e, s.a, E=2, N=12)
        assert digits(sol.theta, mpmath.mpf(1) / 5) > 25
        assert digits(sol.load, 1) > 25
        assert digits(sol.moment, s.moment) > 25


def test_cubic_rotation_free_against_collocation(cubic_line):
    with mpmath.workdps(30):
        s = cubic_line.contact_at(P=1, moment="0.1", E_star=2)
        sol = C.bounded(lambda x: x + 3 * x**2 / 10, s.e, s.a, E=2, N=12)
        assert digits(sol.moment, mpmath.mpf(1) / 10) > 25
        assert digits(sol.load, 1) > 25
        assert digits(sol.theta, s.theta) > 25


@pytest.mark.slow
def test_cubic_gap_against_collocation(cubic_line):
    """The gap g(x) = f(x) - theta x - d + u(x) outside the contact against the
    displacement of the collocated pressure (Gauss-Chebyshev of the log kernel)."""
    with mpmath.workdps(30):
        s = cubic_line.contact_at(P=1, moment="0.1", E_star=2)
        sol = C.bounded(lambda x: x + 3 * x**2 / 10, s.e, s.a, E=2, N=12)
        f = lambda x: x**2 / 2 + x**3 / 10  # noqa: E731
        for x1 in (s.right + 1, s.left - mpmath.mpf(1) / 2):
            # g(x1) - g(x_edge) = f(x1) - f(edge) - theta (x1 - edge) + u(x1) - u(edge)
            edge = s.right if x1 > s.right else s.left
            du = C.displacement_difference(sol, x1, edge)
            expect = f(x1) - f(edge) - s.theta * (x1 - edge) + du
            assert digits(s.gap(x1), expect) > 20


def test_symmetric_profile_level_is_todays_contact(hertz):
    c = hertz[0]
    s = c.contact_at(P=1, E_star=2, R=3)
    assert s.e == 0 and s.theta == 0 and s.moment == 0 and s.edges == ("smooth", "smooth")
    assert digits(s.a, c.half_width(1, E_star=2, R=3)) > 28
    # the pressure is the symmetric contact's own, at |x|
    assert s.pressure(mpmath.mpf("-0.4")) == c.evaluate_at("pressure", dps=15, a=s.a, x="0.4", E_star=2, R=3)
    xs = np.array([-1.0, -0.3, 0.0, 0.7, 2.0])
    assert np.allclose(s.pressure(xs)[1:4], [float(c.evaluate_at("pressure", a=s.a, x=abs(v), E_star=2, R=3))
                                             for v in xs[1:4]], rtol=1e-14, atol=0)
    assert s.pressure(xs)[-1] == 0
    twin = c.asymmetric().core
    assert twin.force().subs(S.e, 0) == c.force
    assert sp.simplify(twin.pressure().subs(S.e, 0) - c.pressure.subs(lcs.x, X)) == 0
    tilted = c.contact_at(P=1, theta="0.01", E_star=2, R=3)      # Hertz shifted by R theta
    assert digits(tilted.e, mpmath.mpf("0.03")) > 25 and digits(tilted.a, s.a) > 25


def test_validation_errors():
    with pytest.raises(ProfileError, match="real x"):
        lcs.LineContact(lcs.x**2, symmetric=False)
    with pytest.raises(ProfileError, match="theta_t"):
        lcs.LineContact(X**2 * S.e, symmetric=False)
    with pytest.raises(DomainError, match="not both"):
        flat_punch(1).contact_at(P=1, theta=0, moment=0, E_star=1)
    with pytest.raises(DomainError, match="positive"):
        flat_punch(1).contact_at(P=-1, theta=0, E_star=1)
    with pytest.raises(ProfileError, match="positive number"):
        flat_punch(-1)


# ---------------------------------------------------------------- the asymmetric wedge (a kink)
K1, K2 = sp.symbols("k1 k2", positive=True)


@pytest.fixture(scope="module")
def wedge():
    return lcs.LineContact(sp.Piecewise((K1 * X, X >= 0), (-K2 * X, True)), symmetric=False, **FAST)


def test_wedge_tilt_is_the_mean_slope(wedge):
    # two cases of the centre; for a > |e| the tilt is (1/pi) int f'(e + a sin phi) dphi
    assert len(wedge.core.cases) == 2
    e, a = S.e, S.a
    mean = (K1 - K2) / 2 + (K1 + K2) * sp.asin(e / a) / sp.pi
    th = wedge.core.tilt()
    for ev, av in ((sp.Rational(1, 5), sp.Rational(1, 2)), (-sp.Rational(1, 3), 2)):
        got = th.subs({e: ev, a: av, K1: 1, K2: sp.Rational(7, 3), S.E_star: 3})
        assert abs(sp.N(got - mean.subs({e: ev, a: av, K1: 1, K2: sp.Rational(7, 3)}), 30)) < 1e-25


@pytest.mark.parametrize("given", [dict(theta=0), dict(moment="0.2"), dict(theta="-0.3")])
def test_wedge_states_against_chebyshev_moments(wedge, given):
    """The wedge's slope jumps: collocation converges like 1/N (and erratically
    with where the jump falls), so the reference is its N -> oo limit, the
    Chebyshev moments of f' by quadrature split at the kink, and the pressure
    by the inversion formula; both share nothing with the superposition."""
    fp = lambda x: 1 if x > 0 else -2  # noqa: E731
    with mpmath.workdps(20):
        s = wedge.contact_at(P=1, E_star=1, k1=1, k2=2, **given)
        th, P, M = C.chebyshev_moments(fp, s.e, s.a, 1, [0])
        assert digits(P, 1) > 18 and digits(th + 1, s.theta + 1) > 18 and digits(M, s.moment) > 18


@pytest.mark.slow
def test_wedge_pressure_against_inversion(wedge):
    """The log pressure of the wedge (the engine's pressures of both cases' parts, about 20 s)."""
    fp = lambda x: 1 if x > 0 else -2  # noqa: E731
    with mpmath.workdps(20):
        s = wedge.contact_at(P=1, E_star=1, k1=1, k2=2, moment="0.2")
        for xv in (s.left + (s.right - s.left) / 3, 2 * s.e, s.right - (s.right - s.left) / 10):
            # 2e: the mirror image of the apex, where the closed form cancels (extra digits there)
            assert digits(s.pressure(xv), C.inversion_pressure(fp, s.left, s.right, xv, [0])) > 12
        # log singularity at the apex: the pressure grows without bound
        assert s.pressure(mpmath.mpf("1e-12")) > s.pressure(mpmath.mpf("1e-3")) + 1


def test_exponential_states_against_collocation(exponential):
    c = exponential
    with mpmath.workdps(25):
        for given in (dict(theta="0.1"), dict(moment="-0.05")):
            s = c.contact_at(P=1, E_star=2, **given)
            sol = C.bounded(lambda x: mpmath.exp(x) - 1, s.e, s.a, E=2, N=20)
            assert digits(sol.theta, s.theta) > 20 and digits(sol.load, 1) > 20
            assert digits(sol.moment, s.moment) > 20


@pytest.mark.slow
def test_exponential_pressure_against_collocation(exponential):
    """The engine leaves Eq. (12) of the cosh profile as an Integral: the pressure is the Eq. (12)
    quadrature over the closed (Bessel) force laws, the odd part's s-derivative under the integral."""
    c = exponential
    with mpmath.workdps(15):
        s = c.contact_at(P=1, E_star=2, moment="-0.05")
        sol = C.bounded(lambda x: mpmath.exp(x) - 1, s.e, s.a, E=2, N=16)
        xv = s.e + s.a / 3
        assert digits(s.pressure(xv), sol.pressure(xv)) > 12


# ---------------------------------------------------------------- float64 at the extremes
import numpy as np  # noqa: E402


def _rel_err(state, xs):
    """The float64 pressure's error at float64 points against mpmath at the same points, in
    units of its conditioning eps |x| / (distance to the nearer end): an end that float64
    cannot represent moves the distance by eps |x|, which no formula can undo."""
    got = state.pressure(np.array(xs))
    worst = 0.0
    with mpmath.workdps(40):
        for g, v in zip(got, xs):
            r = state.pressure(mpmath.mpf(v))
            dist = min(v - state.left, state.right - v)
            cond = float(np.finfo(float).eps * max(1.0, abs(v) / dist))
            worst = max(worst, abs(g - float(r)) / abs(float(r)) / cond)
    return worst


@pytest.mark.parametrize("M", ["0.5", "0.4999999999", "0.5000000001"])
def test_flat_punch_float64_at_the_transition(punch, M):
    # the factor at the lifting corner vanishes: (C0 + C1 s) cancels there unless written with the factors
    s = punch.contact_at(P=1, moment=M, E_star=1, dps=40)
    left = float(s.left)
    xs = [left + 1e-12, left + 1e-8, left + 1e-4, 0.0, 0.9, float(s.right) - 1e-10]
    assert _rel_err(s, xs) < 20


def test_tiny_tilt_float64(cubic_line):
    # a smooth profile tilted by 1e-12: the ends differ by almost nothing; near them the
    # even and odd parts' 1/sqrt terms cancel unless put over one denominator
    s = cubic_line.contact_at(P=1, theta="-2.1e-12", E_star=2, dps=40)
    left, right = float(s.left), float(s.right)
    xs = [left + 1e-12 * (right - left), left + 1e-6, 0.1, right - 1e-9, right - 1e-13]
    assert _rel_err(s, xs) < 20


# ---------------------------------------------------------------- the command line
def test_cli_eval_theta_and_moment(capsys):
    from linecontact_sym import cli
    assert cli.main(["eval", "x**2/2", "e", "--theta", "0.1", "--set", "P=1", "E_star=2", "--dps", "20"]) == 0
    assert capsys.readouterr().out.split()[-1] == "0.1"       # Hertz shifted by R theta (R = 1)
    assert cli.main(["eval", "x**2/2", "e", "--moment", "0.3", "--set", "P=2", "E_star=2"]) == 0
    assert capsys.readouterr().out.split()[-1] == "0.15"      # the line of action M/P
    assert cli.main(["eval", "x**2/2", "force", "--theta", "0.1", "--set", "P=1", "E_star=2"]) == 2


def test_state_evaluate_picks_float64_or_mpmath(cubic_line):
    s = cubic_line.contact_at(P=1, theta="0.2", E_star=2)
    xs = np.array([float(s.e), float(s.left) + 1e-15])
    got = s.evaluate("pressure", xs, rtol=1e-10)          # the second point: too close for float64, mpmath
    with mpmath.workdps(30):
        ref = [float(s.pressure(mpmath.mpf(v))) for v in xs]
    assert all(abs(g - r) <= 1e-10 * abs(r) for g, r in zip(got, ref))
    with pytest.raises(DomainError, match="rtol"):
        s.evaluate("pressure", 0.1, rtol=0)


# ---------------------------------------------------------------- several kinks: refused, and why
def test_several_kinks_are_refused_with_the_switches_named():
    """A tilt or a moment of a profile with several switches (the worn cylinder
    on the whole line: -b, 0 from its |x|, b) is a ProfileError naming them and
    the one-switch case split."""
    wc = lcs.worn_cylinder(verify=False)
    vals = dict(E_star=1, R=1, b=sp.Rational(1, 5))
    for kw in (dict(theta=sp.Rational(1, 10)), dict(moment=sp.Rational(1, 10))):
        with pytest.raises(ProfileError, match=r"switches at 3 points \(0, -b, b;.*several distances \|e - b_i\|"):
            wc.contact_at(P=1, **kw, **vals)
    with pytest.raises(ProfileError, match=r"switches at 2 points \(-1, 1;.*one switch"):
        lcs.LineContact(sp.Piecewise((0, X < -1), (X**2, X < 1), (1, True)), symmetric=False, **FAST)


# ---------------------------------------------------------------- the admissible ends
def _cubic_branches(P, E, th):
    """The six (e, +-a) of the tilted cubic x^2/2 + x^3/10 by hand: P = pi E* a^2 (3e + 5)/20 and
    theta = e + 3e^2/10 + 3a^2/20 give (e + 3e^2/10 - theta)(3e + 5) + 3P/(pi E*) = 0."""
    e = sp.Symbol("e")
    poly = sp.Poly(sp.expand((e + 3 * e**2 / 10 - th) * (3 * e + 5) + 3 * P / (sp.pi * E)), e)
    out = []
    for r in poly.nroots(n=50):
        a = sp.sqrt(20 * P / (sp.pi * E * (3 * r + 5))).evalf(50)
        out += [{"e": r, "a": a}, {"e": r, "a": -a}]
    return out


def test_ends_keep_only_the_admissible_branch(cubic_line):
    """Of the six branches of the cubic at P = 1, theta = 1/5, E* = 2 (one with a complex a,
    two with a < 0 ... and e = -1.51, a = 2.62: real, but its bounded pressure is negative
    across part of the contact) one is admissible: the state contact_at solves."""
    from linecontact_sym.contacts.asymmetric.contact import _admissible_ends, _positive_of_pairs
    brs = _cubic_branches(1, 2, sp.Rational(1, 5))
    assert len(brs) == 6
    kept = _admissible_ends(cubic_line.core, brs, {"E_star": 2})
    assert len(kept) == 1
    st = cubic_line.contact_at(P=1, theta=sp.Rational(1, 5), E_star=2)
    assert digits(kept[0]["e_value"], st.e) > 25 and digits(kept[0]["a_value"], st.a) > 25
    real_positive = [b for b in brs if b["e"].is_real and b["a"].is_real and b["a"] > 0]
    assert len(real_positive) == 2            # the pressure's sign decides between them
    r = sp.sqrt(S.P / S.E_star)
    assert _positive_of_pairs([-2 * r, 2 * r]) == [2 * r]
    assert _positive_of_pairs([r, 1 - r]) == [r, 1 - r]     # not a pair: both kept


@pytest.mark.slow
def test_ends_of_the_cubic_symbolic_and_at_numbers(cubic_line):
    """ends(): the load's pair +-a(e) halves SymPy's six branches to the three roots of the
    cubic in e; with values, the one admissible branch."""
    from linecontact_sym.contacts.asymmetric.contact import _admissible_ends
    branches = cubic_line.ends(load=1, theta="1/5")        # (text: the parser, no eval)
    assert len(branches) == 3
    kept = _admissible_ends(cubic_line.core, branches, {"E_star": 2})   # = ends(..., E_star=2)
    st = cubic_line.contact_at(P=1, theta=sp.Rational(1, 5), E_star=2)
    assert len(kept) == 1 and digits(kept[0]["e_value"], st.e) > 25 and digits(kept[0]["a_value"], st.a) > 25

def test_cosh_parts_close_termwise():
    """cosh(x) - 1 about e: the split writes cosh(e +- s) as cosh(e) cosh(s) +- sinh(e) sinh(s), so
    the termwise rule closes both parts (Bessel I) at once; left as cosh(e + s), each part's
    sympy.integrate spent 8 CPU s to leave an Integral.  P(e, a) and theta(e, a) against
    (E* a/2) int f'(e + a sin phi) sin phi dphi and (1/pi) int f'(e + a sin phi) dphi (mpmath)."""
    from linecontact_sym.contacts.asymmetric.core import OffsetContact
    oc = OffsetContact(sp.cosh(S.x_real) - 1)
    P, th = oc.force(), oc.tilt()
    assert not P.has(sp.Integral) and not th.has(sp.Integral, sp.Derivative)
    ev, av, E = sp.Rational(-3, 10), sp.Rational(7, 5), 2
    with mpmath.workdps(30):
        e, a = mpmath.mpf(ev), mpmath.mpf(av)
        P_ref = E * a / 2 * mpmath.quad(lambda ph: mpmath.sinh(e + a * mpmath.sin(ph)) * mpmath.sin(ph),
                                        [-mpmath.pi / 2, mpmath.pi / 2])
        th_ref = mpmath.quad(lambda ph: mpmath.sinh(e + a * mpmath.sin(ph)), [-mpmath.pi / 2, mpmath.pi / 2]) / mpmath.pi
        at = {S.e: ev, S.a: av, S.E_star: E}
        assert abs(sp.N(P.xreplace(at), 30) - P_ref) < 1e-25 * abs(P_ref)
        assert abs(sp.N(th.xreplace(at), 30) - th_ref) < 1e-25 * abs(th_ref)
