"""The contact base class and its quantity registry (cf. SymPy's ``stats``:
a distribution declares its quantities, the machinery does the rest).

A contact class declares each physical quantity it offers **once**, as a
:class:`Quantity` class attribute::

    class LineContact(Contact):
        kind = "frictionless"
        pressure = Quantity("p(x; a)", "Eq. (12)", "contact pressure, compressive positive",
                            arguments=("a", "x"), domain="inside", unit="Pa")

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

import functools

from dataclasses import dataclass, field

import math

import numpy as np
import sympy as sp

from ..core import symbols as S
from ..core.conversion import point_value
from ..core.precision import checked_dps, serialized
from ..core.printing import lambdify
from ..core.ranges import check_values
from ..core.errors import DomainError, InadmissibleProfileError, LineContactError, singular_point
from ..method.derivation import Derivation, timing
from ..numeric.special import NUMPY_LOGIC
from ..parsing import to_sympy
from ..method.verification import holds
from .domain import DomainValues, elementwise_abs, is_array, x_domain

#: every contact class, by its ``kind``
CONTACT_KINDS: dict = {}

#: where a quantity is defined, as a condition on x (``None``: no x)
DOMAINS = {"any": None, "inside": "|x| <= a", "outside": "|x| >= a"}


@dataclass(frozen=True)
class Quantity:
    """The declaration of a physical quantity of a contact class::

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
        nonnegative  argument names that must be >= 0 here though their symbol
                   is not declared so (the load P of a frictionless contact)
        unit       its SI unit (``"N/m"``, ``"Pa"``, ``"m"``; ``""``
                   dimensionless): a result asked for with pint quantities
                   comes back in it (:mod:`linecontact_sym.core.units`); None:
                   not declared (no units for it)
    """

    symbol: str
    equation: str = ""
    doc: str = ""
    arguments: tuple = ("a",)
    domain: str = "any"
    latex: str = ""
    aliases: tuple = ()
    method: bool = False
    nonnegative: tuple = ()
    unit: str | None = None
    name: str = field(default="", compare=False)

    def __set_name__(self, owner, name):
        object.__setattr__(self, "name", name)

    def __get__(self, obj, owner=None):
        if obj is None:
            return self
        if self.method:
            return _method_with_units(obj, self, getattr(obj, "_" + self.name))
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
    #: names of :mod:`~linecontact_sym.core.ranges` that may also be 0 here
    _zero_ok: tuple = ()

    @classmethod
    def from_frictionless(cls, contact):
        """This kind of contact built on a frictionless
        :class:`~.contact.LineContact`, with its extra parameters left
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
        if "_registry" not in cls.__dict__:
            out = {}
            for klass in reversed(cls.__mro__):
                for name, val in vars(klass).items():
                    if isinstance(val, Quantity):
                        out[name] = val
            cls._registry = out
        return cls._registry

    @classmethod
    def resolve(cls, name: str) -> str:
        """The registry name of ``name`` (itself or an alias); a clear error
        listing the choices otherwise."""
        cls.quantities()  # builds the class's registry once
        if name in cls._registry:
            return name
        qs = cls._registry
        for q in qs.values():
            if name in q.aliases:
                return q.name
        raise LineContactError(f"unknown quantity {name!r} of a {cls.kind} contact; choose one of "
                               f"{', '.join(qs)}")

    # ----------------------------------------------------------- pickling, copies
    #: attributes that hold derived results and compiled functions: not
    #: pickled (a contact pickles as its definition; its derivations come back
    #: from the derivation store, :mod:`~linecontact_sym.method.store`, in
    #: memory or on disk) and not shared by copies
    _transient = ("_cache", "_laws")   # _laws: the adhesive contact's numeric force laws
    #: the caches of derived results (:meth:`_caches`): None until the first is made
    _cache = None

    def __getstate__(self):
        return {k: v for k, v in self.__dict__.items() if k not in self._transient}

    def __setstate__(self, state):
        self.__dict__.update(state)
        self.__dict__.update({k: {} for k in self._transient})

    def __copy__(self):
        """A copy with its own caches (holding what was derived so far):
        what one derives later is not seen by the other."""
        new = object.__new__(type(self))
        new.__dict__.update({k: (dict(v) if k in self._transient else v) for k, v in self.__dict__.items()})
        return new

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
            with serialized():   # symbolic work changes mpmath's precision (core.precision)
                if name not in cache:
                    with timing():
                        cache[name] = getattr(self, "_derive_" + name)()
        return cache[name]

    def _value(self, name: str):
        """What attribute access returns: the derived expression."""
        return self.derivation(name).expr

    # ----------------------------------------------------------- domain
    def check_domain(self, quantity: str, values: dict) -> dict:
        """The one domain check of a quantity at a point (keywords by name),
        used by ``evaluate``, ``evaluate_at``, the CLI: every name is one the
        quantity takes; every value a finite real number (NumPy arrays:
        elementwise); symbols declared positive (a, E_star, R, n, c, theta, ...)
        get positive values (the work of adhesion may be 0); x inside or
        outside the contact as the quantity's domain says; and, where the
        result holds under conditions (e.g. a < R), they hold.  Raises
        :class:`~linecontact_sym.core.errors.DomainError` naming the problem;
        returns the values with x replaced by |x| (a :class:`DomainValues`).
        Arrays: the points outside the contact or where the conditions fail
        are marked in ``outside`` (their results are NaN, a
        :class:`~linecontact_sym.core.errors.DomainWarning` says how many);
        the other points are evaluated.  Invalid values (not finite, a
        positive symbol <= 0) raise for arrays too."""
        name = self.resolve(quantity)
        q = type(self)._registry[name]
        check_values(values, self._zero_ok)   # before anything is derived: nu = 0.7 is refused at once
        self._check_normal_point(values)
        known, conds, cond_fn = self._domain_data(name)
        unknown = sorted(set(values) - set(known))
        if unknown and not q.method:
            raise DomainError(f"{name} takes no value named {', '.join(map(repr, unknown))}; "
                              f"it takes {', '.join(sorted(known)) or 'none'}")
        vals = {k: checked_value(k, v, known.get(k)) for k, v in values.items()}
        for k in q.nonnegative:
            if k in vals and np.any(np.asarray(_as_float_array(vals[k])) < 0):
                raise DomainError(f"{k} = {values[k]} < 0: the {name} of a {self.kind} contact needs {k} >= 0")
        check_values(vals, self._zero_ok)  # nu, mu, c_s, c_r: the physical ranges (core.ranges)
        self._check_admissible(vals)
        out = DomainValues(vals)
        out.mark(*x_domain(name, q.domain, out, values))   # x -> |x| in the values returned
        if conds and set(known) <= set(vals):
            try:
                r = cond_fn(*[_as_float_array(vals[k]) for k in known])
                ok = True if is_array(r) else bool(r)
                if is_array(r):
                    out.mark(~np.asarray(r, dtype=bool), f"{', '.join(map(str, conds))} fails")
            except (TypeError, ValueError, OverflowError):  # a condition numpy cannot decide (or beyond float64): exactly
                ok = holds(self.derivation(name).point_test, {known[k]: v for k, v in vals.items()}) if not any(
                    isinstance(v, np.ndarray) for v in vals.values()) else True
            if not ok:
                raise DomainError(f"{name} holds only where {', '.join(map(str, conds))}; "
                                  f"that fails at {values}")
        out.warn(name)
        return out

    def _check_normal_point(self, values):
        """A contact built on a frictionless one (adhesive, tangential,
        stresses): the normal solution holds at the point (the exact
        cylinder's a < R), checked first, before anything is derived or
        searched; values that are not plain numbers are left to the checks
        that follow."""
        base = getattr(self, "contact", None)
        if base is None or not hasattr(base, "check_point") or "a" not in values:
            return
        point = {}
        for s in (S.a,) + tuple(base.variables):
            v = values.get(s.name)
            if v is None or isinstance(v, (list, tuple, np.ndarray, bool, str)):
                continue
            try:
                v = to_sympy(v, where=s.name)
            except LineContactError:
                continue
            if v.is_number and v.is_real:
                point[s] = v
        if S.a in point:
            base.check_point(point)

    def check_domain_scalar(self, quantity: str, values: dict) -> dict:
        """:meth:`check_domain` for a point of plain Python numbers, in
        microseconds (:func:`check_domain_scalar`): same tests, same result."""
        return check_domain_scalar(self, quantity, values)

    def _domain_data(self, name):
        """(name -> Symbol of the values the quantity takes, its conditions, a
        NumPy function of those values deciding the conditions), cached."""
        cache = self._caches()
        key = ("_domain", name)
        if key not in cache:
            d = self.derivation(name)
            known = {s.name: s for s in d.variables_all}
            # the derivation's point conditions (method.derivation): relations
            # between x and a are the quantity's domain (inside: |x| <= a,
            # outside: |x| >= a), checked above; edges included: a closed form
            # stated for x < a or c_s < a still holds at the edge as a limit
            conds = d.point_conditions
            fn = lambdify(list(known.values()), sp.And(*d.point_test), [NUMPY_LOGIC, "numpy"]) if conds else None
            cache[key] = (known, conds, fn)
        return cache[key]

    def _check_admissible(self, vals):
        """With a numeric half-width and parameters (already checked against
        their symbols' assumptions), the admissibility of the frictionless
        solution at the point: the profile real and not decreasing on (0, a]
        (sampled at 24 points) and dP0/da >= 0 at a where the force law has a
        closed form (else the pressure at the edges is tensile).  Evaluated in
        float64 (a sign test; cached functions), so it costs microseconds.
        :class:`InadmissibleProfileError` names what fails."""
        base = getattr(self, "contact", self)
        prof = getattr(base, "profile", None)
        av = vals.get("a")
        geometry = getattr(base, "geometry", None)
        if geometry is not None and av is not None and not isinstance(av, np.ndarray):
            geometry.check_half_width(vals)       # a periodic array: a <= L/2
        if prof is None or av is None or isinstance(av, np.ndarray) or \
                any(p.name not in vals or isinstance(vals[p.name], np.ndarray) for p in prof.params):
            return
        checks = base._admissibility_fns() if hasattr(base, "_admissibility_fns") else None
        if checks is None:
            return
        fprime, slope, names = checks
        if fprime is None and slope is None:      # both proved by SymPy's assumptions
            return
        try:
            A = float(av)
            pv = [float(vals[n]) for n in names]
        except (TypeError, ValueError, OverflowError):   # (beyond float64: the sign test is not run)
            return
        with np.errstate(all="ignore"):
            xs = A * np.arange(1, 25) / 24
            d = np.asarray(fprime(xs, *pv), dtype=complex) if fprime is not None else None
            if d is not None:
                bad = np.flatnonzero(np.abs(d.imag) > 1e-12 * (np.abs(d.real) + 1e-300))
                if bad.size:
                    raise InadmissibleProfileError(f"profile {prof.name!r} at a = {av}: f is not real at "
                                                   f"x = {xs[bad[0]]:.6g} inside the contact")
                neg = np.flatnonzero(d.real < -1e-12 * np.max(np.abs(d.real)))
                if neg.size:
                    raise InadmissibleProfileError(
                        f"profile {prof.name!r} at a = {av}: f decreases at x = {xs[neg[0]]:.6g} inside the contact "
                        f"(0, a): the frictionless compact-contact solution needs f' >= 0 there")
            if slope is not None and "E_star" in vals:
                k = float(np.real(slope(A, float(vals["E_star"]), *pv)))
                if k < 0:
                    raise InadmissibleProfileError(
                        f"profile {prof.name!r} at a = {av}: dP0/da = {k:.6g} < 0, the pressure at the edges of "
                        f"the contact is tensile; the frictionless solution holds only while dP0/da >= 0 "
                        f"(see admissible_range)")

    # ----------------------------------------------------------- units
    def _strip_units(self, quantity: str, values: dict):
        """``(values in SI, pint registry or None, the result's unit)``:
        :func:`linecontact_sym.core.units.strip_units` with the symbols'
        units and this quantity's declaration."""
        from ..core.units import strip_units
        q = type(self).quantities()[self.resolve(quantity)]
        law = getattr(self, "law", None)          # a cohesive law declares its own symbols' units
        units = {**S.UNITS, **{p.symbol.name: p.unit for p in getattr(law, "parameters", ())
                               if getattr(p, "unit", None) is not None}}
        return strip_units(values, units, q, getattr(self, "profile", None))

    # ----------------------------------------------------------- numbers
    def evaluate_at(self, quantity: str, dps: int = 30, **values):
        """One high-precision value (``dps`` digits) with the domain checked.

        Values may be pint quantities (the ``[units]`` extra): each is
        checked against its dimension and converted to SI, and the result is
        a quantity in the SI unit declared for ``quantity`` (a force per unit
        length in N/m).  Plain numbers are SI values, and give a plain number."""
        checked_dps(dps)
        values, registry, unit = self._strip_units(quantity, values)
        values = self.check_domain(quantity, values)
        v = self.derivation(quantity).evalf(dps=dps, **values)
        if registry is None:
            return v
        from ..core.units import with_unit
        return with_unit(v, unit, registry)

    def to_numeric(self, quantity: str, backend: str = "numpy", dps: int = 30, check: bool = True, **params):
        """A callable of the quantity: ``fn(a=..., x=..., E_star=..., R=...)``;
        ``backend='numpy'`` (vectorised float64, stable form) or ``'mpmath'``
        (``dps`` digits).  Keywords given here are fixed once.  ``check``
        (default True): every call passes the contact's domain check
        (:meth:`check_domain`) and raises
        :class:`~linecontact_sym.core.errors.DomainError` outside it (array
        points outside it: NaN, with a DomainWarning);
        ``check=False``: no check (a few microseconds less per call), NaN or
        complex values outside the domain."""
        from ..numeric.functions import make_callable
        checked_dps(dps)
        name = self.resolve(quantity)
        inputs = ExportInputs(self, name, params)
        return make_callable(self.derivation(name), backend, dps, inputs.params,
                             domain=DomainCheck(self, name) if check else None, inputs=inputs)

    def evaluate(self, quantity: str, rtol=None, certified: bool = False, dps=None, **values):
        """The cheapest evaluation that meets ``rtol``: float64, mpmath at a
        sufficient precision, a cheaper model with its error bound, or with
        ``certified=True`` an Arb ball; see :mod:`linecontact_sym.numeric.evaluate`.
        Values may be pint quantities (as in :meth:`evaluate_at`): the
        Evaluation's numbers stay SI numbers, its ``unit`` says which, and
        ``.quantity_value()`` is the value as a pint quantity."""
        if not certified and dps is None:
            # a point of plain numbers: the scalar plan of this quantity (numeric.evaluate.scalar_evaluator)
            cache = self._cache        # self._caches() without its call
            fast = None if cache is None else cache.get(("_evaluate", quantity))
            if fast is None:
                fast = self._scalar_evaluator(quantity, rtol, values)
            if fast:
                try:
                    r = fast(self, rtol, values)
                except (ZeroDivisionError, OverflowError) as exc:
                    raise singular_point(quantity, values, exc) from None
                if r is not None:
                    return r
        evaluate = _numeric_evaluate()
        if _PLAIN_NUMBERS.issuperset(map(type, values.values())):   # no pint quantity among them
            registry = None
        else:
            values, registry, unit = self._strip_units(quantity, values)
        try:
            r = evaluate(self, self.resolve(quantity), rtol=rtol, certified=certified, dps=dps, **values)
        except (ZeroDivisionError, OverflowError) as exc:
            raise singular_point(quantity, values, exc) from None
        if registry is not None:
            r.unit = registry.Unit(unit or "dimensionless")
        return r

    def _scalar_evaluator(self, quantity, rtol, values):
        """The scalar plan of :meth:`evaluate` for ``quantity`` (cached; False:
        none), built at the first call that may use it (a tolerance in range,
        plain numbers), so that any other call meets its errors where it
        always did."""
        if not (rtol is None or rtol.__class__ is float and 1e-14 <= rtol < 1) or \
                not _PLAIN_NUMBERS.issuperset(map(type, values.values())):
            return None
        name = self.resolve(quantity)
        fast = False
        if not type(self)._registry[name].method:
            plan = scalar_domain_plan(self, name)

            def domain(contact, vals):      # the contact passed per call: a copy's cache holds no other contact
                return check_domain_scalar(contact, name, vals, plan)
            domain.bounds = _bounds_only(plan)
            fast = _numeric_evaluate("scalar_evaluator")(self, name, domain) or False
        self._caches()[("_evaluate", quantity)] = fast
        return fast

    def plot(self, what: str = "force", **kw):
        """A matplotlib figure of the contact in the literature's normalised
        axes: ``"pressure"`` (p/p0 against x/a at ``loads=[...]``),
        ``"force"``, ``"adhesive"`` (JKR branches, pull-off, jump-in),
        ``"gap"``; ``values={"R": 1}``, ``path=`` to save.  See
        :mod:`linecontact_sym.views.contact_plots` (needs the ``[plot]`` extra)."""
        from ..views.contact_plots import plot_contact
        return plot_contact(self, what, **kw)

    def latex(self, quantity: str) -> str:
        """LaTeX of a quantity's expression (the package's one printer)."""
        from ..core.printing import to_latex
        return to_latex(self.derivation(quantity).expr)

    def report(self, quantities=None) -> str:
        """The derivation summaries of the given (default: the expression)
        quantities."""
        names = quantities or [n for n, q in type(self).quantities().items() if not q.method]
        return "\n".join(self.derivation(q).summary() for q in names)


