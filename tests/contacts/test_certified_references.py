"""The ported independent references are Arb enclosures at typical points
and contain values computed independently (published closed results
recomputed in mpmath, or the mpmath quadrature route): the Flamant
integrals of the stresses, the tangential inversions and friction work,
JKR's energy route."""
import random

import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core import symbols as S
from linecontact_sym.core.conversion import to_mpf
from linecontact_sym.core.precision import workdps
from linecontact_sym.contacts.adhesion.jkr import compliance_slope, phat_energy
from linecontact_sym.contacts.stresses import build as B
from linecontact_sym.contacts.stresses.reference import flamant_enclosures, flamant_stresses
from linecontact_sym.contacts.tangential import reference as TR
from linecontact_sym.contacts.tangential import states
from linecontact_sym.contacts.tangential.contact import LOADING, UNLOADING

R = sp.Rational
xs = sp.Dummy("x", positive=True)
HERTZ_P = sp.Lambda(xs, sp.sqrt(1 - xs**2))      # a = 1, E* = 2, R = 1: p0 = 1


def mcewen_mp(x, z):
    """McEwen (1949) / Johnson (1985) Eq. (4.50) in mpmath (p0 = a = 1),
    signs of Johnson's Eq. (2.23)."""
    A = 1 - x**2 + z**2
    r = mpmath.sqrt(A**2 + 4 * x**2 * z**2)
    m, n = mpmath.sqrt((r + A) / 2), mpmath.sqrt((r - A) / 2) * mpmath.sign(x)
    sx = -(m * (1 + (z**2 + n**2) / (m**2 + n**2)) - 2 * z)
    sz = -m * (1 - (z**2 + n**2) / (m**2 + n**2))
    txz = -n * (m**2 - z**2) / (m**2 + n**2)
    return sx, sz, txz


@pytest.mark.slow
@pytest.mark.parametrize("x,z", [(R(3, 10), R(1, 2)), (R(-7, 10), R(1, 10)), (R(3, 2), R(1, 5)), (R(9, 10), R(1, 100))])
def test_flamant_enclosures_of_hertz_contain_mcewens_field(x, z):
    r = flamant_enclosures(lambda lo, hi, s: (sp.sqrt(1 - s**2), 0), 1, x, z, [0], dps=40)
    assert all(v.method == "arb" and v.digits >= 40 for v in r)
    with workdps(70):
        ref = mcewen_mp(mpmath.mpf(x.p) / x.q, mpmath.mpf(z.p) / z.q)
        assert all(v.contains(m) for v, m in zip(r, ref))
        assert not r[0].contains(ref[0] * (1 + mpmath.mpf(10) ** -38))


@pytest.mark.slow
def test_von_mises_and_principal_shear_references_are_enclosures_of_mcewens_field():
    """Quantities made from the three components (von Mises, principal
    shear) are combined on the components' Arb balls
    (numeric.reference.combine with several symbols): enclosures that
    contain McEwen's field combined in mpmath, and not a value 1e-35 off it."""
    sf = lcs.parabola(verify=False).stresses(verify=False)
    nu = R(3, 10)
    vals = {S.R: 1, S.E_star: 2, S.a: 1, S.x: R(3, 10), S.z: R(1, 2), sf.nu: nu}     # p0 = a = 1
    with workdps(70):
        sx, sz, txz = mcewen_mp(mpmath.mpf(3) / 10, mpmath.mpf(1) / 2)
        sy = mpmath.mpf(3) / 10 * (sx + sz)
        expected = {"von_mises": mpmath.sqrt(((sx - sy)**2 + (sy - sz)**2 + (sz - sx)**2) / 2 + 3 * txz**2),
                    "principal_shear": mpmath.sqrt((sx - sz)**2 / 4 + txz**2)}
    for q, ref in expected.items():
        v = sf.derivation(q).reference(vals, 40)
        assert v.method == "arb" and v.digits >= 40, (q, v.method, v.note)
        with workdps(70):
            assert v.contains(ref) and not v.contains(ref * (1 + mpmath.mpf(10) ** -35)), q


