"""Subsurface stresses under a line contact (plane strain): the field under
the frictionless pressure p(x; a) of any contact the engine solves, with a
tangential traction q(x), its equivalent stresses and where they peak.

Signs and coordinates (see :mod:`.kolosov`): x along the surface, z > 0 the
depth, stresses tensile positive, p compressive positive, q the shear
traction on the body in +x.  Tangential tractions:

``None``            frictionless (q = 0)
``"sliding"``       q = mu p (the body is dragged in +x; mu may be a symbol)
``"partial_slip"``  q = mu [p(x; a) - p(x; c)] in the stick zone |x| < c and
                    mu p(x; a) in the slip zones (``stick = c``)
an expression       q(x) on |x| < a (SymPy, in x; any symmetry)
a callable          q(s) vectorised float64 (numeric field only)

The closed forms go through the Cauchy transform of the pressure, G(zeta) =
int p(s)/(zeta - s) ds = int_0^a P'(t) (zeta^2 - t^2)^(-1/2) dt (Popov's
flat punches, :mod:`.kolosov`), and are certified against Arb ball
quadrature of the Flamant integrals of p and q (mpmath where Arb cannot,
recorded; :mod:`~linecontact_sym.contacts.stresses.reference`).
"""
from __future__ import annotations


import numpy as np
import sympy as sp

from ...core import symbols as S
from ...core.errors import DomainError, LineContactError
from ...core.ranges import check_stick, check_value
from ...parsing import user_value
from ...method.derivation import Derivation, fallback_step, values_by_name, timed
from ...method.rules import Step
from . import build as B
from . import extrema as X
from . import field as F
from ..base import ContactOn, Quantity
from ..tangential.coupling import FrictionalCoupling, read_coupling
from .kolosov import cauchy_transform, punch_integral, t
from ...core.conversion import real_mpf, to_mpf
from ...core.precision import workdps

#: the integration variable of a traction given as an expression (real: s < 0 too)
s_real = sp.Dummy("s", real=True)   # an integration variable: never a user's s
_ARGS = ("a", "x", "z")
_MAX = {"max_shear": "principal_shear", "max_von_mises": "von_mises", "max_tresca": "tresca"}


def _q(symbol, doc, latex, aliases=()):
    return Quantity(symbol, "Johnson (1985) Eq. (2.23)", doc, arguments=_ARGS, domain="any", latex=latex,
                    aliases=aliases, unit="Pa")


def _mx(symbol, doc, latex, aliases=(), unit="Pa"):
    return Quantity(symbol, "McEwen (1949)", doc, arguments=("a",), latex=latex, aliases=aliases, unit=unit)


