"""Viscoelastic line contacts: a rigid profile on a linear viscoelastic
half-plane, Lee & Radok (1960) while the contact grows, Ting (1966) when it
recedes, on Popov's (2017) superposition of flat punches (the Method of
Dimensionality Reduction writes the same rule for axisymmetric contacts,
Popov & Hess 2015, ch. 7).

With the elastic force law P(a) = E* Pi(a) (the engine's Eq. 10, any profile,
periodic arrays too: linear in E*), the punch of half-width b enters at t_b,
the first time a(t) reaches b, and relaxes from then on with E*(t - t_b):

    P(t)    = int_0^a(t) Pi'(b) E*(t - t_b) db,
    p(x, t) = (1/pi) int_|x|^a(t) Pi'(b) E*(t - t_b) / sqrt(b^2 - x^2) db     (Eq. 12, each punch relaxed).

While a grows this is the Lee-Radok hereditary integral
int_0^t E*(t - t') d[Pi(a(t'))]; after a single maximum the punches wider
than a(t) have left (Ting) and t_b is still the loading time: the hereditary
integral continued through the receding phase is wrong there.  Why it holds:
a punch still in contact has the force history E*(t - t_b), whose creep
response is the unit step, so the surface slope in |x| < a(t) is f'(x) as
in the elastic solution; a punch that has left contributes a uniform
displacement inside its width (> a(t)), so no slope; the pressure is >= 0.
Creep (load P(t) given): Pi(a(t)) = int_0^t J*(t - t') dP(t') while this
grows, and after its maximum P(t) = int_0^a(t) Pi'(b) E*(t - t_b) db is
solved for a(t) (Ting).  Adhesion is outside Lee-Radok (a package error).

* :mod:`.contact` -- :class:`ViscoelasticLineContact`: closed forms and numbers;
* :mod:`.history` -- the superposition at numbers (mpmath).
* :mod:`.accuracy` -- the histories as quantities of the package's ``evaluate``
  (float64 / mpmath / Arb by rtol) and of its stable float64 exports.
The material (E*(t), J*(t)) is :mod:`linecontact_sym.method.material`.
"""
from .contact import ViscoelasticLineContact, ModelChoice, DissipatedWork
from .history import MultipleMaximaError

__all__ = ["ViscoelasticLineContact", "ModelChoice", "DissipatedWork", "MultipleMaximaError"]
