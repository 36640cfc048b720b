"""The cohesive-law interface (contacts/adhesion/law.py): a law declares its
parameters, checks them, and gives P(a); the generic layer does the rest.

Two test laws, registered here as a new law would be (its module + one
``register_law`` line): ``ScaledJKR`` gives P(a) as one expression,
``InnerSolveJKR`` as a system solved at each a (like Maugis-Dugdale's c(a)).
Both are the JKR law in disguise, so every generic result must equal the JKR
closed form of Popov (2017), Eq. (34), recomputed here."""
from __future__ import annotations

import pickle

import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core import symbols as S
from linecontact_sym.core.conversion import to_mpf
from linecontact_sym.core.roots import root_in_log
from linecontact_sym.core.errors import DomainError, NoPullOffError
from linecontact_sym.contacts.adhesion import LAWS, CohesiveLaw, JKR, Parameter, register_law
from linecontact_sym.contacts.adhesion.law import on_base
from linecontact_sym.contacts.base import CONTACT_KINDS
from linecontact_sym.method.derivation import Derivation
from linecontact_sym.method.rules import Step

w = sp.Symbol("w", positive=True)
_c = sp.Symbol("c", positive=True)


class ScaledJKR(CohesiveLaw):
    """JKR with the work of adhesion written as 2*w (P(a) one expression)."""

    name, kind, label = "test_scaled_jkr", "test_scaled_jkr", "scaled JKR"
    parameters = (Parameter("w", w, "nonnegative", "the half work of adhesion", (0.005, 0.25)),)

    def derive_force(self, ad):
        fd = ad.contact.derivation("force")
        expr = fd.expr - sp.sqrt(4 * sp.pi * S.a * self["w"] * S.E_star)
        return Derivation("force", expr=expr, closed_form=fd.closed_form, step=Step("test", expr),
                          conditions=fd.conditions, variables=(S.a,) + ad.variables)

    def numeric(self, base, values):
        wv, E = self.numbers(values)["w"], values[S.E_star]

        def B():   # at the working precision of the caller
            return mpmath.sqrt(4 * mpmath.pi * to_mpf(wv) * to_mpf(E))

        def build(b):
            expr = None if b.expr is None else b.expr - sp.sqrt(4 * sp.pi * wv * E * S.a)
            return b.on_top(lambda A: b.P(A) - B() * mpmath.sqrt(A), lambda A: b.dP(A) - B() / (2 * mpmath.sqrt(A)),
                            expr=expr)
        return on_base(base, build)


class InnerSolveJKR(CohesiveLaw):
    """JKR written as a system: c(a) solves c**2 = 2 pi a gamma E* (an inner
    root finding at each a), P = P0(a) - c.  No single expression."""

    name, kind, label = "test_inner_jkr", "test_inner_jkr", "inner-solve JKR"
    parameters = (Parameter("work_of_adhesion", S.gamma, "nonnegative", "the work of adhesion"),)

    @property
    def inactive(self):
        return "no adhesion (gamma = 0)" if self["work_of_adhesion"] == 0 else False

    def derive_force(self, ad):
        fd = ad.contact.derivation("force")
        eqs = sp.Tuple(sp.Eq(_c**2, 2 * sp.pi * S.a * self["work_of_adhesion"] * S.E_star),
                       sp.Eq(S.P, fd.expr - _c))
        return Derivation("force", expr=eqs, closed_form=False, step=Step("test_system", eqs),
                          conditions=fd.conditions, variables=(S.a,) + ad.variables)

    def numeric(self, base, values):
        gv, Ev = self.numbers(values)["work_of_adhesion"], values[S.E_star]

        def c_of(A):   # the inner solve, bracketed: k/(2 (1 + k)) < sqrt(k) < 1 + k
            k = 2 * mpmath.pi * to_mpf(gv) * to_mpf(Ev) * A
            return root_in_log(lambda c: c**2 - k, k / (2 * (1 + k)), 1 + k)

        def build(b):
            return b.on_top(lambda A: b.P(A) - c_of(A),
                            lambda A: b.dP(A) - mpmath.pi * to_mpf(gv) * to_mpf(Ev) / c_of(A))
        return on_base(base, build)


@pytest.fixture(scope="module", autouse=True)
def registered():
    """The two test laws registered for this module only (a law's module and
    its one registration line), removed afterwards: no other test sees them."""
    classes = {law: register_law(law) for law in (ScaledJKR, InnerSolveJKR)}
    yield classes
    for law in classes:
        LAWS.pop(law.name)
        CONTACT_KINDS.pop(law.kind)


