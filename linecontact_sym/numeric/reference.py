"""The one reference integrator: Arb ball quadrature (python-flint's
``acb.integral``) of an integrand compiled from SymPy, with mpmath as the
recorded fallback.

Every independent reference of the package (the verification of a closed
form against its defining integral, the claims' references, the
Maugis-Dugdale, tangential and stress checks) integrates through
:func:`integrate`.  Where Arb does it, the answer is a *rigorous enclosure*
[mid +/- rad] of the exact integral (for the exact inputs given: a Rational
is its exact value, a float its binary value), not an estimate; where it
cannot, the caller's mpmath quadrature (tanh-sinh) runs instead and the
result says so (``method == "mpmath"``).

How the integrand reaches Arb (:func:`compile_acb`)
    The SymPy expression, in the integration variable only (every other
    symbol replaced by a number), becomes a function ``f(z, analytic)`` of a
    complex ball z.  ``acb.integral`` bounds the error of its Gauss-Legendre
    rules from the integrand on complex neighbourhoods of the path, so the
    integrand must say where it is not holomorphic: with ``analytic`` set,
    sqrt, log, non-integer powers and Abs use Arb's own ``analytic`` flag,
    and every other function with a branch cut (acosh, asin, acos, atanh,
    elliptic K and E, 2F1, Bessel functions of non-integer order, K and Y)
    returns a non-finite ball when the argument's ball touches its cut.
    A Piecewise is decided on the real part of the ball: a ball inside one
    branch's region takes that branch (its analytic continuation), a ball
    that straddles a switch is not holomorphic (non-finite when
    ``analytic``; the union of the branches otherwise, which encloses the
    value of the function there).  The break points a caller gives are hints
    that make the work fast; a switch between them is still integrated
    rigorously (by bisection), only slower.

What Arb cannot do, and what happens then
    A function without an acb counterpart, a singularity at an end point
    that ball arithmetic cannot bound (a log singularity, a removable 0/0),
    or an integral that needs more than :data:`EVAL_LIMIT` evaluations: the
    fallback runs (``fallback()``, an mpmath quadrature of the caller's, or,
    without one, ``mpmath.quad`` of the lambdified integrand over the same
    pieces) and the result carries ``method="mpmath"`` and the reason.

Precision: python-flint's and mpmath's global precisions are never changed
(``flint.ctx.workprec``, :func:`~linecontact_sym.core.precision.workdps`).

>>> import sympy as sp, mpmath
>>> t = sp.Dummy("t")
>>> r = integrate(sp.sqrt(1 - t**2), t, [0, 1], dps=40)     # pi/4: sqrt's branch point at t = 1
>>> r.method, r.digits >= 40
('arb', True)
>>> with mpmath.workdps(50):
...     print(r.contains(mpmath.pi / 4), mpmath.nstr(r.mid, 30))
True 0.78539816339744830961566084582
"""
from __future__ import annotations

import functools
import math
import operator

import flint
import mpmath
import sympy as sp
from mpmath.libmp import from_man_exp

from ..core.conversion import number, to_basic, to_mpf
from ..core.errors import LineContactError
from ..core.precision import workdps

__all__ = ["RefValue", "integrate", "value_at", "estimate", "combine", "lincomb", "quotient_bound",
           "log_end_integral", "bound_acb", "substitute_end", "compile_acb", "to_acb", "mpf_of_arb", "ANALYTIC", "REAL", "ArbUnsupported",
           "EVAL_LIMIT", "ARB", "MPMATH"]

#: the method names a :class:`RefValue` records
ARB = "arb"
MPMATH = "mpmath"

#: work limit of one Arb integral (integrand evaluations): past it the
#: fallback runs.  A smooth piece at 45 digits takes a few hundred.
EVAL_LIMIT = 20000


class ArbUnsupported(LineContactError):
    """The integrand cannot be integrated in Arb (a function without an acb
    counterpart, a symbol left in it): the fallback runs."""


class RefValue(mpmath.mpf):
    """A reference value: an mpmath ``mpf`` (its midpoint, to every bit Arb
    or mpmath computed: arithmetic with it gives plain mpf, so a caller that
    wants a number has one) that also carries ``rad``, ``method`` and
    ``note``.

    ``method == "arb"``: the exact value lies in [mid - rad, mid + rad]
    (a rigorous enclosure).  ``method == "mpmath"``: the value is an
    estimate (tanh-sinh), ``rad`` is 0 (no guarantee is claimed) and
    ``note`` says why Arb was not used."""

    def __new__(cls, mid, rad, method, note="", ball=None):
        obj = mpmath.mpf.__new__(cls)
        obj._mpf_ = mpmath.mpf(mid)._mpf_ if not isinstance(mid, mpmath.mpf) else mid._mpf_
        obj.rad = rad if isinstance(rad, mpmath.mpf) else mpmath.mpf(rad)
        obj.method = method
        obj.note = note
        obj.ball = ball          # the acb ball itself (Arb only), for :func:`combine`
        return obj

    def __reduce__(self):
        return (_refvalue, (self._mpf_, self.rad._mpf_, self.method, self.note))

    @property
    def mid(self):
        """The midpoint as a plain mpf."""
        return _plain(self)

    @property
    def certified(self) -> bool:
        return self.method == ARB

    @property
    def digits(self) -> float:
        """Relative digits the enclosure guarantees (0 for an estimate)."""
        if not self.certified:
            return 0.0
        if self.rad == 0:
            return math.inf
        if self.mid == 0:
            return 0.0
        return max(float(-mpmath.log10(self.rad / abs(self.mid))), 0.0)

    def contains(self, value, slack=0) -> bool:
        """Does the enclosure contain ``value`` (within ``slack``, the
        uncertainty of ``value`` itself)?  For an estimate: True."""
        if not self.certified:
            return True
        with workdps(max(mpmath.mp.dps, 60)):
            return abs(mpmath.mpf(value) - self.mid) <= self.rad + abs(mpmath.mpf(slack))


