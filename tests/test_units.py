"""Units (issue 23, item 5): the optional [units] extra (pint).  Quantities in,
a quantity out in the SI unit declared for the result; dimensions checked;
plain numbers are SI and unchanged, with or without pint."""
from __future__ import annotations

import math
import sys

import mpmath
import pytest

import linecontact_sym as lcs
from linecontact_sym.contacts.base import CONTACT_KINDS
from linecontact_sym.core.errors import DomainError

pint = pytest.importorskip("pint")
ureg = pint.get_application_registry()      # one registry per process: pint builds it once (about 0.7 CPU s)
Q_ = ureg.Quantity
_c: dict = {}


def contact(name):
    if name not in _c:
        _c[name] = getattr(lcs, name)(verify=False)
    return _c[name]


def test_force_in_newton_per_metre_from_mm_and_gpa():
    """Hertz, Eq. (13): P = pi E* a^2/(4R) = pi 210e9 (1e-3)^2/(4 5e-3) N/m."""
    P = contact("parabola").evaluate_at("force", a=Q_(1, "mm"), E_star=Q_(210, "GPa"), R=Q_(5, "mm"))
    assert isinstance(P, ureg.Quantity) and P.units == ureg.newton / ureg.meter
    assert float(P.magnitude) == pytest.approx(math.pi * 210e9 * 1e-6 / (4 * 5e-3), rel=1e-14)
    assert float(P.to("kN/m").magnitude) == pytest.approx(32986.72286269283, rel=1e-14)
    # the same numbers in SI give the same plain number
    plain = contact("parabola").evaluate_at("force", a=1e-3, E_star=210e9, R=5e-3)
    assert isinstance(plain, mpmath.mpf) and float(plain) == pytest.approx(float(P.magnitude), rel=1e-15)


def test_pressure_in_pascal_and_the_evaluation_carries_its_unit():
    p = contact("parabola").evaluate_at("pressure", a=Q_(1, "mm"), x=Q_(0.6, "mm"), E_star=Q_(2, "GPa"),
                                        R=Q_(10, "mm"))
    assert float(p.to("MPa").magnitude) == pytest.approx(2e9 * math.sqrt(1e-6 - 0.36e-6) / (2 * 1e-2) / 1e6, rel=1e-14)
    r = contact("parabola").evaluate("force", a=Q_(1, "mm"), E_star=Q_(210, "GPa"), R=Q_(5, "mm"), rtol=1e-12)
    assert r.path == "float64" and str(r.unit) == "newton / meter" and " N/m via float64" in repr(r)
    assert float(r.quantity_value().to("kN/m").magnitude) == pytest.approx(32986.72286269283, rel=1e-14)


@pytest.mark.parametrize("values, words", [
    (dict(a=Q_(1, "mm"), E_star=Q_(210, "GPa"), R=Q_(5, "N")), "R = 5 newton has the dimension"),
    (dict(a=Q_(1, "s"), E_star=210e9, R=5e-3), "a is a length"),
    (dict(a=Q_(1, "mm"), E_star=Q_(210, "m"), R=Q_(5, "mm")), "E_star is a pressure"),
])
def test_a_wrong_dimension_is_a_clear_package_error(values, words):
    with pytest.raises(DomainError, match=words):
        contact("parabola").evaluate_at("force", **values)


def test_an_undeclared_parameter_is_checked_through_the_profile():
    """c of c x^n has the unit m^(1-n): m^-1/2 for n = 3/2 passes, m^-1 does not;
    the value equals the SI computation, E* c Z_n a^n (Eq. 16) with Z_n from Gamma functions."""
    pl = contact("power_law")
    P = pl.evaluate_at("force", a=Q_(1, "mm"), E_star=Q_(1, "GPa"), c=Q_(1, "m**-0.5"), n=1.5)
    Zn = math.sqrt(math.pi) * math.gamma(1.25) / math.gamma(0.75)
    assert float(P.to("N/m").magnitude) == pytest.approx(1e9 * Zn * 1e-3**1.5, rel=1e-13)
    with pytest.raises(DomainError, match="not a length; check the units of c"):
        pl.evaluate_at("force", a=Q_(1, "mm"), E_star=Q_(1, "GPa"), c=Q_(1, "m**-1"), n=1.5)


def test_angles_in_degrees():
    w = contact("wedge")
    P = w.evaluate_at("force", a=Q_(1, "mm"), E_star=Q_(1, "GPa"), theta=Q_(5, "degree"))
    assert float(P.magnitude) == pytest.approx(float(w.evaluate_at("force", a=1e-3, E_star=1e9,
                                                                   theta=math.radians(5))), rel=1e-14)


