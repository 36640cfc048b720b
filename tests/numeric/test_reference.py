"""The one reference integrator (numeric/reference.py): Arb ball quadrature
with mpmath as the recorded fallback, and the certified verification of the
seed profiles' closed forms."""
import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core import symbols as S
from linecontact_sym.method.verification import verify
from linecontact_sym.numeric.reference import ARB, MPMATH, RefValue, integrate

t = sp.Dummy("t")


def test_enclosure_contains_exact_value_and_guarantees_digits():
    r = integrate(sp.sqrt(1 - t**2), t, [0, 1], dps=40)     # branch point of sqrt at the end
    assert r.method == ARB and r.digits >= 40
    with mpmath.workdps(60):
        assert r.contains(mpmath.pi / 4)
        assert not r.contains(mpmath.pi / 4 * (1 + mpmath.mpf(10)**-38))


def test_piecewise_switch_between_the_given_points_is_still_enclosed():
    third = sp.Rational(1, 3)
    f = sp.Piecewise((t, t < third), (t**2, True))
    exact = third**2 / 2 + (1 - third**3) / 3
    for pts in ([0, third, 1], [0, 1]):          # with and without the hint
        r = integrate(f, t, pts, dps=30)
        assert r.method == ARB
        with mpmath.workdps(50):
            assert r.contains(mpmath.mpf(exact.p) / exact.q)


def test_piecewise_with_a_bound_parameter_is_decided_on_the_balls():
    """A form made once with a parameter (bound_acb: the parameters' balls a
    tuple beside the variable's) whose Piecewise condition holds the
    parameter: the real parts taken for the condition keep that tuple (it
    raised AttributeError), and the value is the exact one."""
    from linecontact_sym.numeric.arb_compile import bound_acb
    b = sp.Symbol("b", positive=True)
    third = sp.Rational(1, 3)
    f = bound_acb(sp.Piecewise((b * t, t < b), (t**2, True)), t, {b: third})
    exact = third**3 / 2 + (1 - third**3) / 3
    r = integrate(f, None, [0, third, 1], dps=30, fallback=lambda: mpmath.nan)
    assert r.method == ARB and r.digits >= 30
    with mpmath.workdps(50):
        assert r.contains(mpmath.mpf(exact.p) / exact.q)
        assert not r.contains(mpmath.mpf(exact.p) / exact.q * (1 + mpmath.mpf(10)**-28))


def test_log_end_point_is_certified_and_a_planted_value_is_left_out():
    # int_0^1 s acosh(2/s) ds: acosh(2/s) = -ln s + ln(2 + sqrt(4 - s^2)) has no finite ball at
    # s = 0; the integrator splits the logarithm symbolically and integrates ln s in closed form
    r = integrate(t * sp.acosh(2 / t), t, [0, 1], dps=40)
    assert r.method == ARB and r.digits >= 40
    with mpmath.workdps(60):
        ref = mpmath.quad(lambda s: s * mpmath.acosh(2 / s), [0, mpmath.mpf(1) / 2**40, 1])
        assert r.contains(ref, mpmath.mpf(10)**-45)
        assert not r.contains(ref + mpmath.mpf(10)**-35)
    # ln^2 at 0 (the wedge's pressure under the Flamant kernel's ln s), and oo - oo at an inner
    # point where two logarithms cancel (the rounded punch's pressure at the end of its flat)
    third = sp.Rational(1, 3)
    for f, pts in ((sp.acosh(2 / t) * sp.log(t), [0, 1]),
                   (t * sp.log(sp.Abs(sp.sin(t + third) / sp.sin(t - third)))
                    + third * sp.log(sp.Abs(sp.tan(t / 2 - third / 2))), [0, third, 1])):
        r = integrate(f, t, pts, dps=40)
        assert r.method == ARB and r.digits >= 40
        with mpmath.workdps(60):
            g = sp.lambdify(t, f, "mpmath")
            ref = mpmath.quad(g, [mpmath.mpf(p) for p in pts])
            assert r.contains(ref, mpmath.mpf(10)**-48) and not r.contains(ref + mpmath.mpf(10)**-35)


