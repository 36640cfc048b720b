"""What people look at, for one contact, in the normalised axes of the
literature (``contact.plot(what, ...)`` calls :func:`plot_contact`):

``"pressure"``  p(x)/p0 against x/a at several loads P, with
                p0 = 2P/(pi a) the Hertzian maximum pressure of the same load
                and half-width (the Hertz line contact is the unit
                half-circle; a flat punch is singular at the edges x = -a, a);
``"force"``     the force law P/(E* L) against a/L, L the length scale of
                the profile (R, else b, else 1; ``scale=`` chooses);
``"adhesive"``  the force law of an adhesive contact (any cohesive law)
                P/P_adh against a/a_po (a_po the pull-off
                half-width): the stable branch (dP/da > 0, load control)
                solid, the unstable one dashed, the pull-off (1, -1) and the
                jump-in at P = 0 marked;
``"gap"``       g(x)/f(a) against x/a outside the contact at several loads
                (f(a): the profile's height at the edge).
``"wavy_force"``  a periodic array (``LineContact(f, period=L)``): the
                nominal pressure pbar/p* = P/(p* L) against a/L in (0, 1/2),
                p* the nominal pressure of full contact (Westergaard's axes;
                of an adhesive array, Johnson's 1995: P/(p* L) falls below 0);
``"wavy_pressure"``  p/p* against x/L over a period at the nominal pressures
                pbar = ``loads`` (fractions of p*, default 0.25, 0.5, 0.75).

The contact is used by duck typing (``to_numeric``, ``half_width``,
``profile``, and for adhesion ``law`` and ``pull_off_at``); no contact class is
imported.  The ``*_data`` functions return NumPy arrays (no matplotlib);
the plots need the ``[plot]`` extra and return a matplotlib ``Figure``
(written to ``path`` when given).  Parameter values come as ``values``
(by name); E* defaults to 1, it scales out of every normalised axis.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import sympy as sp

from ..core.errors import DomainError

#: what :func:`plot_contact` draws
PLOTS = ("pressure", "force", "adhesive", "gap", "wavy_force", "wavy_pressure")
_STYLES = ("-", "--", "-.", ":")


def _values(contact, values) -> dict:
    vals = {"E_star": 1.0}
    vals.update({str(getattr(k, "name", k)): float(v) for k, v in (values or {}).items()})
    prof = getattr(contact, "contact", contact).profile      # an adhesive contact wraps a frictionless one
    missing = sorted(s.name for s in prof.expr.free_symbols if s.name != "x" and s.name not in vals)
    law = getattr(contact, "law", None)      # an adhesive contact: the symbols of its cohesive law's parameters
    if law is not None:
        missing += sorted(s.name for s in law.symbols if s.name not in vals and s.name not in missing)
    if missing:
        raise DomainError(f"plotting needs numbers for the parameters {missing}: pass values={{...}}, "
                          f"e.g. values={{{', '.join(repr(m) + ': 1' for m in missing)}}}")
    return vals


def _call(fn, **kw):
    names = getattr(fn, "arguments", None)
    if names is not None:
        kw = {k: v for k, v in kw.items() if k in names}
    return np.asarray(fn(**kw), dtype=float)


def _half_width(contact, load, vals) -> float:
    out = contact.half_width(load, **vals)
    return float(out[0] if isinstance(out, tuple) else out)


def pressure_data(contact, loads, values=None, points: int = 201):
    """``(X, [Y per load], [a per load])``: X = x/a in [-1, 1], Y = p/p0 with
    p0 = 2P/(pi a).

    >>> import linecontact_sym as lcs
    >>> X, (Y,), (a,) = pressure_data(lcs.parabola(), [0.5], {"R": 1}, points=5)
    >>> bool(np.allclose(Y, np.sqrt(1 - X**2)))        # Hertz: the unit half-circle
    True
    """
    vals = _values(contact, values)
    X = np.linspace(-1.0, 1.0, int(points))
    fn = contact.to_numeric("pressure", check=False)
    Ys, As = [], []
    for P in loads:
        a = _half_width(contact, P, vals)
        with np.errstate(invalid="ignore", divide="ignore"):
            p = _call(fn, **vals, a=a, x=np.abs(X) * a)
        Y = p / (2 * float(P) / (np.pi * a))
        Y[~np.isfinite(Y)] = np.nan
        Ys.append(Y)
        As.append(a)
    return X, Ys, As


def _scale(contact, vals, scale):
    if scale is not None:
        return (str(scale), float(vals[str(scale)])) if isinstance(scale, str) else ("L", float(scale))
    for name in ("R", "b"):
        if name in vals:
            return name, vals[name]
    return "1", 1.0


def _a_max(contact, vals, name, L):
    conds = getattr(contact.derivation("force"), "conditions", ())
    bounded = any(name in {s.name for s in getattr(c, "free_symbols", ())} for c in conds)
    return 0.99 * L if bounded else (4 * L if name == "b" else L)


def default_loads(contact, values=None, fractions=(0.25, 0.5, 0.75)) -> list:
    """The loads of the pressure and gap plots when none are given: the
    forces P(a) at half-widths a = 0.25, 0.5, 0.75 of the force plot's range
    (its length scale R or b, or 1), rounded to 3 significant digits.

    >>> import linecontact_sym as lcs                # Hertz: P = pi E* a^2/(4R)
    >>> default_loads(lcs.parabola(), {"R": 1})
    [0.0491, 0.196, 0.442]
    """
    vals = _values(contact, values)
    name, L = _scale(contact, vals, None)
    A = _a_max(contact, vals, name, L) * np.asarray(fractions, dtype=float)
    P = _call(contact.to_numeric("force", check=False), **vals, a=A)
    loads = [float(f"{p:.3g}") for p in np.atleast_1d(P) if np.isfinite(p) and p > 0]
    if not loads:
        raise DomainError(f"no positive load P(a) at a = {A.tolist()}: pass loads=[...]")
    return loads


def force_data(contact, values=None, a_max=None, points: int = 401, scale=None):
    """``(X, Y, L)``: X = a/L in (0, a_max/L], Y = P/(E* L); L is the name
    of the length scale ('R', 'b', or '1').  Default a_max: L for R (0.99 L
    where the force law holds only for a < R), 4 L for b, else 1."""
    vals = _values(contact, values)
    name, L = _scale(contact, vals, scale)
    if a_max is None:
        a_max = _a_max(contact, vals, name, L)
    a_max = float(a_max)
    A = np.linspace(a_max / points, a_max, int(points))
    P = _call(contact.to_numeric("force", check=False), **vals, a=A)
    return A / L, P / (vals["E_star"] * L), name


def adhesive_data(contact, values=None, points: int = 601, a_max: float = 4.0):
    """Normalised force law of an adhesive contact: ``dict(X=a/a_po, Y=P/P_adh, stable=bool mask,
    pull_off=(1, -1), jump_in=(a_in/a_po, 0), a_po, P_adh)``."""
    vals = _values(contact, values)
    po = contact.pull_off_at(**vals)
    a_po, P_adh = float(po.half_width), float(-po.force)
    a_in = _half_width(contact, 0, vals)
    if contact.derivation("force").closed_form:
        X = np.linspace(a_max / points, a_max, int(points))
        P = _call(contact.to_numeric("force", check=False), **vals, a=X * a_po)
    else:   # P(a) is a system (an inner solve per a, Maugis-Dugdale): the law's numbers, at most 121 points
        n = min(int(points), 121)
        X = np.linspace(a_max / n, a_max, n)
        P = np.array([float(contact.force_at(float(x) * a_po, 15, **vals)) for x in X])
    Y = P / P_adh
    stable = np.gradient(Y, X) > 0
    return {"X": X, "Y": Y, "stable": stable, "pull_off": (1.0, -1.0), "jump_in": (a_in / a_po, 0.0),
            "a_po": a_po, "P_adh": P_adh}


def gap_data(contact, loads, values=None, x_max: float = 3.0, points: int = 201):
    """``(X, [Y per load], [a per load])``: X = x/a in [1, x_max], Y = g/f(a)."""
    vals = _values(contact, values)
    X = np.linspace(1.0, float(x_max), int(points))
    fn = contact.to_numeric("gap", check=False)
    prof = getattr(contact, "contact", contact).profile.expr
    f_at = sp.lambdify([s for s in sorted(prof.free_symbols, key=lambda s: s.name)], prof,
                                        "numpy")
    names = [s.name for s in sorted(prof.free_symbols, key=lambda s: s.name)]
    Ys, As = [], []
    for P in loads:
        a = _half_width(contact, P, vals)
        fa = float(f_at(*[a if n == "x" else vals[n] for n in names]))
        with np.errstate(invalid="ignore", divide="ignore"):
            g = _call(fn, **vals, a=a, x=X * a)
        Ys.append(g / fa)
        As.append(a)
    return X, Ys, As


# ------------------------------------------------------------------ drawing
def _wavy(contact, values):
    """(the frictionless periodic contact, L, p* as floats) of a periodic array."""
    base = getattr(contact, "contact", contact)
    geometry = getattr(base, "geometry", None)
    if geometry is None or geometry.period is None:
        raise DomainError("the wavy plots need a periodic array: LineContact(f, period=L)")
    vals = _values(contact, values)
    L = float(geometry.period.xreplace({s: vals[s.name] for s in geometry.symbols if s.name in vals}))
    pstar = base.derivation("full_contact_pressure").expr
    if pstar == sp.oo:
        raise DomainError("p* is infinite (the crest is a corner): no full contact to normalise by; "
                          "plot what='force' instead")
    pv = {k: v for k, v in vals.items()}
    pstar = float(sp.N(pstar.xreplace({s: pv[s.name] for s in pstar.free_symbols if s.name in pv})))
    return base, L, pstar, vals


def wavy_force_data(contact, values=None, points: int = 401):
    """``(X, Y)``: X = a/L in (0, 1/2), Y = P(a)/(p* L) (of the adhesive
    law for an adhesive contact)."""
    base, L, pstar, vals = _wavy(contact, values)
    X = np.linspace(0.5 / points, 0.5 * (1 - 1.0 / points), int(points))
    fn = contact.to_numeric("force", check=False)
    Y = _call(fn, a=X * L, **vals) / (pstar * L)
    return X, Y


def wavy_pressure_data(contact, loads=(0.25, 0.5, 0.75), values=None, points: int = 401):
    """``(X, [Y per load], [a/L per load])``: X = x/L in [-1/2, 1/2], Y = p/p*
    (0 outside the contact) at the nominal pressures pbar = load p*."""
    base, L, pstar, vals = _wavy(contact, values)
    X = np.linspace(-0.5, 0.5, int(points))
    fn = base.to_numeric("pressure", check=False)
    Ys, As = [], []
    for f in loads:
        a = _half_width(base, float(f) * pstar * L, vals)
        inside = np.abs(X * L) < a
        Y = np.zeros_like(X)
        Y[inside] = _call(fn, a=a, x=np.abs(X[inside] * L), **vals) / pstar
        Ys.append(Y)
        As.append(a / L)
    return X, Ys, As


def _figure(size=(5.2, 3.8)):
    from .plots import figure_class
    Figure = figure_class()
    fig = Figure(figsize=size)
    return fig, fig.subplots()


def _finish(fig, ax, path, title=""):
    if title:
        ax.set_title(title, fontsize=10)
    ax.grid(alpha=0.3)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=8)
    if path is not None:
        Path(path).parent.mkdir(parents=True, exist_ok=True)
        fig.savefig(path, dpi=150, bbox_inches="tight")
    return fig


def _mathtext(tex: str) -> str:
    """``$tex$`` when matplotlib's mathtext draws it and it fits a title, else ''."""
    if len(tex) > 90:
        return ""
    try:
        from matplotlib.mathtext import MathTextParser
        MathTextParser("path").parse(f"${tex}$")
    except Exception:  # noqa: BLE001 -- LaTeX that mathtext does not know (cases, ...)
        return ""
    return f"${tex}$"


