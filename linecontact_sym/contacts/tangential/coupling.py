"""The two bodies of a frictional contact (tangential loading, fretting,
rolling): what the layers take (``beta=`` or ``materials=``, declared once in
:data:`~linecontact_sym.core.materials.COUPLING_KEYWORDS`) and what every
frictional result says about it.

Every solution of the package is Goodman's approximation: the shear traction
leaves the pressure unchanged, i.e. Dundurs' beta is neglected (exact for
elastically similar bodies).  The numbers never depend on beta; the results
state it: "beta = 0 assumed (elastically similar bodies)" where the bodies
were not given, else the size of the neglected coupling |beta| mu
(:func:`~linecontact_sym.core.materials.neglected_coupling`), with one
:class:`~linecontact_sym.core.errors.DomainWarning` per contact where
beta != 0.  Materials also give E* (``reduced_modulus``): it fills E_star
where a number is asked without it, and a contradicting E_star is refused.
"""
from __future__ import annotations

import dataclasses

from ...core import symbols as S
from ...core.materials import Coupling, CouplingNote, coupling


def read_coupling(friction, beta=None, materials=None, warn: bool = True) -> Coupling:
    """The :class:`~linecontact_sym.core.materials.Coupling` of a new
    frictional contact with the friction coefficient ``friction`` (the
    contact's mu); the DomainWarning of a beta != 0 here, once per contact
    (``warn``)."""
    c = coupling(beta, materials)
    if warn and c.given:
        c.note(friction, warn=True)
    return c


class FrictionalCoupling:
    """Mixin of the frictional contacts (``self.coupling``, ``self.mu``):
    every derivation carries the coupling note first among its notes, and
    numbers asked without E_star (``evaluate``, ``evaluate_at``, the
    parameters fixed by ``to_numeric``) take the materials' E*; an E_star
    that contradicts them is refused."""

    coupling: Coupling = Coupling()

    @property
    def coupling_note(self) -> CouplingNote:
        """What the results of this contact say about the neglected coupling
        (at the contact's mu, symbolic or a number); no warning."""
        return self.coupling.note(self.mu)

    def noted(self, d):
        """The derivation ``d`` with the coupling note first among its notes
        (a copy: derivations remembered across contacts stay as they are);
        ``d`` itself where there is no note (a frictionless stress field)."""
        note = self.coupling_note
        if note is None or d.notes[:1] == (note,):
            return d
        key = ("_noted", d.quantity)
        cache = self._caches()
        hit = cache.get(key)
        if hit is not None and hit[0] is d:
            return hit[1]
        out = dataclasses.replace(d, notes=(note,) + tuple(d.notes))
        cache[key] = (d, out)
        return out

    def derivation(self, quantity: str):
        return self.noted(super().derivation(quantity))

    def _with_materials(self, quantity, values: dict) -> dict:
        """``values`` with E_star from the materials where the quantity takes
        E_star and it is not given; a contradicting E_star refused."""
        if self.coupling.E_star is None:
            return values
        if "E_star" in values or S.E_star in set(super().derivation(quantity).variables_all):
            return self.coupling.values(values)
        return values

    def evaluate_at(self, quantity: str, dps: int = 30, **values):
        return super().evaluate_at(quantity, dps, **self._with_materials(quantity, values))

    def to_numeric(self, quantity: str, backend: str = "numpy", dps: int = 30, check: bool = True, **params):
        return super().to_numeric(quantity, backend, dps, check, **self._with_materials(quantity, params))

    def evaluate(self, quantity: str, rtol=None, certified: bool = False, dps=None, **values):
        return super().evaluate(quantity, rtol=rtol, certified=certified, dps=dps,
                                **self._with_materials(quantity, values))


__all__ = ["FrictionalCoupling", "read_coupling"]
