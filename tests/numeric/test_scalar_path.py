"""The series model's choice of terms (evaluate's model path) is the one of the
former O(N^2) scan: same N, partial sum, bound and ratio on random term lists."""
import random

import pytest

from linecontact_sym.numeric.evaluate import SeriesModel


def _choose_reference(t, rtol):
    """The former implementation, kept here as the reference."""
    sign0 = (t[0] > 0) - (t[0] < 0)
    if any((v > 0) - (v < 0) != sign0 for v in t if v != 0):
        return None
    mags = [abs(v) for v in t]
    if any(m == 0 for m in mags):
        return None
    r = [mags[j + 1] / mags[j] for j in range(len(mags) - 1)]
    jl = len(r) - 1
    r_inf = r[jl] + (r[jl] - r[jl - 1]) * jl
    partial = 0
    for N in range(1, len(t) - 2):
        partial += t[N - 1]
        tail_r = r[N:]
        if any(tail_r[i + 1] < tail_r[i] * (1 - 1e-12) for i in range(len(tail_r) - 1)):
            continue
        rb = max(r_inf, r[-1]) * (1 + 1e-3)
        if rb >= 1:
            return None
        bound = mags[N] / (1 - rb)
        if bound <= rtol / 2 * abs(partial):
            return N, partial, bound, float(rb)
    return None


def test_choice_unchanged():
    rng = random.Random(22)
    model = SeriesModel.__new__(SeriesModel)
    seen = 0
    for _ in range(3000):
        n = rng.randint(6, 40)
        q = rng.uniform(0.01, 0.99)
        t = [rng.choice([1, -1]) if rng.random() < 0.02 else 1.0]
        for k in range(1, n):
            # mostly rising ratios towards q (hypergeometric-like), sometimes a dip
            ratio = q * (1 - 1 / (k + 2)) * (rng.uniform(0.9, 1.0) if rng.random() < 0.2 else 1.0)
            t.append(t[-1] * ratio)
        rtol = 10 ** rng.uniform(-16, -2)
        got = model.choose({}, rtol, t)
        assert got == _choose_reference(t, rtol)
        seen += got is not None
    assert seen > 100


def test_scalar_calls_take_the_scalar_path(monkeypatch):
    """A call on Python floats is served by the scalar plan (the compiled
    stable form called positionally: its arguments are renamed Dummies), not
    by the NumPy path and the full domain check: with both made to fail, a
    valid scalar call still returns the closed form's value."""
    import mpmath
    import linecontact_sym as lcs
    from linecontact_sym.contacts.base import Contact

    f = lcs.exact_cylinder().to_numeric("force")
    f(a=0.5, R=1.0, E_star=1.0)                       # builds the plan (and the point's admissibility)

    def no(*a, **k):
        raise AssertionError("the scalar call took the slow path")
    monkeypatch.setattr(Contact, "check_domain", no)
    monkeypatch.setattr(f, "_fn", no)
    with mpmath.workdps(30):                          # P = E* R (K(m) - E(m)), m = (a/R)^2
        ref = mpmath.ellipk(mpmath.mpf(1) / 4) - mpmath.ellipe(mpmath.mpf(1) / 4)
    assert abs(f(a=0.5, R=1.0, E_star=1.0) - float(ref)) <= 4e-16 * float(ref)


@pytest.mark.slow
def test_condition_number_from_the_monomial_factor_equals_the_differences():
    """kappa found once per export from f = c x^e * rest (exact for the
    monomial's arguments, differences of the rest) equals the central
    differences of f (the former way) at random points: the parabola's force
    law needs no evaluation at all (kappa = 4), the cylinder's differences
    of its Carlson factor only, the power law's of a**n * gamma_ratio."""
    import linecontact_sym as lcs
    from linecontact_sym.numeric.fastpath import STEP, scalar_kit

    rng = random.Random(5)
    for law, q in (("parabola", "force"), ("exact_cylinder", "force"), ("power_law", "force"),
                   ("parabola", "pressure"), ("exact_cylinder", "pressure"), ("worn_cylinder", "force")):
        kit = scalar_kit(getattr(lcs, law)().derivation(q))
        if law == "parabola" and q == "force":
            assert kit.rest is None and not kit.differences and kit.exponents
        if law == "exact_cylinder" and q == "force":
            assert kit.rest is not None and {kit.names[i] for i in kit.rest_index} == {"a", "R"}
        for _ in range(20):
            vals = {"a": rng.uniform(0.05, 0.95), "R": rng.uniform(1.0, 3.0), "E_star": rng.uniform(0.5, 2),
                    "n": rng.uniform(0.5, 4), "c": rng.uniform(0.5, 2), "b": rng.uniform(0.01, 0.04)}
            vals["x"] = vals["a"] * rng.uniform(-0.9, 0.9)
            v = [vals[n] for n in kit.names]
            f0 = kit.value(v)
            ref = kit._differences(kit.value, v, f0, STEP, range(len(v))) / abs(f0)
            got = kit.kappa(v, f0)
            assert abs(got - ref) <= 1e-5 * ref + 1e-8, (law, q, got, ref)


