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
import threading

import mpmath
import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.core import precision

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
