"""What a user gets from ``to_numeric``: a :class:`NumericFunction`, the
compiled derivation (:mod:`.exports`) behind the contact's domain check, with
the scalar fast path of :mod:`.fastpath` for calls on plain Python numbers."""
from __future__ import annotations

from decimal import Decimal

import numpy as np

from ..core.errors import DomainError, LineContactError, singular_point
from ..core.units import is_quantity, with_unit
from .exports import compile_callable
from .fastpath import scalar_plan

__all__ = ["make_callable", "NumericFunction", "fold_x"]


def make_callable(derivation, backend: str = "numpy", dps: int = 30, params: dict | None = None,
                  stable: bool = True, domain=None, inputs=None):
    """A callable ``fn(**values)`` evaluating a derived quantity.

    ``derivation``: a :class:`~linecontact_sym.method.derivation.Derivation`
    (its ``expr``, ``variables_all``, ``closed_form``, ``quantity`` and, for
    quantities without a closed form in mpmath, ``reference`` are used).
    Keyword arguments are the symbol names (``a``, ``x``, ``E_star``, ``R``
    ...); ``params`` fixes some of them once; a missing or unknown name raises
    :class:`~linecontact_sym.core.errors.DomainError`.  ``backend='numpy'``:
    vectorised float64, arrays broadcast (:func:`lambdify_numpy`, compiled
    once per derivation); ``'mpmath'``: scalars at ``dps`` digits (the closed
    form, or the derivation's reference quadrature).  ``stable`` (default True)
    evaluates the stable form (:mod:`linecontact_sym.numeric.stable`).
    Domain: the quantity's (e.g. a > 0, |x| <= a for a pressure); outside it
    the value is NaN or complex, not an error.  ``fn.arguments`` lists the
    names.  ``inputs`` (a contact's ``ExportInputs``): the arguments'
    treatment before anything else, checked or not: pint quantities
    converted to SI (the result then a quantity), x folded to |x| for a
    quantity even in x.

    >>> import sympy as sp
    >>> from linecontact_sym.core.symbols import a, E_star
    >>> from linecontact_sym.method.derivation import Derivation
    >>> from linecontact_sym.method.rules import Step
    >>> R = sp.Symbol("R", positive=True)
    >>> P_expr = sp.pi * E_star * a**2 / (4 * R)                                   # Eq. (13)
    >>> d = Derivation("force", expr=P_expr, closed_form=True, step=Step("example", P_expr))
    >>> P = make_callable(d)
    >>> P.arguments
    ('E_star', 'R', 'a')
    >>> P(a=[0.1, 0.2], R=1.0, E_star=2.0)
    array([0.01570796, 0.06283185])
    >>> import mpmath
    >>> mpmath.nstr(make_callable(d, "mpmath", dps=25, params={"R": 1, "E_star": 4})(a=1), 25)
    '3.141592653589793238462643'
    """
    if backend not in ("numpy", "mpmath"):
        raise LineContactError(f"unknown backend {backend!r}; use 'numpy' or 'mpmath'")
    import sympy as sp
    if not isinstance(derivation.expr, sp.Expr):       # a system of equations (the MD force with its c_D)
        raise LineContactError(f"the {derivation.quantity} is not one expression but {type(derivation.expr).__name__} "
                               f"{str(derivation.expr)[:160]}; it has no export of its own: evaluate it through "
                               f"its contact's numeric methods (e.g. the Maugis-Dugdale state(a, ...))")
    return NumericFunction(derivation, backend, dps, dict(params or {}), stable, domain, inputs)


def fold_x(v):
    """|v| of a number, an array, a list of numbers or a pint quantity (other
    values as given: the checks that follow name them).  A Decimal keeps
    every digit (``copy_abs``: ``abs`` rounds to the decimal context's
    precision, 28 digits by default)."""
    if isinstance(v, bool):
        return v
    if isinstance(v, Decimal):
        return v.copy_abs()
    if isinstance(v, (list, tuple)):
        try:
            return np.abs(np.asarray(v, dtype=float))
        except (TypeError, ValueError):
            return v
    try:
        return abs(v)
    except TypeError:
        return v


