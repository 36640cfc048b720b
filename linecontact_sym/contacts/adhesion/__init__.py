"""Adhesion on top of the normal contact: the JKR line contact of Popov (2017),
Eqs. (29)-(36): a pulled flat punch (Eqs. 30-31) superposed on the non-adhesive
solution; equilibria, stability, pull-off (Eqs. 34-36), jump-in and the
branches of P(a).

* :mod:`.contact`     -- :class:`AdhesiveLineContact` and its registry of quantities;
* :mod:`.jkr`         -- the JKR law: the pulled flat punch, the stress-intensity and
  energy routes;
* :mod:`.pull_off`    -- the pull-off (symbolic attempt and numeric minimum);
* :mod:`.branches`    -- pressure, jump-in half-width, the branches of P(a);
* :mod:`.brute_force` -- the independent second pull-off method;
* :mod:`.maugis`      -- :class:`MaugisDugdaleContact`, the Maugis-Dugdale (cohesive-zone)
  law of any profile (:mod:`.maugis_derive` the derivation, :mod:`.maugis_law` the
  numbers, :mod:`.maugis_check` the independent checks).
"""
from .contact import AdhesiveLineContact
from .maugis import MaugisDugdaleContact

__all__ = ["AdhesiveLineContact", "MaugisDugdaleContact"]
