"""Maugis-Dugdale on every profile (issue 28): the exact cylinder, R (cosh(x/R) - 1)
and the Gaussian bump R (1 - exp(-x^2/R^2)) (whose gaps the engine leaves as an
Integral) and the rounded punch, at three cohesive stresses (lambda about 0.1,
1 and 20; E* = 1, w = 1e-4, R = 1).

The independent solve (:func:`independent_state`) shares nothing with the state
solve of the package: the load by Johnson's bounded-solution condition on the
effective profile (Eq. 10* quadrature of the profile's slope plus the Flamant
slope of the strip), the adhesionless gap g0(c; a) = f(c) - (2/(pi E*)) int_0^a
acosh(c/s) P0'(s) ds by tanh-sinh in s with P0'(s) itself a quadrature of the
profile (P0'(s) = E* int_0^{pi/2} sin(phi) h'(s sin phi) dphi, h = t f'(t)),
the strip's gap by the Flamant kernel (its contact pressure, the derived one, is
checked to keep the contact flat in test_maugis_dugdale.py), and c_D by mpmath.findroot (Anderson).
"""
from __future__ import annotations

import os
from pathlib import Path

import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core import symbols as S
from linecontact_sym.core.errors import DomainError
from linecontact_sym.contacts.adhesion.pull_off import checked_or_fail
from linecontact_sym.contacts.normal.equilibria import searching_until
from linecontact_sym.contacts.adhesion.maugis import check as chk
from linecontact_sym.contacts.adhesion.maugis.numbers import fixed_values

x, R = S.x, S.R
W = sp.Rational(1, 10000)
#: sigma_0 at lambda ~ 0.1, 1, 20 (Baney & Hui's lambda = 40 sigma_0 for the parabola at these values)
SIGMAS = ("1/400", "1/40", "1/2")


def _profiles():
    return {
        "exact_cylinder": (lcs.exact_cylinder, {}, "0.1"),
        "cosh": (lambda **kw: lcs.LineContact(R * (sp.cosh(x / R) - 1), name="cosh", **kw), {}, "0.1"),
        "gaussian": (lambda **kw: lcs.LineContact(R * (1 - sp.exp(-x**2 / R**2)), name="Gaussian bump", **kw),
                     {}, "0.1"),
        "rounded_punch": (lcs.rounded_punch, {"b": sp.Rational(1, 10)}, "0.15"),
    }


PROFILES = _profiles()


@pytest.fixture(scope="module")
def mds():
    return {k: mk().maugis_dugdale() for k, (mk, _, _) in PROFILES.items()}


@pytest.fixture(scope="module")
def parabola_md():
    """The parabola's Maugis-Dugdale contact, derived and verified once for the tests that use it."""
    return lcs.parabola().maugis_dugdale()


def values(name, s0):
    return dict(E_star=1, gamma=W, R=1, sigma_0=sp.Rational(s0), **PROFILES[name][1])


def rel(a, b):
    return abs(a - b) / abs(b)