def _plain(v):
    out = mpmath.mpf.__new__(mpmath.mpf)
    out._mpf_ = v._mpf_
    return out


def _refvalue(mpf_, rad_, method, note):
    return RefValue(_plain(_Raw(mpf_)), _plain(_Raw(rad_)), method, note)


class _Raw:
    def __init__(self, t):
        self._mpf_ = t


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


def _nan():
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
            return _nan()
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
    sp.log: lambda z, an: _nan() if an == REAL and _beyond(z, None, 0) else z.log(analytic=an == ANALYTIC),
    sp.Abs: lambda z, an: z.real_abs(analytic=an == ANALYTIC),
    sp.asin: _cut(lambda z: z.asin(), (None, -1), (1, None), real="asin", slope=_inverse_root_slope),
    sp.acos: _cut(lambda z: z.acos(), (None, -1), (1, None), real="acos", slope=_inverse_root_slope),
    sp.atanh: _cut(lambda z: z.atanh(), (None, -1), (1, None), real="atanh"),
    sp.acosh: _cut(lambda z: z.acosh(), (None, 1), real="acosh", slope=_acosh_slope),
    sp.loggamma: _cut(lambda z: z.lgamma(), (None, 0), real="lgamma"),
    sp.elliptic_k: _cut(lambda m: flint.acb.elliptic_k(m), (1, None)),
    sp.elliptic_e: _cut(lambda m: flint.acb.elliptic_e(m), (1, None)),     # complete E(m) (one argument)
    sp.sign: lambda z, an: _nan() if an == ANALYTIC and _touches(z, 0, 0) else z.real_sgn(),
    sp.Heaviside: lambda z, an: _nan() if an == ANALYTIC and _touches(z, 0, 0) else z.real_heaviside(),
}

# atan and asinh have their branch points at +-i, off the real line: a ball
# near the real segment never reaches them unless it is huge
_UNARY[sp.atan] = lambda z, an: _nan() if an == ANALYTIC and z.imag.abs_upper() >= 1 else z.atan()
_UNARY[sp.asinh] = lambda z, an: _nan() if an == ANALYTIC and z.imag.abs_upper() >= 1 else \
    _mean_value(lambda w: w.asinh(), _asinh_slope, z, ()) if z.imag.abs_upper() < 1 else z.asinh()


