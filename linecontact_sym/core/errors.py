"""Exceptions of ``linecontact_sym``.

Every error the package raises on bad input is one of these, and its message
names the profile, the broken assumption and what to do about it.
"""
from __future__ import annotations


class LineContactError(Exception):
    """Base class of every error raised by linecontact_sym."""


class ProfileError(LineContactError, ValueError):
    """The profile expression is not a valid input (type, symbols, f(0) != 0...)."""


class UnknownSymbolError(ProfileError):
    """The expression holds a free symbol that was not declared as a parameter."""


class InadmissibleProfileError(LineContactError, ValueError):
    """The profile breaks an assumption of the frictionless compact-contact solution
    (pressure < 0 inside, negative gap outside, non-monotone profile, ...)."""


class DomainError(LineContactError, ValueError):
    """An argument lies outside the domain of a quantity (a <= 0, |x| > a, ...)."""


class DivergentIntegralError(LineContactError, ValueError):
    """A defining integral of the method diverges for this profile."""


class NoPullOffError(DomainError):
    """P(a) has no finite (negative) minimum: no finite tensile pull-off."""


class NoEquilibriumError(DomainError):
    """No equilibrium half-width at the requested load (below the pull-off force)."""


class GrossSlidingError(DomainError):
    """The tangential force exceeds the Coulomb limit mu*P: the contact slides
    as a whole, there is no partial-slip state."""


class NumericValuesRequired(DomainError):
    """The quantity has no closed form; a number needs values of every parameter."""


class VerificationError(LineContactError):
    """A closed form disagreed with the independent quadrature of its defining integral."""


class BudgetExceeded(LineContactError, TimeoutError):
    """A symbolic step did not finish within its budget of CPU seconds
    (``wall_guard`` True: it was stopped by the wall-clock guard against a
    hang instead, a verdict that may depend on the machine's load)."""

    wall_guard = False


def singular_point(quantity, values, exc) -> "DomainError":
    """The error of a quantity evaluated where its formula is singular (a
    ZeroDivisionError or OverflowError of the arithmetic)."""
    return DomainError(f"{quantity} is not finite at {values}: a singular point of its formula "
                       f"({type(exc).__name__})")


class DomainWarning(UserWarning):
    """Points of an array argument lie outside a quantity's domain: their
    results are NaN, the other points are evaluated (a scalar outside the
    domain raises :class:`DomainError`)."""


class BudgetError(LineContactError, ValueError):
    """A time budget that is not a number of seconds > 0 (None: no limit)."""


class ClaimError(LineContactError, ValueError):
    """A claim (file or command line) is malformed or unsafe."""


class MissingExtraError(LineContactError, ImportError):
    """An optional dependency is not installed; the message names the extra that
    installs it (see :func:`linecontact_sym.core.extras.require`)."""


__all__ = [name for name in dir() if name.endswith("Error") or name in ("BudgetExceeded", "NumericValuesRequired", "DomainWarning")]
