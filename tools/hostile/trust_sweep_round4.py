"""Hostile sweep of issue 29 (trust, round 4): the classes of the issue, each
tried as a user who read the README would.  A case passes when the package
gives the independently known number, or a clear package error (a
``LineContactError`` subclass; on the command line exit 2 with a message on
stderr and no traceback), within the timeout; a wrong number, a foreign
exception, a hang, or code run from a cache file fails it.

    python tools/hostile/trust_sweep_round4.py [--json out.json] [--only 1,2]
    PYTHONPATH=/path/to/other/checkout python tools/hostile/trust_sweep_round4.py

Every case works in a temporary cache directory of its own (nothing in the
user's cache is read or written).
"""
from __future__ import annotations

import contextlib
import hashlib
import io
import json
import math
import os
import subprocess
import sys
import tempfile
import time
import warnings

import mpmath
import numpy as np
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core.errors import LineContactError
from harness import close, fresh_cache as _fresh_cache, is_refused as refused, isolated_main  # tools/hostile/, beside this file


def fresh_cache():
    return _fresh_cache("lcs-sweep4-")


CASES: list = []
x = lcs.x


def case(group, name=None):
    def deco(fn):
        CASES.append((group, name or fn.__name__, fn))
        return fn
    return deco


def number_or_refused(fn, ref, tol=1e-10):
    try:
        v = fn()
    except LineContactError:
        return True
    if hasattr(v, "magnitude"):
        v = v.magnitude
    return close(v, ref, tol)


# ------------------------------------------------------------------ a fresh cache directory per case
def rewrite_records(d, change):
    """Every record file under ``d``: its JSON payload passed through
    ``change(data) -> data`` and the checksum recomputed (an attacker who
    knows the format)."""
    from linecontact_sym.method import store
    n = 0
    for root, _, files in os.walk(d):
        for f in files:
            if not f.endswith(".json"):
                continue
            p = os.path.join(root, f)
            raw = open(p, "rb").read()
            body = raw[len(store._MAGIC):]
            data = json.loads(body[65:].decode())
            new = change(data)
            if new is None:
                continue
            payload = json.dumps(new, separators=(",", ":")).encode()
            with open(p, "wb") as fh:
                fh.write(store._MAGIC + hashlib.sha256(payload).hexdigest().encode() + b"\n" + payload)
            n += 1
    return n


def set_field(data, field, fn):
    """In a record {"dict": [[k, v], ...]} replace the value of ``field``
    (a {"sympy": text}) by fn(text)."""
    if not (isinstance(data, dict) and "dict" in data):
        return None
    hit = False
    for pair in data["dict"]:
        if pair[0] == field and isinstance(pair[1], dict) and "sympy" in pair[1]:
            pair[1] = {"sympy": fn(pair[1]["sympy"])}
            hit = True
    return data if hit else None


P_PARABOLA = sp.pi * lcs.E_star * lcs.a**2 / (4 * lcs.R)
PAR_VALUES = dict(a=sp.Rational(7, 8), R=sp.Rational(1, 2), E_star=1)
PAR_REF = float(P_PARABOLA.subs({lcs.a: sp.Rational(7, 8), lcs.R: sp.Rational(1, 2), lcs.E_star: 1}))


def planted_force(text_of):
    """Derive the parabola's force (cache on), plant text_of(canary, old srepr)
    as its expression, read it again in a new 'process' (memory cleared):
    (the value the package gives, the canary path)."""
    from linecontact_sym.method import store
    d = fresh_cache()
    canary = os.path.join(d, "pwned")
    lcs.parabola(verify=False).derivation("force")
    n = rewrite_records(d, lambda data: set_field(data, "expr", lambda old: text_of(canary, old)))
    assert n, "no record planted"
    store.clear_memory()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        v = lcs.parabola(verify=False).evaluate_at("force", dps=20, **PAR_VALUES)
    return v, canary


def _code(canary):
    return f"__import__('os').system('touch {canary}')"