def _numeric_evaluate(name="evaluate"):
    """:func:`linecontact_sym.numeric.evaluate.evaluate` (or another function
    ``name`` of that module), imported at the first
    call (not with the contacts: a plain import stays light), then looked up
    once per call in this module's globals, not through the import system."""
    fn = _NUMERIC.get(name)
    if fn is None:
        from ..numeric import evaluate as module
        fn = _NUMERIC[name] = getattr(module, name)
    return fn


_NUMERIC: dict = {}

#: the types of plain SI numbers (no unit to strip: the common, fast case of evaluate)
_PLAIN_NUMBERS = frozenset((float, int))

#: symbols declared positive whose values may be <= 0 (x: the profile is
#: mirrored, f(-x) = f(x))
_ANY_SIGN = {"x"}


def may_be_zero(name: str) -> bool:
    """Is ``name`` (a symbol declared positive) allowed the value 0?  The
    symbols of a registered cohesive law's parameters of domain
    'nonnegative' are (JKR's gamma = 0: the non-adhesive limit), and the
    depth z (z = 0 is the surface)."""
    if name == "z":          # the surface, where surface stresses live
        return True
    for cls in CONTACT_KINDS.values():
        for p in getattr(getattr(cls, "law_class", None), "parameters", ()):
            if p.domain == "nonnegative" and p.symbol.name == name:
                return True
    return False


