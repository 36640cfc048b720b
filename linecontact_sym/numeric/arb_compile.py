"""The SymPy-to-Arb compiler: a SymPy expression as a function of complex
balls (python-flint's ``acb``), for the reference integrator
(:mod:`~linecontact_sym.numeric.reference`), its end-point transforms
(:mod:`~linecontact_sym.numeric.endpoints`) and the certified evaluation
(:mod:`~linecontact_sym.numeric.certified`).

How the integrand reaches Arb (:func:`compile_acb`)
    The SymPy expression, in the integration variable only (every other
    symbol replaced by a number, or bound to its ball: :func:`bound_acb`),
    becomes a function ``f(z, analytic)`` of a complex ball z.
    ``acb.integral`` bounds the error of its Gauss-Legendre rules from the
    integrand on complex neighbourhoods of the path, so the integrand must
    say where it is not holomorphic: with ``analytic`` set, sqrt, log,
    non-integer powers and Abs use Arb's own ``analytic`` flag, and every
    other function with a branch cut (acosh, asin, acos, atanh, elliptic K
    and E, 2F1, Bessel functions of non-integer order, K and Y) returns a
    non-finite ball when the argument's ball touches its cut.
    A Piecewise is decided on the real part of the ball: a ball inside one
    branch's region takes that branch (its analytic continuation), a ball
    that straddles a switch is not holomorphic (non-finite when
    ``analytic``; the union of the branches otherwise, which encloses the
    value of the function there).

A function without an acb counterpart (or a symbol left without a value)
raises :class:`ArbUnsupported`: the caller's fallback runs.  Numbers become
the exact balls of their values (:func:`to_acb`), and exact balls the mpf
that hold them (:func:`mpf_of_arb`).  python-flint's and mpmath's global
precisions are never changed.
"""
from __future__ import annotations

import functools
import math
import operator

import flint
import mpmath
import sympy as sp
from mpmath.libmp import from_man_exp

from ..core.conversion import number
from ..core.errors import LineContactError

__all__ = ["ArbUnsupported", "to_acb", "compile_acb", "bound_acb", "compile_at", "is_compiled", "mpf_of_arb",
           "ANALYTIC", "REAL", "nan_ball", "ball_condition", "Slope", "RealAbs"]


class ArbUnsupported(LineContactError):
    """The integrand cannot be integrated in Arb (a function without an acb
    counterpart, a symbol left in it): the fallback runs."""


# ----------------------------------------------------------------- numbers as balls
def to_acb(v):
    """An acb ball containing the exact value of ``v`` (current python-flint
    precision): int, Rational, float and mpf exactly, other SymPy numbers
    (pi/2, asin(1/3)) through :func:`compile_acb`."""
    if isinstance(v, flint.acb):
        return v
    if isinstance(v, flint.arb):
        return flint.acb(v)
    if isinstance(v, bool):
        raise ArbUnsupported("boolean is not a number")
    if isinstance(v, int):
        return flint.acb(flint.fmpz(v))
    if isinstance(v, float) and math.isfinite(v):
        return flint.acb(v)
    if isinstance(v, mpmath.mpf):
        if not mpmath.isfinite(v):
            raise ArbUnsupported(f"non-finite number {v}")
        return _acb_of_mpf(v._mpf_)
    try:
        q = number(v)
    except LineContactError as exc:
        raise ArbUnsupported(f"cannot make a ball of {v!r}: {exc}") from None
    if q.is_Rational:
        return flint.acb(flint.fmpq(int(q.p), int(q.q)))
    if q.is_number and not q.free_symbols:
        f = compile_acb(q, None)
        if q.is_extended_real:
            # the real functions where they apply (tighter: asin, atanh ...)
            z = f(flint.acb(0), REAL)
            if z.is_finite():
                return z
        return f(flint.acb(0), False)
    raise ArbUnsupported(f"cannot make a ball of {v!r}")


def _acb_of_mpf(t):
    """The exact ball of an mpf's raw (sign, mantissa, exponent, bits) value
    (not through mpmath.mpf(), which rounds to mpmath's working precision,
    nor mpf.man_exp, which drops the sign)."""
    sign, man, exp, _ = t
    man = -int(man) if sign else int(man)
    return flint.acb(flint.arb(flint.fmpz(man)) * flint.arb(2) ** int(exp)) if man else flint.acb(0)


