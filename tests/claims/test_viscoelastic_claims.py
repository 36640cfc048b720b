"""Claims on viscoelastic line contacts (quantities viscoelastic_force and
viscoelastic_half_width, claim fields material and history): the formulas of
claims/data/lee_radok_line.toml are derived by hand there (the hereditary
integral of the elastic law pi E* a^2/(4R) with E0 exp(-t/tau)); the package
must find them true, and a wrong formula false with a counterexample."""
from __future__ import annotations

import pytest
import sympy as sp

from linecontact_sym.claims import spec as SPEC
from linecontact_sym.claims.check import check_claim
from linecontact_sym.claims.derive import Context
from linecontact_sym.claims.results import FAILS, HOLDS
from linecontact_sym.core.errors import ClaimError

PARABOLA = {"profile": "x**2/(2*R)", "material": "E0*exp(-t/tau)", "symbols": ["E0", "tau", "r"],
            "ranges": {"E0": [0.5, 3.0], "tau": [0.2, 3.0], "r": [0.1, 1.0], "t": [0.05, 4.0]}, "points": 3}


def _claim(label, formula, quantity="viscoelastic_force", history="r*t", **kw):
    return SPEC.claim_from_dict({"label": label, "quantity": quantity, "history": history, "formula": formula,
                                 **PARABOLA, **kw}, "test.toml")


def test_lee_radok_holds_and_the_quasi_elastic_substitution_fails():
    ctx = Context(budget=20.0)
    # by hand: (pi E0 r^2/(2R)) int_0^t s exp(-(t - s)/tau) ds
    right = check_claim(_claim("Lee-Radok", "pi*E0*r**2*tau/(2*R)*(t - tau*(1 - exp(-t/tau)))"), ctx, symbolic=False)
    assert right.status == HOLDS
    assert min(f.digits for tr in right.targets for f in tr.forms) >= 30
    # the 'quasi-elastic' shortcut: the elastic law with E*(t) in place of E* (wrong: it relaxes
    # the whole contact from t = 0, not each punch from its entry time)
    wrong = check_claim(_claim("quasi-elastic", "pi*E0*exp(-t/tau)*r**2*t**2/(4*R)"), ctx, symbolic=False)
    assert wrong.status == FAILS
    cex = wrong.targets[0].forms[0].counterexample
    assert cex is not None and cex.status == "fail" and sp.Symbol("t", positive=True) in cex.values


@pytest.mark.slow
def test_creep_under_a_step_load_holds():
    # J*(t) = (1 + t/tau)/E0, Pi(a) = pi a^2/(4R) = P0 J*(t)
    c = _claim("creep", "sqrt(4*R*P0*(1 + t/tau)/(pi*E0))", quantity="viscoelastic_half_width", history="P0",
               symbols=["E0", "tau", "P0"])
    assert check_claim(c, Context(budget=20.0), symbolic=False).status == HOLDS


def test_viscoelastic_fields_are_validated():
    with pytest.raises(ClaimError, match="needs material"):
        SPEC.claim_from_dict({"label": "A", "quantity": "viscoelastic_force", "profile": "x**2/(2*R)",
                              "history": "a*t", "formula": "1"}, "test.toml")
    with pytest.raises(ClaimError, match="only the quantities"):
        SPEC.claim_from_dict({"label": "A", "quantity": "force", "profile": "x**2/(2*R)",
                              "material": "E_star", "formula": "1"}, "test.toml")


def test_shipped_file_loads():
    p = SPEC.load_paper("lee_radok_line")
    assert [c.quantity for c in p.claims] == ["viscoelastic_force", "viscoelastic_force", "viscoelastic_half_width"]


@pytest.mark.slow
def test_shipped_file_holds():
    """Every claim of lee_radok_line.toml (Lee-Radok in two printed forms, Ting, creep) holds
    to 30 digits or more."""
    from linecontact_sym.claims.batch import check_file
    res = check_file("lee_radok_line", budget=60)
    assert [r.status for r in res.results] == [HOLDS] * 3
    assert all(r.digits >= 30 for r in res.results)
