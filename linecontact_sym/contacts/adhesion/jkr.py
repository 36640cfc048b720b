"""The JKR cohesive law (Popov 2017, Eqs. 29-36): the pulled flat punch
(Eqs. 30-31) superposed on the non-adhesive contact, and an energy route to
the punch force that shares nothing with the stress-intensity route.

:class:`JKR` is the law (:class:`~.law.CohesiveLaw`): one parameter, the work
of adhesion gamma >= 0; the balance K_I**2/(2 E*) = gamma fixes the
equilibrium at each half-width, P(a) = P0(a) - Phat(a) (Eq. 33),
p(x; a) = p0(x; a) - Phat/(pi sqrt(a**2 - x**2)) (Eq. 29); closed forms of
the pull-off and the jump-in for a single power term P0 = C a**m.

Near x = a the tensile stress of a flat punch pulled by Phat is
``sigma(x) ~ K_I / sqrt(2 pi (a - x))`` with K_I = Phat/sqrt(pi a) (Eq. 30);
the energy released per unit area when the edge advances is
G = K_I**2/(2 E*).  Griffith's balance G = gamma (the work of adhesion, the
paper's gamma_12) gives Phat = sqrt(2 pi a gamma E*) (Eq. 31).

The same follows from the compliance of the flat punch, Eq. (3):
C(a) = (2/(pi E*)) arccosh(L/a) for the displacement at a distant point L,
so G = (Phat**2/2) |dC/d(2a)| = Phat**2/(2 pi E* a) as L -> oo.
:func:`phat_energy` evaluates that route numerically: the compliance's slope
dC/da as the quadrature of Eq. (3) differentiated under the integral sign
(:func:`compliance_slope`: the log kernel's a-derivative is bounded, so the
one reference integrator encloses it in Arb; the old route, numerical
differentiation of the log-singular quadrature :func:`compliance_quad`, is
its recorded fallback), then the root of G(Phat) = gamma.
"""
from __future__ import annotations

import mpmath
import sympy as sp

import math

from ...core import symbols as S
from ...core.conversion import float_values, number, rational, to_mpf
from ...core.errors import DomainError, NoPullOffError
from ...core.precision import workdps
from ...method.derivation import Derivation
from ...method.geometry import ISOLATED
from ...method.rules import Step
from ...method.verification import verify
from ...numeric.reference import combine, integrate, lincomb
from ..normal.reference import force_reference
from ..base import Quantity
from . import branches
from .law import CohesiveLaw, Parameter, on_base
from .pull_off import same_at_points, single_power

#: range of the work of adhesion at the random verification points
GAMMA_RANGE = (0.005, 0.5)


def flat_punch_force(work_of_adhesion=S.gamma, a=S.a, E_star=S.E_star, geometry=ISOLATED):
    """Eq. (31): Phat = sqrt(2 pi a gamma E*), the force of the pulled flat
    punch that makes the energy release rate at the edges equal to gamma
    (K_I**2/(2 E*) = gamma with K_I = Phat/sqrt(pi a), Eq. 30).

    Another geometry (:mod:`~linecontact_sym.method.geometry`): the punch of
    half-width S in the kernel variable s has K_s = Phat/sqrt(pi S), and the
    edge in x sees K = K_s sqrt(S'(a)) (s - S = S'(a) (x - a) there), so
    Phat = sqrt(2 pi gamma E* S/S').  A periodic array:
    Phat = sqrt(2 gamma E* L tan(pi a/L)), K = pbar sqrt(L cot(pi a/L)), pbar = Phat/L.

    >>> flat_punch_force()
    sqrt(2)*sqrt(pi)*sqrt(E_star)*sqrt(a)*sqrt(gamma)
    """
    return sp.sqrt(2 * sp.pi * geometry.punch_ratio(a) * work_of_adhesion * E_star)


def stress_intensity(Phat, a=S.a):
    """Eq. (30): mode-I stress-intensity factor of a flat punch pulled by Phat,
    K_I = lim_{x->a} sqrt(2 pi (a - x)) sigma(x) = Phat/sqrt(pi a)."""
    return Phat / sp.sqrt(sp.pi * a)


