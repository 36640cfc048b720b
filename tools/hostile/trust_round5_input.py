"""Hostile sweep of issue 42 (trust, round 5), the input classes of helper
trustA: numbers typed by people (CLI values, claims files, environment
variables, with and without pint), values where a result does not hold,
foreign exceptions at the edges, Maugis-Dugdale parameters, forged records
and FIFOs, periodic arrays on the command line and in claims files, the lazy
import under threads, and the wedge's pull-off on the command line.

A case passes when the package gives the independently known number (or
text), or a clear package error (a ``LineContactError`` subclass; on the
command line exit 2 with a message on stderr and no traceback), within the
timeout; a wrong number, a foreign exception, a hang or an internal error
(exit 3) fails it.  Every case runs in a forked child with a temporary cache
directory of its own (nothing in the user's cache is read or written); the
command line runs in that child (``cli.main``), in a new interpreter only
where an environment variable is read at import.

    python tools/hostile/trust_round5_input.py [--json out.json] [--only 1,4] [--match TEXT] [--timeout S]
    PYTHONPATH=/path/to/other/checkout python tools/hostile/trust_round5_input.py --json before.json

Groups: 1 typed numbers, 4 values where the result does not hold, 5 edges,
6 Maugis-Dugdale, 9 records and arrays, 10 threads and exit codes, 11 output.
"""
from __future__ import annotations

import argparse
import hashlib
import json
import os
import subprocess
import sys
import tempfile
import textwrap
import threading
import time
import warnings

import mpmath
import numpy as np
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core.errors import LineContactError
from harness import close, is_refused as refused, isolated_main  # tools/hostile/, beside this file


CASES: list = []
x, a = lcs.x, lcs.a
R = sp.Symbol("R", positive=True)
h, L = sp.symbols("h L", positive=True)


def case(group, name=None):
    def deco(fn):
        CASES.append((group, name or fn.__name__, fn))
        return fn
    return deco


def add(group, name, fn):
    CASES.append((group, name, fn))


# ------------------------------------------------------------------ the command line
_NO_PINT = "import sys; sys.modules['pint'] = None\n"


def cli(argv, env=None, pint=True, timeout=300):
    """``(exit status, stdout, stderr)`` of the command line: in this (forked)
    process, or with ``env`` (read at import) in a new one; ``pint=False``:
    the import of pint fails, as where it is not installed."""
    if env:
        code = ("" if pint else _NO_PINT) + "from linecontact_sym.cli import main\nraise SystemExit(main(sys.argv[1:]))"
        r = subprocess.run([sys.executable, "-c", "import sys\n" + code] + list(argv), capture_output=True,
                           text=True, timeout=timeout, env=dict(os.environ, **env))
        return r.returncode, r.stdout, r.stderr
    import contextlib
    import io
    from linecontact_sym.cli import main
    if not pint:
        sys.modules["pint"] = None           # the case runs in a forked child: nothing else sees it
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main(list(argv))
        except SystemExit as exc:             # argparse's own errors
            code = exc.code if isinstance(exc.code, int) else 2
    return code, out.getvalue(), err.getvalue()


def _last_number_close(out, ref, rtol=1e-12):
    """The value of the table's last row (its last column) within ``rtol`` of ``ref``."""
    try:
        v = mpmath.mpf(out.strip().splitlines()[-1].split()[-1])
    except (ValueError, IndexError):
        return False
    return abs(v - ref) <= rtol * abs(ref)


def bad_input(r):
    """Exit 2 with a message and no traceback."""
    code, _, err = r
    return code == 2 and "error:" in err and "Traceback" not in err


# P = pi E* a**2/(4 R) at a = 1e-3, R = 0.01 and E* = 2.1e11, computed here
_FORCE = mpmath.pi * mpmath.mpf("2.1e11") * mpmath.mpf("1e-6") / (4 * mpmath.mpf("0.01"))


def _eval_force(estar, pint=True, at="a=0.001"):
    code, out, err = cli(["eval", "x**2/(2*R)", "force", "--at", at, "--set", "R=0.01", f"E_star={estar}",
                          "--dps", "15"], pint=pint)
    return code, out, err


