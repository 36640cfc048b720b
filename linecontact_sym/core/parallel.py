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

__all__ = ["default_jobs", "jobs_count", "add_jobs_argument", "process_pool", "map_ordered", "map_chunks"]


def default_jobs() -> int:
    """The number of cores this process may use (the CLI's default ``--jobs``)."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


def jobs_count(text) -> int:
    """A number of worker processes as typed (``--jobs N``): a whole number >= 1."""
    try:
        n = int(text)
    except (TypeError, ValueError):
        n = 0
    if n < 1:
        raise ValueError(f"--jobs expects a whole number >= 1, got {text!r}")
    return n


def add_jobs_argument(parser) -> None:
    """The command line's ``--jobs N`` (default: :func:`default_jobs`)."""
    parser.add_argument("--jobs", "-j", type=jobs_count, default=default_jobs(), metavar="N",
                        help=f"check the claims in N worker processes (default: the cores, here {default_jobs()}); "
                             f"the results are those of --jobs 1, in the same order")


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
