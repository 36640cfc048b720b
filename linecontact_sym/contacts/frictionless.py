"""User-facing contact objects (one object per physical system, each physical
quantity a property returning a SymPy expression; cf. SymPy's ``Beam``).
"""
from __future__ import annotations

import random
import time

import mpmath
import sympy as sp

from ..parsing import to_sympy
from ..core import symbols as S
from ..method import rules as ST
from ..method import transforms as T
from ..core.budget import DEFAULT_BUDGET, run_with_budget
from ..method.derivation import Derivation, VERIFY_DPS, try_strategies, verify, REQUIRED_DIGITS
from ..core.errors import BudgetExceeded, DomainError, InadmissibleProfileError, ProfileError
from ..method.profile import Profile


def _rat(v):
    return sp.Rational(round(v * 10**6), 10**6)


class LineContact:
    """Frictionless, non-adhesive contact of a rigid symmetric profile with an
    elastic half-plane (plane strain), solved by Popov's (2017) superposition
    of flat punches parametrised by the load per unit length.

    Parameters
    ----------
    profile : sympy.Expr
        f(x) for x >= 0 (mirrored to x < 0); ``Piecewise`` for flats/kinks.
    params : list or dict, optional
        Declared parameters (positive symbols are declared implicitly); a dict
        gives each a (low, high) range for the random verification points.
    budget : float
        Seconds allowed to the symbolic derivation of each quantity.
    verify : bool
        Check every closed form against mpmath quadrature (default True).

    Examples
    --------
    >>> import sympy as sp, linecontact_sym as lcs
    >>> R = sp.Symbol("R", positive=True)
    >>> c = lcs.LineContact(lcs.x**2/(2*R))
    >>> c.force
    pi*E_star*a**2/(4*R)
    >>> c.pressure
    E_star*sqrt(a**2 - x**2)/(2*R)
    """

    def __init__(self, profile, params=None, name: str | None = None,
                 budget: float = DEFAULT_BUDGET, verify: bool = True,
                 points: int = 5, digits: int = REQUIRED_DIGITS):
        self.profile = profile if isinstance(profile, Profile) else Profile(profile, params, name)
        self.budget = budget
        self.verify = verify
        self.points = points
        self.digits = digits
        self._cache: dict = {}

    # --------------------------------------------------------------- plumbing
    def __repr__(self):
        return f"LineContact({self.profile.expr})"

    def _repr_latex_(self):
        from ..core.printing import to_latex
        return f"$f(x) = {to_latex(self.profile.expr)}$"

    @property
    def params(self):
        return self.profile.params

    def derivation(self, quantity: str) -> Derivation:
        """The :class:`Derivation` (expression + method + conditions +
        verification record) of ``'force'``, ``'pressure'`` or ``'gap'``."""
        if quantity not in self._cache:
            maker = {"force": self._derive_force, "pressure": self._derive_pressure,
                     "gap": self._derive_gap}.get(quantity)
            if maker is None:
                raise ValueError(f"unknown quantity {quantity!r}; choose force, pressure or gap")
            self._cache[quantity] = maker()
        return self._cache[quantity]

    # --------------------------------------------------------------- sampling
    def _sample_a(self, rng, vals):
        pcs = self.profile.pieces
        pc = pcs[rng.randrange(len(pcs))] if len(pcs) > 1 else pcs[0]
        lo = float(sp.N(pc.lo.xreplace(vals)))
        hi = float(sp.N(pc.hi.xreplace(vals))) if pc.hi != sp.oo else lo + 1.5
        if len(pcs) == 1:
            lo, hi = 0.05, 1.5
        av = rng.uniform(lo + 0.02 * (hi - lo), hi - 0.02 * (hi - lo))
        for _ in range(12):  # shrink into the profile's real domain
            try:
                fp = complex(sp.N(self.profile.piece_at(av, vals).derivative.xreplace(vals).subs(S.x, av)))
                if abs(fp.imag) < 1e-30 and abs(fp) < 1e30:
                    return _rat(av)
            except (TypeError, ValueError):
                pass
            av *= 0.5
        return None

    def _sampler(self, kind: str):
        def sample(rng):
            vals = self.profile.sample_params(rng)
            vals[S.E_star] = _rat(rng.uniform(0.5, 3.0))
            av = self._sample_a(rng, vals)
            if av is None:
                return None
            vals[S.a] = av
            if kind == "pressure":
                vals[S.x] = _rat(float(av) * rng.uniform(0.02, 0.98))
            elif kind == "gap":
                vals[S.x] = _rat(float(av) * rng.uniform(1.05, 2.5))
            return vals
        return sample

    # --------------------------------------------------------------- derivations
    def _finish(self, quantity, strategies, args, reference, sampler, fallback_expr, t0,
                extra_notes=(), variables=()):
        expr, conds, notes, name = try_strategies(strategies, args, self.budget)
        rec = None
        if expr is not None and self.verify:
            rec = verify(expr, reference, sampler, conds, n_points=self.points, dps=VERIFY_DPS,
                         reference_name=f"mpmath quadrature of the defining integral ({quantity})")
            if not rec.passed:
                notes = list(notes) + [f"closed form from {name} FAILED verification "
                                       f"({rec.min_digits:.1f} digits); returned unevaluated: {expr}"]
                expr = None
        if expr is None:
            return Derivation(quantity, fallback_expr, False, "numeric fallback (no closed form found)",
                              (), rec, time.perf_counter() - t0,
                              tuple(list(notes) + list(extra_notes)), reference, variables)
        return Derivation(quantity, expr, True, f"{name}: {'; '.join(notes)}", conds, rec,
                          time.perf_counter() - t0, tuple(extra_notes), reference, variables)

    def _force_reference(self):
        prof = self.profile
        return lambda vals, dps: T.force_quad(prof, vals, dps)

    def _derive_force(self) -> Derivation:
        t0 = time.perf_counter()
        notes = []
        slope = self.profile.slope_at_origin
        if slope != 0:
            notes.append(
                f"f'(0+) = {slope} != 0: the paper's printed Eq. (10) drops the boundary term "
                f"E_star*a*f'(0+) = {S.E_star * S.a * slope}; the force law here includes it (Eq. 10*)")
        else:
            notes.append("f'(0+) = 0: the paper's printed Eq. (10) and Eq. (10*) agree")
        return self._finish("force", ST.FORCE_STRATEGIES, (self.profile,), self._force_reference(),
                            self._sampler("force"), T.force_integral(self.profile), t0, notes,
                            (S.a, S.E_star) + self.params)

    def _dP_callable(self, vals):
        """mpmath callable of P'(s) at fixed parameters, with the breakpoints."""
        fd = self.derivation("force")
        fixed = {k: v for k, v in vals.items() if k not in (S.a, S.x)}
        breaks = [mpmath.mpf(sp.N(b.xreplace(fixed), 60)) for b in self.profile.breakpoints]
        if fd.closed_form:
            names = tuple(sorted(set(fixed) & fd.expr.free_symbols, key=lambda s: s.name))
            key = ("dP/da", names)
            if key not in self._cache:  # lambdified once, parameters as arguments
                args = (S.a,) + names     # dummify: a symbol named gamma must not shadow Gamma
                self._cache[key] = (sp.lambdify(args, sp.diff(fd.expr, S.a), "mpmath", dummify=True),
                                    args[1:])
            fn, names = self._cache[key]
            pv = [mpmath.mpf(sp.N(fixed[k], mpmath.mp.dps + 10)) for k in names]

            def dP(sv):
                return fn(sv, *pv)
        else:
            def dP(sv):
                return mpmath.diff(lambda u: T.force_quad(self.profile, {**fixed, S.a: u}, mpmath.mp.dps), sv)
        return dP, breaks

    def _derive_pressure(self) -> Derivation:
        t0 = time.perf_counter()
        fd = self.derivation("force")

        def reference(vals, dps):
            with mpmath.workdps(dps + 10):
                dP, breaks = self._dP_callable(vals)
                return T.pressure_quad(dP, breaks, vals, dps)
        if not fd.closed_form:
            return Derivation("pressure", T.pressure_integral(fd.expr), False,
                              "numeric fallback (force law has no closed form)", (), None,
                              time.perf_counter() - t0, (), reference,
                              (S.a, S.x, S.E_star) + self.params)
        return self._finish("pressure", ST.PRESSURE_STRATEGIES, (fd.expr, self.profile), reference,
                            self._sampler("pressure"), T.pressure_integral(fd.expr), t0, (),
                            (S.a, S.x, S.E_star) + self.params)

    def _derive_gap(self) -> Derivation:
        t0 = time.perf_counter()
        fd = self.derivation("force")
        fexpr = self.profile.expr

        def reference(vals, dps):
            with mpmath.workdps(dps + 10):
                dP, breaks = self._dP_callable(vals)
                fixed = {k: v for k, v in vals.items() if k not in (S.a, S.x)}
                f = self.profile.mp_callable(fixed)
                return T.gap_quad(f, dP, breaks, vals, dps)
        fallback = T.gap_integral(fexpr, fd.expr)
        if not fd.closed_form:
            return Derivation("gap", fallback, False, "numeric fallback (force law has no closed form)",
                              (), None, time.perf_counter() - t0, (), reference,
                              (S.a, S.x, S.E_star) + self.params)
        return self._finish("gap", ST.GAP_STRATEGIES, (fd.expr, fexpr), reference,
                            self._sampler("gap"), fallback, t0, (), (S.a, S.x, S.E_star) + self.params)

    # --------------------------------------------------------------- quantities
    @property
    def force(self) -> sp.Expr:
        """P(a), Eq. (10*) (Eq. 10 with its boundary term): load per unit length."""
        return self.derivation("force").expr

    @property
    def pressure(self) -> sp.Expr:
        """p(x; a) for 0 <= x < a, Eq. (12) (mirror for x < 0)."""
        return self.derivation("pressure").expr

    @property
    def gap(self) -> sp.Expr:
        """Surface separation g(x; a) for x > a, from Eqs. (3)/(5): f(x) - (d - u_z(x))."""
        return self.derivation("gap").expr

    def half_width(self, load=S.P, **values):
        """Contact half-width a at load P.

        With a symbolic load: the closed-form inverse of the force law where
        SymPy finds one (a :class:`Derivation`, verified: P(a(P)) = P to 30
        digits at random points), else a Derivation with ``closed_form=False``
        whose ``evalf`` solves P(a) = load numerically.  With a numeric load and
        numeric parameters (keywords): the number (mpmath, 30 digits).
        """
        fd = self.derivation("force")
        load = to_sympy(load)
        if load.is_number:
            if load <= 0:
                raise DomainError(f"the load must be positive for a non-adhesive contact, got {load}")
            vals = {s: to_sympy(values[s.name]) for s in (S.E_star,) + self.params if s.name in values}
            missing = [s.name for s in (S.E_star,) + self.params if s not in vals]
            if missing:
                raise DomainError(f"half_width needs values for {missing}")
            return solve_half_width(fd, vals, load, self.profile)
        key = ("half_width", load)
        if key not in self._cache:
            self._cache[key] = self._derive_half_width(load)
        return self._cache[key]

    def _derive_half_width(self, load) -> Derivation:
        t0 = time.perf_counter()
        fd = self.derivation("force")
        expr = None
        notes = []
        if fd.closed_form and not fd.expr.has(sp.Piecewise):
            try:
                sols = run_with_budget(_solve_for_a, fd.expr, load, seconds=self.budget)
            except BudgetExceeded:
                sols = []
                notes.append("sympy.solve ran out of budget")
            except (NotImplementedError, ValueError, TypeError) as exc:
                sols = []
                notes.append(f"sympy.solve: {exc}".splitlines()[0])
            sample = self._sampler("force")
            for cand in sols:
                rng = random.Random(7)
                good = 0
                for _ in range(self.points):
                    vals = sample(rng)
                    if vals is None:
                        continue
                    Pv = sp.N(fd.expr.xreplace(vals), 60)
                    av = sp.N(cand.xreplace({**vals, load: Pv}), 60)
                    if av.is_real and abs(av - vals[S.a]) <= abs(vals[S.a]) * sp.Float(10)**(-self.digits):
                        good += 1
                if good == self.points:
                    expr = cand
                    break
        def reference(vals, dps):
            return solve_half_width(fd, {k: v for k, v in vals.items() if k != load}, vals[load],
                                    self.profile, dps)
        if expr is not None:
            return Derivation("half_width", expr, True, "sympy.solve of P(a) = P, root checked by "
                              "substitution at random points", (), None, time.perf_counter() - t0,
                              tuple(notes), reference, (load, S.E_star) + self.params)
        return Derivation("half_width", sp.Eq(fd.expr, load), False,
                          "numeric root of P(a) = P (no closed-form inverse)", (), None,
                          time.perf_counter() - t0, tuple(notes), reference, (load, S.E_star) + self.params)

    # --------------------------------------------------------------- adhesion
    def adhesive(self, work_of_adhesion=S.gamma):
        """The JKR-adhesive form of this contact (Eqs. 29-36), see
        :mod:`linecontact_sym.adhesion`."""
        from .adhesive import AdhesiveLineContact
        return AdhesiveLineContact(self, work_of_adhesion)

    # --------------------------------------------------------------- numbers
    def to_numeric(self, quantity: str, backend: str = "numpy", dps: int = 30, **params):
        """A callable of the quantity: ``fn(a=..., x=..., E_star=..., R=...)``.

        ``backend='numpy'`` (vectorised float64) or ``'mpmath'`` (``dps``
        digits).  Keywords given here are fixed once."""
        from ..numeric.exports import make_callable
        return make_callable(self.derivation(quantity), backend, dps, params)

    def evaluate(self, quantity: str, rtol=None, certified: bool = False, dps=None, **values):
        """The cheapest evaluation that meets ``rtol``: float64, mpmath at a
        sufficient precision, a cheaper model with its error bound, or with
        ``certified=True`` an Arb ball (python-flint).  The result says which
        path was taken and its error estimate; see :mod:`linecontact_sym.evaluate`."""
        from ..numeric.evaluate import evaluate
        return evaluate(self, quantity, rtol=rtol, certified=certified, dps=dps, **values)

    def evaluate_at(self, quantity: str, dps: int = 30, **values):
        """One high-precision value, with the domain checked (a > 0, |x| <= a
        for the pressure, |x| >= a for the gap)."""
        av = values.get("a")
        if av is not None and to_sympy(av) <= 0:
            raise DomainError(f"the half-width must be positive, got a = {av}")
        if "x" in values and av is not None:
            xv = abs(to_sympy(values["x"]))
            if quantity == "pressure" and xv > to_sympy(av):
                raise DomainError(f"x = {values['x']} lies outside the contact |x| <= a = {av}; "
                                  f"use the 'gap' there")
            if quantity == "gap" and xv < to_sympy(av):
                raise DomainError(f"x = {values['x']} lies inside the contact; the gap is zero there")
            values = {**values, "x": xv}
        return self.derivation(quantity).evalf(dps=dps, **values)

    def _mp_function(self, quantity, dps):
        key = ("mpfun", quantity, dps)
        if key not in self._cache:
            self._cache[key] = self.to_numeric(quantity, backend="mpmath", dps=dps)
        return self._cache[key]

    def report(self) -> str:
        return "\n".join(self.derivation(q).summary() for q in ("force", "pressure", "gap"))

    def check_admissible(self, dps: int = 20, **values):
        """Numerically check the assumptions of the frictionless compact-contact
        solution at one point (a and the parameters as keywords): the profile
        does not decrease on (0, a), p >= 0 inside and the gap >= 0 outside.
        Raises :class:`InadmissibleProfileError` naming the broken assumption."""
        vals = {s: to_sympy(values[s.name]) for s in (S.a, S.E_star) + self.params}
        A = float(vals[S.a])
        fixed = {k: v for k, v in vals.items() if k != S.a}
        fp = self.profile.mp_callable(fixed, derivative=1)
        with mpmath.workdps(dps):
            for i in range(1, 50):
                xv = mpmath.mpf(A) * i / 50
                if fp(xv) < 0:
                    raise InadmissibleProfileError(
                        f"profile {self.profile.name!r} decreases at x = {float(xv):.6g} < a = {A:g}: "
                        f"the contact is not compact there (it would open and close again)")
            pfun = self._mp_function("pressure", dps)
            gfun = self._mp_function("gap", dps)
            kw = {k: v for k, v in values.items() if k != "x"}
            for i in range(1, 20):
                xv = mpmath.mpf(A) * i / 20
                p = pfun(**kw, x=xv)
                if p < 0:
                    raise InadmissibleProfileError(
                        f"profile {self.profile.name!r}: tensile pressure p = {float(p):.3g} at "
                        f"x = {float(xv):.4g} without adhesion; the frictionless solution does not hold")
            # the gap on a geometric grid out to 1000 a (points where the profile
            # is not real, e.g. beyond a cylinder's radius, are skipped)
            for fac in (1.01, 1.1, 1.5, 2, 3, 5, 10, 30, 100, 1000):
                try:
                    g = gfun(**kw, x=mpmath.mpf(A) * fac)
                except (DomainError, ValueError, ZeroDivisionError):
                    continue
                if isinstance(g, mpmath.mpc):
                    continue
                if g < 0:
                    raise InadmissibleProfileError(
                        f"profile {self.profile.name!r}: negative gap {float(g):.3g} at x = {A * fac:.4g}"
                        f" outside the contact: a second contact opens there")
        return True

    def admissible_range(self, a_max: float = 100.0, rtol: float = 1e-6, **values):
        """The half-widths 0 < a < a* for which the frictionless compact-contact
        solution holds at the given parameters (keywords) -- within the
        checks of :meth:`check_admissible` (the gap is sampled out to 1000 a) --
        found by scanning
        :meth:`check_admissible` on a geometric grid up to ``a_max`` and
        bisecting the first failure to ``rtol``.  Returns ``(a_star, reason)``;
        ``a_star = a_max`` and ``reason = None`` when no failure was found."""
        def ok(av):
            try:
                self.check_admissible(**{**values, "a": sp.Float(av, 20)})
                return True, None
            except (InadmissibleProfileError, DomainError, ValueError, TypeError,
                    ZeroDivisionError) as exc:
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
            raise InadmissibleProfileError(f"profile {self.profile.name!r} is not admissible even "
                                           f"at a = {bad:g}: {reason}")
        while bad - good > rtol * bad:
            mid = 0.5 * (good + bad)
            fine, why = ok(mid)
            if fine:
                good = mid
            else:
                bad, reason = mid, why
        return good, reason