# ---------------------------------------------------------------- the independent solve
class Independent:
    """The two MD conditions by direct quadrature of the profile (module docstring)."""

    def __init__(self, md, vals):
        self.md = md
        self.fixed = fixed_values(md._numeric_values(vals), 60)
        pf = {k: v for k, v in self.fixed.items() if k in set(md.contact.params)}
        f = md.profile.expr.xreplace(pf)
        self.f = sp.lambdify(x, f, "mpmath")
        self.f1 = sp.lambdify(x, sp.diff(f, x), "mpmath")
        self.h1 = sp.lambdify(x, sp.diff(x * sp.diff(f, x), x), "mpmath")   # h'(t), h = t f'(t)
        with mpmath.workdps(60):        # held at 60 digits (an mpf made at 15 digits stays at 15)
            # the kinks too: a kink rounded to 15 digits (1e-17 off) leaves h' a jump inside a piece,
            # where Gauss-Legendre runs to its highest degree (its nodes cost seconds at 25 digits)
            self.kinks = [mpmath.mpf(str(sp.N(b.xreplace(pf), 60))) for b in md.profile.breakpoints
                          if sp.N(b.xreplace(pf)) > 0]
            self.E = mpmath.mpf(str(sp.N(self.fixed[S.E_star], 60)))
            self.sig = mpmath.mpf(str(sp.N(self.fixed[S.sigma_0], 60)))
            self.h0 = mpmath.mpf(str(sp.N(self.fixed[S.gamma] / self.fixed[S.sigma_0], 60)))
        # the strip's contact pressure (checked by substitution in tests/contacts/test_maugis_dugdale.py)
        self.pD = sp.lambdify((x, S.a, S.c_D), md.dugdale.pressure.xreplace(self.fixed), "mpmath")
        self._dP0 = {}

    def dP0(self, s):
        """P0'(s) = E* int_0^{pi/2} sin(phi) h'(s sin phi) dphi, split at the kinks (f' continuous
        here, h' analytic on each piece: Gauss-Legendre).  Remembered per (s, precision): the
        s-nodes of :meth:`gap` at one A are the same for every c the root search tries."""
        key = (s, mpmath.mp.prec)
        if key not in self._dP0:
            self._dP0[key] = self._dP0_quad(s)
        return self._dP0[key]

    def _dP0_quad(self, s):
        pts = [mpmath.mpf(0)] + [mpmath.asin(b / s) for b in self.kinks if b < s] + [mpmath.pi / 2]
        return self.E * mpmath.quad(lambda ph: mpmath.sin(ph) * self.h1(s * mpmath.sin(ph)), pts,
                                    method="gauss-legendre")

    def strip_gap(self, A, C):
        """u(c) - u(0) of the Dugdale sub-problem (tension sigma_0 on a < |x| < c, the contact
        pressure that keeps |x| < a flat) by the Flamant kernel."""
        def K(s):
            return mpmath.log(abs(C - s)) + mpmath.log(C + s) - 2 * mpmath.log(s)
        I = mpmath.quad(lambda s: self.pD(s, A, C) * K(s), [0, A]) + mpmath.quad(lambda s: -self.sig * K(s), [A, C])
        return -2 / (mpmath.pi * self.E) * I

    def gap(self, A, C):
        """g(c_D): the adhesionless gap by tanh-sinh in s, plus the strip's by the Flamant kernel."""
        pts = [mpmath.mpf(0)] + [b for b in self.kinks if b < A] + [A]
        I = mpmath.quad(lambda s: mpmath.acosh(C / s) * self.dP0(s), pts)
        return self.f(C) - 2 * I / (mpmath.pi * self.E) + self.strip_gap(A, C)

    def force(self, A, C):
        v = {**self.fixed, S.a: sp.Float(mpmath.nstr(A, 50), 50), S.c_D: sp.Float(mpmath.nstr(C, 50), 50)}
        return chk.force_johnson(self.md, v, mpmath.mp.dps)

    def state(self, A, c_guess):
        """(c_D, P) at A: findroot (secant) of gap(c) = h0 from c_guess (1 +- 1e-6): the root of the
        independent equations, whatever the guess's own error.  findroot stops when the step before
        the last one fell below tol = 10**-(dps - 3) (relative to max(1, c)): the secant's order 1.6
        leaves the last iterate ~1e-35 off, below the working precision; a tol below the working
        precision (it was 10**-(2 dps - 10)) is never met, and the secant then ran its 30 steps on
        the quadrature's rounding noise where 4-6 resolve the root."""
        A = mpmath.mpf(A)
        s = c_guess - A
        seen = {}            # findroot evaluates its first point twice, and the root once more to verify it

        def G(c):
            if c not in seen:
                seen[c] = self.gap(A, c) - self.h0
            return seen[c]
        C = mpmath.findroot(G, (A + s * (1 + mpmath.mpf(10)**-6), A + s * (1 - mpmath.mpf(10)**-6)),
                            solver="secant", tol=mpmath.mpf(10)**(-(mpmath.mp.dps - 3)))
        return C, self.force(A, C)

    def zero_width_zone(self, c_guess):
        """c0 of a vanishing contact: f(c) + (strip's Flamant gap over (0, c)) = h0."""
        def strip(c):
            k = lambda s: mpmath.log(abs(c - s)) + mpmath.log(c + s) - 2 * mpmath.log(s)  # noqa: E731
            return 2 * self.sig / (mpmath.pi * self.E) * mpmath.quad(k, [0, c])
        return mpmath.findroot(lambda c: self.f(c) + strip(c) - self.h0, (c_guess * mpmath.mpf("0.999"),
                                                                          c_guess * mpmath.mpf("1.001")),
                               solver="anderson")


