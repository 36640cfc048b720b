"""Issue 29 (trust, round 4): each class of the hostile pass, with a test that
fails without its fix.  Numbers are checked against independent values
(Eq. (13) P = pi E* a^2/(4R), mpmath quadratures of the defining integrals)."""
from __future__ import annotations

import hashlib
import json
import math
import os
import subprocess
import sys
import time
import warnings

import mpmath
import numpy as np
import pytest
import sympy as sp

import linecontact_sym as lcs
from store_records import rewrite_derivations
from linecontact_sym.core.errors import DomainError, LineContactError
from linecontact_sym.method import store

x = lcs.x
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


# ------------------------------------------------------------------ helpers: a cache of the test's own
@pytest.fixture
def cache(tmp_path, monkeypatch):
    d = tmp_path / "cache"
    d.mkdir(mode=0o700)
    monkeypatch.setenv(store.CACHE_ENV, str(d))
    store.clear_memory()
    yield d
    store.clear_memory()


def _rewrite(d, field, fn):
    """Every record under ``d`` whose ``field`` is a SymPy text: the text
    replaced by fn(text), the checksum recomputed (an attacker who knows the
    format).  Returns the number of records changed."""
    n = 0
    for p in d.rglob("*.json"):
        raw = p.read_bytes()
        data = json.loads(raw[len(store._MAGIC) + 65:].decode())
        hit = False
        for pair in data.get("dict", []):
            if pair[0] == field and isinstance(pair[1], dict) and "sympy" in pair[1]:
                pair[1] = {"sympy": fn(pair[1]["sympy"])}
                hit = True
        if hit:
            payload = json.dumps(data, separators=(",", ":")).encode()
            p.write_bytes(store._MAGIC + hashlib.sha256(payload).hexdigest().encode() + b"\n" + payload)
            n += 1
    return n


HERTZ = dict(a=sp.Rational(7, 8), R=sp.Rational(1, 2), E_star=1)
HERTZ_P = sp.pi * sp.Rational(7, 8)**2 / (4 * sp.Rational(1, 2))     # Eq. (13): pi E* a^2/(4R)


def _near(v, ref=HERTZ_P, digits=24):
    with mpmath.workdps(40):
        return abs(mpmath.mpf(v) - mpmath.mpf(sp.N(ref, 40))) < mpmath.mpf(10)**-digits


def _force_again():
    store.clear_memory()           # a new process: the record comes from disk
    return lcs.parabola(verify=False).evaluate_at("force", dps=25, **HERTZ)


# ------------------------------------------------------------------ 1: the cache is never code
def _code(canary):
    return f"__import__('os').system('touch {canary}')"


EVIL = [
    lambda c: f"Tuple({_code(c)!r})",
    lambda c: f"sin({_code(c)!r})",
    lambda c: f"Integral({_code(c)!r}, Symbol('x'))",
    lambda c: f"Add({_code(c)!r}, Integer(1))",
    lambda c: f"Symbol('x', positive={_code(c)!r})",
    lambda c: f"Float({_code(c)!r}, precision=53)",
    lambda c: f"Integer({_code(c)!r})",
    lambda c: f"Dummy('t', dummy_index={_code(c)!r})",
    lambda c: f"sin(Symbol('x'), **{{'evaluate': {_code(c)!r}}})",
    lambda c: f"Function('f')(Symbol({_code(c)!r}))",
    lambda c: f"Lambda(Symbol('x'), {_code(c)!r})",
]
HUGE = ["Pow(Integer(10), Integer(1000000000))", "factorial(Integer(10000000))",
        "Pow(Rational(3, 2), Integer(100000000))", "Pow(Integer(2), Pow(Integer(2), Integer(40)))",
        "Pow(Pow(Integer(2), Rational(1, 2)), Integer(1000000000))",
        "binomial(Integer(10000000000), Integer(5000000000))", "gamma(Integer(100000000))",
        "Float('1.5', precision=1000000000)", "Integer(" + "9" * 5000 + ")", "Pow(Integer(7), Rational(1, 10**9))"]


@pytest.mark.parametrize("make", EVIL)
def test_item1_string_arguments_never_reach_sympify(make, tmp_path):
    canary = tmp_path / "pwned"
    with pytest.raises(store.UntrustedRecord):
        store.from_srepr(make(canary))
    assert not canary.exists()


@pytest.mark.parametrize("text", HUGE)
def test_item1_huge_literals_refused_before_anything_is_built(text):
    t0 = time.perf_counter()
    with pytest.raises(store.UntrustedRecord):
        store.from_srepr(text)
    assert time.perf_counter() - t0 < 1.0