@pytest.mark.slow
def test_model_ratio_plan_chooses_as_the_general_scan():
    """The exact cylinder's series model: its term ratios are q_j (a/R)^2,
    found once; the choice of N at a point (and the value, to a few ulps,
    and the bound) is the one of the general scan over 40 computed terms."""
    import linecontact_sym as lcs
    from linecontact_sym.numeric.evaluate import _model, _try_model

    c = lcs.exact_cylinder()
    c.derivation("force")
    m = _model(c)
    assert m._ratios is not None and str(m._ratios.rho(2.0, 1.0, 4.0)) in ("0.25", "4.0")
    plan = m._ratios
    rng = random.Random(3)
    for _ in range(60):
        vals = dict(a=10 ** rng.uniform(-7, -0.05), R=rng.uniform(0.5, 2.0), E_star=rng.uniform(0.5, 2.0))
        vals["a"] *= vals["R"]
        rtol = 10 ** rng.uniform(-13.5, -2)
        fast = _try_model(m, "force", vals, rtol, 0.0)
        m._ratios = None
        try:
            slow = _try_model(m, "force", vals, rtol, 0.0)
        finally:
            m._ratios = plan
        assert (fast is None) == (slow is None), vals
        if fast is not None:
            assert fast.details["terms"] == slow.details["terms"]
            assert abs(fast.value - slow.value) <= 8 * 2.2e-16 * abs(slow.value)
            assert slow.error * (1 - 1e-9) <= fast.error <= 1.01 * slow.error + 1e-15 * abs(slow.value)


@pytest.mark.slow
def test_contact_evaluate_plan_is_the_general_path(monkeypatch):
    """``contact.evaluate`` at plain numbers runs the scalar plan found once
    per quantity (numeric.evaluate.scalar_evaluator); it returns what
    numeric.evaluate.evaluate returns (path, value, error, note: the model,
    float64 and mpmath switches alike), raises the same domain errors, and
    leaves the general function alone when it applies."""
    import linecontact_sym as lcs
    from linecontact_sym.contacts import base
    from linecontact_sym.core.errors import DomainError
    from linecontact_sym.numeric.evaluate import evaluate

    rng = random.Random(11)
    cases = [(lcs.parabola(), "force", {}), (lcs.parabola(), "pressure", {}),
             (lcs.exact_cylinder(), "force", {}), (lcs.worn_cylinder(), "force", {"b": 0.02})]
    for c, q, extra in cases:
        for rtol in (1e-3, 1e-12, 1e-14, None):
            for _ in range(3):
                a = rng.uniform(0.05, 0.9)
                vals = dict(a=a, R=rng.choice([1, 1.5]), E_star=rng.uniform(0.5, 2.0), **extra)
                if q == "pressure":
                    vals["x"] = a * rng.uniform(-0.95, 0.95)
                got = c.evaluate(q, rtol=rtol, **vals)
                ref = evaluate(c, q, rtol=1e-12 if rtol is None else rtol, **vals)
                assert (got.path, got.value, got.error, got.rtol, got.note) == \
                    (ref.path, ref.value, ref.error, ref.rtol, ref.note), (q, rtol, vals)
        with pytest.raises(DomainError) as e1:
            c.evaluate(q, rtol=1e-12, **dict(vals, a=-0.5))
        with pytest.raises(DomainError) as e2:
            evaluate(c, q, rtol=1e-12, **dict(vals, a=-0.5))
        assert str(e1.value) == str(e2.value)
    # the plan alone serves a float call: the general function is not called
    c = lcs.exact_cylinder()
    c.evaluate("force", rtol=1e-12, a=0.3, E_star=1.7, R=1.0)

    def no(*a, **k):
        raise AssertionError("the scalar call took the general path")
    monkeypatch.setitem(base._NUMERIC, "evaluate", no)
    r = c.evaluate("force", rtol=1e-12, a=0.31, E_star=1.7, R=1.0)
    assert r.path.startswith("model:") and r.rel_error <= 1e-12
    assert c.evaluate("force", rtol=1e-12, a=0.31, E_star=1.7, R=1.0).note.startswith("series of P(a)")


