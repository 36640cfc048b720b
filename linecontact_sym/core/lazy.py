"""Modules loaded on first use.

:func:`lazy_module` returns a module whose code runs the first time one of
its attributes is read (the standard library's
:class:`importlib.util.LazyLoader`); afterwards it is the ordinary module,
at no cost per access.  SciPy's submodules are imported this way, so that
``import linecontact_sym`` (and the symbolic work) does not pay for
``scipy.special`` (about 1 s with its array-API machinery) until a float64
function is exported.

>>> m = lazy_module("colorsys")
>>> m.rgb_to_hsv(1.0, 0.0, 0.0)
(0.0, 1.0, 1.0)
"""
from __future__ import annotations

import importlib.util
import sys
import threading

__all__ = ["lazy_module"]

_LOCK = threading.Lock()


def lazy_module(name: str):
    """The module ``name`` (dotted), executed on first attribute access; the
    module itself when it is imported already.  Its parent packages are
    imported now (``find_spec`` needs them: ``scipy`` itself is light)."""
    with _LOCK:
        if name in sys.modules:
            return sys.modules[name]
        spec = importlib.util.find_spec(name)
        if spec is None:
            raise ModuleNotFoundError(f"No module named {name!r}", name=name)
        loader = importlib.util.LazyLoader(spec.loader)
        spec.loader = loader
        module = importlib.util.module_from_spec(spec)
        sys.modules[name] = module
        loader.exec_module(module)
        return module
