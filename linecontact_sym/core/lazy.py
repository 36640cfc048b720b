"""Modules loaded on first use.

:func:`lazy_module` returns a stand-in whose first attribute read imports
the module (by the ordinary, thread-safe import system) and then copies the
module's namespace into the stand-in, so that later reads are plain
attribute reads at no cost per access.  SciPy's submodules are imported
this way, so that ``import linecontact_sym`` (and the symbolic work) does
not pay for ``scipy.special`` (about 1 s with its array-API machinery)
until a float64 function is exported.

Thread-safe: the standard library's :class:`importlib.util.LazyLoader`
is not before Python 3.12.3 (two threads reading the first attribute at
once may both execute the module, or one may see it half-initialised);
here the import is ``importlib.import_module`` (Python's per-module locks)
under one lock of this stand-in, and nothing is put into ``sys.modules``
but the real module.

>>> m = lazy_module("colorsys")
>>> m.rgb_to_hsv(1.0, 0.0, 0.0)
(0.0, 1.0, 1.0)
"""
from __future__ import annotations

import importlib
import importlib.util
import sys
import threading
import types

__all__ = ["lazy_module"]


class _LazyModule(types.ModuleType):
    """The stand-in of a module not imported yet (see the module docstring)."""

    def __init__(self, name):
        super().__init__(name)
        object.__setattr__(self, "_lcs_lock", threading.Lock())

    def _lcs_load(self):
        with self._lcs_lock:
            module = sys.modules.get(self.__name__)
            if module is None or isinstance(module, _LazyModule):
                module = importlib.import_module(self.__name__)
            for k, v in module.__dict__.items():
                if k not in ("__name__",):
                    object.__setattr__(self, k, v)
            object.__setattr__(self, "_lcs_module", module)
        return module

    def __getattr__(self, attr):        # only for names not (yet) copied in
        if attr.startswith("_lcs_"):
            raise AttributeError(attr)
        module = self.__dict__.get("_lcs_module") or self._lcs_load()
        return getattr(module, attr)


def lazy_module(name: str):
    """The module ``name`` (dotted), imported on first attribute access; the
    module itself when it is imported already.  A name that does not exist
    raises ``ModuleNotFoundError`` now (its parent packages are imported to
    find it: ``scipy`` itself is light)."""
    if name in sys.modules:
        return sys.modules[name]
    if importlib.util.find_spec(name) is None:
        raise ModuleNotFoundError(f"No module named {name!r}", name=name)
    return _LazyModule(name)
