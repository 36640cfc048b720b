"""The documented grid of extreme arguments, and the points it gives a quantity.

Shared by ``tests/test_extremes.py`` (``tests/conftest.py`` puts this
directory on ``sys.path``) and ``benchmarks/bench.py``.  The grid is keyed to
the seed laws' parameter names (R, b, n, theta ...): it belongs to the
audit of those laws, not to the library (whose generic accuracy tools are in
:mod:`linecontact_sym.numeric.accuracy`).
"""
from __future__ import annotations

import itertools

#: The documented grid of extreme arguments (dimensionless ratios).
EXTREME_GRID = {
    # a/R (cylinders, parabola): from 1e-12 to 1 - 1e-12
    "a_over_R": [1e-12, 1e-8, 1e-4, 1e-2, 0.1, 0.5, 0.9, 0.99, 1 - 1e-4, 1 - 1e-8, 1 - 1e-12],
    # x/a inside the contact (pressure), edge included
    "x_in": [0.0, 1e-12, 1e-8, 1e-4, 0.1, 0.5, 0.9, 0.999, 1 - 1e-8, 1 - 1e-12, 1.0],
    # x/a outside the contact (gap), edge included
    "x_out": [1.0, 1 + 1e-12, 1 + 1e-8, 1 + 1e-4, 1.01, 1.5, 3.0, 10.0, 1e3, 1e6],
    # power-law exponent n, with exactly 1 and 1 +- 1e-9
    "n": [1e-3, 0.01, 0.1, 0.5, 1 - 1e-9, 1.0, 1 + 1e-9, 1.5, 2.0, 2.5, 3.0, 5.0, 10.0, 33.3,
          100.0, 333.0, 1000.0],
    # b/a (worn cylinder flat half-width over contact half-width)
    "b_over_a": [1e-12, 1e-6, 0.1, 0.5, 0.9, 1 - 1e-6, 1 - 1e-12, 1.0, 1.5],
    # 2a/L of a periodic array (period L): from an isolated-like contact to full contact
    # (force, pressure, and the gaps up to full contact: rules asinh-excess, acosh-excess
    # (the sin^4 array), sin-pi-reduction; the gap's x/a runs over x_out up to the crest
    # L/2, e.g. 1 + 1e-8 at 2a/L = 1 - 1e-7)
    "a_over_half_L": [1e-12, 1e-8, 1e-4, 0.1, 0.5, 0.9, 1 - 1e-4, 1 - 1e-7, 1 - 1e-12],
    # 2M/(P w) of a flat punch of half-width w under the load P and the moment M: complete
    # contact (both corners) up to 1, one corner lifted beyond (asymmetric contacts)
    "lift_off_ratio": [0.0, 0.5, 0.9, 1 - 1e-4, 1 - 1e-8, 1 - 1e-12, 1.0, 1 + 1e-12, 1 + 1e-8, 1 + 1e-4, 1.5],
    # the tilt theta of a smooth profile (both edges smooth): the ends differ by nearly nothing
    "tilt": [-1e-4, -1e-8, -2.1e-12, 1e-12, 1e-8, 1e-4, 0.1],
    # (x - left)/(right - left) across an asymmetric contact, both ends approached
    "x_across": [1e-12, 1e-8, 1e-4, 0.1, 0.5, 0.9, 1 - 1e-4, 1 - 1e-8, 1 - 1e-12],
    # absolute scales the ratios are applied at
    "a": [1e-3, 1.0, 7.5],
    # viscoelastic histories: t/tau (t << tau: the Maxwell terms' exp tails cancel in the
    # plain form; t >> tau: relaxed), at the relaxation times tau (tau -> 0 and tau -> oo
    # at a fixed t are the two ends of t/tau at these scales)
    "t_over_tau": [1e-12, 1e-8, 1e-4, 1e-2, 0.5, 1.0, 2.0, 30.0, 1e4, 1e8, 1e12],
    "tau": [1e-6, 1.0, 1e6],
    # the weight of a second Prony term relative to the first (a tiny weight: 1e-12)
    "prony_weight": [1e-12, 1e-4, 1.0],
    # Ting's receding phase of a = r t then r (2 t1 - t): t1/tau, and (t - t1)/t1 in (0, 1)
    "t1_over_tau": [1e-12, 1e-6, 1e-2, 1.0, 1e2, 1e6],
    "receding": [1e-8, 0.1, 0.5, 0.9, 1 - 1e-6],
}


