"""Layer 5: one object per physical system (cf. SymPy's ``Beam``), grouped by
physical effect, one subpackage each:

* :mod:`.normal`     -- the frictionless, non-adhesive line contact (Popov 2017, Eqs. 9-12);
* :mod:`.adhesion`   -- adhesion on top of it (JKR: Popov 2017, Eqs. 29-36);
* :mod:`.tangential` -- partial slip and fretting (Cattaneo-Mindlin-Jaeger superposition);
* :mod:`.stresses`   -- subsurface stresses (Kolosov potentials, McEwen 1949);
* :mod:`.asymmetric` -- a tilt, a moment, a profile that is not symmetric: the
  superposition of flat punches that are not centred (the core the rolling
  contact stands on);
* :mod:`.rolling`    -- steady rolling with traction, the stick zone at the leading
  edge (Carter 1926 for every profile, on the asymmetric core).

:mod:`.base` holds the contact base class and the quantity registry shared by
all of them, :mod:`.sampling` the verification points, :mod:`.catalogue` the
paper's profiles as ready-made contacts.  Importing the package registers every
contact kind (:data:`~.base.CONTACT_KINDS`)."""
from . import normal, adhesion, tangential, stresses, asymmetric, rolling  # importing registers the kinds

__all__ = ["normal", "adhesion", "tangential", "stresses", "asymmetric", "rolling"]
