"""Legendre reduction: algebraic integrals against 1/sqrt(a^2 - t^2) in closed form.

:func:`reduce_integral` evaluates

    I = int_lo^hi h(t) dt / sqrt(a^2 - t^2),       0 <= lo < hi <= a,

for an *algebraic* h: a rational function of t and of at most one kind of
square root sqrt(A - B t^2) (A > 0; e.g. the circle sqrt(R^2 - t^2), an
ellipse).  With t = a sin(phi), S = sin(phi), C = cos(phi) and
Q = sqrt(1 - m S^2), m = B a^2 / A, the integrand becomes
A0(S) + A1(S)/Q dphi with A0, A1 rational (Q^2 = 1 - m S^2 removes every
other power of Q).  Each part is split into its even and odd parts in S:

* even, u = S^2, partial fractions in u: u^j and 1/(1 - n u);
    - without Q: int S^(2j) dphi (the Wallis recurrence, phi = asin(t/a) and
      powers of S, C) and int dphi/(1 - n u), which is
      atan(sqrt(1 - n) tan(phi))/sqrt(1 - n) for n < 1 and, for n > 1,
      atanh(y)/p below the pole (y = p tan(phi) < 1, p = sqrt(n - 1)) and
      atanh(1/y)/p above it: their difference is the Cauchy principal value;
    - with 1/Q: J_0 = F(phi|m), J_1 = (F - E)/m and J_(j+1) from
      d/dphi[S^(2j-1) C Q] = D_j(u)/Q (D_j a polynomial of degree j + 1,
      computed here), and int dphi/((1 - n u) Q) = Pi(n; phi|m); for n > 1
      over the complete interval the principal value
      Pi(n|m) = K(m) - Pi(m/n|m) (DLMF 19.6.5).
* odd, w = C (u = 1 - w^2): a rational function of w^2, partial fractions:
  powers of w and 1/(alpha + beta w^2), whose primitives are atan or (on
  either side of a pole) atanh forms.  (Odd parts with 1/Q are not reduced:
  :class:`NotReducible`.)

Elliptic integrals are SymPy's, in the *parameter* convention m = k^2:
``elliptic_f(phi, m)``, ``elliptic_e(phi, m)``, ``elliptic_pi(n, phi, m)``
(incomplete) and ``elliptic_k(m)``, ``elliptic_e(m)``, ``elliptic_pi(n, m)``
(complete, phi = pi/2).

Which primitive is the right one (sign of 1 - n, side of a pole, sign of
alpha, beta) is decided numerically at ``sample``, a point of the region the
caller works in: within a region of the contact problem these signs do not
change.

>>> import sympy as sp
>>> t, a, x = sp.symbols("t a x", positive=True)
>>> at = {a: 2, x: 1}
>>> reduce_integral(t**2, t, a, 0, a, at)                       # int t^2/sqrt(a^2 - t^2)
pi*a**2/4
>>> R = sp.Symbol("R", positive=True)
>>> reduce_integral(t**2 / sp.sqrt(R**2 - t**2), t, a, 0, a, {a: 1, R: 2})
R*(-elliptic_e(a**2/R**2) + elliptic_k(a**2/R**2))
"""
from __future__ import annotations

import sympy as sp

__all__ = ["reduce_integral", "NotReducible"]


class NotReducible(Exception):
    """The integrand is outside the class this reduction handles."""


_S = sp.Dummy("S", positive=True)   # sin(phi)
_Q = sp.Dummy("Q", positive=True)   # sqrt(1 - m sin(phi)^2)
_U = sp.Dummy("u", positive=True)   # sin(phi)^2
_W = sp.Dummy("w", positive=True)   # cos(phi)


def _root(e, sample):
    """sqrt(e) of a positive e, brought over one denominator and factored, each
    factor made positive at the sample point (sqrt(a**2/x**2 - 1) ->
    sqrt((a - x)*(a + x))/x): the small differences are then formed exactly."""
    num, den = sp.fraction(sp.factor(sp.together(e)))

    def positive(p):
        out = []
        for f in sp.Mul.make_args(p):
            base, ex = f.as_base_exp()
            if base.is_Add and _num(base, sample) < 0:
                f = sp.Pow(sp.Add(*[-u for u in base.args]), ex)
            elif f.is_Number:
                f = abs(f)
            out.append(f)
        return sp.Mul(*out)
    return sp.sqrt(positive(num)) / sp.sqrt(positive(den))


