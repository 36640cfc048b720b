"""Hypergeometric term decomposition and termwise Beta-kernel integration.

This is the engine's main strategy.  An integrand factor g(x) (a profile's
slope, a force law, ...) is split into terms

    coef * x**mu * sum_k  prod (u_i)_k / prod (l_j)_k * (w x**q)**k / k!

(a pure power when there is no series).  Every kernel of the method is of the
Beta type,

    int_0^a x**(s+rho) (a**2 - x**2)**sigma dx
        = a**(s+rho+2 sigma+1) Gamma((s+rho+1)/2) Gamma(sigma+1)
          / (2 Gamma((s+rho+1)/2 + sigma + 1)),          Re(s+rho+1) > 0,

so the integral of each term is again a hypergeometric series whose
Pochhammer parameters follow from Gauss' multiplication formula.  SymPy's
``hyperexpand`` then turns the ``hyper`` into elementary, elliptic (K, E),
Bessel, Struve ... functions where such a form exists.  For a power law this
is Popov's Z_n (Eq. 17); for the exact cylinder it is the K - E law (Eq. 26).

Recognised series factors (argument c*x**q, one per term): powers of a
binomial (A + B x**q)**beta, exp, sin, cos, sinh, cosh, besselj, besseli,
log(1 + c x**q), atan, asin, elliptic_k, elliptic_e and hyper itself.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from ..core.conversion import to_basic
from ..core.errors import DivergentIntegralError


@dataclass(frozen=True)
class SeriesTerm:
    """coef * x**mu * pFq(upper; lower; w x**q) with the k! inside pFq;
    ``w == 0`` marks a pure power."""

    coef: sp.Expr
    mu: sp.Expr
    upper: tuple = ()
    lower: tuple = ()
    w: sp.Expr = sp.S.Zero
    q: sp.Expr = sp.S.One

    @property
    def is_power(self) -> bool:
        return self.w == 0


class NotDecomposable(Exception):
    """The expression is not a sum of (power x hypergeometric) terms."""


def _monomial(arg, x):
    """arg = c * x**q  ->  (c, q) with q > 0, else raise."""
    c, rest = arg.as_independent(x, as_Add=False)
    if rest == x:
        return c, sp.S.One
    if rest.is_Pow and rest.base == x and not rest.exp.has(x):
        q = rest.exp
        if q.is_positive:
            return c, q
    raise NotDecomposable(f"argument {arg} is not c*x**q")


def _series_factor(fac, x):
    """A factor holding x -> (prefactor, upper, lower, w, q) with
    fac = prefactor * pFq(upper; lower; w x**q)."""
    half = sp.S.Half
    if fac.is_Pow and not fac.exp.has(x):
        base, beta = fac.base, fac.exp
        terms = sp.Add.make_args(sp.expand(base))
        const = [t for t in terms if not t.has(x)]
        var = [t for t in terms if t.has(x)]
        if len(var) == 1 and const:
            A = sp.Add(*const)
            B, q = _monomial(var[0], x)
            if A.is_positive:
                return A**beta, (-beta,), (), -B / A, q
            if A.is_negative and (B.is_positive):
                raise NotDecomposable(f"{fac} is not real near x = 0")
        raise NotDecomposable(f"{fac}: base is not A + B*x**q with A > 0")
    if isinstance(fac, sp.exp):
        c, q = _monomial(fac.args[0], x)
        return sp.S.One, (), (), c, q
    if isinstance(fac, (sp.cos, sp.cosh, sp.sin, sp.sinh)):
        c, q = _monomial(fac.args[0], x)
        sign = -1 if isinstance(fac, (sp.cos, sp.sin)) else 1
        if isinstance(fac, (sp.cos, sp.cosh)):
            return sp.S.One, (), (half,), sign * c**2 / 4, 2 * q
        return c * x**q, (), (sp.Rational(3, 2),), sign * c**2 / 4, 2 * q
    if isinstance(fac, (sp.besselj, sp.besseli)):
        nu, arg = fac.args
        if nu.has(x):
            raise NotDecomposable(f"{fac}: order depends on x")
        c, q = _monomial(arg, x)
        sign = -1 if isinstance(fac, sp.besselj) else 1
        return (c * x**q / 2)**nu / sp.gamma(nu + 1), (), (nu + 1,), sign * c**2 / 4, 2 * q
    if isinstance(fac, sp.log):
        arg = sp.expand(fac.args[0])
        rest = arg - 1
        c, q = _monomial(rest, x)
        return c * x**q, (1, 1), (2,), -c, q
    if isinstance(fac, sp.atan):
        c, q = _monomial(fac.args[0], x)
        return c * x**q, (half, 1), (sp.Rational(3, 2),), -c**2, 2 * q
    if isinstance(fac, sp.asin):
        c, q = _monomial(fac.args[0], x)
        return c * x**q, (half, half), (sp.Rational(3, 2),), c**2, 2 * q
    if isinstance(fac, sp.elliptic_k):
        c, q = _monomial(fac.args[0], x)
        return sp.pi / 2, (half, half), (1,), c, q
    if isinstance(fac, sp.elliptic_e) and len(fac.args) == 1:
        c, q = _monomial(fac.args[0], x)
        return sp.pi / 2, (-half, half), (1,), c, q
    if isinstance(fac, sp.hyper):
        c, q = _monomial(fac.argument, x)
        return sp.S.One, tuple(fac.ap), tuple(fac.bq), c, q
    raise NotDecomposable(f"no series known for {fac}")


def decompose(g: sp.Expr, x: sp.Symbol) -> list[SeriesTerm]:
    """Split g(x) into :class:`SeriesTerm` s (raises :class:`NotDecomposable`)."""
    g = sp.expand_mul(sp.powsimp(g, force=False))
    out = []
    for term in sp.Add.make_args(g):
        coef, dep = term.as_independent(x, as_Add=False)
        if dep == 1:
            out.append(SeriesTerm(coef, sp.S.Zero))
            continue
        mu = sp.S.Zero
        series = None
        for fac in sp.Mul.make_args(dep):
            if fac == x:
                mu += 1
            elif fac.is_Pow and fac.base == x and not fac.exp.has(x):
                mu += fac.exp
            else:
                if series is not None:
                    raise NotDecomposable(f"{term}: more than one non-power factor")
                series = _series_factor(fac, x)
        if series is None:
            out.append(SeriesTerm(coef, mu))
            continue
        pre, up, lo, w, q = series
        pc, pdep = sp.expand_power_base(pre, force=False).as_independent(x, as_Add=False)
        if pdep != 1:
            base_exp = sp.powsimp(pdep).as_base_exp()
            if base_exp[0] != x:
                raise NotDecomposable(f"{term}: prefactor {pre} is not a power of x")
            mu += base_exp[1]
        out.append(SeriesTerm(coef * pc, mu, tuple(map(to_basic, up)), tuple(map(to_basic, lo)), to_basic(w), to_basic(q)))
    return out


def _poch_split(p, r, v):
    """(p)_{v j + r} = (p)_r * v**(v j) * prod_l ((p + r + l)/v)_j : returns
    the constant (p)_r and the list of new parameters."""
    return sp.RisingFactorial(p, r), [(p + r + l) / v for l in range(v)]


def beta_kernel_sum(term: SeriesTerm, rho, sigma, a, conditions: list):
    """int_0^a x**rho (a**2 - x**2)**sigma * term(x) dx as a finite sum of ``hyper``.

    Appends convergence conditions (symbolic, where not decidable now) to
    ``conditions``; raises :class:`DivergentIntegralError` where the integral
    diverges for every parameter value.
    """
    sigma = to_basic(sigma)
    if (sigma + 1).is_positive is False:
        raise DivergentIntegralError(f"kernel exponent sigma = {sigma} <= -1")
    alpha = (term.mu + rho + 1) / 2
    pos = alpha.is_positive
    if pos is False:
        raise DivergentIntegralError(
            f"the integrand behaves like x**({term.mu + rho}) at x = 0: the integral diverges")
    if pos is None:
        conditions.append(sp.StrictGreaterThan(alpha, 0))
    beta = alpha + sigma + 1
    pre = term.coef * sp.gamma(sigma + 1) / 2 * a**(term.mu + rho + 2 * sigma + 1)
    if term.is_power:
        return pre * sp.gamma(alpha) / sp.gamma(beta)
    s = term.q / 2
    if not s.is_Rational:
        raise DivergentIntegralError  # not reached for recognised factors
    u, v = int(s.p), int(s.q)
    z = term.w * a**term.q
    total = sp.S.Zero
    for r in range(v):
        const = z**r * sp.gamma(alpha + s * r) / sp.gamma(beta + s * r)
        ups, los = [], []
        for p in term.upper:
            c0, new = _poch_split(p, r, v)
            const *= c0
            ups += new
        for p in term.lower + (sp.S.One,):
            c0, new = _poch_split(p, r, v)
            const /= c0
            los += new
        ups += [(alpha + s * r + l) / u for l in range(u)]
        los += [(beta + s * r + l) / u for l in range(u)]
        ups.append(sp.S.One)  # j! of the new series
        Z = z**v * sp.Integer(v)**(v * (len(term.upper) - len(term.lower) - 1))
        ups, los = _cancel(ups, los)
        if len(ups) > len(los) + 1 and not any(_nonpos_int(p) for p in ups):
            raise DivergentIntegralError("termwise series diverges (p > q + 1)")
        if len(ups) == len(los) + 1:
            conditions.append(sp.StrictLessThan(sp.Abs(Z), 1))
        total += const * sp.hyper(ups, los, Z)
    return pre * total


def _nonpos_int(p):
    return p.is_integer and p.is_nonpositive


def _cancel(ups, los):
    ups, los = list(map(sp.S, ups)), list(map(sp.S, los))
    for p in list(ups):
        for i, q in enumerate(los):
            if sp.simplify(p - q) == 0:
                ups.remove(p)
                los.pop(i)
                break
    return ups, los
