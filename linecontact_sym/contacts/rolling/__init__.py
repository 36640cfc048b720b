"""Steady rolling with traction for any profile (Carter 1926 for the cylinder;
Johnson 1985, ch. 8): the stick zone at the leading edge, the creepage and the
traction, by the reduction to the bounded pressure of the same profile, tilted,
over the stick zone: Popov's (2017) superposition of flat punches, Eqs. (10)
and (12), with the interval's centre as a second parameter (the asymmetric
core, :mod:`linecontact_sym.contacts.asymmetric`).

* :mod:`.contact`  -- :class:`RollingLineContact` (conventions, the reduction, its quantities);
* :mod:`.state`    -- states at numbers, admissibility, the creepage-force curve;
* :mod:`.interval` -- the numbers of the interval solution (load, tilt, pressure, J).
"""
from .contact import RollingLineContact

__all__ = ["RollingLineContact"]
