"""The general plotting view (views/plots.py) and figures as data of a claims
file ([[figures]] of popov2017.toml): normalised curves against closed forms
typed here, file output, and clear errors for malformed figure tables."""
import numpy as np
import pytest

from linecontact_sym.claims import spec
from linecontact_sym.core.errors import ClaimError, DomainError
from linecontact_sym.views.plots import curve_data, plot_quantity


class _Law:
    """A duck-typed contact: to_numeric returns a callable with ``arguments``."""

    def __init__(self, fn, names):
        self.fn, self.names = fn, names
        self.asked = []

    def to_numeric(self, quantity):
        self.asked.append(quantity)

        def call(**kw):
            assert set(kw) == set(self.names), kw          # only the arguments it declares
            return self.fn(**kw)
        call.arguments = tuple(self.names)
        return call


def test_curve_data_sweeps_the_free_symbol_of_the_abscissa():
    hertz = _Law(lambda a, R, E_star: np.pi * E_star * a**2 / (4 * R), ["a", "R", "E_star"])
    X, (Y,) = curve_data([hertz], "force", x="a/b", y="2*R*P/(E_star*b**2)", x_range=(0, 3), points=7,
                         values={"b": 2, "R": 5, "E_star": 3})
    a = 2 * X                                              # a = X b
    assert np.allclose(X, [0, 0.5, 1, 1.5, 2, 2.5, 3])
    assert np.allclose(Y, 2 * 5 * (np.pi * 3 * a**2 / 20) / (3 * 4), rtol=1e-14)
    assert hertz.asked == ["force"]


def test_curve_data_pressure_at_fixed_half_width_and_nan_where_undefined():
    hertz_p = _Law(lambda x, a, R, E_star: E_star / (2 * R) * np.sqrt(a**2 - x**2), ["x", "a", "R", "E_star"])
    X, (Y,) = curve_data([hertz_p], "pressure", x="x/a", y="2*R*p/(E_star*a)", x_range=(0, 1.5), points=4,
                         values={"a": 2, "R": 1, "E_star": 1})
    assert np.allclose(Y[:3], np.sqrt(1 - X[:3]**2), rtol=1e-14)    # the unit half-circle
    assert np.isnan(Y[3])                                           # x > a: sqrt of a negative number


def test_curve_data_of_the_engine_matches_the_printed_eq23_and_eq13():
    import linecontact_sym as lcs
    X, (worn, para) = curve_data([lcs.worn_cylinder(budget=20), lcs.parabola(budget=20)], "force",
                                 x="a/b", y="2*R*P/(E_star*b**2)", x_range=(0, 4), points=9,
                                 values={"b": 1, "R": 1, "E_star": 1})
    with np.errstate(invalid="ignore", divide="ignore"):
        eq23 = np.where(X > 1, X**2 * (np.pi / 2 - np.arcsin(1 / np.maximum(X, 1))
                                       + np.sqrt(np.maximum(1 - 1 / X**2, 0)) / X), 0.0)
    assert np.allclose(worn, eq23, rtol=1e-13, atol=1e-300)
    assert np.allclose(para, np.pi * X**2 / 2, rtol=1e-13)
    assert worn[1] == 0 and worn[2] == 0                   # a <= b: the flat alone carries no load


@pytest.mark.parametrize("kw, words", [
    ({"x": "a/b", "values": {"R": 1, "E_star": 1}}, ["exactly one symbol", "a", "b"]),
    ({"x": "a", "y": "2*R/(E_star*b**2)"}, ["does not contain the value P"]),
    ({"x": "a", "y": "P*k"}, ["unknown name 'k'"]),
])
def test_curve_data_errors_name_the_problem(kw, words):
    law = _Law(lambda a, R, E_star: a, ["a", "R", "E_star"])
    args = {"x": "a", "y": "P", "values": {"b": 1, "R": 1, "E_star": 1}, **kw}
    with pytest.raises((DomainError, ClaimError)) as info:
        curve_data([law], "force", x_range=(0, 1), points=3, **args)
    for w in words:
        assert w in str(info.value)


def test_plot_quantity_writes_png_and_pdf_with_a_ratio_panel(tmp_path):
    pytest.importorskip("matplotlib")
    one = _Law(lambda a, R, E_star: a**2, ["a", "R", "E_star"])
    two = _Law(lambda a, R, E_star: 2 * a**2, ["a", "R", "E_star"])
    paths = plot_quantity([one, two], "force", x="a/R", y="P/(E_star*R)", x_range=(0, 1), points=11,
                          values={"R": 1, "E_star": 1}, labels=["one", "two"], styles=["-", "--"],
                          marks=[(0.5, "half")], ratio=(1, 0), ratio_label="two / one", out_dir=tmp_path,
                          stem="demo")
    assert [p.name for p in paths] == ["demo.png", "demo.pdf"]
    assert all(p.stat().st_size > 1000 for p in paths)
    assert paths[0].read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and paths[1].read_bytes()[:5] == b"%PDF-"


