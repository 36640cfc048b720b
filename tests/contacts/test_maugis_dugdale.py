"""Maugis-Dugdale line contacts (issue 21): the derived conditions, the states,
the pull-off and its limits, each against numbers computed independently of
the flat-punch derivation (Johnson's bounded-solution condition and the
Flamant log kernel, a direct solve of Baney & Hui's normalised equations,
the rigid profile with a Dugdale law, this package's JKR law)."""
from __future__ import annotations

import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core import symbols as S
from linecontact_sym.core.errors import DomainError
from linecontact_sym.contacts.adhesion.maugis import check as chk
from linecontact_sym.contacts.adhesion.maugis.numbers import fixed_values
from linecontact_sym.method.verification import digits_agreeing

PROFILES = {
    "parabola": (lcs.parabola, dict(R=1)),
    "power_law": (lcs.power_law, dict(c=1, n=3)),
    "wedge": (lcs.wedge, dict(theta="3/10")),
    "worn_cylinder": (lcs.worn_cylinder, dict(R=1, b=1)),
}
LAMBDAS = ("0.05", "0.5", "5", "50")


@pytest.fixture(scope="module")
def mds():
    return {k: mk().maugis_dugdale() for k, (mk, _) in PROFILES.items()}


def base(name):
    return dict(E_star=1, gamma=1, **PROFILES[name][1])


@pytest.fixture(scope="module")
def sigma1(mds):
    """sigma_0 at lambda = 1 for each profile (lambda is proportional to sigma_0)."""
    return {k: md.sigma0_for(1, **base(k)) for k, md in mds.items()}


@pytest.mark.parametrize("name", PROFILES)
def test_conditions_closed_and_verified(mds, name):
    md = mds[name]
    bounded, gap = md.conditions
    assert isinstance(bounded, sp.Eq) and isinstance(gap, sp.Eq)
    assert gap.rhs == md.w / md.sigma0
    for q in ("zone_force", "cohesive_gap", "pressure"):
        d = md.derivation(q)
        assert d.closed_form and not d.expr.has(sp.Integral), q
        assert d.verification is not None and d.verification.passed and len(d.verification.points) >= 3, q
    # the Dugdale force and the bounded condition: P = P0 - 2 sigma_0 sqrt(c_D^2 - a^2)
    P0 = md.contact.derivation("force").expr
    assert sp.simplify(md.zone_force - P0 + 2 * S.sigma_0 * sp.sqrt(S.c_D**2 - S.a**2)) == 0


@pytest.mark.parametrize("name", PROFILES)
@pytest.mark.parametrize("lam", LAMBDAS)
def test_state_against_flamant_and_johnson(mds, sigma1, name, lam):
    """The state at a = 0.7: P by Johnson's bounded-solution condition with the
    Flamant kernel, the gap at c_D by the Flamant displacement (both share
    nothing with the flat-punch derivation) -- at lambda from 0.05 to 50."""
    md = mds[name]
    vals = dict(base(name), sigma_0=sigma1[name] * mpmath.mpf(lam))
    st = md.state("0.7", 20, **vals)
    assert st.c_D > st.a
    fixed = fixed_values(md._numeric_values(vals), 60)      # the values the law used
    fixed.update({S.a: sp.Float(mpmath.nstr(st.a, 50), 50), S.c_D: sp.Float(mpmath.nstr(st.c_D, 50), 50)})
    with mpmath.workdps(30):
        P_ref = chk.force_johnson(md, fixed, 20)
        g_ref = chk.gap_reference(md)(fixed, 20)
        assert digits_agreeing(st.force, P_ref) >= 16
        assert digits_agreeing(g_ref, st.h0) >= 16
    # the pressure is bounded and continuous with the Dugdale zone at the edge
    with mpmath.workdps(30):
        sig = md._numeric_values(vals)[S.sigma_0]
        sig = mpmath.mpf(str(sp.N(sig, 30)))
        assert abs(st.pressure(st.a * (1 - mpmath.mpf(10)**-18)) + sig) < 1e-4 * sig
        assert st.pressure(st.c_D * mpmath.mpf("1.01")) == 0
        assert digits_agreeing(st.gap(st.c_D), st.h0) >= 15


