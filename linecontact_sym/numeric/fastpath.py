"""The float64 path of :func:`~.evaluate.evaluate`, fast for scalars and
vectorised for arrays.

Where the time went (measured on the exact cylinder's pressure, 2.3 ms a
call): nine calls of the NumPy export on 0-d arrays (the value and eight
differences for the condition number; each ~200 us, mostly NumPy's
per-call overhead and the array AGM of the complete Carlson integrals), the
domain check converting every float to SymPy, and a walk of the expression
tree per call.  Here, per derivation and once:

* :class:`ScalarKit` compiles the *same* stable form as the NumPy export into
  a pure-Python function on floats (``math`` and the scalar SciPy special
  functions: ``scipy.special.elliprf`` & co. instead of the array AGM), and
  the sums of :func:`~.exports.cancellation_sums` into a second one;
* the estimate is unchanged: 8 eps max(1, kappa, cancellation) |value|, kappa
  by central differences (step 1e-6 relative, one-sided where one side is not
  finite) of the scalar function -- the estimate ``tests/test_extremes.py``
  checks on the grid of extreme arguments;
* anything the scalar function cannot do (a domain error of ``math``, a
  guarded export, an integral) goes to the NumPy export as before.

:func:`vector_float64` does the same for arrays: one vectorised call for the
values, 2n for kappa, one for the cancellation.
"""
from __future__ import annotations

import math

import functools

import numpy as np
import sympy as sp

from ..core.codegen import compile_function
from ..core.errors import LineContactError
from ..core.lazy import lazy_module
from ..core.printing import lambdify
from .accuracy import FLOAT64_SAFE
from .cache import IdentityCache
from .exports import (fold_constants, is_guarded, mp_hyper_vec, to_scipy_names, cancellation_probe,
                      cancellation_sums, compile_callable, stable_form)
from .special import exp_tail_scalar, np_asinh_excess, np_gamma_ratio, np_hyp2f1c, sin_pi_sum_scalar

__all__ = ["ScalarKit", "scalar_kit", "scalar_plan", "vector_float64", "one_pass", "inline_point", "bound_checks",
           "STEP"]

#: relative step of the central differences for kappa
STEP = 1e-6

sc = lazy_module("scipy.special")     # loaded when a scalar function is first built


@functools.cache
def _scalar_funcs() -> dict:
    """The functions of the scalar float64 path, by their printed names."""
    return {
        "_ellipk": sc.ellipk, "_ellipe": sc.ellipe, "_hyp2f1": sc.hyp2f1, "_hyp1f1": sc.hyp1f1,
        "_hyp0f1": sc.hyp0f1, "_struve": sc.struve,
        "carlson_rf": sc.elliprf, "carlson_rd": sc.elliprd, "carlson_rg": sc.elliprg, "carlson_rj": sc.elliprj,
        "gamma_ratio": lambda u, v: float(np_gamma_ratio(u, v)),
        "hyp2f1c": lambda *a: float(np_hyp2f1c(*a)),
        "exp_tail": exp_tail_scalar,
        "asinh_excess": lambda w: float(np_asinh_excess(w)),
        "sin_pi_sum": sin_pi_sum_scalar,
        "gamma": math.gamma, "loggamma": math.lgamma, "besseli": sc.iv, "besselj": sc.jv,
        # pFq beyond SciPy's 2F1/1F1/0F1 (a sin(x) profile's force law): mpmath, as in the NumPy export
        "_mphyper": lambda *a: float(mp_hyper_vec(*a)),
    }


_CACHE = IdentityCache()
_FAIL = (ValueError, ZeroDivisionError, OverflowError, TypeError)


