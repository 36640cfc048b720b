"""linecontact_sym: closed-form solutions of two-dimensional (line) contact
problems by Popov's (2017) superposition of flat punches, derived with SymPy,
verified with mpmath and exported as fast numeric functions.

A plain ``import linecontact_sym`` loads only the symbols and the errors
(SymPy); every other public name is imported on first use (module
``__getattr__``, PEP 562), so the import stays fast and a script that never
draws a figure or checks a claim never loads what those need.
"""
from __future__ import annotations

import importlib

from .core.symbols import x, a, P, E_star, gamma, R, b, n, c, theta, mu, Q, c_s, c_r, z, nu, t, x_real, e, tilt, M
from .core.errors import (LineContactError, ProfileError, UnknownSymbolError, InadmissibleProfileError,
                          DomainError, DivergentIntegralError, VerificationError, BudgetExceeded, ClaimError,
                          NoPullOffError, NoEquilibriumError, GrossSlidingError)

#: public name -> the module it comes from (imported on first use)
_LAZY = {
    "Profile": ".method.profile",
    "Derivation": ".method.derivation",
    "VerificationRecord": ".method.verification",
    "LineContact": ".contacts.normal.contact",
    "profile_from_force": ".contacts.normal.inverse",
    "AdhesiveLineContact": ".contacts.adhesion.contact",
    "SlidingStressField": ".contacts.stresses.contact",
    "StressField": ".contacts.stresses.contact",
    "Contact": ".contacts.base",
    "Quantity": ".contacts.base",
    "TangentialLineContact": ".contacts.tangential.contact",
    "catalogue": ".contacts.catalogue",
    "parabola": ".contacts.catalogue",
    "power_law": ".contacts.catalogue",
    "wedge": ".contacts.catalogue",
    "worn_cylinder": ".contacts.catalogue",
    "rounded_punch": ".contacts.catalogue",
    "exact_cylinder": ".contacts.catalogue",
    "init_printing": ".core.printing",
    "to_latex": ".core.printing",
    "parse_expr": ".parsing",
    "reduced_modulus": ".core.materials",
    "dundurs_beta": ".core.materials",
    "neglected_coupling": ".core.materials",
    "flat_punch": ".contacts.asymmetric",
    "Material": ".method.material",
    "maxwell": ".method.material",
    "kelvin_voigt": ".method.material",
    "standard_linear_solid": ".method.material",
    "prony": ".method.material",
    "ViscoelasticLineContact": ".contacts.viscoelastic",
}

#: the subpackages and modules reachable as attributes (``linecontact_sym.claims``) without an import statement
_SUBMODULES = ("core", "parsing", "method", "numeric", "views", "contacts", "claims", "cli")

__all__ = [
    "x", "a", "P", "E_star", "gamma", "R", "b", "n", "c", "theta", "mu", "Q", "c_s", "c_r", "z", "nu", "t",
    "x_real", "e", "tilt", "M", "reduced_modulus", "dundurs_beta", "neglected_coupling", "flat_punch",
    "LineContactError", "ProfileError", "UnknownSymbolError", "InadmissibleProfileError",
    "DomainError", "DivergentIntegralError", "VerificationError", "BudgetExceeded", "ClaimError",
    "Profile", "Derivation", "VerificationRecord", "LineContact", "profile_from_force",
    "AdhesiveLineContact", "NoPullOffError", "NoEquilibriumError", "Contact", "Quantity", "catalogue",
    "TangentialLineContact", "GrossSlidingError", "StressField", "SlidingStressField",
    "parabola", "power_law", "wedge", "worn_cylinder", "rounded_punch", "exact_cylinder", "to_latex", "init_printing", "parse_expr",
    "Material", "maxwell", "kelvin_voigt", "standard_linear_solid", "prony", "ViscoelasticLineContact",
]


def _import(relative: str):
    """``importlib.import_module(relative, __name__)``, parents first
    (``.contacts``, then ``.contacts.normal``, then ``.contacts.normal.contact``).
    Two threads importing two submodules of one package at once
    (``lcs.LineContact`` and ``lcs.profile_from_force``) each take the
    module lock of the submodule first and then wait for the package's, which
    the other holds while its ``__init__`` imports the first's submodule: a
    deadlock (Python raises ``_DeadlockError``).  Taking the locks from the top,
    one at a time, in the one direction the layers import, has no cycle."""
    parts = relative.lstrip(".").split(".")
    module = None
    for i in range(1, len(parts) + 1):
        module = importlib.import_module("." + ".".join(parts[:i]), __name__)
    return module


def __getattr__(name):
    if name == "__version__":           # pyproject.toml's (core/version.py), read on first use
        from .core.version import package_version
        value = package_version()
    elif name in _LAZY:
        module = _import(_LAZY[name])
        value = module if name == "catalogue" else getattr(module, name)
    elif name in _SUBMODULES:
        value = _import("." + name)
    else:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    globals()[name] = value          # looked up once
    return value


def __dir__():
    return sorted(set(globals()) | set(__all__) | set(_SUBMODULES))
