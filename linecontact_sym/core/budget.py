"""Run symbolic work under a budget of CPU seconds.

A budget is a number of **CPU seconds** > 0: the processor time of the
process doing the work, not wall-clock time, so a result does not depend on
the machine's load (a closed form found on an idle server is found on a
laptop running a video call).  ``None`` or ``math.inf`` means no limit
(:func:`checked_budget`).  The budget of a derivation covers all of it: the
rules, the tidying of the result and its verification
(:mod:`linecontact_sym.method.derivation` keeps one :class:`Deadline`).

SymPy computations cannot be interrupted from another thread, so a step that
may run long is executed in a forked child process (:func:`run_with_budget`).
The child arms a CPU-time timer (``setitimer(ITIMER_PROF)``, which counts
the user and system time of the child alone) whose signal, left at its
default action, ends the child when its budget is spent: the kernel enforces
it, even inside a long C call.  Results come back pickled (SymPy objects
pickle, Dummy symbols keep their identity).

The parent also keeps a **wall-clock guard**, only against a true hang (a
child waiting on something that uses no CPU): :func:`wall_guard` seconds
(10 x the CPU budget + 60 s).  When it fires the :class:`BudgetExceeded`
says so (``wall_guard`` attribute True, "wall-clock guard" in its message),
since such a result, unlike a spent CPU budget, may depend on the load.

A :class:`Deadline` shared by several steps counts the CPU time of this
process since it began (``time.process_time``: the in-process steps) plus
that of every child process reaped since (``getrusage(RUSAGE_CHILDREN)``:
the forked steps, with the children they reaped themselves).  Inside a
forked child, a nested :func:`run_with_budget` gets at most what remains of
the child's own budget, and the child's timer is re-armed after it.

``$LINECONTACT_SYM_BUDGET`` (CPU seconds > 0) replaces the default budget
of a derivation (:data:`DEFAULT_BUDGET`).

:func:`run_stages` runs the stages of one piece of work (a derivation's
rule, the tidying of its result and its verification) in ONE forked child,
each with what remains of the one budget, as separate calls of
:func:`run_with_budget` would give it: the same results, one fork instead
of three, and every stage finds SymPy's caches warm from the one before.

Work done ahead (:class:`Ahead`): values that a stage will need and that do
not depend on the stages before it (a verification's references at its
sample points, which are drawn before the closed form is known) are
computed in a SECOND forked child, concurrently with the first (the rule
and its tidying): on two cores the wall time is the larger of the two, not
their sum.  The budget stays one budget of CPU seconds, and results stay
independent of the load, by this rule: each value comes with the CPU
seconds the second child spent on it, and the stage that takes it
*charges* them to its own budget (:meth:`Deadline.charge`; its CPU timer
re-armed with what remains, a charge past the budget ending it as its
timer would).  A stage so uses the CPU time it would have used doing the
work itself, whichever child did it and however the two were scheduled; a
value not there yet is waited for (no CPU), never computed again, so the
order of events does not change a result either.  The second child runs
under what remained of the budget when it began; values never taken (no
closed form found, a point the conditions exclude) are CPU time of the
second child, counted by the parent's :class:`Deadline` once it is reaped.
The second child is made only where a core is idle (:func:`forks`); where
none is, the first child does the work itself, with the same results.

On platforms without ``fork`` the work runs in-process and the budget is not
enforced (documented limitation).
"""
from __future__ import annotations

import gc
import math
import multiprocessing as _mp
import multiprocessing.connection  # noqa: F401  (Ahead's pipe)
import os
import signal
import pickle
import time
import traceback

from .errors import BudgetError, BudgetExceeded
from .options import read_number

try:
    import resource as _resource
except ImportError:   # no resource module (Windows): children's CPU time is not counted (no fork there either)
    _resource = None

#: Default budget, in CPU seconds, for the derivation of one quantity.
DEFAULT_BUDGET = 20.0