# ----------------------------------------------------------------- the compiler
#: the modes of a compiled function's second argument ``an``: ``False`` plain
#: complex balls; ``True`` (:data:`ANALYTIC`) holomorphy signalled for
#: ``acb.integral`` (a ball touching a branch cut gives a non-finite ball);
#: :data:`REAL` the real function (a ball that reaches beyond the real domain
#: of a function gives a non-finite ball, as Arb's real functions do; inside
#: it, the real Arb function where it is tighter than its complex twin).
#: ``REAL`` is what :func:`~linecontact_sym.numeric.certified.compile_arb`
#: evaluates with.
ANALYTIC = True
REAL = 2


def nan_ball():
    return flint.acb("nan")


def _touches(z, lo=None, hi=None) -> bool:
    """Does the ball ``z`` touch the real segment [lo, hi] (None: unbounded)?"""
    if 0 not in z.imag:
        return False
    re_ = z.real
    if lo is not None and re_ < lo:
        return False
    if hi is not None and re_ > hi:
        return False
    return True


def _beyond(z, lo=None, hi=None) -> bool:
    """Does the real part of ``z`` reach into the open segment (lo, hi) (a
    cut: outside the function's real domain, whose end points are its
    branch points)?"""
    re_ = z.real
    return (lo is None or not re_ <= lo) and (hi is None or not re_ >= hi)


def _guarded(z, an, segments) -> bool:
    """Must a function with branch cuts ``segments`` give a non-finite ball
    at ``z`` in mode ``an``?"""
    if an == REAL:
        return any(_beyond(z, lo, hi) for lo, hi in segments)
    return bool(an) and any(_touches(z, lo, hi) for lo, hi in segments)


def _cut(fn, *segments, real=None, slope=None):
    """``fn(z)`` guarded by its branch cuts (real segments); ``real``: the
    name of Arb's real function, used in mode :data:`REAL` on a real ball;
    ``slope``: fn' on a ball (:func:`_mean_value`)."""
    def g(z, an):
        if _guarded(z, an, segments):
            return nan_ball()
        if real is not None and an == REAL and z.imag.is_zero():
            return flint.acb(getattr(z.real, real)())
        return fn(z) if slope is None else _mean_value(fn, slope, z, segments)
    return g


def _mean_value(fn, slope, z, segments):
    """``fn(z)`` or, where it is tighter, the mean-value enclosure
    fn(m) + B(0, max|fn'| |z - m|) about the midpoint m of a wide ball ``z``
    that touches none of fn's branch cuts (fn holomorphic on the rectangle,
    which is convex: the segment from m to any of its points stays in it),
    max|fn'| bounded by ``slope(z)`` (None: no finite bound).  Both are
    rigorous enclosures.  Arb's asin of a complex ball about the real
    segment is far wider: of 0.574 +- 0.0088 +- 0.0038 i, radii 0.096 and
    0.071 against 0.012 here; sin(asin(b/a) - asin(s/a)) in the rounded
    punch's pressure then held 0, and acb.integral bisected its pieces down
    to 1/64 of their width (the Flamant checks' 3,600 evaluations per
    logarithmic end point, 1,500 with this)."""
    v = fn(z)
    rr, ri = z.real.rad(), z.imag.rad()
    if not (rr > _MV_RAD or ri > _MV_RAD) or any(_touches(z, lo, hi) for lo, hi in segments):
        return v
    d = slope(z)
    if d is None or not d.is_finite():
        return v
    e = flint.arb(0, (d.abs_upper() * (rr * rr + ri * ri).sqrt()).abs_upper())
    w = fn(flint.acb(z.real.mid(), z.imag.mid())) + flint.acb(e, e)
    return w if max(w.real.rad(), w.imag.rad()) < max(v.real.rad(), v.imag.rad()) else v


#: radius (real or imaginary) above which :func:`_mean_value` is tried: a
#: quadrature node's ball (2**-180 wide) keeps Arb's own value
_MV_RAD = flint.arb(2) ** -20


def _acosh_slope(z):
    """1/(sqrt(z - 1) sqrt(z + 1)) on a ball, None where an enclosure of
    z -+ 1 touches sqrt's cut."""
    lo, hi = z - 1, z + 1
    return None if _touches(lo, None, 0) or _touches(hi, None, 0) else lo.rsqrt() * hi.rsqrt()


def _asinh_slope(z):
    """1/sqrt(1 + z^2) on a ball (|Im z| < 1: asinh's cuts i[1, oo), -i[1, oo)
    are not met), None where the enclosure of 1 + z^2 touches sqrt's cut."""
    q = 1 + z * z
    return None if _touches(q, None, 0) else q.rsqrt()


