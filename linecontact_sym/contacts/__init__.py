"""Layer 5: one object per physical system (cf. SymPy's ``Beam``): the
frictionless line contact, its JKR-adhesive and tangential forms, the
subsurface stress field under any of them, the catalogue of the paper's
profiles.  Importing the package registers every
contact kind (:data:`~.base.CONTACT_KINDS`)."""
from . import frictionless, adhesive, tangential, stresses  # importing registers the kinds

__all__ = ["frictionless", "adhesive", "tangential", "stresses"]
