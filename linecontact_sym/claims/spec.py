"""The claims file: what a paper claims, as data (no code).

A paper is a *claims file* (TOML): each claim names the quantity, the profile
(or a list of test profiles for a general formula), the formula *as printed*
in SymPy syntax, and the assumptions on its symbols; figures of the paper are
described as data too.  This module reads and validates such files (and the
claims typed on the command line) into :class:`Paper`, :class:`Claim` and
:class:`Figure` records; :mod:`.check` judges the claims, :mod:`.figures`
draws the figures.

File format
-----------
::

    key = "popov2017"
    title = "..."
    reference = "..."
    symbols = ["k"]               # extra symbol names for the whole file (positive)

    [definitions]                 # named sub-formulas used by the claims
    Z_n = "(n-1)*sqrt(pi)*gamma(n/2 - 1/2)/(2*gamma(n/2))"

    [ranges]                      # default sampling ranges (file-wide)
    R = [0.5, 2.5]

    [[claims]]
    label = "Eq. (13)"
    title = "parabola: force law"
    quantity = "force"            # see QUANTITIES
    profile = "x**2/(2*R)"        # or, for a general formula, test profiles:
                                  # profiles = ["x**2/(2*R)", "x*tan(theta)"]
                                  # profile_names = ["parabola", "wedge"]
    formula = "pi*E_star*a**2/(4*R)"
    forms = ["E_star*a**2/(2*R)*Integral(1/sqrt(a**2 - t**2), (t, 0, a))"]   # other printed forms
    assumptions = ["a < R"]       # where the printed formula is meant to hold
    ranges = { n = [0.3, 6.0] }   # sampling ranges (exact rationals are drawn)
    special = { n = ["1"] }       # exact values always tested
    symbols = ["k"]               # extra symbol names (positive)
    points = 6                    # random points (plus range ends and special values)
    force_law = "..."             # quantity inverse_profile only: the given P(a)
    material = "E0*exp(-t/tau)"   # viscoelastic_* only: the relaxation modulus E*(t) (plane strain)
    impulse = "eta"               # ... and the weight of a Dirac part eta*delta(t) (Kelvin-Voigt)
    history = "r*t"               # viscoelastic_force: the half-width a(t) (a Piecewise for
                                  # loading then unloading); viscoelastic_half_width: the load P(t)
    values = ["1", "pi/2"]        # quantity Z_n only, instead of formula: a table of values
    labels = { "pi/2" = 2 }       # ... and the exponents printed beside them
    note = "..."                  # remark shown in the report
    reading = "..."               # how the transcription was read

    [[figures]]                   # a figure of the paper, redrawn from derived laws
    file = "fig4_worn_cylinder"   # file name stem of the PNG/PDF written
    title = "Fig. 4: ..."         # title drawn above the plot
    caption = "The normalised load ... (a sentence)."
    quantity = "force"            # force, pressure or gap
    x = "a/b"                     # normalised abscissa; its one free symbol not
                                  # fixed by `values` is swept (a, or x at fixed a)
    y = "2*R*P/(E_star*b**2)"     # normalised ordinate in the value P (force),
                                  # p (pressure) or g (gap)
    x_range = [0, 4]              # range of the normalised abscissa
    points = 401                  # points per curve
    values = { b = 1, R = 1, E_star = 1 }   # the other parameters
    xlabel = "half-width $a/b$"   # axis labels (matplotlib mathtext)
    ylabel = "..."
    y_min = 0                     # optional limits of the ordinate (y_max too)
    size = [5.2, 3.8]             # optional figure size in inches
    marks = [{ x = 1, text = "..." }]        # optional vertical marker lines
    ratio = ["exact", "hertz"]    # optional lower panel: curve / curve (by name)
    ratio_label = "exact / Hertz"
    [[figures.curves]]
    name = "worn"
    profile = "Piecewise((0, x < b), ((x**2 - b**2)/(2*R), True))"
    label = "worn cylinder (Eq. 23)"        # legend entry
    style = "-"                   # matplotlib line style; width = 2 (line width)

Formulas may use, besides the standard symbols, ``t`` and ``s`` (integration
variables), ``Integral`` and ``Derivative``, the definitions, and the
placeholders of general (functional) claims: ``f(...)`` the profile,
``force(...)`` the non-adhesive force law P_0 and ``p0`` the non-adhesive
pressure.  Every string is parsed by :mod:`linecontact_sym.parsing`
(whitelist; no code runs).

Sign convention: ``pull_off_force`` is the pull-off load P_min = min_a P(a)
< 0 (a tensile load), ``adhesion_force`` is P_adh = -P_min > 0; a claims file
says which one the paper prints.
"""
from __future__ import annotations

