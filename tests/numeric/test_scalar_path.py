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
