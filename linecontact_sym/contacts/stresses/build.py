"""How a :class:`~.stresses.StressField` is built: the verified closed-form
components, the independent Flamant reference at parameter values, the
random verification points, and the numeric field at numeric values (closed
potentials where they are elementary, Popov's punch superposition or the
Cauchy quadrature otherwise).  Functions of the field object ``sf``."""
from __future__ import annotations


import mpmath
import numpy as np
import sympy as sp

from ...core import symbols as S
from ...core.conversion import nsimplify_basic, rational, real_mpf, to_mpf
from ...method.derivation import Derivation, fallback_step, remembered_many, timed
from ...method.rules import Step
from ...method.verification import verify_many
from . import field as F
from .kolosov import density_breakpoints, symbolic_stresses, t
from ..sampling import point_sampler
from .reference import COMPONENTS, flamant_enclosures, flamant_stresses, punch_potentials
from ...numeric.reference import RefValue, combine, estimate
from ...core.precision import workdps


def sampler(sf):
    """Random verification points: the contact's parameters and a, x in
    (-1.5a, 1.5a) (both signs), z in (0.05a, 1.5a), mu, nu and the stick
    half-width where symbolic."""
    base = point_sampler(sf.profile, "any")
    nparams = 1 + len(sf.contact.params)

    def sample(rng):
        vals = base(rng)
        if vals is None:
            return None
        A = float(vals[S.a])
        vals[S.x] = rational(A * rng.uniform(-1.5, 1.5))
        vals[S.z] = rational(A * rng.uniform(0.05, 1.5))
        for sym in sf.variables[nparams:]:
            if sym == S.mu:
                vals[sym] = rational(rng.uniform(0.05, 0.6))
            elif sym == S.nu:
                vals[sym] = rational(rng.uniform(0.1, 0.45))
            elif sf.stick is not None and sym in sf.stick.free_symbols:
                vals[sym] = rational(A * rng.uniform(0.2, 0.9))
            else:
                vals[sym] = rational(rng.uniform(0.5, 2.0))
        return vals
    return sample


def _mp_pressure(contact, vals, a_value, dps):
    """p(s) on [-a, a] as an mpmath callable (even, 0 outside), a = ``a_value``."""
    d = contact.derivation("pressure")
    fixed = {k: v for k, v in vals.items() if k not in (S.a, S.x, S.z)}
    A = to_mpf(a_value)
    if d.closed_form:
        fn = sp.lambdify(S.x, d.expr.xreplace({**fixed, S.a: a_value}), "mpmath")
    else:
        def fn(sv):
            return d.reference({**fixed, S.a: a_value, S.x: sp.Float(sv, dps + 10)}, dps)

    def p(sv):
        sv = abs(sv)
        if sv >= A:
            return mpmath.mpf(0)
        v = fn(sv)
        if isinstance(v, mpmath.mpc):  # rounding at the contact edge (sqrt of -1e-60)
            if abs(v.imag) > mpmath.mpf(10)**(-dps) * max(abs(v.real), 1):
                raise ValueError(f"the pressure is complex at s = {sv}")
            v = v.real
        return v
    return p


def _mp_tractions(sf, vals, dps):
    """(p, q, breaks): the mpmath tractions at ``vals`` and the points where
    they are not smooth (at the working precision: a kink 1e-17 off its
    piece's end costs tanh-sinh a dozen digits)."""
    p = _mp_pressure(sf.contact, vals, vals[S.a], dps)
    breaks = [mpmath.mpf(0)]
    for bp in sf.profile.breakpoints:
        v = to_mpf(bp.xreplace(vals))
        breaks += [v, -v]
    breaks += list(sf.breaks)
    q = None
    if sf.tangential == "sliding":
        m = real_mpf(sf.mu.xreplace(vals))
        q = lambda sv: m * p(sv)  # noqa: E731
    elif sf.tangential == "partial_slip":
        m = real_mpf(sf.mu.xreplace(vals))
        cv = sf.stick.xreplace(vals)
        pc = _mp_pressure(sf.contact, vals, cv, dps)
        q = lambda sv: m * (p(sv) - pc(sv))  # noqa: E731
        breaks += [to_mpf(cv), -to_mpf(cv)]
    elif isinstance(sf.tangential, sp.Expr):
        fq = sp.lambdify(S.x, sf.tangential.xreplace({k: v for k, v in vals.items() if k != S.x}), "mpmath")
        q = fq
    elif sf.tangential is not None:
        q = lambda sv: mpmath.mpf(float(sf.tangential(np.array([float(sv)]))[0]))  # noqa: E731
    return p, q, breaks


