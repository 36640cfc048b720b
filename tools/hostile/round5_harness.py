"""What the round-5 hostile sweeps share: a case runs under a time limit and is
classified (ok, why, seconds); a case whose right answer is a package error."""
import signal
import time

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
