"""Independent checks of the Maugis-Dugdale line contact, sharing nothing
with the flat-punch derivation of :mod:`.derive`:

* force: Johnson's condition for a pressure bounded at both edges of a 2-D
  rigid punch (Contact Mechanics 1985, Sec. 2.8), P_c = (E*/2) int_-a^a
  s phi'(s)/sqrt(a^2 - s^2) ds, applied to the effective profile
  phi = f + u_D, where u_D' = (2 sigma_0/(pi E*)) log((a-s)(c+s)/((c-s)(a+s)))
  is the surface slope the Dugdale strip causes by the Flamant (logarithmic)
  kernel; plus the strip's own force -2 sigma_0 (c_D - a);
* gap at c_D: the engine's quadrature of the adhesionless gap plus
  u_D(c_D) - u_D(0) of the Dugdale sub-problem by the Flamant kernel
  u(x) - u(0) = -(2/(pi E*)) int p(s) log|(x - s)/s| ds; its contact pressure is
  first checked by substitution (u uniform on |x| < a);
* pressure: the engine's Eq. (12) quadrature plus a direct quadrature of the
  Dugdale punches;
* Baney & Hui's normalisation (lambda, A, F) and the rigid limit
  (a rigid profile with a Dugdale law: P = -2 sigma_0 c_r, f(c_r) = h0).

Every integral goes to the one reference integrator
(:mod:`linecontact_sym.numeric.reference`; the Flamant kernel through
:func:`linecontact_sym.numeric.flamant.flamant_displacement`), its forms
compiled once with a, c_D, sigma_0 as parameters: the three references are
Arb enclosures (40 guaranteed digits of the parabola's conditions), and
tanh-sinh runs, recorded, where Arb cannot.
"""
from __future__ import annotations

import functools

import mpmath
import sympy as sp

from ....core import symbols as S
from ....core.conversion import to_mpf
from ....core.errors import DomainError, VerificationError
from ....core.precision import workdps
from ....numeric.flamant import flamant_displacement
from ....numeric.arb_compile import ArbUnsupported, bound_acb
from ....numeric.reference import RefValue, estimate, integrate, lincomb, log_end_integral


def _mp(v):
    return to_mpf(v) if not isinstance(v, mpmath.mpf) else v


def _values(md, vals):
    sig = _mp(sp.N(md.sigma0.xreplace(vals), mpmath.mp.dps + 10))
    w = _mp(sp.N(md.w.xreplace(vals), mpmath.mp.dps + 10))
    return _mp(vals[S.a]), _mp(vals[S.c_D]), sig, w, _mp(vals[S.E_star])


def _as_ref(v, what):
    """A reference of the engine as a RefValue (an mpf estimate recorded as one)."""
    if isinstance(v, RefValue):
        return v
    return RefValue(v, mpmath.mpf(0), "mpmath", f"the {what}'s reference is an estimate")


_psi = sp.Dummy("psi", positive=True)
_A, _C = sp.Dummy("a", positive=True), sp.Dummy("c", positive=True)


@functools.cache
def _johnson_forms():
    """Johnson's integrand (E*/2) s u_D'(s)/sqrt(a^2 - s^2) ds for s = a cos(psi), without
    its factor 2 sigma_0/pi: a cos(psi) [2 ln psi + S(psi)], where
    (a - s)(c + s)/((c - s)(a + s)) = psi^2 exp(S(psi)) with a - s = (a/2) psi^2 sinc(psi/2)^2
    (sinc(z) = sin(z)/z), so that S is holomorphic on [0, pi/2] and the logarithm at psi = 0
    is ln psi alone (reference.log_end_integral): (a cos(psi) S(psi), 2 a cos(psi)).
    Built at the first check (not at import)."""
    smooth = _A * sp.cos(_psi) * (sp.log(_A * sp.sinc(_psi / 2)**2 / 2) + sp.log(_C + _A * sp.cos(_psi))
                                  - sp.log(_C - _A + 2 * _A * sp.sin(_psi / 2)**2)
                                  - sp.log(_A + _A * sp.cos(_psi)))
    return smooth, 2 * _A * sp.cos(_psi)