import sys
from dataclasses import dataclass, field
from pathlib import Path

import sympy as sp
from sympy.core.function import AppliedUndef

from ..core import symbols as S
from ..contacts.base import qualified_quantities
from ..core.errors import ClaimError, LineContactError
from ..parsing import declare_symbols, parse_expr
from .rounding import DECIMAL, PrintedFloat, printed_spread, printed_variants  # noqa: F401
from .fields import names_field, number_field, parse_range, check_sign, text_field, typed_field, where_text, read_text_file
from ..views.plots import VALUE_SYMBOLS

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

#: what the checker can derive, with a description
QUANTITIES = {
    "force": "non-adhesive force law P(a), Eq. (10*) (engine)",
    "pressure": "non-adhesive pressure p(x; a), 0 < x < a, Eq. (12) (engine) + Flamant check",
    "gap": "surface separation g(x; a), x > a, Eqs. (3)/(5) (engine)",
    "profile_at_a": "the profile at the contact edge f(a), for the inverse map Eq. (9)",
    "inverse_profile": "profile f(x) from a given force law (claim field force_law), Eq. (9) (engine)",
    "half_width": "half-width a at load P (inverse of the force law) (engine)",
    "Z_n": "Popov's coefficient Z_n = P(a)/(E* c a^n) of a power law c*x**n (engine)",
    "adhesive_force": "JKR force law P(a), Eq. (33) (engine, adhesion)",
    "adhesive_pressure": "JKR pressure, Eq. (29) (engine, adhesion) + Flamant check",
    "pull_off_force": "pull-off load P_min = min_a P(a) < 0, Eq. (34) (engine, adhesion) "
                      "+ independent numeric minimum",
    "adhesion_force": "adhesion force P_adh = -min_a P(a) > 0, Eqs. (34)-(36) (engine, adhesion) "
                      "+ independent numeric minimum",
    "pull_off_half_width": "half-width at pull-off (engine, adhesion)",
    "flat_punch_pressure": "pressure under a flat punch, Eq. (1): checked from first principles "
                           "(resultant and flat surface under the punch, Flamant kernel)",
    "flat_punch_displacement": "d - u_z(x) outside a flat punch, Eq. (3), from the Flamant kernel",
    "punch_adhesion_force": "critical force of a pulled flat punch, Eq. (31), from the energy-release "
                            "rate (Griffith) and the stress-intensity factor",
    "viscoelastic_force": "force history P(t) for a half-width history a(t) (claim field history) on the "
                          "material E*(t) (claim field material): Lee-Radok, Ting after the maximum (engine, "
                          "viscoelastic)",
    "viscoelastic_half_width": "half-width history a(t) under a load history P(t) (claim field history) "
                               "that never decreases, creep on the material E*(t) (engine, viscoelastic)",
}

#: the quantities of a viscoelastic contact (claim fields material and history)
VISCOELASTIC = ("viscoelastic_force", "viscoelastic_half_width")

#: the asymmetric contact's quantities (:mod:`linecontact_sym.contacts.asymmetric`): a
#: profile on the whole line (its x read as the real x), the claim's symbols
#: ``e`` (centre), ``M`` (moment about x = 0) declared in its ``symbols``;
#: ``theta`` is the rigid tilt (gap f(x) - theta x - d).  The punch
#: quantities need no profile: the rigid flat punch of half-width ``a``
#: (walls at x = -a, a) at the load P and the moment M
ASYMMETRIC_QUANTITIES = {
    "asymmetric.force": "P(e, a): the load of the bounded contact on [e - a, e + a] (engine, even part)",
    "asymmetric.tilt": "theta(e, a): the tilt of the bounded contact on [e - a, e + a] (engine, odd part)",
    "asymmetric.moment": "M(e, a) = int x p dx: the moment about x = 0 of the bounded contact (engine)",
    "asymmetric.centre": "e: the centre of the contact at the load P and the tilt theta "
                         "(engine state, contact_at(P, theta=theta))",
    "asymmetric.half_width": "a: the half-width of the contact at the load P and the tilt theta "
                             "(engine state, contact_at(P, theta=theta))",
    "punch.pressure": "p(x) under the rigid flat punch of half-width a at the load P and the moment M, "
                      "-a < x < a (engine state, flat_punch(a).contact_at(P, moment=M))",
    "punch.tilt": "theta: the tilt of the flat punch of half-width a at the load P and the moment M "
                  "(engine state)",
    "punch.lift_off_moment": "M at which a corner factor of the completely pressed flat punch of "
                             "half-width a under the load P vanishes (engine's corner factors, solved by SymPy)",
}
QUANTITIES.update(ASYMMETRIC_QUANTITIES)

