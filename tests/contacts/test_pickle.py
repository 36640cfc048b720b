"""Contacts, derivations and exports that users keep or share: pickled and
copied, they give the same numbers (Eq. (13) typed here, mpmath) and say
what an unpickled fallback lacks; a copy does not share later derivations.
Moved from tests/test_state.py (issue 10)."""
from __future__ import annotations

import copy
import math
import pickle

import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from independent_refs import parabola_force
from linecontact_sym.contacts.base import CONTACT_KINDS
from linecontact_sym.core.errors import LineContactError


def test_contact_and_derivation_pickle():
    c = lcs.parabola()
    d = c.derivation("force")
    v = c.evaluate("force", a=0.5, R=1.0, E_star=2.0).value
    c2 = pickle.loads(pickle.dumps(c))
    assert c2.evaluate("force", a=0.5, R=1.0, E_star=2.0).value == v == float(parabola_force(0.5, 1, 2, 20))
    d2 = pickle.loads(pickle.dumps(d))
    assert d2.expr == d.expr and d2.step == d.step and d2.verification.passed
    assert d2.reference is None
    assert float(d2.evalf(a=0.5, R=1, E_star=2)) == pytest.approx(v, rel=1e-15)


def test_unpickled_fallback_derivation_says_what_it_lacks():
    d = lcs.LineContact(sp.cosh(lcs.x) - 1, budget=2).derivation("pressure")
    d2 = pickle.loads(pickle.dumps(d))
    if not d.closed_form:
        with pytest.raises(LineContactError, match="no reference quadrature"):
            d2.evalf(a=0.5, x=0.1, E_star=1)


def test_exports_pickle():
    c = lcs.parabola()
    f = c.to_numeric("force")
    g = pickle.loads(pickle.dumps(f))
    assert g(a=0.5, R=1.0, E_star=2.0) == f(a=0.5, R=1.0, E_star=2.0) == pytest.approx(math.pi / 8, rel=1e-15)
    assert g.arguments == ("E_star", "R", "a")
    fm = c.to_numeric("pressure", backend="mpmath", dps=40)
    gm = pickle.loads(pickle.dumps(fm))
    with mpmath.workdps(40):
        ref = 2 * mpmath.sqrt(mpmath.mpf("0.25") - mpmath.mpf("0.01")) / 2   # E* sqrt(a^2 - x^2) / (2R)
        assert abs(gm(a="0.5", x="0.1", R=1, E_star=2) - ref) < mpmath.mpf(10) ** -38


def test_adhesive_and_every_kind_pickle_after_deriving():
    c = lcs.parabola()
    ad = c.adhesive()
    P = ad.force
    ad2 = pickle.loads(pickle.dumps(ad))
    assert sp.simplify(ad2.force - P) == 0
    for kind, cls in CONTACT_KINDS.items():
        obj = cls.from_frictionless(c)
        first = [n for n, q in type(obj).quantities().items() if not q.method][0]
        expr = obj.derivation(first).expr
        back = pickle.loads(pickle.dumps(obj))
        assert back.derivation(first).expr == expr, kind


def test_copy_does_not_share_later_derivations():
    c = lcs.parabola()
    c.derivation("force")
    c2 = copy.copy(c)
    assert c2._cache is not c._cache and "force" in c2._cache
    c2.derivation("pressure")
    assert "pressure" not in c._cache
