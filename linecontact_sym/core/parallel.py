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

import os
from typing import Callable, Iterable

__all__ = ["default_jobs", "process_pool", "map_ordered"]


def default_jobs() -> int:
    """The number of cores this process may use (the CLI's default ``--jobs``)."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


def process_pool(jobs: int | None = None):
    """A :class:`~concurrent.futures.ProcessPoolExecutor` of ``jobs`` workers
    (default :func:`default_jobs`), forked where the platform can (the workers
    start at once, with the modules already imported)."""
    import multiprocessing as mp
    from concurrent.futures import ProcessPoolExecutor
    ctx = mp.get_context("fork") if "fork" in mp.get_all_start_methods() else None
    return ProcessPoolExecutor(max_workers=jobs or default_jobs(), mp_context=ctx)


def map_ordered(fn: Callable, items: Iterable, executor=None, *, on_done: Callable | None = None,
                on_error: Callable | None = None) -> list:
    """``[fn(item) for item in items]``, each call submitted to ``executor``
    (any :class:`concurrent.futures.Executor`; None: in this process, one after
    the other).  Results in the order of ``items``; ``on_done(i, result)`` is
    called as each one finishes (in the order they finish), ``on_error(i,
    exc)`` gives the result of a call that raised (default: raise)."""
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