def test_singular_end_neither_route_removes_falls_back_to_mpmath_and_says_why():
    # t^(-1/3) ln t: neither t = u^2 nor the subtraction of the logarithm leaves a finite ball
    r = integrate(t ** sp.Rational(-1, 3) * sp.log(t), t, [0, 1], dps=30)
    assert r.method == MPMATH and r.rad == 0 and "singularity" in r.note
    with mpmath.workdps(40):
        assert abs(r - mpmath.mpf(-9) / 4) < mpmath.mpf(10)**-20


@pytest.mark.parametrize("arc", [sp.asin, sp.acos])
def test_arc_branch_point_at_a_singular_end_is_certified(arc):
    # arc(1/(1 + t)) + 1/sqrt(t) on [0, 1]: the end t = 0 is both 1/sqrt's singularity and the
    # branch point of asin/acos (argument 1), which t = u^2 leaves at u = 0 (the worn cylinder's and
    # rounded punch's pressure, asin(b/s) at s = b): the half-angle rewrite makes it holomorphic in u.
    # Exact: y = 1/(1 + t), int asin(y)/y^2 dy = -asin(y)/y - atanh(sqrt(1 - y^2)), and acos = pi/2 - asin
    r = integrate(arc(1 / (1 + t)) + 1 / sp.sqrt(t), t, [0, sp.Rational(1, 2), 1], dps=40)
    assert r.method == ARB and r.digits >= 40
    with mpmath.workdps(60):
        of_asin = -mpmath.pi / 6 + mpmath.atanh(mpmath.sqrt(3) / 2)
        exact = 2 + (of_asin if arc is sp.asin else mpmath.pi / 2 - of_asin)
        assert r.contains(exact) and not r.contains(exact + mpmath.mpf(10)**-35)


def test_refvalue_is_a_number_and_pickles():
    import pickle
    r = integrate(sp.exp(t), t, [0, 1], dps=30)
    assert isinstance(r, mpmath.mpf) and type(r + 1) is mpmath.mpf
    r2 = pickle.loads(pickle.dumps(r))
    assert isinstance(r2, RefValue) and r2.method == ARB and r2.rad == r.rad and r2.mid == r.mid


@pytest.mark.parametrize("profile,quantity", [("parabola", "force"), ("parabola", "pressure"),
                                              ("parabola", "gap"), ("exact_cylinder", "gap"),
                                              ("wedge", "pressure")])
def test_seed_verification_records_are_certified_by_arb(profile, quantity):
    d = getattr(lcs, profile)().derivation(quantity)
    v = d.verification
    assert d.closed_form and v.passed and v.certified, str(v)
    assert len(v.points) == 5 and min(v.guaranteed) >= 30
    assert "Arb ball quadrature" in str(v) and "certified" in str(v)


def test_planted_wrong_coefficient_fails_certification():
    """A closed form 1e-35 off agrees to 35 digits (more than the 30
    required) but lies outside the 40-digit enclosures: it fails."""
    c = lcs.parabola()
    d = c.derivation("force")
    wrong = d.expr * (1 + sp.Rational(1, 10**35))
    sampler = c._sampler("any")
    good = verify(d.expr, d.reference, sampler, n_points=3)
    bad = verify(wrong, d.reference, sampler, n_points=3)
    assert good.passed and good.certified
    assert bad.min_digits > 30 and bad.outside == 3 and not bad.passed
    assert "outside the enclosure" in str(bad)


def test_negative_numbers_keep_their_sign():
    """A negative Float or mpf (a coefficient, an end point) is enclosed with its sign: mpf.man_exp
    drops it, and exp(-0.5 t) was integrated as exp(+0.5 t) (a wrong 'certified' enclosure)."""
    import sympy as sp
    t = sp.Dummy("t")
    with mpmath.workdps(40):
        r = integrate(sp.exp(-sp.Float("0.5", 40) * t), t, [0, 1], 30)
        assert r.method == "arb" and r.contains(2 * (1 - mpmath.exp(-mpmath.mpf("0.5"))))
        r = integrate(t, t, [mpmath.mpf(-1), mpmath.mpf(0)], 30)
        assert r.contains(-mpmath.mpf("0.5"))


