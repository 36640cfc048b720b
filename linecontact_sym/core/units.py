"""Physical units at the edge of the package (the optional ``[units]`` extra: pint).

Inside, every number is a plain number in SI units.  A value given as a pint
``Quantity`` (``Q_(1, "mm")``) is checked against the dimension declared for
its name and converted to SI; a result asked for with quantities comes back
as a pint ``Quantity`` in the SI unit declared for it (``N/m`` for a force
per unit length), in the registry of the quantities given::

    >>> import pint                                            # doctest: +SKIP
    >>> Q_ = pint.UnitRegistry().Quantity                      # doctest: +SKIP
    >>> lcs.parabola().evaluate_at("force", a=Q_(1, "mm"), E_star=Q_(210, "GPa"),
    ...                            R=Q_(5, "mm"))              # doctest: +SKIP
    <Quantity(32986.7..., 'newton / meter')>

Where the units are declared (once each): the arguments' next to their
symbols (:data:`linecontact_sym.core.symbols.UNITS`), each result's next to
its declaration in the contact's registry (``Quantity(..., unit="N/m")``).
A profile parameter without a declared unit (``c`` of ``c x^n``, whose unit
m^(1-n) depends on n; a user's parameter) is converted to SI base units and
checked through the profile: f(x) must come out as a length.

Plain numbers never touch this module's pint side: without quantities
nothing changes, and pint is not imported.
"""
from __future__ import annotations

from .errors import DomainError


def is_quantity(v) -> bool:
    """A pint Quantity (duck-typed: pint is not imported here)."""
    return hasattr(v, "magnitude") and hasattr(v, "dimensionality") and hasattr(v, "to_base_units")


def split_units(values: dict, units: dict):
    """``(plain values in SI, registry or None)``: each pint Quantity among
    ``values`` checked against ``units[name]`` (an SI unit string; ``""``
    dimensionless; missing: not declared, converted to SI base units) and
    replaced by its SI magnitude.  Raises
    :class:`~linecontact_sym.core.errors.DomainError` on a wrong dimension.
    Without quantities: ``(values, None)`` unchanged."""
    if not any(is_quantity(v) or _holds_quantities(v) for v in values.values()):
        return values, None
    registry = None
    out = {}
    for k, v in values.items():
        many = not is_quantity(v) and _holds_quantities(v)     # [Q_(1, "mm"), Q_(2, "mm")]
        if not (is_quantity(v) or many):
            out[k] = v
            continue
        reg = next(e for e in (v.ravel() if hasattr(v, "ravel") else v) if is_quantity(e))._REGISTRY \
            if many else v._REGISTRY
        if registry is None:
            registry = reg
        elif reg is not registry:
            raise DomainError(f"{k} = {v!r} comes from another pint UnitRegistry than the other values; "
                              f"use one registry")
        out[k] = _magnitudes(k, v, units.get(k), reg) if many else _si_of(k, v, units.get(k), reg)
    return out, registry


def si_magnitude(number: str, unit_text: str, unit: str, name: str):
    """The SI magnitude (a float) of ``number`` (decimal text) in ``unit_text``
    (pint's unit parser: ``GPa``, ``mm``, ``N/m``; nothing evaluated) for a
    value named ``name`` whose SI unit is ``unit`` (``""``: dimensionless).
    Needs the ``[units]`` extra (pint);
    raises :class:`~linecontact_sym.core.errors.DomainError` on a wrong
    dimension or a text pint does not know as a unit."""
    from .extras import require
    pint = require("units", "pint")
    reg = pint.get_application_registry()
    try:
        q = reg.Quantity(float(number)) * reg.parse_units(unit_text)
        return float(q.to(unit or "dimensionless").magnitude)
    except pint.DimensionalityError:
        raise DomainError(f"{name} = {number} {unit_text}: the unit {unit_text!r} is not one of "
                          f"{describe(unit)} in {unit or 'dimensionless'} ({name})") from None
    except Exception as exc:  # noqa: BLE001 -- pint's parser refusing the text
        raise DomainError(f"{name} = {number}{unit_text}: {unit_text!r} is not a unit ({exc})") from None


def _magnitudes(k, v, unit, registry):
    """A list or array of pint quantities (one registry, one dimension) as
    a float array in ``unit`` (None: SI base units); a mix of quantities and
    plain numbers is refused (a plain number's unit would be a guess)."""
    import numpy as np
    items = list(v.ravel()) if isinstance(v, np.ndarray) else list(v)
    if not all(is_quantity(e) for e in items):
        raise DomainError(f"{k} = {v!r} mixes pint quantities and plain numbers; give all with units, or "
                          f"all as plain SI numbers")
    if any(e._REGISTRY is not registry for e in items):
        raise DomainError(f"{k} = {v!r} comes from another pint UnitRegistry than the other values; "
                          f"use one registry")
    out = []
    for e in items:
        out.append(_si_of(k, e, unit, registry))
    arr = np.asarray(out, dtype=float)
    return arr.reshape(v.shape) if isinstance(v, np.ndarray) else arr


