"""Trust, round 3 (issue 19), items 2, 3, 4, 7 and 9: the user's symbols are
the user's, conditional results give no number where they do not hold,
physical ranges are checked in one place, the cache is data, and the claims
files and the CLI fail clearly.

Every number asserted here is computed independently of the package: mpmath
quadrature of the defining integrals (Eq. 10*: P(a) = E* a int_0^{pi/2}
sin(phi) f'(a sin phi) dphi; Eq. 12 with P'(s) from Eq. 10* differentiated
under the integral sign), mpmath root finding, and closed forms worked out by
hand.  "before:" says what the code did before the fix.
"""
from __future__ import annotations

import hashlib
import json
import os
import time

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings, strategies as st

import linecontact_sym as lcs
from linecontact_sym import cli
from linecontact_sym.core.errors import DomainError
from linecontact_sym.method import store

x = lcs.x


# ------------------------------------------------------------ independent references
def close(value, ref, tol):
    """|value - ref| < tol, decided at 50 digits (mpf results carry 30+)."""
    if isinstance(value, (np.ndarray, np.floating)):
        value = float(value)
    with mpmath.workdps(50):
        return abs(mpmath.mpf(value) - mpmath.mpf(ref)) < tol


def force_ref(fprime, A, E=1, dps=30):
    """Eq. (10*) by quadrature after t = a sin(phi)."""
    with mpmath.workdps(dps + 10):
        A = mpmath.mpf(A)
        return +(E * A * mpmath.quad(lambda ph: mpmath.sin(ph) * fprime(A * mpmath.sin(ph)), [0, mpmath.pi / 2]))


def pressure_ref(fprime, fsecond, A, X, E=1, dps=20):
    """Eq. (12), p(x) = (1/pi) int_x^a P'(s)/sqrt(s^2 - x^2) ds with s = x cosh(u),
    P'(s) = E int_0^{pi/2} [sin(phi) f'(s sin phi) + s sin^2(phi) f''(s sin phi)] dphi
    (f' and f'' analytic on [0, a] for every profile here: Gauss-Legendre, 30x faster than
    tanh-sinh in this inner integral)."""
    with mpmath.workdps(dps + 10):
        A, X = mpmath.mpf(A), mpmath.mpf(X)

        def dP(s):
            return E * mpmath.quad(lambda ph: mpmath.sin(ph) * fprime(s * mpmath.sin(ph))
                                   + s * mpmath.sin(ph)**2 * fsecond(s * mpmath.sin(ph)), [0, mpmath.pi / 2],
                                   method="gauss-legendre")
        return +(mpmath.quad(lambda u: dP(X * mpmath.cosh(u)), [0, mpmath.acosh(A / X)]) / mpmath.pi)


# ================================================================ item 2: the user's symbols
NAMES = ["s", "t", "pi", "E", "I", "lambda_", "lambda", "gamma", "beta", "numpy", "sqrt", "phi", "u", "w"]