def test_cohesive_zone_unique_gap_rises(mds):
    """c_D(a) is unique: the gap at c_D rises with c_D (sampled densely)."""
    md = mds["parabola"]
    law = md.numeric_law(E_star=1, R=1, gamma=1, sigma_0=2)
    with mpmath.workdps(20):
        for A in ("1e-6", "0.3", "3"):
            A = mpmath.mpf(A)
            vals = [law._G(A, A * (1 + mpmath.mpf(10)**(k / mpmath.mpf(4)))) for k in range(-40, 20)]
            assert all(v1 > v0 for v0, v1 in zip(vals, vals[1:]))


def test_baney_hui_eq23_derived(mds):
    """Baney & Hui (1997) Eq. (23) in their normalisation, from the parabola's
    derived conditions; the literature form is typed here only as the check."""
    P, G = chk.baney_hui_equations(mds["parabola"])
    lam, ab, m = chk.LAM, chk.ABAR, chk.MBAR
    mu = sp.sqrt(m**2 - 1)
    lit_P = ab**2 - lam * ab * mu
    lit_G = lam * ab**2 / 2 * (m * mu - sp.log(m + mu)) + lam**2 * ab / 2 * (mu * sp.log(m + mu) - m * sp.log(m))
    for pt in ({lam: sp.Rational(3, 7), ab: sp.Rational(5, 4), m: sp.Rational(9, 5)},
               {lam: 12, ab: sp.Rational(1, 30), m: 41}):
        assert abs(sp.N((P - lit_P).xreplace(pt), 40)) < 1e-35
        assert abs(sp.N((G - lit_G).xreplace(pt), 40)) < 1e-35
    # the Maugis parameter of the API is Baney & Hui's lambda for the parabola
    lamv = mds["parabola"].maugis_parameter(E_star=2, R=3, gamma="1/2", sigma_0="7/10")
    ref, _, _ = chk.baney_hui_units(mpmath.mpf(2), mpmath.mpf("0.5"), mpmath.mpf(3), mpmath.mpf("0.7"))
    assert digits_agreeing(lamv, ref) >= 15


def _table_direct(lam):
    """Baney & Hui's normalised pull-off by a direct solve of their Eq. (23)
    (no use of the package): m(abar) bracketed on [1, 1e30] (geometric bisection
    down to a factor 2) and then Anderson-Bjorck (mpmath.findroot, to the working
    precision), a log grid of abar, golden-section polish (one new point per step,
    the bracket 0.618**40 ~ 4e-9 of the grid step: P's error is of its square), and
    the limit abar -> 0+ (1 = lam cbar^2/2 + lam^2 ln2 cbar/2, P = -lam cbar)."""
    lam = mpmath.mpf(lam)

    def m_of(ab):
        f = lambda m: (lam * ab**2 / 2 * (m * mpmath.sqrt(m * m - 1) - mpmath.acosh(m))  # noqa: E731
                       + lam**2 * ab / 2 * (mpmath.sqrt(m * m - 1) * mpmath.acosh(m) - m * mpmath.log(m)) - 1)
        lo, hi = mpmath.mpf(1), mpmath.mpf(10)**30      # f rises with m: f(1) < 0 < f(1e30)
        while hi / lo > 2:
            mid = mpmath.sqrt(lo * hi)
            if f(mid) > 0:
                hi = mid
            else:
                lo = mid
        return mpmath.findroot(f, (lo, hi), solver="anderson")     # a bracketing solver: stays in [lo, hi]

    Pbar = lambda ab: ab**2 - lam * ab * mpmath.sqrt(m_of(ab)**2 - 1)  # noqa: E731
    grid = [mpmath.mpf(10)**(k / mpmath.mpf(10)) for k in range(-60, 15)]
    vals = [Pbar(g) for g in grid]
    k = min(range(len(vals)), key=lambda i: vals[i])
    best = vals[k]
    if 0 < k < len(vals) - 1:
        g = (mpmath.sqrt(5) - 1) / 2
        lo, hi = grid[k - 1], grid[k + 1]
        m1, m2 = hi - g * (hi - lo), lo + g * (hi - lo)
        p1, p2 = Pbar(m1), Pbar(m2)
        for _ in range(40):
            if p1 < p2:
                hi, m2, p2 = m2, m1, p1
                m1 = hi - g * (hi - lo)
                p1 = Pbar(m1)
            else:
                lo, m1, p1 = m1, m2, p2
                m2 = lo + g * (hi - lo)
                p2 = Pbar(m2)
        best = min(best, p1, p2)
    cbar = (-lam**2 * mpmath.log(2) / 2 + mpmath.sqrt(lam**4 * mpmath.log(2)**2 / 4 + 2 * lam)) / lam
    return min(best, -lam * cbar)