def test_inverse_sqrt_end_points_are_certified_after_substitution():
    # both ends of int_{-1}^{1} dt/sqrt(1 - t^2) = pi are integrable 1/sqrt singularities
    r = integrate(1 / sp.sqrt(1 - t**2), t, [-1, 1], dps=40)
    assert r.method == ARB and r.digits >= 40
    with mpmath.workdps(60):
        assert r.contains(mpmath.pi)
    # Eq. (9) as printed, for the parabola's force law: gives back f(a) = a^2/(2R)
    a, R = sp.Rational(3, 2), sp.Rational(21, 10)
    J = integrate(sp.pi * t**2 / (4 * R) / (t * sp.sqrt(a**2 - t**2)), t, [0, a], dps=40)
    assert J.method == ARB
    with mpmath.workdps(60):
        f_a = 2 * mpmath.mpf(3) / 2 / mpmath.pi * J
        assert abs(f_a - mpmath.mpf(9) / 4 / (2 * mpmath.mpf(21) / 10)) < mpmath.mpf(10)**-38


def test_closed_form_at_a_point_takes_the_piecewise_branch_the_substitution_would():
    # at_point (the verification's value of a closed form) substitutes only the branch that the
    # Piecewise of the substituted branches evaluates to; undecided conditions substitute it all
    from linecontact_sym.method.verification import at_point
    a, b, x = S.a, S.b, S.x
    pw = sp.Piecewise((sp.sqrt(a - x), x < b), (sp.log(x), sp.Eq(x, b)), (sp.atan(x / a) + 1, True))
    for xv in (sp.Float("0.25", 70), sp.Float("0.5", 70), sp.Float("0.75", 70)):
        vals = {a: sp.Float(1, 70), b: sp.Float("0.5", 70), x: xv}
        assert at_point(pw, vals) == pw.xreplace(vals)
    some = {a: sp.Float(1, 70), x: sp.Float("0.25", 70)}           # b left symbolic: x < b undecided
    assert at_point(pw, some) == pw.xreplace(some) and at_point(pw, some).has(sp.Piecewise)
    nested = sp.Piecewise((pw, a > 0), (0, True))
    vals = {a: sp.Float(1, 70), b: sp.Float("0.5", 70), x: sp.Float("0.75", 70)}
    assert at_point(nested, vals) == nested.xreplace(vals)


def test_removable_quotient_bound_holds_on_complex_balls():
    """quotient_bound's crude(z, analytic): a bound of N(t)/t^k * rest(t)
    on any ball next to 0, real or complex (maximum modulus on the disk
    |w| <= |z|), finite only where N is holomorphic on that disk and rest
    on z, so that acb.integral may use it on its complex neighbourhoods."""
    import flint
    from linecontact_sym.numeric.reference import quotient_bound
    crude = quotient_bound(sp.sin(t), t, 1 / sp.sqrt(4 - t**2))           # sin(t)/t / sqrt(4 - t^2)
    f = lambda w: mpmath.sin(w) / w / mpmath.sqrt(4 - w**2)
    with flint.ctx.workprec(100), mpmath.workdps(30):
        for c, h in ((0, 0.5), (0.3 + 0.2j, 0.25), (-0.1j, 0.1), (1.0 + 0.5j, 0.2)):
            z = flint.acb(flint.arb(c.real if isinstance(c, complex) else c, h),
                          flint.arb(c.imag if isinstance(c, complex) else 0, h))
            b = crude(z, True)
            assert b.is_finite()
            for dx, dy in ((0, 0), (h, h), (-h, h), (h / 2, -h)):
                w = mpmath.mpc(complex(c) + complex(dx, dy))
                v = f(w) if w != 0 else 1 / mpmath.mpf(2)
                assert abs(v) <= float(b.abs_upper())
        # the rest is not holomorphic on a ball over its branch point t = 2: no bound
        assert not crude(flint.acb(flint.arb(2, 0.1), flint.arb(0, 0.1)), True).is_finite()
    # a numerator not holomorphic on the disk (sqrt's branch point at t = -1): no bound
    crude2 = quotient_bound(t * sp.sqrt(1 + t), t, sp.S.One)
    with flint.ctx.workprec(100):
        assert crude2(flint.acb(flint.arb(0, 0.2)), True).is_finite()
        assert not crude2(flint.acb(flint.arb(0.5, 0.7)), True).is_finite()


