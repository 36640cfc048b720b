"""Viscoelastic line contacts (Lee-Radok, Ting) against independent numbers:
the hereditary integral in time by our own quadrature (the elastic force law
by our own quadrature of Eq. 10, textbook relaxation functions written here),
Ting's rule by our own root for the loading time, and a time-stepping
boundary-element solution (tests/contacts/visco_bem.py)."""
from __future__ import annotations

import functools
import os
import sys

import mpmath
import numpy as np
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core.errors import DomainError
from linecontact_sym.contacts.viscoelastic import MultipleMaximaError

sys.path.insert(0, os.path.dirname(__file__))
from visco_bem import creep_bem  # noqa: E402

t = lcs.t
R = lcs.R
HALF = sp.Rational(1, 2)


# ---------------------------------------------------------------- our own references
# P(a)/E* = int_0^a f'(x) x / sqrt(a^2 - x^2) dx (Popov Eq. 10); its derivative in a by tanh-sinh:
def dPi_ref(fprime, A):
    """d/da of Pi_ref after x = a sin(phi): int_0^{pi/2} [f''(a sin) a sin^2 + f'(a sin) sin] dphi."""
    f1, f2 = FP[fprime]
    return mpmath.quad(lambda ph: f2(A * mpmath.sin(ph)) * A * mpmath.sin(ph)**2 + f1(A * mpmath.sin(ph)) * mpmath.sin(ph),
                       [0, mpmath.pi / 2])


PROFILES = {   # name: (contact, f' key, values)
    "parabola": (lambda: lcs.parabola(verify=False), "parabola", {"R": 1}),
    "x^4": (lambda: lcs.LineContact(lcs.x**4, verify=False), "x^4", {}),
    "wedge": (lambda: lcs.wedge(verify=False), "wedge", {"theta": HALF * 2 / 3}),
}
FP = {"parabola": (lambda x: x, lambda x: 1), "x^4": (lambda x: 4 * x**3, lambda x: 12 * x**2),
      "wedge": (lambda x: mpmath.tan(mpmath.mpf(1) / 3), lambda x: 0)}     # f', f''  (R = 1, theta = 1/3)
# materials: (package object, E(t) regular part, eta) -- the textbook relaxation functions written here
MATERIALS = {
    "maxwell": (lambda: lcs.maxwell(E0=2, tau=1), lambda s: 2 * mpmath.exp(-s), 0),
    "kelvin_voigt": (lambda: lcs.kelvin_voigt(E=1, eta=HALF), lambda s: mpmath.mpf(1), HALF),
    "sls": (lambda: lcs.standard_linear_solid(E0=3, E_inf=1, tau=HALF), lambda s: 1 + 2 * mpmath.exp(-2 * s), 0),
    "prony3": (lambda: lcs.prony(E_inf=1, terms=[(2, 1), (HALF * 3, 10), (HALF, sp.Rational(1, 10))]),
               lambda s: 1 + 2 * mpmath.exp(-s) + 1.5 * mpmath.exp(-s / 10) + 0.5 * mpmath.exp(-10 * s), 0),
}
@functools.lru_cache(maxsize=None)
def visco(prof, mat):
    """The viscoelastic contact of a profile and a material (built once per module)."""
    return PROFILES[prof][0]().viscoelastic(MATERIALS[mat][0]())


RAMP = t / 10
CYCLE = sp.Piecewise((t / 10, t <= 1), ((2 - t) / 10, t <= 2), (0, True))


def a_cycle(s):
    return s / 10 if s <= 1 else (2 - s) / 10


def lee_radok(E, eta, fprime, a, da, tv, t_end_load=None):
    """The hereditary integral int_0^t E(t - t') dP_el(a(t'))/dt' dt' (+ eta dP_el/dt),
    continued through unloading when t_end_load is None (the naive one)."""
    g = lambda s: E(tv - s) * dPi_ref(fprime, a(s)) * da(s)  # noqa: E731
    pts = [0, tv] if tv <= 1 else [0, 1, tv]
    val = mpmath.quad(g, pts)
    if eta:
        val += eta * dPi_ref(fprime, a(tv)) * da(tv)
    return val


def ting(E, fprime, tv):
    """Ting for the cycle: int_0^{t1} E(t - t') dP_el, t1 <= 1 with a(t1) = a(t)."""
    t1 = mpmath.findroot(lambda s: s / 10 - a_cycle(tv), mpmath.mpf("0.5"))
    return mpmath.quad(lambda s: E(tv - s) * dPi_ref(fprime, s / 10) / 10, [0, t1])