class StressField(FrictionalCoupling, ContactOn):
    """The stress field under a contact; see the module docstring.

    Examples
    --------
    >>> import linecontact_sym as lcs
    >>> sf = lcs.parabola(verify=False).stresses(verify=False)
    >>> sf.cauchy_transform
    pi*E_star*zeta*(1 - sqrt((-a**2 + zeta**2)/zeta**2))/(2*R)
    >>> m = sf.maximum("principal_shear", a=1, E_star=2, R=1)     # p0 = 1
    >>> round(m.value, 6), round(abs(m.x), 6), round(m.z, 6), m.digits > 9
    (0.300283, 0.0, 0.786151, True)
    """

    kind = "stress"

    sigma_x = _q("sigma_x(x, z; a)", "normal stress parallel to the surface (tensile positive)", r"\sigma_x")
    sigma_z = _q("sigma_z(x, z; a)", "normal stress perpendicular to the surface (tensile positive)", r"\sigma_z")
    tau_xz = _q("tau_xz(x, z; a)", "shear stress in the x-z plane", r"\tau_{xz}")
    sigma_y = _q("sigma_y(x, z; a)", "out-of-plane stress in plane strain, nu (sigma_x + sigma_z)", r"\sigma_y")
    principal_shear = _q("tau_1(x, z; a)", "in-plane principal shear sqrt(((sigma_x - sigma_z)/2)^2 + tau_xz^2)",
                         r"\tau_1", ("tau_1",))
    von_mises = _q("sigma_vM(x, z; a)", "von Mises equivalent stress (plane strain, nu)", r"\sigma_{\mathrm{vM}}")
    tresca = _q("sigma_T(x, z; a)", "Tresca equivalent stress: largest difference of the principal stresses",
                r"\sigma_{\mathrm{T}}")
    cauchy_transform = Quantity("G(zeta; a)", "", "Cauchy transform int p(s)/(zeta - s) ds of the pressure, "
                                "the complex potential of the normal load", arguments=("a", "zeta"),
                                latex=r"G(\zeta)", unit="Pa")
    max_shear = _mx("max tau_1", "largest principal shear stress in the body", r"\tau_{1,\max}")
    max_shear_depth = _mx("z(max tau_1)", "depth of the largest principal shear", r"z_{\tau_1}", unit="m")
    max_von_mises = _mx("max sigma_vM", "largest von Mises stress (plane strain, nu)", r"\sigma_{\mathrm{vM},\max}")
    max_von_mises_depth = _mx("z(max sigma_vM)", "depth of the largest von Mises stress", r"z_{\mathrm{vM}}", unit="m")
    max_tresca = _mx("max sigma_T", "largest Tresca stress", r"\sigma_{\mathrm{T},\max}")
    max_tresca_depth = _mx("z(max sigma_T)", "depth of the largest Tresca stress", r"z_{\mathrm{T}}", unit="m")

    # the numeric fields built per parameter point are rebuilt, not pickled
    _transient = ("_cache", "_laws", "_fields")

    def __init__(self, contact, tangential=None, mu=S.mu, nu=S.nu, stick=None, breaks=(), verify=True,
                 points: int = 4, beta=None, materials=None):
        contact.check_effect(self.kind)             # not on a periodic array yet (normal.periodic)
        if tangential not in (None, "sliding", "partial_slip") and not callable(tangential) \
                and not isinstance(tangential, sp.Expr):
            raise DomainError(f"tangential traction {tangential!r}: use None, 'sliding', 'partial_slip', a SymPy "
                              f"expression q(x) or a vectorised callable q(s)")
        if tangential == "partial_slip" and stick is None:
            raise DomainError("partial slip needs the stick half-width: stick = c")
        self.contact, self.tangential = contact, tangential
        self.mu, self.nu = user_value(mu), user_value(nu)
        check_value("nu", self.nu)
        if tangential is not None:
            check_value("mu", self.mu, zero_ok=tangential == "sliding")
        self.stick = None if stick is None else user_value(stick)
        self.breaks, self.verify, self.points = tuple(breaks), verify, points
        # the two bodies (core.materials.COUPLING_KEYWORDS): a frictional field is
        # Goodman's approximation as the tangential layer's results are, and says so
        if tangential is None:
            if beta is not None or materials is not None:
                raise DomainError("beta= and materials= describe the coupling of a frictional traction; "
                                  "the frictionless field has none (give tangential='sliding' or 'partial_slip')")
        else:
            self.coupling = read_coupling(self.mu, beta, materials)
        self._cache: dict = {}
        self._fields: dict = {}

    @property
    def coupling_note(self):
        """What a frictional field neglects of the two bodies (None: frictionless)."""
        return None if self.tangential is None else self.coupling.note(self.mu)

    @property
    def _zero_ok(self):
        return ("mu",) if self.tangential == "sliding" else ()

    @classmethod
    def from_frictionless(cls, contact):
        """The frictionless field with symbolic nu (the sliding one is the kind
        'sliding_stress', :class:`SlidingStressField`)."""
        return cls(contact)

    def __repr__(self):
        return f"StressField({self.contact.profile.expr}, tangential={self.tangential!r}{self.coupling.keywords()})"

    @property
    def variables(self):
        """E_star, the profile's parameters, and the free symbols of mu and the
        stick half-width (``nu`` is added for the quantities that need it)."""
        extra = set()
        if self.tangential in ("sliding", "partial_slip") or isinstance(self.tangential, sp.Expr):
            extra |= self.mu.free_symbols
        if self.tangential == "partial_slip":
            extra |= self.stick.free_symbols
        if isinstance(self.tangential, sp.Expr):
            extra |= self.tangential.free_symbols - {S.x, S.a}
        extra -= {S.E_star, *self.contact.params, S.a, S.x, S.z}
        return (S.E_star,) + tuple(self.contact.params) + tuple(sorted(extra, key=lambda q: q.name))

    @property
    def nu_symbols(self):
        """The symbols of Poisson's ratio (empty when nu is a number)."""
        return tuple(sorted(self.nu.free_symbols, key=lambda q: q.name))

    # --------------------------------------------------------------- potentials
    def _density(self):
        return sp.diff(self.contact.derivation("force").expr, S.a)

    def _derive_cauchy_transform(self) -> Derivation:
        return B.remembered(self, "cauchy_transform", lambda: (self._cauchy_transform(),), lambda d: d)[0]

    def _cauchy_transform(self) -> Derivation:
        D = self._density()
        step, attempts = cauchy_transform(D, self.contact.budget)
        if step is None:
            expr = punch_integral(D.subs(S.a, t))
            return Derivation("cauchy_transform", expr=expr, closed_form=False, step=fallback_step(),
                              notes=tuple(f"{r}: {w}" for r, w in attempts), variables=(S.a, S.zeta) + self.variables,
                              attempts=tuple(attempts))
        return Derivation("cauchy_transform", expr=step.expr, closed_form=True, step=step, conditions=step.conditions,
                          variables=(S.a, S.zeta) + self.variables, attempts=tuple(attempts))

    def tangential_transform(self):
        """H(zeta) = int q(s)/(zeta - s) ds of the tangential traction (an
        expression in zeta; an undefined function for a callable q)."""
        G = self.derivation("cauchy_transform").expr
        if self.tangential is None:
            return sp.S.Zero
        if self.tangential == "sliding":
            return self.mu * G
        if self.tangential == "partial_slip":
            return self.mu * (G - G.subs(S.a, self.stick))
        if isinstance(self.tangential, sp.Expr):
            return sp.Integral(self.tangential.subs(S.x, s_real) / (S.zeta - s_real), (s_real, -S.a, S.a))
        return sp.Function("H")(S.zeta)

    def _closed(self):
        closed = self.derivation("cauchy_transform").closed_form
        return closed and (self.tangential in (None, "sliding", "partial_slip"))

    def _components(self):
        cache = self._caches()
        if "_components" not in cache:
            cache["_components"] = B.remembered_components(self)
        return cache["_components"]

    def _derive_sigma_x(self):
        return self._components()["sigma_x"]

    def _derive_sigma_z(self):
        return self._components()["sigma_z"]

    def _derive_tau_xz(self):
        return self._components()["tau_xz"]

    def _from_components(self, name, make, note):
        c = self._components()
        expr = make(c["sigma_x"].expr, c["sigma_z"].expr, c["tau_xz"].expr)
        d0 = c["sigma_x"]
        step = Step(name, expr, d0.conditions, (note,)) if d0.closed_form else fallback_step(note)
        extra = self.nu_symbols if name in ("sigma_y", "von_mises", "tresca") else ()
        return Derivation(name, expr=expr, closed_form=d0.closed_form, step=step, conditions=d0.conditions,
                          verification=d0.verification, seconds=d0.seconds, notes=(note,),
                          reference=B.combine_reference(d0.reference, make), variables=d0.variables + extra)

    def _derive_sigma_y(self):
        return self._from_components("sigma_y", lambda sx, sz, txz: self.nu * (sx + sz), "plane strain")

    def _derive_principal_shear(self):
        return self._from_components("principal_shear", lambda sx, sz, txz: sp.sqrt((sx - sz)**2 / 4 + txz**2),
                                     "from the verified components")

    def _derive_von_mises(self):
        def vm(sx, sz, txz):
            sy = self.nu * (sx + sz)
            return sp.sqrt(((sx - sy)**2 + (sy - sz)**2 + (sz - sx)**2) / 2 + 3 * txz**2)
        return self._from_components("von_mises", vm, "from the verified components, plane strain")

    def _derive_tresca(self):
        def tr(sx, sz, txz):
            r, m, sy = sp.sqrt((sx - sz)**2 / 4 + txz**2), (sx + sz) / 2, self.nu * (sx + sz)
            return sp.Max(2 * r, sp.Abs(m + r - sy), sp.Abs(m - r - sy))
        return self._from_components("tresca", tr, "from the verified components, plane strain")

    # --------------------------------------------------------------- numbers
    def _values(self, values, need=("a",)):
        """Numeric values by symbol; Poisson's ratio, when symbolic and not
        given, is NaN (sigma_y, von Mises and Tresca are then NaN)."""
        syms = tuple(S.__dict__[n] for n in need) + self.variables + \
            tuple(q for q in self.nu_symbols if q.name in values)
        given = {k: v for k, v in values.items() if k not in ("x", "z")}
        try:
            vals = values_by_name(syms, given)
        except DomainError as exc:
            raise DomainError(f"{exc} (the stress field of {self.contact.profile.expr})") from None
        if vals[S.a] <= 0:
            raise DomainError(f"the half-width must be positive, got a = {values['a']}")
        by_name = {k.name: v for k, v in vals.items()}
        check_value("nu", by_name.get("nu"))
        if self.tangential is not None:
            check_value("mu", by_name.get("mu"), zero_ok=self.tangential == "sliding")
        if self.stick is not None:
            check_stick(vals[S.a], self.stick.xreplace(vals))
        self.contact.check_point(vals)              # where the normal solution holds (a < R, ...)
        return vals

    def field(self, **values) -> F.FieldEvaluator:
        """The numeric field (float64, vectorised) at numeric parameter values
        (keywords by name: a, E_star, the profile's parameters, mu, nu, ...):
        ``fe(x, z)`` gives every component and equivalent stress,
        ``fe(x, z, "von_mises")`` one of them."""
        vals = self._values(values)
        key = tuple(sorted((k.name, float(v)) for k, v in vals.items()))
        if key not in self._fields:
            self._fields[key] = B.build_field(self, vals)
        return self._fields[key]

    def to_numeric(self, quantity: str, backend: str = "numpy", dps: int = 30, check: bool = True, **params):
        """``fn(a=..., x=..., z=..., E_star=..., R=..., mu=..., nu=...)``: the
        field components (arrays of x and z, scalar parameters) or the
        maxima (scalars); ``backend='mpmath'``: one point at ``dps`` digits.
        The values are always checked (the field is built per parameter
        point); ``check`` is accepted for the common signature."""
        name = self.resolve(quantity)
        if backend == "mpmath":
            return lambda **kw: self.evaluate_at(name, dps=dps, **{**params, **kw})
        if name in _MAX or name.endswith("_depth") or name.startswith("critical"):
            return lambda **kw: float(self.evaluate_at(name, dps=15, **{**params, **kw}))
        if name == "cauchy_transform":
            raise DomainError("the Cauchy transform is complex: use fn = sf.field(...).normal")
        return FieldFunction(self, name, params)

    def maximum(self, criterion: str = "principal_shear", **values) -> X.StressMaximum:
        """The verified maximum of an equivalent stress ('principal_shear',
        'von_mises', 'tresca') at numeric values: :func:`.extrema.find_maximum`."""
        fe = self.field(**values)
        sym = self.tangential is None or (self.tangential == "sliding" and float(fe.mu) == 0)
        return X.find_maximum(lambda x, z: fe(x, z, criterion), float(values["a"]), criterion, symmetric=sym)

    def friction_limit(self, criterion: str = "principal_shear", **values):
        """Sliding: ``(mu_c, check, digits, kind)``, the friction coefficient
        above which the maximum lies on the surface
        (:func:`.extrema.critical_friction`)."""
        if self.tangential != "sliding":
            raise LineContactError("the critical friction is defined for a sliding contact (tangential='sliding')")
        values = {k: v for k, v in values.items() if k != "mu"}
        return X.critical_friction(lambda mu: (lambda x, z, fe=self.field(**values, mu=mu): fe(x, z, criterion)),
                                   float(values["a"]))

    def evaluate_at(self, quantity: str, dps: int = 30, **values):
        name = self.resolve(quantity)
        if self.stick is not None and "a" in values:     # the stick zone lies in the contact: 0 <= c <= a
            given = {q: user_value(values[q.name]) for q in self.stick.free_symbols if q.name in values}
            check_stick(user_value(values["a"]), self.stick.xreplace(given))
        if name in _MAX or name.endswith("_depth") or name.startswith("critical"):
            return self.derivation(name).evalf(dps=dps, **values)
        return super().evaluate_at(name, dps, **values)

    def reference_pressure(self, **values):
        """``(value, name)``: p0 = p(0; a), the usual scale of the plots (Hertz:
        the peak pressure), or the mean pressure p_m = P/(2a) where p(0) is
        infinite (wedge, power laws with n < 1)."""
        fe = self.field(**values)
        v = -float(fe.components(np.array([0.0]), np.array([0.0]))["sigma_z"][0])
        if np.isfinite(v) and v < 1e6 * fe.mean_pressure:
            return v, "p_0"
        return fe.mean_pressure, "p_m"

    #: a plot's values where not given: a, E* scale out; nu (von Mises, Tresca, sigma_y) is in the title
    PLOT_DEFAULTS = {"a": 1.0, "E_star": 1.0, "nu": 0.3}

    def _plot_values(self, kw, quantities):
        """The values of a plot (popped from ``kw``), :data:`PLOT_DEFAULTS` where not given; the title."""
        from ...views.contact_plots import profile_label
        from ...views.stress_plots import LABELS
        names = {q.name for q in (S.a,) + self.variables + self.nu_symbols}
        values = {k: kw.pop(k) for k in list(kw) if k in names}
        said = []
        for k, v in self.PLOT_DEFAULTS.items():
            if k in names and k not in values:
                values[k] = v
                if k == "nu" and any(q in ("von_mises", "tresca", "sigma_y") for q in quantities):
                    said.append(rf"$\nu = {v:g}$")
        what = ", ".join(LABELS.get(q, q) for q in quantities)
        title = f"{what} under {profile_label(self)}" + (f" ({', '.join(said)})" if said else "")
        kw.setdefault("title", title)
        return values

    def plot(self, quantity="von_mises", mark_maximum=True, **kw):
        """Contour map of a stress over (x/a, z/a), scaled by the reference
        pressure, the verified maximum marked; parameters by name (a, E* and
        Poisson's ratio default to :data:`PLOT_DEFAULTS`; the profile's
        parameters are needed), other keywords to
        :func:`linecontact_sym.views.stress_plots.contour`."""
        from ...views.stress_plots import contour
        values = self._plot_values(kw, (quantity,))
        scale, label = self.reference_pressure(**values)
        if mark_maximum and quantity in F.CRITERIA:
            m = self.maximum(quantity, **values)
            kw.setdefault("mark", (m.x, m.z))
        return contour(self.field(**values), float(values["a"]), quantity, scale=scale, scale_label=label, **kw)

    def plot_axis(self, quantities=("sigma_x", "sigma_z", "principal_shear", "von_mises"), **kw):
        """The stresses along the axis x = 0 against z/a:
        :func:`linecontact_sym.views.stress_plots.axis_profile`."""
        from ...views.stress_plots import axis_profile
        values = self._plot_values(kw, quantities)
        scale, label = self.reference_pressure(**values)
        return axis_profile(self.field(**values), float(values["a"]), quantities, scale=scale, scale_label=label, **kw)

    # --------------------------------------------------------------- maxima
    def _derive_max(self, name):
        return _derive_maximum(self, name)

    def _derive_max_shear(self):
        return self._derive_max("max_shear")

    def _derive_max_shear_depth(self):
        return self._derive_max("max_shear_depth")

    def _derive_max_von_mises(self):
        return self._derive_max("max_von_mises")

    def _derive_max_von_mises_depth(self):
        return self._derive_max("max_von_mises_depth")

    def _derive_max_tresca(self):
        return self._derive_max("max_tresca")

    def _derive_max_tresca_depth(self):
        return self._derive_max("max_tresca_depth")



