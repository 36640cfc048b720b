"""The paper's results (Popov 2017), derived by the engine from the profile
alone, against the printed formulas and against independent quadratures
written here (not the package's own reference integrals)."""
import mpmath
import pytest
import sympy as sp

from linecontact_sym import E_star, a, x, R, b, n, c, theta

mp = mpmath


def same(e1, e2):
    return sp.simplify(sp.expand_func(e1 - e2)) == 0 or sp.simplify(sp.gammasimp(e1 / e2)) == 1


def num(expr, **vals):
    subs = {sp.Symbol(k, positive=True): sp.nsimplify(v) for k, v in vals.items()}
    return mp.mpf(sp.N(expr.subs(subs), 40))


def test_eq13_14_parabola(paper_contacts):
    cp = paper_contacts["parabola"]
    assert same(cp.force, sp.pi * E_star * a**2 / (4 * R))                       # (13)
    assert same(cp.pressure, E_star / (2 * R) * sp.sqrt(a**2 - x**2))           # (14)
    for q in ("force", "pressure", "gap"):
        d = cp.derivation(q)
        assert d.closed_form and d.verification.passed and d.verification.min_digits >= 30
        assert len(d.verification.points) >= 5


def test_eq16_17_power_law_symbolic_n(paper_contacts):
    cpow = paper_contacts["power"]
    Zn = (n - 1) * sp.sqrt(sp.pi) * sp.gamma(n / 2 - sp.S.Half) / (2 * sp.gamma(n / 2))   # (17)
    assert same(cpow.force, E_star * c * Zn * a**n)                             # (16)
    d = cpow.derivation("force")
    assert "Z_n" in d.method and d.verification.min_digits >= 30


@pytest.mark.parametrize("nv, Z", [(1, 1), (2, sp.pi / 2), (3, 2), (4, 3 * sp.pi / 4), (5, sp.Rational(8, 3)),
                                  (6, 15 * sp.pi / 16), (10, 315 * sp.pi / 256)])
def test_table1_Zn(paper_contacts, nv, Z):
    """Table 1: Z_n from the derived symbolic force law (the n = 1 entry is the
    limit the printed (17) only reaches as 0*infinity)."""
    Zd = sp.simplify(paper_contacts["power"].force.subs(n, nv) / (E_star * c * a**nv))
    assert sp.simplify(Zd - Z) == 0


def test_eq19_20_wedge(paper_contacts):
    cw = paper_contacts["wedge"]
    assert same(cw.force, E_star * a * sp.tan(theta))                            # (19)
    printed = E_star * sp.tan(theta) / sp.pi * sp.log(a / x + sp.sqrt(a**2 / x**2 - 1))   # (20)
    for av, xv, th in [(1, sp.Rational(1, 3), sp.Rational(1, 5)), (2, sp.Rational(19, 10), 1),
                       (sp.Rational(1, 2), sp.Rational(1, 1000), sp.Rational(7, 10))]:
        vals = {a: av, x: xv, theta: th, E_star: sp.Rational(3, 2)}
        assert abs(sp.N((cw.pressure - printed).subs(vals), 40)) < 1e-35


def test_eq10_printed_form_drops_boundary_term(paper_contacts):
    """Eq. (10) as printed gives 0 for the wedge: the note says so."""
    cw = paper_contacts["wedge"]
    assert cw.profile.slope_at_origin == sp.tan(theta)
    assert any("drops the boundary term" in note for note in cw.derivation("force").notes)
    printed = E_star * a**2 * sp.integrate(sp.diff(x * sp.tan(theta) / x, x) / sp.sqrt(a**2 - x**2), (x, 0, a))
    assert printed == 0 and cw.force != 0


def test_eq23_worn_cylinder(paper_contacts):
    cwc = paper_contacts["worn"]
    printed = E_star * a**2 / (2 * R) * (sp.pi / 2 - sp.asin(b / a) + b / a * sp.sqrt(1 - b**2 / a**2))
    d = cwc.derivation("force")
    assert d.closed_form and d.verification.min_digits >= 30
    for av in (sp.Rational(3, 2), 2, 7):
        vals = {a: av, b: 1, R: 5, E_star: 2}
        assert abs(sp.N((d.expr - printed).subs(vals), 40)) < 1e-35
    assert d.expr.subs({a: sp.Rational(1, 2), b: 1, R: 5}) == 0    # flat fully in contact


