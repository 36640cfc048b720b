"""The Maugis-Dugdale contact's inputs: sigma_0 and the tolerance refused at
the entry, the force export refused clearly (it is not one expression), the
state's gap real and equal to h0 at c, the pull-off of the remembered
conditions equal to the search's.  Moved from tests/test_trust_round4.py
(issue 29, item 4 of the issue)."""
from __future__ import annotations

import time

import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core.errors import DomainError, LineContactError


@pytest.fixture(scope="module")
def par():
    return lcs.parabola(verify=False)


MDV = dict(E_star=1, R=1, gamma=sp.Rational(1, 100))


@pytest.mark.parametrize("sigma0", [sp.oo, 1 + 2j, sp.Symbol("q") + 1, sp.nan, -1, 0])
def test_md_sigma0_refused_at_the_entry(par, sigma0):
    with pytest.raises(DomainError, match="sigma_0"):
        par.maugis_dugdale().pull_off_at(15, sigma_0=sigma0, **MDV)


@pytest.mark.parametrize("rtol", [-0.1, float("nan"), "abc", 0])
def test_model_choice_refuses_a_bad_tolerance(par, rtol):
    t0 = time.perf_counter()
    with pytest.raises(DomainError, match="tolerance"):
        par.maugis_dugdale().model_choice(rtol, sigma_0=1, **MDV)
    assert time.perf_counter() - t0 < 1            # refused before any pull-off is searched


@pytest.mark.slow
def test_md_force_export_refused_clearly(par):
    with pytest.raises(LineContactError, match="not one expression"):
        par.maugis_dugdale().to_numeric("force")


@pytest.mark.slow
def test_md_numbers(par):
    md = par.maugis_dugdale()
    v = md.at(sigma_0=1, **MDV).pull_off_force
    ref = md.pull_off_at(20, sigma_0=1, **MDV).force
    assert float(v) == pytest.approx(float(ref), rel=1e-12) and float(v) < 0
    st = md.state(0.5, sigma_0=1, **MDV)
    g = st.gap(st.c_D)
    assert not isinstance(g, mpmath.mpc) and float(g) == pytest.approx(float(st.h0), rel=1e-10)
    with pytest.raises(DomainError, match="not real"):
        lcs.exact_cylinder(verify=False).maugis_dugdale().pull_off_at(15, E_star=1, R=1, gamma=1,
                                                                      sigma_0=sp.Rational(1, 100))