@pytest.mark.parametrize("lam", ("0.1", "0.5", "1", "2", "10"))
def test_baney_hui_table(mds, lam):
    """The normalised pull-off Pbar = P_min/F against a direct solve of Eq. (23)."""
    with mpmath.workdps(25):
        ref = _table_direct(lam)
    s0 = sp.Rational(lam) * sp.pi**sp.Rational(2, 3) / 4     # lambda = 4 sigma_0/pi^(2/3) at E* = R = w = 1
    po = mds["parabola"].pull_off_at(20, E_star=1, R=1, gamma=1, sigma_0=s0)
    with mpmath.workdps(25):
        assert abs(po.force / mpmath.cbrt(mpmath.pi) - ref) < 1e-9


@pytest.mark.parametrize("name", PROFILES)
def test_jkr_limit(mds, sigma1, name):
    """sigma_0 -> oo recovers this package's JKR law and pull-off."""
    md = mds[name]
    pj = md.jkr.pull_off_at(20, **base(name)).force
    diffs = []
    for lam in (5, 50):
        po = md.pull_off_at(15, **base(name), sigma_0=sigma1[name] * lam)
        diffs.append(abs(po.force / pj - 1))
    assert diffs[1] < diffs[0] and diffs[1] < 1e-3
    # the force law at a fixed half-width: P_MD(a) -> P_JKR(a)
    jkr_force = md.jkr.force.xreplace({s: sp.sympify(v) for s, v in
                                       zip([sp.Symbol(k, positive=True) for k in base(name)], base(name).values())})
    a = sp.Rational(6, 5)
    PJ = sp.N(jkr_force.subs(S.a, a), 30)
    errs = [abs(md.state(a, 20, **base(name), sigma_0=sigma1[name] * lam).force - mpmath.mpf(str(PJ)))
            for lam in (10, 1000)]
    assert errs[1] < errs[0] / 50


@pytest.mark.parametrize("name", PROFILES)
def test_small_lambda_rigid_limit(mds, sigma1, name):
    """At small lambda the pull-off tends to the rigid profile's with a
    Dugdale law (-2 sigma_0 c_r, f(c_r) = h0, an independent root of the
    profile), so the pull-off normalised by JKR's tends to zero -- except for
    the wedge, which has no length scale: 4/pi."""
    md = mds[name]
    pj = md.jkr.pull_off_at(20, **base(name)).force
    ratios, norm = [], []
    for lam in ("0.05", "0.01"):
        s0 = sigma1[name] * mpmath.mpf(lam)
        po = md.pull_off_at(15, **base(name), sigma_0=s0)
        ratios.append(po.force / chk.rigid_limit(md, 20, **base(name), sigma_0=s0))
        norm.append(po.force / pj)
    assert abs(ratios[1] - 1) < abs(ratios[0] - 1) and abs(ratios[1] - 1) < 5e-3
    if name == "wedge":
        assert abs(norm[1] - 4 / mpmath.pi) < 2e-2
    else:
        assert norm[1] < norm[0] < mpmath.mpf("0.3")