def _sym_tractions(sf, vals):
    """(tractions(lo, hi, s), breaks) for :func:`.reference.flamant_enclosures`:
    p and q on the piece lo < s < hi as SymPy expressions with every value
    of ``vals`` exact (p even: written p(s) for s >= 0, p(-s) below), and
    the exact points where they are not smooth; None where a traction is
    not a SymPy expression (a pressure without closed form, a callable q)."""
    d = sf.contact.derivation("pressure")
    if not d.closed_form or (sf.tangential is not None and not isinstance(sf.tangential, sp.Expr)
                             and sf.tangential not in ("sliding", "partial_slip")):
        return None
    fixed = {k: v for k, v in vals.items() if k not in (S.a, S.x, S.z)}
    pa = d.expr.xreplace({**fixed, S.a: vals[S.a]})
    breaks = [sp.S.Zero, *sf.breaks]
    for bp in sf.profile.breakpoints:
        v = bp.xreplace(vals)
        breaks += [v, -v]

    def even(expr, lo, s):
        return expr.xreplace({S.x: s if lo >= 0 else -s})
    mu = sf.mu.xreplace(vals) if sf.tangential in ("sliding", "partial_slip") else None
    cv = pc = qx = None
    if sf.tangential == "partial_slip":
        cv = sf.stick.xreplace(vals)
        pc = d.expr.xreplace({**fixed, S.a: cv})
        breaks += [cv, -cv]
    elif isinstance(sf.tangential, sp.Expr):
        qx = sf.tangential.xreplace(fixed)

    def tractions(lo, hi, s):
        P = even(pa, lo, s)
        if sf.tangential is None:
            return P, 0
        if sf.tangential == "sliding":
            return P, mu * P
        if sf.tangential == "partial_slip":
            inside = -cv <= lo and hi <= cv
            return P, mu * (P - even(pc, lo, s)) if inside else mu * P
        return P, qx.xreplace({S.x: s})
    return tractions, breaks


def flamant_reference(sf):
    """``reference(vals, dps) -> {sigma_x, sigma_z, tau_xz}``: the Flamant
    integrals of the tractions (independent of the closed forms) where the
    pressure is closed: Arb enclosures of the SymPy tractions
    (:func:`.reference.flamant_enclosures`), mpmath quadrature of them as the
    recorded fallback; otherwise Popov's punch superposition in mpmath
    (:func:`.reference.punch_potentials`, no nested quadrature)."""
    if not sf.contact.derivation("pressure").closed_form and sf.tangential in (None, "sliding", "partial_slip"):
        return _punch_reference(sf)

    def reference(vals, dps):
        def mp_values():
            with workdps(dps + 10):
                p, q, breaks = _mp_tractions(sf, vals, dps)
                num = [to_mpf(vals[k]) for k in (S.a, S.x, S.z)]
                return flamant_stresses(p, q, *num, breaks=breaks, dps=dps)
        sym = _sym_tractions(sf, vals) if vals[S.z] > 0 else None
        if sym is None:
            why = "the tractions are not SymPy expressions" if vals[S.z] > 0 else "the surface (no integral)"
            mp = mp_values()
            out = [estimate(lambda k=k: mp[k], why, dps) for k in range(3)]
        else:
            tractions, breaks = sym
            out = flamant_enclosures(tractions, vals[S.a], vals[S.x], vals[S.z], breaks, dps, fallback=mp_values)
        return dict(zip(COMPONENTS, out))
    return reference


def _punch_reference(sf):
    from ..normal.force_law import ForceLaw
    from .kolosov import kolosov_stresses

    def reference(vals, dps):
        with workdps(dps + 10):
            fixed = {k: v for k, v in vals.items() if k in (S.E_star,) + tuple(sf.contact.params)}
            law = ForceLaw.from_contact(sf.contact, fixed)
            num = [to_mpf(vals[k]) for k in (S.a, S.x, S.z)]
            G, dG = punch_potentials(law.dP, *num, breaks=law.breaks(), dps=dps)
            H = dH = 0
            if sf.tangential is not None:
                m = real_mpf(sf.mu.xreplace(vals))
                H, dH = m * G, m * dG
                if sf.tangential == "partial_slip":
                    cv = real_mpf(sf.stick.xreplace(vals))
                    Gc, dGc = punch_potentials(law.dP, cv, num[1], num[2], law.breaks(), dps)
                    H, dH = H - m * Gc, dH - m * dGc
            sx, sz, txz = kolosov_stresses(G, dG, H, dH, num[2], mpmath.re, mpmath.im, mpmath.pi)
        return {"sigma_x": +sx, "sigma_z": +sz, "tau_xz": +txz}
    return reference


