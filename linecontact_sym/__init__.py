"""linecontact_sym: closed-form solutions of two-dimensional (line) contact
problems by Popov's (2017) superposition of flat punches, derived with SymPy,
verified with mpmath and exported as fast numeric functions."""
from __future__ import annotations

from .core.symbols import x, a, P, E_star, gamma, R, b, n, c, theta, mu, Q, c_s, c_r, z, nu
from .core.errors import (LineContactError, ProfileError, UnknownSymbolError, InadmissibleProfileError,
                     DomainError, DivergentIntegralError, VerificationError, BudgetExceeded, ClaimError)
from .method.profile import Profile
from .method.derivation import Derivation
from .method.verification import VerificationRecord
from .contacts.normal.contact import LineContact
from .contacts.normal.inverse import profile_from_force
from .contacts.adhesion.contact import AdhesiveLineContact
from .contacts.stresses.contact import SlidingStressField, StressField
from .contacts.base import Contact, Quantity
from .core.errors import NoPullOffError, NoEquilibriumError, GrossSlidingError
from .contacts.tangential.contact import TangentialLineContact
from .contacts import catalogue
from .contacts.catalogue import parabola, power_law, wedge, worn_cylinder, rounded_punch, exact_cylinder
from .core.printing import init_printing, to_latex
from .parsing import parse_expr

__version__ = "0.1.0"

__all__ = [
    "x", "a", "P", "E_star", "gamma", "R", "b", "n", "c", "theta", "mu", "Q", "c_s", "c_r", "z", "nu",
    "LineContactError", "ProfileError", "UnknownSymbolError", "InadmissibleProfileError",
    "DomainError", "DivergentIntegralError", "VerificationError", "BudgetExceeded", "ClaimError",
    "Profile", "Derivation", "VerificationRecord", "LineContact", "profile_from_force",
    "AdhesiveLineContact", "NoPullOffError", "NoEquilibriumError", "Contact", "Quantity", "catalogue",
    "TangentialLineContact", "GrossSlidingError", "StressField", "SlidingStressField",
    "parabola", "power_law", "wedge", "worn_cylinder", "rounded_punch", "exact_cylinder", "to_latex", "init_printing", "parse_expr",
]
