"""Linear viscoelastic materials: the input of the superposition *in time*,
as a profile is the input of the superposition in space.

A material is a small object: its plane-strain **reduced relaxation
modulus** E*(t) (what replaces E* of the elastic line contact), split into a
regular part and an instantaneous (Dirac) part,

    E*(t) = E_reg(t) + eta delta(t),

and its **creep compliance** J*(t), fixed by the convolution identity

    s E*_hat(s) . s J*_hat(s) = 1      (Laplace transforms in t),

derived here by SymPy (Laplace transform of E_reg, inversion of
1/(s^2 E*_hat) by its poles when it is rational, SymPy's inverse transform
otherwise, under the package's budget) or, where that fails, left as an
unevaluated ``InverseLaplaceTransform`` with numbers from mpmath's Talbot
inversion.  Nothing here knows a contact (:mod:`linecontact_sym.contacts.viscoelastic`
uses it); elastic is the material with E*(t) constant.

Which modulus (the convention)
------------------------------
Every parameter is one of E*(t), the plane-strain reduced modulus of a rigid
indenter on the viscoelastic half-plane (E* = E/(1 - nu^2) for an elastic
one, Popov Eq. 4).  With a constant Poisson ratio, E*(t) = E(t)/(1 - nu^2)
(the relaxation function scales); for an incompressible material
(nu = 1/2 at all times, the usual model of rubbers) E*(t) = 4 E(t)/3 = 4 G(t).
A material whose bulk modulus stays constant while G relaxes has a
time-dependent nu: then give E*(t) directly (``Material(expr)``), e.g. from
s E*_hat = 2 s G_hat / (1 - nu_hat), which this module does not build.

Constructors (each parameter a positive number or SymPy symbol):

* :func:`maxwell`  E*(t) = E0 exp(-t/tau)
* :func:`kelvin_voigt`  E*(t) = E + eta delta(t)
* :func:`standard_linear_solid`  E*(t) = E_inf + (E0 - E_inf) exp(-t/tau)
* :func:`prony`  E*(t) = E_inf + sum_i E_i exp(-t/tau_i)
* ``Material(expr, impulse=0)``  any relaxation expression in ``lcs.t``.
"""
from __future__ import annotations


import mpmath
import sympy as sp

from ..core import symbols as S
from ..core.budget import run_with_budget
from ..core.errors import BudgetExceeded, DomainError
from ..core.precision import workdps
from ..parsing import to_sympy, user_value

#: CPU seconds for the derivation of a creep function
CREEP_BUDGET = 10.0
_s = sp.Symbol("s", positive=True)   # the Laplace variable (a private one: never a user's s)


def _parameter(name, value, positive=False):
    """A material parameter: a number >= 0 (> 0 for a relaxation time,
    ``positive``: tau = 0 is no material, exp(-t/0)) or a SymPy symbol."""
    if value is None:
        raise DomainError(f"the material needs a value (number or SymPy symbol) for {name}")
    v = value if isinstance(value, sp.Basic) else user_value(value, name)
    if v.is_number and not (v.is_positive or (v.is_zero and not positive)):
        raise DomainError(f"the material parameter {name} must be {'> 0' if positive else '>= 0'}, got {value}")
    return v