def test_item1_the_data_a_derivation_writes_still_reads_back():
    R, a = lcs.R, lcs.a
    for e in (sp.Piecewise((sp.atanh(x * sp.sqrt(a**2 - 1)), x < a), (0, True)), sp.Float("1.2345678901234567890123", 40),
              sp.elliptic_k(x**2 / a**2), sp.Integral(sp.sqrt(1 - x**2), (x, 0, a)), sp.gamma(sp.Rational(7, 3)),
              sp.hyper([1, 2], [3], x), sp.Interval(0, 1, True), sp.Eq(a, 2**200), -sp.pi * R**sp.Rational(-3, 2),
              sp.oo, sp.zoo, sp.Float("-1e-30"), sp.Tuple(sp.true, sp.false), sp.Abs(x - 1), sp.Max(x, 1),
              sp.factorial(sp.Integer(20)), sp.Integer(-5), sp.Rational(-3, 7)):
        assert store.from_srepr(sp.srepr(e)) == e


@pytest.mark.slow
def test_item1_planted_records_are_ignored_and_recomputed(cache):
    lcs.parabola(verify=False).derivation("force")
    canary = cache / "pwned"
    original = {}
    _rewrite(cache, "expr", lambda old: original.setdefault("expr", old))
    for text in [make(canary) for make in EVIL[:3]] + HUGE[:2]:
        assert _rewrite(cache, "expr", lambda old: text) == 1
        t0 = time.perf_counter()
        with pytest.warns(store.UntrustedCacheWarning, match="not plain data"):
            v = _force_again()
        assert time.perf_counter() - t0 < 20
        assert _near(v)
        assert not canary.exists()


@pytest.mark.slow
def test_item1_the_cli_never_runs_a_planted_record(cache):
    canary = cache / "pwned"
    env = dict(os.environ, LINECONTACT_SYM_CACHE=str(cache), PYTHONPATH=ROOT)
    cmd = [sys.executable, "-m", "linecontact_sym", "eval", "x**2/(2*R)", "force", "--at", "a=0.875",
           "--set", "R=0.5", "E_star=1", "--dps", "15"]
    subprocess.run(cmd, env=env, capture_output=True, timeout=300, check=True)
    assert _rewrite(cache, "expr", lambda old: f"Tuple({_code(canary)!r})") >= 1
    r = subprocess.run(cmd, env=env, capture_output=True, timeout=300, text=True)
    assert r.returncode == 0 and not canary.exists()
    assert f"{float(HERTZ_P):.12f}"[:12] in r.stdout


# ------------------------------------------------------------------ 2: a tampered record is not trusted
@pytest.mark.slow
@pytest.mark.parametrize("tamper", [
    lambda old: f"Mul(Integer(-1), {old})",                              # the sign flipped
    lambda old: "Mul(Rational(1, 2), pi, Symbol('E_star', positive=True), "   # another profile's result
                "Pow(Symbol('a', positive=True), Integer(3)), Pow(Symbol('R', positive=True), Integer(-1)))",
    lambda old: f"Mul(Rational(1001, 1000), {old})",                     # a small change
])
def test_item2_a_tampered_record_is_rechecked_and_recomputed(cache, tamper):
    lcs.parabola(verify=False).derivation("force")
    assert _rewrite(cache, "expr", tamper) == 1
    with pytest.warns(store.UntrustedCacheWarning, match="disagrees with the independent reference"):
        v = _force_again()
    assert _near(v)
    # the record was replaced by the fresh derivation: a later process reads it without a warning
    with warnings.catch_warnings():
        warnings.simplefilter("error", store.UntrustedCacheWarning)
        assert _near(_force_again())


@pytest.mark.slow
def test_item2_a_record_of_unexpected_shape_is_ignored(cache):
    """A record of the right key and checksum whose derivations are missing
    (an IndexError before): ignored with a warning, derived afresh."""
    lcs.parabola(verify=False).derivation("half_width")
    n = 0
    for p in cache.rglob("*.json"):
        data = json.loads(p.read_bytes()[len(store._MAGIC) + 65:].decode())
        for pair in data.get("dict", []):
            if pair[0] == "derivations":
                pair[1] = {"tuple": []}
                payload = json.dumps(data, separators=(",", ":")).encode()
                p.write_bytes(store._MAGIC + hashlib.sha256(payload).hexdigest().encode() + b"\n" + payload)
                n += 1
    assert n >= 1
    store.clear_memory()
    with pytest.warns(store.UntrustedCacheWarning, match="not a record"):
        e = lcs.parabola(verify=False).derivation("half_width").expr
    assert sp.simplify(e - 2 * sp.sqrt(lcs.P * lcs.R / (sp.pi * lcs.E_star))) == 0


# ------------------------------------------------------------------ 3: negative x (issue item 5)
WORN = dict(a=0.8, b=0.5, R=1.0, E_star=1.0)