for _text in ("2.1e11", "2.1E11", "210e9", "2.1e+11", "210000000000", "21e10", "2.1e11/1", "420e9/2"):
    for _pint in (True, False):
        def _f(t=_text, p=_pint):
            code, out, err = _eval_force(t, p)
            return code == 0 and mpmath.nstr(_FORCE, 12) in out and "[" not in out.splitlines()[0], (code, err)
        add("1 typed numbers", f"--set E_star={_text} ({'with' if _pint else 'without'} pint)",
            lambda f=_f: f()[0])

for _text, _ok in (("210GPa", True), ("210 GPa", True), ("2.1e11Pa", True), ("0.21 TPa", True)):
    def _f(t=_text):
        code, out, err = _eval_force(t, True)
        return code == 0 and mpmath.nstr(_FORCE, 12) in out
    add("1 typed numbers", f"--set E_star={_text} (a unit, pint)", _f)
    add("1 typed numbers", f"--set E_star={_text} (a unit, no pint: refused)",
        lambda t=_text: bad_input(_eval_force(t, False)))

for _text in ("2.1e", "1e", "abc", "nan", "inf", "1/0", "2.1e11 GPa foo", "5 s", "1e11e3"):
    add("1 typed numbers", f"--set E_star={_text} refused", lambda t=_text: bad_input(_eval_force(t, True)))

for _text in ("1e-3", "1/1000", "0.001", "1mm", "1e-3:2e-3:2"):
    def _f(t=_text):
        code, out, err = _eval_force("2.1e11", True, at=f"a={t}")
        return code == 0 and mpmath.nstr(_FORCE, 12) in out
    add("1 typed numbers", f"--at a={_text}", _f)

for _pint in (True, False):
    # the zone force -2 sigma_0 sqrt(c_D**2 - a**2) at sigma_0 = 1e300, a = 1/2, c_D = 0.6, computed here
    add("1 typed numbers", f"--set sigma_0=1e300 ({'with' if _pint else 'without'} pint)", lambda p=_pint: (
        lambda r: r[0] == 0 and _last_number_close(r[1], -2 * mpmath.mpf(10)**300 * mpmath.sqrt(mpmath.mpf("0.11"))))(
        cli(["eval", "x**2/(2*R)", "maugis_dugdale.zone_force", "--at", "a=0.5", "--set", "R=1", "E_star=1",
             "gamma=1", "sigma_0=1e300", "c_D=0.6", "--dps", "15"], pint=p)))

for _text, _code in (("1e3", 0), ("1/2", 0), (" 30 ", 0), ("abc", 2), ("-1", 2), ("nan", 2), ("0", 2)):
    add("1 typed numbers", f"LINECONTACT_SYM_BUDGET={_text!r}", lambda t=_text, c=_code: cli(
        ["eval", "x**2/(2*R)", "force", "--at", "a=1", "--set", "R=1", "E_star=1"],
        env={"LINECONTACT_SYM_BUDGET": t})[0] == c)


def _claims(text, tmp=None):
    d = tempfile.mkdtemp(prefix="lcs-sweep5-claims-")
    p = os.path.join(d, "c.toml")
    with open(p, "w") as fh:
        fh.write(textwrap.dedent(text))
    return cli(["check", p, "--json", "--budget", "30"])


_CLAIM = '''
key = "t"
[ranges]
R = [{lo}, {hi}]
[[claims]]
label = "hertz"
quantity = "force"
profile = "x**2/(2*R)"
formula = "pi*E_star*a**2/(4*R)"
'''
for _lo, _hi, _code in (('"0.5"', '"2.5e0"', 0), ('"1/2"', '"5/2"', 0), ("0.5", "2.5", 0), ('"5e-1"', '"25E-1"', 0),
                        ('"1mm"', '"2mm"', 2), ('"a"', '"b"', 2), ('"nan"', "1", 2), ('"oo"', "1", 2),
                        ("-1", "1", 2)):
    add("1 typed numbers", f"claims ranges R = [{_lo}, {_hi}]",
        lambda lo=_lo, hi=_hi, c=_code: _claims(_CLAIM.format(lo=lo, hi=hi))[0] == c)

try:
    import pint as _pint_module
    Q_ = _pint_module.UnitRegistry().Quantity
except ImportError:       # pragma: no cover
    Q_ = None