def _positive_required(name, sym):
    return sym is not None and sym.is_positive and name not in _ANY_SIGN


def _as_float_array(v):
    return v if isinstance(v, (float, np.ndarray)) else float(v)


def checked_value(name, v, sym):
    """A value given by a user: a finite real number (exact where given
    exactly) or a NumPy array of them; positive where the symbol is."""
    if type(v) in (float, int):  # the common, fast case
        if type(v) is float and not math.isfinite(v):     # (an int is finite; 10**400 has no float)
            raise DomainError(f"{name} = {v!r}: expected a finite real number")
        if _positive_required(name, sym) and not v > 0 and not (v == 0 and may_be_zero(name)):
            what = {"a": "the half-width a", "E_star": "the reduced modulus E*"}.get(name, name)
            raise DomainError(f"{what} must be positive (declared positive), got {name} = {v}")
        return v
    if isinstance(v, (list, tuple)) or isinstance(v, np.ndarray) and v.ndim:
        arr = np.asarray(v)
        if arr.dtype.kind not in "iuf":
            raise DomainError(f"{name} = {v!r}: expected real numbers")
        arr = arr.astype(float)
        if not np.all(np.isfinite(arr)):
            raise DomainError(f"{name} = {v!r}: values must be finite")
        if _positive_required(name, sym) and np.any(arr <= 0) and not (np.all(arr >= 0) and may_be_zero(name)):
            raise DomainError(f"{name} must be positive, got {v!r}")
        return arr
    if v is None or isinstance(v, bool):
        raise DomainError(f"{name} = {v!r} is not a number")
    if isinstance(v, np.ndarray) and v.ndim == 0:
        v = v[()]
    try:
        # text through the whitelisted parser, every number through the one
        # converter (exact; a Float as its binary value, never capping precision)
        val = point_value(to_sympy(v, where=name) if isinstance(v, str) else v)
    except LineContactError as exc:
        raise DomainError(f"{name} = {v!r} is not a number ({exc})") from None
    if not val.is_number or val.has(sp.zoo, sp.nan, sp.oo, -sp.oo) or val.is_real is False:
        raise DomainError(f"{name} = {v!r}: expected a finite real number")
    if not val.is_real:
        if val.is_real is None and abs(sp.im(sp.N(val, 30))) > 0:
            raise DomainError(f"{name} = {v!r}: expected a finite real number")
    if _positive_required(name, sym) and not val.is_positive:
        if not (val.is_zero and may_be_zero(name)):
            what = {"a": "the half-width a", "E_star": "the reduced modulus E*"}.get(name, name)
            raise DomainError(f"{what} must be positive (declared positive), got {name} = {v}")
    return val