class SlidingStressField(StressField):
    """The field under a contact sliding with friction mu (q = mu p on the
    body in +x), with the friction coefficients at which the maxima move to
    the surface.  ``lcs.parabola().stresses("sliding")`` builds it.

    >>> import linecontact_sym as lcs
    >>> sf = lcs.parabola(verify=False).stresses("sliding", verify=False)
    >>> sf.maximum("von_mises", a=1, E_star=2, R=1, mu=0.3, nu=0.3).on_surface
    True
    """

    kind = "sliding_stress"

    critical_friction = Quantity("mu_c", "", "the friction coefficient above which the largest principal "
                                 "shear lies on the surface", arguments=(), latex=r"\mu_c", unit="")
    critical_friction_von_mises = Quantity("mu_c,vM", "", "the friction coefficient above which the largest "
                                           "von Mises stress lies on the surface", arguments=(),
                                           latex=r"\mu_{c,\mathrm{vM}}", unit="")

    def __init__(self, contact, mu=S.mu, nu=S.nu, **kw):
        super().__init__(contact, "sliding", mu, nu, **kw)

    @classmethod
    def from_frictionless(cls, contact):
        """The sliding contact with symbolic mu and nu (mu = 0: frictionless)."""
        return cls(contact)

    def __repr__(self):
        return f"SlidingStressField({self.contact.profile.expr}, mu={self.mu}{self.coupling.keywords()})"

    def _derive_critical_friction(self):
        return _derive_critical(self, "critical_friction", "principal_shear")

    def _derive_critical_friction_von_mises(self):
        return _derive_critical(self, "critical_friction_von_mises", "von_mises")


