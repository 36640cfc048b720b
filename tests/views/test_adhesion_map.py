"""The adhesion map of a Maugis-Dugdale line contact: its data (limits shown
against the JKR law and the rigid profile) and the figure."""
import mpmath
import pytest

import linecontact_sym as lcs
from linecontact_sym.views.adhesion_map import adhesion_map_data, plot_adhesion_map
from linecontact_sym.contacts.adhesion.maugis.check import rigid_limit


@pytest.fixture(scope="module")
def data():
    md = lcs.parabola().maugis_dugdale()
    vals = dict(E_star=1, R=1, gamma=1)
    return adhesion_map_data(md, vals, lambdas=(0.1, 10), points=12, lambda_grid=(0.02, 30),
                             rigid=lambda s0: rigid_limit(md, 15, **vals, sigma_0=s0))


def test_adhesion_map_limits(data):
    po = data["pull_off"]
    assert abs(po[1] + 1) < 1e-3                      # lambda = 30: the JKR pull-off
    assert abs(po[0] / data["rigid"][0] - 1) < 2e-2   # lambda = 0.02: the rigid cylinder with a Dugdale law
    assert -0.3 < po[0] < 0
    # at lambda = 10 the force law is close to JKR's away from a -> 0 (where MD stays finite and
    # JKR's tends to 0); at lambda = 0.1 it is not
    far = data["abar"] > 0.3
    assert max(abs(data["curves"][10] - data["jkr"])[far]) < 0.05
    assert max(abs(data["curves"][0.1] - data["jkr"])) > 0.3
    assert abs(data["a_jkr"] - float(mpmath.cbrt(2 / mpmath.pi))) < 1e-12   # (2 w R^2/(pi E*))^(1/3)


def test_adhesion_map_figure(data, tmp_path):
    pytest.importorskip("matplotlib")
    fig = plot_adhesion_map(data, tmp_path / "map.png")
    assert (tmp_path / "map.png").stat().st_size > 10000
    assert len(fig.axes) == 2


@pytest.mark.slow
def test_generic_adhesive_plot_of_maugis_dugdale():
    """The generic adhesive plot (views.contact_plots, what='adhesive') of a Maugis-Dugdale contact:
    P(a) from the law's inner solve (no expression to export); no sample lies below the pull-off,
    the jump-in half-width is a root of P(a) = 0 on the rising branch, and a sample equals the
    contact's state there (the state's own solve, confirmed at 10 more digits)."""
    from linecontact_sym.views.contact_plots import adhesive_data
    md = lcs.parabola().maugis_dugdale()
    vals = {"R": 1, "gamma": 1e-4, "sigma_0": 0.025}
    d = adhesive_data(md, vals, points=21)
    assert len(d["X"]) == 21 and min(d["Y"]) >= -1 - 1e-12 and min(d["Y"]) < -0.5
    a_in = d["jump_in"][0] * d["a_po"]
    assert abs(md.force_at(a_in, 20, E_star=1, **vals)) < 1e-15 * d["P_adh"]
    assert d["stable"][-1] and not d["stable"][0]
    st = md.state(d["X"][10] * d["a_po"], 15, E_star=1, **vals)
    assert abs(float(st.force) / d["P_adh"] - d["Y"][10]) < 1e-12
