"""What the hostile sweeps share: a case runs under a time limit and is
classified (ok, why, seconds), in this process (:func:`run_case`, an alarm)
or in a forked child killed at the limit (:func:`isolated`, for cases that
hang in C code, which ignores signals); a fresh derivation cache per case;
a case whose right answer is a package error; the summary table by group."""
import json
import os
import signal
import tempfile
import time
import warnings

from linecontact_sym.core.errors import LineContactError


class Hang(Exception):
    pass


def _alarm(signum, frame):
    raise Hang()


def run_case(fn, limit):
    """(ok, why, seconds): fn() returns (ok, why); a hang past ``limit`` s or a foreign exception is not ok."""
    signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(int(limit))
    t0 = time.perf_counter()
    try:
        ok, why = fn()
    except Hang:
        ok, why = False, f"no answer within {limit} s"
    except LineContactError as exc:
        ok, why = False, f"refused where an answer exists: {type(exc).__name__}: {str(exc)[:140]}"
    except Exception as exc:  # noqa: BLE001 -- the point of the sweep
        ok, why = False, f"foreign {type(exc).__name__}: {str(exc)[:140]}"
    finally:
        signal.alarm(0)
    return ok, why, time.perf_counter() - t0


def refused(fn):
    """A case whose right answer is a package error."""
    def case():
        try:
            r = fn()
        except LineContactError as exc:
            return True, f"refused ({type(exc).__name__})"
        return False, f"accepted (an answer where none holds): {str(r)[:100]}"
    return case


def is_refused(fn) -> bool:
    """True where ``fn()`` raises a package error; an AssertionError naming
    what it gave otherwise (never a number, never a foreign exception).
    :func:`refused` is the same test as a case of its own."""
    try:
        v = fn()
    except LineContactError:
        return True
    raise AssertionError(f"gave {v!r} instead of an error")


def close(v, ref, tol=1e-10) -> bool:
    """``v`` (a number, complex, or a pint quantity's magnitude) within ``tol``
    (relative, absolute below 1) of the real ``ref``, its imaginary part too."""
    v = complex(getattr(v, "magnitude", v))
    return abs(v.imag) <= tol * max(1, abs(ref)) and abs(v.real - float(ref)) <= tol * max(1, abs(float(ref)))

def fresh_cache(prefix: str = "lcs-sweep-"):
    """A new, private derivation cache for the case about to run (the cache
    directory of the package's store, its memory cleared)."""
    from linecontact_sym.method import store
    d = tempfile.mkdtemp(prefix=prefix)
    os.chmod(d, 0o700)
    os.environ[store.CACHE_ENV] = d
    store.clear_memory()
    return d


def isolated(fn, timeout, prefix: str = "lcs-sweep-"):
    """``(ok, why)`` of ``fn()`` (True/False, or a tuple whose first item says)
    run in a forked child with a fresh cache, killed after ``timeout`` seconds."""
    import select
    r, w = os.pipe()
    pid = os.fork()
    if pid == 0:
        os.close(r)
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                fresh_cache(prefix)
                res = fn()
            ok = bool(res[0] if isinstance(res, tuple) else res)
            why = "" if ok else f"wrong result {str(res)[:120]}"
        except Exception as exc:   # noqa: BLE001 -- the point of the sweep
            ok, why = False, f"{type(exc).__name__}: {str(exc)[:120]}"
        os.write(w, json.dumps((ok, why)).encode())
        os._exit(0)
    os.close(w)
    deadline = time.monotonic() + timeout
    data = b""
    while True:
        left = deadline - time.monotonic()
        if left <= 0:
            os.kill(pid, signal.SIGKILL)
            os.waitpid(pid, 0)
            os.close(r)
            return False, f"no answer within {timeout} s"
        ready, _, _ = select.select([r], [], [], left)
        if ready:
            chunk = os.read(r, 65536)
            if not chunk:
                break
            data += chunk
    os.close(r)
    os.waitpid(pid, 0)
    return tuple(json.loads(data)) if data else (False, "the case died without an answer")


def _group_key(g):
    head = g.split()[0]
    return (int(head) if head.isdigit() else float("inf"), g)


def summary(out: dict, width: int, t_all: float, json_path=None) -> None:
    """The table of cases and ok per group of ``out`` ({"group | name": {"ok": ...}}),
    the total with the time since ``t_all``, and the per-case results as JSON at ``json_path``."""
    print()
    for g in sorted({k.split(" | ")[0] for k in out}, key=_group_key):
        rs = [v for k, v in out.items() if k.startswith(g + " |")]
        print(f"{g:{width}s} cases {len(rs):3d}  ok {sum(r['ok'] for r in rs):3d}")
    print(f"{'total':{width}s} cases {len(out):3d}  ok {sum(r['ok'] for r in out.values()):3d}   "
          f"({time.perf_counter() - t_all:.0f} s)")
    if json_path:
        with open(json_path, "w") as fh:
            json.dump(out, fh, indent=1)


def isolated_main(cases, description, timeout, prefix, width, name_width):
    """The command line of a sweep whose cases run :func:`isolated`:
    ``--json``, ``--timeout`` (default ``timeout``), ``--only`` (group
    numbers), ``--match`` (text in the case's name); one line per case, then
    :func:`summary`."""
    import argparse
    ap = argparse.ArgumentParser(description=description)
    ap.add_argument("--json", help="write the per-case results here")
    ap.add_argument("--timeout", type=int, default=timeout)
    ap.add_argument("--only", help="comma-separated group numbers, e.g. 1,4")
    ap.add_argument("--match", help="only the cases whose name contains this text")
    args = ap.parse_args()
    only = set(args.only.split(",")) if args.only else None
    out = {}
    t_all = time.perf_counter()
    for group, name, fn in cases:
        if only and group.split()[0] not in only or args.match and args.match not in name:
            continue
        t0 = time.perf_counter()
        ok, why = isolated(fn, args.timeout, prefix)
        out[f"{group} | {name}"] = {"ok": ok, "why": why, "seconds": round(time.perf_counter() - t0, 2)}
        print(f"{'ok  ' if ok else 'FAIL'} {group:{width}s} {name[:name_width]:{name_width}s} "
              f"{time.perf_counter() - t0:6.1f} s  {why}", flush=True)
    summary(out, width, t_all, args.json)
