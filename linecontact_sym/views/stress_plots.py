"""Plots of the subsurface stresses, as in the textbooks: contour maps in the
normalised coordinates (x/a, z/a) with the depth downwards, and the
stresses along the axis x = 0.

The functions take the field as a callable ``field(x, z, quantity)`` (the
:class:`~linecontact_sym.contacts.stresses.field.FieldEvaluator` of
``StressField.field(...)``, or any function of that shape) and know nothing
of contacts.  matplotlib is the optional extra ``[plot]``, imported when a
plot is drawn.
"""
from __future__ import annotations

import numpy as np

from ..core.extras import require

#: axis labels of the stress quantities (matplotlib mathtext)
LABELS = {
    "sigma_x": r"$\sigma_x$", "sigma_z": r"$\sigma_z$", "tau_xz": r"$\tau_{xz}$", "sigma_y": r"$\sigma_y$",
    "principal_shear": r"$\tau_1$", "von_mises": r"$\sigma_{\mathrm{vM}}$", "tresca": r"$\sigma_{\mathrm{T}}$",
}


def _pyplot():
    return require("plot", "matplotlib.pyplot")


def contour(field, a, quantity="von_mises", scale=1.0, scale_label="p_0", x_range=(-2.0, 2.0),
            z_range=(0.0, 2.0), n=(321, 161), levels=14, ax=None, mark=None, title=None):
    """Filled contour map of ``quantity``/``scale`` over (x/a, z/a), depth
    downwards, the contact |x| <= a drawn on the surface.  ``mark``: a point
    (x, z) to mark (e.g. the verified maximum).  Returns the axes.

    >>> import numpy as np
    >>> f = lambda x, z, q: np.exp(-(x**2 + (z - 0.8)**2))     # any field(x, z, quantity)
    >>> ax = contour(f, 1.0, "von_mises", n=(21, 11))           # doctest: +SKIP
    """
    plt = _pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(6.4, 3.6))
    xs = np.linspace(x_range[0], x_range[1], n[0]) * a
    zs = np.linspace(z_range[0], z_range[1], n[1]) * a
    X, Z = np.meshgrid(xs, zs)
    V = np.asarray(field(X, Z, quantity)) / scale
    cs = ax.contourf(X / a, Z / a, V, levels=levels, cmap="viridis")
    ax.contour(X / a, Z / a, V, levels=cs.levels, colors="k", linewidths=0.4)
    ax.figure.colorbar(cs, ax=ax, label=f"{LABELS.get(quantity, quantity)} / ${scale_label}$")
    ax.plot([-1, 1], [0, 0], color="crimson", lw=4, solid_capstyle="butt", label="contact")
    if mark is not None:
        ax.plot(mark[0] / a, mark[1] / a, "w*", ms=12, mec="k", label="maximum")
    ax.set_xlim(*x_range)
    ax.set_ylim(z_range[1], z_range[0])
    ax.set_xlabel("$x/a$")
    ax.set_ylabel("depth $z/a$")
    ax.set_aspect("equal")
    if title:
        ax.set_title(title)
    return ax


def axis_profile(field, a, quantities=("sigma_x", "sigma_z", "principal_shear", "von_mises"), scale=1.0,
                 scale_label="p_0", z_max=3.0, n=301, x=0.0, ax=None, title=None):
    """The stresses along the line x = ``x`` (default the axis) against the
    depth z/a.  Returns the axes."""
    plt = _pyplot()
    if ax is None:
        _, ax = plt.subplots(figsize=(5.2, 3.8))
    zs = np.linspace(0, z_max, n) * a
    xs = np.full_like(zs, x)
    for q in quantities:
        ax.plot(np.asarray(field(xs, zs, q)) / scale, zs / a, label=LABELS.get(q, q))
    ax.axvline(0, color="0.6", lw=0.6)
    ax.set_ylim(z_max, 0)
    ax.set_xlabel(f"stress / ${scale_label}$")
    ax.set_ylabel("depth $z/a$")
    ax.legend(frameon=False)
    if title:
        ax.set_title(title)
    return ax


__all__ = ["contour", "axis_profile", "LABELS"]