# ---------------------------------------------------------------- force histories
COMBOS = [pytest.param("parabola", m) for m in MATERIALS] + [
    pytest.param(p, m, marks=pytest.mark.slow)     # one more profile per material (time budget)
    for p, m in (("x^4", "maxwell"), ("x^4", "prony3"), ("wedge", "sls"), ("wedge", "kelvin_voigt"))]


@pytest.mark.parametrize("prof, mat", COMBOS)
def test_force_ramp_and_recede_against_own_quadrature(prof, mat):
    """Lee-Radok at t = 0.7 (loading) and Ting at t = 1.4 (receding), each to 12 digits."""
    fp, vals = PROFILES[prof][1], PROFILES[prof][2]
    E, eta = MATERIALS[mat][1], MATERIALS[mat][2]
    v = visco(prof, mat)
    with mpmath.workdps(17):
        ref_load = lee_radok(E, eta, fp, a_cycle, lambda s: mpmath.mpf(1) / 10, mpmath.mpf("0.7"))
        ref_rec = ting(E, fp, mpmath.mpf("1.4"))
    got_load = v.evaluate_at("force", sp.Rational(7, 10), CYCLE, dps=15, **vals)
    got_rec = v.evaluate_at("force", sp.Rational(7, 5), CYCLE, dps=15, **vals)
    assert abs(got_load / ref_load - 1) < 1e-12
    assert abs(got_rec / ref_rec - 1) < 1e-12


@pytest.mark.parametrize("prof", ["parabola", pytest.param("x^4", marks=pytest.mark.slow),
                                  pytest.param("wedge", marks=pytest.mark.slow)])
def test_closed_force_history_maxwell(prof):
    """The closed form of a ramp-then-recede with Maxwell: no Integral left, and
    its values (SymPy evalf) equal the own quadrature at t = 0.5 and t = 1.5."""
    fp, vals = PROFILES[prof][1], PROFILES[prof][2]
    v = visco(prof, "maxwell")
    F = v.force_history(CYCLE)
    assert not F.has(sp.Integral)
    sub = {s: sp.sympify(vals[s.name]) for s in F.free_symbols if s.name in vals}
    E = MATERIALS["maxwell"][1]
    with mpmath.workdps(20):
        ref = [lee_radok(E, 0, fp, a_cycle, lambda s: mpmath.mpf(1) / 10, mpmath.mpf("0.5")),
               ting(E, fp, mpmath.mpf("1.5"))]
    for tv, r in zip((HALF, 3 * HALF), ref):
        assert abs(sp.N(F.xreplace({**sub, t: tv}), 20) / r - 1) < 1e-14


def test_ting_differs_from_naive_lee_radok():
    """In the receding phase the hereditary integral continued through unloading is
    wrong (at t = 1.5, Maxwell, parabola: a tension, -1.6 times Ting's force), and
    Ting's value is the package's."""
    fp = PROFILES["parabola"][1]
    E = MATERIALS["maxwell"][1]
    v = visco("parabola", "maxwell")
    with mpmath.workdps(20):
        tv = mpmath.mpf("1.5")
        naive = lee_radok(E, 0, fp, a_cycle, lambda s: mpmath.mpf(1) / 10 if s <= 1 else -mpmath.mpf(1) / 10, tv)
        good = ting(E, fp, tv)
    got = v.evaluate_at("force", 3 * HALF, CYCLE, dps=15, R=1)
    assert abs(got / good - 1) < 1e-12
    assert naive < 0 < good                  # the naive integral pulls: not a rounding difference


@pytest.mark.slow
def test_pressure_integrates_to_the_force():
    """p(x, t) (Ting phase) integrated over the contact, x = a sin(phi) and
    16-point Gauss-Legendre in phi (our own rule), is P(t)."""
    v = visco("parabola", "sls")
    tv = sp.Rational(13, 10)
    A = float(a_cycle(1.3))
    g, w = np.polynomial.legendre.leggauss(16)
    phi = (g + 1) * np.pi / 4
    vals = [float(v.evaluate_at("pressure", tv, CYCLE, x=sp.Float(A * np.sin(ph), 17), dps=12, R=1)) for ph in phi]
    tot = 2 * np.sum(w * np.pi / 4 * np.array(vals) * A * np.cos(phi))
    P = float(v.evaluate_at("force", tv, CYCLE, dps=15, R=1))
    assert abs(tot / P - 1) < 1e-6



