"""The snap into full contact of an adhesive periodic array (Johnson 1995).

Where the end of the range of half-widths closes the contact
(:attr:`~linecontact_sym.method.geometry.Geometry.closes_at_end`: a periodic
array at a = L/2), P(a) of an adhesive contact rises from 0 to its first
local minimum (the pull-off of a partial contact), then to a local maximum,
and falls to -oo as a -> L/2 (the JKR punch's sqrt(tan(pi a/L))).  Under load
control a partial contact loaded beyond that maximum has no partial
equilibrium left: it snaps into full contact, which in JKR holds any
tension.  ``full_contact_at`` is that maximum (method A: every extremum of
the engine's law, :func:`~..normal.equilibria.first_maximum_after`) checked
by the independent grid search of :func:`~.brute_force.maximum_by_grid`
(method B); with no minimum before it the maximum is P(0+) = 0: the array
snaps into full contact at zero load (Johnson's sinusoid for
alpha > (3/4)/3^(1/4) = 0.570).  A maximum <= 0 means full contact at zero load.
"""
from __future__ import annotations

from dataclasses import dataclass

import mpmath

from ...core.errors import LineContactError, NoPullOffError, VerificationError
from ...core.precision import workdps
from ...method.verification import digits_agreeing
from ..normal.equilibria import first_maximum_after, minimum
from .brute_force import maximum_by_grid

__all__ = ["FullContact", "full_contact_at"]


@dataclass(frozen=True)
class FullContact:
    """The load of the snap into full contact of an adhesive periodic array.

    force       the load per period above which no partial contact is in
                equilibrium (the first maximum of P(a) after the pull-off);
                <= 0: full contact at zero load
    half_width  a at that maximum (0: the supremum P(0+) = 0)
    kind        'stationary', 'origin' (no local minimum: P decreases from 0)
                or 'end' (no adhesion: P(a) rises to the full-contact load
                at a = L/2, reached there, no snap)
    digits      agreement of the two independent methods
    note        how it was found
    """

    force: mpmath.mpf
    half_width: mpmath.mpf
    kind: str
    digits: float | None = None
    note: str = ""

    @property
    def at_zero_load(self) -> bool:
        """Does the array snap into full contact at zero load (force <= 0)?"""
        return self.force <= 0


def full_contact_at(ad, vals, dps: int) -> FullContact:
    """Method A (the engine's law, every extremum) checked by method B (grid)."""
    law = ad._law(vals, "closed")
    if not law.geometry.closes_at_end:
        raise LineContactError("full_contact_at: only a periodic array closes into full contact "
                               "(LineContact(f, period=L))")
    if law.inactive:
        return _without_adhesion(law, dps)
    try:
        po = minimum(law, dps)
        top = first_maximum_after(law, po.half_width, dps)
        if top is None:
            raise VerificationError("P(a) has a minimum but no maximum before full contact")
        A, P, kind = top.half_width, top.force, "stationary"
        note = f"the first maximum of P(a) after the pull-off minimum at a = {mpmath.nstr(po.half_width, 12)}"
    except NoPullOffError as exc:
        A, P, kind = mpmath.mpf(0), mpmath.mpf(0), "origin"
        note = f"no pull-off minimum ({exc}): P(a) falls from P(0+) = 0, the array snaps into full contact at once"
    b = maximum_by_grid(law, dps)
    with workdps(dps):
        d = float(dps) if kind == b.kind == "origin" else (digits_agreeing(P, b.force) if kind == b.kind else 0.0)
        # the location of a maximum is fixed to about half the digits of its load (flatter still next to
        # full contact, where a weak adhesion's maximum sits 1e-9 L below L/2): reported, not required
        dA = float(dps) if kind == "origin" else digits_agreeing(A, b.half_width)
    if kind == b.kind and d >= dps and dA < dps:
        note += f"; the half-width at the maximum agrees to {dA:.1f} digits (a maximum's location is fixed " \
                f"to about half the digits of its load)"
    if d < dps:
        raise VerificationError(f"the snap into full contact: the two methods agree to {d:.1f} < {dps} digits "
                                f"(A: P = {mpmath.nstr(P, 20)} at a = {mpmath.nstr(A, 20)}; B: {b.kind}, "
                                f"P = {mpmath.nstr(b.force, 20)})")
    with workdps(dps):      # the numbers at the digits the record states (a bare +P rounds to mpmath's 53 bits)
        return FullContact(+P, +A, kind, d, note + f"; method B ({b.note}) agrees to {d:.1f} digits")


def _without_adhesion(law, dps) -> FullContact:
    """No adhesion (gamma = 0): P(a) = P0(a) rises to the full-contact load
    P* = P0(L/2), which closes the contact at a = L/2 without a snap.  Method
    A: the engine's law at the end; method B: the quadrature law there."""
    top = law.geometry.mp_a_max(law.geometry_values)
    with workdps(dps + 10):
        P = law.base.P(top)
        Pq = law.quadrature_law.base.P(top)
        d = digits_agreeing(P, Pq)
    if d < dps:
        raise VerificationError(f"the full-contact load without adhesion: the engine's law and the quadrature law "
                                f"agree to {d:.1f} < {dps} digits ({mpmath.nstr(P, 20)}, {mpmath.nstr(Pq, 20)})")
    with workdps(dps):
        return FullContact(+P, +top, "end", min(d, float(dps)),
                           f"no adhesion (gamma = 0): P(a) = P0(a) rises to the full-contact load P* = P0(L/2), "
                           f"reached at a = L/2 without a snap; the quadrature law agrees to {d:.1f} digits")
