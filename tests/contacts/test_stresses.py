"""Subsurface stresses: closed forms, numeric field, maxima and critical
friction, each against an independent computation (the mpmath Flamant
quadrature of the tractions, McEwen's explicit Hertz field, Johnson's axis
formulas, a second quadrature route, a second optimiser)."""
import math

import mpmath
import numpy as np
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core import symbols as S
from linecontact_sym.core.errors import DomainError
from linecontact_sym.contacts.base import CONTACT_KINDS, qualified_quantities
from linecontact_sym.contacts.stresses.field import (CauchyPotential, ClosedPotential, FieldEvaluator,
                                                   PunchPotential)
from linecontact_sym.contacts.stresses.reference import flamant_stresses, punch_potentials
from linecontact_sym.contacts.stresses.contact import SlidingStressField, StressField

PHI = (1 + math.sqrt(5)) / 2
#: Hertz with p0 = a = 1: E* = 2, R = 1
HERTZ = dict(a=1, E_star=2, R=1)


def hertz_p(s):
    return mpmath.sqrt(1 - s**2) if abs(s) < 1 else mpmath.mpf(0)


def mcewen(x, z, p0=1.0, a=1.0):
    """McEwen (1949) / Johnson (1985) Eq. (4.50), signs of Johnson's Eq. (2.23)."""
    A = a**2 - x**2 + z**2
    r = math.sqrt(A**2 + 4 * x**2 * z**2)
    m, n = math.sqrt((r + A) / 2), math.copysign(math.sqrt((r - A) / 2), x)
    sx = -(p0 / a) * (m * (1 + (z**2 + n**2) / (m**2 + n**2)) - 2 * z)
    sz = -(p0 / a) * m * (1 - (z**2 + n**2) / (m**2 + n**2))
    txz = -(p0 / a) * n * (m**2 - z**2) / (m**2 + n**2)
    return sx, sz, txz


def hertz_closed(mu=0.0, nu=0.3):
    G = lambda w: np.pi * (w - w * np.sqrt(1 - 1 / w**2))  # noqa: E731
    dG = lambda w: np.pi * (1 - 1 / np.sqrt(1 - 1 / w**2))  # noqa: E731
    return FieldEvaluator(ClosedPotential(G, dG, 1.0), None, nu, friction=mu)


@pytest.fixture(scope="module")
def hertz():
    return lcs.parabola(verify=False).stresses(points=2)


@pytest.fixture(scope="module")
def sliding():
    return lcs.parabola(verify=False).stresses("sliding", verify=False)


POINTS = [(0.3, 0.5), (-0.7, 0.1), (1.5, 0.2), (0.9, 1e-3), (-0.999, 1e-4), (1.0, 1e-6), (-1.3, 2.0), (0.5, 1e-8)]


# ------------------------------------------------------------------ Kolosov formulas
def test_kolosov_field_equals_flamant_quadrature_with_friction():
    """The potentials' field (closed Hertz G, friction mu = 0.3) against the
    mpmath Flamant integrals of p and q = mu p, near the surface and the edges too."""
    fe = hertz_closed(mu=0.3)
    for x, z in POINTS:
        ref = flamant_stresses(hertz_p, lambda s: 0.3 * hertz_p(s), 1, x, z, dps=20)
        got = fe.components(np.array([x]), np.array([z]))
        for k, r in zip(("sigma_x", "sigma_z", "tau_xz"), ref):
            assert abs(got[k][0] - float(r)) < 2e-14, (x, z, k)


def test_mcewen_field_equals_flamant_quadrature():
    for x, z in POINTS[:4]:
        ref = flamant_stresses(hertz_p, None, 1, x, z, dps=20)
        for v, r in zip(mcewen(x, z), ref):
            assert abs(v - float(r)) < 1e-14