@case("1 typed numbers", "evaluate(a=[Q_(1 mm), Q_(2 mm)])")
def units_list():
    r = lcs.parabola(verify=False).evaluate("force", a=[Q_(1, "mm"), Q_(2, "mm")], E_star=Q_(210, "GPa"),
                                            R=Q_(5, "mm"))
    v = np.asarray(getattr(r.value, "magnitude", r.value), dtype=float)
    return np.allclose(v, [np.pi * 210e9 * 1e-6 / 0.02, np.pi * 210e9 * 4e-6 / 0.02], rtol=1e-12)


@case("1 typed numbers", "evaluate_at(a=[Q_(1 mm), Q_(2 mm)]): one number or refused")
def units_list_at():
    try:
        v = lcs.parabola(verify=False).evaluate_at("force", a=[Q_(1, "mm"), Q_(2, "mm")], E_star=Q_(210, "GPa"),
                                                   R=Q_(5, "mm"))
    except LineContactError:
        return True
    return False, v


@case("1 typed numbers", "evaluate(a=[Q_(1 mm), 2e-3]) mixed: refused")
def units_mixed():
    return refused(lambda: lcs.parabola(verify=False).evaluate("force", a=[Q_(1, "mm"), 2e-3], E_star=Q_(210, "GPa"),
                                                               R=Q_(5, "mm")))


@case("1 typed numbers", "pull_off_at(R=Q_(1 mm)): refused, said")
def units_pull_off():
    return refused(lambda: lcs.parabola(verify=False).adhesive().pull_off_at(15, R=Q_(1, "mm"), E_star=1, gamma=1))


# ------------------------------------------------------------------ 4: values where the result does not hold
for _vals in (dict(R=-1, E_star=1, gamma=1), dict(R=0, E_star=1, gamma=1), dict(R=1, E_star=-1, gamma=1),
              dict(R=1, E_star=0, gamma=1), dict(R=1, E_star=1, gamma=-1), dict(R=1, E_star=1, gamma=sp.I),
              dict(R=1, E_star=1, gamma="1+2*I"), dict(R=-sp.Rational(1, 2), E_star=1, gamma=1)):
    add("4 values", f"exact cylinder JKR pull-off {_vals}",
        lambda v=_vals: refused(lambda: lcs.exact_cylinder(verify=False).adhesive().pull_off_at(15, **v)))
add("4 values", "parabola JKR pull-off R=-1", lambda: refused(
    lambda: lcs.parabola(verify=False).adhesive().pull_off_at(15, R=-1, E_star=1, gamma=1)))
add("4 values", "wedge JKR pull-off theta=-0.3", lambda: refused(
    lambda: lcs.wedge(verify=False).adhesive().pull_off_at(15, theta=-0.3, E_star=1, gamma=1)))
add("4 values", "force_law(R=-1)", lambda: refused(lambda: lcs.parabola(verify=False).force_law(R=-1, E_star=1)))
add("4 values", "derivation.evalf(R=-1)", lambda: refused(
    lambda: lcs.parabola(verify=False).derivation("force").evalf(15, a=1, R=-1, E_star=1)))
add("4 values", "evaluate(R=-1)", lambda: refused(
    lambda: lcs.parabola(verify=False).evaluate("force", a=1, R=-1, E_star=1)))
add("4 values", "half_width(1, R=-1)", lambda: refused(lambda: lcs.parabola(verify=False).half_width(1, R=-1, E_star=1)))
add("4 values", "tangential state R=-1", lambda: refused(
    lambda: lcs.parabola(verify=False).tangential().state(0.1, E_star=1, R=-1, mu=0.4, a=0.8)))
add("4 values", "tangential state a=-0.8", lambda: refused(
    lambda: lcs.parabola(verify=False).tangential().state(0.1, E_star=1, R=1, mu=0.4, a=-0.8)))
add("4 values", "MD state R=-1", lambda: refused(
    lambda: lcs.parabola(verify=False).maugis_dugdale().state(0.5, 15, R=-1, E_star=1, gamma=0.1, sigma_0=1)))
for _law in (-a**2, a**2 - a, sp.I * a**2, -sp.pi * lcs.E_star * a**2 / (4 * R), a**3 - 2 * a**2):
    add("4 values", f"profile_from_force({_law})", lambda f=_law: refused(lambda: lcs.profile_from_force(f).expr))