def _jkr_parabola_pull_off(R, E, g):
    """Eq. (34): P_adh = (3/4) (4 pi R E* gamma**2)**(1/3), a_po = (2 R**2 gamma/(pi E*))**(1/3)."""
    return (-mpmath.mpf(3) / 4 * mpmath.cbrt(4 * mpmath.pi * R * E * g**2),
            mpmath.cbrt(2 * R**2 * g / (mpmath.pi * E)))


def test_registration_makes_a_contact_kind_with_the_generic_quantities(registered):
    SCALED = registered[ScaledJKR]
    assert LAWS["jkr"] is lcs.parabola().adhesive().__class__
    assert CONTACT_KINDS["test_scaled_jkr"] is SCALED and SCALED.law_class is ScaledJKR
    assert {"force", "pressure", "pull_off_force", "adhesion_force", "pull_off_half_width",
            "jump_in_half_width", "half_width"} <= set(SCALED.quantities())
    assert "flat_punch_force" in LAWS["jkr"].quantities() and "flat_punch_force" not in SCALED.quantities()
    ad = lcs.parabola().adhesion("test_scaled_jkr")         # a made class pickles like a written one
    P = ad.force
    back = pickle.loads(pickle.dumps(ad))
    assert type(back) is SCALED and back.law == ad.law and sp.simplify(back.force - P) == 0


def test_parameters_are_checked_against_their_domains():
    with pytest.raises(DomainError, match="string"):
        JKR("0.1")
    with pytest.raises(DomainError, match=">= 0"):
        JKR(-1)
    with pytest.raises(DomainError, match="may not depend"):
        JKR(S.a)
    with pytest.raises(DomainError, match="no parameter"):
        JKR(gamma=1)
    with pytest.raises(DomainError, match="sign"):
        JKR(sp.Symbol("q"))
    assert JKR(0).inactive and not JKR().inactive and JKR().check()
    assert JKR().balance == sp.Eq(sp.Symbol("Phat", positive=True)**2 / (2 * sp.pi * S.E_star * S.a), S.gamma)


def test_generic_api_reaches_every_registered_law():
    ad = lcs.parabola().adhesion("jkr", sp.Rational(1, 10))
    assert ad.gamma == sp.Rational(1, 10)
    assert lcs.parabola().adhesion("test_scaled_jkr").law == ScaledJKR()
    with pytest.raises(DomainError, match="unknown cohesive law"):
        lcs.parabola().adhesion("nope")


def test_expression_law_pull_off_by_the_generic_layer():
    """P(a) as one expression: sympy.solve + verification, no JKR code."""
    ad = lcs.parabola().adhesion("test_scaled_jkr")
    po = ad.pull_off_at(30, R="1.3", E_star="0.7", w="0.05")
    with mpmath.workdps(40):
        Pm, A = _jkr_parabola_pull_off(mpmath.mpf("1.3"), mpmath.mpf("0.7"), 2 * mpmath.mpf("0.05"))
        assert abs(po.force - Pm) < abs(Pm) * mpmath.mpf(10)**-25
        assert abs(po.half_width - A) < A * mpmath.mpf(10)**-25


def test_inner_solve_law_pull_off_branches_and_jump_in():
    """P(a) only as a system with an inner solve: the numeric minimum over
    the admissible range, the equilibria and their stability, the jump-in --
    all generic, all equal to JKR's closed forms (Eq. 34; a_in = 16**(1/3) a_po)."""
    ad = lcs.parabola().adhesion("test_inner_jkr")
    assert not ad.derivation("force").closed_form
    vals = dict(R="1.3", E_star="0.7", gamma="0.1")
    po = ad.pull_off_at(20, **vals)
    with mpmath.workdps(30):
        Pm, A = _jkr_parabola_pull_off(mpmath.mpf("1.3"), mpmath.mpf("0.7"), mpmath.mpf("0.1"))
        assert abs(po.force - Pm) < abs(Pm) * mpmath.mpf(10)**-18
        assert abs(po.half_width - A) < A * mpmath.mpf(10)**-9
        assert po.kind == "stationary" and po.digits >= 20
        br = ad.branches(sp.Float(Pm / 2, 30), 20, **vals)
        assert [s for _, s in br] == ["stable", "unstable"] and br[0][0] > A > br[1][0]
        (a_in,) = [r for r, s in ad.branches(0, 20, **vals) if s == "stable"]
        assert abs(a_in - mpmath.cbrt(16) * A) < A * mpmath.mpf(10)**-15


def test_inactive_law_has_no_pull_off():
    ad = lcs.parabola().adhesion("test_inner_jkr", 0)
    with pytest.raises(NoPullOffError):
        ad.pull_off_at(20, R=1, E_star=1)
