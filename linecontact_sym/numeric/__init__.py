"""Layer 3: numbers from derived results.

``stable`` (accuracy-preserving rewrites and their special functions),
``exports`` (float64 / mpmath callables), ``certified`` (Arb balls),
``evaluate`` (the cheapest path that meets a tolerance).  Works on
:class:`~linecontact_sym.method.derivation.Derivation` objects; knows no
contact class.
"""