def test_surface_limits_under_sliding():
    """z -> 0: sigma_z = -p, tau_xz = -q, sigma_x = -p0 (sqrt(1 - x^2) + 2 mu x) (Johnson 7.2),
    tau_1 = mu p0 all over the contact, tensile 2 mu p0 at the trailing edge."""
    mu = 0.2
    fe = hertz_closed(mu)
    x = np.linspace(-0.99, 0.99, 41)
    c = fe(x, np.zeros_like(x))
    p = np.sqrt(1 - x**2)
    assert np.max(np.abs(c["sigma_z"] + p)) < 1e-9
    assert np.max(np.abs(c["tau_xz"] + mu * p)) < 1e-9
    assert np.max(np.abs(c["sigma_x"] + p + 2 * mu * x)) < 1e-9
    assert np.max(np.abs(c["principal_shear"] - mu)) < 1e-9
    assert abs(fe(np.array([-1.0]), np.array([0.0]), "sigma_x")[0] - 2 * mu) < 1e-5


# ------------------------------------------------------------------ the quadratures
def test_punch_superposition_equals_closed_hertz_potential_on_a_grid():
    """Popov's flat-punch superposition (quadrature of P'(t) = pi p0 t) against the closed G,
    down to z = 1e-9 a and across the edges."""
    X, Z = np.meshgrid(np.linspace(-2, 2, 41), np.concatenate([[0, 1e-9, 1e-6, 1e-3], np.linspace(0.01, 2, 12)]))
    num = FieldEvaluator(PunchPotential(lambda t: np.pi * t, 1.0), None, 0.3)(X, Z)
    ref = hertz_closed()(X, Z)
    for k in ("sigma_x", "sigma_z", "tau_xz", "von_mises"):
        assert np.nanmax(np.abs(num[k] - ref[k])) < 5e-13, k


def worn_density(t, b=0.4, R=3.0):
    """P'(t) of the worn cylinder (E* = 1), written by hand: (t acos(b/t) + b t/sqrt(t^2 - b^2))/R for t > b."""
    t = np.asarray(t, float)
    with np.errstate(all="ignore"):
        return np.where(t > b, (t * np.arccos(b / t) + b * t / np.sqrt(t**2 - b**2)) / R, 0.0)


def test_punch_quadrature_at_a_kink_against_mpmath():
    """A density singular at the kink b (the worn cylinder), evaluated there from the offset:
    the float64 potentials against an mpmath quadrature at 20 digits (5e-14: the
    kernel's peak sits on the density's singularity at x = -b)."""
    b = 0.4
    right = lambda dd: (((b + dd) * np.arccos(b / (b + dd)) + b * (b + dd) / np.sqrt(dd * (2 * b + dd))) / 3.0)  # noqa
    pot = PunchPotential(worn_density, 1.0, [b], near={b: (right, None)})
    dP = lambda t: (t * mpmath.acos(mpmath.mpf(2) / 5 / t) + t * mpmath.mpf(2) / 5 /  # noqa: E731
                    mpmath.sqrt(t**2 - mpmath.mpf(4) / 25)) / 3 if t > mpmath.mpf(2) / 5 else mpmath.mpf(0)
    for x, z in [(0.41, 0.02), (-0.4, 1e-4), (5.0, 5.0), (0.99, 1e-3)]:
        G, dG = pot(np.array([x]), np.array([z]))
        with mpmath.workdps(26):
            Gm, dGm = punch_potentials(dP, 1, x, z, [mpmath.mpf(2) / 5], 20)
        assert abs(G[0] - complex(Gm)) < 5e-14 * max(1, abs(Gm)), (x, z)
        assert abs(dG[0] - complex(dGm)) * z < 5e-14 * max(1, abs(Gm)), (x, z)


