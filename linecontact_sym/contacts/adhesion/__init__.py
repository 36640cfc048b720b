"""Adhesion on top of the normal contact, generic over the cohesive law.

A cohesive law (:mod:`.law`) says what is specific to one model of adhesion:
its parameters and their domains, the balance that fixes the equilibrium at
each half-width, P(a) and p(x; a) (symbolic, or as equations with a numeric
inner solve), P and dP/da at numbers, and closed forms where it has them.
Everything else is generic: equilibria and their stability, pull-off (every
minimum, kink and end of the admissible range), jump-in, the branches of
P(a), plots, claims and the CLI.

* :mod:`.law`         -- :class:`~.law.CohesiveLaw`, :class:`~.law.Parameter`: the interface;
* :mod:`.jkr`         -- the JKR law of Popov (2017), Eqs. (29)-(36): a pulled flat punch
  (Eqs. 30-31) superposed on the non-adhesive solution;
* :mod:`.contact`     -- :class:`AdhesiveContact` (any law), :class:`AdhesiveLineContact` (JKR),
  :func:`register_law`, :func:`adhesive_contact`;
* :mod:`.pull_off`    -- the pull-off (symbolic attempt and numeric minimum);
* :mod:`.branches`    -- jump-in half-width, the branches of P(a), the equilibrium check of p;
* :mod:`.brute_force` -- the independent second pull-off method;
* :mod:`.maugis`      -- the folder of the Maugis-Dugdale (cohesive-zone) law of any profile,
  :class:`MaugisDugdale` and :class:`MaugisDugdaleContact` (the generic contact plus its state and
  conditions; its map in its docstring).

The registered laws (a new law: its module, and one line here):
"""
from .contact import LAWS, AdhesiveContact, AdhesiveLineContact, adhesive_contact, register_law
from .jkr import JKR
from .law import CohesiveLaw, Parameter

from .maugis import MaugisDugdale, MaugisDugdaleContact

register_law(JKR, AdhesiveLineContact)
register_law(MaugisDugdale, MaugisDugdaleContact)

__all__ = ["AdhesiveContact", "AdhesiveLineContact", "CohesiveLaw", "Parameter", "JKR", "LAWS", "register_law",
           "adhesive_contact", "MaugisDugdale", "MaugisDugdaleContact"]