@settings(max_examples=6, deadline=None)
@given(name=st.sampled_from(NAMES), shape=st.sampled_from(["parabola", "quartic"]))
def test_item2_a_parameter_of_any_name_is_a_parameter(name, shape):
    """before: a parameter named s turned the parabola's pressure into the
    integral Integral(E_star/(2*sqrt(s**2 - x**2)), (s, x, a)) (the engine's
    integration variable captured it); a parameter named pi made every export
    read pi*a**2/(4*pi) as a**2/4."""
    k = sp.Symbol(name, positive=True)
    prof = x**2 / (2 * k) if shape == "parabola" else x**2 / (2 * k) + x**4
    c = lcs.LineContact(prof, points=2)
    kv = sp.Rational(3, 2)

    def fp(t):
        return t / mpmath.mpf(1.5) + (4 * t**3 if shape == "quartic" else 0)

    def fpp(t):
        return 1 / mpmath.mpf(1.5) + (12 * t**2 if shape == "quartic" else 0)
    d = c.derivation("pressure")
    assert d.closed_form and not d.expr.has(sp.Integral), d.expr
    assert k in d.expr.free_symbols
    P_ref = force_ref(fp, sp.Rational(4, 5))
    p_ref = pressure_ref(fp, fpp, sp.Rational(4, 5), sp.Rational(3, 10))
    vals = {"a": sp.Rational(4, 5), name: kv, "E_star": 1}
    assert close(c.evaluate_at("force", **vals), P_ref, 1e-25 * P_ref)
    assert close(c.evaluate_at("pressure", x=sp.Rational(3, 10), **vals), p_ref, 1e-15 * p_ref)
    fl = {"a": 0.8, name: 1.5, "E_star": 1.0}
    assert close(c.to_numeric("force")(**fl), float(P_ref), 1e-13 * float(P_ref))
    assert close(c.to_numeric("force", backend="mpmath")(**vals), P_ref, 1e-25 * P_ref)
    assert close(float(c.evaluate("force", **fl).value), float(P_ref), 1e-13 * float(P_ref))
    assert close(c.to_numeric("pressure")(x=0.3, **fl), float(p_ref), 1e-12 * float(p_ref))


def test_item2_stick_half_width_in_the_users_own_symbols():
    """before: stick_half_width(F) with a positive F returned the unsolved
    Eq(pi*E_star*c_s**2/(4*R), pi*E_star*a**2/(4*R) - F/mu)."""
    t = lcs.parabola(verify=False).tangential(sp.Symbol("m", positive=True))
    for F in (sp.Symbol("F", positive=True), sp.Symbol("Q", positive=True)):
        d = t.stick_half_width(F)
        assert d.closed_form and not isinstance(d.expr, sp.Eq) and not d.expr.has(sp.Abs), d.expr
        assert d.expr.free_symbols == {F, lcs.a, lcs.R, lcs.E_star, sp.Symbol("m", positive=True)}
        # the root of P(c) = P(a) - F/m with the quadrature force law of f = x^2/(2R), R = 1
        with mpmath.workdps(40):
            P = lambda v: force_ref(lambda s: s, v, dps=40)   # noqa: E731
            target = P(1) - mpmath.mpf("0.1") / mpmath.mpf("0.3")
            c_ref = mpmath.findroot(lambda v: P(v) - target, mpmath.mpf("0.7"))
        got = d.evalf(dps=30, **{F.name: sp.Rational(1, 10), "a": 1, "R": 1, "E_star": 1, "m": sp.Rational(3, 10)})
        assert close(got, c_ref, 1e-25)
    # an assumption-free symbol: the documented assumption (real), said in the notes
    G = sp.Symbol("G")
    d = t.stick_half_width(G)
    assert d.closed_form and d.expr.has(sp.Abs(G)) and any("taken real" in n for n in d.notes)
    with pytest.raises(DomainError, match="already mean"):
        t.stick_half_width(lcs.R)


# ================================================================ item 3: conditional results
CASED = sp.Piecewise((x**2 / (2 * lcs.R), lcs.R < 1), (x**2, True))


@pytest.fixture(scope="module")
def cased():
    return lcs.LineContact(CASED, points=2)


