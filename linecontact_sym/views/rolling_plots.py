"""Plots of steady rolling with traction: mu p and the traction q over x with
the stick zone marked (the rolling direction drawn), and the creepage-force
curve.  The functions take arrays and know nothing of contacts (the rolling
state, :class:`~linecontact_sym.contacts.rolling.state.RollingState`, calls
them); matplotlib is the optional extra ``[plot]``, imported when a plot is
drawn."""
from __future__ import annotations

import numpy as np

from ..core.extras import require


def traction(x, mu_p, q, stick, ax=None, title=None):
    """mu p(x) and q(x) over the contact, the stick zone shaded, an arrow for
    the rolling direction (+x).  Returns the axes."""
    plt = require("plot", "matplotlib.pyplot")
    if ax is None:
        _, ax = plt.subplots(figsize=(6.4, 3.4))
    x, mu_p, q = (np.asarray(v, float) for v in (x, mu_p, q))
    ax.axvspan(float(stick[0]), float(stick[1]), color="tab:green", alpha=0.15, label="stick zone")
    ax.plot(x, mu_p, "k--", lw=1, label=r"$\mu p(x)$")
    ax.plot(x, q, color="tab:blue", lw=2, label=r"$q(x)$")
    top = float(np.max(np.abs(mu_p))) if mu_p.size else 1.0
    ax.annotate("", xy=(x[-1], 1.08 * top), xytext=(x[-1] - 0.2 * (x[-1] - x[0]), 1.08 * top),
                arrowprops=dict(arrowstyle="->"))
    ax.text(x[-1] - 0.1 * (x[-1] - x[0]), 1.12 * top, "rolling", ha="center", va="bottom", fontsize=9)
    ax.set_ylim(min(0.0, 1.1 * float(np.min(q))), 1.25 * top)
    ax.set_xlabel("$x$")
    ax.set_ylabel("traction")
    ax.legend(loc="upper left", fontsize=9)
    if title:
        ax.set_title(title)
    return ax


def creepage_curve(ratio, xi, ax=None, label=None, title=None):
    """The creepage xi against Q/(mu P).  Returns the axes."""
    plt = require("plot", "matplotlib.pyplot")
    if ax is None:
        _, ax = plt.subplots(figsize=(4.8, 3.4))
    ax.plot(np.asarray(xi, float), np.asarray(ratio, float), lw=2, label=label)
    ax.set_xlabel(r"creepage $\xi$")
    ax.set_ylabel(r"$Q/(\mu P)$")
    ax.set_ylim(0, 1.05)
    if label:
        ax.legend(fontsize=9)
    if title:
        ax.set_title(title)
    return ax


__all__ = ["traction", "creepage_curve"]