def _johnson_strip(A, C, dps):
    """int_0^(pi/2) a cos(psi) ln((a - s)(c + s)/((c - s)(a + s))) dpsi, s = a cos(psi), by the
    one reference integrator (an Arb enclosure; tanh-sinh where Arb cannot, recorded)."""
    values = {_A: A, _C: C}
    smooth_form, log_form = _johnson_forms()
    try:
        smooth = integrate(bound_acb(smooth_form, _psi, values), None, [0, sp.pi / 4, sp.pi / 2], dps,
                           fallback=lambda: mpmath.nan)
        log = log_end_integral(bound_acb(log_form, _psi, values), None, 0, sp.pi / 2, dps)
        if smooth.certified and log.certified:
            return lincomb([(1, smooth), (1, log)], dps)
        reason = smooth.note
    except ArbUnsupported as exc:
        reason = str(exc)

    def fallback():
        a, c = _mp(A), _mp(C)
        return mpmath.quad(lambda ps: a * mpmath.cos(ps) * mpmath.log(
            2 * a * mpmath.sin(ps / 2)**2 * (c + a * mpmath.cos(ps))
            / ((c - a + 2 * a * mpmath.sin(ps / 2)**2) * (a + a * mpmath.cos(ps)))), [0, mpmath.pi / 4, mpmath.pi / 2])
    return estimate(fallback, reason, dps)


def force_johnson(md, vals, dps):
    """P(a, c_D) by Johnson's bounded-solution condition (see the module docstring)."""
    with workdps(dps + 15):
        sigma = md.sigma0.xreplace(vals)
        # Eq. (10*): Arb ball quadrature (mpmath where not)
        P0 = _as_ref(md.contact.force_reference(vals, dps + 5), "adhesionless force")
        # E* int_0^a s u_D'(s)/sqrt(a^2 - s^2) ds (even integrand), s = a cos(psi)
        I = _johnson_strip(vals[S.a], vals[S.c_D], dps + 5)
        return lincomb([(1, P0), (2 * sigma / sp.pi, I), (-2 * sigma, vals[S.c_D]), (2 * sigma, vals[S.a])], dps + 5)


def force_reference(md):
    return lambda vals, dps: force_johnson(md, vals, dps)


#: the integration variable of the Dugdale sub-problem's Flamant integrals
_s = sp.Dummy("s", positive=True)


@functools.lru_cache(maxsize=32)
def _contact_piece(expr, sig):
    """The Dugdale sub-problem's contact pressure on |s| < a as a Flamant
    piece, in s with the parameters a, c_D, sigma_0 left as symbols (the
    Flamant routine compiles it once and makes balls per point)."""
    extra = expr.free_symbols - {S.x, S.a, S.c_D, *sig}
    if extra:
        raise VerificationError(f"the Dugdale pressure has symbols {sorted(map(str, extra))} without values")
    return expr.xreplace({S.x: _s}), _s, sp.S.Zero, S.a


def _flamant_differences(md, vals, xs, dps):
    """u(x) - u(0) at each x of ``xs`` of the Dugdale sub-problem (its
    contact pressure on |s| < a and -sigma_0 on a < |s| < c_D), by the one
    Flamant routine (:func:`~linecontact_sym.numeric.flamant.flamant_displacement`:
    Arb enclosures, u(0)'s term once for all x; tanh-sinh where Arb cannot,
    recorded)."""
    # the symbols of sigma_0 (itself, or those of an expression such as 2*gamma) with their values
    sig = tuple(sorted(set(md.sigma0.free_symbols) | {S.sigma_0}, key=lambda q: q.name))
    sigma = md.sigma0.xreplace(vals)
    values = {S.a: vals[S.a], S.c_D: vals[S.c_D],
              **{q: vals.get(q, sigma if q in (S.sigma_0, md.sigma0) else None) for q in sig}}
    values = {k: v for k, v in values.items() if v is not None}
    pieces = [_contact_piece(md.dugdale.pressure, sig), (-md.sigma0, _s, S.a, S.c_D)]
    return [lincomb([(-1, r)], dps) for r in flamant_displacement(pieces, list(xs), vals[S.E_star], dps,
                                                                   values=values)]


