"""Hostile sweep of issue 19 (items 2, 3, 4, 7, 9): every public entry point
fed the user's own symbols, conditional results at points inside and
outside their conditions, values at and beyond the physical ranges, planted
cache files and CLI/claims edges.  Each case passes when the package gives
the independently computed number (mpmath quadrature of the defining
integral) or a clear package error (a ``LineContactError`` subclass, exit
code 2), within a minute; anything else -- a wrong number, a foreign
exception, exit 3, a hang -- fails.

    python tools/hostile/trust_sweep.py            # the installed/checked-out package
    PYTHONPATH=/path/to/other/checkout python tools/hostile/trust_sweep.py --json out.json

Run it against two checkouts and compare the JSON files to count the cases
a change fixed.
"""
from __future__ import annotations

import argparse
import contextlib
import io
import json
import os
import signal
import sys
import tempfile
import time
import warnings

import mpmath
import numpy as np
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core.errors import LineContactError
from harness import summary  # tools/hostile/, beside this file

x = lcs.x
CASES: list = []


def case(group):
    def deco(fn):
        CASES.append((group, fn.__name__, fn))
        return fn
    return deco


class Timeout(Exception):
    pass


def _alarm(signum, frame):
    raise Timeout()


def close(v, ref, tol):
    """|v - ref| <= tol max(1, |ref|) at 50 digits (compute ``ref`` at 40 digits
    or more: a reference formed at mpmath's default 15 digits is not one)."""
    if isinstance(v, (np.ndarray, np.floating)):
        v = float(v)
    with mpmath.workdps(50):
        ref = ref() if callable(ref) else ref
        ref = mpmath.mpf(sp.N(ref, 50)) if isinstance(ref, sp.Basic) else mpmath.mpf(ref)
        return abs(mpmath.mpf(v) - ref) <= tol * max(1, abs(ref))


def refused(fn):
    """A clear package error (never a number, never a foreign exception)."""
    try:
        v = fn()
    except LineContactError:
        return True
    if isinstance(v, (float, np.floating, mpmath.mpf)) and (np.isnan(float(v))):
        return True
    raise AssertionError(f"gave {v!r} instead of an error")


def force_ref(fprime, A, E=1):
    with mpmath.workdps(40):
        A = mpmath.mpf(A)
        return +(E * A * mpmath.quad(lambda ph: mpmath.sin(ph) * fprime(A * mpmath.sin(ph)), [0, mpmath.pi / 2]))


def pressure_ref(fprime, fsecond, A, X):
    with mpmath.workdps(30):
        A, X = mpmath.mpf(A), mpmath.mpf(X)

        def dP(s):
            return mpmath.quad(lambda ph: mpmath.sin(ph) * fprime(s * mpmath.sin(ph))
                               + s * mpmath.sin(ph)**2 * fsecond(s * mpmath.sin(ph)), [0, mpmath.pi / 2])
        return +(mpmath.quad(lambda u: dP(X * mpmath.cosh(u)), [0, mpmath.acosh(A / X)]) / mpmath.pi)


# ------------------------------------------------------------------ item 2: the user's symbols
NAMES = ["s", "t", "pi", "E", "I", "lambda_", "gamma", "beta", "numpy", "sqrt"]
_contacts: dict = {}


def named(name):
    if name not in _contacts:
        k = sp.Symbol(name, positive=True)
        _contacts[name] = lcs.LineContact(x**2 / (2 * k) + x**4, verify=False)
    return _contacts[name]


FP = lambda t: t / mpmath.mpf(1.5) + 4 * t**3          # noqa: E731  f' at k = 3/2
FPP = lambda t: 1 / mpmath.mpf(1.5) + 12 * t**2        # noqa: E731
P_REF = None


def _pref():
    global P_REF
    if P_REF is None:
        P_REF = (force_ref(FP, sp.Rational(4, 5)), pressure_ref(FP, FPP, sp.Rational(4, 5), sp.Rational(3, 10)))
    return P_REF


