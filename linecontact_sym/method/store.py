"""Derivations remembered, so that nothing waits twice for the same answer.

Two levels, one key:

* **in this process** a dict: a quantity derived once (closed form or not)
  is not derived again, in particular a quantity that failed to close is not
  retried (unless with a larger time budget than the one it failed under);
* **across processes** one file per derivation in the user's cache
  directory: ``$LINECONTACT_SYM_CACHE`` if set (a directory, or ``off`` to
  disable), else ``$XDG_CACHE_HOME/linecontact_sym``, else
  ``~/.cache/linecontact_sym``.  ``linecontact-sym --no-cache`` (or
  :func:`set_enabled`) switches the disk off for the process.

The key is a SHA-256 of the profile and force law (``srepr``, so the symbols'
assumptions are part of it), the quantity, the verification settings and
the *code version*: the package version and a hash of the source of this
layer (the rules, the reduction, the dispatcher, the transforms), so a
changed rule never meets an entry written by its predecessor.  A file holds
a magic line, the SHA-256 of its payload and the payload (a pickle of plain
records: SymPy expressions, the :class:`~.rulebase.Step`, the
:class:`~.verification.VerificationRecord`, the attempts); an entry whose
checksum, format, code version or key does not match is ignored (and
replaced by the fresh derivation): it is never trusted.  Files are written
atomically (a temporary file renamed) with owner-only permissions: the cache
is the user's own, written only by this package (pickles are not a format to
accept from others).  The reference quadrature of a derivation is a closure
and is not stored: the caller rebuilds it.
"""
from __future__ import annotations

import hashlib
import os
import pickle
import re
import tempfile
from pathlib import Path

__all__ = ["cache_dir", "set_enabled", "enabled", "code_version", "make_key", "get", "put", "clear_memory",
           "CACHE_ENV"]

#: environment variable: a cache directory, or ``off``
CACHE_ENV = "LINECONTACT_SYM_CACHE"
_MAGIC = b"linecontact_sym-derivation-cache 1\n"
_memory: dict = {}
_state = {"enabled": True, "version": None}


def set_enabled(on: bool) -> None:
    """Switch the on-disk cache on or off for this process (the in-process
    memory stays: within one process nothing is derived twice)."""
    _state["enabled"] = bool(on)


def enabled() -> bool:
    return _state["enabled"] and cache_dir() is not None


def cache_dir() -> Path | None:
    """The cache directory (see the module docstring), or None when disabled."""
    env = os.environ.get(CACHE_ENV)
    if env is not None:
        if env.strip().lower() in ("off", "0", "no", "false", ""):
            return None
        return Path(env).expanduser()
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "linecontact_sym"


def code_version() -> str:
    """The package version and a hash of this layer's source files."""
    if _state["version"] is None:
        here = Path(__file__).resolve().parent
        init = (here.parent / "__init__.py").read_text(encoding="utf-8")
        found = re.search(r"__version__\s*=\s*[\"']([^\"']+)[\"']", init)
        version = found.group(1) if found else "unknown"
        h = hashlib.sha256(version.encode())
        for path in sorted(here.glob("*.py")) + sorted((here.parent / "core").glob("*.py")):
            h.update(path.name.encode())
            h.update(path.read_bytes())
        _state["version"] = f"{version}+{h.hexdigest()[:16]}"
    return _state["version"]


def _part(p):
    import sympy as sp
    if isinstance(p, sp.Basic):
        return sp.srepr(p)
    if isinstance(p, (list, tuple)):
        return "(" + ",".join(_part(q) for q in p) + ")"
    if isinstance(p, dict):
        return "{" + ",".join(f"{_part(k)}:{_part(v)}" for k, v in sorted(p.items(), key=lambda kv: str(kv[0]))) + "}"
    return repr(p)


def make_key(*parts) -> str:
    """A key for the given parts (SymPy objects by ``srepr``) and the code version."""
    text = code_version() + "|" + "|".join(_part(p) for p in parts)
    return hashlib.sha256(text.encode()).hexdigest()


def _path(key):
    d = cache_dir()
    return None if d is None else d / key[:2] / f"{key}.pickle"


def get(key: str):
    """The record stored under ``key`` (in memory, else on disk), or None;
    its ``source`` says which."""
    if key in _memory:
        return dict(_memory[key], source="memory")
    if not enabled():
        return None
    path = _path(key)
    try:
        data = path.read_bytes()
    except OSError:
        return None
    rec = _decode(data, key)
    if rec is None:
        return None
    _memory[key] = rec
    return dict(rec, source="disk")


def _decode(data: bytes, key: str):
    if not data.startswith(_MAGIC):
        return None
    body = data[len(_MAGIC):]
    digest, payload = body[:64], body[65:]
    if hashlib.sha256(payload).hexdigest().encode() != digest:
        return None                                    # corrupt: recomputed, never trusted
    try:
        rec = pickle.loads(payload)
    except Exception:
        return None
    if not isinstance(rec, dict) or rec.get("key") != key or rec.get("version") != code_version():
        return None                                    # stale or misplaced
    return rec


def put(key: str, record: dict) -> None:
    """Remember ``record`` under ``key``: in memory, and on disk if enabled
    (silently skipped when the directory cannot be written)."""
    record = dict(record, key=key, version=code_version())
    _memory[key] = record
    if not enabled():
        return
    path = _path(key)
    try:
        payload = pickle.dumps(record, protocol=pickle.HIGHEST_PROTOCOL)
    except Exception:
        return                                         # not picklable: memory only
    data = _MAGIC + hashlib.sha256(payload).hexdigest().encode() + b"\n" + payload
    try:
        path.parent.mkdir(parents=True, exist_ok=True, mode=0o700)
        fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=".tmp-")
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        os.chmod(tmp, 0o600)
        os.replace(tmp, path)
    except OSError:
        pass


def clear_memory() -> None:
    """Forget the in-process records (the disk cache is untouched)."""
    _memory.clear()
