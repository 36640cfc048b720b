"""Comparisons of the checker remembered, so that a second run does not wait
for the numbers its first run computed.

A comparison at one point (the printed form's value, the derived value, the
first-principles references: 45-digit quadratures, minimisations) is stored
in the derivation store (:mod:`linecontact_sym.method.store`, its key rules:
in this process, and on disk unless the cache is off) under a key of
everything it depends on: the derived record (profile, expression, method,
conditions, notes), the printed form, the point, the digits, and a hash of
the source of the whole package, so a changed reference, evaluator or engine
never meets a value of its predecessor.  The value was computed
independently once; it is read back, not replaced by a cheaper method.
"""
from __future__ import annotations

import hashlib
from pathlib import Path

import mpmath

from ..method import store
from .references import Comparison
from .results import PointResult

__all__ = ["source_version", "point_key", "symbolic_key", "minimum_key", "remembered", "remember"]

_SOURCE: dict = {}


#: files that present, schedule or draw results and compute none of them:
#: editing them keeps the remembered comparisons
_NOT_COMPUTING = ("cli.py", "__main__.py", "views/", "claims/report.py", "claims/figures.py", "claims/batch.py",
                  "core/parallel.py", "core/progress.py")


def source_version() -> str:
    """A hash of the source of every module that computes (the references,
    the engine, the evaluators, the checker; not the CLI, the reports, the
    views or the scheduling): the key part that retires every remembered
    comparison when any of that code changes."""
    if "hash" not in _SOURCE:
        root = Path(__file__).resolve().parent.parent
        h = hashlib.sha256()
        for path in sorted(root.rglob("*.py")):
            rel = path.relative_to(root).as_posix()
            if rel.startswith(_NOT_COMPUTING):
                continue
            h.update(rel.encode())
            h.update(path.read_bytes())
        _SOURCE["hash"] = h.hexdigest()[:16]
    return _SOURCE["hash"]


def point_key(derived, printed_expr, vals, dps, physics):
    """The store key of one comparison, or None when the record cannot be
    keyed (a derived record without an expression or method)."""
    try:
        return store.make_key("claims.point", source_version(), derived.method, derived.profile, derived.expr,
                              tuple(derived.conditions), derived.closed_form, tuple(derived.notes),
                              tuple(sorted(derived.variables, key=str)), printed_expr,
                              dict(vals), int(dps), bool(physics and derived.physics is not None))
    except Exception:  # noqa: BLE001 -- an unkeyable record is simply not remembered
        return None


def minimum_key(derived, profile, vals, dps):
    """The store key of the independent numeric minimum of an adhesive law's
    P(a) at one point (the pull-off claims' reference, which does not depend
    on the printed form: a second claim at the same point, a misprinted
    table entry, reads it back), or None when it cannot be keyed."""
    try:
        return store.make_key("claims.minimum", source_version(), derived.method, profile, derived.expr,
                              tuple(derived.conditions), dict(vals), int(dps))
    except Exception:  # noqa: BLE001 -- an unkeyable record is simply not remembered
        return None


def symbolic_key(printed, derived_expr, vals, budget):
    """The store key of the symbolic comparison of a printed form (its
    verdict depends on the budget it had)."""
    try:
        return store.make_key("claims.symbolic", source_version(), printed, derived_expr,
                              dict(vals) if vals is not None else None, budget)
    except Exception:  # noqa: BLE001
        return None


def _number(v):
    """An mpf as plain data, exactly (mantissa and exponent); other numbers as they are."""
    if isinstance(v, mpmath.mpf):
        if mpmath.isfinite(v):
            sign, man, exp, bc = v._mpf_     # the exact binary value, sign included
            return {"mpf": [int(sign), str(int(man)), int(exp), int(bc)]}
        return {"mpf_text": str(v)}
    return v


def _mpf(v):
    if isinstance(v, dict) and "mpf" in v:
        sign, man, exp, bc = v["mpf"]      # exactly, whatever the working precision (make_mpf does not round)
        return mpmath.mp.make_mpf((int(sign), int(man), int(exp), int(bc)))
    if isinstance(v, dict) and "mpf_text" in v:
        return mpmath.mpf(v["mpf_text"])
    return v


def _record(value):
    """A point's result as the plain data the store keeps (JSON: the store
    unpickles nothing), or the value itself (text)."""
    if isinstance(value, mpmath.mpf):
        return {"number": _number(value)}
    if not isinstance(value, PointResult):
        return value
    comps = [[c.what, _number(c.printed), _number(c.target), _number(c.scale), c.resolution]
             for c in value.comparisons]
    return {"PointResult": [value.kind, value.status, float(value.digits), comps, value.reason]}


def _value(data):
    if isinstance(data, dict) and "number" in data:
        return _mpf(data["number"])
    if isinstance(data, dict) and "PointResult" in data:
        kind, status, digits, comps, reason = data["PointResult"]
        return PointResult({}, kind, status, digits,
                           [Comparison(w, _mpf(p), _mpf(tg), _mpf(s), r) for w, p, tg, s, r in comps], reason)
    return data


def remembered(key, kind):
    """The record of type ``kind`` stored under ``key``, or None (the
    caller puts the point's values back)."""
    if key is None:
        return None
    rec = store.get(key)
    value = _value(rec.get("value")) if rec is not None else None
    return value if isinstance(value, kind) else None


def remember(key, value) -> None:
    if key is not None:
        store.put(key, {"value": _record(value)})
