"""The cohesive-law interface: what one model of adhesion says, and nothing
else (cf. a SymPy ``stats`` distribution: it declares its parameters and
their domains, checks them, and states the defining relation; the generic
machinery computes the rest).

A law is a subclass of :class:`CohesiveLaw` that provides

``parameters``        :class:`Parameter` s (name, default symbol, domain, a
                      range for random verification points);
``derive_force(ad)``  the :class:`~linecontact_sym.method.derivation.Derivation`
                      of P(a) on the normal contact ``ad.contact``: a closed
                      expression in ``a`` (JKR: P0(a) - Phat(a)), or, where the
                      balance is a system (Maugis-Dugdale: bounded pressure at
                      x = +-a and gap(c) = h0), ``closed_form=False`` with the
                      equations as its ``expr`` and an ``evalf`` by an inner solve;
``derive_pressure(ad)``  the pressure p(x; a) likewise;
``numeric(base, values)``  P(a) and dP/da at numbers: a
                      :class:`~linecontact_sym.contacts.normal.force_law.ForceLaw`
                      built on the non-adhesive law ``base`` with :func:`on_base`
                      (an inner solve, e.g. for c(a), goes inside its P and dP);

and optionally closed forms the generic layer uses where they exist
(:meth:`CohesiveLaw.pull_off_conditions`, :meth:`CohesiveLaw.pull_off_compact`,
:meth:`CohesiveLaw.jump_in_candidates`) and quantities of its own
(``quantities``: name -> :class:`~linecontact_sym.contacts.base.Quantity`, each
derived by a method ``derive_<name>(ad)`` of the law).

The generic layer (:mod:`.contact`, :mod:`.pull_off`, :mod:`.branches`,
:mod:`.brute_force`, :mod:`~linecontact_sym.contacts.normal.equilibria`) does the
rest for every law: equilibria and their stability, the pull-off (every
minimum, kink and end of the admissible range), jump-in, the branches a(P),
the plots, the claims quantities and the CLI.  A new law is its own module
and one registration line (:func:`.contact.register_law` in
:mod:`linecontact_sym.contacts.adhesion`); see docs/architecture.md.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from ...core import symbols as S
from ...core.errors import DomainError
from ...parsing import user_value

#: domains a parameter may declare
DOMAINS = ("nonnegative", "positive")


@dataclass(frozen=True)
class Parameter:
    """One parameter of a cohesive law.

    name     the keyword it is given by (``work_of_adhesion``)
    symbol   its default value, a SymPy symbol declared positive (``lcs.gamma``)
    domain   ``"nonnegative"`` (zero allowed: no adhesion) or ``"positive"``
    doc      what it is, as it reads in an error message ("the work of adhesion")
    sample   range of the random verification points of its symbols
    unit     the SI unit of a value given with units (pint), for a symbol of the
             law's own; the standard symbols' are in ``core.symbols.UNITS``
    """

    name: str
    symbol: sp.Symbol
    domain: str = "positive"
    doc: str = ""
    sample: tuple = (0.005, 0.5)
    unit: str | None = None

    def checked(self, value) -> sp.Expr:
        """A user's value of the parameter, checked against its domain (a
        :class:`~linecontact_sym.core.errors.DomainError` names what fails)."""
        what = self.doc or self.name
        if isinstance(value, str):
            raise DomainError(f"{what} is a string; strings are not evaluated. "
                              f"Pass a SymPy expression or a number (e.g. lcs.{self.symbol.name})")
        v = user_value(value)
        if not isinstance(v, sp.Expr):
            raise DomainError(f"{what} must be an expression, got {v!r}")
        if v.has(S.x, S.a, S.P):
            raise DomainError(f"{what} {v} may not depend on x, a or P")
        if self.domain == "nonnegative":
            if v.is_negative:
                raise DomainError(f"{what} must be >= 0, got {v}")
            if v.is_nonnegative is not True:
                raise DomainError(f"the sign of {what} {v} is unknown; use a symbol created with positive=True "
                                  f"(e.g. lcs.{self.symbol.name}) or a number >= 0")
        else:
            if v.is_nonpositive:
                raise DomainError(f"{what} must be > 0, got {v}")
            if v.is_positive is not True:
                raise DomainError(f"the sign of {what} {v} is unknown; use a symbol created with positive=True "
                                  f"(e.g. lcs.{self.symbol.name}) or a number > 0")
        return v


class CohesiveLaw:
    """Base of the cohesive laws (see the module docstring).

    ``CohesiveLaw(*args, **kw)`` binds values to :attr:`parameters` (in order,
    or by name; unset ones are their default symbols) and checks them.
    """

    #: registry key (``"jkr"``) and the kind of the contact it makes (``"adhesive"``)
    name = ""
    kind = ""
    #: what it is, one line, with its reference; a short label for plots and tables
    title = ""
    label = ""
    parameters: tuple = ()
    #: extra quantities of the law's contact: name -> Quantity, each derived by ``derive_<name>(ad)``
    quantities: dict = {}
    #: is the grid search of :mod:`.brute_force` on the quadrature twin (``numeric`` on the quadrature
    #: P0) independent of the law's own P(a)?  True where the adhesive term is closed (JKR).  A law
    #: whose P(a) is an inner solve that its quadrature twin shares (Maugis-Dugdale's c_D(a)) says
    #: False: its numeric pull-offs are then one method's (``PullOff.digits`` None, the note says
    #: so), checked by the law's own independent tests, never reported as agreeing with themselves
    independent_minimum = True

    def __init__(self, *args, **kw):
        names = [p.name for p in self.parameters]
        if len(args) > len(names):
            raise DomainError(f"{type(self).__name__} takes {len(names)} parameter(s): {', '.join(names)}")
        given = dict(zip(names, args))
        for k, v in kw.items():
            if k not in names:
                raise DomainError(f"{type(self).__name__} has no parameter {k!r}; its parameters: {', '.join(names)}")
            if k in given:
                raise DomainError(f"{k} given twice")
            given[k] = v
        self.values = {p.name: p.checked(given.get(p.name, p.symbol)) for p in self.parameters}

    def check(self):
        """Check every parameter against its domain again (values set by hand)."""
        for p in self.parameters:
            p.checked(self.values[p.name])
        return True

    def __getitem__(self, name):
        return self.values[name]

    def __repr__(self):
        return f"{type(self).__name__}({', '.join(f'{k}={v}' for k, v in self.values.items())})"

    def __eq__(self, other):
        return type(self) is type(other) and self.values == other.values

    def __hash__(self):
        return hash((type(self).__name__, tuple(self.values.items())))

    @property
    def symbols(self) -> tuple:
        """The symbols of the parameters' values, sorted by name."""
        out = set()
        for v in self.values.values():
            out |= v.free_symbols
        return tuple(sorted(out, key=lambda s: s.name))

    def sample_ranges(self) -> dict:
        """symbol -> range of random verification points (each parameter's ``sample``)."""
        out = {}
        for p in self.parameters:
            for s in self.values[p.name].free_symbols:
                out.setdefault(s, p.sample)
        return out

    def numbers(self, values: dict) -> dict:
        """The parameters at numeric values (Symbols -> numbers): name -> SymPy number;
        a :class:`DomainError` when one stays symbolic."""
        out = {}
        for name, v in self.values.items():
            n = v.xreplace(values)
            if not n.is_number:
                raise DomainError(f"{name} = {v} needs a value")
            out[name] = n
        return out

    # ----------------------------------------------------------- what a law provides
    @property
    def inactive(self) -> bool:
        """True where the law exerts no adhesion at all (JKR: gamma = 0): then
        P(a) = P0(a) and there is no tensile pull-off."""
        return False

    #: the sentence that says why an inactive law has no pull-off
    inactive_reason = "no adhesion"

    def derive_force(self, ad):
        """The Derivation of P(a) (closed expression, or the equations with a numeric evalf)."""
        raise NotImplementedError(f"{type(self).__name__} does not derive the force law")

    def derive_pressure(self, ad):
        """The Derivation of p(x; a)."""
        raise NotImplementedError(f"{type(self).__name__} does not derive the pressure")

    def numeric(self, base, values: dict):
        """P(a), dP/da at numbers: a ForceLaw on ``base`` (see :func:`on_base`)."""
        raise NotImplementedError(f"{type(self).__name__} has no numeric force law")

    # ----------------------------------------------------------- optional closed forms
    def pull_off_conditions(self, ad, force0, values=None) -> list:
        """Conditions for a finite pull-off read from the non-adhesive force
        law's Derivation ``force0``; raise NoPullOffError where there is none
        (``values``: at a numeric point)."""
        return []

    def pull_off_compact(self, ad, force0, Pmin, a_star, conds):
        """A compact closed form of the pull-off, ``(Pmin, a_star, P_adh, note)``,
        or None (then ``sympy.solve``'s result, tidied, stands)."""
        return None

    def stationary_candidates(self, ad, force0):
        """``(candidates, note)``: half-widths where dP/da = 0 may hold, in
        closed form, tried (checked at random points) before ``sympy.solve``;
        or None."""
        return None

    def jump_in_candidates(self, ad, force0):
        """``(candidates, method, extra conditions)`` for the stable root of
        P(a) = 0 in closed form, or None (then ``sympy.solve`` is tried)."""
        return None


def on_base(base, build):
    """The adhesive ForceLaw ``build(base)`` on the non-adhesive law ``base``,
    with its quadrature twin (the same law built on ``base``'s quadrature
    route: what the independent checks use).  ``build`` returns a ForceLaw."""
    law = build(base)
    law.base = base
    if base.fallback is not None:
        law.quad = on_base(base.fallback, build)
    elif base.mode == "quad":
        law.quad = law
    return law


__all__ = ["Parameter", "CohesiveLaw", "on_base", "DOMAINS"]