def test_every_quantity_declares_its_unit():
    for kind, cls in CONTACT_KINDS.items():
        for name, q in cls.quantities().items():
            assert q.unit is not None, (kind, name)
            ureg.Unit(q.unit or "dimensionless")          # a unit pint reads


def test_plain_numbers_without_pint(monkeypatch):
    """pint blocked: plain numbers give the same value as before."""
    monkeypatch.setitem(sys.modules, "pint", None)
    v = contact("parabola").evaluate_at("force", a=0.5, R=1, E_star=2)
    with mpmath.workdps(30):
        assert abs(v - mpmath.pi / 8) < mpmath.mpf(10) ** -29


def test_adhesive_force_with_units():
    """JKR, Eq. (33): P = pi E* a^2/(4R) - sqrt(2 pi a gamma E*), gamma in J/m^2."""
    ad = contact("parabola").adhesive(lcs.gamma)
    P = ad.evaluate_at("force", a=Q_(1, "mm"), E_star=Q_(1, "GPa"), R=Q_(5, "mm"), gamma=Q_(50, "mJ/m**2"))
    expect = math.pi * 1e9 * 1e-6 / (4 * 5e-3) - math.sqrt(2 * math.pi * 1e-3 * 0.05 * 1e9)
    assert float(P.to("N/m").magnitude) == pytest.approx(expect, rel=1e-13)
    with pytest.raises(DomainError, match="gamma is an energy per area"):
        ad.evaluate_at("force", a=Q_(1, "mm"), E_star=Q_(1, "GPa"), R=Q_(5, "mm"), gamma=Q_(50, "mN"))


@pytest.fixture(scope="module")
def par():
    return lcs.parabola(verify=False)


U_REF = math.pi * 210e9 * 1e-3**2 / (4 * 5e-3)       # Eq. (13) in SI: 32986722.86 N/m


@pytest.mark.slow
def test_exports_take_units_checked_or_not(par):
    vals = dict(a=Q_(1, "mm"), R=Q_(5, "mm"), E_star=Q_(210, "GPa"))
    for check in (True, False):
        v = par.to_numeric("force", check=check)(**vals)
        assert v.to("N/m").magnitude == pytest.approx(U_REF, rel=1e-12)     # 32.99 before: mm read as numbers
        with pytest.raises(DomainError, match="dimension"):
            par.to_numeric("force", check=check)(**{**vals, "R": Q_(5, "s")})
    v = par.to_numeric("force", "mpmath", R=Q_(5, "mm"))(a=Q_(1, "mm"), E_star=Q_(210, "GPa"))
    assert float(v.to("N/m").magnitude) == pytest.approx(U_REF, rel=1e-14)
    assert par.to_numeric("force")(a=1e-3, R=5e-3, E_star=210e9) == pytest.approx(U_REF, rel=1e-12)   # plain: SI


def test_half_width_takes_units(par):
    a = par.half_width(Q_(U_REF, "N/m"), R=Q_(5, "mm"), E_star=Q_(210, "GPa"))
    assert float(a.to("mm").magnitude) == pytest.approx(1.0, rel=1e-12)


def test_record_results_refuse_units_naming_them(par):
    with pytest.raises(DomainError, match="pint quantity"):
        par.tangential().state(Q_(0.1, "N/m"), E_star=1, R=1, mu=0.4, a=0.8)
    with pytest.raises(DomainError, match="pint quantity"):
        par.maugis_dugdale().pull_off_at(15, E_star=Q_(1, "Pa"), R=1, gamma=0.01, sigma_0=1)


@pytest.mark.slow
def test_cli_set_with_units():
    """--set E_star=210GPa: converted to the declared SI unit (before: 'not a
    valid formula'); a wrong dimension is bad input naming the unit."""
    import contextlib
    import io
    from linecontact_sym import cli
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = cli.main(["eval", "x**2/(2*R)", "force", "--at", "a=1e-3", "--set", "R=5 mm", "E_star=210GPa",
                         "--dps", "12"])
    assert code == 0 and "32986722.8627" in out.getvalue() and "[N/m]" in out.getvalue()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        code = cli.main(["eval", "x**2/(2*R)", "force", "--at", "a=1e-3", "--set", "R=5 s", "E_star=1"])
    assert code == 2 and "'s'" in err.getvalue() and "(R)" in err.getvalue()
