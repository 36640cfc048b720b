"""Subsurface stresses of the elastic half-plane under a line contact (plane
strain): Kolosov-Muskhelishvili potentials from the punch superposition's Cauchy
transform, checked against Flamant's integrals (Johnson 1985, Eq. 2.23); maxima of
the equivalent stresses and the critical friction of sliding (McEwen 1949).

* :mod:`.contact`   -- :class:`StressField`, :class:`SlidingStressField`;
* :mod:`.kolosov`   -- the symbolic potentials and stresses;
* :mod:`.build`     -- verified closed-form components, the reference at numbers;
* :mod:`.field`     -- the vectorised float64 field and equivalent stresses;
* :mod:`.extrema`   -- maxima in the body and on the surface, critical friction;
* :mod:`.reference` -- the independent Flamant quadrature.
"""
from .contact import SlidingStressField, StressField

__all__ = ["StressField", "SlidingStressField"]
