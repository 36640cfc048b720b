"""The paper's figures redrawn from the derived laws (matplotlib).

* Fig. 4 -- worn cylinder (a cylinder with a flat of half-width b, Eq. 21):
  normalised load 2 R P / (E* b^2) against a/b, the derived force law
  (Eq. 23, solid) and the parabola without a flat (Eq. 13, dashed).
* Fig. 5 -- exact cylinder f = R - sqrt(R^2 - x^2): P / (E* R) against a/R,
  the derived law (Eq. 26, solid) and the parabolic (Hertz) approximation
  (Eq. 13, dashed), with the ratio of the two in a lower panel.

Every curve is evaluated from the engine's derived SymPy expression (exported
with :meth:`LineContact.to_numeric`), never from a hand-typed formula.  Each
function writes PNG and PDF and returns the paths.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..core.extras import require


def _plt():
    # imported lazily: the package itself does not need matplotlib (the [plot]
    # extra; headless machines fall back to the Agg backend by themselves)
    return require("plot", "matplotlib.pyplot")


def _save(fig, out_dir, stem, formats):
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    paths = []
    for fmt in formats:
        p = out / f"{stem}.{fmt}"
        fig.savefig(p, dpi=150, bbox_inches="tight")
        paths.append(p)
    return paths


def fig4_data(a_over_b=None, budget: float = 20.0):
    """(a/b, worn cylinder 2RP/(E* b^2), parabola 2RP/(E* b^2)) from the engine."""
    from ..contacts.catalogue import parabola, worn_cylinder
    if a_over_b is None:
        a_over_b = np.linspace(0.0, 4.0, 401)
    worn = worn_cylinder(budget=budget)
    para = parabola(budget=budget)
    fw = worn.to_numeric("force", "numpy")
    fp = para.to_numeric("force", "numpy")
    b, R, E = 1.0, 1.0, 1.0
    a = np.asarray(a_over_b, dtype=float) * b
    aa = np.where(a > 0, a, 1e-300)
    worn_load = np.where(a > 0, fw(a=aa, b=b, R=R, E_star=E), 0.0) * 2 * R / (E * b**2)
    para_load = fp(a=a, R=R, E_star=E) * 2 * R / (E * b**2)
    return a_over_b, np.asarray(worn_load, dtype=float), np.asarray(para_load, dtype=float), worn, para


def fig4(out_dir=".", formats=("png", "pdf"), budget: float = 20.0):
    """Fig. 4 of Popov (2017): worn cylinder vs parabola; returns the file paths."""
    plt = _plt()
    ab, worn_load, para_load, worn, para = fig4_data(budget=budget)
    fig, ax = plt.subplots(figsize=(5.2, 3.8))
    ax.plot(ab, worn_load, "-", color="C0", lw=2, label="worn cylinder, flat of half-width $b$ (Eq. 23)")
    ax.plot(ab, para_load, "--", color="C1", lw=1.5, label="parabola without flat (Eq. 13)")
    ax.axvline(1.0, color="0.6", lw=0.8, ls=":")
    ax.text(1.05, 0.5 * max(para_load.max(), 1), "$a = b$: edge of the flat", color="0.4", fontsize=8,
            va="center")
    ax.set_xlabel("half-width $a/b$")
    ax.set_ylabel(r"normalised load $2RP/(E^{*}b^{2})$")
    ax.set_title("Fig. 4: worn cylinder (derived force law)", fontsize=10)
    ax.set_xlim(ab[0], ab[-1])
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    paths = _save(fig, out_dir, "fig4_worn_cylinder", formats)
    plt.close(fig)
    return paths


def fig5_data(a_over_R=None, budget: float = 20.0):
    """(a/R, exact cylinder P/(E* R), Hertz P/(E* R)) from the engine."""
    from ..contacts.catalogue import exact_cylinder, parabola
    if a_over_R is None:
        a_over_R = np.linspace(0.0, 0.99, 397)
    exact = exact_cylinder(budget=budget)
    para = parabola(budget=budget)
    fe = exact.to_numeric("force", "numpy")
    fp = para.to_numeric("force", "numpy")
    R, E = 1.0, 1.0
    a = np.asarray(a_over_R, dtype=float) * R
    exact_load = np.asarray(fe(a=a, R=R, E_star=E), dtype=float) / (E * R)
    hertz_load = np.asarray(fp(a=a, R=R, E_star=E), dtype=float) / (E * R)
    return a_over_R, exact_load, hertz_load, exact, para


def fig5(out_dir=".", formats=("png", "pdf"), budget: float = 20.0):
    """Fig. 5 of Popov (2017): exact cylinder vs Hertz; returns the file paths."""
    plt = _plt()
    aR, exact_load, hertz_load, exact, para = fig5_data(budget=budget)
    fig, (ax, axr) = plt.subplots(2, 1, figsize=(5.2, 5.0), sharex=True,
                                  gridspec_kw={"height_ratios": [3, 1.2], "hspace": 0.08})
    ax.plot(aR, exact_load, "-", color="C0", lw=2, label=r"exact cylinder $E^{*}R\,[K(k)-E(k)]$, $k=a/R$ (Eq. 26)")
    ax.plot(aR, hertz_load, "--", color="C1", lw=1.5, label=r"parabola (Hertz) $\pi E^{*}a^{2}/(4R)$ (Eq. 13)")
    ax.set_ylabel(r"normalised load $P/(E^{*}R)$")
    ax.set_title("Fig. 5: exact cylinder vs Hertz (derived force laws)", fontsize=10)
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    with np.errstate(invalid="ignore", divide="ignore"):
        ratio = np.where(hertz_load > 0, exact_load / hertz_load, 1.0)
    axr.plot(aR, ratio, "-", color="C2", lw=1.5)
    axr.axhline(1.0, color="0.6", lw=0.8, ls=":")
    axr.set_ylabel("exact / Hertz")
    axr.set_xlabel("half-width $a/R$")
    axr.set_xlim(aR[0], aR[-1])
    axr.grid(alpha=0.3)
    paths = _save(fig, out_dir, "fig5_exact_cylinder", formats)
    plt.close(fig)
    return paths


def all_figures(out_dir=".", formats=("png", "pdf"), budget: float = 20.0):
    return fig4(out_dir, formats, budget) + fig5(out_dir, formats, budget)


__all__ = ["fig4", "fig5", "fig4_data", "fig5_data", "all_figures"]