_HAS_FORK = "fork" in _mp.get_all_start_methods()

#: the wall-clock guard against a hang: WALL_GUARD_FACTOR x the CPU budget + WALL_GUARD_EXTRA seconds
WALL_GUARD_FACTOR = 10.0
WALL_GUARD_EXTRA = 60.0


def checked_budget(seconds, text: bool = False):
    """A budget as given by a user: ``None`` or ``math.inf`` (no limit, returned
    as None) or a real number of CPU seconds > 0 (returned as float), read by the
    one reader of numeric settings (:func:`~linecontact_sym.core.options.read_number`:
    NumPy and SymPy numbers, text such as ``" 5 "`` or ``"inf"``; a number
    too large for a float is no limit).  Anything else (NaN, 0, negative,
    text that is not a number, a bool) raises :class:`BudgetError`; so does
    every budget while ``$LINECONTACT_SYM_BUDGET`` holds a value that is not
    one (:func:`check_environment`).

    >>> checked_budget(5), checked_budget(None), checked_budget(float("inf")), checked_budget(" 2.5 ", text=True)
    (5.0, None, None, 2.5)
    """
    check_environment()
    if seconds is None:
        return None
    if isinstance(seconds, (str, bytes)) and not text:     # the API takes numbers; text is the CLI's (text=True)
        raise BudgetError(f"the CPU-time budget must be a number of seconds > 0 (or None / math.inf for no "
                          f"limit), got the text {seconds!r}")
    v = read_number(seconds, "the CPU-time budget", low=0, low_open=True, allow_inf=True, error=BudgetError,
                    what="a number of seconds")
    return None if math.isinf(v) else float(v)


#: the environment variable that replaces the default budget
BUDGET_ENV = "LINECONTACT_SYM_BUDGET"
_ENV: dict = {"problem": None}


def _budget_from_environment(default: float):
    """``$LINECONTACT_SYM_BUDGET`` (CPU seconds > 0, or ``inf`` for no limit:
    None) replaces the default budget of a derivation, for a slow machine
    (or to allow a hard integral more time); a machine's load does not
    matter, the budget being CPU time.
    A value that is not a budget is not raised at import (a command line
    could not report it): it is remembered, and :func:`check_environment`
    (called by every budget check and first by the command line) raises
    :class:`BudgetError` naming the variable."""
    text = os.environ.get(BUDGET_ENV, "")
    if not text.strip():
        return default
    try:
        value = read_number(text, BUDGET_ENV + " (CPU seconds)", low=0, low_open=True, allow_inf=True,
                            error=BudgetError, what="a number of seconds")
    except BudgetError as exc:
        _ENV["problem"] = exc
        return default
    return None if math.isinf(value) else value


def check_environment() -> None:
    """Raise :class:`BudgetError` if ``$LINECONTACT_SYM_BUDGET`` was not a budget."""
    if _ENV["problem"] is not None:
        raise BudgetError(str(_ENV["problem"]))


DEFAULT_BUDGET = _budget_from_environment(DEFAULT_BUDGET)


def children_cpu_time() -> float:
    """CPU seconds (user + system) of the child processes of this process
    reaped so far (with what they reaped themselves); 0 where unknown."""
    if _resource is None:
        return 0.0
    ru = _resource.getrusage(_resource.RUSAGE_CHILDREN)
    return ru.ru_utime + ru.ru_stime


def cpu_time() -> float:
    """CPU seconds of this process and of its reaped children: the work
    done, whichever process did it."""
    return time.process_time() + children_cpu_time()


def wall_guard(seconds) -> float:
    """The wall-clock seconds after which a child with a CPU budget of
    ``seconds`` is taken for hung and killed."""
    return WALL_GUARD_FACTOR * float(seconds) + WALL_GUARD_EXTRA