def test_arcs_on_complex_balls_are_enclosed_by_the_mean_value_form():
    """asin, acos, acosh and asinh of a wide complex ball about the real segment: the
    mean-value enclosure about the ball's midpoint holds the function at
    the ball's corners and centre and is far tighter than Arb's own ball
    (radius 0.012 against 0.096 at 0.574 +- 0.0088 +- 0.0038 i); a ball touching a branch cut stays
    non-finite in the analytic mode; and a quadrature of the rounded
    punch's logarithm in asin takes a quarter of the evaluations (2,601
    with Arb's balls alone) to the same digits, its enclosure holding
    mpmath's value."""
    import flint
    from linecontact_sym.numeric.arb_compile import compile_acb
    with flint.ctx.workprec(180), mpmath.workdps(50):
        arcs = ((0.574, 0.0088, 0.0038), (-0.3, 0.2, 0.1), (0.8, 0.04, 0.02))
        for fn, mfn, balls, cut in ((sp.asin, mpmath.asin, arcs, (0.97, 0.05, 0.01)),
                                    (sp.acos, mpmath.acos, arcs, (-0.97, 0.05, 0.01)),
                                    (sp.acosh, mpmath.acosh, ((1.5, 0.01, 0.005), (3.0, 0.5, 0.2)), (1.02, 0.05, 0.01)),
                                    (sp.asinh, mpmath.asinh, ((0.8, 0.01, 0.005), (-0.5, 0.2, 0.3)), (0.1, 0.05, 1.2))):
            f = compile_acb(fn(t), t)
            for c, hr, hi in balls:
                z = flint.acb(flint.arb(c, hr), flint.arb(0, hi))
                v = f(z, True)
                assert v.is_finite() and max(v.real.rad(), v.imag.rad()) < 4 * (hr + hi)
                for dx, dy in ((0, 0), (hr, hi), (-hr, hi), (hr, -hi), (-hr, -hi)):
                    w = mpmath.mpc(c + dx, dy)
                    assert mpmath.mpf(v.real.lower()) <= mpmath.re(mfn(w)) <= mpmath.mpf(v.real.upper())
                    assert mpmath.mpf(v.imag.lower()) <= mpmath.im(mfn(w)) <= mpmath.mpf(v.imag.upper())
            c, hr, hi = cut       # a ball over a branch cut: not holomorphic there
            assert not f(flint.acb(flint.arb(c, hr), flint.arb(0, hi)), True).is_finite()
        z = flint.acb(flint.arb(0.574, 0.0088), flint.arb(0, 0.0038))
        assert z.asin().real.rad() > 4 * compile_acb(sp.asin(t), t)(z, True).real.rad()
    b = sp.Rational(3, 10)
    g = t * sp.log(sp.Abs(sp.sin(sp.asin(b) + sp.asin(t)) / sp.sin(sp.asin(t) - sp.asin(b))))
    main = compile_acb(g, t)
    count = [0]

    def counted(z, an):
        count[0] += 1
        return main(z, an)
    r = integrate(counted, None, [sp.Rational(1, 2), sp.Rational(9, 10)], 45, fallback=lambda: mpmath.nan)
    assert r.method == ARB and r.digits >= 45
    assert count[0] < 1000, count[0]
    with mpmath.workdps(60):
        bm = mpmath.mpf(3) / 10
        ref = mpmath.quad(lambda s: s * mpmath.log(abs(mpmath.sin(mpmath.asin(bm) + mpmath.asin(s))
                                                       / mpmath.sin(mpmath.asin(s) - mpmath.asin(bm)))),
                          [mpmath.mpf(1) / 2, mpmath.mpf(9) / 10])
        assert r.contains(ref, mpmath.mpf(10)**-55)
        assert not r.contains(ref * (1 + mpmath.mpf(10)**-35))
    # asinh: 5,404 evaluations with Arb's balls alone
    count[0] = 0
    main = compile_acb(t * sp.asinh(3 * t) * sp.log(t + 1), t)
    r = integrate(counted, None, [sp.Rational(1, 10), 2], 45, fallback=lambda: mpmath.nan)
    assert r.method == ARB and r.digits >= 45 and count[0] < 1500, count[0]
    with mpmath.workdps(60):
        ref = mpmath.quad(lambda s: s * mpmath.asinh(3 * s) * mpmath.log(s + 1), [mpmath.mpf(1) / 10, 2])
        assert r.contains(ref, mpmath.mpf(10)**-55) and not r.contains(ref * (1 + mpmath.mpf(10)**-35))


