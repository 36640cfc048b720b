"""Run symbolic work under a wall-clock budget.

A budget is a number of seconds of wall-clock time, > 0; ``None`` or
``math.inf`` means no limit (:func:`checked_budget`).  The budget of a
derivation covers all of it: the rules, the tidying of the result and its
verification (:mod:`linecontact_sym.method.derivation` keeps one deadline).

SymPy computations cannot be interrupted from another thread, so a step that
may run long is executed in a forked child process that is killed when its
budget runs out.  Results come back pickled (SymPy objects pickle, Dummy
symbols keep their identity).  On platforms without ``fork`` the work runs
in-process and the budget is not enforced (documented limitation).
"""
from __future__ import annotations

import math
import multiprocessing as _mp
import os
import signal
import pickle
import time
import traceback

from .errors import BudgetError, BudgetExceeded
from .options import read_number

#: Default time budget, in seconds, for the derivation of one quantity.
DEFAULT_BUDGET = 20.0

_HAS_FORK = "fork" in _mp.get_all_start_methods()


def checked_budget(seconds):
    """A budget as given by a user: ``None`` or ``math.inf`` (no limit, returned
    as None) or a real number of seconds > 0 (returned as float), read by the
    one reader of numeric settings (:func:`~linecontact_sym.core.options.read_number`:
    NumPy and SymPy numbers, text such as ``" 5 "`` or ``"inf"``; a number
    too large for a float is no limit).  Anything else (NaN, 0, negative,
    text that is not a number, a bool) raises :class:`BudgetError`; so does
    every budget while ``$LINECONTACT_SYM_BUDGET`` holds a value that is not
    one (:func:`check_environment`).

    >>> checked_budget(5), checked_budget(None), checked_budget(float("inf")), checked_budget(" 2.5 ")
    (5.0, None, None, 2.5)
    """
    check_environment()
    if seconds is None:
        return None
    v = read_number(seconds, "the budget (seconds)", low=0, low_open=True, allow_inf=True, error=BudgetError)
    return None if math.isinf(v) else float(v)


#: the environment variable that replaces the default budget
BUDGET_ENV = "LINECONTACT_SYM_BUDGET"
_ENV: dict = {"problem": None}


def _budget_from_environment(default: float):
    """``$LINECONTACT_SYM_BUDGET`` (seconds > 0, or ``inf`` for no limit:
    None) replaces the default budget of a derivation, for a machine known
    to be slow or loaded (a CI worker beside other workers): a wall-clock
    budget that runs out turns a closed form into an unevaluated integral.
    A value that is not a budget is not raised at import (a command line
    could not report it): it is remembered, and :func:`check_environment`
    (called by every budget check and first by the command line) raises
    :class:`BudgetError` naming the variable."""
    text = os.environ.get(BUDGET_ENV, "")
    if not text.strip():
        return default
    try:
        value = read_number(text, BUDGET_ENV + " (seconds)", low=0, low_open=True, allow_inf=True,
                            error=BudgetError)
    except BudgetError as exc:
        _ENV["problem"] = exc
        return default
    return None if math.isinf(value) else value


def check_environment() -> None:
    """Raise :class:`BudgetError` if ``$LINECONTACT_SYM_BUDGET`` was not a budget."""
    if _ENV["problem"] is not None:
        raise BudgetError(str(_ENV["problem"]))


DEFAULT_BUDGET = _budget_from_environment(DEFAULT_BUDGET)


class Deadline:
    """One wall-clock deadline shared by the steps of a derivation:
    ``left()`` is the time that remains (None: no limit; never negative)."""

    def __init__(self, budget, start=None):
        self.budget = checked_budget(budget)
        start = time.monotonic() if start is None else start
        self.at = None if self.budget is None else start + self.budget

    def left(self):
        return None if self.at is None else max(self.at - time.monotonic(), 0.0)

    def expired(self, margin: float = 0.0) -> bool:
        return self.at is not None and self.left() <= margin


def _child(conn, fn, args, kwargs):
    try:
        result = ("ok", fn(*args, **kwargs))
    except BaseException as exc:  # sent back and re-raised in the parent
        result = ("err", exc, traceback.format_exc())
    try:
        conn.send_bytes(pickle.dumps(result))
    except Exception as exc:  # unpicklable result: report it as an error
        conn.send_bytes(pickle.dumps(("err", RuntimeError(f"unpicklable result: {exc}"), "")))
    finally:
        conn.close()
        os._exit(0)


class _Forked:
    """The child of :func:`run_with_budget` forked with ``os.fork`` where
    multiprocessing will not start one (inside a daemonic process: a process
    pool's worker, a Dask worker); the same work, the same pipe, so an
    executor never changes a result (before: every rule failed there and the
    parabola's force law came back as an unevaluated integral)."""

    def __init__(self, recv, send, fn, args, kwargs):
        self.pid = os.fork()
        if self.pid == 0:        # the child: never returns
            try:
                recv.close()
                _child(send, fn, args, kwargs)
            finally:
                os._exit(0)
        self._status = None

    def is_alive(self) -> bool:
        if self._status is None:
            pid, status = os.waitpid(self.pid, os.WNOHANG)
            if pid:
                self._status = status
        return self._status is None

    def kill(self):
        try:
            os.kill(self.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass

    def join(self):
        if self._status is None:
            self._status = os.waitpid(self.pid, 0)[1]


def run_with_budget(fn, *args, seconds: float = DEFAULT_BUDGET, **kwargs):
    """Call ``fn(*args, **kwargs)`` and return its result, or raise
    :class:`BudgetExceeded` after ``seconds`` of wall-clock time.

    Exceptions raised by ``fn`` are re-raised in the caller.
    """
    if seconds is None or math.isinf(seconds) or not _HAS_FORK or os.environ.get("LINECONTACT_SYM_NO_FORK"):
        return fn(*args, **kwargs)
    ctx = _mp.get_context("fork")
    recv, send = ctx.Pipe(duplex=False)
    if _mp.current_process().daemon:   # a pool's or a Dask worker's process: multiprocessing refuses it
        proc = _Forked(recv, send, fn, args, kwargs)   # children, a plain fork does the same work
    else:
        proc = ctx.Process(target=_child, args=(send, fn, args, kwargs), daemon=True)
        proc.start()
    send.close()
    try:
        if not recv.poll(max(float(seconds), 0.0) if seconds == seconds else 0.0):
            raise BudgetExceeded(f"{getattr(fn, '__name__', fn)} exceeded its budget of {seconds:g} s")
        try:
            payload = pickle.loads(recv.recv_bytes())
        except EOFError:
            raise BudgetExceeded(f"{getattr(fn, '__name__', fn)}: worker died without a result")
    finally:
        recv.close()
        if proc.is_alive():
            proc.kill()
        proc.join()
    if payload[0] == "ok":
        return payload[1]
    raise payload[1]