@pytest.mark.slow
def test_pressure_history_form():
    """p(x, t) as a formula: 0 outside the contact, an unevaluated Integral inside
    (SymPy finds no closed form for the parabola under Maxwell)."""
    p = visco("parabola", "maxwell").pressure_history(CYCLE)
    assert p.xreplace({t: 3, R: 1, lcs.x: sp.Rational(1, 20)}) == 0
    assert p.xreplace({t: sp.Rational(1, 2), R: 1, lcs.x: sp.Rational(1, 10)}) == 0
    assert p.xreplace({t: sp.Rational(1, 2), R: 1, lcs.x: sp.Rational(1, 40)}).has(sp.Integral)


# ---------------------------------------------------------------- creep
def test_creep_step_load_closed_form_sls():
    """a(t) under a step load P0 (SLS): Pi(a) = P0 J(t) with the textbook compliance
    J = 1/E_inf - (1/E_inf - 1/E0) exp(-t E_inf/(E0 tau)), solved here for the parabola."""
    v = visco("parabola", "sls")
    a_t = v.half_width_history(sp.Integer(2))
    for tv in (sp.Rational(1, 10), sp.Integer(2)):
        J = 1 - (1 - mpmath.mpf(1) / 3) * mpmath.exp(-float(tv) * 2 / 3)
        ref = mpmath.sqrt(4 * 2 * J / mpmath.pi)       # pi a^2/4 = P0 J (R = 1)
        assert abs(sp.N(a_t.xreplace({t: tv, R: 1}), 20) / ref - 1) < 1e-14
        assert abs(v.half_width_at(tv, sp.Integer(2), dps=15, R=1) / ref - 1) < 1e-12


@pytest.mark.slow
def test_creep_against_time_stepping_bem():
    """Load ramp then fast unloading (Maxwell, parabola): the package's a(t) (Lee-Radok,
    then Ting) agrees with the boundary-element solution to its resolution; the naive
    a(t) from Pi(a) = J * dP through unloading does not."""
    v = lcs.parabola(verify=False).viscoelastic(lcs.maxwell(E0=1, tau=1))
    load = sp.Piecewise((t, t <= 1), (1 - 3 * (t - 1), True))
    times = np.linspace(0, 1.3, 27)
    a_bem, _, _, h = creep_bem(lambda x: x**2 / 2, lambda s: 1.0 + s,
                               lambda s: s if s <= 1 else max(1 - 3 * (s - 1), 0.0), times, 2.0, n=200)
    for i in (10, 20, 24):       # t = 0.5 (loading), 1.0 (top), 1.2 (receding)
        tv = sp.Rational(13, 260) * i
        a_pkg = float(v.half_width_at(tv, load, dps=15, R=1))
        assert abs(a_pkg - a_bem[i]) < 0.75 * h
    X = 1.2 + 1.2**2 / 2 - 3 * (0.2 + 0.2**2 / 2)          # int J(t-u) dP(u), J = 1 + t
    a_naive = np.sqrt(4 * X / np.pi)
    assert abs(a_naive - a_bem[24]) > 3 * h


# ---------------------------------------------------------------- limits, model choice, extremes
def test_elastic_limits_of_a_step():
    """a(t) = a0 (a step): P -> E0 Pi(a0) as t -> 0 and E_inf Pi(a0) as t -> oo."""
    v = visco("parabola", "sls")
    el = mpmath.pi / 4 / 100                        # Pi(1/10), R = 1
    step = sp.Rational(1, 10) + 0 * t
    assert abs(v.evaluate_at("force", sp.Rational(1, 10**30), step, dps=20, R=1) / (3 * el) - 1) < 1e-25
    assert abs(v.evaluate_at("force", 200, step, dps=20, R=1) / el - 1) < 1e-20


