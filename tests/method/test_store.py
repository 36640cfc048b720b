"""The derivation cache is data, never code (method/store.py): records are
read without evaluating text, huge literals are refused before anything is
built, a cache others can write is not used, a tampered record (right
checksum, wrong content) is re-checked against the independent reference and
recomputed, the key covers every source file.  Moved from
tests/test_trust_round3.py (issue 19, item 7) and tests/test_trust_round4.py
(issue 29, items 1 and 2).  The force is checked against Eq. (13),
P = pi E* a^2/(4R), typed here."""
from __future__ import annotations

import hashlib
import json
import os
import subprocess
import sys
import time
import warnings

import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from store_records import cache, rewrite_derivations  # noqa: F401 (cache: a fixture)
from linecontact_sym.method import store

x = lcs.x
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def _write_record(path, key, payload: bytes):
    data = store._MAGIC + hashlib.sha256(payload).hexdigest().encode() + b"\n" + payload
    path.parent.mkdir(parents=True, exist_ok=True, mode=0o700)
    path.write_bytes(data)
    os.chmod(path, 0o600)


def test_records_are_data_never_code(tmp_path, monkeypatch):
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


def test_a_cache_others_can_write_is_not_used(tmp_path, monkeypatch):
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


def test_the_key_covers_every_source_file(monkeypatch):
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
def test_string_arguments_never_reach_sympify(make, tmp_path):
    canary = tmp_path / "pwned"
    with pytest.raises(store.UntrustedRecord):
        store.from_srepr(make(canary))
    assert not canary.exists()


@pytest.mark.parametrize("text", HUGE)
def test_huge_literals_refused_before_anything_is_built(text):
    t0 = time.perf_counter()
    with pytest.raises(store.UntrustedRecord):
        store.from_srepr(text)
    assert time.perf_counter() - t0 < 1.0


def test_the_data_a_derivation_writes_still_reads_back():
    R, a = lcs.R, lcs.a
    for e in (sp.Piecewise((sp.atanh(x * sp.sqrt(a**2 - 1)), x < a), (0, True)), sp.Float("1.2345678901234567890123", 40),
              sp.elliptic_k(x**2 / a**2), sp.Integral(sp.sqrt(1 - x**2), (x, 0, a)), sp.gamma(sp.Rational(7, 3)),
              sp.hyper([1, 2], [3], x), sp.Interval(0, 1, True), sp.Eq(a, 2**200), -sp.pi * R**sp.Rational(-3, 2),
              sp.oo, sp.zoo, sp.Float("-1e-30"), sp.Tuple(sp.true, sp.false), sp.Abs(x - 1), sp.Max(x, 1),
              sp.factorial(sp.Integer(20)), sp.Integer(-5), sp.Rational(-3, 7)):
        assert store.from_srepr(sp.srepr(e)) == e


@pytest.mark.slow
def test_planted_records_are_ignored_and_recomputed(cache):
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
def test_the_cli_never_runs_a_planted_record(cache):
    canary = cache / "pwned"
    env = dict(os.environ, LINECONTACT_SYM_CACHE=str(cache), PYTHONPATH=ROOT)
    cmd = [sys.executable, "-m", "linecontact_sym", "eval", "x**2/(2*R)", "force", "--at", "a=0.875",
           "--set", "R=0.5", "E_star=1", "--dps", "15"]
    subprocess.run(cmd, env=env, capture_output=True, timeout=300, check=True)
    assert _rewrite(cache, "expr", lambda old: f"Tuple({_code(canary)!r})") >= 1
    r = subprocess.run(cmd, env=env, capture_output=True, timeout=300, text=True)
    assert r.returncode == 0 and not canary.exists()
    assert f"{float(HERTZ_P):.12f}"[:12] in r.stdout


@pytest.mark.slow
@pytest.mark.parametrize("tamper", [
    lambda old: f"Mul(Integer(-1), {old})",                              # the sign flipped
    lambda old: "Mul(Rational(1, 2), pi, Symbol('E_star', positive=True), "   # another profile's result
                "Pow(Symbol('a', positive=True), Integer(3)), Pow(Symbol('R', positive=True), Integer(-1)))",
    lambda old: f"Mul(Rational(1001, 1000), {old})",                     # a small change
])
def test_a_tampered_record_is_rechecked_and_recomputed(cache, tamper):
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
def test_a_record_of_unexpected_shape_is_ignored(cache):
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


@pytest.mark.slow
def test_a_tampered_half_width_record_is_rechecked(cache):
    """Records made outside derive() (the half-width a(P)) are re-checked too:
    a(P(a)) = a at a random admissible point."""
    lcs.parabola(verify=False).derivation("half_width")
    assert rewrite_derivations(cache, lambda old: f"Mul(Integer(2), {old})") == 1
    store.clear_memory()
    with pytest.warns(store.UntrustedCacheWarning, match="independent check"):
        e = lcs.parabola(verify=False).derivation("half_width").expr
    assert sp.simplify(e - 2 * sp.sqrt(lcs.P * lcs.R / (sp.pi * lcs.E_star))) == 0