# every quantity of every contact kind, by its registry name ('force', 'adhesive.force',
# 'tangential.traction', ...), unless the checker has its own route above
for _key, (_kind, _name, _q) in qualified_quantities().items():
    QUANTITIES.setdefault(_key, f"{_q.symbol}{', ' + _q.equation if _q.equation else ''}: {_q.doc} "
                                f"(engine, {_kind} contact)")

#: quantities derived without a profile
PROFILE_FREE = ("flat_punch_pressure", "flat_punch_displacement", "punch_adhesion_force", "inverse_profile",
                "punch.pressure", "punch.tilt", "punch.lift_off_moment")

#: placeholders of general claims (replaced per test profile)
PLACEHOLDER_F = sp.Function("f")
PLACEHOLDER_FORCE = sp.Function("force")
PLACEHOLDER_P0 = sp.Symbol("p0")
PLACEHOLDERS = {"f": PLACEHOLDER_F, "force": PLACEHOLDER_FORCE, "p0": PLACEHOLDER_P0}

#: default sampling ranges (overridden by the file's and the claim's ranges)
DEFAULT_RANGES = {"a": (0.1, 2.0), "x": (0.1, 2.0), "P": (0.1, 3.0), "E_star": (0.5, 3.0), "gamma": (0.01, 0.5),
                  "R": (0.5, 2.5), "b": (0.1, 0.5), "c": (0.5, 2.5), "n": (0.3, 6.0),
                  "theta": (0.05, 1.2)}
#: the range of a symbol that no table names
FALLBACK_RANGE = (0.5, 2.5)
#: x relative to a, by quantity (the contacts' quantities: from their registry domain)
X_RANGES = {"flat_punch_pressure": (0.02, 0.98), "flat_punch_displacement": (1.05, 3.0),
            "punch.pressure": (-0.98, 0.98)}
_DOMAIN_X = {"inside": (0.02, 0.98), "outside": (1.05, 3.0)}
for _key, (_kind, _name, _q) in qualified_quantities().items():
    if _q.domain in _DOMAIN_X:
        X_RANGES.setdefault(_key, _DOMAIN_X[_q.domain])

_TOP_KEYS = {"key", "title", "reference", "definitions", "ranges", "claims", "source", "symbols", "figures"}
_CLAIM_KEYS = {"label", "title", "description", "quantity", "profile", "profiles", "profile_names", "formula", "forms",
               "assumptions", "ranges", "special", "symbols", "force_law", "values", "labels", "note",
               "points", "reading", "rounding", "period", "material", "impulse", "history"}
_FIGURE_KEYS = {"file", "title", "caption", "quantity", "x", "y", "x_range", "points", "values", "xlabel", "ylabel",
                "y_min", "y_max", "size", "marks", "ratio", "ratio_label", "curves"}
_CURVE_KEYS = {"name", "profile", "label", "style", "width"}


def range_of(name: str, *tables) -> tuple:
    """The sampling range of the symbol ``name``: from the first table that
    names it, else :data:`DEFAULT_RANGES`, else :data:`FALLBACK_RANGE`.

    >>> range_of("R", {"n": (0.3, 6.0)}, {"R": (1.0, 2.0)})
    (1.0, 2.0)
    >>> range_of("theta")
    (0.05, 1.2)
    """
    for table in tables:
        if table and name in table:
            return table[name]
    return DEFAULT_RANGES.get(name, FALLBACK_RANGE)


# =====================================================================  records
@dataclass
class Form:
    """One printed form of a claim: its text, the expression as printed (with
    definitions as symbols, for display) and as evaluated."""

    text: str
    shown: sp.Expr
    expr: sp.Expr
    #: with ``rounding = "printed"``: the formula with every decimal constant
    #: moved by half a unit in its last printed digit, each way (the printed
    #: value stands for the interval these span)
    variants: tuple = ()
    #: how the variants span the interval: "corners" or "sum" (:func:`printed_spread`)
    spread: str = "corners"


