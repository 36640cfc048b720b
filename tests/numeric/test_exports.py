"""The exports of to_numeric (numeric/exports.py) at negative x (every
quantity of x is even in x: the same value on both signs, float64, arrays
and mpmath, checked or not) and with arrays where the mpmath export takes
scalars.  Moved from tests/test_trust_round4.py (issue 29, item 3) and
tests/test_state.py (issue 10).  The reference at +x is the value
evaluate_at verifies against the quadrature of the defining integral; the
worn cylinder's pressure at x = 0.6 is also pinned to its value."""
from __future__ import annotations

import warnings

import numpy as np
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core.errors import DomainError


@pytest.fixture(scope="module")
def par():
    return lcs.parabola(verify=False)


WORN = dict(a=0.8, b=0.5, R=1.0, E_star=1.0)


@pytest.fixture(scope="module")
def worn():
    return lcs.worn_cylinder(verify=False)


def _x_exports(worn, par):
    """(contact, quantity, values without x, x inside its domain): every
    quantity of x of the normal, adhesive and tangential contacts."""
    T = dict(a=1.0, c_s=0.5, mu=0.3, R=1.0, E_star=1.0)
    return [(worn, "pressure", WORN, 0.6), (worn, "gap", WORN, 1.2), (par, "pressure", dict(a=1.0, R=1.0, E_star=1.0), 0.3),
            (par, "gap", dict(a=1.0, R=1.0, E_star=1.0), 1.7),
            (par.adhesive(), "pressure", dict(a=1.0, R=1.0, E_star=1.0, gamma=0.1), 0.3),
            (par.tangential(), "traction", T, 0.3), (par.tangential(), "traction", T, 0.7),
            (par.tangential(), "slip", T, 0.7),
            (par.tangential(), "unloading_traction", {**T, "c_r": 0.8}, 0.6),
            (par.tangential(), "unloading_slip", {**T, "c_r": 0.8}, 0.6)]


@pytest.mark.slow
def test_worn_cylinder_pressure_at_negative_x(worn):
    """The issue's case: NaN at x = -0.6 before (the derived Piecewise reads
    b > x, x a positive symbol); the value at +0.6 is the one verified
    against the quadrature of the defining integral (evaluate_at)."""
    ref = float(worn.evaluate_at("pressure", x=sp.Rational(3, 5), a=sp.Rational(4, 5), b=sp.Rational(1, 2), R=1,
                                 E_star=1))
    assert ref == pytest.approx(0.3188056669639838, rel=1e-14)
    for check in (True, False):
        assert worn.to_numeric("pressure", check=check)(x=-0.6, **WORN) == pytest.approx(ref, rel=1e-13)
        xs = np.linspace(-0.799, 0.799, 501)
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            v = worn.to_numeric("pressure", check=check)(x=xs, **WORN)
        assert np.all(np.isfinite(v)) and np.allclose(v, v[::-1], rtol=1e-12, atol=0)
    assert float(worn.to_numeric("pressure", "mpmath", check=False)(x=-0.6, a=0.8, b=0.5, R=1, E_star=1)) == \
        pytest.approx(ref, rel=1e-14)
    assert worn.to_numeric("pressure", x=-0.6, check=False)(**WORN) == pytest.approx(ref, rel=1e-13)


@pytest.mark.slow
def test_every_x_export_on_both_signs(worn, par):
    for c, q, vals, xv in _x_exports(worn, par):
        ref = float(c.evaluate_at(q, dps=20, x=xv, **vals))
        for check in (True, False):
            f = c.to_numeric(q, check=check)
            for sign in (1, -1):
                assert f(x=sign * xv, **vals) == pytest.approx(ref, rel=1e-10, abs=1e-300), (q, check, sign)
                arr = f(x=np.array([sign * xv, -sign * xv]), **vals)
                assert np.allclose(arr, ref, rtol=1e-10), (q, check, sign)
            fm = c.to_numeric(q, "mpmath", check=check)
            assert float(fm(x=-xv, **vals)) == pytest.approx(ref, rel=1e-12), (q, "mpmath", check)


def test_mpmath_export_refuses_arrays():
    with pytest.raises(DomainError, match="takes scalars"):
        lcs.parabola().to_numeric("force", backend="mpmath")(a=[0.1, 0.5], R=1, E_star=1)