# ===================================================================== maxima
def _names(vals):
    return {k.name: v for k, v in vals.items()}


def _mp_criterion(sf, criterion, vals):
    """The criterion as an mpmath function of (x, z) from the closed-form
    potentials (None when they are not closed)."""
    import mpmath
    Gd = sf.derivation("cauchy_transform")
    if not Gd.closed_form or sf.tangential not in (None, "sliding", "partial_slip"):
        return None
    at = {k: v for k, v in vals.items() if k not in (S.x, S.z)}
    G = Gd.expr.xreplace(at)
    H = sf.tangential_transform().xreplace(at)
    fns = [sp.lambdify(S.zeta, e, "mpmath") for e in (G, sp.diff(G, S.zeta), H, sp.diff(H, S.zeta))]
    nuv = sf.nu.xreplace(vals)
    with workdps(40):
        nu = to_mpf(nuv) if nuv.is_number else mpmath.nan

    def f(xv, zv):
        from .kolosov import kolosov_stresses
        zeta = mpmath.mpc(xv, zv)
        sx, sz, txz = kolosov_stresses(*(fn(zeta) for fn in fns), zv, mpmath.re, mpmath.im, mpmath.pi)
        r = mpmath.sqrt((sx - sz)**2 / 4 + txz**2)
        if criterion == "principal_shear":
            return r
        sy = nu * (sx + sz)
        if criterion == "von_mises":
            return mpmath.sqrt(((sx - sy)**2 + (sy - sz)**2 + (sz - sx)**2) / 2 + 3 * txz**2)
        m = (sx + sz) / 2
        return max(2 * r, abs(m + r - sy), abs(m - r - sy))
    return f