@dataclass
class Claim:
    """One numbered result of a paper, as printed (see the module docstring)."""

    label: str
    quantity: str
    forms: list            # [Form]; the last is the final printed formula
    profiles: list         # [(text, expr)]; empty for profile-free quantities
    general: bool = False  # a general formula checked on test profiles
    assumptions: tuple = ()
    ranges: dict = field(default_factory=dict)        # the claim's own sampling ranges
    special: dict = field(default_factory=dict)
    symbols: dict = field(default_factory=dict)
    force_law: sp.Expr | None = None
    values: list = field(default_factory=list)     # Table claims: [(text, expr)]
    labels: dict = field(default_factory=dict)     # Table claims: value text -> printed n
    title: str = ""
    note: str = ""
    reading: str = ""
    points: int = 6
    source: str = "<claims>"
    file_ranges: dict = field(default_factory=dict)   # the file's default ranges
    period: sp.Expr | None = None   # a periodic array of this period (LineContact(f, period=L))
    material: sp.Expr | None = None  # viscoelastic: E*(t), its regular part
    impulse: sp.Expr = sp.S.Zero     # viscoelastic: the weight of eta*delta(t)
    history: sp.Expr | None = None   # viscoelastic: a(t) (force) or P(t) (half-width)

    @property
    def formula(self) -> Form:
        """The final printed form."""
        return self.forms[-1]

    def range_of(self, sym) -> tuple:
        """Sampling range of a symbol: the claim's, the file's, or the default."""
        return range_of(sym.name, self.ranges, self.file_ranges)


@dataclass
class Curve:
    """One curve of a figure: a profile whose derived quantity is drawn."""

    name: str
    profile_text: str
    profile: sp.Expr
    label: str
    style: str = "-"
    width: float = 1.5


@dataclass
class Figure:
    """A figure of the paper as data (see the module docstring); drawn by
    :func:`linecontact_sym.claims.figures.draw_figures`."""

    file: str
    title: str
    caption: str
    quantity: str
    x: sp.Expr
    y: sp.Expr
    x_range: tuple
    values: dict
    curves: list
    points: int = 401
    xlabel: str = ""
    ylabel: str = ""
    y_min: float | None = None
    y_max: float | None = None
    size: tuple | None = None
    marks: list = field(default_factory=list)    # [(x, text)]
    ratio: tuple | None = None                   # (curve name, curve name)
    ratio_label: str = ""


@dataclass
class Paper:
    """The claims (and figures) of one paper."""

    key: str
    title: str
    reference: str
    claims: list
    definitions: dict
    source: str
    ranges: dict = field(default_factory=dict)
    figures: list = field(default_factory=list)


# =====================================================================  loading
def load_paper(source) -> Paper:
    """Load a claims file: a path, or the name of a shipped paper (``popov2017``).
    The file must be a regular UTF-8 text file of at most
    :data:`MAX_FILE_BYTES` bytes (never a device, a FIFO or a directory)."""
    path = resolve_paper(source)
    text = read_text_file(path)
    try:
        data = tomllib.loads(text, parse_float=PrintedFloat.from_toml)
    except tomllib.TOMLDecodeError as exc:
        raise ClaimError(f"{path}: not valid TOML: {exc}") from None
    except RecursionError:
        raise ClaimError(f"{path}: not a claims file: its TOML nests too deeply") from None
    return paper_from_dict(data, str(path))


def resolve_paper(source) -> Path:
    """The path of a claims file given as a path or as a shipped paper's name."""
    p = Path(source)
    if p.suffix == ".toml" and p.exists():
        return p
    data_dir = Path(__file__).with_name("data")
    shipped = data_dir / f"{source}.toml"
    if shipped.exists():
        return shipped
    if p.exists():
        return p
    names = sorted(q.stem for q in data_dir.glob("*.toml"))
    raise ClaimError(f"no claims file {source!r} (neither a path nor a shipped paper; shipped: {names})")