# ---------------------------------------------------------------- one session's numbers, shared
# by the xdist workers: test_pull_off_independent writes the pull-off it computed (and checked
# against the independent solve) into the session's cache directory (tests/conftest.py), where
# test_jkr_limit_new_profiles reads it instead of searching for the same minimum again on the
# other worker (it computes it itself when it runs first)
def _shared_path(key):
    root = os.environ.get("LINECONTACT_SYM_TEST_SESSION_CACHE")
    return None if root is None else Path(root, "tests-shared", "-".join(k.replace("/", "_") for k in map(str, key)))


def _share_force(key, force):
    path = _shared_path(key)
    if path is not None:
        path.parent.mkdir(exist_ok=True)
        tmp = path.with_suffix(f".{os.getpid()}.tmp")
        tmp.write_text(mpmath.nstr(force, 40, strip_zeros=False))
        os.replace(tmp, path)          # atomic: a reader sees the whole number or nothing


def _shared_force(key):
    path = _shared_path(key)
    if path is None or not path.exists():
        return None
    with mpmath.workdps(40):
        return mpmath.mpf(path.read_text())


# ---------------------------------------------------------------- tests
@pytest.mark.slow
def test_which_parts_are_closed(mds):
    """The engine's closed forms: cosh and the Gaussian bump keep g0(c; a) as an Integral, the
    exact cylinder and the rounded punch have all three; the state says so."""
    st = mds["cosh"].state("0.1", 15, **values("cosh", SIGMAS[1]))
    assert st.closed == {"P0(a)": True, "g0(c_D; a)": False, "p0(x; a)": False}
    # the gap at c_D through the one reference integrator: an Arb enclosure that contains h0
    with mpmath.workdps(30):
        assert st.gap_check.method == "arb" and st.gap_check.contains(st.h0, st.h0 * mpmath.mpf(10)**-15)
    assert mds["cosh"].derivation("cohesive_gap").expr.has(sp.Integral)
    st = mds["exact_cylinder"].state("0.1", 15, **values("exact_cylinder", SIGMAS[1]))
    assert all(st.closed.values())


@pytest.mark.slow
def test_exact_cylinder_low_sigma_stays_in_domain(mds):
    """sigma_0 = 0.0025 (lambda ~ 0.1): the zone stays below 0.42 R (it raised TypeError from a
    guess past R); at a smaller sigma_0 the zone would need to reach past x = R: a DomainError."""
    md = mds["exact_cylinder"]
    st = md.state("0.1", 20, **values("exact_cylinder", SIGMAS[0]))
    assert st.a < st.c_D < mpmath.mpf("0.42")
    with pytest.raises(DomainError, match="past x = 1"):
        md.state("0.1", 20, **values("exact_cylinder", "1/100000"))


@pytest.mark.slow
@pytest.mark.parametrize("name", PROFILES)
@pytest.mark.parametrize("s0", SIGMAS)
def test_state_independent(mds, name, s0):
    """The state at 20 digits against the independent solve (c_D and P)."""
    md = mds[name]
    vals = values(name, s0)
    A = PROFILES[name][2]
    st = md.state(A, 20, **vals)
    assert st.c_D > st.a
    with mpmath.workdps(25):
        C, P = Independent(md, vals).state(st.a, st.c_D)
        assert rel(st.c_D, C) < 1e-20
        assert rel(st.force, P) < 1e-20