def _maximum_mp(sf, criterion, vals, dps):
    """(value, depth) of the maximum at ``vals``: the verified float search,
    refined at ``dps`` digits by an mpmath root of the gradient where the
    potentials are closed and the maximum is interior and smooth."""
    import mpmath
    m = sf.maximum(criterion, **_names(vals))
    out = (mpmath.mpf(m.value), mpmath.mpf(m.z))
    f = _mp_criterion(sf, criterion, vals) if dps > 15 and not m.on_surface else None
    if f is None or (criterion == "tresca"):
        return out
    A = float(vals[S.a])
    with workdps(dps + 15):
        try:
            if abs(m.x) < 1e-6 * A and (sf.tangential is None or float(sf.mu.xreplace(vals)) == 0):
                zr = mpmath.findroot(lambda zv: mpmath.diff(lambda u: f(0, u), zv), mpmath.mpf(m.z))
                xr = mpmath.mpf(0)
            else:
                xr, zr = mpmath.findroot([lambda xv, zv: mpmath.diff(lambda u: f(u, zv), xv),
                                          lambda xv, zv: mpmath.diff(lambda u: f(xv, u), zv)],
                                         (mpmath.mpf(m.x), mpmath.mpf(m.z)))
        except (ValueError, ZeroDivisionError):
            return out
        if abs(xr - m.x) > 1e-5 * A or abs(zr - m.z) > 1e-5 * A:
            return out
        return +f(xr, zr), +zr


