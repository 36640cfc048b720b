"""Layer 5: one object per physical system (cf. SymPy's ``Beam``): the
frictionless line contact, its JKR-adhesive form, the catalogue of the
paper's profiles."""