EVIL = {
    "tuple_string": lambda c, old: f"Tuple({_code(c)!r})",
    "sin_string": lambda c, old: f"sin({_code(c)!r})",
    "integral_string": lambda c, old: f"Integral({_code(c)!r}, Symbol('x'))",
    "add_string": lambda c, old: f"Add({_code(c)!r}, Integer(1))",
    "symbol_kw_string": lambda c, old: f"Symbol('x', positive={_code(c)!r})",
    "float_string": lambda c, old: f"Float({_code(c)!r}, precision=53)",
    "matrix_string": lambda c, old: f"ImmutableMatrix({_code(c)!r})",
}
for _n, _f in EVIL.items():
    def _run(f=_f):
        v, canary = planted_force(f)
        return (not os.path.exists(canary)) and close(v, PAR_REF, 1e-15)
    CASES.append(("1 code from the cache", _n, _run))

HUGE = {
    "pow_10_1e9": lambda c, old: "Pow(Integer(10), Integer(1000000000))",
    "factorial_1e7": lambda c, old: "factorial(Integer(10000000))",
    "integer_1e6_digits": lambda c, old: "Integer(" + "9" * 1000000 + ")",
    "rational_pow": lambda c, old: "Pow(Rational(3, 2), Integer(100000000))",
    "nested_pow": lambda c, old: "Pow(Integer(2), Pow(Integer(2), Integer(40)))",
    "binomial_huge": lambda c, old: "binomial(Integer(10000000000), Integer(5000000000))",
    "float_precision_1e9": lambda c, old: "Float('1.5', precision=1000000000)",
}
for _n, _f in HUGE.items():
    def _run(f=_f):
        t0 = time.perf_counter()
        v, _ = planted_force(f)
        return close(v, PAR_REF, 1e-15) and time.perf_counter() - t0 < 20
    CASES.append(("1 code from the cache", _n, _run))


@case("1 code from the cache")
def cli_reads_planted_record():
    d = fresh_cache()
    canary = os.path.join(d, "pwned")
    env = dict(os.environ, LINECONTACT_SYM_CACHE=d)
    cmd = [sys.executable, "-m", "linecontact_sym", "eval", "x**2/(2*R)", "force", "--at", "a=0.875",
           "--set", "R=0.5", "E_star=1", "--dps", "15"]
    subprocess.run(cmd, env=env, capture_output=True, timeout=120)
    n = rewrite_records(d, lambda data: set_field(data, "expr", lambda old: f"Tuple({_code(canary)!r})"))
    r = subprocess.run(cmd, env=env, capture_output=True, timeout=120, text=True)
    return n > 0 and not os.path.exists(canary) and r.returncode == 0 and f"{PAR_REF:.12f}"[:12] in r.stdout


# ------------------------------------------------------------------ 2: tampered records
TAMPER = {
    "sign_flipped": lambda c, old: f"Mul(Integer(-1), {old})",
    "other_profile": lambda c, old: "Mul(Rational(1, 2), pi, Symbol('E_star', positive=True), "
                                    "Pow(Symbol('a', positive=True), Integer(3)), "
                                    "Pow(Symbol('R', positive=True), Integer(-1)))",
    "scaled": lambda c, old: f"Mul(Rational(1001, 1000), {old})",
}
for _n, _f in TAMPER.items():
    def _run(f=_f):
        v, _ = planted_force(f)
        return close(v, PAR_REF, 1e-15)
    CASES.append(("2 tampered record", _n, _run))


@case("2 tampered record")
def later_process_reads_correct():
    from linecontact_sym.method import store
    planted_force(TAMPER["sign_flipped"])
    store.clear_memory()
    v = lcs.parabola(verify=False).evaluate_at("force", dps=20, **PAR_VALUES)
    return close(v, PAR_REF, 1e-15)


@case("2 tampered record")
def misplaced_derivations_record():
    """A record of the right key whose structure is unexpected (an empty
    list of derivations): ignored, recomputed."""
    from linecontact_sym.method import store
    d = fresh_cache()
    c = lcs.parabola(verify=False)
    c.derivation("half_width")

    def empty(data):
        for pair in data.get("dict", []):
            if pair[0] == "derivations":
                pair[1] = {"tuple": []}
                return data
        return None
    n = rewrite_records(d, empty)
    store.clear_memory()
    e = lcs.parabola(verify=False).derivation("half_width").expr
    return n > 0 and sp.simplify(e - 2 * sp.sqrt(lcs.P * lcs.R / (sp.pi * lcs.E_star))) == 0


# ------------------------------------------------------------------ 3: units
try:
    import pint
    ureg = pint.UnitRegistry()
    Q_ = ureg.Quantity