@pytest.mark.slow
def test_stress_verification_reference_is_certified_and_contains_the_mpmath_route():
    """The field's reference at random points (sliding: q = mu p): three Arb
    enclosures containing the mpmath Flamant quadrature (to its ~50 digits)."""
    sf = lcs.parabola(verify=False).stresses("sliding", verify=False)
    ref, sample = B.flamant_reference(sf), B.sampler(sf)
    rng = random.Random(7)
    for _ in range(2):
        vals = sample(rng)
        r = ref(vals, 45)
        assert [v.method for v in r.values()] == ["arb"] * 3 and min(v.digits for v in r.values()) >= 45
        with workdps(60):
            p, q, breaks = B._mp_tractions(sf, vals, 50)
            m = flamant_stresses(p, q, *[to_mpf(vals[k]) for k in (S.a, S.x, S.z)], breaks=breaks, dps=50)
            for v, mv in zip(r.values(), m):
                assert v.contains(mv, abs(mv) * mpmath.mpf(10) ** -48)


@pytest.mark.slow
def test_partial_slip_fallback_takes_its_kinks_at_working_precision():
    """The stick edge c is a kink of q: the mpmath fallback split at float(c)
    (1e-17 off) was 6e-30 off the Arb enclosure; split at c it agrees."""
    sf = lcs.parabola(verify=False).stresses("partial_slip", stick=S.c_s, verify=False)
    vals = {S.R: R(172, 125), S.E_star: R(1739531, 1000000), S.a: R(201727, 500000), S.x: R(-325749, 1000000),
            S.z: R(148161, 1000000), S.c_s: R(210491, 1000000), S.mu: R(10469, 50000)}
    r = B.flamant_reference(sf)(vals, 45)
    assert all(v.method == "arb" for v in r.values())
    with workdps(55):
        p, q, breaks = B._mp_tractions(sf, vals, 45)
        m = flamant_stresses(p, q, *[to_mpf(vals[k]) for k in (S.a, S.x, S.z)], breaks=breaks, dps=45)
        for v, mv in zip(r.values(), m):
            assert v.contains(mv, abs(mv) * mpmath.mpf(10) ** -46)


def test_stick_traction_and_force_enclosures_contain_cattaneo():
    """Hertz (a = 1, p0 = 1): q = mu [p(x; 1) - p(x; c)] in the stick zone,
    Q = mu [P(1) - P(c)] = mu pi (1 - c^2)/2 (Johnson 1985, ch. 7)."""
    c, x, mu = R(1, 2), R(3, 10), R(1, 5)
    q = TR.stick_traction_enclosure(HERTZ_P, 1, c, x, mu, dps=40)
    Q = TR.tangential_force_enclosure(HERTZ_P, 1, c, mu, dps=40)
    with workdps(60):
        qm = mpmath.mpf(1) / 5 * (mpmath.sqrt(1 - mpmath.mpf(9) / 100) - mpmath.sqrt(mpmath.mpf(1) / 4 - mpmath.mpf(9) / 100))
        Qm = mpmath.mpf(1) / 5 * mpmath.pi * (1 - mpmath.mpf(1) / 4) / 2
        assert q.method == Q.method == "arb" and min(q.digits, Q.digits) >= 40
        assert q.contains(qm) and Q.contains(Qm) and not Q.contains(Qm * (1 + mpmath.mpf(10) ** -38))