add("4 values", "profile_from_force(pi E* a**2/(4R)) = x**2/(2R)", lambda: sp.simplify(
    lcs.profile_from_force(sp.pi * lcs.E_star * a**2 / (4 * R), verify_points=2).expr - x**2 / (2 * R)) == 0)
add("4 values", "gamma = 0: the non-adhesive limit, no pull-off", lambda: refused(
    lambda: lcs.parabola(verify=False).adhesive().pull_off_at(15, R=1, E_star=1, gamma=0)))
add("4 values", "x = -1/2: the mirrored profile's pressure", lambda: close(
    lcs.parabola(verify=False).derivation("pressure").evalf(15, a=1, x=-sp.Rational(1, 2), R=1, E_star=1),
    float(mpmath.sqrt(0.75) / 2)))


# ------------------------------------------------------------------ 5: foreign exceptions at the edges
for _rng in (("a", "b"), (float("nan"), 1), (0.5, float("inf")), (2, 1), (1,), 5, (-1, 1),
             (sp.I, 2), ("0.5", "2")):
    add("5 edges", f"params={{R: {_rng!r}}}", lambda r=_rng: refused(lambda: lcs.LineContact(x**2 / (2 * R),
                                                                                          params={R: r})))


@case("5 edges", "sin nested 300 deep")
def nested_sin():
    e = x
    for _ in range(300):
        e = sp.sin(e, evaluate=False)
    return refused(lambda: lcs.LineContact(e).force)


@case("5 edges", "force law nested 300 deep")
def nested_law():
    e = a
    for _ in range(300):
        e = sp.sinh(e, evaluate=False)
    return refused(lambda: lcs.profile_from_force(e).expr)


@case("5 edges", "sqrt nested 80 deep")
def nested_sqrt():
    e = x
    for _ in range(80):
        e = sp.sqrt(1 + e, evaluate=False)
    return refused(lambda: lcs.LineContact(e - sp.sqrt(1 + x)).force)


for _load in (1 + 2j, sp.I, "1+2*I", float("nan"), sp.oo, -sp.oo, np.complex128(1j), float("inf")):
    add("5 edges", f"half_width({_load!r})", lambda P=_load: refused(
        lambda: lcs.parabola(verify=False).half_width(P, R=1, E_star=1)))
    add("5 edges", f"adhesive half_width({_load!r})", lambda P=_load: refused(
        lambda: lcs.parabola(verify=False).adhesive().half_width(P, R=1, E_star=1, gamma=1)))
add("5 edges", "stick_half_width(1j)", lambda: refused(
    lambda: lcs.parabola(verify=False).tangential().stick_half_width(1j, E_star=1, R=1, mu=0.4, a=0.8)))


# ------------------------------------------------------------------ 6: Maugis-Dugdale
@case("6 Maugis-Dugdale", "sigma0 = 2 gamma: the pull-off of sigma0 = 0.2 at gamma = 0.1")
def md_expression():
    g = sp.Rational(1, 10)
    p1 = lcs.parabola().maugis_dugdale(lcs.gamma, 2 * lcs.gamma).pull_off_at(12, R=1, E_star=1, gamma=g).force
    p2 = lcs.parabola().maugis_dugdale().pull_off_at(12, R=1, E_star=1, gamma=g, sigma_0=2 * g).force
    return close(p1, p2, 1e-9)


@case("6 Maugis-Dugdale", "derive --law maugis_dugdale without --adhesion: the adhesive laws")
def md_law_alone():
    code, out, err = cli(["derive", "x**2/(2*R)", "--law", "maugis_dugdale", "--quantities", "force", "--json"])
    return code == 0 and any(k != "force" for k in json.loads(out)["quantities"])


@case("6 Maugis-Dugdale", "LaTeX of the MD placeholders: no SymPy subscripts")
def md_latex():
    md = lcs.parabola(verify=False).maugis_dugdale()
    tex = md.latex("maugis_lambda")
    return "maugis}_{" not in tex and r"\_" in tex and "off force" not in lcs.to_latex(
        sp.Function("pull_off_force")(lcs.E_star))