#: the three components as symbols of a quantity made from them
_PARTS = tuple(sp.Dummy(k, real=True) for k in COMPONENTS)


def combine_reference(ref, make):
    """The reference of a quantity made from the three components
    (``make(sigma_x, sigma_z, tau_xz)``: von Mises, the principal shear,
    sigma_y): the expression evaluated on the components' references by
    :func:`~linecontact_sym.numeric.reference.combine`, an Arb enclosure
    where the three are (the Flamant integrals of closed tractions), else an
    mpmath estimate that says why."""
    full = getattr(ref, "full", None)
    if full is None:
        return ref

    def reference(vals, dps):
        c = full(vals, dps)
        parts = [c[k] if isinstance(c[k], RefValue) else
                 estimate(lambda v=c[k]: v, "Popov's punch superposition in mpmath (no closed pressure)", dps)
                 for k in COMPONENTS]
        return combine(make(*_PARTS).xreplace(vals), list(_PARTS), parts, dps)
    return reference


@timed
def derive_components(sf) -> dict:
    G = sf.derivation("cauchy_transform").expr
    H = sf.tangential_transform()
    exprs = dict(zip(("sigma_x", "sigma_z", "tau_xz"), symbolic_stresses(G, H)))
    closed = sf._closed()
    sf.contact.derivation("pressure")  # derived here, not inside the (forked) verification
    full = flamant_reference(sf)
    notes, recs = [], {}
    if closed and sf.verify:
        recs = verify_many(exprs, full, sampler(sf), (), n_points=sf.points,
                           reference_name="the Flamant integrals of p and q (Johnson Eq. 2.23, s = x + z sinh u)")
        bad = [k for k, r in recs.items() if not r.passed]
        if bad:
            closed = False
            notes.append(f"closed form FAILED verification for {', '.join(bad)}; evaluated by quadrature")
    G_rule = sf.derivation("cauchy_transform").rule
    out = {}
    for k, e in exprs.items():
        ref = component_reference(full, k)
        step = Step(f"kolosov({G_rule})", e, (), ("Kolosov-Muskhelishvili formulas from G and H",)) if closed \
            else fallback_step("no closed form of the potentials: Flamant quadrature")
        out[k] = Derivation(k, expr=e, closed_form=closed, step=step, verification=recs.get(k), notes=tuple(notes),
                            reference=ref, variables=(S.a, S.x, S.z) + sf.variables)
    return out


def _store_parts(sf, what):
    """What names a field's problem for the on-disk store (None: a callable
    traction, which is code, not data: not stored)."""
    if callable(sf.tangential) and not isinstance(sf.tangential, sp.Basic):
        return None
    c = sf.contact
    return (what, c.profile.expr, dict(c.profile.ranges), c.derivation("force").expr, sf.tangential, sf.mu,
            sf.nu, sf.stick, tuple(sf.breaks), sf.verify, sf.points, c.budget)


def remembered(sf, what, make, rebuild):
    """``make()`` (a tuple of derivations) remembered in memory and on disk
    (:func:`~linecontact_sym.method.derivation.remembered_many`, the store's
    get/put by key), unless the traction is a callable."""
    parts = _store_parts(sf, what)
    return make() if parts is None else remembered_many(parts, make, sf.contact.budget, rebuild,
                                                        sampler=sampler(sf))     # read from disk: re-checked


def remembered_components(sf) -> dict:
    """:func:`derive_components`, remembered with their verification; the
    Flamant reference of stored ones is rebuilt (closures are not stored)."""
    full = []

    def rebuild(d):
        if not full:
            sf.contact.derivation("pressure")
            full.append(flamant_reference(sf))
        d.reference = component_reference(full[0], d.quantity)
        return d
    ds = remembered(sf, "stress_components", lambda: tuple(derive_components(sf).values()), rebuild)
    return {d.quantity: d for d in ds}


def component_reference(full, k):
    """The reference of one stress component from the shared Flamant reference."""
    def ref(vals, dps):
        return full(vals, dps)[k]
    ref.full = full
    return ref