class Material:
    """A linear viscoelastic material (see the module docstring).

    Parameters
    ----------
    relaxation : SymPy expression in ``lcs.t``
        The regular part E_reg(t) of the reduced relaxation modulus E*(t).
    impulse : number or symbol, default 0
        eta of an instantaneous part eta delta(t) (Kelvin-Voigt's dashpot).
    name : str
    """

    def __init__(self, relaxation, impulse=0, name: str = "material"):
        expr = to_sympy(relaxation, "the relaxation function")     # text by the whitelisted parser, never eval
        if expr.has(sp.DiracDelta):
            raise DomainError("give the Dirac part of E*(t) as impulse=eta, not inside the expression "
                              "(its integral from an endpoint is ambiguous in SymPy)")
        if expr.has(S.x, S.a, S.P, S.E_star):
            raise DomainError(f"the relaxation function {expr} may depend on t and material parameters only")
        self.relaxation = expr
        self.impulse = _parameter("impulse", impulse)
        self.name = name
        self._creep = None
        self._numeric = {}

    def __repr__(self):
        d = f" + {self.impulse}*delta(t)" if self.impulse != 0 else ""
        return f"{self.name}: E*(t) = {self.relaxation}{d}"

    @property
    def parameters(self):
        """The material's free symbols (its parameters), sorted by name."""
        return sorted((self.relaxation.free_symbols | self.impulse.free_symbols) - {S.t}, key=lambda s: s.name)

    # ------------------------------------------------------------ limits
    @property
    def E0(self):
        """E*(0+): the glassy (instantaneous) modulus; oo with a Dirac part."""
        if self.impulse != 0:
            return sp.oo
        return sp.limit(self.relaxation, S.t, 0, "+")

    @property
    def E_inf(self):
        """E*(oo): the rubbery (long-time) modulus (0 for a fluid, Maxwell)."""
        return sp.limit(self.relaxation, S.t, sp.oo)

    # ------------------------------------------------------------ Laplace
    @property
    def laplace(self):
        """E*_hat(s) = L[E_reg](s) + eta (None where SymPy finds no transform)."""
        L = sp.laplace_transform(self.relaxation, S.t, _s, noconds=True)
        if L.has(sp.LaplaceTransform):
            return None
        return L + self.impulse

    def creep(self, budget: float = CREEP_BUDGET):
        """J*(t), the plane-strain creep compliance: s^2 E*_hat(s) J*_hat(s) = 1,
        derived under ``budget`` CPU seconds; an unevaluated
        ``InverseLaplaceTransform`` where no closed form is found."""
        if self._creep is None:
            try:
                self._creep = run_with_budget(_derive_creep, self.relaxation, self.impulse, seconds=budget)
            except BudgetExceeded:
                self._creep = _unevaluated(self.relaxation, self.impulse)
        return self._creep

    @property
    def creep_closed(self) -> bool:
        return not self.creep().has(sp.InverseLaplaceTransform, sp.LaplaceTransform)

    # ------------------------------------------------------------ numbers
    def _fix(self, values):
        vals = {}
        by_name = {p.name: p for p in self.parameters}
        for p in self.parameters:
            if p.name not in values:
                raise DomainError(f"the material {self.name} needs a value for {p.name}")
            vals[p] = user_value(values[p.name], p.name)
        return vals, {k: v for k, v in values.items() if k not in by_name}

    def at(self, **values) -> "Material":
        """This material with its parameters replaced by numbers (unknown names are ignored)."""
        vals = {p: user_value(values[p.name], p.name) for p in self.parameters if p.name in values}
        new = Material(self.relaxation.xreplace(vals), self.impulse.xreplace(vals), self.name)
        if self._creep is not None:
            new._creep = self._creep.xreplace(vals)
        return new

    def numeric(self, **values) -> "NumericMaterial":
        """E_reg(t), eta, J*(t) as mpmath callables at the parameter ``values``."""
        vals, _ = self._fix(values)
        key = tuple(sorted((k.name, v) for k, v in vals.items()))
        if key not in self._numeric:
            self._numeric[key] = NumericMaterial(self, vals)
        return self._numeric[key]


def _unevaluated(relaxation, impulse):
    L = sp.laplace_transform(relaxation, S.t, _s, noconds=True) + impulse
    return sp.InverseLaplaceTransform(1 / (_s**2 * L), _s, S.t, None)


def _derive_creep(relaxation, impulse):
    """J*(t) from s^2 E*_hat J*_hat = 1: a rational J*_hat is inverted by its
    poles (residues of exp(s t) J*_hat: CRootOf where a numeric denominator has
    no radical roots), anything else by SymPy's inverse transform."""
    L = sp.laplace_transform(relaxation, S.t, _s, noconds=True)
    if L.has(sp.LaplaceTransform):
        return sp.InverseLaplaceTransform(1 / (_s**2 * (L + impulse)), _s, S.t, None)
    Jh = sp.cancel(sp.together(1 / (_s**2 * (L + impulse))))
    num, den = sp.fraction(Jh)
    if num.is_polynomial(_s) and den.is_polynomial(_s):
        J = _residues(sp.Poly(num, _s), sp.Poly(den, _s))
        if J is not None:
            return sp.simplify(J) if J.free_symbols - {S.t} else J
    J = sp.inverse_laplace_transform(Jh, _s, S.t)
    return J.subs(sp.Heaviside(S.t), 1)


