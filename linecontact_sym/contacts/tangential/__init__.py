"""Tangential line contact with Coulomb friction: partial slip, unloading,
reloading and fretting for any profile by the Cattaneo-Mindlin-Jaeger
superposition on Popov's (2017) flat-punch parametrisation (the paper's outlook).

* :mod:`.contact`   -- :class:`TangentialLineContact` and its registry of quantities;
* :mod:`.states`    -- the derivations' machinery (verification points, references);
* :mod:`.history`   -- load histories at numbers (Mindlin-Deresiewicz, fretting loops);
* :mod:`.reference` -- independent solutions used to check the superposition.
"""
from .contact import TangentialLineContact

__all__ = ["TangentialLineContact"]