def viscoelastic_points(names, size: str = "full"):
    """Points of :data:`EXTREME_GRID` for a force history P(t) at a constant
    rate of a (argument names ``names``): t = (t/tau) tau over the grid of
    t/tau and tau; a second relaxation time tau_2 = 10 tau (Prony), its weight
    E_2 = w E0 over ``prony_weight``; other parameters one generic value
    (r = 0.1, R = 2, c = 1.3, theta = 0.3, E0 = 2, E_inf = 0.5).  ``size='small'``:
    one tau.  With a maximum time t1 among ``names`` (a = r t, then r (2 t1 - t)):
    the receding phase t = t1 (1 + f) over ``t1_over_tau`` and ``receding`` at tau = 1."""
    G = EXTREME_GRID
    if "t1" in names:           # Ting's receding phase, t = t1 (1 + f)
        return [{k: v for k, v in {"t": u * (1 + f), "t1": u, "tau": 1.0, "r": 0.1, "R": 2.0, "E0": 2.0}.items()
                 if k in names} for u in G["t1_over_tau"] for f in G["receding"]]
    taus = G["tau"] if size == "full" else [1.0]
    weights = G["prony_weight"] if "E_2" in names else [None]
    pts = []
    for tau, u, w in itertools.product(taus, G["t_over_tau"], weights):
        pt = {"t": u * tau, "tau": tau, "tau_1": tau, "tau_2": 10 * tau, "r": 0.1, "R": 2.0, "c": 1.3,
              "theta": 0.3, "E0": 2.0, "E_1": 2.0, "E_inf": 0.5}
        if w is not None:
            pt["E_2"] = w * 2.0
        pts.append({k: pt[k] for k in names if k in pt})
    return pts


def extreme_points(names, quantity: str, size: str = "full"):
    """Points of :data:`EXTREME_GRID` for a quantity with arguments ``names``
    (symbol names).  Ratios are applied to the half-width ``a``: R = a/(a/R),
    b = (b/a) a, x = (x/a) a.  Other parameters get one generic value
    (E_star = 2, c = 1.3, theta = 0.3, h = 0.3); a periodic array's period
    L = 2a/(2a/L), its gap at a < x <= L/2.  ``size='small'`` thins the grid (for
    quantities that only have a quadrature)."""
    G = EXTREME_GRID
    thin = (lambda L, k: L[::k] if size == "small" else L)
    lists = {}
    lists["a"] = G["a"][1:] if quantity != "force" else G["a"]
    if size == "small":
        lists["a"] = [1.0]
    if "R" in names:
        lists["a/R"] = G["a_over_R"] if quantity == "force" else [1e-8, 0.5, 1 - 1e-8]
        if size == "small":
            lists["a/R"] = [1e-4, 0.5, 0.99]
    if "b" in names:
        lists["b/a"] = G["b_over_a"] if size != "small" else [1e-6, 0.5, 1 - 1e-6, 1.5]
    if "n" in names:
        lists["n"] = G["n"] if quantity == "force" else [n for n in G["n"] if n not in (0.01, 2.5, 33.3)]
    if "L" in names:
        lists["2a/L"] = G["a_over_half_L"] if size != "small" else [1e-4, 0.5, 1 - 1e-7]
    if "x" in names:
        lists["x/a"] = thin(G["x_in"] if quantity == "pressure" else G["x_out"], 2)
        if "L" in names and quantity != "pressure":     # a < |x| <= L/2: 1 + 1e-12 ... 1.5
            lists["x/a"] = [r for r in G["x_out"][:5]] + [1.5]
    if quantity != "force" and "R" not in names and "b" not in names:
        lists["a"] = [1.0]
    keys = list(lists)
    pts = []
    for combo in itertools.product(*[lists[k] for k in keys]):
        d = dict(zip(keys, combo))
        a_ = d["a"]
        pt = {"a": a_}
        if "a/R" in d:
            pt["R"] = a_ / d["a/R"]
        if "b/a" in d:
            pt["b"] = d["b/a"] * a_
        if "n" in d:
            pt["n"] = d["n"]
        if "2a/L" in d:
            pt["L"] = 2 * a_ / d["2a/L"]
        if "x/a" in d:
            pt["x"] = d["x/a"] * a_
            if "L" in pt and pt["x"] > pt["L"] / 2:
                continue                # beyond the crest: the next period's contact
        for nm, val in (("E_star", 2.0), ("c", 1.3), ("theta", 0.3), ("h", 0.3)):
            if nm in names:
                pt[nm] = val
        pts.append({k: pt[k] for k in names if k in pt})
    return pts


def asymmetric_points(given: str, size: str = "full"):
    """Points of an asymmetric state's pressure: ``given`` 'lift_off_ratio'
    (the flat punch, M = ratio P w/2) or 'tilt' (a smooth profile), each
    with u = (x - left)/(right - left) of :data:`EXTREME_GRID`; the caller
    places x in the contact of its state.  ``size='small'`` thins the grid
    to the transition (or the smallest tilts) and the ends."""
    G = EXTREME_GRID
    given_values, us = G[given], G["x_across"]
    if size == "small":
        given_values = [1 - 1e-12, 1.0, 1 + 1e-8] if given == "lift_off_ratio" else [-2.1e-12, 1e-8]
        us = [1e-12, 1e-4, 0.5, 1 - 1e-8]
    return [{given: g, "u": u} for g in given_values for u in us]
