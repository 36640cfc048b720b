"""The record types of the integration rules: :class:`Problem` (what to
integrate), :class:`Step` (what a rule did), the :class:`Rule` base class
and :class:`NotApplicable`.  The rules themselves are in :mod:`.rules`,
:mod:`.rules_swap` and :mod:`.rules_inverse`; this module is their common
base, so that the rule modules can import it without importing each other.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

TRANSFORMS = ("force", "pressure", "gap", "profile")


class NotApplicable(Exception):
    """The rule does not apply to this problem (the dispatcher tries the next one)."""


@dataclass(frozen=True)
class Problem:
    """One transform to carry out: ``transform`` is one of :data:`TRANSFORMS`;
    ``profile`` the :class:`~linecontact_sym.method.profile.Profile` (force,
    pressure: its breakpoints, gap: f(x)); ``force_law`` P(a) for the
    pressure, the gap and the inverse map (Eq. 9)."""

    transform: str
    profile: object = None
    force_law: sp.Expr | None = None

    def __post_init__(self):
        if self.transform not in TRANSFORMS:
            raise ValueError(f"unknown transform {self.transform!r}; one of {TRANSFORMS}")


@dataclass(frozen=True)
class Step:
    """The record of a successful rule: the closed form ``expr``, the
    relations under which it holds, remarks, and the rule's name."""

    rule: str
    expr: sp.Expr
    conditions: tuple = ()
    notes: tuple = ()

    def describe(self) -> str:
        """'rule: note; note' (for people; programs read the fields)."""
        return self.rule + (": " + "; ".join(self.notes) if self.notes else "")


class Rule:
    """Base of the integration rules (see the module docstring)."""

    name = "rule"
    transform = ""

    def applies(self, problem: Problem) -> str | None:
        """``None`` if the rule may apply, else the reason it does not (cheap)."""
        return None

    def cap(self, problem: Problem) -> float | None:
        """CPU seconds this rule may spend on ``problem`` at most (None: what
        remains of the derivation's budget)."""
        return None

    def run(self, problem: Problem) -> Step:  # pragma: no cover - abstract
        raise NotImplementedError

    def __repr__(self):
        return f"<rule {self.name}>"