def test_exact_cylinder_gap_integral_certified_with_few_evaluations():
    """The gap's J = int_0^a P(s)/(s sqrt(x^2 - s^2)) ds of the exact
    cylinder (P with elliptic K and E, P(0) = 0): the enclosure holds
    mpmath's value and not one 1e-35 off, and with the complex-ball bound
    next to s = 0 Arb needs about a third of the evaluations it took when it
    could only bisect towards 0 on real balls (about 3,300)."""
    from linecontact_sym.numeric.arb_compile import compile_acb
    from linecontact_sym.numeric.reference import quotient_bound
    R_, A, X = sp.Rational(1962, 1000), sp.Rational(7171, 10000), sp.Rational(1624, 1000)
    P = R_ * (sp.elliptic_k(t**2 / R_**2) - sp.elliptic_e(t**2 / R_**2))     # elliptic_k(m): m = k^2
    root = sp.sqrt(X**2 - t**2)
    main = compile_acb(P / (t * root), t)
    count = [0]

    def counted(z, an):
        count[0] += 1
        return main(z, an)
    r = integrate(counted, None, [0, A], 45, fallback=lambda: mpmath.nan, crude=quotient_bound(P, t, 1 / root))
    assert r.method == ARB and r.digits >= 45
    assert count[0] < 2000, count[0]
    with mpmath.workdps(60):
        Rm, Xm = mpmath.mpf(1962) / 1000, mpmath.mpf(1624) / 1000
        ref = mpmath.quad(lambda s: Rm * (mpmath.ellipk(s**2 / Rm**2) - mpmath.ellipe(s**2 / Rm**2))
                          / (s * mpmath.sqrt(Xm**2 - s**2)), [0, mpmath.mpf(7171) / 10000])
        assert r.contains(ref, mpmath.mpf(10)**-55)
        assert not r.contains(ref * (1 + mpmath.mpf(10)**-35))


@pytest.mark.slow
def test_references_done_ahead_give_the_same_record():
    """verify_here with the references computed ahead in a second child
    (core.budget.Ahead, method.verification.references_ahead) gives the
    record it gives computing them itself: with conditions that exclude
    some of the points done ahead (passed over; the further points computed
    here), and for a closed form 1e-35 off (outside every enclosure)."""
    from linecontact_sym.core.budget import Ahead
    from linecontact_sym.method.verification import references_ahead, verify_here
    c = lcs.parabola()
    d = c.derivation("force")
    sampler = c._sampler("any")
    conds = (sp.Lt(S.a, sp.Rational(8, 10)),)
    calls = []

    def reference(vals, dps):       # counts the references computed in this process
        calls.append(vals)
        return d.reference(vals, dps)
    for expr in (d.expr, d.expr * (1 + sp.Rational(1, 10**35))):
        calls.clear()
        here = verify_here(expr, reference, sampler, conds, n_points=5)
        n_here = len(calls)
        ahead = Ahead(references_ahead(reference, sampler, 5), 60)
        calls.clear()
        try:
            taken = verify_here(expr, reference, sampler, conds, n_points=5, ahead=ahead)
        finally:
            ahead.close()
        assert taken == here and len(here.points) == 5
        assert 0 < len(calls) < n_here          # some taken from the second child, the further ones here
        assert all(p[S.a] < sp.Rational(8, 10) for p in here.points)
    assert here.outside == 5 and not here.passed