class Deadline:
    """One budget of CPU seconds shared by the steps of a derivation:
    ``used()`` the CPU time since it began (this process and the children
    it reaped since), ``left()`` what remains (None: no limit; never
    negative)."""

    def __init__(self, budget):
        self.budget = checked_budget(budget)
        self.start = cpu_time()
        self.charged = 0.0

    def used(self) -> float:
        return cpu_time() - self.start + self.charged

    def charge(self, seconds: float) -> None:
        """Count ``seconds`` of CPU time spent elsewhere on this work (a
        value done ahead by another child, :class:`Ahead`)."""
        self.charged += max(float(seconds), 0.0)

    def left(self):
        return None if self.budget is None else max(self.budget - self.used(), 0.0)

    def expired(self, margin: float = 0.0) -> bool:
        return self.budget is not None and self.left() <= margin


#: inside a forked child of run_with_budget: its own Deadline (nested calls get at most what remains)
_IN_CHILD: dict = {"deadline": None}


def child_left():
    """CPU seconds left to the forked child this runs in (None: not in one,
    or no limit)."""
    d = _IN_CHILD["deadline"]
    return None if d is None else d.left()


def _arm(seconds):
    """Arm this process's CPU-time timer (ITIMER_PROF: user + system time of
    the process); its signal, at its default action, ends the process.
    Where there is no such timer (or signals cannot be set here), nothing:
    only the wall-clock guard remains."""
    try:
        signal.signal(signal.SIGPROF, signal.SIG_DFL)
        signal.setitimer(signal.ITIMER_PROF, max(float(seconds), 1e-3))
    except (AttributeError, OSError, ValueError):
        pass


def _disarm():
    try:
        signal.setitimer(signal.ITIMER_PROF, 0)
    except (AttributeError, OSError, ValueError):
        pass


def _child(conn, fn, args, kwargs, seconds):
    try:
        # The objects inherited from the parent are never garbage here (the
        # child ends with os._exit): moved to the collector's permanent
        # generation, no collection of the child walks them.  A walk writes
        # every object's header, copying the parent's memory page by page
        # (copy-on-write) at each full collection: tens of ms per child.
        gc.freeze()
        _IN_CHILD["deadline"] = Deadline(seconds)
        _arm(seconds)
        try:
            result = ("ok", fn(*args, **kwargs))
        except BaseException as exc:  # sent back and re-raised in the parent
            result = ("err", exc, traceback.format_exc())
        _disarm()                     # pickling and sending the result is not the work budgeted
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

    def __init__(self, recv, send, fn, args, kwargs, seconds):
        self.pid = os.fork()
        if self.pid == 0:        # the child: never returns
            try:
                recv.close()
                _child(send, fn, args, kwargs, seconds)
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

    @property
    def exitcode(self):
        """As multiprocessing's: -N for a child ended by signal N."""
        if self._status is None:
            return None
        return -os.WTERMSIG(self._status) if os.WIFSIGNALED(self._status) else os.WEXITSTATUS(self._status)


def _exceeded(fn, seconds, *, guard=None):
    name = getattr(fn, "__name__", fn)
    if guard is None:
        return BudgetExceeded(f"{name} exceeded its budget of {seconds:g} CPU s")
    exc = BudgetExceeded(f"{name} did not finish within the wall-clock guard of {guard:g} s against a hang "
                         f"(its CPU budget was {seconds:g} s): the wall-clock guard fired")
    exc.wall_guard = True
    return exc


def _no_result(fn, seconds, proc):
    """The error of a child that sent no result: its CPU timer's signal (the
    budget spent), or it died otherwise."""
    if proc.exitcode in (-signal.SIGPROF, -getattr(signal, "SIGXCPU", signal.SIGPROF)):
        return _exceeded(fn, seconds)
    return BudgetExceeded(f"{getattr(fn, '__name__', fn)}: worker died without a result "
                          f"(exit code {proc.exitcode})")


