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

The frictional layers take the two bodies by the keywords of
:data:`COUPLING_KEYWORDS` (declared here once, read by :func:`coupling`):
``c.tangential(mu, beta=...)``, ``c.rolling(mu, materials=((E1, nu1), (E2, nu2)))``.
Every frictional result then carries a :class:`CouplingNote`: the neglected
coupling |beta| mu where beta is given (a :class:`~.errors.DomainWarning`
once per contact where beta != 0), :data:`NOT_GIVEN` where it is not.  The
numbers never change: the solution stays Goodman's approximation.

Values may be numbers (checked: E > 0 or oo, -1 < nu <= 1/2, via
:mod:`.ranges`) or SymPy symbols (the expressions are returned).
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass

import sympy as sp

from .conversion import exact_number
from .errors import DomainError, DomainWarning
from .ranges import check_value

__all__ = ["reduced_modulus", "dundurs_beta", "neglected_coupling", "CouplingNote", "COUPLING_KEYWORDS",
           "NOT_GIVEN", "Coupling", "coupling"]

#: The keywords by which the frictional layers (``c.tangential``, its fretting
#: cycle, ``c.rolling``) take the two bodies, and their meaning: the one
#: declaration (docstrings and the command line's help quote it).
COUPLING_KEYWORDS = {
    "beta": "Dundurs' second constant beta of the two bodies, -1/2 <= beta <= 1/2 (0: elastically similar "
            "bodies); the solution stays Goodman's approximation (beta neglected) and every result states the "
            "size of the neglected coupling, |beta| mu",
    "materials": "((E1, nu1), (E2, nu2)): the two bodies' Young's moduli (oo: a rigid body) and Poisson's "
                 "ratios, numbers, E in the unit of E_star; beta = dundurs_beta(E1, nu1, E2, nu2), and "
                 "E* = reduced_modulus(E1, nu1, E2, nu2) fills E_star where a state or a number is asked "
                 "without it (an E_star that differs from it by more than 1e-9 relative is refused)",
}

#: The statement of a frictional result made without beta or materials.
NOT_GIVEN = "beta = 0 assumed (elastically similar bodies)"