def test_monomial_one_pass_is_the_general_path():
    """The parabola's force (a monomial, a bounds-only domain check) runs in
    one pass (numeric.evaluate.scalar_evaluator's lean loop): the same
    Evaluation as numeric.evaluate.evaluate at floats and ints, and every
    point it does not take (0, negative, inf, NaN, bool, NumPy floats, a
    missing or an extra name) meets the same error or the same result."""
    import numpy as np

    import linecontact_sym as lcs
    from linecontact_sym.core.errors import LineContactError
    from linecontact_sym.numeric.evaluate import evaluate

    c = lcs.parabola()
    good = [dict(a=0.3, E_star=1.7, R=1.0), dict(a=2, E_star=3, R=5), dict(a=1e-150, E_star=1e300, R=1e-5),
            dict(a=np.float64(0.3), E_star=1.7, R=1.0)]
    for vals in good:
        for rtol in (1e-12, 1e-3, None):
            got = c.evaluate("force", rtol=rtol, **vals)
            ref = evaluate(c, "force", rtol=1e-12 if rtol is None else rtol, **vals)
            assert (got.path, got.value, got.error, got.rtol, got.note, got.details, got.unit, got.certified,
                    got.enclosure) == (ref.path, ref.value, ref.error, ref.rtol, ref.note, ref.details, ref.unit,
                                       ref.certified, ref.enclosure), vals
            assert got.value == np.pi * float(vals["E_star"]) * float(vals["a"])**2 / (4 * float(vals["R"])) \
                or abs(got.value / (np.pi * vals["E_star"] * vals["a"]**2 / (4 * vals["R"])) - 1) < 1e-15
    bad = [dict(a=0.0, E_star=1.0, R=1.0), dict(a=-0.5, E_star=1.0, R=1.0), dict(a=float("inf"), E_star=1.0, R=1.0),
           dict(a=float("nan"), E_star=1.0, R=1.0), dict(a=True, E_star=1.0, R=1.0), dict(a=0.5, R=1.0),
           dict(a=0.5, E_star=1.0, R=1.0, q=2.0), dict(a=0.5, E_star=1.0, R=-1)]
    for vals in bad:
        with pytest.raises(LineContactError) as e1:
            c.evaluate("force", rtol=1e-12, **vals)
        with pytest.raises(LineContactError) as e2:
            evaluate(c, "force", rtol=1e-12, **vals)
        assert (type(e1.value), str(e1.value)) == (type(e2.value), str(e2.value)), vals
    # the parabola's exports, checked and unchecked, read a point in one pass
    # (fastpath.one_pass): the NumPy path's value, the same errors
    for check in (True, False):
        fx = c.to_numeric("force", check=check)
        for vals in good:
            ref = np.asarray(fx(**{k: np.asarray([v], dtype=float) for k, v in vals.items()}))[0]
            got = fx(**vals)
            assert type(got) is np.float64 and got == ref, (check, vals)
    fx = c.to_numeric("force")
    for vals in bad:
        with pytest.raises(LineContactError) as e1:
            fx(**vals)
        with pytest.raises(LineContactError) as e2:
            c.evaluate("force", rtol=1e-12, **vals)
        assert type(e1.value) is type(e2.value), vals


def test_inlined_one_pass_is_the_loop():
    """fastpath.inline_point (the law's expression generated into the pass
    over a point) gives what the loop it replaces gives, bit for bit, at
    floats, ints and every point the loop refuses (0, signs, inf, NaN, bool,
    NumPy floats, huge ints, missing and extra keys), for bounds 'positive'
    and 'any'; and it is refused for a function that is not one return line
    (a cse'd lambdify), which then takes the loop."""
    import math
    import random

    import numpy as np
    import sympy as sp

    from linecontact_sym.core.printing import lambdify
    from linecontact_sym.numeric import fastpath

    a, b, c = sp.symbols("a b c", positive=True)
    expr = sp.pi * b * a**sp.Rational(3, 2) / (4 * c) + sp.log(a) * sp.sqrt(b + c)
    f = lambdify([a, b, c], expr, "math")
    names = ("a", "b", "c")
    rng = random.Random(7)
    points = [dict(a=0.3, b=1.7, c=1.0), dict(a=2, b=3, c=5), dict(a=10**400, b=1.0, c=1.0), dict(a=1.0, b=2.0),
              dict(a=1.0, b=2.0, c=3.0, d=1.0), dict(b=2.0, c=3.0, d=1.0), dict(a=True, b=1.0, c=1.0),
              dict(a=np.float64(0.5), b=1.0, c=1.0), dict(a=1e300, b=1e300, c=1e-300)]
    for _ in range(300):
        points.append({n: rng.choice([rng.uniform(0.01, 3), rng.uniform(0.01, 3), rng.randint(1, 9),
                                      10.0**rng.randint(-300, 300), 10.0**rng.randint(-30, 30), rng.uniform(-3, 3),
                                      0.0, -0.0, math.inf, -math.inf, math.nan, rng.randint(-3, 3)])
                       for n in names})
    for kinds in (("positive", "positive", "positive"), ("any", "positive", "any"), ("any", "any", "any")):
        bounds = dict(zip(names, kinds))
        checks = tuple((n, bounds[n] in ("positive", "nonnegative")) for n in names)
        inlined = fastpath._inlined_pass(checks, f)
        assert inlined is not None and inlined.__code__.co_filename == "<linecontact_sym generated _lcs_pass>"
        loop = fastpath.one_pass(bounds, names, lambda *v: f(*v))   # a lambda's source is not one def: the loop
        assert loop.__code__.co_filename != "<linecontact_sym generated _lcs_pass>"
        taken = 0
        for p in points:
            got, ref = inlined(p), loop(p)
            assert (got is None and ref is None) or (type(got) is float and got == ref), (kinds, p, got, ref)
            taken += got is not None
        assert taken > 20
    g = lambdify([a, b, c], sp.Tuple(expr, expr**2), "math", cse=True)
    assert fastpath._inlined_pass(tuple((n, True) for n in names), g) is None
