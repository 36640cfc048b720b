"""Tangential line contact with Coulomb friction (issue 13): Cattaneo-Mindlin
partial slip, Mindlin-Deresiewicz unloading, fretting, for any profile.

Every number is checked against a computation that does not use the
superposition: the Hertz formulas typed here from the literature, the
inversion of the stick-zone integral equation and the Flamant kernel
(mpmath, 30 digits), and a direct boundary-element solution with a Coulomb
active set along the load history (a few digits, stated per check).
"""
from __future__ import annotations


import mpmath
import numpy as np
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.contacts.tangential import reference as ref
from linecontact_sym.contacts.base import CONTACT_KINDS, qualified_quantities
from linecontact_sym.contacts.tangential.contact import TangentialLineContact
from linecontact_sym.core import symbols as S
from linecontact_sym.core.errors import DomainError, GrossSlidingError
from linecontact_sym.method.verification import digits_agreeing

a, x, E, R, mu, Q, cs, cr, b = S.a, S.x, S.E_star, S.R, S.mu, S.Q, S.c_s, S.c_r, S.b
#: the numbers of the boundary-element comparisons
VALS = {"parabola": dict(E_star=1.3, mu=0.4, a=0.8, R=1.0),
        "worn": dict(E_star=1.3, mu=0.4, a=1.0, R=5.0, b=0.4),
        "exact": dict(E_star=1.3, mu=0.4, a=1.0, R=1.5)}


@pytest.fixture(scope="module")
def hertz():
    """Cylinder (parabola) with the package's own 30-digit verification (1 point each)."""
    return lcs.parabola(points=1).tangential()


@pytest.fixture(scope="module")
def plain():
    """Contacts without the package's verification: the checks here are the tests'."""
    out = {"parabola": lcs.parabola(verify=False).tangential(),
           "worn": lcs.worn_cylinder(verify=False, budget=20).tangential(),
           "exact": lcs.exact_cylinder(verify=False, budget=20).tangential()}
    for t in out.values():   # what is tested: closed force laws; the pressures are closed for the parabola only
        assert t.contact.derivation("force").closed_form
        t.contact.budget = 1.0   # the symbolic attempts that fail here (pressure, gap, W) give up sooner
    return out


def test_registry_and_construction():
    assert CONTACT_KINDS["tangential"] is TangentialLineContact
    names = qualified_quantities()
    for q in ("traction", "tangential_force", "stick_half_width", "slip", "dissipated_energy",
              "loop_displacement", "unloading_traction", "unloading_force", "unloading_slip"):
        assert names[f"tangential.{q}"][:2] == ("tangential", q)
    t = TangentialLineContact.from_frictionless(lcs.parabola())
    assert t.mu == S.mu and t.variables == (S.mu, S.E_star, S.R)
    assert lcs.parabola().tangential(0.3).mu == sp.Rational(3, 10)
    with pytest.raises(DomainError, match="string"):
        lcs.parabola().tangential("0.3")
    with pytest.raises(DomainError, match="positive"):
        lcs.parabola().tangential(-1)
    with pytest.raises(DomainError, match="positive"):
        lcs.parabola().tangential(sp.Symbol("k"))
    assert lcs.worn_cylinder().tangential().c0 == S.b and lcs.parabola().tangential().c0 == 0


def test_hertz_closed_forms(plain):
    """Johnson (1985) ch. 7 for the cylinder, and the forms derived here."""
    t = plain["parabola"]
    P = sp.pi * E * a**2 / (4 * R)
    p0 = E * a / (2 * R)
    assert sp.simplify(t.tangential_force - mu * P * (1 - cs**2 / a**2)) == 0
    c_of_Q = t.stick_half_width().expr
    Qp = sp.Symbol("Qp", positive=True)
    assert sp.simplify((c_of_Q.subs(Q, Qp) / a)**2 - (1 - Qp / (mu * P))) == 0
    q = t.traction
    stick, slip = q.args[0][0], q.args[1][0]
    assert sp.simplify(stick - mu * p0 * (sp.sqrt(1 - x**2 / a**2) - cs / a * sp.sqrt(1 - x**2 / cs**2))) == 0
    assert sp.simplify(slip - mu * p0 * sp.sqrt(1 - x**2 / a**2)) == 0
    s_slip = t.slip.args[1][0]
    assert sp.simplify(s_slip - mu / (2 * R) * (x * sp.sqrt(x**2 - cs**2) - cs**2 * sp.acosh(x / cs))) == 0
    W = sp.pi * E * mu**2 / (8 * R**2) * (a**4 - cs**4 - 4 * a**2 * cs**2 * sp.log(a / cs))
    assert sp.simplify(sp.expand_log(t.dissipated_energy - W, force=True)) == 0
    assert "Dundurs" in t.derivation("traction").notes[-1]


