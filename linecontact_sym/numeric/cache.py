"""Caches the numeric layer owns, kept beside (never inside) the objects they describe.

Stabilising and lambdifying a derivation costs seconds, so the results are
kept per object.  They are not written into the object's ``__dict__``: an
:class:`IdentityCache` maps the object's identity to a dict and forgets the
entry when the object is garbage-collected (a ``weakref`` callback).  It
works for unhashable objects such as the ``Derivation`` dataclass.  Values
stored must not refer back to their key object (else it would never be
collected): cache compiled functions and expressions, not closures over
the object.

>>> class Thing:
...     pass
>>> cache = IdentityCache()
>>> t = Thing()
>>> cache.of(t)["answer"] = 42
>>> cache.of(t)["answer"], vars(t), len(cache)
(42, {}, 1)
>>> del t
>>> import gc; _ = gc.collect()
>>> len(cache)
0
"""
from __future__ import annotations

import weakref

__all__ = ["IdentityCache"]


class IdentityCache:
    """Per-object dicts keyed by object identity, dropped with the object."""

    def __init__(self):
        self._entries: dict = {}

    def of(self, obj) -> dict:
        """The cache dict of ``obj`` (created empty on first use)."""
        key = id(obj)
        entry = self._entries.get(key)
        if entry is not None and entry[0]() is obj:
            return entry[1]
        entries = self._entries

        def drop(ref, key=key):
            current = entries.get(key)
            if current is not None and current[0] is ref:
                del entries[key]
        ref = weakref.ref(obj, drop)
        store: dict = {}
        entries[key] = (ref, store)
        return store

    def __len__(self):
        return len(self._entries)