def paper_from_dict(data: dict, source: str = "<claims>") -> Paper:
    """Validate and parse a claims document (the TOML as a dict)."""
    if not isinstance(data, dict):
        raise ClaimError(f"{source}: the claims document must be a table")
    unknown = set(data) - _TOP_KEYS
    if unknown:
        raise ClaimError(f"{source}: unknown top-level field(s) {sorted(unknown)}")
    for key, types in (("key", str), ("title", str), ("reference", str), ("definitions", dict), ("ranges", dict),
                       ("claims", list), ("figures", list)):
        typed_field(data, key, types, source)
    file_syms = declare_symbols(names_field(data, "symbols", source), where_text(source, fld="symbols"))
    defs_show, defs = {}, {}
    for name, text in (data.get("definitions") or {}).items():
        where = where_text(source, fld=f"definitions.{name}")
        if not name.isidentifier() or name.startswith("_"):
            raise ClaimError(f"{where}: {name!r} is not a plain name")
        defs[name] = parse_expr(text, symbols=file_syms, definitions=defs, where=where)
        defs_show[name] = sp.Symbol(name, positive=True)
    ranges = {k: parse_range(v, where_text(source, fld=f"ranges.{k}")) for k, v in (data.get("ranges") or {}).items()}
    for k, (lo, _hi) in ranges.items():          # the file's ranges as the claims' own: R = [-1, 1] is bad input
        check_sign(k, lo, file_syms, where_text(source, fld=f"ranges.{k}"))
    claims_data = data.get("claims")
    if not isinstance(claims_data, list) or not claims_data:
        raise ClaimError(f"{source}: no [[claims]] in the file")
    claims = []
    seen = set()
    for i, cd in enumerate(claims_data):
        claim = claim_from_dict(cd, source, defs, defs_show, ranges, file_syms, index=i)
        if claim.label in seen:
            raise ClaimError(f"{where_text(source, claim.label)}: duplicate label")
        seen.add(claim.label)
        claims.append(claim)
    figs_data = data.get("figures", [])
    if not isinstance(figs_data, list):
        raise ClaimError(f"{source}: figures: expected [[figures]] tables")
    figures = [figure_from_dict(fd, source, file_syms, index=i) for i, fd in enumerate(figs_data)]
    if len({f.file for f in figures}) != len(figures):
        raise ClaimError(f"{source}: two [[figures]] write the same file")
    return Paper(str(data.get("key", Path(source).stem)), str(data.get("title", "")),
                 str(data.get("reference", "")), claims, defs, source, ranges, figures)


