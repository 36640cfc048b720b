"""Figures of a viscoelastic line-contact history (matplotlib, imported only
when drawing): the force P(t) with the two elastic limits E*(0) Pi(a(t)) and
E*(oo) Pi(a(t)) drawn beside it, the half-width a(t), and the hysteresis loop
P(a) of a load-unload cycle.  The numbers come in as arrays (the contact
computes them, :meth:`~linecontact_sym.contacts.viscoelastic.ViscoelasticLineContact.history_data`);
this module never imports a contact class."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..core.extras import require


def _save(fig, path):
    if path is not None:
        Path(path).parent.mkdir(parents=True, exist_ok=True)
        fig.savefig(path, dpi=150, bbox_inches="tight")
    return fig


def history_figure(data: dict, path=None, title: str = ""):
    """P(t) (solid) between its elastic limits (dashed: E*(0), dotted: E*(oo);
    a Kelvin-Voigt E*(0) is infinite and not drawn) over a(t) (lower panel)."""
    Figure = require("plot", "matplotlib.figure").Figure
    fig = Figure(figsize=(5.2, 5.2))
    ax, ax2 = fig.subplots(2, 1, sharex=True)
    ts = np.asarray(data["t"])
    ax.plot(ts, data["P"], "k-", label="viscoelastic (Lee-Radok / Ting)")
    if np.all(np.isfinite(data["P_E0"])):
        ax.plot(ts, data["P_E0"], "C0--", label="elastic, E*(0)")
    ax.plot(ts, data["P_Einf"], "C1:", label="elastic, E*(oo)")
    ax.set_ylabel("P(t)")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    ax2.plot(ts, data["a"], "k-")
    ax2.set_xlabel("t")
    ax2.set_ylabel("a(t)")
    ax2.grid(alpha=0.3)
    if title:
        ax.set_title(title, fontsize=10)
    return _save(fig, path)


def hysteresis_figure(data: dict, path=None, title: str = ""):
    """The loop P(a) of a load-unload cycle, with the elastic law E*(oo) Pi(a)."""
    Figure = require("plot", "matplotlib.figure").Figure
    fig = Figure(figsize=(5.2, 3.8))
    ax = fig.subplots()
    ax.plot(data["a"], data["P"], "k-", label="viscoelastic cycle")
    ax.plot(data["a"], data["P_Einf"], "C1:", label="elastic, E*(oo)")
    ax.set_xlabel("a")
    ax.set_ylabel("P")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    if title:
        ax.set_title(title, fontsize=10)
    return _save(fig, path)


__all__ = ["history_figure", "hysteresis_figure"]