def _solve_for_a(Pexpr, load):
    sols = sp.solve(sp.Eq(Pexpr, load), S.a)
    return [sp.simplify(s) for s in sols]


def solve_half_width(fd: Derivation, vals: dict, load, profile: Profile, dps: int = 30):
    """Solve P(a) = load for a at fixed parameters (bracketing on the
    increasing force law, then mpmath's Anderson-Bjorck root finder)."""
    with mpmath.workdps(dps + 10):
        L = mpmath.mpf(sp.N(load, dps + 10))
        if fd.closed_form:
            Pf = sp.lambdify(S.a, fd.expr.xreplace(vals), "mpmath")
        else:
            def Pf(av):
                return T.force_quad(profile, {**vals, S.a: av}, dps)
        lo = mpmath.mpf(0)
        hi = mpmath.mpf("1e-3")
        for _ in range(200):
            try:
                v = Pf(hi)
            except (ValueError, ZeroDivisionError):
                v = mpmath.mpf("nan")
            if isinstance(v, mpmath.mpc) or not mpmath.isfinite(v):
                raise DomainError(f"no half-width found for load {load}: the force law is "
                                  f"undefined beyond a = {float(lo):.6g}")
            if v >= L:
                break
            lo, hi = hi, hi * 2
        else:
            raise DomainError(f"no half-width found for load {load}")
        root = mpmath.findroot(lambda av: Pf(av) - L, (lo, hi), solver="anderson")
        return +root