def _entry(kind):
    def run(name):
        c = named(name)
        P, p = _pref()
        ex = {"a": sp.Rational(4, 5), name: sp.Rational(3, 2), "E_star": 1}
        fl = {"a": 0.8, name: 1.5, "E_star": 1.0}
        if kind == "pressure_closed":
            d = c.derivation("pressure")
            return d.closed_form and not d.expr.has(sp.Integral)
        if kind == "evaluate_at":
            return close(c.evaluate_at("force", **ex), P, 1e-25)
        if kind == "evaluate":
            return close(c.evaluate("force", **fl).value, P, 1e-13)
        if kind == "evalf":
            return close(c.derivation("force").evalf(**ex), P, 1e-25)
        if kind == "numpy":
            return close(c.to_numeric("force")(**fl), P, 1e-13)
        if kind == "mpmath":
            return close(c.to_numeric("force", "mpmath")(**ex), P, 1e-25)
        if kind == "pressure":
            return close(c.evaluate_at("pressure", x=sp.Rational(3, 10), **ex), p, 1e-15)
        if kind == "half_width":
            load = sp.Float(mpmath.nstr(P, 40), 40)     # (an mpf load is read through float: item 1's converter)
            return close(c.half_width(load, **{name: sp.Rational(3, 2), "E_star": 1}), sp.Rational(4, 5), 1e-20)
    return run


for _n in NAMES:
    for _k in ("pressure_closed", "evaluate_at", "evaluate", "evalf", "numpy", "mpmath", "pressure", "half_width"):
        CASES.append(("2 user symbols", f"{_k}[{_n}]", (lambda n=_n, k=_k: _entry(k)(n))))


@case("2 user symbols")
def stick_half_width_positive_F():
    F, m = sp.Symbol("F", positive=True), sp.Symbol("m", positive=True)
    d = lcs.parabola(verify=False).tangential(m).stick_half_width(F)
    if not d.closed_form or isinstance(d.expr, sp.Eq):
        return False
    with mpmath.workdps(40):
        P = lambda v: force_ref(lambda s: s, v)   # noqa: E731
        target = P(1) - mpmath.mpf("0.1") / mpmath.mpf("0.3")
        ref = mpmath.findroot(lambda v: P(v) - target, mpmath.mpf("0.7"))
    return close(d.evalf(F=sp.Rational(1, 10), a=1, R=1, E_star=1, m=sp.Rational(3, 10)), ref, 1e-25)


@case("2 user symbols")
def stick_half_width_positive_Q():
    Q = sp.Symbol("Q", positive=True)
    d = lcs.parabola(verify=False).tangential().stick_half_width(Q)
    return d.closed_form and not isinstance(d.expr, sp.Eq)


@case("2 user symbols")
def stick_half_width_assumption_free():
    G = sp.Symbol("G")
    d = lcs.parabola(verify=False).tangential().stick_half_width(G)
    return d.closed_form and d.expr.has(sp.Abs(G))


# ------------------------------------------------------------------ item 3: conditional results
CASED = sp.Piecewise((x**2 / (2 * lcs.R), lcs.R < 1), (x**2, True))
_cased = []


def cased():
    if not _cased:
        _cased.append(lcs.LineContact(CASED, points=2))
    return _cased[0]


Q4 = sp.Rational(1, 4)
PI = mpmath.pi


def _c3(fn):
    CASES.append(("3 conditional results", fn.__name__, fn))
    return fn


@_c3
def cased_evaluate_at():
    return close(cased().evaluate_at("force", a=1, R=Q4, E_star=1), force_ref(lambda t: 4 * t, 1), 1e-25)


@_c3
def cased_evaluate():
    return close(cased().evaluate("force", a=1, R=0.25, E_star=1).value, PI, 1e-13)


@_c3
def cased_evalf():
    return close(cased().derivation("force").evalf(a=1, R=Q4, E_star=1), PI, 1e-25)


@_c3
def cased_numpy_check():
    return close(cased().to_numeric("force")(a=1.0, R=0.25, E_star=1.0), PI, 1e-13)


@_c3
def cased_numpy_nocheck():
    return close(cased().to_numeric("force", check=False)(a=1.0, R=0.25, E_star=1.0), PI, 1e-13)


@_c3
def cased_mpmath_nocheck():
    return close(cased().to_numeric("force", "mpmath", check=False)(a=1, R=Q4, E_star=1), PI, 1e-25)


@_c3
def cased_other_case():
    return close(cased().evaluate_at("force", a=1, R=2, E_star=1), force_ref(lambda t: 2 * t, 1), 1e-25)


