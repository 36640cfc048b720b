"""Where the frictionless compact-contact solution holds: the profile does
not decrease on (0, a), dP0/da >= 0 (else the pressure at the edges,
p ~ (dP0/da) sqrt(a - |x|)/pi, is tensile), the pressure is compressive
inside, the gap is non-negative outside (no second contact).

How far out the gap is checked: to 1000 a, on a geometric grid.  In 2-D the
elastic displacement outside the contact grows like ln|x|, so for a bounded
profile (a bump, a periodic profile) the gap turns negative far enough away
whatever a is: such profiles are admissible only "within 1000 a".

The same conditions, cheaply, are part of every result: the verification
points (:mod:`~linecontact_sym.contacts.sampling`), the pull-off search range
(:func:`.equilibria.admissible_range`: dP0/da >= 0 and the real domain) and
``evaluate`` / ``evaluate_at`` (:meth:`.base.Contact._check_admissible`:
parameter assumptions, f' >= 0 on (0, a), dP0/da >= 0)."""
from __future__ import annotations

import mpmath
import sympy as sp

from ...core import symbols as S
from ...core.errors import DomainError, InadmissibleProfileError
from ...method.verification import holds
from ...parsing import to_sympy
from ...core.precision import workdps


def _mp_function(contact, quantity, dps):
    cache = contact._caches()
    key = ("mpfun", quantity, dps)
    if key not in cache:
        cache[key] = contact.to_numeric(quantity, backend="mpmath", dps=dps, check=False)
    return cache[key]


def check_admissible(contact, dps: int = 20, **values):
    """Numerically check the assumptions of the frictionless compact-contact
    solution at one point (a and the parameters as keywords): the profile
    does not decrease on (0, a), p >= 0 inside and the gap >= 0 outside.
    Raises :class:`InadmissibleProfileError` naming the broken assumption."""
    prof = contact.profile
    vals = {s: to_sympy(values[s.name]) for s in (S.a,) + tuple(contact.variables)}
    A = float(vals[S.a])
    fixed = {k: v for k, v in vals.items() if k != S.a}
    fp = prof.mp_callable(fixed, derivative=1)
    with workdps(dps):
        for i in range(1, 50):
            xv = mpmath.mpf(A) * i / 50
            if fp(xv) < 0:
                raise InadmissibleProfileError(
                    f"profile {prof.name!r} decreases at x = {float(xv):.6g} < a = {A:g}: "
                    f"the contact is not compact there (it would open and close again)")
        fd = contact.derivation("force")
        if fd.closed_form and not fd.expr.has(sp.Integral):
            d = sp.N(sp.diff(fd.expr, S.a).xreplace(vals), dps)
            if d.is_real and d < 0:
                raise InadmissibleProfileError(
                    f"profile {prof.name!r}: dP0/da = {float(d):.3g} < 0 at a = {A:g}: tensile pressure at "
                    f"the edges of the contact; the frictionless solution does not hold")
        pfun = _mp_function(contact, "pressure", dps)
        gfun = _mp_function(contact, "gap", dps)
        kw = {k: v for k, v in values.items() if k != "x"}
        for i in range(1, 20):
            xv = mpmath.mpf(A) * i / 20
            p = pfun(**kw, x=xv)
            if p < 0:
                raise InadmissibleProfileError(
                    f"profile {prof.name!r}: tensile pressure p = {float(p):.3g} at "
                    f"x = {float(xv):.4g} without adhesion; the frictionless solution does not hold")
        # the gap on a geometric grid out to 1000 a (points where the profile
        # is not real, e.g. beyond a cylinder's radius, are skipped); a periodic
        # array: on (a, L/2], up to the crest between two contacts
        top = contact.geometry.mp_a_max(fixed)
        facs = (1.01, 1.1, 1.5, 2, 3, 5, 10, 30, 100, 1000) if top == mpmath.inf else \
            tuple(1 + (top / mpmath.mpf(A) - 1) * k for k in (0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99))
        for fac in facs:
            try:
                g = gfun(**kw, x=mpmath.mpf(A) * fac)
            except (DomainError, ValueError, ZeroDivisionError):
                continue
            if isinstance(g, mpmath.mpc):
                continue
            if g < 0:
                raise InadmissibleProfileError(
                    f"profile {prof.name!r}: negative gap {float(g):.3g} at x = {float(A * fac):.4g}"
                    f" outside the contact: a second contact opens there")
    return True


def admissible_range(contact, a_max: float = 100.0, rtol: float = 1e-6, **values):
    """The half-widths 0 < a < a* (a periodic array: a* <= L/2) for which the frictionless compact-contact
    solution holds at the given parameters (keywords) -- within the checks of
    :func:`check_admissible` (the gap is sampled out to 1000 a) -- found by
    scanning it on a geometric grid up to ``a_max`` and bisecting the first
    failure to ``rtol``.  Returns ``(a_star, reason)``; ``a_star = a_max`` and
    ``reason = None`` when no failure was found."""
    top = contact.geometry.mp_a_max({s: to_sympy(values[s.name]) for s in contact.geometry.symbols})
    if top != mpmath.inf:       # a periodic array: full contact at a = L/2
        a_max = min(a_max, float(top))

    def ok(av):
        try:
            check_admissible(contact, **{**values, "a": sp.Float(av, 20)})
            return True, None
        except (InadmissibleProfileError, DomainError, ValueError, TypeError, ZeroDivisionError) as exc:
            return False, str(exc)
    grid = [a_max * 2.0**(-k) for k in range(30, -1, -1)]
    good, bad, reason = None, None, None
    for av in grid:
        fine, why = ok(av)
        if fine:
            good = av
        else:
            bad, reason = av, why
            break
    if bad is None:
        return a_max, None
    if good is None:
        raise InadmissibleProfileError(f"profile {contact.profile.name!r} is not admissible even "
                                       f"at a = {bad:g}: {reason}")
    while bad - good > rtol * bad:
        mid = 0.5 * (good + bad)
        fine, why = ok(mid)
        if fine:
            good = mid
        else:
            bad, reason = mid, why
    return good, reason


__all__ = ["check_admissible", "admissible_range", "check_point"]


def check_point(contact, values: dict) -> None:
    """The frictionless solution holds at ``values`` (Symbol -> number, with
    ``a``): the point conditions of the force law (the exact cylinder's
    a < R, ...) that the values decide hold there.  The contacts built on
    this one (adhesive, tangential, stresses) call it before any numeric
    work, so a point outside is a :class:`~linecontact_sym.core.errors.DomainError`
    at once, not a foreign exception after a long search."""
    d = contact.derivation("force")
    failed = [c for c, t in zip(d.point_conditions, d.point_test)
              if c.free_symbols <= set(values) and not holds((t,), values)]
    if failed:
        shown = {k.name if hasattr(k, "name") else k: v for k, v in values.items()}
        raise DomainError(f"the frictionless solution holds only where {', '.join(map(str, d.point_conditions))}; "
                          f"{', '.join(map(str, failed))} fails at {shown}")
