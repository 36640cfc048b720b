"""Standard symbols of ``linecontact_sym``, with SymPy assumptions.

Every module imports its symbols from here, so results built by different
parts of the toolkit share the same symbols and simplify together.  Users can
import them too::

    >>> import linecontact_sym as lcs
    >>> lcs.x, lcs.a, lcs.E_star
    (x, a, E_star)

Conventions (Popov 2017):

* ``x``      -- coordinate along the surface; profiles are given for x >= 0
  and mirrored (f(-x) = f(x)).
* ``a``      -- contact half-width.
* ``P``      -- normal force per unit length ("force intensity").  Real, not
  positive: adhesive contacts carry tensile (negative) loads.
* ``E_star`` -- reduced modulus E* = E/(1 - nu**2) (Eq. 4).
* ``gamma``  -- work of adhesion (the paper's gamma_12).
* ``R``, ``b``, ``n``, ``c``, ``theta`` -- the paper's profile parameters:
  radius, flat half-width, power-law exponent, power-law coefficient c_n and
  wedge angle.
* ``z``      -- depth below the surface (z > 0 into the body), for the
  subsurface stresses.
* ``zeta``   -- the complex coordinate x + i z of the complex potentials
  (no assumptions: complex).
* ``t``      -- time (viscoelastic materials and contacts,
  :mod:`linecontact_sym.method.material`, :mod:`linecontact_sym.contacts.viscoelastic`);
  positive.  It is also the name people give a bound integration variable
  in a formula (:mod:`linecontact_sym.parsing`): bound, it never meets the time.
* ``nu``     -- Poisson's ratio (plane strain: sigma_y = nu (sigma_x + sigma_z)); real,
  -1 < nu <= 1/2 (checked in one place, :mod:`linecontact_sym.core.ranges`).

Tangential (partial-slip) contact, :mod:`linecontact_sym.contacts.tangential.contact`:

* ``mu``  -- Coulomb friction coefficient (one coefficient, static = kinetic).
* ``Q``   -- tangential force per unit length, signed (real): its sign is the
  direction of the load; |Q| < mu*P for partial slip.
* ``c_s`` -- half-width of the central *stick* zone |x| < c_s (the literature's
  ``c``, Johnson 1985 ch. 7, Hills & Nowell 1994; ``c`` is taken here by the
  power-law coefficient and ``b`` by the flat half-width).  In a load
  reversal it is the stick half-width at the turning point.
* ``c_r`` -- half-width of the stick zone of a *reversal* (Mindlin-Deresiewicz
  unloading or reloading), c_s <= c_r <= a.

Asymmetric contacts (a tilt, a moment, a profile that is not symmetric),
:mod:`linecontact_sym.contacts.asymmetric`:

* ``x_real`` -- the coordinate x on the whole line (real, printed ``x``): the
  variable of a profile that is not mirrored (``LineContact(f, symmetric=False)``).
* ``e``      -- the centre of the contact interval [e - a, e + a] (real).
* ``tilt``   -- the rigid rotation theta_t of the indenter: the gap is
  f(x) - theta_t x - d, so theta_t > 0 moves the contact to +x (``theta`` is the
  wedge angle).
* ``M``      -- the moment per unit length about x = 0, M = int x p(x) dx: the
  load's line of action is at x = M/P.

Maugis-Dugdale adhesion, :mod:`linecontact_sym.contacts.adhesion.maugis`:

* ``sigma_0`` -- the Dugdale (cohesive) tension, constant while the gap is
  below h0 = gamma/sigma_0.
* ``c_D``     -- half-width of the Dugdale (cohesive) zone a <= |x| <= c_D
  (Maugis' and Baney & Hui's ``c``; ``c`` is the power-law coefficient here).
"""
from __future__ import annotations

import sympy as sp

x = sp.Symbol("x", positive=True)
a = sp.Symbol("a", positive=True)
P = sp.Symbol("P", real=True)
E_star = sp.Symbol("E_star", positive=True)
gamma = sp.Symbol("gamma", positive=True)

R = sp.Symbol("R", positive=True)
b = sp.Symbol("b", positive=True)
n = sp.Symbol("n", positive=True)
c = sp.Symbol("c", positive=True)
theta = sp.Symbol("theta", positive=True)

z = sp.Symbol("z", positive=True)
zeta = sp.Symbol("zeta")
nu = sp.Symbol("nu", real=True)   # -1 < nu <= 1/2: checked by core.ranges (0 and negative are valid)
mu = sp.Symbol("mu", positive=True)
Q = sp.Symbol("Q", real=True)
c_s = sp.Symbol("c_s", positive=True)
c_r = sp.Symbol("c_r", positive=True)
sigma_0 = sp.Symbol("sigma_0", positive=True)
x_real = sp.Symbol("x", real=True)
e = sp.Symbol("e", real=True)
tilt = sp.Symbol("theta_t", real=True)
M = sp.Symbol("M", real=True)
c_D = sp.Symbol("c_D", positive=True)
t = sp.Symbol("t", positive=True)

#: The SI unit of each symbol's value, for values given with units (pint,
#: :mod:`linecontact_sym.core.units`): "" is dimensionless.  ``c`` (of c x^n,
#: unit m^(1-n)) has none: its unit depends on n; it is checked through the profile.
UNITS = {"x": "m", "a": "m", "P": "N/m", "E_star": "Pa", "gamma": "J/m**2", "R": "m", "b": "m", "n": "",
         "theta": "rad", "z": "m", "nu": "", "mu": "", "Q": "N/m", "c_s": "m", "c_r": "m",
         "sigma_0": "Pa", "c_D": "m", "t": "s", "e": "m", "theta_t": "rad", "M": "N"}

#: Symbols the engine reserves; a profile may not use them as parameters.
RESERVED = (a, P, E_star)

#: LaTeX names in the paper's notation (used by the LaTeX views).
LATEX_NAMES = {
    E_star: r"E^{*}",
    gamma: r"\gamma_{12}",
    theta: r"\theta",
    c_s: r"c_{\mathrm{s}}",
    c_r: r"c_{\mathrm{r}}",
    sigma_0: r"\sigma_0",
    c_D: r"c_{\mathrm{D}}",
    tilt: r"\vartheta",
    zeta: r"\zeta",
    nu: r"\nu",
    mu: r"\mu",
}

__all__ = ["x", "a", "P", "E_star", "gamma", "R", "b", "n", "c", "theta", "mu", "Q", "c_s", "c_r", "sigma_0", "c_D", "t", "z", "zeta", "nu",
           "x_real", "e", "tilt", "M",
           "RESERVED", "LATEX_NAMES", "UNITS"]