_ELEMENTARY = (sp.Add, sp.Mul, sp.Pow, sp.Symbol, sp.Number, sp.NumberSymbol, sp.core.numbers.ImaginaryUnit, sp.log,
               sp.asin, sp.acos, sp.atan, sp.asinh, sp.acosh, sp.atanh, sp.exp, sp.sin, sp.cos, sp.tan)


def _elementary(expr) -> bool:
    return all(isinstance(e, _ELEMENTARY) for e in sp.preorder_traversal(expr))


def _potential(sf, vals, a_value):
    """The normal potential (G, G') at numeric values for half-width a_value."""
    Gd = sf.derivation("cauchy_transform")
    at = {**{k: v for k, v in vals.items() if k not in (S.x, S.z)}, S.a: a_value}
    if Gd.closed_form and _elementary(Gd.expr):
        G = Gd.expr.xreplace(at)
        return F.ClosedPotential(sp.lambdify(S.zeta, G, "numpy"),
                                 sp.lambdify(S.zeta, sp.diff(G, S.zeta), "numpy"), float(a_value))
    from ...numeric.exports import lambdify_numpy
    D = sf._density().xreplace({k: v for k, v in at.items() if k != S.a})
    bps = [nsimplify_basic(b.xreplace(at)) for b in density_breakpoints(D)]
    near = {float(b): (_offset_density(D, b, 1), _offset_density(D, b, -1)) for b in bps}
    dens = lambdify_numpy(D.subs(S.a, t), [t])
    return F.PunchPotential(dens, float(a_value), [float(b) for b in bps], near=near)


def _offset_density(D, b, side):
    """D(b + side*d) as a float64 function of the offset d > 0, the
    arguments of its square roots put over one denominator and factored, so
    that no t - b is formed (the density may be singular at a kink, b)."""
    from ...numeric.exports import lambdify_numpy
    d = sp.Dummy("d", positive=True)
    e = D.subs(S.a, b + side * d)
    if e.has(sp.Piecewise):
        return None
    e = e.replace(lambda q: q.is_Pow and q.exp.is_Rational and q.exp.q == 2,
                  lambda q: sp.factor(sp.together(sp.expand(q.base)))**q.exp)
    try:
        return lambdify_numpy(e, [d])
    except Exception:  # no float64 export of this form: the plain density is used there
        return None


def _normal_part(sf, vals):
    """(normal potential, P/(2a)) at the values: neither depends on the friction
    coefficient, so they are built once for every mu (a search in mu, as
    :meth:`friction_limit`, builds a field per mu), kept with the fields."""
    friction = sf.mu.free_symbols - set(sf.contact.params)
    key = ("normal",) + tuple(sorted((k.name, float(v)) for k, v in vals.items() if k not in friction))
    if key not in sf._fields:
        normal = _potential(sf, vals, vals[S.a])
        force = float(sf.contact.derivation("force").evalf(dps=15, **{k.name: v for k, v in vals.items()
                                                                       if k in (S.a, S.E_star) + sf.contact.params}))
        sf._fields[key] = (normal, force / (2 * float(vals[S.a])))
    return sf._fields[key]


def build_field(sf, vals) -> F.FieldEvaluator:
    normal, mean_pressure = _normal_part(sf, vals)
    nuv = sf.nu.xreplace(vals)
    nu = float(nuv) if nuv.is_number else float("nan")  # not given: sigma_y, von Mises, Tresca are NaN
    mu = float(sf.mu.xreplace(vals)) if sf.tangential in ("sliding", "partial_slip") else 0.0
    tangential = None
    if sf.tangential == "partial_slip":
        tangential = F.Scaled(_potential(sf, vals, sf.stick.xreplace(vals)), -mu)
    elif isinstance(sf.tangential, sp.Expr):
        q = sf.tangential.xreplace({k: v for k, v in vals.items() if k != S.x})
        from ...numeric.quadrature import piecewise_breakpoints
        bps = [float(b) for b in piecewise_breakpoints(q, S.x) if b.is_number] + list(sf.breaks)
        tangential = F.CauchyPotential(sp.lambdify(S.x, q, "numpy"), float(vals[S.a]), bps + [-b for b in bps])
    elif sf.tangential not in (None, "sliding"):
        tangential = F.CauchyPotential(sf.tangential, float(vals[S.a]), sf.breaks)
    return F.FieldEvaluator(normal, tangential, nu, friction=mu, mean_pressure=mean_pressure)


__all__ = ["derive_components", "remembered_components", "remembered", "component_reference", "build_field", "flamant_reference", "sampler"]
