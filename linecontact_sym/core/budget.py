"""Run symbolic work under a wall-clock budget.

SymPy computations cannot be interrupted from another thread, so a step that
may run long is executed in a forked child process that is killed when its
budget runs out.  Results come back pickled (SymPy objects pickle, Dummy
symbols keep their identity).  On platforms without ``fork`` the work runs
in-process and the budget is not enforced (documented limitation).
"""
from __future__ import annotations

import multiprocessing as _mp
import os
import pickle
import traceback

from .errors import BudgetExceeded

#: Default time budget, in seconds, for the derivation of one quantity.
DEFAULT_BUDGET = 20.0

_HAS_FORK = "fork" in _mp.get_all_start_methods()


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


def run_with_budget(fn, *args, seconds: float = DEFAULT_BUDGET, **kwargs):
    """Call ``fn(*args, **kwargs)`` and return its result, or raise
    :class:`BudgetExceeded` after ``seconds`` of wall-clock time.

    Exceptions raised by ``fn`` are re-raised in the caller.
    """
    if seconds is None or not _HAS_FORK or os.environ.get("LINECONTACT_SYM_NO_FORK"):
        return fn(*args, **kwargs)
    ctx = _mp.get_context("fork")
    recv, send = ctx.Pipe(duplex=False)
    proc = ctx.Process(target=_child, args=(send, fn, args, kwargs), daemon=True)
    proc.start()
    send.close()
    try:
        if not recv.poll(max(float(seconds), 0.0)):
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
