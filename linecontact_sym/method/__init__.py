"""Layer 2: Popov's (2017) method itself.

``profile`` (validation, pieces, breakpoints), ``hyperseries`` (termwise
Beta-kernel integration), ``transforms`` (Eqs. 9, 10*, 12 and the gap as
integrals, and their independent reference quadratures), ``rules`` (the
integration strategies), ``derivation`` (the dispatcher under the time
budget, the record of a result and its verification).
"""