def _axis_closed_form(sf):
    """Frictionless, closed G: tau_1 on the axis is z |Re G'(iz)|/pi
    (tau_xz = 0 there); its stationary point by sympy.solve (unchecked roots,
    the real positive one where tau_1 is largest at a sample point; the
    result is verified against the 2-D search).  Returns (value, depth)
    expressions, or None.  Derived once per field."""
    cache = sf._caches()
    if "_axis" in cache:
        return cache["_axis"]
    cache["_axis"] = None
    from ...core.budget import run_with_budget
    Gd = sf.derivation("cauchy_transform")
    if not Gd.closed_form or sf.tangential is not None:
        return None
    e = sp.simplify(S.z * sp.re(sp.diff(Gd.expr, S.zeta).subs(S.zeta, sp.I * S.z)) / sp.pi)
    if e.has(sp.re, sp.im, sp.hyper):
        return None
    try:
        roots = run_with_budget(sp.solve, sp.diff(e, S.z), S.z, check=False, seconds=sf.contact.budget)
    except Exception:
        return None
    at = {q: sp.Integer(1) for q in e.free_symbols - {S.z}}
    good = []
    for r in roots:
        rv = sp.N(r.xreplace(at), 30)
        if rv.is_real and rv > 0:
            good.append((abs(sp.N(e.subs(S.z, r).xreplace(at), 30)), r))
    if not good:
        return None
    zr = sp.simplify(max(good, key=lambda g: g[0])[1])
    cache["_axis"] = (sp.simplify(sp.Abs(e.subs(S.z, zr))), zr)
    return cache["_axis"]


