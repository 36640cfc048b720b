"""Tangential line contact with Coulomb friction: partial slip, unloading,
reloading and fretting for any profile by the Cattaneo-Mindlin-Jaeger
superposition on Popov's (2017) flat-punch parametrisation (the paper's outlook):
the traction is mu times differences of normal pressures p(x; c) of Eq. (12), the slip
mu times normal gaps (Eqs. 3-5), with the plane-strain Flamant kernel of the normal
problem (Johnson 1985, Eqs. 2.19-2.25); Cattaneo 1938, Mindlin 1949, Mindlin &
Deresiewicz 1953, Ciavarella 1998, Jaeger 1998.

* :mod:`.contact`   -- :class:`TangentialLineContact` and its registry of quantities;
* :mod:`.states`    -- the derivations' machinery (verification points, references);
* :mod:`.history`   -- load histories at numbers (Mindlin-Deresiewicz, fretting loops);
* :mod:`.reference` -- independent solutions used to check the superposition.
"""
from .contact import TangentialLineContact

__all__ = ["TangentialLineContact"]
