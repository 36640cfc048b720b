"""numeric.arb_functions.MPMATH_ARB: Bessel I, J and the complete elliptic Pi through Arb give
mpmath's own values to its working precision, and fall back to mpmath where Arb cannot
(complex arguments, Pi(n|m) with n > 1, an argument that is not a number)."""
import mpmath
import pytest

from linecontact_sym.numeric.arb_functions import MPMATH_ARB
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
