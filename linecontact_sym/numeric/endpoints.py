"""The end-point transforms of the reference integrator: a piece whose
integrand has an integrable singularity at an end point that ball
arithmetic cannot bound, made into integrals that Arb encloses
(:func:`singular_piece`, which :func:`~linecontact_sym.numeric.reference.integrate`
calls for a piece it could not enclose as it stands).

A power end (:func:`substitute_end`)
    One substitution t = e + d u^q, u in [0, 1], with the power q chosen
    from the end's exponent: the powers (t - e)^beta of the factors that
    vanish at e decide it (q = 2 for beta >= -1/2: a 1/sqrt or a sqrt-type
    branch point; the integer q >= 4/(1 + beta) below, -1 < beta < -1/2);
    the radicands are factored so that the u^q they vanish with leaves the
    root and cancels the Jacobian q d u^(q-1).  The integrator's half
    pieces and the Flamant routine's contact edge
    (:mod:`~linecontact_sym.numeric.flamant`) both use it.
A logarithmic end (:func:`singular_piece`'s second way)
    The logarithms are split symbolically as m ln u + ln of a quotient
    finite at u = 0, the powers of ln u integrated exactly and the rest by
    Arb (u = v^8 next to 0).

With parameters (``values``), the symbolic forms are made once per
integrand and end (kept in :data:`_FORMS`) and bound to each point's
numbers.
"""
from __future__ import annotations

import math

import flint
import sympy as sp

from ..core.conversion import to_basic
from .arb_compile import (ANALYTIC, ArbUnsupported, RealAbs, Slope, ball_condition, bound_acb, compile_acb, compile_at,
                          nan_ball, to_acb)

__all__ = ["substitute_end", "singular_piece", "value_at"]


def value_at(e, values):
    """The number a point (or end) that holds parameters has at ``values``
    (SymPy, exact where the values are); ``e`` itself where ``values`` is None."""
    return e if values is None else to_basic(sp.sympify(e, strict=True).xreplace(values))


#: the substitution variable of an end-point singularity
_u = sp.Dummy("u", positive=True)
#: the same without assumptions (the root end's substitution, :func:`_root_out`)
_w = sp.Dummy("w")


def _root_out(base, r, w):
    """``base**r`` with the powers of ``w`` (> 0 on the substituted piece)
    among the factors of the factored ``base`` taken out of the root:
    (w^k B)^r = w^(k r) B^r, so that w^(k r) cancels the Jacobian's power
    of w in the product (ball arithmetic cannot cancel 0/0 by itself).
    What a positive u would have done at construction, without SymPy's
    sign queries on every intermediate expression."""
    k, rest = 0, []
    for f in sp.Mul.make_args(base):
        if f == w:
            k += 1
        elif f.is_Pow and f.base == w and f.exp.is_Integer:
            k += int(f.exp)
        else:
            rest.append(f)
    return w ** (k * r) * sp.Mul(*rest) ** r if k else base ** r


def substitute_end(expr, var, end, d, branches: bool = True):
    """``expr`` d``var`` on the half piece from ``end`` (a singular end: a
    power (t - e)^beta of a factor vanishing there, -1 < beta, or a
    sqrt-type branch point) to end + d, in var = end + d w^q, w in [0, 1],
    the power q chosen from the end's exponent (:func:`_end_power`: 2 for
    beta >= -1/2, larger below): (the integrand in w, w, q).  The Jacobian
    q d w^(q-1) included, a Piecewise folded and, with ``branches``, its
    branch on the half piece taken and an asin or acos at its branch point
    +-1 there rewritten (:func:`_arcs_at_end`: what ball arithmetic needs;
    a pointwise evaluation, mpmath's, does without), and the powers of w
    out of each factored radicand (:func:`_root_out`), so that they cancel
    the Jacobian's (no digits lost to cancellation in a^2 - t^2 next to the
    end) and the integrand is holomorphic at w = 0 (or vanishes there like
    a power >= 3 of w, which ball arithmetic bounds).  A power beta <= -1
    (the integral diverges) or one that needs q > 2000 raises
    :class:`~.arb_compile.ArbUnsupported`.
    ``end`` and ``d`` may be symbols (a form made once for many points).
    In a variable without assumptions: SymPy's sign queries on a positive
    one were three quarters of this route's CPU.

    >>> t = sp.Dummy("t")
    >>> g, w, q = substitute_end((1 - t)**sp.Rational(-2, 3), t, 1, -1)
    >>> q, g, sp.integrate(g, (w, 0, 1))      # int_0^1 (1 - t)^(-2/3) dt = 3, oriented from t = 1
    (12, -12*_w**3, -3)
    """
    expr, q = _end_power(expr, var, end)
    w = _w
    g = sp.piecewise_fold(expr.xreplace({var: end + d * w**q}) * q * d * w**(q - 1))
    if branches:
        g = _arcs_at_end(_inside_branch(g, w), w)
    g = g.replace(lambda z: z.is_Pow and z.exp.is_Rational and not z.exp.is_Integer and z.base.has(w),
                  lambda z: _root_out(sp.factor(z.base), z.exp, w))
    return sp.expand_mul(g), w, q