@_c3
def cased_half_width():
    return close(cased().half_width(sp.pi, R=Q4, E_star=1), 1, 1e-20)


@_c3
def cased_pressure():
    ref = pressure_ref(lambda t: 4 * t, lambda t: 4, 1, sp.Rational(1, 2))
    return close(cased().evaluate_at("pressure", a=1, x=sp.Rational(1, 2), R=Q4, E_star=1), ref, 1e-15)


@_c3
def cased_tangential_state():
    st = cased().tangential().state(sp.Rational(1, 2), a=1, R=Q4, E_star=1, mu=sp.Rational(1, 2))
    with mpmath.workdps(30):
        ref = mpmath.findroot(lambda v: force_ref(lambda s: 4 * s, v) - (PI - 1), mpmath.mpf("0.8"))
    return close(st.c, ref, 1e-20)


@_c3
def cased_pull_off():
    po = cased().adhesive(sp.Rational(1, 10)).pull_off_at(R=Q4, E_star=1)
    with mpmath.workdps(40):
        a_ref = (mpmath.sqrt(2 * PI / 10) / (4 * PI))**(mpmath.mpf(2) / 3)
        P = force_ref(lambda s: 4 * s, a_ref) - mpmath.sqrt(2 * PI * a_ref / 10)
    return close(po.force, P, 1e-25)


@_c3
def cased_stress_surface():
    ref = pressure_ref(lambda t: 4 * t, lambda t: 4, 1, sp.Rational(1, 2))
    v = cased().stresses().evaluate_at("sigma_z", dps=20, a=1, x=sp.Rational(1, 2), z=0,
                                       R=Q4, E_star=1)
    return close(v, -ref, 1e-12)


_cyl = []


def cyl():
    if not _cyl:
        _cyl.append(lcs.exact_cylinder(verify=False))
    return _cyl[0]


OUT = dict(a=2, R=1, E_star=1)
for _name, _fn in {
    "cylinder_evalf_a_gt_R": lambda: refused(lambda: cyl().derivation("force").evalf(**OUT)),
    "cylinder_evaluate_at_a_gt_R": lambda: refused(lambda: cyl().evaluate_at("force", **OUT)),
    "cylinder_evaluate_a_gt_R": lambda: refused(lambda: cyl().evaluate("force", **OUT)),
    "cylinder_numpy_nocheck_nan": lambda: bool(np.isnan(cyl().to_numeric("force", check=False)(a=2.0, R=1.0,
                                                                                            E_star=1.0))),
    "cylinder_mpmath_nocheck_nan": lambda: bool(mpmath.isnan(cyl().to_numeric("force", "mpmath",
                                                                              check=False)(**OUT))),
    "cylinder_pressure_evalf": lambda: refused(lambda: cyl().derivation("pressure").evalf(x=sp.Rational(1, 2), **OUT)),
    "cylinder_state": lambda: refused(lambda: cyl().tangential().state(0.1, mu=0.3, **OUT)),
    "cylinder_unload": lambda: refused(lambda: cyl().tangential().unload(0.1, 0.05, mu=0.3, **OUT)),
    "cylinder_reload": lambda: refused(lambda: cyl().tangential().reload(0.1, 0.05, mu=0.3, **OUT)),
    "cylinder_cycle": lambda: refused(lambda: cyl().tangential().cycle(0.1, mu=0.3, **OUT)),
    "cylinder_stress_evaluate_at": lambda: refused(lambda: cyl().stresses().evaluate_at(
        "sigma_x", x=sp.Rational(1, 10), z=sp.Rational(1, 5), **OUT)),
    "cylinder_stress_maximum": lambda: refused(lambda: cyl().stresses().maximum("von_mises", nu=0.3, **OUT)),
    "cylinder_tangential_force_at": lambda: refused(lambda: cyl().tangential().evaluate_at(
        "tangential_force", c_s=sp.Rational(1, 2), mu=sp.Rational(3, 10), **OUT)),
}.items():
    CASES.append(("3 conditional results", _name, _fn))


# ------------------------------------------------------------------ item 4: physical ranges
_par = []


def par():
    if not _par:
        _par.append(lcs.parabola(verify=False))
    return _par[0]


H = dict(a=1, R=1, E_star=1)


