"""Working precision that is safe in threads.

mpmath keeps its working precision in one global context, ``mpmath.mp``;
``mpmath.workdps`` sets it and restores it on exit.  Two threads that do so
at once interleave: one restores the other's precision, and a 50-digit
computation comes back with 20 digits (or ``mp.dps`` is left changed).

Every precision change of the package goes through :func:`workdps` /
:func:`workprec` here: they hold one re-entrant lock for as long as the
precision is changed, so high-precision computations of different threads
run one after the other (Python's GIL lets only one run at a time anyway),
and each sees exactly the precision it asked for.  The global precision is
never changed outside such a block, and is the same afterwards.  The lock is
re-created in a forked child (the time budget forks), where its owner thread
does not exist.

SymPy changes mpmath's precision too, by itself: ``nsimplify`` sets
``mp.dps`` (it runs inside ``Expr.equals`` and the simplification of
conditions), every ``Function._eval_evalf`` runs in ``mpmath.workprec``.
Outside the lock such a change in one thread captures another thread's raised
precision and restores it after that thread has left its block: ``mp.dps``
stays at 30.  So the package's symbolic work also runs under the lock
(:func:`serialized`: every derivation, :meth:`Contact.derivation
<linecontact_sym.contacts.base.Contact.derivation>` and
:func:`~linecontact_sym.method.derivation.derive`), and so does every SymPy
evaluation to numbers (:func:`linecontact_sym.core.conversion.evalf`).

>>> import mpmath
>>> before = mpmath.mp.dps
>>> with workdps(40):
...     mpmath.mp.dps
40
>>> mpmath.mp.dps == before
True
"""
from __future__ import annotations

import numbers
import os
import threading
from contextlib import contextmanager

import mpmath

from .errors import DomainError

#: the most significant digits a user may ask for (``evaluate(dps=...)``, ``--dps``)
MAX_DPS = 1000

_LOCK = threading.RLock()


def checked_dps(dps) -> int:
    """``dps`` as a user gives it: an integer from 1 to :data:`MAX_DPS`;
    anything else raises :class:`~linecontact_sym.core.errors.DomainError`."""
    if isinstance(dps, bool) or not isinstance(dps, numbers.Integral) or not 1 <= dps <= MAX_DPS:
        raise DomainError(f"dps must be an integer from 1 to {MAX_DPS}, got {dps!r}")
    return int(dps)


def _reinit_after_fork():
    global _LOCK
    _LOCK = threading.RLock()


if hasattr(os, "register_at_fork"):
    os.register_at_fork(after_in_child=_reinit_after_fork)


@contextmanager
def serialized():
    """Hold the package's precision lock without changing the precision:
    for symbolic work that may change mpmath's global precision for a moment
    (SymPy's nsimplify, evalf), so that no other thread is inside a
    :func:`workdps` block meanwhile."""
    with _LOCK:
        yield


@contextmanager
def workdps(dps: int):
    """``mpmath.workdps(dps)`` under the package's precision lock."""
    with _LOCK, mpmath.workdps(dps):
        yield


@contextmanager
def workprec(prec: int):
    """``mpmath.workprec(prec)`` (bits) under the package's precision lock."""
    with _LOCK, mpmath.workprec(prec):
        yield


@contextmanager
def extradps(n: int):
    """``mpmath.extradps(n)`` under the package's precision lock."""
    with _LOCK, mpmath.extradps(n):
        yield


__all__ = ["workdps", "workprec", "extradps", "serialized", "MAX_DPS", "checked_dps"]