def singular_piece(integrand, var, lo, hi, piece, values=None):
    """The piece [lo, hi] whose integrand has an algebraic end-point
    singularity (1/sqrt(a^2 - t^2) at t = a, 1/sqrt(s^2 - b^2) behind a
    break, a power t^beta, -1 < beta < 0, at 0): split at the middle m and,
    on each half with a singular end e, t = e + (m - e) u^q, u in [0, 1],
    q from the end's exponent (:func:`substitute_end`): the radicands are
    factored, so that the u^q they vanish with comes out of the root and
    cancels the Jacobian q (m - e) u^(q-1) (ball arithmetic cannot cancel
    0/0 by itself).  A
    logarithmic end point (a log singularity, or logarithms whose infinities
    cancel there) goes to :func:`_log_end`.  A singularity that neither
    removes raises :class:`~.arb_compile.ArbUnsupported` (the fallback runs).

    ``values``: lo, hi and the integrand hold parameters (see
    :func:`~.reference.integrate`): the substituted forms are made with the parameters
    and the half piece's length as symbols, once per integrand and end
    (kept), and bound to the numbers here."""
    m = (lo + hi) / 2
    f = compile_at(integrand, var, values)
    total = flint.acb(0)
    for e, other in ((lo, m), (m, hi)):
        try:
            total += piece(f, value_at(e, values), value_at(other, values))
            continue
        except ArbUnsupported:
            pass
        total_half = None
        # only an end where the integrand has no finite ball is substituted
        ends = [(end, far) for end, far in ((e, other), (other, e))
                if not _bounded_next_to(f, value_at(end, values), value_at(far, values))] or \
            [(e, other), (other, e)]      # bounded at both ends (the work limit): either may still be substituted

        def root_end(end, far):
            if values is None:
                g, w, _ = substitute_end(integrand, var, end, far - end)
                return piece(compile_acb(g, w), sp.S.Zero, sp.S.One)
            g, w, _ = _root_end_form(integrand, var, end)
            return piece(bound_acb(g, w, {**values, _DE: value_at(far, values) - value_at(end, values)}), sp.S.Zero,
                         sp.S.One)

        def log_end(end, far):
            # a power B^beta, beta < 0, of a base vanishing at the end stays
            # in the split integrand (only logarithms are split) and has no
            # finite ball next to it: :func:`_log_end` would fail there after
            # its symbolic work (the pressure's 1/sqrt at s = a under the
            # kernel's logarithm), so it is not tried
            if any(b < 0 for b in _end_betas(integrand, var, end)[1]):
                raise ArbUnsupported("a negative power vanishing at the end point: no logarithmic end point")
            return _log_end(integrand, var, end, far, piece, values)
        # an integrand with logarithms tries their subtraction first
        ways = (log_end, root_end) if integrand.has(sp.log, sp.acosh, sp.asinh, sp.atanh) else (root_end, log_end)
        for way in ways:
            for end, far in ends:
                try:
                    v = way(end, far)
                except ArbUnsupported:
                    continue
                # t runs from ``end`` to ``far`` as u runs from 0 to 1
                total_half = v if end == e else -v
                break
            if total_half is not None:
                break
        if total_half is None:
            raise ArbUnsupported("an end-point singularity that neither the substitution t = e + d u^q nor the "
                                 "subtraction of its logarithms removes")
        total += total_half
    return total