def energy_release_rate(K, E_star=S.E_star):
    """G = K_I**2/(2 E*) at the edge of a rigid-elastic line contact."""
    return K**2 / (2 * E_star)


def compliance_quad(A, E, dps, L):
    """Compliance of the flat punch (unit force), displacement difference
    between the punch and a distant point L, by quadrature of the
    half-plane's log kernel over the punch pressure 1/(pi sqrt(a^2 - s^2)):
    C = (2/(pi E*)) (1/pi) int_{-pi/2}^{pi/2} ln(|L - a sin phi| / |a sin phi|) dphi."""
    with workdps(max(mpmath.mp.dps, dps + 10)):  # never below a caller's (mpmath.diff) precision
        f = lambda ph: mpmath.log(abs(L - A * mpmath.sin(ph))) - mpmath.log(abs(A * mpmath.sin(ph)))  # noqa: E731
        I = mpmath.quad(f, [-mpmath.pi / 2, 0, mpmath.pi / 2]) / mpmath.pi
        return 2 * I / (mpmath.pi * E)


_phi = sp.Dummy("phi", real=True)
_dC = sp.Dummy("dC", negative=True)


def _exact(v):
    """A number as an exact SymPy number (an mpf by its binary value): the
    package's one converter."""
    return number(v)


def compliance_slope(A, E, dps, L):
    """dC/da of :func:`compliance_quad` (a RefValue): Eq. (3) differentiated
    under the integral sign, d/da [ln|L - a sin phi| - ln|a sin phi|] =
    -sin phi/(L - a sin phi) - 1/a (bounded: the log singularity at phi = 0
    does not depend on a), integrated by the one reference integrator;
    mpmath.diff of :func:`compliance_quad` is the recorded fallback.
    ``A, E, L``: exact numbers (SymPy, int, float)."""
    A, E, L = (_exact(v) for v in (A, E, L))
    f = 2 / (sp.pi**2 * E) * (-sp.sin(_phi) / (L - A * sp.sin(_phi)) - 1 / A)

    def fallback():
        Am, Em, Lm = to_mpf(A), to_mpf(E), to_mpf(L)
        return mpmath.diff(lambda u: compliance_quad(u, Em, dps + 10, Lm), Am)
    return integrate(f, _phi, [-sp.pi / 2, 0, sp.pi / 2], dps, fallback=fallback)


def phat_energy(A, gamma, E, dps, quadrature=True, geometry=ISOLATED, values=None):
    """Phat from the energy balance G = gamma, G = (P^2/2) |dC/d(2a)| with C
    the punch compliance (Eq. 3): with ``quadrature`` (default) its slope by
    :func:`compliance_slope` and the root Phat = sqrt(4 gamma/|dC/da|) as a
    :class:`~linecontact_sym.numeric.reference.RefValue` (an Arb enclosure
    where the slope is one); with ``quadrature=False`` the closed arccosh
    form differentiated numerically and the root by findroot (an mpf).
    Another geometry (``values``: its parameters): its punch's compliance
    (:meth:`~linecontact_sym.method.geometry.Geometry.mp_punch_compliance`,
    a periodic array: Koiter's punch under the periodic Green's function),
    with ``quadrature`` its defining integral differentiated under the
    integral sign (``mp_punch_compliance_slope``: one quadrature, where a
    finite difference of the quadrature took two at twice the digits), else
    the closed form differentiated numerically; the root by findroot."""
    if not geometry.is_isolated:
        with workdps(dps + 10):
            A, g, E = to_mpf(A), to_mpf(gamma), to_mpf(E)
            if g == 0:
                return mpmath.mpf(0)
            dC = geometry.mp_punch_compliance_slope(A, E, values) if quadrature else \
                mpmath.diff(lambda u: geometry.mp_punch_compliance(u, E, values), A)
            G = lambda Pv: Pv**2 / 4 * abs(dC) - g  # noqa: E731
            guess = mpmath.sqrt(4 * g / abs(dC))
            return mpmath.findroot(G, (guess * mpmath.mpf("0.5"), guess * 2), solver="anderson")
    if quadrature:
        g = number(gamma)
        if g == 0:
            return mpmath.mpf(0)
        L = number(A) * sp.Integer(10)**(dps + 20)
        slope = compliance_slope(A, E, dps + 5, L)
        return combine(sp.sqrt(-4 * g / _dC), _dC, slope, dps)
    with workdps(dps + 10):
        A, g, E = to_mpf(A), to_mpf(gamma), to_mpf(E)
        if g == 0:
            return mpmath.mpf(0)
        L = A * mpmath.mpf(10)**(dps + 20)
        dC = mpmath.diff(lambda u: 2 * mpmath.acosh(L / u) / (mpmath.pi * E), A)
        G = lambda Pv: Pv**2 / 4 * abs(dC) - g  # noqa: E731
        guess = mpmath.sqrt(4 * g / abs(dC))
        return mpmath.findroot(G, (guess * mpmath.mpf("0.5"), guess * 2), solver="anderson")