def test_hertz_verification_records(hertz):
    """The package's own record of each closed form: its independent
    reference (stick-zone inversion, friction work, quadrature force law)
    agrees to >= 30 digits (the slip's Flamant check: next test)."""
    for name in ("tangential_force", "traction", "dissipated_energy"):
        rec = hertz.derivation(name).verification
        assert rec.passed and rec.min_digits >= 30, name
    assert hertz.stick_half_width().verification.min_digits >= 30


def test_independent_references_on_hand_typed_hertz():
    """The references themselves, on the Hertz pressure and gap typed here:
    the stick-zone inversion, its resultant, the Flamant slip and shift, and
    the friction work reproduce the closed forms to >= 30 digits."""
    with mpmath.workdps(45):
        A, C, X, Xs = mpmath.mpf("1.1"), mpmath.mpf("0.7"), mpmath.mpf("0.4"), mpmath.mpf("0.93")
        Ev, Rv, m = mpmath.mpf("1.7"), mpmath.mpf("1.3"), mpmath.mpf("0.35")
        k = Ev / (2 * Rv)

        def p(xv, Av=A):
            return k * mpmath.sqrt(Av**2 - xv**2) if abs(xv) < Av else mpmath.mpf(0)

        def g(xv, Cv=C):
            return (xv * mpmath.sqrt(xv**2 - Cv**2) - Cv**2 * mpmath.acosh(xv / Cv)) / (2 * Rv)

        def q(xi):
            return m * (p(xi) - p(xi, C))
        checks = [
            (ref.stick_traction_inversion(p, A, C, X, m), m * (p(X) - p(X, C))),
            (ref.tangential_force_inversion(p, A, C, m), m * mpmath.pi * Ev * (A**2 - C**2) / (4 * Rv)),
            (ref.slip_flamant(q, A, Xs, Ev, [C]), m * g(Xs)),
            (ref.displacement_flamant(q, A, Ev, [C]),
             m / (4 * Rv) * (A**2 - C**2 - 2 * C**2 * mpmath.log(A / C) + 2 * (A**2 - C**2) * mpmath.log(2))),
            (ref.friction_work(p, g, A, C, m),
             mpmath.pi * Ev * m**2 / (8 * Rv**2) * (A**4 - C**4 - 4 * A**2 * C**2 * mpmath.log(A / C))),
        ]
        for got, want in checks:
            assert digits_agreeing(got, want, 40) >= 30


