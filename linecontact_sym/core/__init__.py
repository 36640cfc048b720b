"""Layer 0 of linecontact_sym: what every other layer stands on.

``symbols`` (the standard symbols, one place), ``errors`` (the package's
exceptions), ``conversion`` (number <-> SymPy <-> mpmath), ``budget``
(wall-clock limits for symbolic work), ``printing`` (the one LaTeX
printer), ``quadrature`` (the one tanh-sinh toolkit for difficult endpoints).  Nothing here imports anything else of the package.
"""