def test_a_figure_is_redrawn_only_when_its_inputs_or_its_files_changed(tmp_path, monkeypatch):
    pytest.importorskip("matplotlib")
    from linecontact_sym.views import plots
    law = _Law(lambda a, R, E_star: a**2, ["a", "R", "E_star"])
    kw = dict(x="a/R", y="P/(E_star*R)", x_range=(0, 1), points=11, values={"R": 1, "E_star": 1},
              out_dir=tmp_path, stem="demo")
    paths = plot_quantity([law], "force", **kw)
    first = [p.read_bytes() for p in paths]

    def no_drawing():
        raise AssertionError("redrawn")
    monkeypatch.setattr(plots, "figure_class", no_drawing)
    assert plot_quantity([law], "force", **kw) == paths            # same inputs, files intact: not redrawn
    with pytest.raises(AssertionError, match="redrawn"):            # another curve: redrawn
        plot_quantity([_Law(lambda a, R, E_star: 2 * a**2, ["a", "R", "E_star"])], "force", **kw)
    with pytest.raises(AssertionError, match="redrawn"):            # another label: redrawn
        plot_quantity([law], "force", labels=["other"], **kw)
    paths[0].write_bytes(first[0][:-1] + b"!")                      # a file changed since: redrawn
    with pytest.raises(AssertionError, match="redrawn"):
        plot_quantity([law], "force", **kw)
    monkeypatch.undo()
    assert [p.read_bytes()[:4] for p in plot_quantity([law], "force", **kw)] == [b[:4] for b in first]


def test_popov2017_figures_are_data():
    paper = spec.load_paper("popov2017")
    figs = {f.file: f for f in paper.figures}
    assert set(figs) == {"fig4_worn_cylinder", "fig5_exact_cylinder"}
    for f in figs.values():
        assert f.caption.endswith(".") and len(f.caption.split()) > 10 and f.file not in f.caption
        assert f.quantity == "force" and len(f.curves) == 2
    assert str(figs["fig4_worn_cylinder"].x) == "a/b" and figs["fig5_exact_cylinder"].ratio == ("exact cylinder",
                                                                                               "parabola")


@pytest.mark.parametrize("change, words", [
    ({"caption": "fig4_worn_cylinder"}, ["caption", "sentence"]),
    ({"colour": "red"}, ["unknown field", "colour"]),
    ({"ratio": ["a", "nope"]}, ["ratio", "curve names"]),
    ({"y": "2*R/(E_star*b**2)"}, ["ordinate", "value P"]),
    ({"file": "../evil"}, ["plain file name"]),
    ({"x": "__import__('os')"}, ["figure 'f'", "dunder"]),
])
def test_malformed_figure_tables_get_clear_errors(change, words):
    fd = {"file": "f", "caption": "A figure.", "x": "a/b", "y": "P", "x_range": [0, 1],
          "curves": [{"name": "a", "profile": "x**2"}], **change}
    with pytest.raises(ClaimError) as info:
        spec.figure_from_dict(fd, "mine.toml")
    for w in words:
        assert w in str(info.value)


# ------------------------------------------------------------------ contact.plot: normalised views
_CACHE = {}


def hertz():
    """One parabola contact (and its adhesive form) for all the tests below: derived once."""
    import linecontact_sym as lcs
    if not _CACHE:
        _CACHE["c"] = lcs.parabola(budget=10)
        _CACHE["ad"] = _CACHE["c"].adhesive(lcs.gamma)
    return _CACHE["c"], _CACHE["ad"]

def test_pressure_view_hertz_is_the_unit_half_circle():
    import linecontact_sym as lcs
    from linecontact_sym.views.contact_plots import pressure_data
    X, Ys, As = pressure_data(hertz()[0], [0.2, 1.5], {"R": 2, "E_star": 3}, points=9)
    for P, Y, a in zip([0.2, 1.5], Ys, As):
        assert np.isclose(a, 2 * np.sqrt(P * 2 / (np.pi * 3)), rtol=1e-12)      # Hertz: a = 2 sqrt(PR/(pi E*))
        assert np.allclose(Y, np.sqrt(1 - X**2), rtol=1e-12, atol=1e-12)


def test_force_and_gap_views_hertz():
    import linecontact_sym as lcs
    from linecontact_sym.views.contact_plots import force_data, gap_data
    c = hertz()[0]
    X, Y, L = force_data(c, {"R": 2, "E_star": 3}, points=5)
    assert L == "R" and np.isclose(X[-1], 1.0) and np.allclose(Y, np.pi * X**2 / 4, rtol=1e-13)
    X, (Y,), _ = gap_data(c, [0.7], {"R": 2, "E_star": 3}, points=6)
    assert np.allclose(Y, X * np.sqrt(X**2 - 1) - np.arccosh(X), rtol=1e-10, atol=1e-14)


