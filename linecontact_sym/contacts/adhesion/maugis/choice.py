"""Which adhesion model a scene needs: the Maugis parameter of any profile
and the JKR-or-MD choice for a tolerance on the pull-off.

The Maugis parameter: Baney & Hui's lambda = 4 sigma_0 (R/(pi^2 E*^2 w))^(1/3)
equals sqrt(2^(5/3) a_JKR/delta) for the parabola, with a_JKR the JKR pull-off
half-width (2 w R^2/(pi E*))^(1/3) and delta = pi E* w/(4 sigma_0^2) the
cohesive-zone length of the JKR limit (c_D - a -> delta as sigma_0 -> oo);
the second form defines lambda for every profile (tested against the first).
"""
from __future__ import annotations

from dataclasses import dataclass

import mpmath
import sympy as sp

from ....core import symbols as S
from ....core.conversion import to_mpf
from ....core.errors import DomainError
from ....parsing import user_value
from ....core.precision import workdps
from .numbers import fixed_values


@dataclass
class ModelChoice:
    """Which adhesion model a tolerance needs.

    model        'JKR' (its pull-off within rtol of MD's) or 'MD'
    maugis_parameter  lambda (Baney & Hui's for the parabola; see the module docstring)
    jkr, md      the two pull-off forces (P_min)
    relative_difference  |P_JKR - P_MD|/|P_MD|
    """

    model: str
    maugis_parameter: mpmath.mpf
    jkr: mpmath.mpf
    md: mpmath.mpf
    relative_difference: mpmath.mpf
    rtol: float

    def __str__(self):
        return (f"{self.model}: lambda = {mpmath.nstr(self.maugis_parameter, 6)}, pull-off JKR "
                f"{mpmath.nstr(self.jkr, 8)} vs MD {mpmath.nstr(self.md, 8)} (relative difference "
                f"{mpmath.nstr(self.relative_difference, 3)}, rtol {self.rtol})")


def maugis_parameter(md, dps: int = 20, **values):
    """lambda = sqrt(2^(5/3) a_JKR/delta), delta = pi E* w/(4 sigma_0^2) (the
    cohesive-zone length of the JKR limit), a_JKR the JKR pull-off
    half-width; equal to Baney & Hui's 4 sigma_0 (R/(pi^2 E*^2 w))^(1/3)
    for the parabola."""
    vals = fixed_values(md._numeric_values(values))
    po = md.jkr.pull_off_at(dps, **md._jkr_values(values))
    with workdps(dps + 10):
        E = mpmath.mpf(str(sp.N(vals[S.E_star], dps + 20)))
        w = mpmath.mpf(str(sp.N(md.w.xreplace(vals), dps + 20)))
        s0 = mpmath.mpf(str(sp.N(md.sigma0.xreplace(vals), dps + 20)))
        delta = mpmath.pi * E * w / (4 * s0**2)
        return +mpmath.sqrt(mpmath.mpf(2)**(mpmath.mpf(5) / 3) * po.half_width / delta)


def sigma0_for(md, lam, dps: int = 20, **values):
    """The cohesive stress sigma_0 that gives the Maugis parameter ``lam``
    at the other values (lambda is proportional to sigma_0)."""
    if not md.sigma0.is_Symbol:
        raise DomainError("sigma0_for needs sigma_0 to be a symbol of the contact")
    with workdps(dps + 10):
        one = md.maugis_parameter(dps, **{**values, md.sigma0.name: 1})
        return to_mpf(user_value(lam)) / one


def model_choice(md, rtol=0.05, dps: int = 15, **values) -> ModelChoice:
    """'JKR' when the JKR pull-off is within ``rtol`` of the MD one, else
    'MD'; with the Maugis parameter."""
    po_md = md.pull_off_at(dps, **values)
    po_j = md.jkr.pull_off_at(dps, **md._jkr_values(values))
    lam = md.maugis_parameter(dps, **values)
    with workdps(dps + 5):
        rel = abs(po_j.force - po_md.force) / abs(po_md.force)
    return ModelChoice("JKR" if rel <= rtol else "MD", lam, po_j.force, po_md.force, rel, rtol)


__all__ = ["ModelChoice", "maugis_parameter", "sigma0_for", "model_choice"]