class ScalarKit:
    """Per derivation: the argument names, the scalar function of the stable
    form (None where it cannot be built: integrals, guarded forms), the scalar
    cancellation probe, and whether the closed form is expensive for the
    model path."""

    def __init__(self, d):
        syms = d.variables_all
        self.names = tuple(s.name for s in syms)
        self.name_set = frozenset(self.names)
        e = d.expr
        self.expensive = (not d.closed_form or e.has(sp.Integral) or e.has(sp.elliptic_k)
                          or e.has(sp.elliptic_e) or e.has(sp.hyper)
                          or any(g.args[0].free_symbols for g in e.atoms(sp.gamma)))
        self.f = self.probe = self.rest = None
        self.exponents = ()        # the monomial factor's exponent of each argument (see _split_monomial)
        self.monomial_kappa = None
        self.rest_index = ()       # the arguments the rest depends on
        if not d.closed_form:
            return
        expr = stable_form(d).expr
        if expr.has(sp.Integral):
            return
        try:
            self.f = lambdify(syms, to_scipy_names(fold_constants(expr)), modules=[_scalar_funcs(), "math"])
            pairs = cancellation_sums(d)
            if pairs:
                tup = to_scipy_names(fold_constants(sp.Tuple(*[q for p in pairs for q in p])))
                self.probe = lambdify(syms, tup, modules=[_scalar_funcs(), "math"], cse=True)
        except Exception:          # a function the math module does not have
            self.f = self.probe = None
            return
        exponents, rest = _split_monomial(expr, syms)
        if exponents is not None:
            try:
                self.rest = None if rest == 1 else \
                    lambdify(syms, to_scipy_names(fold_constants(rest)), modules=[_scalar_funcs(), "math"])
                self.exponents = exponents
                self.rest_index = tuple(i for i, s in enumerate(syms) if rest.has(s))
                # kappa of a pure monomial with no argument 0: a number, found here once
                self.monomial_kappa = sum(abs(e) for e in exponents) if self.rest is None else None
            except Exception:      # the rest does not compile alone: kappa by differences of f
                self.rest, self.exponents, self.monomial_kappa = None, (), None

    @property
    def differences(self) -> bool:
        """Does :meth:`kappa` take differences (then its step matters)?"""
        return not self.exponents or self.rest is not None

    def value(self, vals):
        """f at the floats ``vals`` (positional), or None where it fails."""
        try:
            v = float(self.f(*vals))
        except _FAIL:
            return None
        return v if math.isfinite(v) else None

    def kappa(self, vals, f0, step=None):
        """Componentwise relative condition number sum_i |x_i df/dx_i| / |f|.

        Where f = c x_1^e_1 ... x_n^e_n * rest(x) (:func:`_split_monomial`,
        found once per export), x_i df/dx_i / f = e_i + x_i d(rest)/dx_i / rest:
        exact for the arguments only in the monomial (the parabola's force
        law: kappa = 4 with no evaluation at all), by central differences of
        the rest for the others (relative step ``step``, default :data:`STEP`;
        smaller where a breakpoint lies within the default step).  Otherwise
        central differences of f, as for every argument before."""
        if f0 == 0:
            return math.inf
        if self.monomial_kappa is not None and 0 not in vals:
            return self.monomial_kappa
        STEP_ = STEP if step is None else step
        exps = self.exponents
        if not exps:
            return self._differences(self.value, vals, f0, STEP_, range(len(vals))) / abs(f0)
        total = 0.0
        for i, v in enumerate(vals):
            if v != 0 and i not in self.rest_index:
                total += abs(exps[i])
        if self.rest is None:
            return total
        r0 = self._rest(vals)
        if r0 is None or r0 == 0:          # the rest alone fails here: differences of f, as before
            return self._differences(self.value, vals, f0, STEP_, range(len(vals))) / abs(f0)
        for i in self.rest_index:
            v = vals[i]
            if v == 0:
                continue
            total += abs(exps[i] + self._differences(self._rest, vals, r0, STEP_, (i,), signed=True) / r0)
        return total

    @staticmethod
    def _differences(fn, vals, f0, step, which, signed=False):
        """sum over i in ``which`` of |x_i dfn/dx_i| (``signed``: the one
        term with its sign) by central differences, one-sided where one
        side fails, 0 where both do."""
        total = 0.0
        for i in which:
            v = vals[i]
            if v == 0:
                continue
            shifted = list(vals)
            shifted[i] = v * (1 + step)
            up = fn(shifted)
            shifted[i] = v * (1 - step)
            dn = fn(shifted)
            if up is not None and dn is not None:
                t = (up - dn) / (2 * step)
            elif up is not None:
                t = (up - f0) / step
            elif dn is not None:
                t = (f0 - dn) / step
            else:
                continue
            total += t if signed else abs(t)
        return total

    def _rest(self, vals):
        """The rest of f beyond its monomial factor at the floats ``vals``, or None where it fails."""
        try:
            v = float(self.rest(*vals))
        except _FAIL:
            return None
        return v if math.isfinite(v) else None

    def cancellation(self, vals):
        if self.probe is None:
            return 1.0
        try:
            out = self.probe(*vals)
        except _FAIL:
            return math.inf
        worst = 1.0
        for A, Sm in zip(out[::2], out[1::2]):
            A, Sm = float(A), float(Sm)
            if math.isfinite(A) and math.isfinite(Sm) and A > 0:
                worst = max(worst, A / abs(Sm) if Sm != 0 else math.inf)   # inf: cancelled to 0
        return worst


