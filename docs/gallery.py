"""The documentation's gallery: one figure per physical effect, each drawn by
the code shown under it.

Every public function below is one entry, in the order written: its first
docstring line is the heading (the effect), the rest of the docstring the
caption, its body the code a user types.  The Sphinx build (docs/conf.py)
writes ``docs/gallery.md`` from them with :func:`page`: a MyST notebook that
MyST-NB executes like the tutorials (cached in the same jupyter-cache), so
every figure is drawn by the build from the code beside it, and a cell that
raises fails the build.  Adding an effect is adding one function here.

``python docs/gallery.py`` prints the page.
"""
from __future__ import annotations

import inspect
import sys
import textwrap


def normal_contact():
    """Normal contact

    Pressure under the worn cylinder, a cylinder of radius R with a flat of
    half-width b = 0.3 R (Popov's Eqs. 21-23): logarithmic peaks at the edges
    of the flat, x = b; at a = 0.25 < b only the flat touches (P = 0), so two
    loads are drawn.
    """
    import linecontact_sym as lcs

    worn = lcs.worn_cylinder()
    worn.plot("pressure", values={"R": 1, "b": 0.3})


def jkr_adhesion():
    """Adhesion (JKR)

    The force law of the adhesive parabola (Eqs. 33-36): the stable and
    unstable branches, the pull-off and the jump-in.
    """
    import linecontact_sym as lcs

    jkr = lcs.parabola().adhesive(lcs.gamma)
    jkr.plot("adhesive", values={"R": 1, "gamma": 0.05})


def maugis_dugdale_adhesion():
    """Adhesion (Maugis-Dugdale)

    Force against half-width of the parabola with a Dugdale cohesive zone,
    for three values of the Tabor-like parameter lambda: from the rigid (DMT)
    limit to JKR.
    """
    import linecontact_sym as lcs

    md = lcs.parabola().maugis_dugdale()
    md.adhesion_map(dict(E_star=1, R=1, gamma=1), lambdas=(0.1, 1, 10), points=15, lambda_grid=[0.1, 1, 10])


def tangential_and_fretting():
    """Tangential loading and fretting

    Cattaneo-Mindlin: the tangential force Q against the shift delta of the
    parabola over full fretting cycles between +-Q_A; the loop's area is the
    energy dissipated per cycle.
    """
    import matplotlib.pyplot as plt
    import linecontact_sym as lcs

    t = lcs.parabola(points=1).tangential()
    vals = dict(E_star=1.0, R=1.0, mu=0.4, a=0.8)
    muP = vals["mu"] * float(t.state(0, **vals).P)
    fig, ax = plt.subplots(figsize=(6, 4))
    for ratio in (0.3, 0.6, 0.9):
        cycle = t.cycle(ratio * muP, 61, **vals)
        ax.plot(cycle.delta * 1e3, cycle.Q, label=f"Q_A/(mu P) = {ratio}, W = {cycle.W:.2e}")
    ax.set(xlabel="delta x 1e3", ylabel="Q", title="fretting loops")
    ax.legend(fontsize=8);


def subsurface_stresses():
    """Subsurface stresses

    Principal shear under the Hertz contact, scaled by p0: the maximum,
    0.300 p0 at the depth z = 0.786 a, is marked.
    """
    import linecontact_sym as lcs

    hertz = lcs.parabola().stresses(points=2)
    hertz.plot("principal_shear", R=1);


def periodic_contact():
    """Periodic (wavy) surfaces

    Pressure p/p* over one period of the wavy surface h (1 - cos(2 pi x/L))
    at three nominal pressures: Westergaard's solution, derived by the engine
    from the profile (p* = pi E* h/L is the nominal pressure of full contact).
    """
    import sympy as sp
    import linecontact_sym as lcs

    h, L = sp.symbols("h L", positive=True)
    wavy = lcs.LineContact(h * (1 - sp.cos(2 * sp.pi * lcs.x / L)), period=L)
    wavy.plot("wavy_pressure", values={"h": 1, "L": 1})