@pytest.mark.slow
@pytest.mark.parametrize("name", PROFILES)
@pytest.mark.parametrize("s0", SIGMAS)
def test_pull_off_independent(mds, name, s0):
    """The pull-off to 15 digits: the independent load at the reported half-width (a stationary
    minimum: an error delta in a changes P by O(delta^2)), and the package's states at a (1 +- 1e-4)
    higher; an infimum
    P(0+) = -2 sigma_0 c0 with c0 from the Flamant strip and the profile."""
    md = mds[name]
    vals = values(name, s0)
    po = md.pull_off_at(17, **vals)      # the generic layer's minimum (cached on md: reused below)
    _share_force(("pull_off", name, s0, 17), po.force)
    ind = Independent(md, vals)
    law = md.numeric_law(**vals)         # only the starting guesses of the independent roots
    # 22 digits: 7 above the 15 asserted (the independent solve's own error is ~1e-20)
    if po.kind == "infimum":
        with mpmath.workdps(22):
            c0 = ind.zero_width_zone(law.c0(15))
            assert rel(po.force, -2 * ind.sig * c0) < 1e-15
        return
    with mpmath.workdps(22):
        C, P = ind.state(po.half_width, law.c_of(po.half_width, 15)[0])
        assert rel(po.force, P) < 1e-15
    # a minimum: the package's own states a relative 1e-4 on either side lie higher (by ~1e-8
    # relative: 15 digits resolve it)
    for f in ("0.9999", "1.0001"):
        assert md.state(po.half_width * mpmath.mpf(f), 15, **vals).force > po.force


