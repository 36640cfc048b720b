"""mpmath's global context never changes (issue 19 item 6), also when the
first derivations of one contact run in several threads at once.

The cause found: SymPy changes mpmath's global precision by itself
(``nsimplify`` sets ``mp.dps``, inside the simplification of a derivation's
conditions; ``Function._eval_evalf`` runs in ``mpmath.workprec``).  Done
outside the package's precision lock, such a change in one thread saves
another thread's raised precision (a ``workdps(30)`` of an evaluation) and
restores it after that thread has left its block: ``mp.dps`` stays at 30.
The fix: the package's symbolic work runs under the lock
(``core.precision.serialized``).

``test_every_precision_change_is_under_the_lock`` is deterministic: a spy on
mpmath's precision setters records every change made while the current
thread does not hold the lock.  Before the fix it records the nsimplify of
``tidy_conditions``; the threaded test shows the symptom itself.
"""
from __future__ import annotations

import itertools
import sys
import threading

import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from independent_refs import parabola_force
from linecontact_sym.core import precision
from linecontact_sym.core.precision import workdps

_fresh = itertools.count(1)


def _fresh_contact():
    """A contact no test derived before (the session's derivation cache
    would serve an old one without any symbolic work)."""
    k = next(_fresh)
    R = sp.Symbol("R", positive=True)
    return lcs.LineContact(lcs.x**2 / (2 * R) + lcs.x**4 * sp.Rational(k, 97 + k) / R**3, verify=True)


@pytest.fixture
def unlocked_changes(monkeypatch):
    """Every change of mpmath's precision made while the calling thread does
    not hold the package's precision lock: (thread name, new prec)."""
    ctx = type(mpmath.mp)
    prec, dps = ctx.prec, ctx.dps
    seen = []

    def spy(self, bits):
        if self is mpmath.mp and not precision._LOCK._is_owned():
            seen.append((threading.current_thread().name, bits))

    def set_prec(self, v):
        spy(self, v)
        prec.fset(self, v)

    def set_dps(self, v):
        spy(self, mpmath.libmp.dps_to_prec(v))
        dps.fset(self, v)

    monkeypatch.setattr(ctx, "prec", property(prec.fget, set_prec))
    monkeypatch.setattr(ctx, "dps", property(dps.fget, set_dps))
    return seen


def test_every_precision_change_is_under_the_lock(unlocked_changes):
    c = _fresh_contact()
    for q in ("force", "pressure", "gap"):
        c.derivation(q)
    c.evaluate_at("pressure", dps=40, x=sp.sqrt(3) / 4, a=1, R=1, E_star=1)
    assert unlocked_changes == []
    assert mpmath.mp.prec == 53


def test_first_derivations_in_threads_leave_the_precision(unlocked_changes):
    """Four threads derive the quantities of one new contact and evaluate at
    30 digits at once; afterwards mpmath's precision is what it was, and no
    thread changed it outside the lock.  The values agree with the formula
    P(a) = pi E* a^2/(4R) + 3 pi E* k a^4/(4 R^3) of f = x^2/(2R) + k x^4/R^3
    (the Eq. (10) integral, term by term), computed here with mpmath."""
    before = mpmath.mp.prec
    for trial in range(3):
        c = _fresh_contact()
        k = c.profile.expr.coeff(lcs.x, 4) * lcs.R**3
        errors, values = [], {}

        def work(q):
            try:
                c.derivation(q)
                values[q] = c.evaluate_at("force", dps=30, a=sp.Rational(1, 2), R=1, E_star=1)
            except Exception as exc:  # noqa: BLE001 -- reported below
                errors.append(exc)

        threads = [threading.Thread(target=work, args=(q,), name=q)
                   for q in ("force", "pressure", "gap", "mean_pressure")]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        assert not errors, errors
        assert mpmath.mp.prec == before, f"trial {trial}: mp.dps left at {mpmath.mp.dps}"
        mp = mpmath.MPContext()            # the reference: a context of its own
        mp.dps = 50
        a = mp.mpf(1) / 2
        exact = mp.pi * a**2 / 4 + 3 * mp.pi * mp.mpf(int(k.p)) / int(k.q) * a**4 / 4
        for q, v in values.items():
            assert abs(mp.mpf(v) - exact) <= abs(exact) * mp.mpf(10)**-28, (q, v, exact)
    assert unlocked_changes == []


def test_threads_do_not_mix_precisions():
    """Four threads evaluating at 50 and 20 digits (evaluate_at, the mpmath
    export, evaluate's mpmath path): each result has the digits it asked for
    and mpmath's global precision is unchanged afterwards (before: dps-50
    results with 16-22 digits, mp.dps left at 50 or 20)."""
    c = lcs.parabola()
    fns = {d: c.to_numeric("force", backend="mpmath", dps=d) for d in (50, 20)}
    before = mpmath.mp.dps
    errors, results = [], []

    def work(dps, k):
        try:
            for i in range(40):
                a = f"0.{3 + i + k}1"
                ref = parabola_force(a, "1.3", "2.1", dps)
                got = (c.evaluate_at("force", dps=dps, a=a, R="1.3", E_star="2.1") if i % 3 == 0 else
                       fns[dps](a=a, R="1.3", E_star="2.1") if i % 3 == 1 else
                       c.evaluate("force", rtol=10.0 ** -dps, model=False, a=a, R="1.3", E_star="2.1").value)
                with workdps(dps + 10):     # the package's locked helper: this runs in threads too
                    err = abs(mpmath.mpf(got) / ref - 1)
                    results.append((dps, i % 3, float(-mpmath.log10(err + mpmath.mpf(10) ** (-dps - 5)))))
        except Exception as exc:  # noqa: BLE001 - reported below
            errors.append(exc)
    threads = [threading.Thread(target=work, args=(d, k)) for k, d in enumerate((50, 20, 50, 20))]
    interval = sys.getswitchinterval()
    sys.setswitchinterval(1e-6)           # switch threads often: interleave the precision changes
    try:
        for t in threads:
            t.start()
        for t in threads:
            t.join()
    finally:
        sys.setswitchinterval(interval)
    assert not errors, errors
    assert mpmath.mp.dps == before
    assert len(results) == 160
    low = [r for r in results if r[2] < r[0] - 2]
    assert not low, low[:5]


def test_no_bare_mpmath_precision_changes():
    """Every precision change of the package goes through the locked
    helpers of core.precision (doctests excepted)."""
    import pathlib
    import re
    root = pathlib.Path(lcs.__file__).parent
    bad = []
    for p in root.rglob("*.py"):
        if p.name == "precision.py":
            continue
        for n, line in enumerate(p.read_text().splitlines(), 1):
            if re.search(r"mpmath\.(workdps|workprec|extradps)\(|mp\.(dps|prec)\s*=[^=]", line) \
                    and ">>>" not in line and "..." not in line.lstrip()[:3]:
                bad.append(f"{p.relative_to(root)}:{n}: {line.strip()}")
    assert not bad, "\n".join(bad)