def test_item3_every_case_is_derived_and_every_path_agrees(cased):
    """before: the force was pi*E_star*a**2/2 'holding for R >= 1'; R = 1/4
    was refused by evaluate_at and given pi/2 by Derivation.evalf and
    to_numeric(check=False).  At R = 1/4 the profile is 2 x^2: P(1) = pi."""
    ref = force_ref(lambda t: 4 * t, 1)                 # f' = 4 t where R = 1/4
    ref_hi = force_ref(lambda t: 2 * t, 1)              # f' = 2 t where R >= 1
    with mpmath.workdps(50):
        assert abs(ref - mpmath.pi) < 1e-25 and abs(ref_hi - mpmath.pi / 2) < 1e-25
    d = cased.derivation("force")
    assert d.closed_form and isinstance(d.expr, sp.Piecewise)
    q = sp.Rational(1, 4)
    near = force_ref(lambda t: t / mpmath.mpf("0.999"), 1)   # R = 0.999 < 1: f' = t/R
    for R, want in ((q, ref), (2, ref_hi), (1, ref_hi), (sp.Rational(999, 1000), near)):
        assert close(cased.evaluate_at("force", a=1, R=R, E_star=1), want, 1e-25)
        assert close(d.evalf(a=1, R=R, E_star=1), want, 1e-25)
        for check in (True, False):
            assert close(cased.to_numeric("force", check=check)(a=1.0, R=float(R), E_star=1.0), float(want), 1e-13)
            assert close(cased.to_numeric("force", "mpmath", check=check)(a=1, R=R, E_star=1), want, 1e-25)
        assert close(float(cased.evaluate("force", a=1, R=float(R), E_star=1).value), float(want), 1e-13)
    # the inverse at R = 1/4: P = pi -> a = 1
    assert close(cased.half_width(sp.pi, R=q, E_star=1), 1, 1e-25)
    # the pressure at R = 1/4 against Eq. (12) of the 2 x^2 profile
    p_ref = pressure_ref(lambda t: 4 * t, lambda t: 4, 1, sp.Rational(1, 2))
    assert close(cased.evaluate_at("pressure", a=1, x=sp.Rational(1, 2), R=q, E_star=1), p_ref, 1e-15)


def test_item3_other_kinds_see_the_right_case(cased):
    q = sp.Rational(1, 4)
    # tangential: Q = mu (P(a) - P(c)), P of the 2 x^2 profile = pi a^2 E*
    t = cased.tangential()
    st_ = t.state(sp.Rational(1, 2), a=1, R=q, E_star=1, mu=sp.Rational(1, 2))
    with mpmath.workdps(30):
        c_ref = mpmath.findroot(lambda v: force_ref(lambda s: 4 * s, v) - (mpmath.pi - 1), mpmath.mpf("0.8"))
    assert close(st_.c, c_ref, 1e-20)
    # pull-off (JKR, Eq. 31 of the 2 x^2 profile at R = 1/4): P(a) = pi a^2 - sqrt(2 pi gamma a), gamma = 1/10
    po = cased.adhesive(sp.Rational(1, 10)).pull_off_at(R=q, E_star=1)
    with mpmath.workdps(40):
        P = lambda v: force_ref(lambda s: 4 * s, v, dps=40) - mpmath.sqrt(2 * mpmath.pi * v / 10)   # noqa: E731
        # by hand: P0 = pi a^2 (Eq. 10* of 2 x^2), dP/da = 0 at a^(3/2) = sqrt(2 pi gamma)/(4 pi)
        a_ref = (mpmath.sqrt(2 * mpmath.pi / 10) / (4 * mpmath.pi))**(mpmath.mpf(2) / 3)
        assert close(po.force, P(a_ref), 1e-25) and close(po.half_width, a_ref, 1e-20)
    # stresses: sigma_z on the surface is -p(x)
    sf = cased.stresses()
    p_ref = pressure_ref(lambda s: 4 * s, lambda s: 4, 1, sp.Rational(1, 2))
    assert close(sf.evaluate_at("sigma_z", dps=20, a=1, x=sp.Rational(1, 2), z=0, R=q, E_star=1), -p_ref, 1e-12)


