"""The paper's profiles as ready-made contacts.  A convenience only: each
function builds the profile *expression* and hands it to the engine, so the
results are exactly those of typing the profile by hand."""
from __future__ import annotations

import sympy as sp

from ..core import symbols as S
from ..core.errors import LineContactError, ProfileError
from ..parsing import user_value
from .normal.contact import LineContact


def _param(value, name):
    """A catalogue parameter: a symbol or a number > 0 (text through the
    whitelisted parser, floats their shortest decimal); anything else raises
    :class:`ProfileError`."""
    try:
        v = user_value(value, where=name)
    except LineContactError as exc:
        raise ProfileError(f"{name}: {exc}") from None
    if v.has(sp.zoo, sp.nan, sp.oo, -sp.oo) or (v.is_number and not v.is_positive):
        raise ProfileError(f"{name} must be positive (a symbol or a number > 0), got {value!r}")
    return v


def parabola_profile(R=S.R):
    """f = x**2/(2R), Eq. (13)."""
    return S.x**2 / (2 * _param(R, "R"))


def power_law_profile(c=S.c, n=S.n):
    """f = c_n |x|**n, Eq. (15)."""
    return _param(c, "c") * S.x**_param(n, "n")


def wedge_profile(theta=S.theta):
    """f = |x| tan(theta), Eq. (18)."""
    return S.x * sp.tan(_param(theta, "theta"))


def worn_cylinder_profile(R=S.R, b=S.b):
    """Cylinder with a flat of half-width b, Eq. (21)."""
    R, b = _param(R, "R"), _param(b, "b")
    return sp.Piecewise((0, S.x < b), ((S.x**2 - b**2) / (2 * R), True))


def rounded_punch_profile(R=S.R, b=S.b):
    """A flat of half-width b with rounded corners of radius R (parabolic):
    f = 0 for |x| < b, (|x| - b)**2/(2R) beyond."""
    R, b = _param(R, "R"), _param(b, "b")
    return sp.Piecewise((0, S.x < b), ((S.x - b)**2 / (2 * R), True))


def exact_cylinder_profile(R=S.R):
    """f = R - sqrt(R**2 - x**2), Eq. (24)."""
    R = _param(R, "R")
    return R - sp.sqrt(R**2 - S.x**2)


def parabola(R=S.R, **kw):
    """The parabola f(x) = x**2/(2R), Popov (2017) Eqs. (13)-(14): the Hertz
    line contact of a cylinder of radius R (small a/R), with
    P(a) = pi E* a**2/(4R) and p(x) = E* sqrt(a**2 - x**2)/(2R).

    ``R``: the radius (a positive symbol or a number); keywords go to
    :class:`~linecontact_sym.contacts.normal.contact.LineContact` (``budget``,
    ``verify``, ...).  Domain: a > 0 (any half-width).

    >>> import linecontact_sym as lcs
    >>> lcs.parabola().profile.expr
    x**2/(2*R)
    >>> lcs.parabola(R=2).profile.expr
    x**2/4
    """
    return LineContact(parabola_profile(R), name="parabola", **kw)


def power_law(c=S.c, n=S.n, **kw):
    """The power law f(x) = c |x|**n, Eqs. (15)-(17): P(a) = E* c Z_n a**n
    with Popov's Z_n (Table 1); n may stay symbolic (random verification
    points then draw n from 0.3 to 6).

    ``c`` (the paper's c_n) > 0, ``n`` > 0; keywords go to
    :class:`~linecontact_sym.contacts.normal.contact.LineContact`.  A finite
    adhesive pull-off exists iff n > 1/2.

    >>> import linecontact_sym as lcs
    >>> lcs.power_law().profile.expr
    c*x**n
    >>> lcs.power_law(n=3).profile.expr
    c*x**3
    """
    kw.setdefault("params", {c: (0.5, 2.5), n: (0.3, 6.0)} if isinstance(n, sp.Symbol) else None)
    return LineContact(power_law_profile(c, n), name="power law", **kw)


def wedge(theta=S.theta, **kw):
    """The wedge f(x) = |x| tan(theta), Eqs. (18)-(20): P(a) = E* a tan(theta)
    (the printed Eq. (10) misses this boundary term, the engine's Eq. (10*)
    has it) and a pressure with a logarithmic singularity at x = 0.

    ``theta``: the wedge angle, 0 < theta < pi/2; keywords go to
    :class:`~linecontact_sym.contacts.normal.contact.LineContact`.

    >>> import linecontact_sym as lcs
    >>> lcs.wedge().profile.expr
    x*tan(theta)
    """
    kw.setdefault("params", {theta: (0.05, 1.2)} if isinstance(theta, sp.Symbol) else None)
    return LineContact(wedge_profile(theta), name="wedge", **kw)


def worn_cylinder(R=S.R, b=S.b, **kw):
    """A cylinder of radius R worn flat over |x| < b, Eqs. (21)-(23):
    f = 0 for |x| < b and (x**2 - b**2)/(2R) beyond; P(a) = 0 for a <= b and
    Eq. (23) for a > b.  The pressure and the gap have no closed form (the
    engine evaluates their integrals numerically and says so).

    ``R`` > 0, ``b`` > 0; keywords go to
    :class:`~linecontact_sym.contacts.normal.contact.LineContact`.

    >>> import linecontact_sym as lcs
    >>> lcs.worn_cylinder().profile.expr
    Piecewise((0, b > x), ((-b**2 + x**2)/(2*R), True))
    """
    kw.setdefault("params", {R: (4.0, 8.0), b: (0.3, 1.5)})
    return LineContact(worn_cylinder_profile(R, b), name="worn cylinder", **kw)


def rounded_punch(R=S.R, b=S.b, **kw):
    """The rounded punch of Ciavarella, Hills & Monno (1998): a flat of
    half-width b with corners of radius R, f = 0 for |x| < b and
    (|x| - b)**2/(2R) beyond.  For a <= b the flat is in full contact at
    P = 0 (Popov's parametrisation: the force law is 0 up to b); past b the
    contact grows with the load, P(a) = E* a**2/(4R) (pi - 2 phi0 - sin 2 phi0)
    with sin(phi0) = b/a, and the pressure is bounded everywhere.

    ``R`` > 0, ``b`` > 0; keywords go to
    :class:`~linecontact_sym.contacts.normal.contact.LineContact`.

    >>> import linecontact_sym as lcs
    >>> lcs.rounded_punch().profile.expr
    Piecewise((0, b > x), ((-b + x)**2/(2*R), True))
    """
    kw.setdefault("params", {R: (4.0, 8.0), b: (0.3, 1.5)})
    return LineContact(rounded_punch_profile(R, b), name="rounded punch", **kw)


def exact_cylinder(R=S.R, **kw):
    """The exact circle f(x) = R - sqrt(R**2 - x**2), Eqs. (24)-(28):
    P(a) = E* R [K(k) - E(k)] with the modulus k = a/R (in SymPy:
    elliptic_k(a**2/R**2), which takes the parameter m = k**2); defined for
    0 < a < R.

    ``R`` > 0; keywords go to
    :class:`~linecontact_sym.contacts.normal.contact.LineContact`.

    >>> import linecontact_sym as lcs
    >>> lcs.exact_cylinder().profile.expr
    R - sqrt(R**2 - x**2)
    """
    return LineContact(exact_cylinder_profile(R), name="exact cylinder", **kw)