def _split_monomial(expr, syms):
    """``(exponents, rest)`` with expr = constant * prod(s_i**exponents[i]) * rest,
    the exponents real numbers (a symbolic exponent, a**n, stays in the rest),
    or ``(None, expr)`` where expr is not a product."""
    if not isinstance(expr, sp.Mul) and not (isinstance(expr, (sp.Pow, sp.Symbol))):
        return None, expr
    index = {s: i for i, s in enumerate(syms)}
    exps = [0.0] * len(syms)
    rest = []
    for fac in sp.Mul.make_args(expr):
        if fac.is_number:
            continue
        base, e = fac.as_base_exp()
        if base in index and e.is_number and e.is_real:
            exps[index[base]] += float(e)
        else:
            rest.append(fac)
    return tuple(exps), sp.Mul(*rest)


def scalar_kit(d) -> ScalarKit:
    """The (cached) :class:`ScalarKit` of a derivation."""
    cache = _CACHE.of(d)
    if "kit" not in cache:
        cache["kit"] = ScalarKit(d)
    return cache["kit"]


def vector_float64(d, names, arrays):
    """Float64 values, condition numbers and cancellation ratios of a
    derivation at arrays of arguments (``names`` order, broadcast):
    ``(values, kappa, cancellation)``."""
    f = compile_callable(d, "numpy")
    point = dict(zip(names, arrays))
    with np.errstate(all="ignore"):
        v = np.asarray(f(**point), dtype=float)
        shape = np.broadcast_shapes(v.shape, *[np.shape(a) for a in arrays])
        v = np.broadcast_to(v, shape)
        total = np.zeros(shape)
        for n, arr in zip(names, arrays):
            arr = np.broadcast_to(np.asarray(arr, dtype=float), shape)
            up = np.asarray(f(**{**point, n: arr * (1 + STEP)}), dtype=float)
            dn = np.asarray(f(**{**point, n: arr * (1 - STEP)}), dtype=float)
            d_c = np.abs(up - dn) / (2 * STEP)
            d_u = np.abs(up - v) / STEP
            d_d = np.abs(v - dn) / STEP
            part = np.where(np.isfinite(d_c), d_c, np.where(np.isfinite(d_u), d_u, np.where(np.isfinite(d_d), d_d, 0)))
            total = total + np.where(arr == 0, 0.0, part)
        kappa = np.where(v != 0, total / np.abs(v), np.inf)
        cancel = np.broadcast_to(np.asarray(cancellation_probe(d)(*arrays), dtype=float), shape)
    return v, kappa, cancel


def one_pass(bounds, names, f):
    """For a domain check that is bounds only (``bounds``: name ->
    'positive', 'nonnegative' or 'any', as the contacts layer's scalar plan
    has them; None: not bounds only), the scalar function ``f`` (positional
    floats in ``names`` order) called in one pass over a point:
    ``value(values)`` is f's finite float value when ``values`` has exactly
    these names, each a Python float or int within its bound and none 0,
    else None (the caller then takes its full path, whose check names the
    problem, and which patches a removable point at 0).  None where
    ``bounds`` is None or does not cover ``names``.

    Where ``f`` is a one-line function generated by ``lambdify`` (its source
    is kept for ``inspect``, as SymPy documents), the pass is generated as
    one function with f's expression in it (:func:`_inlined_pass`): the
    same operations on the same floats, without a loop or a call per point
    (the parabola's force: 0.75 -> 0.3 us); else it is the loop below."""
    checks = bound_checks(bounds, names)
    if checks is None:
        return None
    inlined = _inlined_pass(checks, f)
    if inlined is not None:
        return inlined
    n_names, missing = len(names), object()
    lo, hi = FLOAT64_SAFE
    fail = (ValueError, ZeroDivisionError, OverflowError, TypeError)

    def value(values):
        if len(values) != n_names:
            return None
        vals = []
        for n, positive in checks:
            v = values.get(n, missing)
            c = v.__class__
            if c is not float:
                if c is not int:
                    return None                 # a missing name, another number type
                try:
                    v = float(v)
                except OverflowError:
                    return None
            # 0 is left to the full path: a bound 'nonnegative' is then 'positive', 'any' finite and nonzero;
            # so are magnitudes beyond FLOAT64_SAFE (an intermediate power could under/overflow)
            if not (lo <= v <= hi if positive else (v - v == 0.0 and lo <= abs(v) <= hi)):
                return None
            vals.append(v)
        try:
            v = float(f(*vals))
        except fail:
            return None
        return v if v - v == 0 else None
    return value