def test_item3_a_condition_that_fails_gives_no_number():
    """The exact cylinder holds for a < R: evalf refuses, the exports give NaN
    (check=False), and the contacts built on it refuse at once.  before:
    Derivation.evalf 'the quantity is complex', mpmath export a complex
    number, tangential state raised core.roots.Outside, the stress field a
    ValueError after 27 s."""
    c = lcs.exact_cylinder(verify=False)
    d = c.derivation("force")
    with pytest.raises(DomainError, match="a < R|a <= R"):
        d.evalf(a=2, R=1, E_star=1)
    assert np.isnan(c.to_numeric("force", check=False)(a=2.0, R=1.0, E_star=1.0))
    v = c.to_numeric("force", check=False)(a=np.array([0.5, 2.0]), R=1.0, E_star=1.0)
    assert np.isnan(v[1]) and np.isfinite(v[0])
    assert mpmath.isnan(c.to_numeric("force", "mpmath", check=False)(a=2, R=1, E_star=1))
    t0 = time.perf_counter()
    with pytest.raises(DomainError, match="a < R|a <= R"):
        c.tangential().state(sp.Rational(1, 10), a=2, R=1, E_star=1, mu=sp.Rational(3, 10))
    with pytest.raises(DomainError, match="a < R|a <= R"):
        c.stresses().evaluate_at("sigma_x", a=2, x=sp.Rational(1, 10), z=sp.Rational(1, 5), R=1, E_star=1)
    with pytest.raises(DomainError, match="a < R|a <= R"):
        c.stresses().maximum("von_mises", a=2, R=1, E_star=1, nu=0.3)
    assert time.perf_counter() - t0 < 10


# ================================================================ item 4: physical ranges
def test_item4_physical_ranges_in_one_place():
    c = lcs.parabola(verify=False)
    H = dict(a=1, R=1, E_star=1)
    sf = c.stresses()
    # nu = 0 and nu = 1/2 are valid: sigma_y = nu (sigma_x + sigma_z) = -2 nu p(x) on the surface,
    # p(x) = E* sqrt(a^2 - x^2)/(2R): at x = 1/10, -nu sqrt(0.99)
    for nu in (0, sp.Rational(1, 2), -sp.Rational(1, 2)):
        got = sf.evaluate_at("sigma_y", dps=20, x=sp.Rational(1, 10), z=0, nu=nu, **H)
        with mpmath.workdps(30):
            assert close(got, -mpmath.mpf(nu) * mpmath.sqrt(mpmath.mpf("0.99")), 1e-15), (nu, got)
        c.stresses(nu=nu)
    for bad in (0.7, -1, 1, sp.Rational(1, 2) + sp.Rational(1, 10**30)):
        with pytest.raises(DomainError, match="Poisson"):
            c.stresses(nu=bad)
        with pytest.raises(DomainError, match="Poisson"):
            sf.evaluate_at("sigma_y", x=0.1, z=0.3, nu=bad, **H)
    t = c.tangential()
    for bad in (0, -0.3):
        with pytest.raises(DomainError, match="positive"):
            c.tangential(bad)
        with pytest.raises(DomainError, match="positive"):
            t.evaluate_at("tangential_force", a=1, c_s=0.5, mu=bad, R=1, E_star=1)
        with pytest.raises(DomainError, match="positive"):
            t.state(0.1, mu=bad, **H)
    with pytest.raises(DomainError, match="stick half-width"):
        t.evaluate_at("tangential_force", a=1, c_s=1.5, mu=0.3, R=1, E_star=1)
    with pytest.raises(DomainError, match="reversal stick"):
        t.evaluate_at("unloading_force", a=1, c_s=0.5, c_r=0.3, mu=0.3, R=1, E_star=1)
    for bad in (1, 0, 2.5, True):
        with pytest.raises(DomainError, match="points >= 2"):
            t.cycle(0.1, points=bad, mu=0.3, **H)
    with pytest.raises(DomainError, match="stick half-width"):
        c.stresses("partial_slip", stick=2, mu=0.3).field(**H)
    # the edges of the strict conditions c_s < c_r < a are limits, accepted: Q_u = Q(c_s) - 2 Q(c_r) is
    # Q at the turning point (c_r = a) and -Q at the full reversal (c_r = c_s)
    kw = dict(a=1, c_s=sp.Rational(1, 2), mu=sp.Rational(3, 10), R=1, E_star=1)
    Q = t.evaluate_at("tangential_force", **kw)
    with mpmath.workdps(40):
        assert close(Q, mpmath.mpf(3) / 10 * mpmath.pi / 4 * (1 - mpmath.mpf(1) / 4), 1e-25)   # mu (P(a) - P(c_s))
    assert close(t.evaluate_at("unloading_force", c_r=1, **kw), Q, 1e-25)
    with mpmath.workdps(40):
        assert close(t.evaluate_at("unloading_force", c_r=sp.Rational(1, 2), **kw), -Q, 1e-25)
    # z = 0 is the surface: sigma_z = -p(x) = -E* sqrt(a^2 - x^2)/(2R)
    got = sf.evaluate_at("sigma_z", x=sp.Rational(1, 10), z=0, **H)
    with mpmath.workdps(40):
        assert close(got, -mpmath.sqrt(mpmath.mpf("0.99")) / 2, 1e-25)
    with pytest.raises(DomainError):
        sf.evaluate_at("sigma_z", x=0.1, z=-0.1, **H)


