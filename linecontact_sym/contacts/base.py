"""The contact base class and its quantity registry (cf. SymPy's ``stats``:
a distribution declares its quantities, the machinery does the rest).

A contact class declares each physical quantity it offers **once**, as a
:class:`Quantity` class attribute::

    class LineContact(Contact):
        kind = "frictionless"
        pressure = Quantity("p(x; a)", "Eq. (12)", "contact pressure, compressive positive",
                            arguments=("a", "x"), domain="inside")

        def _derive_pressure(self) -> Derivation: ...

and builds its :class:`~linecontact_sym.method.derivation.Derivation` in a
method ``_derive_<name>``.  Everything else reads the registry: attribute
access (``c.pressure`` is the expression), :meth:`Contact.derivation`,
:meth:`Contact.to_numeric`, :meth:`Contact.evaluate`,
:meth:`Contact.evaluate_at`, the domain check, the CLI verbs, the claims
checker and the LaTeX/report views.  A new physical effect is a new subclass
(registered under its ``kind``); a new quantity is one declaration and one
``_derive_`` method.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..core.errors import DomainError, LineContactError
from ..method.derivation import Derivation
from ..parsing import to_sympy

def _number(v):
    """A value for the domain check: floats and NumPy arrays as they are (the
    fast path of numeric evaluation), anything else through the strict
    converter (strings are parsed, never evaluated)."""
    if isinstance(v, (int, float)) and not isinstance(v, bool):
        return float(v)
    if isinstance(v, np.ndarray):
        return v.astype(float)
    return to_sympy(v)


def _positive(v) -> bool:
    if isinstance(v, float):
        return v > 0
    if isinstance(v, np.ndarray):
        return bool(np.all(v > 0))
    return not (v.is_number and not v.is_positive)


def _any(rel) -> bool:
    return bool(np.any(rel)) if isinstance(rel, (np.ndarray, np.bool_)) else bool(rel)


#: every contact class, by its ``kind``
CONTACT_KINDS: dict = {}

#: where a quantity is defined, as a condition on x (``None``: no x)
DOMAINS = {"any": None, "inside": "|x| <= a", "outside": "|x| >= a"}


@dataclass(frozen=True)
class Quantity:
    """The declaration of a physical quantity of a contact class.

    symbol     how it is written (``"p(x; a)"``; LaTeX in ``latex``)
    equation   the paper's equation (``"Eq. (12)"``), or ``""``
    doc        what it is: definition, units, sign convention
    arguments  the variables it depends on besides parameters (``("a", "x")``)
    domain     ``"any"``, ``"inside"`` (|x| <= a) or ``"outside"`` (|x| >= a)
    latex      its LaTeX symbol, for tables and reports
    aliases    other names that mean this quantity (e.g. claims files)
    method     True: the attribute is a method (``c.half_width(P)``) that
               calls ``_<name>``; the registry entry and ``_derive_<name>``
               serve the symbolic form
    """

    symbol: str
    equation: str = ""
    doc: str = ""
    arguments: tuple = ("a",)
    domain: str = "any"
    latex: str = ""
    aliases: tuple = ()
    method: bool = False
    name: str = field(default="", compare=False)

    def __set_name__(self, owner, name):
        object.__setattr__(self, "name", name)

    def __get__(self, obj, owner=None):
        if obj is None:
            return self
        if self.method:
            return getattr(obj, "_" + self.name)
        return obj._value(self.name)

    @property
    def description(self) -> str:
        """One line for help texts: 'symbol, equation: doc'."""
        eq = f", {self.equation}" if self.equation else ""
        return f"{self.symbol}{eq}: {self.doc}"


class Contact:
    """Base of every contact class: the registry, the derivation cache and the
    numeric views.  Subclasses set ``kind``, declare :class:`Quantity`
    attributes and write ``_derive_<name>`` methods; they provide
    ``profile`` (a :class:`~linecontact_sym.method.profile.Profile`) and
    ``variables`` (the symbols a number needs besides the arguments)."""

    kind = "contact"

    @classmethod
    def from_frictionless(cls, contact):
        """This kind of contact built on a frictionless
        :class:`~.frictionless.LineContact`, with its extra parameters left
        symbolic (the claims checker and the CLI build contacts this way)."""
        raise NotImplementedError(f"{cls.__name__} does not say how it is built from a frictionless contact")

    def __init_subclass__(cls, **kw):
        super().__init_subclass__(**kw)
        if "kind" in cls.__dict__:
            CONTACT_KINDS[cls.kind] = cls

    # ----------------------------------------------------------- registry
    @classmethod
    def quantities(cls) -> dict:
        """name -> :class:`Quantity`, in declaration order (base classes first).
        Built once per class (numeric evaluation asks on every call); do not
        modify the returned dict."""
        out = cls.__dict__.get("_quantities")
        if out is None:
            out = {}
            for klass in reversed(cls.__mro__):
                for name, val in vars(klass).items():
                    if isinstance(val, Quantity):
                        out[name] = val
            cls._quantities = out
        return out

    @classmethod
    def resolve(cls, name: str) -> str:
        """The registry name of ``name`` (itself or an alias); a clear error
        listing the choices otherwise."""
        qs = cls.quantities()
        if name in qs:
            return name
        for q in qs.values():
            if name in q.aliases:
                return q.name
        raise LineContactError(f"unknown quantity {name!r} of a {cls.kind} contact; choose one of "
                               f"{', '.join(qs)}")

    # ----------------------------------------------------------- derivations
    def _caches(self) -> dict:
        if "_cache" not in self.__dict__:
            self._cache = {}
        return self._cache

    def derivation(self, quantity: str) -> Derivation:
        """The :class:`~linecontact_sym.method.derivation.Derivation` of a
        quantity (expression, rule, conditions, verification), derived once."""
        name = self.resolve(quantity)
        cache = self._caches()
        if name not in cache:
            cache[name] = getattr(self, "_derive_" + name)()
        return cache[name]

    def _value(self, name: str):
        """What attribute access returns: the derived expression."""
        return self.derivation(name).expr

    # ----------------------------------------------------------- domain
    def check_domain(self, quantity: str, values: dict) -> dict:
        """The one domain check of a quantity at a point (keywords by name):
        a > 0, E_star > 0, x inside or outside the contact as the quantity's
        domain says.  Returns the values with x replaced by |x|."""
        q = type(self).quantities()[self.resolve(quantity)]
        vals = dict(values)
        for name in ("a", "E_star"):
            if name in vals and vals[name] is not None:
                v = _number(vals[name])
                if not _positive(v):
                    what = "the half-width" if name == "a" else "the reduced modulus E*"
                    raise DomainError(f"{what} must be positive, got {name} = {vals[name]}")
        if "x" in vals and "a" in vals and q.domain != "any":
            xv, av = abs(_number(vals["x"])), _number(vals["a"])
            if q.domain == "inside" and _any(xv > av):
                raise DomainError(f"x = {vals['x']} lies outside the contact |x| <= a = {vals['a']}; "
                                  f"the {q.name} is defined inside (use the gap outside)")
            if q.domain == "outside" and _any(xv < av):
                raise DomainError(f"x = {vals['x']} lies inside the contact |x| < a = {vals['a']}; "
                                  f"the {q.name} is defined outside (zero inside)")
            vals["x"] = xv
        return vals

    # ----------------------------------------------------------- numbers
    def evaluate_at(self, quantity: str, dps: int = 30, **values):
        """One high-precision value (``dps`` digits) with the domain checked."""
        values = self.check_domain(quantity, values)
        return self.derivation(quantity).evalf(dps=dps, **values)

    def to_numeric(self, quantity: str, backend: str = "numpy", dps: int = 30, **params):
        """A callable of the quantity: ``fn(a=..., x=..., E_star=..., R=...)``;
        ``backend='numpy'`` (vectorised float64, stable form) or ``'mpmath'``
        (``dps`` digits).  Keywords given here are fixed once."""
        from ..numeric.exports import make_callable
        return make_callable(self.derivation(quantity), backend, dps, params)

    def evaluate(self, quantity: str, rtol=None, certified: bool = False, dps=None, **values):
        """The cheapest evaluation that meets ``rtol``: float64, mpmath at a
        sufficient precision, a cheaper model with its error bound, or with
        ``certified=True`` an Arb ball; see :mod:`linecontact_sym.numeric.evaluate`."""
        from ..numeric.evaluate import evaluate
        return evaluate(self, self.resolve(quantity), rtol=rtol, certified=certified, dps=dps, **values)

    def latex(self, quantity: str) -> str:
        """LaTeX of a quantity's expression (the package's one printer)."""
        from ..core.printing import to_latex
        return to_latex(self.derivation(quantity).expr)

    def report(self, quantities=None) -> str:
        """The derivation summaries of the given (default: the expression)
        quantities."""
        names = quantities or [n for n, q in type(self).quantities().items() if not q.method]
        return "\n".join(self.derivation(q).summary() for q in names)


def contact_kind(kind: str):
    """The contact class registered under ``kind`` (e.g. 'frictionless', 'adhesive')."""
    try:
        return CONTACT_KINDS[kind]
    except KeyError:
        raise LineContactError(f"unknown contact kind {kind!r}; one of {', '.join(CONTACT_KINDS)}") from None


def qualified_quantities() -> dict:
    """Every quantity of every registered contact kind: 'force',
    'adhesive.force', ... -> (kind, name, Quantity); plus the aliases and the
    bare names of other kinds that the frictionless contact does not use
    ('pull_off_force' is 'adhesive.pull_off_force')."""
    out = {}
    for kind, cls in CONTACT_KINDS.items():
        for name, q in cls.quantities().items():
            key = name if kind == "frictionless" else f"{kind}.{name}"
            out[key] = (kind, name, q)
            for al in q.aliases:
                out.setdefault(al, (kind, name, q))
    for kind, cls in CONTACT_KINDS.items():  # bare names where no other kind claims them
        for name, q in cls.quantities().items():
            out.setdefault(name, (kind, name, q))
    return out


__all__ = ["Quantity", "Contact", "CONTACT_KINDS", "contact_kind", "qualified_quantities", "DOMAINS"]