def _several(method, cuts):
    """A function of several balls (``method(*balls)``), the k-th guarded by
    the branch cuts ``cuts[k]`` (a tuple of segments; () for none)."""
    def g(args, an):
        if an and any(_guarded(w, an, c) for w, c in zip(args, cuts) if c):
            return _nan()
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
_SEVERAL = {
    "carlson_rf": (_several(flint.acb.elliptic_rf, (_NEG, _NEG, _NEG)), True),
    "carlson_rd": (_several(flint.acb.elliptic_rd, (_NEG, _NEG, _NEG)), True),
    "carlson_rg": (_several(flint.acb.elliptic_rg, (_NEG, _NEG, _NEG)), True),
    "carlson_rj": (_several(flint.acb.elliptic_rj, (_NEG, _NEG, _NEG, _NEG)), True),
    "gamma_ratio": (_several(lambda u, v: v.rgamma() * u.gamma(), ((), ())), True),   # order: see mul
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
                    return _nan()           # a negative base: no real power
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
                    return _nan()
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
                    return _nan()
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
                    return _nan()
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
        if isinstance(e, _RealAbs):
            fx = build(e.args[0])

            def real_abs(z, an):
                v = fx(z, an)
                return _UNARY[sp.Abs](v, an) if v.imag.is_zero() else _nan()
            return real_abs
        if isinstance(e, _Slope):
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
            return _nan()
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
            return _nan()
        acc = vals[maybe[0]]
        for i in maybe[1:]:
            acc = acc.union(vals[i])
        return acc
    return g


def _root(b, an, name):
    """sqrt or rsqrt of the ball ``b`` in mode ``an``."""
    if an == REAL and _beyond(b, None, 0):
        return _nan()
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
        branches.append((build(ex_), None if cond == sp.true else _condition(cond, build)))

    def pw(z, an):
        zr = z if an == REAL else _real_parts(z, several)
        acc = None
        for fb_, fc in branches:
            dec = True if fc is None else fc(zr)
            if dec is False:
                continue
            if dec is None and an == ANALYTIC:
                return _nan()
            val = fb_(z, an)
            acc = val if acc is None else acc.union(val)
            if dec is True:
                return acc
        return acc if acc is not None else _nan()
    return pw


def _condition(c, build):
    if c == sp.true:
        return lambda z: True
    if c == sp.false:
        return lambda z: False
    if isinstance(c, (sp.And, sp.Or)):
        parts = [_condition(t, build) for t in c.args]
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
        inner = _condition(c.args[0], build)
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


# ----------------------------------------------------------------- integration
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


def _compile_at(expr, var, values=None):
    """:func:`compile_acb` of ``expr`` in ``var``, or with ``values`` (its
    parameters' numbers) :func:`bound_acb`: compiled once with the
    parameters as symbols."""
    return compile_acb(expr, var) if values is None else bound_acb(expr, var, values)


def _is_compiled(e) -> bool:
    """Is ``e`` a compiled integrand (``f(z, analytic)``), not a SymPy expression?"""
    return callable(e) and not isinstance(e, sp.Basic)


def _bits(dps: int) -> int:
    return int(math.ceil(dps * math.log2(10)))


def integrate(integrand, var, points, dps: int = 45, fallback=None, eval_limit: int = EVAL_LIMIT,
              crude=None, removable: bool = False, values: dict | None = None) -> RefValue:
    """int over [points[0], points[-1]] of ``integrand`` d``var``, split at
    every point given: a :class:`RefValue`.

    ``integrand``: a SymPy expression in ``var`` alone (all parameters
    already replaced by numbers, exact ones preferably), or a list of them,
    one per piece [points[k], points[k+1]] (a function whose formula
    differs between pieces, |s| written s or -s: no switch to bisect); an
    expression may also be a compiled ``f(z, analytic)`` (:func:`compile_acb`
    with the parameters' balls bound: no SymPy work per call; then
    ``fallback`` is the caller's, and no end point is substituted);
    ``points``: the end points and break points, ascending (SymPy numbers,
    ints, Rationals, mpf); ``dps``: the relative digits asked of the
    enclosure (of the sum; each piece is asked a little more);
    ``fallback``: a callable returning the mpmath estimate (mpf) when Arb
    cannot do it (default: ``mpmath.quad`` of the lambdified integrand over
    the same pieces, at ``dps`` + 10 digits).

    ``crude``: ``crude(z, analytic)``, a bound of the integrand on a ball
    where its own ball is not finite (:func:`quotient_bound`: holomorphic
    where ``analytic`` is set, as ``acb.integral`` asks); ``removable``: from 0, look for a
    removable 0/0 N(t)/t^k of the integrand and take its
    :func:`quotient_bound` (a single piece is then split at its middle: the
    bound next to 0 on one half, an end singularity on the other).

    The result is certified (``method == "arb"``) when every piece's ball
    is finite and the sum's ball is accurate to ``dps`` digits (or its
    absolute radius is below 10**-dps for a value that is 0).

    ``values`` (symbol -> number): the integrand (SymPy) and the points hold
    these parameters as symbols (the points ascending at their values): the
    integrand is compiled once with the parameters as symbols
    (:func:`bound_acb`), and the symbolic work of a singular end point (its
    substitution, the split of its logarithms) is done once per integrand
    and end point and kept (:func:`_log_end`), so that the same integral
    at many parameter values does it once, not at every one.  The result
    is the same enclosure's kind: only where the work is done changes."""
    if values is not None:
        if crude is not None or removable:
            raise ValueError("crude and removable are not taken with values")
        if not all(isinstance(e, sp.Basic) for e in _per_piece(integrand, points)):
            raise ValueError("with values the integrand is SymPy")
        if fallback is None:
            def fallback():
                return _mpmath_integral([e.xreplace(values) for e in _per_piece(integrand, points)], var,
                                        [value_at(p, values) for p in points], dps)
    if removable and crude is None and isinstance(integrand, sp.Basic) and points[0] == 0:
        crude = _removable_quotient(integrand, var)
        if crude is not None and len(points) == 2:
            points = [points[0], sp.sympify(points[1], strict=True) / 2, points[1]]
    try:
        ball = _arb_integral(integrand, var, points, dps, eval_limit, crude, values)
        reason = None
    except ArbUnsupported as exc:
        ball, reason = None, str(exc)
    if ball is not None:
        with flint.ctx.workprec(_bits(dps) + 64):
            mid, rad = mpf_of_arb(ball.real.mid()), mpf_of_arb(ball.real.rad())
        return RefValue(mid, rad, ARB, ball=ball)
    if fallback is None:
        def fallback():
            return _mpmath_integral(integrand, var, points, dps)
    return estimate(fallback, reason or "", dps)


def quotient_bound(numerator, var, rest, order: int = 1):
    """``crude(z, analytic)`` for :func:`integrate`: a bound of
    numerator(t)/t^k * rest(t) (k = ``order``) on a ball z (real or complex)
    next to t = 0, where the numerator has a zero of order >= k at t = 0
    (the caller must know it: the gap's P(s)/s, P(0) = 0), so that the
    quotient has a removable singularity there.

    With r >= |z| (every point of the ball), the numerator is evaluated on
    the disk |w| <= r (a box holding it) with Arb's holomorphy check: a
    finite ball M proves it holomorphic there (a numerator that is not gives
    no bound).  numerator(w)/w^k is then holomorphic on that disk, and by
    the maximum modulus principle at most M/r^k on it, at z too.  ``rest``
    is evaluated on z itself with the ``analytic`` flag given: where it is
    finite, the product is a bound of the integrand on z, and holomorphic
    there when ``analytic`` is set; so ``acb.integral`` may use it on its
    complex neighbourhoods of a piece from 0 (its Gauss-Legendre error
    bound), not only bisect towards 0 with real balls (issue 26: the exact
    cylinder's gap took about 3,200 evaluations a point, about 700 now)."""
    fn, fr = compile_acb(numerator, var), compile_acb(rest, var)

    def crude(z, analytic=False):
        r = z.abs_upper()
        if r == 0:
            return _nan()
        rest_z = fr(z, analytic)
        if not rest_z.is_finite():
            return _nan()
        disk = flint.acb(flint.arb(0, r), flint.arb(0, r))
        M = fn(disk, True)
        if not M.is_finite():
            return _nan()
        b = M.abs_upper() / r**order
        return flint.acb(flint.arb(0, b), flint.arb(0, b)) * rest_z
    return crude


def _removable_quotient(f, var):
    """For an integrand N(t)/(t^k D(t)) with a zero of order >= k of N at
    t = 0 (the printed Eq. (9): P(t)/(t sqrt(a^2 - t^2)); Eq. (10) of the
    exact cylinder: (f'(t)/t ...)/t^2 over a common denominator), the
    bound next to t = 0 (:func:`quotient_bound`; the order is checked
    exactly: N(0) = ... = N^(k-1)(0) = 0); None for any other integrand.
    A factor t^k of the denominator, as it stands or over a common one,
    comes from a power t^-k of the integrand: without one, None at once
    (``together`` of a large integrand was most of this test's CPU)."""
    if not any(p.base == var and p.exp.is_Integer and p.exp < 0 for p in f.atoms(sp.Pow)):
        return None
    for form in (f, None):
        if form is None:
            try:
                form = sp.together(f)
            except (TypeError, ValueError):
                return None
        num, den = sp.fraction(form)
        k = next((int(d.exp) if d.is_Pow else 1 for d in sp.Mul.make_args(den)
                  if d == var or (d.is_Pow and d.base == var and d.exp.is_Integer and d.exp > 0)), 0)
        if k == 0 or k > 4 or not num.has(var):
            continue
        try:
            if any(sp.diff(num, var, j).xreplace({var: sp.S.Zero}) != 0 for j in range(k)):
                continue
        except (TypeError, ValueError, ZeroDivisionError):
            continue
        try:
            return quotient_bound(num, var, var**k / den, order=k)
        except ArbUnsupported:
            continue
    return None


def log_end_integral(p, var, c, other, dps: int = 45) -> RefValue:
    """int over the segment between c and ``other`` (either side of c) of
    p(t) ln|t - c| dt, for p holomorphic next to that segment and finite at
    c (its logarithmic end).  The exponential substitution
    t = c + (other - c) e^(-u), h = |other - c|, makes it

        h int_0^oo p(c + (other - c) e^(-u)) (ln h - u) e^(-u) du,

    an integrand holomorphic next to [0, oo).  Its part p(c) h (ln h - 1)
    is exact; the rest, with p(t) - p(c) in place of p(t), decays like
    u e^(-2u) for p differentiable at c: Arb integrates it on [0, U]
    (Gauss-Legendre, no bisection towards the logarithm, which a
    subtraction bounded crudely next to c would need), and the tail beyond U
    is enclosed by D h e^(-U) (|ln h| + U + 1), D an Arb bound of
    |p(t) - p(c)| on the real segment between c and c + (other - c) e^(-U)
    (U grows until that bound is below the digits asked).
    ``p``: SymPy in ``var`` alone, or compiled (``f(z, analytic)``, see
    :func:`integrate`); a certified :class:`RefValue`, or
    :class:`ArbUnsupported` (p not finite at c, or any part Arb cannot
    enclose): the caller's own route runs.

    >>> t = sp.Dummy("t")
    >>> r = log_end_integral(1 + t, t, sp.Rational(1, 3), 1, 40)
    >>> exact = sp.integrate((1 + t) * sp.log(t - sp.Rational(1, 3)), (t, sp.Rational(1, 3), 1))
    >>> with mpmath.workdps(60):
    ...     print(r.method, r.contains(to_mpf(sp.N(exact, 60))), r.digits > 40)
    arb True True
    """
    goal = _bits(dps)
    f = p if _is_compiled(p) else compile_acb(p, var)
    with flint.ctx.workprec(goal + 30):
        cb, ob = to_acb(_exact(c)), to_acb(_exact(other))
        step = ob - cb
        if not (step.real.abs_lower() > 0 and step.is_finite()):
            raise ArbUnsupported("an empty or unbounded segment next to a logarithmic end")
        h = abs(step.real)
        lnh = h.log()
        try:
            pc = f(cb, False)
            if not pc.is_finite():
                raise ArbUnsupported(f"the integrand has no finite value at its logarithmic end {c}")
            # the size of the integral, to bound the absolute error of the pieces by
            size = ((pc.abs_upper() + 1) * h * (abs(lnh) + 1)).abs_upper()
            tol = flint.arb(2) ** -(goal + 8)
            U, tail = int(math.ceil(((goal + 20) * math.log(2) + math.log(1 + abs(float(lnh.mid())))) / 2)), None
            for _ in range(4):
                end = (cb + step * flint.arb(-U).exp()).real
                D = f(flint.acb(end.union(cb.real)), False) - pc
                tail = D.abs_upper() * h * flint.arb(-U).exp() * (abs(lnh) + U + 1)
                if tail.is_finite() and tail < tol * size:
                    break
                U = U * 3 // 2

            def g(u, an):
                e = (-u).exp()
                return (f(cb + step * e, an) - pc) * (lnh - u) * h * e
            v = flint.acb.integral(g, 0, U, rel_tol=tol, abs_tol=tol * size, eval_limit=EVAL_LIMIT)
        except (ZeroDivisionError, ValueError, TypeError) as exc:
            raise ArbUnsupported(f"Arb could not evaluate the integrand: {exc}") from None
        if not (v.is_finite() and tail is not None and tail.is_finite()):
            raise ArbUnsupported("Arb could not enclose the integral next to a logarithmic end")
        if 0 not in v.imag:
            raise ArbUnsupported(f"the integral is not real: {v}")
        exact = pc * h * (lnh - 1)
        if 0 not in exact.imag:
            raise ArbUnsupported(f"the integrand is not real at its logarithmic end: {pc}")
        total = v.real + exact.real + flint.arb(0, tail.abs_upper())
        if total.rel_accuracy_bits() < goal and total.rad() > flint.arb(2) ** -goal:
            raise ArbUnsupported(f"enclosure too wide: {total.rel_accuracy_bits()} of {goal} bits")
        ball = flint.acb(total)
    with flint.ctx.workprec(goal + 64):
        return RefValue(mpf_of_arb(total.mid()), mpf_of_arb(total.rad()), ARB, ball=ball)


def estimate(fallback, reason: str, dps: int = 45) -> RefValue:
    """The mpmath route, recorded: ``fallback()`` (an mpf) at ``dps`` + 10
    digits as a :class:`RefValue` with ``method == "mpmath"`` and ``reason``."""
    with workdps(dps + 10):
        val = fallback()
        val = val.mid if isinstance(val, RefValue) else +mpmath.mpf(val)
    return RefValue(val, mpmath.mpf(0), MPMATH, reason)


def combine(expr, sym, ref, dps: int = 45) -> RefValue:
    """``expr`` (SymPy, in the symbol ``sym``, or in the list of symbols
    ``sym``; every other value exact) at ``sym`` = the reference ``ref`` (a
    :class:`RefValue`, or a list of them matching the list of symbols):
    rigorous in Arb when every reference is an enclosure (the terms of a
    reference outside its integral: the gap's f(x) - (2/(pi E*)) [P(a)
    acosh(x/a) + x J]; a stress made from the three Flamant components, von
    Mises or the principal shear), else in mpmath, with the first reason a
    reference gives why not."""
    several = isinstance(sym, (list, tuple))
    syms, refs = (list(sym), list(ref)) if several else ([sym], [ref])
    if len(syms) != len(refs):
        raise ValueError(f"{len(refs)} references for {len(syms)} symbols")
    why = next((r.note for r in refs if not r.certified), None)
    note = why if why is not None else next((r.note for r in refs if r.note), "")
    if why is None and all(r.ball is not None for r in refs):
        try:
            with flint.ctx.workprec(_bits(dps) + 64):
                f = compile_acb(expr, syms if several else sym)
                b = f(tuple(r.ball for r in refs) if several else ref.ball, False)
                if b.is_finite() and 0 in b.imag:
                    return RefValue(mpf_of_arb(b.real.mid()), mpf_of_arb(b.real.rad()), ARB, note, ball=b)
        except ArbUnsupported:
            pass
    from .exports import lambdify_mpmath
    with workdps(dps + 10):
        val = mpmath.re(lambdify_mpmath(expr, syms)(*[r.mid for r in refs]))
    return RefValue(+val, mpmath.mpf(0), MPMATH, note or "outer terms not in Arb")


def lincomb(terms, dps: int = 45, note: str = "") -> RefValue:
    """sum(coef * value) for ``terms`` [(coef, value)]: ``coef`` an exact
    number, ``value`` a :class:`RefValue` or an exact SymPy number (a closed
    term beside the integrals: mu p(x) outside the stick zone).  Rigorous in
    Arb when every RefValue is an enclosure, else an mpmath estimate that
    keeps the first reason why not."""
    refs = [v for _, v in terms if isinstance(v, RefValue)]
    why = next((r.note for r in refs if not r.certified), None)
    if why is None and all(r.ball is not None for r in refs):
        try:
            with flint.ctx.workprec(_bits(dps) + 64):
                b = flint.acb(0)
                for c, v in terms:
                    b += to_acb(c) * (v.ball if isinstance(v, RefValue) else to_acb(v))
            if b.is_finite() and 0 in b.imag:
                return RefValue(mpf_of_arb(b.real.mid()), mpf_of_arb(b.real.rad()), ARB, note, ball=b)
        except ArbUnsupported as exc:
            why = str(exc)
    with workdps(dps + 10):
        val = mpmath.fsum(to_mpf(c) * (v.mid if isinstance(v, RefValue) else to_mpf(v)) for c, v in terms)
    return RefValue(val, mpmath.mpf(0), MPMATH, why or note)


def mpf_of_arb(b):
    """An exact arb (a midpoint, radius or end point: ``mid()``, ``rad()``,
    ``lower()``) as the mpf that holds it exactly."""
    if b.is_zero():
        return mpmath.mpf(0)
    man, exp = b.man_exp()
    # the raw mpf man * 2**exp, normalised exactly (no rounding, no change of
    # mpmath's working precision): a tenth of the time of ldexp under a workprec
    return mpmath.mp.make_mpf(from_man_exp(int(man), int(exp)))


def _per_piece(integrand, points):
    """The integrand of each piece (one expression for all, or a list)."""
    if isinstance(integrand, (list, tuple)):
        if len(integrand) != len(points) - 1:
            raise ValueError(f"{len(integrand)} integrands for {len(points) - 1} pieces")
        return list(integrand)
    return [integrand] * (len(points) - 1)


def value_at(e, values):
    """The number a point (or end) that holds parameters has at ``values``
    (SymPy, exact where the values are); ``e`` itself where ``values`` is None."""
    return e if values is None else to_basic(sp.sympify(e, strict=True).xreplace(values))


def _arb_integral(integrand, var, points, dps, eval_limit, crude=None, values=None):
    goal = _bits(dps)
    prec = _bits(dps) + 30 if crude is None else 2 * goal + 40

    def compiled(expr):
        main = expr if _is_compiled(expr) else _compile_at(expr, var, values)
        if crude is None:
            return main

        def f(z, an):
            v = main(z, an)
            return v if v.is_finite() else crude(z, an)
        return f
    fs = {}
    for e in _per_piece(integrand, points):
        if e not in fs:
            fs[e] = compiled(e)
    with flint.ctx.workprec(prec):
        exact = [_exact(p) if values is None else value_at(p, values) for p in points]
        ends = exact if values is None else [sp.sympify(p, strict=True) for p in points]
        total = flint.acb(0)
        tol = flint.arb(2) ** -(goal + 8)

        def piece(fn, lo, hi):
            lo_b, hi_b = to_acb(lo), to_acb(hi)
            _ends_bounded(fn, lo_b, hi_b)
            try:
                v = flint.acb.integral(fn, lo_b, hi_b, rel_tol=tol, eval_limit=eval_limit)
            except (ZeroDivisionError, ValueError, TypeError) as exc:
                raise ArbUnsupported(f"Arb could not evaluate the integrand: {exc}") from None
            if not v.is_finite():
                raise ArbUnsupported("Arb could not bound a piece (a singularity at an end point that "
                                     "ball arithmetic cannot enclose, or the evaluation limit)")
            return v
        for e, lo, hi, lo_s, hi_s in zip(_per_piece(integrand, points), exact[:-1], exact[1:], ends[:-1], ends[1:]):
            try:
                total += piece(fs[e], lo, hi)
            except ArbUnsupported:
                # ``crude`` bounds the integrand next to t = 0 only: a piece from 0 has no other remedy
                if (crude is not None and lo == 0) or not (isinstance(lo, sp.Basic) and isinstance(hi, sp.Basic)) \
                        or not isinstance(e, sp.Basic):
                    raise
                total += _substituted(e, var, lo_s, hi_s, piece, values)
        if 0 not in total.imag:
            raise ArbUnsupported(f"the integral is not real: {total}")
        re_ = total.real
        if not re_.is_finite():
            raise ArbUnsupported("non-finite enclosure")
        if re_.rel_accuracy_bits() < goal and re_.rad() > flint.arb(2) ** -goal:
            raise ArbUnsupported(f"enclosure too wide: {re_.rel_accuracy_bits()} of {goal} bits")
        return total


def _exact(p):
    """A break point as an exact SymPy number where it is one (an mpf is its
    binary value); as given where it is not."""
    try:
        q = number(p) if not isinstance(p, sp.Basic) else p
    except LineContactError:
        return p
    return q if q.is_number and q.is_real is not False else p


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


def substitute_end(expr, var, end, d, q: int = 2):
    """``expr`` d``var`` on the half piece from ``end`` (a root end: a
    radicand vanishing there) to end + d, in var = end + d w^q, w in [0, 1]:
    (the integrand in w, w).  The Jacobian q d w^(q-1) included, a
    Piecewise folded and its branch on the half piece taken, an asin or
    acos at its branch point +-1 there rewritten (:func:`_arcs_at_end`),
    and the powers of w out of each factored radicand (:func:`_root_out`),
    so that they cancel the Jacobian's and the integrand is holomorphic at
    w = 0.
    ``end`` and ``d`` may be symbols (a form made once for many points).
    In a variable without assumptions: SymPy's sign queries on a positive
    one were three quarters of this route's CPU."""
    w = _w
    g = expr.xreplace({var: end + d * w**q}) * q * d * w**(q - 1)
    g = _arcs_at_end(_inside_branch(sp.piecewise_fold(g), w), w)
    g = g.replace(lambda z: z.is_Pow and z.exp.is_Rational and not z.exp.is_Integer and z.base.has(w),
                  lambda z: _root_out(sp.factor(z.base), z.exp, w))
    return sp.expand_mul(g), w


def _substituted(integrand, var, lo, hi, piece, values=None):
    """The piece [lo, hi] whose integrand has an algebraic end-point
    singularity (1/sqrt(a^2 - t^2) at t = a, 1/sqrt(s^2 - b^2) behind a
    break, a power t^beta, -1 < beta < 0, at 0): split at the middle m and,
    on each half with a singular end e, t = e + (m - e) u^q, u in [0, 1],
    q = 2 or from the end's power (:func:`_end_power`): the radicands are
    factored, so that the u^q they vanish with comes out of the root and
    cancels the Jacobian q (m - e) u^(q-1) (ball arithmetic cannot cancel
    0/0 by itself).  A
    logarithmic end point (a log singularity, or logarithms whose infinities
    cancel there) goes to :func:`_log_end`.  A singularity that neither
    removes raises :class:`ArbUnsupported` (the fallback runs).

    ``values``: lo, hi and the integrand hold parameters (see
    :func:`integrate`): the substituted forms are made with the parameters
    and the half piece's length as symbols, once per integrand and end
    (kept), and bound to the numbers here."""
    m = (lo + hi) / 2
    f = _compile_at(integrand, var, values)
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
                f_end, q = _end_power(integrand, var, end)
                g, w = substitute_end(f_end, var, end, far - end, q)
                return piece(compile_acb(g, w), sp.S.Zero, sp.S.One)
            g, w = _root_end_form(integrand, var, end)
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
            raise ArbUnsupported("an end-point singularity that neither the substitution t = e + d u^2 nor the "
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
    """(the integrand in w, w) of :func:`substitute_end` at ``end`` (symbols
    allowed) with the half piece's length the symbol :data:`_DE`: made once
    per (integrand, end).  A Piecewise (whose branch is decided on numbers)
    is not taken."""
    def make():
        if integrand.has(sp.Piecewise):
            raise ArbUnsupported("a Piecewise integrand with parameters: no end substitution made once")
        f_end, q = _end_power(integrand, var, end)
        return substitute_end(f_end, var, end, _DE, q)
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


class _Slope(sp.Function):
    """F(u)/u for a real F with F(0) = 0 exactly (the argument of a
    logarithm that vanishes at a logarithmic end point, divided by the
    distance to it): ``_Slope(F, F', u)``.  On balls
    (:func:`compile_acb`): F(z)/z where z excludes 0; on a real ball that
    reaches 0 the mean value theorem, F(u)/u = F'(xi) with xi between 0
    and u, enclosed by F' on the hull of the ball and 0; non-finite on a
    complex ball around 0 (holomorphy is not claimed there)."""
    nargs = 3


class _RealAbs(sp.Function):
    """|x| of a real x, whose derivative is sign(x) x' (SymPy's Abs of an
    expression not known to be real differentiates into re and im): only in
    the derivative that bounds a coefficient of a logarithmic end point
    (:func:`_log_end`).  On balls it is non-finite unless x is real (its
    ball's imaginary part exactly 0), so the rule holds wherever it gives
    a bound."""
    nargs = 1

    def fdiff(self, argindex=1):
        return self.args[0] / self


def _slope(F, dF, i):
    """The ball of _Slope(F, F', u), u the variable (``i`` None) or the i-th
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
                return _nan()
            return dF(at, an)
        return F(z, an) / w
    return g


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
        f = _compile_at(F, u, at)
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
            q = _Slope(base, sp.diff(base, u), u)
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
        f = _compile_at(expr, u, at)
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
    theorem: :class:`_Slope`), so that the integrand is exactly
    sum_k A_k(u) ln^k u with every A_k finite next to 0.  The integral is

        int_0^1 [g - sum_{k>=1} c_k ln^k u] du + sum_{k>=1} c_k int_0^1 ln^k u du,

    c_k = A_k(0) exact, int_0^1 ln^k u du = (-1)^k k!; next to u = 0 the
    bracket is bounded on a real ball [0, d] (d <= e^-k) by
    sum_k max|A_k'| d |ln d|^k + |A_0| (the ball of A_0), which Arb's
    bisection refines.  :class:`ArbUnsupported` where the integrand does
    not take that form.

    ``values``: the integrand, ``end`` and ``far`` hold parameters (see
    :func:`integrate`): the split (:func:`_log_end_form`) is made once per
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
    bounds = [(k, _compile_at(dA, w, at)) for k, dA in slopes]
    f0 = _compile_at(coef.get(0, sp.S.Zero), w, at)
    kmax = max(consts, default=0)
    # the split form, A_k(u) - c_k and ln u = L apart: composed with u = v^q
    # below, no function's cut is met by a ball that winds around u = 0
    split = _compile_at(coef.get(0, sp.S.Zero) + sum((A - consts[k]) * L**k for k, A in coef.items() if k), [w, L], at)
    q = _LOG_END_POWER

    def crude(ub):
        """The split integrand on a real ball ub of u that reaches 0."""
        dd = ub.real.upper()
        if not dd < flint.arb(-kmax).exp():
            return _nan()
        hull = flint.acb(ub.real.union(flint.arb(0)))
        b = f0(hull, False)
        if not b.is_finite():
            return _nan()
        rad = flint.arb(0)
        if dd > 0:
            lnd = -dd.log()
            for k, fd in bounds:
                M = fd(hull, False)
                if not M.is_finite():
                    return _nan()
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
    total = piece(h, sp.S.Zero, sp.Rational(1, 2)) + piece(_compile_at(g, w, at), u0, sp.S.One)
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
    :class:`ArbUnsupported` where the integrand does not take that form."""
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
        expanded = sp.expand_mul(g.xreplace(logs))
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
        if A.has(_Slope):
            raise ArbUnsupported("a coefficient of the logarithm needs a mean-value quotient")
        c = A.xreplace({w: sp.S.Zero})
        if c.has(sp.nan, sp.zoo, sp.oo, -sp.oo) or (not c.is_number if at is None else c.free_symbols - set(at)):
            raise ArbUnsupported("a coefficient of the logarithm has no value at the end point")
        consts[k] = c
        slopes.append((k, sp.diff(A.replace(lambda z: isinstance(z, sp.Abs), lambda z: _RealAbs(z.args[0])), w)))
    return g, w, L, coef, consts, slopes


def _inside_branch(g, u):
    """A Piecewise integrand of a substituted half piece (u in [0, 1], the
    singular end at u = 0, which is a break point of the caller) replaced
    by the branch that holds on all of [2**-20, 1] (decided on balls: the
    caller's break points are the switch points, so the branch of the open
    half piece is the branch next to its end); :class:`ArbUnsupported` where
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
        test = _condition(cond, lambda e: compile_acb(e, u))
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


def _ends_bounded(f, lo, hi):
    """Fail at once where Arb would spend its evaluation limit in vain: the
    integrand must have a finite ball on a short segment at each end of the
    piece (an integrable 1/sqrt or log singularity there has none; a
    removable one with a ``crude`` bound, a sqrt-type branch point, a
    Piecewise decided next to its switch have one)."""
    eps = (hi - lo) * flint.arb(2) ** -30
    for end in ((lo).union(lo + eps), (hi - eps).union(hi)):
        try:
            v = f(flint.acb(end.real), False)
        except (ZeroDivisionError, ValueError, TypeError):
            v = _nan()
        if not v.is_finite():
            raise ArbUnsupported("Arb cannot bound the integrand next to an end point of a piece (an integrable "
                                 "singularity such as 1/sqrt or log there: ball arithmetic has no finite bound)")


def _mpmath_integral(integrand, var, points, dps):
    from .exports import lambdify_mpmath
    pts = [to_mpf(p) for p in points]
    pieces = _per_piece(integrand, points)
    if all(e is pieces[0] for e in pieces):
        pieces, spans = pieces[:1], [pts]
    else:
        spans = [pts[k:k + 2] for k in range(len(pieces))]
    total = 0
    for e, span in zip(pieces, spans):
        g = lambdify_mpmath(e, [var])

        def h(t, g=g):
            v = g(t)
            return mpmath.re(v) if isinstance(v, mpmath.mpc) and abs(mpmath.im(v)) < mpmath.eps * abs(v) else v
        total += mpmath.quad(h, span)
    return total
