"""A paper's claims checked one after the other, or side by side on any
:class:`concurrent.futures.Executor` (worker processes on this machine, a
Dask cluster).

The unit of work is a claim, or, for a general claim checked on several test
profiles (Eqs. 9, 10, 12, 29), the claim for one profile: those are
independent too, and one such claim alone can cost as much as the rest of a
paper.  The results come back in the claims' order and equal those of a
serial run (the verdict of a claim is combined from its profiles' verdicts
exactly as :func:`~.check.check_claim` combines them)."""
from __future__ import annotations

import dataclasses
import functools
import time
from typing import Callable

from ..core.budget import checked_budget
from ..core.errors import ClaimError
from ..core.parallel import capped_jobs, check_executor, map_ordered, process_pool
from .check import check_claim, check_target, claim_result
from .derive import Context
from .references import DPS
from .results import UNDECIDED, ClaimResult, PaperResult, TargetResult
from .spec import Claim, Paper, load_paper

__all__ = ["check_paper", "check_file", "check_claim_portable", "check_part", "check_and_draw"]


def check_file(path, **kw) -> PaperResult:
    """The claims file at ``path`` checked (:func:`check_paper`)."""
    return check_paper(load_paper(path), **kw)


def check_and_draw(paper, jobs, out_dir, budget, **kw):
    """``(check_paper(paper, ...), figure paths or None)``: with ``jobs > 1``
    one process pool checks the claims and, beside them, draws the paper's
    figures into ``out_dir`` (None: no figures; they are drawn with the
    reports when ``jobs == 1``)."""
    check = check_paper
    if not isinstance(paper, Paper):
        paper = load_paper(paper)
    only = kw.get("only")
    work = len(_parts([c for c in paper.claims if only is None or c.label in only]))
    work += 1 if out_dir is not None and paper.figures else 0
    jobs = capped_jobs(jobs, work)          # never more workers than work (paper --jobs 1000)
    if jobs <= 1:
        return check(paper, budget=budget, **kw), None
    with process_pool(jobs) as pool:
        figs = None
        if out_dir is not None and paper.figures:
            from pathlib import Path
            from .figures import draw_figures
            Path(out_dir).mkdir(parents=True, exist_ok=True)
            figs = pool.submit(draw_figures, paper, out_dir, budget=budget)
        result = check(paper, budget=budget, executor=pool, **kw)
        return result, (figs.result() if figs is not None else None)


def _failed(claim, exc) -> ClaimResult:
    """The result of a claim whose check raised (one claim's failure is
    reported, never raised)."""
    if isinstance(exc, ClaimError):
        return ClaimResult(claim, UNDECIDED, f"{UNDECIDED}: {exc}", 0.0, 0.0)
    return ClaimResult(claim, UNDECIDED, f"{UNDECIDED}: internal error {type(exc).__name__}: {exc}", 0.0, 0.0)


def _checked(claim, ctx, budget, dps, symbolic) -> ClaimResult:
    """check_claim, with a failure of one claim reported, never raised."""
    try:
        return check_claim(claim, ctx, budget=budget, dps=dps, symbolic=symbolic)
    except Exception as exc:  # noqa: BLE001 -- report, and go on with the next claim
        return _failed(claim, exc)


#: per worker process: one Context per budget, kept across the work the
#: worker is given (a contact derived for one claim serves the next)
_WORKER_CONTEXTS: dict = {}


def _worker_context(budget) -> Context:
    ctx = _WORKER_CONTEXTS.get(budget)
    if ctx is None:
        ctx = _WORKER_CONTEXTS[budget] = Context(budget)
    return ctx


def _portable(t: TargetResult) -> TargetResult:
    """The target without the closures of its derived record (so it pickles)."""
    if t.derived is not None:
        t.derived = dataclasses.replace(t.derived, evaluator=None, comparer=None, physics=None)
    return t


def check_claim_portable(claim: Claim, budget, dps=DPS, symbolic=True) -> ClaimResult:
    """:func:`~.check.check_claim` for an executor: run in a worker (a process,
    a Dask worker), the result returned without the closures of the derived
    records (their evaluators), so that it pickles; the verdicts, points and
    digits are those of :func:`~.check.check_claim`."""
    r = _checked(claim, _worker_context(budget), budget, dps, symbolic)
    for t in r.targets:
        _portable(t)
    return r


