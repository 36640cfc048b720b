"""Layer 3: numbers from derived results.

``special`` (the stable special functions: Carlson integrals, Gamma ratios,
2F1 with its complement), ``stable`` (accuracy-preserving rewrites, one rule
object each, and :func:`~.stable.stabilize`), ``exports`` (float64 / mpmath
callables), ``quadrature`` (vectorised float64 tanh-sinh for integrals without
a closed form), ``certified`` (Arb balls; python-flint, the ``[certified]``
extra), ``reference`` (the one reference integrator: Arb ball quadrature,
mpmath as its recorded fallback) with ``arb_compile`` (SymPy compiled to
functions of Arb balls) and ``endpoints`` (its end-point transforms),
``accuracy`` (condition numbers, audits against a reference), ``evaluate``
(the cheapest path that meets a tolerance), ``cache`` (the per-object caches
this layer owns).  Works on
:class:`~linecontact_sym.method.derivation.Derivation` objects; knows no
contact class.
"""