#: the length of a half piece in the forms made once with parameters (may be negative)
_DE = sp.Dummy("d")
#: (integrand, var, end, ...) -> a singular end's symbolic form, made once with parameters
_FORMS: dict = {}
_FORMS_MAX = 256


def _kept(key, make):
    """The form ``make()`` made once per key (a failure too: it is raised
    again, not looked for at every point); the oldest dropped past
    :data:`_FORMS_MAX`."""
    if key not in _FORMS:
        try:
            _FORMS[key] = (make(), None)
        except ArbUnsupported as exc:
            _FORMS[key] = (None, str(exc))
        if len(_FORMS) > _FORMS_MAX:
            del _FORMS[next(iter(_FORMS))]
    form, why = _FORMS[key]
    if why is not None:
        raise ArbUnsupported(why)
    return form


def _root_end_form(integrand, var, end):
    """(the integrand in w, w, q) of :func:`substitute_end` at ``end`` (symbols
    allowed) with the half piece's length the symbol :data:`_DE`: made once
    per (integrand, end).  A Piecewise (whose branch is decided on numbers)
    is not taken."""
    def make():
        if integrand.has(sp.Piecewise):
            raise ArbUnsupported("a Piecewise integrand with parameters: no end substitution made once")
        return substitute_end(integrand, var, end, _DE)
    return _kept(("root", integrand, var, end), make)


def _arcs_at_end(g, u):
    """asin(z) and acos(z) of a substituted half piece whose argument is
    exactly +-1 at the singular end u = 0 (the pressure's asin(b/s) where s
    reaches a break point b): their branch point, where no ball of z is
    holomorphic although asin(z(u)) is (z = 1 - c u^2 + ...), rewritten by
    the half-angle identities, exact for real z in [-1, 1] (where the
    integrand is real),

        asin z = 2 atan(z / (1 + sqrt(1 - z^2))),
        acos z = 2 atan(sqrt(1 - z^2) / (1 + z))       (z -> 1),
        acos z = pi - 2 atan(sqrt(1 - z^2) / (1 - z))  (z -> -1),

    whose radicand 1 - z^2 vanishes with u^2 and leaves its root when the
    caller factors it (:func:`_root_out`), as the integrand's own radicands
    do.  A z that is not real on the piece makes the integral's ball not
    real: the caller then falls back, as before."""
    def swap(f):
        z = f.args[0]
        z0 = z.xreplace({u: sp.S.Zero})
        if z0 not in (sp.S.One, sp.S.NegativeOne):
            return f
        r = sp.sqrt(1 - z**2)
        if isinstance(f, sp.asin):
            return 2 * sp.atan(z / (1 + r))
        return 2 * sp.atan(r / (1 + z)) if z0 == 1 else sp.pi - 2 * sp.atan(r / (1 - z))
    return g.replace(lambda f: isinstance(f, (sp.asin, sp.acos)) and f.args[0].has(u), swap)


def _end_power(integrand, var, end):
    """(integrand, q) for the substitution t = e + d u^q at the end e: the
    powers (t - e)^beta of the integrand's factors that vanish there (bases
    B with B(e) = 0 exactly, a Float exponent read as its exact binary
    value, as the compiler reads every Float) decide q: q = 2 where beta >=
    -1/2 (1/sqrt), else the integer q >= 4/(1 + beta), which turns
    (t - e)^beta dt into a power of u >= 3 that ball arithmetic bounds next
    to u = 0 (a power law's t^(n-2), 1 < n < 2, in Eq. (10)); the radicands
    are factored afterwards, so the u^q they vanish with leaves the root."""
    integrand, betas = _end_betas(integrand, var, end)
    beta = min(betas, default=sp.S.Zero)
    if beta <= -1:
        raise ArbUnsupported(f"a power {beta} <= -1 at the end point: the integral diverges there")
    if beta >= -sp.S.Half:
        return integrand, 2
    q = int(sp.ceiling(4 / (1 + beta)))
    if q > 2000:
        raise ArbUnsupported(f"the end point's power {beta} needs t = e + d u^{q}")
    return integrand, q