@timed
def _derive_maximum(sf, name):
    depth = name.endswith("_depth")
    criterion = _MAX[name.replace("_depth", "")]
    variables = (S.a,) + sf.variables + (sf.nu_symbols if criterion != "principal_shear" else ())

    def reference(vals, dps):
        value, z = _maximum_mp(sf, criterion, vals, dps)
        return z if depth else value
    if criterion == "principal_shear":
        closed = _axis_closed_form(sf)
        if closed is not None:
            expr = closed[1] if depth else closed[0]
            rec = _check_maximum(sf, expr, reference, variables)
            if rec.passed:
                step = Step("axis_stationary_point", expr, (), ("root of d tau_1/dz on the axis x = 0 (sympy.solve)",))
                return Derivation(name, expr=expr, closed_form=True, step=step, verification=rec, reference=reference,
                                  variables=variables)
    expr = sp.Function(name)(*variables)
    step = fallback_step("verified numeric maximum: grid, Nelder-Mead, checked by a root of the gradient")
    return Derivation(name, expr=expr, closed_form=False, step=step, reference=reference, variables=variables)


def _check_maximum(sf, expr, reference, variables):
    """The axis closed form against the 2-D search at two random points."""
    import random
    from ...method.verification import VerificationRecord, digits_agreeing
    import mpmath
    sample = B.sampler(sf)
    rng, pts, digits = random.Random(11), [], []
    while len(pts) < 2:
        vals = sample(rng)
        if vals is None:
            continue
        vals = {k: v for k, v in vals.items() if k in variables}
        with workdps(30):
            val = real_mpf(expr.xreplace(vals))
            digits.append(digits_agreeing(val, reference(vals, 30), 30))
        pts.append(vals)
    return VerificationRecord(tuple(pts), tuple(digits), 30, "2-D Nelder-Mead search of the field refined by an "
                              "mpmath root of the gradient", required=12)


@timed
def _derive_critical(sf, name, criterion):
    variables = (S.a,) + tuple(v for v in sf.variables if v != S.mu) + \
        (sf.nu_symbols if criterion != "principal_shear" else ())

    def reference(vals, dps):
        import mpmath
        return mpmath.mpf(sf.friction_limit(criterion, **_names(vals))[0])
    if sf.tangential != "sliding":
        raise LineContactError(f"{name} is defined for a sliding contact (tangential='sliding')")
    step = fallback_step("Brent root of (surface max - interior max) in mu, checked by bisection on "
                         "'the maximum is on the surface'")
    return Derivation(name, expr=sp.Function(name)(*variables), closed_form=False, step=step, reference=reference,
                      variables=variables)

class FieldFunction:
    """What :meth:`StressContact.to_numeric` returns for a field component:
    ``fn(x=..., z=..., a=..., E_star=..., ...)`` (arrays of x and z).  Pickles
    (the contact, the quantity and the fixed values; the field is built again
    in the process that calls it), so a 500x500 grid can be cut into blocks
    for worker processes or a Dask cluster
    (:func:`~linecontact_sym.core.parallel.map_chunks`)."""

    def __init__(self, contact, quantity, params):
        self.contact, self.quantity, self.params = contact, quantity, dict(params)

    def __call__(self, **kw):
        kw = {**self.params, **kw}
        return self.contact.field(**kw)(kw["x"], kw["z"], self.quantity)

    def __repr__(self):
        return f"<{self.quantity} of the stress field of {self.contact.contact.profile.expr}>"