def test_adhesive_view_branches_pull_off_and_jump_in():
    import linecontact_sym as lcs
    from linecontact_sym.views.contact_plots import adhesive_data
    ad = hertz()[1]
    d = adhesive_data(ad, {"R": 1, "gamma": 0.05}, points=401)
    # JKR line contact of a parabola: a_po^3 = 2 R^2 gamma/(pi E*), a_in^3 = 32 R^2 gamma/(pi E*)
    assert np.isclose(d["a_po"], (2 * 0.05 / np.pi) ** (1 / 3), rtol=1e-12)
    assert np.isclose(d["jump_in"][0], 16 ** (1 / 3), rtol=1e-10)
    assert np.isclose(d["Y"].min(), -1, rtol=1e-4) and np.isclose(d["X"][d["Y"].argmin()], 1, atol=0.02)
    assert not d["stable"][d["X"] < 0.95].any() and d["stable"][d["X"] > 1.05].all()
    pytest.importorskip("matplotlib")
    fig = ad.plot("adhesive", values={"R": 1, "gamma": 0.05}, points=101)
    labels = fig.axes[0].get_legend_handles_labels()[1]
    assert "stable branch" in labels and "unstable branch" in labels and any("pull-off" in t for t in labels)


def test_every_contact_kind_has_numeric_views_through_the_registry():
    import linecontact_sym as lcs
    ad = hertz()[1]
    p = ad.to_numeric("pressure")(a=1.0, x=0.5, R=1.0, E_star=1.0, gamma=0.02)
    expect = np.sqrt(0.75) / 2 - np.sqrt(2 * np.pi * 0.02) / (np.pi * np.sqrt(0.75))   # Eq. (29) by hand
    assert np.isclose(p, expect, rtol=1e-13)
    r = ad.evaluate("force", a=1, R=1, E_star=1, gamma=0.02, rtol=1e-12)
    assert abs(float(r.value) - (np.pi / 4 - np.sqrt(2 * np.pi * 0.02))) < 1e-12


def test_contact_plot_writes_figures(tmp_path):
    pytest.importorskip("matplotlib")
    import linecontact_sym as lcs
    c = hertz()[0]
    for what, kw in (("pressure", {"loads": [0.1, 1.0]}), ("force", {}), ("gap", {"loads": [0.5]})):
        fig = c.plot(what, values={"R": 1}, path=tmp_path / f"{what}.png", points=41, **kw)
        assert (tmp_path / f"{what}.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        assert fig.axes[0].get_xlabel()
    # shown in Jupyter as an image without pyplot or %matplotlib inline (the docs' notebooks)
    png = fig._repr_png_()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 5000
    import matplotlib.figure
    assert isinstance(fig, matplotlib.figure.Figure)
    with pytest.raises(DomainError, match="choose one of"):
        c.plot("torque")
    with pytest.raises(DomainError, match="'R'"):
        c.plot("pressure", loads=[1.0])


def test_plots_need_no_loads_and_title_the_profile_in_latex():
    """Issue 23: a plot without loads draws the loads at a = 0.25, 0.5, 0.75 R
    (Hertz: P = pi E* a^2/(4R)); titles carry the profile in LaTeX, not SymPy's str."""
    pytest.importorskip("matplotlib")
    from linecontact_sym.views.contact_plots import default_loads
    c = hertz()[0]
    assert default_loads(c, {"R": 2, "E_star": 3}) == [float(f"{np.pi * 3 * (f * 2)**2 / 8:.3g}") for f in (0.25, 0.5, 0.75)]
    for what in ("pressure", "gap"):
        fig = c.plot(what, values={"R": 1}, points=21)
        ax = fig.axes[0]
        labels = [t.get_text() for t in ax.get_legend().get_texts()]
        assert labels == ["$P = 0.0491$ ($a = 0.25$)", "$P = 0.196$ ($a = 0.5$)", "$P = 0.442$ ($a = 0.75$)"]
        assert r"$f(x) = \frac{x^{2}}{2 R}$" in ax.get_title() and "**" not in ax.get_title()


def test_plot_quantity_labels_default_to_the_axis_formulas_in_latex(tmp_path):
    pytest.importorskip("matplotlib")
    import linecontact_sym as lcs
    from unittest import mock
    from linecontact_sym.views import plots
    seen = {}
    real = plots.figure_class

    def spy():
        Fig = real()

        class F(Fig):
            def savefig(self, *a, **k):
                seen["x"], seen["y"] = self.axes[0].get_xlabel(), self.axes[0].get_ylabel()
        return F
    with mock.patch.object(plots, "figure_class", spy):
        plots.plot_quantity([hertz()[0]], "force", x="a/R", y="P/(E_star*R)", x_range=(0, 1), points=5,
                            values={"R": 1, "E_star": 1}, out_dir=tmp_path, formats=("png",))
    assert seen == {"x": r"$\frac{a}{R}$", "y": r"$\frac{P}{E^{*} R}$"}