def _residues(num, den):
    """sum of the residues of exp(s t) num/den (None where the poles are not found)."""
    m = 0
    while den.eval(0) == 0:
        den = sp.Poly(sp.cancel(den.as_expr() / _s), _s)
        m += 1
    total = sp.S.Zero
    if m:
        g = sp.exp(_s * S.t) * num.as_expr() / den.as_expr()
        total += sp.diff(g, _s, m - 1).subs(_s, 0) / sp.factorial(m - 1)
    if den.degree() == 0:
        return sp.expand(total)
    numeric = not (den.free_symbols - {_s})
    if numeric:
        poles = [sp.CRootOf(den, k) for k in range(den.degree())]
        if len(set(poles)) < len(poles):
            return None
        roots = {}
        for p in poles:
            rad = p.expand(func=True) if den.degree() <= 2 else p
            roots[rad] = 1
    else:
        roots = sp.roots(den, _s)
        if sum(roots.values()) != den.degree() or any(k > 1 for k in roots.values()):
            return None
    dden = den.diff(_s)
    for p in roots:
        total += num.as_expr().subs(_s, p) / (p**m * dden.as_expr().subs(_s, p)) * sp.exp(p * S.t)
    return total


class NumericMaterial:
    """A material at numbers: ``E(t)`` the regular relaxation modulus,
    ``eta`` the Dirac weight, ``J(t)`` the creep compliance (mpmath, at the
    working precision); ``E0``, ``E_inf`` as mpf (E0 inf with a Dirac part)."""

    def __init__(self, material, vals):
        self.material = material
        rel = material.relaxation.xreplace(vals)
        self.relaxation = rel
        self._E = sp.lambdify(S.t, rel, "mpmath")
        self.eta = material.impulse.xreplace(vals)
        self.E_inf_exact = sp.limit(rel, S.t, sp.oo)
        self.E0_exact = sp.limit(rel, S.t, 0, "+") if self.eta == 0 else sp.oo
        for name, v in (("E(0+)", self.E0_exact), ("E(oo)", self.E_inf_exact)):
            if v.is_number and v.is_negative:
                raise DomainError(f"the relaxation modulus {material} has {name} = {v} < 0")
        if self.E_inf_exact.has(sp.oo, -sp.oo, sp.zoo, sp.nan) or self.E_inf_exact.has(sp.AccumBounds):
            raise DomainError(f"the relaxation modulus {material} has no finite limit E(oo) = {self.E_inf_exact}: "
                              "a relaxation modulus decreases to a finite E(oo) >= 0")
        self._vals = vals
        self._J = None
        self._check_relaxing()

    def _check_relaxing(self):
        """E_reg(t) >= 0 and nonincreasing on a log grid 1e-8 .. 1e8 (a passive
        material relaxes; a modulus that grows or turns negative is no
        relaxation modulus: the superposition would give a number, a wrong one)."""
        with workdps(15):
            grid = [mpmath.mpf(10)**k for k in range(-8, 9)]
            vals = [self.E(tv) for tv in grid]          # E raises where a value is negative
            for k in range(len(grid) - 1):
                if vals[k + 1] > vals[k] * (1 + mpmath.mpf(10)**-10) + mpmath.mpf(10)**-300:
                    raise DomainError(f"the relaxation modulus {self.material} grows from t = {mpmath.nstr(grid[k], 3)} "
                                      f"to {mpmath.nstr(grid[k + 1], 3)} ({mpmath.nstr(vals[k], 8)} -> "
                                      f"{mpmath.nstr(vals[k + 1], 8)}): a relaxation modulus is nonincreasing in t")

    def _creep(self):
        """J*(t) at the numbers, as an mpmath callable (derived on first use: only creep needs it)."""
        J = self.material.creep().xreplace(self._vals)
        if J.has(sp.InverseLaplaceTransform):
            Jh = sp.lambdify(_s, J.args[0], "mpmath")
            self.creep_closed = False
            self._J = lambda tv: mpmath.invertlaplace(Jh, tv, method="talbot")
        else:
            self.creep_closed = True
            roots = {r: sp.Float(sp.N(r, 60), 60) for r in J.atoms(sp.CRootOf)}   # exact roots, as 60-digit numbers
            self._J = sp.lambdify(S.t, J.xreplace(roots), "mpmath")
        self.creep_expr = J

    def E(self, tv):
        """E_reg(t) (0 for t < 0)."""
        if tv < 0:
            return mpmath.mpf(0)
        v = mpmath.re(self._E(tv)) if tv > 0 else mpmath.mpf(sp.N(self.E0_exact if self.eta == 0
                                                                     else sp.limit(self.relaxation, S.t, 0, "+"),
                                                                     mpmath.mp.dps + 5))
        if v < 0 or not mpmath.isfinite(v):
            raise DomainError(f"the relaxation modulus {self.material} is {mpmath.nstr(v, 8)} at t = {mpmath.nstr(tv, 8)}: "
                              "a relaxation modulus is finite and >= 0 at every time")
        return v

    def J(self, tv):
        """J*(t) (0 for t < 0)."""
        if tv <= 0:
            return mpmath.mpf(0) if tv < 0 or self.eta != 0 else 1 / mpmath.mpf(sp.N(self.E0_exact, mpmath.mp.dps + 5))
        if self._J is None:
            self._creep()
        return mpmath.re(self._J(tv))

    @property
    def E0(self):
        return mpmath.inf if self.E0_exact == sp.oo else mpmath.mpf(sp.N(self.E0_exact, mpmath.mp.dps + 5))

    @property
    def E_inf(self):
        return mpmath.mpf(sp.N(self.E_inf_exact, mpmath.mp.dps + 5))


