"""Certified evaluation with python-flint (Arb ball arithmetic).

:func:`arb_evaluate` evaluates a SymPy closed form on exact inputs with Arb
balls: every operation returns a ball guaranteed to contain the exact result,
so the final ball is a rigorous enclosure of the quantity (for the inputs as
given: a Python float is its exact binary value, a string or a SymPy Rational
its exact decimal/rational value).  The working precision is raised until
the ball's relative radius meets the requested number of digits.

The stable form (:mod:`linecontact_sym.numeric.stable`) is evaluated when available:
in ball arithmetic cancellation cannot produce a wrong result, only a wide
ball, so the stable form just reaches the target at a lower precision.

Supported: + - * /, powers, sqrt, exp, log, trigonometric, hyperbolic and
their inverses, gamma / loggamma, elliptic_k / elliptic_e / elliptic_pi (complete and
incomplete, elliptic_f), 2F1 (``hyper``), Bessel J, I, K, Y (real argument),
Piecewise (conditions decided on balls; where a ball straddles a
breakpoint the union of the branches is returned, which encloses the value
of a continuous piecewise function), and the stable primitives carlson_rf,
carlson_rd, carlson_rg, carlson_rj, gamma_ratio, hyp2f1c.  Unevaluated integrals are not
supported (no certified quadrature here): :class:`CertificationError`.

The global precision of python-flint is never changed (``ctx.workprec``).
python-flint is a core dependency of the package (one code path for
numbers: no result depends on whether an optional package is installed).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import flint
import mpmath
import sympy as sp

from ..parsing import to_sympy
from ..core.conversion import number
from ..core.errors import LineContactError
from .special import carlson_rd, carlson_rf, carlson_rg, carlson_rj, gamma_ratio, hyp2f1c
from ..core.precision import workprec


def _flint():
    """The python-flint module (a core dependency: one code path for numbers)."""
    return flint


class CertificationError(LineContactError):
    """The expression cannot be evaluated in certified ball arithmetic."""


def to_arb(v):
    """An Arb ball containing the exact value of ``v`` at the current
    python-flint precision: every number goes through the package's one
    converter (:func:`~linecontact_sym.core.conversion.number`): int, float
    (its binary value), Fraction, Decimal, decimal text, mpf, NumPy scalars
    and SymPy Rationals and Floats exactly; other SymPy numbers
    (``sqrt(3)/2``, ``pi/4``, ``exp(-1)``) as balls evaluated in Arb."""
    flint = _flint()
    arb = flint.arb
    if isinstance(v, arb):
        return v
    if isinstance(v, bool):
        raise TypeError("boolean is not a number")
    if isinstance(v, int):
        return arb(flint.fmpz(v))
    if isinstance(v, float):
        if not math.isfinite(v):
            raise CertificationError(f"non-finite input {v}")
        return arb(v)  # a double is exact in Arb
    try:
        q = number(v)
    except LineContactError as exc:
        raise CertificationError(f"cannot convert {v!r} to a ball: {exc}") from None
    if q.is_Rational:
        return arb(flint.fmpq(int(q.p), int(q.q)))
    if q.is_number and not q.free_symbols:
        return compile_arb(q, [])()
    raise CertificationError(f"cannot convert {v} to a ball")


def _real(z):
    """The real part of the acb ball ``z``, which must contain a real number."""
    if not z.imag.contains(0):
        raise CertificationError(f"complex value {z} where a real one was expected")
    return z.real


def _cmp(rel, lhs, rhs):
    """True/False if decided on the balls, None if not."""
    if isinstance(rel, sp.StrictLessThan):
        t, f = lhs < rhs, lhs >= rhs
    elif isinstance(rel, sp.LessThan):
        t, f = lhs <= rhs, lhs > rhs
    elif isinstance(rel, sp.StrictGreaterThan):
        t, f = lhs > rhs, lhs <= rhs
    elif isinstance(rel, sp.GreaterThan):
        t, f = lhs >= rhs, lhs < rhs
    elif isinstance(rel, sp.Eq):
        t, f = lhs == rhs, lhs != rhs
    else:
        raise CertificationError(f"unsupported relation {rel}")
    return True if t else (False if f else None)


_UNARY = {
    sp.exp: lambda x: x.exp(), sp.log: lambda x: x.log(), sp.sin: lambda x: x.sin(),
    sp.cos: lambda x: x.cos(), sp.tan: lambda x: x.tan(), sp.asin: lambda x: x.asin(),
    sp.acos: lambda x: x.acos(), sp.atan: lambda x: x.atan(), sp.sinh: lambda x: x.sinh(),
    sp.cosh: lambda x: x.cosh(), sp.tanh: lambda x: x.tanh(), sp.asinh: lambda x: x.asinh(),
    sp.acosh: lambda x: x.acosh(), sp.atanh: lambda x: x.atanh(), sp.gamma: lambda x: x.gamma(),
    sp.loggamma: lambda x: x.lgamma(), sp.Abs: lambda x: abs(x),
    sp.elliptic_k: lambda m: _real(_flint().acb(m).elliptic_k()),
}


def compile_arb(expr, args):
    """A function ``f(*balls) -> arb`` evaluating ``expr`` at the current
    python-flint precision."""
    flint = _flint()
    arb, acb = flint.arb, flint.acb
    index = {s: i for i, s in enumerate(args)}

    def build(e):
        if e in index:
            i = index[e]
            return lambda v: v[i]
        if e.is_Integer:
            c = int(e)
            return lambda v: arb(flint.fmpz(c))
        if e.is_Rational:
            p_, q_ = int(e.p), int(e.q)
            return lambda v: arb(flint.fmpq(p_, q_))
        if e.is_Float:
            c = to_arb(mpmath.mpf(e._mpf_))
            return lambda v: c
        if e is sp.pi:
            return lambda v: arb.pi()
        if e is sp.E:
            return lambda v: arb.const_e()
        if e is sp.EulerGamma:
            return lambda v: arb.const_euler()
        if e.is_Add:
            fs = [build(t) for t in e.args]

            def add(v):
                s_ = fs[0](v)
                for f in fs[1:]:
                    s_ = s_ + f(v)
                return s_
            return add
        if e.is_Mul:
            fs = [build(t) for t in e.args]

            def mul(v):
                p_ = fs[0](v)
                for f in fs[1:]:
                    p_ = p_ * f(v)
                return p_
            return mul
        if e.is_Pow:
            fb = build(e.base)
            ex = e.exp
            if ex.is_Integer:
                k = int(ex)
                return lambda v: fb(v) ** k if k >= 0 else 1 / fb(v) ** (-k)
            if ex == sp.S.Half:
                return lambda v: fb(v).sqrt()
            if ex == -sp.S.Half:
                return lambda v: fb(v).rsqrt()
            fe = build(ex)
            return lambda v: fb(v) ** fe(v)
        if isinstance(e, sp.Piecewise):
            branches = [(build(ex_), cond) for ex_, cond in e.args]
            conds = [(None if c == sp.true else _build_cond(c)) for _, c in e.args]

            def pw(v):
                acc = None
                for (fb_, _), fc in zip(branches, conds):
                    dec = True if fc is None else fc(v)
                    if dec is False:
                        continue
                    val = fb_(v)
                    acc = val if acc is None else acc.union(val)
                    if dec is True:
                        return acc
                if acc is None:
                    raise CertificationError("no Piecewise branch applies")
                return acc
            return pw
        if isinstance(e, sp.elliptic_e) and len(e.args) == 1:
            fm = build(e.args[0])
            return lambda v: _real(acb(fm(v)).elliptic_e())
        if isinstance(e, sp.hyper) and len(e.ap) == 2 and len(e.bq) == 1:
            fa, fb_, fc, fz = build(e.ap[0]), build(e.ap[1]), build(e.bq[0]), build(e.argument)
            return lambda v: fz(v).hypgeom_2f1(fa(v), fb_(v), fc(v))
        if isinstance(e, hyp2f1c):
            fa, fb_, fc, fz, fzc = [build(t) for t in e.args]

            def h2(v):
                z, zc = fz(v), fzc(v)
                zz = (1 - zc) if z > 0.5 else z     # both are rigorous balls
                return zz.hypgeom_2f1(fa(v), fb_(v), fc(v))
            return h2
        if isinstance(e, (carlson_rf, carlson_rd, carlson_rg, carlson_rj)):
            fx = [build(t) for t in e.args]
            meth = {carlson_rf: acb.elliptic_rf, carlson_rd: acb.elliptic_rd,
                    carlson_rg: acb.elliptic_rg, carlson_rj: acb.elliptic_rj}[type(e)]
            return lambda v: _real(meth(*[acb(f(v)) for f in fx]))
        if isinstance(e, (sp.elliptic_f, sp.elliptic_pi)) or (isinstance(e, sp.elliptic_e) and len(e.args) == 2):
            fx = [build(t) for t in e.args]
            if isinstance(e, sp.elliptic_pi) and len(e.args) == 2:
                return lambda v: _real(acb.elliptic_pi(acb(fx[0](v)), acb(fx[1](v))))
            meth = {sp.elliptic_f: acb.elliptic_f, sp.elliptic_e: acb.elliptic_e_inc,
                    sp.elliptic_pi: acb.elliptic_pi_inc}[type(e)]
            return lambda v: _real(meth(*[acb(f(v)) for f in fx]))
        if isinstance(e, (sp.besselj, sp.besseli, sp.besselk, sp.bessely)):
            fo, fz = build(e.args[0]), build(e.args[1])
            meth = {sp.besselj: "bessel_j", sp.besseli: "bessel_i", sp.besselk: "bessel_k",
                    sp.bessely: "bessel_y"}[type(e)]
            return lambda v: getattr(fz(v), meth)(fo(v))
        if isinstance(e, gamma_ratio):
            fu, fv = build(e.args[0]), build(e.args[1])
            return lambda v: fu(v).gamma() * fv(v).rgamma()
        if type(e) in _UNARY and len(e.args) == 1:
            fx = build(e.args[0])
            op = _UNARY[type(e)]
            return lambda v: op(fx(v))
        if isinstance(e, sp.Integral):
            raise CertificationError("certified evaluation of an unevaluated integral is not "
                                     "supported (no closed form)")
        raise CertificationError(f"no Arb translation for {type(e).__name__}: {e}")

    def _build_cond(c):
        if isinstance(c, sp.And):
            parts = [_build_cond(t) for t in c.args]

            def f_and(v):
                res = [p(v) for p in parts]
                return False if False in res else (True if all(r is True for r in res) else None)
            return f_and
        if isinstance(c, sp.Or):
            parts = [_build_cond(t) for t in c.args]

            def f_or(v):
                res = [p(v) for p in parts]
                return True if True in res else (False if all(r is False for r in res) else None)
            return f_or
        if isinstance(c, sp.core.relational.Relational):
            fl, fr = build(c.lhs), build(c.rhs)
            return lambda v: _cmp(c, fl(v), fr(v))
        raise CertificationError(f"unsupported condition {c}")

    f = build(to_sympy(expr))
    return lambda *vals: f(vals)


@dataclass
class Enclosure:
    """A rigorous enclosure: ``ball`` (python-flint arb) = [mid +/- rad]."""

    ball: object
    prec: int            # bits used

    def _mp(self, ball_method, digits=None):
        """The exact binary end point / midpoint / radius as an mpmath mpf
        (exact: an mpf with enough bits holds the Arb float as it is)."""
        with _flint().ctx.workprec(self.prec + 64):
            b = getattr(self.ball, ball_method)()
            if not b.is_finite():
                return mpmath.nan
            if b.is_zero():
                return mpmath.mpf(0)
            man, exp = b.man_exp()
        man, exp = int(man), int(exp)
        with workprec(max(man.bit_length(), 53) + 10):
            return mpmath.ldexp(mpmath.mpf(man), exp)

    @property
    def mid(self):
        return self._mp("mid")

    @property
    def rad(self):
        return self._mp("rad", 20)

    @property
    def lower(self):
        """A number <= the exact value (the ball's lower end, rounded down)."""
        return self._mp("lower")

    @property
    def upper(self):
        """A number >= the exact value."""
        return self._mp("upper")

    def rel_accuracy_digits(self):
        return self.ball.rel_accuracy_bits() * math.log10(2)

    def __str__(self):
        with _flint().ctx.workprec(self.prec):
            return self.ball.str(max(int(self.prec * 0.30103) - 3, 15), radius=True)


def arb_callable(expr, args):
    """``g(values, dps=15) -> Enclosure``: :func:`arb_evaluate` with the
    translation to Arb done once."""
    f = compile_arb(expr, args)

    def g(values, dps: int = 15, max_prec: int = 40000):
        return _enclose(f, values, dps, max_prec)
    return g


def arb_evaluate(expr, args, values, dps: int = 15, max_prec: int = 40000) -> Enclosure:
    """A rigorous enclosure of the exact value of ``expr`` at ``args`` = ``values``.

    ``expr``: a SymPy expression in the supported functions (module
    docstring; no unevaluated integrals); ``values``: a sequence matching
    ``args``, each taken exactly (a float is its binary value, a string such
    as ``"0.1"`` or a Rational its exact value).  The ball arithmetic runs at
    increasing precision until the ball's relative radius is below 10**-dps;
    :class:`CertificationError` if ``max_prec`` bits do not suffice or a
    function has no Arb translation.  Needs python-flint (the
    ``[certified]`` extra), else
    :class:`~linecontact_sym.core.errors.MissingExtraError`.

    sqrt(1 + 10**-22) - 1 = 5e-23 (1 - 2.5e-23 + ...): float64 gives 0, the
    ball is certain of 20 digits.

    >>> import mpmath, sympy as sp
    >>> x = sp.Symbol("x", positive=True)
    >>> enc = arb_evaluate(sp.sqrt(1 + x) - 1, [x], ["1e-22"], dps=20)
    >>> with mpmath.workdps(60):
    ...     exact = mpmath.sqrt(1 + mpmath.mpf("1e-22")) - 1
    ...     print(enc.lower <= exact <= enc.upper, mpmath.nstr(enc.mid, 5))
    True 5.0e-23
    >>> enc.rel_accuracy_digits() >= 20
    True
    """
    return _enclose(compile_arb(expr, args), values, dps, max_prec)


def _enclose(f, values, dps, max_prec):
    flint = _flint()
    prec = int(dps * 3.33) + 30
    target_bits = dps * math.log2(10) + 1
    last = None
    while prec <= max_prec:
        with flint.ctx.workprec(prec):
            balls = [to_arb(v) for v in values]
            try:
                y = f(*balls)
            except (ZeroDivisionError, ValueError) as exc:
                raise CertificationError(f"ball evaluation failed: {exc}")
            last = y
            if y.is_finite() and (y.is_exact() or y.rel_accuracy_bits() >= target_bits):
                return Enclosure(y, prec)
            if y.is_finite() and y.is_zero():
                return Enclosure(y, prec)
        prec *= 2
    raise CertificationError(f"no enclosure with {dps} digits within {max_prec} bits (last: {last})")
