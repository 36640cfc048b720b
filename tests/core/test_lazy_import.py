"""Lazy imports under threads: the package's public names (PEP 562
``__getattr__``) and :func:`linecontact_sym.core.lazy.lazy_module` may be
first touched by several threads at once, without a deadlock or a
half-initialised module (issue 42, class 10)."""
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

_NAMES = """
import sys, threading, time
import linecontact_sym as lcs

class Slow:
    # widens the window deterministically: finding the package linecontact_sym.contacts
    # takes 0.5 s, while the first thread may hold the locks of the submodules it asked for
    def find_spec(self, name, path=None, target=None):
        if name in ("linecontact_sym.contacts", "linecontact_sym.contacts.normal"):
            time.sleep(0.5)
        return None

sys.meta_path.insert(0, Slow())
names = ["LineContact", "profile_from_force"]
barrier = threading.Barrier(len(names))
errors = []
def touch(n):
    barrier.wait()
    try:
        getattr(lcs, n)
    except BaseException as exc:
        errors.append(f"{n}: {type(exc).__name__}: {exc}")
threads = [threading.Thread(target=touch, args=(n,)) for n in names]
[t.start() for t in threads]
[t.join(40) for t in threads]
print("alive" if any(t.is_alive() for t in threads) else "; ".join(errors) or "ok")
sys.stdout.flush()
os._exit(0)
"""

_LAZY = """
import os, sys, threading
from linecontact_sym.core.lazy import lazy_module
assert "json.tool" not in sys.modules
m = lazy_module("json.tool")
barrier = threading.Barrier(8)
out = []
def read():
    barrier.wait()
    out.append(m.main.__name__)
threads = [threading.Thread(target=read) for _ in range(8)]
[t.start() for t in threads]
[t.join(20) for t in threads]
print("ok" if out == ["main"] * 8 else f"bad {out}")
sys.stdout.flush()
os._exit(0)
"""


def _run(code):
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    return subprocess.Popen([sys.executable, "-c", "import os\n" + code], env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)


def test_threads_touching_public_names_at_once_do_not_deadlock():
    """Before: ``_DeadlockError`` (Python's detection) in 5 of 8 plain runs, and
    in every run with the window widened as here."""
    out, err = _run(_NAMES).communicate(timeout=120)
    assert out.strip() == "ok", (out, err[-2000:])


def test_lazy_module_under_threads_imports_once_and_completely():
    p = _run(_LAZY)
    out, err = p.communicate(timeout=60)
    assert out.strip() == "ok", (out, err[-2000:])