except ImportError:       # pragma: no cover
    Q_ = None

# parabola, a = 1 mm, R = 5 mm, E* = 210 GPa: P = pi E* a^2/(4R) = 32986722.86 N/m
U_REF = math.pi * 210e9 * 1e-3**2 / (4 * 5e-3)


def _unit_value(v, unit="N/m"):
    if not hasattr(v, "to"):
        raise AssertionError(f"a plain number {v!r}: the unit was dropped")
    return float(v.to(unit).magnitude)


def units_ok(fn, ref, unit="N/m", tol=1e-9):
    try:
        v = fn()
    except LineContactError as exc:
        return "unit" in str(exc).lower() or "pint" in str(exc).lower() or "dimension" in str(exc).lower()
    return close(_unit_value(v, unit), ref, tol)


UV = lambda: dict(a=Q_(1, "mm"), R=Q_(5, "mm"), E_star=Q_(210, "GPa"))   # noqa: E731
for _n, _f in {
    "to_numeric_check": lambda: units_ok(lambda: lcs.parabola(verify=False).to_numeric("force")(**UV()), U_REF),
    "to_numeric_nocheck": lambda: units_ok(
        lambda: lcs.parabola(verify=False).to_numeric("force", check=False)(**UV()), U_REF),
    "to_numeric_mpmath": lambda: units_ok(
        lambda: lcs.parabola(verify=False).to_numeric("force", "mpmath")(**UV()), U_REF),
    "to_numeric_fixed_param": lambda: units_ok(
        lambda: lcs.parabola(verify=False).to_numeric("force", R=Q_(5, "mm"))(a=Q_(1, "mm"), E_star=Q_(210, "GPa")),
        U_REF),
    "to_numeric_pressure_array": lambda: units_ok(
        lambda: lcs.parabola(verify=False).to_numeric("pressure", check=False)(
            x=Q_(np.array([0.0, 0.5]), "mm"), **UV())[1],
        210e9 * math.sqrt(1e-6 - 0.25e-6) / (2 * 5e-3), "Pa"),
    "half_width": lambda: units_ok(lambda: lcs.parabola(verify=False).half_width(
        Q_(U_REF, "N/m"), R=Q_(5, "mm"), E_star=Q_(210, "GPa")), 1e-3, "m"),
    "md_pull_off_at": lambda: units_ok(lambda: lcs.parabola(verify=False).maugis_dugdale().pull_off_at(
        15, E_star=Q_(1, "Pa"), R=Q_(1, "m"), gamma=Q_(0.01, "J/m**2"), sigma_0=Q_(1, "Pa")).force,
        float(lcs.parabola(verify=False).maugis_dugdale().pull_off_at(15, E_star=1, R=1, gamma=0.01,
                                                                       sigma_0=1).force), "N/m", 1e-8),
    "md_model_choice": lambda: number_or_refused(lambda: {"JKR": 1, "MD": 2}[lcs.parabola(
        verify=False).maugis_dugdale().model_choice(0.05, E_star=Q_(1, "Pa"), R=Q_(1, "m"),
                                                    gamma=Q_(0.01, "J/m**2"), sigma_0=Q_(1, "Pa")).model],
        {"JKR": 1, "MD": 2}[lcs.parabola(verify=False).maugis_dugdale().model_choice(
            0.05, E_star=1, R=1, gamma=0.01, sigma_0=1).model]),
    "tangential_state": lambda: units_ok(lambda: lcs.parabola(verify=False).tangential().state(
        Q_(0.1, "N/m"), E_star=Q_(1, "Pa"), R=Q_(1, "m"), mu=0.4, a=Q_(0.8, "m")).c, 0.8 * 0.708971651646,
        "m", 1e-9),
    "md_state": lambda: units_ok(lambda: lcs.parabola(verify=False).maugis_dugdale().state(
        Q_(0.5, "m"), E_star=Q_(1, "Pa"), R=Q_(1, "m"), gamma=Q_(0.01, "J/m**2"), sigma_0=Q_(1, "Pa")).force,
        float(lcs.parabola(verify=False).maugis_dugdale().state(0.5, E_star=1, R=1, gamma=0.01, sigma_0=1).force),
        "N/m", 1e-8),
    "wrong_dimension_nocheck": lambda: refused(lambda: lcs.parabola(verify=False).to_numeric(
        "force", check=False)(a=Q_(1, "mm"), R=Q_(5, "s"), E_star=Q_(210, "GPa"))),
}.items():
    CASES.append(("3 units", _n, _f))