def _within_outer(seconds):
    """``seconds`` cut to what remains of the budget of the child this runs
    in (if any): a nested budget never outlasts its parent's."""
    outer = _IN_CHILD["deadline"]
    if outer is not None and outer.budget is not None:
        left = max(outer.left(), 1e-3)
        seconds = left if seconds is None or math.isinf(seconds) else min(float(seconds), left)
    return seconds


def _reap(proc, recv):
    """Close the pipe, end and join the child; inside a budgeted child, re-arm
    its own CPU timer with what remains after the grandchild's work."""
    recv.close()
    if proc.is_alive():
        proc.kill()
    proc.join()
    outer = _IN_CHILD["deadline"]
    if outer is not None and outer.budget is not None:
        _arm(outer.left())


def run_with_budget(fn, *args, seconds: float = DEFAULT_BUDGET, **kwargs):
    """Call ``fn(*args, **kwargs)`` in a forked child and return its result,
    or raise :class:`BudgetExceeded` once the child has used ``seconds`` of
    CPU time (or, against a true hang, after :func:`wall_guard` seconds of
    wall-clock time: the exception's ``wall_guard`` is then True).

    Inside another budgeted child, ``seconds`` is cut to what remains of
    that child's budget.  Exceptions raised by ``fn`` are re-raised in the
    caller.
    """
    seconds = _within_outer(seconds)
    if seconds is None or math.isinf(seconds) or not _HAS_FORK or os.environ.get("LINECONTACT_SYM_NO_FORK"):
        return fn(*args, **kwargs)
    seconds = max(float(seconds), 1e-3) if seconds == seconds else 1e-3
    ctx = _mp.get_context("fork")
    recv, send = ctx.Pipe(duplex=False)
    if _mp.current_process().daemon:   # a pool's or a Dask worker's process: multiprocessing refuses it
        proc = _Forked(recv, send, fn, args, kwargs, seconds)   # children, a plain fork does the same work
    else:
        proc = ctx.Process(target=_child, args=(send, fn, args, kwargs, seconds), daemon=True)
        proc.start()
    send.close()
    payload = None
    try:
        guard = wall_guard(seconds)
        if not recv.poll(guard):
            raise _exceeded(fn, seconds, guard=guard)
        try:
            payload = pickle.loads(recv.recv_bytes())
        except EOFError:
            payload = None
    finally:
        _reap(proc, recv)
    if payload is None:
        raise _no_result(fn, seconds, proc)
    if payload[0] == "ok":
        return payload[1]
    raise payload[1]


def _stages_child(conn, stages, args, seconds, margin):
    """The child of :func:`run_stages`: each stage's result sent as soon as it
    is there (the timer disarmed while it is pickled and sent; the value
    pickled on its own, so that the parent unpickles only the results it
    reads: :class:`Packed`), the next stage begun only with more than
    ``margin`` CPU seconds left; the first stage's exception is sent back, a
    later stage's ends the work (``("stop",)``)."""
    try:
        gc.freeze()                       # as in _child: no collection walks the parent's objects
        deadline = _IN_CHILD["deadline"] = Deadline(seconds)
        value = None
        for k, stage in enumerate(stages):
            if k and deadline.left() <= margin:
                break
            if k:
                conn.send_bytes(pickle.dumps(("start", k)))
            _arm(deadline.left())
            ok = True
            try:
                value = stage(*args) if k == 0 else stage(value)
            except BaseException as exc:
                ok, msg = False, (("err", exc, traceback.format_exc()) if k == 0 else ("stop",))
            _disarm()
            try:
                if ok:
                    msg = ("ok", pickle.dumps(value))
                conn.send_bytes(pickle.dumps(msg))
            except Exception as exc:
                conn.send_bytes(pickle.dumps(("err", RuntimeError(f"unpicklable result: {exc}"), "") if k == 0
                                             else ("stop",)))
                break
            if msg[0] != "ok":
                break
    finally:
        conn.close()
        os._exit(0)


