"""The domain of a quantity over array arguments: which points lie outside
it (|x| on the wrong side of a, a condition such as a < R failing).  Those
points are NaN in the result, with a
:class:`~linecontact_sym.core.errors.DomainWarning`; the other points are
evaluated.  A scalar outside the domain raises
:class:`~linecontact_sym.core.errors.DomainError`
(:meth:`~linecontact_sym.contacts.base.Contact.check_domain`).
"""
from __future__ import annotations

import warnings

import numpy as np

from ..core.errors import DomainError, DomainWarning


class DomainValues(dict):
    """What :meth:`Contact.check_domain` returns: the checked values (by
    name), and ``outside``: None, or a boolean array (the broadcast shape of
    the array arguments) marking the points outside the quantity's domain,
    whose results are NaN (:class:`~linecontact_sym.core.errors.DomainWarning`)."""

    outside = None
    why = ""

    def mark(self, mask, why):
        """Add the array points ``mask`` (None: none) that fail for the reason ``why``."""
        if mask is None or not np.any(mask):
            return
        self.outside = mask if self.outside is None else (self.outside | mask)
        self.why = f"{self.why} or {why}" if self.why else why

    def warn(self, name):
        if self.outside is not None:
            warnings.warn(f"{int(np.sum(self.outside))} of {self.outside.size} points of the {name} lie outside "
                          f"its domain ({self.why}): their values are NaN, the others are evaluated",
                          DomainWarning, stacklevel=4)


def x_domain(name, domain, vals, values):
    """x against a for a quantity defined inside or outside the contact: a
    scalar on the wrong side raises; for arrays, ``(mask of the points on the
    wrong side, why)``; replaces x by |x| in ``vals``.  ``(None, '')`` else."""
    if "x" not in vals or "a" not in vals or domain == "any":
        return None, ""
    xv, av = elementwise_abs(vals["x"]), vals["a"]
    bad = xv > av if domain == "inside" else xv < av
    if np.any(bad) and not is_array(bad):
        if domain == "inside":
            raise DomainError(f"x = {values['x']} lies outside the contact |x| <= a = {values['a']}; "
                              f"the {name} is defined inside (use the gap outside)")
        raise DomainError(f"x = {values['x']} lies inside the contact |x| < a = {values['a']}; "
                          f"the {name} is defined outside (zero inside)")
    vals["x"] = xv
    sign = ">" if domain == "inside" else "<"
    return (bad if is_array(bad) else None), f"|x| {sign} a, the {name} is defined {domain} the contact"


def is_array(v):
    return isinstance(v, np.ndarray) and v.ndim > 0


def elementwise_abs(v):
    return np.abs(v) if isinstance(v, np.ndarray) else abs(v)


__all__ = ["DomainValues", "x_domain", "is_array", "elementwise_abs"]
