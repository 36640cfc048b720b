"""Claims on asymmetric contacts (claims/data/asymmetric.toml): the formulas
of the file are derived by hand and checked here independently of the
engine (the flat punch's pressure by its resultant, moment and Flamant
surface, the tilt of the cubic by the bounded solution's condition
theta = (1/pi) int_0^pi f'(e + a cos phi) dphi, by quadrature); the
checker's verdicts on them hold, and a wrong formula gets a counterexample."""
import mpmath
import pytest

from linecontact_sym.claims.batch import check_file
from linecontact_sym.claims.results import FAILS, HOLDS
from linecontact_sym.claims.spec import load_paper, resolve_paper
from linecontact_sym.core.precision import workdps

# a point inside the complete-contact range M < P a/2
P, M, A, E = mpmath.mpf(2), mpmath.mpf("0.3"), mpmath.mpf("1.5"), mpmath.mpf("1.7")


def punch_pressure(t):
    """The file's formula, typed in by hand: (P + 2 M t/a^2)/(pi sqrt(a^2 - t^2))."""
    return (P + 2 * M * t / A**2) / (mpmath.pi * mpmath.sqrt(A**2 - t**2))


def test_the_punch_formulas_by_first_principles():
    """Resultant P, moment M, and a rigidly tilted surface under the punch
    (the log-kernel displacement into the body, u(x) = -(2/(pi E*)) int p ln|x - t| dt
    + const, is d + theta x under the punch: linear in x with the slope
    theta = 4 M/(pi E* a^2), deeper where the moment presses), all by quadrature;
    the lift-off moment P a/2 is where p's factor at x = -a vanishes."""
    with workdps(30):
        # t = a sin(phi) removes the end singularities: p dt = (P + 2 M sin(phi)/a)/pi dphi
        q = lambda ph: (P + 2 * M * mpmath.sin(ph) / A) / mpmath.pi   # noqa: E731
        half = mpmath.pi / 2
        assert abs(mpmath.quad(q, [-half, half]) - P) < mpmath.mpf(10)**-25
        assert abs(mpmath.quad(lambda ph: q(ph) * A * mpmath.sin(ph), [-half, half]) - M) < mpmath.mpf(10)**-25

        def u(x):
            ph0 = mpmath.asin(x / A)
            return -2 / (mpmath.pi * E) * mpmath.quad(lambda ph: q(ph) * mpmath.log(abs(x - A * mpmath.sin(ph))),
                                                       [-half, ph0, half])
        xs = [mpmath.mpf(v) for v in ("-1.1", "-0.2", "0.7", "1.3")]
        us = [u(x) for x in xs]
        theta = 4 * M / (mpmath.pi * E * A**2)
        for x, ux in zip(xs[1:], us[1:]):
            assert abs((ux - us[0]) / (x - xs[0]) - theta) < mpmath.mpf(10)**-20
        # (P + 2 M t/a^2) at t = -a vanishes at M = P a/2
        assert P - 2 * (P * A / 2) / A == 0


def test_the_cubic_tilt_by_quadrature():
    """theta(e, a) = (1/pi) int_0^pi f'(e + a cos phi) dphi for f = x^2/(2R) + x^3/(6 R b),
    against the file's e/R + (e^2 + a^2/2)/(2 R b)."""
    R, b, e, a = (mpmath.mpf(v) for v in ("1.3", "0.7", "0.4", "0.9"))
    with workdps(30):
        fp = lambda x: x / R + x**2 / (2 * R * b)                    # noqa: E731
        quad = mpmath.quad(lambda ph: fp(e + a * mpmath.cos(ph)), [0, mpmath.pi]) / mpmath.pi
        assert abs(quad - (e / R + (e**2 + a**2 / 2) / (2 * R * b))) < mpmath.mpf(10)**-25


def test_the_file_reads_and_names_its_quantities():
    paper = load_paper("asymmetric")
    assert {c.quantity for c in paper.claims} == {
        "asymmetric.tilt", "asymmetric.force", "asymmetric.moment", "asymmetric.centre",
        "asymmetric.half_width", "punch.pressure", "punch.tilt", "punch.lift_off_moment"}


FAST = {"parabola: centre", "punch: pressure", "punch: tilt", "punch: lift-off moment"}


def test_verdicts_of_the_punch_and_the_shifted_hertz():
    res = check_file("asymmetric", budget=60, only=FAST)
    assert [r.status for r in res.results] == [HOLDS] * len(FAST)
    assert all(r.digits >= 30 for r in res.results)


def test_a_wrong_formula_gets_a_counterexample(tmp_path):
    """The punch's pressure with M x/a^2 for 2 M x/a^2, and the tilt with 2 M
    for 4 M: both fail, at a point the report names."""
    text = resolve_paper("asymmetric").read_text()
    wrong = text.replace('formula = "(P + 2*M*x/a**2)', 'formula = "(P + M*x/a**2)') \
                .replace('formula = "4*M/(pi*E_star*a**2)"', 'formula = "2*M/(pi*E_star*a**2)"')
    assert "2*M*x" not in wrong and "2*M/(pi*E_star" in wrong
    f = tmp_path / "wrong.toml"
    f.write_text(wrong)
    res = check_file(f, budget=60, only={"punch: pressure", "punch: tilt"})
    assert [r.status for r in res.results] == [FAILS, FAILS]
    for r in res.results:
        cex = r.targets[0].forms[-1].counterexample
        assert cex is not None and cex.status == "fail" and cex.digits < 3


@pytest.mark.slow
def test_every_claim_of_the_file_holds():
    res = check_file("asymmetric", budget=120)
    assert [r.status for r in res.results] == [HOLDS] * 10
    assert all(r.digits >= 30 for r in res.results)
