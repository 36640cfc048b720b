"""The series model's choice of terms (evaluate's model path) is the one of the
former O(N^2) scan: same N, partial sum, bound and ratio on random term lists."""
import random

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