def profile_label(contact) -> str:
    """The profile for a title, in LaTeX (the package's printer,
    :func:`~linecontact_sym.core.printing.to_latex`): 'the parabola,
    $f(x) = \\frac{x^{2}}{2 R}$'; a profile without a name of its own is its
    formula; a formula mathtext cannot draw is left out."""
    from ..core.printing import to_latex
    prof = getattr(contact, "contact", contact).profile
    name = getattr(prof, "name", None) or ""
    tex = _mathtext("f(x) = " + to_latex(prof.expr))
    if name and name != str(prof.expr):
        return f"the {name}" + (f", {tex}" if tex else "")
    return tex or (f"f(x) = {name}" if name else "")


def _name(contact):
    return profile_label(contact)


def plot_contact(contact, what: str = "force", *, loads=None, values=None, path=None, title=None,
                 points=None, **kw):
    """Draw ``what`` (one of :data:`PLOTS`) for ``contact``; see the module
    docstring for the normalisations.  ``loads``: the loads P (pressure and
    gap; default :func:`default_loads`, the loads at a = 0.25, 0.5, 0.75 of
    the length scale); ``values``: parameter values by name; ``path``: write the figure
    there (PNG, PDF, ... by its suffix).  Returns the matplotlib Figure."""
    if what not in PLOTS:
        raise DomainError(f"unknown plot {what!r}; choose one of {', '.join(PLOTS)}")
    if what in ("pressure", "gap") and not loads:
        loads = default_loads(contact, values)
    name = _name(contact)
    if what == "pressure":
        X, Ys, As = pressure_data(contact, loads, values, points or 201)
        fig, ax = _figure()
        for i, (P, Y, a) in enumerate(zip(loads, Ys, As)):   # styles differ: self-similar laws coincide
            ax.plot(X, Y, _STYLES[i % 4], lw=1.5, label=f"$P = {float(P):g}$ ($a = {a:.3g}$)")
        ax.set_xlabel("$x/a$")
        ax.set_ylabel(r"$p(x)/p_0$,  $p_0 = 2P/(\pi a)$")
        ax.set_xlim(-1, 1)
        ax.set_ylim(bottom=0)
        default = f"Contact pressure{' of ' + name if name else ''}"
    elif what == "force":
        X, Y, L = force_data(contact, values, points=points or 401, **kw)
        fig, ax = _figure()
        ax.plot(X, Y, lw=1.5, label=name or None)
        sub = "" if L == "1" else L
        ax.set_xlabel(f"$a/{sub}$" if sub else "$a$")
        ax.set_ylabel(f"$P/(E^* {sub})$" if sub else "$P/E^*$")
        ax.set_xlim(0, X[-1])
        ax.set_ylim(bottom=0)
        default = f"Force law{' of ' + name if name else ''}"
    elif what == "adhesive":
        d = adhesive_data(contact, values, points or 601, **kw)
        fig, ax = _figure()
        X, Y, st = d["X"], d["Y"], d["stable"]
        ax.plot(np.where(st, X, np.nan), np.where(st, Y, np.nan), "-", color="C0", lw=1.6, label="stable branch")
        ax.plot(np.where(~st, X, np.nan), np.where(~st, Y, np.nan), "--", color="C0", lw=1.2,
                label="unstable branch")
        ax.plot(*d["pull_off"], "o", color="C3", label="pull-off $(a_{po}, P_{min})$")
        ax.plot(*d["jump_in"], "s", color="C2", label="jump-in ($P = 0$)")
        ax.axhline(0, color="0.5", lw=0.8)
        ax.set_xlabel(r"$a/a_{\mathrm{po}}$")
        ax.set_ylabel(r"$P/P_{\mathrm{adh}}$")
        ax.set_xlim(0, X[-1])
        law = getattr(getattr(contact, "law", None), "label", "")
        default = f"{law + ' f' if law else 'F'}orce law{' of ' + name if name else ''}"
    elif what == "wavy_force":
        X, Y = wavy_force_data(contact, values, points or 401)
        fig, ax = _figure()
        ax.plot(X, Y, lw=1.5, label=name or None)
        ax.axhline(0, color="0.5", lw=0.8)
        ax.set_xlabel("$a/L$")
        ax.set_ylabel(r"$\bar{p}/p^{*} = P/(p^{*} L)$")
        ax.set_xlim(0, 0.5)
        ax.set_ylim(max(float(np.nanmin(Y)), -1.0) - 0.05, max(float(np.nanmax(Y)), 0.0) + 0.05)  # -oo at L/2
        default = f"Nominal pressure of a periodic array{' of ' + name if name else ''}"
    elif what == "wavy_pressure":
        loads = loads or (0.25, 0.5, 0.75)
        X, Ys, As = wavy_pressure_data(contact, loads, values, points or 401)
        fig, ax = _figure()
        for i, (f, Y, a) in enumerate(zip(loads, Ys, As)):
            ax.plot(X, Y, _STYLES[i % 4], lw=1.5, label=rf"$\bar{{p}}/p^* = {float(f):g}$ ($a/L = {a:.3g}$)")
        ax.set_xlabel("$x/L$")
        ax.set_ylabel(r"$p(x)/p^{*}$")
        ax.set_xlim(-0.5, 0.5)
        ax.set_ylim(bottom=0)
        default = f"Pressure over a period{' of ' + name if name else ''}"
    else:
        X, Ys, As = gap_data(contact, loads, values, points=points or 201, **kw)
        fig, ax = _figure()
        for i, (P, Y, a) in enumerate(zip(loads, Ys, As)):
            ax.plot(X, Y, _STYLES[i % 4], lw=1.5, label=f"$P = {float(P):g}$ ($a = {a:.3g}$)")
        ax.set_xlabel("$x/a$")
        ax.set_ylabel("$g(x)/f(a)$")
        ax.set_xlim(1, X[-1])
        ax.set_ylim(bottom=0)
        default = f"Gap outside the contact{' of ' + name if name else ''}"
    return _finish(fig, ax, path, default if title is None else title)


__all__ = ["PLOTS", "plot_contact", "default_loads", "profile_label", "pressure_data", "force_data", "adhesive_data",
           "gap_data", "wavy_force_data", "wavy_pressure_data"]
