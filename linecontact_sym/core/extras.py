"""Optional dependencies, grouped as the package's extras.

matplotlib (plots) is not needed to derive, check or export anything, so it
is optional::

    pip install "linecontact_sym[plot]"        # matplotlib
    pip install "linecontact_sym[all]"         # every extra

python-flint (Arb balls) is a core dependency (an optional package may add a
feature, never change a result); ``[certified]`` remains as an alias that
installs it, so that old install commands keep working.

Code that needs one imports it through :func:`require`, at the time of use
(never at module import), and a missing package becomes a
:class:`~linecontact_sym.core.errors.MissingExtraError` that says what to
install.

>>> require("certified", "math").sqrt(4.0)       # any importable module works
2.0
>>> require("nonsense", "math")
Traceback (most recent call last):
...
ValueError: unknown extra 'nonsense'; the extras are ['all', 'certified', 'plot']
"""
from __future__ import annotations

import importlib

from .errors import MissingExtraError

__all__ = ["EXTRAS", "require", "install_hint"]

#: extra -> (distribution names it installs, what it is for)
EXTRAS = {
    "plot": (("matplotlib",), "plotting"),
    "certified": (("python-flint",), "certified (Arb ball) evaluation (a core dependency; alias)"),
    "all": (("matplotlib", "python-flint"), "every optional feature"),
}


def install_hint(extra: str) -> str:
    """The pip command that installs ``extra``: ``pip install "linecontact_sym[extra]"``."""
    return f'pip install "linecontact_sym[{extra}]"'


def require(extra: str, module: str):
    """Import and return ``module`` (a dotted name, e.g. ``"matplotlib.pyplot"``)
    that the optional ``extra`` provides; if it cannot be imported, raise
    :class:`~linecontact_sym.core.errors.MissingExtraError` naming the extra
    and the command that installs it."""
    if extra not in EXTRAS:
        raise ValueError(f"unknown extra {extra!r}; the extras are {sorted(EXTRAS)}")
    try:
        return importlib.import_module(module)
    except ImportError as exc:
        dists, purpose = EXTRAS[extra]
        raise MissingExtraError(
            f"{purpose} needs the optional package {' and '.join(dists)} (module {module!r} "
            f"could not be imported: {exc}); install it with: {install_hint(extra)}") from exc
