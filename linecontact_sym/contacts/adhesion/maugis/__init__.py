"""The Maugis-Dugdale (cohesive-zone) law of line contacts of any profile, an
ordinary cohesive law (:class:`~..law.CohesiveLaw`) on the generic adhesive
contact (:class:`~..contact.AdhesiveContact`): the pull-off, half_width(P),
the branches, the jump-in, the plots and the claims quantities come from the
generic layer over the ForceLaw this law builds (with its scan hint and
P(0+) != 0, :mod:`~linecontact_sym.contacts.normal.equilibria`).  Baney & Hui
(1997) for the parabola; here any profile through Popov's (2017) flat-punch
superposition.

The map (one law, five modules):

* :mod:`.law`     -- :class:`MaugisDugdale` (the law: parameters w and sigma_0,
  the two conditions, its numeric ForceLaw) and :class:`MaugisDugdaleContact`
  (the generic contact with what only this law has: ``conditions``, ``state``,
  ``numeric_law``, ``maugis_parameter``, ``model_choice``, ``adhesion_map``);
* :mod:`.derive`  -- the Dugdale strip's parts (force, pressure, gap at c_D),
  derived with SymPy from the Abel inversion;
* :mod:`.numbers` -- the numbers at values: c_D(a) (bracketed Newton), P(a),
  dP/da, the state, P(0+); quadrature where the engine left an Integral;
* :mod:`.check`   -- the independent checks (Johnson's bounded-solution
  condition, the Flamant kernel, Baney & Hui's normalisation, the rigid limit);
* :mod:`.choice`  -- the Maugis parameter of any profile and JKR-or-MD.
"""
from .law import DISPLACEMENT_CONTROL, MaugisDugdale, MaugisDugdaleContact, ModelChoice
from .numbers import MDState

__all__ = ["MaugisDugdale", "MaugisDugdaleContact", "ModelChoice", "MDState", "DISPLACEMENT_CONTROL"]