def check_domain_scalar(self, quantity: str, values: dict, plan=None) -> dict:
    """``self.check_domain(quantity, values)`` (``self`` a contact) for a point of plain Python numbers, in
    microseconds: the same tests in plain Python on the cached domain data,
    the admissibility test once per point (remembered per a, E* and the
    profile's parameters).  Anything else, and every point that fails a
    test, goes to :meth:`Contact.check_domain`, which raises the error naming the
    problem; so both accept and return the same."""
    plan = plan or scalar_domain_plan(self, quantity)
    if not plan:
        return self.check_domain(quantity, values)
    known, lower, domain, cond_names, cond_fn, adm = plan
    inf = math.inf
    for k, v in values.items():
        # lower[k]: "any" (finite), "positive" (0 < v), "nonnegative" (0 <= v: a
        # nonnegative quantity, or a positive symbol that may be 0)
        low = lower.get(k)
        if low is None or v.__class__ not in _PLAIN_NUMBERS or \
                not (0 < v < inf if low == "positive" else (0 <= v < inf if low == "nonnegative"
                                                            else -inf < v < inf)):
            return self.check_domain(quantity, values)
    vals = dict(values)
    if domain is not None and "x" in vals and "a" in vals:
        xv = abs(vals["x"])
        if (xv > vals["a"]) if domain == "inside" else (xv < vals["a"]):
            return self.check_domain(quantity, values)
        vals["x"] = xv
    if adm is not None and "a" in vals:
        key = tuple(map(vals.get, adm))
        caches = self._caches()
        seen = caches.get(("_admissible", adm))
        if seen is None:
            seen = caches[("_admissible", adm)] = {}
        if key not in seen:
            self._check_admissible(vals)          # raises where inadmissible
            if len(seen) > 100000:
                seen.clear()
            seen[key] = True
    if cond_fn is not None and known.issubset(vals.keys()):          # cond_names: the names of known
        try:
            ok = bool(cond_fn(*[float(vals[n]) for n in cond_names]))
        except (TypeError, ValueError, OverflowError):     # (an int beyond float64: the exact check decides)
            ok = False
        if not ok:
            return self.check_domain(quantity, values)
    return vals

