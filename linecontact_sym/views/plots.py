"""Plots of a derived quantity of one or more contacts, in normalised axes.

The contacts are passed in and used by duck typing: the view calls
``contact.to_numeric(quantity)`` (a NumPy callable of keyword arguments; its
``arguments`` attribute, when present, names the ones it takes) and never
imports a contact class.  The axes are *data*: formulas such as
``x = "a/b"`` and ``y = "2*R*P/(E_star*b**2)"`` (strings are parsed by the
whitelisted :mod:`linecontact_sym.parsing`; SymPy expressions are taken as
they are).  The abscissa's one symbol not fixed by ``values`` is swept (the
half-width ``a`` for a force law, ``x`` at fixed ``a`` for a pressure or a
gap); the ordinate is written in the value of the quantity: ``P`` (force),
``p`` (pressure) or ``g`` (gap), see :data:`VALUE_SYMBOLS`.

:func:`curve_data` computes the normalised curves (NumPy only);
:func:`plot_quantity` draws them (matplotlib, imported only then), with an
optional lower panel holding the ratio of two curves, and writes PNG and PDF.
A figure whose inputs (a SHA-256 of its numbers, labels and styles, this
module's source and matplotlib's version) were drawn before into files that
are still the bytes written then (their SHA-256, in a hidden record
``.<stem>.drawn`` beside them) is not redrawn.
"""
from __future__ import annotations

import inspect

from pathlib import Path

import numpy as np
import sympy as sp

from ..core import symbols as S
from ..core.conversion import to_basic
from ..core.errors import DomainError
from ..core.extras import require
from ..parsing import parse_expr

#: the symbol that stands for the value of each quantity in an ordinate formula
VALUE_SYMBOLS = {"force": S.P, "pressure": sp.Symbol("p", real=True), "gap": sp.Symbol("g", real=True)}


def _axis_expr(v, quantity=None, where="axis"):
    if isinstance(v, str):
        ph = {VALUE_SYMBOLS[quantity].name: VALUE_SYMBOLS[quantity]} if quantity else {}
        return parse_expr(v, placeholders=ph, where=where)
    return to_basic(v)


def _fixed(values):
    out = {}
    for k, v in (values or {}).items():
        sym = k if isinstance(k, sp.Symbol) else sp.Symbol(str(k))
        out[sym.name] = float(v)
    return out


def curve_data(contacts, quantity: str = "force", *, x, y, x_range, values=None, points: int = 401):
    """The normalised curves ``(X, [Y_1, Y_2, ...])``, one Y per contact.

    ``X`` runs over ``points`` equally spaced values of the normalised
    abscissa ``x`` in ``x_range``; the swept symbol is the one free symbol of
    ``x`` that ``values`` does not fix, recovered by solving ``x = X`` for
    it.  Each contact's quantity is evaluated there with ``values`` and put
    into the ordinate formula ``y``.  Points where a value is not finite are
    NaN (a gap in the drawn line).

    >>> class Hertz:   # duck-typed: P(a) = pi E* a^2/(4R)
    ...     def to_numeric(self, quantity):
    ...         return lambda a, R, E_star: np.pi * E_star * a**2 / (4 * R)
    >>> X, (Y,) = curve_data([Hertz()], x="a/R", y="P/(E_star*R)", x_range=(0, 1), points=3,
    ...                      values={"R": 2, "E_star": 3})
    >>> X.tolist(), np.allclose(Y, np.pi * X**2 / 4)
    ([0.0, 0.5, 1.0], True)
    """
    if quantity not in VALUE_SYMBOLS:
        raise DomainError(f"plots draw one of {sorted(VALUE_SYMBOLS)}, got {quantity!r}")
    x_expr = _axis_expr(x, where="x axis")
    y_expr = _axis_expr(y, quantity, where="y axis")
    fixed = _fixed(values)
    subs = {s: fixed[s.name] for s in (x_expr.free_symbols | y_expr.free_symbols) if s.name in fixed}
    swept = [s for s in x_expr.free_symbols if s.name not in fixed]
    if len(swept) != 1:
        raise DomainError(f"the abscissa {x_expr} must have exactly one symbol not fixed by the values "
                          f"{sorted(fixed)}; it has {sorted(map(str, swept))}")
    var = swept[0]
    Xs = sp.Dummy("X", real=True)
    sol = sp.solve(sp.Eq(x_expr.xreplace(subs), Xs), var)
    if len(sol) != 1:
        raise DomainError(f"cannot recover {var} from the abscissa {x_expr} = X (solutions: {sol})")
    value = VALUE_SYMBOLS[quantity]
    if value not in y_expr.free_symbols:
        raise DomainError(f"the ordinate {y_expr} does not contain the value {value} of the {quantity}")
    left = y_expr.free_symbols - {value, var} - set(subs)
    if left:
        raise DomainError(f"the ordinate {y_expr} needs values for {sorted(map(str, left))}")
    X = np.linspace(float(x_range[0]), float(x_range[1]), int(points))
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        sweep = np.broadcast_to(np.asarray(sp.lambdify(Xs, sol[0], "numpy")(X), dtype=float), X.shape)
        y_of = sp.lambdify((value, var), y_expr.xreplace(subs), "numpy")
        curves = []
        for contact in contacts:
            # a package contact's export without its per-call domain check: grids may touch a = 0
            takes_check = "check" in inspect.signature(contact.to_numeric).parameters
            fn = contact.to_numeric(quantity, check=False) if takes_check else contact.to_numeric(quantity)
            kw = {**fixed, var.name: sweep}
            names = getattr(fn, "arguments", None)
            if names is not None:
                kw = {k: v for k, v in kw.items() if k in names}
            vals = np.asarray(fn(**kw), dtype=float)
            Y = np.broadcast_to(np.asarray(y_of(vals, sweep), dtype=float), X.shape).copy()
            Y[~np.isfinite(Y)] = np.nan
            curves.append(Y)
    return X, curves