def profile_from_force(force_law, params=None, budget: float = DEFAULT_BUDGET,
                       verify_points: int = 5) -> Derivation:
    """Eq. (9): the profile f(x) whose contact has the force law ``force_law``
    (a SymPy expression in ``a``).  Returns a :class:`Derivation` whose
    ``expr`` is f(x) (closed form, verified) or the unevaluated Eq. (9).
    """
    if isinstance(force_law, str) or not isinstance(force_law, sp.Basic):
        raise ProfileError(f"the force law must be a SymPy expression in a, got {force_law!r}")
    t0 = time.perf_counter()
    free = force_law.free_symbols - {S.a, S.E_star}
    declared = set(params or ())
    for s in free:
        if s not in declared and not s.is_positive:
            raise ProfileError(f"force law {force_law} holds the unknown symbol {s}; declare it "
                               f"with params=[{s}] or make it positive=True")
    if S.a not in force_law.free_symbols:
        raise ProfileError(f"the force law {force_law} does not depend on a")
    psyms = tuple(sorted(free, key=lambda s: s.name))

    def sampler(rng):
        vals = {p: _rat(rng.uniform(0.5, 2.5)) for p in psyms}
        vals[S.E_star] = _rat(rng.uniform(0.5, 3))
        vals[S.a] = _rat(rng.uniform(0.05, 1.5))
        return vals

    def reference(vals, dps):
        fixed = {k: v for k, v in vals.items() if k != S.a}
        Pf = sp.lambdify(S.a, force_law.xreplace(fixed), "mpmath")
        return T.profile_quad(Pf, [], vals, dps)
    expr, conds, notes, name = try_strategies(ST.INVERSE_STRATEGIES, (force_law,), budget)
    fallback = T.profile_integral(force_law).subs(S.a, S.x)
    rec = None
    if expr is not None:
        rec = verify(expr, reference, sampler, conds, n_points=verify_points,
                     reference_name="mpmath quadrature of Eq. (9)")
        if not rec.passed:
            notes = list(notes) + [f"closed form FAILED verification ({rec.min_digits:.1f} digits)"]
            expr = None
    # the profile is reported in x
    sub = {S.a: S.x}
    if expr is None:
        return Derivation("profile", fallback, False, "numeric fallback (no closed form found)",
                          (), rec, time.perf_counter() - t0, tuple(notes),
                          lambda vals, dps: reference({**vals, S.a: vals[S.x]}, dps),
                          (S.x, S.E_star) + psyms)
    return Derivation("profile", expr.xreplace(sub), True, f"{name}: {'; '.join(notes)}",
                      tuple(c.xreplace(sub) for c in conds), rec, time.perf_counter() - t0, (),
                      lambda vals, dps: reference({**vals, S.a: vals[S.x]}, dps),
                      (S.x, S.E_star) + psyms)
