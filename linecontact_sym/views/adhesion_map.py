"""The adhesion map of a Maugis-Dugdale line contact: the force law P(a) for
several Maugis parameters lambda (with the JKR law, lambda -> oo), and the
load-control pull-off against lambda (with its two limits: JKR, and the rigid
profile with a Dugdale law at small lambda).

Axes are normalised by the JKR pull-off of the same profile and work of
adhesion: P/|P_JKR| against a/a_JKR (for the parabola, Baney & Hui's
Pbar/Pbar_JKR and abar/abar_JKR).  The contact is used by duck typing
(``sigma0_for``, ``law``, ``pull_off_at``, ``jkr``); no contact class is
imported.  :func:`adhesion_map_data` returns NumPy arrays; the plot needs the
``[plot]`` extra.
"""
from __future__ import annotations

from pathlib import Path

import mpmath
import numpy as np

from ..core.precision import workdps


def adhesion_map_data(md, values: dict, lambdas=(0.1, 0.5, 1, 3, 10), a_range=(0.02, 3.0), points: int = 60,
                      lambda_grid=None, rigid=None) -> dict:
    """Arrays for the adhesion map.

    ``values``: E_star, the work of adhesion and the profile's parameters (by
    name; sigma_0 is set from each lambda).  ``a_range``: a/a_JKR.  ``rigid``:
    an optional function sigma_0 -> the rigid-profile pull-off (the small-lambda
    limit), evaluated along ``lambda_grid``.
    """
    po_j = md.jkr.pull_off_at(15, **values)
    PJ, AJ = abs(po_j.force), po_j.half_width
    s1 = md.sigma0_for(1, **values)
    name = md.sigma0.name
    abar = np.geomspace(a_range[0], a_range[1], points)
    curves = {}
    with workdps(15):
        for lam in lambdas:
            law = md.numeric_law(**values, **{name: s1 * mpmath.mpf(lam)})
            curves[lam] = np.array([float(law.P_and_slope(AJ * mpmath.mpf(float(x)), 10)[0] / PJ) for x in abar])
        jkr = md.jkr.to_numeric("force", backend="mpmath", dps=15, check=False)
        jkr_curve = np.array([float(jkr(a=AJ * mpmath.mpf(float(x)), **values) / PJ) for x in abar])
        lam_grid = np.geomspace(0.02, 50, 13) if lambda_grid is None else np.asarray(lambda_grid, dtype=float)
        po = np.array([float(md.pull_off_at(10, **values, **{name: s1 * mpmath.mpf(float(lm))}).force / PJ)
                       for lm in lam_grid])
        rig = None if rigid is None else np.array([float(rigid(s1 * mpmath.mpf(float(lm))) / PJ) for lm in lam_grid])
    return {"abar": abar, "curves": curves, "jkr": jkr_curve, "lambda": lam_grid, "pull_off": po, "rigid": rig,
            "P_jkr": float(PJ), "a_jkr": float(AJ)}


def plot_adhesion_map(data: dict, path=None, title: str = "Maugis-Dugdale line contact"):
    """Two panels: P/|P_JKR| against a/a_JKR for each lambda (JKR dashed), and
    the pull-off P_min/|P_JKR| against lambda (the rigid limit dotted)."""
    from .plots import figure_class
    Figure = figure_class()
    fig = Figure(figsize=(10, 4))
    ax1, ax2 = fig.subplots(1, 2)
    for lam, y in data["curves"].items():
        ax1.plot(data["abar"], y, "-", lw=1.6, label=rf"$\lambda = {lam:g}$")
    ax1.plot(data["abar"], data["jkr"], "k--", lw=1.2, label=r"JKR ($\lambda\to\infty$)")
    ax1.axhline(0, color="0.7", lw=0.8)
    ax1.set_xlabel(r"$a/a_{\mathrm{JKR}}$")
    ax1.set_ylabel(r"$P/|P_{\mathrm{JKR}}|$")
    ax1.set_ylim(-1.5, 2.0)
    ax1.legend(fontsize=8)
    ax2.semilogx(data["lambda"], data["pull_off"], "o-", lw=1.6, label="Maugis-Dugdale")
    ax2.axhline(-1, color="k", ls="--", lw=1.0, label="JKR")
    if data.get("rigid") is not None:
        ax2.semilogx(data["lambda"], data["rigid"], "k:", lw=1.2, label="rigid profile, Dugdale law")
    ax2.set_xlabel(r"Maugis parameter $\lambda$")
    ax2.set_ylabel(r"$P_{\min}/|P_{\mathrm{JKR}}|$")
    ax2.set_ylim(-1.6, 0.05)
    ax2.legend(fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    if path is not None:
        Path(path).parent.mkdir(parents=True, exist_ok=True)
        fig.savefig(path, dpi=150, bbox_inches="tight")
    return fig


__all__ = ["adhesion_map_data", "plot_adhesion_map"]
