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

__version__ = "0.1.0"

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


def __getattr__(name):
    if name in _LAZY:
        module = importlib.import_module(_LAZY[name], __name__)
        value = module if name == "catalogue" else getattr(module, name)
    elif name in _SUBMODULES:
        value = importlib.import_module("." + name, __name__)
    else:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    globals()[name] = value          # looked up once
    return value


def __dir__():
    return sorted(set(globals()) | set(__all__) | set(_SUBMODULES))
