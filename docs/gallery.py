"""The figures of the documentation's gallery, drawn with the package's own
plot functions: ``python docs/gallery.py`` (from the repository root) writes
``docs/gallery/*.png``; the Sphinx build (docs/conf.py) lists them with their
captions and code, and draws nothing.

Each figure is one function below: its docstring is the caption, its body
the code a user types (shown under the figure).
"""
from __future__ import annotations

import inspect
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
OUT = HERE / "gallery"


def hertz_pressure(lcs):
    """Contact pressure of the parabola (Hertz) at the default loads: the unit
    half-circle p/p0 = sqrt(1 - x^2/a^2), the same curve at every load."""
    return lcs.parabola().plot("pressure", values={"R": 1})


def exact_cylinder_force(lcs):
    """Force law of the exact cylinder R - sqrt(R^2 - x^2) (elliptic integrals,
    Eq. 26), up to a = 0.99 R."""
    return lcs.exact_cylinder().plot("force", values={"R": 1})


def worn_cylinder_pressure(lcs):
    """Pressure under the worn cylinder with a flat of half-width b = 0.3 R
    (Eqs. 21-23): logarithmic peaks at the edges of the flat, x = b; at
    a = 0.25 < b only the flat touches (P = 0), so two loads are drawn."""
    return lcs.worn_cylinder().plot("pressure", values={"R": 1, "b": 0.3})


def parabola_gap(lcs):
    """Gap outside the Hertz contact, g(x)/f(a) against x/a: the surfaces part
    tangentially at the edges."""
    return lcs.parabola().plot("gap", values={"R": 1})


def jkr_parabola(lcs):
    """JKR adhesion of the parabola (Eqs. 33-36): the stable and unstable
    branches, the pull-off and the jump-in."""
    return lcs.parabola().adhesive(lcs.gamma).plot("adhesive", values={"R": 1, "gamma": 0.05})


def hertz_principal_shear(lcs):
    """Principal shear under the Hertz contact, scaled by p0: the maximum,
    0.300 p0 at depth z = 0.786 a, is marked."""
    return lcs.parabola().stresses(points=2).plot("principal_shear", R=1)


FIGURES = [hertz_pressure, exact_cylinder_force, worn_cylinder_pressure, parabola_gap, jkr_parabola,
           hertz_principal_shear]


def entries():
    """``(stem, caption, code)`` per figure, for the gallery page."""
    out = []
    for f in FIGURES:
        body = inspect.getsource(f).split('"""', 2)[2].strip()
        out.append((f.__name__, " ".join(inspect.getdoc(f).split()), body.replace("return ", "", 1)))
    return out


def draw(names=()):
    """Draw the figures (all, or those named) into docs/gallery/."""
    sys.path.insert(0, str(HERE.parent))
    import matplotlib
    matplotlib.use("Agg")
    import linecontact_sym as lcs
    OUT.mkdir(exist_ok=True)
    for f in FIGURES:
        if names and f.__name__ not in names:
            continue
        out = f(lcs)
        fig = getattr(out, "figure", out)        # an Axes (stress plots) or a Figure
        fig.savefig(OUT / f"{f.__name__}.png", dpi=110, bbox_inches="tight")
        print("wrote", OUT / f"{f.__name__}.png")


if __name__ == "__main__":
    draw(sys.argv[1:])