# ================================================================ item 7: the cache is data
def _write_record(path, key, payload: bytes):
    data = store._MAGIC + hashlib.sha256(payload).hexdigest().encode() + b"\n" + payload
    path.parent.mkdir(parents=True, exist_ok=True, mode=0o700)
    path.write_bytes(data)
    os.chmod(path, 0o600)


def test_item7_records_are_data_never_code(tmp_path, monkeypatch):
    monkeypatch.setenv(store.CACHE_ENV, str(tmp_path))
    os.chmod(tmp_path, 0o700)
    store.clear_memory()
    key = store.make_key("test", x**2)
    canary = tmp_path / "pwned"
    for evil in (f"__import__('os').system('touch {canary}')",
                 f"Symbol('x').__class__.__init__.__globals__['os'].system('touch {canary}')",
                 "eval('1')", "exec('1')", "Symbol(lambda: 1)", "[].__class__"):
        payload = json.dumps({"dict": [["value", {"sympy": evil}], ["key", key],
                                       ["version", store.code_version()]]}).encode()
        _write_record(tmp_path / key[:2] / f"{key}.json", key, payload)
        store.clear_memory()
        assert store.get(key) is None, evil
    assert not canary.exists()
    with pytest.raises(store.UntrustedRecord):
        store.from_srepr("__import__('os').getcwd()")
    # a real record round-trips exactly, Dummies of the engine included
    from linecontact_sym.method import transforms as T
    e = sp.Integral(sp.sqrt(T.s**2 - x**2) / lcs.R, (T.s, x, lcs.a)) + sp.pi * sp.Float("1.25", 40)
    store.put(key, {"expr": e, "note": ("a", 1, 2.5, None)})
    store.clear_memory()
    rec = store.get(key)
    assert rec["source"] == "disk" and rec["expr"] == e and rec["note"] == ("a", 1, 2.5, None)
    assert not list(tmp_path.rglob("*.pickle"))


def test_item7_a_cache_others_can_write_is_not_used(tmp_path, monkeypatch):
    shared = tmp_path / "shared"
    shared.mkdir()
    os.chmod(shared, 0o777)
    monkeypatch.setenv(store.CACHE_ENV, str(shared))
    store.clear_memory()
    key = store.make_key("test-shared", x**3)
    with pytest.warns(store.UntrustedCacheWarning, match="writable by group or others"):
        store.put(key, {"value": 1})
    assert not list(shared.rglob("*.json"))
    # a planted file in a world-writable directory is never read
    os.chmod(shared, 0o700)
    store.put(key, {"value": 2})
    os.chmod(shared, 0o777)
    store.clear_memory()
    assert store.get(key) is None
    if hasattr(os, "getuid") and os.getuid() == 0:     # as root: a directory owned by someone else
        own = tmp_path / "foreign"
        own.mkdir(mode=0o700)
        os.chown(own, 4321, 4321)
        monkeypatch.setenv(store.CACHE_ENV, str(own))
        store.clear_memory()
        with pytest.warns(store.UntrustedCacheWarning, match="owned by uid 4321"):
            store.put(store.make_key("test-foreign", x), {"value": 3})
        assert not list(own.rglob("*.json"))