def test_cauchy_route_for_an_asymmetric_callable_traction():
    """A traction of no symmetry, q(s) = s sqrt(1 - s^2), by the Cauchy quadrature, against Flamant."""
    q = lambda s: s * np.sqrt(np.clip(1 - s**2, 0, None))  # noqa: E731
    fe = FieldEvaluator(ClosedPotential(lambda w: 0 * w, lambda w: 0 * w, 1.0), CauchyPotential(q, 1.0), 0.3)
    for x, z in [(0.3, 0.5), (-0.6, 0.01), (1.4, 0.3)]:
        ref = flamant_stresses(lambda s: 0, lambda s: s * mpmath.sqrt(1 - s**2) if abs(s) < 1 else 0, 1, x, z, dps=20)
        got = fe.components(np.array([x]), np.array([z]))
        for k, r in zip(("sigma_x", "sigma_z", "tau_xz"), ref):
            assert abs(got[k][0] - float(r)) < 1e-13, (x, z, k)


# ------------------------------------------------------------------ the contact class
def test_registry_and_construction(sliding):
    assert CONTACT_KINDS["stress"] is StressField
    names = qualified_quantities()
    for q in ("stress.sigma_x", "stress.max_shear", "stress.max_shear_depth", "stress.max_von_mises",
              "sliding_stress.sigma_x", "sliding_stress.critical_friction",
              "sliding_stress.critical_friction_von_mises"):
        assert q in names
    assert "stress.critical_friction" not in names and CONTACT_KINDS["sliding_stress"] is SlidingStressField
    sf = StressField.from_frictionless(lcs.parabola(verify=False))
    assert sf.tangential is None and S.mu not in sf.variables
    sl = SlidingStressField.from_frictionless(lcs.parabola(verify=False))
    assert sl.tangential == "sliding" and S.mu in sl.variables and isinstance(sliding, SlidingStressField)
    with pytest.raises(DomainError):
        StressField(lcs.parabola(verify=False), "partial_slip")
    with pytest.raises(DomainError):
        StressField(lcs.parabola(verify=False), "rolling")
    with pytest.raises(DomainError):
        sliding.field(a=1, E_star=2, R=1, mu=0.1)(np.array([0.0]), np.array([-0.1]))


def test_hertz_closed_form_is_verified_and_is_mcewens(hertz):
    G = hertz.cauchy_transform
    zeta0 = 0.3 + 0.7j
    assert abs(complex(G.subs({S.a: 1, S.E_star: 2, S.R: 1, S.zeta: zeta0}).evalf())
               - np.pi * (zeta0 - np.sqrt(zeta0**2 - 1))) < 1e-14
    d = hertz.derivation("sigma_x")
    assert d.closed_form and d.verification.passed and d.verification.min_digits >= 30
    assert abs(float(hertz.evaluate_at("sigma_x", x=-1.3, z=0.2, **HERTZ)) - mcewen(-1.3, 0.2)[0]) < 1e-15
    X, Z = np.meshgrid(np.linspace(-2, 2, 9), [1e-3, 0.1, 0.5, 1.5])
    c = hertz.field(**HERTZ)(X, Z)
    for k, v in zip(("sigma_x", "sigma_z", "tau_xz"), np.vectorize(mcewen)(X, Z)):
        assert np.max(np.abs(c[k] - v)) < 5e-14     # p0 = 1: roundoff of either formula


def test_hertz_maximum_shear_closed_form(hertz):
    """max tau_1 = phi^(-5/2) p0 = 0.300283 p0 at z = phi^(-1/2) a = 0.786151 a (McEwen 1949), the
    closed form from the axis, verified by the 2-D search."""
    assert sp.simplify(hertz.max_shear_depth - S.a * sp.sqrt((sp.sqrt(5) - 1) / 2)) == 0
    p0 = S.E_star * S.a / (2 * S.R)
    assert abs(sp.N(hertz.max_shear / p0 - PHI**-2.5, 30)) < 1e-15
    assert hertz.derivation("max_shear").verification.min_digits >= 12
    m = hertz.maximum("principal_shear", **HERTZ)
    assert m.digits >= 10 and abs(m.x) < 1e-6 and not m.on_surface
    assert abs(m.value - PHI**-2.5) < 1e-12 and abs(m.z - PHI**-0.5) < 1e-7