def asymmetric_contact():
    """Tilted and asymmetric contacts

    Left: the pressure under the asymmetric profile x^2/2 + x^3/10 (not
    mirrored) at the load P = 1 and three tilts theta; the contact [e - a,
    e + a] moves with the tilt and both edges stay smooth.  Right: the flat
    punch |x| < 1 under the moments M = 0.2, 0.5, 0.65 (P = 1): complete
    contact with square-root singular corners while M < P w/2, the left
    corner's factor vanishing at M = P w/2 = 0.5, then the left edge lifts
    and is smooth.  Dotted lines: smooth ends, dashed: corners.
    """
    import matplotlib.pyplot as plt
    import linecontact_sym as lcs

    xr = lcs.x_real                                   # the whole line: the profile is not mirrored
    cubic = lcs.LineContact(xr**2 / 2 + xr**3 / 10, symmetric=False)
    punch = lcs.flat_punch(1)
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 3.6))
    for theta in (-0.3, 0.1, 0.3):
        cubic.contact_at(P=1, theta=theta, E_star=2).plot(ax=left)
    for M in (0.2, 0.5, 0.65):
        punch.contact_at(P=1, moment=M, E_star=1).plot(ax=right)
    left.set(title="x^2/2 + x^3/10, P = 1, tilted", ylim=(0, 1.2))
    right.set(title="flat punch |x| < 1, P = 1, moment M", ylim=(0, 3))
    for ax in (left, right):
        ax.legend(fontsize=8, loc="upper left")


def steady_rolling():
    """Steady rolling with traction

    The traction q (solid) under mu p (dashed) at Q = 0.5 mu P (P = 1,
    mu = 0.3), rolling in +x: the stick zone (shaded) at the leading edge,
    slip with q = mu p behind it.  Left, the parabola: Carter's stick
    half-width c_s = a sqrt(1 - Q/(mu P)); right, the quartic x^4, whose
    stick zone comes out of the engine the same way.
    """
    import matplotlib.pyplot as plt
    import sympy as sp
    import linecontact_sym as lcs

    k = sp.Symbol("k", positive=True)
    carter = lcs.parabola(verify=False).rolling(0.3)
    quartic = lcs.LineContact(k * lcs.x**4, verify=False).rolling(0.3)
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 3.6))
    carter.state_at(Q=0.15, P=1, E_star=1, R=1).plot(ax=left, title="parabola (Carter), Q = 0.5 mu P")
    quartic.state_at(Q=0.15, P=1, E_star=1, k=1).plot(ax=right, title="$x^4$, Q = 0.5 mu P")
    right.get_legend().remove()


def viscoelastic_contact():
    """Viscoelastic contact

    A parabola (R = 1) on a standard linear solid, E*(t) = 1 + 2 exp(-2t),
    pressed in and withdrawn at a constant rate, a(t) = t/2 then (4 - t)/2:
    the force P(t) (Lee-Radok while the contact grows, Ting after) lies
    between the elastic forces with the instantaneous modulus E*(0) and the
    relaxed one E*(oo) while loading, drops when the contact starts to
    recede and then relaxes onto the relaxed one.
    """
    import sympy as sp
    import linecontact_sym as lcs

    t = lcs.t
    zener = lcs.standard_linear_solid(E0=3, E_inf=1, tau=sp.Rational(1, 2))
    v = lcs.parabola(points=1).viscoelastic(zener)
    cycle = sp.Piecewise((t / 2, t <= 2), ((4 - t) / 2, t <= 4), (0, True))
    fig = v.plot(cycle, 4, points=40, R=1)            # P(t) over a(t)
    fig.axes[0].legend(fontsize=8, loc="upper left")
    fig


def entries() -> list:
    """``(name, heading, caption, code)`` per entry, in the order written."""
    here = sys.modules[__name__]
    funcs = [f for name, f in vars(here).items()
             if inspect.isfunction(f) and f.__module__ == __name__ and not name.startswith("_")
             and name not in ("entries", "page")]
    out = []
    for f in sorted(funcs, key=lambda f: f.__code__.co_firstlineno):
        heading, _, caption = inspect.getdoc(f).partition("\n")
        body = inspect.getsource(f).split('"""', 2)[2]
        out.append((f.__name__, heading.strip(), " ".join(caption.split()), textwrap.dedent(body).strip()))
    return out


def page() -> str:
    """The gallery page: a MyST notebook, one code cell per entry."""
    out = ["---", "file_format: mystnb", "kernelspec:", "  name: python3", "  display_name: Python 3", "---", "",
           "<!-- generated by docs/conf.py from docs/gallery.py: edit that file -->", "", "# Gallery", "",
           "One figure per physical effect, drawn when these pages were built by the code under its "
           "heading (docs/gallery.py).  The tutorials show more, with the closed forms behind each figure.",
           ""]
    for name, heading, caption, code in entries():
        out += [f"({name})=", f"## {heading}", "", caption, "", "```{code-cell} ipython3", code, "```", ""]
    return "\n".join(out)


if __name__ == "__main__":
    print(page())
