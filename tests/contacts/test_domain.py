"""The physical domain of every entry point (contacts/domain.py): values
outside it (a non-positive modulus, radius or half-width, a point outside
or inside the contact, a singular point, a negative load, an unknown
parameter, NaN) are refused with a DomainError naming the problem, by
evaluate_at, evaluate and the exports alike; values inside still evaluate.
Moved from tests/test_hardening.py and tests/test_state.py (issue 10).
References: Eq. (13) and the exact cylinder's force typed here."""
from __future__ import annotations

import math

import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core.errors import DomainError


@pytest.fixture(scope="module")
def contacts():
    return {"parabola": lcs.parabola(), "power": lcs.power_law(), "cylinder": lcs.exact_cylinder()}


@pytest.mark.parametrize("which,quantity,values,match", [
    ("parabola", "force", dict(a=1, R=1, E_star=-1), "E\\* must be positive"),
    ("parabola", "force", dict(a=1, R=-1, E_star=1), "R must be positive"),
    ("power", "force", dict(a=1, n=-1, c=1, E_star=1), "n must be positive"),
    ("power", "force", dict(a=1, n=0, c=1, E_star=1), "n must be positive"),
    ("power", "force", dict(a=1, n=2, c=-1, E_star=1), "c must be positive"),
    ("parabola", "force", dict(a=0, R=1, E_star=1), "half-width a must be positive"),
    ("cylinder", "force", dict(a=2, R=1, E_star=1), "a < R"),
    ("parabola", "force", dict(a=1, R=1, E_star=1, Q=3), "'Q'"),
    ("parabola", "force", dict(a=float("nan"), R=1, E_star=1), "finite real"),
    ("parabola", "force", dict(a=float("inf"), R=1, E_star=1), "finite real"),
    ("parabola", "force", dict(a=1j, R=1, E_star=1), "finite real"),
    ("parabola", "force", dict(a=None, R=1, E_star=1), "not a number"),
    ("parabola", "pressure", dict(a=1, x=2, R=1, E_star=1), "outside the contact"),
    ("parabola", "gap", dict(a=1, x=0.5, R=1, E_star=1), "inside the contact"),
    ("parabola", "force", dict(a=[0.5, -1.0], R=1.0, E_star=1.0), "must be positive"),
])
def test_values_outside_the_domain_are_refused(contacts, which, quantity, values, match):
    c = contacts[which]
    for call in (c.evaluate_at, c.evaluate):
        if call is c.evaluate_at and isinstance(values.get("a"), list):
            continue
        with pytest.raises(lcs.DomainError, match=match):
            call(quantity, **values)


def test_values_inside_the_domain_still_evaluate(contacts):
    c = contacts["cylinder"]
    assert abs(float(c.evaluate_at("force", a=sp_half(), R=1, E_star=1)) - 0.218288145473169) < 1e-14
    assert abs(float(contacts["parabola"].evaluate("force", a=1.0, R=1.0, E_star=1.0).value) - 0.7853981633974483) < 1e-15


def sp_half():
    import sympy as sp
    return sp.Rational(1, 2)


def test_singular_points_and_negative_loads_are_domain_errors():
    w = lcs.wedge()
    with pytest.raises(lcs.DomainError, match="not finite|singular"):
        w.evaluate("pressure", x=0, a=1.0, theta=0.3, E_star=1.0)
    with pytest.raises(lcs.DomainError, match="not finite|singular"):
        w.to_numeric("pressure", backend="mpmath")(x=0, a=1.0, theta=0.3, E_star=1.0)
    with pytest.raises(lcs.DomainError, match="P >= 0"):
        lcs.parabola().evaluate("half_width", P=-1, R=1.0, E_star=1.0)
    with pytest.raises(lcs.DomainError, match="keyword arguments only"):
        lcs.parabola().to_numeric("force")(0.5, 1.0, 1.0)


@pytest.mark.parametrize("vals", [dict(a=0.5, R=1.0, E_star=-1.0), dict(a=-0.5, R=1.0, E_star=1.0),
                                  dict(a=float("nan"), R=1.0, E_star=1.0), dict(a=0.5, R=0.0, E_star=1.0),
                                  dict(a=[0.5, 0.2], R=1.0, E_star=[1.0, -1.0])])
@pytest.mark.parametrize("backend", ["numpy", "mpmath"])
def test_exports_check_the_domain(vals, backend):
    """The exports of to_numeric pass the contact's domain check (before: NaN,
    negative forces, ZeroDivisionError); check=False keeps the raw export."""
    c = lcs.parabola()
    if backend == "mpmath" and isinstance(vals["a"], list):
        vals = dict(vals, a=0.5, E_star=-1.0)
    with pytest.raises(DomainError):
        c.to_numeric("force", backend=backend)(**vals)
    assert c.to_numeric("force", backend="numpy")(a=0.5, R=1.0, E_star=2.0) == pytest.approx(math.pi / 8, rel=1e-15)


def test_exports_outside_the_contact_raise():
    c = lcs.parabola()
    with pytest.raises(DomainError, match="outside the contact"):
        c.to_numeric("pressure")(a=1.0, x=2.0, R=1.0, E_star=1.0)
    raw = c.to_numeric("pressure", check=False)(a=1.0, x=2.0, R=1.0, E_star=1.0)
    assert math.isnan(raw)