def test_hertz_von_mises_maximum_against_johnsons_axis_formulas(sliding):
    """Von Mises (nu = 0.3): the 2-D search against an mpmath root on the axis of
    Johnson's Eq. (4.49) sigma_x = -p0((1 + 2u^2)/sqrt(1 + u^2) - 2u), sigma_z = -p0/sqrt(1 + u^2)."""
    def vm(u):
        sx = -((1 + 2 * u**2) / mpmath.sqrt(1 + u**2) - 2 * u)
        sz = -1 / mpmath.sqrt(1 + u**2)
        sy = mpmath.mpf(3) / 10 * (sx + sz)
        return mpmath.sqrt(((sx - sy)**2 + (sy - sz)**2 + (sz - sx)**2) / 2)
    with mpmath.workdps(30):
        u = mpmath.findroot(lambda v: mpmath.diff(vm, v), 0.7)
        ref_value, ref_depth = vm(u), u
    m = sliding.maximum("von_mises", mu=0, nu=0.3, **HERTZ)
    assert m.digits >= 10 and abs(m.x) < 1e-6
    assert abs(m.value - float(ref_value)) < 1e-12 and abs(m.z - float(ref_depth)) < 1e-7
    assert round(m.value, 4) == 0.5575 and round(m.z, 4) == 0.7043
    t = sliding.maximum("tresca", mu=0, nu=0.3, **HERTZ)   # sigma_y intermediate: Tresca = 2 tau_1
    assert abs(t.value - 2 * PHI**-2.5) < 1e-11


def test_sliding_maximum_moves_off_axis_and_to_the_surface(sliding):
    m = sliding.maximum("principal_shear", mu=0.2, **HERTZ)
    assert m.digits >= 10 and 0.6 < m.x < 0.65 and 0.58 < m.z < 0.62 and abs(m.value - 0.318989) < 1e-6
    v = sliding.maximum("von_mises", mu=0.3, nu=0.3, **HERTZ)
    assert v.on_surface and v.digits >= 10 and abs(v.x - 0.287348) < 1e-5


def test_critical_friction_von_mises(sliding):
    muc, check, digits, kind = sliding.friction_limit("von_mises", nu=0.3, **HERTZ)
    assert kind == "crossing" and digits >= 6 and abs(muc - 0.2628258) < 1e-6
    below = sliding.maximum("von_mises", mu=muc - 1e-4, nu=0.3, **HERTZ)
    above = sliding.maximum("von_mises", mu=muc + 1e-4, nu=0.3, **HERTZ)
    assert not below.on_surface and above.on_surface


def test_partial_slip_against_flamant():
    """q = mu [p(x; a) - p(x; c)] in the stick zone: H = mu (G(a) - G(c)), against Flamant."""
    sf = lcs.parabola(verify=False).stresses("partial_slip", stick=sp.Rational(1, 2), verify=False)
    fe = sf.field(mu=0.3, nu=0.3, **HERTZ)
    c = 0.5

    def q(s):
        return 0.3 * (hertz_p(s) - (mpmath.sqrt(c**2 - s**2) if abs(s) < c else 0))
    for x, z in [(0.2, 0.3), (-0.5, 0.01), (0.8, 1e-3), (1.3, 0.5)]:
        ref = flamant_stresses(hertz_p, q, 1, x, z, breaks=(-c, c), dps=20)
        got = fe.components(np.array([x]), np.array([z]))
        for k, r in zip(("sigma_x", "sigma_z", "tau_xz"), ref):
            assert abs(got[k][0] - float(r)) < 1e-13, (x, z, k)


def test_tangential_expression_equals_sliding(sliding):
    q = S.mu * S.E_star / (2 * S.R) * sp.sqrt(S.a**2 - S.x**2)
    sf = lcs.parabola(verify=False).stresses(q, verify=False)
    X, Z = np.meshgrid(np.linspace(-1.5, 1.5, 7), [0.01, 0.3, 1.0])
    a = sf.field(mu=0.25, **HERTZ)(X, Z)
    b = sliding.field(mu=0.25, **HERTZ)(X, Z)
    for k in ("sigma_x", "sigma_z", "tau_xz"):
        assert np.max(np.abs(a[k] - b[k])) < 1e-12