def _end_betas(integrand, var, end):
    """(integrand, betas): the exponents beta of the powers B^beta of the
    integrand (beta rational, not an integer) whose base vanishes at the
    end exactly (B(e) = 0), a Float exponent there read as its exact binary
    value (the integrand returned with it so replaced)."""
    end = sp.sympify(end, strict=True)
    floats = {z.exp: sp.Rational(z.exp) for z in integrand.atoms(sp.Pow)
              if z.exp.is_Float and z.base.has(var) and z.base.xreplace({var: end}) == 0}
    if floats:
        integrand = integrand.xreplace(floats)
    betas = [z.exp for z in integrand.atoms(sp.Pow)
             if z.exp.is_Rational and not z.exp.is_Integer and z.base.has(var)
             and z.base.xreplace({var: end}) == 0]
    return integrand, betas


#: the powers of ln u a logarithmic end point may carry (ln^k, k <= 3)
_LOG_POWERS = 3
#: u = v^q at a logarithmic end point
_LOG_END_POWER = 8


def _order_at_zero(F, u, at=None):
    """The power m of u with which F vanishes (m > 0) or blows up (m < 0) at
    u = 0+, read from its balls at u = 2^-40 and 2^-80 (a hint only:
    whatever m is, ln|F| = m ln u + ln|F u^-m| holds; a wrong m leaves a
    quotient that ball arithmetic cannot bound, and the route fails).
    ``at``: the numbers of F's parameters (None: it has none)."""
    try:
        f = compile_at(F, u, at)
        with flint.ctx.workprec(320):
            v1, v2 = (f(flint.acb(flint.arb(2) ** -e), False).abs_lower() for e in (40, 80))
            if not (v1 > 0 and v2 > 0 and v1.is_finite() and v2.is_finite()):
                return None
            m = float((v1 / v2).log() / (flint.arb(2).log() * 40))
    except (ArbUnsupported, ZeroDivisionError, ValueError, TypeError):
        return None
    k = round(m)
    return k if abs(m - k) < 0.05 else None


def _split_log(arg, absolute, u, L, at=None):
    """ln|arg| (``absolute``) or ln(arg) as m L + ln of a quotient that is
    finite at u = 0 (L stands for ln u), factor by factor under ln|.| (ln|x
    y| = ln|x| + ln|y|); None where a factor's order or quotient is not
    found.  ``at``: the parameters' numbers (:func:`_order_at_zero`)."""
    factors = sp.Mul.make_args(arg) if absolute else (arg,)
    out = sp.S.Zero
    for fac in factors:
        base, ex = (fac.base, fac.exp) if fac.is_Pow and fac.exp.is_Integer else (fac, sp.S.One)
        if not base.has(u):
            out += ex * (sp.log(sp.Abs(base)) if absolute else sp.log(base))
            continue
        m = _order_at_zero(base, u, at)
        if m is None:
            return None
        if m == 0:
            out += ex * (sp.log(sp.Abs(base)) if absolute else sp.log(base))
            continue
        if base == u:
            out += ex * L
            continue
        q = sp.expand(base * u**-m)
        if not _finite_next_to_zero(q, u, at):
            q = sp.cancel(sp.together(q))
        if not _finite_next_to_zero(q, u, at):
            q = _conjugate_quotient(base, u, m)
        if q is None or not _finite_next_to_zero(q, u, at):
            # a simple zero: F(u)/u by the mean value theorem
            if m != 1 or base.xreplace({u: sp.S.Zero}) != 0 or \
                    base.has(sp.Abs, sp.sign, sp.Heaviside, sp.Piecewise, sp.Min, sp.Max):
                return None
            q = Slope(base, sp.diff(base, u), u)
            if not _finite_next_to_zero(q, u, at):
                return None
        out += ex * (m * L + (sp.log(sp.Abs(q)) if absolute else sp.log(q)))
    return out