def test_model_choice():
    m = lcs.standard_linear_solid(E0=3, E_inf=1, tau=1)
    v = lcs.parabola(verify=False).viscoelastic(m)
    fast = v.model_choice(t / 10, rtol=0.02, t_end=sp.Rational(1, 1000), R=1)
    slow = v.model_choice(t / 10, rtol=0.02, t_end=2000, R=1)
    mid = v.model_choice(t / 10, rtol=0.02, t_end=1, R=1)
    assert fast.model == "elastic E*(0)" and fast.errors["elastic E*(0)"] < 1e-3
    assert slow.model == "elastic E*(oo)" and slow.errors["elastic E*(oo)"] < 0.02
    assert mid.model == "viscoelastic" and mid.errors["elastic E*(0)"] > 0.1 and mid.errors["elastic E*(oo)"] > 0.1


@pytest.mark.parametrize("tau", [sp.Rational(1, 10**12), 10**12])
def test_extreme_relaxation_times(tau):
    """tau -> 0 (Maxwell: almost no force left) and tau -> oo (elastic with E0), to 12 digits
    against the own quadrature (no cancellation in a positive integrand)."""
    v = lcs.parabola(verify=False).viscoelastic(lcs.maxwell(E0=2, tau=tau))
    tau_m = mpmath.mpf(sp.N(tau, 30))
    with mpmath.workdps(30):
        ref = mpmath.quad(lambda s: 2 * mpmath.exp(-(1 - s) / tau_m) * mpmath.pi * (s / 10) / 2 / 10, [0, 1 - 50 * tau_m, 1]
                          if tau_m < 1e-3 else [0, 1])
    assert abs(v.evaluate_at("force", 1, RAMP, dps=15, R=1) / ref - 1) < 1e-12
    F = v.force_history(RAMP)          # closed form, evaluated by SymPy's adaptive evalf
    assert abs(sp.N(F.xreplace({t: 1, R: 1}), 15) / ref - 1) < 1e-12


def test_tiny_prony_weight():
    """A Prony term of weight 1e-30 changes nothing at 15 digits."""
    base = lcs.parabola(verify=False).viscoelastic(lcs.standard_linear_solid(E0=3, E_inf=1, tau=1))
    tiny = lcs.parabola(verify=False).viscoelastic(lcs.prony(E_inf=1, terms=[(2, 1), (sp.Rational(1, 10**30), 1000)]))
    a, b = (base.evaluate_at("force", sp.Rational(3, 2), CYCLE, dps=20, R=1),
            tiny.evaluate_at("force", sp.Rational(3, 2), CYCLE, dps=20, R=1))
    assert abs(a / b - 1) < 1e-25 and a != 0


# ---------------------------------------------------------------- materials and refusals
@pytest.mark.slow
def test_creep_functions_derived():
    """J* from s^2 E*_hat J*_hat = 1, checked by the convolution identity
    int_0^t E(t - s) J'(s) ds + E(t) J(0) = 1 by our own quadrature."""
    for m in (lcs.maxwell(E0=2, tau=3), lcs.standard_linear_solid(E0=3, E_inf=1, tau=HALF),
              lcs.prony(E_inf=1, terms=[(2, 1), (HALF * 3, 10), (HALF, sp.Rational(1, 10))])):
        nm = m.numeric()
        with mpmath.workdps(20):
            tv = mpmath.mpf(2)
            conv = nm.E(tv) * nm.J(0) + mpmath.quad(lambda s: nm.E(tv - s) * mpmath.diff(nm.J, s), [0, tv])
        assert abs(conv - 1) < 1e-12
    kv = lcs.kelvin_voigt(E=1, eta=HALF).creep()
    assert sp.simplify(kv - (1 - sp.exp(-2 * t))) == 0


def test_adhesion_is_refused():
    c = lcs.parabola(verify=False)
    with pytest.raises(DomainError, match="outside Lee-Radok"):
        c.adhesive().viscoelastic(lcs.maxwell(E0=1, tau=1))


def test_more_than_one_maximum_is_refused():
    v = lcs.parabola(verify=False).viscoelastic(lcs.maxwell(E0=1, tau=1))
    twice = sp.Piecewise((t, t <= 1), (2 - t, t <= sp.Rational(3, 2)), (t - 1, True))
    with pytest.raises(MultipleMaximaError):
        v.force_history(twice)
    with pytest.raises(MultipleMaximaError):
        v.evaluate_at("force", 2, twice, R=1)