class NumericFunction:
    """What :func:`make_callable` returns: ``fn(**values)``, with
    ``fn.arguments`` (the names) and a docstring naming the formula.

    Pickles (for multiprocessing, disk): its state is the derivation, the
    backend, ``dps``, the fixed ``params`` and ``stable``; the compiled
    function is built again on the first call after unpickling.  The mpmath
    function of a quantity without closed form evaluates the derivation's
    reference quadrature, a closure that does not pickle: pickling it raises
    :class:`~linecontact_sym.core.errors.LineContactError` (pickle the contact
    and export again)."""

    def __init__(self, derivation, backend, dps, params, stable, domain=None, inputs=None):
        self.derivation, self.backend, self.dps = derivation, backend, dps
        self.params, self.stable, self.domain = params, stable, domain
        self.inputs = inputs
        self._fold = inputs is not None and inputs.fold_x
        self.arguments = tuple(s.name for s in derivation.variables_all)
        self.__doc__ = (f"{derivation.quantity} ({backend}); arguments: {', '.join(self.arguments)}.\n"
                        f"Formula: {derivation.expr}\nMethod: {derivation.method}")
        self._fn = compile_callable(derivation, backend, dps, params, stable)
        self._scalar = None   # the scalar fast path, built on the first call

    def __call__(self, *args, **kw):
        if self._fold and "x" in kw:         # an even quantity of x: the closed form holds for x > 0
            kw["x"] = fold_x(kw["x"])
        if not args:
            fast = self._scalar
            if fast is None:
                fast = self._scalar = scalar_plan(self) or False
            if fast:
                v = fast(kw)
                if v is not None:
                    return v
        if args:
            raise DomainError(f"{self.derivation.quantity} takes keyword arguments only: "
                              f"fn({', '.join(n + '=...' for n in self.arguments)})")
        registry = unit = None
        if self.inputs is not None and (self.inputs.has_units or any(is_quantity(v) for v in kw.values())):
            kw, registry, unit = self.inputs.strip(kw)    # checked against their units, in SI
        kw = {k: v[()] if isinstance(v, np.ndarray) and v.ndim == 0 else v for k, v in kw.items()}
        if self.backend == "mpmath" and any(isinstance(v, (list, tuple, np.ndarray)) for v in kw.values()):
            raise DomainError(f"the mpmath function of {self.derivation.quantity} takes scalars; use "
                              f"backend='numpy' for arrays (or loop over the points)")
        outside = None
        if self.domain is not None:          # the contact's domain check (raises DomainError)
            outside = getattr(self.domain({**self.params, **kw}), "outside", None)
        if self._fn is None:
            self._fn = compile_callable(self.derivation, self.backend, self.dps, self.params, self.stable)
        try:
            out = self._fn(**kw)
        except (ZeroDivisionError, OverflowError) as exc:   # mpmath at a singular point
            raise singular_point(self.derivation.quantity, kw, exc) from None
        if outside is not None:              # array points outside the domain (a DomainWarning said so)
            out = np.array(np.broadcast_to(out, np.broadcast_shapes(np.shape(out), outside.shape)), dtype=float)
            out[np.broadcast_to(outside, out.shape)] = np.nan
        if registry is not None:
            return with_unit(out, unit, registry)
        return out

    def __getstate__(self):
        if self.backend == "mpmath" and not self.derivation.closed_form:
            raise LineContactError(f"the mpmath function of {self.derivation.quantity} (no closed form) "
                                   f"evaluates a reference quadrature that does not pickle; pickle the "
                                   f"contact and export again")
        state = dict(self.__dict__)
        state["_fn"] = None
        state["_scalar"] = None
        return state

    def __repr__(self):
        return f"<{self.derivation.quantity} ({self.backend}) of {', '.join(self.arguments)}>"