#: Eq. (31) derivations, shared by all contacts (the flat punch has no profile)
_PHAT_CACHE: dict = {}


class JKR(CohesiveLaw):
    """The JKR law of a line contact (Popov 2017, Eqs. 29-36): the
    stress-intensity balance K_I**2/(2 E*) = gamma at the edges x = +-a,
    K_I = Phat/sqrt(pi a), gives the pulled flat punch Phat = sqrt(2 pi a gamma E*)
    superposed on the normal contact.

    >>> JKR().balance
    Eq(Phat**2/(2*pi*E_star*a), gamma)
    >>> JKR(0).inactive
    'no adhesion (gamma = 0)'
    """

    name = "jkr"
    kind = "adhesive"
    title = "JKR (Popov 2017, Eqs. 29-36)"
    label = "JKR"
    parameters = (Parameter("work_of_adhesion", S.gamma, "nonnegative", "the work of adhesion", GAMMA_RANGE),)
    quantities = {"flat_punch_force": Quantity("Phat(a)", "Eq. (31)", "force of the pulled flat punch "
                                               "sqrt(2 pi a gamma E*)", aliases=("Phat",), latex=r"\hat{P}(a)",
                                               unit="N/m")}

    @property
    def gamma(self):
        return self.values["work_of_adhesion"]

    @property
    def inactive(self):
        return "no adhesion (gamma = 0)" if self.gamma == 0 else False

    inactive_reason = "no adhesion (gamma = 0)"

    @property
    def balance(self) -> sp.Eq:
        """Eq. (30)-(31): the energy release rate of the pulled punch equals gamma."""
        Phat = sp.Symbol("Phat", positive=True)
        return sp.Eq(energy_release_rate(stress_intensity(Phat)), self.gamma)

    def flat_punch_force(self):
        """Phat(a), Eq. (31)."""
        return flat_punch_force(self.gamma)

    # ----------------------------------------------------------- Eqs. (29), (31), (33)
    def derive_flat_punch_force(self, ad) -> Derivation:
        """Eq. (31), verified against the energy balance of the flat-punch
        compliance (its slope by quadrature of Eq. 3, :func:`compliance_slope`); shared by all
        contacts with the same work of adhesion."""
        key = (self.gamma, ad.contact.points, ad.contact.verify, ad.contact.geometry)
        if key not in _PHAT_CACHE:
            _PHAT_CACHE[key] = _derive_phat(ad, self.gamma)
        return _PHAT_CACHE[key]

    def derive_force(self, ad) -> Derivation:
        """Eq. (33): P(a) = P0(a) - Phat, verified against the quadrature of
        Eq. (10*) minus Phat from the energy balance."""
        fd = ad.contact.derivation("force")
        geometry = ad.contact.geometry
        expr = fd.expr - flat_punch_force(self.gamma, geometry=geometry)
        contact, prof, gexpr = ad.contact, ad.profile, self.gamma

        def reference(vals, dps):
            if not geometry.is_isolated:    # the contact's own reference (a periodic array: the tan route)
                return lincomb([(1, contact.force_reference(vals, dps)),
                                (-1, phat_energy(vals[S.a], gexpr.xreplace(vals), vals[S.E_star], dps,
                                                 geometry=geometry, values=vals))], dps)
            return lincomb([(1, force_reference(prof, vals, dps)),
                            (-1, phat_energy(vals[S.a], gexpr.xreplace(vals), vals[S.E_star], dps))], dps)
        rec = None
        if fd.closed_form and ad.contact.verify:
            rec = verify(expr, reference, ad._sampler(), fd.conditions, n_points=ad.contact.points,
                         reference_name="Eq. (10*) minus Phat from the energy balance of the flat-punch "
                                        "compliance (Eq. 3 differentiated under the integral sign)")
            ad._require(rec, "force")
        step = Step("jkr_superposition", expr, fd.conditions,
                    (f"Eq. (33): P0(a) of the engine ({fd.method}) minus Phat, Eq. (31)" if fd.closed_form
                     else "numeric fallback: unevaluated Eq. (10*) minus Phat",))
        return Derivation("force", expr=expr, closed_form=fd.closed_form, step=step, conditions=fd.conditions,
                          verification=rec, notes=fd.notes, reference=reference, variables=(S.a,) + ad.variables)

    def derive_pressure(self, ad) -> Derivation:
        """Eq. (29): p(x) = p0(x) - Phat/(pi sqrt(a^2 - x^2)), verified against
        the quadrature of Eq. (12) minus the punch with Phat from the energy
        balance, and by equilibrium: 2 int_0^a p dx = P(a) of Eq. (33)."""
        pd = ad.contact.derivation("pressure")
        geometry = ad.contact.geometry
        expr = pd.expr - geometry.punch_pressure(flat_punch_force(self.gamma, geometry=geometry))
        gexpr = self.gamma

        def reference(vals, dps):
            A, X = vals[S.a], vals[S.x]
            ph = phat_energy(A, gexpr.xreplace(vals), vals[S.E_star], dps, geometry=geometry, values=vals)
            # the punch's pressure per unit load at the point (isolated: 1/(pi sqrt(a^2 - x^2)))
            unit = geometry.punch_pressure(sp.S.One).xreplace({**vals, S.a: A, S.x: X})
            return lincomb([(1, pd.reference(vals, dps)), (-unit, ph)], dps)
        rec, notes = None, list(pd.notes)
        if pd.closed_form and ad.contact.verify:
            rec = verify(expr, reference, ad._sampler("inside"), pd.conditions, n_points=ad.contact.points,
                         reference_name="Eq. (12) of p0 minus the flat punch (Eq. 1) with Phat from the energy "
                                        "balance (Eq. 3 differentiated under the integral sign)")
            ad._require(rec, "pressure")
            eq = branches.equilibrium_digits(ad, expr)
            notes.append(f"equilibrium: 2 int_0^a p dx (quadrature of Eq. 29) = P(a) of Eq. (33) to "
                         f">= {eq:.1f} digits at {ad.contact.points} random points")
        step = Step("jkr_superposition", expr, pd.conditions,
                    ("Eq. (29): p0 of the engine (" + pd.method + ") minus the pulled flat punch" if pd.closed_form
                     else "numeric fallback: unevaluated Eq. (12) minus the flat punch",))
        return Derivation("pressure", expr=expr, closed_form=pd.closed_form, step=step, conditions=pd.conditions,
                          verification=rec, notes=tuple(notes), reference=reference,
                          variables=(S.a, S.x) + ad.variables)

    # ----------------------------------------------------------- numbers
    def numeric(self, base, values):
        """P(a) = P0(a) - B1 sqrt(a), B1 = sqrt(2 pi gamma E*), on ``base``."""
        g = self.numbers(values)["work_of_adhesion"]
        E = sp.sympify(values[S.E_star], strict=True)
        if g < 0:
            raise DomainError(f"the work of adhesion must be >= 0, got {g}")
        # no adhesion at the value given (gamma = 0 at the point, not only a law built with 0)
        inactive = self.inactive or (self.inactive_reason if g == 0 else False)

        def build(b):
            P0, dP0 = b.P, b.dP

            def B1():
                return mpmath.sqrt(2 * mpmath.pi * to_mpf(g) * to_mpf(E))
            b1f = math.sqrt(2 * math.pi * float(g) * float(E))
            geo, gv = b.geometry, getattr(b, "geometry_values", {})
            if geo.is_isolated:
                expr = None if b.expr is None else b.expr - sp.sqrt(2 * sp.pi * g * E * S.a)
                return b.on_top(lambda A: P0(A) - B1() * mpmath.sqrt(A),
                                lambda A: dP0(A) - B1() / (2 * mpmath.sqrt(A)),
                                expr=expr, float_P=lambda P0f: (lambda A: P0f(A) - b1f * math.sqrt(float(A))),
                                inactive=inactive, monotone_term=True)
            # another geometry: Phat = B1 sqrt(S/S') (flat_punch_force), S/S' the geometry's punch ratio
            expr = None if b.expr is None else b.expr - flat_punch_force(g, E_star=E, geometry=geo).xreplace(gv)
            ratio_f = geo.float_punch_ratio(gv)

            def P(A):
                r, _ = geo.mp_punch_ratio(A, gv)
                return P0(A) - B1() * mpmath.sqrt(r)

            def dP(A):
                r, dr = geo.mp_punch_ratio(A, gv)
                return dP0(A) - B1() * dr / (2 * mpmath.sqrt(r))
            return b.on_top(P, dP, expr=expr, float_P=lambda P0f: (lambda A: P0f(A) - b1f * math.sqrt(ratio_f(A))),
                            inactive=inactive, monotone_term=False)
        return on_base(base, build)

    # ----------------------------------------------------------- closed forms
    def pull_off_conditions(self, ad, force0, values=None):
        """A single power term P0 = C a**m has a finite pull-off iff m > 1/2."""
        single = single_power(force0.expr) if force0.closed_form and ad.contact.geometry.is_isolated else None
        if single is None:
            return []
        C, m = single
        check_existence(ad, C, m, values)
        return [] if m.is_number else [sp.Gt(m, sp.S.Half)]

    def pull_off_compact(self, ad, force0, Pmin, a_star, conds):
        """For P0 = C a**m: P_adh = (2m-1)/(2m) ((2 pi gamma E*)**m/(2 m C))**(1/(2m-1)),
        a_po = (2 pi gamma E*/(4 m**2 C**2))**(1/(2m-1)) -- kept where they equal
        the solve result at random points (the single stationary point is
        the global minimum)."""
        single = single_power(force0.expr) if force0.closed_form and ad.contact.geometry.is_isolated else None
        if single is None:
            return None
        C, m = single
        gE = 2 * sp.pi * self.gamma * S.E_star
        adh = (2 * m - 1) / (2 * m) * (gE**m / (2 * m * C))**(1 / (2 * m - 1))
        a_po = (gE / (4 * m**2 * C**2))**(1 / (2 * m - 1))
        if same_at_points(ad, -adh, Pmin, conds) and same_at_points(ad, a_po, a_star, conds):
            return -adh, a_po, adh, ("single power term P0 = C a**m: P_min = -(2m-1)/(2m) "
                                     "((2 pi gamma E*)**m/(2 m C))**(1/(2m-1)) (equal to the solve "
                                     "result at 5 points to 40 digits)")
        return None

    def stationary_candidates(self, ad, force0):
        """For P0 = C a**m: m C a**(m-1) = B1/(2 sqrt(a)) solved by hand,
        a**(m - 1/2) = B1/(2 m C); sympy.solve of the same equation with
        symbolic C and m spent its whole budget (K x**4: 20 s)."""
        single = single_power(force0.expr) if force0.closed_form and ad.contact.geometry.is_isolated else None
        if single is None:
            return None
        C, m = single
        a_po = (2 * sp.pi * self.gamma * S.E_star / (4 * m**2 * C**2))**(1 / (2 * m - 1))
        return [a_po], ("dP/da = 0 of P = C a**m - sqrt(2 pi a gamma E*) solved as a**(m - 1/2) = "
                        "sqrt(2 pi gamma E*)/(2 m C)")

    def jump_in_candidates(self, ad, force0):
        single = single_power(force0.expr) if force0.closed_form and ad.contact.geometry.is_isolated else None
        if single is None:
            return None
        C, m = single
        return ([(2 * sp.pi * self.gamma * S.E_star / C**2)**(1 / (2 * m - 1))],
                "P(a) = 0 for the single power term P0 = C a**m: a_in = (2 pi gamma E*/C**2)**(1/(2m-1))",
                [] if m.is_number else [sp.Gt(m, sp.S.Half)])