def test_constant_modulus_is_the_elastic_contact():
    """Elastic is the material with E*(t) constant: the force history is E Pi(a(t))
    exactly (Pi(a) = 3 pi a^4/4 for x^4, from Eq. 10 by hand)."""
    E = sp.Symbol("E", positive=True)
    v = lcs.LineContact(lcs.x**4, verify=False).viscoelastic(lcs.Material(E))
    assert sp.simplify(v.force_history(t / 10) - E * 3 * sp.pi * (t / 10)**4 / 4) == 0


def test_kelvin_voigt_creep_under_a_step():
    """Kelvin-Voigt under a step load P0: Pi(a) = P0 (1 - exp(-E t/eta))/E (no instantaneous
    contact: J(0) = 0), parabola R = 1, solved here."""
    v = visco("parabola", "kelvin_voigt")                       # E = 1, eta = 1/2
    for tv in (sp.Rational(1, 10), sp.Integer(3)):
        ref = mpmath.sqrt(4 * 2 * (1 - mpmath.exp(-2 * float(tv))) / mpmath.pi)
        assert abs(v.half_width_at(tv, sp.Integer(2), dps=15, R=1) / ref - 1) < 1e-12


def test_periodic_array_step():
    """A periodic array (force law linear in E*): after a step to a0 the load per
    period is E*(t) Pi(a0), Pi of 1 - cos x on the period 2 pi is pi sin(a/2)^2
    (Westergaard, evaluated here)."""
    v = lcs.LineContact(1 - sp.cos(lcs.x), period=2 * sp.pi, verify=False).viscoelastic(
        lcs.standard_linear_solid(E0=3, E_inf=1, tau=1))
    ref = (1 + 2 * mpmath.exp(-2)) * mpmath.pi * mpmath.sin(mpmath.mpf(1) / 4)**2
    assert abs(v.evaluate_at("force", 2, HALF + 0 * t, dps=15) / ref - 1) < 1e-12


@pytest.mark.slow
def test_dissipated_work_of_a_cycle():
    """The indenter's work over a closed cycle (depth from the distance L): positive
    for Maxwell, linear in the relaxing part of an almost elastic SLS, and growing
    with L (a 2-D viscoelastic half-plane dissipates in its far field)."""
    cyc = lambda m, L: lcs.parabola(verify=False).viscoelastic(m).dissipated_work(  # noqa: E731
        CYCLE, t_end=2, L=L, points=25, R=1)
    W = cyc(lcs.maxwell(E0=2, tau=1), 10)
    assert W > 0 and cyc(lcs.maxwell(E0=2, tau=1), 100) > W
    w1 = cyc(lcs.standard_linear_solid(E0=1 + sp.Rational(1, 10**6), E_inf=1, tau=1), 10)
    w2 = cyc(lcs.standard_linear_solid(E0=1 + sp.Rational(2, 10**6), E_inf=1, tau=1), 10)
    assert 0 < w1 < 1e-9 and abs(w2 / w1 - 2) < 1e-3


def test_history_data_between_the_elastic_limits():
    """While the contact grows (SLS), E*(oo) Pi(a) <= P(t) <= E*(0) Pi(a): the arrays of the plot."""
    d = visco("parabola", "sls").history_data(CYCLE, 1, points=8, R=1)
    assert d["t"].shape == (8,) and np.all(d["P_Einf"] < d["P"]) and np.all(d["P"] < d["P_E0"])


@pytest.mark.slow
def test_a_wrong_closed_form_is_not_returned(monkeypatch):
    """The closed form is checked against the quadrature of the superposition at one
    point per phase: a SymPy integral that came out wrong (here: doubled) gives way
    to the unevaluated Integral."""
    from linecontact_sym.contacts.viscoelastic import contact as vc
    from linecontact_sym.method import store
    good = vc._integrate
    monkeypatch.setattr(vc, "_integrate", lambda *a: 2 * good(*a))
    monkeypatch.setattr(store, "get", lambda key: None)       # no closed form remembered from another test
    monkeypatch.setattr(store, "put", lambda key, rec: None)
    v = lcs.parabola(verify=False).viscoelastic(lcs.maxwell(E0=2, tau=1))
    F = v.force_history(CYCLE)
    assert F.has(sp.Integral)
    ref = mpmath.quad(lambda s: 2 * mpmath.exp(-(0.5 - s)) * mpmath.pi * s / 200, [0, 0.5])   # by hand, R = 1
    assert abs(sp.N(F.xreplace({t: sp.Rational(1, 2), R: 1}), 15) / ref - 1) < 1e-12