class Packed:
    """A stage's result as :func:`run_stages` (``lazy=True``) returns it:
    unpickled on the first :meth:`load` only (a derivation reads the result
    of its last stage and rarely the rule's raw expression before tidying,
    whose unpickling rebuilds every SymPy node: hypergeometric functions
    cost the parent about 0.05 CPU s each)."""

    __slots__ = ("_data", "_value")
    _EMPTY = object()

    def __init__(self, data: bytes | None = None, value=_EMPTY):
        self._data, self._value = data, value

    def load(self):
        if self._value is Packed._EMPTY:
            self._value, self._data = pickle.loads(self._data), None
        return self._value


def run_stages(stages, *args, seconds: float = DEFAULT_BUDGET, margin: float = 0.05, lazy: bool = False) -> list:
    """The stages of one piece of work in ONE forked child under one budget of
    ``seconds`` CPU seconds: ``stages[0](*args)``, then ``stages[k](result of
    stage k-1)``.  Returns ``(results, started)``: the results of the stages
    that finished, in order (at least the first), and how many stages were
    begun.  A stage the budget ended (begun, no result), or that raised, and
    the stages after it are missing, for the caller to do otherwise; a stage
    is begun only with more than ``margin`` CPU seconds left.  The first
    stage behaves as :func:`run_with_budget` (its exception re-raised, its
    spent budget a :class:`BudgetExceeded`).  What each stage may use is what
    :func:`run_with_budget` called for it in turn would give it (what remains
    of ``seconds``), so results do not change, but one fork serves them all
    and each stage finds SymPy's caches warm from the stage before (a
    derivation's rule, tidying and verification: issue 26).  ``lazy``: each
    result comes as a :class:`Packed`, unpickled when the caller loads it."""
    seconds = _within_outer(seconds)
    if seconds is None or math.isinf(seconds) or not _HAS_FORK or os.environ.get("LINECONTACT_SYM_NO_FORK") \
            or _mp.current_process().daemon:
        # in-process (no limit, no fork) or a pool's worker: each stage as run_with_budget runs it
        deadline = Deadline(seconds)
        out = [run_with_budget(stages[0], *args, seconds=seconds)]
        for stage in stages[1:]:
            if deadline.expired(margin):
                break
            try:
                out.append(run_with_budget(stage, out[-1], seconds=deadline.left()))
            except Exception:
                return _packed(out, lazy), len(out) + 1
        return _packed(out, lazy), len(out)
    seconds = max(float(seconds), 1e-3) if seconds == seconds else 1e-3
    ctx = _mp.get_context("fork")
    recv, send = ctx.Pipe(duplex=False)
    proc = ctx.Process(target=_stages_child, args=(send, stages, args, seconds, margin), daemon=True)
    proc.start()
    send.close()
    out, first, started = [], None, 1
    try:
        guard = wall_guard(seconds)
        while True:
            if not recv.poll(guard):
                if not out:
                    raise _exceeded(stages[0], seconds, guard=guard)
                break
            try:
                msg = pickle.loads(recv.recv_bytes())
            except EOFError:
                break
            if msg[0] == "ok":
                out.append(Packed(msg[1]) if lazy else pickle.loads(msg[1]))
                continue
            if msg[0] == "start":
                started = msg[1] + 1
                continue
            if msg[0] == "err":
                first = msg[1]
            break
    finally:
        _reap(proc, recv)
    if first is not None:
        raise first
    if not out:
        raise _no_result(stages[0], seconds, proc)
    return out, started


def _packed(values, lazy):
    return [Packed(value=v) for v in values] if lazy else values