def _sy(nu):   # sigma_y on the surface at x = 1/10: -2 nu p(x) = -nu sqrt(0.99)
    v = par().stresses().evaluate_at("sigma_y", dps=20, x=sp.Rational(1, 10), z=0, nu=nu, **H)
    with mpmath.workdps(30):
        return close(v, -mpmath.mpf(nu) * mpmath.sqrt(mpmath.mpf("0.99")), 1e-15)


for _name, _fn in {
    "nu_0_valid": lambda: _sy(0),
    "nu_half_valid": lambda: _sy(sp.Rational(1, 2)),
    "nu_negative_valid": lambda: _sy(-sp.Rational(1, 2)),
    "nu_0_construct": lambda: par().stresses(nu=0) is not None,
    "nu_0.7_construct": lambda: refused(lambda: par().stresses(nu=0.7)),
    "nu_0.7_evaluate": lambda: refused(lambda: par().stresses().evaluate_at("sigma_y", x=0.1, z=0.3, nu=0.7, **H)),
    "nu_-1_evaluate": lambda: refused(lambda: par().stresses().evaluate_at("sigma_y", x=0.1, z=0.3, nu=-1, **H)),
    "mu_0_construct": lambda: refused(lambda: par().tangential(0)),
    "mu_negative_construct": lambda: refused(lambda: par().tangential(-0.3)),
    "mu_negative_evaluate": lambda: refused(lambda: par().tangential().evaluate_at(
        "tangential_force", a=1, c_s=0.5, mu=-0.3, R=1, E_star=1)),
    "mu_negative_state": lambda: refused(lambda: par().tangential().state(0.1, mu=-0.3, **H)),
    "mu_negative_sliding": lambda: refused(lambda: par().stresses("sliding", mu=-1)),
    "c_s_above_a": lambda: refused(lambda: par().tangential().evaluate_at(
        "tangential_force", a=1, c_s=1.5, mu=0.3, R=1, E_star=1)),
    "c_r_below_c_s": lambda: refused(lambda: par().tangential().evaluate_at(
        "unloading_force", a=1, c_s=0.5, c_r=0.3, mu=0.3, R=1, E_star=1)),
    "stick_above_a_stresses": lambda: refused(lambda: par().stresses("partial_slip", stick=2, mu=0.3).field(**H)),
    "cycle_points_1": lambda: refused(lambda: par().tangential().cycle(0.1, points=1, mu=0.3, **H)),
    "cycle_points_0": lambda: refused(lambda: par().tangential().cycle(0.1, points=0, mu=0.3, **H)),
    "cycle_points_2": lambda: np.isfinite(par().tangential().cycle(0.1, points=2, mu=0.3, **H).W),
    "surface_z_0": lambda: close(par().stresses().evaluate_at("sigma_z", x=sp.Rational(1, 10), z=0, **H),
                                 lambda: -pressure_ref(lambda t: t, lambda t: 1, 1, sp.Rational(1, 10)), 1e-25),
    "z_negative": lambda: refused(lambda: par().stresses().evaluate_at("sigma_z", x=0.1, z=-0.1, **H)),
}.items():
    CASES.append(("4 physical ranges", _name, _fn))


# ------------------------------------------------------------------ item 7: the cache
def _cache_case(fn):
    CASES.append(("7 cache", fn.__name__, fn))
    return fn


@_cache_case
def planted_record_never_runs():
    import hashlib
    from linecontact_sym.method import store
    d = tempfile.mkdtemp()
    os.environ[store.CACHE_ENV] = d
    store.clear_memory()
    canary = os.path.join(d, "pwned")
    key = store.make_key("sweep", x**2)
    import pickle

    class Evil:
        def __reduce__(self):
            return (os.system, (f"touch {canary}",))
    for payload in (pickle.dumps({"key": key, "expr": Evil()}),
                    json.dumps({"dict": [["key", key], ["expr", {"sympy": f"__import__('os').system('touch {canary}')"}]]}
                               ).encode()):
        for magic in (b"linecontact_sym-derivation-cache 1\n", getattr(store, "_MAGIC", b"")):
            data = magic + hashlib.sha256(payload).hexdigest().encode() + b"\n" + payload
            for suffix in (".pickle", ".json"):
                p = os.path.join(d, key[:2], key + suffix)
                os.makedirs(os.path.dirname(p), exist_ok=True)
                with open(p, "wb") as fh:
                    fh.write(data)
            store.clear_memory()
            store.get(key)
    return not os.path.exists(canary)