def test_creep_closed_form_only_for_a_load_that_never_decreases():
    v = visco("parabola", "maxwell")
    with pytest.raises(DomainError, match="Ting"):
        v.half_width_history(sp.Piecewise((t, t <= 1), (2 - t, True)))


@pytest.mark.slow
def test_creep_ramp_then_hold_closed_form():
    v = visco("parabola", "maxwell")
    # a ramp then hold: a(t) = sqrt(4 X/pi), X = int J dP by hand (J = (1 + t)/2, Maxwell E0 = 2, tau = 1)
    a_t = v.half_width_history(sp.Piecewise((t, t <= 1), (1, True)))
    X = (2 + 2**2 / 2 - (1 + 1 / 2)) / 2              # int_0^1 J(2 - u) du = int_1^2 J(w) dw at t = 2
    assert abs(float(a_t.xreplace({t: 2, R: 1})) / np.sqrt(4 * X / np.pi) - 1) < 1e-13


def run_cli(capsys, *argv):
    from linecontact_sym import cli
    code = cli.main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_viscoelastic_derive_and_eval(capsys):
    """derive/eval with a material: the Maxwell force history of a ramp-recede, and
    Ting's number at t = 3/2, which is int_0^{1/2} 2 exp(-(3/2 - s)) (pi s/200) ds by hand
    (a(s) = s/10 reaches a(3/2) = 1/20 at s = 1/2)."""
    import json
    cyc = "Piecewise((t/10, t <= 1), ((2 - t)/10, t <= 2), (0, True))"
    code, out, _ = run_cli(capsys, "derive", "x**2/(2*R)", "--material", "maxwell:E0=2,tau=1", "--history", cyc, "--json")
    assert code == 0 and "exp(-t)" in json.loads(out)["force_history"]
    code, out, _ = run_cli(capsys, "eval", "x**2/(2*R)", "force", "--material", "maxwell:E0=2,tau=1", "--history", cyc,
                       "--set", "R=1", "--at", "t=1.5", "--dps", "20", "--json")
    ref = mpmath.quad(lambda s: 2 * mpmath.exp(-(1.5 - s)) * mpmath.pi * s / 200, [0, 0.5])
    assert code == 0 and abs(float(json.loads(out)["rows"][0]["value"]) / ref - 1) < 1e-12
    code, _, err = run_cli(capsys, "eval", "x**2/(2*R)", "force", "--material", "burgers:E0=1", "--history", "t", "--at", "t=1")
    assert code != 0 and "burgers" in err


# ---------------------------------------------------------------- accuracy on request (evaluate)
TAU, E0S, RS = sp.symbols("tau E0 r", positive=True)


@functools.lru_cache(maxsize=None)
def visco_symbolic():
    """The parabola on a Maxwell material with symbolic E0, tau; history a = r t."""
    return lcs.parabola(verify=False).viscoelastic(lcs.maxwell(E0=E0S, tau=TAU))


def lee_radok_by_hand(tv, tau, E0, r, Rv, dps=60):
    """(pi E0 r^2/(2R)) int_0^t s exp(-(t - s)/tau) ds, our own tanh-sinh at ``dps`` digits."""
    with mpmath.workdps(dps):
        tv, tau, E0, r, Rv = (mpmath.mpf(v) for v in (tv, tau, E0, r, Rv))
        return mpmath.pi * E0 * r**2 / (2 * Rv) * mpmath.quad(lambda s: s * mpmath.exp(-(tv - s) / tau), [0, tv])


@pytest.mark.parametrize("tv", [1e-10, 0.5, 1e6])
def test_evaluate_force_history_picks_its_path(tv):
    """float64 when it meets rtol (t << tau included: the stable form's exp_tail), mpmath
    beyond float64, an Arb ball on request; all against our own quadrature at 60 digits."""
    v = visco_symbolic()
    pt = dict(t=tv, tau=1.0, E0=2.0, r=0.1, R=1.5)
    ref = lee_radok_by_hand(tv, 1.0, 2.0, 0.1, 1.5)
    r64 = v.evaluate("force", RS * t, rtol=1e-12, **pt)
    assert r64.path == "float64" and abs(r64.value / ref - 1) < 1e-14
    r30 = v.evaluate("force", RS * t, rtol=1e-30, **pt)
    assert r30.path.startswith("mpmath@") and abs(r30.value / ref - 1) < 1e-30
    arb = v.evaluate("force", RS * t, certified=True, dps=25, **pt)
    assert arb.path == "arb" and arb.enclosure[0] <= ref <= arb.enclosure[1] and arb.rel_error < 1e-24