def _cli(argv, env=None):
    r = subprocess.run([sys.executable, "-m", "linecontact_sym"] + argv, capture_output=True, text=True,
                       timeout=300, env=dict(os.environ, **(env or {})))
    return r


@case("3 units")
def cli_set_GPa():
    r = _cli(["eval", "x**2/(2*R)", "force", "--at", "a=1e-3", "--set", "R=5e-3", "E_star=210GPa", "--dps", "12"])
    if r.returncode == 2:
        return "GPa" in r.stderr or "unit" in r.stderr
    return r.returncode == 0 and "32986722.86" in r.stdout


# ------------------------------------------------------------------ 4: Maugis-Dugdale inputs
MDV = dict(E_star=1, R=1, gamma=sp.Rational(1, 100))


def _md():
    return lcs.parabola(verify=False).maugis_dugdale()


def _jkr_po():
    return float(lcs.parabola(verify=False).adhesive().pull_off_at(20, E_star=1, R=1, gamma=sp.Rational(1, 100)).force)


for _n, _f in {
    "sigma0_oo_values": lambda: number_or_refused(lambda: _md().pull_off_at(15, sigma_0=sp.oo, **MDV).force,
                                                  _jkr_po(), 1e-6),
    "sigma0_oo_construct": lambda: number_or_refused(lambda: lcs.parabola(verify=False).maugis_dugdale(
        sigma0=sp.oo).pull_off_at(15, **MDV).force, _jkr_po(), 1e-6),
    "sigma0_complex_values": lambda: refused(lambda: _md().pull_off_at(15, sigma_0=1 + 2j, **MDV)),
    "sigma0_I_construct": lambda: refused(lambda: lcs.parabola(verify=False).maugis_dugdale(sigma0=1 + sp.I)),
    "sigma0_symbolic_values": lambda: refused(lambda: _md().pull_off_at(15, sigma_0=sp.Symbol("q") + 1, **MDV)),
    "sigma0_text_values": lambda: number_or_refused(lambda: _md().pull_off_at(15, sigma_0="1", **MDV).force,
                                                    float(_md().pull_off_at(15, sigma_0=1, **MDV).force)),
    "sigma0_1e100": lambda: number_or_refused(lambda: _md().pull_off_at(15, sigma_0=1e100, **MDV).force,
                                              _jkr_po(), 1e-6),
    "rtol_negative": lambda: refused(lambda: _md().model_choice(-0.1, sigma_0=1, **MDV)),
    "rtol_nan": lambda: refused(lambda: _md().model_choice(float("nan"), sigma_0=1, **MDV)),
    "rtol_text": lambda: refused(lambda: _md().model_choice("abc", sigma_0=1, **MDV)),
    "gap_at_cD_real": lambda: (lambda st: isinstance(st.gap(st.c_D), (mpmath.mpf, float, sp.Float))
                               or complex(st.gap(st.c_D)).imag == 0)(_md().state(0.5, sigma_0=1, **MDV)),
    "at_pull_off_force_number": lambda: (lambda v: float(v) < 0)(
        _md().at(sigma_0=1, **MDV).pull_off_force),
    "to_numeric_force": lambda: number_or_refused(
        lambda: _md().to_numeric("force")(a=0.5, c_D=0.7, sigma_0=1, **MDV),
        float(_md().to_numeric("zone_force")(a=0.5, c_D=0.7, sigma_0=1, **MDV))),
    "exact_cylinder_zone_past_R": lambda: number_or_refused(lambda: lcs.exact_cylinder(
        verify=False).maugis_dugdale().pull_off_at(15, E_star=1, R=1, gamma=1, sigma_0=sp.Rational(1, 100)).force,
        math.nan),
}.items():
    CASES.append(("4 Maugis-Dugdale inputs", _n, _f))


# ------------------------------------------------------------------ 5: negative x
def _pressure_ref_worn(xv):
    # the worn cylinder's pressure at |x| (the closed form is even in x; +0.6 is the reference point)
    return 0.3188056669639838 if abs(xv) == 0.6 else None


WORN = dict(a=0.8, b=0.5, R=1.0, E_star=1.0)
_worn = []