def claim_from_dict(cd: dict, source="<claims>", definitions=None, definitions_shown=None,
                    file_ranges=None, file_symbols=None, index=0) -> Claim:
    """Validate and parse one ``[[claims]]`` table."""
    if not isinstance(cd, dict):
        raise ClaimError(f"{source}: claim #{index + 1} is not a table")
    label = cd.get("label")
    if not isinstance(label, str) or not label.strip():
        raise ClaimError(f"{source}: claim #{index + 1} has no label")
    W = lambda fld=None: where_text(source, label, fld)  # noqa: E731
    unknown = set(cd) - _CLAIM_KEYS
    if unknown:
        raise ClaimError(f"{W()}: unknown field(s) {sorted(unknown)}; allowed: {sorted(_CLAIM_KEYS)}")
    for key, types in (("quantity", str), ("profile", str), ("profiles", list), ("profile_names", list),
                       ("formula", (str, int, float)), ("forms", list), ("assumptions", list), ("ranges", dict),
                       ("special", dict), ("force_law", str), ("values", list), ("labels", dict), ("note", str),
                       ("reading", str), ("title", str), ("description", str), ("points", int), ("period", str),
                       ("material", str), ("impulse", str), ("history", str)):
        typed_field(cd, key, types, W())
    quantity = cd.get("quantity")
    if quantity not in QUANTITIES:
        raise ClaimError(f"{W('quantity')}: unknown quantity {quantity!r}; choose one of {sorted(QUANTITIES)}")
    syms = dict(file_symbols or {})
    syms.update(declare_symbols(names_field(cd, "symbols", W()), W("symbols")))
    defs = dict(definitions or {})
    shown = dict(definitions_shown or {})
    general = "profiles" in cd
    if "profile" in cd and general:
        raise ClaimError(f"{W()}: give either profile or profiles, not both")
    ph = PLACEHOLDERS if general else {}

    def parse(text, fld, **kw):
        return parse_expr(text, symbols=syms, definitions=defs, placeholders=kw.pop("placeholders", ph),
                          where=W(fld), **kw)

    profiles = []
    if general:
        plist = cd["profiles"]
        if not isinstance(plist, list) or not plist:
            raise ClaimError(f"{W('profiles')}: expected a non-empty list of profile formulas")
        names = cd.get("profile_names", [])
        if names and (not isinstance(names, list) or len(names) != len(plist)):
            raise ClaimError(f"{W('profile_names')}: expected one name per profile ({len(plist)})")
        for j, ptxt in enumerate(plist):
            display = f"{names[j]} ({ptxt})" if names else str(ptxt)
            profiles.append((display, parse(ptxt, f"profiles[{j}]", placeholders={})))
    elif "profile" in cd:
        profiles.append((str(cd["profile"]), parse(cd["profile"], "profile", placeholders={})))
    if quantity not in PROFILE_FREE and not profiles:
        raise ClaimError(f"{W()}: quantity {quantity!r} needs a profile (profile = \"...\")")
    for txt, e in profiles:
        if S.x not in e.free_symbols:
            raise ClaimError(f"{W('profile')}: the profile {txt!r} does not depend on x")
    force_law = None
    if quantity == "inverse_profile":
        if "force_law" not in cd:
            raise ClaimError(f"{W()}: quantity 'inverse_profile' needs force_law = \"...\"")
        force_law = parse(cd["force_law"], "force_law")
    values, labels = [], {}
    texts = []
    if "values" in cd:
        if quantity != "Z_n":
            raise ClaimError(f"{W('values')}: a table of values is supported for quantity 'Z_n' only")
        for j, vt in enumerate(cd["values"]):
            v = parse(str(vt), f"values[{j}]")
            if v.free_symbols:
                raise ClaimError(f"{W(f'values[{j}]')}: expected a number, got {vt!r}")
            values.append((str(vt), v))
        for k, v in (cd.get("labels") or {}).items():
            if k not in [vt for vt, _ in values]:
                raise ClaimError(f"{W('labels')}: {k!r} is not one of the values")
            labels[k] = number_field(v, W(f"labels.{k}"))
    else:
        if "formula" not in cd:
            raise ClaimError(f"{W()}: no formula")
        forms_raw = cd.get("forms", [])
        if not isinstance(forms_raw, list):
            raise ClaimError(f"{W('forms')}: expected a list of formulas")
        texts = [str(f) for f in forms_raw] + [str(cd["formula"])]
    rounding = cd.get("rounding", "exact")
    if rounding not in ("exact", "printed"):
        raise ClaimError(f"{W('rounding')}: 'exact' (30 digits) or 'printed' (to the printed digits), got {rounding!r}")
    if rounding == "printed" and not any(DECIMAL.search(t) for t in texts):
        raise ClaimError(f"{W('rounding')}: 'printed' needs a decimal constant such as 0.300 in the formula")
    forms = []
    for j, text in enumerate(texts):
        fld = "formula" if j == len(texts) - 1 else f"forms[{j}]"
        expr = parse(text, fld)
        shown_expr = parse_expr(text, symbols=syms, definitions=shown, placeholders=ph, where=W(fld))
        variants = tuple(parse(v, fld) for v in printed_variants(text)) if rounding == "printed" else ()
        forms.append(Form(text, shown_expr, expr, variants, printed_spread(text)))
    assumptions = tuple(parse_expr(str(r), symbols=syms, where=W(f"assumptions[{j}]"), allow_relational=True)
                        for j, r in enumerate(cd.get("assumptions", [])))
    table = {}
    for k, v in (cd.get("ranges") or {}).items():
        table[k] = parse_range(v, W(f"ranges.{k}"))
    special = {}
    for k, vals in (cd.get("special") or {}).items():
        if not isinstance(vals, list):
            vals = [vals]
        special[k] = [number_field(v, W(f"special.{k}")) for v in vals]
    for k, (lo, _hi) in table.items():
        check_sign(k, lo, syms, W(f"ranges.{k}"))
    for k, vals in special.items():
        for v in vals:
            check_sign(k, v, syms, W(f"special.{k}"))
    visco = {}
    if quantity in VISCOELASTIC:
        for key in ("material", "history"):
            if key not in cd:
                raise ClaimError(f"{W()}: quantity {quantity!r} needs {key} = \"...\" (E*(t) for material, "
                                 "a(t) or P(t) in t for history)")
            visco[key] = parse(cd[key], key, placeholders={})
        visco["impulse"] = parse(cd.get("impulse", "0"), "impulse", placeholders={})
    else:
        for key in ("material", "impulse", "history"):
            if key in cd:
                raise ClaimError(f"{W(key)}: only the quantities {', '.join(VISCOELASTIC)} take a {key}")
    pts = cd.get("points", 6)
    if isinstance(pts, bool) or not isinstance(pts, int) or not 1 <= pts <= 50:
        raise ClaimError(f"{W('points')}: expected an integer 1..50")
    return Claim(label.strip(), quantity, forms, profiles, general, assumptions, table, special,
                 {**syms}, force_law, values, labels, str(cd.get("title", cd.get("description", ""))),
                 str(cd.get("note", "")), str(cd.get("reading", "")), pts, str(source),
                 dict(file_ranges or {}), _period(parse(cd["period"], "period", placeholders={}), W("period"))
                 if "period" in cd else None,
                 **visco)