def _bounds_only(plan):
    """The bounds of a :func:`scalar_domain_plan` that tests nothing else (no
    inside/outside test, no condition, no admissibility test), else None."""
    if plan and plan[2] is None and plan[4] is None and plan[5] is None:
        return dict(plan[1])
    return None


def scalar_domain_plan(self, quantity):
    """The tests of :meth:`check_domain_scalar`, cached per quantity (None:
    a quantity whose tests it does not mirror, checked the full way)."""
    name = self.resolve(quantity)
    cache = self._caches()
    key = ("_scalar_domain", name)
    if key not in cache:
        q = type(self)._registry[name]
        known, conds, cond_fn = self._domain_data(name)
        plan = ()
        if not q.method:
            positive = frozenset(k for k, sym in known.items() if _positive_required(k, sym))
            domain = q.domain if q.domain in ("inside", "outside") else None
            base = getattr(self, "contact", self)
            prof = getattr(base, "profile", None)
            adm = None
            if prof is not None and hasattr(base, "_admissibility_fns"):
                fprime, slope, names = base._admissibility_fns()
                if fprime is not None or slope is not None:
                    adm = ("a", "E_star", *names)
            lower = {k: ("positive" if k in positive and not may_be_zero(k) else
                         "nonnegative" if k in positive or k in q.nonnegative else "any") for k in known}
            plan = (frozenset(known), lower, domain, tuple(known),
                    _scalar_test(self, name, known, cond_fn) if conds else None, adm)
        cache[key] = plan
    return cache[key]


