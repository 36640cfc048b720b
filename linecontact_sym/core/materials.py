"""Two elastic bodies in plane strain: the reduced modulus E* and Dundurs'
second constant beta.

Popov's (2017) Eq. (4) writes E* = E/(1 - nu^2) for a rigid indenter on an
elastic half-plane; two elastic bodies add their compliances (Johnson 1985,
Contact Mechanics, ch. 4-5):

    1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2            (E = oo: a rigid body)

Dundurs' beta measures how a normal pressure on the interface makes the two
surfaces slide against each other (and a shear traction opens them):

    beta = (1/2) [(1 - 2 nu1)/G1 - (1 - 2 nu2)/G2] / [(1 - nu1)/G1 + (1 - nu2)/G2],
    G = E/(2 (1 + nu)),

so |beta| <= 1/2; beta = 0 for elastically similar bodies (and for two
incompressible ones), -(1 - 2 nu)/(2 (1 - nu)) for a rigid body 1 on body 2.
Every frictional result of the package (tangential loading, fretting, rolling)
neglects beta, i.e. the coupling of the normal and tangential problems:
:func:`neglected_coupling` says how large that is for a friction coefficient.

Values may be numbers (checked: E > 0 or oo, -1 < nu <= 1/2, via
:mod:`.ranges`) or SymPy symbols (the expressions are returned).
"""
from __future__ import annotations

import warnings

import sympy as sp

from .conversion import exact_number
from .errors import DomainError, DomainWarning
from .ranges import check_value

__all__ = ["reduced_modulus", "dundurs_beta", "neglected_coupling", "CouplingNote"]


def _value(v):
    """A value as an exact SymPy object: floats and decimal text as their
    shortest decimal (0.3 -> 3/10), a fraction '1/2', oo."""
    if isinstance(v, str) and "/" in v:
        try:
            return sp.Rational(v)
        except (TypeError, ValueError):
            raise DomainError(f"not a number: {v!r}") from None
    if v == sp.oo or (isinstance(v, float) and v == float("inf")):
        return sp.oo
    return exact_number(v)


def _modulus(E, which):
    E = _value(E)
    if E.is_number and not (E == sp.oo or E.is_positive):
        raise DomainError(f"the Young's modulus {which} must be > 0 (or oo for a rigid body), got {E}")
    return E


def _ratio(nu, which):
    nu = _value(nu)
    if nu.is_number:
        check_value("nu", nu)
    return nu


def reduced_modulus(E1, nu1, E2=sp.oo, nu2=0):
    """E* of bodies 1 and 2 in plane strain: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2
    (body 2 rigid by default: Popov's Eq. 4, E* = E1/(1 - nu1^2)).

    >>> reduced_modulus(210, 0.3, 210, 0.3)
    1500/13
    """
    E1, E2 = _modulus(E1, "E1"), _modulus(E2, "E2")
    nu1, nu2 = _ratio(nu1, "nu1"), _ratio(nu2, "nu2")
    if E1 == sp.oo and E2 == sp.oo:
        raise DomainError("both bodies are rigid: no elastic contact")
    compliance = sum(((1 - nu**2) / E for E, nu in ((E1, nu1), (E2, nu2)) if E != sp.oo), sp.S.Zero)
    return sp.simplify(1 / compliance)


def dundurs_beta(E1, nu1, E2=sp.oo, nu2=0):
    """Dundurs' beta of bodies 1 and 2 in plane strain (see the module docstring).

    >>> dundurs_beta(210, 0.3, 210, 0.3)
    0
    >>> dundurs_beta(sp.oo, 0, 1, sp.Rational(3, 10))
    -2/7
    """
    E1, E2 = _modulus(E1, "E1"), _modulus(E2, "E2")
    nu1, nu2 = _ratio(nu1, "nu1"), _ratio(nu2, "nu2")
    # compliances 1/G = 2 (1 + nu)/E (0 for a rigid body)
    c1 = sp.S.Zero if E1 == sp.oo else 2 * (1 + nu1) / E1
    c2 = sp.S.Zero if E2 == sp.oo else 2 * (1 + nu2) / E2
    num = (1 - 2 * nu1) * c1 - (1 - 2 * nu2) * c2
    den = (1 - nu1) * c1 + (1 - nu2) * c2
    if den == 0:
        raise DomainError("both bodies are rigid: Dundurs' beta is undefined")
    return sp.simplify(num / (2 * den))


class CouplingNote(str):
    """A note (str) on the neglected normal-tangential coupling, with the
    numbers: ``beta``, ``mu`` and ``size`` = |beta| mu."""

    beta: sp.Expr
    mu: sp.Expr
    size: sp.Expr


def neglected_coupling(beta, mu, warn: bool = True) -> CouplingNote:
    """How large the coupling that a frictional result neglects is: the
    shear traction q <= mu p moves the interface normally by beta times what
    the pressure does, so the relative error of the normal problem (and of
    the stick zone) is of order |beta| mu.  A
    :class:`~.errors.DomainWarning` (``warn``) where beta != 0; the note
    either way."""
    beta, mu = _value(beta), _value(mu)
    size = sp.Abs(beta) * mu
    if beta == 0:
        text = "beta = 0: elastically similar bodies, the normal and tangential problems uncouple exactly"
    else:
        text = (f"beta = {sp.N(beta, 4) if beta.is_number else beta} != 0: the coupling of the normal and tangential "
                f"problems is neglected (Goodman's approximation); its relative size is about |beta| mu = "
                f"{sp.N(size, 3) if size.is_number else size}")
        if warn:
            warnings.warn(text, DomainWarning, stacklevel=2)
    note = CouplingNote(text)
    note.beta, note.mu, note.size = beta, mu, size
    return note