def _inverse_root_slope(z):
    """1/sqrt(1 - z^2) on a ball (asin's slope, acos's up to its sign), None
    where the enclosure of 1 - z^2 touches sqrt's cut (-oo, 0]."""
    q = 1 - z * z
    return None if _touches(q, None, 0) else 1 / q.sqrt()


#: functions holomorphic wherever they are finite (poles give non-finite balls by themselves)
_MEROMORPHIC = {sp.exp: "exp", sp.sin: "sin", sp.cos: "cos", sp.tan: "tan", sp.cot: "cot", sp.sec: "sec",
                sp.csc: "csc", sp.sinh: "sinh", sp.cosh: "cosh", sp.tanh: "tanh", sp.coth: "coth",
                sp.sech: "sech", sp.csch: "csch", sp.gamma: "gamma", sp.erf: "erf", sp.erfc: "erfc",
                sp.sinc: "sinc"}

#: the other functions of one argument: ``op(ball, mode)`` (a meromorphic one is its ball's method)
_UNARY = {
    sp.log: lambda z, an: nan_ball() if an == REAL and _beyond(z, None, 0) else z.log(analytic=an == ANALYTIC),
    sp.Abs: lambda z, an: z.real_abs(analytic=an == ANALYTIC),
    sp.asin: _cut(lambda z: z.asin(), (None, -1), (1, None), real="asin", slope=_inverse_root_slope),
    sp.acos: _cut(lambda z: z.acos(), (None, -1), (1, None), real="acos", slope=_inverse_root_slope),
    sp.atanh: _cut(lambda z: z.atanh(), (None, -1), (1, None), real="atanh"),
    sp.acosh: _cut(lambda z: z.acosh(), (None, 1), real="acosh", slope=_acosh_slope),
    sp.loggamma: _cut(lambda z: z.lgamma(), (None, 0), real="lgamma"),
    sp.elliptic_k: _cut(lambda m: flint.acb.elliptic_k(m), (1, None)),
    sp.elliptic_e: _cut(lambda m: flint.acb.elliptic_e(m), (1, None)),     # complete E(m) (one argument)
    sp.sign: lambda z, an: nan_ball() if an == ANALYTIC and _touches(z, 0, 0) else z.real_sgn(),
    sp.Heaviside: lambda z, an: nan_ball() if an == ANALYTIC and _touches(z, 0, 0) else z.real_heaviside(),
}

# atan and asinh have their branch points at +-i, off the real line: a ball
# near the real segment never reaches them unless it is huge
_UNARY[sp.atan] = lambda z, an: nan_ball() if an == ANALYTIC and z.imag.abs_upper() >= 1 else z.atan()
_UNARY[sp.asinh] = lambda z, an: nan_ball() if an == ANALYTIC and z.imag.abs_upper() >= 1 else \
    _mean_value(lambda w: w.asinh(), _asinh_slope, z, ()) if z.imag.abs_upper() < 1 else z.asinh()


def _several(method, cuts):
    """A function of several balls (``method(*balls)``), the k-th guarded by
    the branch cuts ``cuts[k]`` (a tuple of segments; () for none)."""
    def g(args, an):
        if an and any(_guarded(w, an, c) for w, c in zip(args, cuts) if c):
            return nan_ball()
        return method(*args)
    return g


#: functions of several arguments: (handler(args, an), holomorphy known).
#: The package's own stable primitives (numeric/special.py) are here, so a
#: stable form compiles as its plain form does.  Carlson's integrals are
#: holomorphic with every argument off (-oo, 0] (DLMF 19.2(i)); 2F1 off its
#: cut [1, oo) in z.  The incomplete elliptic integrals' cuts in (phi, m)
#: are not encoded: real evaluation only (``holomorphic=False``).
_NEG = ((None, 0),)
_ABOVE_ONE = ((1, None),)


def _arb_exp_tail(n, z):
    """exp(z) - sum_{k<n} z^k/k! = z^n/n! 1F1(1; n + 1; z) (entire in z; n an exact integer)."""
    k = int(round(float(n.real.mid())))
    return z.hypgeom_1f1(1, k + 1) * z**k * flint.acb(k + 1).rgamma()