def bound_checks(bounds, names):
    """(name, positive) per name: the bound test of :func:`inline_point`
    ('positive' and 'nonnegative': 1e-75 <= v <= 1e75, 0 and the magnitudes
    beyond :data:`~.accuracy.FLOAT64_SAFE` being left to the full path; 'any':
    the same on |v|).  None where ``bounds`` is None or does
    not cover ``names`` (no one pass)."""
    if bounds is None or not frozenset(names) <= bounds.keys():
        return None
    return tuple((n, bounds[n] in ("positive", "nonnegative")) for n in names)


def _int_as_float(v):
    """An int as a float (None where it is another type or too large)."""
    if v.__class__ is not int:
        return None
    try:
        return float(v)
    except OverflowError:
        return None


#: the template of :func:`_inlined_pass` (see :func:`inline_point`)
_PASS_TEMPLATE = """
def _lcs_pass(_lcs_values):
    CHECK
    return _lcs_v if _lcs_v - _lcs_v == 0 else None
"""
#: :func:`inline_point`'s block CHECK: the point read (each argument of f: ARG its name in f, NAME the
#: key of the point, BOUND the test of its bound), then f's expression EXPR; FAIL where it is not such a point
_CHECK_TEMPLATE = """
if len(_lcs_values) != _lcs_n:
    return FAIL
try:
    ARG = _lcs_values[NAME]
except KeyError:
    return FAIL
if ARG.__class__ is not float:
    ARG = _lcs_int_as_float(ARG)
    if ARG is None:
        return FAIL
if not BOUND:
    return FAIL
try:
    _lcs_v = EXPR
    if _lcs_v.__class__ is not float:
        _lcs_v = float(_lcs_v)
except _lcs_fail:
    return FAIL
"""
#: 'positive' and 'nonnegative' (0 is left to the full path), 'any' (finite and nonzero)
_BOUND_TESTS = {True: "_lcs_lo <= ARG <= _lcs_hi", False: "ARG - ARG == 0.0 and _lcs_lo <= abs(ARG) <= _lcs_hi"}


def _inlined_pass(checks, f):
    """:func:`one_pass`'s ``value`` generated by :func:`inline_point`."""
    return inline_point(checks, f, _PASS_TEMPLATE, "None")


def inline_point(checks, f, template: str, fail: str, space=None):
    """A function generated from ``template`` (Python source of one ``def``
    named ``_lcs_pass``, its names prefixed ``_lcs_``, a point dict
    ``_lcs_values``) whose line ``CHECK`` becomes the one pass over a point
    (``checks``: (key, positive) per argument of f, in f's order): each
    value read, a float (an int converted; else ``return fail``) within its
    bound, then ``_lcs_v``, the value of f's expression as a float; ``fail``
    (an expression of the template's names) is returned where the point is
    not one of these or f fails there.  f is a one-line function generated
    by ``lambdify`` (a ``def`` of positional arguments returning one
    expression, without ``cse``), whose source SymPy keeps for
    :mod:`inspect`: it is parsed with :mod:`ast` and its expression placed in
    the new function, in f's own namespace (with ``space`` added), so the
    same operations run on the same floats without a call.  The names in the
    code are f's renamed Dummies (:func:`~linecontact_sym.core.printing.lambdify`)
    and the point's keys enter as string constants (AST nodes, not text):
    no user text becomes code; the tree is compiled by
    :func:`~linecontact_sym.core.codegen.compile_function`, which checks
    every node first.  None where f is not such a function."""
    import ast
    import inspect
    try:
        fn = ast.parse(inspect.getsource(f)).body[0]
    except (OSError, TypeError, SyntaxError, IndexError):
        return None
    a = fn.args if isinstance(fn, ast.FunctionDef) else None
    if a is None or len(fn.body) != 1 or not isinstance(fn.body[0], ast.Return) or fn.body[0].value is None \
            or a.vararg or a.kwarg or a.kwonlyargs or a.defaults or a.posonlyargs or len(a.args) != len(checks):
        return None
    args = [x.arg for x in a.args]
    namespace = dict(f.__globals__)
    placeholders = ("ARG", "NAME", "BOUND", "EXPR", "CHECK", "FAIL")
    if any(n.startswith("_lcs_") or n in placeholders for n in list(namespace) + args):
        return None

    class Fill(ast.NodeTransformer):
        def __init__(self, nodes):
            self.nodes = nodes

        def visit_Name(self, node):
            new = self.nodes.get(node.id)
            return node if new is None else ast.copy_location(new(node), node)

    def parsed(text):
        return ast.parse(text, mode="eval").body

    block = ast.parse(_CHECK_TEMPLATE).body
    code = block[:1]                           # the number of keys
    for arg, (name, positive) in zip(args, checks):
        fill = Fill({"BOUND": lambda n, b=_BOUND_TESTS[positive]: Fill(
                         {"ARG": lambda m, v=arg: ast.Name(v, m.ctx)}).visit(parsed(b)),
                     "NAME": lambda n, k=name: ast.Constant(k), "ARG": lambda n, v=arg: ast.Name(v, n.ctx)})
        code.extend(fill.visit(node) for node in ast.parse(ast.unparse(block[1:4])).body)
    code.append(Fill({"EXPR": lambda n: fn.body[0].value}).visit(block[4]))
    Fill({"FAIL": lambda n: parsed(fail)}).visit(ast.Module(body=code, type_ignores=[]))
    module = ast.parse(template)
    func = module.body[0]
    at = next(i for i, st in enumerate(func.body) if isinstance(st, ast.Expr) and isinstance(st.value, ast.Name)
              and st.value.id == "CHECK")
    func.body[at:at + 1] = code
    namespace.update(space or {})
    namespace.update(_lcs_n=len(checks), _lcs_lo=FLOAT64_SAFE[0], _lcs_hi=FLOAT64_SAFE[1],
                     _lcs_int_as_float=_int_as_float,
                     _lcs_fail=(ValueError, ZeroDivisionError, OverflowError, TypeError))
    try:
        return compile_function(module, namespace, "_lcs_pass")
    except LineContactError:        # f's expression holds a node the check does not allow: the loop
        return None