_FIGURE: dict = {}       # matplotlib's Figure -> the package's


def figure_class():
    """The class of the package's figures: a matplotlib ``Figure`` (made
    without pyplot) that shows itself as PNG in Jupyter even where no pyplot
    figure has switched the inline backend on yet (a kernel's first plot):
    there IPython printed ``<Figure size ...>``.  Where IPython has a
    formatter for figures (the inline backend is on), that formatter is used."""
    base = require("plot", "matplotlib.figure").Figure
    if base not in _FIGURE:
        class Figure(base):
            __module__ = base.__module__        # pickles (and unpickles) as matplotlib's own

            def _repr_png_(self):
                import io
                buf = io.BytesIO()
                self.savefig(buf, format="png", bbox_inches="tight")
                return buf.getvalue()
        Figure.__qualname__ = "Figure"
        _FIGURE[base] = Figure
    return _FIGURE[base]


def plot_quantity(contacts, quantity: str = "force", *, x, y, x_range, values=None, points: int = 401,
                  labels=None, styles=None, widths=None, title: str = "", xlabel: str = "", ylabel: str = "",
                  y_min=None, y_max=None, marks=(), ratio=None, ratio_label: str = "", size=None,
                  out_dir=".", stem: str = "figure", formats=("png", "pdf")) -> list:
    """Draw ``quantity`` of each contact in normalised axes; write ``stem``.png/.pdf.

    The curves are those of :func:`curve_data` (same ``x``, ``y``,
    ``x_range``, ``values``, ``points``).  ``labels``, ``styles`` (line
    styles such as ``"--"``) and ``widths`` go one per contact (colours C0,
    C1, ... in order).  ``marks`` are ``(X, text)`` vertical marker lines;
    ``ratio = (i, j)`` adds a lower panel with curve i / curve j (where
    curve j is non-zero) labelled ``ratio_label``.  Axis labels not given
    are the axis formulas in LaTeX (``$\\frac{a}{R}$``).  Returns the paths
    written, one per format.  Needs matplotlib (the ``[plot]`` extra).
    """
    from ..core.printing import to_latex
    xlabel = xlabel or f"${to_latex(_axis_expr(x, where='x axis'))}$"     # the axis formulas, in LaTeX
    ylabel = ylabel or f"${to_latex(_axis_expr(y, quantity, where='y axis'))}$"
    X, curves = curve_data(contacts, quantity, x=x, y=y, x_range=x_range, values=values, points=points)
    k = len(curves)
    labels = list(labels or [None] * k)
    styles = list(styles or ["-"] * k)
    widths = list(widths or [1.5] * k)
    out = Path(out_dir)
    paths = [out / f"{stem}.{fmt}" for fmt in formats]
    inputs = _drawing_inputs(X, curves, labels, styles, widths, title, xlabel, ylabel, y_min, y_max, marks, ratio,
                             ratio_label, size, formats)
    if _drawn_before(out, stem, inputs, paths):
        return paths
    Figure = figure_class()
    if ratio is None:
        fig = Figure(figsize=size or (5.2, 3.8))
        ax, axr = fig.subplots(), None
    else:
        fig = Figure(figsize=size or (5.2, 5.0))
        ax, axr = fig.subplots(2, 1, sharex=True, gridspec_kw={"height_ratios": [3, 1.2], "hspace": 0.08})
    for i, Y in enumerate(curves):
        ax.plot(X, Y, styles[i], color=f"C{i}", lw=widths[i], label=labels[i])
    span = X[-1] - X[0]
    for xm, text in marks:
        ax.axvline(xm, color="0.6", lw=0.8, ls=":")
        if text:
            ax.text(xm + 0.0125 * span, 0.5, text, color="0.4", fontsize=8, va="center",
                    transform=ax.get_xaxis_transform())
    ax.set_ylabel(ylabel)
    if title:
        ax.set_title(title, fontsize=10)
    ax.set_ylim(bottom=y_min, top=y_max)
    ax.grid(alpha=0.3)
    if any(labels):
        ax.legend(fontsize=8, loc="upper left")
    bottom = ax
    if axr is not None:
        i, j = ratio
        with np.errstate(invalid="ignore", divide="ignore"):
            r = np.where(curves[j] != 0, curves[i] / np.where(curves[j] != 0, curves[j], 1.0), np.nan)
        axr.plot(X, r, "-", color=f"C{k}", lw=1.5)
        axr.axhline(1.0, color="0.6", lw=0.8, ls=":")
        axr.set_ylabel(ratio_label)
        axr.grid(alpha=0.3)
        bottom = axr
    bottom.set_xlabel(xlabel)
    bottom.set_xlim(X[0], X[-1])
    out.mkdir(parents=True, exist_ok=True)
    for p in paths:
        fig.savefig(p, dpi=150, bbox_inches="tight")
    _record_drawing(out, stem, inputs, paths)
    return paths


