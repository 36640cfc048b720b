"""Ask for an accuracy, get the cheapest way to it, for the viscoelastic
histories: the force and pressure histories of one half-width history a(t)
as quantities of the package's :func:`~linecontact_sym.numeric.evaluate.evaluate`
(float64 where its estimate meets ``rtol``, mpmath at the digits rtol asks
otherwise, a python-flint Arb ball with ``certified=True``).

``force_history`` / ``pressure_history`` are :class:`~linecontact_sym.method.derivation.Derivation`
objects of the closed forms of :meth:`ViscoelasticLineContact.force_history`
and :meth:`~ViscoelasticLineContact.pressure_history` (variables: t, x for
the pressure, the profile's and the material's parameters, those of the
history).  Their float64 exports are the stable forms
(:func:`~linecontact_sym.numeric.stable.stabilize`: the tails of the
exponential series that the Maxwell terms give at t << tau become
``exp_tail``, :class:`~linecontact_sym.numeric.stable.ExpTail`).

Where SymPy leaves an integral unevaluated, the quantity is that integral:
float64 by the vectorised tanh-sinh quadrature, beyond float64 one Arb
enclosure of the integral (:func:`~linecontact_sym.numeric.reference.integrate`,
a true bound) where Arb evaluates the integrand, else two mpmath
quadratures compared (the path the normal engine's quantities take).
``certified=True`` needs a closed form (as for every quantity of the
package): an unevaluated history is certified on the ``rtol`` path only
when the Arb enclosure succeeds (its ``certified`` flag says so).
"""
from __future__ import annotations

import sympy as sp

from ...core import symbols as S
from ...core.conversion import to_mpf
from ...core.errors import DomainError
from ...core.ranges import check_values
from ...method.derivation import Derivation, fallback_step
from ...method.rulebase import Step
from ...parsing import user_value
from ..base import checked_value
from .history import history_expr

QUANTITIES = ("force_history", "pressure_history", "half_width_history")


def history_quantity(name: str) -> str:
    """The history quantity of a name: 'force' -> 'force_history' (the full names pass)."""
    q = name if name in QUANTITIES else f"{name}_history"
    if q not in QUANTITIES:
        raise DomainError(f"unknown history quantity {name!r}: one of force, pressure, half_width")
    return q


class HistoryQuantities:
    """The histories of the contact ``v`` under the history ``a_t`` (a half-width
    a(t) for the force and the pressure, a load P(t) for the half-width: creep),
    as a 'contact' of :func:`~linecontact_sym.numeric.evaluate.evaluate`
    (``derivation``, ``check_domain``; no series model: ``profile`` None)."""

    profile = None

    def __init__(self, v, a_t):
        self.v, self.history = v, history_expr(a_t)      # text parsed, never evaluated
        self._d = {}

    def derivation(self, quantity: str) -> Derivation:
        if quantity not in QUANTITIES:
            raise DomainError(f"unknown history quantity {quantity!r}: one of {', '.join(QUANTITIES)}")
        if quantity not in self._d:
            v, h = self.v, self.history
            expr = {"force_history": v.force_history, "pressure_history": v.pressure_history,
                    "half_width_history": v.half_width_history}[quantity](h)
            closed = not expr.has(sp.Integral, sp.InverseLaplaceTransform)
            extra = (S.x,) if quantity == "pressure_history" else ()
            params = tuple(sorted((set(v.variables) | h.free_symbols) - {S.t, S.x}, key=lambda s: s.name))
            what = quantity[:-len("_history")]

            def reference(vals, dps, what=what):
                by = {s.name: val for s, val in vals.items()}
                tv, xv = by.pop("t"), by.pop("x", None)
                hist = h.xreplace({s: val for s, val in vals.items() if s in h.free_symbols})
                return v.evaluate_at(what, tv, hist, x=xv, dps=dps, **by)
            step = (Step(f"viscoelastic_{quantity}", expr, (), ("Popov's superposition in time (Lee-Radok, Ting)",))
                    if closed else fallback_step("SymPy leaves the superposition integral unevaluated"))
            self._d[quantity] = Derivation(quantity, expr=expr, closed_form=closed, step=step,
                                           variables=(S.t,) + extra + params, reference=reference)
        return self._d[quantity]

    def check_domain(self, quantity: str, values: dict) -> dict:
        """Finite real values, t >= 0, the parameters positive (as the
        material's and profile's are), checked before anything is derived;
        then every name one the quantity takes."""
        values = {k: user_value(val, k) if isinstance(val, str) else val for k, val in values.items()}   # '1/3': exact
        check_values(values)
        out = dict(values)
        for k, val in values.items():
            val = out[k] = checked_value(k, val, None)   # a finite real number (arrays elementwise): 1j is no time
            try:
                num = to_mpf(val)
            except (TypeError, ValueError):
                continue                  # arrays: checked elementwise by the export (NaN outside)
            if k == "t" and num < 0:
                raise DomainError(f"the time must be >= 0, got t = {val}")
            if k == "x":
                out[k] = abs(val)
            elif k != "t" and num <= 0:
                raise DomainError(f"{k} must be > 0, got {val}")
        names = {s.name for s in self.derivation(quantity).variables_all}
        unknown = sorted(set(values) - names)
        if unknown:
            raise DomainError(f"{quantity} takes no value named {', '.join(map(repr, unknown))}; "
                              f"it takes {', '.join(sorted(names))}")
        return out


__all__ = ["HistoryQuantities", "QUANTITIES", "history_quantity"]