_SEVERAL = {
    "carlson_rf": (_several(flint.acb.elliptic_rf, (_NEG, _NEG, _NEG)), True),
    "carlson_rd": (_several(flint.acb.elliptic_rd, (_NEG, _NEG, _NEG)), True),
    "carlson_rg": (_several(flint.acb.elliptic_rg, (_NEG, _NEG, _NEG)), True),
    "carlson_rj": (_several(flint.acb.elliptic_rj, (_NEG, _NEG, _NEG, _NEG)), True),
    "gamma_ratio": (_several(lambda u, v: v.rgamma() * u.gamma(), ((), ())), True),   # order: see mul
    "exp_tail": (_several(_arb_exp_tail, ((), ())), True),
    # w sqrt(1 + w^2) - asinh(w): the plain form on balls (rigorous; Arb's precision loop pays the cancellation)
    "asinh_excess": (_several(lambda w: w * (1 + w * w).sqrt() - w.asinh(), ((),)), False),
    # sin(pi (t_1 + ... + t_k)/L): on balls the plain sine (Arb's precision loop pays the reduction)
    "sin_pi_sum": (_several(lambda L, *t: (flint.acb.pi() * sum(t[1:], t[0]) / L).sin(), ()), True),
    "elliptic_pi2": (_several(flint.acb.elliptic_pi, (_ABOVE_ONE, _ABOVE_ONE)), True),
    "elliptic_f": (_several(flint.acb.elliptic_f, ((), ())), False),
    "elliptic_e2": (_several(flint.acb.elliptic_e_inc, ((), ())), False),
    "elliptic_pi3": (_several(flint.acb.elliptic_pi_inc, ((), (), ())), False),
}


def _several_key(e):
    """The key of ``e`` in :data:`_SEVERAL` (None: not there)."""
    name = type(e).__name__
    if isinstance(e, (sp.elliptic_pi, sp.elliptic_e)):
        return f"{name}{len(e.args)}" if len(e.args) > 1 else None
    if isinstance(e, sp.elliptic_f):
        return name
    from . import special
    return name if isinstance(e, sp.Function) and getattr(special, name, None) is type(e) else None


def _relation(rel):
    if isinstance(rel, sp.StrictLessThan):
        return lambda l, r: (True if l < r else (False if l >= r else None))
    if isinstance(rel, sp.LessThan):
        return lambda l, r: (True if l <= r else (False if l > r else None))
    if isinstance(rel, sp.StrictGreaterThan):
        return lambda l, r: (True if l > r else (False if l <= r else None))
    if isinstance(rel, sp.GreaterThan):
        return lambda l, r: (True if l >= r else (False if l < r else None))
    if isinstance(rel, sp.Eq):
        return lambda l, r: (True if l == r else (False if l != r else None))
    if isinstance(rel, sp.Ne):
        return lambda l, r: (True if l != r else (False if l == r else None))
    raise ArbUnsupported(f"no ball test for the relation {rel}")