def _conjugate_quotient(base, u, m):
    """F u^-m for F = P + Q sqrt(R) (one square root in u) rationalised:
    (P^2 - Q^2 R) u^-m / (P - Q sqrt(R)), whose numerator cancels the power
    of u (1 - sqrt(1 - u^2) = u^2/(1 + sqrt(1 - u^2))); None for another F."""
    roots = {z for z in base.atoms(sp.Pow) if z.exp == sp.S.Half and z.base.has(u)}
    if len(roots) != 1:
        return None
    r = roots.pop()
    conj = base.xreplace({r: -r})
    num = sp.expand(base * conj)
    if num.has(r):
        return None
    return sp.cancel(num * u**-m) / conj


def _unsigned(f):
    """A factor |x|**k or |x| of a logarithm's argument as x**k or x (under
    ln|.| the sign does not matter)."""
    if f.is_Pow and isinstance(f.base, sp.Abs):
        return f.base.args[0] ** f.exp
    return f.args[0] if isinstance(f, sp.Abs) else f


def _finite_next_to_zero(expr, u, at=None) -> bool:
    try:
        f = compile_at(expr, u, at)
        with flint.ctx.workprec(128):
            return f(flint.acb(flint.arb(0).union(flint.arb(2) ** -40)), False).is_finite()
    except (ArbUnsupported, ZeroDivisionError, ValueError, TypeError):
        return False


def _normal_radicands(e, u):
    """Radicands over a common denominator, the positive powers of u taken
    out of the root (u > 0): sqrt(a^2/u^2 - 1) -> sqrt(a^2 - u^2)/u."""
    return e.replace(lambda z: z.is_Pow and z.exp.is_Rational and not z.exp.is_Integer and z.base.has(u),
                     lambda z: sp.expand_power_base(sp.together(z.base) ** z.exp, force=False))