# ------------------------------------------------------------------ 9: records and arrays
def _rewrite_remembered(d, fn):
    from linecontact_sym.method import store
    n = 0
    for root, _, files in os.walk(d):
        for f in files:
            p = os.path.join(root, f)
            raw = open(p, "rb").read()
            data = json.loads(raw[len(store._MAGIC) + 65:].decode())
            for pair in data.get("dict", []):
                if pair[0] == "derivations":
                    for r in pair[1]["tuple"]:
                        for fld in r["dict"]:
                            if fld[0] == "expr":
                                fld[1] = {"sympy": fn(fld[1]["sympy"])}
                                n += 1
                    payload = json.dumps(data, separators=(",", ":")).encode()
                    open(p, "wb").write(store._MAGIC + hashlib.sha256(payload).hexdigest().encode() + b"\n" + payload)
    return n


def _forged(build, value, fn):
    """``value(build())`` after every remembered record was rewritten by ``fn``
    (checksums recomputed) equals the value before; or a clear refusal."""
    from linecontact_sym.method import store
    d = os.environ[store.CACHE_ENV]
    before = value(build())
    if not _rewrite_remembered(d, fn):
        return False, "no record written"
    store.clear_memory()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        after = value(build())
    return sp.simplify(after - before) == 0, (before, after)


def _sinusoid():
    return lcs.LineContact(h * (1 - sp.cos(2 * sp.pi * x / L)), period=L, verify=False)


add("9 records and arrays", "forged array force (sin for sin**2)", lambda: _forged(
    _sinusoid, lambda c: c.force, lambda t: t.replace("Integer(2)", "Integer(1)", 1))[0])
add("9 records and arrays", "forged array full-contact load (x2)", lambda: _forged(
    _sinusoid, lambda c: c.derivation("full_contact_force").expr, lambda t: f"Mul(Integer(2), {t})")[0])
add("9 records and arrays", "forged JKR pull-off (x2)", lambda: _forged(
    lambda: lcs.parabola(verify=False).adhesive(), lambda ad: ad.pull_off_force, lambda t: f"Mul(Integer(2), {t})")[0])
add("9 records and arrays", "forged wedge pull-off half-width (x3)", lambda: _forged(
    lambda: lcs.wedge(verify=False).adhesive(), lambda ad: ad.pull_off_half_width,
    lambda t: f"Mul(Integer(3), {t})")[0])


@case("9 records and arrays", "a FIFO at a record's path: not waited on")
def fifo():
    from linecontact_sym.method import store
    key = store.make_key("remembered", "sweep fifo")
    path = store._path(key)
    path.parent.mkdir(parents=True, exist_ok=True, mode=0o700)
    os.mkfifo(path)
    out = []
    t = threading.Thread(target=lambda: out.append(store.get(key)), daemon=True)
    t.start()
    t.join(10)
    return not t.is_alive() and out == [None]


@case("9 records and arrays", "a FIFO at a derivation's record: derived anyway")
def fifo_derivation():
    from linecontact_sym.method import store
    lcs.parabola(verify=False).force
    d = os.environ[store.CACHE_ENV]
    paths = [os.path.join(r, f) for r, _, fs in os.walk(d) for f in fs]
    for p in paths:
        os.remove(p)
        os.mkfifo(p)
    store.clear_memory()
    out = []
    t = threading.Thread(target=lambda: out.append(lcs.parabola(verify=False).force), daemon=True)
    t.start()
    t.join(60)
    return not t.is_alive() and out and sp.simplify(out[0] - sp.pi * lcs.E_star * a**2 / (4 * lcs.R)) == 0


@case("9 records and arrays", "eval --period L nominal_pressure")
def eval_nominal():
    code, out, err = cli(["eval", "h*(1 - cos(2*pi*x/L))", "nominal_pressure", "--symbols", "h", "L", "--period",
                          "L", "--at", "a=0.1", "--set", "h=1", "L=1", "E_star=1", "--dps", "20"])
    with mpmath.workdps(30):
        return code == 0 and mpmath.nstr(mpmath.pi * mpmath.sin(mpmath.pi / 10)**2, 18) in out