@_cache_case
def world_writable_dir_not_used():
    from linecontact_sym.method import store
    d = tempfile.mkdtemp()
    os.chmod(d, 0o777)
    os.environ[store.CACHE_ENV] = d
    store.clear_memory()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        store.put(store.make_key("sweep-ww", x**3), {"value": 1})
    return not any(f for _, _, fs in os.walk(d) for f in fs)


@_cache_case
def key_covers_contacts():
    from pathlib import Path
    from linecontact_sym.method import store
    read = []
    orig = Path.read_bytes
    Path.read_bytes = lambda self: (read.append(self.as_posix()), orig(self))[1]
    try:
        store._state["version"] = None
        store.code_version()
    finally:
        Path.read_bytes = orig
    return any(r.endswith("contacts/normal/contact.py") for r in read)


# ------------------------------------------------------------------ item 9: claims and CLI
def _cli(argv):
    from linecontact_sym import cli
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        return cli.main(argv)


_tmp = tempfile.mkdtemp()
_afile = os.path.join(_tmp, "a-file")
open(_afile, "w").close()
for _name, _argv, _want in (
        ("paper_out_is_file", ["paper", "popov2017", "--out", _afile, "--quiet", "--only", "Eq. (13)"], (2,)),
        ("paper_out_under_file", ["paper", "popov2017", "--out", _afile + "/sub", "--quiet", "--only", "Eq. (13)"], (2,)),
        ("table_n_1e400", ["table", "power-law", "--n", "1e400"], (2,)),
        ("table_n_1e-400", ["table", "power-law", "--n", "1e-400"], (2,)),
        ("table_n_sqrt2", ["table", "power-law", "--n=sqrt(2)"], (0, 2)),
        ("table_n_oo", ["table", "power-law", "--n=oo"], (2,)),
        ("table_n_I", ["table", "power-law", "--n=I"], (2,))):
    CASES.append(("9 claims and CLI", _name, (lambda a=_argv, w=_want: _cli(a) in w)))


@case("9 claims and CLI")
def printed_float_keeps_digits():
    from linecontact_sym.claims.spec import load_paper
    f = os.path.join(_tmp, "t.toml")
    with open(f, "w") as fh:
        fh.write('key = "t"\ntitle = "t"\n[[claims]]\nlabel = "c"\nquantity = "force"\nprofile = "x**2/(2*R)"\n'
                 'formula = -0.08090\nrounding = "printed"\n')
    form = load_paper(f).claims[0].forms[-1]
    return sorted(float(v) for v in form.variants) == [-0.080905, -0.080895]


@case("9 claims and CLI")
def printed_every_constant_varied():
    from linecontact_sym.claims.spec import printed_variants
    text = "+".join(f"0.{k}1*x**{k}" for k in range(1, 9))
    vs = printed_variants(text)
    return all(any(f"0.{k}05*x**{k}" in v for v in vs) for k in range(1, 9))


# ------------------------------------------------------------------ run
def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--json", help="write the per-case results here")
    ap.add_argument("--timeout", type=int, default=60)
    args = ap.parse_args()
    signal.signal(signal.SIGALRM, _alarm)
    out = {}
    t_all = time.perf_counter()
    for group, name, fn in CASES:
        t0 = time.perf_counter()
        signal.alarm(args.timeout)
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                ok = bool(fn())
            why = "" if ok else "wrong result"
        except Timeout:
            ok, why = False, f"no answer within {args.timeout} s"
        except Exception as exc:   # noqa: BLE001
            ok, why = False, f"{type(exc).__name__}: {str(exc)[:120]}"
        finally:
            signal.alarm(0)
        out[f"{group} | {name}"] = {"ok": ok, "why": why, "seconds": round(time.perf_counter() - t0, 2)}
        print(f"{'ok  ' if ok else 'FAIL'} {group:24s} {name:40s} {time.perf_counter() - t0:6.1f} s  {why}",
              flush=True)
    summary(out, 24, t_all, args.json)


if __name__ == "__main__":
    sys.exit(main())