def _drawing_inputs(*parts) -> str:
    """SHA-256 of everything a drawing depends on: the curves' numbers (their
    bytes), every label, style and size, the source of this module and the
    matplotlib version."""
    import hashlib
    from importlib.metadata import PackageNotFoundError, version
    h = hashlib.sha256()
    for part in parts:
        if isinstance(part, np.ndarray):
            h.update(np.ascontiguousarray(part, dtype=float).tobytes())
        elif isinstance(part, list) and part and isinstance(part[0], np.ndarray):
            for arr in part:
                h.update(np.ascontiguousarray(arr, dtype=float).tobytes())
        else:
            h.update(repr(part).encode())
        h.update(b"\x00")
    h.update(Path(__file__).read_bytes())
    try:
        h.update(version("matplotlib").encode())
    except PackageNotFoundError:
        pass
    return h.hexdigest()


def _record_path(out, stem):
    return out / f".{stem}.drawn"


def _drawn_before(out, stem, inputs, paths) -> bool:
    """Were these very inputs drawn into ``paths`` before, and are the files
    still what was written then (each file's SHA-256 checked against the
    record)?  Then the figure is not redrawn (nor matplotlib imported)."""
    import hashlib
    import json
    try:
        rec = json.loads(_record_path(out, stem).read_text())
        if not isinstance(rec, dict) or rec.get("inputs") != inputs:
            return False
        files = rec.get("files")
        if not isinstance(files, dict) or set(files) != {p.name for p in paths}:
            return False
        return all(hashlib.sha256(p.read_bytes()).hexdigest() == files[p.name] for p in paths)
    except (OSError, ValueError):
        return False


def _record_drawing(out, stem, inputs, paths) -> None:
    import hashlib
    import json
    try:
        rec = {"inputs": inputs, "files": {p.name: hashlib.sha256(p.read_bytes()).hexdigest() for p in paths}}
        _record_path(out, stem).write_text(json.dumps(rec))
    except OSError:          # no record: the next call draws again
        pass


__all__ = ["VALUE_SYMBOLS", "curve_data", "plot_quantity"]