def test_power_law_closed_form_is_hypergeometric_and_field_matches_reference():
    c = lcs.power_law(verify=False)
    sf = c.stresses(points=1)
    assert sf.cauchy_transform.has(sp.hyper) and sf.derivation("sigma_z").verification.passed
    fe = sf.field(a=1, E_star=1, c=1, n=2.5, nu=0.3)
    for x, z in [(0.3, 0.4), (-0.95, 0.01)]:
        ref = sf.evaluate_at("sigma_z", dps=20, x=x, z=z, a=1, E_star=1, c=1, n=2.5)
        assert abs(fe(np.array([x]), np.array([z]), "sigma_z")[0] - float(ref)) < 1e-13


def test_to_numeric_field_and_plots(sliding, tmp_path):
    fn = sliding.to_numeric("von_mises", mu=0.1, nu=0.3, **HERTZ)
    X, Z = np.meshgrid(np.linspace(-2, 2, 50), np.linspace(0, 2, 40))
    V = fn(x=X, z=Z)
    assert V.shape == X.shape and np.all(np.isfinite(V))
    plt = pytest.importorskip("matplotlib.pyplot")
    ax = sliding.plot("von_mises", mu=0.1, nu=0.3, n=(41, 21), **HERTZ)
    ax2 = sliding.plot_axis(mu=0, nu=0.3, **HERTZ)
    ax.figure.savefig(tmp_path / "vm.png")
    assert ax.get_xlabel() == "$x/a$" and ax2.get_ylabel() == "depth $z/a$"
    plt.close("all")


def test_singular_tractions_give_unbounded_maxima():
    """The wedge: the pressure is logarithmic at the tip, so sigma_x, sigma_z and with them von Mises
    grow without bound there; tau_1 stays bounded, E* tan(theta)/pi on the axis at the surface."""
    sf = lcs.wedge(verify=False).stresses(verify=False)
    vm = sf.maximum("von_mises", a=1, E_star=1, theta=0.2, nu=0.3)
    assert vm.unbounded and vm.value == math.inf and abs(vm.x) < 1e-6
    t1 = sf.maximum("principal_shear", a=1, E_star=1, theta=0.2)
    assert not t1.unbounded and abs(t1.value - math.tan(0.2) / math.pi) < 1e-7


def test_principal_shear_reaches_the_surface_at_mu_one_over_sqrt7(sliding):
    """At mu = 1/sqrt(7) the interior maximum of tau_1 is mu p0, the surface value, at
    (3 sqrt(7)/8, 1/8) a: the value and a vanishing gradient there (float64 field)."""
    fe = sliding.field(mu=1 / np.sqrt(7), **HERTZ)           # a NumPy scalar is accepted
    x0, z0, h = 3 * math.sqrt(7) / 8, 1 / 8, 1e-5

    def f(x, z):
        return fe(np.array([x]), np.array([z]), "principal_shear")[0]
    assert abs(f(x0, z0) - 1 / math.sqrt(7)) < 1e-14
    assert abs(f(x0 + h, z0) - f(x0 - h, z0)) / (2 * h) < 1e-8
    assert abs(f(x0, z0 + h) - f(x0, z0 - h)) / (2 * h) < 1e-8
    m = sliding.maximum("principal_shear", mu=1 / math.sqrt(7) - 1e-3, **HERTZ)
    assert not m.on_surface and m.value > 1 / math.sqrt(7) - 1e-3


