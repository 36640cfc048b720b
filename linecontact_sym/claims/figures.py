"""A paper's figures, redrawn from the derived laws.

The figures are data of the claims file (``[[figures]]`` tables, see
:mod:`.spec`): profiles, parameter values, normalised axes, labels and a
caption.  Each curve is the engine's derived quantity of its profile
(exported with ``to_numeric``), never a hand-typed formula; the drawing is
the general view :func:`linecontact_sym.views.plots.plot_quantity`.
"""
from __future__ import annotations

from ..views.plots import plot_quantity
from .derive import figure_contacts
from .spec import Paper, load_paper


def draw_figures(paper, out_dir=".", formats=("png", "pdf"), budget: float = 20.0, only=None) -> list:
    """Draw the figures of ``paper`` (a :class:`~.spec.Paper`, a path or a
    shipped name such as ``popov2017``) into ``out_dir``; ``only`` limits the
    run to the given file stems.  Returns the paths written, in order."""
    if not isinstance(paper, Paper):
        paper = load_paper(paper)
    paths = []
    for fig in paper.figures:
        if only is not None and fig.file not in only:
            continue
        contacts = figure_contacts([c.profile for c in fig.curves], paper.ranges, budget)
        names = [c.name for c in fig.curves]
        ratio = (names.index(fig.ratio[0]), names.index(fig.ratio[1])) if fig.ratio else None
        paths += plot_quantity(contacts, fig.quantity, x=fig.x, y=fig.y, x_range=fig.x_range, values=fig.values,
                               points=fig.points, labels=[c.label for c in fig.curves],
                               styles=[c.style for c in fig.curves], widths=[c.width for c in fig.curves],
                               title=fig.title, xlabel=fig.xlabel, ylabel=fig.ylabel, y_min=fig.y_min,
                               y_max=fig.y_max, marks=fig.marks, ratio=ratio, ratio_label=fig.ratio_label,
                               size=fig.size, out_dir=out_dir, stem=fig.file, formats=formats)
    return paths


def captions(paper) -> dict:
    """{file stem: caption} of the paper's figures."""
    return {fig.file: fig.caption for fig in paper.figures}


__all__ = ["draw_figures", "captions"]