def _period(expr, where):
    """The period of a claim, checked as the contact will check it
    (:class:`~linecontact_sym.method.geometry.Periodic`: a positive finite
    number or positive symbols): ``period = "0"`` is bad input at load
    (exit 2), not an undecided claim."""
    from ..method.geometry import Periodic
    try:
        Periodic(expr)
    except LineContactError as exc:
        raise ClaimError(f"{where}: {exc}") from None
    return expr


def claim_from_cli(quantity: str, formula: str, profile: str | None = None, *, label="command line",
                   assumptions=(), ranges=None, symbols=(), force_law=None, special=None) -> Claim:
    """A claim typed on the command line (``check --profile ... --force ...``)."""
    d = {"label": label, "quantity": quantity, "formula": formula}
    if profile is not None:
        d["profile"] = profile
    if force_law is not None:
        d["force_law"] = force_law
    if assumptions:
        d["assumptions"] = list(assumptions)
    if ranges:
        d["ranges"] = ranges
    if symbols:
        d["symbols"] = list(symbols)
    if special:
        d["special"] = special
    return claim_from_dict(d, "command line")


def figure_from_dict(fd: dict, source="<claims>", file_symbols=None, index=0) -> Figure:
    """Validate and parse one ``[[figures]]`` table."""
    if not isinstance(fd, dict):
        raise ClaimError(f"{source}: figure #{index + 1} is not a table")
    stem = fd.get("file")
    if not isinstance(stem, str) or not stem or not all(ch.isalnum() or ch in "_-" for ch in stem):
        raise ClaimError(f"{source}: figure #{index + 1}: file must be a plain file name stem "
                         f"(letters, digits, _ and -), got {stem!r}")
    W = lambda fld=None: f"{source}: figure {stem!r}" + (f": {fld}" if fld else "")  # noqa: E731
    unknown = set(fd) - _FIGURE_KEYS
    if unknown:
        raise ClaimError(f"{W()}: unknown field(s) {sorted(unknown)}; allowed: {sorted(_FIGURE_KEYS)}")
    quantity = fd.get("quantity", "force")
    if quantity not in VALUE_SYMBOLS:
        raise ClaimError(f"{W('quantity')}: a figure draws one of {sorted(VALUE_SYMBOLS)}, got {quantity!r}")
    caption = text_field(fd.get("caption"), W("caption"), required=True).strip()
    if not caption.endswith("."):
        raise ClaimError(f"{W('caption')}: the caption is a sentence (ending with a full stop)")
    syms = dict(file_symbols or {})
    value = VALUE_SYMBOLS[quantity]
    for key in ("x", "y"):
        if not isinstance(fd.get(key), str):
            raise ClaimError(f"{W(key)}: the normalised axis is a formula, e.g. x = \"a/b\"")
    x = parse_expr(fd["x"], symbols=syms, where=W("x"))
    y = parse_expr(fd["y"], symbols=syms, placeholders={value.name: value}, where=W("y"))
    if value not in y.free_symbols:
        raise ClaimError(f"{W('y')}: the ordinate must contain the value {value} of the {quantity}")
    xr = parse_range(fd.get("x_range"), W("x_range"))
    values = {}
    for k, v in (fd.get("values") or {}).items():
        sym = declare_symbols([k], W("values"))[k] if k not in syms else syms[k]
        values[sym] = number_field(v, W(f"values.{k}"))
    curves_data = fd.get("curves")
    if not isinstance(curves_data, list) or not curves_data:
        raise ClaimError(f"{W()}: no [[figures.curves]]")
    curves = []
    for j, cd in enumerate(curves_data):
        cw = W(f"curves[{j}]")
        if not isinstance(cd, dict) or set(cd) - _CURVE_KEYS or "profile" not in cd:
            raise ClaimError(f"{cw}: a curve is a table with profile and optional {sorted(_CURVE_KEYS - {'profile'})}")
        prof = parse_expr(text_field(cd["profile"], cw, required=True), symbols=syms, where=f"{cw}: profile")
        if S.x not in prof.free_symbols:
            raise ClaimError(f"{cw}: the profile {cd['profile']!r} does not depend on x")
        width = cd.get("width", 1.5)
        if isinstance(width, bool) or not isinstance(width, (int, float)) or width <= 0:
            raise ClaimError(f"{cw}: width must be a positive number")
        curves.append(Curve(text_field(cd.get("name", f"curve {j + 1}"), cw), cd["profile"], prof,
                            text_field(cd.get("label"), cw), text_field(cd.get("style", "-"), cw), float(width)))
    names = [c.name for c in curves]
    ratio = fd.get("ratio")
    if ratio is not None:
        if not (isinstance(ratio, list) and len(ratio) == 2 and all(r in names for r in ratio)):
            raise ClaimError(f"{W('ratio')}: expected [numerator, denominator], two of the curve names {names}")
        ratio = tuple(ratio)
    marks = []
    for j, m in enumerate(fd.get("marks", [])):
        if not (isinstance(m, dict) and set(m) <= {"x", "text"} and "x" in m):
            raise ClaimError(f"{W(f'marks[{j}]')}: a mark is {{ x = ..., text = \"...\" }}")
        marks.append((float(number_field(m["x"], W(f"marks[{j}].x"))), text_field(m.get("text"), W(f"marks[{j}].text"))))
    pts = fd.get("points", 401)
    if not isinstance(pts, int) or not 2 <= pts <= 100000:
        raise ClaimError(f"{W('points')}: expected an integer 2..100000")
    size = fd.get("size")
    if size is not None:
        if not (isinstance(size, list) and len(size) == 2):
            raise ClaimError(f"{W('size')}: expected [width, height] in inches")
        size = tuple(float(number_field(v, W("size"))) for v in size)
    lims = {k: (float(number_field(fd[k], W(k))) if k in fd else None) for k in ("y_min", "y_max")}
    return Figure(stem, text_field(fd.get("title"), W("title")), caption, quantity, x, y, xr, values, curves, pts,
                  text_field(fd.get("xlabel"), W("xlabel")), text_field(fd.get("ylabel"), W("ylabel")),
                  lims["y_min"], lims["y_max"], size, marks, ratio, text_field(fd.get("ratio_label"), W("ratio_label")))