def dugdale_subproblem_gap(md, vals, dps):
    """u_D(c_D) - u_D(0) of the Dugdale sub-problem (strip traction and the
    contact pressure that keeps |x| < a flat), by the Flamant kernel; the
    contact pressure (the derived one) is first checked by substitution:
    u(x) - u(0) = 0 at x = 0.3 a and 0.8 a, to dps + 3 digits of the
    strip's scale sigma_0 (c_D - a)/E* (with an Arb enclosure: the whole
    ball within that bound)."""
    with workdps(dps + 15):
        A, C, sig, w, E = _values(md, vals)
        scale = abs(sig * (C - A) / E) * mpmath.mpf(10)**-(dps + 3)
        fracs = (sp.Rational(3, 10), sp.Rational(4, 5))
        *flat, gap = _flamant_differences(md, vals, [vals[S.a] * f for f in fracs] + [vals[S.c_D]], dps + 5)
        for frac, r in zip(fracs, flat):
            if abs(r.mid) + r.rad > scale:
                raise VerificationError(f"the Dugdale sub-problem's contact pressure does not keep the contact flat: "
                                        f"u(x) - u(0) = {mpmath.nstr(r.mid, 5)} +- {mpmath.nstr(r.rad, 3)} at "
                                        f"x = {frac} a")
        return gap


def gap_reference(md):
    gd = md.contact.derivation("gap")

    def ref(vals, dps):
        with workdps(dps + 15):
            g0 = _as_ref(gd.reference({**vals, S.x: vals[S.c_D]}, dps + 5), "adhesionless gap")
            return lincomb([(1, g0), (1, dugdale_subproblem_gap(md, vals, dps))], dps + 5)
    return ref


_v, _X, _SIG = sp.Dummy("v", positive=True), sp.Dummy("x", real=True), sp.Dummy("sigma", positive=True)


@functools.cache
def _punches_form():
    """The Dugdale punches' pressure at x: (1/pi) int_a^c_D -2 sigma_0 t/(sqrt(t^2 - x^2) sqrt(c_D^2 - t^2)) dt,
    t = c_D sin(phi), phi = phi0 + (pi/2 - phi0) v (phi0 = asin(a/c_D): the ends exact, in Arb);
    built at the first check (not at import)."""
    phi0 = sp.asin(_A / _C)
    phi = phi0 + (sp.pi / 2 - phi0) * _v
    return -2 * _SIG * _C * sp.sin(phi) / sp.sqrt((_C * sp.sin(phi))**2 - _X**2) * (sp.pi / 2 - phi0)


def _punches(A, C, sig, X, dps):
    """The integral of :func:`_punches_form` over v in [0, 1] by the one reference
    integrator (certified; tanh-sinh where Arb cannot, recorded)."""
    def fallback():
        a, c, s0, x = _mp(A), _mp(C), _mp(sig), _mp(X)
        return mpmath.quad(lambda ph: -2 * s0 * c * mpmath.sin(ph) / mpmath.sqrt((c * mpmath.sin(ph))**2 - x**2),
                           [mpmath.asin(a / c), mpmath.pi / 2])
    try:
        f = bound_acb(_punches_form(), _v, {_A: A, _C: C, _SIG: sig, _X: X})
    except ArbUnsupported as exc:
        return estimate(fallback, str(exc), dps)
    return integrate(f, None, [0, sp.Rational(1, 2), 1], dps, fallback=fallback)


def pressure_reference(md):
    pd = md.contact.derivation("pressure")

    def ref(vals, dps):
        with workdps(dps + 15):
            p0 = _as_ref(pd.reference(vals, dps + 5), "adhesionless pressure")
            I = _punches(vals[S.a], vals[S.c_D], md.sigma0.xreplace(vals), vals[S.x], dps + 5)
            return lincomb([(1, p0), (1 / sp.pi, I)], dps + 5)
    return ref