def check_existence(ad, C, m, vals=None):
    """Raise NoPullOffError for a single power law P0 = C a**m, m <= 1/2."""
    mv = m.xreplace(vals) if vals else m
    if not mv.is_number:
        return
    gamma = ad.law.gamma
    if gamma.xreplace(vals or {}) == 0:
        raise NoPullOffError(f"{ad.profile.name!r}: no adhesion (gamma = 0), no tensile pull-off")
    if mv > sp.S.Half:
        return
    name = ad.profile.name
    if mv < sp.S.Half:
        raise NoPullOffError(
            f"{name!r}: P0 ~ a**({mv}) grows slower than the adhesive term sqrt(2 pi a gamma E*) "
            f"(exponent {mv} < 1/2): P(a) has a maximum, not a minimum; tensile equilibria are "
            f"all unstable and P -> -oo as a -> oo, loads above the maximum have no equilibrium. "
            f"No finite pull-off exists for n < 1/2 (it needs n > 1/2).")
    gc = sp.simplify(C**2 / (2 * sp.pi * S.E_star))
    raise NoPullOffError(
        f"{name!r}: exponent n = 1/2 is the borderline: P = (C - sqrt(2 pi gamma E*)) sqrt(a) with "
        f"C = {C} is monotone. For gamma < gamma_c = {gc} no tensile load is sustained (zero "
        f"pull-off, reached only as a -> 0); for gamma > gamma_c P -> -oo, every equilibrium "
        f"is unstable and the contact spreads without bound. No finite pull-off (needs n > 1/2).")