def test_parabola_small_lambda_sqrt(mds):
    """Parabola: Pbar -> -sqrt(2 lambda) (rigid cylinder, P = -2 sigma_0 sqrt(2 R h0))."""
    lam = sp.Rational(1, 1000)
    po = mds["parabola"].pull_off_at(15, E_star=1, R=1, gamma=1, sigma_0=lam * sp.pi**sp.Rational(2, 3) / 4)
    assert po.kind == "infimum" and po.half_width == 0
    assert abs(po.force / mpmath.cbrt(mpmath.pi) / -mpmath.sqrt(2 * mpmath.mpf("0.001")) - 1) < 2e-3


def test_exponentially_small_minimum(mds):
    """lambda = 0.2: the minimum sits at abar ~ 1e-13, below P(0+) by ~1e-28 (found by the descent)."""
    s0 = sp.Rational(1, 5) * sp.pi**sp.Rational(2, 3) / 4
    law = mds["parabola"].numeric_law(E_star=1, R=1, gamma=1, sigma_0=s0)
    po = mds["parabola"].pull_off_at(30, E_star=1, R=1, gamma=1, sigma_0=s0)
    assert po.kind == "stationary" and 1e-15 < po.half_width < 1e-11
    with mpmath.workdps(40):
        assert po.force < law.force_zero_width(35)
        # independent: P(a) at a decade on either side is higher
        for f in ("0.1", "10"):
            assert law.P_and_slope(po.half_width * mpmath.mpf(f), 35)[0] > po.force


def test_worn_cylinder_two_minima(mds):
    """The worn cylinder has two minima at some sigma_0; the global one is reported."""
    md = mds["worn_cylinder"]
    vals = dict(E_star=1, R=1, gamma=1, b="3/10", sigma_0=20)
    po = md.pull_off_at(15, **vals)
    assert len(po.minima) == 2
    assert po.force == min(m.force for m in po.minima)     # the generic layer's Extremum s
    # independent: a dense scan of P(a) at low precision shows both local minima
    law = md.numeric_law(**vals)
    with mpmath.workdps(15):
        grid = [mpmath.mpf(k) / 400 for k in range(40, 600)]
        Ps = [law.P_and_slope(g, 12)[0] for g in grid]
    mins = [grid[i] for i in range(1, len(Ps) - 1) if Ps[i] < Ps[i - 1] and Ps[i] < Ps[i + 1]]
    assert len(mins) == 2
    for m, A in zip(mins, sorted(e.half_width for e in po.minima)):
        assert abs(m - A) < 0.01


def test_model_choice(mds, sigma1):
    md = mds["parabola"]
    ch = md.model_choice(rtol=1e-3, E_star=1, R=1, gamma=1, sigma_0=sigma1["parabola"] * 50)
    assert ch.model == "JKR" and abs(ch.maugis_parameter - 50) < 1e-8
    ch = md.model_choice(rtol=1e-3, E_star=1, R=1, gamma=1, sigma_0=sigma1["parabola"] / 2)
    assert ch.model == "MD" and ch.relative_difference > 0.1


def test_displacement_control_undefined(mds):
    with pytest.raises(DomainError, match="not defined for line contacts"):
        mds["parabola"].displacement_control()