def _real_load(v, name):
    """The load of a method quantity (``half_width(P)``, ``stick_half_width(Q)``)
    is a real number (or a symbol): a complex number, NaN or an infinity
    raises :class:`~linecontact_sym.core.errors.DomainError` naming it
    (before: SymPy's TypeError of an invalid comparison)."""
    if isinstance(v, str):
        try:
            v = to_sympy(v, where=name)
        except LineContactError:
            return                           # the method itself says what the text is not
    if isinstance(v, (complex, np.complexfloating)):
        raise DomainError(f"the load {name} must be a real number, got {name} = {v} (complex)")
    if isinstance(v, (float, np.floating)) and not math.isfinite(v):
        raise DomainError(f"the load {name} must be a finite real number, got {name} = {v}")
    if isinstance(v, sp.Basic) and v.is_number:
        if v.has(sp.oo, -sp.oo, sp.zoo, sp.nan):
            raise DomainError(f"the load {name} must be a finite real number, got {name} = {v}")
        if v.is_real is False:
            raise DomainError(f"the load {name} must be a real number, got {name} = {v} (complex)")


def _method_with_units(contact, q, fn):
    """A method quantity (``c.half_width(P, **values)``, ``t.stick_half_width(Q, ...)``)
    that takes pint quantities: the load (its first argument, named
    ``q.arguments[-1]``) and the values converted to SI by the contact's one
    unit stripper (:meth:`Contact._strip_units`), the result (a number, or a
    tuple of numbers) in the quantity's declared unit.  Plain numbers pass
    straight through."""
    from ..core.units import is_quantity, with_unit

    @functools.wraps(fn)
    def call(*args, **kw):
        if args:
            _real_load(args[0], q.arguments[-1] if q.arguments else "load")
        if not any(is_quantity(v) for v in args) and not any(is_quantity(v) for v in kw.values()):
            return fn(*args, **kw)
        load = q.arguments[-1] if q.arguments else "load"
        vals = dict(kw)
        if args:
            vals[load] = args[0]
        plain, registry, unit = contact._strip_units(q.name, vals)
        rest = {k: v for k, v in plain.items() if k != load or not args}
        out = fn(*((plain[load],) + tuple(args[1:]) if args else ()), **rest)
        if isinstance(out, tuple):
            return tuple(with_unit(o, unit, registry) for o in out)
        return with_unit(out, unit, registry)
    return call


