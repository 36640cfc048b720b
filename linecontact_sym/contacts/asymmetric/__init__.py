"""Asymmetric line contacts (issue 39): a tilt, a moment, a profile that is
not symmetric, on Popov's (2017) superposition of flat punches that are no
longer centred.  The contact [e - a, e + a] of a profile f on the whole line
splits, in s = x - e, into the even part E and the integral H of the odd
part: the force law (Eq. 10*) of E is the load, the slope of the force law of
H gives the tilt of the bounded solution, the pressure is Eq. (12) of E plus
the s-derivative of Eq. (12) of H - theta s^2/2, the gap likewise from
Eqs. (3)/(5).  :mod:`.core` states the reduction, the sign conventions and
the API; :mod:`.split` is the even/odd split of a profile about the centre."""
from ..normal.contact import LineContact
from .contact import AsymmetricLineContact, AsymmetricState, flat_punch, whole_line
from .core import OffsetContact, OffsetNumbers
from .split import even_part, odd_integral, odd_part

LineContact.GEOMETRIES["asymmetric"] = AsymmetricLineContact

__all__ = ["OffsetContact", "OffsetNumbers", "even_part", "odd_part", "odd_integral", "AsymmetricLineContact",
           "AsymmetricState", "flat_punch", "whole_line"]
