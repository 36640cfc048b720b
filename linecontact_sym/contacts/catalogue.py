"""The paper's profiles as ready-made contacts.  A convenience only: each
function builds the profile *expression* and hands it to the engine, so the
results are exactly those of typing the profile by hand."""
from __future__ import annotations

import sympy as sp

from ..core import symbols as S
from .frictionless import LineContact


def parabola_profile(R=S.R):
    """f = x**2/(2R), Eq. (13)."""
    return S.x**2 / (2 * R)


def power_law_profile(c=S.c, n=S.n):
    """f = c_n |x|**n, Eq. (15)."""
    return c * S.x**n


def wedge_profile(theta=S.theta):
    """f = |x| tan(theta), Eq. (18)."""
    return S.x * sp.tan(theta)


def worn_cylinder_profile(R=S.R, b=S.b):
    """Cylinder with a flat of half-width b, Eq. (21)."""
    return sp.Piecewise((0, S.x < b), ((S.x**2 - b**2) / (2 * R), True))


def exact_cylinder_profile(R=S.R):
    """f = R - sqrt(R**2 - x**2), Eq. (24)."""
    return R - sp.sqrt(R**2 - S.x**2)


def parabola(R=S.R, **kw):
    return LineContact(parabola_profile(R), name="parabola", **kw)


def power_law(c=S.c, n=S.n, **kw):
    kw.setdefault("params", {c: (0.5, 2.5), n: (0.3, 6.0)} if isinstance(n, sp.Symbol) else None)
    return LineContact(power_law_profile(c, n), name="power law", **kw)


def wedge(theta=S.theta, **kw):
    kw.setdefault("params", {theta: (0.05, 1.2)} if isinstance(theta, sp.Symbol) else None)
    return LineContact(wedge_profile(theta), name="wedge", **kw)


def worn_cylinder(R=S.R, b=S.b, **kw):
    kw.setdefault("params", {R: (4.0, 8.0), b: (0.3, 1.5)})
    return LineContact(worn_cylinder_profile(R, b), name="worn cylinder", **kw)


def exact_cylinder(R=S.R, **kw):
    return LineContact(exact_cylinder_profile(R), name="exact cylinder", **kw)