def test_stress_plot_needs_only_the_profile_parameters(hertz):
    """Issue 23: a, E* and Poisson's ratio default (a = E* = 1 scale out of
    sigma/p0 over (x/a, z/a); nu = 0.3 is said in the title); the maximum
    marked is Hertz's tau_1 = 0.300 p0 at z = 0.786 a (Johnson, Eq. 4.51)."""
    plt = pytest.importorskip("matplotlib.pyplot")
    ax = hertz.plot("principal_shear", R=1, n=(41, 21))
    assert ax.get_title() == r"$\tau_1$ under the parabola, $f(x) = \frac{x^{2}}{2 R}$"
    star = [ln for ln in ax.lines if ln.get_marker() == "*"][0]
    assert star.get_ydata()[0] == pytest.approx(0.786, abs=2e-3)
    ax = hertz.plot(R=1, n=(41, 21))
    assert ax.get_title().endswith(r"($\nu = 0.3$)")
    plt.close("all")


def test_unchecked_search_finds_the_same_maximum():
    """find_maximum(check=False) (the critical-friction searches) skips only
    the gradient-root check: value, place, interior and surface are the same
    numbers, analytic maxima below and on the surface."""
    from linecontact_sym.contacts.stresses.extrema import find_maximum
    below = lambda x, z: z * np.exp(-x**2 - z**2)                       # noqa: E731  max 1/sqrt(2e) at (0, 1/sqrt 2)
    on = lambda x, z: np.exp(-(x - 0.3)**2 - z) * (1 + 0 * z)           # noqa: E731  max 1 at (0.3, 0)
    for fn, surface in ((below, False), (on, True)):
        full, fast = find_maximum(fn, 1.0, symmetric=True), find_maximum(fn, 1.0, symmetric=True, check=False)
        assert (fast.value, fast.x, fast.z, fast.on_surface, fast.interior, fast.surface) == \
            (full.value, full.x, full.z, full.on_surface, full.interior, full.surface)
        assert full.on_surface is surface and math.isnan(fast.check) and math.isnan(fast.digits)
    assert abs(find_maximum(below, 1.0, check=False).value - 1 / math.sqrt(2 * math.e)) < 1e-14


def test_one_equivalent_stress_is_the_same_as_in_all():
    fe = hertz_closed(mu=0.2)
    X, Z = np.meshgrid(np.linspace(-1.5, 1.5, 9), [1e-3, 0.4, 1.2])
    every = fe(X, Z)
    for k in ("principal_shear", "von_mises", "tresca", "sigma_x", "sigma_y"):
        assert np.array_equal(fe(X, Z, k), every[k])
    with pytest.raises(DomainError, match="unknown stress quantity"):
        fe(X, Z, "sigma_q")


def test_a_frictional_field_states_the_neglected_coupling_and_keeps_its_numbers():
    """The stress field of a sliding contact is Goodman's approximation as the
    tangential layer's results are: its derivations say 'beta = 0 assumed' or
    |beta| mu for the bodies given (steel on aluminium: beta from Dundurs'
    shear moduli by hand, -0.1167), one DomainWarning, the same numbers; the
    frictionless field takes no bodies."""
    import warnings
    from linecontact_sym.core.errors import DomainError, DomainWarning
    c = lcs.parabola(verify=False)
    plain = c.stresses("sliding", verify=False)
    assert plain.derivation("critical_friction").notes[0].startswith("beta = 0 assumed")
    E1, n1, E2, n2 = 210e9, 0.3, 70e9, 0.33
    G1, G2 = E1 / (2 * (1 + n1)), E2 / (2 * (1 + n2))
    beta = 0.5 * ((1 - 2 * n1) / G1 - (1 - 2 * n2) / G2) / ((1 - n1) / G1 + (1 - n2) / G2)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        bodies = c.stresses("sliding", verify=False, materials=((E1, n1), (E2, n2)))
    assert sum(issubclass(w.category, DomainWarning) for w in caught) == 1
    note = bodies.derivation("critical_friction").notes[0]
    assert f"{beta:.4f}" in note and "|beta| mu" in note, note
    vals = dict(a=1, R=1, mu=0.3, nu=0.3, E_star=2)
    assert bodies.maximum("von_mises", **vals).value == plain.maximum("von_mises", **vals).value
    with pytest.raises(DomainError, match="frictional traction"):
        c.stresses(verify=False, beta=0.1)
