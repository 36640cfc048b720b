"""Work spread over processes or machines through the one standard interface,
:class:`concurrent.futures.Executor`: a
:class:`~concurrent.futures.ProcessPoolExecutor` on this machine, or a Dask
``distributed.Client`` (its ``get_executor()``; the ``[distributed]`` extra)
on a cluster.  No scheduler of the package's own: :func:`map_ordered` submits
and collects, the executor schedules.

>>> default_jobs() >= 1
True
>>> map_ordered(abs, [-2, 3, -1])                   # no executor: in this process
[2, 3, 1]
"""
from __future__ import annotations

import functools
import os
from typing import Callable, Iterable

__all__ = ["default_jobs", "jobs_count", "capped_jobs", "check_executor", "process_pool",
           "map_ordered", "map_chunks"]


def default_jobs() -> int:
    """The number of cores this process may use (the CLI's default ``--jobs``)."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


def jobs_count(text) -> int:
    """A number of worker processes (``--jobs N``, ``jobs=``): a whole number
    >= 1, read by the one reader of numeric settings
    (:func:`~linecontact_sym.core.options.read_number`: NumPy integers, text
    with spaces); anything else raises
    :class:`~linecontact_sym.core.errors.DomainError`."""
    from .options import read_number
    return read_number(text, "--jobs (worker processes)", integer=True, low=1)


def capped_jobs(jobs, work: int) -> int:
    """The workers to start for ``work`` independent items: ``jobs`` (None:
    :func:`default_jobs`) read by :func:`jobs_count`, never more than the
    work (``paper --jobs 1000`` on 20 claims starts 20), at least 1."""
    n = default_jobs() if jobs is None else jobs_count(jobs)
    return max(1, min(n, int(work)))


def check_executor(executor) -> None:
    """``executor`` is None or has ``submit`` (a :class:`concurrent.futures.Executor`,
    a Dask client's ``get_executor()``); anything else (a name as text)
    raises :class:`~linecontact_sym.core.errors.DomainError`."""
    if executor is not None and not callable(getattr(executor, "submit", None)):
        from .errors import DomainError
        raise DomainError(f"executor must be a concurrent.futures.Executor (an object with submit(), e.g. "
                          f"process_pool(4) or a Dask client's get_executor()), got {executor!r}")


def process_pool(jobs: int | None = None):
    """A :class:`~concurrent.futures.ProcessPoolExecutor` of ``jobs`` workers
    (default :func:`default_jobs`), forked where the platform can (the workers
    start at once, with the modules already imported)."""
    import multiprocessing as mp
    from concurrent.futures import ProcessPoolExecutor
    ctx = mp.get_context("fork") if "fork" in mp.get_all_start_methods() else None
    return ProcessPoolExecutor(max_workers=default_jobs() if jobs is None else jobs_count(jobs), mp_context=ctx)


def map_ordered(fn: Callable, items: Iterable, executor=None, *, on_done: Callable | None = None,
                on_error: Callable | None = None) -> list:
    """``[fn(item) for item in items]``, each call submitted to ``executor``
    (any :class:`concurrent.futures.Executor`; None: in this process, one after
    the other).  Results in the order of ``items``; ``on_done(i, result)`` is
    called as each one finishes (in the order they finish), ``on_error(i,
    exc)`` gives the result of a call that raised (default: raise)."""
    check_executor(executor)
    items = list(items)
    out = [None] * len(items)

    def finish(i, get):
        try:
            r = get()
        except Exception as exc:  # noqa: BLE001 -- handed to on_error, or raised
            if on_error is None:
                raise
            r = on_error(i, exc)
        out[i] = r
        if on_done is not None:
            on_done(i, r)

    if executor is None:
        for i, item in enumerate(items):
            finish(i, lambda item=item: fn(item))
        return out
    from concurrent.futures import as_completed
    futures = {executor.submit(fn, item): i for i, item in enumerate(items)}
    for fut in as_completed(futures):
        finish(futures[fut], fut.result)
    return out


def _call_kw(fn, kw):
    return fn(**kw)


def map_chunks(fn: Callable, executor=None, *, chunks: int | None = None, **arrays):
    """``fn(**arrays)`` for a vectorised ``fn`` (a float64 export, a stress
    field's evaluator ``lambda x, z: ...``), the broadcast arrays cut into
    ``chunks`` blocks of rows (default: one per worker of a process pool,
    else 4), each evaluated by ``executor`` (None: in this process), the
    blocks joined again: the same values as one call.  ``fn`` must pickle for
    a process pool or a Dask cluster (exports, contacts and a stress
    contact's ``to_numeric`` functions do); it travels with each block and
    compiles again there, so few large blocks beat many small ones.

    >>> import numpy as np
    >>> map_chunks(lambda x, y: x * y, x=np.arange(6.0), y=2.0, chunks=3)
    array([ 0.,  2.,  4.,  6.,  8., 10.])
    """
    import numpy as np
    names = list(arrays)
    shape = np.broadcast_shapes(*[np.shape(a) for a in arrays.values()])
    if not shape or executor is None and chunks is None:
        return fn(**arrays)
    full = {n: np.broadcast_to(np.asarray(a), shape) for n, a in arrays.items()}
    if chunks is None:
        chunks = getattr(executor, "_max_workers", None) or 4
    edges = np.linspace(0, shape[0], min(chunks, shape[0]) + 1).astype(int)
    blocks = [{n: full[n][lo:hi] for n in names} for lo, hi in zip(edges[:-1], edges[1:]) if hi > lo]
    if executor is None:
        parts = [fn(**b) for b in blocks]
    else:
        parts = map_ordered(functools.partial(_call_kw, fn), blocks, executor)
    if isinstance(parts[0], dict):      # an evaluator returning every component
        return {k: np.concatenate([np.broadcast_to(p[k], np.shape(b[names[0]])) for p, b in zip(parts, blocks)])
                for k in parts[0]}
    return np.concatenate([np.broadcast_to(p, np.shape(b[names[0]])) for p, b in zip(parts, blocks)])