def compile_acb(expr, var, holomorphic: bool = True, fixed: int = 0):
    """``f(z, analytic) -> acb``: ``expr`` (SymPy) evaluated on complex
    balls at the current python-flint precision, holomorphy signalled as
    ``acb.integral`` expects (module docstring).

    ``var``: the one symbol (``z`` is a ball), ``None`` for a number, or a
    list of symbols (``z`` is a tuple of balls, in that order).  The second
    argument is a mode: ``False``, ``True`` (:data:`ANALYTIC`) or
    :data:`REAL` (the real function, as :func:`~linecontact_sym.numeric.
    certified.compile_arb` asks).  ``holomorphic=False``: the function will
    not be asked for holomorphy, so functions whose branch cuts are not
    encoded (incomplete elliptic integrals) are allowed.  ``fixed``: the
    last ``fixed`` symbols of a list ``var`` are parameters: ``z`` is then
    (the other symbols' balls ..., P) with P one tuple of the parameters'
    balls, the same object over many calls (:func:`bound_acb`), and the
    subexpressions free of the other symbols are computed once per
    precision and P, as numbers are.
    :class:`ArbUnsupported` for a function without an acb counterpart or a
    symbol not in ``var``."""
    expr = sp.sympify(expr, strict=True)
    if var is None:
        index, several = {}, False
    elif isinstance(var, (list, tuple)):
        index, several = {s: i for i, s in enumerate(var)}, True
    else:
        index, several = {var: None}, False
    extra = expr.free_symbols - set(index)
    if extra:
        raise ArbUnsupported(f"symbols {sorted(map(str, extra))} have no value in the integrand {expr}")
    acb, arb, ctx = flint.acb, flint.arb, flint.ctx
    moving = len(index) - fixed if several else len(index)
    symbols = tuple(index)[:moving]
    params = bool(fixed) and several
    # subexpressions in the variables that occur more than once (the
    # pressure's asin(x/a) in four places) are evaluated once per ball
    seen: dict = {}
    for node in sp.preorder_traversal(expr):
        if not node.is_Atom and node.has(*symbols):
            seen[node] = seen.get(node, 0) + 1
    built: dict = {}

    def build(e):
        if e in index:
            i = index[e]
            if i is not None and i >= moving:
                j = i - moving
                return lambda z, an: z[-1][j]
            return (lambda z, an: z) if i is None else (lambda z, an: z[i])
        if symbols and not e.has(*symbols):
            return constant(build_node(e))
        if seen.get(e, 0) > 1:
            if e not in built:
                built[e] = shared(build_node(e))
            return built[e]
        return build_node(e)

    def shared(f):
        """A repeated subexpression: its ball for the last (ball, mode,
        precision) it was asked for is kept (the ball itself is held, so
        its identity names it)."""
        last_z = last_an = last_prec = last_v = None

        def g(z, an):
            nonlocal last_z, last_an, last_prec, last_v
            prec = ctx.prec
            if last_z is z and last_an == an and last_prec == prec:
                return last_v
            v = f(z, an)
            last_z, last_an, last_prec, last_v = z, an, prec, v
            return v
        return g

    def constant(f):
        """A subexpression free of the variables: its ball computed once per
        working precision (the rationals and parameter combinations of an
        integrand are not rebuilt at every node), in the real mode or the
        complex one."""
        memo = {}
        # the last (precision, mode, parameters) asked and its ball: the
        # memo's entry for them, read without building its key (an
        # integrand's constants are asked at every node of a quadrature)
        last_prec = last_real = last_at = last_v = None

        def g(z, an):
            nonlocal last_prec, last_real, last_at, last_v
            prec, real = ctx.prec, an == REAL
            at = z[-1] if params else None
            if last_prec == prec and last_real == real and last_at is at:
                return last_v
            key = (prec, real)
            v = memo.get(key)
            if v is None or v[0] is not at:
                v = memo[key] = (at, f(z, REAL if real else False))
            last_prec, last_real, last_at, last_v = prec, real, at, v[1]
            return v[1]
        return g

    def build_node(e):
        if e.is_Integer:
            c = int(e)
            return lambda z, an: acb(flint.fmpz(c))
        if e.is_Rational:
            p_, q_ = int(e.p), int(e.q)
            return lambda z, an: acb(flint.fmpq(p_, q_))
        if e.is_Float:
            if not mpmath.isfinite(mpmath.mpf(e._mpf_)):
                raise ArbUnsupported(f"non-finite number {e}")
            t_ = e._mpf_
            return lambda z, an: _acb_of_mpf(t_)
        if e is sp.pi:
            return lambda z, an: acb(arb.pi())
        if e is sp.E:
            return lambda z, an: acb(arb.const_e())
        if e is sp.EulerGamma:
            return lambda z, an: acb(arb.const_euler())
        if e is sp.I:
            return lambda z, an: acb(0, 1)
        if e.is_Add or e.is_Mul:
            fs = _folded(e, build, constant, symbols)
            return fs[0] if len(fs) == 1 else _combined(fs, e.is_Add)
        if e.is_Pow:
            fb = build(e.base)
            ex = e.exp
            if ex.is_Integer:
                k = int(ex)
                if k >= 0:
                    return lambda z, an: fb(z, an) ** k
                return lambda z, an: 1 / fb(z, an) ** (-k)
            if ex == sp.S.Half:
                return lambda z, an: _root(fb(z, an), an, "sqrt")
            if ex == -sp.S.Half:
                return lambda z, an: _root(fb(z, an), an, "rsqrt")
            fe = build(ex)
            positive = ex.is_number and ex.is_positive

            def power(z, an):
                b, y = fb(z, an), fe(z, an)
                if an == REAL and _beyond(b, None, 0):
                    return nan_ball()           # a negative base: no real power
                if an != ANALYTIC and positive and 0 in b:
                    # a ball around the branch point 0 of b**y, y > 0: |b**y| <= |b|**y there
                    # (a crude bound of the whole piece, which acb's pow leaves as nan)
                    m = b.abs_upper() ** y.real
                    return acb(arb(0, m), arb(0, m))
                return b.pow(y, analytic=an == ANALYTIC)
            return power
        if isinstance(e, sp.Piecewise):
            return _piecewise(e, build, several)
        if isinstance(e, (sp.Min, sp.Max)):
            return _extremum([build(t) for t in e.args], isinstance(e, sp.Max))
        key = _several_key(e)
        if key is not None and key in _SEVERAL:
            handler, known = _SEVERAL[key]
            if holomorphic and not known:
                raise ArbUnsupported(f"the branch cuts of {type(e).__name__} are not encoded (real evaluation only)")
            fx = [build(t) for t in e.args]
            return lambda z, an: handler([f(z, an) for f in fx], an)
        if isinstance(e, sp.hyper) and len(e.ap) == 2 and len(e.bq) == 1:
            fa, fb_, fc, fz = build(e.ap[0]), build(e.ap[1]), build(e.bq[0]), build(e.argument)

            def h2(z, an):
                w = fz(z, an)
                if _guarded(w, an, _ABOVE_ONE):
                    return nan_ball()
                return w.hypgeom_2f1(fa(z, an), fb_(z, an), fc(z, an))
            return h2
        if isinstance(e, sp.hyper) and len(e.ap) <= len(e.bq) and all(q.is_number for q in e.ap + e.bq):
            # pFq with p <= q: entire in its argument (no cut), constant parameters (Arb's acb_hypgeom_pfq)
            if any(q.is_integer and q <= 0 for q in e.bq):
                raise ArbUnsupported(f"a lower parameter of {e} is a non-positive integer")
            fa, fb_, fz = [build(q) for q in e.ap], [build(q) for q in e.bq], build(e.argument)
            return lambda z, an: fz(z, an).hypgeom([f(z, an) for f in fa], [f(z, an) for f in fb_])
        if key == "hyp2f1c":
            # 2F1 at z given also its complement zc = 1 - z: at z > 1/2 the
            # argument is taken as 1 - zc (both are rigorous balls of it; zc
            # is the one computed without cancellation)
            fa, fb_, fc, fz, fzc = [build(t) for t in e.args]

            def h2c(z, an):
                w = fz(z, an)
                if w.real > 0.5:
                    w = 1 - fzc(z, an)
                if _guarded(w, an, _ABOVE_ONE):
                    return nan_ball()
                return w.hypgeom_2f1(fa(z, an), fb_(z, an), fc(z, an))
            return h2c
        if isinstance(e, (sp.besselj, sp.besseli, sp.besselk, sp.bessely)):
            order = e.args[0]
            fo, fz = build(order), build(e.args[1])
            meth = {sp.besselj: "bessel_j", sp.besseli: "bessel_i", sp.besselk: "bessel_k",
                    sp.bessely: "bessel_y"}[type(e)]
            entire = isinstance(e, (sp.besselj, sp.besseli)) and order.is_integer is True

            def bes(z, an):
                w = fz(z, an)
                if not entire and _guarded(w, an, _NEG):
                    return nan_ball()
                return getattr(w, meth)(fo(z, an))
            return bes
        if (type(e) in _MEROMORPHIC or type(e) in _UNARY) and len(e.args) == 1:
            fx = build(e.args[0])
            name = _MEROMORPHIC.get(type(e))
            if name is not None:       # the ball's method, called in the same frame
                m = operator.methodcaller(name)
                return lambda z, an: m(fx(z, an))
            op = _UNARY[type(e)]
            return lambda z, an: op(fx(z, an), an)
        if isinstance(e, RealAbs):
            fx = build(e.args[0])

            def real_abs(z, an):
                v = fx(z, an)
                return _UNARY[sp.Abs](v, an) if v.imag.is_zero() else nan_ball()
            return real_abs
        if isinstance(e, Slope):
            if e.args[2] not in index:
                raise ArbUnsupported("a mean-value quotient in a variable that is not the integrand's one")
            return _slope(build(e.args[0]), build(e.args[1]), index[e.args[2]])
        if isinstance(e, sp.Integral):
            raise ArbUnsupported("an unevaluated integral inside the integrand (no closed form)")
        raise ArbUnsupported(f"no acb counterpart for {type(e).__name__}: {e}")

    return build(expr)