class ExportInputs:
    """What an export does with its arguments before anything else, checked
    or not (``to_numeric(check=False)`` too): pint quantities checked against
    their units and converted to SI (:meth:`Contact._strip_units`, the one
    place; the result then carries the quantity's declared unit), and x
    replaced by |x| for a quantity of x inside or outside the contact (the
    profile is mirrored, f(-x) = f(x): the pressure, gap, traction ... are
    even in x, and the derived closed forms hold for x > 0, x being a
    positive symbol).  The parameters fixed at export time are converted
    once (``params``, SI numbers).  Pickles with its contact."""

    def __init__(self, contact, quantity, params):
        from ..core.units import is_quantity
        self.contact, self.quantity = contact, quantity
        self.fold_x = type(contact)._registry[quantity].domain in ("inside", "outside")
        self.given = dict(params)
        self.has_units = any(is_quantity(v) for v in self.given.values())
        self.params = contact._strip_units(quantity, self.given)[0] if self.has_units else self.given
        if self.fold_x and "x" in self.params:
            from ..numeric.functions import fold_x
            self.params = {**self.params, "x": fold_x(self.params["x"])}

    def strip(self, kw):
        """``(values in SI, registry or None, unit)`` of a call's keywords."""
        plain, registry, unit = self.contact._strip_units(self.quantity, {**self.given, **kw})
        return {k: plain[k] for k in kw}, registry, unit