def _num(e, sample) -> float:
    v = complex(sp.N(sp.sympify(e, strict=True).xreplace(sample), 30))
    if abs(v.imag) > 1e-20 * max(1.0, abs(v.real)):
        raise NotReducible(f"{e} is not real in the region")
    return v.real


# ------------------------------------------------------------------ radicals
def _radicals(hS, sample):
    """Replace every sqrt(A - B S^2)^k by A^(k/2) Q^k; returns (expr, m, radicands)
    with m = B/A (None if there is no radical) and the (A, B) found."""
    ms, reps, rads = [], {}, []
    for p in hS.atoms(sp.Pow):
        if not p.base.has(_S):
            continue
        if p.exp.is_Integer:
            continue
        if not (p.exp.is_Rational and p.exp.q == 2):
            raise NotReducible(f"{p}: not a square root")
        try:
            poly = sp.Poly(sp.expand(p.base), _S)
        except sp.PolynomialError:
            raise NotReducible(f"{p}: radicand not polynomial")
        if poly.degree() != 2 or poly.coeff_monomial(_S) != 0:
            raise NotReducible(f"{p}: radicand is not A - B t^2")
        A = poly.coeff_monomial(1)
        B = -poly.coeff_monomial(_S**2)
        if _num(A, sample) <= 0:
            raise NotReducible(f"{p}: A <= 0")
        m = sp.cancel(B / A)
        for m0 in ms:
            if sp.cancel(m0 - m) == 0:
                m = m0
                break
        else:
            ms.append(m)
        reps[p] = A**p.exp * _Q**(2 * p.exp)
        rads.append((A, B))
    if len(ms) > 1:
        raise NotReducible(f"more than one kind of square root ({ms})")
    if any(f.has(_S) for f in hS.atoms(sp.Function)):
        raise NotReducible("transcendental integrand")
    return hS.xreplace(reps), (ms[0] if ms else None), rads