def _folded(e, build, constant, symbols):
    """The compiled terms of a sum (factors of a product) ``e``, those free of
    the variables folded into one constant ball (computed once per working
    precision, not combined again at every evaluation: an integrand's
    Rationals, pi, gamma values and parameter powers), which comes first."""
    const = [t for t in e.args if not t.has(*symbols)] if symbols else []
    if len(const) < 2:
        return [build(t) for t in e.args]
    fold = _combined([build(t) for t in const], e.is_Add)
    return [constant(fold)] + [build(t) for t in e.args if t.has(*symbols)]


def _combined(fs, add):
    """The compiled sum (``add``) or product of the compiled terms ``fs``."""
    f0, rest = fs[0], tuple(fs[1:])
    # two terms (most nodes) without the loop; the same operations in the same order
    f1 = rest[0] if len(rest) == 1 else None
    if add:
        if f1 is not None:
            def total2(z, an):
                return f0(z, an) + f1(z, an)
            return total2

        def total(z, an):
            s_ = f0(z, an)
            for f in rest:
                s_ = s_ + f(z, an)
            return s_
        return total

    # f * p: Arb's acb_mul(f, p) on real balls is arb_mul(p, f),
    # the real product in the order of the factors (its radius
    # rounding is not symmetric)
    if f1 is not None:
        def product2(z, an):
            p_ = f0(z, an)
            return f1(z, an) * p_
        return product2

    def product(z, an):
        p_ = f0(z, an)
        for f in rest:
            p_ = f(z, an) * p_
        return p_
    return product


