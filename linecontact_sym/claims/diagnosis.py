"""Diagnosis of a formula that does not hold: does it match the engine after a
known transformation, i.e. is it one of the common mistakes?

When a printed form fails at every point, :func:`diagnose` tries, in order,

* ``modulus``: the elliptic modulus k passed where SymPy's ``elliptic_k(m)``,
  ``elliptic_e(m)`` take the parameter m = k**2 (the formula holds after
  ``elliptic_k(z) -> elliptic_k(z**2)``); ``parameter``: the reverse;
* ``swap K E``: the complete elliptic integrals of the first and second kind
  exchanged (alone, or together with the modulus/parameter mix-up);
* ``load``: a quantity written in the load P where the checker takes the
  half-width a: the formula holds after substituting the contact's force law
  P = P(a) (Eq. 10*, derived by the engine);
* ``width``: the contact width 2a used as the half-width a (``a -> a/2``),
  or the reverse;
* ``factor``: a constant factor (2, pi, 1/2, -1, ...): the ratio printed /
  derived is the same number at every sample point; for a sign the message
  names the pull-off / adhesion-force convention.

A candidate counts only when the transformed formula agrees with the derived
value to the checker's 30 digits at the sample points (at most
:data:`POINTS`).  The first rule that matches gives the diagnosis, a
sentence such as "holds with m = k^2: the formula uses the modulus k where
SymPy takes the parameter m = k^2".
"""
from __future__ import annotations

from dataclasses import dataclass

import mpmath
import sympy as sp

from ..core import symbols as S
from ..core.precision import workdps
from .derive import evaluate_point

#: at most this many sample points are used to confirm a candidate
POINTS = 3
#: agreeing digits a transformed formula (or a constant ratio) must reach
DIGITS = 30


@dataclass(frozen=True)
class Diagnosis:
    """A known transformation under which the printed formula holds."""

    rule: str          # 'modulus', 'parameter', 'swap K E', 'load', 'width', 'factor'
    message: str       # one sentence, starting "holds with ..." / "holds up to ..."
    formula: str = ""  # the corrected formula (SymPy syntax), where there is one

    def __str__(self):
        return self.message


def _elliptic(expr, modulus=None, swap=False):
    """Replace elliptic_k/elliptic_e (one argument): ``modulus='square'``
    squares the argument, ``'root'`` takes its square root; ``swap``
    exchanges K and E."""
    K, E = sp.elliptic_k, sp.elliptic_e

    def arg(z):
        if modulus == "square":
            return z**2
        if modulus == "root":
            return sp.sqrt(z)
        return z

    def rep(e):
        if isinstance(e, K):
            return (E if swap else K)(arg(e.args[0]))
        if isinstance(e, E) and len(e.args) == 1:
            return (K if swap else E)(arg(e.args[0]))
        return None
    return expr.replace(lambda e: rep(e) is not None, rep)


def _agrees(derived, expr, points, dps) -> bool:
    if not points:
        return False
    for vals in points:
        pr = evaluate_point(derived, expr, vals, "diagnosis", dps=dps)
        if pr.status != "pass" or pr.digits < DIGITS:
            return False
    return True


def _candidates(claim, printed, force_law):
    """(rule, transformed expression, message) in the order tried."""
    has_ell = printed.has(sp.elliptic_k) or printed.has(sp.elliptic_e)
    if has_ell:
        yield ("modulus", _elliptic(printed, "square"),
               "holds with m = k^2: the formula uses the modulus k where SymPy's elliptic_k(m) and "
               "elliptic_e(m) take the parameter m = k^2 (write elliptic_k(k**2))")
        yield ("parameter", _elliptic(printed, "root"),
               "holds with k = sqrt(m): the formula passes the parameter m = k^2 where the modulus is meant "
               "(SymPy's elliptic_k(m) already takes m; pass k**2 once, not twice)")
        yield ("swap K E", _elliptic(printed, swap=True),
               "holds with K and E swapped: the formula exchanges the complete elliptic integrals of the "
               "first kind K and the second kind E")
        yield ("swap K E", _elliptic(printed, "square", swap=True),
               "holds with K and E swapped and m = k^2: the formula exchanges K and E and uses the modulus k "
               "where SymPy takes the parameter m = k^2")
    if force_law is not None and S.P in printed.free_symbols and not force_law.has(S.P):
        yield ("load", printed.xreplace({S.P: force_law}),
               f"holds with P = {force_law}: the formula is written in the load P; the checker takes the "
               f"half-width a as the variable (substitute the force law P(a), Eq. 10*)")
    if S.a in printed.free_symbols:
        yield ("width", printed.xreplace({S.a: S.a * 2}),
               "holds with a -> 2a: the formula uses the half-width where the contact width 2a is meant")
        yield ("width", printed.xreplace({S.a: S.a / 2}),
               "holds with a -> a/2: the formula uses the contact width 2a where the half-width a is meant")


