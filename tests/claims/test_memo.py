"""The checker's remembered comparisons survive the disk (the store keeps JSON
data only): a warm paper run reads back exactly what the cold run computed
(before, a point's result was not plain data and stayed in memory, so every
new process computed the 45-digit references again)."""
import mpmath
import sympy as sp

from linecontact_sym.claims import memo
from linecontact_sym.claims.references import Comparison
from linecontact_sym.claims.results import PointResult
from linecontact_sym.method import store


def test_point_result_round_trip_through_the_disk():
    with mpmath.workdps(50):
        printed, target = -mpmath.pi / 3, -mpmath.pi / 3 + mpmath.mpf(10)**-40   # a pull-off: negative
    pr = PointResult({sp.Symbol("a"): sp.Rational(1, 3)}, "random", "pass", 40.0,
                     [Comparison("value", printed, target), Comparison("resultant", mpmath.mpf(2), mpmath.mpf(2),
                                                                     mpmath.mpf(3), 12.5),
                      Comparison("u_z", mpmath.inf, mpmath.mpf(1))], "")
    key = store.make_key("test.memo", "round trip")
    memo.remember(key, pr)
    store.clear_memory()
    back = memo.remembered(key, PointResult)
    assert back is not None and back.status == "pass" and back.digits == 40.0 and back.kind == "random"
    c0, c1, c2 = back.comparisons
    assert c0.printed == printed and c0.target == target        # exactly, all 50 digits
    assert c0.digits == Comparison("value", printed, target).digits
    assert (c1.scale, c1.resolution) == (mpmath.mpf(3), 12.5) and mpmath.isinf(c2.printed)


def test_text_verdicts_are_kept_as_they_are():
    key = store.make_key("test.memo", "text")
    memo.remember(key, "holds symbolically")
    store.clear_memory()
    assert memo.remembered(key, str) == "holds symbolically"