def scalar_plan(nf):
    """The scalar fast path of a float64 export (None where there is none): a
    call whose values are all Python floats (or ints) evaluates the same
    stable form compiled for ``math`` and the scalar SciPy special functions
    (:class:`~.fastpath.ScalarKit`, as :func:`~.evaluate.evaluate` does),
    after the contact's scalar domain check; it returns None (the call takes
    the NumPy path) for anything else: an argument 0 (where a removable
    singularity is patched), a value that is not finite, a guarded export."""
    d = nf.derivation
    if nf.backend != "numpy" or not nf.stable or not d.closed_form or is_guarded(d):
        return None
    kit = scalar_kit(d)
    if kit.f is None or any(type(v) not in (float, int) for v in nf.params.values()):
        return None
    f, names, params = kit.f, kit.names, dict(nf.params)
    if any(not n.isidentifier() for n in names):
        return None
    wanted = frozenset(names) - frozenset(params)
    domain = getattr(nf.domain, "scalar", nf.domain)
    scalar_types = (float, int)
    f64 = np.float64
    bounds = None
    if not params:    # no check (any finite number), or a bounds-only check: one pass (one_pass)
        bounds = dict.fromkeys(names, "any") if nf.domain is None else getattr(nf.domain, "bounds", None)
    checks, one = bound_checks(bounds, names), None

    def fast(kw):
        if one is not None:
            v = one(kw)
            if v is not None:
                return f64(v)
        return general(kw)

    def general(kw):
        if kw.keys() != wanted:
            return None
        for v in kw.values():
            if v.__class__ not in scalar_types or not v:
                return None
        merged = {**params, **kw} if params else kw
        if domain is not None:
            merged = domain(merged)
        try:   # positionally: the compiled arguments are renamed Dummies (core.printing.lambdify)
            v = float(f(*[merged[n] for n in names]))
        except (ValueError, ZeroDivisionError, OverflowError, TypeError, KeyError):
            return None
        return np.float64(v) if math.isfinite(v) else None
    if checks is not None:  # fast generated as one function with f's expression in it (inline_point)
        inlined = inline_point(checks, f, _EXPORT_TEMPLATE, "_lcs_general(_lcs_values)",
                               {"_lcs_f64": f64, "_lcs_general": general})
        if inlined is not None:
            return inlined
        one = one_pass(bounds, names, f)    # f is not a one-line function: the loop
    return fast


#: :func:`scalar_plan`'s ``fast`` where the point is read in one pass, as :func:`inline_point` generates it
_EXPORT_TEMPLATE = """
def _lcs_pass(_lcs_values):
    CHECK
    if _lcs_v - _lcs_v == 0:
        return _lcs_f64(_lcs_v)
    return _lcs_general(_lcs_values)
"""