@pytest.mark.slow
def test_model_choice_cli_new_profile(capsys):
    """`linecontact-sym model` on a profile whose gap has no closed form: lambda from the JKR
    pull-off half-width, the choice JKR at large sigma_0 and MD at lambda ~ 1."""
    import json
    from linecontact_sym.cli import main
    args = ["model", "R*(cosh(x/R) - 1)", "--set", "R=1", "E_star=1", "gamma=1/10000"]
    assert main(args + ["sigma_0=1/40", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["model"] == "MD" and 0.8 < float(d["maugis_parameter"]) < 1.25
    assert main(args + ["sigma_0=5", "--rtol", "0.01", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["model"] == "JKR" and float(d["maugis_parameter"]) > 100
    # the two pull-offs the choice compared (15 digits, the command's default), this package's JKR
    # one and the MD one at sigma_0 = 5: test_jkr_limit_new_profiles[cosh] reads them instead of
    # searching for the same minima again (it computes them itself when it runs first)
    with mpmath.workdps(20):
        _share_force(("jkr", "cosh", 15), mpmath.mpf(d["pull_off_jkr"]))
        _share_force(("pull_off", "cosh", "5", 15), mpmath.mpf(d["pull_off_md"]))


@pytest.mark.slow
@pytest.mark.parametrize("name", PROFILES)
def test_jkr_limit_new_profiles(mds, name):
    """sigma_0 -> oo: the MD pull-off tends to this package's JKR pull-off (closer at the larger sigma_0)."""
    md = mds[name]
    base = {k: v for k, v in values(name, "1").items() if k != "sigma_0"}
    # this package's JKR pull-off by its numeric minimum, checked by the independent grid (what
    # pull_off_at returns where the symbolic attempt finds nothing; that attempt, sympy.solve of
    # dP/da = 0 over Bessel and elliptic functions up to the contact's budget, is skipped here)
    jkr = md.jkr
    pj = _shared_force(("jkr", name, 15))     # cosh: the pull-off test_model_choice_cli_new_profile compared
    if pj is None:
        with searching_until(900):
            pj = checked_or_fail(jkr, jkr._numeric_values(base), 15).force
    # sigma_0 = 1/2 at 17 digits: the pull-off test_pull_off_independent found (cached on md)
    # (by whichever xdist worker ran test_pull_off_independent[1/2-name], which asserts it to 1e-15)
    half = _shared_force(("pull_off", name, "1/2", 17))
    if half is None:
        half = md.pull_off_at(17, **values(name, "1/2")).force
    five = _shared_force(("pull_off", name, "5", 15))   # cosh: likewise
    if five is None:
        five = md.pull_off_at(15, **base, sigma_0=5).force
    d = [rel(half, pj), rel(five, pj)]
    assert d[1] < d[0] / 5 and d[1] < 2e-3


@pytest.mark.slow
def test_exact_cylinder_small_a_is_baney_hui(mds, parabola_md):
    """At a small a/R the exact cylinder's normalised pull-off is the parabola's (Baney & Hui at
    lambda = 1); the difference falls like (A/R)^2 as the work of adhesion (hence A) falls.
    (The module's contacts: their conditions are derived and verified once, not per test.)"""
    cyl, par = mds["exact_cylinder"], parabola_md
    diffs = []
    for w in (sp.Rational(1, 10**4), sp.Rational(1, 10**7)):
        lam, A, F = chk.baney_hui_units(sp.Integer(1), w, sp.Integer(1), S.sigma_0)
        s0 = sp.solve(sp.Eq(lam, 1), S.sigma_0)[0]
        v = dict(E_star=1, R=1, gamma=w, sigma_0=s0)
        pc, pp = cyl.pull_off_at(15, **v), par.pull_off_at(15, **v)
        diffs.append((rel(pc.force, pp.force), sp.N(A)))
        # the Maugis parameter of any profile (through its JKR pull-off half-width) tends to B&H's
        lam_c = cyl.maugis_parameter(15, **v)
        assert abs(lam_c - 1) < 20 * float(A)**2
    assert diffs[1][0] < 1e-3
    # O((A/R)^2): a 1000-fold smaller w makes A 10 times smaller and the difference ~100 times
    assert 30 < diffs[0][0] / diffs[1][0] < 300


# ---------------------------------------------------------------- the generic descent (normal/equilibria)
def _synthetic(P, dP, P_zero, lo=mpmath.mpf(10)**-6):
    """A ForceLaw with P(0+) = P_zero and a search range starting at lo (its landscape given)."""
    from linecontact_sym.contacts.normal.equilibria import Landscape
    from linecontact_sym.contacts.normal.force_law import ForceLaw
    law = ForceLaw(P, dP, mode="quad")
    law.P_zero = lambda: mpmath.mpf(P_zero)
    law._landscape = Landscape(lo, mpmath.mpf(10), "search", (), "adaptive", (), True)
    return law


def test_generic_descent_infimum_and_tiny_minimum():
    """The generic minimum follows dP/da down below its search range when P(0+) != 0 (every law
    gets what Maugis-Dugdale needed): P = -1 + a^2 decreases to P(0+) = -1, an infimum at a = 0;
    P = -1 + (a - 1e-13)^2 - 1e-26 has its minimum 1e-26 below P(0+), seven decades below the range."""
    from linecontact_sym.contacts.normal.equilibria import minimum
    po = minimum(_synthetic(lambda a: -1 + a * a, lambda a: 2 * a, -1), 20)
    assert po.kind == "infimum" and po.half_width == 0 and po.force == -1
    t = mpmath.mpf(10)**-13
    law = _synthetic(lambda a: -1 + (a - t)**2 - t * t, lambda a: 2 * (a - t), -1)
    po = minimum(law, 30)
    assert po.kind == "stationary" and abs(po.half_width / t - 1) < 1e-10
    with mpmath.workdps(40):
        assert abs(po.force - (-1 - t * t)) < mpmath.mpf(10)**-38


@pytest.mark.slow
def test_half_width_and_branches_from_the_layer(parabola_md):
    """half_width(P) and branches of the MD contact come from the generic equilibria over its
    ForceLaw; each root is checked by the contact's own state (P(a) = load, the sign of dP/da)."""
    md = parabola_md
    v = dict(E_star=1, R=1, gamma=1, sigma_0=sp.Rational(1, 2))
    po = md.pull_off_at(15, **v)
    Pz = md.numeric_law(**v).force_zero_width(20)        # P(0+): the unstable branch ends there
    assert po.force < Pz < 0
    load = (po.force + Pz) / 2                            # between them: two equilibria
    br = md.branches(load, 20, **v)
    assert [s for _, s in br] == ["stable", "unstable"]
    assert br[1][0] < po.half_width < br[0][0]
    for a, s in br:
        st = md.state(a, 20, **v)
        assert abs(st.force - load) < 1e-18 * abs(load)
        assert (st.dP_da > 0) == (s == "stable")
    assert md.half_width(load, 20, **v) == tuple(a for a, _ in br)
    # above P(0+) only the stable branch (P(a) > P(0+) on the whole unstable branch)
    assert [s for _, s in md.branches(Pz / 2, 20, **v)] == ["stable"]
    with pytest.raises(lcs.core.errors.NoEquilibriumError):
        md.half_width(2 * po.force, 20, **v)