def test_item7_the_key_covers_every_source_file(monkeypatch):
    """before: the hash globbed method/*.py and core/*.py only: an edit of a
    contact, a sampler or a reference served stale results."""
    from pathlib import Path
    read = []
    orig = Path.read_bytes

    def spy(self):
        read.append(self.as_posix())
        return orig(self)
    monkeypatch.setattr(Path, "read_bytes", spy)
    monkeypatch.setitem(store._state, "version", None)
    store.code_version()
    for f in ("contacts/normal/contact.py", "contacts/sampling.py", "contacts/tangential/states.py",
              "numeric/exports.py", "parsing/expressions.py", "method/transforms.py"):
        assert any(r.endswith("linecontact_sym/" + f) for r in read), f
    monkeypatch.setitem(store._state, "version", None)


# ================================================================ item 9: claims and CLI edges
def test_item9_printed_digits_of_a_toml_float(tmp_path):
    """before: formula = -0.08090 was read as the float -0.0809 (four
    digits): its interval was ten times too wide."""
    from linecontact_sym.claims.spec import load_paper, printed_spread, printed_variants
    f = tmp_path / "t.toml"
    f.write_text('key = "t"\ntitle = "t"\n[[claims]]\nlabel = "c2"\nquantity = "force"\nprofile = "x**2/(2*R)"\n'
                 'formula = -0.08090\nrounding = "printed"\nranges = { a = [0.5, 1.5] }\n')
    paper = load_paper(str(f))
    form = paper.claims[0].forms[-1]
    assert form.text == "-0.08090"
    ends = sorted(float(v) for v in form.variants)
    assert ends == [-0.080905, -0.080895]
    # every constant is varied, not the first six
    text = "+".join(f"0.{k}1*x**{k}" for k in range(1, 9))
    vs = printed_variants(text)
    assert printed_spread(text) == "sum" and len(vs) == 17
    for k in range(1, 9):
        assert any(f"0.{k}05*x**{k}" in v for v in vs) and any(f"0.{k}15*x**{k}" in v for v in vs)


def test_item9_cli_edges_are_input_errors(tmp_path, capsys):
    afile = tmp_path / "a-file"
    afile.write_text("x")
    t0 = time.perf_counter()
    assert cli.main(["paper", "popov2017", "--out", str(afile), "--quiet"]) == cli.EXIT_INPUT
    assert cli.main(["paper", "popov2017", "--out", str(afile / "sub"), "--quiet"]) == cli.EXIT_INPUT
    assert time.perf_counter() - t0 < 20          # refused before any claim is checked
    assert "is a file" in capsys.readouterr().err
    for n in ("1e400", "1e-400", "2,1e400", "-1", "0", "oo", "nan", "I"):
        assert cli.main(["table", "power-law", f"--n={n}"]) == cli.EXIT_INPUT, n
    # an irrational exponent is an exponent: Z_n = n int_0^{pi/2} sin^n(phi) dphi (Eq. 10* of c x^n)
    capsys.readouterr()
    assert cli.main(["table", "power-law", "--n=sqrt(2)", "--json"]) == 0
    row = json.loads(capsys.readouterr().out)["rows"][0]
    n = mpmath.sqrt(2)
    assert close(row["Z_n_float"], float(n * mpmath.quad(lambda p: mpmath.sin(p)**n, [0, mpmath.pi / 2])), 1e-14)