def _extremum(fs, largest):
    """Max (``largest``) or Min of real arguments on balls, decided as a
    Piecewise is (not through SymPy's rewrite, which recurses without end on
    three radicals): the argument whose real part is certainly >= (<=) every
    other one is taken (its continuation: holomorphic where it is); where none
    is, not holomorphic (non-finite when ``analytic``), else the union of the
    arguments that may be the extremum."""
    def g(z, an):
        vals = [f(z, an) for f in fs]
        if any(0 not in v.imag for v in vals):
            return nan_ball()
        re_ = [v.real for v in vals]
        if largest:
            maybe = [i for i, r in enumerate(re_) if not any(o > r for o in re_)]
            sure = [i for i in maybe if all(r <= re_[i] for r in re_)]
        else:
            maybe = [i for i, r in enumerate(re_) if not any(o < r for o in re_)]
            sure = [i for i in maybe if all(r >= re_[i] for r in re_)]
        if sure:
            return vals[sure[0]]
        if an == ANALYTIC:
            return nan_ball()
        acc = vals[maybe[0]]
        for i in maybe[1:]:
            acc = acc.union(vals[i])
        return acc
    return g


def _root(b, an, name):
    """sqrt or rsqrt of the ball ``b`` in mode ``an``."""
    if an == REAL and _beyond(b, None, 0):
        return nan_ball()
    return getattr(b, name)(analytic=an == ANALYTIC)


def _real_parts(z, several):
    """The real parts of the balls ``z``; the tuple of the parameters' balls
    (:func:`bound_acb`: real numbers) kept as it is, the same object, since
    the constant subexpressions are kept per that object."""
    return tuple(w if isinstance(w, tuple) else flint.acb(w.real) for w in z) if several else flint.acb(z.real)


def _piecewise(e, build, several=False):
    """A Piecewise on balls: a branch whose condition holds on the whole ball
    (real part) is taken; a ball where a condition is undecided is not
    holomorphic (non-finite when ``analytic``; otherwise the union of the
    branches that may apply)."""
    branches = []
    for ex_, cond in e.args:
        branches.append((build(ex_), None if cond == sp.true else ball_condition(cond, build)))

    def pw(z, an):
        zr = z if an == REAL else _real_parts(z, several)
        acc = None
        for fb_, fc in branches:
            dec = True if fc is None else fc(zr)
            if dec is False:
                continue
            if dec is None and an == ANALYTIC:
                return nan_ball()
            val = fb_(z, an)
            acc = val if acc is None else acc.union(val)
            if dec is True:
                return acc
        return acc if acc is not None else nan_ball()
    return pw


def ball_condition(c, build):
    if c == sp.true:
        return lambda z: True
    if c == sp.false:
        return lambda z: False
    if isinstance(c, (sp.And, sp.Or)):
        parts = [ball_condition(t, build) for t in c.args]
        if isinstance(c, sp.And):
            def f_and(z):
                res = [p(z) for p in parts]
                return False if False in res else (True if all(r is True for r in res) else None)
            return f_and

        def f_or(z):
            res = [p(z) for p in parts]
            return True if True in res else (False if all(r is False for r in res) else None)
        return f_or
    if isinstance(c, sp.Not):
        inner = ball_condition(c.args[0], build)
        return lambda z: (None if inner(z) is None else not inner(z))
    if isinstance(c, sp.core.relational.Relational):
        fl, fr, test = build(c.lhs), build(c.rhs), _relation(c)

        def rel(z):
            lv, rv = fl(z, False), fr(z, False)
            if 0 not in lv.imag or 0 not in rv.imag:
                return None
            return test(lv.real, rv.real)
        return rel
    raise ArbUnsupported(f"no ball test for the condition {c}")