def test_eq26_exact_cylinder_elliptic(paper_contacts):
    """(26) with the modulus k = a/R: SymPy's elliptic_k takes m = k**2."""
    cc = paper_contacts["cylinder"]
    d = cc.derivation("force")
    assert d.closed_form and d.verification.min_digits >= 30
    assert d.expr.has(sp.elliptic_k) and d.expr.has(sp.elliptic_e)
    for k in ("0.001", "0.3", "0.9", "0.999"):
        with mp.workdps(40):
            kv = mp.mpf(k)
            ref = 2 * (mp.ellipk(kv**2) - mp.ellipe(kv**2))      # E* = 1, R = 2, mpmath takes m
            got = num(d.expr, a=2 * kv, R=2, E_star=1)
            assert abs(got - ref) <= abs(ref) * mp.mpf(10)**-30


def _independent_force(fprime, av):
    """Eq. (10*) by mpmath quadrature after t = a - u**2 (a different route
    from the package's t = a sin(phi)): sqrt(a^2 - t^2) = u sqrt(2a - u^2)."""
    with mp.workdps(45):
        def g(u):
            t = av - u**2
            return 2 * t * fprime(t) / mp.sqrt(2 * av - u**2)
        return mp.quad(g, [0, mp.sqrt(av)])


def test_cylinder_force_against_direct_quadrature(paper_contacts):
    f = paper_contacts["cylinder"].to_numeric("force", backend="mpmath", dps=40)
    with mp.workdps(40):
        av, Rv = mp.mpf("0.7"), mp.mpf("1.3")
        ref = _independent_force(lambda t: t / mp.sqrt(Rv**2 - t**2), av)
        assert abs(f(a=av, R=Rv, E_star=1) - ref) < mp.mpf(10)**-25


@pytest.mark.parametrize("name", ["parabola", "wedge", "worn", "cylinder", "power"])
def test_pressure_integrates_to_the_load(paper_contacts, name):
    """Equilibrium: int_{-a}^{a} p dx = P(a), for closed forms and fallbacks."""
    cont = paper_contacts[name]
    vals = {"a": mp.mpf("1.7") if name == "worn" else mp.mpf("0.6"), "E_star": mp.mpf(2)}
    vals.update({p.name: v for p, v in {R: mp.mpf(5) if name == "worn" else mp.mpf("1.5"),
                                        b: mp.mpf(1), n: mp.mpf("2.5"), c: mp.mpf("0.8"),
                                        theta: mp.mpf("0.3")}.items() if p in cont.params})
    with mp.workdps(20):
        Pv = cont.evaluate_at("force", dps=20, **vals)
        # the strip below 1e-12 a (wedge: log singularity at 0) adds < 1e-10 P
        lo = mp.mpf("1e-12") * vals["a"]
        pts = [lo, 1, vals["a"]] if name == "worn" else [lo, vals["a"]]
        integral = 2 * mp.quad(lambda xv: cont.evaluate_at("pressure", dps=20, **vals, x=xv), pts)
        assert abs(integral - Pv) < mp.mpf(10)**-8 * abs(Pv)


def test_hertz_gap_closed_form(paper_contacts):
    g = paper_contacts["parabola"].gap
    known = (x * sp.sqrt(x**2 - a**2) - a**2 * sp.acosh(x / a)) / (2 * R)
    assert sp.simplify(g - known) == 0
    assert g.subs(x, a) == 0


def test_gap_is_nonnegative_and_vanishes_at_edge(paper_contacts):
    for name in ("power", "wedge"):
        cont = paper_contacts[name]
        vals = {"a": 1, "E_star": 1, "c": 1, "n": sp.Rational(3, 2), "theta": sp.Rational(1, 4)}
        vals = {k: v for k, v in vals.items() if k in {"a", "E_star"} | {p.name for p in cont.params}}
        assert abs(cont.evaluate_at("gap", **vals, x=1)) < 1e-25
        for xv in ("1.001", "1.5", "4"):
            assert cont.evaluate_at("gap", **vals, x=sp.Rational(xv)) > 0


def test_fallbacks_are_honest(paper_contacts):
    d = paper_contacts["cylinder"].derivation("pressure")
    if not d.closed_form:
        assert d.expr.has(sp.Integral) and "fallback" in d.method
    v = paper_contacts["cylinder"].evaluate_at("pressure", a=sp.Rational(1, 2), x=sp.Rational(1, 4),
                                              R=1, E_star=1, dps=25)
    # independent: Eq. (12) with P'(s) from mpmath's K, E (parameter m = k^2)
    with mp.workdps(30):
        def dP(s):
            return mp.diff(lambda u: mp.ellipk(u**2) - mp.ellipe(u**2), s)
        ref = mp.quad(lambda s: dP(s) / mp.sqrt(s**2 - mp.mpf(1) / 16), [mp.mpf(1) / 4, mp.mpf(1) / 2]) / mp.pi
        assert abs(v - ref) < mp.mpf(10)**-15 * ref