def test_law_of_the_generic_layer(mds):
    """MD is a registered cohesive law: reachable as contact.adhesion('maugis_dugdale', w, sigma0),
    its parameters checked, and its numeric ForceLaw gives the generic layer's minimum equal to
    the MD pull-off (two different searches)."""
    from linecontact_sym.contacts.adhesion import LAWS, MaugisDugdale
    from linecontact_sym.contacts.normal.equilibria import minimum
    from linecontact_sym.contacts.normal.force_law import ForceLaw
    assert LAWS["maugis_dugdale"] is type(mds["parabola"])
    with pytest.raises(DomainError):
        MaugisDugdale(1, 0)
    md = lcs.parabola().adhesion("maugis_dugdale", 1, sp.Rational(1, 2))
    assert md.variables == (S.E_star, S.R)
    po = md.pull_off_at(20, E_star=1, R=1)
    vals = {S.E_star: sp.Integer(1), S.R: sp.Integer(1), S.gamma: sp.Integer(1), S.sigma_0: sp.Rational(1, 2)}
    fl = mds["parabola"].law.numeric(ForceLaw.from_contact(mds["parabola"].contact, vals), vals)
    with mpmath.workdps(20):
        generic = minimum(fl, 15)
        assert digits_agreeing(generic.force, po.force) >= 12
        assert digits_agreeing(generic.half_width, po.half_width) >= 6


def test_state_refuses_a_half_width_that_is_not_one_real_number(mds):
    """half_width(P) returns one a per branch (a tuple); passing it to state
    is a DomainError naming the problem, not a foreign AttributeError.  (The module's
    parabola contact: a fresh one would derive and verify its conditions again first.)"""
    md = mds["parabola"]
    vals = dict(E_star=1, R=1, gamma="1e-4", sigma_0="1/40")
    with pytest.raises(DomainError, match="one a per branch"):
        md.state((sp.Rational(7, 100),), 20, **vals)
    with pytest.raises(DomainError, match="must be a real number"):
        md.state("1 + 2*I", 20, **vals)


@pytest.mark.parametrize("q", ["zone_force", "cohesive_gap"])
def test_planted_wrong_condition_fails_certification(mds, q):
    """The zone force and the gap at c_D are checked against Arb enclosures
    (Johnson's condition; the Flamant kernel through numeric.flamant): a
    closed form 1e-35 off agrees to 35 digits (more than the 30 required)
    but lies outside every 40-digit enclosure, so it fails."""
    from linecontact_sym.method.verification import verify
    md = mds["parabola"]
    d = md.derivation(q)
    assert d.verification.certified and min(d.verification.guaranteed) >= 40
    wrong = d.expr * (1 + sp.Rational(1, 10**35))
    bad = verify(wrong, d.reference, md._sampler("any"), d.conditions, n_points=2)
    assert bad.min_digits > 30 and bad.outside == 2 and not bad.passed


@pytest.mark.slow
def test_a_tampered_record_of_the_conditions_is_rechecked(tmp_path, monkeypatch):
    """The conditions are remembered on disk (another contact of the same profile and law does not
    verify them again); a record whose closed form was changed (and its checksum recomputed) is
    re-checked against the independent reference at a random point, dropped with a warning and
    derived afresh."""
    import warnings
    from store_records import rewrite_derivations
    from linecontact_sym.method import store
    d = tmp_path / "cache"
    d.mkdir(mode=0o700)
    monkeypatch.setenv(store.CACHE_ENV, str(d))
    store.clear_memory()
    try:
        expr = lcs.parabola(verify=False).maugis_dugdale().derivation("pressure").expr
        n = rewrite_derivations(d, lambda old: f"Mul(Integer(-1), {old})")
        assert n == 1
        store.clear_memory()               # a new process: the record comes from disk
        with pytest.warns(store.UntrustedCacheWarning, match="independent check"):
            again = lcs.parabola(verify=False).maugis_dugdale().derivation("pressure")
        assert again.expr == expr and not again.cached
        store.clear_memory()               # the fresh derivation replaced the record: read without a warning
        with warnings.catch_warnings():
            warnings.simplefilter("error", store.UntrustedCacheWarning)
            third = lcs.parabola(verify=False).maugis_dugdale().derivation("pressure")
        assert third.expr == expr and third.cached == "disk"
    finally:
        store.clear_memory()
