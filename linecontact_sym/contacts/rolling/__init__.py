"""Steady rolling with traction for any profile (Carter 1926 for the cylinder):
the stick zone at the leading edge, the creepage and the traction, by the
reduction to the bounded pressure of the same profile, tilted, over the stick
zone.

* :mod:`.contact`  -- :class:`RollingLineContact` (conventions, the reduction, its quantities);
* :mod:`.state`    -- states at numbers, admissibility, the creepage-force curve;
* :mod:`.interval` -- the bounded solution on a non-centred interval (load, tilt, pressure).
"""
from .contact import RollingLineContact

__all__ = ["RollingLineContact"]