def _derive_phat(ad, gamma) -> Derivation:
    """Eq. (31), verified against the energy balance G = gamma computed from
    the flat-punch compliance's slope by quadrature (Eq. 3 differentiated
    under the integral sign, an Arb enclosure; another geometry: its punch's
    compliance by quadrature, differentiated numerically) and its root."""
    geometry = ad.contact.geometry
    expr = flat_punch_force(gamma, geometry=geometry)
    gsyms = tuple(sorted(gamma.free_symbols, key=lambda s: s.name))
    psyms = tuple(v for v in geometry.symbols if v not in gsyms)

    def sampler(rng):
        if geometry.is_isolated:
            vals = {S.a: rational(rng.uniform(0.05, 2.0)), S.E_star: rational(rng.uniform(0.5, 3.0))}
        else:       # a periodic array: a in (0.05, 0.92) L/2
            vals = {S.E_star: rational(rng.uniform(0.5, 3.0))}
            vals.update({v: rational(rng.uniform(0.5, 2.5)) for v in psyms})
            vals[S.a] = rational(rng.uniform(0.05, 0.92) * float(geometry.a_max().xreplace(vals)))
        for gs in gsyms:
            vals[gs] = rational(rng.uniform(*GAMMA_RANGE))
        return float_values(vals, 80)

    def reference(vals, dps):
        return phat_energy(vals[S.a], gamma.xreplace(vals), vals[S.E_star], dps, quadrature=True, geometry=geometry,
                           values=vals)
    rec = None
    if ad.contact.verify and gamma != 0:
        rec = verify(expr, reference, sampler, (), n_points=ad.contact.points,
                     reference_name="the energy release rate G = (Phat^2/2)|dC/d(2a)| = gamma of the flat punch, "
                                    "the compliance's slope by quadrature of Eq. (3) differentiated under the "
                                    "integral sign")
        ad._require(rec, "flat_punch_force")
    step = Step("griffith", expr, (), ("Eq. (31): Griffith balance K_I^2/(2 E*) = gamma at the edge, "
                                       "K_I = Phat/sqrt(pi a) (Eq. 30)",))
    return Derivation("flat_punch_force", expr=expr, closed_form=True, step=step, verification=rec,
                      notes=("K_I = Phat/sqrt(pi*a) = sqrt(2*gamma*E_star); G = K_I^2/(2 E*) = Phat^2/(2 pi a E*)",),
                      reference=reference, variables=(S.a, S.E_star) + gsyms + psyms)


__all__ = ["JKR", "check_existence", "flat_punch_force", "stress_intensity", "energy_release_rate",
           "compliance_quad", "compliance_slope", "phat_energy", "GAMMA_RANGE"]