# ---------------------------------------------------------------- Baney & Hui (1997)
def baney_hui_units(E_star, w, R, sigma0):
    """(lambda, A, F) of Baney & Hui (1997): lambda = 4 sigma_0 (R/(pi^2 E*^2 w))^(1/3),
    A = 2 (w R^2/(pi E*))^(1/3), F = (pi E* w^2 R)^(1/3); SymPy or mpmath numbers."""
    if all(isinstance(v, (sp.Basic, int)) for v in (E_star, w, R, sigma0)):
        cbrt = lambda v: v**sp.Rational(1, 3)  # noqa: E731
        pi = sp.pi
    else:
        cbrt = mpmath.cbrt
        pi = mpmath.pi
    lam = 4 * sigma0 * cbrt(R / (pi**2 * E_star**2 * w))
    A = 2 * cbrt(w * R**2 / (pi * E_star))
    F = cbrt(pi * E_star * w**2 * R)
    return lam, A, F


LAM, ABAR, MBAR, PBAR = sp.symbols("lambda abar m Pbar", positive=True)


def baney_hui_equations(md):
    """The parabola's two conditions in Baney & Hui's normalisation, derived
    from ``md`` (a Maugis-Dugdale contact of the parabola): (Pbar(abar, m),
    the gap condition as an expression equal to 1); a = A abar, c_D = m a,
    P = F Pbar, sigma_0 from lambda."""
    lam, A, F = baney_hui_units(S.E_star, md.w, S.R, md.sigma0)
    sig_of_lam = sp.solve(sp.Eq(lam, LAM), md.sigma0)[0] if md.sigma0.is_Symbol else None
    if sig_of_lam is None:
        raise ValueError("Baney & Hui's form needs sigma_0 as a symbol")
    sub = {S.a: A * ABAR, S.c_D: A * ABAR * MBAR}
    P = sp.simplify(sp.expand_power_base((md.zone_force.xreplace(sub) / F).subs(md.sigma0, sig_of_lam), force=True))
    g = md.cohesive_gap.xreplace(sub).subs(md.sigma0, sig_of_lam)
    h = (md.h0).subs(md.sigma0, sig_of_lam)
    G = sp.simplify(sp.expand_power_base(sp.expand(g / h), force=True))
    return sp.simplify(P), sp.expand(G)


def rigid_limit(md, dps=30, **values):
    """Pull-off of the rigid profile with the Dugdale law (E* -> oo): the
    gap is the profile itself, P = -2 sigma_0 c_r with f(c_r) = h0.
    Independent of the elastic solution (a root of the profile)."""
    vals = md._numeric_values(values)
    with workdps(dps + 10):
        sig = _mp(sp.N(md.sigma0.xreplace(vals), dps + 20))
        h0 = _mp(sp.N(md.h0.xreplace(vals), dps + 20))
        f = sp.lambdify(S.x, md.profile.expr.xreplace({k: v for k, v in vals.items() if k != S.E_star}), "mpmath")
        lo, hi = mpmath.mpf(0), mpmath.mpf(1)
        for _ in range(1100):
            if not f(hi) < h0:
                break
            hi *= 2
        else:     # a bounded profile (1 - cos(x) at h0 > 2): it waited here for ever
            raise DomainError(f"no rigid Dugdale limit of f(x) = {md.profile.expr}: the profile stays below h0 = "
                              f"w/sigma_0 = {mpmath.nstr(h0, 8)} up to x = 2**1100 (f(c_r) = h0 has no root)")
        cr = mpmath.findroot(lambda x: f(x) - h0, (lo if f(lo) < h0 else hi / 2, hi), solver="anderson")
        return -2 * sig * cr


__all__ = ["force_johnson", "force_reference", "gap_reference", "pressure_reference", "dugdale_subproblem_gap",
           "baney_hui_units", "baney_hui_equations", "rigid_limit"]