def check_part(part, budget, dps=DPS, symbolic=True):
    """One unit of work: ``(claim, None)`` -> its :class:`ClaimResult`;
    ``(claim, j)`` -> ``(TargetResult of profile j, seconds)``, or the
    exception that stopped it (returned, for the claim to report)."""
    claim, j = part
    if j is None:
        return check_claim_portable(claim, budget, dps, symbolic)
    t0 = time.perf_counter()
    ptxt, prof = claim.profiles[j]
    try:
        t = check_target(claim, ptxt, prof, _worker_context(budget), budget=budget, dps=dps, symbolic=symbolic)
    except Exception as exc:  # noqa: BLE001 -- reported as the claim's failure
        return exc
    return _portable(t), time.perf_counter() - t0


def _parts(claims):
    """The units of work: each claim, or each (claim, profile) of a general
    claim with several test profiles."""
    out = []
    for i, c in enumerate(claims):
        if not c.values and len(c.profiles) > 1:
            out += [(i, (c, j)) for j in range(len(c.profiles))]
        else:
            out.append((i, (c, None)))
    return out


def check_paper(paper, *, budget: float = 20.0, progress: Callable | None = None, only=None,
                dps: int = DPS, symbolic: bool = True, on_start: Callable | None = None,
                jobs: int = 1, executor=None) -> PaperResult:
    """Check every claim of a paper (a :class:`Paper`, a path, or a shipped name).

    ``on_start(i, n, claim)`` is called before and ``progress(i, n, result)``
    after each claim (e.g. :class:`~linecontact_sym.core.progress.Progress`);
    ``only`` limits the run to the given labels.

    The claims (and the test profiles of a general claim) are independent:
    ``jobs > 1`` checks them in that many worker processes
    (:func:`~linecontact_sym.core.parallel.process_pool`), or any
    :class:`concurrent.futures.Executor` given as ``executor`` does the work
    (e.g. a Dask ``distributed.Client(...).get_executor()``).  The results are
    in the claims' order and equal those of a serial run (``jobs=1``, the
    default); with workers, ``on_start`` is called as the claims are handed
    out, ``progress`` as each claim is complete, a claim's ``seconds`` is
    the sum over its parts, and the results hold the derived expressions, not
    their evaluators."""
    if not isinstance(paper, Paper):
        paper = load_paper(paper)
    budget = checked_budget(budget)
    t0 = time.perf_counter()
    claims = [c for c in paper.claims if only is None or c.label in only]
    parts = _parts(claims)
    check_executor(executor)
    workers = capped_jobs(jobs, len(parts))
    if executor is None and workers > 1:
        with process_pool(workers) as pool:
            results = _check_on(pool, claims, parts, budget, dps, symbolic, on_start, progress)
    elif executor is not None:
        results = _check_on(executor, claims, parts, budget, dps, symbolic, on_start, progress)
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


def _check_on(executor, claims, parts, budget, dps, symbolic, on_start, progress) -> list:
    """The parts checked by ``executor`` (any concurrent.futures.Executor),
    assembled into the claims' results, in the claims' order."""
    n = len(claims)
    if on_start is not None:
        for i, claim in enumerate(claims):
            on_start(i, n, claim)
    owner = [i for i, _ in parts]
    left = {i: owner.count(i) for i in set(owner)}
    got: dict = {i: [] for i in left}
    results = [None] * n

    def done(k, r):
        i = owner[k]
        got[i].append((k, r))
        left[i] -= 1
        if left[i]:
            return
        results[i] = _assemble(claims[i], [r for _, r in sorted(got[i], key=lambda kr: kr[0])])
        if progress is not None:
            progress(i, n, results[i])

    def lost(k, exc):   # a worker lost: the claim is reported, the others go on
        return exc
    map_ordered(functools.partial(check_part, budget=budget, dps=dps, symbolic=symbolic),
                [p for _, p in parts], executor, on_done=done, on_error=lost)
    return results


def _assemble(claim, outs) -> ClaimResult:
    """A claim's result from the results of its parts (in profile order)."""
    if len(outs) == 1 and not isinstance(outs[0], tuple):
        return outs[0] if isinstance(outs[0], ClaimResult) else _failed(claim, outs[0])
    for r in outs:
        if isinstance(r, BaseException):
            return _failed(claim, r)
    try:
        return claim_result(claim, [t for t, _ in outs], sum(s for _, s in outs))
    except Exception as exc:  # noqa: BLE001
        return _failed(claim, exc)