def test_an_integral_with_parameters_makes_its_log_end_forms_once_and_encloses_the_integral():
    """integrate(values=...): the logarithmic end point t = b of
    (1 + t) ln|t - b| is split symbolically once (b a symbol), bound to each
    point's number; each enclosure holds the integral by its antiderivative
    in u = t - b, F(u) = (1 + b)(u ln|u| - u) + u^2 ln|u|/2 - u^2/4."""
    from linecontact_sym.numeric import endpoints
    t, b = sp.Dummy("t"), sp.Symbol("b", positive=True)
    f = (1 + t) * sp.log(sp.Abs(t - b))
    endpoints._FORMS.clear()
    for bv in (sp.Rational(1, 3), sp.Rational(3, 5)):
        r = integrate(f, t, [0, b / 2, b, (b + 1) / 2, 1], 40, values={b: bv})
        with mpmath.workdps(60):
            B = mpmath.mpf(bv.p) / bv.q

            def F(u):
                return (1 + B) * (u * mpmath.log(abs(u)) - u) + u**2 * mpmath.log(abs(u)) / 2 - u**2 / 4
            assert r.method == "arb" and r.contains(F(1 - B) - F(-B)) and r.digits > 40
    # one form for both sides of t = b (the half piece's signed length a
    # symbol too), made at the first point, used at the second
    assert [k[0] for k in endpoints._FORMS] == ["log"]


def test_flamant_arb_never_certifies_a_displacement_without_its_whole_u_z0(monkeypatch):
    """u_z(0) - u_z(x) sums the term u_z(0) = -2/(pi E*) int p(s) ln s ds of
    every piece.  Where Arb cannot enclose that term for one piece, no
    displacement is given (None), never one certified without that piece's
    term (the code once kept the pieces it had made and summed them into
    every later x)."""
    from linecontact_sym.numeric import flamant
    s = sp.Symbol("s", positive=True)
    p = sp.sqrt(1 - s**2)
    pieces = [(p, s, 0, sp.Rational(1, 2)), (p, s, sp.Rational(1, 2), 1)]
    xs = [sp.Rational(3, 10), sp.Rational(7, 10)]
    whole = flamant.flamant_arb(pieces, xs, 1, 30)
    assert all(r is not None and r.certified for r in whole)
    real = flamant._log_terms
    calls = []

    def failing_second_u_z0(p_, s_, lo, hi, c, m, smooth, values, dps):
        if c == 0 and smooth == 0 and lo == sp.Rational(1, 2):      # u_z(0)'s term of the second piece
            calls.append(lo)
            raise flamant.ArbUnsupported("planted")
        return real(p_, s_, lo, hi, c, m, smooth, values, dps)
    monkeypatch.setattr(flamant, "_log_terms", failing_second_u_z0)
    got = flamant.flamant_arb(pieces, xs, 1, 30)
    assert calls
    for r, w in zip(got, whole):
        assert r is None or abs(r - w) <= r.rad + w.rad, (r, w)


def test_entire_hypergeometric_pfq_is_enclosed():
    """pFq with p <= q (entire: 1F2, 0F1) in Arb; 3F2 (a cut at [1, oo)) is not encoded: mpmath."""
    t = sp.Dummy("t")
    e = t * sp.hyper([3], [sp.Rational(3, 2), sp.Rational(7, 2)], t**2 / 4) + sp.hyper([], [2], -t)
    r = integrate(e, t, [0, 2], dps=30)
    with mpmath.workdps(50):
        ref = mpmath.quad(lambda s: s * mpmath.hyp1f2(3, 1.5, 3.5, s**2 / 4) + mpmath.hyp0f1(2, -s), [0, 2])
        assert r.method == ARB and r.digits >= 30 and r.contains(ref, slack=mpmath.mpf(10)**-45)
    r3 = integrate(sp.hyper([1, 1, 1], [2, 2], t / 2), t, [0, 1], dps=20)
    assert r3.method == MPMATH and "hyper" in r3.note