# =====================================================================  placeholders
def substitute_placeholders(expr, profile, derived_force=None, derived_pressure=None):
    """Replace the placeholders f(.), force(.), p0 of a general formula by the
    profile, the derived force law P_0 and the derived pressure p_0."""
    if profile is not None and expr.has(PLACEHOLDER_F):
        expr = expr.replace(lambda e: isinstance(e, AppliedUndef) and e.func == PLACEHOLDER_F,
                            lambda e: profile.xreplace({S.x: e.args[0]}))
    if expr.has(PLACEHOLDER_FORCE):
        if derived_force is None:
            raise ClaimError("force(...) is used but the engine found no closed-form force law")
        expr = expr.replace(lambda e: isinstance(e, AppliedUndef) and e.func == PLACEHOLDER_FORCE,
                            lambda e: derived_force.xreplace({S.a: e.args[0]}))
    if expr.has(PLACEHOLDER_P0):
        if derived_pressure is None:
            raise ClaimError("p0 is used but the engine found no closed-form pressure")
        expr = expr.xreplace({PLACEHOLDER_P0: derived_pressure})
    return expr


__all__ = ["QUANTITIES", "ASYMMETRIC_QUANTITIES", "VISCOELASTIC", "PROFILE_FREE", "PLACEHOLDERS", "DEFAULT_RANGES", "X_RANGES", "Form", "Claim", "Curve",
           "Figure", "Paper", "range_of", "load_paper", "resolve_paper", "paper_from_dict", "claim_from_dict",
           "claim_from_cli", "figure_from_dict", "substitute_placeholders"]