def _constant_ratio(points_results):
    """The ratio printed/derived if it is the same at every point (None
    otherwise); from the comparisons the checker already made."""
    ratios = []
    for pr in points_results:
        if not pr.comparisons:
            continue
        c = pr.comparisons[0]
        if c.target == 0 or c.printed is None:
            return None
        with workdps(60):
            ratios.append(c.printed / c.target)
    if len(ratios) < 2:
        return None
    with workdps(60):
        r0 = ratios[0]
        if any(abs(r - r0) > abs(r0) * mpmath.mpf(10) ** -DIGITS for r in ratios[1:]):
            return None
    return r0


def identify_constant(r):
    """A short exact form of the number ``r`` (an mpf) built from small
    rationals, pi and square roots, or None.

    ``r`` must carry about 40 digits (the match is to 35):

    >>> with mpmath.workdps(50):
    ...     identify_constant(mpmath.mpf(2)), identify_constant(-mpmath.pi / 2)
    (2, -pi/2)
    >>> with mpmath.workdps(50):
    ...     identify_constant(mpmath.sqrt(2) * mpmath.pi) is not None
    True
    """
    with workdps(50):
        for k in (0, 1, -1, 2, -2):
            for root in (1, 2, 3):
                base = mpmath.pi ** k * mpmath.sqrt(root)
                q = r / base
                for den in range(1, 17):
                    num = q * den
                    if abs(num - mpmath.nint(num)) < mpmath.mpf(10) ** -35 * max(1, abs(num)) and mpmath.nint(num):
                        c = sp.Rational(int(mpmath.nint(num)), den) * sp.pi ** k * sp.sqrt(root)
                        return c
    return None


def diagnose(claim, derived, printed, point_results, force_law=None, dps: int = 45) -> Diagnosis | None:
    """The first known transformation under which ``printed`` equals the
    derived quantity at the sample points (see the module docstring), or
    None.  ``point_results``: the checker's :class:`~.results.PointResult`
    list for this form; ``force_law``: the contact's P(a) for the ``load``
    rule (None: not tried)."""
    pts = [p.values for p in point_results if p.kind == "random"][:POINTS] \
        or [p.values for p in point_results][:POINTS]
    for rule, expr, message in _candidates(claim, printed, force_law):
        if expr == printed:
            continue
        try:
            if _agrees(derived, expr, pts, dps):
                return Diagnosis(rule, message, str(expr))
        except Exception:  # noqa: BLE001 -- a diagnosis is a hint; it must never break a check
            continue
    ratio = _constant_ratio([p for p in point_results if p.status == "fail"])
    if ratio is not None:
        c = identify_constant(ratio)
        if c is not None and c != 1:
            if c == -1:
                msg = "holds with the opposite sign: the formula is minus the derived value"
                if claim.quantity in ("pull_off_force", "adhesion_force"):
                    msg += (" (pull_off_force is the pull-off load P_min < 0, adhesion_force is "
                            "P_adh = -P_min > 0: check which one the formula gives)")
            else:
                msg = f"holds up to a constant factor: the formula is {c} times the derived value"
            corrected = sp.simplify(printed / c)
            if _agrees(derived, corrected, pts, dps):
                return Diagnosis("factor", msg, str(corrected))
    return None


__all__ = ["Diagnosis", "diagnose", "identify_constant", "POINTS", "DIGITS"]