@pytest.mark.slow
def test_friction_work_enclosure_contains_hertz():
    """W = pi E* mu^2/(8 R^2) [a^4 - c^4 - 4 a^2 c^2 ln(a/c)] (E* = 2, R = 1, a = 1)."""
    c, mu = R(1, 2), R(1, 5)
    g = sp.Lambda(xs, (xs * sp.sqrt(xs**2 - c**2) - c**2 * sp.acosh(xs / c)) / 2)
    W = TR.friction_work_enclosure(HERTZ_P, g, 1, c, mu, dps=40)
    with workdps(60):
        Wm = mpmath.pi * 2 * mpmath.mpf(1) / 25 / 8 * (1 - mpmath.mpf(1) / 16 - mpmath.log(2))
        assert W.method == "arb" and W.digits >= 40 and W.contains(Wm)


@pytest.mark.slow
@pytest.mark.parametrize("what,terms,domain", [("traction", LOADING, "inside"), ("force", LOADING, "any"),
                                               ("traction", UNLOADING, "inside")])
def test_tangential_checks_are_certified_and_contain_the_mpmath_route(what, terms, domain, monkeypatch):
    t = lcs.parabola(verify=False).tangential()
    check, _, _ = states.references(t, what, terms)
    sample = t._sampler(domain, len(terms) > 1)
    rng = random.Random(3)
    vals = None
    while vals is None:
        vals = sample(rng)
    r = check(vals, 45)
    assert r.method == "arb" and r.digits >= 44
    monkeypatch.setattr(states, "normal_lambda", lambda *a: None)      # the mpmath route
    m = check(vals, 45)
    assert not hasattr(m, "method")
    with workdps(60):
        assert r.contains(m, abs(m) * mpmath.mpf(10) ** -45)


def test_jkr_energy_route_is_certified_and_contains_eq31():
    """Phat from the energy balance of the flat punch's compliance encloses
    Eq. (31) sqrt(2 pi a gamma E*) (up to the distant point's 1/L)."""
    for A, g, E in [(sp.Float(0.7, 80), sp.Float(0.1, 80), sp.Float(1.3, 80)), (R(3, 2), R(1, 50), R(2))]:
        r = phat_energy(A, g, E, 45)
        with workdps(70):
            Am, gm, Em = (to_mpf(v) for v in (A, g, E))
            assert r.method == "arb" and r.digits >= 45
            assert r.contains(mpmath.sqrt(2 * mpmath.pi * Am * gm * Em))
    s = compliance_slope(R(1, 2), 1, 30, R(1, 2) * 10**50)
    with workdps(40):
        assert s.method == "arb" and s.contains(-4 / mpmath.pi)      # -2/(pi E* a)


@pytest.mark.slow
def test_jkr_verification_records_are_certified_by_arb():
    """Eq. (31), (33) and (29) of the parabola: every point checked against an
    Arb enclosure (Eq. 10* / Eq. 12 minus the energy route's Phat)."""
    ad = lcs.parabola().adhesive(S.gamma)
    for q in ("flat_punch_force", "force", "pressure"):
        v = ad.derivation(q).verification
        assert v.passed and v.certified and min(v.guaranteed) >= 30, (q, str(v))
        assert "Arb ball quadrature" in str(v)


@pytest.mark.slow
def test_gap_reference_refuses_a_point_where_the_profile_is_not_real():
    """The exact cylinder's R - sqrt(R^2 - x^2) past x = R: no gap there, a
    DomainError at once (it returned a real mpmath estimate after an Arb
    quadrature in vain); inside the profile's domain the certified value."""
    from linecontact_sym.core.errors import DomainError
    c = lcs.exact_cylinder()
    d = c.derivation("gap")
    vals = {S.R: R(73, 100), S.E_star: R(2), S.a: R(62, 100), S.x: R(15, 10)}
    with pytest.raises(DomainError, match="not real at x"):
        d.reference(vals, 30)
    vals[S.x] = R(7, 10)
    r = d.reference(vals, 30)
    assert r.certified and r.digits >= 30
    with workdps(40):
        assert abs(d.evalf(30, R=R(73, 100), E_star=2, a=R(62, 100), x=R(7, 10)) - r.mid) < 10**-28