def _compare(t, vals, n=80):
    """Boundary elements along load 0 -> Q_A -> -Q_A/2 -> -Q_A -> Q_A against the
    superposition; returns the relative errors."""
    bem = t.bem(elements=n, **vals)
    QA = 0.6 * vals["mu"] * bem.P
    bem.run(np.linspace(0, QA, 6)[1:])
    st = t.state(QA, **vals)
    errs = {"P": abs(bem.P / float(st.P) - 1)}
    c = float(st.c)

    def away(*edges):   # the traction is compared a few elements away from the stick edges
        ok = np.ones(n, bool)
        for e in edges:
            ok &= np.abs(bem.x - e) > 2.5 * np.interp(e, bem.x, bem.h)
        return np.flatnonzero(ok)[::n // 10]
    scale_q, scale_s = np.max(np.abs(bem.state.q)), np.max(bem.slip())
    errs["c/h"] = abs(bem.stick_half_width() - c) / np.interp(c, bem.x, bem.h)
    i = away(c)
    errs["q"] = np.max(np.abs(st.traction(bem.x[i]) - bem.state.q[i])) / scale_q
    errs["s"] = np.max(np.abs(st.slip(bem.x[i]) - bem.slip()[i])) / scale_s
    w0 = bem.state.dissipated
    bem.run(np.linspace(QA, -0.5 * QA, 9)[1:])
    su = t.unload(QA, -0.5 * QA, **vals)
    errs["c_r/h"] = abs(bem.stick_half_width() - float(su.c_r)) / np.interp(float(su.c_r), bem.x, bem.h)
    i = away(c, float(su.c_r))
    errs["q_u"] = np.max(np.abs(su.traction(bem.x[i]) - bem.state.q[i])) / scale_q
    errs["s_u"] = np.max(np.abs(su.slip(bem.x[i]) - bem.slip()[i])) / scale_s
    bem.run(np.linspace(-0.5 * QA, -QA, 4)[1:])
    bem.run(np.linspace(-QA, QA, 11)[1:])
    errs["W"] = abs((bem.state.dissipated - w0) / t.cycle(QA, 5, **vals).W - 1)
    return errs


@pytest.mark.parametrize("name", ["parabola", "worn", "exact"])
def test_direct_boundary_element_solution(plain, name):
    """The superposition (closed for the cylinder, numeric where the pressure
    has no closed form: worn and exact cylinders) against the direct solution
    with 80 elements on the half-contact.  Measured: stick edges within half
    an element, traction and slip to 1e-4 .. 6e-4 of their maxima (3-4
    digits), the energy per cycle to 2e-5 .. 3e-4."""
    errs = _compare(plain[name], VALS[name])
    assert errs["P"] < 1e-7
    assert errs["c/h"] < 0.75 and errs["c_r/h"] < 0.75
    for key in ("q", "s", "q_u", "s_u"):
        assert errs[key] < 2e-3, (key, errs[key])
    assert errs["W"] < 1e-3


def test_gross_sliding(plain):
    t, vals = plain["parabola"], VALS["parabola"]
    muP = float(t.state(0, **vals).P) * vals["mu"]
    with pytest.raises(GrossSlidingError, match="exceeds the Coulomb limit"):
        t.state(1.001 * muP, **vals)
    onset = t.state(muP, **vals)
    assert onset.branch == "gross sliding onset" and onset.c == 0
    with pytest.raises(GrossSlidingError):
        t.stick_half_width(1.001 * muP, **vals)
    worn, wv = plain["worn"], VALS["worn"]
    muPw = float(worn.state(0, **wv).P) * wv["mu"]
    with mpmath.workdps(30):
        assert abs(worn.state(muPw, **wv).c - mpmath.mpf(2) / 5) < 1e-25   # the flat sticks up to the onset
    assert wv["b"] < worn.state(0.999 * muPw, **wv).c < 0.41
    with pytest.raises(DomainError, match="outside"):
        t.unload(0.5 * muP, 0.6 * muP, **vals)
    with pytest.raises(DomainError):
        t.check_domain("traction", {"a": 1, "c_s": 2, "x": 0.5})


def test_mindlin_deresiewicz_identities(plain):
    """A full unloading reverses the loading state; the reloading branch ends
    where the loading branch did; the stick half-width of Cattaneo's cylinder."""
    t, vals = plain["parabola"], VALS["parabola"]
    P = float(t.state(0, **vals).P)
    QA = 0.55 * vals["mu"] * P
    load, down = t.state(QA, **vals), t.unload(QA, -QA, **vals)
    exact = dict(E_star=sp.Rational(13, 10), mu=sp.Rational(2, 5), a=sp.Rational(4, 5), R=1)  # no float reading
    with mpmath.workdps(30):
        for ratio in ("0.01", "0.55", "0.9", "0.99", "0.999999999"):   # Cattaneo: c/a = sqrt(1 - Q/(mu P))
            st0 = t.state(0, **exact)
            Qexact = sp.Rational(ratio) * sp.Rational(2, 5) * sp.nsimplify(st0.P, rational=True)
            st = t.state(Qexact, **exact)
            want = mpmath.mpf(4) / 5 * mpmath.sqrt(1 - mpmath.mpf(sp.N(Qexact, 40)) / (mpmath.mpf(2) / 5 * st.P))
            assert abs(st.c / want - 1) < 1e-20   # 30 digits, less the cancellation in P - Q/mu near 1
    with mpmath.workdps(30):
        assert abs(down.c_r - load.c) < 1e-25
    xs = np.linspace(0.01, 0.79, 23)
    assert np.max(np.abs(down.traction(xs) + load.traction(xs))) < 1e-14
    assert np.max(np.abs(down.slip(xs) + load.slip(xs))) < 1e-14
    up = t.reload(QA, QA, **vals)
    assert np.max(np.abs(up.traction(xs) - load.traction(xs))) < 1e-14
    with mpmath.workdps(30):
        assert abs(t.unload(QA, QA, **vals).c_r - mpmath.mpf(4) / 5) < 1e-25
    # Coulomb's inequality holds on the unloading branch (|q| <= mu p)
    mid = t.unload(QA, 0.1 * QA, **vals)
    p = vals["mu"] * vals["E_star"] / (2 * vals["R"]) * np.sqrt(vals["a"]**2 - xs**2)
    assert np.all(np.abs(mid.traction(xs)) <= p * (1 + 1e-12))


def test_fretting_loop_area_is_the_dissipated_energy(plain):
    """Energy balance: the area of the (Q, delta) loop equals the friction work
    W; W in terms of the load ratio, and its small-amplitude limit."""
    t, vals = plain["parabola"], VALS["parabola"]
    P = float(t.state(0, **vals).P)
    m = vals["mu"]
    for ratio in (0.3, 0.7, 0.95):
        QA = ratio * m * P
        cyc = t.cycle(QA, 401, **vals)
        assert abs(cyc.loop_area / cyc.W - 1) < 2e-5
        r = 1 - ratio
        assert abs(cyc.W / (2 * (m * P)**2 / (np.pi * vals["E_star"]) * (1 - r**2 + 2 * r * np.log(r))) - 1) < 1e-12
    small = t.cycle(1e-3 * m * P, 3, **vals)
    assert abs(small.W / (2 * (1e-3 * m * P)**3 / (3 * np.pi * vals["E_star"] * m * P)) - 1) < 2e-3


def _claim_points(claim, syms, ranges, rng, k):
    """k points drawn from the claim's (absolute) ranges, rejected where an
    assumption fails -- as the package's checker samples."""
    pts = []
    for _ in range(500 * k):
        vals = {s: sp.Rational(round(rng.uniform(*ranges.get(s.name, (0.5, 2.5))) * 1000), 1000) for s in syms}
        if all(bool(r.xreplace(vals)) for r in claim["assumptions"]):
            pts.append(vals)
        if len(pts) == k:
            return pts
    raise AssertionError(f"no admissible points for {claim['label']}")


def test_claims_file_holds():
    """The classical results of cattaneo_mindlin.toml (cylinder: stick zone,
    traction, force, slip, unloading traction, energy per cycle) hold by the
    package's own checker, which reads the tangential quantities from the
    registry: >= 30 digits at random admissible points."""
    from linecontact_sym.claims import check_paper, load_paper
    paper = load_paper("cattaneo_mindlin")
    cylinder = {c.label for c in paper.claims if "(cylinder)" in c.label}
    assert len(cylinder) == 6
    # three of them (a loading state, an unloading state, the cycle's energy): the
    # whole file is the CLI's job (`linecontact-sym check cattaneo_mindlin`, 8 of 8 hold)
    only = {lab for lab in cylinder if any(w in lab for w in ("stick zone", "unloading", "energy"))}
    result = check_paper(paper, budget=20, only=only)
    assert [r.status for r in result.results] == ["holds"] * 3
    assert min(r.digits for r in result.results) >= 30


# ---------------------------------------------------------------- the two bodies (issue 39, item 4)
STEEL, ALUMINIUM = (210e9, 0.3), (70e9, 0.33)


def _domain_warnings(seen):
    from linecontact_sym.core.errors import DomainWarning
    return [w for w in seen if issubclass(w.category, DomainWarning)]


@pytest.fixture(scope="module")
def cylinder_mu04():
    """The cylinder and its tangential contact at mu = 0.4 without the bodies
    (its derivations shared by the tests below)."""
    import warnings
    c = lcs.parabola(verify=False)
    with warnings.catch_warnings():
        warnings.simplefilter("error")          # no warning without the bodies
        return c, c.tangential(0.4)


def test_every_tangential_result_states_the_coupling(cylinder_mu04):
    """Without the bodies: "beta = 0 assumed" on the state, the unloading
    state, the fretting cycle, the derivations and the repr; no warning."""
    import warnings
    _, t = cylinder_mu04
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        st = t.state(0.1, E_star=1, R=1, a=0.8)
        un = t.unload(0.1, -0.05, E_star=1, R=1, a=0.8)
        cy = t.cycle(0.1, points=5, E_star=1, R=1, a=0.8)
    for r in (st, un, cy):
        assert r.coupling.startswith("beta = 0 assumed (elastically similar bodies)") and r.coupling.size == 0
    assert "beta = 0 assumed" in repr(st) and "beta = 0 assumed" in repr(cy)
    assert t.derivation("tangential_force").notes[0] == t.coupling_note
    assert "Dundurs" in t.derivation("tangential_force").notes[-1]           # the conditions stay last


def test_materials_state_the_neglected_coupling_once_and_change_no_number(cylinder_mu04):
    """Steel on aluminium: one DomainWarning per contact (not per state), the
    note's |beta| mu on every result (beta by hand from Dundurs' shear moduli
    and kappa = 3 - 4 nu), E_star filled from the materials (E* by hand), and
    the numbers of every state identical to those made without the bodies."""
    import warnings
    nu1, nu2 = STEEL[1], ALUMINIUM[1]
    G1, G2 = STEEL[0] / (2 * (1 + nu1)), ALUMINIUM[0] / (2 * (1 + nu2))
    k1, k2 = 3 - 4 * nu1, 3 - 4 * nu2
    beta = (G2 * (k1 - 1) - G1 * (k2 - 1)) / (G2 * (k1 + 1) + G1 * (k2 + 1))
    E_hand = 1 / ((1 - nu1**2) / STEEL[0] + (1 - nu2**2) / ALUMINIUM[0])
    c, plain = cylinder_mu04
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        t = c.tangential(0.4, materials=(STEEL, ALUMINIUM))
        st = t.state(1e6, R=0.01, a=1e-3)                       # E_star from the materials
        un = t.unload(1e6, 5e5, R=0.01, a=1e-3)
        cy = t.cycle(1e6, points=5, R=0.01, a=1e-3)
    assert len(_domain_warnings(seen)) == 1
    assert "materials=((210000000000, 3/10), (70000000000, 33/100))" in repr(t)
    for r in (st, un, cy):
        assert float(r.coupling.size) == pytest.approx(abs(beta) * 0.4, rel=1e-13)
        assert "neglected" in r.coupling and f"{abs(beta) * 0.4:.3g}" in r.coupling
    assert "0.0467" in repr(st)
    # the same numbers as the contact without the bodies at E_star = E* (by hand)
    st0 = plain.state(1e6, E_star=E_hand, R=0.01, a=1e-3)
    assert float(st.P) == pytest.approx(float(st0.P), rel=1e-14) and float(st.c) == pytest.approx(float(st0.c), rel=1e-14)
    st1 = plain.state(1e6, E_star=t.coupling.E_star, R=0.01, a=1e-3)   # at the same E*: identical
    xs = np.linspace(-1e-3, 1e-3, 9)
    assert (st.P, st.c, st.a, st.mu) == (st1.P, st1.c, st1.a, st1.mu)
    assert np.array_equal(st.traction(xs), st1.traction(xs))
    cy1 = plain.cycle(1e6, points=5, E_star=t.coupling.E_star, R=0.01, a=1e-3)
    assert cy.W == cy1.W and np.array_equal(cy.delta, cy1.delta)
    assert t.tangential_force == plain.tangential_force
    assert t.evaluate_at("tangential_force", a=1e-3, c_s=5e-4, R=0.01) == \
        plain.evaluate_at("tangential_force", a=1e-3, c_s=5e-4, R=0.01, E_star=t.coupling.E_star)
    assert t.to_numeric("tangential_force", R=0.01)(a=1e-3, c_s=5e-4) == \
        plain.to_numeric("tangential_force", R=0.01, E_star=float(t.coupling.E_star))(a=1e-3, c_s=5e-4)


def test_a_contradicting_E_star_is_refused(cylinder_mu04):
    c, _ = cylinder_mu04
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        t = c.tangential(0.4, materials=(STEEL, ALUMINIUM))
    with pytest.raises(DomainError, match="contradicts the materials.*58605"):
        t.state(2e6, E_star=210e9, R=0.01, a=1e-3)
    with pytest.raises(DomainError, match="contradicts the materials"):
        t.evaluate_at("tangential_force", a=1e-3, c_s=5e-4, R=0.01, E_star=1)
    with pytest.raises(DomainError, match="contradicts the materials"):
        c.tangential(0.4, beta=0, materials=(STEEL, ALUMINIUM))
    with pytest.raises(DomainError, match=r"\[-1/2, 1/2\]"):
        c.tangential(0.4, beta=-0.6)