def _split_q(expr, m):
    """expr rational in S and Q -> (A0, A1) with expr = A0 + A1 Q, Q^2 = 1 - m S^2."""
    if m is None or not expr.has(_Q):
        return sp.cancel(expr), sp.S.Zero
    q2 = 1 - m * _S**2

    def lin(e):
        poly = sp.Poly(sp.expand(e), _Q)
        r0 = r1 = sp.S.Zero
        for (k,), c in poly.terms():
            if k % 2:
                r1 += c * q2**(k // 2)
            else:
                r0 += c * q2**(k // 2)
        return r0, r1
    num, den = sp.fraction(sp.together(expr))
    n0, n1 = lin(num)
    d0, d1 = lin(den)
    if d1 != 0:   # times the conjugate d0 - d1 Q
        n0, n1 = n0 * d0 - n1 * d1 * q2, n1 * d0 - n0 * d1
        d0 = d0**2 - d1**2 * q2
    return sp.cancel(n0 / d0), sp.cancel(n1 / d0)


def _parity(e):
    """(even part, odd part / S) of a rational function of S."""
    neg = e.xreplace({_S: -_S})
    return sp.cancel((e + neg) / 2), sp.cancel((e - neg) / (2 * _S))


def _in_u(e):
    out = sp.cancel(e.xreplace({_S: sp.sqrt(_U)}))
    if any(p.base == _U and not p.exp.is_Integer for p in out.atoms(sp.Pow)):
        raise NotReducible("not even in sin(phi)")
    return out


def _partial_fractions(e, var):
    """e rational in var -> [(c, 'pow', j)] and [(c, 'pole', (alpha, beta))] for
    c var**j and c/(alpha + beta var); other forms raise NotReducible."""
    out = []
    for term in sp.Add.make_args(sp.apart(sp.cancel(e), var)):
        c, dep = term.as_independent(var, as_Add=False)
        if dep == 1:
            out.append((c, "pow", 0))
            continue
        if dep == var:
            out.append((c, "pow", 1))
            continue
        base, ex = dep.as_base_exp()
        if base == var and ex.is_Integer and ex > 0:
            out.append((c, "pow", int(ex)))
            continue
        if ex == -1:
            try:
                poly = sp.Poly(base, var)
            except sp.PolynomialError:
                raise NotReducible(f"term {term}")
            if poly.degree() == 1:
                out.append((c, "pole", (poly.coeff_monomial(1), poly.coeff_monomial(var))))
                continue
        raise NotReducible(f"partial fraction {term} is not reduced here")
    return out


# ------------------------------------------------------------------ end points
class _End:
    """An end point t of the interval: sin, cos, phi, Q there, and whether it
    is the lower (0) or the upper (a) end of the complete interval."""

    def __init__(self, t_e, a, m, sample):
        self.t = t_e
        self.top = sp.simplify(t_e - a) == 0
        self.zero = t_e == 0
        self.m = m
        self.sample = sample
        if self.top:
            self.S, self.C, self.phi = sp.S.One, sp.S.Zero, sp.pi / 2
        elif self.zero:
            self.S, self.C, self.phi = sp.S.Zero, sp.S.One, sp.S.Zero
        else:
            self.S, self.C, self.phi = t_e / a, sp.sqrt(a - t_e) * sp.sqrt(a + t_e) / a, sp.asin(t_e / a)
        self.Q = sp.sqrt(1 - m * self.S**2) if m is not None else sp.S.One
        self.s2 = _num(self.S**2, sample)

    def F(self):
        return sp.elliptic_k(self.m) if self.top else (0 if self.zero else sp.elliptic_f(self.phi, self.m))

    def E(self):
        return sp.elliptic_e(self.m) if self.top else (0 if self.zero else sp.elliptic_e(self.phi, self.m))


def _wallis(end, j, memo):
    """int_0^phi S^(2j) dphi."""
    key = ("W", j)
    if key not in memo:
        memo[key] = end.phi if j == 0 else \
            ((2 * j - 1) * _wallis(end, j - 1, memo) - end.S**(2 * j - 1) * end.C) / (2 * j)
    return memo[key]


def _legendre_j(end, j, memo):
    """int_0^phi S^(2j)/Q dphi: F, (F - E)/m, then the recurrence of
    d/dphi [S^(2i-1) C Q] = D_i(u)/Q."""
    key = ("J", j)
    if key in memo:
        return memo[key]
    m = end.m
    if j == 0:
        val = end.F()
    elif j == 1:
        val = (end.F() - end.E()) / m
    else:
        i = j - 1
        D = sp.Poly(sp.expand((2 * i - 1) * _U**(i - 1) * (1 - _U) * (1 - m * _U)
                              - _U**i * (1 - m * _U) - m * _U**i * (1 - _U)), _U)
        boundary = end.S**(2 * i - 1) * end.C * end.Q
        lower = sum(D.coeff_monomial(_U**k) * _legendre_j(end, k, memo) for k in range(j))
        val = (boundary - lower) / D.coeff_monomial(_U**j)
    memo[key] = val
    return val


def _pole_plain(end, n, sample):
    """int_0^phi dphi/(1 - n S^2) (Cauchy principal value across a pole)."""
    nv = _num(n, sample)
    if nv < 1:
        r = _root(1 - n, sample)
        if end.top:
            return sp.pi / (2 * r)
        return sp.atan(r * end.S / end.C) / r
    p = _root(n - 1, sample)
    if nv * end.s2 < 1:      # below the pole: y = p tan(phi) < 1
        return sp.atanh(p * end.S / end.C) / p if not end.zero else sp.S.Zero
    return sp.atanh(end.C / (p * end.S)) / p


def _pole_elliptic(lo, hi, n, sample):
    """int_lo^hi dphi/((1 - n S^2) Q) (principal value for n > 1 on the complete interval)."""
    nv = _num(n, sample)
    m = lo.m

    def inc(end):
        if end.zero:
            return sp.S.Zero
        return sp.elliptic_pi(n, m) if end.top else sp.elliptic_pi(n, end.phi, m)
    if nv < 1 or (nv * hi.s2 < 1):
        return inc(hi) - inc(lo)
    if lo.zero and hi.top:
        return sp.elliptic_k(m) - sp.elliptic_pi(sp.cancel(m / n), m)
    raise NotReducible("principal value of an incomplete Pi across its pole")


def _odd_primitive(c, kind, arg, w, sample):
    """Primitive in w of c w^(2j) or c/(alpha + beta w^2), evaluated at w."""
    if kind == "pow":
        if arg % 2:
            raise NotReducible("odd power of cos(phi)")
        return c * w**(arg + 1) / (arg + 1)
    alpha, beta = arg
    al, be = _num(alpha, sample), _num(beta, sample)
    if al * be > 0:
        if al < 0:
            alpha, beta, c = -alpha, -beta, -c
        return c * sp.atan(_root(beta / alpha, sample) * w) / _root(alpha * beta, sample)
    if al < 0:
        alpha, beta, c = -alpha, -beta, -c
    k = _root(-beta / alpha, sample)
    z = k * w
    if _num(z**2, sample) < 1:
        return c * sp.atanh(z) / (alpha * k)
    return c * sp.atanh(1 / z) / (alpha * k)


# ------------------------------------------------------------------ main
def reduce_integral(h, t, a, lo, hi, sample, conditions=None):
    """int_lo^hi h(t)/sqrt(a^2 - t^2) dt in closed form (see the module
    docstring); ``sample`` is a point (Symbol -> number) of the region in
    which the result is to hold.  Raises :class:`NotReducible` outside the
    class of integrands handled.  A list ``conditions`` receives the
    relations under which the result is real (each radicand A - B t^2 > 0
    up to t = hi: a < R for the circle)."""
    hS = sp.sympify(h, strict=True).xreplace({t: a * _S})
    hS, m, rads = _radicals(hS, sample)
    if conditions is not None:
        s_hi = sp.sympify(hi, strict=True) / a
        for A, B in rads:
            lhs = B * s_hi**2
            c = sp.Lt(sp.sqrt(lhs), sp.sqrt(A)) if lhs.is_positive and A.is_positive \
                else sp.Gt(sp.factor(A - lhs), 0)
            if c not in conditions and c is not sp.true:
                conditions.append(c)
    A0, A1 = _split_q(hS, m)
    parts = [(A0, False)]
    if A1 != 0:
        parts.append((sp.cancel(A1 * (1 - m * _S**2)), True))
    ends = (_End(lo, a, m, sample), _End(hi, a, m, sample))
    memo = ({}, {})
    total = sp.S.Zero
    for part, with_q in parts:
        if part == 0:
            continue
        even, odd = _parity(part)
        if even != 0:
            for c, kind, arg in _partial_fractions(_in_u(even), _U):
                if kind == "pow":
                    fn = _legendre_j if with_q else _wallis
                    total += c * (fn(ends[1], arg, memo[1]) - fn(ends[0], arg, memo[0]))
                    continue
                alpha, beta = arg
                n = sp.cancel(-beta / alpha)
                if with_q:
                    total += c / alpha * _pole_elliptic(ends[0], ends[1], n, sample)
                else:
                    total += c / alpha * (_pole_plain(ends[1], n, sample) - _pole_plain(ends[0], n, sample))
        if odd != 0:
            if with_q:
                raise NotReducible("odd part with 1/sqrt(1 - m sin^2)")
            ow = sp.cancel(_in_u(odd).xreplace({_U: 1 - _W**2}))
            for c, kind, arg in _partial_fractions_w(ow):
                # int S o(S^2) dphi = -int o(1 - w^2) dw, w = cos(phi)
                total -= (_odd_primitive(c, kind, arg, ends[1].C, sample)
                          - _odd_primitive(c, kind, arg, ends[0].C, sample))
    return total


def _partial_fractions_w(e):
    """Partial fractions of an even rational function of w over w^2."""
    v = sp.Dummy("v", positive=True)
    ev = sp.cancel(e.xreplace({_W: sp.sqrt(v)}))
    out = []
    for c, kind, arg in _partial_fractions(ev, v):
        out.append((c, "pow", 2 * arg) if kind == "pow" else (c, "pole", arg))
    return out