#: relative difference beyond which a given E_star contradicts the materials' E*
E_STAR_RTOL = sp.Rational(1, 10**9)


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
    numbers: ``beta``, ``mu`` and ``size`` = |beta| mu; ``assumed`` is True
    where beta was not given (0 assumed: :data:`NOT_GIVEN`)."""

    beta: sp.Expr
    mu: sp.Expr
    size: sp.Expr
    assumed: bool = False


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


def _beta_value(beta):
    b = _value(beta)
    if not isinstance(b, sp.Expr) or b.is_real is False:
        raise DomainError(f"Dundurs' beta must be a real number or expression, got {beta!r}")
    if b.is_number and not (-sp.S.Half <= b <= sp.S.Half):
        raise DomainError(f"Dundurs' beta must lie in [-1/2, 1/2], got beta = {b} (|beta| <= 1/2 for any two "
                          f"elastic bodies; lcs.dundurs_beta(E1, nu1, E2, nu2) computes it)")
    return b


def _material_pair(materials):
    try:
        (E1, nu1), (E2, nu2) = materials
    except (TypeError, ValueError):
        raise DomainError(f"materials must be ((E1, nu1), (E2, nu2)), the two bodies' Young's moduli and Poisson's "
                          f"ratios, got {materials!r}") from None
    out = (_modulus(E1, "E1"), _ratio(nu1, "nu1"), _modulus(E2, "E2"), _ratio(nu2, "nu2"))
    if not all(v.is_number for v in out):
        raise DomainError(f"materials take numbers (E* and beta are checked against the state's E_star), got "
                          f"{materials!r}; for symbols pass beta=lcs.dundurs_beta(E1, nu1, E2, nu2)")
    return out


@dataclass(frozen=True)
class Coupling:
    """The two bodies as a frictional layer takes them (read by
    :func:`coupling` from the keywords of :data:`COUPLING_KEYWORDS`):
    ``beta`` (None: not given, 0 assumed), ``E_star`` (the materials' E*,
    None without materials), ``materials`` (E1, nu1, E2, nu2, or None)."""

    beta: sp.Expr | None = None
    E_star: sp.Expr | None = None
    materials: tuple | None = None

    @property
    def given(self) -> bool:
        return self.beta is not None

    def keywords(self) -> str:
        """', beta=...' for a repr ('' where nothing was given)."""
        if self.materials is not None:
            E1, nu1, E2, nu2 = self.materials
            return f", materials=(({E1}, {nu1}), ({E2}, {nu2}))"
        return "" if self.beta is None else f", beta={self.beta}"

    def note(self, mu, warn: bool = False) -> CouplingNote:
        """The statement a frictional result carries at the friction
        coefficient ``mu``: :data:`NOT_GIVEN` where beta was not given, else
        :func:`neglected_coupling` (its DomainWarning where ``warn`` and
        beta != 0)."""
        if self.beta is None:
            m = _value(mu)
            note = CouplingNote(NOT_GIVEN + ": the normal and tangential problems are taken as uncoupled "
                                "(Goodman's approximation); give beta= or materials= to have the neglected "
                                "coupling |beta| mu stated")
            note.beta, note.mu, note.size, note.assumed = sp.S.Zero, m, sp.S.Zero, True
            return note
        return neglected_coupling(self.beta, mu, warn=warn)

    def values(self, values: dict) -> dict:
        """Keyword values of a state or an evaluation with E_star filled from
        the materials where it is not given; an E_star that contradicts the
        materials' E* (relative difference > 1e-9) raises DomainError.
        Without materials: ``values`` as they are."""
        if self.E_star is None:
            return values
        if "E_star" not in values:
            return {**values, "E_star": self.E_star}
        given = values["E_star"]
        mag = given.to("Pa").magnitude if hasattr(given, "to") and hasattr(given, "units") else given
        try:
            g = _value(mag)
        except (DomainError, TypeError, ValueError):
            return values          # not a number: the state's own reading refuses it
        if not (isinstance(g, sp.Expr) and g.is_number):
            return values
        if sp.Abs(g - self.E_star) > E_STAR_RTOL * self.E_star:
            E1, nu1, E2, nu2 = self.materials
            raise DomainError(f"E_star = {given} contradicts the materials ((E1, nu1), (E2, nu2)) = (({E1}, {nu1}), "
                              f"({E2}, {nu2})), whose reduced modulus is E* = {sp.N(self.E_star, 12)} "
                              f"(reduced_modulus); omit E_star to use the materials' value, or give the "
                              f"materials that belong to it")
        return values


def coupling(beta=None, materials=None) -> Coupling:
    """The one reader of the keywords of :data:`COUPLING_KEYWORDS`: beta
    given (a number in [-1/2, 1/2] or an expression), or the two bodies'
    materials (numbers: beta and E* computed), or nothing (0 assumed, said).
    Both: they must agree.

    >>> coupling(materials=((210, 0.3), (70, 0.33))).beta
    -4183/35833
    >>> coupling().note(0.3)[:44]
    'beta = 0 assumed (elastically similar bodies'
    """
    if isinstance(beta, Coupling):
        return beta
    if materials is None:
        return Coupling(None if beta is None else _beta_value(beta))
    E1, nu1, E2, nu2 = _material_pair(materials)
    b, E = dundurs_beta(E1, nu1, E2, nu2), reduced_modulus(E1, nu1, E2, nu2)
    if beta is not None and sp.simplify(_beta_value(beta) - b) != 0:
        raise DomainError(f"beta = {beta} contradicts the materials, whose Dundurs beta is {b} "
                          f"(= {sp.N(b, 6)}); give one of them")
    return Coupling(b, E, (E1, nu1, E2, nu2))
