"""Test helper: tamper with the derivation records of a cache directory (the
store's on-disk format: magic, sha256 of the payload, newline, JSON payload),
recomputing each file's checksum so that only the independent re-check on
reading can catch the change (tests of method/store.py's trust rules)."""
import hashlib
import json

import pytest

from linecontact_sym.method import store


def rewrite_derivations(d, fn):
    """Replace the ``expr`` of every derivation record under directory ``d``
    by ``fn(its srepr text)``; returns how many were rewritten."""
    n = 0
    for p in d.rglob("*.json"):
        data = json.loads(p.read_bytes()[len(store._MAGIC) + 65:].decode())
        for pair in data.get("dict", []):
            if pair[0] == "derivations":
                for r in pair[1]["tuple"]:
                    for f in r["dict"]:
                        if f[0] == "expr":
                            f[1] = {"sympy": fn(f[1]["sympy"])}
                            n += 1
                payload = json.dumps(data, separators=(",", ":")).encode()
                p.write_bytes(store._MAGIC + hashlib.sha256(payload).hexdigest().encode() + b"\n" + payload)
    return n


@pytest.fixture
def cache(tmp_path, monkeypatch):
    """An empty derivation cache of its own for the test (0700, the store's rule)."""
    d = tmp_path / "cache"
    d.mkdir(mode=0o700)
    monkeypatch.setenv(store.CACHE_ENV, str(d))
    store.clear_memory()
    yield d
    store.clear_memory()
