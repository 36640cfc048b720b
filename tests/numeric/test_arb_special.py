"""numeric.arb_functions.MPMATH_ARB: Bessel I, J and the complete elliptic Pi through Arb give
mpmath's own values to its working precision, and fall back to mpmath where Arb cannot
(complex arguments, Pi(n|m) with n > 1, an argument that is not a number); a value asked
again (remembered) is the one computed afresh.  arb_lambdify / lambdify_law: a whole closed
form in Arb gives the value of mpmath's evaluation at 30 more digits, and mpmath's own answer
outside the real domain."""
import mpmath
import pytest
import sympy as sp

from linecontact_sym.numeric import arb_functions
from linecontact_sym.numeric.arb_functions import MPMATH_ARB, arb_lambdify, lambdify_law
from linecontact_sym.numeric.special import mp_elliptic_pi

CASES = [("besseli", mpmath.besseli, (1, "0.123456789012345678901234567890123")),
         ("besseli", mpmath.besseli, (0, "0")),
         ("besseli", mpmath.besseli, ("0.5", "7.25")),
         ("besselj", mpmath.besselj, (1, "3.8317059702075123156144358863081607665645")),   # near a zero
         ("besselj", mpmath.besselj, (0, "-2.5")),
         ("elliptic_pi", mpmath.ellippi, ("0.3", "0.7")),
         ("elliptic_pi", mpmath.ellippi, ("-3", "-0.7")),
         ("elliptic_pi", mpmath.ellippi, ("1e-7", "3e-7")),       # Arb needs the exact arguments here
         ("elliptic_pi", mpmath.ellippi, ("0.999", "0.5"))]


@pytest.mark.parametrize("dps", [15, 30, 60])
@pytest.mark.parametrize("name, mp_fn, args", CASES)
def test_same_value_as_mpmath(name, mp_fn, args, dps):
    with mpmath.workdps(dps):
        xs = [mpmath.mpf(a) if isinstance(a, str) else a for a in args]
        got, ref = MPMATH_ARB[name](*xs), mp_fn(*xs)
        assert isinstance(got, mpmath.mpf)
        assert abs(got - ref) <= 4 * mpmath.eps * max(abs(ref), mpmath.mpf(10)**-40 if ref else 1)


def test_falls_back_to_mpmath():
    with mpmath.workdps(30):
        z = mpmath.mpc(1, 1)
        assert MPMATH_ARB["besseli"](1, z) == mpmath.besseli(1, z)
        n, m = mpmath.mpf(3), mpmath.mpf("0.7")          # n > 1: the principal value, as the exports
        assert MPMATH_ARB["elliptic_pi"](n, m) == mp_elliptic_pi(n, m)
        phi = mpmath.mpf("0.4")                           # the incomplete integral: mpmath's
        assert MPMATH_ARB["elliptic_pi"](n / 10, phi, m) == mpmath.ellippi(n / 10, phi, m)


def test_remembered_value_is_the_fresh_one():
    """The memo keys on the arguments' exact values and the precision: the same call at another
    precision, or at an argument one unit in the last place away, is computed, not remembered."""
    with mpmath.workdps(30):
        z = mpmath.mpf("0.3217")
        first = MPMATH_ARB["besseli"](1, z)
        assert MPMATH_ARB["besseli"](1, z) is first
        assert first == mpmath.besseli(1, z)
        nxt = mpmath.mpf((z.man + 1, z.exp))
        assert MPMATH_ARB["besseli"](1, nxt) == mpmath.besseli(1, nxt) != first
    with mpmath.workdps(50):
        assert MPMATH_ARB["besseli"](1, z) == mpmath.besseli(1, z)


def test_whole_form_in_arb_against_mpmath_at_more_digits():
    """dP0/da of the Gaussian bump (Bessel I of a**2/2, a cancelling sum) in Arb: within a unit or
    two in the last place of the value mpmath gives at 30 more digits; a square root beyond its real
    domain is mpmath's complex value; a form without Bessel functions stays mpmath's (lambdify_law)."""
    a = sp.Symbol("a", positive=True)
    P0 = sp.pi * a**2 * (sp.besseli(0, a**2 / 2) - sp.besseli(1, a**2 / 2)) * sp.exp(-a**2 / 2) / 2
    dP0 = sp.diff(P0, a)
    f = lambdify_law([a], dP0)
    ref = sp.lambdify(a, dP0, "mpmath")
    for dps in (20, 45):
        for A in ("0.0018885993165908670018", "0.5", "3.25"):
            with mpmath.workdps(dps):
                got = f(mpmath.mpf(A))
                with mpmath.workdps(dps + 30):
                    exact = ref(mpmath.mpf(A))
                assert isinstance(got, mpmath.mpf)
                assert abs(got - exact) <= 2 * mpmath.eps * abs(exact)
    g = arb_lambdify([a], sp.sqrt(1 - a) * sp.besseli(0, a))
    with mpmath.workdps(25):
        v = g(mpmath.mpf(2))
        assert isinstance(v, mpmath.mpc) and abs(v - mpmath.sqrt(-1) * mpmath.besseli(0, 2)) < mpmath.mpf(10)**-24
    assert lambdify_law([a], a**2 / 3).__module__ != arb_functions.__name__