def worn():
    if not _worn:
        _worn.append(lcs.worn_cylinder(verify=False))
    return _worn[0]


for _n, _f in {
    "worn_pressure_check": lambda: close(worn().to_numeric("pressure")(x=-0.6, **WORN), 0.3188056669639838, 1e-12),
    "worn_pressure_nocheck": lambda: close(worn().to_numeric("pressure", check=False)(x=-0.6, **WORN),
                                           0.3188056669639838, 1e-12),
    "worn_pressure_mpmath": lambda: close(worn().to_numeric("pressure", "mpmath")(
        x=-0.6, a=0.8, b=0.5, R=1, E_star=1), 0.3188056669639838, 1e-12),
    "worn_pressure_array": lambda: (lambda xs, f: bool(np.allclose(f(x=xs, **WORN), f(x=-xs, **WORN),
                                                                   rtol=1e-12, atol=0)
                                                       and np.all(np.isfinite(f(x=-xs, **WORN)))))(
        np.linspace(0.001, 0.799, 101), worn().to_numeric("pressure")),
    "worn_pressure_array_nocheck": lambda: (lambda xs, f: bool(np.allclose(f(x=xs, **WORN), f(x=-xs, **WORN),
                                                                           rtol=1e-12, atol=0)))(
        np.linspace(0.001, 0.799, 101), worn().to_numeric("pressure", check=False)),
    "worn_gap_negative": lambda: close(worn().to_numeric("gap")(x=-1.2, **WORN),
                                       float(worn().to_numeric("gap")(x=1.2, **WORN)), 1e-12),
    "worn_gap_nocheck": lambda: close(worn().to_numeric("gap", check=False)(x=-1.2, **WORN),
                                      float(worn().to_numeric("gap")(x=1.2, **WORN)), 1e-12),
    "worn_evalf_negative": lambda: number_or_refused(lambda: worn().derivation("pressure").evalf(
        x=-sp.Rational(3, 5), a=sp.Rational(4, 5), b=sp.Rational(1, 2), R=1, E_star=1), 0.3188056669639838, 1e-12),
    "traction_negative_nocheck": lambda: close(lcs.parabola(verify=False).tangential().to_numeric(
        "traction", check=False)(x=-0.3, a=1.0, c_s=0.5, mu=0.3, R=1.0, E_star=1.0),
        float(lcs.parabola(verify=False).tangential().to_numeric("traction")(
            x=0.3, a=1.0, c_s=0.5, mu=0.3, R=1.0, E_star=1.0)), 1e-12),
}.items():
    CASES.append(("5 negative x", _n, _f))


# ------------------------------------------------------------------ 6: executors and budgets
def _incli(argv):
    from linecontact_sym import cli
    err = io.StringIO()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        try:
            code = cli.main(argv)
        except SystemExit as exc:
            code = exc.code
    return code, err.getvalue()


def _budget_ok(v):
    from linecontact_sym.core.budget import checked_budget
    try:
        r = checked_budget(v)
    except LineContactError:
        return True
    return r is None or (isinstance(r, float) and r > 0)