# ---------------------------------------------------------------- the catalogue
def maxwell(E0=None, tau=None) -> Material:
    """Maxwell fluid: E*(t) = E0 exp(-t/tau) (a spring E0 in series with a dashpot E0 tau)."""
    E0, tau = _parameter("E0", E0), _parameter("tau", tau, positive=True)
    return Material(E0 * sp.exp(-S.t / tau), 0, "Maxwell")


def kelvin_voigt(E=None, eta=None) -> Material:
    """Kelvin-Voigt solid: E*(t) = E + eta delta(t) (a spring E beside a dashpot eta);
    the Dirac part is carried as ``impulse`` (see :class:`Material`)."""
    return Material(_parameter("E", E) + 0 * S.t, _parameter("eta", eta), "Kelvin-Voigt")


def standard_linear_solid(E0=None, E_inf=None, tau=None) -> Material:
    """Standard linear solid (Zener): E*(t) = E_inf + (E0 - E_inf) exp(-t/tau), E0 >= E_inf."""
    E0, Ei, tau = _parameter("E0", E0), _parameter("E_inf", E_inf), _parameter("tau", tau, positive=True)
    if (E0 - Ei).is_negative:
        raise DomainError(f"the standard linear solid needs E0 >= E_inf, got E0 = {E0}, E_inf = {Ei}")
    return Material(Ei + (E0 - Ei) * sp.exp(-S.t / tau), 0, "standard linear solid")


def prony(E_inf=None, terms=()) -> Material:
    """Generalised Maxwell (Prony series): E*(t) = E_inf + sum_i E_i exp(-t/tau_i)."""
    try:
        terms = list(terms) if not isinstance(terms, (str, bytes)) else None
    except TypeError:
        terms = None
    if not terms or not all(
            isinstance(tm, (tuple, list)) and len(tm) == 2 for tm in terms):
        raise DomainError(f"a Prony series needs terms=[(E_1, tau_1), ...] (pairs), got {terms!r}")
    expr = _parameter("E_inf", E_inf)
    for k, (Ek, tk) in enumerate(terms, 1):
        expr += _parameter(f"E_{k}", Ek) * sp.exp(-S.t / _parameter(f"tau_{k}", tk, positive=True))
    return Material(expr, 0, f"Prony series ({len(terms)} terms)")


__all__ = ["Material", "NumericMaterial", "maxwell", "kelvin_voigt", "standard_linear_solid", "prony",
           "CREEP_BUDGET"]
