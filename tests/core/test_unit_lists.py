"""A list of pint quantities is a list of values with units (issue 42,
class 1): converted elementwise where quantities are taken, refused where
plain SI numbers are (before: pint's DimensionalityError)."""
import numpy as np
import pytest

import linecontact_sym as lcs

pint = pytest.importorskip("pint")
Q_ = pint.UnitRegistry().Quantity


def test_a_list_of_quantities_is_converted_elementwise():
    c = lcs.parabola(verify=False)
    r = c.evaluate("force", a=[Q_(1, "mm"), Q_(2, "mm")], E_star=Q_(210, "GPa"), R=Q_(5, "mm"))
    plain = c.evaluate("force", a=np.array([1e-3, 2e-3]), E_star=210e9, R=5e-3)
    assert np.allclose(np.asarray(r.value, dtype=float), np.asarray(plain.value, dtype=float), rtol=1e-14)
    assert str(r.unit) in ("newton / meter", "N / m")
    # P = pi E* a**2/(4 R) at a = 1 mm: 32986.72... N/m per GPa: 3.2987e7 N/m
    assert abs(float(np.asarray(plain.value)[0]) - np.pi * 210e9 * 1e-6 / (4 * 5e-3)) < 1e-6


def test_a_list_mixing_quantities_and_numbers_or_dimensions_is_refused():
    c = lcs.parabola(verify=False)
    with pytest.raises(lcs.DomainError, match="mixes pint quantities and plain numbers"):
        c.evaluate("force", a=[Q_(1, "mm"), 2e-3], E_star=Q_(210, "GPa"), R=Q_(5, "mm"))
    with pytest.raises(lcs.DomainError, match="dimension"):
        c.evaluate("force", a=[Q_(1, "mm"), Q_(1, "s")], E_star=Q_(210, "GPa"), R=Q_(5, "mm"))
    with pytest.raises(lcs.DomainError, match="plain SI"):
        c.adhesive().pull_off_at(R=[Q_(1, "mm")], E_star=1, gamma=1)