def test_evaluate_refuses_outside_the_domain():
    v = visco_symbolic()
    with pytest.raises(DomainError, match="time"):
        v.evaluate("force", RS * t, t=-1.0, tau=1.0, E0=2.0, r=0.1, R=1.0)
    with pytest.raises(DomainError, match="tau"):
        v.evaluate("force", RS * t, t=1.0, tau=-1.0, E0=2.0, r=0.1, R=1.0)
    with pytest.raises(DomainError, match="unknown history quantity"):
        v.evaluate("gap", RS * t, t=1.0)
    exact = v.evaluate("force", RS * t, t="1/3", tau="1", E0=2, r=sp.Rational(1, 10), R=1, rtol=1e-12)   # text: exact
    assert abs(exact.value / lee_radok_by_hand(mpmath.mpf(1) / 3, 1, 2, mpmath.mpf(1) / 10, 1) - 1) < 1e-14


@pytest.mark.slow
def test_evaluate_pressure_history_without_closed_form_is_enclosed_by_arb():
    """p(x, t) of the ramp on Maxwell: SymPy leaves the integral over the punches
    unevaluated; beyond float64 one Arb enclosure of it (a true bound), checked against
    our own tanh-sinh of (1/pi) int_x^a Pi'(b) E(t - b/r)/sqrt(b^2 - x^2) db, Pi' = pi b/(2R)."""
    v = visco_symbolic()
    pt = dict(t=0.5, x=0.01, tau=1.0, E0=2.0, r=0.1, R=1.0)
    with mpmath.workdps(50):
        # the floats' exact binary values, as the package reads them (0.1 is not 1/10)
        rv, tv, xv = (mpmath.mpf(pt[k]) for k in ("r", "t", "x"))
        A = rv * tv
        # b = sqrt(x^2 + w^2) takes the 1/sqrt(b - x) end away (the plain tanh-sinh at
        # 50 digits is off by 3e-28 there, far more than the enclosure's width)
        ref = mpmath.quad(lambda w: mpmath.exp(-(tv - mpmath.sqrt(xv * xv + w * w) / rv)),
                          [0, mpmath.sqrt(A * A - xv * xv)])
    r64 = v.evaluate("pressure", RS * t, rtol=1e-10, **pt)
    assert r64.path == "float64" and abs(r64.value / ref - 1) < 1e-12
    arb = v.evaluate("pressure", RS * t, rtol=1e-25, **pt)
    assert arb.path == "arb" and arb.certified and arb.enclosure[0] <= ref <= arb.enclosure[1]


@pytest.mark.slow
def test_evaluate_creep_half_width_step_load_sls():
    """a(t) under a step load P0 on a standard linear solid: Pi(a) = pi a^2/(4R) = P0 J*(t),
    J*(t) = 1/E_inf - (1/E_inf - 1/E0) exp(-E_inf t/(E0 tau)) (the textbook creep function,
    written here); float64 on request of 1e-12, an Arb ball on request of certainty."""
    Ei, P0 = sp.symbols("E_inf P0", positive=True)
    v = lcs.parabola(verify=False).viscoelastic(lcs.standard_linear_solid(E0=E0S, E_inf=Ei, tau=TAU))
    pt = dict(tau=1.0, E0=2.0, E_inf=0.5, P0=1.0, R=1.0)
    for tv in (1e-12, 0.3, 1e3):
        with mpmath.workdps(40):
            J = 2 - (2 - mpmath.mpf(1) / 2) * mpmath.exp(-mpmath.mpf(tv) / 4)
            ref = mpmath.sqrt(4 * J / mpmath.pi)
        r = v.evaluate("half_width", P0, t=tv, rtol=1e-12, **pt)
        assert r.path == "float64" and abs(r.value / ref - 1) < 1e-14
    arb = v.evaluate("half_width", P0, t=0.3, certified=True, **pt)
    with mpmath.workdps(40):
        ref = mpmath.sqrt(4 * (2 - mpmath.mpf(3) / 2 * mpmath.exp(-mpmath.mpf(0.3) / 4)) / mpmath.pi)
    assert arb.enclosure[0] <= ref <= arb.enclosure[1]