for _period, _code in (('"0"', 2), ('"-1"', 2), ('"oo"', 2), ('"x"', 2), ('"1"', None), ('"L"', None)):
    add("9 records and arrays", f"claims period = {_period}", lambda p=_period, c=_code: (lambda r: (
        r[0] == c if c is not None else r[0] in (0, 1, 4)) and "Traceback" not in r[2])(_claims(f'''
        key = "t"
        symbols = ["h", "L"]
        [ranges]
        h = [0.1, 1.0]
        L = [1.0, 2.0]
        a = [0.02, 0.49]
        [[claims]]
        label = "w"
        quantity = "force"
        profile = "h*(1 - cos(2*pi*x/L))"
        period = {p}
        formula = "pi*E_star*h*sin(pi*a/L)**2"
        ''')))

for _q in ("maugis_dugdale.zone_force", "maugis_dugdale.pull_off_force", "tangential.stick_half_width",
           "stress.sigma_x"):
    add("9 records and arrays", f"claims {_q} on an array: never 'holds'", lambda q=_q: (lambda r: r[0] in (2, 4) and (
        r[0] == 2 or json.loads(r[1])["claims"][0]["status"] == "undecided"))(_claims(f'''
        key = "t"
        symbols = ["h", "L"]
        [[claims]]
        label = "on an array"
        quantity = "{q}"
        profile = "h*(1 - cos(2*pi*x/L))"
        period = "L"
        formula = "2*sigma_0*sqrt(c_D**2 - a**2)"
        ''')))


# ------------------------------------------------------------------ 10: exit codes, threads
add("10 threads and exits", "derive --period --adhesion --law maugis_dugdale: exit 2", lambda: bad_input(cli(
    ["derive", "h*(1 - cos(2*pi*x/L))", "--symbols", "h", "L", "--period", "L", "--adhesion", "--law",
     "maugis_dugdale"])))
add("10 threads and exits", "derive --period --law maugis_dugdale: exit 2", lambda: bad_input(cli(
    ["derive", "h*(1 - cos(2*pi*x/L))", "--symbols", "h", "L", "--period", "L", "--law", "maugis_dugdale"])))

_THREADS = """
import os, sys, threading, time
import linecontact_sym as lcs
class Slow:
    def find_spec(self, name, path=None, target=None):
        if name in ("linecontact_sym.contacts", "linecontact_sym.contacts.normal"):
            time.sleep(0.5)
        return None
if {slow}:
    sys.meta_path.insert(0, Slow())
names = {names!r}
b = threading.Barrier(len(names))
errs = []
def touch(n):
    b.wait()
    try:
        getattr(lcs, n)
    except BaseException as e:
        errs.append(repr(e))
ts = [threading.Thread(target=touch, args=(n,)) for n in names]
[t.start() for t in ts]
[t.join(40) for t in ts]
print("ok" if not errs and not any(t.is_alive() for t in ts) else errs)
sys.stdout.flush()
os._exit(0)
"""
for _slow in (False, True):
    for _names in (["LineContact", "profile_from_force"], ["profile_from_force", "AdhesiveLineContact",
                                                            "TangentialLineContact", "StressField"]):
        add("10 threads and exits", f"threads {_names} (window widened: {_slow})", lambda s=_slow, n=_names: subprocess.run(
            [sys.executable, "-c", _THREADS.format(slow=s, names=n)], capture_output=True, text=True,
            timeout=120).stdout.strip() == "ok")


# ------------------------------------------------------------------ 11: output
@case("11 output", "derive x*tan(theta) --adhesion prints the pull-off -pi gamma/(2 tan theta)")
def wedge_pull_off():
    code, out, _ = cli(["derive", "x*tan(theta)", "--adhesion", "--json"])
    q = json.loads(out)["quantities"]
    return code == 0 and any(v.get("expr") == "-pi*gamma/(2*tan(theta))" for v in q.values())


@case("11 output", "derive x*tan(theta) --adhesion (text) shows -pi*gamma/(2*tan(theta))")
def wedge_pull_off_text():
    code, out, _ = cli(["derive", "x*tan(theta)", "--adhesion"])
    return code == 0 and "-pi*gamma/(2*tan(theta))" in out


# ------------------------------------------------------------------ run
def main():
    isolated_main(CASES, __doc__.splitlines()[0], 150, "lcs-sweep5-", 22, 60)


if __name__ == "__main__":
    sys.exit(main())
