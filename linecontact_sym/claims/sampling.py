"""Sample points of a claim: exact rationals over its sampling ranges, with its
assumptions enforced."""
from __future__ import annotations

import random

import sympy as sp

from ..core import symbols as S
from ..core.conversion import rational
from ..parsing import t as T_VAR
from .spec import VISCOELASTIC, X_RANGES, Claim


def holds_at(rels, vals) -> bool:
    """Do the relations ``rels`` hold at the point ``vals``?  A relation on
    symbols the point does not fix is skipped.

    >>> import linecontact_sym as lcs
    >>> holds_at([lcs.a < lcs.R], {lcs.a: 1, lcs.R: 2}), holds_at([lcs.a < lcs.R], {lcs.a: 3, lcs.R: 2})
    (True, False)
    """
    for r in rels:
        v = r.xreplace(vals)
        if getattr(v, "free_symbols", None):
            continue          # an assumption on symbols this point does not involve
        try:
            if v in (sp.true, sp.false):
                ok = bool(v)
            else:
                ok = bool(sp.N(v.lhs - v.rhs, 30) < 0) if isinstance(v, (sp.StrictLessThan, sp.LessThan)) \
                    else bool(sp.simplify(v))
        except TypeError:
            return False
        if not ok:
            return False
    return True


def sample_points(claim: Claim, symbols, k: int, seed: int = 2017):
    """Latin-hypercube points (exact rationals) over the sampling ranges, with
    the claim's assumptions enforced (rejection), plus one point near each end
    of every range the claim declares, plus the claim's special values.
    Returns [(kind, {symbol: value})]; x is drawn relative to a where the
    quantity has an x-range (:data:`~.spec.X_RANGES`)."""
    rng = random.Random(seed)
    # t is an integration variable of a printed form, except where it is the time of a history
    syms = sorted((s for s in symbols if s not in ((S.x,) if claim.quantity in VISCOELASTIC else (S.x, T_VAR))),
                  key=lambda z: z.name)
    has_x = S.x in symbols or claim.quantity in X_RANGES
    xr = X_RANGES.get(claim.quantity, (0.02, 0.98))
    perms = {s: rng.sample(range(k), k) for s in syms}
    xperm = rng.sample(range(k), k)
    out = []

    def draw(u_of):
        vals = {}
        for s in syms:
            lo, hi = claim.range_of(s)
            vals[s] = rational(lo + (hi - lo) * u_of(s))
        if has_x and S.a in vals:
            vals[S.x] = rational(float(vals[S.a]) * (xr[0] + (xr[1] - xr[0]) * u_of(S.x)))
        elif has_x:
            lo, hi = claim.range_of(S.x)
            vals[S.x] = rational(lo + (hi - lo) * u_of(S.x))
        return vals

    def accept(vals):
        return holds_at(claim.assumptions, vals)

    for i in range(k):
        for attempt in range(60):
            if attempt == 0:
                u_of = lambda s, i=i: (  # noqa: E731
                    ((perms[s][i] if s in perms else xperm[i]) + rng.uniform(0.15, 0.85)) / k)
            else:
                u_of = lambda s: rng.uniform(0.02, 0.98)  # noqa: E731
            vals = draw(u_of)
            if accept(vals):
                out.append(("random", vals))
                break
    base = out[0][1] if out else None
    for s in syms:
        if s.name in claim.ranges and base is not None:
            lo, hi = claim.ranges[s.name]
            for v in (lo + 0.01 * (hi - lo), hi - 0.01 * (hi - lo)):
                vals = dict(base)
                vals[s] = rational(v)
                if has_x and S.a in vals and s == S.a:
                    vals[S.x] = rational(float(vals[S.a]) * (xr[0] + xr[1]) / 2)
                if accept(vals):
                    out.append((f"end of the range of {s}", vals))
        for v in claim.special.get(s.name, []):
            if base is None:
                continue
            vals = dict(base)
            vals[s] = v
            if accept(vals):
                out.append((f"special value {s} = {v}", vals))
    return out


__all__ = ["holds_at", "sample_points"]