@pytest.fixture(scope="module")
def worn():
    return lcs.worn_cylinder(verify=False)


@pytest.fixture(scope="module")
def par():
    return lcs.parabola(verify=False)


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
def test_item3_worn_cylinder_pressure_at_negative_x(worn):
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
def test_item3_every_x_export_on_both_signs(worn, par):
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


# ------------------------------------------------------------------ 4: one reader of numeric settings (issue item 6)
def test_item4_one_reader_for_budgets_jobs_tolerances():
    from linecontact_sym.core.budget import checked_budget
    from linecontact_sym.core.errors import BudgetError
    from linecontact_sym.core.parallel import capped_jobs, jobs_count
    from linecontact_sym.core.ranges import check_tolerance
    assert checked_budget(" 2.5 ", text=True) == 2.5 and checked_budget(np.float32(4)) == 4.0
    assert checked_budget("inf", text=True) is None
    assert checked_budget(10**400) is None    # larger than any float: no limit
    for bad in ("abc", "nan", 0, -1, True, 1j, "1e-400x"):
        with pytest.raises(BudgetError):
            checked_budget(bad)
    assert jobs_count(" 3 ") == 3 and jobs_count(np.int64(2)) == 2 and jobs_count(2.0) == 2
    for bad in ("abc", 0, 2.5, "inf", None, True):
        with pytest.raises(DomainError):
            jobs_count(bad)
    assert capped_jobs(1000, 20) == 20 and capped_jobs(4, 0) == 1
    assert check_tolerance("0.05") == 0.05
    for bad in (-0.1, float("nan"), 0, "abc", 2):
        with pytest.raises(DomainError):
            check_tolerance(bad)


def test_item4_an_executor_given_as_text_is_refused():
    from linecontact_sym.core.parallel import map_ordered
    with pytest.raises(DomainError, match="executor"):
        map_ordered(abs, [1, -2], executor="processes")


def _cli(args, **env):
    return subprocess.run([sys.executable, "-m", "linecontact_sym"] + args, capture_output=True, text=True,
                          timeout=300, env={**os.environ, "PYTHONPATH": ROOT, **env})


@pytest.mark.slow
def test_item4_budget_environment_on_the_cli():
    args = ["eval", "x**2/(2*R)", "force", "--at", "a=1", "--set", "R=1", "E_star=1", "--dps", "12"]
    r = _cli(args, LINECONTACT_SYM_BUDGET="abc")
    assert r.returncode == 2 and "LINECONTACT_SYM_BUDGET" in r.stderr and "Traceback" not in r.stderr
    r = _cli(args, LINECONTACT_SYM_BUDGET="inf")        # the README's "no limit"
    assert r.returncode == 0 and "0.785398163397" in r.stdout
    r = _cli(["paper", "popov2017", "--jobs", "abc"])
    assert r.returncode == 2 and "--jobs" in r.stderr and "Traceback" not in r.stderr


@pytest.mark.slow
def test_item4_paper_jobs_are_capped_at_the_work(monkeypatch, tmp_path):
    from linecontact_sym import cli
    from linecontact_sym.claims import batch
    seen = []
    real = batch.process_pool
    monkeypatch.setattr(batch, "process_pool", lambda jobs=None: seen.append(jobs) or real(jobs))
    code = cli.main(["paper", "popov2017", "--jobs", "1000", "--only", "Eq. (13)", "--no-figures", "--quiet",
                     "--out", str(tmp_path)])
    assert code == 0 and all(j <= 2 for j in seen)


# ------------------------------------------------------------------ 5: units never dropped (issue item 3)
pint = pytest.importorskip("pint")
ureg = pint.get_application_registry()      # one registry per process: pint builds it once (about 0.7 CPU s)
Q_ = ureg.Quantity
U_REF = math.pi * 210e9 * 1e-3**2 / (4 * 5e-3)       # Eq. (13) in SI: 32986722.86 N/m


@pytest.mark.slow
def test_item5_exports_take_units_checked_or_not(par):
    vals = dict(a=Q_(1, "mm"), R=Q_(5, "mm"), E_star=Q_(210, "GPa"))
    for check in (True, False):
        v = par.to_numeric("force", check=check)(**vals)
        assert v.to("N/m").magnitude == pytest.approx(U_REF, rel=1e-12)     # 32.99 before: mm read as numbers
        with pytest.raises(DomainError, match="dimension"):
            par.to_numeric("force", check=check)(**{**vals, "R": Q_(5, "s")})
    v = par.to_numeric("force", "mpmath", R=Q_(5, "mm"))(a=Q_(1, "mm"), E_star=Q_(210, "GPa"))
    assert float(v.to("N/m").magnitude) == pytest.approx(U_REF, rel=1e-14)
    assert par.to_numeric("force")(a=1e-3, R=5e-3, E_star=210e9) == pytest.approx(U_REF, rel=1e-12)   # plain: SI


