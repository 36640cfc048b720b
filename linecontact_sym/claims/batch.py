"""A paper's claims checked one after the other, or side by side on any
:class:`concurrent.futures.Executor` (worker processes on this machine, a
Dask cluster): the claims are independent, the results come back in the
claims' order and equal those of a serial run."""
from __future__ import annotations

import dataclasses
import functools
import time
from typing import Callable

from ..core.budget import checked_budget
from ..core.errors import ClaimError
from ..core.parallel import default_jobs, map_ordered, process_pool
from .check import check_claim
from .derive import Context
from .references import DPS
from .results import UNDECIDED, ClaimResult, PaperResult
from .spec import Claim, Paper, load_paper

__all__ = ["check_paper", "check_claim_portable"]


def _checked(claim, ctx, budget, dps, symbolic) -> ClaimResult:
    """check_claim, with a failure of one claim reported, never raised."""
    try:
        return check_claim(claim, ctx, budget=budget, dps=dps, symbolic=symbolic)
    except ClaimError as exc:
        return ClaimResult(claim, UNDECIDED, f"{UNDECIDED}: {exc}", 0.0, 0.0)
    except Exception as exc:  # noqa: BLE001 -- report, and go on with the next claim
        return ClaimResult(claim, UNDECIDED, f"{UNDECIDED}: internal error {type(exc).__name__}: {exc}", 0.0, 0.0)


#: per worker process: one Context per budget, kept across the claims the
#: worker is given (a contact derived for one claim serves the next)
_WORKER_CONTEXTS: dict = {}


def check_claim_portable(claim: Claim, budget, dps=DPS, symbolic=True) -> ClaimResult:
    """:func:`check_claim` for an executor: run in a worker (a process, a Dask
    worker), the result returned without the closures of the derived records
    (their evaluators), so that it pickles; the verdicts, points and digits
    are those of :func:`check_claim`."""
    ctx = _WORKER_CONTEXTS.get(budget)
    if ctx is None:
        ctx = _WORKER_CONTEXTS[budget] = Context(budget)
    r = _checked(claim, ctx, budget, dps, symbolic)
    for t in r.targets:
        if t.derived is not None:
            t.derived = dataclasses.replace(t.derived, evaluator=None, comparer=None, physics=None)
    return r


def check_paper(paper, *, budget: float = 20.0, progress: Callable | None = None, only=None,
                dps: int = DPS, symbolic: bool = True, on_start: Callable | None = None,
                jobs: int = 1, executor=None) -> PaperResult:
    """Check every claim of a paper (a :class:`Paper`, a path, or a shipped name).

    ``on_start(i, n, claim)`` is called before and ``progress(i, n, result)``
    after each claim (e.g. :class:`~linecontact_sym.core.progress.Progress`);
    ``only`` limits the run to the given labels.

    The claims are independent: ``jobs > 1`` checks them in that many worker
    processes (a :class:`concurrent.futures.ProcessPoolExecutor`), or any
    :class:`concurrent.futures.Executor` given as ``executor`` (e.g. a Dask
    ``distributed.Client.get_executor()``) does the work.  The results are in
    the claims' order and equal to those of a serial run (``jobs=1``, the
    default); with workers, ``on_start`` is called as a claim is handed out
    and ``progress`` as it comes back (in the order they finish), and the
    results hold the derived expressions, not their evaluators."""
    if not isinstance(paper, Paper):
        paper = load_paper(paper)
    budget = checked_budget(budget)
    t0 = time.perf_counter()
    claims = [c for c in paper.claims if only is None or c.label in only]
    if executor is None and (jobs is None or jobs > 1) and len(claims) > 1:
        workers = min(default_jobs() if jobs is None else int(jobs), len(claims))
        with process_pool(workers) as pool:
            results = _check_on(pool, claims, budget, dps, symbolic, on_start, progress)
    elif executor is not None:
        results = _check_on(executor, claims, budget, dps, symbolic, on_start, progress)
    else:
        ctx = Context(budget)
        results = []
        for i, claim in enumerate(claims):
            if on_start is not None:
                on_start(i, len(claims), claim)
            r = _checked(claim, ctx, budget, dps, symbolic)
            results.append(r)
            if progress is not None:
                progress(i, len(claims), r)
    return PaperResult(paper, results, time.perf_counter() - t0)


def _check_on(executor, claims, budget, dps, symbolic, on_start, progress) -> list:
    """The claims checked by ``executor`` (any concurrent.futures.Executor),
    results in the claims' order."""
    n = len(claims)
    if on_start is not None:
        for i, claim in enumerate(claims):
            on_start(i, n, claim)

    def lost(i, exc):   # a worker lost: the claim is reported, the others go on
        return ClaimResult(claims[i], UNDECIDED, f"{UNDECIDED}: internal error {type(exc).__name__}: {exc}",
                           0.0, 0.0)
    return map_ordered(functools.partial(check_claim_portable, budget=budget, dps=dps, symbolic=symbolic),
                       claims, executor, on_error=lost,
                       on_done=None if progress is None else (lambda i, r: progress(i, n, r)))


