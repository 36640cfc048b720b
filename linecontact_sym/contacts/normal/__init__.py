"""The frictionless, non-adhesive line contact: Popov (2017), Eqs. (9)-(12).

* :mod:`.contact`       -- :class:`LineContact`: force law P(a) (Eq. 10), pressure
  p(x; a) (Eq. 12), gap, half-width a(P), each declared once in the registry;
* :mod:`.admissibility` -- where the compact-contact solution holds (f non-decreasing,
  dP/da >= 0);
* :mod:`.inverse`       -- the inverse map, Eq. (9): the profile of a given force law;
* :mod:`.force_law`     -- the numeric force law P(a) at fixed parameters (slope, kinks,
  admissible range);
* :mod:`.equilibria`    -- the one scan / bracket / root / minimum toolkit over a force law;
* :mod:`.periodic`      -- :class:`PeriodicLineContact`: a periodic array (``LineContact(f, period=L)``),
  the isolated contact of its kernel twin in s = sin(pi x/L) mapped back (Koiter's periodic punch).
"""
from .contact import LineContact
from .periodic import PeriodicLineContact

LineContact.GEOMETRIES["periodic"] = PeriodicLineContact

__all__ = ["LineContact", "PeriodicLineContact"]