def _si_of(k, v, unit, registry):
    if unit is None:
        return _plain(v.to_base_units().magnitude)
    target = registry.Quantity(1, unit)
    if v.dimensionality != target.dimensionality:
        raise DomainError(f"{k} = {v} has the dimension {v.dimensionality}; {k} is "
                          f"{describe(unit)} ({unit or 'dimensionless'}, dimension {target.dimensionality})")
    return _plain(v.to(target.units).magnitude)


def _holds_quantities(v) -> bool:
    """A list, tuple or object array with a pint quantity among its elements."""
    if isinstance(v, (list, tuple)):
        return any(is_quantity(e) for e in v)
    return getattr(v, "dtype", None) is not None and v.dtype.kind == "O" and any(is_quantity(e) for e in v.ravel())


def strip_units(values: dict, units: dict, quantity, profile=None):
    """``(values in SI, registry or None, unit of the result)`` for a
    ``quantity`` (a registry declaration: its ``unit`` and ``name``):
    :func:`split_units`, the result's unit (None declared: a DomainError),
    and the profile's parameters without a declared unit checked through
    the profile (:func:`check_profile_units`)."""
    plain, registry = split_units(values, units)
    if registry is None:
        return values, None, None
    if quantity.unit is None:
        raise DomainError(f"the {quantity.name} declares no unit; give plain SI numbers")
    if profile is not None:
        check_profile_units(profile, values, registry, units)
    return plain, registry, quantity.unit


def check_profile_units(profile, values, registry, units):
    """The profile's parameters without a declared unit (c of c x^n, a
    user's parameter), when all given as quantities: f(x) evaluated with
    the quantities (x in the unit of a) must be a length, else a
    :class:`~linecontact_sym.core.errors.DomainError` naming them.  A
    profile pint cannot carry through (a Piecewise, ...) is not checked."""
    import sympy as sp
    from .extras import require
    free = [p for p in profile.params if p.name not in units]
    if not free or not all(is_quantity(values.get(p.name)) for p in free):
        return                       # nothing undeclared, or given as plain SI numbers: not checked
    pint = require("units", "pint")
    syms = sorted(profile.expr.free_symbols, key=lambda s: s.name)
    args = []
    for s in syms:
        v = values.get("a", registry.Quantity(1.0, "m")) if s.name == "x" else values.get(s.name)
        if v is None:
            return
        if not is_quantity(v) and s.name in units:
            v = registry.Quantity(v, units[s.name] or "dimensionless")
        args.append(v.to_base_units() if is_quantity(v) else v)
    names = ", ".join(p.name for p in free)
    try:
        out = sp.lambdify(syms, profile.expr, "numpy")(*args)
    except pint.DimensionalityError as exc:
        raise DomainError(f"with the units given, the profile f(x) = {profile.expr} is not a length "
                          f"({exc}); check the units of {names}") from None
    except Exception:  # noqa: BLE001 -- a function pint does not carry: not checked
        return
    if not is_quantity(out) or out.dimensionality != registry.Quantity(1.0, "m").dimensionality:
        dim = out.dimensionality if is_quantity(out) else "dimensionless"
        raise DomainError(f"with the units given, the profile f(x) = {profile.expr} has the dimension {dim}, "
                          f"not a length; check the units of {names}")


def with_unit(value, unit, registry):
    """``value`` as a Quantity of ``registry`` in ``unit`` (None: not declared:
    a DomainError, since the number's unit is unknown)."""
    if registry is None:
        return value
    if unit is None:
        raise DomainError("this quantity declares no unit; evaluate it with plain SI numbers")
    return registry.Quantity(value, unit or "dimensionless")


def refuse_units(values: dict, where: str, units: dict | None = None) -> None:
    """Entry points whose results are records of several numbers (a pull-off,
    a partial-slip state) take plain SI numbers: a pint Quantity among
    ``values`` raises :class:`~linecontact_sym.core.errors.DomainError`
    naming it, its unit and its SI value (never read as a bare number with
    its unit dropped)."""
    for k, v in values.items():
        if is_quantity(v):
            unit = (units or {}).get(k)
            try:
                si = v.to(unit).magnitude if unit else v.to_base_units().magnitude
                hint = f"; in SI {k} = {si:g}" + (f" ({unit})" if unit else "")
            except Exception:  # noqa: BLE001 -- a wrong dimension: the hint is left out
                hint = ""
            raise DomainError(f"{where} takes plain SI numbers; {k} = {v} is a pint quantity in {v.units}"
                              f"{hint}")
        if _holds_quantities(v):
            raise DomainError(f"{where} takes plain SI numbers; {k} = {v!r} holds pint quantities")


def describe(unit: str) -> str:
    return _WORDS.get(unit, "a quantity")


_WORDS = {"m": "a length", "Pa": "a pressure (stress)", "N/m": "a force per unit length",
          "J/m**2": "an energy per area", "J/m": "an energy per unit length", "N/m**2": "a force per area",
          "": "a dimensionless number", "rad": "an angle"}


def _plain(m):
    """A pint magnitude as a plain number: NumPy arrays stay arrays; an int that
    the conversion kept exact stays an int, other numbers are floats."""
    import numpy as np
    if isinstance(m, np.ndarray):
        return m.astype(float)
    if isinstance(m, int) and not isinstance(m, bool):
        return m
    return float(m)


__all__ = ["is_quantity", "split_units", "si_magnitude", "strip_units", "check_profile_units", "with_unit", "describe",
           "refuse_units"]