def charge_child(seconds: float) -> None:
    """Charge ``seconds`` of CPU time done elsewhere (:class:`Ahead`) to the
    budget of the forked child this runs in: its CPU timer is re-armed with
    what remains; with nothing left the child ends as its timer would end
    it (SIGPROF at its default action).  Outside a budgeted child: nothing."""
    d = _IN_CHILD["deadline"]
    if d is None:
        return
    d.charge(seconds)
    if d.budget is None:
        return
    left = d.left()
    if left <= 0:
        signal.signal(signal.SIGPROF, signal.SIG_DFL)
        os.kill(os.getpid(), signal.SIGPROF)
    _arm(left)


def _cores() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def _idle_core() -> bool:
    """A core idle now: the processes running on the machine, this one
    included, fewer than its cores (Linux: the running count of
    ``/proc/loadavg``, at this instant; elsewhere the 1-minute load average
    below the number of cores)."""
    cores = _cores()
    if cores < 2:
        return False
    try:
        with open("/proc/loadavg") as fh:
            return int(fh.read().split()[3].split("/")[0]) < cores
    except (OSError, ValueError, IndexError):
        pass
    try:
        return os.getloadavg()[0] < cores
    except (AttributeError, OSError):
        return True


def forks(seconds) -> bool:
    """Does budgeted work of ``seconds`` CPU seconds run in a forked child
    here (:func:`run_stages`), with an idle core for a second child
    (:class:`Ahead`) to work on beside it (:func:`_idle_core`)?  On a
    single core, or on cores the machine's other work keeps busy, the second
    child would only compete with the first (measured on 2 busy cores: no
    gain in wall time, 10-30 % more CPU time), so the work is done in the
    first child as before.  This choice never changes a result: the
    verification takes the same references at the same points either way
    and is charged their CPU time (module docstring)."""
    seconds = _within_outer(seconds)
    return not (seconds is None or math.isinf(seconds) or not _HAS_FORK or os.environ.get("LINECONTACT_SYM_NO_FORK")
                or _mp.current_process().daemon or not _idle_core())


class Ahead:
    """Values computed ahead in a second forked child (module docstring):
    ``Ahead(produce, seconds)`` forks a child that iterates ``produce()``
    under ``seconds`` CPU seconds and sends each item with the CPU seconds
    it took (the time since the item before); :meth:`take` (in this process
    or in a child forked after this one) returns the next ``(item,
    seconds)``, waiting for it, or None once the child has ended without
    sending it (its generator done, or its budget spent).  :meth:`close`
    ends and reaps the child (in the process that made it)."""

    def __init__(self, produce, seconds):
        self._owner = os.getpid()
        self._done = False
        rfd, wfd = os.pipe()
        self.pid = os.fork()
        if self.pid == 0:           # the child: never returns
            try:
                os.close(rfd)
                _ahead_child(wfd, produce, seconds)
            finally:
                os._exit(0)
        os.close(wfd)
        self._recv = _mp.connection.Connection(rfd, writable=False)
        self._guard = wall_guard(seconds)

    def take(self):
        if self._done:
            return None
        try:
            if not self._recv.poll(self._guard):
                self._done = True
                return None
            return pickle.loads(self._recv.recv_bytes())
        except (EOFError, OSError, pickle.UnpicklingError):
            self._done = True
            return None

    def close(self):
        if os.getpid() != self._owner:
            return
        try:
            os.kill(self.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        try:
            os.waitpid(self.pid, 0)
        except ChildProcessError:
            pass
        self._recv.close()
        self._done = True


def _ahead_child(wfd, produce, seconds):
    send = _mp.connection.Connection(wfd, readable=False)
    gc.freeze()                             # as in _child: no collection walks the parent's objects
    _IN_CHILD["deadline"] = Deadline(seconds)
    _arm(seconds)
    last = time.process_time()
    try:
        for item in produce():
            now = time.process_time()
            _disarm()
            send.send_bytes(pickle.dumps((item, now - last)))
            _arm(max(_IN_CHILD["deadline"].left(), 1e-3))
            last = time.process_time()
    except Exception:       # the consumer does the rest itself (and meets the same error)
        pass
    finally:
        _disarm()
        send.close()