# ----------------------------------------------------------------- compiled once, bound to numbers
@functools.lru_cache(maxsize=256)
def _compiled(expr, syms, fixed):
    return compile_acb(expr, list(syms), fixed=fixed)


def bound_acb(expr, var, values: dict):
    """``f(z, analytic)`` of ``expr`` in ``var`` with the other symbols at
    ``values`` (symbol -> number): compiled once per (expression, symbols)
    with the parameters as symbols, their exact balls made once per working
    precision, so that a reference evaluated at many points does no SymPy
    work per point (``integrate`` and ``log_end_integral`` take it).
    ``var`` may be a list or tuple of symbols: ``z`` is then a tuple of
    their balls."""
    params = tuple(values)
    several = isinstance(var, (list, tuple))
    F = _compiled(expr, (tuple(var) if several else (var,)) + params, len(params))
    nums = tuple(values[q] for q in params)
    balls: dict = {}

    def f(z, an):
        prec = flint.ctx.prec
        if prec not in balls:
            balls[prec] = tuple(to_acb(v) for v in nums)
        return F((*z, balls[prec]) if several else (z, balls[prec]), an)
    return f


def compile_at(expr, var, values=None):
    """:func:`compile_acb` of ``expr`` in ``var``, or with ``values`` (its
    parameters' numbers) :func:`bound_acb`: compiled once with the
    parameters as symbols."""
    return compile_acb(expr, var) if values is None else bound_acb(expr, var, values)


def is_compiled(e) -> bool:
    """Is ``e`` a compiled integrand (``f(z, analytic)``), not a SymPy expression?"""
    return callable(e) and not isinstance(e, sp.Basic)


def mpf_of_arb(b):
    """An exact arb (a midpoint, radius or end point: ``mid()``, ``rad()``,
    ``lower()``) as the mpf that holds it exactly."""
    if b.is_zero():
        return mpmath.mpf(0)
    man, exp = b.man_exp()
    # the raw mpf man * 2**exp, normalised exactly (no rounding, no change of
    # mpmath's working precision): a tenth of the time of ldexp under a workprec
    return mpmath.mp.make_mpf(from_man_exp(int(man), int(exp)))


# ----------------------------------------------------------------- functions of the end-point forms
class Slope(sp.Function):
    """F(u)/u for a real F with F(0) = 0 exactly (the argument of a
    logarithm that vanishes at a logarithmic end point, divided by the
    distance to it): ``Slope(F, F', u)``.  On balls
    (:func:`compile_acb`): F(z)/z where z excludes 0; on a real ball that
    reaches 0 the mean value theorem, F(u)/u = F'(xi) with xi between 0
    and u, enclosed by F' on the hull of the ball and 0; non-finite on a
    complex ball around 0 (holomorphy is not claimed there)."""
    nargs = 3


class RealAbs(sp.Function):
    """|x| of a real x, whose derivative is sign(x) x' (SymPy's Abs of an
    expression not known to be real differentiates into re and im): only in
    the derivative that bounds a coefficient of a logarithmic end point
    (:func:`~.endpoints._log_end`).  On balls it is non-finite unless x is real (its
    ball's imaginary part exactly 0), so the rule holds wherever it gives
    a bound."""
    nargs = 1

    def fdiff(self, argindex=1):
        return self.args[0] / self


def _slope(F, dF, i):
    """The ball of Slope(F, F', u), u the variable (``i`` None) or the i-th
    of several."""
    def g(z, an):
        w = z if i is None else z[i]
        # next to 0 (|w| < 2^(-prec/2)) F(z)/w would lose more bits to the
        # cancellation in F than the enclosure by F' is wide
        if (0 in w.real and 0 in w.imag) or w.abs_upper() < flint.arb(2) ** (-flint.ctx.prec // 2):
            # F(w)/w = int_0^1 F'(s w) ds lies in the ball F'(hull of w and 0),
            # F holomorphic there (checked: finite with the analytic flag)
            hull = w.union(flint.acb(0))
            at = hull if i is None else z[:i] + (hull,) + z[i + 1:]
            if not F(at, ANALYTIC).is_finite():
                return nan_ball()
            return dF(at, an)
        return F(z, an) / w
    return g
