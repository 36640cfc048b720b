"""Profiles whose Piecewise switches on the parameters alone
(``Piecewise((x**2/(2*R), R < 1), (x**2, True))``): every case is derived
by the engine as a contact of its own, and the results are joined into one
``Piecewise`` over the cases (:attr:`~linecontact_sym.method.profile.Profile.cases`).

Before, the profile was read in the one case its sample point fell in and the
result carried that case as a condition: the other case's points were
refused (or, through paths that did not look at the conditions, given the
wrong case's number).  Now a result holds for every parameter value; each
case's closed form is verified against the quadrature of its own defining
integral, and the reference of the joined result is the reference of the
case that holds at the point.
"""
from __future__ import annotations

import time

import sympy as sp

from ...core import symbols as S
from ...core.errors import DomainError, LineContactError
from ...method.derivation import Derivation
from ...method.rules import Step
from ...method.verification import VerificationRecord, holds


def case_contacts(contact):
    """``[(condition, LineContact of that case)]``, built once per contact."""
    cache = contact._caches()
    if "_case_contacts" not in cache:
        prof = contact.profile
        out = []
        for cond, expr in prof.cases:
            syms = expr.free_symbols - {S.x}
            params = {p: prof.declared_ranges.get(p) for p in syms}
            try:
                sub = type(contact)(expr, params=params, name=f"{prof.name} where {cond}", budget=contact.budget,
                                  verify=contact.verify, points=contact.points, digits=contact.digits)
            except LineContactError as exc:   # this case is no admissible profile: refused at its points
                sub = exc
            out.append((cond, sub))
        cache["_case_contacts"] = out
    return cache["_case_contacts"]


def _case_at(parts, vals):
    for cond, d in parts:
        if cond == sp.true or holds((cond,), vals):
            return cond, d
    raise DomainError(f"no case of the profile holds at {vals}")


def case_of(contact, values: dict):
    """The contact of the case that holds at ``values`` (by name), for the
    numeric methods of a contact built on a frictionless one (pull_off_at,
    ...); the contact itself when its profile has no cases."""
    base = getattr(contact, "contact", contact)
    if not base.profile.cases:
        return contact
    vals = {p: values[p.name] for p in base.params if p.name in values}
    for cond, sub in case_contacts(base):
        if cond == sp.true or holds((cond,), vals):
            if isinstance(sub, Exception):
                raise DomainError(f"the profile is not admissible in this case ({cond}): {sub}")
            return sub if base is contact else contact.on(sub)
    raise DomainError(f"no case of the profile holds at {values}")


def derive_by_case(contact, name: str) -> Derivation:
    """The derivation of ``name`` joined over the cases of the profile
    (``contact`` a frictionless contact, or one built on it: each case is
    the same kind of contact built on that case's frictionless one)."""
    t0 = time.perf_counter()
    parts = []
    base = getattr(contact, "contact", contact)
    for cond, sub in case_contacts(base):
        if base is not contact and not isinstance(sub, Exception):
            sub = contact.on(sub)
        if isinstance(sub, Exception):
            parts.append((cond, sub))
        else:
            parts.append((cond, sub.derivation(name)))
    ds = [d for _, d in parts if isinstance(d, Derivation)]
    if not ds:
        raise parts[0][1]
    closed = all(isinstance(d, Derivation) and d.closed_form for _, d in parts)
    pairs, conds, shared = [], [], []
    for cond, d in parts:
        e = d.expr if isinstance(d, Derivation) else sp.nan
        pairs.append((e, cond))
        if not isinstance(d, Derivation):
            conds.append(sp.Not(cond) if cond != sp.true else sp.false)
            continue
        for c in d.conditions:
            if c.free_symbols <= {S.x, S.a}:          # the quantity's domain, the same in every case
                if c not in shared:
                    shared.append(c)
            else:
                conds.append(sp.Or(sp.Not(cond), c) if cond != sp.true else c)
    expr = sp.Piecewise(*pairs)
    conditions = tuple(shared) + tuple(c for c in conds if c != sp.true)
    recs = [d.verification for d in ds]
    rec = None
    if recs and all(r is not None for r in recs) and len(ds) == len(parts):
        rec = VerificationRecord(sum((r.points for r in recs), ()), sum((r.digits for r in recs), ()),
                                 min(r.dps for r in recs), "each case against its own reference: "
                                 + "; ".join(r.reference for r in recs), max(r.required for r in recs))
    said = ["derived case by case: " + "; ".join(
        ("otherwise" if c == sp.true else f"where {c}") + ": "
        + (d.rule if isinstance(d, Derivation) else f"not an admissible profile ({d})") for c, d in parts)]
    for n in (n for d in ds for n in d.notes):
        if n not in said:
            said.append(n)
    notes = tuple(said)

    def reference(vals, dps):
        _, d = _case_at(parts, vals)
        if not isinstance(d, Derivation):
            raise DomainError(f"the profile is not admissible in this case: {d}")
        if d.reference is None:
            raise LineContactError(f"the {name} of this case has no reference quadrature")
        return d.reference(vals, dps)
    variables = []
    for v in tuple(v for d in ds for v in d.variables) + tuple(contact.variables):
        if v not in variables:
            variables.append(v)
    step = Step("cases", expr, conditions, notes[:1])
    return Derivation(name, expr=expr, closed_form=closed, step=step, conditions=conditions, verification=rec,
                      seconds=time.perf_counter() - t0 + sum(d.seconds or 0 for d in ds), notes=notes,
                      reference=reference, variables=tuple(variables),
                      attempts=tuple(a for d in ds for a in d.attempts))


__all__ = ["case_contacts", "case_of", "derive_by_case"]