def test_item5_half_width_takes_units(par):
    a = par.half_width(Q_(U_REF, "N/m"), R=Q_(5, "mm"), E_star=Q_(210, "GPa"))
    assert float(a.to("mm").magnitude) == pytest.approx(1.0, rel=1e-12)


def test_item5_record_results_refuse_units_naming_them(par):
    with pytest.raises(DomainError, match="pint quantity"):
        par.tangential().state(Q_(0.1, "N/m"), E_star=1, R=1, mu=0.4, a=0.8)
    with pytest.raises(DomainError, match="pint quantity"):
        par.maugis_dugdale().pull_off_at(15, E_star=Q_(1, "Pa"), R=1, gamma=0.01, sigma_0=1)


# ------------------------------------------------------------------ 6: Maugis-Dugdale inputs (issue item 4)
MDV = dict(E_star=1, R=1, gamma=sp.Rational(1, 100))


@pytest.mark.parametrize("sigma0", [sp.oo, 1 + 2j, sp.Symbol("q") + 1, sp.nan, -1, 0])
def test_item6_md_sigma0_refused_at_the_entry(par, sigma0):
    with pytest.raises(DomainError, match="sigma_0"):
        par.maugis_dugdale().pull_off_at(15, sigma_0=sigma0, **MDV)


@pytest.mark.parametrize("rtol", [-0.1, float("nan"), "abc", 0])
def test_item6_model_choice_refuses_a_bad_tolerance(par, rtol):
    t0 = time.perf_counter()
    with pytest.raises(DomainError, match="tolerance"):
        par.maugis_dugdale().model_choice(rtol, sigma_0=1, **MDV)
    assert time.perf_counter() - t0 < 1            # refused before any pull-off is searched


@pytest.mark.slow
def test_item6_md_force_export_refused_clearly(par):
    with pytest.raises(LineContactError, match="not one expression"):
        par.maugis_dugdale().to_numeric("force")


@pytest.mark.slow
def test_item6_md_numbers(par):
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


# ------------------------------------------------------------------ 7: carried over
def test_item7_cli_eval_bad_value_on_stderr():
    import contextlib
    import io
    from linecontact_sym import cli
    err = io.StringIO()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        code = cli.main(["eval", "x**2/(2*R)", "force", "--at", "a=-1", "--set", "R=1", "E_star=1"])
    assert code == 2 and "a = -1" in err.getvalue() and "positive" in err.getvalue()


@pytest.mark.slow
def test_item7_partial_slip_stick_beyond_a_refused(par):
    c = sp.Symbol("c", positive=True)
    for sf, extra in ((par.stresses("partial_slip", stick=c, mu=0.3), {"c": sp.Rational(3, 2)}),
                      (par.stresses("partial_slip", stick=sp.Rational(3, 2), mu=0.3), {})):
        with pytest.raises(DomainError, match="stick half-width"):
            sf.evaluate_at("sigma_x", x=sp.Rational(1, 10), z=sp.Rational(1, 5), a=1, R=1, E_star=1, **extra)


@pytest.mark.slow
def test_item7_cos_bump_pull_off_gives_the_reason():
    """The cos bump's JKR pull-off at gamma = 1: its minimum lies at the end of
    the admissible range, where the two methods place that end differently (a
    VerificationError before): a NoPullOffError stating why there is none."""
    from linecontact_sym.core.errors import NoPullOffError
    A, L = sp.Symbol("A", positive=True), sp.Symbol("L", positive=True)
    c = lcs.LineContact(A * (1 - sp.cos(sp.pi * x / L)), verify=False)
    with pytest.raises(NoPullOffError, match="no minimum inside the admissible range"):
        c.adhesive().pull_off_at(15, A=sp.Rational(1, 10), L=1, E_star=1, gamma=1)


@pytest.mark.slow
def test_item5_cli_set_with_units():
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


@pytest.mark.slow
def test_item2_a_tampered_half_width_record_is_rechecked(cache):
    """Records made outside derive() (the half-width a(P)) are re-checked too:
    a(P(a)) = a at a random admissible point."""
    lcs.parabola(verify=False).derivation("half_width")
    assert rewrite_derivations(cache, lambda old: f"Mul(Integer(2), {old})") == 1
    store.clear_memory()
    with pytest.warns(store.UntrustedCacheWarning, match="independent check"):
        e = lcs.parabola(verify=False).derivation("half_width").expr
    assert sp.simplify(e - 2 * sp.sqrt(lcs.P * lcs.R / (sp.pi * lcs.E_star))) == 0