for _n, _f in {
    "jobs_abc_cli": lambda: _incli(["paper", "popov2017", "--jobs", "abc", "--only", "Eq. (13)"])[0] == 2,
    "jobs_abc_api": lambda: refused(lambda: __import__("linecontact_sym.core.parallel", fromlist=["x"]).jobs_count(
        "abc")),
    "jobs_numpy": lambda: __import__("linecontact_sym.core.parallel", fromlist=["x"]).jobs_count(np.int64(3)) == 3,
    "jobs_spaces": lambda: __import__("linecontact_sym.core.parallel", fromlist=["x"]).jobs_count(" 2 ") == 2,
    "budget_1e400": lambda: _budget_ok(10**400),
    "budget_text": lambda: _budget_ok("abc"),
    "budget_numpy": lambda: _budget_ok(np.float32(5)),
    "budget_text_number": lambda: _budget_ok(" 5 "),
    "executor_text": lambda: refused(lambda: lcs.check_paper("popov2017", executor="processes", only=["Eq. (13)"])
                                     if hasattr(lcs, "check_paper") else
                                     __import__("linecontact_sym.claims.batch", fromlist=["x"]).check_paper(
                                         __import__("linecontact_sym.claims.spec", fromlist=["x"]).load_paper(
                                             "popov2017"), executor="processes")),
    "env_budget_abc_cli": lambda: (lambda r: r.returncode == 2 and "Traceback" not in r.stderr
                                   and "LINECONTACT_SYM_BUDGET" in r.stderr)(
        _cli(["eval", "x**2/(2*R)", "force", "--at", "a=1", "--set", "R=1", "E_star=1"],
             {"LINECONTACT_SYM_BUDGET": "abc"})),
    "env_budget_inf_cli": lambda: (lambda r: r.returncode == 0)(
        _cli(["eval", "x**2/(2*R)", "force", "--at", "a=1", "--set", "R=1", "E_star=1"],
             {"LINECONTACT_SYM_BUDGET": "inf"})),
    "env_budget_abc_api": lambda: (lambda r: r.returncode == 0 and "BudgetError" in r.stdout)(subprocess.run(
        [sys.executable, "-c", "import linecontact_sym as l\ntry:\n l.parabola(verify=False).derivation('force')\n"
         "except l.core.errors.LineContactError as e: print(type(e).__name__)\n"],
        capture_output=True, text=True, env=dict(os.environ, LINECONTACT_SYM_BUDGET="abc"), timeout=120)),
    "paper_jobs_1000_capped": lambda: _workers_capped(),
}.items():
    CASES.append(("6 executors and budgets", _n, _f))


def _workers_capped():
    """paper --jobs 1000 on 1 claim: at most as many workers as claims."""
    from linecontact_sym.core import parallel
    seen = []
    orig = parallel.process_pool

    def spy(jobs=None, *a, **kw):
        seen.append(jobs)
        return orig(jobs, *a, **kw)
    import linecontact_sym.claims.batch as batch
    parallel.process_pool, batch.process_pool = spy, spy
    try:
        out = tempfile.mkdtemp()
        _incli(["paper", "popov2017", "--jobs", "1000", "--only", "Eq. (13)", "--no-figures", "--quiet",
                "--out", out])
    finally:
        parallel.process_pool, batch.process_pool = orig, orig
    return all(j is not None and j <= 1 for j in seen)


# ------------------------------------------------------------------ 7: carried over
@case("7 carried over")
def eval_bad_value_on_stderr():
    code, err = _incli(["eval", "x**2/(2*R)", "force", "--at", "a=-1", "--set", "R=1", "E_star=1"])
    return code == 2 and "a" in err and err.strip() != ""


@case("7 carried over")
def stick_above_a_values():
    c = sp.Symbol("c", positive=True)
    return refused(lambda: lcs.parabola(verify=False).stresses("partial_slip", stick=c, mu=0.3).evaluate_at(
        "sigma_x", x=sp.Rational(1, 10), z=sp.Rational(1, 5), a=1, c=sp.Rational(3, 2), R=1, E_star=1))


@case("7 carried over")
def stick_above_a_field():
    return refused(lambda: lcs.parabola(verify=False).stresses("partial_slip", stick=1.5, mu=0.3).evaluate_at(
        "sigma_x", x=sp.Rational(1, 10), z=sp.Rational(1, 5), a=1, R=1, E_star=1))


@case("7 carried over")
def stick_above_a_to_numeric():
    c = sp.Symbol("c", positive=True)
    f = lcs.parabola(verify=False).stresses("partial_slip", stick=c, mu=0.3).to_numeric("sigma_x")
    return refused(lambda: f(x=0.1, z=0.2, a=1.0, c=1.5, R=1.0, E_star=1.0))


@case("7 carried over")
def cos_bump_jkr_gamma_1():
    A, L = sp.Symbol("A", positive=True), sp.Symbol("L", positive=True)
    c = lcs.LineContact(A * (1 - sp.cos(sp.pi * x / L)), verify=False)
    try:
        po = c.adhesive().pull_off_at(15, A=sp.Rational(1, 10), L=1, E_star=1, gamma=1)
    except LineContactError as exc:
        return "admissible" in str(exc) or "no pull-off" in str(exc).lower() or "range" in str(exc)
    return float(po.force) < 0


# ------------------------------------------------------------------ run
def main():
    isolated_main(CASES, __doc__.splitlines()[0], 90, "lcs-sweep4-", 26, 32)


if __name__ == "__main__":
    sys.exit(main())