def _log_end(integrand, var, end, far, piece, values=None):
    """int from ``end`` to ``far`` of an integrand with logarithmic
    singularities at ``end`` (an unbounded ln^k, or logarithms whose
    infinities cancel there: the rounded punch's pressure at the end of its
    flat, which ball arithmetic meets as oo - oo).  With t = end + (far -
    end) u, every logarithm (acosh, asinh, atanh written as logarithms)
    is split symbolically as ln|F| = m ln u + ln|F u^-m|, with the
    quotient finite at u = 0 (simplified, or F(u)/u by the mean value
    theorem: :class:`Slope`), so that the integrand is exactly
    sum_k A_k(u) ln^k u with every A_k finite next to 0.  The integral is

        int_0^1 [g - sum_{k>=1} c_k ln^k u] du + sum_{k>=1} c_k int_0^1 ln^k u du,

    c_k = A_k(0) exact, int_0^1 ln^k u du = (-1)^k k!; next to u = 0 the
    bracket is bounded on a real ball [0, d] (d <= e^-k) by
    sum_k max|A_k'| d |ln d|^k + |A_0| (the ball of A_0), which Arb's
    bisection refines.  :class:`~.arb_compile.ArbUnsupported` where the integrand does
    not take that form.

    ``values``: the integrand, ``end`` and ``far`` hold parameters (see
    :func:`~.reference.integrate`): the split (:func:`_log_end_form`) is made once per
    (integrand, end) with the parameters and the length far - end as
    symbols, the orders of the logarithms' arguments read at the first
    values it meets (a hint only: where another point's order differs the
    quotient has no finite ball there, and the route fails there, it is
    not wrong), and the forms are bound to each point's numbers."""
    if values is None:
        form = _log_end_form(integrand, var, end, far - end, None)
        at = None
    else:
        at = {**values, _DE: value_at(far, values) - value_at(end, values)}

        def make():
            if integrand.has(sp.Piecewise):
                raise ArbUnsupported("a Piecewise integrand with parameters: no logarithmic end made once")
            return _log_end_form(integrand, var, end, _DE, at)
        form = _kept(("log", integrand, var, end, tuple(values)), make)
    g, w, L, coef, consts, slopes = form

    cballs = {}
    for k, c in consts.items():
        cb = to_acb(c) if at is None else bound_acb(c, w, at)(flint.acb(0), False)
        if not cb.is_finite():
            raise ArbUnsupported("a coefficient of the logarithm has no finite value at the end point")
        cballs[k] = cb
    bounds = [(k, compile_at(dA, w, at)) for k, dA in slopes]
    f0 = compile_at(coef.get(0, sp.S.Zero), w, at)
    kmax = max(consts, default=0)
    # the split form, A_k(u) - c_k and ln u = L apart: composed with u = v^q
    # below, no function's cut is met by a ball that winds around u = 0
    split = compile_at(coef.get(0, sp.S.Zero) + sum((A - consts[k]) * L**k for k, A in coef.items() if k), [w, L], at)
    q = _LOG_END_POWER

    def crude(ub):
        """The split integrand on a real ball ub of u that reaches 0."""
        dd = ub.real.upper()
        if not dd < flint.arb(-kmax).exp():
            return nan_ball()
        hull = flint.acb(ub.real.union(flint.arb(0)))
        b = f0(hull, False)
        if not b.is_finite():
            return nan_ball()
        rad = flint.arb(0)
        if dd > 0:
            lnd = -dd.log()
            for k, fd in bounds:
                M = fd(hull, False)
                if not M.is_finite():
                    return nan_ball()
                rad += M.abs_upper() * (dd * lnd ** k).abs_upper()
        r = rad.abs_upper()
        return b + flint.acb(flint.arb(0, r), flint.arb(0, r))

    def h(z, an):
        # u = v^q on [0, u0]: the integrand vanishes like v^(q-1) |ln v|^k at
        # v = 0, so few bisections reach the tolerance there
        ub = z ** q
        if not an and z.imag.is_zero() and 0 in z.real:
            v = crude(ub)
        else:
            v = split((ub, q * z.log(analytic=an == ANALYTIC)), an)
        return v * q * z ** (q - 1)
    u0 = sp.Rational(1, 2**q)
    total = piece(h, sp.S.Zero, sp.Rational(1, 2)) + piece(compile_at(g, w, at), u0, sp.S.One)
    ln_u0 = flint.arb(2).log() * -q
    for k, c in cballs.items():
        # int_0^u0 ln^k u du = u0 sum_j (-1)^(k-j) k!/j! ln^j u0
        closed = sum(flint.arb((-1) ** (k - j) * math.factorial(k) // math.factorial(j)) * ln_u0 ** j
                     for j in range(k + 1))
        total += c * to_acb(u0) * closed
    return total


def _log_end_form(integrand, var, end, d, at):
    """The symbolic split of :func:`_log_end`: (g, w, L, {k: A_k}, {k: c_k},
    [(k, A_k')]) for t = end + d w; ``at``: the parameters' numbers (None:
    there are none) where the orders of the logarithms' arguments are read.
    :class:`~.arb_compile.ArbUnsupported` where the integrand does not take that form."""
    L, w = sp.Dummy("L"), sp.Dummy("w")
    try:
        # the integrand in a variable without assumptions (SymPy's sign
        # queries on a positive one cost more than the integral); only the
        # logarithms' arguments are analysed with u > 0
        g = _inside_branch(sp.piecewise_fold(integrand.xreplace({var: end + d * w}) * d), w)
        g = g.replace(lambda z: isinstance(z, (sp.acosh, sp.asinh, sp.atanh)), lambda z: z.rewrite(sp.log))
        logs = {}
        for lg in g.atoms(sp.log):
            arg = lg.args[0]
            # a factor free of w that is positive (a number; a positive parameter)
            absolute = all(isinstance(b, sp.Abs) or (not b.has(w) and b.is_positive)
                           for b in (f.base if f.is_Pow and f.exp.is_Integer else f for f in sp.Mul.make_args(arg)))
            inner = sp.Mul(*[_unsigned(f) for f in sp.Mul.make_args(arg)]) if absolute else arg
            if not inner.has(w):
                continue
            split = _split_log(_normal_radicands(inner.xreplace({w: _u}), _u), absolute, _u, L, at)
            if split is None:
                raise ArbUnsupported(f"the logarithm {lg} has no quotient finite at the end point")
            logs[lg] = split.xreplace({_u: w})
        if not logs:
            raise ArbUnsupported("no logarithm at the end point")
        # a power of a split logarithm, (m L + ln q)^k, multiplied out (expand_mul leaves it whole)
        expanded = sp.expand_mul(g.xreplace(logs).replace(
            lambda z: z.is_Pow and z.exp.is_Integer and z.exp > 1 and z.base.has(L), sp.expand_multinomial))
        parts = sp.collect(expanded, L, evaluate=False)
    except (TypeError, ValueError, ZeroDivisionError, sp.PolynomialError) as exc:
        raise ArbUnsupported(f"the logarithmic end point could not be split: {exc}") from None
    coef = {}
    for key, val in parts.items():
        k = 0 if key == 1 else (1 if key == L else (int(key.exp) if key.is_Pow and key.base == L and key.exp.is_Integer else -1))
        if not 0 <= k <= _LOG_POWERS or val.has(L):
            raise ArbUnsupported("the integrand is not a polynomial in the logarithm at the end point")
        coef[k] = coef.get(k, sp.S.Zero) + val
    consts, slopes = {}, []
    for k, A in coef.items():
        if k == 0:
            continue
        if A.has(Slope):
            raise ArbUnsupported("a coefficient of the logarithm needs a mean-value quotient")
        c = A.xreplace({w: sp.S.Zero})
        if c.has(sp.nan, sp.zoo, sp.oo, -sp.oo) or (not c.is_number if at is None else c.free_symbols - set(at)):
            raise ArbUnsupported("a coefficient of the logarithm has no value at the end point")
        consts[k] = c
        slopes.append((k, sp.diff(A.replace(lambda z: isinstance(z, sp.Abs), lambda z: RealAbs(z.args[0])), w)))
    return g, w, L, coef, consts, slopes


def _inside_branch(g, u):
    """A Piecewise integrand of a substituted half piece (u in [0, 1], the
    singular end at u = 0, which is a break point of the caller) replaced
    by the branch that holds on all of [2**-20, 1] (decided on balls: the
    caller's break points are the switch points, so the branch of the open
    half piece is the branch next to its end); :class:`~.arb_compile.ArbUnsupported` where
    no branch is decided there.  The span is cut at the powers 2**-k into 20
    balls, each narrow next to its own distance from the end, and a ball
    still undecided is bisected (:func:`_decided_on`): one ball of the whole
    span left a condition that holds by a margin of order u^2 (the
    pressure's s > b behind the break s = b) undecided."""
    if not isinstance(g, sp.Piecewise):
        if g.has(sp.Piecewise):
            raise ArbUnsupported("a Piecewise inside the substituted integrand")
        return g
    two = flint.arb(2)
    for expr, cond in g.args:
        if cond == sp.true:
            return expr
        test = ball_condition(cond, lambda e: compile_acb(e, u))
        decided = set()
        for k in range(20):
            decided |= _decided_on(test, two ** -(k + 1), two ** -k)
        if decided == {True}:
            return expr
        if decided != {False}:
            raise ArbUnsupported("the branch of a Piecewise is not decided on the substituted half piece")
    raise ArbUnsupported("no branch of the Piecewise holds on the substituted half piece")


def _decided_on(test, lo, hi, depth: int = 6) -> set:
    """The values (True, False, None) of the ball test ``test`` on [lo, hi]
    (arb end points), an undecided ball bisected up to ``depth`` times."""
    dec = test(flint.acb(lo.union(hi)))
    if dec is not None or depth == 0:
        return {dec}
    mid = (lo + hi) / 2
    return _decided_on(test, lo, mid, depth - 1) | _decided_on(test, mid, hi, depth - 1)


def _bounded_next_to(f, end, far) -> bool:
    """Has ``f`` a finite ball on a short segment at ``end`` towards ``far``?"""
    try:
        e_b, f_b = to_acb(end), to_acb(far)
        seg = e_b.real.union((e_b + (f_b - e_b) * flint.arb(2) ** -30).real)
        return f(flint.acb(seg), False).is_finite()
    except (ZeroDivisionError, ValueError, TypeError, ArbUnsupported):
        return False