def _scalar_test(contact, name, known, cond_fn):
    """The derivation's point test for plain floats: compiled for the math
    module (a comparison of floats, not a NumPy call), else ``cond_fn``."""
    try:
        test = sp.And(*contact.derivation(name).point_test)
        return lambdify(list(known.values()), test, "math")
    except Exception:   # noqa: BLE001 -- a function the math module lacks: the NumPy test
        return cond_fn


class DomainCheck:
    """The domain check of one quantity of a contact, as an export calls it:
    ``check(values)`` (:meth:`Contact.check_domain`) and ``check.scalar(values)``
    (:meth:`Contact.check_domain_scalar`, for a point of plain numbers).
    Pickles with its contact."""

    def __init__(self, contact, quantity):
        self.contact, self.quantity = contact, quantity

    def __call__(self, values):
        return self.contact.check_domain(self.quantity, values)

    def scalar(self, values):
        return check_domain_scalar(self.contact, self.quantity, values, self._scalar_plan())

    def _scalar_plan(self):
        plan = self.__dict__.get("_plan")
        if plan is None:
            plan = self._plan = scalar_domain_plan(self.contact, self.quantity)
        return plan

    @property
    def bounds(self):
        """name -> 'positive', 'nonnegative' or 'any' where this check is
        bounds only (no condition, no inside/outside test, no admissibility
        test), else None: an export may then read a point in one pass
        (:func:`~linecontact_sym.numeric.fastpath.one_pass`); the same
        attribute as the ``bounds`` of :meth:`Contact.evaluate`'s scalar
        domain check."""
        return _bounds_only(self._scalar_plan())

    def __getstate__(self):
        return {"contact": self.contact, "quantity": self.quantity}


class ContactOn(Contact):
    """A contact built on a frictionless one, ``self.contact`` (adhesive,
    tangential, stresses): its profile and parameters are that contact's.
    On a profile that switches on its parameters alone, every quantity is
    derived case by case (:mod:`.normal.cases`), each case by this kind of
    contact built on that case's frictionless contact (:meth:`on`)."""

    def on(self, contact):
        """This contact, with the same settings, built on another
        frictionless ``contact`` (nothing derived is shared)."""
        import copy
        new = copy.copy(self)
        new.contact = contact
        for k in tuple(self._transient) + ("_fields",):
            if k in new.__dict__:
                new.__dict__[k] = {}
        return new

    def derivation(self, quantity: str):
        if not self.contact.profile.cases:
            return super().derivation(quantity)
        name = self.resolve(quantity)
        cache = self._caches()
        if name not in cache:
            cache[name] = self.contact.derive_by_case(self, name)
        return cache[name]

    @property
    def profile(self):
        return self.contact.profile

    @property
    def params(self):
        return self.contact.params


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


__all__ = ["Quantity", "Contact", "CONTACT_KINDS", "contact_kind", "qualified_quantities", "DOMAINS", "checked_value"]
